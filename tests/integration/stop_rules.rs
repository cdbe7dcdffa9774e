//! The rules that end an experiment figure's runs decide from the physics
//! of the scene, with margins against its own scales (docs/experiments.md,
//! "Each of the figures' runs ends once it has decided"): a pin is held
//! when slow against both the friction's smoothing ω_ε and the block's
//! own rate ω_b = √(G/I); where ω_ε is not small against ω_b the rule
//! cannot decide, says so, and the run goes to its end.

use jacobs_ladder::catalog;
use jacobs_ladder::scene::{Kind, Scene};
use jacobs_ladder::scenes::experiments;

fn linkage(friction_rate: f64) -> Scene {
    let mut scene = catalog::find(Kind::Figure, "linkage-friction")
        .unwrap()
        .scene
        .clone();
    scene.apparatus.as_mut().unwrap().friction_rate = friction_rate;
    scene
}

/// At ω_ε = 3 rad/s every run with μ_p ≥ 0.125 ended at the earliest time
/// the rule could fire (2390 τ) with 3–4 blocks flipped, while the same
/// kink at μ_p = 0.5 run to its 20 s flips all 8: a pin turning at 9 rad/s
/// was "held". Now the rule cannot decide there (3 ω_ε = 9 rad/s against
/// ω_b = 48 rad/s), each run says so in its data, and goes to its 20 s.
#[test]
fn a_smoothing_as_fast_as_the_blocks_decides_nothing_and_runs_to_the_end() {
    for rate in [3.0, 100.0] {
        let scene = linkage(rate);
        let t_end = scene.run.t_end;
        let (rows, data) = experiments::fronts(&scene, &[0.5]).unwrap();
        println!("ω_ε = {rate} rad/s: {rows:?}");
        for d in &data {
            assert!(
                d.label.contains("the stop rule cannot decide") && d.label.contains("rad/s"),
                "{}",
                d.label
            );
            // Every block flipped ends a run too; otherwise it ran to its end.
            let all = d.arrival_times.iter().all(Option::is_some);
            assert!(
                all || d.t_end >= t_end * (1.0 - 1e-9),
                "{}: {}",
                d.label,
                d.t_end
            );
        }
        // The kink at μ_p = 0.5 flips the whole chain, as it does at the
        // scene's ω_ε (and as run to 20 s at 3 rad/s).
        assert_eq!(rows[0].1, scene.model.n, "ω_ε = {rate}: {rows:?}");
    }
}

/// In air, without pin friction, nothing but "every block flipped" ends a
/// run, whatever ω_ε says: the friction-free runs of the figure at 100
/// rad/s are those at the scene's 0.05 rad/s.
#[test]
fn without_pin_friction_the_smoothing_changes_nothing() {
    let (fast, _) = experiments::fronts(&linkage(100.0), &[0.0]).unwrap();
    let (slow, _) = experiments::fronts(&linkage(0.05), &[0.0]).unwrap();
    assert_eq!(fast, slow);
}

/// At the scene's own ω_ε (0.05 rad/s, 3 ω_ε a hundredth of ω_b) the rule
/// decides as it did: the antikink at μ_p = 0.875 stops after 2 blocks
/// and says nothing about the rule.
#[test]
fn the_scenes_own_smoothing_still_decides() {
    let scene = linkage(0.05);
    let (rows, data) = experiments::fronts(&scene, &[0.875]).unwrap();
    assert_eq!(rows, vec![(0.875, scene.model.n, 2)]);
    assert!(data.iter().all(|d| !d.label.contains("cannot decide")));
    let rate = experiments::block_rate(2e-4, (1.0 + 0.01) / 12.0, 0.0).unwrap();
    assert!(experiments::decidable(3.0 * 1.01e-3, Some(rate), 1.01e-3).is_err());
}
