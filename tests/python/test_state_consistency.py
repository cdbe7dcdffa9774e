"""The state arrays of a Run checked against each other: each
velocity against its position's rate of change between close samples,
vx against ΔX/Δt, vy against ΔY/Δt, ω against Δθ/Δt. The energies alone
cannot tell vx from vy (the kinetic energy is symmetric in them); this
check can, and the test shows it on the columns swapped.

The run is the paper's kink on 7 blocks, rk4 at dt = 0.01 τ, sampled every
0.05 τ: central differences over 0.1 τ err by about Δt² X‴/6, measured
4e-7 against velocities up to 5e-3, and the tolerance is a thousandth of
the largest velocity (10 times that error, about 100 times below what
swapping vx and vy gives). The drive turns block 1 at a constant rate from
t = 0 to the drive time, so ω₁ jumps there: differences straddling those
two times are left out.
"""

import numpy as np
import pytest

import jacobs_ladder as jl

DRIVE_TIME = 1000.0


@pytest.fixture(scope="module")
def run():
    return jl.simulate(
        alpha=60, n=7, t_end=1500, integrator="rk4", dt=0.01,
        drive_time=DRIVE_TIME, sample_every=0.05,
    )


def mismatch(t, p, v, wrap=False):
    """Largest |v_k − (p_{k+1} − p_{k−1}) / (t_{k+1} − t_{k−1})|."""
    t, p, v = np.asarray(t), np.asarray(p), np.asarray(v)
    d = p[2:] - p[:-2]
    if wrap:
        d = (d + np.pi) % (2 * np.pi) - np.pi
    rate = d / (t[2:] - t[:-2])[:, None]
    keep = np.ones(len(t) - 2, dtype=bool)
    for corner in (0.0, DRIVE_TIME):
        keep &= ~((t[:-2] <= corner) & (corner <= t[2:]))
    return float(np.max(np.abs(v[1:-1][keep] - rate[keep])))


def agrees(t, p, v, wrap=False):
    return mismatch(t, p, v, wrap) <= 1e-3 * float(np.max(np.abs(v)))


def test_each_velocity_is_its_position_rate_of_change(run):
    assert len(run.t) > 20000
    assert np.max(np.abs(run.vx)) > 1e-3, "the blocks move"
    assert agrees(run.t, run.x, run.vx), mismatch(run.t, run.x, run.vx)
    assert agrees(run.t, run.y, run.vy), mismatch(run.t, run.y, run.vy)
    assert agrees(run.t, run.theta, run.omega, wrap=True), mismatch(
        run.t, run.theta, run.omega, wrap=True
    )


def test_swapped_velocities_fail_the_same_check(run):
    # A planted probe: vx and vy swapped must not pass.
    assert not agrees(run.t, run.x, run.vy)
    assert not agrees(run.t, run.y, run.vx)
    # Nor ω of the neighbouring block.
    assert not agrees(run.t, run.theta, np.roll(run.omega, 1, axis=1), wrap=True)
