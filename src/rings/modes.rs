//! The linearised ring chain at rest: its normal modes. The paper reads
//! the double ring chain's wave as a zero mode ("ZM initially localized
//! at the top edge migrates helically toward the bottom", Fig. 4b), a
//! motion that costs no energy, as the Jacob's ladder's edge zero mode
//! survives the stiffening by gravity's pretension. This module asks the
//! model whether its chain has one (docs/rings.md, "What the simulation
//! shows"): the potential U (gravity, the contacts' Hertz energy, the
//! tapes' springs) is brought to its minimum with the held rings fixed
//! ([`relax`]), its Hessian K = ∂²U/∂q² is taken by central differences
//! of the program's own forces ([`stiffness`]), and K v = ω² M v is
//! solved with the rings' mass and torus inertia ([`modes`]).
//!
//! Coordinates ([`coords`]): per free ring three translations (m) and
//! rotations R·θ (m) about world-frame axes, θ a small rotation vector
//! (q → exp(θ) q). A torus turned about its own normal is the same torus,
//! so that turn (a trivial zero mode of every ring no tape holds) is left
//! out: an untaped ring has five coordinates, a taped one six. Friction
//! and the contacts' damping vanish at rest and add no stiffness.

use super::body::Body;
use super::chain::G;
use super::contact::Touch;
use super::math::{self, M3, Quat, V3};
use super::system::System;
use super::warm::Relative;
use nalgebra::{DMatrix, DVector, SymmetricEigen};

/// One generalized coordinate: ring `ring` moved by `dx` (m per m) and
/// turned by the rotation vector `dth` (rad per m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coord {
    pub ring: usize,
    pub dx: V3,
    pub dth: V3,
}

/// Central-difference step of [`stiffness`], m: far below the smallest
/// static overlap of a contact (about 5·10⁻⁶ m, the bottom ring of the
/// 30-ring chain), far above rounding (10⁻¹⁷ m at these sizes).
pub const STEP: f64 = 1e-8;

/// Two unit vectors perpendicular to `n` (and to each other).
fn perpendicular(n: V3) -> (V3, V3) {
    let helper = if n[2].abs() < 0.9 {
        [0.0, 0.0, 1.0]
    } else {
        [1.0, 0.0, 0.0]
    };
    let a = math::cross(n, helper);
    let a = math::scale(a, 1.0 / math::norm(a));
    (a, math::cross(n, a))
}

/// The coordinates of the rings not in `fixed`: three translations,
/// rotations about two axes perpendicular to the ring's normal, and
/// about the normal itself only if a tape pins the ring.
pub fn coords(sys: &System, fixed: &[usize]) -> Vec<Coord> {
    let radius = sys.chain.major_radius;
    let mut out = Vec::new();
    for (k, b) in sys.bodies.iter().enumerate() {
        if fixed.contains(&k) {
            continue;
        }
        let n = Body::normal(&b.q.matrix());
        let (a, c) = perpendicular(n);
        for e in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] {
            out.push(Coord {
                ring: k,
                dx: e,
                dth: [0.0; 3],
            });
        }
        let pinned = sys.pins.iter().any(|p| p.i == k || p.j == k);
        let axes = if pinned { vec![a, c, n] } else { vec![a, c] };
        for axis in axes {
            out.push(Coord {
                ring: k,
                dx: [0.0; 3],
                dth: math::scale(axis, 1.0 / radius),
            });
        }
    }
    out
}

/// Every touch of the chain at rest, each refined to the distance's
/// local minimum by Newton's method ([`Relative::minimum`], to rounding;
/// the step's four parabolas stop 3·10⁻⁸ m short, which would be noise
/// in a difference of forces over [`STEP`]).
pub fn exact_touches(sys: &System, rots: &[M3]) -> Vec<(usize, usize, Touch)> {
    let radius = sys.chain.major_radius;
    sys.touches(rots)
        .into_iter()
        .map(|(i, j, t)| {
            let (a, b) = (sys.circle(i, &rots[i]), sys.circle(j, &rots[j]));
            let local = math::mul_mtv(&a.rot, math::sub(t.p, a.c));
            let cs = (local[0] / radius, local[1] / radius);
            let polished = Relative::of(&a, &b).minimum(cs).and_then(|cs| {
                let p = a.point(cs);
                b.nearest(p).map(|(q, d)| Touch { p, q, d })
            });
            (i, j, polished.unwrap_or(t))
        })
        .collect()
}

