"""Executor sweeps asked only for what the docs ask (docs/cluster.md):
`submit(fn, *args)` and a future's `result()`. A chunk's error reaches the
user as that chunk's own error with its grid points; a worker that
returns something else than the chunk is named by its chunk; a broken
pool reports which chunks were lost and the sweep resumes from the rest;
a cached earlier sweep's chunk, or an edited one, is refused."""

import json
import pickle
from concurrent.futures.process import BrokenProcessPool

import pytest

import jacobs_ladder as jl
from jacobs_ladder._sweep import _sweep_chunk

# 7 × 2 runs of N = 8: under a second on one core.
GRID = dict(alpha="40:70:5", gamma=[0.01, 0.02], n=8, name="ex")


class Bare:
    """A future with `result()` and nothing else (no cancel, no done)."""

    def __init__(self, call):
        self._call = call

    def result(self, timeout=None):
        return self._call()


class Inline:
    """An executor that runs each chunk when its result is asked for;
    `returns(k, shard)` may replace what chunk k gives back, `fails` maps a
    chunk to the exception its future raises."""

    def __init__(self, fails=None, returns=None):
        self.fails = fails or {}
        self.returns = returns or (lambda k, shard: shard)
        self.sent = []

    def submit(self, fn, *args):
        k = args[2]
        self.sent.append(k)

        def call():
            if k in self.fails:
                raise self.fails[k]
            return self.returns(k, fn(*args))

        return Bare(call)


@pytest.fixture(scope="module")
def local_table():
    return jl.sweep(**GRID)


def same(a, b):
    return a.csv == b.csv and a.json_text == b.json_text


def test_futures_with_only_result_give_the_local_table(local_table):
    assert same(jl.sweep(**GRID, executor=Inline(), chunks=3), local_table)


def test_a_chunks_run_error_is_its_own_error_with_its_points():
    """Before: the sweep called `cancel()` on the other futures, and a
    future without it turned the chunk's RunError into AttributeError."""
    with pytest.raises(jl.RunError) as err:
        jl.sweep(**GRID, executor=Inline(fails={2: jl.RunError("chunk 2 failed")}), chunks=3)
    e = err.value
    assert isinstance(e, jl.ChunkError)
    assert "chunk 2 failed" in str(e) and "chunk 2 (" in str(e)
    assert isinstance(e.__cause__, jl.RunError) and str(e.__cause__) == "chunk 2 failed"
    # Its points: runs 1, 4, 7, 10, 13 of 14 (round robin over 3 chunks).
    runs = [run for run, _ in e.points[2]]
    assert runs == [1, 4, 7, 10, 13]
    assert e.points[2][0][1] == {"alpha": 40.0, "n": 8.0, "gamma": 0.02}
    assert "run 1: alpha=40, n=8, gamma=0.02" in str(e)
    assert list(e.lost) == [2] and sorted(e.done) == [1, 3]


def test_a_worker_returning_none_is_named_by_its_chunk():
    """Before: "argument 'chunks': 'NoneType' object cannot be cast as
    'bytes'", though the user's `chunks=` was an integer."""
    ex = Inline(returns=lambda k, shard: None if k == 2 else shard)
    with pytest.raises(jl.ChunkError) as err:
        jl.sweep(**GRID, executor=ex, chunks=3)
    text = str(err.value)
    assert "chunk 2 of 3" in text and "returned None" in text
    assert "argument" not in text and "cast" not in text


def test_a_broken_pool_reports_the_lost_chunks_and_the_sweep_resumes(local_table):
    broken = Inline(fails={k: BrokenProcessPool("a worker died") for k in (2, 3)})
    with pytest.raises(jl.ChunkError) as err:
        jl.sweep(**GRID, executor=broken, chunks=4)
    e = err.value
    assert sorted(e.lost) == [2, 3] and sorted(e.done) == [1, 4]
    assert "2 of 4 chunks" in str(e) and "BrokenProcessPool" in str(e)
    assert isinstance(e.lost[2], BrokenProcessPool)
    # It pickles (a notebook may keep it), and resumes: only the lost
    # chunks run again, and the table is the local one byte for byte.
    e = pickle.loads(pickle.dumps(e))
    again = Inline()
    table = e.resume(again)
    assert sorted(again.sent) == [2, 3]
    assert same(table, local_table)


