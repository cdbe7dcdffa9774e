//! A sweep: one scene run over a grid of parameters (docs/sweeps.md), as
//! data. `[output] kind = "sweep"` names the grid in `[output.grid]`, one
//! key per varied parameter, in the order the file gives them (the first
//! varies slowest), each a range `"start:stop:step"` (inclusive), a list
//! of numbers, or a list mixing both:
//!
//! ```toml
//! [output]
//! kind = "sweep"
//! [output.grid]
//! alpha = ["40:89.5:0.5", "-40:-89.5:-0.5"]
//! gamma = [0.01, 0.02, 0.04]
//! ```
//!
//! Running it is `crate::sweep`'s job; this module parses and checks.

use super::{Model, Scene};
use serde::de::{self, MapAccess, Visitor};
use serde::ser::SerializeMap;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;

mod values;
pub use values::{MAX_AXIS_VALUES, Piece, Values, range_values};

/// A parameter a sweep can vary: every parameter of the table
/// ([`crate::model::table`]), its key in `[output.grid]` its name.
pub use crate::scene::params::Param;

/// The axes of a grid, in order: the first varies slowest. Keys that name
/// no parameter are kept aside (second field) for [`SweepSpec::check`] to
/// report with their place in the file (the TOML parser cannot locate an
/// error inside an `[output]` table).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Grid(pub Vec<(Param, Values)>, pub Vec<String>);

impl Grid {
    pub fn new(axes: Vec<(Param, Values)>) -> Self {
        Self(axes, Vec::new())
    }
}

impl Serialize for Grid {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (p, v) in &self.0 {
            map.serialize_entry(p.name(), v)?;
        }
        map.end()
    }
}

impl<'de> Deserialize<'de> for Grid {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct G;
        impl<'de> Visitor<'de> for G {
            type Value = Grid;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                let names: Vec<&str> = Param::ALL.iter().map(|p| p.name()).collect();
                write!(
                    f,
                    "a table of parameters ({}) and their values",
                    names.join(", ")
                )
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Grid, A::Error> {
                let mut grid = Grid::default();
                while let Some(key) = map.next_key::<String>()? {
                    match Param::from_name(&key) {
                        Some(param) => {
                            let values: Values = map.next_value()?;
                            grid.0.push((param, values));
                        }
                        None => {
                            map.next_value::<de::IgnoredAny>()?;
                            grid.1.push(key);
                        }
                    }
                }
                Ok(grid)
            }
        }
        d.deserialize_map(G)
    }
}

/// Which charts a sweep draws beside its results.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SweepCharts {
    /// With α on the horizontal axis, a panel of the linear-theory
    /// quantities the paper uses to explain pinning (the gap ω₊(0) and
    /// the barrier ΔU) on the same axis. Default true.
    pub theory: bool,
    /// A 1-D sweep over α of both signs plotted against |α|, kinks and
    /// antikinks as two series. Default true.
    pub fold_alpha: bool,
}

impl Default for SweepCharts {
    fn default() -> Self {
        Self {
            theory: true,
            fold_alpha: true,
        }
    }
}

/// A sweep (`[output] kind = "sweep"`): the grid, the rule that decides
/// each run's outcome, and the charts.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepSpec {
    /// The varied parameters and their values; every other parameter is
    /// the scene's.
    pub grid: Grid,
    /// Removed: the quiet-time rule no longer decides outcomes (the state
    /// does, docs/sweeps.md). Still read, so that an old file gets a clear
    /// error rather than an unknown key.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub quiet: Option<f64>,
    /// The latest time a run may reach while its outcome is undecided, τ.
    /// Default 100 000 (25 times the paper's 4000 τ).
    #[serde(default = "default_cap")]
    pub cap: f64,
    /// Charts drawn from the results.
    #[serde(default)]
    pub charts: SweepCharts,
}

fn default_cap() -> f64 {
    100_000.0
}

impl Default for SweepSpec {
    fn default() -> Self {
        Self {
            grid: Grid::default(),
            quiet: None,
            cap: default_cap(),
            charts: SweepCharts::default(),
        }
    }
}

/// The error for the removed `quiet` key (and `--quiet`).
pub const QUIET_REMOVED: &str = "the quiet-time rule is removed: a run is called pinned or \
     stalled only when its state is proved at rest at a stable equilibrium (docs/sweeps.md); \
     delete this key (raise `cap` to look longer)";

/// Largest cap on a run's time, τ.
pub const MAX_CAP: f64 = 1e8;
/// Default largest number of runs of one sweep.
pub const DEFAULT_MAX_RUNS: usize = 100_000;

