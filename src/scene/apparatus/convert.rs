//! The apparatus in the model's units (s = m = k = 1, τ = √(m/k)): the
//! unit physics of the module's doc, and the terms it switches on.

use super::*;
use crate::model::built::AsBuilt;
use crate::model::contact::Contact;
use crate::model::links::{Links, PinFriction};
use crate::model::media::Terms;
use crate::model::outline::Outline;
use crate::model::ribbons::{Anchor, Ribbons};

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
        // Ribbons hang the blocks in a column: α = ±90°.
        let alpha = if self.ribbons {
            Some(90.0_f64.copysign(alpha_deg))
        } else {
            alpha
        };
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

    /// The toy as built (`model::built`), where the apparatus has ribbons:
    /// ribbon 1 on the face w = +h (edge 2) glued at fraction x₁ of s from
    /// the A end, ribbon 2 on the face w = −h (edge 0) at x₂, each the same
    /// on both blocks of a junction (the faces swapped when mirrored),
    /// glued taut in the hanging column at pitch b; contact with the
    /// material's e and μ.
    pub fn built(&self, c: &Conversion) -> Option<AsBuilt> {
        if !self.ribbons {
            return None;
        }
        let [x1, x2] = self.ribbon_anchors.unwrap_or([0.0, 1.0]);
        // Face w = +h runs c₂ → c₃ (from the B end), w = −h c₀ → c₁.
        let plus = |x: f64| face_anchor(2, 1.0 - x);
        let minus = |x: f64| face_anchor(0, x);
        let (a1, a2) = if self.ribbon_mirror {
            (minus(x1), plus(x2))
        } else {
            (plus(x1), minus(x2))
        };
        let outline = Outline::new(self.thickness / self.s);
        let mut ribbons = Ribbons::glued_in_column(outline, [(a1, a1), (a2, a2)], c.b);
        if self.stiffness == Stiffness::Word(StiffWord::Inextensible) {
            ribbons = ribbons.inextensible();
        }
        let contact = self.contact.map(|m| {
            let (restitution, friction) = m.coefficients();
            Contact {
                stiffness: self.contact_stiffness.unwrap_or(CONTACT_STIFFNESS),
                restitution,
                friction,
                slip_speed: SLIP_SPEED,
            }
        });
        Some(AsBuilt { ribbons, contact })
    }
}

impl Apparatus {
    /// The ribbons that break the kink–antikink symmetry (docs/experiments.md,
    /// "The toy as built"): the map between the two waves (every block
    /// turned over, y mirrored) takes a ribbon glued at x on a face to
    /// 1 − x on the same face; a ribbon whose image is not a ribbon of the
    /// arrangement is named, with its anchor. Empty without ribbons.
    pub fn symmetry_breakers(&self) -> Vec<String> {
        if !self.ribbons {
            return Vec::new();
        }
        let [x1, x2] = self.ribbon_anchors.unwrap_or([0.0, 1.0]);
        let faces = if self.ribbon_mirror {
            ["-h", "+h"]
        } else {
            ["+h", "-h"]
        };
        let ribbons = [(faces[0], x1), (faces[1], x2)];
        ribbons
            .iter()
            .enumerate()
            .filter(|(_, (face, x))| {
                !ribbons
                    .iter()
                    .any(|(f, y)| f == face && (y - (1.0 - x)).abs() < 1e-12)
            })
            .map(|(k, (face, x))| {
                format!(
                    "ribbon {} (glued at {x} s from the A end of face {face}, wrapping round the \
                     block's {} end) maps to {} s, where no ribbon is glued",
                    k + 1,
                    if *x < 0.5 { "B" } else { "A" },
                    1.0 - x
                )
            })
            .collect()
    }
}

/// The anchor at fraction f along edge k, at the next corner where f = 1.
fn face_anchor(k: usize, f: f64) -> Anchor {
    if f >= 1.0 {
        Anchor {
            edge: (k + 1) % 4,
            along: 0.0,
        }
    } else {
        Anchor { edge: k, along: f }
    }
}
