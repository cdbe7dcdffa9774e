//! Every domain wall a wave of its own (docs/sweeps.md), checked against a
//! detector written here, and outcomes proved by the state.

use jacobs_ladder::scene::sweep::SweepSpec;
use jacobs_ladder::scene::{Flip, Method, OutputSpec, Scene};
use jacobs_ladder::sim::IntegratorKind;
use jacobs_ladder::sim::waves::{Fate, WaveKind};
use jacobs_ladder::sweep::outcome::Outcome;
use jacobs_ladder::sweep::run::run_point;

/// A scene at `alpha` with flips of block 1 starting at `starts` (each
/// T_d = 1000 τ), Verlet at dt = 0.25 τ, to `t_end`.
fn scene(alpha: f64, n: usize, starts: &[f64], t_end: f64) -> Scene {
    let mut s = Scene::default();
    s.model.alpha = alpha;
    s.model.n = n;
    s.drive.flips = starts
        .iter()
        .map(|&start| Flip {
            start,
            duration: 1000.0,
        })
        .collect();
    s.run.t_end = t_end;
    s.run.integrator = Method::Fixed(IntegratorKind::Verlet);
    s.run.dt = Some(0.25);
    s.output = OutputSpec::Data;
    s
}

/// The test's own detector: from θ_n sampled every `dt`, every sign change
/// of sin θ_n, as (time by linear interpolation of sin θ, block), in time
/// order.
fn sign_changes(times: &[f64], states: &[Vec<f64>]) -> Vec<(f64, usize)> {
    let n = states[0].len() / 3;
    let mut out = Vec::new();
    for k in 1..times.len() {
        for i in 0..n {
            let (a, b) = (states[k - 1][3 * i + 2].sin(), states[k][3 * i + 2].sin());
            if (a >= 0.0) != (b >= 0.0) {
                let s = a / (a - b);
                out.push((times[k - 1] + s * (times[k] - times[k - 1]), i));
            }
        }
    }
    out.sort_by(|x, y| x.0.total_cmp(&y.0));
    out
}

/// Runs `s` sampled every 0.25 τ; returns the run and the test detector's
/// sign changes.
fn run_and_detect(s: &Scene) -> (jacobs_ladder::scenes::run::SceneRun, Vec<(f64, usize)>) {
    let samples: Vec<f64> = (0..=(s.run.t_end / 0.25) as usize)
        .map(|k| k as f64 * 0.25)
        .collect();
    let run = jacobs_ladder::scenes::run::simulate(s, &samples).unwrap();
    let changes = sign_changes(&run.trajectory.times, &run.trajectory.states);
    (run, changes)
}

/// Every recorded arrival of every wave is one of the detector's sign
/// changes (same block, within 0.3 τ, a step and the interpolation), and
/// every sign change of the detector is some wave's arrival at that block
/// or a later crossing of a block a wave had already crossed.
fn assert_waves_match(run: &jacobs_ladder::scenes::run::SceneRun, changes: &[(f64, usize)]) {
    let waves = &run.trajectory.waves.waves;
    let mut used = vec![false; changes.len()];
    for (w, wave) in waves.iter().enumerate() {
        for (i, a) in wave.arrival_times.iter().enumerate() {
            let Some(a) = a else { continue };
            let hit = changes
                .iter()
                .position(|&(t, b)| b == i && (t - a).abs() < 0.3)
                .unwrap_or_else(|| panic!("wave {w} at block {} ({a}): {changes:?}", i + 1));
            used[hit] = true;
        }
    }
    // The first sign change of every block belongs to some wave.
    let n = run.trajectory.arrival_times.len();
    for i in 0..n {
        if let Some(k) = changes.iter().position(|c| c.1 == i) {
            assert!(
                used[k],
                "block {}'s first change at {}",
                i + 1,
                changes[k].0
            );
        }
    }
}

#[test]
fn two_flips_launch_a_kink_and_an_antikink() {
    // α = 60°, N = 10: the kink (first flip) and, 2500 τ later, block 1
    // turned back: an antikink behind it.
    let s = scene(60.0, 10, &[0.0, 2500.0], 8000.0);
    let (run, changes) = run_and_detect(&s);
    let waves = &run.trajectory.waves.waves;
    let driven: Vec<_> = waves.iter().filter(|w| w.origin == 1).collect();
    assert_eq!(driven.len(), 2, "{waves:?}");
    assert_eq!(driven[0].kind, WaveKind::Kink);
    assert_eq!(driven[1].kind, WaveKind::Antikink);
    assert!((driven[0].launched_at - 500.0).abs() < 0.3);
    assert!((driven[1].launched_at - 3000.0).abs() < 0.3);
    assert_eq!(driven[0].fate, Fate::End);
    assert_waves_match(&run, &changes);
    // The top-level arrival times are the first wave's.
    for (i, a) in run.trajectory.arrival_times.iter().enumerate().take(9) {
        assert_eq!(*a, driven[0].arrival_times[i], "block {}", i + 1);
    }
}

