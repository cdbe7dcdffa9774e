"""jacobs_ladder: the Jacob's-ladder engine of ``ladder`` as a numpy package.

Simulate the toy of "Topological antiqued mechanical toy" (Wada, Mizobata,
Ueno, Yoneda) and render its figures and movies from Python, with the same
engine, numbers and files as the ``ladder`` command line::

    import jacobs_ladder as jl
    run = jl.simulate(alpha=60, n=10)          # the paper's kink
    run.arrival_times                          # τ, NaN where a block never flipped
    run.theta                                  # radians, samples × N
    jl.Scene.builtin("3").render()             # figure 3, shown inline in Jupyter
    jl.sweep(alpha=[-50, -55, -60], gamma=[0.01, 0.02]).to_pandas()
    jl.theory(alpha=60)["winding_number"]

Units: lengths in the block length s, times in τ = sqrt(m/k), angles in
degrees where a keyword takes them (``alpha``) and radians in arrays
(``theta``). Keyword names are the command line's long flags with
underscores (``--t-end`` → ``t_end``). A mistake in a keyword raises
ValueError with the command line's one-line message and the scene key
(``model.alpha: ...``); a failed run raises RunError with a hint. Every
call releases the GIL while the engine works, and Ctrl-C stops it.

The whole tour: docs/python.md.
"""

from __future__ import annotations

import json
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

from . import _native
from ._native import InternalError, RunError
from ._params import DEFAULTS, PARAMETERS, filled, parameter_line, parameter_lines
from ._progress import Reporting
from ._run import Run
from ._scene import Files, Image, Scene, _scene_from_json
from ._sweep import OUTCOMES, SWEEP_PARAMETERS, ChunkError, Table, _sweep_chunk, sweep

__all__ = [
    "simulate",
    "sweep",
    "theory",
    "catalogue",
    "Scene",
    "Run",
    "Table",
    "Image",
    "Files",
    "RunError",
    "ChunkError",
    "InternalError",
    "__version__",
]

# The public classes are the package's: their reprs and pickles name
# `jacobs_ladder`, not the module that defines them.
for _cls in (Run, Scene, Image, Files, Table, ChunkError):
    _cls.__module__ = __name__
del _cls

__version__ = "0.1.0"
#: The engine's version and git commit (``ladder --version``).
ENGINE_VERSION: str = _native.VERSION


def simulate(
    alpha: Optional[float] = None,
    n: Optional[int] = None,
    b: Optional[float] = None,
    gamma: Optional[float] = None,
    gravity: Optional[float] = None,
    inertia: Optional[float] = None,
    drive_time: Optional[float] = None,
    flips: Optional[Sequence[float]] = None,
    t_end: Union[float, str, None] = None,
    integrator: Optional[str] = None,
    *,
    dt: Optional[float] = None,
    rtol: Optional[float] = None,
    tolerance: Optional[float] = None,
    second_flip: Optional[float] = None,
    sample_every: Optional[float] = None,
    samples: Optional[Sequence[float]] = None,
    dissipation: bool = False,
    progress: Any = None,
    **scene_keys: Any,
) -> Run:
    """Simulate the ladder and return a :class:`Run` of numpy arrays.

    The keywords are ``ladder simulate``'s long flags with underscores;
    a keyword left out (None) keeps the engine's default, the paper's
    value. The parameters (``PARAMETERS``, the engine's table, whose
    words, ranges and defaults these are):

    {parameters}

    and the run's:

    - ``flips``: start times of the flips of block 1, τ. Default [0].
    - ``second_flip``: turn block 1 back from this time too (= flips [0, T]).
    - ``t_end``: end of the window, τ (or ``"auto"``). Default {t_end}.
    - ``integrator``: ``auto`` (picks the step and verifies the arrival
      times to ``tolerance``), ``explicit-euler``, ``symplectic-euler`` (the
      paper's), ``verlet``, ``rk4``, ``dopri5`` or ``moreau`` (inextensible
      ribbons only). Default {integrator}.
    - ``dt``: step of a named integrator, τ. Default {dt}.
    - ``rtol``: tolerance of dopri5. Default {rtol}.
    - ``tolerance``: largest arrival-time error auto accepts, τ. Default
      {tolerance}.
    - ``sample_every``: interval of the samples kept, τ. Default
      {sample_every} (as ``simulate --csv``); or ``samples``: the sample
      times themselves.
    - ``dissipation``: also record the energy dissipated so far at each
      sample (``Run.dissipated``; the steps are then taken one per call,
      a slower run with the same trajectory bit for bit). Default False:
      ``Run.dissipated`` then runs it again with them when first asked for.
    - ``progress``: None shows a bar (simulated τ) in a notebook or a
      terminal (tqdm's, where installed), True always, False never; a
      callable is called ``progress(t, t_end)`` as the run goes (t_end
      None while an ``auto`` window is not yet known).
    - any other scene key (``model``, ``drive``, ``run``, or a dotted path
      such as ``**{"run.tolerance": 0.05}``): see docs/scenes.md.

    Raises ValueError for bad input (the message names the key) and
    RunError for a run that failed (with a hint).
    """
    kw = dict(
        alpha=alpha, n=n, b=b, gamma=gamma, gravity=gravity, inertia=inertia,
        drive_time=drive_time, flips=flips, second_flip=second_flip, t_end=t_end,
        integrator=integrator, dt=dt, rtol=rtol, tolerance=tolerance,
    )
    kw.update(scene_keys)
    with Reporting(progress, "simulate", "τ") as report:
        return Run(_native.simulate(kw, sample_every, samples, bool(dissipation), report))


def theory(
    alpha: Optional[float] = None, n: Optional[int] = None, b: Optional[float] = None
) -> Dict[str, Any]:
    """The linear theory, as ``ladder theory --json`` prints it: ``a``,
    ``u_min`` and ``barrier`` (m g s), ``kappa``, ``winding_number``,
    ``gap_omega_plus_q0``, ``omega_max``, zero modes, ...

    {theory_parameters}
    """
    return json.loads(_native.theory(alpha, n, b))


def catalogue() -> List[Tuple[str, str, str]]:
    """The built-in scenes (``ladder list``): (ID, kind, title) tuples."""
    return _native.catalogue()


filled(simulate)
# The theory takes α = 0 and 90 (the gapless and the symmetric ladder) and
# chains up to its own largest.
filled(
    theory,
    theory_parameters=parameter_lines(
        [
            parameter_line("alpha", "|alpha| <= 90"),
            parameter_line("n", f"from 2 to {DEFAULTS['theory_max_n']}"),
            parameter_line("b"),
        ]
    ),
)


def __dir__() -> List[str]:
    """The public names only (``dir(jl)``, tab completion): not the
    helpers this module imports (typing, json, numpy)."""
    return sorted(set(__all__) | {"ENGINE_VERSION", "SWEEP_PARAMETERS", "OUTCOMES", "PARAMETERS"})
