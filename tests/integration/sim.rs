//! Simulation core: forces, ground states, energy decay, convergence orders
//! and the paper's qualitative results (docs/model.md).

use crate::common;

use crate::common::lcg::Lcg;
use jacobs_ladder::model::{Ladder, Params};
use jacobs_ladder::sim::{
    self, Drive, IntegratorConfig, IntegratorKind, Protocol, Scenario, State, Stepping, Trajectory,
};

fn perturbed(q: &[f64], rng: &mut Lcg, size: f64) -> Vec<f64> {
    q.iter().map(|x| x + size * rng.uniform()).collect()
}

#[test]
fn analytic_gradient_matches_finite_differences() {
    let mut rng = Lcg(7);
    for alpha in [60.0, -60.0, 86.0, -50.0, 20.0] {
        let mut params = Params::paper(alpha).unwrap();
        params.gravity = 0.3; // large enough that the gravity term is tested too
        let ladder = Ladder::new(params);
        for _ in 0..5 {
            let q = perturbed(&ladder.ground_state(), &mut rng, 0.4);
            let mut grad = vec![0.0; q.len()];
            ladder.gradient(&q, &mut grad);
            let h = 1e-5;
            for k in 0..q.len() {
                let (mut qp, mut qm) = (q.clone(), q.clone());
                qp[k] += h;
                qm[k] -= h;
                let fd = (ladder.energy(&qp) - ladder.energy(&qm)) / (2.0 * h);
                let scale = grad[k].abs().max(1e-3);
                assert!(
                    (fd - grad[k]).abs() / scale < 1e-6,
                    "alpha {alpha}, coordinate {k}: analytic {} vs finite difference {fd}",
                    grad[k]
                );
            }
        }
    }
}

#[test]
fn ground_states_are_force_free_without_gravity() {
    for alpha in [60.0, -60.0, 75.0, -75.0, 86.0, 5.0] {
        let mut params = Params::paper(alpha).unwrap();
        params.gravity = 0.0;
        let ladder = Ladder::new(params);
        let q = ladder.ground_state();
        let mut grad = vec![1.0; q.len()];
        ladder.gradient(&q, &mut grad);
        let worst = grad.iter().fold(0.0f64, |m, g| m.max(g.abs()));
        assert!(worst < 1e-13, "alpha {alpha}: largest force {worst:e}");
    }
}

/// Free chain (no drive), damped, from a perturbed ground state with
/// random velocities: the mechanical energy must never increase.
fn energy_history(kind: IntegratorKind, dt: f64, rtol: Option<f64>) -> Vec<f64> {
    let mut rng = Lcg(11);
    let params = Params::paper(60.0).unwrap();
    let ladder = Ladder::new(params);
    let q = perturbed(&ladder.ground_state(), &mut rng, 0.05);
    let v = (0..q.len()).map(|_| 0.05 * rng.uniform()).collect();
    let scenario = Scenario {
        ladder,
        protocol: Protocol::Free,
        initial: State { q, v },
        t_end: 100.0,
    };
    let samples: Vec<f64> = (0..=1000).map(|k| k as f64 * 0.1).collect();
    let config = IntegratorConfig { kind, dt, rtol };
    let traj = sim::simulate(&scenario, &samples, &config).unwrap();
    traj.states
        .iter()
        .zip(&traj.velocities)
        .map(|(q, v)| ladder.kinetic_energy(v) + ladder.energy(q))
        .collect()
}

#[test]
fn damped_energy_never_increases() {
    for (kind, dt, rtol) in [
        (IntegratorKind::SymplecticEuler, 1e-4, None),
        (IntegratorKind::Rk4, 0.01, None),
        (IntegratorKind::Dopri5, 0.01, Some(1e-10)),
    ] {
        let e = energy_history(kind, dt, rtol);
        assert!(
            e[0] - e[e.len() - 1] > 1e-4,
            "{kind}: energy hardly decayed"
        );
        for w in e.windows(2) {
            assert!(
                w[1] <= w[0] + 1e-9,
                "{kind}: energy rose from {} to {}",
                w[0],
                w[1]
            );
        }
    }
}

