//! One wave speed, consistent counts and outcome words that say what the
//! driven wave did, and a sweep point that cannot start kept
//! as a `failed` outcome: checked through every front end that
//! reports them (`simulate --json`, a run's data, figure S6's legend, a
//! sweep's CSV and JSON).

use jacobs_ladder::catalog;
use jacobs_ladder::scene::Kind;
use jacobs_ladder::scene::{self, Scene};
use jacobs_ladder::scenes;
use jacobs_ladder::sweep::outcome::{self, Outcome};
use std::path::PathBuf;
use std::process::Output;

use crate::common::ladder_cli as ladder;

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ladder-speed-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn ok(out: &Output) -> String {
    assert!(
        out.status.success(),
        "exit {:?}: {}",
        out.status.code(),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The CSV's rows as maps of column → cell.
fn rows(csv: &str) -> Vec<std::collections::BTreeMap<String, String>> {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    lines
        .map(|l| {
            header
                .iter()
                .zip(l.split(','))
                .map(|(h, c)| (h.to_string(), c.to_string()))
                .collect()
        })
        .collect()
}

/// Least squares of t against n over blocks `from`..N−1, written here
/// from the definition (docs/sweeps.md, "The wave speed").
fn fit(arrivals: &[Option<f64>], from: usize) -> f64 {
    let pts: Vec<(f64, f64)> = (from - 1..arrivals.len() - 1)
        .filter_map(|i| arrivals[i].map(|t| (i as f64 + 1.0, t)))
        .collect();
    let k = pts.len() as f64;
    let mx = pts.iter().map(|p| p.0).sum::<f64>() / k;
    let my = pts.iter().map(|p| p.1).sum::<f64>() / k;
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    sxx / sxy
}

#[test]
fn one_wave_speed_and_one_count_at_60_degrees() {
    // simulate --json: the paper's run.
    let json: serde_json::Value =
        serde_json::from_str(&ok(&ladder(&["simulate", "--json"]))).unwrap();
    let arrivals: Vec<Option<f64>> = serde_json::from_value(json["arrival_times"].clone()).unwrap();
    let speed = json["speed"]
        .as_f64()
        .expect("simulate --json states the speed");
    // Blocks 3..N−1, not 2..N−1 (0.007543 there: it follows the drive).
    assert!((speed - fit(&arrivals, 3)).abs() < 1e-12 * speed, "{speed}");
    assert!((speed - fit(&arrivals, 2)).abs() > 1e-4, "{speed}");
    assert_eq!(json["blocks_flipped"], 9, "blocks 1..N−1, block N apart");

    // The library's run record (Python's Run.record is this), with the
    // integrator simulate uses.
    let mut scene = Scene {
        output: scene::OutputSpec::Data,
        ..Scene::default()
    };
    scene.run.integrator = "symplectic-euler".parse().unwrap();
    scene.run.dt = Some(0.01);
    let run = scenes::run::simulate(&scene, &[]).unwrap();
    let data = scenes::RunData::from_run(&scene, &run);
    assert_eq!(data.speed, Some(speed));
    assert_eq!(data.blocks_flipped, 9);

    // Figure S6: the α = 60° kink's legend and fitted line.
    let s6 = catalog::find(Kind::Figure, "S6").unwrap().scene.clone();
    let (spec, runs) = scenes::arrivals::arrivals_chart(&s6).unwrap();
    let d60 = runs.iter().find(|d| d.model.alpha == 60.0).unwrap();
    assert_eq!(d60.speed, outcome::wave_speed(&d60.arrival_times));
    let want = format!("{:.1} blocks/1000τ", 1000.0 * d60.speed.unwrap());
    assert!(
        spec.series
            .iter()
            .any(|s| s.label.as_deref().is_some_and(|l| l.contains(&want))),
        "no legend says {want}"
    );

    // A sweep of the same run (same integrator and step): the same speed
    // (6 significant digits) and count.
    let dir = tmp("60");
    let d = dir.to_str().unwrap();
    ok(&ladder(&[
        "sweep",
        "--alpha",
        "60",
        "--integrator",
        "symplectic-euler",
        "--dt",
        "0.01",
        "--name",
        "s",
        "--out",
        d,
    ]));
    let csv = std::fs::read_to_string(dir.join("sweep-s.csv")).unwrap();
    let row = &rows(&csv)[0];
    let swept: f64 = row["speed"].parse().unwrap();
    assert!((swept - speed).abs() < 1e-5 * speed, "{swept} vs {speed}");
    assert_eq!(row["blocks_flipped"], "9");
    assert_eq!(row["outcome"], "propagated");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_kink_annihilated_by_block_n_s_wall_is_not_propagated() {
    // α = 40°: block N falls over at 136 τ and its wall meets the driven
    // kink at block 3; every block ends flipped.
    let json: serde_json::Value =
        serde_json::from_str(&ok(&ladder(&["simulate", "--alpha", "40", "--json"]))).unwrap();
    let driven = json["waves"]["waves"]
        .as_array()
        .unwrap()
        .iter()
        .find(|w| w["origin"] == 1)
        .unwrap();
    assert_eq!(driven["fate"], "annihilated");
    let dir = tmp("40");
    let d = dir.to_str().unwrap();
    ok(&ladder(&[
        "sweep",
        "--alpha",
        "40,60",
        "--integrator",
        "verlet",
        "--dt",
        "0.25",
        "--name",
        "a",
        "--out",
        d,
    ]));
    let csv = std::fs::read_to_string(dir.join("sweep-a.csv")).unwrap();
    let r = rows(&csv);
    assert_eq!(r[0]["outcome"], "annihilated", "{csv}");
    assert_eq!(r[0]["front"], "9", "the chain still ends flipped");
    assert_eq!(r[0]["speed"], "", "no speed from walls of both ends");
    assert_eq!(r[1]["outcome"], "propagated", "{csv}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// α = 44..48°, N = 10, `start = "relaxed"`: at 46° the relaxation finds
/// no hanging equilibrium (docs/sweeps.md, "Spontaneous flips").
const RELAXED: &str = r#"
name = "relaxed"
[model]
start = "relaxed"
[run]
integrator = "verlet"
dt = 0.25
[output]
kind = "sweep"
[output.grid]
alpha = ["44:48:1"]
"#;

#[test]
fn a_point_that_cannot_start_is_failed_and_the_others_are_kept() {
    let dir = tmp("failed");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("relaxed.toml");
    std::fs::write(&file, RELAXED).unwrap();
    let out = dir.join("out");
    let o = ladder(&[
        "sweep",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    ok(&o);
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("1 failed"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let csv = std::fs::read_to_string(out.join("sweep-relaxed.csv")).unwrap();
    let r = rows(&csv);
    assert_eq!(r.len(), 5, "{csv}");
    for row in &r {
        let failed = row["alpha"] == "46";
        assert_eq!(row["outcome"] == "failed", failed, "{csv}");
        if failed {
            assert_eq!(row["t_decided"], "");
            assert_eq!(row["speed"], "");
        }
    }
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("sweep-relaxed.json")).unwrap())
            .unwrap();
    let run = &json["runs"][2];
    assert_eq!(run["outcome"], "failed");
    assert!(
        run["message"]
            .as_str()
            .unwrap()
            .contains("did not converge"),
        "{run}"
    );
    assert_eq!(json["outcomes"]["failed"], 1);
    // Kept in the shard file too: a rerun resumes all five.
    let again = ladder(&[
        "sweep",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    ok(&again);
    assert!(
        String::from_utf8_lossy(&again.stderr).contains("5 of 5 runs already done"),
        "{}",
        String::from_utf8_lossy(&again.stderr)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_library_keeps_the_chunk_of_a_failing_point() {
    let base = jacobs_ladder::scene::file::parse(RELAXED, "relaxed.toml", "relaxed").unwrap();
    let plan = jacobs_ladder::sweep::Plan::new(&base, 10).unwrap().unwrap();
    let all: Vec<usize> = (0..plan.len()).collect();
    let records = plan
        .run(&all, &|| {})
        .expect("one failing point fails no chunk");
    let words: Vec<Outcome> = records.iter().map(|r| r.result.outcome).collect();
    assert_eq!(words.len(), 5);
    assert_eq!(words[2], Outcome::Failed);
    assert!(words.iter().filter(|o| **o == Outcome::Failed).count() == 1);
}
