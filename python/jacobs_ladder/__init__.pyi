"""Type stubs of jacobs_ladder (docs/python.md). Units: lengths in the block
length s, times in τ = sqrt(m/k), α in degrees, arrays' angles in radians."""

import os
from pathlib import Path
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str
ENGINE_VERSION: str
SWEEP_PARAMETERS: Tuple[str, ...]
OUTCOMES: Tuple[str, ...]

class RunError(RuntimeError):
    """A run that failed (a diverging integrator, ...): message and hint."""

class ChunkError(RunError):
    """Chunks of an executor's sweep lost: each one's error and grid points;
    the chunks that came back kept for resume()."""

    lost: Dict[int, BaseException]
    points: Dict[int, List[Tuple[int, Dict[str, float]]]]
    done: Dict[int, bytes]
    def resume(self, executor: Any, *, progress: Any = None) -> Table: ...

class InternalError(RuntimeError):
    """A bug of jacobs_ladder (a caught panic of the engine)."""

FloatArray = npt.NDArray[np.float64]

class Run:
    """A simulated run; arrays per block are samples × N."""

    record: Dict[str, Any]
    scene: Optional[Scene]
    @property
    def t(self) -> FloatArray:
        """Sample times, τ."""
    @property
    def theta(self) -> FloatArray:
        """θ_n(t), radians, samples × N (not wrapped)."""
    @property
    def x(self) -> FloatArray:
        """X_n(t), block centres, s; X runs down the ladder, along gravity."""
    @property
    def y(self) -> FloatArray:
        """Y_n(t), block centres, s; Y runs across the ladder."""
    @property
    def kinetic(self) -> FloatArray:
        """Kinetic energy at each sample, k s²."""
    @property
    def elastic(self) -> FloatArray:
        """Elastic energy at each sample, k s²."""
    @property
    def gravitational(self) -> FloatArray:
        """−m G Σ X_n at each sample, k s²."""
    @property
    def dissipated(self) -> FloatArray:
        """Energy dissipated since t = 0, k s²; recorded with dissipation=True,
        else computed by a second run when first asked for."""
    @property
    def t_s(self) -> Optional[FloatArray]:
        """Sample times, s (an apparatus' run; else None)."""
    @property
    def arrival_times_s(self) -> Optional[FloatArray]:
        """Arrival times, s (an apparatus' run; else None)."""
    @property
    def tau_s(self) -> Optional[float]:
        """τ in s (an apparatus' run; else None)."""
    @property
    def vx(self) -> FloatArray:
        """dX_n/dt, s/τ."""
    @property
    def vy(self) -> FloatArray:
        """dY_n/dt, s/τ."""
    @property
    def omega(self) -> FloatArray:
        """dθ_n/dt, rad/τ."""
    @property
    def kink_position(self) -> FloatArray:
        """The wall's position at each sample, in blocks (fractional)."""
    @property
    def arrival_times(self) -> FloatArray:
        """Arrival time per block, τ; NaN where the block never flipped."""
    @property
    def final_theta_deg(self) -> FloatArray:
        """θ_n at t_end, degrees, wrapped to (−180, 180]."""
    @property
    def n(self) -> int: ...
    @property
    def integrator(self) -> Dict[str, Any]:
        """requested, name, dt, steps, force_evals; auto: tolerance, arrival_error (τ)."""
    @property
    def speed(self) -> float:
        """Wave speed, blocks/τ; NaN when too few blocks flipped."""
    @property
    def speed_cm_s(self) -> Optional[float]:
        """speed in cm/s (an apparatus' run; else None)."""
    @property
    def bulk_speed(self) -> float:
        """The experiment figures' fit over the lower half, blocks/τ; NaN if none."""
    @property
    def bulk_speed_cm_s(self) -> Optional[float]:
        """bulk_speed in cm/s (an apparatus' run; else None)."""
    @property
    def bulk_fit(self) -> Optional[Dict[str, Any]]:
        """The figures' fitted line: speed_cm_s, blocks, centroid_s, centroid_cm."""
    @property
    def waves(self) -> Optional[List[Dict[str, Any]]]:
        """One record per domain wall, where the engine reports them."""
    @property
    def block_n(self) -> Optional[Dict[str, Any]]:
        """The free bottom block's record beside the waves."""
    def to_dict(self) -> Dict[str, Any]: ...

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
    """Simulate the ladder. alpha: degrees (default 60); n: blocks (10); b: s
    (1.3); gamma (0.02); gravity G = mg/(ks) (2e-4); inertia: m s² (0.25);
    drive_time: τ (1000); flips: start times, τ ([0]); t_end: τ (4000);
    integrator: auto | explicit-euler | symplectic-euler | verlet | rk4 |
    dopri5 (auto); dt: τ (0.01); rtol (1e-6); tolerance: τ (0.1);
    sample_every: τ (10); progress: None (a bar where seen) | True | False |
    progress(t, t_end)."""