/// The potential energy, J: gravity of every ring, the contacts' Hertz
/// energy and the tapes' springs (the held rings' gravity is a constant).
pub fn potential(sys: &System) -> f64 {
    let rots: Vec<M3> = sys.bodies.iter().map(|b| b.q.matrix()).collect();
    let mut u: f64 = sys.bodies.iter().map(|b| sys.inertia.m * G * b.x[2]).sum();
    for (_, _, t) in exact_touches(sys, &rots) {
        u += sys.law.energy(&t);
    }
    for pin in &sys.pins {
        let s = {
            let (pa, pb) = sys.pin_points(pin, &rots);
            math::sub(pa, pb)
        };
        u += 0.5 * sys.pin_k * math::dot(s, s);
    }
    u
}

/// The force and torque (about its centre) on every ring at rest:
/// weight, the contacts' normal force (friction and damping vanish at
/// rest) and the tapes' springs: −∂U/∂x and −∂U/∂θ.
pub fn loads(sys: &System) -> (Vec<V3>, Vec<V3>) {
    let n = sys.n();
    let rots: Vec<M3> = sys.bodies.iter().map(|b| b.q.matrix()).collect();
    let mut force = vec![[0.0, 0.0, -sys.inertia.m * G]; n];
    let mut torque = vec![[0.0; 3]; n];
    let mut apply = |k: usize, at: V3, f: V3| {
        force[k] = math::add(force[k], f);
        let arm = math::sub(at, sys.bodies[k].x);
        torque[k] = math::add(torque[k], math::cross(arm, f));
    };
    for (i, j, t) in exact_touches(sys, &rots) {
        let c = math::scale(math::add(t.p, t.q), 0.5);
        let f = sys.law.force(&t, [0.0; 3]);
        apply(i, c, f);
        apply(j, c, math::scale(f, -1.0));
    }
    for pin in &sys.pins {
        let (pa, pb) = sys.pin_points(pin, &rots);
        let f = math::scale(math::sub(pa, pb), -sys.pin_k);
        apply(pin.i, pa, f);
        apply(pin.j, pb, math::scale(f, -1.0));
    }
    (force, torque)
}

/// The generalized forces −∂U/∂s, N: F·dx + τ·dθ for each coordinate.
pub fn generalized(sys: &System, coords: &[Coord]) -> DVector<f64> {
    let (force, torque) = loads(sys);
    DVector::from_iterator(
        coords.len(),
        coords
            .iter()
            .map(|c| math::dot(force[c.ring], c.dx) + math::dot(torque[c.ring], c.dth)),
    )
}

/// Moves the rings by `s` along `coords`: x += Σ s dx, q → exp(Σ s dθ) q.
pub fn displace(bodies: &mut [Body], coords: &[Coord], s: &DVector<f64>) {
    let mut dx = vec![[0.0; 3]; bodies.len()];
    let mut dth = vec![[0.0; 3]; bodies.len()];
    for (c, &v) in coords.iter().zip(s.iter()) {
        dx[c.ring] = math::axpy(dx[c.ring], v, c.dx);
        dth[c.ring] = math::axpy(dth[c.ring], v, c.dth);
    }
    for (k, b) in bodies.iter_mut().enumerate() {
        b.x = math::add(b.x, dx[k]);
        let angle = math::norm(dth[k]);
        if angle > 0.0 {
            let turn = Quat::axis_angle(math::scale(dth[k], 1.0 / angle), angle);
            b.q = turn.mul(b.q).normalized();
        }
    }
}

