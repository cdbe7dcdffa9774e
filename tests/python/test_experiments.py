"""The experiments' apparatus from Python (docs/experiments.md,
docs/experiments.md): the `[apparatus]` keys of a scene file reach
``Scene(apparatus=...)`` and ``simulate(..., apparatus=...)``; the
conversion is made afresh after every keyword change (a stale one stayed
in ``Run.record``); a bad value is a ValueError naming its key."""

import math

import pytest

import jacobs_ladder as jl

# The tank's plates (5 cm, 3 mm, 1.2 g/cm³) in water of 1.0 g/cm³, buoyant.
TANK = {
    "s": 5.0,
    "b": 7.5,
    "thickness": 0.3,
    "density": 1.2,
    "medium": "water",
    "medium_density": 1.0,
    "stiffness": "stiff",
    "buoyancy": True,
    "drag": True,
    "motor": 0.4,
    "duration": 1.0,
}


def tau_s(b_cm=7.5):
    """τ = √(m/k) (s) for "stiff" links: k = m g*/(s G), G = 2e-4, g* = g/6."""
    m = 1.2 * 5.0 * 5.0 * 0.3
    g_star = (1.0 - 1.0 / 1.2) * 981.0
    k = m * g_star / (5.0 * 2e-4)
    return math.sqrt(m / k)


def conversion(record):
    """The conversion in a run's record."""
    return record["scene"]["apparatus"]["conversion"]


def scene_conversion(scene):
    """The conversion a scene carries."""
    return scene.to_dict()["apparatus"]["conversion"]


def test_simulate_takes_an_apparatus_and_records_its_conversion():
    run = jl.simulate(alpha=86, n=4, integrator="rk4", dt=0.125, apparatus=TANK)
    c = conversion(run.record)
    assert c["tau_s"] == pytest.approx(tau_s(), rel=1e-12)
    assert c["b"] == pytest.approx(7.5 / 5.0, rel=1e-15)
    assert c["cm_per_s"] == pytest.approx(7.5 / tau_s(), rel=1e-12)
    # duration (s) is the window in τ.
    assert run.record["scene"]["run"]["t_end"] == pytest.approx(1.0 / tau_s(), rel=1e-12)
    assert run.t[-1] <= 1.0 / tau_s() + 1e-9


def test_a_keyword_change_converts_the_apparatus_afresh():
    scene = jl.Scene(alpha=86, n=4, integrator="rk4", dt=0.125, apparatus=TANK)
    before = scene_conversion(scene)
    # b changes the pitch (cm/s per block/τ) and the model's b/s; the
    # conversion the scene carried must not survive into the record.
    wider = scene.replace(**{"apparatus.b": 9.0})
    after = scene_conversion(wider)
    assert after["b"] == pytest.approx(9.0 / 5.0, rel=1e-15)
    assert after["cm_per_s"] == pytest.approx(9.0 / tau_s(), rel=1e-12)
    assert before["b"] == pytest.approx(1.5, rel=1e-15)
    run = wider.simulate()
    assert conversion(run.record) == after
    # The motor's drive time follows α: 2|α| / (2π f) in τ.
    turned = scene.replace(alpha=80)
    t_d = 2 * math.radians(80) / (2 * math.pi * 0.4) / tau_s()
    assert scene_conversion(turned)["drive_time"] == pytest.approx(t_d, rel=1e-12)


def test_the_built_in_tank_takes_keywords():
    tank = jl.Scene.builtin("water-tank")
    assert scene_conversion(tank)["tau_s"] == pytest.approx(tau_s(), rel=1e-12)
    heavier = tank.replace(**{"apparatus.density": 1.5})
    c = scene_conversion(heavier)
    # m = 1.5 × 7.5 g/cm²·cm; "stiff" keeps G, so τ = √(s G / g*) changes
    # only through g* = (1 − 1/1.5) g.
    g_star = (1.0 - 1.0 / 1.5) * 981.0
    assert c["tau_s"] == pytest.approx(math.sqrt(5.0 * 2e-4 / g_star), rel=1e-12)


@pytest.mark.parametrize(
    "key, value, words",
    [
        ("apparatus.drag_coefficient", -1.0, "apparatus.drag_coefficient"),
        ("apparatus.density", 0.5, "apparatus.buoyancy"),
        ("apparatus.medium", "oil", "apparatus.medium"),
        ("apparatus.motor", 0.0, "apparatus.motor"),
    ],
)
def test_bad_apparatus_values_name_their_key(key, value, words):
    scene = jl.Scene(alpha=86, n=4, apparatus=TANK)
    with pytest.raises(ValueError, match=words.replace(".", r"\.")):
        scene.replace(**{key: value})


