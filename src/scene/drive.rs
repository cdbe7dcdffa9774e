//! `[drive]`: what block 1 does, a sequence of flips (docs/model.md and docs/scenes.md).

use crate::error::{Error, Result};
use crate::sim::Drive;
use serde::{Deserialize, Serialize};

/// Block 1's drive: a sequence of flips, each turning block 1 from the
/// ground state it is in to the other one (α → −α, then −α → α, ...)
/// linearly over `duration` from `start` (docs/model.md and docs/scenes.md).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct DriveSpec {
    /// The flips, in time order, not overlapping. Default: one flip
    /// starting at 0 over the paper's T_d = 1000 τ. An empty list holds
    /// block 1 at α.
    pub flips: Vec<Flip>,
}

impl Default for DriveSpec {
    fn default() -> Self {
        Self {
            flips: vec![Flip::default()],
        }
    }
}

/// One flip of block 1.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Flip {
    /// When the flip starts, in τ. Default 0.
    pub start: f64,
    /// How long it takes, T_d, in τ. Default 1000.
    pub duration: f64,
}

impl Default for Flip {
    fn default() -> Self {
        Self {
            start: 0.0,
            duration: crate::sim::PAPER_DRIVE_TIME,
        }
    }
}

impl Flip {
    pub fn end(&self) -> f64 {
        self.start + self.duration
    }
}

impl DriveSpec {
    /// The drive with the shortcuts of the command line and of Python's
    /// keywords applied: `drive_time` (the duration of every flip; default
    /// the first flip's, or the paper's T_d), `flips` (the start of each
    /// flip) or `second_flip` (flips at 0 and there). Starts left out keep
    /// this drive's.
    pub fn reshaped(
        &self,
        drive_time: Option<f64>,
        flips: Option<&[f64]>,
        second_flip: Option<f64>,
    ) -> DriveSpec {
        let duration = drive_time
            .or_else(|| self.flips.first().map(|f| f.duration))
            .unwrap_or(crate::sim::PAPER_DRIVE_TIME);
        let starts: Vec<f64> = match (flips, second_flip) {
            (Some(f), _) => f.to_vec(),
            (None, Some(t)) => vec![0.0, t],
            (None, None) => self.flips.iter().map(|f| f.start).collect(),
        };
        DriveSpec::flips_at(&starts, duration)
    }

    /// Flips at `start_k`, each over `duration`.
    pub fn flips_at(starts: &[f64], duration: f64) -> Self {
        Self {
            flips: starts
                .iter()
                .map(|&start| Flip { start, duration })
                .collect(),
        }
    }

    /// θ_1(t) as a piecewise-linear drive, α in radians.
    pub fn drive(&self, alpha: f64) -> Result<Drive> {
        self.check().map_err(|(_, msg)| Error::bad_input(msg))?;
        if self.flips.is_empty() {
            return Ok(Drive::hold(alpha));
        }
        let mut knots = Vec::with_capacity(2 * self.flips.len() + 1);
        let mut theta = alpha;
        if self.flips[0].start > 0.0 {
            knots.push((0.0, theta));
        }
        for f in &self.flips {
            if knots.last().is_none_or(|k: &(f64, f64)| k.0 < f.start) {
                knots.push((f.start, theta));
            }
            theta = -theta;
            knots.push((f.end(), theta));
        }
        Drive::new(knots)
    }

    /// End of the last flip (0 when there is none).
    pub fn end(&self) -> f64 {
        self.flips.last().map_or(0.0, Flip::end)
    }

    /// Checks the flips: finite, start ≥ 0, duration > 0, in order and not
    /// overlapping. On error: (index of the offending flip, message).
    pub fn check(&self) -> std::result::Result<(), (usize, String)> {
        let mut prev_end = 0.0;
        for (k, f) in self.flips.iter().enumerate() {
            if !(f.start.is_finite() && f.start >= 0.0) {
                return Err((
                    k,
                    format!("start must be a finite time >= 0, got {}", f.start),
                ));
            }
            if !(f.duration.is_finite() && f.duration > 0.0) {
                return Err((
                    k,
                    format!("duration must be a finite time > 0, got {}", f.duration),
                ));
            }
            // The end must be a finite time after the start in floating
            // point too (start + duration can round to start, or overflow).
            if !(f.end().is_finite() && f.end() > f.start) {
                return Err((
                    k,
                    format!(
                        "a flip from {} for {} ends at {}: the duration must be finite and \
                         not lost in the rounding of the start",
                        crate::numfmt::plain(f.start),
                        crate::numfmt::plain(f.duration),
                        crate::numfmt::plain(f.end())
                    ),
                ));
            }
            if k > 0 && f.start < prev_end {
                return Err((
                    k,
                    format!(
                        "flip {} starts at {} before flip {} ends at {prev_end}; flips must not overlap",
                        k + 1,
                        f.start,
                        k
                    ),
                ));
            }
            prev_end = f.end();
        }
        Ok(())
    }
}