/// An axis with its values.
pub type Axis = (Param, Vec<f64>);

/// One point of the grid: a value of each axis, in the axes' order.
pub type Point = Vec<f64>;

impl SweepSpec {
    /// Each axis with its values.
    pub fn axes(&self) -> Result<Vec<Axis>, (String, String)> {
        let mut seen = Vec::new();
        self.grid
            .0
            .iter()
            .map(|(p, v)| {
                let key = format!("output.grid.{}", p.name());
                if seen.contains(p) {
                    return Err((key, "is given twice".to_string()));
                }
                seen.push(*p);
                v.expand(*p).map(|vals| (*p, vals)).map_err(|m| (key, m))
            })
            .collect()
    }

    /// Number of runs: the product of the axes' lengths (saturating).
    pub fn run_count(&self) -> Result<usize, (String, String)> {
        Ok(self
            .axes()?
            .iter()
            .fold(1usize, |n, (_, v)| n.saturating_mul(v.len())))
    }

    /// The points of the grid in order (the last axis varies fastest).
    pub fn points(&self) -> Result<Vec<Point>, (String, String)> {
        let axes = self.axes()?;
        let count = axes
            .iter()
            .fold(1usize, |n, (_, v)| n.saturating_mul(v.len()));
        Ok((0..count)
            .map(|mut i| {
                let mut p = vec![0.0; axes.len()];
                for (k, (_, vals)) in axes.iter().enumerate().rev() {
                    p[k] = vals[i % vals.len()];
                    i /= vals.len();
                }
                p
            })
            .collect())
    }

    /// The single-run scene of `point` on `base`.
    pub fn scene_at(&self, base: &Scene, point: &[f64]) -> Scene {
        let mut s = base.clone();
        for ((p, _), v) in self.grid.0.iter().zip(point) {
            s.set_param(*p, *v);
        }
        s.output = super::OutputSpec::Data;
        s.label = None;
        s.title = None;
        s.caption = None;
        // An apparatus's values for this point's model (what it runs).
        s.with_conversion()
    }

    /// Checks the grid and the rule; every point of the grid must make a
    /// valid simulation (`check_point` checks one). `Err((key, message))`.
    pub fn check(
        &self,
        check_point: impl Fn(&Scene) -> Result<(), (String, String)>,
        base: &Scene,
    ) -> Result<(), (String, String)> {
        if let Some(key) = self.grid.1.first() {
            return Err((
                format!("output.grid.{key}"),
                format!(
                    "unknown parameter '{key}'; a sweep varies {}",
                    Param::names()
                ),
            ));
        }
        if self.grid.0.is_empty() {
            return Err((
                "output.grid".into(),
                format!(
                    "a sweep needs at least one parameter to vary: {}",
                    Param::names()
                ),
            ));
        }
        if self.quiet.is_some() {
            return Err(("output.quiet".into(), QUIET_REMOVED.into()));
        }
        if !(self.cap.is_finite() && self.cap >= base.run.t_end && self.cap <= MAX_CAP) {
            return Err((
                "output.cap".into(),
                format!(
                    "must be a time from t_end = {} to {MAX_CAP} τ, got {}",
                    base.run.t_end, self.cap
                ),
            ));
        }
        let axes = self.axes()?;
        if let Some(a) = &base.apparatus {
            for (param, _) in &axes {
                let why = match *param {
                    Param::DriveTime if a.motor.is_some() => Some(
                        "the apparatus' motor sets block 1's drive time; leave `motor` out to \
                         sweep it"
                            .to_string(),
                    ),
                    p => a.replaces(p),
                };
                if let Some(why) = why {
                    return Err((format!("output.grid.{}", param.name()), why));
                }
            }
        }
        // Each axis's values one at a time on the base: the model's ranges
        // are per parameter, so this checks every point, and names the axis.
        for (param, vals) in &axes {
            let key = format!("output.grid.{}", param.name());
            for v in vals {
                let mut s = base.clone();
                s.set_param(*param, *v);
                s.output = super::OutputSpec::Data;
                check_point(&s).map_err(|(_, msg)| {
                    (
                        key.clone(),
                        format!("the value {v} makes a bad scene: {msg}"),
                    )
                })?;
                if s.model.n < MIN_SWEEP_BLOCKS {
                    return Err((
                        key.clone(),
                        format!(
                            "a sweep needs N >= {MIN_SWEEP_BLOCKS} (so that reaching block N - 1 and passing block 2 differ), got {}",
                            s.model.n
                        ),
                    ));
                }
            }
        }
        Ok(())
    }
}

