//! `[output]`: what a scene renders, its panels, its camera, and the
//! figures of the linear theory.

use super::model::{ModelPatch, is_default_patch};
use super::{Fidelity, sweep};
use serde::{Deserialize, Serialize};

/// What a scene renders (`[output]`; `kind` picks the variant).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum OutputSpec {
    /// A GIF of the ladder beside its live kymograph, plus the kymograph
    /// PNG (`movie-NAME.gif`, `movie-NAME-kymograph.png`).
    Movie {
        /// `auto` (default: `fixed` when the whole ladder fits the frame
        /// with blocks large enough to see, otherwise the ladder folded
        /// into columns side by side, every block in the frame), `fixed`
        /// (one window that fits every frame) or `follow` (a window that
        /// moves with the kink, movie 3).
        #[serde(default)]
        camera: Camera,
    },
    /// Snapshots at given times, one strip per panel (`figure-NAME.png`).
    Filmstrip {
        /// Times of the snapshots, in τ, within [0, t_end]. Used by
        /// panels that give none. Default: seven times evenly over the
        /// window.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        times: Vec<f64>,
        /// Strips, each a variant of the scene. Default: one strip of the
        /// scene itself.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        panels: Vec<Panel>,
    },
    /// The kymograph of sin θ_n alone (`figure-NAME.png`).
    Kymograph,
    /// Arrival time t_n against n, one curve per variant
    /// (`figure-NAME.png`), with the fitted speeds.
    Arrivals {
        /// Curves. Default: one curve of the scene itself.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        curves: Vec<Panel>,
    },
    /// The energies of the run against t/τ (`figure-NAME.png`): kinetic,
    /// elastic, gravitational, the energy dissipated so far, and their
    /// total with and without the dissipated energy.
    Energy,
    /// No picture: the run's numbers only (`data-NAME.json`).
    Data,
    /// A figure of the linear theory or a drawing (`figure-NAME.png`).
    Theory(TheorySpec),
    /// The scene run over a grid of parameters, each run's outcome
    /// decided, charted (`figure-NAME.png`) and tabulated
    /// (`figure-NAME.csv`); `ladder sweep` writes `sweep-NAME.*`
    /// (docs/sweeps.md, `sweep::SweepSpec`).
    Sweep(sweep::SweepSpec),
    /// A figure of the experiments (docs/experiments.md) from the scene's
    /// `[apparatus]` (`figure-NAME.png`, `scenes::experiments`).
    Experiment(super::apparatus::ExperimentSpec),
}

impl Default for OutputSpec {
    fn default() -> Self {
        Self::Movie {
            camera: Camera::Auto,
        }
    }
}

/// A movie's camera.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Camera {
    /// Fixed when the whole ladder fits with blocks of at least
    /// [`MIN_BLOCK_PIXELS`], otherwise the ladder folded into columns side
    /// by side, like lines of text (`render::fold`).
    #[default]
    Auto,
    /// One window that fits every frame.
    Fixed,
    /// A window that moves with the kink (movie 3).
    Follow,
}

/// A variant of the scene: one strip of a filmstrip or one curve of an
/// arrival chart.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Panel {
    /// Label before the strip's generated title ("(a1)"). Default none.
    #[serde(skip_serializing_if = "String::is_empty")]
    pub label: String,
    /// Model fields that differ from the scene's `[model]`.
    #[serde(skip_serializing_if = "is_default_patch")]
    pub model: ModelPatch,
    /// End of this variant's window, in τ. Default: the scene's t_end.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub t_end: Option<f64>,
    /// Snapshot times of this strip. Default: the filmstrip's `times`.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub times: Vec<f64>,
}

/// The figures of the linear theory and the drawings (README.md).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum TheoryFigure {
    /// Fig. 2b: one unit, drawn.
    UnitSchematic,
    /// Fig. 2c: U(θ) for several a/b.
    GravityPotential,
    /// Fig. 2d: the ground states ±α.
    GroundStates,
    /// Fig. S3: α = 0.
    Gapless,
    /// Fig. S4: zero-mode shapes.
    ZeroModes,
    /// Fig. S5: ω±(q).
    Dispersion,
    /// det C(q) over the Brillouin zone.
    Winding,
    /// The surface zero mode.
    EdgeMode,
    /// ΔU(α).
    Barrier,
}

impl TheoryFigure {
    /// How much model the figure needs.
    pub fn fidelity(self) -> Fidelity {
        match self {
            Self::UnitSchematic | Self::GroundStates | Self::Gapless => Fidelity::Drawing,
            Self::GravityPotential | Self::Barrier | Self::ZeroModes => Fidelity::Formula,
            Self::Dispersion | Self::Winding | Self::EdgeMode => Fidelity::LinearTheory,
        }
    }
}

/// Parameters of a theory figure beyond the scene's `[model]` (which gives
/// N, b and α).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TheorySpec {
    /// Which figure.
    pub figure: TheoryFigure,
    /// Angles α of the dispersion curves (Fig. S5), in degrees.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub alphas: Vec<f64>,
    /// Ratios a/b of the U(θ) curves (Fig. 2c).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub a_over_b: Vec<f64>,
    /// Zero modes (Fig. S4): mode number m and amplitude ε₀ of each panel.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub modes: Vec<ZeroMode>,
}

/// One zero-mode panel of Fig. S4.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ZeroMode {
    /// Mode number m.
    pub m: usize,
    /// Amplitude ε₀.
    pub epsilon: f64,
}