def test_a_pool_that_refuses_new_work_loses_those_chunks():
    class Refusing(Inline):
        def submit(self, fn, *args):
            if args[2] > 1:
                raise BrokenProcessPool("the pool is broken")
            return super().submit(fn, *args)

    with pytest.raises(jl.ChunkError) as err:
        jl.sweep(**GRID, executor=Refusing(), chunks=3)
    assert sorted(err.value.lost) == [2, 3] and sorted(err.value.done) == [1]


def test_a_cached_earlier_sweeps_chunks_are_refused():
    """Before: an executor returning an earlier sweep's chunks gave that
    sweep's table back, without an error."""
    earlier = {}
    keep = Inline(returns=lambda k, shard: earlier.setdefault(k, shard))
    jl.sweep(alpha="40:70:5", gamma=[0.01, 0.02], n=8, name="ex", executor=keep, chunks=2)
    cached = Inline(returns=lambda k, shard: earlier[k])
    with pytest.raises(jl.ChunkError, match="another sweep") as err:
        jl.sweep(alpha="45:75:5", gamma=[0.01, 0.02], n=8, name="ex", executor=cached, chunks=2)
    assert sorted(err.value.lost) == [1, 2]


def one_chunk():
    plan = jl._native._Sweep(None, dict(GRID), None, None, True, 2)
    return json.loads(_sweep_chunk(plan.scene, plan.max_runs, 1, 2))


def edited(change):
    """An executor whose chunk 1 comes back edited by `change`."""

    def returns(k, shard):
        if k != 1:
            return shard
        data = json.loads(shard)
        change(data)
        return json.dumps(data).encode()

    return Inline(returns=returns)


def set_version(d):
    d["version"] = "0.0.9"


def set_fingerprint(d):
    d["fingerprint"] = "0123456789abcdef"


def drop_a_run(d):
    d["records"].pop()


@pytest.mark.parametrize(
    "change, words",
    [
        (set_version, "made by ladder 0.0.9"),
        (set_fingerprint, "another sweep"),
        (drop_a_run, "of its"),
    ],
)
def test_a_chunk_edited_in_its_header_is_refused(change, words):
    with pytest.raises(jl.ChunkError, match=words) as err:
        jl.sweep(**GRID, executor=edited(change), chunks=2)
    assert list(err.value.lost) == [1]


def propagated(d):
    """The first record of a chunk whose wave propagated."""
    return next(r for r in d["records"] if r["outcome"] == "propagated")


def say_pinned(d):
    propagated(d)["outcome"] = "pinned"


def say_two_flipped(d):
    propagated(d)["blocks_flipped"] = 2


def say_speed_99(d):
    propagated(d)["speed"] = 99.0


def say_decided_late(d):
    propagated(d)["t_decided"] = 1e300


# The records' checks against their own arrivals and the outcome rules are
# the shard format's (`ShardFile::validate`), being added beside this work:
# until they land these are expected to fail, and strict, so that a pass
# is noticed and the mark removed.
@pytest.mark.xfail(strict=True, reason="the shard format's record checks are not in yet")
@pytest.mark.parametrize("change", [say_pinned, say_two_flipped, say_speed_99, say_decided_late])
def test_a_chunk_with_an_edited_record_is_refused(change):
    """Each record is checked against its own arrival times and the
    outcome rules (the shard format's checks), here as in `sweep gather`."""
    first = propagated(one_chunk())
    assert first["blocks_flipped"] == 7 and first["speed"] < 1
    with pytest.raises(jl.ChunkError, match="chunk 1 of 2") as err:
        jl.sweep(**GRID, executor=edited(change), chunks=2)
    assert list(err.value.lost) == [1]


def test_default_chunks_show_progress():
    """A sweep of 2040 runs is cut into 32 chunks (was 4: dask showed
    "processing: 4" from start to end); a small one into a chunk a run,
    up to 16."""

    class Nothing:
        def submit(self, fn, *args):
            raise BrokenProcessPool("nothing runs here")

    with pytest.raises(jl.ChunkError) as err:
        jl.sweep(alpha="40:89.5:0.5", gamma="0.001:0.02:0.001", n=8, executor=Nothing())
    assert len(err.value.lost) == 32
    with pytest.raises(jl.ChunkError) as err:
        jl.sweep(**GRID, executor=Nothing())
    assert len(err.value.lost) == 14
