//! The apparatus in the model's units (s = m = k = 1, τ = √(m/k)): the
//! unit physics of the module's doc, and the terms it switches on.

use super::*;
use crate::model::links::{Links, PinFriction};
use crate::model::media::Terms;

/// The apparatus in the model's units, and the units themselves.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Conversion {
    /// Block mass (g), and the unit of time τ = √(m/k) (s).
    pub mass_g: f64,
    pub tau_s: f64,
    /// The links' stiffness k (N/m).
    pub stiffness_n_per_m: f64,
    /// Gravity acting (cm/s²): g* with buoyancy.
    pub gravity_cm_s2: f64,
    /// Model parameters: b (s), α (degrees, where `a` sets it), G, γ, I.
    pub b: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub alpha: Option<f64>,
    pub gravity: f64,
    pub gamma: f64,
    pub inertia: f64,
    /// Terms: m_a (m), I_a (m s²), c (model units), μ_p r_p (s), ω_ε (1/τ).
    pub added_mass: f64,
    pub added_inertia: f64,
    pub drag: f64,
    pub pin_friction_mu_rp: f64,
    pub friction_rate: f64,
    /// Drive time of the motor (τ) and the run's end (τ), where given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub drive_time: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub t_end: Option<f64>,
    /// One block per τ in cm/s (b/τ): speeds in blocks/τ times this.
    pub cm_per_s: f64,
}

impl Apparatus {
    pub(super) fn density_g_cm3(&self) -> f64 {
        self.density
            .unwrap_or_else(|| self.mass_g() / (self.s * self.span_cm() * self.thickness))
    }

    pub(super) fn span_cm(&self) -> f64 {
        self.span.unwrap_or(self.s)
    }

    pub(super) fn mass_g(&self) -> f64 {
        self.mass.unwrap_or_else(|| {
            self.density.unwrap_or(0.0) * self.s * self.span_cm() * self.thickness
        })
    }

    /// ρ_m (g/cm³).
    pub fn medium_density(&self) -> f64 {
        self.medium_density.unwrap_or(self.medium.density())
    }

    /// The gravity acting: g* = (1 − ρ_m/ρ) g with buoyancy, else g.
    pub fn gravity_acting(&self) -> f64 {
        if self.buoyancy {
            (1.0 - self.medium_density() / self.density_g_cm3()) * self.g
        } else {
            self.g
        }
    }

    /// k in dyn/cm (g/s²).
    pub(super) fn stiffness_cgs(&self) -> f64 {
        match self.stiffness {
            Stiffness::NewtonPerMetre(k) => 1e3 * k,
            Stiffness::Word(_) => {
                self.mass_g() * self.gravity_acting() / (self.s * self.stiff_gravity)
            }
        }
    }

    /// G = m g*/(k s).
    pub(super) fn model_gravity(&self) -> f64 {
        self.mass_g() * self.gravity_acting() / (self.stiffness_cgs() * self.s)
    }

    /// The conversion, for `[model] alpha` (degrees) where `a` is not given.
    pub fn convert(&self, alpha_deg: f64) -> Conversion {
        let m = self.mass_g();
        let k = self.stiffness_cgs();
        let tau = (m / k).sqrt();
        let gravity = self.model_gravity();
        let (s, h, rho_m) = (self.s, self.span_cm(), self.medium_density());
        let gamma = match self.damping {
            None => 0.0,
            Some(Damping::Word(_)) => PAPER_GAMMA_PER_ROOT_G * gravity.sqrt(),
            Some(Damping::PerSecond(r)) => r * tau,
        };
        let d = self.thickness;
        let inertia = (1.0 + (d / s).powi(2)) / 12.0;
        let r = 0.5 * s;
        let f = self.added_mass_factor;
        let (added_mass, added_inertia) = if self.added_mass {
            let ma = f * rho_m * std::f64::consts::PI * r * r * h;
            let ia = f * rho_m * std::f64::consts::PI * r.powi(4) * h / 8.0;
            (ma / m, ia / (m * s * s))
        } else {
            (0.0, 0.0)
        };
        let drag = if self.drag {
            0.5 * rho_m * self.drag_coefficient * h * s * s / m
        } else {
            0.0
        };
        let alpha = self.a.map(|a| {
            let c = ((a * a - self.b * self.b).sqrt() / (2.0 * s)).clamp(-1.0, 1.0);
            c.acos()
                .to_degrees()
                .copysign(if alpha_deg < 0.0 { -1.0 } else { 1.0 })
        });
        let alpha_used = alpha.unwrap_or(alpha_deg).to_radians();
        let drive_time = self
            .motor
            .map(|hz| 2.0 * alpha_used.abs() / (std::f64::consts::TAU * hz) / tau);
        Conversion {
            mass_g: m,
            tau_s: tau,
            stiffness_n_per_m: k * 1e-3,
            gravity_cm_s2: self.gravity_acting(),
            b: self.b / s,
            alpha,
            gravity,
            gamma,
            inertia,
            added_mass,
            added_inertia,
            drag,
            pin_friction_mu_rp: self.pin_friction * self.pin_radius / s,
            friction_rate: self.friction_rate * tau,
            drive_time,
            t_end: self.duration.map(|t| t / tau),
            cm_per_s: self.b / tau,
        }
    }

    /// This apparatus with its conversion for `[model] alpha` filled in
    /// (what data files record).
    pub fn converted(&self, alpha_deg: f64) -> Self {
        Self {
            conversion: Some(self.convert(alpha_deg)),
            ..self.clone()
        }
    }

    /// The model's terms (`model::media`).
    pub fn terms(&self, c: &Conversion) -> Terms {
        Terms {
            added_mass: c.added_mass,
            added_inertia: c.added_inertia,
            drag: c.drag,
            links: Links {
                stiffness: 1.0,
                tension_only: self.tension_only,
            },
            friction: (self.pin_friction > 0.0).then_some(PinFriction {
                mu_rp: c.pin_friction_mu_rp,
                omega_eps: c.friction_rate,
            }),
        }
    }
}
