"""A run carries its energies (docs/python.md): kinetic, elastic,
gravitational at each sample, and the energy dissipated so far when asked;
after the drive ends their sum is flat to the integrator's accuracy."""

import numpy as np

import jacobs_ladder as jl


def test_total_plus_dissipated_is_flat_after_the_drive():
    run = jl.simulate(integrator="verlet", dt=0.05, t_end=3000, drive_time=500,
                      sample_every=50, dissipation=True)
    for name in ("kinetic", "elastic", "gravitational", "dissipated"):
        a = getattr(run, name)
        assert a.shape == run.t.shape and np.isfinite(a).all(), name
    total = run.kinetic + run.elastic + run.gravitational + run.dissipated
    after = run.t >= 500
    dissipated = run.dissipated[-1] - run.dissipated[after][0]
    # The wave dissipates energy after the drive: the check is not empty.
    assert dissipated > 1e-4
    # Flat to well under a thousandth of what was dissipated meanwhile
    # (measured: 5.5e-10 against 1.9e-3).
    assert np.ptp(total[after]) < 1e-3 * dissipated, np.ptp(total[after])
    # During the drive, block 1's motor works on the ladder: not flat.
    assert np.ptp(total[~after]) > 100 * np.ptp(total[after])
    assert np.all(np.diff(run.dissipated) >= 0)


def test_dissipated_is_computed_when_asked_for_and_the_trajectory_is_the_same():
    """Before: NaN unless dissipation=True was passed."""
    plain = jl.simulate(integrator="verlet", dt=0.05, t_end=1500)
    asked = jl.simulate(integrator="verlet", dt=0.05, t_end=1500, dissipation=True)
    assert plain.theta.tobytes() == asked.theta.tobytes()
    assert plain.kinetic.tobytes() == asked.kinetic.tobytes()
    assert "dissipated" not in plain.to_dict()  # not made until asked for
    assert plain.dissipated.tobytes() == asked.dissipated.tobytes()
    assert np.isfinite(plain.dissipated).all() and plain.dissipated[-1] > 0
    # A scene's run (and an `auto` one) the same way.
    scene = jl.Scene.builtin("4", kind="movie").replace(n=6, t_end=1500)
    run = scene.simulate(sample_every=100)
    assert run.dissipated.tobytes() == scene.simulate(sample_every=100, dissipation=True).dissipated.tobytes()
