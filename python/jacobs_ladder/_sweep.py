"""Sweeps (``jacobs_ladder.sweep``): a scene over a grid of parameters,
here or on an executor's workers, and its results as a :class:`Table`.

Everything a sweep decides comes from the engine: which keywords are grid
axes and in which order they vary (``SWEEP_PARAMETERS``), the checks, the
chunks and their checks, the columns and their types (``OUTCOMES`` lists
the outcomes). This module converts and hands over.
"""

from __future__ import annotations

import json
from typing import Any, Dict, List, Optional, Tuple

from . import _native
from ._lazy import np
from ._native import RunError
from ._progress import Reporting

#: The parameters a sweep varies (``ladder sweep``'s grid flags), in the
#: order the axes vary (the first slowest): the engine's.
SWEEP_PARAMETERS: Tuple[str, ...] = tuple(_native.SWEEP_PARAMETERS)

#: Every outcome a sweep's run can have (the ``outcome`` column): the
#: engine's.
OUTCOMES: Tuple[str, ...] = tuple(_native.OUTCOMES)

#: The provenance keys a table carries (``Table.provenance``).
_PROVENANCE = ("program", "version", "git_commit", "build")


class Table(dict):
    """A sweep's results: column name → numpy array, one row per run in
    grid order, the columns of the CSV ``ladder sweep`` writes, in its
    order: ``run``, the parameters (``SWEEP_PARAMETERS``), ``outcome``
    (one of ``OUTCOMES``), ``blocks_flipped``, ``front`` (≤ N − 1),
    ``speed`` (blocks/τ), ``t_decided`` (τ), ``block_n_turned_at`` (τ)
    and ``waves``, then, where a run had more than one wave,
    ``wave1_kind``, ``wave1_launched_at``, ``wave1_front``, ``wave1_fate``,
    ``wave1_fate_at``, ... The engine gives each column its type (whole
    numbers int64, numbers float64, names str) and its numbers at full
    precision (the CSV prints a speed to 6 digits): NaN where a number is
    empty, -1 where a whole number is, "" where a name is.

    ``csv`` is the CSV's text (the CLI's bytes), ``json`` the sweep's JSON
    (every run's arrival times) as a dict, ``provenance`` the program, its
    version, git commit and build, the scene (JSON) and the call that made
    the table; :meth:`to_csv` writes the CSV with it."""

    csv: str
    json: Dict[str, Any]
    json_text: str
    command: str

    def __init__(
        self,
        csv_text: str,
        json_text: str,
        columns: Optional[List[Tuple[str, Any]]] = None,
        command: str = "",
    ):
        if columns is None:
            columns = _native.table_columns(json_text)
        super().__init__(
            (name, values if hasattr(values, "dtype") else np.array(values, dtype=str))
            for name, values in columns
        )
        self.csv = csv_text
        self.json_text = json_text
        self.json = json.loads(json_text)
        self.command = command

    def __reduce__(self):
        # Made again from its text: the columns from the JSON, by the engine.
        return (Table, (self.csv, self.json_text, None, self.command))

    def __len__(self) -> int:  # rows, as a table's length
        return len(self["run"]) if "run" in self else 0

    @property
    def columns(self) -> List[str]:
        return list(self.keys())

    @property
    def provenance(self) -> Dict[str, str]:
        """Where the table comes from, as strings (netCDF attributes take
        them): ``program``, ``version``, ``git_commit`` (empty outside a
        clone), ``build``, ``scene`` (the sweep scene's JSON),
        ``fingerprint`` and ``command`` (the Python call)."""
        j = self.json
        out = {k: "" if j.get(k) is None else str(j[k]) for k in _PROVENANCE}
        out["scene"] = json.dumps(j.get("scene"), sort_keys=True)
        out["fingerprint"] = str(j.get("fingerprint", ""))
        out["command"] = self.command
        return out

    def to_csv(self, path: Any = None) -> str:
        """The CSV with its provenance first, as ``# key: value`` lines
        (``pandas.read_csv(path, comment="#")`` reads it); written to
        ``path`` when given. Returns the text."""
        lines = [f"# {k}: {v}" for k, v in self.provenance.items() if k != "scene"]
        lines.append(f"# scene: {json.dumps(self.json.get('scene'), sort_keys=True)}")
        text = "\n".join(line.replace("\n", " ") for line in lines) + "\n" + self.csv
        if path is not None:
            import os

            with open(os.fspath(path), "w", encoding="utf-8") as f:
                f.write(text)
        return text

    def to_pandas(self):
        """The table as a pandas DataFrame (needs pandas), its provenance
        in ``attrs``."""
        import pandas as pd

        df = pd.DataFrame({k: self[k] for k in self.keys()})
        df.attrs.update(self.provenance)
        return df

    def to_xarray(self):
        """The table as an ``xarray.Dataset`` (needs xarray) with the grid's
        axes as dimensions, in the sweep's order (the first varies
        slowest), each with its values as coordinate; every other column a
        variable over them (``outcome[alpha, gamma]``); the provenance in
        ``attrs`` (so a netCDF file written from it carries it)."""
        import xarray as xr

        axes = [(a["param"], np.asarray(a["values"])) for a in self.json["axes"]]
        dims = [name for name, _ in axes]
        shape = tuple(len(values) for _, values in axes)
        data = {k: (dims, np.asarray(v).reshape(shape)) for k, v in self.items() if k not in dims}
        return xr.Dataset(
            data, coords={name: values for name, values in axes}, attrs=self.provenance
        )

    def __repr__(self) -> str:
        outcomes, counts = np.unique(self["outcome"], return_counts=True)
        summary = ", ".join(f"{c} {o}" for o, c in zip(outcomes, counts))
        return f"<Table of {len(self)} runs ({summary}); columns {', '.join(self.keys())}>"


