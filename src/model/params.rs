//! Validated model parameters (docs/model.md).
//!
//! Units: block length s = 1, block mass m = 1, spring constant k = 1, time
//! unit τ = sqrt(m/k). Angles are stored in radians; constructors take degrees
//! because the paper quotes degrees.

use thiserror::Error;

/// Block length s (the unit of length).
pub const S: f64 = 1.0;
/// Half block length r = s/2.
pub const R: f64 = 0.5 * S;
/// Block mass m (the unit of mass).
pub const M: f64 = 1.0;
/// Spring constant k (the unit of stiffness).
pub const K: f64 = 1.0;

/// A parameter that is out of its allowed range. Always a user error (exit 2).
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{0}")]
pub struct ParamError(pub String);

/// Parameters of the asymmetric ladder (docs/model.md table).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Params {
    /// Number of blocks N; block 1 is the driven top block.
    pub n: usize,
    /// Rest length b of the B springs (in units of s).
    pub b: f64,
    /// Equilibrium angle α in radians; its sign picks the ground state.
    pub alpha: f64,
    /// Moment of inertia I of a block (paper: m s²/4).
    pub inertia: f64,
    /// Damping γ: force −γẊ on the centre, torque −γ r² θ̇.
    pub gamma: f64,
    /// Gravity G = mg/(ks).
    pub gravity: f64,
}

/// Largest N accepted: far beyond any scene, small enough to bound memory
/// (`crate::limits::MAX_BLOCKS`).
pub const MAX_BLOCKS: usize = crate::limits::MAX_BLOCKS;

impl Params {
    /// Parameters from their values, validated: N blocks, rest length b
    /// (units of s), α in degrees, damping γ, gravity G = mg/(ks) and
    /// moment of inertia I (units of m s²).
    pub fn new(
        n: usize,
        b: f64,
        alpha_deg: f64,
        gamma: f64,
        gravity: f64,
        inertia: f64,
    ) -> Result<Self, ParamError> {
        if !(alpha_deg.is_finite() && alpha_deg.abs() <= 90.0) {
            // Reported as typed, not as converted back from radians.
            return Err(ParamError(format!(
                "alpha must be a number of degrees with |alpha| <= 90, got {alpha_deg}"
            )));
        }
        Self {
            n,
            b,
            alpha: alpha_deg.to_radians(),
            inertia,
            gamma,
            gravity,
        }
        .validated()
    }

    /// The paper's simulation values (supplement, "Details of numerical
    /// simulation"): N = 10, b/s = 1.3, I = m s²/4, γ = 0.02, G = 2e-4.
    pub fn paper(alpha_deg: f64) -> Result<Self, ParamError> {
        Self {
            n: 10,
            b: 1.3,
            alpha: alpha_deg.to_radians(),
            inertia: 0.25 * M * S * S,
            gamma: 0.02,
            gravity: 2e-4,
        }
        .validated()
    }

    /// Same parameters with another N, b or α (degrees), validated again.
    pub fn with(self, n: usize, b: f64, alpha_deg: f64) -> Result<Self, ParamError> {
        Self {
            n,
            b,
            alpha: alpha_deg.to_radians(),
            ..self
        }
        .validated()
    }

    /// Checks every field; returns the parameters unchanged when they are legal.
    /// |α| ≤ 90° is allowed here (α = 90° is the symmetric toy, α = 0 the
    /// gapless configuration); simulations further require 0 < |α| < 90°.
    pub fn validated(self) -> Result<Self, ParamError> {
        let deg = self.alpha.to_degrees();
        if !self.alpha.is_finite() || deg.abs() > 90.0 + 1e-9 {
            return Err(ParamError(format!(
                "alpha must be a number of degrees with |alpha| <= 90, got {}",
                crate::numfmt::plain(deg)
            )));
        }
        if self.n < 2 || self.n > MAX_BLOCKS {
            return Err(ParamError(format!(
                "the number of blocks N must be between 2 and {MAX_BLOCKS}, got {}",
                self.n
            )));
        }
        use crate::limits::{MAX_INERTIA, MAX_LENGTH, MIN_INERTIA, MIN_LENGTH};
        within(
            "b (rest length of the B springs, in units of s)",
            self.b,
            (MIN_LENGTH, MAX_LENGTH),
        )?;
        within(
            "the moment of inertia I (in units of m s²)",
            self.inertia,
            (MIN_INERTIA, MAX_INERTIA),
        )?;
        non_negative("the damping gamma", self.gamma)?;
        non_negative("the gravity G", self.gravity)?;
        Ok(self)
    }

    /// α in degrees, rounded to 1e-9° so that 60 reads back as 60.
    pub fn alpha_deg(&self) -> f64 {
        (self.alpha.to_degrees() * 1e9).round() / 1e9
    }

    /// Rest length of the A springs, a = sqrt(b² + 4 s² cos²α) (supplement
    /// Eq. for the equilibrium angle, `eq:eq_alpha`).
    pub fn a(&self) -> f64 {
        let c = self.alpha.cos();
        (self.b * self.b + 4.0 * S * S * c * c).sqrt()
    }

    /// Number of generalised coordinates, 3N (X, Y, θ per block).
    pub fn dof(&self) -> usize {
        3 * self.n
    }
}

/// `x` within [lo, hi] (`crate::limits`: outside, the linear algebra
/// cannot converge or the numbers overflow).
fn within(name: &str, x: f64, (lo, hi): (f64, f64)) -> Result<(), ParamError> {
    if x.is_finite() && (lo..=hi).contains(&x) {
        Ok(())
    } else {
        Err(ParamError(format!(
            "{name} must be a number between {lo:e} and {hi:e}, got {}",
            crate::numfmt::plain(x)
        )))
    }
}

fn non_negative(name: &str, x: f64) -> Result<(), ParamError> {
    if x.is_finite() && x >= 0.0 {
        Ok(())
    } else {
        Err(ParamError(format!(
            "{name} must be a finite number >= 0, got {}",
            crate::numfmt::plain(x)
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derived_a_matches_geometry() {
        let p = Params::paper(60.0).unwrap();
        assert!((p.a() - (1.69f64 + 1.0).sqrt()).abs() < 1e-12);
        let sym = Params::paper(90.0).unwrap();
        assert!((sym.a() - sym.b).abs() < 1e-12);
    }

    #[test]
    fn rejects_bad_values() {
        assert!(Params::paper(f64::NAN).is_err());
        assert!(Params::paper(91.0).is_err());
        let p = Params::paper(60.0).unwrap();
        assert!(p.with(1, 1.3, 60.0).is_err());
        assert!(p.with(10, 0.0, 60.0).is_err());
        assert!(p.with(10, f64::INFINITY, 60.0).is_err());
        for b in [1e-17, 5e-324, 1e308, 1e-4, 1e4] {
            assert!(p.with(10, b, 60.0).is_err(), "b = {b}");
        }
        assert!(p.with(10, 1e-3, 60.0).is_ok() && p.with(10, 1e3, 60.0).is_ok());
        let neg = Params { gamma: -1.0, ..p };
        assert!(neg.validated().is_err());
    }
}
