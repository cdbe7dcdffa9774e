//! Many runs at once (`sim::batch`): every run's trajectory is the one the
//! portable path gives it alone (`sim::run` without samples), bit for bit, with
//! any mix of scenarios, more runs than lanes, runs ending at different
//! times, stop rules, divergence, and every instruction set this CPU has.

use crate::common::lcg::Lcg;
use jacobs_ladder::model::{Ladder, Params};
use jacobs_ladder::sim::{
    self, Drive, IntegratorConfig, IntegratorKind, Isa, Protocol, Scenario, State, Stepping,
    StopRule, Trajectory, batch,
};

fn kink(n: usize, alpha: f64, t_d: f64, t_end: f64) -> Scenario {
    let params = Params::paper(alpha).unwrap().with(n, 1.3, alpha).unwrap();
    Scenario::single_flip(params, t_d, t_end).unwrap()
}

/// A free ladder from a perturbed, moving start; `spin` on block 3's θ̇.
fn free(n: usize, seed: u64, spin: f64, t_end: f64) -> Scenario {
    let mut rng = Lcg(seed);
    let params = Params::paper(60.0).unwrap().with(n, 1.3, 60.0).unwrap();
    let ladder = Ladder::new(params);
    let q = ladder
        .ground_state()
        .iter()
        .map(|x| x + 0.05 * rng.uniform())
        .collect();
    let mut v: Vec<f64> = (0..3 * n).map(|_| 0.02 * rng.uniform()).collect();
    v[8] += spin;
    Scenario {
        ladder,
        protocol: Protocol::Free,
        initial: State { q, v },
        t_end,
    }
}

/// A mix of N = 10 scenarios (more than the lanes of both workers), a few
/// other N (N = 2, 3, 17 and one beyond the fused kernel's 32), and runs
/// that diverge or have nothing to do.
fn mixed() -> Vec<Scenario> {
    let mut out = Vec::new();
    for (k, alpha) in [
        40.0, 50.0, 60.0, 75.0, 86.0, 88.0, -50.0, -60.0, -86.0, 89.5,
    ]
    .into_iter()
    .enumerate()
    {
        out.push(kink(10, alpha, 100.0, 300.0 + 37.3 * k as f64));
    }
    for (k, alpha) in [45.0, 55.0, 65.0, -70.0, 80.0, -80.0]
        .into_iter()
        .enumerate()
    {
        let mut sc = kink(10, alpha, 60.0 + 10.0 * k as f64, 250.0);
        // Other damping, gravity and b, read per lane.
        let mut p = sc.ladder.params;
        p.gamma = 0.01 * (k + 1) as f64;
        p.gravity = 1e-4 * (k + 1) as f64;
        p.b = 1.2 + 0.05 * k as f64;
        sc = Scenario::single_flip(p, 60.0 + 10.0 * k as f64, 250.0 + k as f64).unwrap();
        out.push(sc);
    }
    let two = {
        let params = Params::paper(60.0).unwrap();
        let drive = Drive::two_flips(params.alpha, 50.0, 120.0).unwrap();
        Scenario::with_drive(params, drive, 300.0).unwrap()
    };
    out.push(two);
    out.push(free(10, 5, 0.0, 77.7));
    // Spins more than four turns within a few τ: diverges.
    out.push(free(10, 6, 60.0, 200.0));
    out.push(kink(10, 60.0, 100.0, 0.0));
    out.push(kink(10, 70.0, 1000.0, 123.456));
    for n in [2, 3, 17, 40] {
        out.push(kink(n, 60.0, 50.0, 180.0));
        out.push(kink(n, -60.0, 50.0, 140.0));
    }
    out
}

fn same_run(
    got: &jacobs_ladder::Result<Trajectory>,
    want: &jacobs_ladder::Result<Trajectory>,
    what: &str,
) {
    match (got, want) {
        (Ok(g), Ok(w)) => {
            assert_eq!(g.arrival_times, w.arrival_times, "{what}: arrivals");
            assert_eq!(g.final_state, w.final_state, "{what}: final state");
            assert_eq!(
                (g.t_final, g.steps, g.force_evals),
                (w.t_final, w.steps, w.force_evals),
                "{what}: time, steps, evaluations"
            );
        }
        (Err(g), Err(w)) => assert_eq!(g.to_string(), w.to_string(), "{what}"),
        (g, w) => panic!(
            "{what}: batch {:?}, portable {:?}",
            g.as_ref().map(|t| t.t_final),
            w.as_ref().map(|t| t.t_final)
        ),
    }
}

/// Every way of stepping a batch that this CPU offers.
fn steppings() -> Vec<Stepping> {
    let fused = [Isa::Avx2, Isa::Avx512]
        .into_iter()
        .filter(|isa| isa.available())
        .map(Stepping::Fused);
    [Stepping::Fastest].into_iter().chain(fused).collect()
}