/// The difference step: [`STEP`], or a tenth of the lightest touch's
/// overlap where that is less (a touch that grazes, with an overlap of
/// 10⁻¹⁰ m, has Hertz's stiffness 1.5 k δ^{1/2}, which a step across
/// δ = 0 does not see), no less than 10⁻¹³ m.
pub fn step_for(sys: &System) -> f64 {
    let rots: Vec<M3> = sys.bodies.iter().map(|b| b.q.matrix()).collect();
    exact_touches(sys, &rots)
        .iter()
        .map(|(_, _, t)| 0.1 * (sys.law.reach - t.d))
        .fold(STEP, f64::min)
        .max(1e-13)
}

/// K = −∂f/∂s by central differences of [`generalized`] over [`step_for`],
/// unsymmetrised (its asymmetry measures the differences' error and
/// what is left of the rest state's unbalanced load).
pub fn stiffness(sys: &System, coords: &[Coord]) -> DMatrix<f64> {
    stiffness_at(sys, coords, step_for(sys))
}

/// [`stiffness`] with the difference step `h`, m (a check of its error:
/// the same modes with another step).
pub fn stiffness_at(sys: &System, coords: &[Coord], h: f64) -> DMatrix<f64> {
    let d = coords.len();
    let mut k = DMatrix::zeros(d, d);
    let mut moved = sys.clone();
    for col in 0..d {
        let mut f = [DVector::zeros(d), DVector::zeros(d)];
        for (side, sign) in [(0, 1.0), (1, -1.0)] {
            moved.bodies.clone_from(&sys.bodies);
            let mut s = DVector::zeros(d);
            s[col] = sign * h;
            displace(&mut moved.bodies, coords, &s);
            f[side] = generalized(&moved, coords);
        }
        let column = (&f[1] - &f[0]) / (2.0 * h);
        k.set_column(col, &column);
    }
    k
}

/// The mass matrix of the coordinates: m dx·dx' + dθ·I dθ' within a ring,
/// I = I_d (1 − n nᵀ) + I_a n nᵀ in the world frame (the torus).
pub fn mass(sys: &System, coords: &[Coord]) -> DMatrix<f64> {
    let d = coords.len();
    let inertia = sys.inertia;
    DMatrix::from_fn(d, d, |r, c| {
        let (a, b) = (coords[r], coords[c]);
        if a.ring != b.ring {
            return 0.0;
        }
        let n = Body::normal(&sys.bodies[a.ring].q.matrix());
        let along = math::dot(a.dth, n) * math::dot(b.dth, n);
        let rot = inertia.i_d * math::dot(a.dth, b.dth) + (inertia.i_a - inertia.i_d) * along;
        inertia.m * math::dot(a.dx, b.dx) + rot
    })
}

/// The modes of K v = ω² M v, lowest first: (ω² (1/s²), v with vᵀ M v =
/// 1), from the symmetric eigenproblem of L⁻¹ K_sym L⁻ᵀ, M = L Lᵀ.
pub fn modes(k: &DMatrix<f64>, m: &DMatrix<f64>) -> Vec<(f64, DVector<f64>)> {
    let l = m.clone().cholesky().expect("a mass matrix is positive").l();
    let l_inv = l.clone().try_inverse().expect("L is invertible");
    let sym = (k + k.transpose()) * 0.5;
    let a = &l_inv * sym * l_inv.transpose();
    let a = (&a + a.transpose()) * 0.5;
    let eig = SymmetricEigen::new(a);
    let back = l_inv.transpose();
    let mut out: Vec<(f64, DVector<f64>)> = (0..eig.eigenvalues.len())
        .map(|i| (eig.eigenvalues[i], &back * eig.eigenvectors.column(i)))
        .collect();
    out.sort_by(|a, b| a.0.total_cmp(&b.0));
    out
}

/// ω from ω², the sign kept (an unstable direction has ω < 0).
pub fn omega(w2: f64) -> f64 {
    w2.signum() * w2.abs().sqrt()
}

