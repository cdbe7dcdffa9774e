//! Validated model parameters (docs/model.md).
//!
//! Units: block length s = 1, block mass m = 1, spring constant k = 1, time
//! unit τ = sqrt(m/k). Angles are stored in radians; constructors take degrees
//! because the paper quotes degrees.

use super::table::Param;
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
    /// The paper's simulation values (supplement, "Details of numerical
    /// simulation"; the defaults of the parameter table,
    /// [`crate::model::table`]) at α = `alpha_deg`, validated. The
    /// other values by name (`with_n`, `with_b`, ...):
    /// `Params::paper(60.0)?.with_n(20).with_gamma(0.0).validated()`.
    pub fn paper(alpha_deg: f64) -> Result<Self, ParamError> {
        Self::defaults().with_alpha_deg(alpha_deg).validated()
    }

    /// The table's defaults, unvalidated (every one is valid).
    pub fn defaults() -> Self {
        let d = |p: Param| p.default_value();
        Self {
            n: d(Param::N) as usize,
            b: d(Param::B),
            alpha: d(Param::Alpha).to_radians(),
            inertia: d(Param::Inertia),
            gamma: d(Param::Gamma),
            gravity: d(Param::Gravity),
        }
    }

    /// Parameter `p`'s value in the table's unit (α in degrees, as
    /// [`Params::alpha_deg`]); `None` for the drive's.
    pub fn get(&self, p: Param) -> Option<f64> {
        Some(match p {
            Param::Alpha => self.alpha_deg(),
            Param::N => self.n as f64,
            Param::B => self.b,
            Param::Gamma => self.gamma,
            Param::Gravity => self.gravity,
            Param::Inertia => self.inertia,
            Param::DriveTime => return None,
        })
    }

    /// Parameter `p` set to `x` in the table's unit (α in degrees; N a
    /// whole number, as [`Params::validated`] then checks), unvalidated;
    /// the drive's leave the parameters as they are.
    pub fn with_param(self, p: Param, x: f64) -> Self {
        match p {
            Param::Alpha => self.with_alpha_deg(x),
            Param::N => Self {
                n: x as usize,
                ..self
            },
            Param::B => Self { b: x, ..self },
            Param::Gamma => Self { gamma: x, ..self },
            Param::Gravity => Self { gravity: x, ..self },
            Param::Inertia => Self { inertia: x, ..self },
            Param::DriveTime => self,
        }
    }

    /// The parameters from each one's value (the table's units, α in
    /// degrees), each checked against the table's range as given (so
    /// that an error quotes the number typed), then validated.
    pub fn from_values(value: impl Fn(Param) -> f64) -> Result<Self, ParamError> {
        let mut params = Self::defaults();
        for p in Param::MODEL {
            let x = value(p);
            p.spec()
                .check(x, false)
                .map_err(|e| ParamError(format!("{} ({}): {e}", p.name(), p.spec().symbol)))?;
            params = params.with_param(p, x);
        }
        params.validated()
    }

    /// With N blocks, unvalidated.
    pub fn with_n(self, n: usize) -> Self {
        Self { n, ..self }
    }

    /// With rest length b (units of s), unvalidated.
    pub fn with_b(self, b: f64) -> Self {
        Self { b, ..self }
    }

    /// With α in degrees, unvalidated.
    pub fn with_alpha_deg(self, alpha_deg: f64) -> Self {
        Self {
            alpha: alpha_deg.to_radians(),
            ..self
        }
    }

    /// With damping γ, unvalidated.
    pub fn with_gamma(self, gamma: f64) -> Self {
        Self { gamma, ..self }
    }

    /// With gravity G = mg/(ks), unvalidated.
    pub fn with_gravity(self, gravity: f64) -> Self {
        Self { gravity, ..self }
    }

    /// With moment of inertia I (units of m s²), unvalidated.
    pub fn with_inertia(self, inertia: f64) -> Self {
        Self { inertia, ..self }
    }

    /// Same parameters with another N, b and α (degrees), validated again.
    pub fn with(self, n: usize, b: f64, alpha_deg: f64) -> Result<Self, ParamError> {
        self.with_n(n)
            .with_b(b)
            .with_alpha_deg(alpha_deg)
            .validated()
    }

    /// Checks every field against the parameter table's range
    /// ([`crate::model::table`]); returns the parameters unchanged when
    /// they are legal. |α| ≤ 90° is allowed here (α = 90° is the
    /// symmetric toy, α = 0 the gapless configuration); simulations
    /// further require 0 < |α| < 90°.
    pub fn validated(self) -> Result<Self, ParamError> {
        for p in Param::MODEL {
            // α read back from radians within 1e-9° ([`Params::alpha_deg`]).
            let x = self.get(p).expect("a model parameter");
            if let Err(e) = p.spec().check(x, false) {
                return Err(ParamError(format!(
                    "{} ({}): {e}",
                    p.name(),
                    p.spec().symbol
                )));
            }
        }
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

    #[test]
    fn the_paper_values_are_the_tables() {
        let p = Params::paper(60.0).unwrap();
        for param in Param::MODEL {
            assert_eq!(p.get(param), Some(param.default_value()), "{param}");
        }
        let q = Params::from_values(|p| match p {
            Param::N => 20.0,
            p => p.default_value(),
        })
        .unwrap();
        assert_eq!(q, p.with_n(20));
        let e = Params::from_values(|p| match p {
            Param::Alpha => 120.0,
            p => p.default_value(),
        })
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "alpha (α): must be degrees with |alpha| <= 90, got 120"
        );
    }
}
