//! Normal modes and phonon dispersion (supplement, "phonon dispersion":
//! eq:D, eq:constraint_Y, eq:D_comp, eq:dispersion, eq:d_s, eq:gap).
//!
//! Frequencies are in units of ω_0 = sqrt(k/m) = 1/τ, the only natural
//! frequency that the paper defines (its unit of time τ = sqrt(m/k)). The
//! closed form of eq:dispersion is the spectrum of the constrained chain
//! with kinetic metric diag(m, I) only if ω_0² = 2k/m; in units of 1/τ the
//! numerical frequencies are √2 times the printed closed form (see
//! docs/paper-errata.md).

use super::bloch::{BlochChain, C64, Coefficients};
use super::compatibility::{self, Boundary, Ring, block_masses, clamp_block_one};
use super::linalg::{BandSymmetric, frequency, mass_weighted_eigenvalues};
use crate::error::Result;
use crate::model::Params;
use crate::model::params::{M, S};
use nalgebra::{Matrix2, Matrix3, SymmetricEigen, Vector3};
use serde::Serialize;

/// Kinetic energy of the constrained chain, δv_n = (−1)^n (s/2) sin α δθ_n.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum KineticMetric {
    /// The paper's eq:D: diag(m, I); the kinetic energy of δv̇ is dropped.
    Paper,
    /// The consistent metric: ½ m δv̇² = ½ m (s/2)² sin²α δθ̇², so the angle
    /// carries I + m (s/2)² sin²α.
    Constrained,
}

impl KineticMetric {
    /// Inertia of the angle in the constrained chain.
    pub fn theta_inertia(self, inertia: f64, alpha: f64) -> f64 {
        match self {
            Self::Paper => inertia,
            Self::Constrained => inertia + M * (0.5 * S * alpha.sin()).powi(2),
        }
    }
}

/// (d_11, d_22, d_12²) of eq:d_s as printed (they assume I = m s²/4).
pub fn closed_form_d(k: &Coefficients, q: f64) -> (f64, f64, f64) {
    let (a2, b2, s2) = (k.a * k.a, k.b * k.b, S * S);
    let w = 1.0 - (q * k.b).cos();
    let sin2a = (2.0 * k.alpha).sin();
    let d11 = (1.0 + b2 / a2) * w;
    let d22 = 8.0 * s2 / a2 * sin2a.powi(2)
        + ((1.0 + b2 / a2) * k.alpha.cos().powi(2) - 4.0 * s2 / a2 * sin2a.powi(2)) * w;
    let d12_sq = (1.0 - b2 / a2).powi(2) * k.alpha.cos().powi(2) * w * w
        + 4.0 * b2 * s2 / (a2 * a2) * sin2a.powi(2) * (q * k.b).sin().powi(2);
    (d11, d22, d12_sq)
}

/// ω_∓(q) of eq:dispersion as printed, with ω_0 = 1: [ω_−, ω_+].
pub fn omega_closed_form(k: &Coefficients, q: f64) -> [f64; 2] {
    let (d11, d22, d12_sq) = closed_form_d(k, q);
    let root = ((d11 - d22).powi(2) + 4.0 * d12_sq).sqrt();
    [
        frequency(0.5 * (d11 + d22 - root)),
        frequency(0.5 * (d11 + d22 + root)),
    ]
}

/// ω_+(0) = 2√2 ω_0 (s/a) sin 2α as printed (eq:gap), with ω_0 = 1 (signed:
/// negative for α < 0, as the printed formula is).
pub fn gap_closed_form(k: &Coefficients) -> f64 {
    2.0 * 2f64.sqrt() * S / k.a * (2.0 * k.alpha).sin()
}

/// (D_11, D_12, D_22)/k of eq:D_comp as printed.
pub fn paper_dynamical_entries(k: &Coefficients, q: f64) -> (f64, C64, f64) {
    let w = 1.0 - (q * k.b).cos();
    let (a, b) = (k.a, k.b);
    let d11 = 2.0 * (1.0 + b * b / (a * a)) * w;
    let d12 = C64::new(
        2.0 * k.gamma * (a - b * b / a) * w,
        2.0 * b * S * S / (a * a) * (2.0 * k.alpha).sin() * (q * b).sin(),
    );
    let d22 = (k.v1 - k.v2).powi(2) + 2.0 * (k.v1 * k.v2 + (k.gamma * a).powi(2)) * w;
    (d11, d12, d22)
}

