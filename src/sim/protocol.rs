//! Drive protocols (docs/model.md, "Kink and antikink"; movies 10 and 11 of
//! README.md): block 1's centre is held at its ground-state position and
//! its angle follows a piecewise-linear ramp θ_1(t).

use crate::error::{Error, Result};

/// A piecewise-linear angle θ_1(t) through `knots` (t, θ), constant before
/// the first knot and after the last one.
#[derive(Debug, Clone, PartialEq)]
pub struct Drive {
    knots: Vec<(f64, f64)>,
}

impl Drive {
    /// Ramp through the given knots; times must be finite and strictly increasing.
    pub fn new(knots: Vec<(f64, f64)>) -> Result<Self> {
        if knots.is_empty() {
            return Err(Error::bad_input("a drive needs at least one knot"));
        }
        let finite = knots.iter().all(|(t, th)| t.is_finite() && th.is_finite());
        let increasing = knots.windows(2).all(|w| w[1].0 > w[0].0);
        if !finite || !increasing {
            return Err(Error::bad_input(
                "drive knots must be finite with strictly increasing times",
            ));
        }
        Ok(Self { knots })
    }

    /// Block 1 held at angle `theta` for all time (no drive).
    pub fn hold(theta: f64) -> Self {
        Self {
            knots: vec![(0.0, theta)],
        }
    }

    /// The single flip of the kink/antikink scenes:
    /// θ_1(t) = α (1 − 2 min(t/T_d, 1)), α in radians.
    pub fn single_flip(alpha: f64, t_d: f64) -> Result<Self> {
        positive_time("the drive time T_d", t_d)?;
        Self::new(vec![(0.0, alpha), (t_d, -alpha)])
    }

    /// Two flips (movies 10 and 11): α → −α on [0, T_d], then −α → α on
    /// [t_second, t_second + T_d].
    pub fn two_flips(alpha: f64, t_d: f64, t_second: f64) -> Result<Self> {
        positive_time("the drive time T_d", t_d)?;
        if !(t_second.is_finite() && t_second > t_d) {
            return Err(Error::bad_input(format!(
                "the second flip must start after the first ends (T_d = {t_d}), got {}",
                crate::error::num(t_second)
            )));
        }
        Self::new(vec![
            (0.0, alpha),
            (t_d, -alpha),
            (t_second, -alpha),
            (t_second + t_d, alpha),
        ])
    }

    /// θ_1(t).
    pub fn theta(&self, t: f64) -> f64 {
        self.piece(t).theta(t)
    }

    /// dθ_1/dt, taken from the right at a corner.
    pub fn omega(&self, t: f64) -> f64 {
        self.piece(t).omega()
    }

    /// The piece of θ_1 in force at `t`: the ramp [t_k, t_{k+1}) that
    /// contains it (from the right at a knot), or the constant before the
    /// first knot or after the last.
    pub fn piece(&self, t: f64) -> Piece {
        let k = &self.knots;
        if t < k[0].0 {
            return Piece::Hold {
                theta: k[0].1,
                from: f64::NEG_INFINITY,
                until: k[0].0,
            };
        }
        match k.windows(2).find(|w| t < w[1].0) {
            Some(w) => Piece::Ramp {
                start: w[0],
                end: w[1],
                slope: (w[1].1 - w[0].1) / (w[1].0 - w[0].0),
            },
            None => Piece::Hold {
                theta: k[k.len() - 1].1,
                from: k[k.len() - 1].0,
                until: f64::INFINITY,
            },
        }
    }

    /// Times at which θ̇_1 jumps (the knots), where integrators must land.
    pub fn corners(&self) -> impl Iterator<Item = f64> + '_ {
        self.knots.iter().map(|k| k.0)
    }

    /// Number of ramps of θ_1 (flips of block 1): pieces on which it moves.
    pub fn flips(&self) -> usize {
        self.knots.windows(2).filter(|w| w[0].1 != w[1].1).count()
    }

    /// Time after which the drive does no more work.
    pub fn end(&self) -> f64 {
        self.knots[self.knots.len() - 1].0
    }
}

/// One piece of the piecewise-linear θ_1(t), valid on [from, until).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Piece {
    Hold {
        theta: f64,
        from: f64,
        until: f64,
    },
    /// Through the knots `start` and `end`; `slope` = dθ_1/dt.
    Ramp {
        start: (f64, f64),
        end: (f64, f64),
        slope: f64,
    },
}

impl Piece {
    /// Whether the piece is the one in force at `t`.
    #[inline]
    pub fn contains(&self, t: f64) -> bool {
        match *self {
            Self::Hold { from, until, .. } => t >= from && t < until,
            Self::Ramp { start, end, .. } => t >= start.0 && t < end.0,
        }
    }

    #[inline]
    pub fn theta(&self, t: f64) -> f64 {
        match *self {
            Self::Hold { theta, .. } => theta,
            Self::Ramp { start, end, .. } => {
                start.1 + (end.1 - start.1) * (t - start.0) / (end.0 - start.0)
            }
        }
    }

    #[inline]
    pub fn omega(&self) -> f64 {
        match *self {
            Self::Hold { .. } => 0.0,
            Self::Ramp { slope, .. } => slope,
        }
    }
}

fn positive_time(name: &str, t: f64) -> Result<()> {
    if t.is_finite() && t > 0.0 {
        Ok(())
    } else {
        Err(Error::bad_input(format!(
            "{name} must be a finite number > 0, got {}",
            crate::error::num(t)
        )))
    }
}

/// What happens to block 1.
#[derive(Debug, Clone, PartialEq)]
pub enum Protocol {
    /// No constraint: every block moves freely.
    Free,
    /// Block 1's centre clamped at its initial position, its angle driven.
    Driven(Drive),
}

impl Protocol {
    pub fn drive(&self) -> Option<&Drive> {
        match self {
            Self::Free => None,
            Self::Driven(d) => Some(d),
        }
    }

    /// Time after which nothing does work on the ladder.
    pub fn drive_end(&self) -> f64 {
        self.drive().map_or(0.0, Drive::end)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn single_flip_matches_spec_formula() {
        let alpha = 60f64.to_radians();
        let d = Drive::single_flip(alpha, 1000.0).unwrap();
        for t in [0.0, 250.0, 500.0, 999.0, 1000.0, 3000.0] {
            let want = alpha * (1.0 - 2.0 * (t / 1000.0f64).min(1.0));
            assert!((d.theta(t) - want).abs() < 1e-15, "t = {t}");
        }
        assert!((d.omega(10.0) + 2.0 * alpha / 1000.0).abs() < 1e-15);
        assert_eq!(d.omega(1000.0), 0.0);
    }

    #[test]
    fn two_flips_return_to_start() {
        let d = Drive::two_flips(1.0, 1000.0, 1500.0).unwrap();
        assert_eq!(d.theta(1200.0), -1.0);
        assert_eq!(d.theta(3000.0), 1.0);
        assert_eq!(
            d.corners().collect::<Vec<_>>(),
            [0.0, 1000.0, 1500.0, 2500.0]
        );
        assert!(Drive::two_flips(1.0, 1000.0, 900.0).is_err());
        assert!(Drive::single_flip(1.0, 0.0).is_err());
    }
}
