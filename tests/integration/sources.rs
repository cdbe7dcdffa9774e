//! Independent checks behind regression values that other tests take
//! from the program's own runs (docs/testing.md, "Expected values"):
//! each value is recomputed here with a different integrator (dopri5 at a
//! tight tolerance instead of the sweep's Verlet) and with this file's own
//! arithmetic (least squares, front) instead of the program's.
//!
//! - tests/integration/sweep.rs: the α = −52° antikink stops with its front at block 6
//!   (regression value of the sweep's `auto` run);
//! - tests/integration/sweep.rs and the `friction` figure's caption: where friction
//!   dominates (G/γ ≤ 0.005), the antikink runs at about 0.30 G/γ blocks/τ
//!   (regression value of Verlet at dt = 0.25 τ).
//!
//! Run in release: `cargo test --release --test integration sources::`.

#![allow(clippy::field_reassign_with_default)]

use jacobs_ladder::model::Params;
use jacobs_ladder::sim::{self, IntegratorConfig, Scenario};

/// dopri5 at this relative tolerance: arrival errors far below the
/// differences these checks could confuse.
const RTOL: f64 = 1e-9;

fn antikink(alpha: f64, gamma: f64, gravity: f64, t_end: f64) -> Vec<Option<f64>> {
    let mut p = Params::paper(alpha).unwrap();
    p.gamma = gamma;
    p.gravity = gravity;
    let scene = Scenario::single_flip(p, sim::PAPER_DRIVE_TIME, t_end).unwrap();
    sim::simulate(&scene, &[], &IntegratorConfig::adaptive(RTOL))
        .unwrap()
        .arrival_times
}

/// The −52° antikink (N = 10, the paper's γ, G) flips blocks 1–6 and then
/// nothing more, run on to 60 000 τ (the sweep decides it near 63 000 τ
/// after its quiet time; its last arrival is near 15 000 τ).
#[test]
fn the_antikink_at_minus_52_degrees_stops_at_block_6() {
    let a = antikink(-52.0, 0.02, 2e-4, 60_000.0);
    let front = a.iter().take_while(|a| a.is_some()).count();
    let flipped = a.iter().flatten().count();
    assert_eq!((front, flipped), (6, 6), "{a:?}");
}

/// Blocks per τ: the inverse least-squares slope of t_n against n over
/// blocks 3..=9 (this file's own fit).
fn speed(a: &[Option<f64>]) -> f64 {
    let pts: Vec<(f64, f64)> = (2..9)
        .map(|i| (i as f64 + 1.0, a[i].expect("block flipped")))
        .collect();
    let n = pts.len() as f64;
    let (mx, my) = (
        pts.iter().map(|p| p.0).sum::<f64>() / n,
        pts.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
    sxx / sxy
}

/// The friction law's constant: at G/γ = 0.005 (G = 1e-4, γ = 0.02 and
/// G = 2e-4, γ = 0.04) the −60° antikink runs at 0.30 G/γ blocks/τ within
/// 5 %, and the two runs of equal G/γ within 6 % of each other.
#[test]
fn the_friction_law_constant_is_0_30_by_an_independent_integrator() {
    let ratio = 0.005;
    let v1 = speed(&antikink(-60.0, 0.02, 1e-4, 9000.0));
    let v2 = speed(&antikink(-60.0, 0.04, 2e-4, 9000.0));
    for v in [v1, v2] {
        assert!(
            (v / ratio - 0.30).abs() < 0.015,
            "speed {v:.4e} blocks/τ = {:.3} G/γ",
            v / ratio
        );
    }
    assert!((v1 / v2 - 1.0).abs() < 0.06, "{v1:.4e} vs {v2:.4e}");
}
