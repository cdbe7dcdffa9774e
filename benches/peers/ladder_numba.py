#!/usr/bin/env python3
"""The peer of `ladder`'s kernels: the Jacob's-ladder model of docs/model.md
integrated by symplectic Euler in a numba-compiled loop, as a physicist would
write it today.

Same model as `ladder` (energy, analytic forces, damping, gravity, drive of
block 1, ground state), same scheme (symplectic Euler with the damping taken
implicitly: v' = (v + h F/m) / (1 + h c), q' = q + h v'), same subdivision of
the time between drive corners into equal steps of at most dt, and the same
arrival rule (the first sign change of the polarisation sin(theta_n),
interpolated by a cubic Hermite polynomial). Not bit-identical to `ladder`
(the C library's sin and cos, another order of operations), so arrival times
agree to round-off amplified by the dynamics, not bit for bit.

    python3 ladder_numba.py single --n 10 --alpha 60 --t-end 4000
    python3 ladder_numba.py sweep --runs 100 --alpha-from 40 --alpha-to 89.5 --procs 2

Each prints one JSON object: the runs' arrival times, steps and wall time
(for `single`, of the loop alone, after the compiled code is loaded; time the
whole process with hyperfine, as compare.sh does).
See README.md beside this file.
"""

import argparse
import json
import math
import multiprocessing
import sys
import time

import numpy as np
from numba import njit

from ladder_model import M, R, ground_state, rest_a



