//! What the wave of one run did, decided from its arrival times alone
//! (SPEC section 7; the rule is documented in docs/sweeps.md).
//!
//! - **propagated**: the wave's front reached block N − 1: blocks 1 to
//!   N − 1 have all flipped (the free bottom block N is left out: it turns
//!   its own way). Decided when the last of them flipped.
//! - otherwise the wave has **stopped** once it has not moved (no new
//!   arrival) for `quiet` times its longest inter-arrival gap, counted
//!   from its last arrival or from the end of the drive, whichever is
//!   later, and not before the scene's nominal t_end. The gaps are those
//!   of the sorted arrival times, the first counted from the start of the
//!   first flip (so a wave that only ever moved with the drive waits
//!   `quiet` × t_1). A stopped wave is **pinned** if its front never got
//!   past block 2, **stalled** otherwise. The front is the last block n
//!   such that blocks 1..=n have all flipped: a block that flips on its
//!   own ahead of the wave (the free end of a kink's chain at α ≤ 46° does,
//!   within a few hundred τ) counts as motion but not as the wave's
//!   progress; `blocks_flipped` > `front` shows it.
//! - a run that reaches the cap without either is **undecided**; one whose
//!   integration blew up is **diverged** (decided by the run loop).
//!
//! The decision is a pure function of the arrival times and the time
//! reached, and it replays the history: a run is decided at the first
//! moment the rule held, whatever the cadence at which it is asked, so
//! two runs that flip the same blocks at the same times are decided alike.

use serde::{Deserialize, Serialize};
use std::fmt;

/// The outcome of one run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Outcome {
    /// The wave's front reached block N − 1.
    Propagated,
    /// The wave stopped in the bulk, its front past block 2.
    Stalled,
    /// The wave's front never got past block 2.
    Pinned,
    /// The integration blew up.
    Diverged,
    /// Neither propagated nor stopped by the cap.
    Undecided,
}

impl Outcome {
    pub const ALL: [Outcome; 5] = [
        Self::Propagated,
        Self::Stalled,
        Self::Pinned,
        Self::Diverged,
        Self::Undecided,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Self::Propagated => "propagated",
            Self::Stalled => "stalled",
            Self::Pinned => "pinned",
            Self::Diverged => "diverged",
            Self::Undecided => "undecided",
        }
    }

    pub fn from_name(s: &str) -> Option<Outcome> {
        Self::ALL.into_iter().find(|o| o.name() == s)
    }
}

impl fmt::Display for Outcome {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The rule's parameters for one run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rule {
    /// Start of the first flip of block 1 (the wave's clock starts here).
    pub drive_start: f64,
    /// End of the last flip: nothing stops while block 1 is driven.
    pub drive_end: f64,
    /// The scene's nominal end: no wave is called stopped before it.
    pub t_end: f64,
    /// Quiet time, in multiples of the longest inter-arrival gap.
    pub quiet: f64,
    /// Latest time reached while undecided.
    pub cap: f64,
}

/// A decided outcome and when it was decided.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Decision {
    pub outcome: Outcome,
    /// t_{N−1} for a propagated wave; the end of the quiet time for a
    /// stopped one; the cap for an undecided one.
    pub t_decided: f64,
}

impl Rule {
    /// The decision at time `t` from `arrivals` (one per block, `None`
    /// where the block has not flipped), or `None` while undecided and
    /// `t` is before the cap. Arrivals later than `t` are ignored.
    pub fn decide(&self, arrivals: &[Option<f64>], t: f64) -> Option<Decision> {
        let n = arrivals.len();
        // The front reached block N − 1 when the last of blocks 1..N−1 flipped.
        let reached = arrivals[..n.saturating_sub(1)]
            .iter()
            .try_fold(f64::NEG_INFINITY, |m, a| {
                a.filter(|&a| a <= t).map(|a| m.max(a))
            });
        if n >= 2
            && let Some(t_prop) = reached
        {
            // The wave may have stopped before it got there.
            if let Some(d) = self.stopped_before(arrivals, t_prop) {
                return Some(d);
            }
            return Some(Decision {
                outcome: Outcome::Propagated,
                t_decided: t_prop,
            });
        }
        if let Some(d) = self.stopped_before(arrivals, t) {
            return Some(d);
        }
        (t >= self.cap).then_some(Decision {
            outcome: Outcome::Undecided,
            t_decided: self.cap,
        })
    }

