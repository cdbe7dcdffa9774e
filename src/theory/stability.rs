//! Rest and linear stability of a state of the clamped chain (docs/sweeps.md):
//! the proof that a wave has stopped.
//!
//! Block 1's centre and angle are held (clamped), so the free coordinates
//! are those of blocks 2..N, 3(N − 1) of them. The Hessian of the energy E
//! (docs/model.md, springs and gravity) at any state, not only the ground
//! state, is a band matrix of half-bandwidth 5, like the ground-state one
//! behind ω_max (`dispersion::clamped_band_hessian`): a spring couples two
//! neighbouring blocks. It is built here from the analytic gradient by
//! central differences, perturbing every third block at once (their
//! gradients do not overlap): 18 gradient evaluations whatever N, O(N).
//! Its smallest mass-weighted eigenvalue (ω² of the slowest mode) is
//! bounded from below by band Cholesky tests, O(N) each.

use super::linalg::BandSymmetric;
use crate::model::Ladder;
use crate::model::params::M;

/// Half-bandwidth of the clamped Hessian in the free coordinates.
const WIDTH: usize = 5;
/// Central-difference step for the Hessian, in s and radians.
const FD_STEP: f64 = 1e-5;

/// Tolerances of the rest proof. Defaults are stated with each field.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RestTolerances {
    /// Largest kinetic energy of the whole chain at rest, k s²
    /// (default 1e-12: a block moving at 1.4e-6 s/τ).
    pub kinetic: f64,
    /// Largest residual generalised force |∂E/∂q| on a free coordinate,
    /// k s (forces) and k s² (torques) (default 1e-8, a twentieth of a
    /// block's weight G = 2e-4 divided by a thousand).
    pub force: f64,
    /// Least smallest mass-weighted eigenvalue ω²_min of the clamped
    /// Hessian, 1/τ² (default 1e-7: the slowest mode's period under
    /// 20 000 τ). At rest, N = 10 chains have ω²_min ≈ 2e-5 (the pinned
    /// antikink at α = −50°: 2.2e-5), the kink held at block 2 of
    /// N = 186–300 blocks 1.2e-6 to 7e-7.
    pub margin: f64,
}

impl Default for RestTolerances {
    fn default() -> Self {
        Self {
            kinetic: 1e-12,
            force: 1e-8,
            margin: 1e-7,
        }
    }
}

/// What the rest test found at one state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RestProof {
    /// Kinetic energy of the chain, k s².
    pub kinetic: f64,
    /// Largest residual force on a free coordinate.
    pub force: f64,
    /// Whether the clamped Hessian minus `margin` times the mass is
    /// positive definite (only tested when the first two hold).
    pub stable: Option<bool>,
    /// Whether all three hold: the state is proved at rest at a linearly
    /// stable equilibrium.
    pub proved: bool,
}

