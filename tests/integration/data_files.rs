//! Every data file records what reproduces it: the scene with
//! every value, the settings it was drawn with, the command line, the
//! program's version and git commit. The proof: a scene file made from a
//! data file's recorded scene, rendered with its recorded settings, gives
//! the same numbers. And the kymograph's matrix is in the data file, equal
//! to sin θ of the frames it is drawn from.

use crate::common::tempdir::TempDir;
use jacobs_ladder::scene::{self, Scene};
use serde_json::Value;
use std::path::Path;
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_ladder");

fn ladder(args: &[String]) -> std::process::Output {
    let out = Command::new(BIN).args(args).output().unwrap();
    assert!(
        out.status.success(),
        "ladder {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

fn words(args: &[&str]) -> Vec<String> {
    args.iter().map(|s| s.to_string()).collect()
}

fn json(path: &Path) -> Value {
    serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap()
}

/// The recorded scene of a data file written back as a scene file.
fn scene_file(data: &Value, dir: &TempDir, name: &str) -> String {
    let scene: Scene = serde_json::from_value(data["scene"].clone()).unwrap();
    dir.file(name, &scene::file::to_toml(&scene).unwrap())
}

/// The program and command recorded in `data`, checked against `args`.
fn check_made_by(data: &Value, args: &[String]) {
    assert_eq!(data["program"], "ladder");
    assert_eq!(data["version"], env!("CARGO_PKG_VERSION"));
    assert!(
        data["build"]
            .as_str()
            .unwrap()
            .starts_with(env!("CARGO_PKG_VERSION")),
        "{}",
        data["build"]
    );
    // null outside a clone; the commit's hex digits inside one.
    match &data["git_commit"] {
        Value::Null => assert!(jacobs_ladder::version::GIT_COMMIT.is_none()),
        Value::String(c) => {
            assert_eq!(Some(c.as_str()), jacobs_ladder::version::GIT_COMMIT);
            assert!(c.len() >= 7 && c.chars().take(7).all(|ch| ch.is_ascii_hexdigit()));
        }
        other => panic!("git_commit: {other}"),
    }
    let recorded: Vec<String> = data["command_line"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap().to_string())
        .collect();
    assert_eq!(recorded[0], BIN, "the program as called");
    assert_eq!(&recorded[1..], args, "every word of the command line");
}

#[test]
fn a_movie_s_data_file_reruns_to_the_same_numbers() {
    let dir = TempDir::new("data-movie");
    let (a, b) = (dir.join("a"), dir.join("b"));
    let args = words(&[
        "movie",
        "--alpha",
        "70",
        "--n",
        "8",
        "--gamma",
        "0.02",
        "--t-end",
        "900",
        "--frames",
        "12",
        "--size",
        "320x240",
        "--fps",
        "10",
        "--name",
        "k",
        "--out",
        a.to_str().unwrap(),
    ]);
    ladder(&args);
    let data = json(&a.join("movie-k.json"));
    check_made_by(&data, &args);
    let m = &data["settings"]["movie"];
    assert_eq!(m["frames"], 12);
    assert_eq!(
        (m["width"].clone(), m["height"].clone()),
        (320.into(), 240.into())
    );
    assert_eq!(m["fps"], 10.0);
    assert_eq!(m["formats"], serde_json::json!(["gif"]));
    assert_eq!(m["mp4_quality"], "high");
    // Every value of the scene, defaults included.
    for key in ["alpha", "n", "b", "gamma", "gravity", "inertia"] {
        assert!(data["scene"]["model"][key].is_number(), "{key}");
    }
    assert_eq!(data["scene"]["model"]["gamma"], 0.02);

    // Rerun from the record alone: the scene as a file, the settings as flags.
    let file = scene_file(&data, &dir, "movie-k.toml");
    let size = format!("{}x{}", m["width"], m["height"]);
    let rerun = words(&[
        "render",
        &file,
        "--frames",
        &m["frames"].to_string(),
        "--size",
        &size,
        "--fps",
        &m["fps"].to_string(),
        "--out",
        b.to_str().unwrap(),
    ]);
    ladder(&rerun);
    let again = json(&b.join("movie-k.json"));
    assert_eq!(again["scene"], data["scene"]);
    assert_eq!(again["settings"], data["settings"]);
    assert_eq!(again["runs"], data["runs"], "the same numbers");
    assert_eq!(
        std::fs::read(a.join("movie-k.gif")).unwrap(),
        std::fs::read(b.join("movie-k.gif")).unwrap(),
        "the same movie"
    );

    // The kymograph's matrix: one row per frame, sin θ of the frame's
    // angles.
    let run = &data["runs"][0];
    let k = &run["kymograph"];
    let frames = run["frames"].as_array().unwrap();
    assert_eq!(k["times"].as_array().unwrap().len(), 12);
    let rows = k["sin_theta"].as_array().unwrap();
    assert_eq!(rows.len(), frames.len());
    for (row, frame) in rows.iter().zip(frames) {
        assert_eq!(k["times"][0], frames[0]["t"]);
        let row = row.as_array().unwrap();
        let theta = frame["theta_deg"].as_array().unwrap();
        assert_eq!(row.len(), 8);
        for (s, th) in row.iter().zip(theta) {
            let expect = th.as_f64().unwrap().to_radians().sin();
            assert!(
                (s.as_f64().unwrap() - expect).abs() < 1e-12,
                "{s} vs sin {th}°"
            );
        }
    }
    // Row 0 is the ground state at α = 70°: sin 70° on every block.
    for v in rows[0].as_array().unwrap() {
        assert!((v.as_f64().unwrap() - 70f64.to_radians().sin()).abs() < 1e-9);
    }
}

#[test]
fn a_kymograph_figure_records_its_matrix_and_settings() {
    let dir = TempDir::new("data-kymo");
    let args = words(&[
        "figure",
        "--view",
        "kymograph",
        "--alpha",
        "60",
        "--n",
        "6",
        "--t-end",
        "400",
        "--format",
        "png,svg",
        "--name",
        "ky",
        "--out",
        dir.path().to_str().unwrap(),
    ]);
    ladder(&args);
    let data = json(&dir.join("figure-ky.json"));
    check_made_by(&data, &args);
    assert_eq!(
        data["settings"]["figure"]["formats"],
        serde_json::json!(["png", "svg"])
    );
    assert_eq!(data["settings"]["figure"]["scale"], 1.0);
    assert!(data["settings"].get("movie").is_none());
    let k = &data["runs"][0]["kymograph"];
    let rows = k["sin_theta"].as_array().unwrap();
    assert!(rows.len() > 100, "the figure's rows: {}", rows.len());
    assert!(rows.iter().all(|r| r.as_array().unwrap().len() == 6));
    // Row 0 is the ground state at α = 60°: sin 60° everywhere.
    for s in rows[0].as_array().unwrap() {
        assert!((s.as_f64().unwrap() - 60f64.to_radians().sin()).abs() < 1e-9);
    }
}

#[test]
fn simulate_json_and_a_data_scene_rerun_to_the_same_numbers() {
    let dir = TempDir::new("data-sim");
    let args = words(&[
        "simulate", "--alpha", "-55", "--n", "6", "--t-end", "700", "--json",
    ]);
    let out = ladder(&args);
    let report: Value = serde_json::from_slice(&out.stdout).unwrap();
    check_made_by(&report, &args);
    assert_eq!(report["scene"]["model"]["alpha"], -55.0);
    // The recorded scene is a data scene: `ladder render` reruns it.
    let file = scene_file(&report, &dir, "sim.toml");
    let out_dir = dir.join("out");
    let rerun = words(&["render", &file, "--out", out_dir.to_str().unwrap()]);
    ladder(&rerun);
    let name = report["scene"]["name"].as_str().unwrap().to_string();
    let found: Vec<_> = std::fs::read_dir(&out_dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    assert_eq!(found.len(), 1, "one data file: {found:?} ({name})");
    let data = json(&found[0]);
    check_made_by(&data, &rerun);
    let run = &data["runs"][0];
    assert_eq!(run["arrival_times"], report["arrival_times"]);
    assert_eq!(run["final_theta_deg"], report["final_theta_deg"]);
    assert_eq!(run["waves"], report["waves"]);
    assert!(data["settings"].get("movie").is_none() && data["settings"].get("figure").is_none());
}

/// A sweep's data file records the program and its build, and no command
/// line: its bytes depend on the sweep only (not on the folder, the
/// program's path or the shards); its scene reruns it.
#[test]
fn a_sweep_s_data_file_records_its_program_but_no_command_line() {
    let dir = TempDir::new("data-sweep");
    let args = words(&[
        "sweep",
        "--alpha",
        "60,70",
        "--n",
        "4",
        "--name",
        "rec",
        "--out",
        dir.path().to_str().unwrap(),
    ]);
    ladder(&args);
    let data = json(&dir.join("sweep-rec.json"));
    assert_eq!(data["program"], "ladder");
    assert_eq!(data["version"], env!("CARGO_PKG_VERSION"));
    assert_eq!(data["command_line"], serde_json::json!([]));
    assert_eq!(data["scene"]["name"], "rec");
    assert_eq!(data["runs"].as_array().unwrap().len(), 2, "α = 60°, 70°");
}

/// A data file past its cap (docs/limits.md) is refused before any work,
/// with the flag that raises it, and nothing is written: a 400-row
/// kymograph of N = 100,000 is an estimated 6.4 GB of JSON.
#[test]
fn a_data_file_past_the_cap_is_refused_with_its_flag() {
    let dir = TempDir::new("data-cap");
    let out = dir.join("out");
    let args = words(&[
        "figure",
        "--view",
        "kymograph",
        "--n",
        "100000",
        "--t-end",
        "10",
        "--name",
        "big",
        "--out",
        out.to_str().unwrap(),
    ]);
    let start = std::time::Instant::now();
    let o = Command::new(BIN).args(&args).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("bytes") && err.contains("--max-data-bytes") && err.contains("figure big"),
        "{err}"
    );
    assert!(start.elapsed().as_secs() < 20, "refused before the run");
    let written: Vec<_> = std::fs::read_dir(&out)
        .map(|d| d.map(|e| e.unwrap().file_name()).collect())
        .unwrap_or_default();
    assert!(written.is_empty(), "{written:?}");
}
