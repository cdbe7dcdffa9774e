//! Every simulated scene of the catalogue is run with the measured scene
//! integrator (`SCENE_INTEGRATOR`, velocity Verlet at dt = 0.25) and with a
//! tight dopri5 reference: each block flips in both or in neither, and every
//! arrival time agrees within 1 τ; every block ends with the same
//! orientation (within 1°), which covers the later flips of movies 10 and
//! 11. And the issue's goal: for the α = 60°
//! kink the cheapest setting within 1 τ costs at most 4 × 10^4 force
//! evaluations (the paper's forward Euler at dt = 0.01 costs 4 × 10^5).
//!
//! Run in release: `cargo test --release --test scenes_accuracy`.

use jacobs_ladder::bench::{self, BenchScene};
use jacobs_ladder::catalog::{self, CATALOGUE, Content, SCENE_INTEGRATOR, SimSpec};
use jacobs_ladder::sim::{self, IntegratorConfig, IntegratorKind};

/// Tolerance of the reference runs.
const REFERENCE_RTOL: f64 = 1e-10;

/// Every distinct simulation the catalogue draws, with the entries using it.
fn simulated_scenes() -> Vec<(String, SimSpec)> {
    let mut out: Vec<(String, SimSpec)> = Vec::new();
    let mut add = |what: String, sim: SimSpec| {
        if let Some(seen) = out.iter_mut().find(|(_, s)| *s == sim) {
            seen.0.push_str(&format!(", {what}"));
        } else {
            out.push((what, sim));
        }
    };
    for e in CATALOGUE {
        match e.content {
            Content::Strips(strips) => {
                for s in strips {
                    add(format!("{} {}", e.id, s.label), s.sim);
                }
            }
            Content::Movie { sim, .. } => add(format!("movie {}", e.id), sim),
            Content::Arrivals(alphas) => {
                for &a in alphas {
                    for alpha in [a, -a] {
                        // The S6 scenes: the paper's single flip, 4000 τ.
                        let sim = SimSpec {
                            alpha_deg: alpha,
                            b: 1.3,
                            n: 10,
                            drive: jacobs_ladder::catalog::DriveSpec::Single,
                            t_end: 4000.0,
                        };
                        add(format!("{} α = {alpha}", e.id), sim);
                    }
                }
            }
            Content::Theory(_) => {}
        }
    }
    out
}

#[test]
fn every_scene_matches_the_reference_within_one_tau() {
    use rayon::prelude::*;
    let scenes = simulated_scenes();
    assert!(scenes.len() >= 10, "found {} scenes", scenes.len());
    let failures: Vec<String> = scenes
        .par_iter()
        .map(|(what, spec)| {
            let scenario = spec.scenario().unwrap();
            let run = sim::simulate(&scenario, &[], &SCENE_INTEGRATOR)
                .unwrap_or_else(|e| panic!("{what}: {e}"));
            let reference = sim::simulate(
                &scenario,
                &[],
                &IntegratorConfig::adaptive(REFERENCE_RTOL),
            )
            .unwrap_or_else(|e| panic!("{what}: reference: {e}"));
            let mut bad = Vec::new();
            let mut worst: f64 = 0.0;
            for (n, (a, r)) in run
                .arrival_times
                .iter()
                .zip(&reference.arrival_times)
                .enumerate()
            {
                match (a, r) {
                    (Some(a), Some(r)) => {
                        worst = worst.max((a - r).abs());
                        if (a - r).abs() > 1.0 {
                            bad.push(format!("block {}: {a:.3} vs {r:.3}", n + 1));
                        }
                    }
                    (None, None) => {}
                    _ => bad.push(format!("block {}: flips {a:?} vs {r:?}", n + 1)),
                }
            }
            // Later flips (movies 10, 11) show in the final orientations.
            let (fa, fr) = (run.final_theta_deg(), reference.final_theta_deg());
            for (n, (a, r)) in fa.iter().zip(&fr).enumerate() {
                if a.signum() != r.signum() || (a - r).abs() > 1.0 {
                    bad.push(format!("block {} ends at {a:.3}° vs {r:.3}°", n + 1));
                }
            }
            if worst > catalog::SCENE_ARRIVAL_ERROR {
                bad.push(format!(
                    "worst arrival error {worst:.4} τ above the catalogue's {} τ",
                    catalog::SCENE_ARRIVAL_ERROR
                ));
            }
            let flips = run.arrival_times.iter().filter(|t| t.is_some()).count();
            eprintln!(
                "{what}: {flips} flips, worst arrival error {worst:.4} τ, {} vs {} force evaluations",
                run.force_evals, reference.force_evals
            );
            if bad.is_empty() {
                String::new()
            } else {
                format!("{what}: {}", bad.join("; "))
            }
        })
        .filter(|s| !s.is_empty())
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn cheapest_setting_within_one_tau_meets_the_issue_goal() {
    let scene = BenchScene::paper(60.0).unwrap();
    let reference = scene.reference(bench::REFERENCE_RTOL).unwrap();
    let sweeps = vec![
        bench::sweep(
            &scene,
            &reference,
            IntegratorKind::Verlet,
            &[0.1, 0.25, 0.6],
            1,
        )
        .unwrap(),
        bench::sweep(
            &scene,
            &reference,
            IntegratorKind::SymplecticEuler,
            &[0.01, 0.1],
            1,
        )
        .unwrap(),
    ];
    let (name, point) = bench::cheapest_within(&sweeps, 1.0).expect("a setting within 1 τ");
    eprintln!(
        "cheapest within 1 τ: {name} at dt = {:?}, {} force evaluations, arrival error {:?} τ",
        point.dt, point.force_evals, point.arrival_error
    );
    assert!(
        point.force_evals <= 40_000,
        "{name}: {} force evaluations",
        point.force_evals
    );
    // The paper's setting is converged too, at ten times the goal's cost.
    let paper = &sweeps[1].points[0];
    assert!(paper.arrival_error.is_some_and(|e| e < 1.0));
    assert!(paper.force_evals >= 400_000);
}