#[test]
fn three_flips_at_80_degrees_launch_three_waves() {
    let s = scene(80.0, 10, &[0.0, 2000.0, 4000.0], 9000.0);
    let (run, changes) = run_and_detect(&s);
    let waves = &run.trajectory.waves.waves;
    let driven: Vec<_> = waves.iter().filter(|w| w.origin == 1).collect();
    assert_eq!(driven.len(), 3, "{waves:?}");
    let kinds: Vec<_> = driven.iter().map(|w| w.kind).collect();
    assert_eq!(
        kinds,
        [WaveKind::Kink, WaveKind::Antikink, WaveKind::Kink],
        "{waves:?}"
    );
    assert_waves_match(&run, &changes);
    // Block 1's three sign changes, at the middle of each flip.
    let top: Vec<f64> = changes.iter().filter(|c| c.1 == 0).map(|c| c.0).collect();
    assert_eq!(top.len(), 3);
    for (w, t) in driven.iter().zip(&top) {
        assert!((w.launched_at - t).abs() < 0.3, "{} vs {t}", w.launched_at);
    }
}

#[test]
fn movie_11s_two_waves_annihilate_each_other_at_the_same_time() {
    let entry = jacobs_ladder::catalog::find_any("11").unwrap();
    let mut s = entry.scene.clone();
    s.output = OutputSpec::Data;
    let (run, changes) = run_and_detect(&s);
    let waves = &run.trajectory.waves.waves;
    let driven: Vec<usize> = (0..waves.len()).filter(|&k| waves[k].origin == 1).collect();
    assert_eq!(driven.len(), 2, "{waves:?}");
    let (a, b) = (&waves[driven[0]], &waves[driven[1]]);
    assert_eq!(a.kind, WaveKind::Antikink);
    assert_eq!(b.kind, WaveKind::Kink);
    let (
        Fate::Annihilated {
            with: wa,
            at: ta,
            block: ba,
        },
        Fate::Annihilated {
            with: wb,
            at: tb,
            block: bb,
        },
    ) = (a.fate, b.fate)
    else {
        panic!("{:?} / {:?}", a.fate, b.fate);
    };
    assert_eq!((wa, wb), (driven[1], driven[0]));
    assert_eq!(ta, tb);
    assert_eq!(ba, bb);
    // At that time and block, the test's detector sees the block change.
    assert!(
        changes
            .iter()
            .any(|&(t, i)| i + 1 == ba && (t - ta).abs() < 0.3),
        "{ta} at block {ba}: {changes:?}"
    );
    assert_waves_match(&run, &changes);
}

#[test]
fn a_pinned_antikink_is_proved_at_rest_and_its_wave_stopped() {
    // α = −50°, N = 10: pinned at the top (docs/model.md, item 3).
    let s = scene(-50.0, 10, &[0.0], 10_000.0);
    let run = jacobs_ladder::scenes::run::simulate(&s, &[]).unwrap();
    let waves = &run.trajectory.waves.waves;
    assert_eq!(waves.len(), 1, "{waves:?}");
    assert_eq!(waves[0].fate, Fate::Stopped);
    assert!(waves[0].front <= 2);
    // The proof itself, at the final state.
    let st = &run.trajectory.final_state;
    let ladder = jacobs_ladder::model::Ladder::new(s.model.params().unwrap());
    let tol = jacobs_ladder::theory::stability::RestTolerances::default();
    let proof = jacobs_ladder::theory::stability::rest_proof(&ladder, &st.q, &st.v, &tol);
    assert!(proof.proved, "{proof:?}");
    let w2 = jacobs_ladder::theory::stability::smallest_omega_sq(&ladder, &st.q);
    assert!(w2 > 10.0 * tol.margin, "ω²_min = {w2}");
    // The sweep calls it pinned, decided by the proof (after the drive).
    let spec = SweepSpec {
        cap: 20_000.0,
        ..SweepSpec::default()
    };
    let r = run_point(&s, &spec).unwrap();
    assert_eq!(r.outcome, Outcome::Pinned, "{r:?}");
    assert!(r.t_decided.unwrap() > 1000.0);
}

