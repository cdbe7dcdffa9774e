"""The type stubs (`__init__.pyi`) match the module: every public name,
and every public function's and method's parameters (names, kinds and
defaults); `dir(jl)` shows the public names only."""

import ast
import inspect
from pathlib import Path

import jacobs_ladder as jl

STUBS = Path(jl.__file__).with_name("__init__.pyi")


def stub_tree():
    return ast.parse(STUBS.read_text())


def params(node):
    """(name, kind, default source) of a stub's function."""
    a = node.args
    out = []
    positional = a.posonlyargs + a.args
    defaults = [None] * (len(positional) - len(a.defaults)) + list(a.defaults)
    for arg, d in zip(positional, defaults):
        out.append((arg.arg, "pos", None if d is None else ast.literal_eval(d)))
    if a.vararg:
        out.append((a.vararg.arg, "*", None))
    for arg, d in zip(a.kwonlyargs, a.kw_defaults):
        out.append((arg.arg, "kw", None if d is None else ast.literal_eval(d)))
    if a.kwarg:
        out.append((a.kwarg.arg, "**", None))
    return out


def live(fn):
    kinds = {
        inspect.Parameter.POSITIONAL_ONLY: "pos",
        inspect.Parameter.POSITIONAL_OR_KEYWORD: "pos",
        inspect.Parameter.VAR_POSITIONAL: "*",
        inspect.Parameter.KEYWORD_ONLY: "kw",
        inspect.Parameter.VAR_KEYWORD: "**",
    }
    return [
        (p.name, kinds[p.kind], None if p.default is inspect.Parameter.empty else p.default)
        for p in inspect.signature(fn).parameters.values()
    ]


def test_every_public_name_is_in_the_stubs_and_back():
    tree = stub_tree()
    stubbed = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            stubbed.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            stubbed.add(node.target.id)
    public = set(jl.__all__) | {"ENGINE_VERSION", "SWEEP_PARAMETERS", "OUTCOMES"}
    assert public - stubbed == set(), "public names missing from the stubs"
    assert {n for n in stubbed if not n.startswith("_")} - public <= {"FloatArray"}


def test_every_signature_matches_the_stubs():
    checked = 0
    for node in stub_tree().body:
        if isinstance(node, ast.FunctionDef) and not node.name.startswith("_"):
            assert params(node) == live(getattr(jl, node.name)), node.name
            checked += 1
        if isinstance(node, ast.ClassDef):
            cls = getattr(jl, node.name)
            for item in node.body:
                if not isinstance(item, ast.FunctionDef):
                    continue
                decorators = {getattr(d, "id", None) for d in item.decorator_list}
                if "property" in decorators or item.name in ("__new__",):
                    continue
                fn = getattr(cls, item.name)
                stub = params(item)
                if "classmethod" in decorators or "staticmethod" in decorators:
                    stub = stub[1:] if "classmethod" in decorators else stub
                else:
                    stub = stub[1:]  # self
                    fn = getattr(cls, item.name)
                got = live(fn)
                if got and got[0][0] == "self":
                    got = got[1:]
                assert stub == got, f"{node.name}.{item.name}"
                checked += 1
    assert checked > 15


def test_dir_shows_the_public_names_only():
    names = dir(jl)
    for helper in ("Any", "Dict", "np", "os", "json", "Optional"):
        assert helper not in names
    for public in ("simulate", "sweep", "Scene", "RunError", "__version__"):
        assert public in names