    /// The first time in [0, t] at which the quiet rule held, replaying
    /// the arrivals in time order.
    fn stopped_before(&self, arrivals: &[Option<f64>], t: f64) -> Option<Decision> {
        let mut times: Vec<(f64, usize)> = arrivals
            .iter()
            .enumerate()
            .filter_map(|(i, a)| a.filter(|&a| a <= t).map(|a| (a, i)))
            .collect();
        times.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        let mut last = self.drive_start;
        let mut longest_gap: f64 = 0.0;
        let mut flipped = vec![false; arrivals.len()];
        // Before the k-th arrival (k = 0..=len): the history so far.
        for k in 0..=times.len() {
            let stop_at = self.quiet_end(last, longest_gap);
            let next = times.get(k).map_or(f64::INFINITY, |a| a.0);
            if stop_at < next && stop_at <= t && stop_at <= self.cap {
                let front = flipped.iter().take_while(|f| **f).count();
                return Some(Decision {
                    outcome: stopped_outcome(front),
                    t_decided: stop_at,
                });
            }
            if let Some(&(a, block)) = times.get(k) {
                longest_gap = longest_gap.max(a - last);
                last = last.max(a);
                flipped[block] = true;
            }
        }
        None
    }

    /// When a wave last seen at `last`, with longest gap `gap`, is called
    /// stopped.
    fn quiet_end(&self, last: f64, gap: f64) -> f64 {
        let from = last.max(self.drive_end);
        (from + self.quiet * gap).max(self.t_end)
    }
}

/// The outcome of a wave that stopped with its front at block `front`
/// (SPEC section 7): **pinned** if it never got past block 2 (front ≤ 2),
/// **stalled** if it stopped in between.
pub fn stopped_outcome(front: usize) -> Outcome {
    if front <= 2 {
        Outcome::Pinned
    } else {
        Outcome::Stalled
    }
}

/// The last block the wave reached: the largest n such that blocks
/// 1..=n have all flipped (0 if block 1 has not).
pub fn front(arrivals: &[Option<f64>]) -> usize {
    arrivals.iter().take_while(|a| a.is_some()).count()
}

/// Number of blocks that flipped.
pub fn blocks_flipped(arrivals: &[Option<f64>]) -> usize {
    arrivals.iter().filter(|a| a.is_some()).count()
}

/// Shortest time between the arrivals of successive blocks that is still
/// a wave passing from one to the next, τ. The model's waves take hundreds
/// of τ per block (the paper's kink: about 220 τ; the slowest antikinks of
/// the pinning sweep several thousand); blocks that flip less than 1 τ
/// apart flip together, faster than a block can respond to its neighbour
/// (the shortest period of the linear chain, 2π/ω_max, is 2.3 τ at
/// |α| = 89°, N = 10, b/s = 1.3: `ladder theory --alpha 89`).
pub const COLLECTIVE_FLIP_GAP: f64 = 1.0;

