//! The strap hinge (docs/experiments.md, "The strap hinge: reduced
//! coordinates"): the toy's blocks end to end (b = s), each junction a
//! pivot about a pair of corners, against the maximal model (x, y, θ per
//! block, stiff wrapped ribbons) while every ribbon is taut. The two must
//! agree better as the ribbons are made stiffer (κ, 2κ, 4κ): the strap
//! hinge is the limit of inextensible ribbons, not a fit to them.

use jacobs_ladder::model::ladder::itheta;
use jacobs_ladder::model::ribbons::Ribbons;
use jacobs_ladder::model::strap::{StrapChain, fold};
use jacobs_ladder::scene::file::parse;
use jacobs_ladder::sim::strap::{Outcome, simulate_strap};
use jacobs_ladder::sim::{
    self, Drive, IntegratorConfig, IntegratorKind, Protocol, Scenario, State,
};
use std::f64::consts::{FRAC_PI_2, PI};

const TOY: &str = include_str!("../../assets/scenes/toy.toml");
const DT: f64 = 0.02;

/// The toy's blocks, `n` of them end to end (b = s), ribbons of
/// stiffness `kappa` (in k) and no contact: while both ribbons of every
/// junction are taut they alone hold the pivot.
fn toy(n: usize, kappa: f64) -> (Scenario, StrapChain) {
    let text = TOY
        .replace("n = 6", &format!("n = {n}"))
        .replace("b = 5.75", "b = 5.7")
        .replace("contact = \"wood\"\n", "");
    let mut sc = parse(&text, "toy", "toy").unwrap().scenario().unwrap();
    let mut built = sc.ladder.built.unwrap();
    built.ribbons = Ribbons::new(built.ribbons.outline, built.ribbons.ribbons, kappa);
    sc.ladder.built = Some(built);
    let chain = StrapChain {
        outline: built.ribbons.outline,
        inertia: sc.ladder.params.inertia + sc.ladder.terms.added_inertia,
        gravity: sc.ladder.params.gravity,
        top: [0.0, 0.0],
    };
    (sc, chain)
}

/// Block angles with folds `phi` below block 1 at `theta1`.
fn folded(theta1: f64, phi: &[f64]) -> Vec<f64> {
    let mut th = vec![theta1];
    for p in phi {
        let last = *th.last().unwrap();
        th.push(PI - p - last);
    }
    th
}

struct Agreement {
    /// The largest difference of any block's x, y (in s) or θ over the
    /// samples at κ, 2κ and 4κ.
    worst: [f64; 3],
    window: f64,
    least_tension: f64,
}

/// Both formulations from the folded start `theta` (at rest, block 1
/// driven by `drive`) over [0, window], sampled every τ; the window ends
/// where the strap run's folds leave [0.3, π − 0.3] (the ribbons' lines
/// turn parallel at φ = 0 and π, where the pivot degenerates).
fn agreement(theta: &[f64], drive: Drive, t_max: f64) -> Agreement {
    let n = theta.len();
    let (_, chain) = toy(n, 1.0);
    let samples: Vec<f64> = (0..=t_max as usize).map(|k| k as f64).collect();
    let zero = vec![0.0; n];
    let strap = simulate_strap(&chain, &drive, (theta, &zero), t_max, DT, &samples, 0.5).unwrap();
    let inside = |q: &[f64]| {
        let th: Vec<f64> = (0..n).map(|i| q[itheta(i)]).collect();
        (0..n - 1).all(|j| {
            let p = fold(&th, j).abs();
            (0.3..=PI - 0.3).contains(&p)
        })
    };
    let last = strap
        .states
        .iter()
        .position(|q| !inside(q))
        .unwrap_or(strap.states.len());
    assert!(last > 10, "the window is {last} τ long");
    assert!(strap.impacts.iter().all(|i| i.t > strap.times[last - 1]));
    let window = strap.times[last - 1];
    let start = chain.kinematics(theta, &zero, &strap_regions(theta));
    let mut worst = [0.0; 3];
    for (w, kappa) in worst.iter_mut().zip([1.0, 2.0, 4.0]) {
        let (mut sc, _) = toy(n, kappa);
        sc.protocol = Protocol::Driven(drive.clone());
        sc.initial = State {
            q: start.q.clone(),
            v: vec![0.0; 3 * n],
        };
        sc.t_end = window;
        let cfg = IntegratorConfig::fixed(IntegratorKind::Rk4, DT);
        let traj = sim::simulate(&sc, &samples[..last], &cfg).unwrap();
        for (a, b) in traj.states.iter().zip(&strap.states) {
            for (x, y) in a.iter().zip(b) {
                *w = f64::max(*w, (x - y).abs());
            }
        }
    }
    // The tension over the window only (the strap run went on past it).
    let (_, c) = toy(n, 1.0);
    let short = simulate_strap(&c, &drive, (theta, &zero), window, DT, &[], 0.5).unwrap();
    Agreement {
        worst,
        window,
        least_tension: short.least_tension,
    }
}