/// Largest |∂E/∂q| over the free coordinates (blocks 2..N).
pub fn residual_force(ladder: &Ladder, q: &[f64]) -> f64 {
    let mut g = vec![0.0; q.len()];
    ladder.gradient(q, &mut g);
    g[3..].iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// Masses of the free coordinates in order (m, m, I per block 2..N).
pub fn free_masses(ladder: &Ladder) -> Vec<f64> {
    let inertia = ladder.params.inertia;
    (1..ladder.n()).flat_map(|_| [M, M, inertia]).collect()
}

/// The Hessian of E at `q` in the free coordinates (blocks 2..N), by
/// central differences of the analytic gradient (see the module's doc).
pub fn clamped_hessian(ladder: &Ladder, q: &[f64]) -> BandSymmetric {
    let n = ladder.n();
    let free = 3 * (n - 1);
    let mut h = BandSymmetric::zeros(free, WIDTH);
    let mut qp = q.to_vec();
    let (mut gp, mut gm) = (vec![0.0; q.len()], vec![0.0; q.len()]);
    for colour in 0..3 {
        for c in 0..3 {
            let moved: Vec<usize> = (1..n).filter(|i| i % 3 == colour).collect();
            for &i in &moved {
                qp[3 * i + c] = q[3 * i + c] + FD_STEP;
            }
            ladder.gradient(&qp, &mut gp);
            for &i in &moved {
                qp[3 * i + c] = q[3 * i + c] - FD_STEP;
            }
            ladder.gradient(&qp, &mut gm);
            for &i in &moved {
                qp[3 * i + c] = q[3 * i + c];
            }
            // Block k's gradient moved only with the perturbed block within
            // one of it (the others are at least three apart). Each
            // off-diagonal pair is seen from both of its coordinates: half
            // of each estimate (which symmetrises the matrix).
            for &i in &moved {
                let col = 3 * (i - 1) + c;
                for k in i.saturating_sub(1).max(1)..=(i + 1).min(n - 1) {
                    for d in 0..3 {
                        let row = 3 * (k - 1) + d;
                        let x = (gp[3 * k + d] - gm[3 * k + d]) / (2.0 * FD_STEP);
                        let w = if row == col { 1.0 } else { 0.5 };
                        h.add(row, col, w * x);
                    }
                }
            }
        }
    }
    h
}

/// Band Cholesky factor of `a` − `shift` · diag(`mass`) (upper rows of
/// width `WIDTH` + 1), or `None` where a pivot is not positive.
fn cholesky(a: &BandSymmetric, shift: f64, mass: &[f64]) -> Option<Vec<f64>> {
    let n = a.dim();
    let (p, w) = (a.width, a.width + 1);
    let mut u: Vec<f64> = vec![0.0; n * w];
    for i in 0..n {
        let mut diag = a.get(i, i) - shift * mass[i];
        for k in i.saturating_sub(p)..i {
            diag -= u[k * w + i - k].powi(2);
        }
        if diag.is_nan() || diag <= 0.0 {
            return None;
        }
        let pivot = diag.sqrt();
        u[i * w] = pivot;
        for j in i + 1..(i + w).min(n) {
            let mut x = a.get(i, j);
            for k in j.saturating_sub(p)..i {
                x -= u[k * w + i - k] * u[k * w + j - k];
            }
            u[i * w + j - i] = x / pivot;
        }
    }
    Some(u)
}

/// The solution x of (`a` + `shift` · diag(`mass`)) x = `rhs` by band
/// Cholesky (O(n · width²)), or `None` where that matrix is not positive
/// definite: the damped Newton step of `sim::relax`.
pub fn solve_shifted(a: &BandSymmetric, shift: f64, mass: &[f64], rhs: &[f64]) -> Option<Vec<f64>> {
    let u = cholesky(a, -shift, mass)?;
    let n = a.dim();
    let (p, w) = (a.width, a.width + 1);
    // Uᵀ y = rhs, then U x = y; u[k w + d] = U[k][k + d].
    let mut y = rhs.to_vec();
    for i in 0..n {
        for k in i.saturating_sub(p)..i {
            y[i] -= u[k * w + i - k] * y[k];
        }
        y[i] /= u[i * w];
    }
    for i in (0..n).rev() {
        for j in i + 1..(i + w).min(n) {
            y[i] -= u[i * w + j - i] * y[j];
        }
        y[i] /= u[i * w];
    }
    Some(y)
}

/// Whether the clamped Hessian at `q` exceeds `margin` times the mass
/// matrix (all mass-weighted eigenvalues ω² above `margin`).
pub fn is_stable(ladder: &Ladder, q: &[f64], margin: f64) -> bool {
    cholesky(&clamped_hessian(ladder, q), margin, &free_masses(ladder)).is_some()
}

/// The smallest mass-weighted eigenvalue ω²_min of the clamped Hessian at
/// `q`, to a relative 1e-6 by bisection on Cholesky tests (negative where
/// the state is not a minimum).
pub fn smallest_omega_sq(ladder: &Ladder, q: &[f64]) -> f64 {
    let h = clamped_hessian(ladder, q);
    let mass = free_masses(ladder);
    let mut hi = (0..h.dim())
        .map(|i| h.get(i, i) / mass[i])
        .fold(f64::INFINITY, f64::min);
    let mut lo = -1.0f64;
    while cholesky(&h, lo, &mass).is_none() {
        lo *= 2.0;
        if lo < -1e6 {
            return lo;
        }
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if hi - lo <= 1e-6 * mid.abs().max(1e-12) {
            break;
        }
        if cholesky(&h, mid, &mass).is_some() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// The rest test of docs/sweeps.md at state (`q`, `v`): kinetic energy and
/// residual forces under `tol`, then (only then: it costs 18 gradients)
/// the clamped Hessian above `tol.margin`.
pub fn rest_proof(ladder: &Ladder, q: &[f64], v: &[f64], tol: &RestTolerances) -> RestProof {
    let kinetic = ladder.kinetic_energy(&v[3..]);
    let mut proof = RestProof {
        kinetic,
        force: f64::INFINITY,
        stable: None,
        proved: false,
    };
    if kinetic > tol.kinetic {
        return proof;
    }
    proof.force = residual_force(ladder, q);
    if proof.force > tol.force {
        return proof;
    }
    let stable = is_stable(ladder, q, tol.margin);
    proof.stable = Some(stable);
    proof.proved = stable;
    proof
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Params;

    #[test]
    fn finite_difference_hessian_matches_the_dense_one() {
        // The springs-only ground state: H = CᵀC (clamped), as the band
        // Hessian behind ω_max assembles it analytically.
        let p = crate::theory::compatibility::springs_only(&Params::paper(60.0).unwrap());
        let ladder = Ladder::new(p);
        let h = clamped_hessian(&ladder, &ladder.ground_state());
        let c = ladder.spring_length_jacobian(&ladder.ground_state());
        let ctc = c.transpose() * &c;
        for i in 0..h.dim() {
            for j in 0..h.dim() {
                let want = ctc[(i + 3, j + 3)];
                assert!((h.get(i, j) - want).abs() < 1e-8, "({i}, {j})");
            }
        }
    }

    #[test]
    fn the_unrelaxed_ground_state_is_not_at_rest() {
        // Gravity pulls every block with G = 2e-4: the residual force.
        let ladder = Ladder::new(Params::paper(60.0).unwrap());
        let g = ladder.ground_state();
        assert!((residual_force(&ladder, &g) - 2e-4).abs() < 1e-12);
        let v = vec![0.0; g.len()];
        assert!(!rest_proof(&ladder, &g, &v, &RestTolerances::default()).proved);
    }
}
