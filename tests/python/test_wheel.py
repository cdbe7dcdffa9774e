"""`pip wheel .` gives an abi3 wheel that installs into a fresh virtual
environment with no Rust on PATH and imports (docs/python.md). The build
shares target/ with the rest of the tests (CARGO_TARGET_DIR), so it mostly
relinks."""

import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_the_wheel_is_abi3_and_installs_without_rust(tmp_path):
    # scripts/test builds the wheel once (`pip wheel .`), installs it for
    # every test and names it in LADDER_WHEEL; without it, built here.
    start = time.perf_counter()
    if os.environ.get("LADDER_WHEEL"):
        wheels = [Path(os.environ["LADDER_WHEEL"])]
    else:
        env = dict(os.environ)
        env.setdefault("CARGO_TARGET_DIR", str(ROOT / "target"))
        subprocess.run(
            [sys.executable, "-m", "pip", "wheel", str(ROOT), "--no-deps", "-q", "-w", str(tmp_path / "w")],
            check=True, env=env, timeout=900,
        )
        wheels = list((tmp_path / "w").glob("jacobs_ladder-*.whl"))
    assert len(wheels) == 1, wheels
    wheel = wheels[0]
    assert "-abi3-" in wheel.name, wheel.name
    print(f"wheel {wheel.name}: {wheel.stat().st_size} bytes, built in {time.perf_counter() - start:.0f} s")
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    py = venv / "bin" / "python"
    # No Rust on PATH: only the system's folders, none holding cargo or rustc.
    path = os.pathsep.join(
        d for d in ("/usr/local/bin", "/usr/bin", "/bin")
        if not (Path(d) / "cargo").exists() and not (Path(d) / "rustc").exists()
    )
    clean = {k: v for k, v in os.environ.items() if not k.startswith(("CARGO", "RUSTUP", "PYTHON"))}
    clean["PATH"] = path
    assert shutil.which("cargo", path=path) is None and shutil.which("rustc", path=path) is None
    subprocess.run([str(py), "-m", "pip", "install", "-q", str(wheel)], check=True, env=clean, timeout=600)
    code = (
        "import jacobs_ladder as jl; r = jl.simulate(n=6, t_end=1500); "
        "assert r.theta.shape[1] == 6; print(jl.__version__)"
    )
    out = subprocess.run([str(py), "-c", code], check=True, env=clean, cwd=tmp_path,
                         capture_output=True, text=True, timeout=120)
    assert out.stdout.strip() == subprocess.run(
        [sys.executable, "-c", "import jacobs_ladder as jl; print(jl.__version__)"],
        capture_output=True, text=True, check=True).stdout.strip()
