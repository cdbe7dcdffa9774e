"""The parameter table's Python front end (docs/python.md): every
parameter of the engine's table (`jl.PARAMETERS`, read from the program,
not a copy) is a keyword of `simulate` and of the stubs, a sweep's grid
keyword, in the docstrings with the table's default and range, the
default scene's value, and refused past its range naming its key. The
Rust side checks the command line, scene files, sweep axes and data
files against the same table (tests/integration/parameter_table.rs)."""

import ast
import inspect
import math
from pathlib import Path

import pytest

import jacobs_ladder as jl

STUBS = Path(jl.__file__).with_name("__init__.pyi")
NAMES = [p["name"] for p in jl.PARAMETERS]


def default_scene_value(p):
    scene = jl.Scene().to_dict()
    if p["place"] == "model":
        return scene["model"][p["name"]]
    return scene["drive"]["flips"][0]["duration"]


def stub_function(name):
    tree = ast.parse(STUBS.read_text())
    return next(n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == name)


def item(doc, name):
    """The docstring's item ``- ``name``: ...`` with its wrapped lines."""
    lines = doc.splitlines()
    start = next(i for i, l in enumerate(lines) if l.strip().startswith(f"- ``{name}``"))
    indent = len(lines[start]) - len(lines[start].lstrip())
    out = [lines[start]]
    for l in lines[start + 1 :]:
        if len(l) - len(l.lstrip()) <= indent or not l.strip():
            break
        out.append(l)
    return "\n".join(out)


def test_the_table_has_every_parameter_of_the_program():
    assert NAMES[:3] == ["alpha", "n", "b"] and "drive_time" in NAMES
    assert tuple(NAMES) == jl.SWEEP_PARAMETERS
    for p in jl.PARAMETERS:
        assert p["kind"] in ("int", "float") and p["place"] in ("model", "drive")
        assert p["min"] <= p["default"] <= p["max"], p


@pytest.mark.parametrize("p", jl.PARAMETERS, ids=NAMES)
def test_every_parameter_is_a_keyword_with_the_tables_default_and_range(p):
    name = p["name"]
    assert name in inspect.signature(jl.simulate).parameters
    args = stub_function("simulate").args
    assert name in [a.arg for a in args.args + args.kwonlyargs], "the stub's simulate"
    # The docstring says what the table says: its doc, range and default.
    line = " ".join(item(jl.simulate.__doc__, name).split())
    assert p["doc"].split()[0] in line and " ".join(p["range"].split()) in line, line
    assert f"Default {p['default']:g}." in line, line
    # The engine's default scene has the table's default.
    assert default_scene_value(p) == p["default"]
    # Past the range: a ValueError naming the key.
    bad = p["max"] * 2 if math.isfinite(p["max"]) else p["min"] - 1
    if p["kind"] == "int":
        bad = int(bad)
    with pytest.raises(ValueError) as err:
        jl.simulate(**{name: bad})
    assert str(err.value).split(":")[0] in (name, f"model.{name}"), str(err.value)


def test_the_stubs_point_at_the_table_and_type_no_default():
    for fn in ("simulate", "theory", "sweep"):
        assert "PARAMETERS" in ast.get_docstring(stub_function(fn)), fn
    text = STUBS.read_text()
    for p in jl.PARAMETERS:
        assert f"({p['default']:g})" not in text, p["name"]


def test_the_run_defaults_in_the_docstrings_are_the_engines():
    d = jl._params.DEFAULTS
    scene = jl.Scene().to_dict()["run"]
    assert d["t_end"] == scene["t_end"] and d["tolerance"] == scene["tolerance"]
    doc = " ".join(jl.simulate.__doc__.split())
    assert f"Default {d['t_end']:g}." in doc and f"Default {d['tolerance']:g}." in doc
    assert "{" + "parameters}" not in doc and "{t_end}" not in doc
    render = " ".join(jl.Scene.render.__doc__.split())
    assert f"Default {d['frames']}." in render and "{frames}" not in render
    assert f"Default {d['cap']:g}" in " ".join(jl.sweep.__doc__.split())
    theory = " ".join(jl.theory.__doc__.split())
    assert f"from 2 to {d['theory_max_n']}" in theory
