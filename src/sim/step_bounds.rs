//! The linear stability bounds of the fixed-step schemes (README.md):
//! the largest step each takes for a mode of frequency ω and damping rate
//! c. `auto` starts from them (`scenes::run`), and `ladder bench stability`
//! charts them beside the measured critical steps.

use super::IntegratorKind;
use crate::model::Params;
use nalgebra::Complex;

/// Linear stability bound of each scheme for a mode of frequency ω and
/// damping rate c, λ = −c/2 ± i sqrt(ω² − c²/4) (README.md): 2/ω for
/// symplectic Euler, Verlet and Moreau's midpoint (a leapfrog between
/// impulses), 2√2/ω for RK4 (the undamped bounds the spec
/// quotes), and for explicit Euler and fixed-step dopri5 the damped bound,
/// the first h at which |R(hλ)| exceeds 1 (c/ω² for explicit Euler). Both of
/// those are unstable on the imaginary axis, so only damping gives a bound.
pub fn predicted_dt(kind: IntegratorKind, omega: f64, damping: f64) -> f64 {
    match kind {
        IntegratorKind::SymplecticEuler | IntegratorKind::Verlet | IntegratorKind::Moreau => {
            2.0 / omega
        }
        IntegratorKind::Rk4 => 2.0 * std::f64::consts::SQRT_2 / omega,
        IntegratorKind::ExplicitEuler | IntegratorKind::Dopri5 => {
            let lambda = Complex::new(
                -0.5 * damping,
                (omega * omega - 0.25 * damping * damping).max(0.0).sqrt(),
            );
            damped_bound(kind, lambda)
        }
    }
}

/// Stability function R(z) of the explicit one-step schemes: 1 + z for
/// explicit Euler, the Taylor polynomial of degree 4 for RK4, and
/// Σ_{k≤5} z^k/k! + z⁶/600 for Dormand–Prince 5.
pub fn stability_function(kind: IntegratorKind, z: Complex<f64>) -> Complex<f64> {
    let coeffs: &[f64] = match kind {
        IntegratorKind::ExplicitEuler => &[1.0, 1.0],
        IntegratorKind::Dopri5 => &[
            1.0,
            1.0,
            0.5,
            1.0 / 6.0,
            1.0 / 24.0,
            1.0 / 120.0,
            1.0 / 600.0,
        ],
        _ => &[1.0, 1.0, 0.5, 1.0 / 6.0, 1.0 / 24.0],
    };
    coeffs
        .iter()
        .rev()
        .fold(Complex::new(0.0, 0.0), |acc, c| acc * z + c)
}

/// First h > 0 at which |R(hλ)| > 1, by a scan in steps of 0.1 % and bisection.
fn damped_bound(kind: IntegratorKind, lambda: Complex<f64>) -> f64 {
    let grows = |h: f64| stability_function(kind, lambda * h).norm() > 1.0;
    let mut h = 1e-6 / lambda.norm();
    while !grows(h * 1.001) {
        h *= 1.001;
        if h * lambda.norm() > 100.0 {
            return f64::INFINITY;
        }
    }
    let (mut lo, mut hi) = (h, h * 1.001);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if grows(mid) { hi = mid } else { lo = mid }
    }
    lo
}

/// The smaller of the translational (γ/m) and rotational (γ r²/I) damping rates.
pub fn damping_rate(params: &Params) -> f64 {
    use crate::model::params::{M, R};
    (params.gamma / M).min(params.gamma * R * R / params.inertia)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn damped_bounds_match_closed_forms() {
        let (omega, c) = (3.0, 0.02);
        let euler = predicted_dt(IntegratorKind::ExplicitEuler, omega, c);
        assert!(
            (euler - c / (omega * omega)).abs() / euler < 1e-6,
            "{euler}"
        );
        // RK4 with damping is stable a little beyond its undamped bound 2√2/ω.
        let lambda = Complex::new(-c / 2.0, (omega * omega - c * c / 4.0).sqrt());
        let rk4 = damped_bound(IntegratorKind::Rk4, lambda);
        let undamped = predicted_dt(IntegratorKind::Rk4, omega, c);
        assert!(
            rk4 > undamped && rk4 < 1.05 * undamped,
            "{rk4} vs {undamped}"
        );
        // Dormand–Prince 5 is (barely) unstable on the imaginary axis beyond
        // ωh ≈ 1: with light damping its bound sits a little above that.
        let dp5 = predicted_dt(IntegratorKind::Dopri5, omega, c) * omega;
        assert!(dp5 > 1.0 && dp5 < 3.5, "{dp5}");
    }
}
