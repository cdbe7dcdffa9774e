"""One version everywhere (jl.__version__, `ladder --version`, the data
files), and a sweep's table as an xarray Dataset over its grid."""

import pickle
import re
from pathlib import Path

import pytest

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


# ------------------------------------------------ tables: provenance, types


def test_a_tables_provenance_reaches_pandas_xarray_netcdf_and_its_csv(ladder, tmp_path):
    xr = needed("xarray")
    pd = needed("pandas")
    table = jl.sweep(alpha=[55, 65], gamma=[0.01, 0.02], n=6, name="prov")
    p = table.provenance
    cli = ladder("--version").stdout
    assert p["program"] == "ladder" and p["version"] == jl.__version__
    assert p["build"] == jl.ENGINE_VERSION and p["git_commit"] in cli
    assert '"name": "prov"' in p["scene"] and p["fingerprint"] == table.json["fingerprint"]
    assert p["command"].startswith("jacobs_ladder.sweep(alpha=[55, 65], gamma=[0.01, 0.02], n=6")
    ds = table.to_xarray()
    assert ds.attrs == p
    needed("scipy")  # xarray's netCDF writer without netCDF4
    ds.to_netcdf(tmp_path / "t.nc")
    with xr.open_dataset(tmp_path / "t.nc") as back:
        assert back.attrs["version"] == jl.__version__
        assert back.attrs["command"] == p["command"]
    assert table.to_pandas().attrs == p
    text = table.to_csv(tmp_path / "t.csv")
    assert text.startswith("# program: ladder\n# version: " + jl.__version__)
    assert text.endswith(table.csv)
    df = pd.read_csv(tmp_path / "t.csv", comment="#")
    assert list(df.columns) == table.columns and len(df) == len(table)


def test_table_columns_are_the_engines_at_full_precision():
    """Before: the columns were parsed from the CSV (speed to 6 digits,
    0.00772892 where the run's speed is 0.007728914214276395), and their
    types guessed from their names."""
    table = jl.sweep(alpha=[60, -60], n=10)
    runs = table.json["runs"]
    for k, r in enumerate(runs):
        assert table["speed"][k] == r["speed"]  # every bit
    assert any(float(f"{s:.6g}") != s for s in table["speed"])
    assert table["n"].dtype.kind == "i" and table["run"].dtype.kind == "i"
    assert table["alpha"].dtype.kind == "f" and table["outcome"].dtype.kind == "U"
    again = pickle.loads(pickle.dumps(table))
    assert all(again[c].tobytes() == table[c].tobytes() for c in table)
    assert again.command == table.command


def test_outcomes_and_sweep_parameters_are_the_engines():
    """Before: the Table's docstring listed 5 outcomes of 7, and
    SWEEP_PARAMETERS was a copy."""
    assert len(jl.OUTCOMES) == 7 and {"annihilated", "failed"} <= set(jl.OUTCOMES)
    table = jl.sweep(alpha=[60], n=6)
    rule = table.json["rule"]["description"]
    assert all(o in rule for o in jl.OUTCOMES)
    assert set(table["outcome"]) <= set(jl.OUTCOMES)
    header = table.csv.splitlines()[0].split(",")
    assert tuple(header[1 : 1 + len(jl.SWEEP_PARAMETERS)]) == jl.SWEEP_PARAMETERS


def test_the_grid_keywords_vary_in_the_engines_order():
    table = jl.sweep(gamma=[0.01, 0.02], alpha=[55, 65], n=6)
    assert [a["param"] for a in table.json["axes"]] == ["alpha", "n", "gamma"]
    with pytest.raises(ValueError, match="^sweep needs at least one grid keyword: alpha, n"):
        jl.sweep(t_end=100)