fn assert_batch_matches_portable(
    scenarios: &[Scenario],
    config: &IntegratorConfig,
    stop: &StopRule,
) {
    let portable: Vec<_> = scenarios
        .iter()
        .map(|sc| {
            sim::run(
                sc,
                &[],
                config,
                &sim::RunOptions::default()
                    .stepping(Stepping::Portable)
                    .stop(stop)
                    .every_step(false),
            )
        })
        .collect();
    for stepping in steppings() {
        let many = batch::simulate_many(
            scenarios,
            config,
            &sim::RunOptions::default().stepping(stepping).stop(stop),
        );
        assert_eq!(many.len(), scenarios.len());
        for (k, (got, want)) in many.iter().zip(&portable).enumerate() {
            let sc = &scenarios[k];
            let what = format!(
                "run {k} (N = {}, α = {:.1}°, t_end = {}), {stepping:?}",
                sc.ladder.n(),
                sc.ladder.params.alpha_deg(),
                sc.t_end
            );
            same_run(got, want, &what);
        }
    }
}

#[test]
fn every_run_of_a_batch_is_the_portable_run_bit_for_bit() {
    let scenarios = mixed();
    let config = IntegratorConfig::paper();
    assert_batch_matches_portable(&scenarios, &config, &sim::run_to_end);
    // Velocity Verlet at the scenes' step (`auto`) and a finer one.
    for dt in [0.25, 0.1] {
        let verlet = IntegratorConfig::fixed(IntegratorKind::Verlet, dt);
        assert_batch_matches_portable(&scenarios, &verlet, &sim::run_to_end);
    }
    // The mix does what it is meant to: runs flip, one diverges.
    let many = batch::simulate_many(&scenarios, &config, &sim::RunOptions::default());
    let flipped = many
        .iter()
        .flatten()
        .filter(|t| t.arrival_times.iter().skip(2).any(Option::is_some))
        .count();
    assert!(flipped >= 10, "{flipped} runs flipped");
    let diverged: Vec<String> = many
        .iter()
        .filter_map(|r| r.as_ref().err().map(|e| e.to_string()))
        .collect();
    assert_eq!(diverged.len(), 1, "{diverged:?}");
    assert!(
        diverged[0].contains("turned more than four times"),
        "{diverged:?}"
    );
}

#[test]
fn a_stop_rule_ends_runs_where_the_portable_path_ends_them() {
    let scenarios = mixed();
    let config = IntegratorConfig::paper();
    // Decided once five blocks have flipped, or past 200 τ.
    let stop =
        |v: &sim::StopView| v.arrivals.iter().filter(|a| a.is_some()).count() >= 5 || v.t > 200.0;
    assert_batch_matches_portable(&scenarios, &config, &stop);
    let verlet = IntegratorConfig::fixed(IntegratorKind::Verlet, 0.25);
    assert_batch_matches_portable(&scenarios, &verlet, &stop);
    let many = batch::simulate_many(&scenarios, &config, &sim::RunOptions::default().stop(&stop));
    let early = many
        .iter()
        .zip(&scenarios)
        .filter(|(r, sc)| r.as_ref().is_ok_and(|t| t.t_final < sc.t_end))
        .count();
    assert!(early >= 10, "{early} runs stopped early");
}

#[test]
fn other_steps_and_integrators_also_match() {
    let scenarios: Vec<Scenario> = [60.0, -60.0, 86.0, 40.0]
        .into_iter()
        .map(|a| kink(10, a, 100.0, 200.0))
        .collect();
    // A step that does not divide the drive time; a step beyond the
    // stability bound (every run diverges, with the portable message).
    for dt in [0.0137, 0.3, 1.5] {
        let config = IntegratorConfig::fixed(IntegratorKind::SymplecticEuler, dt);
        assert_batch_matches_portable(&scenarios, &config, &sim::run_to_end);
    }
    // Verlet beyond its stability bound; RK4 goes one by one through the
    // single-run path.
    for config in [
        IntegratorConfig::fixed(IntegratorKind::Verlet, 1.5),
        IntegratorConfig::fixed(IntegratorKind::Verlet, 0.0137),
        IntegratorConfig::fixed(IntegratorKind::Rk4, 0.25),
    ] {
        assert_batch_matches_portable(&scenarios, &config, &sim::run_to_end);
    }
    // Bad input reaches every run.
    let bad = IntegratorConfig::fixed(IntegratorKind::SymplecticEuler, -1.0);
    let many = batch::simulate_many(&scenarios, &bad, &sim::RunOptions::default());
    assert!(
        many.iter()
            .all(|r| r.as_ref().is_err_and(|e| e.exit_code() == 2))
    );
}
