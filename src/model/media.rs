//! Terms beyond the paper's model (docs/experiments.md): added mass and added
//! inertia of a flat plate, quadratic drag by strip theory, and the links'
//! own terms (`links`: stiffness, tension-only tape, pin friction).
//! Buoyancy needs no term of its own: it scales the gravity G of the
//! parameters ((1 − ρ_m/ρ) m g, `scene::apparatus`).
//!
//! Every term is off by default ([`Terms::default`] is the paper's model),
//! and the paper's force loop (`Ladder::gradient_with`, the fused kernels)
//! never sees them: a scenario with any term goes through the portable
//! path of `sim::rhs`.
//!
//! Units are the model's (s = m = k = 1, τ = √(m/k)).
//!
//! # Added mass (Lagrange's equations)
//!
//! With t = (sin θ, p cos θ) (p = (−1)ⁿ) and ν = ∂t/∂θ = (cos θ, −p sin θ),
//! the plate's in-plane normal (|ν| = 1, ν ⊥ t, ∂ν/∂θ = −t), a block's
//! kinetic energy is
//!
//! T = ½ m |V|² + ½ m_a (V·ν)² + ½ (I + I_a) θ̇².
//!
//! ∂T/∂V = M V with M = m 1 + m_a ν νᵀ, and since ν̇ = −θ̇ t,
//!
//! d/dt (M V) = M V̇ − m_a θ̇ [(V·t) ν + (V·ν) t];
//!
//! ∂T/∂X = 0, ∂T/∂θ = −m_a (V·ν)(V·t). Lagrange's equations with the
//! generalised forces Q (elastic, gravity, damping, drag, friction) give
//!
//! M V̇ = Q_V + m_a θ̇ [(V·t) ν + (V·ν) t],
//! (I + I_a) θ̈ = Q_θ − m_a (V·ν)(V·t)   (the Munk moment),
//!
//! and M⁻¹ = (1/m) [1 − m_a/(m + m_a) ν νᵀ] (Sherman–Morrison: closed
//! form). The velocity terms do no work: d/dt T = Q_V·V + Q_θ θ̇ exactly
//! (the θ̇ terms of M V̇ give 2 m_a θ̇ (V·t)(V·ν), ½ Vᵀ Ṁ V gives
//! −m_a θ̇ (V·t)(V·ν), the Munk moment −m_a θ̇ (V·ν)(V·t)).
//!
//! # Quadratic drag (strip theory)
//!
//! The point at ℓ ∈ [−r, r] along t moves normal to the plate at
//! u(ℓ) = V·ν + ℓ θ̇; the force per unit length is −c u|u| ν with
//! c = ½ ρ_m C_D h, so Q_V = −c ν ∫ u|u| dℓ and Q_θ = −c ∫ ℓ u|u| dℓ
//! ([`drag_integrals`], closed form). The drag dissipates
//! c ∫ u²|u| dℓ ≥ 0.

pub use super::ladder::frame;
use super::ladder::{Ladder, itheta, ix, iy};
use super::params::{M, R};
pub use super::terms::Terms;

/// Strip-theory integrals over ℓ ∈ [−r, r] of u|u| and ℓ u|u|, with
/// u = u0 + w ℓ, in closed form.
///
/// Where u keeps its sign (|w| r ≤ |u0|), u|u| = sgn(u0) u² and the
/// integrals are the polynomials sgn(u0) (2 r u0² + ⅔ r³ w²) and
/// sgn(u0) ⁴⁄₃ r³ u0 w. Where it changes sign, |w| r > |u0| ≥ 0 and the
/// substitution u = u0 + w ℓ gives (G(u₊) − G(u₋))/w and
/// (H(u₊) − H(u₋) − u0 (G(u₊) − G(u₋)))/w², with G(u) = u²|u|/3,
/// H(u) = u³|u|/4 and u± = u0 ± w r (no division by a small w).
pub fn drag_integrals(u0: f64, w: f64, r: f64) -> (f64, f64) {
    if (w * r).abs() <= u0.abs() {
        let sign = u0.signum();
        let force = sign * (2.0 * r * u0 * u0 + (2.0 / 3.0) * r * r * r * w * w);
        let torque = sign * (4.0 / 3.0) * r * r * r * u0 * w;
        (force, torque)
    } else {
        let g = |u: f64| u * u * u.abs() / 3.0;
        let h = |u: f64| u * u * u * u.abs() / 4.0;
        let (up, um) = (u0 + w * r, u0 - w * r);
        let dg = g(up) - g(um);
        (dg / w, (h(up) - h(um) - u0 * dg) / (w * w))
    }
}

