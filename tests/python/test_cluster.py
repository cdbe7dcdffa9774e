"""From a notebook to a cluster (docs/python.md): a process forked after
the engine ran still works; scenes, runs, tables, images and exceptions
pickle; `sweep(..., executor=EX)` gives, byte for byte, the local sweep's
table through a process pool, dask.distributed and submitit."""

import copy
import multiprocessing as mp
import os
import pickle
import signal
import sys
import time
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pytest

import jacobs_ladder as jl
from conftest import needed

# A small sweep: 7 × 2 runs of N = 8, under a second on one core.
GRID = dict(alpha="40:70:5", gamma=[0.01, 0.02], n=8, name="ex")


# ----------------------------------------------------------------- fork


def wait_child(pid, seconds):
    """The child's exit status, or None after `seconds` (the child killed)."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        done, status = os.waitpid(pid, os.WNOHANG)
        if done:
            return status
        time.sleep(0.02)
    os.kill(pid, signal.SIGKILL)
    os.waitpid(pid, 0)
    return None


@pytest.mark.skipif(not hasattr(os, "fork"), reason="no os.fork on this platform")
@pytest.mark.parametrize("call", ["simulate", "sweep", "render"])
def test_a_child_forked_after_a_run_still_works(call):
    """The engine's threads do not cross a fork: the child builds its own
    pool. Before, the child's call waited forever for the parent's pool."""
    work = {
        "simulate": lambda: jl.simulate(n=8, t_end=1500, sample_every=100),
        "sweep": lambda: jl.sweep(alpha=[55, 65], n=6),
        "render": lambda: jl.Scene.builtin("2d").render(),
    }[call]
    work()  # the parent's pool is made and busy once
    pid = os.fork()
    if pid == 0:  # the child: the same call, exit 0 when it returns
        code = 1
        try:
            work()
            code = 0
        finally:
            os._exit(code)
    status = wait_child(pid, 60)
    assert status is not None, f"the forked child's {call} hung (killed after 60 s)"
    assert os.waitstatus_to_exitcode(status) == 0
    work()  # the parent's pool still works too


def simulate_in_worker(alpha):
    run = jl.simulate(alpha=alpha, n=6, t_end=1500, sample_every=500)
    return alpha, run.speed


@pytest.mark.skipif("fork" not in mp.get_all_start_methods(), reason="no fork start method")
def test_a_fork_pool_after_a_run_returns():
    jl.simulate(n=6, t_end=1500)
    ctx = mp.get_context("fork")
    with ctx.Pool(2) as pool:
        result = pool.map_async(simulate_in_worker, [55, 60, 65])
        got = result.get(timeout=120)
    assert [a for a, _ in got] == [55, 60, 65]
    assert all(s > 0 for _, s in got)


# -------------------------------------------------------------- pickling


def test_scenes_pickle_and_deep_copy():
    for scene in (
        jl.Scene.builtin("3"),
        jl.Scene.builtin("4", kind="movie").replace(alpha=70, n=12, name="k70"),
        jl.Scene(**{"run.tolerance": 0.05}),
    ):
        back = pickle.loads(pickle.dumps(scene))
        assert back == scene and back.to_toml() == scene.to_toml()
        deep = copy.deepcopy(scene)
        assert deep == scene and deep is not scene
        assert copy.copy(scene) == scene


def test_runs_tables_images_and_files_pickle():
    run = jl.simulate(n=6, t_end=1500, sample_every=100)
    back = pickle.loads(pickle.dumps(run))
    for name in ("t", "theta", "x", "y", "vx", "vy", "omega", "arrival_times"):
        assert np.array_equal(getattr(back, name), getattr(run, name), equal_nan=True), name
    assert back.record == run.record and repr(back) == repr(run)
    scene_run = jl.Scene.builtin("4", kind="movie").replace(n=6, t_end=1500).simulate()
    assert pickle.loads(pickle.dumps(scene_run)).scene == scene_run.scene

    table = jl.sweep(alpha=[55, 65], n=6)
    t2 = pickle.loads(pickle.dumps(table))
    assert t2.csv == table.csv and t2.json == table.json and list(t2) == list(table)
    assert all(t2[k].dtype == table[k].dtype and t2[k].tobytes() == table[k].tobytes() for k in table)

    image = jl.Scene.builtin("2d").render()
    i2 = pickle.loads(pickle.dumps(image))
    assert isinstance(i2, jl.Image) and i2 == image and i2.name == image.name
    files = jl.Files({"a.png": jl.Image(b"x", "a.png")})
    f2 = pickle.loads(pickle.dumps(files))
    assert isinstance(f2, jl.Files) and f2["a.png"].name == "a.png"


def test_every_exception_pickles_as_itself():
    errors = []
    for call in (
        lambda: jl.simulate(alpha=120),
        lambda: jl.simulate(integrator="symplectic-euler", dt=3.0, t_end=500),
        lambda: jl.Scene.builtin("no-such-figure"),
    ):
        with pytest.raises(Exception) as err:
            call()
        errors.append(err.value)
    errors.append(jl.InternalError("a bug"))
    for e in errors:
        assert type(e).__module__ in ("builtins", "jacobs_ladder"), type(e)
        back = pickle.loads(pickle.dumps(e))
        assert type(back) is type(e) and str(back) == str(e)
    assert jl.RunError.__module__ == "jacobs_ladder"


def failing_run(dt):
    return float(jl.simulate(integrator="symplectic-euler", dt=dt, t_end=500).t[-1])


def test_a_pool_worker_that_raises_run_error_reaches_the_parent_as_run_error():
    with ProcessPoolExecutor(1, mp_context=mp.get_context("spawn")) as pool:
        ok = pool.submit(failing_run, 0.05)
        bad = pool.submit(failing_run, 3.0)
        assert ok.result(timeout=120) == 500
        with pytest.raises(jl.RunError, match="diverged"):
            bad.result(timeout=120)


# ------------------------------------------------------ executor sweeps


def same_table(mine, local):
    """Byte for byte: the CSV and the JSON text."""
    assert mine.csv == local.csv
    assert mine.json_text == local.json_text
    return True


@pytest.fixture(scope="module")
def local_table():
    return jl.sweep(**GRID)


def test_a_process_pool_sweep_is_the_local_sweep_byte_for_byte(local_table):
    with ProcessPoolExecutor(2, mp_context=mp.get_context("spawn")) as pool:
        for chunks in (None, 1, 3, len(local_table)):
            assert same_table(jl.sweep(**GRID, executor=pool, chunks=chunks), local_table)


def test_executor_sweeps_refuse_bad_chunks(local_table):
    with ProcessPoolExecutor(1, mp_context=mp.get_context("spawn")) as pool:
        for bad in (0, len(local_table) + 1):
            with pytest.raises(ValueError, match="^chunks: "):
                jl.sweep(**GRID, executor=pool, chunks=bad)
    with pytest.raises(ValueError, match="^chunks: "):
        jl.sweep(**GRID, chunks=3)


def test_an_executor_sweep_with_a_failing_chunk_raises(local_table):
    """A chunk that fails in its worker surfaces as its exception; the
    other chunks are cancelled."""

    class Broken:
        def submit(self, fn, *args):
            from concurrent.futures import Future

            f = Future()
            if args[2] == 2:  # chunk 2 of 3
                f.set_exception(jl.RunError("chunk 2 failed"))
            else:
                f.set_result(fn(*args))
            return f

    with pytest.raises(jl.RunError, match="chunk 2 failed"):
        jl.sweep(**GRID, executor=Broken(), chunks=3)


def test_a_dask_local_cluster_sweep_is_the_local_sweep(local_table):
    needed("dask")
    distributed = needed("distributed")
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as client:
        assert same_table(jl.sweep(**GRID, executor=client.get_executor(), chunks=4), local_table)


def test_a_submitit_local_sweep_is_the_local_sweep(local_table, tmp_path):
    submitit = needed("submitit")
    executor = submitit.AutoExecutor(folder=tmp_path / "submitit", cluster="local")
    executor.update_parameters(timeout_min=5)
    assert same_table(jl.sweep(**GRID, executor=executor, chunks=2), local_table)
