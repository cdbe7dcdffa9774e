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
import os
from pathlib import Path
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union


class _LazyNumpy:
    """numpy, imported on first use: `import jacobs_ladder` stays fast (numpy
    alone takes about 120 ms to import); the first array made loads it."""

    def __getattr__(self, name: str) -> Any:
        import numpy

        globals()["np"] = numpy
        return getattr(numpy, name)


np: Any = _LazyNumpy()

from . import _native
from ._native import InternalError, RunError

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
    "InternalError",
    "__version__",
]

__version__ = "0.1.0"
#: The engine's version and git commit (``ladder --version``).
ENGINE_VERSION: str = _native.VERSION


# ---------------------------------------------------------------- runs


class Run:
    """A simulated run: numpy arrays of its samples and its record.

    Arrays (samples × N where per block; N = blocks, block 1 driven):

    - ``t``: sample times, τ (every ``sample_every`` τ from 0 to t_end).
    - ``theta``: angles θ_n, radians, as integrated (not wrapped).
    - ``x``, ``y``: block centres X_n, Y_n, in s: x runs down the ladder
      (along gravity, block 1 at the top), y across it (the paper's Fig. 1).
    - ``vx``, ``vy``, ``omega``: their velocities, s/τ and rad/τ.
    - ``kink_position``: where the wall is at each sample, in blocks
      (fractional: the count of blocks past the wall plus the fraction by
      which the block at the wall has turned; 10.11 for N = 10 means the
      wave has run off the end), not a count of flipped blocks.
    - ``kinetic``, ``elastic``, ``gravitational``: the energies at each
      sample, in k s² (½ m (Ẋ² + Ẏ²) + ½ I θ̇² summed; Σ ½ k [(L_A − a)² +
      (L_B − b)²]; −m G Σ X_n); ``dissipated``: the energy dissipated from
      t = 0, recorded when ``simulate(..., dissipation=True)`` (NaN
      otherwise). After the drive ends, kinetic + elastic + gravitational
      + dissipated stays constant to the integrator's accuracy.
    - ``arrival_times``: per block, τ: the first sign change of sin θ_n;
      NaN where the block never flipped (the CLI's ``null``).
    - ``final_theta_deg``: θ_n at t_end in degrees, wrapped to (−180, 180]
      (the CLI's ``final_theta_deg``).

    Records: ``integrator`` (the report the data files carry: scheme, dt,
    steps, force evaluations, auto's achieved arrival error), ``speed``
    (blocks/τ, NaN when too few blocks flipped), ``waves`` (one record per
    domain wall, where the engine reports them, else None) and ``record``
    (everything the engine reports about the run, as a dict).
    """

    __slots__ = ("_d", "record", "scene")

    def __init__(self, arrays: Dict[str, Any], scene: Optional["Scene"] = None):
        self._d = arrays
        self.record: Dict[str, Any] = json.loads(arrays["record"])
        self.scene = scene

    def __reduce__(self):
        # The arrays (numpy pickles them whole) and the record's JSON text.
        return (Run, (self._d, self.scene))

    t = property(lambda self: self._d["t"], doc="Sample times, τ.")
    theta = property(lambda self: self._d["theta"], doc="θ_n(t), radians, samples × N.")
    x = property(
        lambda self: self._d["x"],
        doc="X_n(t), block centres, s; samples × N. X runs down the ladder, along gravity.",
    )
    y = property(
        lambda self: self._d["y"],
        doc="Y_n(t), block centres, s; samples × N. Y runs across the ladder.",
    )
    kinetic = property(
        lambda self: self._d["kinetic"], doc="Kinetic energy at each sample, k s²."
    )
    elastic = property(
        lambda self: self._d["elastic"], doc="Elastic energy of the springs at each sample, k s²."
    )
    gravitational = property(
        lambda self: self._d["gravitational"], doc="−m G Σ X_n at each sample, k s²."
    )
    dissipated = property(
        lambda self: self._d["dissipated"],
        doc="Energy dissipated since t = 0 at each sample, k s² (NaN unless dissipation=True).",
    )
    vx = property(lambda self: self._d["vx"], doc="dX_n/dt, s/τ; samples × N.")
    vy = property(lambda self: self._d["vy"], doc="dY_n/dt, s/τ; samples × N.")
    omega = property(lambda self: self._d["omega"], doc="dθ_n/dt, rad/τ; samples × N.")
    kink_position = property(
        lambda self: self._d["kink_position"],
        doc="The wall's position at each sample, in blocks (fractional; N + a fraction once it ran off the end).",
    )
    arrival_times = property(
        lambda self: self._d["arrival_times"], doc="Arrival time per block, τ; NaN where none."
    )
    final_theta_deg = property(
        lambda self: self._d["final_theta_deg"], doc="θ_n at t_end, degrees, wrapped to (−180, 180]."
    )

    @property
    def n(self) -> int:
        """Number of blocks N."""
        return int(self.arrival_times.shape[0])

    @property
    def integrator(self) -> Dict[str, Any]:
        """The integrator report: ``requested``, ``name``, ``dt``, ``steps``,
        ``force_evals``, and for ``auto`` its ``tolerance`` and achieved
        ``arrival_error`` (τ)."""
        return self.record["integrator"]

    @property
    def speed(self) -> float:
        """Wave speed, blocks/τ (least squares over the arrivals); NaN when
        too few blocks flipped."""
        s = self.record.get("speed")
        return float("nan") if s is None else float(s)

    @property
    def waves(self) -> Optional[List[Dict[str, Any]]]:
        """One record per domain wall (kind, launched_at, arrival_times with
        NaN for none, front, fate), where the engine reports waves; None
        otherwise."""
        waves = self.record.get("waves")
        if waves is None:
            return None
        if isinstance(waves, dict):  # {"waves": [...], "block_n": {...}}
            waves = waves.get("waves", [])
        out = []
        for w in waves:
            w = dict(w)
            if isinstance(w.get("arrival_times"), list):
                w["arrival_times"] = np.array(
                    [np.nan if a is None else a for a in w["arrival_times"]], dtype=float
                )
            out.append(w)
        return out

    @property
    def block_n(self) -> Optional[Dict[str, Any]]:
        """The free bottom block's own record beside the waves (its sign
        changes, τ, and final angle), where the engine reports waves."""
        waves = self.record.get("waves")
        return waves.get("block_n") if isinstance(waves, dict) else None

    def to_dict(self) -> Dict[str, Any]:
        """Every array and record, as a dict (arrays are numpy arrays)."""
        d = {k: v for k, v in self._d.items() if k != "record"}
        d.update({k: v for k, v in self.record.items() if k not in d})
        d["waves"] = self.waves
        return d

    def __repr__(self) -> str:
        m = self.record.get("model", {})
        alpha = m.get("alpha")
        wave = self.record.get("launched", "wave")
        # Blocks 1..N-1 (block N, free, turns its own way): the engine's count.
        flipped = self.record.get("blocks_flipped")
        integ = self.integrator
        t_end = self.record.get("t_end")
        if not isinstance(t_end, (int, float)):  # "auto": the window it reached
            t_end = float(self.t[-1]) if len(self.t) else float("nan")
        return (
            f"<Run {wave} α = {alpha:g}°, N = {self.n}, b = {m.get('b'):g}, "
            f"γ = {m.get('gamma'):g}: t = 0..{t_end:g} τ, "
            f"{len(self.t)} samples, {flipped}/{self.n - 1} blocks flipped, "
            f"{integ['name']} dt = {integ['dt']:g} ({integ['requested']})>"
        )


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
    **scene_keys: Any,
) -> Run:
    """Simulate the ladder and return a :class:`Run` of numpy arrays.

    The keywords are ``ladder simulate``'s long flags with underscores;
    a keyword left out (None) keeps the engine's default, the paper's
    value:

    - ``alpha``: equilibrium angle α, degrees, 0 < |α| < 90; its sign picks
      the wave (α > 0 kink, α < 0 antikink). Default 60.
    - ``n``: number of blocks N, 2 to 100000. Default 10.
    - ``b``: rest length of the B springs, in units of the block length s.
      Default 1.3.
    - ``gamma``: damping γ (force −γẊ, torque −γr²θ̇). Default 0.02.
    - ``gravity``: G = mg/(ks). Default 2e-4.
    - ``inertia``: moment of inertia I of a block, m s². Default 0.25.
    - ``drive_time``: time T_d each flip of block 1 takes, τ. Default 1000.
    - ``flips``: start times of the flips of block 1, τ. Default [0].
    - ``second_flip``: turn block 1 back from this time too (= flips [0, T]).
    - ``t_end``: end of the window, τ. Default 4000.
    - ``integrator``: ``auto`` (picks the step and verifies the arrival
      times to ``tolerance``), ``explicit-euler``, ``symplectic-euler`` (the
      paper's, dt 0.01), ``verlet``, ``rk4`` or ``dopri5``. Default auto.
    - ``dt``: step of a named integrator, τ. Default 0.01.
    - ``rtol``: tolerance of dopri5. Default 1e-6.
    - ``tolerance``: largest arrival-time error auto accepts, τ. Default 0.1.
    - ``sample_every``: interval of the samples kept, τ. Default 10 (as
      ``simulate --csv``); or ``samples``: the sample times themselves.
    - ``dissipation``: also record the energy dissipated so far at each
      sample (``Run.dissipated``; the steps are then taken one per call,
      a slower run with the same trajectory bit for bit). Default False.
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
    return Run(_native.simulate(kw, sample_every, samples, bool(dissipation)))


def theory(
    alpha: Optional[float] = None, n: Optional[int] = None, b: Optional[float] = None
) -> Dict[str, Any]:
    """The linear theory, as ``ladder theory --json`` prints it: ``a``,
    ``u_min`` and ``barrier`` (m g s), ``kappa``, ``winding_number``,
    ``gap_omega_plus_q0``, ``omega_max``, zero modes, ...

    - ``alpha``: degrees, 0 ≤ |α| ≤ 90. Default 60.
    - ``n``: blocks of the finite chain, 2 to 400. Default 10.
    - ``b``: rest length of the B springs, s. Default 1.3.
    """
    return json.loads(_native.theory(alpha, n, b))


def catalogue() -> List[Tuple[str, str, str]]:
    """The built-in scenes (``ladder list``): (ID, kind, title) tuples."""
    return _native.catalogue()


# --------------------------------------------------------------- scenes

# The render options' defaults (frames, size, fps, scale, formats) are the
# library's (jacobs_ladder::front::options::RenderOptions): a keyword left
# at None is not sent.


class Scene:
    """A scene: a model, the drive of block 1, a time window, an integrator
    and a picture (docs/scenes.md). Every field has the paper's default.

    Make one with :meth:`builtin`, :meth:`from_toml` or ``Scene(**keys)``
    (the paper's scene with keywords applied, as :meth:`replace`).
    """

    __slots__ = ("_s",)

    def __init__(self, **keys: Any):
        base = _native._Scene.from_json("{}")
        self._s = base.replace(keys) if keys else base

    def __reduce__(self):
        # A scene travels as its JSON (every key written out), checked again
        # when read: it pickles, deep-copies and crosses to a pool's worker.
        return (_scene_from_json, (self._s.to_json(),))

    def __copy__(self) -> "Scene":
        return self  # immutable: replace() makes the changed copies

    def __deepcopy__(self, memo: Any) -> "Scene":
        return self._wrap(_native._Scene.from_json(self._s.to_json()))

    def __hash__(self) -> int:
        return hash(self._s.to_json())

    @classmethod
    def _wrap(cls, native: Any) -> "Scene":
        s = cls.__new__(cls)
        s._s = native
        return s

    @classmethod
    def builtin(cls, id: str, kind: Optional[str] = None) -> "Scene":
        """The built-in scene ``id`` (``ladder list``, :func:`catalogue`):
        ``"3"``, ``"S5"``, ``"pinning"``; ``kind="movie"`` where a figure
        has the same ID. IDs are case-insensitive."""
        return cls._wrap(_native._Scene.builtin(str(id), kind))

    @classmethod
    def from_toml(cls, source: Union[str, os.PathLike]) -> "Scene":
        """A scene from TOML text, or from the file at a path (named after
        the file, as ``ladder render`` does). Errors name the line, column
        and key."""
        if isinstance(source, os.PathLike):
            return cls._wrap(_native._Scene.load(os.fspath(source)))
        text = str(source)
        looks_like_path = "\n" not in text and "=" not in text and "[" not in text
        if looks_like_path and (text.endswith(".toml") or os.path.exists(text)):
            return cls._wrap(_native._Scene.load(text))
        return cls._wrap(_native._Scene.parse(text, "<toml>", "custom"))

    def to_toml(self) -> str:
        """The scene as a TOML file, every value written out (without its
        name: a file takes its name from its file name)."""
        return self._s.to_toml()

    def to_dict(self) -> Dict[str, Any]:
        """The scene as a dict of its keys (docs/scenes.md)."""
        return json.loads(self._s.to_json())

    def replace(self, **keys: Any) -> "Scene":
        """A changed copy: the keywords of :func:`simulate` (``alpha``,
        ``n``, ``t_end``, ``flips``, ...), any scene key (``name``,
        ``title``, ``model={...}``, ``output={"kind": "filmstrip", ...}``)
        or a dotted key path (``**{"output.camera": "follow"}``)."""
        return self._wrap(self._s.replace(keys))

    @property
    def name(self) -> str:
        """The name of its files (``figure-NAME.png``, ``movie-NAME.gif``)."""
        return self._s.name

    @property
    def kind(self) -> str:
        """``figure``, ``movie`` or ``data``."""
        return self._s.kind

    @property
    def title(self) -> str:
        return self._s.title

    @property
    def runs(self) -> int:
        """Number of simulations the scene runs (0 for theory figures)."""
        return self._s.runs

    def simulate(
        self,
        sample_every: Optional[float] = None,
        samples: Optional[Sequence[float]] = None,
        index: int = 0,
        dissipation: bool = False,
    ) -> Run:
        """Simulate run ``index`` of the scene (its only one, for most), as
        :func:`simulate` does; samples every ``sample_every`` τ (default 10)
        or at ``samples``."""
        return Run(self._s.simulate(sample_every, samples, index, bool(dissipation)), self)

    def _args(self, format, frames, size, fps, scale):
        return dict(
            format=format,
            frames=frames,
            size=size,
            fps=fps,
            scale=scale,
        )

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
    ) -> Union["Image", "Files"]:
        """Render the scene as the command line does, in memory.

        - ``format``: ``png``, ``svg``, ``pdf`` (figures), ``gif``, ``mp4``
          (movies), or several (``"png,svg"`` or a list). Default png / gif.
        - ``size``: a movie's frame size, ``(640, 480)`` or ``"640x480"``,
          pixels. Default 640 × 480.
        - ``style``: the scene's ``style`` key (print styles), where the
          engine has one.
        - ``frames``: frames of a movie, 2 to 5000. Default 200.
        - ``fps``: frames per second of a movie. Default 25.
        - ``scale``: pixels per design pixel of PNG figures. Default 1.
        - ``data``: keep the data file (``NAME.json``) among the files.

        Returns the bytes of the one file (an :class:`Image`, shown inline
        by Jupyter) or, where the output has several files (a movie and its
        kymograph, several formats), a :class:`Files` dict of name → bytes.
        """
        scene = self if style is None else self.replace(style=style)
        files = scene._s.render(self._args(format, frames, size, fps, scale))
        files = [(n, b) for n, b in files if data or not n.endswith(".json")]
        args = self._args("png", frames, size, fps, scale)
        images = [_shown(Image(b, n), scene, args) for n, b in files]
        if len(images) == 1:
            return images[0]
        return Files((img.name, img) for img in images)

    def save(
        self,
        dir: Union[str, os.PathLike] = "out",
        format: Union[str, Sequence[str], None] = None,
        size: Union[str, Tuple[int, int], None] = None,
        *,
        frames: Optional[int] = None,
        fps: Optional[float] = None,
        scale: Optional[float] = None,
    ) -> List[Path]:
        """Write the scene's files into ``dir`` exactly as ``ladder render
        --out DIR`` does (atomically, the data file beside them); the
        options as :meth:`render`. Returns the paths written."""
        paths = self._s.save(os.fspath(dir), self._args(format, frames, size, fps, scale))
        return [Path(p) for p in paths]

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Scene) and self._s == other._s

    def __repr__(self) -> str:
        return f"<Scene {self.kind} {self.name}: {self.title}; {self._s.parameters}>"


def _scene_from_json(text: str) -> Scene:
    """A scene from its JSON (unpickling)."""
    return Scene._wrap(_native._Scene.from_json(text))


# ---------------------------------------------------------- rendered files

_MIME = {
    "png": "image/png",
    "svg": "image/svg+xml",
    "gif": "image/gif",
    "mp4": "video/mp4",
    "pdf": "application/pdf",
    "json": "application/json",
    "csv": "text/csv",
}


def _shown(image: "Image", scene: "Scene", png_args: Dict[str, Any]) -> "Image":
    """A PDF is displayed with a PNG of the same figure beside it (what
    a browser shows inline; the PDF is kept for export): the engine renders
    that PNG when the PDF is first displayed, never before."""
    if image.format == "pdf":
        stem = image.name[: -len(".pdf")]

        def preview() -> Optional[bytes]:
            files = scene._s.render(png_args)
            return next((b for n, b in files if n == stem + ".png"), None)

        image._preview = preview
    return image


class Image(bytes):
    """The bytes of one rendered file, which Jupyter shows inline (PNG,
    SVG, GIF, MP4; a PDF as an embedded object). ``name`` is its file name."""

    name: str

    def __new__(cls, data: bytes, name: str = ""):
        obj = super().__new__(cls, data)
        obj.name = name
        return obj

    def __reduce__(self):
        return (Image, (bytes(self), self.name))

    @property
    def format(self) -> str:
        return self.name.rsplit(".", 1)[-1].lower() if "." in self.name else ""

    _preview = None

    def _preview_png(self) -> Optional[bytes]:
        """The PNG shown beside a PDF (rendered once, on first display)."""
        make = self._preview
        if make is None:
            return None
        if callable(make):
            self._preview = make()
        return self._preview

    def _repr_mimebundle_(self, include=None, exclude=None):
        """A PDF as itself and as a PNG beside it: browsers show the PNG
        (a PDF alone is a blank box in Chromium), exports take the PDF."""
        if self.format != "pdf":
            return None
        bundle = {"application/pdf": bytes(self), "text/plain": repr(self)}
        png = self._preview_png()
        if png is not None:
            bundle["image/png"] = png
            bundle["text/html"] = self._repr_html_()
        return bundle

    def _repr_png_(self):
        if self.format == "pdf":
            return self._preview_png()
        return bytes(self) if self.format == "png" else None

    def _repr_svg_(self):
        return self.decode("utf-8") if self.format == "svg" else None

    def _repr_html_(self):
        fmt = self.format
        mime = _MIME.get(fmt)
        if mime is None or fmt in ("json", "csv"):
            return None
        import base64

        b64 = base64.b64encode(self).decode("ascii")
        if fmt == "mp4":
            return f'<video controls loop autoplay muted src="data:{mime};base64,{b64}"></video>'
        if fmt == "pdf":
            png = self._preview_png()
            if png is not None:
                import html

                png64 = base64.b64encode(png).decode("ascii")
                return f'<img alt="{html.escape(self.name)}" src="data:image/png;base64,{png64}">'
            return f'<embed type="{mime}" width="100%" height="480" src="data:{mime};base64,{b64}">'
        import html

        return f'<img alt="{html.escape(self.name)}" src="data:{mime};base64,{b64}">'

    def save(self, path: Union[str, os.PathLike]) -> Path:
        """Write the bytes to ``path`` (a folder: under the file's name)."""
        p = Path(path)
        if p.is_dir():
            p = p / self.name
        p.write_bytes(self)
        return p

    def __repr__(self) -> str:
        return f"<Image {self.name}: {len(self)} bytes>"


class Files(dict):
    """Several rendered files: file name → :class:`Image`; Jupyter shows
    each picture inline."""

    def _repr_html_(self):
        parts = []
        for name, img in self.items():
            html = img._repr_html_() if isinstance(img, Image) else None
            if html:
                import html as _html

                parts.append(f"<figure>{html}<figcaption>{_html.escape(name)}</figcaption></figure>")
        return "".join(parts) or None

    def __repr__(self) -> str:
        inner = ", ".join(f"{k}: {len(v)} bytes" for k, v in self.items())
        return f"<Files {inner}>"


# ----------------------------------------------------------------- sweeps

#: The parameters a sweep varies (``ladder sweep``'s grid flags).
SWEEP_PARAMETERS = ("alpha", "n", "b", "gamma", "gravity", "inertia", "drive_time")


class Table(dict):
    """A sweep's results: column name → numpy array, every column of the
    CSV ``ladder sweep`` writes, in its order and grid order: ``run``, the
    parameters (``alpha`` ... ``drive_time``), ``outcome`` (strings:
    propagated, stalled, pinned, diverged, undecided), ``blocks_flipped``,
    ``front`` (≤ N − 1), ``speed`` (blocks/τ), ``t_decided`` (τ),
    ``block_n_turned_at`` (τ) and ``waves``, then, where a run had more
    than one wave, ``wave1_kind``, ``wave1_launched_at``, ``wave1_front``,
    ``wave1_fate``, ``wave1_fate_at``, ... (kinds and fates as strings);
    NaN where a number is empty, -1 where a whole number is, "" where a
    string is. ``csv`` is the CSV's text, ``json`` the sweep's JSON
    (every run's arrival times) as a dict."""

    csv: str
    json: Dict[str, Any]

    def __init__(self, csv_text: str, json_text: str):
        import csv
        import io

        rows = list(csv.reader(io.StringIO(csv_text)))
        header, body = rows[0], rows[1:]
        cols: Dict[str, Any] = {}
        for j, name in enumerate(header):
            values = [r[j] for r in body]
            if name == "outcome" or name.endswith(("_kind", "_fate")):
                cols[name] = np.array(values, dtype=str)
            elif name in ("run", "n", "blocks_flipped", "front", "waves") or (
                name.startswith("wave") and name.endswith("_front")
            ):
                cols[name] = np.array([int(v) if v else -1 for v in values], dtype=np.int64)
            else:
                cols[name] = np.array([float(v) if v else np.nan for v in values], dtype=float)
        super().__init__(cols)
        self.csv = csv_text
        self.json_text = json_text
        self.json = json.loads(json_text)

    def __reduce__(self):
        # Made again from its CSV and JSON text (the columns follow).
        return (Table, (self.csv, self.json_text))

    def __len__(self) -> int:  # rows, as a table's length
        return len(self["run"]) if "run" in self else 0

    @property
    def columns(self) -> List[str]:
        return list(self.keys())

    def to_pandas(self):
        """The table as a pandas DataFrame (needs pandas)."""
        import pandas as pd

        return pd.DataFrame({k: self[k] for k in self.keys()})

    def to_xarray(self):
        """The table as an ``xarray.Dataset`` (needs xarray) with the grid's
        axes as dimensions, in the sweep's order (the first varies
        slowest), each with its values as coordinate; every other column a
        variable over them (``outcome[alpha, gamma]``)."""
        import xarray as xr

        axes = [(a["param"], np.asarray(a["values"])) for a in self.json["axes"]]
        dims = [name for name, _ in axes]
        shape = tuple(len(values) for _, values in axes)
        data = {
            k: (dims, np.asarray(v).reshape(shape))
            for k, v in self.items()
            if k not in dims
        }
        return xr.Dataset(data, coords={name: values for name, values in axes})

    def __repr__(self) -> str:
        outcomes, counts = np.unique(self["outcome"], return_counts=True)
        summary = ", ".join(f"{c} {o}" for o, c in zip(outcomes, counts))
        return f"<Table of {len(self)} runs ({summary}); columns {', '.join(self.keys())}>"


def sweep(
    base: Optional[Scene] = None,
    *,
    cap: Optional[float] = None,
    name: Optional[str] = None,
    max_runs: Optional[int] = None,
    executor: Any = None,
    chunks: Optional[int] = None,
    **keys: Any,
) -> Table:
    """Run a scene over a grid of parameters and decide what the wave did
    in each run, as ``ladder sweep`` does (same batch kernel, every core).

    - a grid keyword per varied parameter (``alpha``, ``n``, ``b``,
      ``gamma``, ``gravity``, ``inertia``, ``drive_time``): a list of
      values, one value, or a range string ``"start:stop:step"``
      (inclusive), e.g. ``sweep(alpha=[-50, -55, -60], gamma="0.01:0.04:0.01")``.
    - ``base``: the scene swept (default: the paper's). Other keywords
      (``t_end``, ``integrator``, ``tolerance``, scene keys) change it.
    - ``cap``: latest time a run may reach undecided, τ. Default 100000.
      A run is called stopped only when its state is proved at rest
      (docs/sweeps.md); otherwise it runs on to the cap.
    - ``name``: the sweep's name (in its JSON). Default the base's.
    - ``max_runs``: refuse a larger grid. Default 100000.
    - ``executor``: run the sweep on another machine's cores, or many: any
      ``concurrent.futures.Executor`` (a ``ProcessPoolExecutor``,
      dask.distributed's ``client.get_executor()``, submitit's
      ``AutoExecutor``, mpi4py's ``MPIPoolExecutor``), or anything with
      ``submit(fn, *args)`` returning a future with ``result()``. The grid
      is cut into ``chunks`` (round robin, as ``ladder sweep --shard``
      does); each chunk is sent to a worker, runs there on the Rust core
      with that worker's threads (``RAYON_NUM_THREADS``; one worker per
      node), and comes back as its shard; the shards are merged by the
      code of ``ladder sweep gather``. The table is byte for byte the
      local one's. docs/cluster.md.
    - ``chunks``: how many pieces the grid is cut into for ``executor``.
      Default about one per 512 runs.

    The axes vary in the order of ``SWEEP_PARAMETERS`` (the first slowest),
    as ``ladder sweep``'s flags do. Returns a :class:`Table` equal to the
    CLI's ``sweep-NAME.csv``.
    """
    # Axes in the command line's order (the first varies slowest), whatever
    # the order of the keywords, so that the rows are the CLI's.
    grid = {k: keys.pop(k) for k in SWEEP_PARAMETERS if k in keys}
    if not grid:
        raise ValueError(
            "sweep needs at least one grid keyword: " + ", ".join(SWEEP_PARAMETERS)
        )
    # The first axis goes with the scene (a sweep needs one to be checked);
    # the others follow in order (a JSON object would sort them).
    (first, first_values), *rest = grid.items()
    output: Dict[str, Any] = {"kind": "sweep", "grid": {first: first_values}}
    if cap is not None:
        output["cap"] = cap
    keys["output"] = output
    if name is not None:
        keys["name"] = name
    native = None if base is None else base._s
    axes = list(rest)
    if executor is None:
        if chunks is not None:
            raise ValueError("chunks: cuts the grid for an executor; give executor= too")
        csv_text, json_text = _native.sweep(native, keys, axes, max_runs)
        return Table(csv_text, json_text)
    scene, max_runs, count = _native.sweep_prepare(native, keys, axes, max_runs, chunks)
    futures = [
        executor.submit(_sweep_chunk, scene, max_runs, k, count) for k in range(1, count + 1)
    ]
    try:
        shards = [f.result() for f in futures]
    except BaseException:
        for f in futures:
            f.cancel()
        raise
    import tempfile

    with tempfile.TemporaryDirectory(prefix="jacobs-ladder-sweep-") as tmp:
        csv_text, json_text = _native.sweep_gather(tmp, shards, max_runs)
    return Table(csv_text, json_text)


def _sweep_chunk(scene: str, max_runs: int, k: int, chunks: int) -> bytes:
    """Chunk ``k`` of ``chunks`` of a sweep, run in an executor's worker:
    the bytes of its shard file."""
    return _native.sweep_chunk(scene, max_runs, k, chunks)


def __dir__() -> List[str]:
    """The public names only (``dir(jl)``, tab completion): not the
    helpers this module imports (typing, json, os, numpy)."""
    return sorted(set(__all__) | {"ENGINE_VERSION", "SWEEP_PARAMETERS"})