/// Block N is free and turns its own way: kept out of the front (which
/// stops at N − 1) and recorded apart (docs/sweeps.md, "front and block
/// N"). In the pinning sweep's setting (N = 10) the bottom block falls over
/// on its own at α = 40° (at about 136 τ, before block 1 changes sign) and
/// at 48° (just before the kink arrives): the wall it launches annihilates
/// the driven kink. At 49° it has not turned when block N − 1 flips. Every
/// time checked against this test's own detector.
#[test]
fn block_n_is_kept_apart_from_the_front() {
    for (alpha, falls) in [(40.0, true), (48.0, true), (49.0, false)] {
        let s = scene(alpha, 10, &[0.0], 4000.0);
        let r = run_point(&s, &SweepSpec::default()).unwrap();
        // The outcome says what the driven kink did: annihilated where
        // block N's wall met it, though the chain ends flipped.
        let word = if falls {
            Outcome::Annihilated
        } else {
            Outcome::Propagated
        };
        assert_eq!(r.outcome, word, "α = {alpha}°: {r:?}");
        assert_eq!(r.front, 9, "α = {alpha}°: the front stops at N − 1");
        let t_decided = r.t_decided.unwrap();
        // The test's detector on the same scene, sampled every 0.25 τ.
        let mut again = s.clone();
        again.run.t_end = (t_decided / 0.25).ceil() * 0.25;
        let (_, changes) = run_and_detect(&again);
        let first = |block: usize| changes.iter().find(|c| c.1 == block).map(|c| c.0);
        let t_block_n = first(9).filter(|&t| t <= t_decided);
        assert_eq!(t_block_n.is_some(), falls, "α = {alpha}°: {changes:?}");
        match (r.block_n_turned_at, t_block_n) {
            (Some(a), Some(b)) => {
                assert!((a - b).abs() < 0.3, "α = {alpha}°: {a} against {b}");
                // Before block N − 1 flipped: on its own, not following.
                assert!(a < first(8).unwrap(), "α = {alpha}°");
            }
            (a, b) => assert_eq!(a, b, "α = {alpha}°"),
        }
        let driven = r.waves.waves.iter().find(|w| w.origin == 1).unwrap();
        if falls {
            let Fate::Annihilated { with, .. } = driven.fate else {
                panic!("α = {alpha}°: {:?}", r.waves)
            };
            assert_eq!(r.waves.waves[with].origin, 10, "α = {alpha}°");
        } else {
            assert_eq!(driven.fate, Fate::End, "α = {alpha}°");
        }
    }
    // At 40° block N turns before block 1 changes sign (the drive's sign
    // change is at 500 τ, the middle of its 1000 τ turn).
    let r = run_point(&scene(40.0, 10, &[0.0], 4000.0), &SweepSpec::default()).unwrap();
    assert!(r.block_n_turned_at.unwrap() < r.arrival_times[0].unwrap());
}

/// The kink at α = 60° on N = 185 blocks waits at block 2 for about
/// 23 000 τ, then runs to the bottom (docs/sweeps.md): the quiet-time rule
/// called it pinned; the rest proof never does (its kinetic energy stays
/// above the tolerance while it creeps), and it propagates.
#[test]
fn a_slow_escape_near_the_chain_length_edge_is_not_called_pinned() {
    let s = scene(60.0, 185, &[0.0], 4000.0);
    let spec = SweepSpec {
        cap: 80_000.0,
        ..SweepSpec::default()
    };
    let r = run_point(&s, &spec).unwrap();
    assert_eq!(r.outcome, Outcome::Propagated, "{:?}", (r.outcome, r.front));
    // It did wait: block 3 flipped after 20 000 τ.
    assert!(
        r.arrival_times[2].unwrap() > 20_000.0,
        "{:?}",
        r.arrival_times[2]
    );
}

