//! A scene's apparatus in physical units (SPEC section 12, `[apparatus]`)
//! and its conversion to the model's units (s = m = k = 1, τ = √(m/k)).
//!
//! Units of the table: centimetres, grams, seconds (cgs); the link
//! stiffness in N/m. The conversion:
//!
//! - m = ρ s² d (or the `mass` given); I = m (s² + d²)/12, the plate
//!   turning about its centre in its own plane;
//! - g* = (1 − ρ_m/ρ) g with `buoyancy`, else g;
//! - "stiff" links: k = m g*/(s G_stiff), so that G = m g*/(k s) is
//!   `stiff_gravity` (2e-4, the paper's G: the links then stretch by
//!   about N G s under the chain's weight). A number k (N/m) gives
//!   G = m g*/(k s) instead. τ = √(m/k) in seconds; a speed of one block
//!   per τ is b/τ in cm/s;
//! - added mass (`added_mass`): m_a = f ρ_m π (s/2)² h and
//!   I_a = f ρ_m π (s/2)⁴ h / 8, the 2D strip values (potential flow)
//!   times the finite-plate factor f (0.579 for a square plate);
//! - quadratic drag (`drag`): c = ½ ρ_m C_D h, in the model's units
//!   c s²/m; C_D = 1.17 (square plate broadside);
//! - linear damping `damping`: "paper" (γ = 0.02 at G = 2e-4, i.e.
//!   γ = √2 m √(g*/s), so it keeps its meaning when k changes) or a rate
//!   γ/m in 1/s;
//! - pin friction: μ_p r_p / s, and ω_ε in 1/τ;
//! - the motor turns block 1 through its flip, 2|α|, at `motor` Hz:
//!   T_d = 2|α| / (2π f).
//!
//! docs/model.md and docs/experiments.md cite the coefficients.

use crate::error::{Error, Result};
use crate::model::Params;
use crate::model::links::{Links, PinFriction};
use crate::model::media::Terms;
use crate::sim::{Drive, Scenario};
use serde::{Deserialize, Serialize};

impl super::Scene {
    /// This scene with its apparatus' conversion made afresh for its
    /// `[model] alpha` (a conversion the scene carried is never trusted:
    /// a data file's, or one left from before a keyword changed the
    /// apparatus) and its `duration` (s) as the run's window in τ. The one
    /// step a scene file (`scene::file::parse`) and Python's keywords end
    /// with; a scene without an apparatus is returned as it is.
    pub fn with_conversion(mut self) -> Self {
        if let Some(a) = &self.apparatus {
            let a = a.converted(self.model.alpha);
            if let Some(t) = a.conversion.as_ref().and_then(|c| c.t_end) {
                self.run.t_end = t;
            }
            self.apparatus = Some(a);
        }
        self
    }
}

/// The medium the ladder moves in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Medium {
    Air,
    Water,
}

impl Medium {
    /// Density in g/cm³ (water at 20 °C; air at 20 °C, sea level).
    pub fn density(self) -> f64 {
        match self {
            Self::Air => 1.204e-3,
            Self::Water => 0.998,
        }
    }
}

/// "stiff" or a stiffness in N/m.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Stiffness {
    NewtonPerMetre(f64),
    Word(StiffWord),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum StiffWord {
    Stiff,
}

/// "paper" or a rate γ/m in 1/s.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Damping {
    PerSecond(f64),
    Word(PaperWord),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum PaperWord {
    Paper,
}

/// The finite-plate factor of a square plate's added mass (Brennen 1982,
/// rectangular plate of aspect ratio 1: 0.579 of the 2D strip value).
pub const SQUARE_PLATE_ADDED_MASS: f64 = 0.579;
/// C_D of a square flat plate broadside to the flow, Re ≳ 10³ (Hoerner,
/// Fluid-Dynamic Drag, 1965, ch. 3: 1.17).
pub const SQUARE_PLATE_CD: f64 = 1.17;
/// The paper's G, which "stiff" links are given (k = m g*/(s G)).
pub const STIFF_GRAVITY: f64 = 2e-4;
/// The paper's γ/√G, 0.02/√(2e-4) = √2: "paper" damping keeps it.
pub const PAPER_GAMMA_PER_ROOT_G: f64 = std::f64::consts::SQRT_2;

