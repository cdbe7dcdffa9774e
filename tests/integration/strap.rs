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
/// The ribbons' glue points, this fraction of s inside the faces from
/// the ends (`ribbon_anchors = [0.05, 0.95]`). Glued exactly at the
/// corners (the toy's [0, 1]), each ribbon's two ways round its anchor
/// are equally long (s + d) all along the strap hinge's motion at b = s:
/// the maximal model's ribbon, which takes the shorter way, may then
/// leave the pivot by switching way, and the blocks swing about no pivot
/// (`the_generalised_accelerations_agree_at_the_start`). Glued on the
/// face the ribbon lies along it to the end, the other way is 2 × 0.05 s
/// longer, and the strap hinge's geometry is unchanged (it holds for any
/// anchor on the faces).
const INSET: f64 = 0.05;

/// The toy's blocks, `n` of them end to end (b = s), ribbons of
/// stiffness `kappa` (in k) glued `inset` inside the faces and no
/// contact: while both ribbons of every junction are taut they alone
/// hold the pivot.
fn toy_glued(n: usize, kappa: f64, inset: f64) -> (Scenario, StrapChain) {
    let anchors = format!("ribbon_anchors = [{inset}, {}]", 1.0 - inset);
    let text = TOY
        .replace("n = 6", &format!("n = {n}"))
        .replace("b = 5.75", "b = 5.7")
        .replace("contact = \"wood\"\n", "")
        .replace("ribbon_anchors = [0.0, 1.0]", &anchors);
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

fn toy(n: usize, kappa: f64) -> (Scenario, StrapChain) {
    toy_glued(n, kappa, INSET)
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
    let stretch = glued_stretch(n, &start.q);
    assert!(
        stretch < 1e-12,
        "the maximal start is not glued taut: |L − ℓ| = {stretch:.3e}"
    );
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

/// The largest |L − ℓ| of any ribbon of the maximal model at `q`.
fn glued_stretch(n: usize, q: &[f64]) -> f64 {
    let (sc, _) = toy(n, 1.0);
    let r = sc.ladder.built.unwrap().ribbons;
    r.spans(n, q)
        .iter()
        .map(|(_, s)| (s.length - r.ribbons[0].rest).abs())
        .fold(0.0, f64::max)
}

/// Block 2's θ̈ at the start from a strap-hinge state at rest: the strap
/// hinge's (its equations solved), and the maximal model's at stiffness
/// κ = 400 k glued `inset` inside the faces, 2 (θ(t) − θ(0))/t² over
/// t = 2 τ (the ribbons take up the load within 2/√κ = 0.1 τ).
fn start_accelerations(theta: &[f64], inset: f64) -> (f64, f64) {
    use jacobs_ladder::model::strap::solve_spd;
    let n = theta.len();
    let (mut sc, chain) = toy_glued(n, 400.0, inset);
    let zero = vec![0.0; n];
    let k = chain.kinematics(theta, &zero, &strap_regions(theta));
    let (m, f) = chain.equations(&k);
    let free: Vec<Vec<f64>> = (1..n).map(|j| m[j][1..].to_vec()).collect();
    let strap = solve_spd(&free, &f[1..])[0];
    let t = 2.0;
    sc.protocol = Protocol::Driven(Drive::hold(theta[0]));
    sc.initial = State {
        q: k.q.clone(),
        v: vec![0.0; 3 * n],
    };
    sc.t_end = t;
    let cfg = IntegratorConfig::fixed(IntegratorKind::Rk4, 0.002);
    let traj = sim::simulate(&sc, &[t], &cfg).unwrap();
    let maximal = 2.0 * (traj.states[0][itheta(1)] - theta[1]) / (t * t);
    (strap, maximal)
}

#[test]
fn the_generalised_accelerations_agree_at_the_start() {
    // Block 2 folded to φ = −1.2 below a held block 1, at rest: the
    // sharp comparison before any trajectory. Glued on the faces the two
    // agree to the ribbons' stretch (θ̈ −2.6421e-4 against −2.6407e-4 at
    // 400 k); glued at the corners the maximal ribbons switch way and
    // block 2 leaves the pivot (+4.6e-5 at 100 k and 400 k alike: the
    // wrong sign, whatever κ).
    let theta = folded(FRAC_PI_2, &[-1.2]);
    let (strap, maximal) = start_accelerations(&theta, INSET);
    println!("glued on the faces: strap {strap:.5e}, maximal {maximal:.5e}");
    assert!(
        (maximal - strap).abs() < 2e-3 * strap.abs(),
        "{strap} {maximal}"
    );
    let (strap, maximal) = start_accelerations(&theta, 0.0);
    println!("glued at the corners: strap {strap:.5e}, maximal {maximal:.5e}");
    assert!(
        (maximal - strap).abs() > 0.5 * strap.abs(),
        "{strap} {maximal}"
    );
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
fn a_two_block_hinge_swings_about_its_pivot_as_the_stiff_ribbons_do() {
    // Block 1 held upright, block 2 folded 2 rad up towards block 1's
    // face w = −h and let go: it swings down about block 1's corner c₁.
    let theta = folded(FRAC_PI_2, &[-1.2]);
    // The difference is the ribbons' stretch and dashpot, falling with κ
    // (4.3e-3, 2.5e-3, 1.4e-3 at κ, 2κ, 4κ over the 87 τ window): the
    // tolerance at 4κ is that stretch with a 40 % margin. Glued at the
    // corners (INSET = 0) it is 0.307 at every κ.
    let a = agreement(&theta, Drive::hold(FRAC_PI_2), 400.0);
    check(&a, 2e-3);
}

#[test]
fn a_six_block_toy_folds_as_the_stiff_ribbons_fold_it() {
    // The toy's six blocks folded in a zig-zag (folds −1.0 … −0.4,
    // alternately either way in the lab), block 1 turned by the hand's
    // 232 τ turn: every junction rolls on its pivot. (The zig-zag of
    // equal folds −0.9 is not taut in the strap run: least tension
    // −1.7e-5.)
    let theta = folded(FRAC_PI_2, &[-1.0, -0.8, -0.6, -0.5, -0.4]);
    let drive = Drive::new(vec![(0.0, FRAC_PI_2), (232.0, -FRAC_PI_2)]).unwrap();
    // The difference falls with κ (1.79e-2, 1.04e-2, 6.5e-3 at κ, 2κ,
    // 4κ over the 31 τ window, as the two blocks' above): the tolerance
    // at 4κ is that with a 38 % margin. Before a cycling span search was
    // given its length (`model::tangent`) two junctions' ribbons jumped
    // 0.085 s round a block's end at 0.13 τ, and the motions parted by
    // 0.77, 1.38, 3.05 s.
    let a = agreement(&theta, drive, 400.0);
    check(&a, 9e-3);
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

/// The gradient of one ribbon's length over both blocks' (x, y, θ) as
/// the span gives it (its direction at its two ends, the envelope
/// theorem) and by central differences of the length, `k` the ribbon.
fn span_gradient(r: &Ribbons, q: &[f64], k: usize) -> ([f64; 6], [f64; 6]) {
    use jacobs_ladder::model::outline::{Pose, add_point_force};
    let length = |q: &[f64]| r.spans(2, q)[k].1.length;
    let s = r.spans(2, q)[k].1;
    let (pu, pl) = (Pose::of(q, 0), Pose::of(q, 1));
    let mut g = [0.0; 6];
    add_point_force(&mut g, &pu, 0, s.d, [-s.dir[0], -s.dir[1]]);
    add_point_force(&mut g, &pl, 1, s.e, s.dir);
    let h = 1e-9;
    let mut fd = [0.0; 6];
    for (c, x) in fd.iter_mut().enumerate() {
        let (mut qp, mut qm) = (q.to_vec(), q.to_vec());
        qp[c] += h;
        qm[c] -= h;
        *x = (length(&qp) - length(&qm)) / (2.0 * h);
    }
    (g, fd)
}

#[test]
fn the_span_through_coinciding_pivot_corners_is_the_strap_path() {
    // Two blocks end to end (b = s) rolling on their pivot through every
    // fold φ ∈ (−2π, 2π), block 1 at three angles, the ribbons glued at
    // the corners (the toy's) and inside the faces: the pivot corners
    // coincide, the free span has zero length, and the span search's
    // test e · a ≥ 0 there is a tie of the poses' rounding. Each ribbon
    // must take the strap path, L = ℓ = s + d to 10⁻¹² (a tie lost sends
    // it round the next corner: without it, L − ℓ = 5.2e-3 at φ = −6.24,
    // glued at the corners, θ₁ = 0.4), and pulled
    // 10⁻⁶ s off the pivot along the centres' line its length grows by
    // at most that and its span's direction is the length's gradient.
    let eps = 1e-6;
    let (mut spans, mut worst, mut worst_grad) = (0, 0.0f64, 0.0f64);
    for inset in [0.0, INSET] {
        let (sc, chain) = toy_glued(2, 1.0, inset);
        let r = sc.ladder.built.unwrap().ribbons;
        for theta1 in [0.4, FRAC_PI_2, 2.9] {
            for k in 0..1200 {
                let phi = -2.0 * PI + (k as f64 + 0.5) * 4.0 * PI / 1200.0;
                let theta = folded(theta1, &[phi]);
                let regions = strap_regions(&theta);
                let q = chain.kinematics(&theta, &[0.0; 2], &regions).q;
                let mut pulled = q.clone();
                let c = [q[3] - q[0], q[4] - q[1]];
                let l = (c[0] * c[0] + c[1] * c[1]).sqrt();
                pulled[3] += eps * c[0] / l;
                pulled[4] += eps * c[1] / l;
                for (j, (_, s)) in r.spans(2, &q).iter().enumerate() {
                    let rest = r.ribbons[j].rest;
                    let off = s.length - rest;
                    assert!(
                        off.abs() < 1e-12,
                        "inset {inset}, θ₁ {theta1}, φ {phi:.4}, ribbon {}: L − ℓ = {off:.3e}",
                        j + 1
                    );
                    worst = worst.max(off.abs());
                    let stretch = r.spans(2, &pulled)[j].1.length - rest;
                    assert!(
                        (-1e-12..=eps + 1e-12).contains(&stretch),
                        "φ {phi:.4}, ribbon {}: pulled {eps} off, L − ℓ = {stretch:.3e}",
                        j + 1
                    );
                    if k % 8 == 0 {
                        let (g, fd) = span_gradient(&r, &pulled, j);
                        for (a, b) in g.iter().zip(&fd) {
                            worst_grad = worst_grad.max((a - b).abs());
                        }
                    }
                    spans += 1;
                }
            }
        }
    }
    println!("{spans} spans: largest |L − ℓ| {worst:.2e}, gradient off by {worst_grad:.2e}");
    assert!(worst_grad < 1e-5, "{worst_grad}");
}

#[test]
fn a_ribbon_length_is_continuous_as_the_pivot_corners_cross() {
    // Block 2 at the strap hinge's pivot under block 1, then carried
    // slowly along a straight line through it (from 10⁻³ s pressed into
    // block 1 to 10⁻³ s out, in steps of 10⁻⁶ s, eight directions, folds
    // through both quarters a toy's junction rolls in): each ribbon's
    // length moves by no more than the block does. It jumped by
    // 0.085 s (7.7 %) where the corners pressed 10⁻⁴ s into each other,
    // and the six blocks' motions parted from the strap hinge's
    // (docs/experiments.md, "The strap hinge").
    let (sc, chain) = toy(2, 1.0);
    let r = sc.ladder.built.unwrap().ribbons;
    let (mut worst, mut lines) = (0.0f64, 0);
    for k in 0..24 {
        let phi = -3.0 + k as f64 * 0.25;
        let theta = folded(FRAC_PI_2, &[phi]);
        let q0 = chain
            .kinematics(&theta, &[0.0; 2], &strap_regions(&theta))
            .q;
        for a in 0..8 {
            let angle = (a as f64 + 0.3) * PI / 4.0;
            let at = |x: f64| {
                let mut q = q0.clone();
                q[3] += x * angle.cos();
                q[4] += x * angle.sin();
                r.spans(2, &q)
                    .iter()
                    .map(|(_, s)| s.length)
                    .collect::<Vec<_>>()
            };
            let step = 1e-6;
            let mut prev = at(-1e-3);
            for m in 1..=2000 {
                let now = at(-1e-3 + m as f64 * step);
                for (j, (x, y)) in prev.iter().zip(&now).enumerate() {
                    let moved = (y - x).abs() / step;
                    assert!(
                        moved <= 1.0 + 1e-6,
                        "φ {phi}, direction {angle:.3}, step {m}, ribbon {}: L {x} → {y}",
                        j + 1
                    );
                    worst = worst.max(moved);
                }
                prev = now;
            }
            lines += 1;
        }
    }
    println!("{lines} lines: largest |ΔL| / |Δx| {worst:.6}");
}
