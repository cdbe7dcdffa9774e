#!/usr/bin/env python3
"""The Python package's speed (a benchmark, not a test; docs/python.md):

1. `import jacobs_ladder` in a fresh interpreter (goal: under 100 ms);
2. the paper's run (N = 10, α = 60°, symplectic Euler, dt = 0.01,
   t_end = 4000 τ: 4 × 10^5 steps) through Python, against the same run in
   the library as `ladder simulate --json` reports it (`wall_seconds`: the
   library call alone, without process start; goal: within 5 %);
3. the numba peer of benches/peers/ (its compiled loop, loaded first) on
   the same run, in this same process, when numba is installed.

Times are medians over ROUNDS alternating rounds (A B A B ...).

    python benches/python_bench.py [--rounds 15] [--ladder target/release/ladder]
"""

import argparse
import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PAPER = dict(alpha=60, n=10, t_end=4000, integrator="symplectic-euler")


def import_time(python: str, rounds: int) -> float:
    """Median wall time of `import jacobs_ladder` in a fresh interpreter,
    measured inside it (interpreter start excluded)."""
    code = (
        "import time; t = time.perf_counter(); import jacobs_ladder; "
        "print(time.perf_counter() - t)"
    )
    times = [float(subprocess.check_output([python, "-c", code])) for _ in range(rounds)]
    return statistics.median(times)


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--rounds", type=int, default=15)
    p.add_argument("--ladder", default=str(ROOT / "target" / "release" / "ladder"))
    args = p.parse_args()

    import numpy as np

    import jacobs_ladder as jl

    flags = ["simulate", "--json", "--alpha", "60", "--n", "10", "--t-end", "4000",
             "--integrator", "symplectic-euler"]

    def through_python(samples):
        t = time.perf_counter()
        run = jl.simulate(**PAPER, samples=samples)
        return time.perf_counter() - t, run

    def through_library():
        out = json.loads(subprocess.check_output([args.ladder, *flags]))
        return out["wall_seconds"], out

    peer = None
    try:
        sys.path.insert(0, str(ROOT / "benches" / "peers"))
        import ladder_numba

        ladder_numba.simulate(10, 60.0, 1.3, 0.02, 2e-4, 0.25, 1000.0, 0.01, 0.01)  # load

        def peer():
            t = time.perf_counter()
            arrival, steps, theta = ladder_numba.simulate(
                10, 60.0, 1.3, 0.02, 2e-4, 0.25, 1000.0, 4000.0, 0.01
            )
            return time.perf_counter() - t, arrival

    except ImportError as e:
        print(f"numba peer skipped: {e} (pip install numba)", file=sys.stderr)

    through_python([])  # warm
    py_times, py_sampled, lib_times, peer_times = [], [], [], []
    for _ in range(args.rounds):
        t, run = through_python([])
        py_times.append(t)
        t, lib = through_library()
        lib_times.append(t)
        t, _ = through_python(None)
        py_sampled.append(t)
        if peer:
            t, peer_arrival = peer()
            peer_times.append(t)
    same = np.array_equal(
        run.arrival_times,
        np.array([np.nan if a is None else a for a in lib["arrival_times"]]),
        equal_nan=True,
    )
    med = statistics.median
    imp = import_time(sys.executable, args.rounds)
    rows = [
        ("import jacobs_ladder", imp * 1e3, "ms", "goal < 100 ms"),
        ("paper's run, library (ladder simulate wall_seconds)", med(lib_times) * 1e3, "ms", ""),
        ("paper's run, Python jl.simulate (no samples)", med(py_times) * 1e3, "ms",
         f"{med(py_times) / med(lib_times):.3f} × library; goal ≤ 1.05"),
        ("paper's run, Python with 401 samples (default)", med(py_sampled) * 1e3, "ms",
         f"{med(py_sampled) / med(lib_times):.3f} × library"),
    ]
    if peer_times:
        rows.append(("paper's run, numba peer (loop only)", med(peer_times) * 1e3, "ms",
                     f"{med(peer_times) / med(py_times):.2f} × Python"))
    for name, value, unit, note in rows:
        print(f"{name:52s} {value:9.2f} {unit}  {note}")
    print(f"arrival times, Python = library bit for bit: {same}")
    print(json.dumps({
        "rounds": args.rounds,
        "import_ms": imp * 1e3,
        "library_ms": med(lib_times) * 1e3,
        "python_ms": med(py_times) * 1e3,
        "python_sampled_ms": med(py_sampled) * 1e3,
        "numba_ms": med(peer_times) * 1e3 if peer_times else None,
    }))


if __name__ == "__main__":
    main()
