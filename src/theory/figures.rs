//! Data for the figures of the linear theory (no drawing here): the U(θ)
//! double wells (Fig. 2c), the barrier ΔU(α), the dispersion ω_±(q) (Fig. S5),
//! the det C(q) loops (winding figure), the surface zero mode (edge-mode
//! figure), the zero-mode shapes of eq:zm_n (Fig. S4) and the gapless α = 0
//! configuration (Fig. S3).

use super::bloch::{
    BlochChain, C64, Coefficients, corrected_zero_mode, paper_det, paper_zero_mode, zone_samples,
};
use super::dispersion::{KineticMetric, omega_closed_form};
use super::edge::{Edge, kappa, surface_zero_mode};
use super::gravity::{a_from_alpha, alpha_from_lengths, barrier, potential};
use crate::error::Result;
use crate::model::ladder::parity;
use crate::model::{Ladder, Params};
use nalgebra::{DVector, Vector3};
use serde::Serialize;
use std::f64::consts::{FRAC_PI_2, PI, SQRT_2};

/// U(θ) for one a/b (eq:U_g): points (θ in degrees, U in m g s).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PotentialCurve {
    pub a_over_b: f64,
    pub a: f64,
    pub b: f64,
    /// Equilibrium angle (eq:eq_alpha) in degrees.
    pub alpha_deg: Option<f64>,
    pub points: Vec<[f64; 2]>,
}

/// U(θ) on `samples` angles in (−90°, 90°) for each a/b; angles where the
/// links cannot close are left out.
pub fn potential_curves(b: f64, a_over_b: &[f64], samples: usize) -> Vec<PotentialCurve> {
    a_over_b
        .iter()
        .map(|&r| {
            let a = r * b;
            let points = (0..samples)
                .map(|k| -FRAC_PI_2 + PI * (k as f64 + 0.5) / samples as f64)
                .filter_map(|th| potential(a, b, th).map(|u| [th.to_degrees(), u]))
                .collect();
            PotentialCurve {
                a_over_b: r,
                a,
                b,
                alpha_deg: alpha_from_lengths(a, b).map(f64::to_degrees),
                points,
            }
        })
        .collect()
}

/// ΔU(α) (eq:delta_U) for α from 0 to 90°: points (α in degrees, ΔU in m g s).
pub fn barrier_curve(b: f64, samples: usize) -> Vec<[f64; 2]> {
    (0..=samples)
        .filter_map(|k| {
            let alpha = FRAC_PI_2 * k as f64 / samples as f64;
            barrier(b, alpha).map(|du| [alpha.to_degrees(), du])
        })
        .collect()
}

/// One wavenumber of the dispersion figure; frequencies in 1/τ.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DispersionSample {
    pub qb: f64,
    /// [ω_−, ω_+] of eq:dispersion as printed, ω_0 = 1/τ.
    pub closed_form: [f64; 2],
    /// The same with ω_0 = sqrt(2k/m), the normalisation that makes it exact.
    pub closed_form_rescaled: [f64; 2],
    /// [ω_−, ω_+] of the model's constrained chain, metric diag(m, I).
    pub numerical: [f64; 2],
    /// The same with the consistent metric (θ inertia I + m (s/2)² sin²α).
    pub numerical_consistent_metric: [f64; 2],
    /// The three branches of the unconstrained chain.
    pub unconstrained: [f64; 3],
}

/// ω_±(q) for one α.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DispersionCurve {
    pub alpha_deg: f64,
    pub b: f64,
    pub samples: Vec<DispersionSample>,
}

/// Dispersion curves for each α at b, `samples` + 1 points on qb ∈ [−π, π].
pub fn dispersion_curves(
    base: &Params,
    b: f64,
    alphas_deg: &[f64],
    samples: usize,
) -> Result<Vec<DispersionCurve>> {
    alphas_deg
        .iter()
        .map(|&alpha_deg| {
            let chain = BlochChain::new(&base.with(base.n, b, alpha_deg)?)?;
            let samples = (0..=samples)
                .map(|k| dispersion_sample(&chain, -PI + 2.0 * PI * k as f64 / samples as f64))
                .collect();
            Ok(DispersionCurve {
                alpha_deg,
                b,
                samples,
            })
        })
        .collect()
}

