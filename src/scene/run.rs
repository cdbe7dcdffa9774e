//! `[run]`: the time window and the integrator (docs/scenes.md).

use crate::error::{Error, Result};
use crate::sim::{IntegratorConfig, IntegratorKind};
use serde::{Deserialize, Serialize};
use std::fmt;

/// Which integrator a run uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// Chosen by the program and verified (docs/scenes.md): velocity Verlet
    /// at a step below the stability bound, checked against a run at half
    /// the step and tightened until every arrival time is within the
    /// scene's tolerance.
    #[default]
    Auto,
    /// One of the named schemes, at the scene's `dt` (or `rtol`).
    Fixed(IntegratorKind),
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Auto => f.write_str("auto"),
            Self::Fixed(k) => f.write_str(k.name()),
        }
    }
}

impl std::str::FromStr for Method {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        if s == "auto" {
            return Ok(Self::Auto);
        }
        s.parse::<IntegratorKind>()
            .map(Self::Fixed)
            .map_err(|e| Error::bad_input(format!("{e}, or auto")))
    }
}

impl Serialize for Method {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

impl<'de> Deserialize<'de> for Method {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        let s = String::deserialize(d)?;
        s.parse().map_err(|e: Error| serde::de::Error::custom(e))
    }
}

/// The time window and the integrator (`[run]` in a scene file).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Run {
    /// End of the simulated window [0, t_end], in τ, or `"auto"` (held as
    /// +∞ until [`Scene::with_auto_window`] resolves it: until every wave
    /// has a fate, plus a margin, `sim::window`). Default 4000; a movie or
    /// figure whose file or flags set none uses `"auto"`.
    #[serde(with = "t_end_value")]
    pub t_end: f64,
    /// `auto` (default) or explicit-euler, symplectic-euler, verlet, rk4,
    /// dopri5.
    pub integrator: Method,
    /// Time step of a fixed-step integrator (first trial step of dopri5).
    /// Default 0.01; `auto` picks its own.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dt: Option<f64>,
    /// Tolerance of adaptive dopri5. Default 1e-6.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rtol: Option<f64>,
    /// Largest error `auto` accepts in any arrival time, in τ. Default 0.1.
    pub tolerance: f64,
}

impl Default for Run {
    fn default() -> Self {
        Self {
            t_end: 4000.0,
            integrator: Method::Auto,
            dt: None,
            rtol: None,
            tolerance: 0.1,
        }
    }
}

/// `run.t_end = "auto"` before it is resolved ([`Scene::with_auto_window`]).
pub const AUTO_T_END: f64 = f64::INFINITY;

/// `t_end` in a scene file: a number of τ or `"auto"` ([`AUTO_T_END`]).
mod t_end_value {
    use super::AUTO_T_END;
    use serde::{Deserializer, Serializer, de};

    pub fn serialize<S: Serializer>(t: &f64, s: S) -> Result<S::Ok, S::Error> {
        if *t == AUTO_T_END {
            s.serialize_str("auto")
        } else {
            s.serialize_f64(*t)
        }
    }

    struct Visitor;

    impl de::Visitor<'_> for Visitor {
        type Value = f64;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("a time in τ or \"auto\"")
        }
        fn visit_f64<E: de::Error>(self, x: f64) -> Result<f64, E> {
            Ok(x)
        }
        fn visit_i64<E: de::Error>(self, x: i64) -> Result<f64, E> {
            Ok(x as f64)
        }
        fn visit_u64<E: de::Error>(self, x: u64) -> Result<f64, E> {
            Ok(x as f64)
        }
        fn visit_str<E: de::Error>(self, s: &str) -> Result<f64, E> {
            if s == "auto" {
                Ok(AUTO_T_END)
            } else {
                Err(E::custom(format!(
                    "must be a time in τ or \"auto\", got \"{s}\""
                )))
            }
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        d.deserialize_any(Visitor)
    }
}

/// The highest frequency ω_max of the chain `scenario` runs, from its
/// parameters as run (an apparatus's converted ones, not the scene
/// file's `[model]`): the one source of `auto`'s first step
/// ([`auto_config`]) and of its stability bound, for a scene and for a
/// sweep's point alike.
pub fn omega_max(scenario: &crate::sim::Scenario) -> Result<f64> {
    let springs = crate::theory::dispersion::omega_max_clamped(&scenario.ladder.params)?;
    // Blocks in contact ring at the contact's frequency while they touch
    // (`model::contact::Contact::frequency`).
    let l = &scenario.ladder;
    let contact = l.built.and_then(|b| {
        b.contact
            .map(|c| c.frequency(l.blocks(), &b.ribbons.outline))
    });
    Ok(springs.max(contact.unwrap_or(0.0)))
}

/// `auto`'s first configuration for `scenario` (`IntegratorConfig::auto`
/// at [`omega_max`]).
pub fn auto_config(scenario: &crate::sim::Scenario) -> Result<IntegratorConfig> {
    Ok(IntegratorConfig::auto(omega_max(scenario)?))
}

/// Default step of a fixed-step integrator: the paper's 0.01 τ.
pub const DEFAULT_DT: f64 = 0.01;
/// Default tolerance of adaptive dopri5.
pub const DEFAULT_RTOL: f64 = 1e-6;

impl Run {
    /// The fixed integrator's configuration; `None` for `auto`.
    pub fn fixed_config(&self) -> Result<Option<IntegratorConfig>> {
        match self.integrator {
            Method::Auto => Ok(None),
            Method::Fixed(kind) => {
                let rtol = match kind {
                    IntegratorKind::Dopri5 => Some(self.rtol.unwrap_or(DEFAULT_RTOL)),
                    _ => None,
                };
                Ok(Some(
                    IntegratorConfig {
                        kind,
                        dt: self.dt.unwrap_or(DEFAULT_DT),
                        rtol,
                    }
                    .validated()?,
                ))
            }
        }
    }
}