/// The experiments' figures (`[output] kind = "experiment"`,
/// `scenes::experiments`; SPEC section 12).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ExperimentFigure {
    /// Block positions (cm) against time (s) at the three motor speeds.
    TankPositions,
    /// c_kink and c_antikink / c_kink for each level of model.
    TankLevels,
    /// The linkage's kink and antikink fronts against pin friction μ_p.
    LinkageFriction,
}

impl ExperimentFigure {
    /// What the figure shows, for the gallery's description.
    pub fn describe(self) -> &'static str {
        match self {
            Self::TankPositions => {
                "Chart of each block's position down the chain (cm) against the time it \
                 flips (s), kink and antikink at the motor speeds 0.1, 0.2 and 0.4 Hz, \
                 with their speeds in cm/s"
            }
            Self::TankLevels => {
                "Two charts: the kink's speed (cm/s) and the antikink's speed over the \
                 kink's for each level of model, beside the measured 6.0 cm/s and 1.75"
            }
            Self::LinkageFriction => {
                "Chart of how many blocks the kink and the antikink flip against the pin \
                 friction coefficient"
            }
        }
    }
}

/// `[output] kind = "experiment"`: which figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ExperimentSpec {
    pub figure: ExperimentFigure,
}

/// `[apparatus]`: the ladder as built, in cm, g, s (N/m for k).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Apparatus {
    /// Block length s (cm).
    pub s: f64,
    /// Rest length b of the B links (cm).
    pub b: f64,
    /// Rest length a of the A links (cm); sets |α| from cos α =
    /// √(a² − b²)/(2s). Without it, α is `[model] alpha`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub a: Option<f64>,
    /// Block thickness d (cm).
    pub thickness: f64,
    /// Out-of-plane width h of the block (cm). Default s (square plate).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub span: Option<f64>,
    /// Block density (g/cm³), or its mass (g): one of the two.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub density: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass: Option<f64>,
    /// Gravity (cm/s²). Default 981.
    #[serde(default = "default_g")]
    pub g: f64,
    /// `air` or `water`.
    pub medium: Medium,
    /// The medium's density (g/cm³). Default: the medium's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub medium_density: Option<f64>,
    /// "stiff" or k in N/m. Default "stiff".
    #[serde(default = "stiff")]
    pub stiffness: Stiffness,
    /// G of "stiff" links. Default 2e-4.
    #[serde(default = "stiff_gravity")]
    pub stiff_gravity: f64,
    /// Tape or ribbon links: they pull, never push. Default false.
    #[serde(default)]
    pub tension_only: bool,
    /// Buoyancy: gravity (1 − ρ_m/ρ) m g. Default false.
    #[serde(default)]
    pub buoyancy: bool,
    /// Added mass and inertia of a flat plate. Default false.
    #[serde(default)]
    pub added_mass: bool,
    /// Finite-plate factor of the added mass. Default 0.579.
    #[serde(default = "square_added_mass")]
    pub added_mass_factor: f64,
    /// Quadratic drag by strip theory. Default false.
    #[serde(default)]
    pub drag: bool,
    /// C_D of the plate. Default 1.17.
    #[serde(default = "square_cd")]
    pub drag_coefficient: f64,
    /// Linear damping: "paper" or γ/m in 1/s. Default none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub damping: Option<Damping>,
    /// Pin friction coefficient μ_p. Default 0 (no friction).
    #[serde(default)]
    pub pin_friction: f64,
    /// Pin radius r_p (cm). Default 0.1.
    #[serde(default = "pin_radius")]
    pub pin_radius: f64,
    /// Friction's smoothing rate ω_ε (rad/s). Default 0.05.
    #[serde(default = "friction_rate")]
    pub friction_rate: f64,
    /// The motor turns block 1 through its flip at this rate (Hz).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub motor: Option<f64>,
    /// Length of the run (s); overrides `[run] t_end`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub duration: Option<f64>,
    /// What the program derived (written into data files; recomputed,
    /// never trusted, when a file gives it: `scene::file::parse`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub conversion: Option<Conversion>,
}

