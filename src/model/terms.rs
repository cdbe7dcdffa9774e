//! Which terms of docs/experiments.md a ladder has beyond the paper's model,
//! as plain parameters (model units): added mass and inertia, strip drag,
//! the links' stiffness and whether they push, pin friction. The forces
//! they make are in `media` (the fluid) and `links` (links and pins); the
//! ladder only carries them.

use super::params::ParamError;

/// The terms of docs/experiments.md beyond the paper's model, in model units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Terms {
    /// Added mass m_a of a block moving normal to its face, in m.
    pub added_mass: f64,
    /// Added moment of inertia I_a of a block turning, in m s².
    pub added_inertia: f64,
    /// Strip drag coefficient c = ½ ρ_m C_D h, in m/s² (force per unit
    /// length per squared normal speed).
    pub drag: f64,
    /// The links: stiffness and whether they push (`links`).
    pub links: Links,
    /// Coulomb friction at the pins, if any (`links`).
    pub friction: Option<PinFriction>,
}

impl Default for Terms {
    /// The paper's model: no term.
    fn default() -> Self {
        Self {
            added_mass: 0.0,
            added_inertia: 0.0,
            drag: 0.0,
            links: Links::default(),
            friction: None,
        }
    }
}

impl Terms {
    /// Whether these are the paper's model (no term at all).
    pub fn is_paper(&self) -> bool {
        *self == Self::default()
    }

    /// Whether the accelerations depend on the velocities beyond the
    /// paper's linear damping (added mass, drag, friction): such terms
    /// need an integrator that evaluates a(q, v) (`sim::rhs`).
    pub fn velocity_dependent(&self) -> bool {
        self.added_mass != 0.0
            || self.added_inertia != 0.0
            || self.drag != 0.0
            || self.friction.is_some()
    }

    /// Checks every coefficient (finite, ≥ 0; stiffness > 0; ω_ε > 0).
    pub fn validated(self) -> Result<Self, ParamError> {
        let non_negative = |name: &str, x: f64| {
            if x.is_finite() && x >= 0.0 {
                Ok(())
            } else {
                Err(ParamError(format!(
                    "{name} must be a finite number >= 0, got {x}"
                )))
            }
        };
        non_negative("the added mass", self.added_mass)?;
        non_negative("the added inertia", self.added_inertia)?;
        non_negative("the drag coefficient", self.drag)?;
        if !(self.links.stiffness.is_finite() && self.links.stiffness > 0.0) {
            return Err(ParamError(format!(
                "the link stiffness must be a finite number > 0, got {}",
                self.links.stiffness
            )));
        }
        if let Some(f) = self.friction {
            non_negative("the pin friction mu_p r_p", f.mu_rp)?;
            if !(f.omega_eps.is_finite() && f.omega_eps > 0.0) {
                return Err(ParamError(format!(
                    "the friction's smoothing rate omega_eps must be > 0, got {}",
                    f.omega_eps
                )));
            }
        }
        Ok(self)
    }
}

/// The links' stiffness and whether they push.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Links {
    /// Stiffness κ in units of the model's k (1: the paper's springs).
    pub stiffness: f64,
    /// Tape or ribbon: pulls when stretched, pushes nothing when slack.
    pub tension_only: bool,
}

impl Default for Links {
    fn default() -> Self {
        Self {
            stiffness: 1.0,
            tension_only: false,
        }
    }
}

/// Coulomb friction at the pins, smoothed: torque μ_p r_p |T| tanh(ω/ω_ε).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PinFriction {
    /// μ_p r_p: friction coefficient times pin radius, in s.
    pub mu_rp: f64,
    /// Smoothing rate ω_ε, in 1/τ.
    pub omega_eps: f64,
}
