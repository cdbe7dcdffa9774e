//! The alternating hand as a scene key (`[rings] alternate = { start =
//! 0.3, period = 0.6, count = 4 }`; docs/rings.md, "Retrieving the top
//! rings alternately"): the paper's "by retrieving a top ring of one of
//! two strands alternately, one can generate a unidirectional wave
//! indefinitely" (Fig. 4b, SI Movie 12). The hand holds ring `held`; at
//! `start` it lets that ring go and takes hold of the top ring of the
//! other strand where it is then; every `period` after, it lets the ring
//! it holds go and takes the top ring of the other strand again, `count`
//! passes in all. The top ring of a strand is the one whose centre is
//! highest at that moment ([`top_ring`]), decided from the state. With
//! `lift` the hand carries each ring it takes up to where it held the
//! ring it let go, over `lift` seconds (docs/rings.md, "Retrieving with
//! a lifting hand"; the motion in [`super::hand::Lift`]). Each
//! key is declared once, with its name, unit, default, range and
//! meaning, from which the check and its message are made.

use super::body::Body;
use super::start::Key;
use crate::error::{Error, Result};
use crate::model::table::Range;
use serde::{Deserialize, Serialize};

/// When the hand first passes the chain to the other strand, s.
pub const START: Key = Key {
    name: "start",
    unit: "s",
    default: 0.3,
    range: Range::Between(0.0, 600.0),
    what: "seconds",
    doc: "When the hand first lets the held ring go and takes the other strand's top ring",
};

/// The time between two passes, s.
pub const PERIOD: Key = Key {
    name: "period",
    unit: "s",
    default: 0.6,
    range: Range::Between(0.01, 60.0),
    what: "seconds",
    doc: "The time between two passes of the hand from one strand's top ring to the other's",
};

/// How many passes the hand makes.
pub const COUNT: Key = Key {
    name: "count",
    unit: "",
    default: 4.0,
    range: Range::Between(1.0, 1000.0),
    what: "a whole number",
    doc: "How many passes the hand makes (the first at start, one every period after)",
};

/// How long the hand takes to lift the ring it has taken to where it
/// held the ring it let go, s; 0: it holds the ring where it took it.
pub const LIFT: Key = Key {
    name: "lift",
    unit: "s",
    default: 0.0,
    range: Range::Between(0.0, 60.0),
    what: "seconds",
    doc: "How long the hand takes to lift the ring it takes to where it held the ring it let go \
          (0: it holds the ring where it took it); at most the period",
};

/// Every key, in the order of docs/rings.md.
pub const KEYS: [Key; 4] = [START, PERIOD, COUNT, LIFT];

/// The alternating hand: `count` passes from one strand's top ring to the
/// other's, at `start`, `start + period`, ...
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Alternate {
    /// [`START`], s.
    pub start: f64,
    /// [`PERIOD`], s.
    pub period: f64,
    /// [`COUNT`].
    pub count: usize,
    /// [`LIFT`], s.
    pub lift: f64,
}

impl Default for Alternate {
    fn default() -> Self {
        Alternate {
            start: START.default,
            period: PERIOD.default,
            count: COUNT.default as usize,
            lift: LIFT.default,
        }
    }
}

impl Alternate {
    /// The time of pass `i` (from 0), s.
    pub fn time(&self, i: usize) -> f64 {
        self.start + i as f64 * self.period
    }

    /// Refuses a value out of its key's range with one line ("rings:
    /// alternate.period must be seconds from 0.01 to 60, got 0"), and a
    /// lift longer than the period (the ring must be up before the hand
    /// lets it go).
    pub fn validated(&self) -> Result<&Self> {
        let values = [
            (START, self.start),
            (PERIOD, self.period),
            (COUNT, self.count as f64),
            (LIFT, self.lift),
        ];
        for (key, x) in values {
            if !key.range.contains(x) {
                return Err(Error::bad_input(format!(
                    "rings: alternate.{} must be {} from {} to {}, got {x}",
                    key.name,
                    key.what,
                    key.range.min(),
                    key.range.max()
                )));
            }
        }
        if self.lift > self.period {
            return Err(Error::bad_input(format!(
                "rings: alternate.{} must be at most alternate.{} ({} s), got {}",
                LIFT.name, PERIOD.name, self.period, self.lift
            )));
        }
        Ok(self)
    }
}

/// The top ring of `strand` (0: the even rings, 1: the odd): the ring of
/// that strand whose centre is highest; of two at the same height, the
/// lower index. Heights are unchanged by the mirror x → −x, so the
/// mirrored chain's hand takes the same ring.
pub fn top_ring(bodies: &[Body], strand: usize) -> usize {
    let mut top = strand;
    for k in (strand..bodies.len()).step_by(2) {
        if bodies[k].x[2] > bodies[top].x[2] {
            top = k;
        }
    }
    top
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rings::math::Quat;

    #[test]
    fn the_defaults_are_in_range_and_the_ends_are_kept() {
        assert!(Alternate::default().validated().is_ok());
        for k in KEYS {
            assert!(k.range.contains(k.default), "{}", k.name);
        }
        let e = Alternate {
            period: 0.0,
            ..Default::default()
        };
        let msg = e.validated().unwrap_err().to_string();
        assert_eq!(
            msg,
            "rings: alternate.period must be seconds from 0.01 to 60, got 0"
        );
        let none = Alternate {
            count: 0,
            ..Default::default()
        };
        assert!(none.validated().is_err());
        let nan = Alternate {
            start: f64::NAN,
            ..Default::default()
        };
        assert!(nan.validated().is_err());
        let long = Alternate {
            lift: 0.7,
            ..Default::default()
        };
        let msg = long.validated().unwrap_err().to_string();
        assert_eq!(
            msg,
            "rings: alternate.lift must be at most alternate.period (0.6 s), got 0.7"
        );
        for bad in [-0.1, f64::NAN] {
            let e = Alternate {
                lift: bad,
                ..Default::default()
            };
            assert!(e.validated().is_err(), "lift {bad}");
        }
        let full = Alternate {
            lift: 0.6,
            ..Default::default()
        };
        assert!(full.validated().is_ok(), "a lift as long as the period");
    }

    /// The top ring of a strand is the highest centre of its rings, the
    /// other strand's rings and their heights aside: in the chain as
    /// built, rings 0 and 1; with ring 6 raised above ring 0 (and ring 7
    /// above all), ring 6 of the even strand and ring 7 of the odd; of
    /// two at one height, the lower index.
    #[test]
    fn the_top_ring_is_the_highest_centre_of_the_strand() {
        // The chain as built: ring k at depth k(R − r), R = 12.5 mm, r = 1 mm.
        let mut bodies: Vec<Body> = (0..8)
            .map(|k| Body {
                x: [0.0, 0.0, -0.0115 * k as f64],
                v: [0.0; 3],
                q: Quat::axis_angle([0.0, 0.0, 1.0], 0.25 * k as f64),
                l: [0.0; 3],
            })
            .collect();
        assert_eq!((top_ring(&bodies, 0), top_ring(&bodies, 1)), (0, 1));
        bodies[6].x[2] = bodies[0].x[2] + 1e-9;
        assert_eq!(top_ring(&bodies, 0), 6);
        assert_eq!(top_ring(&bodies, 1), 1, "ring 6 is not of the odd strand");
        bodies[7].x[2] = 1.0;
        assert_eq!((top_ring(&bodies, 0), top_ring(&bodies, 1)), (6, 7));
        bodies[2].x[2] = bodies[6].x[2];
        assert_eq!(top_ring(&bodies, 0), 2, "a tie: the lower index");
    }
}