/// Steps `sys` for `time` (s) with its hand still and a damping as the
/// settle's (velocities and angular momenta scaled by exp(−`rate`·dt)
/// each step; [`super::settle::RATE`] is 20 s⁻¹), the linking guard on; then stops
/// every ring. The chain as built starts at rest but not balanced (its
/// contacts touch without overlap), so its settle's rest test would end
/// at once: a fixed time brings it near its rest state for [`relax`].
pub fn damp(sys: &mut System, time: f64, rate: f64) -> crate::error::Result<()> {
    let angle = sys.hand.turn.angle;
    sys.hand.turn.angle = 0.0;
    let keep = (-rate * sys.dt).exp();
    let every = sys.chain.guard_every as u64;
    let mut steps = 0u64;
    while sys.t < time {
        sys.step()?;
        steps += 1;
        for b in sys.bodies.iter_mut() {
            b.v = math::scale(b.v, keep);
            b.l = math::scale(b.l, keep);
        }
        if steps.is_multiple_of(every) {
            sys.check_links()?;
        }
    }
    for b in &mut sys.bodies {
        b.v = [0.0; 3];
        b.l = [0.0; 3];
    }
    sys.hand.turn.angle = angle;
    sys.t = 0.0;
    Ok(())
}

/// How [`relax`] ended: its Newton steps and the largest generalized
/// force left, as a fraction of one ring's weight.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Relaxed {
    pub steps: usize,
    pub residual: f64,
}

/// The largest generalized force, over one ring's weight.
fn residual(sys: &System, coords: &[Coord]) -> f64 {
    generalized(sys, coords).amax() / (sys.inertia.m * G)
}

/// Brings the rings not in `fixed` to a minimum of [`potential`] by
/// damped Newton steps (K + λM) Δs = f, λ ≥ 10 s⁻² (a shift far below the
/// gravity modes' ω² ≈ g/R ≈ 800 s⁻², above the differences' noise),
/// no coordinate moved more than r/2 at once, each kept if every pair
/// stays linked or apart as the topology says (the linking guard) and it
/// lowers U or, within U's rounding, the force; until no generalized
/// force exceeds `tol` times one ring's weight, or `most` steps.
pub fn relax(sys: &mut System, fixed: &[usize], tol: f64, most: usize) -> Relaxed {
    const LAMBDA_MIN: f64 = 10.0;
    let cap = 0.5 * sys.chain.tube_radius;
    let mut lambda = 1e4;
    for steps in 0..most {
        let c = coords(sys, fixed);
        let f = generalized(sys, &c);
        let res = f.amax() / (sys.inertia.m * G);
        if res < tol {
            return Relaxed {
                steps,
                residual: res,
            };
        }
        let k = stiffness(sys, &c);
        let k = (&k + k.transpose()) * 0.5;
        let m = mass(sys, &c);
        let u0 = potential(sys);
        loop {
            if lambda > 1e12 {
                return Relaxed {
                    steps,
                    residual: res,
                };
            }
            let Some(chol) = (&k + &m * lambda).cholesky() else {
                lambda *= 10.0;
                continue;
            };
            let mut step = chol.solve(&f);
            let longest = step.amax();
            if longest > cap {
                step *= cap / longest;
            }
            let mut trial = sys.clone();
            displace(&mut trial.bodies, &c, &step);
            if trial.check_links().is_err() {
                lambda *= 10.0;
                continue;
            }
            let u1 = potential(&trial);
            let lower = u1 < u0 - 1e-14 * u0.abs();
            let level = u1 <= u0 + 1e-14 * u0.abs();
            if lower || (level && generalized(&trial, &c).norm() < f.norm()) {
                sys.bodies = trial.bodies;
                lambda = (lambda * 0.1).max(LAMBDA_MIN);
                break;
            }
            lambda *= 10.0;
        }
    }
    Relaxed {
        steps: most,
        residual: residual(sys, &coords(sys, fixed)),
    }
}

