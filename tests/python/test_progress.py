"""Python at scale (docs/python.md, "Progress"): a progress callback on
`sweep`, `simulate` and `Scene.save`, and a bar where someone sees it; a
callback that raises stops the call."""

import pytest

import jacobs_ladder as jl
from jacobs_ladder import _progress
from conftest import needed

GRID = dict(alpha="40:70:5", gamma=[0.01, 0.02], n=8)


def recorder():
    calls = []
    return calls, lambda done, total: calls.append((done, total))


def test_a_sweep_reports_its_runs():
    calls, cb = recorder()
    table = jl.sweep(**GRID, progress=cb)
    assert calls, "no progress reported"
    assert calls[-1] == (len(table), len(table))
    done = [d for d, _ in calls]
    assert done == sorted(done) and all(isinstance(d, int) for d in done)
    assert {t for _, t in calls} == {14}


def test_an_executor_sweep_reports_each_chunk():
    from test_executors import Inline

    calls, cb = recorder()
    jl.sweep(**GRID, executor=Inline(), chunks=3, progress=cb)
    # Before any chunk, then after each: 5 + 5 + 4 runs.
    assert calls == [(0, 14), (5, 14), (10, 14), (14, 14)]


def test_simulate_reports_simulated_time():
    calls, cb = recorder()
    run = jl.simulate(n=8, t_end=3000, integrator="rk4", dt=0.05, progress=cb)
    assert calls[-1][1] == 3000.0
    assert calls[-1][0] == pytest.approx(run.t[-1], abs=5.0)
    times = [t for t, _ in calls]
    assert times == sorted(times)


def test_save_reports_a_movies_frames(tmp_path):
    calls, cb = recorder()
    movie = jl.Scene.builtin("4", kind="movie").replace(n=6, t_end=1500, name="m")
    movie.save(tmp_path, format="gif", frames=12, size=(64, 64), progress=cb)
    assert calls[-1] == (12, 12)


def test_a_callback_that_raises_stops_the_call():
    class Enough(Exception):
        pass

    def stop(done, total):
        raise Enough(f"{done} of {total}")

    with pytest.raises(Enough):
        jl.simulate(n=8, t_end=20000, integrator="rk4", dt=0.01, progress=stop)


def test_a_bad_progress_is_a_value_error():
    with pytest.raises(ValueError, match="^progress: "):
        jl.sweep(**GRID, progress="yes")


def test_no_bar_where_nobody_sees_it(capsys, monkeypatch):
    monkeypatch.setattr(_progress, "BAR_DELAY", 0.0)
    jl.sweep(**GRID)  # pytest's stderr is no terminal
    assert capsys.readouterr().err == ""


def test_a_bar_with_tqdm_and_without(capsys, monkeypatch):
    monkeypatch.setattr(_progress, "BAR_DELAY", 0.0)
    needed("tqdm")
    jl.sweep(**GRID, progress=True)
    err = capsys.readouterr().err
    assert "sweep" in err and "14/14" in err
    # Without tqdm: one line on stderr.
    monkeypatch.setattr(_progress, "_tqdm", lambda *a: None)
    jl.sweep(**GRID, progress=True)
    err = capsys.readouterr().err
    assert "sweep: 14/14 runs (100%)" in err and err.endswith("\n")


def test_a_terminal_gets_a_bar(capsys, monkeypatch):
    monkeypatch.setattr(_progress, "BAR_DELAY", 0.0)
    monkeypatch.setattr(_progress, "shown", lambda: True)
    monkeypatch.setattr(_progress, "_tqdm", lambda *a: None)
    jl.sweep(**GRID)
    assert "sweep: 14/14 runs" in capsys.readouterr().err