/// A smooth short run (no drive corner inside): the kink scene's first 10 τ,
/// with random initial velocities so that every mode moves.
fn smooth_run(kind: IntegratorKind, dt: f64) -> Vec<f64> {
    let mut rng = Lcg(3);
    let params = Params::paper(60.0).unwrap();
    let mut scenario = Scenario::single_flip(params, 5.0, 4.0).unwrap();
    for v in scenario.initial.v.iter_mut().skip(3) {
        *v = 0.1 * rng.uniform();
    }
    let config = IntegratorConfig::fixed(kind, dt);
    let t = sim::simulate(&scenario, &[], &config).unwrap();
    t.final_state
        .q
        .iter()
        .chain(&t.final_state.v)
        .copied()
        .collect()
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).fold(0.0, |m, (x, y)| m.max((x - y).abs()))
}

#[test]
fn integrators_converge_at_their_order() {
    let reference = smooth_run(IntegratorKind::Dopri5, 1e-3);
    // Moreau's time-stepping takes inextensible ribbons only; its order is
    // measured on them (tests/inextensible.rs).
    for kind in IntegratorKind::ALL
        .into_iter()
        .filter(|k| *k != IntegratorKind::Moreau)
    {
        let coarse = match kind.order() {
            1 => 0.01,
            2 => 0.02,
            _ => 0.05,
        };
        let e1 = max_diff(&smooth_run(kind, coarse), &reference);
        let e2 = max_diff(&smooth_run(kind, coarse / 2.0), &reference);
        let order = (e1 / e2).log2();
        let want = kind.order() as f64;
        eprintln!("{kind}: measured order {order:.2}");
        assert!(
            (order - want).abs() < 0.3,
            "{kind}: measured order {order:.2} (errors {e1:e}, {e2:e}), expected {want}"
        );
    }
}

fn kink_run(alpha: f64) -> Trajectory {
    let params = Params::paper(alpha).unwrap();
    let scenario = Scenario::single_flip(params, sim::PAPER_DRIVE_TIME, 4000.0).unwrap();
    sim::simulate(&scenario, &[], &IntegratorConfig::paper()).unwrap()
}

/// Blocks per τ from a least-squares line through the arrival times.
fn speed(t: &Trajectory) -> f64 {
    sim::speed::wave_speed(&t.arrival_times).expect("the wave ran")
}

#[test]
fn kink_at_60_degrees_reaches_the_bottom() {
    let t = kink_run(60.0);
    assert!(
        t.arrival_times.iter().all(Option::is_some),
        "{:?}",
        t.arrival_times
    );
    let arrivals: Vec<f64> = t.arrival_times.iter().map(|a| a.unwrap()).collect();
    assert!((arrivals[0] - 500.0).abs() < 1e-6, "t_1 = T_d/2");
    assert!(
        arrivals.windows(2).all(|w| w[1] > w[0]),
        "top to bottom: {arrivals:?}"
    );
    let theta = t.final_theta_deg();
    for (n, th) in theta.iter().enumerate().take(9) {
        assert!((th + 60.0).abs() < 5.0, "block {} ends at {th}°", n + 1);
    }
}

#[test]
fn antikink_at_60_degrees_is_slower_and_spares_the_last_block() {
    let kink = kink_run(60.0);
    let anti = kink_run(-60.0);
    for n in 2..9 {
        let (k, a) = (
            kink.arrival_times[n].unwrap(),
            anti.arrival_times[n].unwrap(),
        );
        assert!(
            a > k,
            "block {}: antikink {a} not later than kink {k}",
            n + 1
        );
    }
    assert!(speed(&anti) < 0.8 * speed(&kink));
    let theta = anti.final_theta_deg();
    for (n, th) in theta.iter().enumerate().take(8) {
        assert!(
            (th - 60.0).abs() < 5.0,
            "block {} ends at {th}°, not +60°",
            n + 1
        );
    }
    // The free bottom block turns backwards past 180° (its polarisation
    // changes sign, so it has an arrival time) into a configuration of its
    // own, never reaching +60° (docs/model.md and section 2, item 2).
    let last = theta[9];
    assert!((last - 60.0).abs() > 20.0, "block 10: {last}°");
    let unwrapped = anti.final_theta_deg_unwrapped()[9];
    assert!(unwrapped < -90.0, "block 10 turned backwards: {unwrapped}°");
    assert!(anti.arrival_times[9].is_some(), "block 10: no arrival");
}

