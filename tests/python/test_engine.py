"""The package gives what the command line gives: the same numbers bit for
bit, the same files byte for byte, the same messages (docs/python.md)."""

import json
import math
from pathlib import Path

import numpy as np
import pytest

import jacobs_ladder as jl


def nan_list(values):
    """A JSON list with null for none, as floats with NaN."""
    return np.array([math.nan if v is None else v for v in values], dtype=float)


def same_bits(a, b):
    """Equal as float64 bit patterns (NaN equal to NaN)."""
    a = np.asarray(a, dtype=np.float64)
    b = np.asarray(b, dtype=np.float64)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


# ------------------------------------------------------------- simulate


@pytest.mark.parametrize(
    "flags, keywords",
    [
        # The paper's scheme and step, a kink; samples every 10 τ as --csv.
        (
            ["--integrator", "symplectic-euler", "--t-end", "2500"],
            dict(integrator="symplectic-euler", t_end=2500),
        ),
        # auto on an antikink with a second flip and its own N, b, γ.
        (
            ["--alpha", "-62", "--n", "12", "--b", "1.25", "--gamma", "0.03",
             "--flips", "0,1800", "--drive-time", "700", "--t-end", "3000",
             "--integrator", "auto"],
            dict(alpha=-62, n=12, b=1.25, gamma=0.03, flips=[0, 1800], drive_time=700,
                 t_end=3000, integrator="auto"),
        ),
    ],
)
def test_simulate_equals_the_cli_json_bit_for_bit(ladder_json, tmp_path, flags, keywords):
    csv = tmp_path / "theta.csv"
    cli = ladder_json("simulate", "--json", "--csv", csv, "--sample-every", "10", *flags)
    run = jl.simulate(**keywords, sample_every=10)
    assert same_bits(run.arrival_times, nan_list(cli["arrival_times"]))
    assert same_bits(run.final_theta_deg, cli["final_theta_deg"])
    # One shape for a run: the CLI's integrator report is the record's.
    assert run.integrator == cli["integrator"]
    # The CSV's samples (θ in degrees, 6 decimals) are the arrays' samples.
    rows = np.loadtxt(csv, delimiter=",", skiprows=1)
    assert same_bits(run.t, rows[:, 0])
    wrapped = np.degrees(np.angle(np.exp(1j * run.theta)))
    assert np.abs(wrapped - rows[:, 1:]).max() < 1e-6
    # Shapes: samples × N, N from the keywords.
    n = keywords.get("n", 10)
    assert run.theta.shape == (len(run.t), n) == run.x.shape == run.omega.shape
    assert run.arrival_times.shape == (n,)


def test_a_block_that_never_flips_is_nan(ladder_json):
    # Too short for the wave to reach the bottom: the last blocks never flip.
    # No samples on either side (a sample time is a stop the steps land on,
    # which changes the last bits).
    cli = ladder_json("simulate", "--json", "--integrator", "symplectic-euler", "--t-end", "900")
    run = jl.simulate(integrator="symplectic-euler", t_end=900, samples=[])
    assert run.t.shape == (0,) and run.theta.shape == (0, 10)
    assert None in cli["arrival_times"]
    assert np.isnan(run.arrival_times).sum() == cli["arrival_times"].count(None) > 0
    assert same_bits(run.arrival_times, nan_list(cli["arrival_times"]))


def test_the_arrays_equal_a_movie_data_file_bit_for_bit(ladder, tmp_path):
    """x, y and the arrival times of the run equal the frames the CLI's data
    file gives, for the same scene file; θ to the last bits of a degree."""
    scene_file = tmp_path / "py.toml"
    scene_file.write_text("[model]\nalpha = 70\nn = 8\n\n[run]\nt_end = 1600\n")
    out = tmp_path / "cli"
    ladder("render", scene_file, "--frames", "9", "--size", "128x96", "--out", out)
    data = json.loads((out / "movie-py.json").read_text())
    run_data = data["runs"][0]
    frames = run_data["frames"]
    scene = jl.Scene.from_toml(scene_file)
    run = scene.simulate(samples=[f["t"] for f in frames])
    assert same_bits(run.t, [f["t"] for f in frames])
    assert same_bits(run.x, [f["x"] for f in frames])
    assert same_bits(run.y, [f["y"] for f in frames])
    wrapped = np.degrees(np.angle(np.exp(1j * run.theta)))
    assert np.abs(wrapped - np.array([f["theta_deg"] for f in frames])).max() < 1e-9
    assert same_bits(run.arrival_times, nan_list(run_data["arrival_times"]))
    assert run.integrator == run_data["integrator"]


