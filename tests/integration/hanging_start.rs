//! The hanging start (docs/sweeps.md, docs/model.md "The hanging start"):
//! `[model] start = "relaxed"` starts every run at rest in the static
//! equilibrium under gravity with block 1 clamped. Its residual force is at
//! most 1e-12; it is the same state, and gives the same arrival times, as
//! an independent relaxation written here (damped dynamics, the ladder's
//! own gradient the only shared code); a bad `start` value is exit 2 with
//! the file, line and key; `simulate` and `sweep` take `--start`, and a
//! sweep point whose relaxed start is not found is `failed`.
//!
//! Run in release: `cargo test --release --test integration hanging_start::`.

#![allow(clippy::field_reassign_with_default)]

use crate::common::tempdir::TempDir;
use jacobs_ladder::model::Ladder;
use jacobs_ladder::scene::Scene;
use jacobs_ladder::sim::{self, IntegratorConfig, IntegratorKind, Start, State};
use std::process::Command;

/// Residual the relaxed start must reach (docs/sweeps.md).
const RESIDUAL: f64 = 1e-12;

fn scene(alpha: f64, n: usize, start: Start) -> Scene {
    let mut s = Scene::default();
    s.model.alpha = alpha;
    s.model.n = n;
    s.model.start = start;
    s
}

