//! What the wave of one run did (docs/sweeps.md; the rule is
//! documented in docs/sweeps.md).
//!
//! - **propagated**: the wave's front reached block N − 1: blocks 1 to
//!   N − 1 have all flipped (the free bottom block N is left out: it turns
//!   its own way). Decided when the last of them flipped.
//! - **pinned** / **stalled**: the state proves the wave stopped: after
//!   the drive, the ladder is at rest (kinetic energy and residual forces
//!   under the tolerances of `theory::stability::RestTolerances`) at a
//!   linearly stable equilibrium (the smallest eigenvalue ω² of the
//!   clamped Hessian above the margin). Pinned if its front never got past
//!   block 2, stalled otherwise ([`stopped_outcome`]). The front is the
//!   last block n ≤ N − 1 such that blocks 1..=n have all flipped: block N
//!   is free and turns its own way (at small |α| it falls over on its own
//!   before the wave arrives), so its turn is recorded beside the front
//!   (`RunResult::block_n_turned_at`), never counted in it.
//! - **annihilated**: the wave the drive launched (the first wave from
//!   block 1) met a wall running the other way (one that the free block N
//!   launched on its own, at small |α|) and the two annihilated
//!   ([`of_driven_wave`]): the chain may end flipped, but the driven wave
//!   did not propagate.
//! - a run that reaches the cap without either is **undecided**; one whose
//!   integration blew up is **diverged** (decided by the run loop); one
//!   that could not start (its relaxed start found no hanging
//!   equilibrium) is **failed**, with its reason.
//!
//! No waiting time decides anything: near an edge a wave can wait at a
//! block for tens of thousands of τ and then move on (docs/sweeps.md), so
//! only a state at rest at a stable equilibrium, which stays there, stops
//! a run.

use crate::theory::stability::RestTolerances;
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
    /// The driven wave was annihilated by a wall running the other way.
    Annihilated,
    /// The run could not be made (its start found no equilibrium); the
    /// record's message says why.
    Failed,
}

impl Outcome {
    pub const ALL: [Outcome; 7] = [
        Self::Propagated,
        Self::Annihilated,
        Self::Stalled,
        Self::Pinned,
        Self::Diverged,
        Self::Undecided,
        Self::Failed,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Self::Propagated => "propagated",
            Self::Stalled => "stalled",
            Self::Pinned => "pinned",
            Self::Diverged => "diverged",
            Self::Undecided => "undecided",
            Self::Annihilated => "annihilated",
            Self::Failed => "failed",
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
    /// End of the last flip: nothing stops while block 1 is driven.
    pub drive_end: f64,
    /// Latest time reached while undecided.
    pub cap: f64,
    /// The tolerances of the rest proof (`theory::stability`).
    pub tolerances: RestTolerances,
}

/// A decided outcome and when it was decided.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Decision {
    pub outcome: Outcome,
    /// t_{N−1} for a propagated wave; the time the state was proved at
    /// rest for a stopped one; the cap for an undecided one.
    pub t_decided: f64,
}

/// The outcome of a wave the state proved stopped with its front at
/// block `front`: pinned if it never got past block 2, stalled otherwise.
pub fn stopped_outcome(front: usize) -> Outcome {
    if front <= 2 {
        Outcome::Pinned
    } else {
        Outcome::Stalled
    }
}

impl Rule {
    /// Propagation, from `arrivals` (one per block, `None` where the block
    /// has not flipped; arrivals later than `t` ignored): the time the last
    /// of blocks 1..N − 1 flipped, if all have by `t`.
    pub fn propagated(&self, arrivals: &[Option<f64>], t: f64) -> Option<Decision> {
        let n = arrivals.len();
        if n < 2 {
            return None;
        }
        arrivals[..n - 1]
            .iter()
            .try_fold(f64::NEG_INFINITY, |m, a| {
                a.filter(|&a| a <= t).map(|a| m.max(a))
            })
            .map(|t_prop| Decision {
                outcome: Outcome::Propagated,
                t_decided: t_prop,
            })
    }

    /// The decision at time `t`: propagated (see [`Rule::propagated`]);
    /// else stopped when `at_rest` (the state at `t` proved at rest at a
    /// linearly stable equilibrium) and the drive is over, pinned or
    /// stalled by the front; else undecided at the cap; else `None`.
    pub fn decide(&self, arrivals: &[Option<f64>], t: f64, at_rest: bool) -> Option<Decision> {
        if let Some(d) = self.propagated(arrivals, t) {
            return Some(d);
        }
        if at_rest && t >= self.drive_end {
            return Some(Decision {
                outcome: stopped_outcome(front(arrivals)),
                t_decided: t,
            });
        }
        (t >= self.cap).then_some(Decision {
            outcome: Outcome::Undecided,
            t_decided: self.cap,
        })
    }