#[test]
fn at_50_degrees_kink_runs_but_antikink_is_pinned() {
    let kink = kink_run(50.0);
    assert!(kink.arrival_times.iter().all(Option::is_some));
    let anti = kink_run(-50.0);
    for n in 2..10 {
        assert!(anti.arrival_times[n].is_none(), "block {} flipped", n + 1);
    }
}

#[test]
fn nearly_symmetric_ladder_has_equal_speeds() {
    let (k, a) = (speed(&kink_run(86.0)), speed(&kink_run(-86.0)));
    assert!((k - a).abs() / k < 0.05, "kink {k}, antikink {a} blocks/τ");
    assert!(kink_run(-86.0).arrival_times.iter().all(Option::is_some));
}

#[test]
fn explicit_euler_diverges_at_the_papers_step() {
    let params = Params::paper(60.0).unwrap();
    let scenario = Scenario::single_flip(params, sim::PAPER_DRIVE_TIME, 4000.0).unwrap();
    let config = IntegratorConfig::fixed(IntegratorKind::ExplicitEuler, 0.01);
    let err = sim::simulate(&scenario, &[], &config).unwrap_err();
    assert_eq!(err.exit_code(), 1);
    let msg = err.to_string();
    assert!(msg.starts_with("explicit-euler diverged at t = "), "{msg}");
    assert!(msg.contains("dt = 0.01") && msg.contains("hint"), "{msg}");
    // At a tenth of the step it is stable and agrees with symplectic Euler.
    let fine = IntegratorConfig::fixed(IntegratorKind::ExplicitEuler, 0.001);
    let t = sim::simulate(&scenario, &[], &fine).unwrap();
    let reference = kink_run(60.0);
    for (a, b) in t.arrival_times.iter().zip(&reference.arrival_times) {
        assert!((a.unwrap() - b.unwrap()).abs() < 2.0);
    }
}

#[test]
fn dopri5_lands_on_samples_and_corners() {
    let params = Params::paper(86.0).unwrap();
    let drive = Drive::two_flips(params.alpha, 100.0, 150.0).unwrap();
    let scenario = Scenario::with_drive(params, drive, 300.0).unwrap();
    let samples = [0.0, 33.3, 100.0, 250.0, 300.0];
    let t = sim::simulate(&scenario, &samples, &IntegratorConfig::adaptive(1e-8)).unwrap();
    assert_eq!(t.times, samples);
    // Block 1 follows the drive exactly at every sample.
    for (time, q) in t.times.iter().zip(&t.states) {
        let want = scenario.protocol.drive().unwrap().theta(*time);
        assert!((q[2] - want).abs() < 1e-12, "t = {time}");
    }
}

#[test]
fn simd_force_kernel_matches_the_portable_one_bit_for_bit() {
    use jacobs_ladder::model::ladder::ForceScratch;
    if fused_kernels("simd_force_kernel_matches_the_portable_one_bit_for_bit").is_none() {
        return;
    }
    let mut rng = Lcg(19);
    for n in 2..=13 {
        for alpha in [60.0, -50.0, 86.0] {
            let ladder = Ladder::new(Params::paper(alpha).unwrap().with(n, 1.3, alpha).unwrap());
            let q = perturbed(&ladder.ground_state(), &mut rng, 2.0);
            let (mut fast, mut portable) = (vec![0.0; 3 * n], vec![1.0; 3 * n]);
            let mut scratch = ForceScratch::new(n);
            ladder.gradient_with(&q, &mut fast, &mut scratch);
            ladder.gradient_portable(&q, &mut portable, &mut scratch);
            assert_eq!(fast, portable, "N = {n}, α = {alpha}");
        }
    }
}

/// Every fused way of taking symplectic Euler's steps that this CPU
/// offers (`Fastest` first), or `None` when there is none: without AVX2
/// the fused path is the portable one and comparing them would prove
/// nothing. A missing AVX2 fails under CI and is reported as a skip
/// elsewhere; a missing AVX-512 is reported (`common::kernels`).
fn fused_kernels(test: &str) -> Option<Vec<Stepping>> {
    let fused: Vec<Stepping> = common::kernels::fused(test)
        .into_iter()
        .map(|k| k.0)
        .collect();
    if fused.is_empty() {
        return None;
    }
    Some([Stepping::Fastest].into_iter().chain(fused).collect())
}

