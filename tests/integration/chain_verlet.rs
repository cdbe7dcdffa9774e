//! Velocity Verlet on long ladders in the chain kernel (`sim::chain`,
//! N > 32): the portable path's trajectory bit for bit (docs/performance.md,
//! "Long chains").

use crate::common;
use crate::common::lcg::Lcg;
use jacobs_ladder::model::Params;
use jacobs_ladder::sim::{
    Drive, IntegratorConfig, IntegratorKind, Protocol, Scenario, State, Stepping,
};

/// Every kernel this CPU offers, `Fastest` first; `None` without AVX2
/// (then the chain path is the portable one and there is nothing to
/// compare).
fn kernels(test: &str) -> Option<Vec<Stepping>> {
    let fused: Vec<Stepping> = common::kernels::fused(test)
        .into_iter()
        .map(|k| k.0)
        .collect();
    (!fused.is_empty()).then(|| [Stepping::Fastest].into_iter().chain(fused).collect())
}

/// Asserts that every kernel gives the portable path's Verlet run at
/// step `dt`: samples, arrivals, final state, counts, or the same error.
fn assert_same(kernels: &[Stepping], scenario: &Scenario, samples: &[f64], dt: f64, what: &str) {
    let config = IntegratorConfig::fixed(IntegratorKind::Verlet, dt);
    let portable = common::kernels::run_stepped(scenario, samples, &config, Stepping::Portable);
    for &stepping in kernels {
        let fast = common::kernels::run_stepped(scenario, samples, &config, stepping);
        let label = format!("{what}, dt = {dt}, {stepping:?}");
        let (fast, portable) = match (fast, &portable) {
            (Ok(f), Ok(p)) => (f, p),
            (Err(f), Err(p)) => {
                assert_eq!(f.to_string(), p.to_string(), "{label}");
                continue;
            }
            (f, p) => panic!("{label}: {:?} against {:?}", f.err(), p.as_ref().err()),
        };
        assert_eq!(fast.times, portable.times, "{label}");
        assert_eq!(fast.states, portable.states, "{label}");
        assert_eq!(fast.velocities, portable.velocities, "{label}");
        assert_eq!(fast.arrival_times, portable.arrival_times, "{label}");
        assert!(
            fast.arrival_times.iter().filter(|a| a.is_some()).count() > 1 || what.contains("free"),
            "{label}: the kink must arrive inside the run"
        );
        assert_eq!(fast.final_state, portable.final_state, "{label}");
        assert_eq!(
            (fast.steps, fast.force_evals),
            (portable.steps, portable.force_evals),
            "{label}"
        );
    }
}

#[test]
fn chain_verlet_matches_the_portable_path_bit_for_bit() {
    let Some(kernels) = kernels("chain_verlet_matches_the_portable_path_bit_for_bit") else {
        return;
    };
    // One to many vectors, every remainder of the last vector, both signs
    // of α; dt = 0.25 (the scenes' step) and 0.3 (steps that land on the
    // samples and the drive's end).
    for (n, alpha, dt) in [
        (33, 60.0, 0.25),
        (34, -60.0, 0.3),
        (39, 86.0, 0.25),
        (40, 60.0, 0.3),
        (47, -50.0, 0.25),
        (64, 60.0, 0.25),
        (100, -86.0, 0.3),
        (200, 60.0, 0.25),
    ] {
        let params = Params::paper(alpha).unwrap().with(n, 1.3, alpha).unwrap();
        let scenario = Scenario::single_flip(params, 100.0, 300.0).unwrap();
        let samples: Vec<f64> = (0..=30).map(|k| 10.0 * k as f64 + 0.07).collect();
        assert_same(
            &kernels,
            &scenario,
            &samples,
            dt,
            &format!("N = {n}, α = {alpha}"),
        );
    }
    let params = Params::paper(60.0).unwrap().with(50, 1.3, 60.0).unwrap();
    let drive = Drive::two_flips(params.alpha, 50.0, 120.0).unwrap();
    let two = Scenario::with_drive(params, drive, 300.0).unwrap();
    assert_same(
        &kernels,
        &two,
        &[33.3, 120.0, 299.99],
        0.25,
        "N = 50, two flips",
    );
    let mut rng = Lcg(9);
    let mut free = Scenario::single_flip(params, 100.0, 50.0).unwrap();
    free.protocol = Protocol::Free;
    let moved = |x: &[f64], rng: &mut Lcg, size: f64| -> Vec<f64> {
        x.iter().map(|x| x + size * rng.uniform()).collect()
    };
    free.initial = State {
        q: moved(&free.initial.q, &mut rng, 0.05),
        v: moved(&vec![0.0; free.initial.v.len()], &mut rng, 0.02),
    };
    assert_same(&kernels, &free, &[1.0, 25.0], 0.25, "N = 50, free ladder");
    // Far beyond Verlet's bound 2/ω_max ≈ 0.79: the same divergence.
    let params = Params::paper(60.0).unwrap().with(70, 1.3, 60.0).unwrap();
    let wild = Scenario::single_flip(params, 100.0, 300.0).unwrap();
    assert_same(&kernels, &wild, &[], 1.5, "N = 70, unstable");
}