/// The scale of the differences' error in ω² (s⁻²): the spectral norm
/// of L⁻¹ ½(K − Kᵀ) L⁻ᵀ, M = L Lᵀ, the antisymmetric part K must not
/// have, seen as the eigenproblem sees K. A mode with |ω²| below it is a
/// zero mode to the accuracy of the differences.
pub fn noise(k: &DMatrix<f64>, m: &DMatrix<f64>) -> f64 {
    let l = m.clone().cholesky().expect("a mass matrix is positive").l();
    let l_inv = l.try_inverse().expect("L is invertible");
    let skew = (k - k.transpose()) * 0.5;
    let a = &l_inv * skew * l_inv.transpose();
    a.svd(false, false).singular_values.max()
}

/// ‖K − Kᵀ‖/‖K‖ (Frobenius): zero for a Hessian at a rest state, up to
/// the differences' error.
pub fn asymmetry(k: &DMatrix<f64>) -> f64 {
    (k - k.transpose()).norm() / k.norm()
}

/// The contacts and tapes as constraints (the paper's compatibility
/// matrix, Calladine–Maxwell counting): one row per touch, ∂d/∂s (the
/// distance of the two centre circles), and three per tape pin,
/// ∂(p_a − p_b)/∂s. Its null space is the chain's mechanisms: motions
/// that change no contact and stretch no tape, to first order.
pub fn compatibility(sys: &System, coords: &[Coord]) -> DMatrix<f64> {
    let rots: Vec<M3> = sys.bodies.iter().map(|b| b.q.matrix()).collect();
    // (ring, point, direction): a row is Σ over its terms of
    // direction·(dx + dθ × (point − x_ring)), with sign.
    let mut rows: Vec<Vec<(usize, V3, V3)>> = Vec::new();
    for (i, j, t) in exact_touches(sys, &rots) {
        let n = math::scale(math::sub(t.p, t.q), 1.0 / t.d);
        rows.push(vec![(i, t.p, n), (j, t.q, math::scale(n, -1.0))]);
    }
    for pin in &sys.pins {
        let (pa, pb) = sys.pin_points(pin, &rots);
        for e in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] {
            rows.push(vec![(pin.i, pa, e), (pin.j, pb, math::scale(e, -1.0))]);
        }
    }
    DMatrix::from_fn(rows.len(), coords.len(), |r, col| {
        let c = coords[col];
        rows[r]
            .iter()
            .filter(|(k, _, _)| *k == c.ring)
            .map(|&(k, p, dir)| {
                let moved = math::add(c.dx, math::cross(c.dth, math::sub(p, sys.bodies[k].x)));
                math::dot(dir, moved)
            })
            .sum()
    })
}

/// The rank of `c` (singular values above 10⁻⁹ of the largest).
pub fn rank(c: &DMatrix<f64>) -> usize {
    if c.nrows() == 0 {
        return 0;
    }
    let sv = c.clone().svd(false, false).singular_values;
    let top = sv.max();
    sv.iter().filter(|&&s| s > 1e-9 * top).count()
}

/// One mode as the chain sees it.
#[derive(Clone, Debug, PartialEq)]
pub struct Shape {
    /// ω, rad/s (negative: ω² < 0).
    pub omega: f64,
    /// Each ring's share of the mode's kinetic energy (sum 1).
    pub share: Vec<f64>,
    /// The odd strand's share.
    pub odd: f64,
    /// The share in rotation about the vertical (twist).
    pub twist: f64,
    /// The number of rings it lives on: (Σ share)² / Σ share².
    pub rings: f64,
    /// Its centre along the chain: Σ k share_k.
    pub centre: f64,
    /// Each ring's rotation axis (its horizontal part's azimuth, degrees)
    /// where the ring takes part (share ≥ 5 % of the largest) and turns
    /// (rotation ≥ 20 % of its share): else none.
    pub axes: Vec<Option<f64>>,
    /// The median step of that azimuth from a ring to the next of its
    /// strand along the longest run of the stronger strand, and the run.
    pub step: Option<f64>,
    pub run: Vec<usize>,
    /// Whether that run is helical by the wave's rule (docs/rings.md,
    /// "What is observed"): three rings or more, every step within 30° of
    /// the median, the median neither within 15° of 0 nor of 180°.
    pub helical: bool,
}