fn strap_regions(theta: &[f64]) -> Vec<i32> {
    (0..theta.len() - 1)
        .map(|j| jacobs_ladder::model::strap::region_of(fold(theta, j)))
        .collect()
}

fn check(a: &Agreement, tolerance: f64) {
    println!(
        "window {:.0} τ, least tension {:.3e}; worst difference at κ, 2κ, 4κ: {:.3e} {:.3e} {:.3e}",
        a.window, a.least_tension, a.worst[0], a.worst[1], a.worst[2]
    );
    assert!(
        a.least_tension > 0.0,
        "a ribbon went slack: {}",
        a.least_tension
    );
    assert!(
        a.worst[1] < 0.7 * a.worst[0] && a.worst[2] < 0.7 * a.worst[1],
        "{:?}",
        a.worst
    );
    assert!(a.worst[2] < tolerance, "{:?}", a.worst);
}

#[test]
#[ignore = "open: does not pass. Block 2 let go from φ = −1.2: the strap run stays taut (least \
            tension 8.8e-5) but the maximal model differs by 0.307 at κ, 2κ and 4κ alike: a \
            difference that does not fall with κ points at a mismatch of the two runs' set-up or \
            mapping, not yet found"]
fn a_two_block_hinge_swings_about_its_pivot_as_the_stiff_ribbons_do() {
    // Block 1 held upright, block 2 folded 2 rad up towards block 1's
    // face w = −h and let go: it swings down about block 1's corner c₁.
    let theta = folded(FRAC_PI_2, &[-1.2]);
    let a = agreement(&theta, Drive::hold(FRAC_PI_2), 400.0);
    check(&a, 2e-3);
}

#[test]
#[ignore = "open: does not pass. Zig-zag start φ = −0.9: least tension −1.7e-5 (not taut), \
            difference 0.231 at κ, 2κ and 4κ alike"]
fn a_six_block_toy_folds_as_the_stiff_ribbons_fold_it() {
    // The toy's six blocks folded in a zig-zag (every junction at
    // φ = −1.2 rad, alternately either way in the lab), block 1 turned
    // by the hand's 232 τ turn: every junction rolls on its pivot.
    let theta = folded(FRAC_PI_2, &[-0.9, -0.9, -0.9, -0.9, -0.9]);
    let drive = Drive::new(vec![(0.0, FRAC_PI_2), (232.0, -FRAC_PI_2)]).unwrap();
    let a = agreement(&theta, drive, 400.0);
    check(&a, 5e-3);
}

#[test]
fn the_strap_hinge_keeps_its_energy_between_impacts_and_loses_it_at_them() {
    // Block 1 held: no work is done on the chain. Between impacts the
    // energy stays to the integrator's accuracy; each impact (rolling
    // on about a new pivot, rebounding with e = 0.5) only takes energy.
    let theta = folded(FRAC_PI_2, &[2.5, -1.0, 0.6]);
    let (_, c) = toy(4, 1.0);
    let drive = Drive::hold(FRAC_PI_2);
    let zero = vec![0.0; 4];
    let samples: Vec<f64> = (0..=3000).map(|k| k as f64).collect();
    let run = simulate_strap(&c, &drive, (&theta, &zero), 3000.0, DT, &samples, 0.5).unwrap();
    println!(
        "{} impacts: {:?}",
        run.impacts.len(),
        &run.impacts[..run.impacts.len().min(8)]
    );
    assert!(run.impacts.iter().any(|i| i.outcome == Outcome::Switch));
    let scale = run.energies.iter().map(|e| e.abs()).fold(0.0, f64::max);
    let (mut drift, mut lost) = (0.0f64, 0.0);
    for (k, w) in run.energies.windows(2).enumerate() {
        let (t0, t1) = (run.times[k], run.times[k + 1]);
        let hit = run.impacts.iter().any(|i| i.t > t0 && i.t <= t1);
        let de = w[1] - w[0];
        if hit {
            assert!(de < 1e-10 * scale, "an impact gave energy: {de} at {t1}");
            lost -= de;
        } else {
            drift = drift.max(de.abs());
        }
    }
    println!("drift between impacts {drift:.2e}, lost at impacts {lost:.3e}, of {scale:.3e}");
    assert!(drift < 1e-9 * scale, "{drift}");
    assert!(lost > 0.0);
}
