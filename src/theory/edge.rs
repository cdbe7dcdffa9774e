//! The surface zero mode of the reduced chain (supplement, "Reduction to K-L
//! chain model", eq:R_B, eq:u-v-theta, eq:e-KL, eq:2nd_sol).
//!
//! Pinning every B node, δX_n + r δt_n = 0, leaves one angle per block:
//! δu_n = −(s/2) cos α δθ_n, δv_n = (−1)^n (s/2) sin α δθ_n (eq:u-v-theta).
//! The A extensions then read e_{A,n} = −2c_1 δθ_{n+1} + 2c_2 δθ_n (eq:e-KL),
//! whose single zero mode is δθ_{n+1} = (c_2/c_1) δθ_n (eq:2nd_sol), decaying
//! as e^{−κ n b} with κ = b^{-1} log|(b + 2s sin α)/(b − 2s sin α)|.

use super::bloch::Coefficients;
use super::linalg;
use crate::error::{Error, Result};
use crate::model::ladder::{itheta, ix, iy, parity};
use crate::model::params::R;
use crate::model::{Ladder, Params};
use nalgebra::DMatrix;
use serde::Serialize;

/// |cos α| below this is the symmetric toy a = b, where γ = c_1 = c_2 = 0.
pub const SYMMETRIC_COS: f64 = 1e-12;

/// Ratio δθ_{n+1}/δθ_n = c_2/c_1 = (b − 2s sin α)/(b + 2s sin α) of the
/// surface zero mode (eq:2nd_sol). `None` for the symmetric toy (c_1 = c_2 = 0)
/// or where c_1 = 0.
pub fn zero_mode_ratio(b: f64, alpha: f64) -> Option<f64> {
    let k = Coefficients::new(b, alpha);
    (alpha.cos().abs() > SYMMETRIC_COS && k.c1 != 0.0).then(|| k.c2 / k.c1)
}

/// Inverse penetration length κ = b^{-1} log|(b + 2s sin α)/(b − 2s sin α)|
/// (after eq:2nd_sol). Positive for α > 0 (mode at the top), negative for
/// α < 0 (mode at the bottom), 0 for α = 0 (delocalised). `None` where it is
/// infinite (b = 2s|sin α|: the mode sits on one block) or undefined (a = b).
pub fn kappa(b: f64, alpha: f64) -> Option<f64> {
    let ratio = zero_mode_ratio(b, alpha)?;
    (ratio != 0.0).then(|| ratio.abs().recip().ln() / b)
}

/// The edge that a surface mode is localised at.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Edge {
    /// Block 1, the driven top block.
    Top,
    /// Block N.
    Bottom,
}

/// Projection δq = P δθ onto the B-pinned subspace, 3N × N:
/// δX_n = −r (dt_n/dθ_n) δθ_n with dt_n/dθ = (cos θ_n, −(−1)^n sin θ_n).
pub fn pinned_b_projection(ladder: &Ladder, q: &[f64]) -> DMatrix<f64> {
    let n = ladder.n();
    let mut p = DMatrix::zeros(3 * n, n);
    for i in 0..n {
        let (s, c) = q[itheta(i)].sin_cos();
        p[(ix(i), i)] = -R * c;
        p[(iy(i), i)] = R * parity(i) * s;
        p[(itheta(i), i)] = 1.0;
    }
    p
}

/// Compatibility matrix of the reduced chain, C P: 2(N − 1) × N, rows
/// [A_1, B_1, ...]; the B rows vanish identically (eq:e-KL).
pub fn reduced_chain_matrix(params: &Params) -> DMatrix<f64> {
    let ladder = Ladder::new(*params);
    let q = ladder.ground_state();
    ladder.spring_length_jacobian(&q) * pinned_b_projection(&ladder, &q)
}

/// The surface zero mode of the reduced N-block chain, found numerically.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SurfaceMode {
    /// δθ_n, n = 1..N, normalised to max |δθ_n| = 1 with a positive largest entry.
    pub theta: Vec<f64>,
    /// δθ_{n+1}/δθ_n from the numerical null vector.
    pub ratios: Vec<f64>,
    /// c_2/c_1 of eq:2nd_sol.
    pub ratio_formula: f64,
    /// Number of zero singular values of the reduced chain (1 expected).
    pub zero_modes: usize,
    /// The end where |δθ_n| is largest; `None` when |δθ_1| = |δθ_N| (α = 0:
    /// the mode is uniform, κ = 0).
    pub edge: Option<Edge>,
}

/// Null vector of the reduced chain's compatibility matrix (SVD) compared
/// with c_2/c_1. Errors for the symmetric toy, where every δθ_n is free.
pub fn surface_zero_mode(params: &Params) -> Result<SurfaceMode> {
    let ratio_formula = zero_mode_ratio(params.b, params.alpha)
        .ok_or_else(|| Error::bad_input("no single surface zero mode for a = b (alpha = 90)"))?;
    let c = reduced_chain_matrix(params);
    let v = linalg::null_vector(&c)?;
    let big = v
        .iter()
        .copied()
        .max_by(|x, y| x.abs().total_cmp(&y.abs()))
        .unwrap_or(1.0);
    let theta: Vec<f64> = v.iter().map(|x| x / big).collect();
    let ratios = theta.windows(2).map(|w| w[1] / w[0]).collect();
    let edge = localisation(theta[0], theta[theta.len() - 1]);
    Ok(SurfaceMode {
        theta,
        ratios,
        ratio_formula,
        zero_modes: params.n - linalg::rank(&c)?,
        edge,
    })
}

/// The edge of the larger of |δθ_1| and |δθ_N| (equal within 1e-9: none).
fn localisation(first: f64, last: f64) -> Option<Edge> {
    let (f, l) = (first.abs(), last.abs());
    if (f - l).abs() <= 1e-9 * f.max(l) {
        None
    } else if f > l {
        Some(Edge::Top)
    } else {
        Some(Edge::Bottom)
    }
}

/// |C P δθ| / |δθ| for δθ_n = (c_2/c_1)^{n−1} of eq:2nd_sol: zero when the
/// formula is a zero mode of the model's reduced chain.
pub fn formula_mode_residual(params: &Params) -> Option<f64> {
    let ratio = zero_mode_ratio(params.b, params.alpha)?;
    let theta: Vec<f64> = (0..params.n as i32).map(|k| ratio.powi(k)).collect();
    let v = nalgebra::DVector::from_vec(theta);
    Some((reduced_chain_matrix(params) * &v).norm() / v.norm())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reduced_chain_reproduces_eq_e_kl() {
        for alpha in [60.0, -60.0, 30.0, 86.0] {
            let p = Params::paper(alpha).unwrap();
            let k = Coefficients::of(&p);
            let c = reduced_chain_matrix(&p);
            for i in 0..p.n - 1 {
                assert!((c[(2 * i, i + 1)] + 2.0 * k.c1).abs() < 1e-12);
                assert!((c[(2 * i, i)] - 2.0 * k.c2).abs() < 1e-12);
                assert!(c.row(2 * i + 1).amax() < 1e-12);
            }
        }
    }

    #[test]
    fn kappa_signs_and_limits() {
        assert!(kappa(1.3, 60f64.to_radians()).unwrap() > 0.0);
        assert!(kappa(1.3, -60f64.to_radians()).unwrap() < 0.0);
        assert_eq!(kappa(1.3, 0.0), Some(0.0));
        assert!(kappa(1.3, std::f64::consts::FRAC_PI_2).is_none());
        assert!(kappa(1.3, (0.65f64).asin()).is_none());
    }
}
