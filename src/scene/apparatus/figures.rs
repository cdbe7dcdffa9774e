//! The experiments' figures a scene may ask for (`[output] kind =
//! "experiment"`, docs/experiments.md).

use serde::{Deserialize, Serialize};

/// The experiments' figures (`[output] kind = "experiment"`,
/// `scenes::experiments`; docs/experiments.md).
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
