"""The engine's parameter table and defaults, and the docstrings made from
them: no default, range or unit of a parameter is typed in this package.

``PARAMETERS`` is the table (``scene::params`` of the engine, in its
order): one dict per parameter with ``name`` (the keyword, sweep axis and
CSV column), ``flag``, ``symbol``, ``unit``, ``label``, ``doc``,
``default``, ``min``, ``max`` (±inf where unbounded), ``range`` (in
words, as the messages give it), ``kind`` ("int" or "float") and
``place`` ("model" or "drive"). ``DEFAULTS`` holds the other defaults the
docstrings show, each read from the type that owns it.
"""

from __future__ import annotations

from typing import Any, Callable, Dict, Tuple

from . import _native

PARAMETERS: Tuple[Dict[str, Any], ...] = tuple(dict(p) for p in _native.PARAMETERS)
DEFAULTS: Dict[str, Any] = dict(_native.DEFAULTS)

_BY_NAME = {p["name"]: p for p in PARAMETERS}


def number(x: Any) -> str:
    """A default as the docstrings write it: 60, 1.3, 0.0002, 1000."""
    return f"{x:g}" if isinstance(x, float) else str(x)


def parameter_line(name: str, range_text: str = "") -> str:
    """``- ``alpha`` (°): <doc>; <range>. Default <default>.``"""
    p = _BY_NAME[name]
    unit = f" ({p['unit']})" if p["unit"] else ""
    default = number(p["default"])
    return f"- ``{name}``{unit}: {p['doc']}; {range_text or p['range']}. Default {default}."


def parameter_lines(lines: "list[str]", indent: str = "    ") -> str:
    """Docstring items, wrapped, the first line's indent left to the
    placeholder they replace."""
    return ("\n" + indent).join(_wrapped(line, indent) for line in lines)


def filled(fn: Callable[..., Any], **fields: str) -> Callable[..., Any]:
    """``fn`` with its docstring's ``{parameters}`` (every parameter's
    line, indented as the placeholder), ``{grid}`` (the sweep's
    parameters) and ``{NAME}`` of :data:`DEFAULTS` filled in."""
    doc = fn.__doc__ or ""
    for key, value in {**DEFAULTS, **fields}.items():
        text = value if isinstance(value, str) else number(value)
        if isinstance(value, tuple):
            text = "×".join(str(v) for v in value)
        doc = doc.replace("{" + key + "}", text)
    if "{parameters}" in doc:
        lines = [parameter_line(p["name"]) for p in PARAMETERS]
        doc = doc.replace("{parameters}", parameter_lines(lines))
    fn.__doc__ = doc
    return fn


def _wrapped(text: str, indent: str, width: int = 76) -> str:
    """``text`` wrapped at ``width``, continued lines indented two more."""
    import textwrap

    return ("\n" + indent + "  ").join(textwrap.wrap(text, width - len(indent)))


def grid_names() -> str:
    """``alpha``, ``n``, ... of the sweep's parameters (the table's)."""
    return ", ".join(f"``{p['name']}``" for p in PARAMETERS)
