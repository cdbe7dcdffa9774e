#!/usr/bin/env python3
"""The sweep a physicist writes today: the paper's integrator (symplectic
Euler, dt = 0.01 tau, to the paper's 4000 tau) compiled with numba, one run
per alpha, spread over every core with multiprocessing. The peer of
`ladder sweep` in benches/sweep_vs_numba.sh (docs/performance.md).

    python3 benches/peers/sweep_numba.py [--alpha START:STOP:STEP] [--n N]
        [--t-end T] [--dt DT] [--processes P] [--out FILE.csv]

Model of docs/model.md (ladder_model.py): blocks of length s = 1, mass m = 1, inertia I,
A springs (rest length a = sqrt(b^2 + 4 cos^2 alpha)) between the A nodes
X_n - (s/2) t_n and B springs (rest length b) between the B nodes
X_n + (s/2) t_n, t_n = (sin theta_n, (-1)^n cos theta_n); gravity G pulls
along +x; damping -gamma v and -gamma r^2 omega; block 1 held at its
ground-state centre and turned alpha -> -alpha over T_d = 1000 tau.
Arrival time of block n: the first sign change of sin theta_n (linear
interpolation within the step). Needs numpy and numba (PyPI).
"""
import argparse
import math
import multiprocessing as mp
import sys
import time

import numpy as np
from numba import njit

from ladder_model import R, ground_state, rest_a


@njit(cache=True)
def simulate(alpha_deg, n, b, gamma, gravity, inertia, t_d, t_end, dt):
    alpha = math.radians(alpha_deg)
    r = R
    a = rest_a(b, alpha)
    x, y, th, par = ground_state(n, alpha, b)
    vx = np.zeros(n)
    vy = np.zeros(n)
    vt = np.zeros(n)
    fx = np.zeros(n)
    fy = np.zeros(n)
    ft = np.zeros(n)
    s0 = np.zeros(n)
    for i in range(n):
        s0[i] = 1.0 if math.sin(th[i]) >= 0.0 else -1.0
    arrival = np.full(n, -1.0)
    prev = np.zeros(n)
    steps = int(round(t_end / dt))
    for k in range(steps):
        # Forces: gradient of the spring energy, gravity along +x.
        for i in range(n):
            fx[i] = gravity
            fy[i] = 0.0
            ft[i] = 0.0
        for i in range(n - 1):
            j = i + 1
            si, ci = math.sin(th[i]), math.cos(th[i])
            sj, cj = math.sin(th[j]), math.cos(th[j])
            for side in (-1.0, 1.0):
                rest = a if side < 0.0 else b
                pix = x[i] + side * r * si
                piy = y[i] + side * r * par[i] * ci
                pjx = x[j] + side * r * sj
                pjy = y[j] + side * r * par[j] * cj
                dx = pjx - pix
                dyy = pjy - piy
                length = math.sqrt(dx * dx + dyy * dyy)
                f = (length - rest) / length
                gx = f * dx
                gy = f * dyy
                fx[i] += gx
                fy[i] += gy
                fx[j] -= gx
                fy[j] -= gy
                # d(node)/d(theta) = side * r * (cos, -(-1)^n sin)
                ft[i] += gx * side * r * ci - gy * side * r * par[i] * si
                ft[j] -= gx * side * r * cj - gy * side * r * par[j] * sj
        # Symplectic Euler: velocities first, then positions.
        for i in range(1, n):
            vx[i] += dt * (fx[i] - gamma * vx[i])
            vy[i] += dt * (fy[i] - gamma * vy[i])
            vt[i] += dt * (ft[i] - gamma * r * r * vt[i]) / inertia
            x[i] += dt * vx[i]
            y[i] += dt * vy[i]
            th[i] += dt * vt[i]
        t1 = (k + 1) * dt
        th[0] = alpha * (1.0 - 2.0 * min(t1 / t_d, 1.0))
        for i in range(n):
            sn = math.sin(th[i])
            if arrival[i] < 0.0 and sn * s0[i] < 0.0:
                p = prev[i]
                frac = p / (p - sn) if p != sn else 1.0
                arrival[i] = t1 - dt + frac * dt
            prev[i] = sn
    return arrival


def one(job):
    alpha, args = job
    return alpha, simulate(alpha, args.n, args.b, args.gamma, args.gravity,
                           args.inertia, args.drive_time, args.t_end, args.dt)


def values(text):
    a, b, h = (float(v) for v in text.split(":"))
    count = int(math.floor((b - a) / h + 1e-6)) + 1
    return [round(a + k * h, 9) for k in range(count)]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--alpha", default="40:89.5:0.5")
    p.add_argument("--n", type=int, default=10)
    p.add_argument("--b", type=float, default=1.3)
    p.add_argument("--gamma", type=float, default=0.02)
    p.add_argument("--gravity", type=float, default=2e-4)
    p.add_argument("--inertia", type=float, default=0.25)
    p.add_argument("--drive-time", type=float, default=1000.0)
    p.add_argument("--t-end", type=float, default=4000.0)
    p.add_argument("--dt", type=float, default=0.01)
    p.add_argument("--processes", type=int, default=mp.cpu_count())
    p.add_argument("--out", default=None)
    args = p.parse_args()
    start = time.perf_counter()
    # Compile (or load from the cache) once in the parent; forked workers
    # inherit the machine code.
    simulate(60.0, 3, args.b, args.gamma, args.gravity, args.inertia, 1.0, 0.02, 0.01)
    compiled = time.perf_counter() - start
    jobs = [(a, args) for a in values(args.alpha)]
    with mp.get_context("fork").Pool(args.processes) as pool:
        results = pool.map(one, jobs, chunksize=1)
    wall = time.perf_counter() - start
    lines = ["alpha," + ",".join(f"t_{i + 1}" for i in range(args.n))]
    for alpha, arr in results:
        lines.append(f"{alpha}," + ",".join("" if t < 0 else f"{t:.4f}" for t in arr))
    if args.out:
        with open(args.out, "w") as f:
            f.write("\n".join(lines) + "\n")
    steps = len(jobs) * int(round(args.t_end / args.dt))
    print(f"numba peer: {len(jobs)} runs, N = {args.n}, {steps} steps, "
          f"{args.processes} processes, compile {compiled:.2f} s, total {wall:.2f} s, "
          f"{1e9 * (wall - compiled) * args.processes / (steps * args.n):.1f} ns per block-step per core",
          file=sys.stderr)


if __name__ == "__main__":
    main()
