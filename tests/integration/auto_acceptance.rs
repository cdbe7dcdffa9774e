//! The `auto` integrator's acceptance rule (docs/scenes.md), for
//! `simulate` and for sweeps, at its boundary: a coarse/fine pair whose
//! arrival times differ by more than the tolerance, or in which a block
//! flips in one run and not the other, is rejected and the step halved.
//!
//! Each test uses a fixed scene that needs at least one halving, shown
//! by the test itself: it runs velocity Verlet at `auto`'s first step and
//! at half of it, and finds them more than the tolerance apart, and the
//! half-step run more than the tolerance away from the reference. So an
//! `auto` that accepted its first pair, or its first run, unchecked would
//! return arrival times off by more than the tolerance. The result is
//! checked against dopri5 at rtol 1e-10 (an independent integrator, with
//! errors far below the tolerance) on every block.
//!
//! Run in release: `cargo test --release --test integration auto_acceptance::`.

#![allow(clippy::field_reassign_with_default)]

use crate::common;

use jacobs_ladder::scene::sweep::SweepSpec;
use jacobs_ladder::scene::{DriveSpec, Scene};
use jacobs_ladder::scenes::run;
use jacobs_ladder::sim::auto::arrival_difference;
use jacobs_ladder::sim::{self, IntegratorConfig, IntegratorKind};
use jacobs_ladder::sweep::run::run_point;

const REFERENCE_RTOL: f64 = 1e-10;

/// The fixed scene: a 70° kink on 8 blocks, T_d = 300 τ, tolerance
/// `tol`. Verlet is accurate on it (its arrivals are off by 2e-3 τ at
/// dt = 0.125), so the tolerances below are tight enough for the first
/// pair to be rejected, and loose enough against the reference's own
/// error (dopri5 at rtol 1e-10: far below 1e-4 τ).
fn scene(tol: f64) -> Scene {
    let mut s = Scene::default();
    s.model.alpha = 70.0;
    s.model.n = 8;
    s.drive = DriveSpec::flips_at(&[0.0], 300.0);
    s.run.t_end = 2000.0;
    s.run.tolerance = tol;
    s
}

/// Velocity Verlet's arrival times on `s` at `dt`.
fn verlet(s: &Scene, dt: f64) -> Vec<Option<f64>> {
    let c = IntegratorConfig::fixed(IntegratorKind::Verlet, dt);
    sim::simulate(&s.scenario().unwrap(), &[], &c)
        .unwrap()
        .arrival_times
}

fn reference(s: &Scene) -> Vec<Option<f64>> {
    sim::simulate(
        &s.scenario().unwrap(),
        &[],
        &IntegratorConfig::adaptive(REFERENCE_RTOL),
    )
    .unwrap()
    .arrival_times
}

/// Largest arrival difference, this test's own: a block that flips in
/// one run only is an infinite difference.
fn max_gap(a: &[Option<f64>], b: &[Option<f64>]) -> f64 {
    a.iter()
        .zip(b)
        .map(|p| match p {
            (Some(x), Some(y)) => (x - y).abs(),
            (None, None) => 0.0,
            _ => f64::INFINITY,
        })
        .fold(0.0, f64::max)
}

/// The tolerance of the simulate test, τ.
const SIMULATE_TOL: f64 = 1e-3;

#[test]
fn simulate_auto_rejects_a_pair_further_apart_than_the_tolerance() {
    let s = scene(SIMULATE_TOL);
    let params = s.model.params().unwrap();
    let omega_max = jacobs_ladder::theory::dispersion::omega_max_clamped(&params).unwrap();
    let dt0 = IntegratorConfig::auto(omega_max).dt;
    let reference = reference(&s);
    assert!(reference.iter().flatten().count() >= 6, "{reference:?}");
    // The scene needs a halving: the first pair disagrees, and its finer
    // run is off the reference by more than the tolerance.
    let (first, second) = (verlet(&s, dt0), verlet(&s, dt0 / 2.0));
    let pair = max_gap(&first, &second);
    let second_error = max_gap(&second, &reference);
    common::require::note(&format!(
        "auto_acceptance (simulate): dt0 = {dt0}, first pair {pair:.3e} τ apart, \
         its fine run {second_error:.3e} τ off the reference (tolerance {SIMULATE_TOL})"
    ));
    assert!(pair > SIMULATE_TOL, "first pair only {pair} τ apart");
    assert!(
        second_error > SIMULATE_TOL,
        "fine run only {second_error} τ off"
    );
    // auto halves until the pair agrees, and the result is within the
    // tolerance of the reference on every block.
    let r = run::simulate(&s, &[]).unwrap();
    let got = &r.trajectory.arrival_times;
    let error = max_gap(got, &reference);
    common::require::note(&format!(
        "auto_acceptance (simulate): accepted dt = {}, error {error:.3e} τ",
        r.integrator.dt
    ));
    assert!(
        r.integrator.dt <= dt0 / 4.0,
        "accepted dt = {}",
        r.integrator.dt
    );
    assert!(
        error <= SIMULATE_TOL,
        "arrival error {error} τ > {SIMULATE_TOL} τ"
    );
    // The error auto reports (a third of the last pair's difference:
    // Richardson for a second-order method) is honest: within a factor 3
    // of the true error against the reference.
    let estimate = r.integrator.arrival_error.expect("auto reports its error");
    assert!(
        (error / 3.0..=3.0 * error).contains(&estimate),
        "auto reports an arrival error of {estimate:.3e} τ, the reference says {error:.3e} τ"
    );
}

