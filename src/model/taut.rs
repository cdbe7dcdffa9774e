//! Inextensible ribbons (docs/experiments.md, "Inextensible ribbons"): a
//! taut ribbon as a length constraint L(q) = ℓ instead of a stiff spring.
//!
//! A ribbon's span leaves the upper block at D and reaches the lower one
//! at E, both points fixed in their blocks (corners or anchors,
//! `ribbons`), with the wrapped lengths constant while they are, so
//!
//! L̇ = e · (v_E − v_D) = G q̇,
//!
//! e the span's unit vector. G's entries on a block are the generalised
//! force of a unit force −e at D (upper) or +e at E (lower): an impulse
//! P ≥ 0 acts on the blocks as −P Gᵀ, the stiff ribbon's force with its
//! tension (`Ribbons::gradient`) over an instant.

use super::outline::{Pose, add_point_force, point_velocity};
use super::ribbons::{Ribbons, Span};

impl Ribbons {
    /// The same ribbons inextensible: lengths held by the run (`sim::taut`),
    /// no spring and no dashpot.
    pub fn inextensible(self) -> Self {
        Self {
            stiffness: 0.0,
            damping: 0.0,
            inextensible: true,
            ..self
        }
    }
}

/// One ribbon's constraint at a state: its gradient on the upper and the
/// lower block ((X, Y, θ) each), L̇ and L − ℓ.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Row {
    pub upper: [f64; 3],
    pub lower: [f64; 3],
    pub rate: f64,
    pub gap: f64,
}

/// The row of the ribbon `span` (rest length `rest`) between block `i`
/// (pose `pu`) and block i + 1 (pose `pl`) at velocities `v`.
pub fn row(span: &Span, rest: f64, (pu, pl): (&Pose, &Pose), i: usize, v: &[f64]) -> Row {
    let e = span.dir;
    let mut g = [0.0; 6];
    add_point_force(&mut g, pu, 0, span.d, [-e[0], -e[1]]);
    add_point_force(&mut g, pl, 1, span.e, e);
    let vd = point_velocity(pu, i, span.d, v);
    let ve = point_velocity(pl, i + 1, span.e, v);
    let rate = e[0] * (ve[0] - vd[0]) + e[1] * (ve[1] - vd[1]);
    Row {
        upper: [g[0], g[1], g[2]],
        lower: [g[3], g[4], g[5]],
        rate,
        gap: span.length - rest,
    }
}

/// Solves A x = b in place for a symmetric positive definite `a` (n × n,
/// row major) whose entries vanish more than `band` off the diagonal
/// (Cholesky, the band's loops only). Returns false where A is not
/// positive definite (a pivot ≤ 0 or not finite).
pub fn solve_banded(a: &mut [f64], b: &mut [f64], n: usize, band: usize) -> bool {
    if !factor_banded(a, n, band) {
        return false;
    }
    solve_factored(a, b, n, band);
    true
}

/// Cholesky A = L Lᵀ in place of `a`'s lower band (`solve_banded`),
/// each diagonal entry holding 1/L_jj (the solves multiply by it); false
/// where A is not positive definite.
pub fn factor_banded(a: &mut [f64], n: usize, band: usize) -> bool {
    for j in 0..n {
        let lo = j.saturating_sub(band);
        let mut d = a[j * n + j];
        for k in lo..j {
            d -= a[j * n + k] * a[j * n + k];
        }
        if !(d > 0.0 && d.is_finite()) {
            return false;
        }
        let inv = 1.0 / d.sqrt();
        a[j * n + j] = inv;
        for i in j + 1..(j + band + 1).min(n) {
            let mut s = a[i * n + j];
            for k in i.saturating_sub(band).max(lo)..j {
                s -= a[i * n + k] * a[j * n + k];
            }
            a[i * n + j] = s * inv;
        }
    }
    true
}

/// Solves L Lᵀ x = b in place with the factor `factor_banded` left.
pub fn solve_factored(a: &[f64], b: &mut [f64], n: usize, band: usize) {
    for i in 0..n {
        let mut s = b[i];
        for k in i.saturating_sub(band)..i {
            s -= a[i * n + k] * b[k];
        }
        b[i] = s * a[i * n + i];
    }
    for i in (0..n).rev() {
        let mut s = b[i];
        for k in i + 1..(i + band + 1).min(n) {
            s -= a[k * n + i] * b[k];
        }
        b[i] = s * a[i * n + i];
    }
}

#[cfg(test)]
mod tests;