def test_an_apparatus_run_gives_seconds_and_cm_per_s_beside_the_models_units():
    """Before: speeds only in blocks/τ and times in τ, and no bulk fit."""
    run = jl.simulate(alpha=86, n=11, integrator="rk4", dt=0.125, apparatus=dict(TANK, duration=6.0))
    c = conversion(run.record)
    assert run.tau_s == c["tau_s"]
    assert list(run.t_s) == [t * c["tau_s"] for t in run.t]
    finite = [a for a in run.arrival_times if a == a]
    assert [a for a in run.arrival_times_s if a == a] == [a * c["tau_s"] for a in finite]
    assert run.speed_cm_s == run.speed * c["cm_per_s"]
    # The figures' fit over the lower half (blocks 6..10), as cm/s too.
    assert 0 < run.bulk_speed < 1
    assert run.bulk_speed_cm_s == pytest.approx(run.bulk_speed * c["cm_per_s"], rel=1e-12)
    assert run.record["units"]["speed_cm_s"] == run.speed_cm_s
    # The bulk fit is the figures' line (the data file's `apparatus.bulk`).
    fit = run.bulk_fit
    assert fit["blocks"] == [6, 10] and fit["speed_cm_s"] == run.bulk_speed_cm_s
    assert abs(run.bulk_speed_cm_s - run.speed_cm_s) < 0.2 * run.speed_cm_s
    assert run.record["apparatus"]["arrival_times_s"][0] == run.arrival_times_s[0]


def test_a_run_of_the_model_alone_has_no_apparatus_units():
    run = jl.simulate(n=10, t_end=4000)
    assert run.t_s is None and run.speed_cm_s is None and run.tau_s is None
    assert run.bulk_speed_cm_s is None and run.bulk_fit is None
    assert run.bulk_speed > 0  # the paper's kink runs steadily in the bulk


def test_t_end_replaces_the_apparatus_duration():
    """Before: the apparatus' duration, converted again, replaced t_end."""
    run = jl.simulate(alpha=86, n=4, integrator="rk4", dt=0.125, apparatus=TANK, t_end=50.0)
    assert run.record["t_end"] == 50.0
    assert run.record["scene"]["run"]["t_end"] == 50.0
    assert "duration" not in run.record["scene"]["apparatus"]
    assert run.t[-1] == pytest.approx(50.0, abs=1e-9)
    # A scene with the duration, then a window given by replace().
    scene = jl.Scene(alpha=86, n=4, integrator="rk4", dt=0.125, apparatus=TANK)
    assert scene.to_dict()["run"]["t_end"] == pytest.approx(1.0 / tau_s(), rel=1e-12)
    shorter = scene.replace(t_end=60.0)
    assert shorter.to_dict()["run"]["t_end"] == 60.0
    assert "duration" not in shorter.to_dict()["apparatus"]
    # An apparatus has no automatic window.
    with pytest.raises(ValueError, match='"auto" is not a window for an apparatus'):
        scene.replace(t_end="auto")


def test_drive_time_replaces_the_apparatus_motor():
    """Before: the motor's flip replaced the drive given."""
    run = jl.simulate(alpha=86, n=4, integrator="rk4", dt=0.125, apparatus=TANK, drive_time=300.0)
    assert run.record["drive"]["flips"][0]["duration"] == 300.0
    assert "motor" not in run.record["scene"]["apparatus"]
    # Without it the motor (0.4 Hz) sets the drive time: 2 × 86° at 0.4 Hz.
    run = jl.simulate(alpha=86, n=4, integrator="rk4", dt=0.125, apparatus=TANK)
    want = 2 * math.radians(86) / (2 * math.pi * 0.4) / tau_s()
    assert run.record["drive"]["flips"][0]["duration"] == pytest.approx(want, rel=1e-12)


@pytest.mark.parametrize("key", ["b", "gamma", "gravity", "inertia"])
def test_a_model_keyword_the_apparatus_sets_is_refused(key):
    """Before: the apparatus' value replaced the keyword without a word."""
    with pytest.raises(ValueError, match=f"^{key}: the apparatus sets"):
        jl.simulate(alpha=86, n=4, apparatus=TANK, **{key: 0.3})
