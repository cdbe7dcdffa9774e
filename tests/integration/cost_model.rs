//! One cost model per force path (`sim::cost`, docs/limits.md), read by
//! every check before work: a run's steps × N are weighed by what its
//! path costs a block-step, a figure's runs are checked together, a run
//! with its "stiff" links' second run is one cost, the studies of `bench`
//! are weighed, and a sweep rendered from a scene file counts its files
//! after each chunk.

use crate::common::tempdir::TempDir;
use std::process::Output;
use std::time::{Duration, Instant};

const TANK: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/assets/scenes/movie-water-tank.toml"
);

fn ladder(args: &[&str]) -> (Output, Duration) {
    let start = Instant::now();
    let out = crate::common::ladder_cli(args);
    (out, start.elapsed())
}

/// Exit 2 within `limit`, one line on stderr, nothing on stdout, every
/// needle in the line; the line.
fn refused(args: &[&str], limit: Duration, needles: &[&str]) -> String {
    let (out, took) = ladder(args);
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(
        took < limit,
        "{args:?} took {took:?}: not refused before work"
    );
    assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?} printed a result");
    for n in needles {
        assert!(err.contains(n), "{args:?}: no '{n}' in: {err}");
    }
    err
}

/// The tank by RK4 at N = 100 000 is 2.6 × 10⁹ steps × N: under the cap
/// counted plainly, which let it start (hours of computing); weighed by
/// its path (RK4 with added mass and drag, about 20 times the paper's
/// Verlet a block-step) it is refused at once, with its weight and time.
#[test]
fn the_tank_at_n_100000_by_rk4_is_refused_before_work() {
    refused(
        &[
            "simulate",
            "--apparatus",
            TANK,
            "--n",
            "100000",
            "--integrator",
            "rk4",
            "--dt",
            "0.125",
        ],
        Duration::from_secs(5),
        &[
            "--max-block-steps",
            "rk4 with added mass and drag",
            "of computing",
        ],
    );
}

/// The linkage's figure with a window of 2000 s and a motor that never
/// ends (at 10⁵ s, its reproducer, one run alone is past the cap): each
/// of its 26 runs (13 μ_p its refinement may reach, kink and
/// antikink) alone passes the cap, together they are refused by `render
/// --check` and by `render`, before any run; `render --check` counts
/// every run the figure may make.
#[test]
fn an_experiment_figures_runs_are_checked_together() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/assets/scenes/figure-linkage-friction.toml"
    ))
    .unwrap();
    let dir = TempDir::new("cost-linkage");
    let shipped = dir.path().join("shipped.toml");
    std::fs::write(&shipped, &text).unwrap();
    let (out, _) = ladder(&["render", "--check", shipped.to_str().unwrap()]);
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{said}");
    assert!(said.contains("(26 runs)"), "{said}");
    let long = text
        .replace("duration = 20.0", "duration = 2000.0")
        .replace("motor = 0.2", "motor = 1e-9");
    assert_ne!(long, text);
    let file = dir.path().join("long.toml");
    std::fs::write(&file, long).unwrap();
    let f = file.to_str().unwrap();
    let out_dir = dir.path().join("out");
    let o = out_dir.to_str().unwrap();
    for args in [vec!["render", "--check", f], vec!["render", f, "--out", o]] {
        refused(
            &args,
            Duration::from_secs(10),
            &["the 26 runs of figure", "together", "--max-block-steps"],
        );
        assert!(!out_dir.join("figure-linkage-friction.png").exists());
    }
}