/// Eigenvalues of the 2 × 2 Hermitian M^{-1/2} D M^{-1/2}, M = diag(m1, m2).
fn hermitian2_eigenvalues(d: &Matrix2<C64>, m1: f64, m2: f64) -> [f64; 2] {
    let (p, r) = (d[(0, 0)].re / m1, d[(1, 1)].re / m2);
    let c = d[(0, 1)].norm_sqr() / (m1 * m2);
    let root = (0.25 * (p - r).powi(2) + c).sqrt();
    [0.5 * (p + r) - root, 0.5 * (p + r) + root]
}

impl BlochChain {
    /// Pᵀ D(q) P with P: (û, θ̂) ↦ (û, (s/2) sin α θ̂, θ̂) (eq:constraint_Y);
    /// compare eq:D_comp.
    pub fn reduced_dynamical_matrix(&self, q: f64) -> Matrix2<C64> {
        let w = self.coefficients.constraint();
        let d = self.dynamical_matrix(q);
        let p = nalgebra::Matrix3x2::new(1.0, 0.0, 0.0, w, 0.0, 1.0).map(C64::from);
        p.transpose() * d * p
    }

    /// [ω_−(q), ω_+(q)] of the constrained chain with the given kinetic metric.
    pub fn constrained_dispersion(&self, q: f64, metric: KineticMetric) -> [f64; 2] {
        let i = metric.theta_inertia(self.inertia, self.coefficients.alpha);
        hermitian2_eigenvalues(&self.reduced_dynamical_matrix(q), M, i).map(frequency)
    }

    /// The three branches of the unconstrained chain, ascending, from
    /// M^{-1/2} D(q) M^{-1/2} with M = diag(m, m, I).
    pub fn unconstrained_dispersion(&self, q: f64) -> [f64; 3] {
        let w = Vector3::new(1.0 / M.sqrt(), 1.0 / M.sqrt(), 1.0 / self.inertia.sqrt());
        let weight = Matrix3::from_diagonal(&w).map(C64::from);
        let ev = SymmetricEigen::new(weight * self.dynamical_matrix(q) * weight).eigenvalues;
        let mut out = [ev[0], ev[1], ev[2]];
        out.sort_by(f64::total_cmp);
        out.map(frequency)
    }

    /// The gap ω_+(0) of the constrained chain.
    pub fn gap(&self, metric: KineticMetric) -> f64 {
        self.constrained_dispersion(0.0, metric)[1]
    }
}

/// Normal-mode frequencies ω (ascending, units 1/τ) of the N-block chain in
/// its ground state, springs only (G = 0), masses m and inertia I.
pub fn normal_mode_frequencies(params: &Params, boundary: Boundary) -> Result<Vec<f64>> {
    let (hessian, blocks) = match boundary {
        Boundary::Free => (compatibility::chain_hessian(params), params.n),
        Boundary::Clamped => (
            clamp_block_one(&compatibility::chain_hessian(params)),
            params.n - 1,
        ),
        Boundary::Periodic => (Ring::new(params)?.hessian(), params.n),
    };
    let ev = mass_weighted_eigenvalues(&hessian, &block_masses(params, blocks))?;
    Ok(ev.into_iter().map(frequency).collect())
}

/// Largest N for which [`omega_max_clamped`] diagonalises the dense
/// Hessian (O(N³) time, O(N²) memory); above it the band bisection of
/// [`omega_max_clamped_band`] (O(N) time and memory).
pub const DENSE_OMEGA_MAX_BLOCKS: usize = 64;

/// ω_max of the N-block chain with block 1 clamped (springs only, ground
/// state): the stability bound of explicit integrators, e.g. dt < 2/ω_max
/// for Verlet and symplectic Euler. Dense eigen-decomposition up to
/// [`DENSE_OMEGA_MAX_BLOCKS`] blocks, band bisection above (the two agree
/// to ~1e-14).
pub fn omega_max_clamped(params: &Params) -> Result<f64> {
    if params.n <= DENSE_OMEGA_MAX_BLOCKS {
        omega_max_clamped_dense(params)
    } else {
        omega_max_clamped_band(params)
    }
}

