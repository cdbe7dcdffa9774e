//! The leaning start as a scene key (`[rings] leaning = { angle = 30.0,
//! squeeze = 0.7 }`, docs/rings.md, "The leaning start"): each key
//! declared once, with its name, unit, default, range and meaning, from
//! which the check and its message are made. Without the key the chain
//! starts as built (every ring hanging vertical).

use crate::error::{Error, Result};
use crate::model::table::Range;
use serde::{Deserialize, Serialize};

/// One key of the leaning start: everything the program says of it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Key {
    /// The key in `[rings.leaning]`.
    pub name: &'static str,
    /// The unit of its values ("" for a pure number).
    pub unit: &'static str,
    /// Its value when the table is given without it.
    pub default: f64,
    /// The values accepted.
    pub range: Range,
    /// What a value must be, in an error.
    pub what: &'static str,
    /// What it is, in a sentence.
    pub doc: &'static str,
}

/// The tilt of every ring of the guess, degrees.
pub const ANGLE: Key = Key {
    name: "angle",
    unit: "°",
    default: 30.0,
    range: Range::Between(-45.0, 45.0),
    what: "degrees",
    doc: "Tilt of every ring of the guess about the horizontal diameter in its plane, all the \
          same way (n_z = sin angle); the chain then settles from it",
};

/// The guess's spacing as a fraction of the built chain's.
pub const SQUEEZE: Key = Key {
    name: "squeeze",
    unit: "",
    default: 0.7,
    range: Range::Between(0.5, 1.0),
    what: "a fraction",
    doc: "The guess's spacing between rings as a fraction of the chain as built (R − r per ring)",
};

/// Every key, in the order of docs/rings.md.
pub const KEYS: [Key; 2] = [ANGLE, SQUEEZE];

/// The leaning start of a ring chain: the chain built leaning and let
/// settle under gravity before the run (`crate::rings::settle`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Leaning {
    /// [`ANGLE`], degrees.
    pub angle: f64,
    /// [`SQUEEZE`].
    pub squeeze: f64,
}

impl Default for Leaning {
    fn default() -> Self {
        Leaning {
            angle: ANGLE.default,
            squeeze: SQUEEZE.default,
        }
    }
}

impl Leaning {
    /// Refuses a value out of its key's range with one line:
    /// "rings: leaning.angle must be degrees from -45 to 45, got 60".
    pub fn validated(&self) -> Result<&Self> {
        for (key, x) in [(ANGLE, self.angle), (SQUEEZE, self.squeeze)] {
            if !key.range.contains(x) {
                return Err(Error::bad_input(format!(
                    "rings: leaning.{} must be {} from {} to {}, got {x}",
                    key.name,
                    key.what,
                    key.range.min(),
                    key.range.max()
                )));
            }
        }
        Ok(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_defaults_are_in_range_and_the_ends_are_kept() {
        assert!(Leaning::default().validated().is_ok());
        for k in KEYS {
            assert!(k.range.contains(k.default), "{}", k.name);
        }
        let e = Leaning {
            angle: 60.0,
            ..Default::default()
        };
        let msg = e.validated().unwrap_err().to_string();
        assert_eq!(
            msg,
            "rings: leaning.angle must be degrees from -45 to 45, got 60"
        );
        let nan = Leaning {
            squeeze: f64::NAN,
            ..Default::default()
        };
        assert!(nan.validated().is_err());
    }
}