fn dispersion_sample(chain: &BlochChain, qb: f64) -> DispersionSample {
    let q = qb / chain.coefficients.b;
    let closed_form = omega_closed_form(&chain.coefficients, q);
    DispersionSample {
        qb,
        closed_form,
        closed_form_rescaled: closed_form.map(|w| SQRT_2 * w),
        numerical: chain.constrained_dispersion(q, KineticMetric::Paper),
        numerical_consistent_metric: chain.constrained_dispersion(q, KineticMetric::Constrained),
        unconstrained: chain.unconstrained_dispersion(q),
    }
}

/// det C(q) traced over the Brillouin zone, as [re, im] pairs.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DetLoop {
    pub alpha_deg: f64,
    pub winding_number: Option<i32>,
    pub c1: f64,
    pub c2: f64,
    /// qb of each sample ((k + ½) 2π/M: q = 0 itself is avoided).
    pub qb: Vec<f64>,
    /// det C_red(q) of the model.
    pub det: Vec<[f64; 2]>,
    /// det C_red(q)/(e^{iqb} − 1): the circle of radius 2c_1 about −2c_2
    /// whose winding is n_C.
    pub reduced: Vec<[f64; 2]>,
    /// eq:det-C as printed.
    pub paper: Vec<[f64; 2]>,
}

/// The det C(q) loop of `params` with `samples` points.
pub fn det_loop(params: &Params, samples: usize) -> Result<DetLoop> {
    let chain = BlochChain::new(params)?;
    let k = chain.coefficients;
    let qb: Vec<f64> = zone_samples(samples).collect();
    let pair = |z: C64| [z.re, z.im];
    let det: Vec<C64> = qb.iter().map(|x| chain.det(x / k.b)).collect();
    Ok(DetLoop {
        alpha_deg: params.alpha_deg(),
        winding_number: chain.winding_number(),
        c1: k.c1,
        c2: k.c2,
        reduced: qb
            .iter()
            .zip(&det)
            .map(|(x, d)| pair(d / (k.z(x / k.b) - 1.0)))
            .collect(),
        paper: qb.iter().map(|x| pair(paper_det(&k, x / k.b))).collect(),
        det: det.into_iter().map(pair).collect(),
        qb,
    })
}

/// |δθ_n| of the surface zero mode, numerical and e^{−κ(n−1)b}.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EdgeModeProfile {
    pub alpha_deg: f64,
    pub kappa: Option<f64>,
    pub edge: Option<Edge>,
    /// Block labels n = 1..N.
    pub n: Vec<usize>,
    /// |δθ_n| of the null vector, max 1.
    pub numerical: Vec<f64>,
    /// e^{−κ(n−1)b} scaled to max 1 (|c_2/c_1|^{n−1}).
    pub formula: Vec<f64>,
}

/// The edge-mode profile of the reduced chain of `params` (not a = b).
pub fn edge_mode_profile(params: &Params) -> Result<EdgeModeProfile> {
    let mode = surface_zero_mode(params)?;
    let r = mode.ratio_formula.abs();
    let raw: Vec<f64> = (0..params.n as i32).map(|k| r.powi(k)).collect();
    let top = raw.iter().copied().fold(0.0, f64::max);
    Ok(EdgeModeProfile {
        alpha_deg: params.alpha_deg(),
        kappa: kappa(params.b, params.alpha),
        edge: mode.edge,
        n: (1..=params.n).collect(),
        numerical: mode.theta.iter().map(|t| t.abs()).collect(),
        formula: raw.iter().map(|x| x / top).collect(),
    })
}