    /// Whether the state (`q`, `v`) of `ladder` is proved at rest by this
    /// rule's tolerances.
    pub fn at_rest(&self, ladder: &crate::model::Ladder, q: &[f64], v: &[f64]) -> bool {
        crate::theory::stability::rest_proof(ladder, q, v, &self.tolerances).proved
    }
}

/// The last block the wave reached: the largest n ≤ N − 1 such that
/// blocks 1..=n have all flipped (0 if block 1 has not). Block N, the free
/// bottom block, is left out: whether it has turned by the time block
/// N − 1 flips says when the run was looked at, not how far the wave got
/// (its turn is kept apart, [`block_n_turned_at`]).
pub fn front(arrivals: &[Option<f64>]) -> usize {
    let above_n = arrivals.len().saturating_sub(1).max(1).min(arrivals.len());
    arrivals[..above_n]
        .iter()
        .take_while(|a| a.is_some())
        .count()
}

/// When block N (the free bottom block, the last of `arrivals`) first
/// turned, if it has.
pub fn block_n_turned_at(arrivals: &[Option<f64>]) -> Option<f64> {
    if arrivals.len() < 2 {
        return None;
    }
    arrivals.last().copied().flatten()
}

/// How many blocks flipped, counted as the front is: of blocks 1..N − 1
/// (the chain the driven wave crosses), those whose polarisation changed
/// sign. Block N, free, is left out (its own turn is
/// [`block_n_turned_at`]): whether it has turned says when the run was
/// looked at (a sweep stops at t_{N−1}, a single run goes on to its
/// t_end), not what the wave did, so a run and a sweep of the same
/// scene agree on this count (docs/sweeps.md, "The files").
pub fn blocks_flipped(arrivals: &[Option<f64>]) -> usize {
    let above_n = arrivals.len().saturating_sub(1).max(1).min(arrivals.len());
    arrivals[..above_n].iter().filter(|a| a.is_some()).count()
}

/// The outcome word of a run whose rule decided `decided`, told by what
/// the driven wave did (the first wave launched by block 1, from
/// `waves`): a driven wave annihilated by a wall running the other way
/// is [`Outcome::Annihilated`], whatever the chain's blocks did after
/// (at α = 40°, N = 10, the free block N falls over at 136 τ and its wall
/// meets the driven kink at block 3: every block ends flipped, but the
/// kink did not propagate). A diverged or failed run keeps its word.
pub fn of_driven_wave(decided: Outcome, waves: &crate::sim::waves::Waves) -> Outcome {
    use crate::sim::waves::Fate;
    if matches!(decided, Outcome::Diverged | Outcome::Failed) {
        return decided;
    }
    match waves.waves.iter().find(|w| w.origin == 1).map(|w| w.fate) {
        Some(Fate::Annihilated { .. }) => Outcome::Annihilated,
        _ => decided,
    }
}

pub use crate::sim::speed::{
    COLLECTIVE_FLIP_GAP, FIRST_SPEED_BLOCK, SpeedFit, wave_speed, wave_speed_fit,
};

#[cfg(test)]
mod tests {
    use super::*;

    fn rule() -> Rule {
        Rule {
            drive_end: 1000.0,
            cap: 100_000.0,
            tolerances: RestTolerances::default(),
        }
    }

    fn arr(ts: &[Option<f64>]) -> Vec<Option<f64>> {
        ts.to_vec()
    }

    #[test]
    fn reaching_block_n_minus_one_is_propagation() {
        // N = 5: block 4 is N − 1; the free block 5 need not flip.
        let a = arr(&[Some(500.0), Some(900.0), Some(1300.0), None, None]);
        assert_eq!(rule().decide(&a, 1700.0, false), None);
        let b = arr(&[Some(500.0), Some(900.0), Some(1300.0), Some(1700.0), None]);
        let d = rule().decide(&b, 1705.0, false).unwrap();
        assert_eq!(d.outcome, Outcome::Propagated);
        assert_eq!(d.t_decided, 1700.0);
    }

    #[test]
    fn only_a_state_at_rest_stops_a_wave() {
        // Held at block 2 for 90 000 τ: still undecided while not at rest,
        // however long the wait.
        let a = arr(&[Some(500.0), Some(943.0), None, None, None, None]);
        assert_eq!(rule().decide(&a, 90_000.0, false), None);
        // At rest: pinned, at that time; not during the drive.
        let d = rule().decide(&a, 7000.0, true).unwrap();
        assert_eq!(d.outcome, Outcome::Pinned);
        assert_eq!(d.t_decided, 7000.0);
        assert_eq!(rule().decide(&a, 999.0, true), None);
        // Past block 2: stalled.
        let b = arr(&[Some(500.0), Some(943.0), Some(1822.0), None, None, None]);
        assert_eq!(
            rule().decide(&b, 9000.0, true).unwrap().outcome,
            Outcome::Stalled
        );
    }