/// Largest |∂E/∂q| over blocks 2..N (block 1 is clamped).
fn residual(ladder: &Ladder, q: &[f64]) -> f64 {
    let mut g = vec![0.0; q.len()];
    ladder.gradient(q, &mut g);
    g[3..].iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// The independent reference: damped dynamics from the ground state,
/// m q̈ = −∂E/∂q − c q̇ on blocks 2..N with block 1 held, by symplectic
/// Euler (written here, not the program's integrators) at step `DT`, with
/// a damping rate `C` near critical for the slowest mode of a ten-block
/// chain (ω ≈ 4.5e-3/τ), until the residual is below `TOL`.
fn relaxed_by_damped_dynamics(ladder: &Ladder) -> Vec<f64> {
    const DT: f64 = 0.2;
    const C: f64 = 0.01;
    const TOL: f64 = 1e-11;
    const MAX_STEPS: usize = 2_000_000;
    let inertia = ladder.params.inertia;
    let mut q = ladder.ground_state();
    let mut v = vec![0.0; q.len()];
    let mut g = vec![0.0; q.len()];
    for _ in 0..MAX_STEPS {
        ladder.gradient(&q, &mut g);
        if g[3..].iter().all(|x| x.abs() < TOL) {
            return q;
        }
        for k in 3..q.len() {
            let mass = if k % 3 == 2 { inertia } else { 1.0 };
            v[k] += DT * (-g[k] - C * mass * v[k]) / mass;
            q[k] += DT * v[k];
        }
    }
    panic!("the damped-dynamics reference did not settle");
}

#[test]
fn the_relaxed_start_is_at_rest_to_1e_12_on_the_paper_scenes_and_long_chains() {
    for (alpha, n) in [
        (60.0, 10),
        (-60.0, 10),
        (50.0, 10),
        (-50.0, 10),
        (86.0, 10),
        (-86.0, 10),
        (60.0, 186),
        (60.0, 400),
    ] {
        let s = scene(alpha, n, Start::Relaxed).scenario().unwrap();
        let r = residual(&s.ladder, &s.initial.q);
        assert!(r <= RESIDUAL, "α = {alpha}, N = {n}: residual {r:e}");
        assert!(s.initial.v.iter().all(|&x| x == 0.0));
        // Block 1 stays where the ground state put it, at θ_1 = α.
        let ground = s.ladder.ground_state();
        assert_eq!(&s.initial.q[..3], &ground[..3]);
        // A minimum, not a saddle: stable (the rest proof's Hessian test,
        // margin 0), and proved at rest by the default tolerances.
        assert!(jacobs_ladder::theory::stability::is_stable(
            &s.ladder,
            &s.initial.q,
            0.0
        ));
        // Not the ground state: gravity stretched the chain, the bottom
        // block hangs lower by a positive amount.
        let last = 3 * (n - 1);
        assert!(
            s.initial.q[last] > ground[last] + 1e-6,
            "α = {alpha}, N = {n}"
        );
    }
}

#[test]
fn the_relaxed_start_matches_damped_dynamics_state_and_arrivals() {
    // Tolerances: the reference stops at residual 1e-11; with the slowest
    // mode's ω² ≈ 2e-5 a residual r leaves the state off by about r/ω² =
    // 5e-7, so positions agree to 1e-5 and arrival times (moved by an
    // initial offset of that size, over a 4000 τ run) to 1e-3 τ.
    const STATE_TOL: f64 = 1e-5;
    const ARRIVAL_TOL: f64 = 1e-3;
    let config = IntegratorConfig::fixed(IntegratorKind::SymplecticEuler, 0.01);
    for alpha in [60.0, -50.0] {
        let program = scene(alpha, 10, Start::Relaxed).scenario().unwrap();
        let q_ref = relaxed_by_damped_dynamics(&program.ladder);
        let off = program
            .initial
            .q
            .iter()
            .zip(&q_ref)
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        assert!(off <= STATE_TOL, "α = {alpha}: states differ by {off:e}");
        let mut reference = program.clone();
        reference.initial = State::at_rest(q_ref);
        let a = sim::simulate(&program, &[], &config).unwrap();
        let b = sim::simulate(&reference, &[], &config).unwrap();
        assert!(a.arrival_times.iter().flatten().count() >= 2);
        for (k, (x, y)) in a.arrival_times.iter().zip(&b.arrival_times).enumerate() {
            match (x, y) {
                (Some(x), Some(y)) => assert!(
                    (x - y).abs() <= ARRIVAL_TOL,
                    "α = {alpha}, block {}: {x} vs {y}",
                    k + 1
                ),
                (None, None) => {}
                _ => panic!("α = {alpha}, block {}: {x:?} vs {y:?}", k + 1),
            }
        }
    }
}

#[test]
fn the_ground_start_is_the_ground_state() {
    let s = scene(60.0, 10, Start::Ground).scenario().unwrap();
    assert_eq!(s.initial.q, s.ladder.ground_state());
}

fn ladder(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .output()
        .expect("the ladder binary runs")
}

#[test]
fn a_bad_start_is_exit_2_with_file_line_and_key() {
    let dir = TempDir::new("bad-start");
    let path = dir.file("bad.toml", "[model]\nn = 12\nstart = \"hanging\"\n");
    let out = ladder(&["render", &path, "--out", dir.path().to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.starts_with(&format!("ladder: {path}:3:9: model.start: ")),
        "{stderr}"
    );
    assert!(
        stderr.contains("relaxed") && stderr.contains("ground"),
        "{stderr}"
    );
    // On the command line, clap's own message, exit 2.
    let out = ladder(&["simulate", "--start", "hanging"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn start_relaxed_on_the_command_line_changes_the_run() {
    let run = |start: &str| {
        let out = ladder(&["simulate", "--json", "--start", start, "--t-end", "1500"]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stdout).unwrap()
    };
    assert_ne!(run("relaxed"), run("ground"));
}

#[test]
fn a_sweep_takes_the_relaxed_start() {
    let dir = TempDir::new("sweep-start");
    let run = |start: Option<&str>| {
        let out = dir.join(start.unwrap_or("default"));
        let mut args = vec![
            "sweep",
            "--alpha",
            "46",
            "--integrator",
            "verlet",
            "--dt",
            "0.25",
            "--name",
            "s",
            "--out",
            out.to_str().unwrap(),
        ];
        if let Some(s) = start {
            args.extend(["--start", s]);
        }
        let o = ladder(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        std::fs::read_to_string(out.join("sweep-s.csv")).unwrap()
    };
    // At 46° the hanging equilibrium is not found (docs/sweeps.md): the
    // relaxed start is honoured, and its point is `failed`.
    assert!(run(Some("relaxed")).contains(",failed,"));
    assert!(!run(None).contains(",failed,"));
    assert!(!run(Some("ground")).contains(",failed,"));
}