class ChunkError(RunError):
    """Chunks of an executor's sweep that did not come back: each lost
    chunk's own error (``lost``: chunk → exception; the first is this
    exception's ``__cause__``) and its grid points (``points``: chunk →
    [(run, {parameter: value})]). The chunks that came back are kept
    (``done``), checked: :meth:`resume` runs the lost ones again, on the
    same executor or another, and returns the table."""

    def __init__(
        self,
        message: str,
        lost: Dict[int, BaseException],
        points: Dict[int, List[Tuple[int, Dict[str, float]]]],
        done: Dict[int, bytes],
        state: Tuple[str, int, int, str],
    ):
        super().__init__(message)
        self.lost = lost
        self.points = points
        self.done = done
        self._state = state

    def __reduce__(self):
        return (ChunkError, (str(self), self.lost, self.points, self.done, self._state))

    def resume(self, executor: Any, *, progress: Any = None) -> "Table":
        """Runs the lost chunks on ``executor`` and gathers the sweep with
        the chunks kept; raises a ChunkError again if some are lost again."""
        scene, max_runs, chunks, command = self._state
        plan = _native._Sweep.from_json(scene, max_runs, chunks)
        return _on_executor(plan, executor, progress, dict(self.done), command)


def _points_text(points: List[Tuple[int, Dict[str, float]]], most: int = 3) -> str:
    shown = "; ".join(
        f"run {run}: " + ", ".join(f"{k}={v:g}" for k, v in at.items()) for run, at in points[:most]
    )
    more = len(points) - most
    return shown + (f"; and {more} more" if more > 0 else "")


def _lost_error(plan: Any, lost: Dict[int, BaseException], done: Dict[int, bytes], command: str):
    points = {k: plan.chunk_points(k) for k in sorted(lost)}
    runs = sum(plan.chunk_runs(k) for k in lost)
    parts = [
        f"chunk {k} ({_points_text(points[k])}): {type(e).__name__}: {e}"
        for k, e in sorted(lost.items())
    ]
    message = (
        f"{len(lost)} of {plan.chunks} chunks of the sweep were lost ({runs} of {plan.runs} "
        f"runs): " + " | ".join(parts) + f"; the {len(done)} chunks that came back are kept: "
        "err.resume(executor) runs the lost ones again and returns the table"
    )
    state = (plan.scene, plan.max_runs, plan.chunks, command)
    return ChunkError(message, dict(sorted(lost.items())), points, done, state)


def _cancel(futures: List[Tuple[int, Any]]) -> None:
    """Cancels what can be (a future need not have ``cancel``)."""
    for _, f in futures:
        cancel = getattr(f, "cancel", None)
        if callable(cancel):
            try:
                cancel()
            except Exception:
                pass


def _on_executor(plan: Any, executor: Any, progress: Any, done: Dict[int, bytes], command: str):
    """The chunks of ``plan`` not in ``done`` run on ``executor``, each
    checked as it comes back (in order: a future needs only ``result()``);
    every chunk is waited for, then the lost ones are reported together,
    or the sweep gathered."""
    lost: Dict[int, BaseException] = {}
    futures: List[Tuple[int, Any]] = []
    args = (plan.scene, plan.max_runs)
    for k in range(1, plan.chunks + 1):
        if k in done:
            continue
        try:
            futures.append((k, executor.submit(_sweep_chunk, *args, k, plan.chunks)))
        except Exception as e:  # a broken pool refuses new work
            lost[k] = e
    runs = sum(plan.chunk_runs(k) for k in done)
    with Reporting(progress, "sweep", "runs") as report:
        if report is not None:
            report(runs, plan.runs)
        try:
            for k, future in futures:
                try:
                    returned = future.result()
                    plan.check_chunk(k, returned)
                except Exception as e:
                    lost[k] = e
                    continue
                done[k] = returned
                runs += plan.chunk_runs(k)
                if report is not None:
                    report(runs, plan.runs)
        except BaseException:  # Ctrl-C: the rest is not waited for
            _cancel(futures)
            raise
    if lost:
        first = lost[min(lost)]
        raise _lost_error(plan, lost, done, command) from first
    csv_text, json_text, columns = plan.gather(sorted(done.items()))
    return Table(csv_text, json_text, columns, command)


