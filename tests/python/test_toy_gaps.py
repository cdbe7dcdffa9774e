"""`scripts/toy-gaps` (docs/experiments.md, "A longer toy"): the least
distance between two blocks' rectangles, which says whether a junction
of the toy as built is open, checked against geometry worked by hand, and
the script run on the states of a short run of the toy."""

import importlib.machinery
import importlib.util
import math
import subprocess
import sys

import pytest

from conftest import ROOT

D = 0.635 / 5.7  # the toy's thickness, in s


def toy_gaps():
    path = str(ROOT / "scripts" / "toy-gaps")
    loader = importlib.machinery.SourceFileLoader("toy_gaps", path)
    spec = importlib.util.spec_from_loader("toy_gaps", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def test_the_gap_is_the_distance_between_the_rectangles():
    g = toy_gaps()
    h = D / 2
    upper = g.corners(0.0, 0.0, math.pi / 2, 0, h)
    # Hanging end to end b apart: the gap is b - s.
    for b in (1.0, 1.0088, 1.3):
        lower = g.corners(b, 0.0, math.pi / 2, 1, h)
        assert g.distance(upper, lower) == pytest.approx(b - 1.0, abs=1e-12)
    # Side by side (a rope ladder's rung beside the block above), w apart.
    for w in (D, 0.5):
        beside = g.corners(0.3, D + w, math.pi / 2, 1, h)
        assert g.distance(upper, beside) == pytest.approx(w, abs=1e-12)
    # Hanging at an angle from the upper block's corner: touching, gap 0
    # (where the distance of the centre lines is large).
    corner = upper[1]
    a = math.radians(50)
    lower_centre = (corner[0] + 0.5 * math.sin(a) + h * math.cos(a), corner[1] - 0.5 * math.cos(a) + h * math.sin(a))
    tilted = g.corners(lower_centre[0], lower_centre[1], a, 0, h)
    assert g.distance(upper, tilted) < 1e-9


def test_the_script_reads_a_runs_states(ladder, tmp_path):
    app = tmp_path / "toy.toml"
    text = (ROOT / "assets" / "scenes" / "toy.toml").read_text()
    app.write_text(text[text.index("[apparatus]"):text.index("[drive]")])
    npz = tmp_path / "run.npz"
    ladder("simulate", "--apparatus", app, "--alpha", "86", "--n", "4", "--integrator", "rk4",
           "--dt", "0.02", "--drive-time", "232", "--t-end", "50", "--npz", npz, "--sample-every", "5")
    out = subprocess.run([sys.executable, str(ROOT / "scripts" / "toy-gaps"), str(npz)],
                         capture_output=True, text=True, check=True).stdout.splitlines()
    assert out[0].startswith("junction median-gap")
    rows = [line.split() for line in out[1:]]
    assert [r[0] for r in rows] == ["1-2", "2-3", "3-4"]
    # 50 tau into the turn every junction is still closed: its blocks
    # never more than half a thickness apart.
    for r in rows:
        assert float(r[2]) < D / 2 and r[3] == "0.00" and r[4] == "-", r
    bad = subprocess.run([sys.executable, str(ROOT / "scripts" / "toy-gaps"), str(app)],
                         capture_output=True, text=True)
    assert bad.returncode == 1 and bad.stderr.count("\n") == 1 and "toy-gaps:" in bad.stderr