/// Asserts that `scenario` gives the portable path's trajectory, bit for
/// bit, with every fused kernel in `kernels`: samples, arrivals, final
/// state, counts.
fn assert_fused_matches_portable(
    kernels: &[Stepping],
    scenario: &Scenario,
    samples: &[f64],
    what: &str,
) {
    let config = IntegratorConfig::paper();
    let portable =
        crate::common::kernels::run_stepped(scenario, samples, &config, Stepping::Portable)
            .unwrap();
    for &stepping in kernels {
        let fused =
            crate::common::kernels::run_stepped(scenario, samples, &config, stepping).unwrap();
        let label = format!("{what}, {stepping:?}");
        assert_eq!(fused.times, portable.times, "{label}");
        assert_eq!(fused.states, portable.states, "{label}");
        assert_eq!(fused.velocities, portable.velocities, "{label}");
        assert_eq!(fused.arrival_times, portable.arrival_times, "{label}");
        assert_eq!(fused.final_state, portable.final_state, "{label}");
        assert_eq!(
            (fused.steps, fused.force_evals),
            (portable.steps, portable.force_evals),
            "{label}"
        );
    }
}

#[test]
fn fused_stepper_matches_the_portable_path_bit_for_bit() {
    let Some(kernels) = fused_kernels("fused_stepper_matches_the_portable_path_bit_for_bit") else {
        return;
    };
    // Every register count (N = 2..32 in 1..8 registers), both signs of α,
    // the paper's single flip with a kink that arrives inside the run.
    for (n, alpha) in [
        (2, 60.0),
        (3, -60.0),
        (4, 86.0),
        (5, 60.0),
        (8, -50.0),
        (9, 60.0),
        (10, 60.0),
        (10, -60.0),
        (12, 50.0),
        (13, -86.0),
        (17, 60.0),
        (24, 60.0),
        (32, -60.0),
    ] {
        let params = Params::paper(alpha).unwrap().with(n, 1.3, alpha).unwrap();
        let scenario = Scenario::single_flip(params, 100.0, 400.0).unwrap();
        let samples: Vec<f64> = (0..=40).map(|k| 10.0 * k as f64).collect();
        let what = format!("N = {n}, α = {alpha}");
        assert_fused_matches_portable(&kernels, &scenario, &samples, &what);
    }
}

#[test]
fn chain_stepper_matches_the_portable_path_bit_for_bit() {
    let Some(kernels) = fused_kernels("chain_stepper_matches_the_portable_path_bit_for_bit") else {
        return;
    };
    // N > 32: one to many vectors, every remainder of the last vector,
    // both signs of α, a kink that arrives inside the run.
    for (n, alpha) in [
        (33, 60.0),
        (34, -60.0),
        (39, 86.0),
        (40, 60.0),
        (47, -50.0),
        (64, 60.0),
        (100, -86.0),
        (257, 60.0),
        (1000, 60.0),
    ] {
        let params = Params::paper(alpha).unwrap().with(n, 1.3, alpha).unwrap();
        let scenario = Scenario::single_flip(params, 100.0, 300.0).unwrap();
        let samples: Vec<f64> = (0..=30).map(|k| 10.0 * k as f64).collect();
        assert_fused_matches_portable(
            &kernels,
            &scenario,
            &samples,
            &format!("N = {n}, α = {alpha}"),
        );
    }
    let params = Params::paper(60.0).unwrap().with(50, 1.3, 60.0).unwrap();
    let drive = Drive::two_flips(params.alpha, 50.0, 120.0).unwrap();
    let two = Scenario::with_drive(params, drive, 300.0).unwrap();
    assert_fused_matches_portable(&kernels, &two, &[33.3, 120.0, 299.99], "N = 50, two flips");
    let mut rng = Lcg(9);
    let mut free = Scenario::single_flip(params, 100.0, 50.0).unwrap();
    free.protocol = Protocol::Free;
    free.initial = State {
        q: perturbed(&free.initial.q, &mut rng, 0.05),
        v: perturbed(&vec![0.0; free.initial.v.len()], &mut rng, 0.02),
    };
    assert_fused_matches_portable(&kernels, &free, &[1.0, 25.0], "N = 50, free ladder");
}

