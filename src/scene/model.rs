//! `[model]`: the ladder's parameters (docs/model.md) and a panel's
//! patch of them.

use crate::error::Result;
use crate::model::Params;
use crate::sim::Start;
use serde::{Deserialize, Serialize};

/// The model's parameters (docs/model.md, `[model]` in a scene file).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Model {
    /// Equilibrium angle α in degrees; its sign picks the ground state
    /// (α > 0: kink, α < 0: antikink). Default 60.
    pub alpha: f64,
    /// Number of blocks N; block 1 is the driven top block. Default 10.
    pub n: usize,
    /// Rest length b of the B springs, in units of s. Default 1.3.
    pub b: f64,
    /// Damping γ: force −γẊ, torque −γr²θ̇. Default 0.02.
    pub gamma: f64,
    /// Gravity G = mg/(ks). Default 2e-4.
    pub gravity: f64,
    /// Moment of inertia I of a block, in m s². Default 0.25 (m s²/4).
    pub inertia: f64,
    /// How the run starts: `ground` (at rest in the ground state, springs
    /// at rest length) or `relaxed` (at rest hanging under gravity with
    /// block 1 clamped, `sim::relax`). Default `ground` (docs/model.md,
    /// "The hanging start", gives the measurement behind it).
    pub start: Start,
}

impl Default for Model {
    /// The paper's simulation values (supplement, "Details of numerical
    /// simulation").
    fn default() -> Self {
        Self {
            alpha: 60.0,
            n: 10,
            b: 1.3,
            gamma: 0.02,
            gravity: 2e-4,
            inertia: 0.25,
            start: Start::default(),
        }
    }
}

impl Model {
    /// Validated model parameters.
    pub fn params(&self) -> Result<Params> {
        Ok(Params::new(
            self.n,
            self.b,
            self.alpha,
            self.gamma,
            self.gravity,
            self.inertia,
        )?)
    }

    /// "kink" for α > 0, "antikink" for α < 0.
    pub fn wave(&self) -> &'static str {
        crate::sim::waves::WaveKind::launched(self.alpha).name()
    }
}

/// Overrides of some model fields (a filmstrip panel, a chart curve, a
/// sweep point). Missing fields keep the scene's value.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelPatch {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub alpha: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub n: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub b: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gamma: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gravity: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inertia: Option<f64>,
}

impl ModelPatch {
    pub fn apply(&self, m: &Model) -> Model {
        Model {
            alpha: self.alpha.unwrap_or(m.alpha),
            n: self.n.unwrap_or(m.n),
            b: self.b.unwrap_or(m.b),
            gamma: self.gamma.unwrap_or(m.gamma),
            gravity: self.gravity.unwrap_or(m.gravity),
            inertia: self.inertia.unwrap_or(m.inertia),
            start: m.start,
        }
    }
}

/// Whether a panel leaves the model as it is (its patch is empty).
pub(crate) fn is_default_patch(p: &ModelPatch) -> bool {
    *p == ModelPatch::default()
}