/// A zero-mode shape of eq:zm_n as full configurations q = [X, Y, θ, ...]
/// that a snapshot renderer can draw over the ground state.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ZeroModeShape {
    /// Mode number m, k = 2π m/(N b).
    pub m: usize,
    pub epsilon0: f64,
    pub ground: Vec<f64>,
    /// Ground state plus eq:zm_n as printed.
    pub paper: Vec<f64>,
    /// Ground state plus the model's zero mode (staggered v, see `bloch`).
    pub model: Vec<f64>,
    /// |C δq|/|δq| of the free chain for the printed and the model's mode
    /// (0 for a vanishing mode: the model's mode vanishes for k b ∈ 2πℤ).
    pub paper_residual: f64,
    pub model_residual: f64,
}

/// The zero mode of mode number `m` and amplitude `epsilon0` of the N-block
/// chain of `params`, printed (eq:zm_n) and corrected.
pub fn zero_mode_shape(params: &Params, m: usize, epsilon0: f64) -> ZeroModeShape {
    let ladder = Ladder::new(*params);
    let k = Coefficients::of(params);
    let q = 2.0 * PI * m as f64 / (params.n as f64 * params.b);
    let paper = real_space_mode(params.n, &k, q, &paper_zero_mode(&k, q), false, epsilon0);
    let model = real_space_mode(params.n, &k, q, &corrected_zero_mode(&k, q), true, epsilon0);
    let ground = ladder.ground_state();
    let c = ladder.spring_length_jacobian(&ground);
    let residual = |d: &DVector<f64>| {
        let norm = d.norm();
        if norm > 0.0 {
            (&c * d).norm() / norm
        } else {
            0.0
        }
    };
    let shifted = |d: &DVector<f64>| ground.iter().zip(d.iter()).map(|(g, x)| g + x).collect();
    ZeroModeShape {
        m,
        epsilon0,
        paper_residual: residual(&paper),
        model_residual: residual(&model),
        paper: shifted(&paper),
        model: shifted(&model),
        ground: ground.clone(),
    }
}

/// δx_n = ε_0 Re[U(q) e^{iqnb}], n = 1..N, with δv_n = (−1)^n Re[...] when
/// the transverse component is staggered (ε(q) = (ε_0/2)(δ_{q,k} + δ_{−q,k})).
fn real_space_mode(
    n: usize,
    k: &Coefficients,
    q: f64,
    u: &Vector3<C64>,
    staggered: bool,
    eps: f64,
) -> DVector<f64> {
    DVector::from_iterator(
        3 * n,
        (0..n).flat_map(|i| {
            let phase = k.z(q).powu(i as u32 + 1);
            let sign = if staggered { parity(i) } else { 1.0 };
            [
                eps * (u[0] * phase).re,
                sign * eps * (u[1] * phase).re,
                eps * (u[2] * phase).re,
            ]
        }),
    )
}

/// The gapless α = 0 ground state (Fig. S3): a = sqrt(b² + 4 s²), blocks flat.
pub fn gapless_configuration(base: &Params, n: usize, b: f64) -> Result<(f64, Vec<f64>)> {
    let ladder = Ladder::new(base.with(n, b, 0.0)?);
    Ok((a_from_alpha(b, 0.0), ladder.ground_state()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn figure_data_has_the_expected_shape() {
        let p = Params::paper(60.0).unwrap();
        let curves = potential_curves(1.2, &[1.05, 1.2, 1.4, 1.6, 1.8], 181);
        assert_eq!(curves.len(), 5);
        assert!(
            curves
                .iter()
                .all(|c| c.points.len() > 50 && c.alpha_deg.is_some())
        );
        assert_eq!(barrier_curve(1.3, 90).len(), 91);
        let d = dispersion_curves(&p, 1.3, &[15.0, 30.0, 45.0, 60.0, 75.0, 86.0], 64).unwrap();
        assert_eq!(d[0].samples.len(), 65);
        let l = det_loop(&p, 256).unwrap();
        assert_eq!((l.det.len(), l.winding_number), (256, Some(1)));
        let e = edge_mode_profile(&p).unwrap();
        assert_eq!(e.numerical.len(), 10);
        let (a, q) = gapless_configuration(&p, 10, 1.3).unwrap();
        assert!((a - (1.69f64 + 4.0).sqrt()).abs() < 1e-12 && q.len() == 30);
    }
}