fn default_g() -> f64 {
    981.0
}
fn stiff() -> Stiffness {
    Stiffness::Word(StiffWord::Stiff)
}
fn stiff_gravity() -> f64 {
    STIFF_GRAVITY
}
fn square_added_mass() -> f64 {
    SQUARE_PLATE_ADDED_MASS
}
fn square_cd() -> f64 {
    SQUARE_PLATE_CD
}
fn pin_radius() -> f64 {
    0.1
}
fn friction_rate() -> f64 {
    0.05
}

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
    /// Checks every value: `Err((key, message))` names the first bad one
    /// (the file loader locates `apparatus.KEY`).
    pub fn check(&self) -> std::result::Result<(), (String, String)> {
        let bad = |k: &str, m: String| Err((k.to_string(), m));
        let positive = |k: &str, x: f64, what: &str| {
            if x.is_finite() && x > 0.0 {
                Ok(())
            } else {
                bad(k, format!("must be {what} > 0, got {x}"))
            }
        };
        positive("s", self.s, "a length in cm")?;
        positive("b", self.b, "a length in cm")?;
        positive("thickness", self.thickness, "a length in cm")?;
        if self.thickness >= self.s {
            return bad(
                "thickness",
                format!(
                    "must be less than s = {} cm (a plate), got {}",
                    self.s, self.thickness
                ),
            );
        }
        let b_over_s = self.b / self.s;
        if !(1e-3..=1e3).contains(&b_over_s) {
            return bad("b", format!("b/s must lie in [1e-3, 1e3], got {b_over_s}"));
        }
        if let Some(a) = self.a {
            positive("a", a, "a length in cm")?;
            let c2 = (a * a - self.b * self.b) / (4.0 * self.s * self.s);
            if !(c2 > 0.0 && c2 < 1.0) {
                return bad(
                    "a",
                    format!(
                        "needs b < a < sqrt(b² + 4 s²) = {:.4} cm for an angle 0 < |alpha| < 90; \
                         a = b is alpha = 90, where the flip is undefined: leave a out and set \
                         [model] alpha near 90 (the paper simulates 86), got {a}",
                        (self.b * self.b + 4.0 * self.s * self.s).sqrt()
                    ),
                );
            }
        }
        if let Some(h) = self.span {
            positive("span", h, "a length in cm")?;
        }
        match (self.density, self.mass) {
            (Some(_), Some(_)) => {
                return bad("mass", "give density or mass, not both".into());
            }
            (None, None) => {
                return bad(
                    "density",
                    "give the blocks' density (g/cm³) or mass (g)".into(),
                );
            }
            (Some(r), None) => positive("density", r, "a density in g/cm³")?,
            (None, Some(m)) => positive("mass", m, "a mass in g")?,
        }
        positive("g", self.g, "an acceleration in cm/s²")?;
        if let Some(r) = self.medium_density
            && !(r.is_finite() && r >= 0.0)
        {
            return bad(
                "medium_density",
                format!("must be a density >= 0 in g/cm³, got {r}"),
            );
        }
        if self.buoyancy && self.medium_density() >= self.density_g_cm3() {
            return bad(
                "buoyancy",
                format!(
                    "the blocks ({} g/cm³) would float in the medium ({} g/cm³): nothing pulls \
                     the ladder down",
                    self.density_g_cm3(),
                    self.medium_density()
                ),
            );
        }
        match self.stiffness {
            Stiffness::NewtonPerMetre(k) => positive("stiffness", k, "\"stiff\" or N/m")?,
            Stiffness::Word(_) => {}
        }
        if !(self.stiff_gravity.is_finite()
            && self.stiff_gravity > 0.0
            && self.stiff_gravity <= 1e-2)
        {
            return bad(
                "stiff_gravity",
                format!("must be a number in (0, 0.01], got {}", self.stiff_gravity),
            );
        }
        let g = self.model_gravity();
        if !(g > 0.0 && g <= 1.0) {
            return bad(
                "stiffness",
                format!("gives G = m g/(k s) = {g}; links must hold the weight: 0 < G <= 1"),
            );
        }
        if !(self.added_mass_factor.is_finite() && (0.0..=2.0).contains(&self.added_mass_factor)) {
            return bad(
                "added_mass_factor",
                format!("must be a number in [0, 2], got {}", self.added_mass_factor),
            );
        }
        if !(self.drag_coefficient.is_finite() && (0.0..=10.0).contains(&self.drag_coefficient)) {
            return bad(
                "drag_coefficient",
                format!("must be a number in [0, 10], got {}", self.drag_coefficient),
            );
        }
        if let Some(Damping::PerSecond(r)) = self.damping
            && !(r.is_finite() && r >= 0.0)
        {
            return bad(
                "damping",
                format!("must be \"paper\" or a rate >= 0 in 1/s, got {r}"),
            );
        }
        if !(self.pin_friction.is_finite() && (0.0..=10.0).contains(&self.pin_friction)) {
            return bad(
                "pin_friction",
                format!(
                    "must be a coefficient in [0, 10], got {}",
                    self.pin_friction
                ),
            );
        }
        positive("pin_radius", self.pin_radius, "a length in cm")?;
        if self.pin_radius >= 0.5 * self.s {
            return bad(
                "pin_radius",
                format!("must be less than s/2, got {}", self.pin_radius),
            );
        }
        positive("friction_rate", self.friction_rate, "a rate in rad/s")?;
        if let Some(f) = self.motor {
            positive("motor", f, "a rate in Hz")?;
        }
        if let Some(t) = self.duration {
            positive("duration", t, "a time in s")?;
        }
        Ok(())
    }

    fn density_g_cm3(&self) -> f64 {
        self.density
            .unwrap_or_else(|| self.mass_g() / (self.s * self.span_cm() * self.thickness))
    }

    fn span_cm(&self) -> f64 {
        self.span.unwrap_or(self.s)
    }

    fn mass_g(&self) -> f64 {
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
    fn stiffness_cgs(&self) -> f64 {
        match self.stiffness {
            Stiffness::NewtonPerMetre(k) => 1e3 * k,
            Stiffness::Word(_) => {
                self.mass_g() * self.gravity_acting() / (self.s * self.stiff_gravity)
            }
        }
    }

    /// G = m g*/(k s).
    fn model_gravity(&self) -> f64 {
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

    /// The simulation of `scene` with this apparatus: the model from the
    /// conversion (N, the sign of α and α itself unless `a` sets it from
    /// `[model]`), the motor's drive or the scene's, `duration` or
    /// `[run] t_end`.
    pub fn scenario(&self, scene: &super::Scene) -> Result<Scenario> {
        self.check()
            .map_err(|(k, m)| Error::bad_input(format!("apparatus.{k}: {m}")))?;
        let model = &scene.model;
        let c = self.convert(model.alpha);
        let alpha = c.alpha.unwrap_or(model.alpha);
        let params = Params::new(model.n, c.b, alpha, c.gamma, c.gravity, c.inertia)?;
        crate::sim::check_simulable(&params)?;
        let drive = match c.drive_time {
            Some(t_d) => Drive::single_flip(params.alpha, t_d)?,
            None => scene.drive.drive(params.alpha)?,
        };
        let t_end = match c.t_end {
            Some(t) => t,
            None if scene.run.t_end.is_finite() => scene.run.t_end,
            None => {
                return Err(Error::bad_input(
                    "apparatus: give duration (s) or [run] t_end for a scene with an apparatus",
                ));
            }
        };
        let mut sc = Scenario::with_drive(params, drive, t_end)?.started(model.start)?;
        let terms = self.terms(&c).validated()?;
        sc.ladder = sc.ladder.with_terms(terms);
        Ok(sc)
    }
}