/// The smallest mass-weighted eigenvalue ω² of the clamped Hessian at
/// `q`, computed here independently: a dense Hessian by central
/// differences of the analytic gradient (every free coordinate moved on
/// its own), symmetrised, scaled by M^(−1/2) on both sides, and nalgebra's
/// dense symmetric eigenvalues.
fn dense_smallest_omega_sq(ladder: &jacobs_ladder::model::Ladder, q: &[f64]) -> f64 {
    let free = q.len() - 3;
    let h_step = 1e-5;
    let mut h = nalgebra::DMatrix::<f64>::zeros(free, free);
    let (mut gp, mut gm) = (vec![0.0; q.len()], vec![0.0; q.len()]);
    for j in 0..free {
        let mut qp = q.to_vec();
        qp[3 + j] += h_step;
        ladder.gradient(&qp, &mut gp);
        qp[3 + j] -= 2.0 * h_step;
        ladder.gradient(&qp, &mut gm);
        for i in 0..free {
            h[(i, j)] = (gp[3 + i] - gm[3 + i]) / (2.0 * h_step);
        }
    }
    let inertia = ladder.params.inertia;
    let w = |k: usize| if k % 3 == 2 { inertia.sqrt() } else { 1.0 };
    let scaled = nalgebra::DMatrix::from_fn(free, free, |i, j| {
        0.5 * (h[(i, j)] + h[(j, i)]) / (w(i) * w(j))
    });
    scaled.symmetric_eigen().eigenvalues.min()
}

/// The rest proof's stability verdict agrees with dense eigenvalues on
/// small chains (stable hanging states, marginal unstretched ones, and
/// perturbed ones with negative directions), and a state at rest with zero
/// force at a marginal equilibrium is not proved: the proof must not
/// ignore the Hessian.
#[test]
fn the_rest_proof_decides_stability_by_the_hessian() {
    use jacobs_ladder::model::{Ladder, Params};
    use jacobs_ladder::sim::relax::{RelaxConfig, hanging};
    use jacobs_ladder::theory::stability::{RestTolerances, is_stable, rest_proof};
    let tol = RestTolerances::default();
    let mut verdicts = (0, 0);
    for alpha in [60.0, -50.0, 86.0, 20.0] {
        for n in [3, 5, 8] {
            let p = Params::paper(alpha).unwrap().with(n, 1.3, alpha).unwrap();
            let ladder = Ladder::new(p);
            let ground = ladder.ground_state();
            let hung = hanging(&ladder, &ground, &RelaxConfig::default())
                .unwrap()
                .q;
            let mut bent = hung.clone();
            for (k, x) in bent.iter_mut().enumerate().skip(3) {
                *x += 0.3 * ((k * 7919) as f64).sin();
            }
            for q in [&ground, &hung, &bent] {
                let dense = dense_smallest_omega_sq(&ladder, q);
                for margin in [tol.margin, 1e-4, -1e-3] {
                    if (dense - margin).abs() < 1e-6 {
                        continue; // too close to call by finite differences
                    }
                    let want = dense > margin;
                    assert_eq!(
                        is_stable(&ladder, q, margin),
                        want,
                        "α = {alpha}, N = {n}, margin {margin}: dense ω²_min = {dense:e}"
                    );
                    if want {
                        verdicts.0 += 1
                    } else {
                        verdicts.1 += 1
                    }
                }
            }
            // At rest with no force: the hanging state is proved only
            // where the dense ω²_min clears the margin.
            let rest = vec![0.0; hung.len()];
            let proof = rest_proof(&ladder, &hung, &rest, &tol);
            let dense = dense_smallest_omega_sq(&ladder, &hung);
            if (dense - tol.margin).abs() > 1e-6 {
                assert_eq!(proof.proved, dense > tol.margin, "α = {alpha}, N = {n}");
            }
        }
    }
    assert!(
        verdicts.0 > 5 && verdicts.1 > 5,
        "both verdicts tested: {verdicts:?}"
    );
    // Without gravity the ground state is an equilibrium with zero force
    // whose springs-only Hessian CᵀC has N − 1 zero modes (3(N − 1) free
    // coordinates, 2(N − 1) springs): marginal, never proved.
    let flat = Params::paper(60.0)
        .unwrap()
        .with_n(10)
        .with_b(1.3)
        .with_gamma(0.02)
        .with_gravity(0.0)
        .with_inertia(0.25)
        .validated()
        .unwrap();
    let ladder = Ladder::new(flat);
    let q = ladder.ground_state();
    let v = vec![0.0; q.len()];
    let proof = rest_proof(&ladder, &q, &v, &tol);
    assert!(
        proof.force <= tol.force && proof.kinetic == 0.0,
        "{proof:?}"
    );
    assert!(dense_smallest_omega_sq(&ladder, &q) < 1e-8);
    assert!(
        !proof.proved,
        "a marginal equilibrium was proved: {proof:?}"
    );
}