impl SweepSpec {
    /// "α = 40:89.5:0.5, −40:−89.5:−0.5; γ = 0.01, 0.02".
    pub fn describe_grid(&self) -> String {
        let axes: Vec<String> = self
            .grid
            .0
            .iter()
            .map(|(p, v)| {
                let pieces: Vec<String> =
                    v.0.iter()
                        .map(|piece| match piece {
                            Piece::Range { text } => text.replace('-', "−"),
                            Piece::Value(x) => crate::numfmt::typeset(*x),
                        })
                        .collect();
                format!("{} = {}", p.symbol(), pieces.join(", "))
            })
            .collect();
        axes.join("; ")
    }

    /// A title made from the grid: "outcome against α, N = 10" or
    /// "phase diagram over α and γ".
    pub fn title(&self, m: &Model) -> String {
        let varied: Vec<&'static str> = self
            .axes()
            .map(|a| {
                a.iter()
                    .filter(|(_, v)| v.len() > 1)
                    .map(|(p, _)| p.symbol())
                    .collect()
            })
            .unwrap_or_default();
        let fixed = if self.grid.0.iter().any(|(p, _)| *p == Param::N) {
            format!("b/s = {}", crate::numfmt::typeset(m.b))
        } else {
            format!("N = {}, b/s = {}", m.n, crate::numfmt::typeset(m.b))
        };
        match varied.len() {
            0 | 1 => format!(
                "what the wave does against {}, {fixed}",
                varied.first().copied().unwrap_or("nothing")
            ),
            2 => format!(
                "phase diagram over {} and {}, {fixed}",
                varied[0], varied[1]
            ),
            _ => format!("sweep over {}, {fixed}", varied.join(", ")),
        }
    }
}

/// Fewest blocks of a swept ladder: with N ≥ 4, "the wave reached block
/// N − 1" (propagated) and "no block past block 2 flipped" (pinned) are
/// different events.
pub const MIN_SWEEP_BLOCKS: usize = 4;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_are_inclusive_and_rounded() {
        assert_eq!(
            range_values("-45:-47:-0.5").unwrap(),
            vec![-45.0, -45.5, -46.0, -46.5, -47.0]
        );
        assert_eq!(
            range_values("0.01:0.05:0.01").unwrap(),
            vec![0.01, 0.02, 0.03, 0.04, 0.05]
        );
        assert_eq!(range_values("1:2:0.3").unwrap(), vec![1.0, 1.3, 1.6, 1.9]);
        assert_eq!(range_values("5:5:1").unwrap(), vec![5.0]);
        assert_eq!(
            range_values("1e-4:3e-4:1e-4").unwrap(),
            vec![1e-4, 2e-4, 3e-4]
        );
    }

    #[test]
    fn malformed_ranges_say_why() {
        assert!(range_values("1:2:0").unwrap_err().contains("must not be 0"));
        assert!(
            range_values("1:2:-1")
                .unwrap_err()
                .contains("never reaches")
        );
        assert!(
            range_values("1:NaN:1")
                .unwrap_err()
                .contains("not a finite number")
        );
        assert!(range_values("1:2").unwrap_err().contains("three numbers"));
        assert!(
            range_values("0:1e9:1e-3")
                .unwrap_err()
                .contains("more than")
        );
    }

    #[test]
    fn lists_mix_numbers_and_ranges() {
        let v = Values::parse("40:42:1,-40:-42:-1,7").unwrap();
        assert_eq!(
            v.expand(Param::Alpha).unwrap(),
            vec![40.0, 41.0, 42.0, -40.0, -41.0, -42.0, 7.0]
        );
        assert!(Values::parse("1,x").is_err());
        assert!(Values::parse("1,nan").is_err());
        assert!(Values::parse("10.5").unwrap().expand(Param::N).is_err());
    }

    #[test]
    fn points_run_the_last_axis_fastest() {
        let spec = SweepSpec {
            grid: Grid::new(vec![
                (Param::Alpha, Values::parse("1,2").unwrap()),
                (Param::Gamma, Values::parse("0.1,0.2,0.3").unwrap()),
            ]),
            ..SweepSpec::default()
        };
        let p = spec.points().unwrap();
        assert_eq!(p.len(), 6);
        assert_eq!(p[0], vec![1.0, 0.1]);
        assert_eq!(p[1], vec![1.0, 0.2]);
        assert_eq!(p[3], vec![2.0, 0.1]);
    }
}