/// Speed of the wave in blocks per τ: the inverse least-squares slope of
/// t_n against n over the blocks past block 2 and before the free bottom
/// block (n = 3..N−1) that flipped; `None` with fewer than three of them,
/// no positive slope, or blocks that flip in groups rather than one after
/// another: when at least half the gaps between successive arrivals are
/// shorter than [`COLLECTIVE_FLIP_GAP`] (near |α| = 90°: at 89° the
/// antikink's blocks 2–9 flip within 0.8 τ, the kink's in two groups), a
/// slope through them is no speed.
pub fn speed(arrivals: &[Option<f64>]) -> Option<f64> {
    let n = arrivals.len();
    let pts: Vec<(f64, f64)> = (2..n.saturating_sub(1))
        .filter_map(|i| arrivals[i].map(|t| (i as f64 + 1.0, t)))
        .collect();
    if pts.len() < 3 {
        return None;
    }
    let together = pts
        .windows(2)
        .filter(|w| (w[1].1 - w[0].1).abs() < COLLECTIVE_FLIP_GAP)
        .count();
    if 2 * together >= pts.len() - 1 {
        return None;
    }
    let slope = crate::sim::observables::least_squares_slope(&pts);
    (slope.is_finite() && slope > 0.0).then(|| 1.0 / slope)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rule() -> Rule {
        Rule {
            drive_start: 0.0,
            drive_end: 1000.0,
            t_end: 4000.0,
            quiet: 10.0,
            cap: 100_000.0,
        }
    }

    fn arr(ts: &[Option<f64>]) -> Vec<Option<f64>> {
        ts.to_vec()
    }

    #[test]
    fn reaching_block_n_minus_one_is_propagation() {
        // N = 5: block 4 is N − 1; the free block 5 need not flip.
        let a = arr(&[Some(500.0), Some(900.0), Some(1300.0), None, None]);
        assert_eq!(rule().decide(&a, 1700.0), None);
        let b = arr(&[Some(500.0), Some(900.0), Some(1300.0), Some(1700.0), None]);
        let d = rule().decide(&b, 1705.0).unwrap();
        assert_eq!(d.outcome, Outcome::Propagated);
        assert_eq!(d.t_decided, 1700.0);
        // Decided before the nominal window ends.
        assert!(d.t_decided < rule().t_end);
    }

    #[test]
    fn a_slow_steady_wave_is_never_called_stopped() {
        // Gaps of 4000 τ, far beyond the paper's window: still moving.
        let mut a = vec![None; 10];
        a[0] = Some(500.0);
        a[1] = Some(950.0);
        let mut t = 950.0;
        for slot in a.iter_mut().take(9).skip(2) {
            t += 4000.0;
            *slot = Some(t);
        }
        // At every moment before t_9 the rule has not fired.
        for k in 0..400 {
            let now = k as f64 * (t / 400.0);
            let seen: Vec<Option<f64>> = a.iter().map(|x| x.filter(|&v| v <= now)).collect();
            assert_eq!(rule().decide(&seen, now), None, "at t = {now}");
        }
        let d = rule().decide(&a, t).unwrap();
        assert_eq!(d.outcome, Outcome::Propagated);
        assert_eq!(d.t_decided, t);
    }

    #[test]
    fn a_wave_that_stopped_is_stalled_after_the_quiet_time() {
        // The α = −52° antikink: blocks 1–6, then nothing.
        let a = arr(&[
            Some(500.0),
            Some(945.0),
            Some(1822.0),
            Some(6605.0),
            Some(11279.0),
            Some(15255.0),
            None,
            None,
            None,
            None,
        ]);
        let gap = 6605.0 - 1822.0;
        let end = 15255.0 + 10.0 * gap;
        assert_eq!(rule().decide(&a, end - 1.0), None);
        let d = rule().decide(&a, end + 3.0).unwrap();
        assert_eq!(d.outcome, Outcome::Stalled);
        assert_eq!(d.t_decided, end);
        // The same history asked much later is decided at the same time.
        assert_eq!(rule().decide(&a, 90_000.0), Some(d));
    }

    #[test]
    fn a_wave_held_at_the_top_is_pinned_not_before_t_end() {
        let a = arr(&[Some(500.0), Some(943.0), None, None, None, None]);
        // Longest gap 500 (0 → t_1); quiet from the drive's end.
        let d = rule().decide(&a, 10_000.0).unwrap();
        assert_eq!(d.outcome, Outcome::Pinned);
        assert_eq!(d.t_decided, 6000.0);
        // A short quiet time is held up to the nominal window.
        let short = Rule {
            quiet: 1.0,
            ..rule()
        };
        assert_eq!(short.decide(&a, 10_000.0).unwrap().t_decided, 4000.0);
    }

    #[test]
    fn an_arrival_after_the_quiet_time_does_not_change_the_decision() {
        // Decided pinned at 6000; a flip at 6002 (between two checks) is
        // after the decision and does not turn it into propagation.
        let a = arr(&[Some(500.0), Some(943.0), Some(6002.0), Some(6003.0), None]);
        let d = rule().decide(&a, 6005.0).unwrap();
        assert_eq!(d.outcome, Outcome::Pinned);
    }

    #[test]
    fn a_block_flipping_ahead_of_the_wave_is_not_propagation() {
        // Block 4 of 5 (N − 1) flips on its own at 200 τ, before the wave.
        let a = arr(&[Some(500.0), Some(900.0), None, Some(200.0), None]);
        assert_eq!(rule().decide(&a, 1000.0), None);
        let b = arr(&[Some(500.0), Some(900.0), Some(1300.0), Some(200.0), None]);
        let d = rule().decide(&b, 1300.0).unwrap();
        assert_eq!(d.outcome, Outcome::Propagated);
        assert_eq!(d.t_decided, 1300.0);
        // Held at block 2 with a stray flip far ahead: pinned.
        let c = arr(&[Some(500.0), Some(900.0), None, Some(200.0), None]);
        assert_eq!(
            rule().decide(&c, 50_000.0).unwrap().outcome,
            Outcome::Pinned
        );
    }

    #[test]
    fn undecided_at_the_cap() {
        let r = Rule {
            cap: 5000.0,
            ..rule()
        };
        let a = arr(&[Some(500.0), Some(943.0), None, None, None]);
        assert_eq!(r.decide(&a, 4999.0), None);
        let d = r.decide(&a, 5000.0).unwrap();
        assert_eq!(d.outcome, Outcome::Undecided);
        assert_eq!(d.t_decided, 5000.0);
    }

    #[test]
    fn front_speed_and_counts() {
        let a = arr(&[
            Some(500.0),
            Some(900.0),
            Some(1000.0),
            Some(1100.0),
            Some(1200.0),
            None,
        ]);
        assert_eq!(front(&a), 5);
        assert_eq!(blocks_flipped(&a), 5);
        // Blocks 3, 4, 5 one per 100 τ.
        assert!((speed(&a).unwrap() - 0.01).abs() < 1e-12);
        let b = arr(&[Some(500.0), None, Some(1000.0), Some(1100.0), None]);
        assert_eq!(front(&b), 1);
        assert_eq!(blocks_flipped(&b), 3);
        assert_eq!(speed(&b), None);
    }

    #[test]
    fn blocks_that_flip_together_have_no_speed() {
        // |α| = 89°, N = 10: blocks 2..9 within 0.8 τ (a real run's times).
        let together = arr(&[
            Some(500.0),
            Some(747.4),
            Some(747.6),
            Some(747.7),
            Some(747.8),
            Some(748.0),
            Some(748.1),
            Some(748.2),
            Some(748.2),
            None,
        ]);
        assert_eq!(front(&together), 9);
        assert_eq!(speed(&together), None);
        // The kink at 89°: blocks 2–4 together, then 5–9 together.
        let groups = arr(&[
            Some(500.0),
            Some(892.6),
            Some(892.7),
            Some(892.8),
            Some(1095.5),
            Some(1095.5),
            Some(1095.5),
            Some(1095.5),
            Some(1095.5),
            None,
        ]);
        assert_eq!(speed(&groups), None);
        // The kink at 88°: blocks 3–5 together (a third of the gaps), then
        // a wave at about 205 τ per block: a speed.
        let mostly_wave = arr(&[
            Some(500.0),
            Some(945.8),
            Some(1165.5),
            Some(1165.4),
            Some(1165.3),
            Some(1379.2),
            Some(1578.8),
            Some(1789.1),
            Some(1989.9),
            None,
        ]);
        assert!(speed(&mostly_wave).is_some());
        // The same blocks 1.1 τ apart: a (fast) wave, 1/1.1 blocks per τ.
        let mut fast = together.clone();
        for (k, a) in fast.iter_mut().enumerate().take(9).skip(1) {
            *a = Some(747.4 + 1.1 * (k - 1) as f64);
        }
        assert!((speed(&fast).unwrap() - 1.0 / 1.1).abs() < 1e-9);
    }
}
