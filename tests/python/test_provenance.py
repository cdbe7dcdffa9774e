"""One version everywhere (jl.__version__, `ladder --version`, the data
files), and a sweep's table as an xarray Dataset over its grid."""

import re
from pathlib import Path

import jacobs_ladder as jl
from conftest import needed

ROOT = Path(__file__).resolve().parents[2]


def test_one_version_everywhere(ladder):
    cli = re.match(r"ladder (\S+) ", ladder("--version").stdout).group(1)
    pyproject = re.search(r'^version = "([^"]+)"', (ROOT / "pyproject.toml").read_text(), re.M).group(1)
    cargo = re.search(r'^version = "([^"]+)"', (ROOT / "Cargo.toml").read_text(), re.M).group(1)
    table = jl.sweep(alpha=[60], n=6)
    assert jl.__version__ == cli == pyproject == cargo == table.json["version"]
    assert jl.ENGINE_VERSION.startswith(jl.__version__ + " ")


def test_to_xarray_has_the_grid_as_dimensions():
    xr = needed("xarray")
    table = jl.sweep(alpha=[55, 65], gamma=[0.01, 0.02, 0.03], n=6)
    ds = table.to_xarray()
    assert list(ds["outcome"].dims) == ["alpha", "n", "gamma"]
    assert ds["outcome"].shape == (2, 1, 3)
    assert list(ds["gamma"].values) == [0.01, 0.02, 0.03]
    # Row k of the table is the grid point (k // 3, 0, k % 3).
    for k in range(len(table)):
        point = ds.sel(alpha=table["alpha"][k], gamma=table["gamma"][k], n=6)
        assert point["run"].item() == table["run"][k]
        assert point["outcome"].item() == table["outcome"][k]
    assert isinstance(ds, xr.Dataset)


def test_a_run_records_the_program_version_commit_and_scene(ladder):
    run = jl.simulate(alpha=55, n=8, t_end=500)
    r = run.record
    assert r["program"] == "ladder" and r["version"] == jl.__version__
    # The commit the CLI names (or none, for a build outside a clone).
    cli = ladder("--version").stdout
    assert (r["git_commit"] or "") in cli
    assert r["build"] == jl.ENGINE_VERSION
    assert r["scene"]["model"]["alpha"] == 55 and r["scene"]["model"]["n"] == 8
