"""Scenes (``jacobs_ladder.Scene``): read, changed by keywords, simulated,
rendered and saved by the engine, as the command line does; and the
rendered files (``Image``, ``Files``), which Jupyter shows inline."""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

from . import _native
from ._progress import Reporting
from ._run import Run


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
        *,
        progress: Any = None,
    ) -> Run:
        """Simulate run ``index`` of the scene (its only one, for most), as
        :func:`simulate` does; samples every ``sample_every`` τ (the
        engine's default, 10) or at ``samples``; ``progress`` as
        :func:`simulate`'s."""
        with Reporting(progress, "simulate", "τ") as report:
            arrays = self._s.simulate(sample_every, samples, index, bool(dissipation), report)
        return Run(arrays, self)

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
        progress: Any = None,
    ) -> List[Path]:
        """Write the scene's files into ``dir`` exactly as ``ladder render
        --out DIR`` does (atomically, the data file beside them); the
        options as :meth:`render`. ``progress``: None shows a bar in a
        notebook or a terminal, True always, False never, a callable is
        called ``progress(done, total)`` (a movie's frames, else files).
        Returns the paths written."""
        args = self._args(format, frames, size, fps, scale)
        unit = "frames" if self.kind == "movie" else "files"
        with Reporting(progress, f"save {self.name}", unit) as report:
            paths = self._s.save(os.fspath(dir), args, report)
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