def test_the_run_says_what_it_is():
    run = jl.simulate(alpha=-60, n=6, t_end=1500, integrator="verlet", dt=0.05)
    text = repr(run)
    for part in ("antikink", "α = -60°", "N = 6", "verlet", "dt = 0.05"):
        assert part in text, text
    d = run.to_dict()
    for key in ("t", "theta", "x", "y", "vx", "vy", "omega", "arrival_times", "integrator", "waves"):
        assert key in d
    assert d["integrator"]["requested"] == "verlet"


def test_the_run_carries_the_waves_when_the_engine_reports_them():
    run = jl.simulate(n=8, t_end=2500)
    if "waves" not in run.record:
        assert run.waves is None
        return
    waves = run.waves
    assert len(waves) == 1, "one flip launches one wave"
    first = waves[0]
    # docs/sweeps.md: the top-level arrival times are the first wave's.
    assert same_bits(first["arrival_times"], run.arrival_times)
    assert first["kind"] == "kink"
    assert first["fate"] == "end"
    assert run.block_n is not None


# ----------------------------------------------------------------- errors


def test_bad_input_raises_value_error_naming_the_key():
    with pytest.raises(ValueError, match=r"^model\.alpha: must be degrees with 0 < \|alpha\| < 90, got 120$"):
        jl.simulate(alpha=120)
    with pytest.raises(ValueError, match="alpah"):
        jl.simulate(alpah=60)
    with pytest.raises(ValueError, match=r"^model\.n: invalid type"):
        jl.simulate(n="ten")
    with pytest.raises(ValueError, match="run.integrator"):
        jl.simulate(integrator="rk5")
    with pytest.raises(ValueError, match=r"drive\.flips\.1"):
        jl.simulate(flips=[0, 500], drive_time=1000)
    with pytest.raises(ValueError, match="unknown"):
        jl.Scene.builtin("no-such-figure")


