"""examples/python_tour.py runs, and writes what it says."""

import runpy
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_the_tour_runs(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(sys, "argv", ["python_tour.py", str(tmp_path)])
    runpy.run_path(str(ROOT / "examples" / "python_tour.py"), run_name="__main__")
    printed = capsys.readouterr().out
    assert "<Run kink α = 60°" in printed
    assert (tmp_path / "figure-2d.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert (tmp_path / "figure-k70.png").exists() and (tmp_path / "figure-k70.json").exists()