#[test]
fn fused_stepper_matches_with_two_flips_and_without_a_drive() {
    let Some(kernels) = fused_kernels("fused_stepper_matches_with_two_flips_and_without_a_drive")
    else {
        return;
    };
    let params = Params::paper(60.0).unwrap();
    let drive = Drive::two_flips(params.alpha, 50.0, 120.0).unwrap();
    let two = Scenario::with_drive(params, drive, 300.0).unwrap();
    assert_fused_matches_portable(&kernels, &two, &[33.3, 120.0, 299.99], "two flips");
    // Free ladder (block 1 not driven) from a random, moving start.
    let mut rng = Lcg(5);
    let mut free = Scenario::single_flip(params, 100.0, 50.0).unwrap();
    free.protocol = Protocol::Free;
    free.initial = State {
        q: perturbed(&free.initial.q, &mut rng, 0.05),
        v: perturbed(&vec![0.0; free.initial.v.len()], &mut rng, 0.02),
    };
    assert_fused_matches_portable(&kernels, &free, &[1.0, 25.0], "free ladder");
}

#[test]
fn fused_stepper_reports_the_same_divergence() {
    let Some(kernels) = fused_kernels("fused_stepper_reports_the_same_divergence") else {
        return;
    };
    // Symplectic Euler far beyond its stability bound (2/ω_max ≈ 0.79),
    // in registers (N = 10) and along a chain (N = 70).
    for n in [10, 70] {
        let params = Params::paper(60.0).unwrap().with(n, 1.3, 60.0).unwrap();
        let scenario = Scenario::single_flip(params, 1000.0, 4000.0).unwrap();
        let config = IntegratorConfig::fixed(IntegratorKind::SymplecticEuler, 1.5);
        let portable =
            crate::common::kernels::run_stepped(&scenario, &[], &config, Stepping::Portable)
                .unwrap_err();
        for &stepping in &kernels {
            let fused =
                crate::common::kernels::run_stepped(&scenario, &[], &config, stepping).unwrap_err();
            assert_eq!(
                fused.to_string(),
                portable.to_string(),
                "N = {n}, {stepping:?}"
            );
        }
        assert!(
            portable.to_string().contains("diverged at t = "),
            "{portable}"
        );
    }
}

/// Near α = 90° whole groups of blocks turn the other way round, through
/// ±180°, instead of through the horizontal: their polarisation sin θ
/// changes sign although θ does not (docs/model.md). Every block that ends
/// near −α (mod 360°) has arrived, and the fused kernels agree with the
/// portable path bit for bit.
#[test]
fn blocks_turning_through_180_degrees_have_arrival_times() {
    let alpha = 88.0;
    let params = Params::paper(alpha).unwrap().with(20, 1.3, alpha).unwrap();
    let scenario = Scenario::single_flip(params, sim::PAPER_DRIVE_TIME, 3000.0).unwrap();
    let config = IntegratorConfig::paper();
    let traj =
        crate::common::kernels::run_stepped(&scenario, &[], &config, Stepping::Portable).unwrap();
    let wrapped = traj.final_theta_deg();
    let unwrapped = traj.final_theta_deg_unwrapped();
    let mut turned_round = 0;
    for (n, (w, u)) in wrapped.iter().zip(&unwrapped).enumerate() {
        assert!(*w > -180.0 && *w <= 180.0, "block {}: {w}°", n + 1);
        assert!(
            ((u - w) / 360.0).fract() == 0.0,
            "block {}: {u}° wraps to {w}°",
            n + 1
        );
        if (w + alpha).abs() < 10.0 {
            assert!(
                traj.arrival_times[n].is_some(),
                "block {} ends at {w}° (unwrapped {u}°) with no arrival",
                n + 1
            );
        }
        if *u > 180.0 {
            turned_round += 1;
        }
    }
    // The run does what this test is about: blocks turned through 180°
    // (θ ends near 272°, so θ never changed sign), and most blocks end
    // near −88°.
    assert!(turned_round >= 3, "{unwrapped:?}");
    let near = wrapped
        .iter()
        .filter(|w| (**w + alpha).abs() < 10.0)
        .count();
    assert!(near >= 15, "{wrapped:?}");
    if let Some(kernels) = fused_kernels("blocks_turning_through_180_degrees (fused part)") {
        assert_fused_matches_portable(&kernels, &scenario, &[500.0, 1500.0], "α = 88°, N = 20");
    }
}
