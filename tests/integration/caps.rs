//! Costs checked before work: the worst case of
//! `auto`'s halvings and the cost of every theory figure are estimated and
//! refused before any work, naming the flag that raises the cap, in
//! `render` and in `render --check` alike; the catalogue passes the
//! default caps.

use crate::common::tempdir::TempDir;
use jacobs_ladder::limits::Limits;
use jacobs_ladder::scenes::{self, MovieOptions, Outputs};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// Runs ladder with `args`, killing it after `limit` (then `None`): a
/// refusal before work answers at once, while the old code computed for
/// minutes.
fn ladder_within(args: &[&str], limit: Duration) -> Option<Output> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the ladder binary runs");
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    Some(child.wait_with_output().unwrap())
}

/// Exit 2, one line, every needle in it, within `limit`.
fn refused(args: &[&str], limit: Duration, needles: &[&str]) {
    let out = ladder_within(args, limit)
        .unwrap_or_else(|| panic!("{args:?}: still computing after {limit:?}, not refused"));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: '{n}' not in {err}");
    }
}

/// The `[output]` table of a theory figure at `n` blocks.
fn theory_scene(dir: &TempDir, name: &str, figure: &str, n: usize, lists: &str) -> String {
    let text = format!(
        "name = \"{name}\"\n[model]\nn = {n}\n[output]\nkind = \"theory\"\nfigure = \"{figure}\"\n{lists}\n"
    );
    let p = dir.join(format!("{name}.toml"));
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_string()
}