    #[test]
    fn stopped_outcome_by_front() {
        assert_eq!(stopped_outcome(0), Outcome::Pinned);
        assert_eq!(stopped_outcome(2), Outcome::Pinned);
        assert_eq!(stopped_outcome(3), Outcome::Stalled);
        assert_eq!(stopped_outcome(9), Outcome::Stalled);
    }

    #[test]
    fn a_block_flipping_ahead_of_the_wave_is_not_propagation() {
        // Block 4 of 5 (N − 1) flips on its own at 200 τ, before the wave.
        let a = arr(&[Some(500.0), Some(900.0), None, Some(200.0), None]);
        assert_eq!(rule().decide(&a, 1000.0, false), None);
        let b = arr(&[Some(500.0), Some(900.0), Some(1300.0), Some(200.0), None]);
        let d = rule().decide(&b, 1300.0, false).unwrap();
        assert_eq!(d.outcome, Outcome::Propagated);
        assert_eq!(d.t_decided, 1300.0);
        // Held at block 2 with a stray flip far ahead, at rest: pinned.
        assert_eq!(
            rule().decide(&a, 50_000.0, true).unwrap().outcome,
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
        assert_eq!(r.decide(&a, 4999.0, false), None);
        let d = r.decide(&a, 5000.0, false).unwrap();
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
        assert!((wave_speed(&a).unwrap() - 0.01).abs() < 1e-12);
        let b = arr(&[Some(500.0), None, Some(1000.0), Some(1100.0), None]);
        assert_eq!(front(&b), 1);
        assert_eq!(blocks_flipped(&b), 3);
        assert_eq!(wave_speed(&b), None);
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
        assert_eq!(wave_speed(&together), None);
        assert_eq!(block_n_turned_at(&together), None);
        // Block N turned on its own before the wave reached block N − 1
        // (|α| = 40°, N = 10: at 136 τ, before the drive): the front still
        // stops at N − 1, and block N's turn is recorded apart.
        let mut all = together.clone();
        all[9] = Some(135.9);
        assert_eq!(front(&all), 9);
        assert_eq!(blocks_flipped(&all), 9);
        assert_eq!(block_n_turned_at(&all), Some(135.9));
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
        assert_eq!(wave_speed(&groups), None);
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
        assert!(wave_speed(&mostly_wave).is_some());
        // The same blocks 1.1 τ apart: a (fast) wave, 1/1.1 blocks per τ.
        let mut fast = together.clone();
        for (k, a) in fast.iter_mut().enumerate().take(9).skip(1) {
            *a = Some(747.4 + 1.1 * (k - 1) as f64);
        }
        assert!((wave_speed(&fast).unwrap() - 1.0 / 1.1).abs() < 1e-9);
    }

    #[test]
    fn an_annihilated_driven_wave_is_not_propagation() {
        use crate::sim::waves::{Fate, Wave, WaveKind, Waves};
        let wave = |origin, fate| Wave {
            kind: WaveKind::Kink,
            origin,
            launched_at: 0.0,
            arrival_times: vec![None; 4],
            front: origin,
            fate,
        };
        let met = Fate::Annihilated {
            with: 0,
            at: 773.4,
            block: 3,
        };
        // α = 40°: block N's wall (listed first) meets the driven kink.
        let waves = Waves {
            waves: vec![wave(10, met), wave(1, met)],
            ..Default::default()
        };
        assert_eq!(
            of_driven_wave(Outcome::Propagated, &waves),
            Outcome::Annihilated
        );
        assert_eq!(of_driven_wave(Outcome::Diverged, &waves), Outcome::Diverged);
        // Only the driven wave's fate counts: a wall born elsewhere that
        // annihilated leaves a driven wave that reached the end propagated.
        let ended = Waves {
            waves: vec![wave(1, Fate::End), wave(6, met), wave(7, met)],
            ..Default::default()
        };
        assert_eq!(
            of_driven_wave(Outcome::Propagated, &ended),
            Outcome::Propagated
        );
        assert_eq!(
            Outcome::from_name("annihilated"),
            Some(Outcome::Annihilated)
        );
        assert_eq!(Outcome::from_name("failed"), Some(Outcome::Failed));
    }
}