/// Each ring's displacement and rotation vector in mode `v`.
fn per_ring(n: usize, coords: &[Coord], v: &DVector<f64>) -> (Vec<V3>, Vec<V3>) {
    let mut dx = vec![[0.0; 3]; n];
    let mut dth = vec![[0.0; 3]; n];
    for (c, &s) in coords.iter().zip(v.iter()) {
        dx[c.ring] = math::axpy(dx[c.ring], s, c.dx);
        dth[c.ring] = math::axpy(dth[c.ring], s, c.dth);
    }
    (dx, dth)
}

/// Mode (ω², v) of `sys` described ring by ring.
pub fn shape(sys: &System, coords: &[Coord], w2: f64, v: &DVector<f64>) -> Shape {
    let n = sys.n();
    let (dx, dth) = per_ring(n, coords, v);
    let inertia = sys.inertia;
    let mut energy = vec![0.0; n];
    let mut turning = vec![0.0; n];
    let mut twist = 0.0;
    for k in 0..n {
        let normal = Body::normal(&sys.bodies[k].q.matrix());
        let along = math::dot(dth[k], normal);
        let rot =
            inertia.i_d * math::dot(dth[k], dth[k]) + (inertia.i_a - inertia.i_d) * along * along;
        energy[k] = inertia.m * math::dot(dx[k], dx[k]) + rot;
        turning[k] = rot;
        twist += inertia.i_d * dth[k][2] * dth[k][2];
    }
    let total: f64 = energy.iter().sum();
    let share: Vec<f64> = energy.iter().map(|e| e / total).collect();
    let top = share.iter().cloned().fold(0.0, f64::max);
    let axes = (0..n)
        .map(|k| {
            let part = share[k] >= 0.05 * top && turning[k] >= 0.2 * energy[k];
            part.then(|| dth[k][1].atan2(dth[k][0]).to_degrees())
        })
        .collect::<Vec<_>>();
    let odd = share.iter().skip(1).step_by(2).sum();
    let strand = usize::from(odd > 0.5);
    let (run, step, helical) = helix(&axes, strand);
    Shape {
        omega: omega(w2),
        rings: 1.0 / share.iter().map(|s| s * s).sum::<f64>(),
        centre: share.iter().enumerate().map(|(k, s)| k as f64 * s).sum(),
        twist: twist / total,
        odd,
        share,
        axes,
        step,
        run,
        helical,
    }
}

/// The longest run of consecutive rings of `strand` with an axis, its
/// median step of azimuth and whether it is helical (see [`Shape`]).
fn helix(axes: &[Option<f64>], strand: usize) -> (Vec<usize>, Option<f64>, bool) {
    let mut best: Vec<usize> = Vec::new();
    let mut run: Vec<usize> = Vec::new();
    for k in (strand..axes.len()).step_by(2) {
        if axes[k].is_some() {
            run.push(k);
        } else {
            run.clear();
        }
        if run.len() > best.len() {
            best.clone_from(&run);
        }
    }
    if best.len() < 2 {
        return (best, None, false);
    }
    let mut steps: Vec<f64> = best
        .windows(2)
        .map(|w| super::observe::angle_step(axes[w[0]].unwrap(), axes[w[1]].unwrap()))
        .collect();
    steps.sort_by(f64::total_cmp);
    let median = steps[steps.len() / 2];
    let even = steps
        .iter()
        .all(|s| super::observe::angle_step(median, *s).abs() <= 30.0);
    let turns = median.abs() > 15.0 && median.abs() < 165.0;
    (best.clone(), Some(median), best.len() >= 3 && even && turns)
}