/// [`omega_max_clamped`] from every normal mode (dense, O(N³)).
pub fn omega_max_clamped_dense(params: &Params) -> Result<f64> {
    let omega = normal_mode_frequencies(params, Boundary::Clamped)?;
    Ok(omega.last().copied().unwrap_or(0.0))
}

/// The mass-weighted Hessian M^{-1/2} Cᵀ C M^{-1/2} of the clamped chain
/// (block 1's coordinates dropped; the stress-free ground state's Hessian,
/// as `compatibility::chain_hessian`), assembled spring by spring from the
/// sparse compatibility matrix as a band matrix of half-bandwidth 5 (a
/// spring couples the 6 coordinates of two neighbouring blocks).
pub fn clamped_band_hessian(params: &Params) -> BandSymmetric {
    use crate::model::Ladder;
    let ladder = Ladder::new(compatibility::springs_only(params));
    let rows = ladder.spring_length_gradients(&ladder.ground_state());
    let masses = block_masses(params, params.n);
    let mut h = BandSymmetric::zeros(3 * (params.n - 1), 5);
    for (r, g) in rows.iter().enumerate() {
        let base = 3 * (r / 2);
        // Weighted entries over the global coordinates base..base + 6;
        // those of block 1 (global 0..3) are clamped.
        let entries: Vec<(usize, f64)> = (0..6)
            .filter(|k| base + k >= 3)
            .map(|k| (base + k - 3, g[k] / masses[base + k].sqrt()))
            .collect();
        for &(i, gi) in &entries {
            for &(j, gj) in &entries {
                if i <= j {
                    h.add(i, j, gi * gj);
                }
            }
        }
    }
    h
}

/// [`omega_max_clamped`] from the band Hessian [`clamped_band_hessian`]:
/// bisection on its largest eigenvalue with a band Cholesky test
/// (`linalg::BandSymmetric::largest_eigenvalue`), O(N) time and memory,
/// so N = 100,000 takes a fraction of a second.
pub fn omega_max_clamped_band(params: &Params) -> Result<f64> {
    Ok(frequency(
        clamped_band_hessian(params).largest_eigenvalue()?,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn model_reduced_d_is_eq_d_comp() {
        for alpha in [60.0, -60.0, 30.0, 80.0] {
            let ch = BlochChain::new(&Params::paper(alpha).unwrap()).unwrap();
            for q in [0.0, 0.4, 1.7, 2.9] {
                let d = ch.reduced_dynamical_matrix(q);
                let (d11, d12, d22) = paper_dynamical_entries(&ch.coefficients, q);
                assert!((d[(0, 0)].re - d11).abs() < 1e-7, "alpha {alpha} q {q}");
                assert!((d[(1, 1)].re - d22).abs() < 1e-7);
                assert!((d[(0, 1)] - d12).norm() < 1e-7, "{} vs {}", d[(0, 1)], d12);
            }
        }
    }

    #[test]
    fn band_omega_max_is_the_dense_one() {
        // The longest chain, 90 blocks (270 coordinates), is the one the
        // dense eigenproblem affords at the unit tests' opt-level 0
        // (scripts/rustc-unit-tests): 120 blocks took 4.2 s of this
        // binary's 11 s of CPU, the last of its tests to end.
        for (n, b, alpha) in [
            (2, 1.3, 60.0),
            (3, 1.3, 60.0),
            (10, 1.3, 60.0),
            (10, 1.3, -60.0),
            (17, 0.7, 30.0),
            (40, 1.3, 89.0),
            (64, 2.5, -45.0),
            (90, 1.3, 60.0),
        ] {
            let p = Params::paper(60.0).unwrap().with(n, b, alpha).unwrap();
            let dense = omega_max_clamped_dense(&p).unwrap();
            let band = omega_max_clamped_band(&p).unwrap();
            assert!(
                (dense - band).abs() < 1e-12 * dense,
                "N {n} b {b} alpha {alpha}: dense {dense}, band {band}"
            );
        }
    }
}
