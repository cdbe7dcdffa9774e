"""Progress of a long call (``simulate``, ``sweep``, ``Scene.save``): the
``progress=`` keyword as the engine's callback.

The engine calls ``callback(done, total)`` from the calling thread about
ten times a second while the work moves, and once at its end (``done``:
τ simulated, runs of a sweep, frames of a movie; ``total`` None where it
is not known before the work). ``progress=None`` shows a bar where
someone sees it (a Jupyter notebook, or a terminal on stderr) and nothing
elsewhere; ``True`` always a bar; ``False`` never; a callable is called.
The bar is tqdm's (``tqdm.auto``, a widget in a notebook) where tqdm is
installed, else one line on stderr; it appears only once a call has run
for :data:`BAR_DELAY` seconds, so quick calls stay quiet.
"""

from __future__ import annotations

import sys
import time
from typing import Any, Callable, Optional

#: Seconds a call runs before its bar appears.
BAR_DELAY = 0.5

Callback = Callable[[Any, Any], Any]


def shown() -> bool:
    """Whether a bar would be seen: a Jupyter kernel, or stderr a terminal."""
    ipython = sys.modules.get("IPython")
    if ipython is not None:
        get = getattr(ipython, "get_ipython", None)
        shell = get() if callable(get) else None
        if shell is not None and hasattr(shell, "kernel"):
            return True
    try:
        return sys.stderr.isatty()
    except (AttributeError, ValueError):
        return False


class Bar:
    """A progress bar, callable as the engine's callback; :meth:`close`
    ends it."""

    def __init__(self, what: str, unit: str):
        self.what = what
        self.unit = unit
        self.started = time.monotonic()
        self.bar: Any = None
        self.line = False

    def __call__(self, done: Any, total: Any) -> None:
        if self.bar is None and not self.line:
            if time.monotonic() - self.started < BAR_DELAY:
                return
            self.bar = _tqdm(self.what, self.unit, total)
            self.line = self.bar is None
        if self.bar is not None:
            if total is not None and self.bar.total != total:
                self.bar.total = total
            self.bar.n = done
            self.bar.refresh()
        else:
            shown_total = "" if total is None else f"/{_number(total)}"
            share = f" ({100 * done / total:.0f}%)" if total else ""
            sys.stderr.write(f"\r{self.what}: {_number(done)}{shown_total} {self.unit}{share}")
            sys.stderr.flush()

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()
        elif self.line:
            sys.stderr.write("\n")
            sys.stderr.flush()


def _number(x: Any) -> str:
    return f"{x:.6g}" if isinstance(x, float) else str(x)


def _tqdm(what: str, unit: str, total: Any) -> Any:
    """A tqdm bar (a notebook widget where one runs), or None without tqdm."""
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return None
    return tqdm(total=total, desc=what, unit=unit, leave=True)


class Reporting:
    """``with Reporting(progress, what, unit) as callback:`` the callback
    for the engine (None: none), its bar closed at the end."""

    def __init__(self, progress: Any, what: str, unit: str):
        if progress is not None and not isinstance(progress, bool) and not callable(progress):
            raise ValueError(
                f"progress: must be None (a bar where one is seen), True, False or a "
                f"callable progress(done, total), got {progress!r}"
            )
        self.bar: Optional[Bar] = None
        self.callback: Optional[Callback] = None
        if callable(progress) and not isinstance(progress, bool):
            self.callback = progress
        elif progress is True or (progress is None and shown()):
            self.bar = Bar(what, unit)
            self.callback = self.bar

    def __enter__(self) -> Optional[Callback]:
        return self.callback

    def __exit__(self, *exc: Any) -> None:
        if self.bar is not None:
            self.bar.close()
