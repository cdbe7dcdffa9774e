//! The parameter table as a scene sees it ([`crate::model::table`]: one
//! declaration per parameter, with its name, symbol, unit, default,
//! range, meaning and kind): each parameter's value in a scene, read and
//! set by the table's name, and the list of every declaration for the
//! front ends (the command line's flags, Python's keywords and docs).
//!
//! ```
//! use jacobs_ladder::scene::params::{Kind, Param};
//! for p in Param::ALL {
//!     let s = p.spec();
//!     let _ = (s.name, s.symbol, s.unit, s.default, s.range.min(), s.range.max(), s.doc);
//! }
//! assert_eq!(Param::N.spec().kind, Kind::Int);
//! ```

pub use crate::model::table::{COUNT, Kind, MODEL_COUNT, Param, Place, Range, Spec};

use super::{DriveSpec, Scene};
use serde::Serialize;

/// One parameter as the front ends read it (Python's keywords, `.pyi`
/// and docstrings; `ParamInfo::all` in the table's order): every field
/// from the table, nothing typed twice.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ParamInfo {
    /// The key, keyword, sweep axis and CSV column: `alpha`.
    pub name: &'static str,
    /// The command-line flag: `--alpha`, `--drive-time`.
    pub flag: String,
    /// α, N, b/s, γ, G, I, T_d.
    pub symbol: &'static str,
    /// °, s, m s², τ, or "" for a pure number.
    pub unit: &'static str,
    /// The chart axis's label: "α (°)".
    pub label: &'static str,
    /// What it is, in a sentence (help texts, docstrings).
    pub doc: &'static str,
    /// The paper's value.
    pub default: f64,
    /// The least and largest values accepted (±∞ where unbounded; the
    /// least is exclusive where `range` says "> x").
    pub min: f64,
    pub max: f64,
    /// The range in words, as messages and help texts give it ("from
    /// 1e-3 to 1e3"; α's for a simulation, "0 < |alpha| < 90").
    pub range: String,
    /// "int" or "float".
    pub kind: &'static str,
    /// "model" (`[model]`) or "drive" (`[drive]`, the drive time).
    pub place: &'static str,
}

impl ParamInfo {
    pub fn of(p: Param) -> Self {
        let s = p.spec();
        Self {
            name: s.name,
            flag: p.flag(),
            symbol: s.symbol,
            unit: s.unit,
            label: s.label,
            doc: s.doc,
            default: s.default,
            min: s.range.min(),
            max: s.range.max(),
            range: s.range_text(true),
            kind: s.kind.name(),
            place: match s.place {
                Place::Model => "model",
                Place::Drive => "drive",
            },
        }
    }

    /// Every parameter, in the table's order (`Param::ALL`).
    pub fn all() -> Vec<Self> {
        Param::ALL.into_iter().map(Self::of).collect()
    }
}

impl Scene {
    /// Parameter `p`'s value in this scene: the model's, or the drive
    /// time of the first flip of block 1 (the paper's T_d where there is
    /// none).
    pub fn param(&self, p: Param) -> f64 {
        match p.spec().place {
            Place::Model => self.model.get(p).expect("a model parameter"),
            Place::Drive => self
                .drive
                .flips
                .first()
                .map_or(p.default_value(), |f| f.duration),
        }
    }

    /// Sets parameter `p` to `x` (N must be a whole number, checked by
    /// the sweep's [`super::sweep::Values::expand`] and `Scene::check`).
    /// The drive time sets the duration of every flip, keeping each
    /// flip's start.
    pub fn set_param(&mut self, p: Param, x: f64) {
        match p.spec().place {
            Place::Model => self.model.set(p, x),
            Place::Drive => {
                let starts: Vec<f64> = self.drive.flips.iter().map(|f| f.start).collect();
                self.drive = DriveSpec::flips_at(&starts, x);
            }
        }
    }
}

impl Param {
    /// The parameter's value in `scene` ([`Scene::param`]).
    pub fn get(self, scene: &Scene) -> f64 {
        scene.param(self)
    }

    /// Sets it in `scene` ([`Scene::set_param`]).
    pub fn set(self, scene: &mut Scene, x: f64) {
        scene.set_param(self, x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_scene_reads_and_sets_every_parameter() {
        let mut s = Scene::default();
        for p in Param::ALL {
            assert_eq!(s.param(p), p.default_value(), "{p}");
            s.set_param(p, 7.0);
            assert_eq!(s.param(p), 7.0, "{p}");
        }
    }
}
