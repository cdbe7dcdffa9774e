//! The energies of a run (`sim::Trajectory::energies`): kinetic, elastic,
//! gravitational and the energy dissipated so far, recorded in the run
//! loop (`sim::RunOptions::dissipation`). Once the drive has ended nothing
//! works on the ladder, so kinetic + elastic + gravitational + dissipated
//! must stay flat to the integrator's accuracy.

use jacobs_ladder::model::Params;
use jacobs_ladder::sim::{self, IntegratorConfig, IntegratorKind, RunOptions, Scenario};

/// The paper's kink at α = 60° with a short drive, sampled every τ.
fn kink(t_d: f64, t_end: f64) -> (Scenario, Vec<f64>) {
    let params = Params::paper(60.0).unwrap();
    let scenario = Scenario::single_flip(params, t_d, t_end).unwrap();
    let samples = (0..=t_end as usize).map(|k| k as f64).collect();
    (scenario, samples)
}

/// Largest departure of `e` from its value at the first sample at or after
/// `from`, over the samples from there on.
fn drift(times: &[f64], e: &[f64], from: f64) -> f64 {
    let start = times.iter().position(|&t| t >= from).unwrap();
    e[start..]
        .iter()
        .map(|x| (x - e[start]).abs())
        .fold(0.0, f64::max)
}

/// Kinetic + elastic + gravitational + dissipated after the drive, for a
/// run with `config`: (its drift, the energy dissipated after the drive).
fn budget(config: &IntegratorConfig) -> (f64, f64, f64) {
    let (t_d, t_end) = (100.0, 600.0);
    let (scenario, samples) = kink(t_d, t_end);
    let options = RunOptions::default().dissipation(true);
    let traj = sim::run(&scenario, &samples, config, &options).unwrap();
    let e = traj.energies(&scenario.ladder);
    assert_eq!(e.dissipated.len(), traj.times.len());
    let total = e.total();
    let with_dissipated: Vec<f64> = total
        .iter()
        .zip(&e.dissipated)
        .map(|(a, b)| a + b)
        .collect();
    let start = traj.times.iter().position(|&t| t >= t_d).unwrap();
    let lost = e.dissipated.last().unwrap() - e.dissipated[start];
    (
        drift(&traj.times, &with_dissipated, t_d),
        drift(&traj.times, &total, t_d),
        lost,
    )
}

#[test]
fn total_plus_dissipated_is_flat_after_the_drive() {
    // Velocity Verlet (second order): halving the step must shrink the
    // drift about fourfold, and at dt = 0.05 it must be a small part of
    // what was dissipated after the drive. Without the dissipated energy
    // the total falls by all of it: the test fails if it is left out.
    let verlet = |dt| IntegratorConfig::fixed(IntegratorKind::Verlet, dt);
    let (coarse, _, _) = budget(&verlet(0.1));
    let (fine, without, lost) = budget(&verlet(0.05));
    println!(
        "verlet: drift {coarse:.3e} at dt 0.1, {fine:.3e} at dt 0.05; \
         total alone drifts {without:.3e}; dissipated after the drive {lost:.3e}"
    );
    assert!(lost > 0.0, "the kink's motion dissipates energy");
    assert!(
        without > 0.5 * lost,
        "total alone {without:e}, lost {lost:e}"
    );
    assert!(fine < 1e-3 * lost, "drift {fine:e} of {lost:e} dissipated");
    let ratio = coarse / fine;
    assert!(
        (2.5..6.0).contains(&ratio),
        "second order: drift ratio {ratio} for a halved step"
    );
    // The paper's symplectic Euler (first order) at its dt = 0.01.
    let (paper, _, lost) = budget(&IntegratorConfig::paper());
    println!("symplectic Euler dt 0.01: drift {paper:.3e} of {lost:.3e}");
    assert!(
        paper < 1e-2 * lost,
        "drift {paper:e} of {lost:e} dissipated"
    );
}

#[test]
fn recording_the_dissipation_leaves_the_trajectory_bit_for_bit() {
    let (scenario, samples) = kink(100.0, 300.0);
    for config in [
        IntegratorConfig::paper(),
        IntegratorConfig::fixed(IntegratorKind::Verlet, 0.05),
    ] {
        let plain = sim::simulate(&scenario, &samples, &config).unwrap();
        let options = RunOptions::default().dissipation(true);
        let recorded = sim::run(&scenario, &samples, &config, &options).unwrap();
        assert!(plain.dissipated.is_empty());
        assert_eq!(plain.states, recorded.states);
        assert_eq!(plain.velocities, recorded.velocities);
        assert_eq!(plain.arrival_times, recorded.arrival_times);
        // Dissipation only grows.
        assert!(recorded.dissipated.windows(2).all(|w| w[1] >= w[0]));
        assert_eq!(recorded.dissipated[0], 0.0);
    }
}
