"""One conversion of keywords: every message names the key;
ValueError for a value, TypeError only for an object that is no value at
all; keywords that set one key twice are refused; samples are kept as
asked; sizes are refused before anything is allocated."""

import math
import random
import time

import numpy as np
import pytest

import jacobs_ladder as jl

MOVIE = jl.Scene.builtin("4", kind="movie")


@pytest.mark.parametrize(
    "call, key",
    [
        (lambda: jl.simulate(gamma=float("nan")), "gamma"),
        (lambda: jl.simulate(alpha=math.inf), "alpha"),
        (lambda: jl.simulate(flips=[0, float("nan")]), "flips.1"),
        (lambda: jl.simulate(sample_every="10"), "sample_every"),
        (lambda: jl.simulate(samples=[[1, 2]]), "samples"),
        (lambda: jl.simulate(samples=[3000, 1000, 3000]), "samples"),
        (lambda: jl.simulate(samples=[1000, 1000]), "samples"),
        (lambda: jl.theory(n=10.7), "n"),
        (lambda: jl.theory(n=-1), "n"),
        (lambda: jl.theory(n=2**70), "n"),
        (lambda: jl.sweep(alpha=[60], max_runs=-1), "max_runs"),
        (lambda: jl.sweep(alpha=[60], max_runs=2**70), "max_runs"),
        (lambda: jl.sweep(alpha=[60], max_runs=math.inf), "max_runs"),
        (lambda: jl.Scene.builtin("3").simulate(index=-1), "index"),
        (lambda: MOVIE.render(frames=-1), "frames"),
        (lambda: MOVIE.render(frames=2**70), "frames"),
        (lambda: MOVIE.render(size=(2**40, 2)), "size"),
        (lambda: MOVIE.render(format=["gif", 5]), "format"),
        (lambda: MOVIE.render(format="gif,,mp4"), "format"),
        (lambda: jl.Scene(model=[70, 20]), "model"),
        (lambda: jl.Scene.builtin("2d").save(""), "dir"),
        (lambda: jl.simulate(run={"t_end": 100}, **{"run.t_end": 200}), "run.t_end"),
        (lambda: jl.simulate(t_end=100, run={"t_end": 100}), "run.t_end"),
        (lambda: jl.simulate(alpha=70, model={"alpha": 60}), "model.alpha"),
    ],
)
def test_a_bad_value_is_a_value_error_naming_its_key(call, key):
    with pytest.raises(ValueError) as err:
        call()
    assert str(err.value).startswith(key + ":"), str(err.value)


def test_none_is_the_engines_default():
    # The defaults live in Rust (the model's, the sweep's cap): None, or
    # the keyword left out, is the same call as the default's value.
    assert jl.theory(alpha=None, n=None, b=None) == jl.theory(alpha=60, n=10, b=1.3)
    assert jl.theory() == jl.theory(alpha=60, n=10, b=1.3)
    with pytest.raises(ValueError, match="raise the cap with max_runs=2"):
        jl.sweep(alpha=[60, 70], max_runs=1)
    # The default cap (10^5) takes a two-run grid, as max_runs=None does.
    assert len(jl.sweep(alpha=[60, 70], n=6, max_runs=None)) == 2


def test_an_object_that_is_no_value_is_a_type_error_naming_its_key():
    with pytest.raises(TypeError, match="^alpha: "):
        jl.simulate(alpha=object())
    with pytest.raises(TypeError, match="^model: "):
        jl.simulate(model={1: 2})


def test_nested_and_dotted_keys_mean_the_same():
    nested = jl.simulate(run={"t_end": 100}, samples=[])
    dotted = jl.simulate(**{"run.t_end": 100}, samples=[])
    flag = jl.simulate(t_end=100, samples=[])
    assert nested.record["t_end"] == dotted.record["t_end"] == flag.record["t_end"] == 100
    # A dotted key changes the table another keyword gives, whatever the order.
    s = jl.Scene(run={"integrator": "verlet"}, **{"run.dt": 0.05})
    assert (s.to_dict()["run"]["integrator"], s.to_dict()["run"]["dt"]) == ("verlet", 0.05)


def test_samples_are_kept_as_asked():
    run = jl.simulate(t_end=1000, samples=[100, 250.5, 900])
    assert list(run.t) == [100, 250.5, 900]
    arr = jl.simulate(t_end=1000, samples=np.array([0.0, 500.0]))
    assert list(arr.t) == [0, 500]