/// ∫_{−r}^{r} u²|u| dℓ with u = u0 + w ℓ: the drag's dissipation per unit c.
pub fn drag_dissipation_integral(u0: f64, w: f64, r: f64) -> f64 {
    // u0 ∫u|u| + w ∫ℓ u|u| = ∫ u · u|u|.
    let (f, t) = drag_integrals(u0, w, r);
    u0 * f + w * t
}

/// Generalised drag force (Q_X, Q_Y, Q_θ) on block `i` with coefficient
/// `c` at angle `theta` moving with (Ẋ, Ẏ, θ̇) = `v`.
#[inline]
pub fn drag_force(c: f64, i: usize, theta: f64, v: [f64; 3]) -> [f64; 3] {
    drag_force_framed(c, frame(i, theta).1, v)
}

/// [`drag_force`] with the block's normal ν given.
#[inline(always)]
pub fn drag_force_framed(c: f64, nu: [f64; 2], v: [f64; 3]) -> [f64; 3] {
    let u0 = v[0] * nu[0] + v[1] * nu[1];
    let (f, t) = drag_integrals(u0, v[2], R);
    [-c * f * nu[0], -c * f * nu[1], -c * t]
}

/// Accelerations (Ẍ, Ÿ, θ̈) of block `i` under the generalised forces
/// `q` (everything but the velocity terms of the kinetic energy), with
/// added mass `ma` and total moment of inertia `j` = I + I_a: Lagrange's
/// equations of the module's doc, M⁻¹ in closed form.
#[inline]
pub fn block_acceleration(
    ma: f64,
    j: f64,
    i: usize,
    theta: f64,
    v: [f64; 3],
    q: [f64; 3],
) -> [f64; 3] {
    block_acceleration_framed(ma, j, frame(i, theta), v, q)
}

/// [`block_acceleration`] with the block's frame (t, ν) given.
#[inline(always)]
pub fn block_acceleration_framed(
    ma: f64,
    j: f64,
    (t, nu): ([f64; 2], [f64; 2]),
    v: [f64; 3],
    q: [f64; 3],
) -> [f64; 3] {
    let vn = v[0] * nu[0] + v[1] * nu[1];
    let vt = v[0] * t[0] + v[1] * t[1];
    let w = v[2];
    // Right-hand side of M V̇ = Q + m_a θ̇ [(V·t) ν + (V·ν) t].
    let fx = q[0] + ma * w * (vt * nu[0] + vn * t[0]);
    let fy = q[1] + ma * w * (vt * nu[1] + vn * t[1]);
    let fn_ = fx * nu[0] + fy * nu[1];
    let k = ma / (M + ma);
    [
        (fx - k * fn_ * nu[0]) / M,
        (fy - k * fn_ * nu[1]) / M,
        (q[2] - ma * vn * vt) / j,
    ]
}

/// Kinetic energy of the free blocks (every block but the first when
/// `skip_first`) with added mass and added inertia:
/// Σ ½ m |V|² + ½ m_a (V·ν)² + ½ (I + I_a) θ̇².
pub fn kinetic_energy(
    ladder: &Ladder,
    terms: &Terms,
    q: &[f64],
    v: &[f64],
    skip_first: bool,
) -> f64 {
    let j = ladder.params.inertia + terms.added_inertia;
    (usize::from(skip_first)..ladder.n())
        .map(|i| {
            let (_, nu) = frame(i, q[itheta(i)]);
            let (vx, vy, w) = (v[ix(i)], v[iy(i)], v[itheta(i)]);
            let vn = vx * nu[0] + vy * nu[1];
            0.5 * M * (vx * vx + vy * vy) + 0.5 * terms.added_mass * vn * vn + 0.5 * j * w * w
        })
        .sum()
}

/// Potential energy with the links' terms: the links' elastic energy
/// (`links`) minus m G Σ X_n.
pub fn potential_energy(ladder: &Ladder, terms: &Terms, q: &[f64]) -> f64 {
    terms.links.elastic_energy(ladder, q) + gravity_energy(ladder, q)
}

/// Gravity's part of the potential energy, −m G Σ X_n (G with buoyancy).
pub fn gravity_energy(ladder: &Ladder, q: &[f64]) -> f64 {
    let x: f64 = (0..ladder.n()).map(|i| q[ix(i)]).sum();
    -M * ladder.params.gravity * x
}

