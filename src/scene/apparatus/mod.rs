//! A scene's apparatus in physical units (docs/experiments.md, `[apparatus]`)
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
//!
//! Files: this one holds the schema (`[apparatus]` and its words);
//! `check` the checks of every value; `convert` the unit physics (the
//! conversion to the model's units and the terms); `scenario` the run a
//! scene's apparatus makes; `figures` the experiments' figures.

mod check;
mod convert;
mod figures;
mod scenario;

pub use convert::Conversion;
pub use figures::{ExperimentFigure, ExperimentSpec};

use serde::de::Error as _;
use serde::{Deserialize, Serialize};

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

/// A block material's contact coefficients (docs/experiments.md cites
/// them): restitution e and Coulomb friction μ between two blocks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Material {
    Wood,
    Acrylic,
}

impl Material {
    /// (e, μ): wood on wood e = 0.5, μ = 0.3 (kinetic); acrylic on
    /// acrylic e = 0.6, μ = 0.5 (docs/experiments.md, "The toy as built").
    pub fn coefficients(self) -> (f64, f64) {
        match self {
            Self::Wood => (0.5, 0.3),
            Self::Acrylic => (0.6, 0.5),
        }
    }
}

/// The contact's default penalty stiffness, in the links' k per s.
pub const CONTACT_STIFFNESS: f64 = 1000.0;
/// The friction's slip speed v_ε, in s/τ.
pub const SLIP_SPEED: f64 = 1e-4;

/// "stiff", "inextensible" (ribbons only) or a stiffness in N/m.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Stiffness {
    NewtonPerMetre(f64),
    Word(StiffWord),
}

impl<'de> Deserialize<'de> for Stiffness {
    /// A number, or one of the words; anything else one line naming
    /// what the key takes (serde's untagged enums say only that no
    /// variant matched).
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Raw {
            Number(f64),
            Word(String),
        }
        let expected = "\"stiff\", \"inextensible\" (ribbons only) or a stiffness in N/m";
        let bad = |got: &str| D::Error::custom(format!("must be {expected}, got {got}"));
        match Raw::deserialize(d).map_err(|_| bad("another kind of value"))? {
            Raw::Number(k) => Ok(Self::NewtonPerMetre(k)),
            Raw::Word(w) if w == "stiff" => Ok(Self::Word(StiffWord::Stiff)),
            Raw::Word(w) if w == "inextensible" => Ok(Self::Word(StiffWord::Inextensible)),
            Raw::Word(w) => Err(bad(&format!("\"{w}\""))),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum StiffWord {
    /// k from the paper's G ([`STIFF_GRAVITY`]), checked stiff by a run
    /// with 2k.
    Stiff,
    /// Ribbons that never stretch: held at their length by impulses
    /// (Moreau's time-stepping, `sim::taut`); k then only sets τ, as
    /// "stiff" would.
    Inextensible,
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
    /// "stiff", "inextensible" (ribbons only: run by the `moreau`
    /// integrator) or k in N/m. Default "stiff".
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
    /// Ribbons glued to the blocks' faces and wrapped round their ends in
    /// place of the links (docs/experiments.md, "The toy as built"); the
    /// run hangs the blocks in a column (α = ±90°, the sign of `[model]
    /// alpha`). Default false.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub ribbons: bool,
    /// Where ribbons 1 and 2 are glued, as fractions of s along their
    /// faces from the block's A end (its top in the hanging column):
    /// ribbon 1 on one face, ribbon 2 on the other. Default [0, 1]: at the
    /// two ends, where the paper's links join the nodes.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ribbon_anchors: Option<[f64; 2]>,
    /// The mirror arrangement: each ribbon on the other face. Default false.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub ribbon_mirror: bool,
    /// Contact between the blocks, with the restitution and friction of
    /// a material: "wood" or "acrylic" (docs/experiments.md). Default none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact: Option<Material>,
    /// The contact's penalty stiffness, in units of the links' k per s
    /// of overlap. Default 1000.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_stiffness: Option<f64>,
    /// The motor turns block 1 through its flip at this rate (Hz); it
    /// overrides a scene file's `[drive]`, and yields to a drive given
    /// where the scene is made (`--drive-time`, Python's `drive_time`:
    /// `Scene::with_drive`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub motor: Option<f64>,
    /// Length of the run (s); overrides a scene file's `[run] t_end`, and
    /// yields to a window given where the scene is made (`--t-end`,
    /// Python's `t_end`, a panel's: `Scene::with_t_end`).
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
