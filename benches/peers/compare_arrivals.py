#!/usr/bin/env python3
"""Compares the arrival times of two runs or sweeps, as printed by
`ladder simulate --json`, `kink_sweep` or `ladder_numba.py`: prints the
largest difference and exits 1 if a block flipped in one and not the other
or a difference exceeds the tolerance (default 1e-6 tau).

    python3 compare_arrivals.py OURS.json PEER.json [TOLERANCE]
"""

import json
import sys


def runs(path):
    with open(path) as f:
        d = json.load(f)
    if "runs" in d:
        return [r["arrival_times"] for r in d["runs"]]
    return [d["arrival_times"]]


def main(argv):
    ours, peer = runs(argv[0]), runs(argv[1])
    tol = float(argv[2]) if len(argv) > 2 else 1e-6
    if len(ours) != len(peer):
        print(f"{len(ours)} runs against {len(peer)}")
        return 1
    worst, where, bad = 0.0, None, []
    for k, (a, b) in enumerate(zip(ours, peer)):
        for n, (x, y) in enumerate(zip(a, b)):
            if (x is None) != (y is None):
                bad.append(f"run {k}, block {n + 1}: {x} against {y}")
            elif x is not None and abs(x - y) > worst:
                worst, where = abs(x - y), (k, n + 1)
    flips = sum(x is not None for a in ours for x in a)
    print(f"{len(ours)} runs, {flips} arrivals; largest difference {worst:.3g} tau"
          + (f" (run {where[0]}, block {where[1]})" if where else ""))
    for line in bad:
        print("flip differs:", line)
    return 1 if bad or worst > tol else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
