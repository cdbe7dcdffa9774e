//! Arrival times of every block checked against a detector written here,
//! independent of the program's (`sim::observables::ArrivalDetector`): the
//! binary writes θ_n(t) at every τ (`--csv`) and its arrival times
//! (`--json`) from the same run; this test finds, for each block, the first
//! sample at which the polarisation sin θ_n has the sign opposite to the
//! one it started with (docs/model.md), and requires the program's
//! arrival time to lie between that sample and the one before it. A block
//! whose samples never change sign must have no arrival. So a shift of any
//! block's arrival by more than one sample interval, or a missed or
//! invented flip, fails.

use crate::common::tempdir::TempDir;
use std::process::Command;

/// Sample interval of the CSV, τ.
const EVERY: f64 = 1.0;

struct Run {
    /// Sample times and θ_n (degrees) per sample.
    times: Vec<f64>,
    theta: Vec<Vec<f64>>,
    arrivals: Vec<Option<f64>>,
}

fn run(dir: &TempDir, args: &[&str]) -> Run {
    let csv = dir.join(format!("theta-{}.csv", args.join("_")));
    let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .arg("simulate")
        .args(args)
        .args(["--json", "--sample-every", &EVERY.to_string(), "--csv"])
        .arg(&csv)
        .output()
        .expect("the ladder binary runs");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let arrivals = v["arrival_times"]
        .as_array()
        .unwrap()
        .iter()
        .map(serde_json::Value::as_f64)
        .collect();
    let text = std::fs::read_to_string(&csv).unwrap();
    let (mut times, mut theta) = (Vec::new(), Vec::new());
    for line in text.lines().skip(1) {
        let mut cells = line.split(',').map(|c| c.parse::<f64>().unwrap());
        times.push(cells.next().unwrap());
        theta.push(cells.collect::<Vec<f64>>());
    }
    Run {
        times,
        theta,
        arrivals,
    }
}

/// This test's own detector: for each block, the bracket (t_{k−1}, t_k) of
/// the first sample k whose sin θ has the sign opposite to sample 0's.
fn brackets(run: &Run) -> Vec<Option<(f64, f64)>> {
    let n = run.theta[0].len();
    (0..n)
        .map(|i| {
            let sign0 = run.theta[0][i].to_radians().sin().signum();
            let k =
                (1..run.times.len()).find(|&k| run.theta[k][i].to_radians().sin() * sign0 < 0.0)?;
            Some((run.times[k - 1], run.times[k]))
        })
        .collect()
}

/// Every block's arrival agrees with this test's detector; returns how
/// many blocks arrived.
fn check(args: &[&str]) -> usize {
    let dir = TempDir::new("arrivals");
    let run = run(&dir, args);
    let brackets = brackets(&run);
    assert_eq!(brackets.len(), run.arrivals.len(), "{args:?}");
    for (i, (bracket, arrival)) in brackets.iter().zip(&run.arrivals).enumerate() {
        match (bracket, arrival) {
            (Some((lo, hi)), Some(t)) => assert!(
                *lo <= *t && *t <= *hi,
                "{args:?}: block {} arrives at {t} by the program, between {lo} and {hi} by the samples",
                i + 1
            ),
            (None, None) => {}
            _ => panic!(
                "{args:?}: block {}: program says {arrival:?}, samples say {bracket:?}",
                i + 1
            ),
        }
    }
    run.arrivals.iter().flatten().count()
}

#[test]
fn kink_and_antikink_arrivals_of_every_block_match_an_independent_detector() {
    // The paper's kink reaches every block, the antikink every one.
    assert_eq!(check(&["--alpha", "60"]), 10);
    assert_eq!(check(&["--alpha", "-60"]), 10);
}

#[test]
fn arrivals_match_with_other_integrators_and_longer_ladders() {
    let n = check(&[
        "--alpha",
        "70",
        "--n",
        "30",
        "--integrator",
        "verlet",
        "--dt",
        "0.2",
    ]);
    assert!(n >= 20, "{n} blocks arrived");
    let n = check(&[
        "--alpha",
        "-75",
        "--n",
        "16",
        "--integrator",
        "dopri5",
        "--rtol",
        "1e-8",
    ]);
    assert!(n >= 10, "{n} blocks arrived");
}

#[test]
fn pinned_and_turned_round_blocks_match_an_independent_detector() {
    // α = −50°: the antikink is pinned near the top (docs/model.md).
    let n = check(&["--alpha", "-50"]);
    assert!(n <= 3, "{n} blocks arrived");
    // α = 88°: groups of blocks turn through ±180° instead of through the
    // horizontal; their polarisation changes sign all the same.
    let n = check(&["--alpha", "88", "--n", "20", "--t-end", "3000"]);
    assert!(n >= 15, "{n} blocks arrived");
}