/// The "stiff" links' check is a second run (2k, √2 more steps over the
/// same seconds), one cost with the first: with a cap the first run
/// passes alone (about 5.2 × 10⁶ block-steps of the paper's model) and
/// the two do not (about 1.2 × 10⁷), the command is refused before any
/// run, naming both runs and no window of the second run in τ (4574.7,
/// which the user never gave).
#[test]
fn the_stiff_links_second_run_is_one_cost_with_the_first() {
    let base = [
        "simulate",
        "--apparatus",
        TANK,
        "--integrator",
        "rk4",
        "--dt",
        "0.125",
    ];
    let mut args = base.to_vec();
    args.extend(["--max-block-steps", "8e6"]);
    let err = refused(
        &args,
        Duration::from_secs(5),
        &["\"stiff\" links' check", "the run, ", "--max-block-steps"],
    );
    assert!(!err.contains("4574"), "{err}");
    // Below the first run's own cost: refused by it, no t_end of the
    // second run either.
    let mut args = base.to_vec();
    args.extend(["--max-block-steps", "800000"]);
    let err = refused(&args, Duration::from_secs(5), &["--max-block-steps"]);
    assert!(!err.contains("4574"), "{err}");
    // And under a cap that holds both, it runs.
    let mut args = base.to_vec();
    args.extend(["--max-block-steps", "2e7"]);
    let (out, _) = ladder(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// `bench work-precision` on the tank with a window of 10⁶ τ is refused
/// before any run, its runs weighed by their path.
#[test]
fn bench_studies_are_weighed_by_their_path() {
    let dir = TempDir::new("cost-bench");
    refused(
        &[
            "bench",
            "work-precision",
            "--scene",
            "water-tank",
            "--t-end",
            "1e6",
            "--out",
            dir.path().to_str().unwrap(),
        ],
        Duration::from_secs(10),
        &["weighed by each run's force path", "--max-block-steps"],
    );
}

/// `auto` on the tank in air (undamped): its first pair of runs is
/// weighed by RK4's path with the tank's terms, so a cap over their plain
/// steps × N (4.6 × 10⁵: 12 941 + 25 882 steps × N = 11, with the stops)
/// but under their weighed cost refuses it at once, before any run.
#[test]
fn autos_budget_is_weighed_by_the_path() {
    refused(
        &[
            "simulate",
            "--apparatus",
            TANK,
            "--medium",
            "air",
            "--integrator",
            "auto",
            "--max-block-steps",
            "1e6",
        ],
        Duration::from_secs(5),
        &["rk4 with added mass and drag", "--max-block-steps"],
    );
}

/// A sweep scene rendered (`ladder render FILE`) whose runs take many
/// times the bytes estimated (about 31 waves a run where 3 are assumed)
/// stops after the first chunk that passes `--max-data-bytes`, not after
/// all 151 runs, and writes nothing.
#[test]
fn a_rendered_sweep_stops_after_the_chunk_that_passes_the_data_cap() {
    let dir = TempDir::new("cost-sweep");
    let file = dir.path().join("m.toml");
    std::fs::write(
        &file,
        r#"
name = "m"
[model]
n = 40
gravity = 3e-3
gamma = 0.002
[run]
integrator = "verlet"
dt = 0.1
[output]
kind = "sweep"
[output.grid]
alpha = ["15:30:0.1"]
"#,
    )
    .unwrap();
    let out_dir = dir.path().join("out");
    let err = refused(
        &[
            "render",
            file.to_str().unwrap(),
            "--max-data-bytes",
            "3e6",
            "--out",
            out_dir.to_str().unwrap(),
        ],
        Duration::from_secs(60),
        &["runs done so far of 151", "--max-data-bytes"],
    );
    let done: usize = err
        .split(" runs done so far")
        .next()
        .and_then(|s| s.rsplit(' ').next())
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("no count in: {err}"));
    assert!(done < 151, "stopped only after {done} runs: {err}");
    let written: Vec<_> = std::fs::read_dir(&out_dir)
        .map(|d| d.filter_map(|e| e.ok()).map(|e| e.file_name()).collect())
        .unwrap_or_default();
    assert!(
        !written
            .iter()
            .any(|n| n.to_string_lossy().ends_with(".json")),
        "{written:?}"
    );
}
