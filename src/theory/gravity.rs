//! Gravity potential of the linkage limit and the equilibrium angle
//! (supplement, "Equilibrium configuration under gravity").
//!
//! In the linkage limit every A link has length a and every B link length b.
//! Both blocks of a pair at the same angle θ then fix the spacing of their
//! centres, X_{n+1} − X_n = s sin θ + Δ_x(θ) and |Y_{n+1} − Y_n| = Δ_y(θ)
//! (eq:b, eq:del_y). The potential per pair of blocks is U(θ) = −2 m g
//! (s sin θ + Δ_x(θ)) (eq:U_g; the paper's normalisation, kept here). All
//! energies are in units of m g s, lengths in units of s.

use crate::model::params::S;
use crate::model::{Ladder, Params};

/// Δ_y(θ) = (a² − b²)/(4 s cos θ), the transverse spacing of the centres
/// (eq:del_y).
pub fn delta_y(a: f64, b: f64, theta: f64) -> f64 {
    (a * a - b * b) / (4.0 * S * theta.cos())
}

/// Centre spacing along gravity, X_{n+1} − X_n = s sin θ + Δ_x(θ)
/// = sqrt(½(a² + b²) − s² cos²θ − (a² − b²)²/(16 s² cos²θ)) (eq:del_y).
/// `None` where the linkage cannot close (negative radicand or |θ| ≥ 90°).
pub fn centre_spacing(a: f64, b: f64, theta: f64) -> Option<f64> {
    let c2 = theta.cos().powi(2);
    if c2 <= 0.0 {
        return None;
    }
    let d = a * a - b * b;
    let radicand = 0.5 * (a * a + b * b) - S * S * c2 - d * d / (16.0 * S * S * c2);
    (radicand >= 0.0).then(|| radicand.sqrt())
}

/// Gravity potential per pair of blocks in units of m g s,
/// U(θ) = −sqrt(2(a² + b²) − 4 s² cos²θ − (a² − b²)²/(4 s² cos²θ)) (eq:U_g).
pub fn potential(a: f64, b: f64, theta: f64) -> Option<f64> {
    centre_spacing(a, b, theta).map(|dx| -2.0 * dx / S)
}

/// Equilibrium angle α ≥ 0 of rest lengths (a, b): cos α = sqrt(a² − b²)/(2s)
/// (eq:eq_alpha). `None` unless b ≤ a ≤ sqrt(b² + 4 s²).
pub fn alpha_from_lengths(a: f64, b: f64) -> Option<f64> {
    let cos_alpha = (a * a - b * b).sqrt() / (2.0 * S);
    (a >= b && cos_alpha <= 1.0).then(|| cos_alpha.acos())
}

/// Rest length of the A springs for an equilibrium angle α,
/// a = sqrt(b² + 4 s² cos²α) (eq:eq_alpha).
pub fn a_from_alpha(b: f64, alpha: f64) -> f64 {
    (b * b + 4.0 * S * S * alpha.cos().powi(2)).sqrt()
}

/// U_min = U(±α) = −2 m g b, in units of m g s (eq:min_values).
pub fn u_min(b: f64) -> f64 {
    -2.0 * b / S
}

/// Barrier ΔU(α) = U(0) − U(α) = 2 m g b (1 − sqrt(1 − (s²/b²) sin⁴α)), in
/// units of m g s (eq:delta_U). `None` when b < s sin²α: the flat
/// configuration θ = 0 cannot be closed by the links.
pub fn barrier(b: f64, alpha: f64) -> Option<f64> {
    let x = 1.0 - (S * S / (b * b)) * alpha.sin().powi(4);
    (x >= 0.0).then(|| 2.0 * b / S * (1.0 - x.sqrt()))
}

/// Rest length a = sqrt(b² + 4 s²) of the gapless case α = 0, where the
/// bistability is lost (text after eq:delta_U).
pub fn gapless_a(b: f64) -> f64 {
    (b * b + 4.0 * S * S).sqrt()
}

/// Centre spacing (X_2 − X_1, Y_2 − Y_1) of a two-block model chain with both
/// blocks at angle θ and both springs at their rest lengths, found by Newton
/// iteration on the model's spring lengths and Jacobian (no closed form
/// used). `guess` is the starting spacing; `None` if Newton does not converge.
pub fn model_pair_spacing(params: &Params, theta: f64, guess: [f64; 2]) -> Option<[f64; 2]> {
    let pair = Ladder::new(params.with(2, params.b, params.alpha_deg()).ok()?);
    let mut q = vec![0.0, 0.0, theta, guess[0], guess[1], theta];
    let (mut la, mut lb) = ([0.0], [0.0]);
    for _ in 0..100 {
        pair.spring_lengths(&q, &mut la, &mut lb);
        let r = [la[0] - pair.a, lb[0] - params.b];
        if r[0].abs().max(r[1].abs()) < 1e-13 {
            return Some([q[3], q[4]]);
        }
        let j = pair.spring_length_jacobian(&q);
        let (j11, j12, j21, j22) = (j[(0, 3)], j[(0, 4)], j[(1, 3)], j[(1, 4)]);
        let det = j11 * j22 - j12 * j21;
        if det.abs() < 1e-14 {
            return None;
        }
        q[3] -= (j22 * r[0] - j12 * r[1]) / det;
        q[4] -= (j11 * r[1] - j21 * r[0]) / det;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn potential_minimum_is_u_min_at_alpha() {
        for alpha_deg in [30.0f64, 60.0, 75.0, 86.0] {
            let (b, alpha) = (1.3, alpha_deg.to_radians());
            let a = a_from_alpha(b, alpha);
            assert!((potential(a, b, alpha).unwrap() - u_min(b)).abs() < 1e-12);
            assert!((potential(a, b, -alpha).unwrap() - u_min(b)).abs() < 1e-12);
            assert!((alpha_from_lengths(a, b).unwrap() - alpha).abs() < 1e-9);
        }
    }

    #[test]
    fn potential_is_even_in_theta() {
        let (a, b) = (1.6, 1.2);
        for k in 0..80 {
            let th = -1.5 + 3.0 * k as f64 / 80.0;
            assert_eq!(potential(a, b, th), potential(a, b, -th));
        }
    }

    #[test]
    fn barrier_is_u0_minus_umin() {
        for alpha_deg in [10.0f64, 45.0, 60.0, 89.0] {
            let (b, alpha) = (1.3, alpha_deg.to_radians());
            let a = a_from_alpha(b, alpha);
            let du = potential(a, b, 0.0).unwrap() - potential(a, b, alpha).unwrap();
            assert!(
                (du - barrier(b, alpha).unwrap()).abs() < 1e-12,
                "{alpha_deg}"
            );
        }
        assert_eq!(barrier(1.3, 0.0), Some(0.0));
        assert!(barrier(0.5, 1.5).is_none());
    }

    #[test]
    fn gapless_case_has_alpha_zero() {
        let b = 1.3;
        assert!(alpha_from_lengths(gapless_a(b), b).unwrap().abs() < 1e-7);
        assert!((alpha_from_lengths(b, b).unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
        assert!(alpha_from_lengths(gapless_a(b) + 0.01, b).is_none());
    }
}