def _command(base: Any, given: Dict[str, Any]) -> str:
    """The call, as provenance: ``jacobs_ladder.sweep(alpha=[...], ...)``."""
    args = [] if base is None else [f"base=<Scene {base.name}>"]
    args += [f"{k}={v!r}" for k, v in given.items() if v is not None and k != "executor"]
    text = f"jacobs_ladder.sweep({', '.join(args)})"
    return text if len(text) <= 4000 else text[:3997] + "..."


def sweep(
    base: Optional[Any] = None,
    *,
    cap: Optional[float] = None,
    name: Optional[str] = None,
    max_runs: Optional[int] = None,
    executor: Any = None,
    chunks: Optional[int] = None,
    progress: Any = None,
    **keys: Any,
) -> Table:
    """Run a scene over a grid of parameters and decide what the wave did
    in each run, as ``ladder sweep`` does (same batch kernel, every core).

    - a grid keyword per varied parameter (``SWEEP_PARAMETERS``: ``alpha``,
      ``n``, ``b``, ``gamma``, ``gravity``, ``inertia``, ``drive_time``): a
      list of values, one value, or a range string ``"start:stop:step"``
      (inclusive), e.g. ``sweep(alpha=[-50, -55, -60], gamma="0.01:0.04:0.01")``.
      The axes vary in that order (the first slowest), whatever the order
      of the keywords, as ``ladder sweep``'s flags do.
    - ``base``: the scene swept (default: the paper's). Other keywords
      (``t_end``, ``integrator``, ``tolerance``, scene keys) change it.
    - ``cap``: latest time a run may reach undecided, τ (the engine's
      default, ``[output] cap`` of docs/sweeps.md). A run is called
      stopped only when its state is proved at rest; otherwise it runs on
      to the cap.
    - ``name``: the sweep's name (in its JSON). Default the base's.
    - ``max_runs``: refuse a larger grid (the engine's default cap).
    - ``executor``: run the sweep on other processes or machines: any
      ``concurrent.futures.Executor`` (a ``ProcessPoolExecutor``,
      dask.distributed's ``client.get_executor()``, submitit's
      ``AutoExecutor``, mpi4py's ``MPIPoolExecutor``), or anything with
      ``submit(fn, *args)`` returning a future with ``result()`` (nothing
      else is asked of it). The grid is cut into ``chunks`` (round robin,
      as ``ladder sweep --shard`` does); each chunk runs on a worker with
      that worker's threads (``RAYON_NUM_THREADS``; one worker per node)
      and comes back as its shard, checked against this sweep (its
      fingerprint and version: a cached chunk of an earlier sweep or an
      edited one is refused). The table is byte for byte the local one's.
      A chunk that fails, or does not come back, is reported with its own
      error and grid points in a :class:`ChunkError` (a ``RunError``)
      once every chunk is in; ``err.resume(executor)`` runs only the lost
      ones again. docs/cluster.md.
    - ``chunks``: how many pieces the grid is cut into for ``executor``.
      Default about 64 runs a chunk, at least 16 (so that progress shows).
    - ``progress``: None shows a bar in a notebook or a terminal (tqdm's,
      where installed), True always, False never; a callable is called
      ``progress(runs_done, runs)`` as runs (or chunks) finish.

    Returns a :class:`Table` with the columns of the CLI's
    ``sweep-NAME.csv``.
    """
    given = dict(keys, cap=cap, name=name, max_runs=max_runs, chunks=chunks)
    command = _command(base, given)
    if name is not None:
        keys["name"] = name
    native_base = None if base is None else base._s
    plan = _native._Sweep(native_base, keys, cap, max_runs, executor is not None, chunks)
    if executor is not None:
        return _on_executor(plan, executor, progress, {}, command)
    with Reporting(progress, "sweep", "runs") as report:
        csv_text, json_text, columns = plan.run(report)
    return Table(csv_text, json_text, columns, command)


def _sweep_chunk(scene: str, max_runs: int, k: int, chunks: int) -> bytes:
    """Chunk ``k`` of ``chunks`` of a sweep, run in an executor's worker:
    the bytes of its shard file."""
    return _native.sweep_chunk(scene, max_runs, k, chunks)