@njit(cache=True)
def hermite_root(y0, m0, y1, m1):
    """Root in [0, 1] of the cubic Hermite interpolant (bisection)."""
    lo, hi = 0.0, 1.0
    sign_lo = -1.0 if y1 > 0 else (1.0 if y1 < 0 else 0.0)
    for _ in range(60):
        s = 0.5 * (lo + hi)
        s2 = s * s
        s3 = s2 * s
        p = ((2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * m0
             + (-2 * s3 + 3 * s2) * y1 + (s3 - s2) * m1)
        if p * sign_lo > 0:
            lo = s
        else:
            hi = s
    return 0.5 * (lo + hi)


@njit(cache=True)
def simulate(n, alpha_deg, b, gamma, gravity, inertia, t_d, t_end, dt):
    """One kink (alpha > 0) or antikink run; returns (arrivals, steps,
    final theta)."""
    alpha = alpha_deg * math.pi / 180.0
    a = rest_a(b, alpha)
    x, y, th, par = ground_state(n, alpha, b)
    vx = np.zeros(n)
    vy = np.zeros(n)
    vt = np.zeros(n)
    sn = np.empty(n)
    cs = np.empty(n)
    fx = np.zeros(n)
    fy = np.zeros(n)
    tu = np.zeros(n)
    tl = np.zeros(n)
    # Arrival: the starting interval (k pi, (k + 1) pi) of sin(theta).
    sign0 = 1.0 if math.sin(alpha) >= 0 else -1.0
    k = math.floor(alpha / math.pi)
    lo_b, hi_b = k * math.pi, (k + 1) * math.pi
    # Only angles outside this window can have changed the sign of sin.
    lo_w, hi_w = lo_b + 1e-6 * (1 + abs(k)), hi_b - 1e-6 * (1 + abs(k))
    arrival = np.full(n, np.nan)
    rate_xy = gamma / M
    rate_th = gamma * R * R / inertia
    x0, y0 = x[0], y[0]
    g = M * gravity
    t = 0.0
    steps = 0
    for c in range(2):
        stop = min(t_d, t_end) if c == 0 else t_end
        if stop <= t:
            continue
        span = stop - t
        count = int(math.ceil(span / dt - 1e-6))
        if count < 1:
            count = 1
        h = span / count
        d_xy = 1.0 / (1.0 + h * rate_xy)
        k_xy = h / M * d_xy
        d_th = 1.0 / (1.0 + h * rate_th)
        k_th = h / inertia * d_th
        for step in range(count):
            t_new = stop if step == count - 1 else t + h
            for i in range(n):
                sn[i] = math.sin(th[i])
                cs[i] = math.cos(th[i])
            for j in range(n - 1):
                tx0, ty0 = sn[j], par[j] * cs[j]
                tx1, ty1 = sn[j + 1], par[j + 1] * cs[j + 1]
                ex, ey = x[j + 1] - x[j], y[j + 1] - y[j]
                ux, uy = R * (tx1 - tx0), R * (ty1 - ty0)
                ax, ay, bx, by = ex - ux, ey - uy, ex + ux, ey + uy
                ka = 1.0 - a / math.sqrt(ax * ax + ay * ay)
                kb = 1.0 - b / math.sqrt(bx * bx + by * by)
                fax, fay, fbx, fby = ka * ax, ka * ay, kb * bx, kb * by
                fx[j] = fax + fbx
                fy[j] = fay + fby
                dx, dyy = R * (fbx - fax), R * (fby - fay)
                tu[j] = dx * cs[j + 1] - dyy * par[j + 1] * sn[j + 1]
                tl[j] = -(dx * cs[j] - dyy * par[j] * sn[j])
            for i in range(1, n):
                gx = -g + fx[i - 1] - (fx[i] if i < n - 1 else 0.0)
                gy = fy[i - 1] - (fy[i] if i < n - 1 else 0.0)
                gt = tu[i - 1] + (tl[i] if i < n - 1 else 0.0)
                th_old, om_old = th[i], vt[i]
                vx[i] = vx[i] * d_xy - gx * k_xy
                vy[i] = vy[i] * d_xy - gy * k_xy
                vt[i] = vt[i] * d_th - gt * k_th
                x[i] += h * vx[i]
                y[i] += h * vy[i]
                th[i] += h * vt[i]
                if ((th[i] <= lo_w or th[i] >= hi_w) and math.isnan(arrival[i])
                        and math.sin(th[i]) * sign0 < 0):
                    c = lo_b if th[i] < th_old else hi_b
                    s = hermite_root(th_old - c, h * om_old, th[i] - c, h * vt[i])
                    arrival[i] = t + s * (t_new - t)
            # Block 1: centre clamped, angle driven.
            th_old, om_old = th[0], vt[0]
            if t_new < t_d:
                th[0] = alpha + (-2 * alpha) * t_new / t_d
                vt[0] = -2 * alpha / t_d
            else:
                th[0] = -alpha
                vt[0] = 0.0
            x[0], y[0], vx[0], vy[0] = x0, y0, 0.0, 0.0
            if ((th[0] <= lo_w or th[0] >= hi_w) and math.isnan(arrival[0])
                    and math.sin(th[0]) * sign0 < 0):
                c = lo_b if th[0] < th_old else hi_b
                s = hermite_root(th_old - c, h * om_old, th[0] - c, h * vt[0])
                arrival[0] = t + s * (t_new - t)
            t = t_new
            steps += 1
    return arrival, steps, th.copy()


def run_one(job):
    """One run of a sweep (in a worker process)."""
    n, alpha, t_end, dt = job
    arrival, steps, theta = simulate(n, alpha, 1.3, 0.02, 2e-4, 0.25, 1000.0, t_end, dt)
    return {
        "alpha_deg": alpha,
        "arrival_times": [None if math.isnan(v) else float(v) for v in arrival],
        "steps": int(steps),
        "final_theta_deg": [float(math.degrees(v)) for v in theta],
    }


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = p.add_subparsers(dest="mode", required=True)
    one = sub.add_parser("single", help="one run")
    one.add_argument("--n", type=int, default=10)
    one.add_argument("--alpha", type=float, default=60.0)
    sweep = sub.add_parser("sweep", help="many kinks over alpha, on every core")
    sweep.add_argument("--n", type=int, default=10)
    sweep.add_argument("--runs", type=int, default=100)
    sweep.add_argument("--alpha-from", type=float, default=40.0)
    sweep.add_argument("--alpha-to", type=float, default=89.5)
    sweep.add_argument("--procs", type=int, default=multiprocessing.cpu_count())
    for q in (one, sweep):
        q.add_argument("--t-end", type=float, default=4000.0)
        q.add_argument("--dt", type=float, default=0.01)
    args = p.parse_args(argv)
    if args.mode == "single":
        # Load the compiled loop (from numba's cache, or compile it) before
        # the clock starts: `wall_seconds` is the loop's time alone.
        run_one((args.n, args.alpha, 0.01, args.dt))
    start = time.perf_counter()
    if args.mode == "single":
        runs = [run_one((args.n, args.alpha, args.t_end, args.dt))]
    else:
        k = max(args.runs - 1, 1)
        alphas = [args.alpha_from + (args.alpha_to - args.alpha_from) * i / k
                  for i in range(args.runs)]
        jobs = [(args.n, a, args.t_end, args.dt) for a in alphas]
        with multiprocessing.Pool(args.procs) as pool:
            runs = pool.map(run_one, jobs, chunksize=1)
    wall = time.perf_counter() - start
    block_steps = sum(r["steps"] for r in runs) * args.n
    json.dump({
        "mode": args.mode,
        "n": args.n,
        "runs": runs,
        "wall_seconds": wall,
        "ns_per_block_step": wall * 1e9 / block_steps,
    }, sys.stdout)
    print()


if __name__ == "__main__":
    main(sys.argv[1:])