/// The tolerance of the sweep test, τ.
const SWEEP_TOL: f64 = 5e-3;

#[test]
fn sweep_auto_rejects_a_pair_further_apart_than_the_tolerance() {
    let s = scene(SWEEP_TOL);
    let spec = SweepSpec::default();
    // A sweep's auto starts at 0.5 τ (checked against 0.25 τ) where the
    // stability bound allows it; this scene's is far above.
    let dt0 = jacobs_ladder::sweep::run::SWEEP_AUTO_DT;
    let reference = reference(&s);
    let (first, second) = (verlet(&s, dt0), verlet(&s, dt0 / 2.0));
    let pair = max_gap(&first, &second);
    let second_error = max_gap(&second, &reference);
    common::require::note(&format!(
        "auto_acceptance (sweep): first pair {pair:.3e} τ apart, its fine run \
         {second_error:.3e} τ off the reference (tolerance {SWEEP_TOL})"
    ));
    assert!(pair > SWEEP_TOL, "first pair only {pair} τ apart");
    assert!(
        second_error > SWEEP_TOL,
        "fine run only {second_error} τ off"
    );
    let r = run_point(&s, &spec).unwrap();
    assert_eq!(r.outcome.name(), "propagated", "{r:?}");
    assert!(r.message.is_none(), "{:?}", r.message);
    // Every block up to the decision, against the reference.
    let t = r.t_decided.unwrap();
    let upto: Vec<Option<f64>> = reference
        .iter()
        .map(|a| a.filter(|&a| a <= t + SWEEP_TOL))
        .collect();
    let error = max_gap(&r.arrival_times, &upto);
    common::require::note(&format!(
        "auto_acceptance (sweep): accepted dt = {}, error {error:.3e} τ",
        r.dt
    ));
    assert!(r.dt <= dt0 / 4.0, "accepted dt = {}", r.dt);
    assert!(
        error <= SWEEP_TOL,
        "arrival error {error} τ > {SWEEP_TOL} τ"
    );
}

/// The rule on a pair in which a block flips in one run only: rejected
/// (an infinite difference), whatever the tolerance, unless the flip is
/// within the tolerance of the window's end (where the other run may flip
/// just after it): the boundary on both sides.
#[test]
fn a_pair_in_which_a_block_flips_in_one_run_only_is_rejected() {
    let (t_end, tol) = (4000.0, 0.1);
    let a = [Some(500.0), Some(900.0), Some(1300.0)];
    let b = [Some(500.0), Some(900.0), None];
    assert_eq!(arrival_difference(&a, &b, t_end, tol), f64::INFINITY);
    assert_eq!(arrival_difference(&b, &a, t_end, tol), f64::INFINITY);
    // A flip just inside the tolerance of the end: accepted (≤ tol).
    let late = [Some(500.0), Some(900.0), Some(t_end - 0.5 * tol)];
    assert!(arrival_difference(&late, &b, t_end, tol) <= tol);
    // Just outside it: rejected.
    let early = [Some(500.0), Some(900.0), Some(t_end - 1.5 * tol)];
    assert!(arrival_difference(&early, &b, t_end, tol) > tol);
    // Both flip, a hair either side of the tolerance.
    let c = [Some(500.0), Some(900.0 + 0.99 * tol), Some(1300.0)];
    let d = [Some(500.0), Some(900.0 + 1.01 * tol), Some(1300.0)];
    assert!(arrival_difference(&a, &c, t_end, tol) <= tol);
    assert!(arrival_difference(&a, &d, t_end, tol) > tol);
}