def test_sizes_are_refused_before_allocation():
    # 10^8 sample times, no memory behind them: refused by their count.
    huge = np.broadcast_to(np.float64(1.0), (10**8,))
    start = time.perf_counter()
    with pytest.raises(ValueError, match="^samples: .*block-samples"):
        jl.simulate(samples=huge)
    assert time.perf_counter() - start < 2


def test_style_by_name_and_auto_runs_repr():
    pdf = jl.Scene.builtin("3").render(format="pdf", style="paper")
    assert bytes(pdf[:5]) == b"%PDF-"
    run = jl.simulate(t_end="auto", n=6)
    assert "t = 0.." in repr(run)


def test_html_escapes_the_name():
    html = jl.Image(b"x", '"><script>.png')._repr_html_()
    assert "<script>" not in html and "&lt;script&gt;" in html


# --------------------------------------------------- random keyword sets

GOOD = {
    "alpha": [55, -60, 70.5],
    "n": [4, 6, 8],
    "b": [1.2, 1.3],
    "gamma": [0.02, 0.05],
    "gravity": [0, 2e-4],
    "inertia": [0.25],
    "drive_time": [500, 1000],
    "flips": [[0], [0, 800]],
    "t_end": [300, 800],
    "integrator": ["auto", "verlet", "rk4"],
    "dt": [0.05, 0.1],
    "tolerance": [0.1],
    "sample_every": [50, 100],
    "samples": [[0, 100], []],
    "run.t_end": [400],
    "model": [{"n": 5}],
}
BAD = [
    float("nan"), math.inf, -1, 0, 2**70, 10.7, "x", "", None, [], [1, "a"], [[1]],
    {"a": 1}, True, -1e300, 1e300, object(), b"bytes",
]


def test_random_keyword_sets_return_or_name_the_key():
    """Every call returns a run or raises ValueError/TypeError naming one
    of the keys given (or its scene path), each within a time bound."""
    rng = random.Random(32)
    keys = list(GOOD)
    calls = 0
    for _ in range(300):
        chosen = rng.sample(keys, rng.randint(1, 4))
        kw = {}
        for k in chosen:
            kw[k] = rng.choice(BAD) if rng.random() < 0.35 else rng.choice(GOOD[k])
        kw.setdefault("t_end", 300)
        if "run.t_end" in kw or "model" in kw:
            kw.pop("t_end", None) if "run.t_end" in kw else None
        start = time.perf_counter()
        try:
            run = jl.simulate(**kw)
            assert isinstance(run, jl.Run)
        except (ValueError, TypeError) as e:
            text = str(e)
            names = set(kw) | {p for k in kw for p in (f"model.{k}", f"run.{k}", f"drive.{k}")}
            head = text.split(":", 1)[0]
            assert any(head == k or head.startswith(k + ".") or k in head for k in names) or any(
                k in text for k in kw
            ), f"{kw!r}: {text}"
        except jl.RunError:
            pass  # a run that failed is an outcome, with its hint
        elapsed = time.perf_counter() - start
        assert elapsed < 30, f"{kw!r} took {elapsed:.1f} s"
        calls += 1
    assert calls == 300


@pytest.mark.parametrize("key, value", [("alpha", 70.0), ("n", 8), ("t_end", 1.0), ("drive_time", 300.0), ("model.b", 1.5)])
def test_a_ring_scene_refuses_the_ladders_keywords(key, value):
    """Before: a ring chain took them and ran the same chain (docs/rings.md)."""
    rings = jl.Scene.builtin("12")
    with pytest.raises(ValueError, match=f"^{key}: the ring chain has no ladder"):
        rings.replace(**{key: value})
    # Its own keys still work.
    assert rings.replace(**{"rings.t_end": 1.0}).to_dict()["rings"]["t_end"] == 1.0


@pytest.mark.parametrize("key, value", [("t_end", 100.0), ("integrator", "rk4"), ("drive_time", 5.0), ("run.dt", 0.1)])
def test_a_figure_that_runs_no_simulation_refuses_run_keywords(key, value):
    """Before: figure 2b took them and drew the same figure."""
    drawing = jl.Scene.builtin("2b")
    with pytest.raises(ValueError, match=f"^{key}: this figure is a drawing and runs no simulation"):
        drawing.replace(**{key: value})
    assert drawing.replace(alpha=70.0).to_dict()["model"]["alpha"] == 70.0