def theory(
    alpha: Optional[float] = None, n: Optional[int] = None, b: Optional[float] = None
) -> Dict[str, Any]:
    """`ladder theory --json` as a dict. alpha: degrees (60); n (10); b: s (1.3)."""

def catalogue() -> List[Tuple[str, str, str]]:
    """The built-in scenes: (ID, kind, title)."""

class Image(bytes):
    """One rendered file's bytes, shown inline by Jupyter."""

    name: str
    def __new__(cls, data: bytes, name: str = "") -> Image: ...
    @property
    def format(self) -> str: ...
    def _repr_mimebundle_(
        self, include: Any = None, exclude: Any = None
    ) -> Optional[Dict[str, Any]]: ...
    def _repr_png_(self) -> Optional[bytes]: ...
    def _repr_svg_(self) -> Optional[str]: ...
    def _repr_html_(self) -> Optional[str]: ...
    def save(self, path: Union[str, os.PathLike[str]]) -> Path: ...

class Files(Dict[str, Image]):
    """Several rendered files: name → Image."""

    def _repr_html_(self) -> Optional[str]: ...

class Scene:
    """A scene (docs/scenes.md): model, drive, window, integrator, picture."""

    def __init__(self, **keys: Any) -> None: ...
    @classmethod
    def builtin(cls, id: str, kind: Optional[str] = None) -> Scene: ...
    @classmethod
    def from_toml(cls, source: Union[str, os.PathLike[str]]) -> Scene: ...
    def to_toml(self) -> str: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def replace(self, **keys: Any) -> Scene: ...
    @property
    def name(self) -> str: ...
    @property
    def kind(self) -> str: ...
    @property
    def title(self) -> str: ...
    @property
    def runs(self) -> int: ...
    def simulate(
        self,
        sample_every: Optional[float] = None,
        samples: Optional[Sequence[float]] = None,
        index: int = 0,
        dissipation: bool = False,
        *,
        progress: Any = None,
    ) -> Run:
        """sample_every: τ (10)."""
    def render(
        self,
        format: Union[str, Sequence[str], None] = None,
        size: Union[str, Tuple[int, int], None] = None,
        style: Optional[Any] = None,
        *,
        frames: Optional[int] = None,
        fps: Optional[float] = None,
        scale: Optional[float] = None,
        data: bool = False,
    ) -> Union[Image, Files]:
        """format: png|svg|pdf|gif|mp4 or several (png / gif); size: WxH
        pixels (640x480); frames (200); fps (25); scale (1)."""
    def save(
        self,
        dir: Union[str, os.PathLike[str]] = "out",
        format: Union[str, Sequence[str], None] = None,
        size: Union[str, Tuple[int, int], None] = None,
        *,
        frames: Optional[int] = None,
        fps: Optional[float] = None,
        scale: Optional[float] = None,
        progress: Any = None,
    ) -> List[Path]: ...

class Table(Dict[str, Any]):
    """A sweep's CSV as numpy columns."""

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
    ) -> None: ...
    @property
    def columns(self) -> List[str]: ...
    @property
    def provenance(self) -> Dict[str, str]:
        """program, version, git_commit, build, scene (JSON), fingerprint, command."""
    def to_csv(self, path: Any = None) -> str:
        """The CSV with its provenance as leading '# key: value' lines."""
    def to_pandas(self) -> Any: ...
    def to_xarray(self) -> Any:
        """An xarray.Dataset with the grid's axes as dimensions."""

def sweep(
    base: Optional[Scene] = None,
    *,
    cap: Optional[float] = None,
    name: Optional[str] = None,
    max_runs: Optional[int] = None,
    executor: Any = None,
    chunks: Optional[int] = None,
    progress: Any = None,
    **keys: Any,
) -> Table:
    """Grid keywords SWEEP_PARAMETERS (alpha, n, b, gamma, gravity, inertia,
    drive_time): a list, a value or "start:stop:step". cap: τ (100000).
    executor: anything with submit(fn, *args) → future.result(); chunks:
    pieces of the grid sent to it (about 64 runs each, at least 16);
    progress: None (a bar where seen) | True | False | progress(done, runs)."""