/// `auto` halves its step up to 10 times, each run twice as long as the
/// last: every halving would be 2047 times the first run. The old code
/// costed each run alone, as it came, so it could compute for minutes and
/// then refuse. Now its budget is set before any run: the first pair must
/// fit under the cap (else it is refused at once, naming the flag), and
/// only the halvings that keep the total under the cap are made; a run
/// that needs more ends with the cap's error, never past the cap.
/// At N = 10, t_end = 4000, the runs at dt = 0.25 and 0.125 are 1.6 × 10^5
/// and 3.2 × 10^5 steps × N; the next, at 0.0625, 6.4 × 10^5.
#[test]
fn autos_halvings_are_budgeted_before_the_first_run() {
    // The first pair, 4.8e5, is past a cap of 4e5: refused before work.
    refused(
        &[
            "simulate",
            "--integrator",
            "auto",
            "--max-block-steps",
            "4e5",
        ],
        Duration::from_secs(20),
        &["--max-block-steps", "auto", "first two runs", "480060"],
    );
    // A cap of 1e6 allows the first pair but not the next halving
    // (4.8e5 + 6.4e5 = 1.12e6): a tolerance no pair meets ends after the
    // first pair (at dt = 0.25 and 0.125), naming what the next halving
    // would need.
    refused(
        &[
            "simulate",
            "--integrator",
            "auto",
            "--tolerance",
            "1e-6",
            "--max-block-steps",
            "1e6",
        ],
        Duration::from_secs(20),
        &[
            "--max-block-steps",
            "one more halving",
            "1.1e6",
            "dt = 0.125 τ",
        ],
    );
    // The same cap with the default tolerance: the first pair verifies.
    let args = [
        "simulate",
        "--integrator",
        "auto",
        "--max-block-steps",
        "1e6",
    ];
    let out = ladder_within(&args, Duration::from_secs(120)).expect("runs");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// A ground-states drawing at N = 100,000 took about a quarter of an hour
/// (quadratic in N) before any cap; the zero-mode figure at N = 20,000
/// would fill 19 GB with a dense matrix (48 N² bytes). Both are refused at
/// once, by `render` and by `render --check` alike.
#[test]
fn theory_figures_are_costed_before_work() {
    let dir = TempDir::new("theory-cost");
    let out = dir.join("out");
    let o = out.to_str().unwrap();
    let big = theory_scene(&dir, "big", "ground-states", 100_000, "");
    let limit = Duration::from_secs(30);
    for args in [
        vec!["render", &big, "--out", o],
        vec!["render", "--check", &big],
    ] {
        refused(
            &args,
            limit,
            &["--max-theory-work", "ground-states", "N = 100000"],
        );
    }
    let modes = "modes = [{ m = 1, epsilon = 0.1 }]";
    let s4 = theory_scene(&dir, "s4", "zero-modes", 20_000, modes);
    for args in [
        vec!["render", &s4, "--out", o],
        vec!["render", "--check", &s4],
    ] {
        refused(&args, limit, &["bytes", "N = 20000"]);
    }
    assert!(!out.join("figure-big.png").exists());
    // Raised, the same file passes the check (the cap is what refused it).
    let args = ["render", "--check", &big, "--max-theory-work", "2e12"];
    let ok = ladder_within(&args, limit).expect("the check answers");
    assert_eq!(ok.status.code(), Some(0));
}

/// Every scene of the catalogue passes the checks rendering makes before
/// its work (the worst case of `auto` included) at the default caps.
#[test]
fn the_catalogue_passes_the_default_caps() {
    let (movie, outputs) = (MovieOptions::default(), Outputs::default());
    for e in jacobs_ladder::catalog::catalogue().unwrap() {
        assert_eq!(e.scene.limits, Limits::default(), "{}", e.id);
        if let Err(err) = scenes::check(&e.scene, &movie, &outputs) {
            panic!("{} {}: {err}", e.kind().name(), e.id);
        }
    }
}

/// A sweep keeps its runs in a shard file that a reader takes up to 1 GiB:
/// a shard estimated past it (70 runs of N = 100 000, about 1.1 GB of
/// arrival times) is refused before any run, naming the fewest shards that
/// fit, unsharded or as one shard of one; nothing is written.
#[test]
fn a_shard_file_past_what_gather_reads_is_refused_before_work() {
    let dir = TempDir::new("caps-shard");
    let out = dir.path().join("o");
    let out = out.to_str().unwrap();
    for shard in [None, Some("1/1")] {
        let mut args = vec!["sweep", "--alpha", "20:89:1", "--n", "100000", "--out", out];
        if let Some(s) = shard {
            args.extend(["--shard", s]);
        }
        refused(
            &args,
            Duration::from_secs(20),
            &["shard", "at least 3 shards", "--shard K/3"],
        );
        assert!(
            !dir.path().join("o").exists(),
            "{args:?} wrote into its folder"
        );
    }
}

/// The caps travel with each scene (`Scene::limits`), not in a process
/// global: in one process, at the same time, a scene whose cap on
/// steps × N is below its run's cost is refused by the run itself (its
/// figures' runs, the CLI's `--max-block-steps`), while the same scene
/// with the default caps runs.
#[test]
fn each_scene_carries_its_own_caps() {
    use jacobs_ladder::scene::Scene;
    let mut base = Scene::default();
    base.model.n = 10;
    base.run.t_end = 200.0;
    base.run.integrator =
        jacobs_ladder::scene::Method::Fixed(jacobs_ladder::sim::IntegratorKind::Verlet);
    base.run.dt = Some(0.01);
    // 2e4 steps × N = 10 = 2e5 block-steps.
    let mut capped = base.clone();
    capped.limits.block_steps = 1e5;
    let (refused, ran) = std::thread::scope(|s| {
        let a = s.spawn(|| scenes::run::simulate(&capped, &[]));
        let b = s.spawn(|| scenes::run::simulate(&base, &[]));
        (a.join().unwrap(), b.join().unwrap())
    });
    match refused {
        Err(jacobs_ladder::Error::Limit(l)) => {
            assert_eq!(l.resource, jacobs_ladder::limits::Resource::BlockSteps);
            assert_eq!(l.cap, 1e5);
        }
        other => panic!("the capped scene was not refused: {:?}", other.map(drop)),
    }
    assert!(ran.is_ok(), "the default scene failed");
    // The check before work says the same, from the same field.
    assert!(scenes::run::check_cost(&capped, 0).is_err());
    assert!(scenes::run::check_cost(&base, 0).is_ok());
}

/// The "stiff" links' check is a second run (2k, √2 more steps over the
/// same seconds); its cost is checked with the first, before any run.
/// Before, with a cap between the two runs' costs (the tank's 8 s:
/// 258 800 and 366 010 steps × N) the first run was made, then the
/// command ended (exit 2) naming a t_end of 4574.7 τ the user never gave.
/// Weighed by their path (RK4 with the tank's terms, `sim::cost`) they
/// are about 5.2 × 10⁶ and 7.3 × 10⁶ block-steps of the paper's model.
#[test]
fn the_stiff_links_second_run_is_checked_before_the_first() {
    let tank = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/assets/scenes/movie-water-tank.toml"
    );
    let args = [
        "simulate",
        "--apparatus",
        tank,
        "--integrator",
        "rk4",
        "--dt",
        "0.125",
        "--max-block-steps",
        "8e6",
    ];
    let out = crate::common::ladder_cli(&args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(
        err.contains("\"stiff\" links' check") && err.contains("--max-block-steps"),
        "{err}"
    );
    assert!(out.stdout.is_empty());
}