/// Power dissipated (≥ 0) by each dissipative term at (q, v), blocks
/// `from..N`: (linear damping, quadratic drag, pin friction). Pin
/// friction counts every pin (`links::PinFriction::dissipation`).
pub fn dissipation(
    ladder: &Ladder,
    terms: &Terms,
    q: &[f64],
    v: &[f64],
    from: usize,
) -> (f64, f64, f64) {
    let gamma = ladder.params.gamma;
    let (mut linear, mut drag) = (0.0, 0.0);
    for i in from..ladder.n() {
        let (vx, vy, w) = (v[ix(i)], v[iy(i)], v[itheta(i)]);
        linear += gamma * (vx * vx + vy * vy) + gamma * R * R * w * w;
        if terms.drag != 0.0 {
            let (_, nu) = frame(i, q[itheta(i)]);
            let u0 = vx * nu[0] + vy * nu[1];
            drag += terms.drag * drag_dissipation_integral(u0, w, R);
        }
    }
    let friction = terms
        .friction
        .map_or(0.0, |f| f.dissipation(ladder, &terms.links, q, v));
    (linear, drag, friction)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Simpson's rule with many panels: the reference for the closed forms.
    fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
        let n = 20_000;
        let h = (b - a) / n as f64;
        let mut s = f(a) + f(b);
        for k in 1..n {
            s += f(a + k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 };
        }
        s * h / 3.0
    }

    #[test]
    fn drag_integrals_match_quadrature() {
        let r = 0.5;
        for (u0, w) in [
            (0.3, 0.1),
            (-0.3, 0.1),
            (0.01, 1.0),
            (-0.02, -0.7),
            (0.0, 0.4),
            (0.2, 0.0),
            (0.1, 0.2),
            (0.1, -0.2),
            (1e-9, 1e-3),
        ] {
            let (f, t) = drag_integrals(u0, w, r);
            let u = |l: f64| u0 + w * l;
            let fq = simpson(|l| u(l) * u(l).abs(), -r, r);
            let tq = simpson(|l| l * u(l) * u(l).abs(), -r, r);
            let scale = u0.abs().max(w.abs() * r).powi(2) * r;
            assert!(
                (f - fq).abs() <= 1e-9 * scale.max(1e-30),
                "{u0} {w}: {f} {fq}"
            );
            assert!(
                (t - tq).abs() <= 1e-9 * scale.max(1e-30),
                "{u0} {w}: {t} {tq}"
            );
            let d = drag_dissipation_integral(u0, w, r);
            let dq = simpson(|l| u(l) * u(l) * u(l).abs(), -r, r);
            assert!(d >= 0.0);
            assert!((d - dq).abs() <= 1e-9 * scale * u0.abs().max(w.abs() * r) + 1e-30);
        }
    }

    #[test]
    fn mass_matrix_inverse_is_exact() {
        // M a = F' for the returned a (no gyroscopic terms at θ̇ = 0).
        let (ma, j) = (6.3, 0.4);
        for (i, th) in [(0, 0.3), (1, 1.2), (2, -2.0)] {
            let q = [0.7, -0.2, 0.1];
            let a = block_acceleration(ma, j, i, th, [0.0; 3], q);
            let (_, nu) = frame(i, th);
            let an = a[0] * nu[0] + a[1] * nu[1];
            let back = [M * a[0] + ma * an * nu[0], M * a[1] + ma * an * nu[1]];
            assert!((back[0] - q[0]).abs() < 1e-14 && (back[1] - q[1]).abs() < 1e-14);
            assert!((a[2] * j - q[2]).abs() < 1e-15);
        }
    }

    #[test]
    fn velocity_terms_do_no_work() {
        // d/dt T = Q·v with Q = 0: the gyroscopic terms and the Munk
        // moment are workless. dT/dt from the accelerations, by the
        // chain rule: V·M V̇ + ½ Vᵀ Ṁ V + J θ̇ θ̈.
        let (ma, j) = (2.5, 0.3);
        for (i, th, v) in [(0, 0.4, [0.3, -0.1, 0.7]), (1, -1.1, [-0.2, 0.5, -0.4])] {
            let a = block_acceleration(ma, j, i, th, v, [0.0; 3]);
            let (t, nu) = frame(i, th);
            let vn = v[0] * nu[0] + v[1] * nu[1];
            let vt = v[0] * t[0] + v[1] * t[1];
            let an = a[0] * nu[0] + a[1] * nu[1];
            // d/dt (V·ν) = V̇·ν + V·ν̇ = an − θ̇ vt.
            let dt = M * (v[0] * a[0] + v[1] * a[1]) + ma * vn * (an - v[2] * vt) + j * v[2] * a[2];
            assert!(dt.abs() < 1e-14, "{dt}");
        }
    }
}