def test_a_bad_scene_file_gives_the_cli_line(ladder, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[model]\nn = 20\nalpha = 120\n")
    cli = ladder("render", bad, "--out", tmp_path, check=False)
    assert cli.returncode == 2
    with pytest.raises(ValueError) as err:
        jl.Scene.from_toml(bad)
    assert "ladder: " + str(err.value) == cli.stderr.strip()
    assert str(err.value).endswith(": model.alpha: must be degrees with 0 < |alpha| < 90, got 120")


def test_a_failed_run_raises_run_error_with_a_hint():
    with pytest.raises(jl.RunError, match="diverged at t = .*hint"):
        jl.simulate(integrator="symplectic-euler", dt=3.0, t_end=500)
    assert issubclass(jl.RunError, RuntimeError)


# ------------------------------------------------------------------ scenes


def test_scenes_read_write_and_replace():
    four = jl.Scene.builtin("4", kind="movie")
    assert four.kind == "movie" and four.name == "4"
    text = four.to_toml()
    back = jl.Scene.from_toml(text)
    assert back.to_dict()["model"] == four.to_dict()["model"]
    k70 = four.replace(alpha=70, n=20, name="k70", **{"run.tolerance": 0.05})
    d = k70.to_dict()
    assert (d["model"]["alpha"], d["model"]["n"], d["run"]["tolerance"]) == (70, 20, 0.05)
    assert four.to_dict()["model"]["alpha"] != 70, "replace returns a copy"
    strip = k70.replace(output={"kind": "filmstrip", "times": [0, 500, 1000]})
    assert strip.kind == "figure"
    assert "k70" in repr(k70)


# What made a data file (the process's command line, the build): the
# Python call and the CLI differ there by nature; the rest is equal.
MADE_BY = {"command_line", "build", "git_commit"}


def same_file(name, mine, theirs):
    """Equal bytes, a data file's MADE_BY keys set aside."""
    if name.endswith(".json"):
        a, b = json.loads(mine), json.loads(theirs)
        return {k: v for k, v in a.items() if k not in MADE_BY} == {
            k: v for k, v in b.items() if k not in MADE_BY
        }
    return mine == theirs


def test_render_equals_the_cli_files(ladder, tmp_path):
    out = tmp_path / "cli"
    ladder("figure", "2d", "--format", "png,svg", "--out", out)
    scene = jl.Scene.builtin("2d")
    png = scene.render()
    assert isinstance(png, jl.Image) and png.name == "figure-2d.png"
    assert bytes(png) == (out / "figure-2d.png").read_bytes()
    assert png._repr_png_() == bytes(png)
    files = scene.render(format=["png", "svg"], data=True)
    assert set(files) == {p.name for p in out.iterdir()}
    for name, blob in files.items():
        assert same_file(name, bytes(blob), (out / name).read_bytes()), name
    assert files["figure-2d.svg"]._repr_svg_().lstrip().startswith("<")


def test_save_writes_what_the_cli_writes(ladder, tmp_path):
    scene_file = tmp_path / "py.toml"
    scene_file.write_text("[model]\nalpha = 65\nn = 6\n\n[run]\nt_end = 1500\n")
    cli, mine = tmp_path / "cli", tmp_path / "py"
    ladder("render", scene_file, "--frames", "6", "--size", "96x64", "--out", cli)
    paths = jl.Scene.from_toml(scene_file).save(mine, frames=6, size=(96, 64))
    assert sorted(p.name for p in paths) == sorted(p.name for p in cli.iterdir())
    for p in cli.iterdir():
        assert same_file(p.name, (mine / p.name).read_bytes(), p.read_bytes()), p.name
    movie = jl.Scene.from_toml(scene_file).render(frames=6, size="96x64")
    assert isinstance(movie, jl.Files)
    assert bytes(movie["movie-py.gif"]) == (cli / "movie-py.gif").read_bytes()
    assert "data:image/gif;base64," in movie._repr_html_()


# ------------------------------------------------------- sweep and theory


def test_sweep_equals_the_cli_csv(ladder, tmp_path):
    ladder("sweep", "--alpha", "55,70", "--gamma", "0.02,0.04", "--n", "8",
           "--name", "py", "--out", tmp_path)
    # Keywords in another order than the flags: the grid is the CLI's.
    table = jl.sweep(gamma=[0.02, 0.04], n=8, alpha=[55, 70], name="py")
    assert table.csv == (tmp_path / "sweep-py.csv").read_text()
    assert len(table) == 4
    assert all(len(v) == 4 for v in table.values())
    assert list(table.columns[:3]) == ["run", "alpha", "n"]
    assert set(table["outcome"]) <= {"propagated", "stalled", "pinned", "diverged", "undecided"}
    assert same_bits(table["alpha"], [55, 55, 70, 70])
    # The JSON too, but for its list of files (the CLI's has the chart).
    cli_json = json.loads((tmp_path / "sweep-py.json").read_text())
    assert len(cli_json["runs"]) == 4
    skip = MADE_BY | {"files"}
    assert {k: v for k, v in table.json.items() if k not in skip} == {
        k: v for k, v in cli_json.items() if k not in skip
    }


def test_sweep_table_reads_per_wave_and_block_n_columns():
    """At α = 40° the free block N falls over on its own and launches a
    second wave, so the CSV has per-wave columns (kinds and fates are
    words); block N's turn is a time there and NaN at 60°."""
    table = jl.sweep(alpha=[40, 60], n=10, integrator="verlet", dt=0.25)
    assert list(table["front"]) == [9, 9]
    assert list(table["waves"]) == [2, 1]
    assert table["block_n_turned_at"][0] < 500 and np.isnan(table["block_n_turned_at"][1])
    assert list(table["wave1_kind"]) == ["antikink", "kink"]
    assert list(table["wave2_kind"]) == ["kink", ""]
    assert table["wave1_fate"][0] == "annihilated" and table["wave2_front"][1] == -1


def test_sweep_to_pandas():
    pd = pytest.importorskip("pandas", reason="pandas is not installed: to_pandas untested")
    table = jl.sweep(alpha="60:70:10", n=6)
    frame = table.to_pandas()
    assert list(frame.columns) == table.columns and len(frame) == 2


def test_theory_equals_the_cli_json(ladder_json):
    for alpha in (60, -45.5, 90):
        assert jl.theory(alpha=alpha, n=12) == ladder_json(
            "theory", "--json", "--alpha", alpha, "--n", 12
        )


def test_catalogue_lists_the_builtin_scenes(ladder):
    ids = [i for i, _, _ in jl.catalogue()]
    assert "3" in ids and "S5" in ids
    for i, kind, _ in jl.catalogue()[:3]:
        assert jl.Scene.builtin(i, kind=kind).kind == kind


def test_import_does_not_load_numpy_until_an_array_is_made():
    """`import jacobs_ladder` stays light (numpy alone takes ~120 ms to
    import): numpy is loaded by the first call that makes an array."""
    import subprocess
    import sys

    code = (
        "import sys, jacobs_ladder as jl\n"
        "assert 'numpy' not in sys.modules, 'numpy imported by import jacobs_ladder'\n"
        "run = jl.simulate(integrator='symplectic-euler', t_end=600)\n"
        "assert 'numpy' in sys.modules and run.theta.shape[1] == 10\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)
