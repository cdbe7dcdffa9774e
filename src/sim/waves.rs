//! The domain walls of a run, each one a wave with its own record (docs/sweeps.md).
//!
//! A block's polarisation sign is that of sin θ_n (docs/model.md). A wall
//! sits in gap g (between blocks g + 1 and g + 2, one-based) wherever two
//! neighbouring blocks have opposite signs. Every sign change of a block
//! moves, creates or removes walls, and the tracker follows each wall from
//! its birth:
//!
//! - block 1 (driven) changes sign: a new wave is launched into gap 1; if a
//!   wall was already there, the two annihilate at once;
//! - a block with a wall on one side only: that wall moves across it (the
//!   wave arrives at the block);
//! - a block with walls on both sides: the two waves annihilate, each with
//!   the other, at that block and time;
//! - a block with no wall beside it (a flip on its own, such as the free
//!   bottom block of a long kink chain): two walls are born there (one at
//!   the bottom block), waves of their own, launched from that block.
//!
//! A wall is a **kink** when the block above it has negative polarisation
//! and the block below positive (the wall that the drive of a chain at
//! α > 0 launches), an **antikink** the other way round; a wall keeps its
//! kind as it moves.
//!
//! The sign changes are found between two observations of the state as
//! the root of the cubic Hermite interpolant of θ through the multiple of
//! π crossed (as `observables::ArrivalDetector`). Fed after every step,
//! every change is seen at its time; fed at coarser intervals (a sweep's
//! checks, every 5 τ), a block that changes sign twice between two
//! observations is not seen to change, and the time of a block's first
//! change is taken from the arrival detector, which sees every step.
//! Single runs (`sim::run`) feed it after every step when the
//! drive has several flips; with one flip, the one driven wave's times are
//! the arrival detector's (exact), and it is fed at the checks, which keeps
//! the fused kernel's speed (a spontaneous wall's later sign changes are
//! then interpolated between checks).

use super::observables::hermite_root;
use serde::{Deserialize, Serialize};

/// Kink or antikink (see the module's doc).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum WaveKind {
    Kink,
    Antikink,
}

impl WaveKind {
    /// The wave the first flip of block 1 launches from the ground state
    /// of sign α (docs/model.md): block 1 turned from α to −α leaves
    /// negative polarisation above positive for α > 0, a kink; the
    /// reverse, an antikink, for α < 0. The one rule the program names
    /// waves by; α = 0 (no ground state to flip) is named a kink.
    pub fn launched(alpha: f64) -> Self {
        if alpha >= 0.0 {
            Self::Kink
        } else {
            Self::Antikink
        }
    }

    /// The other kind: the wave the next flip of block 1 launches.
    pub fn other(self) -> Self {
        match self {
            Self::Kink => Self::Antikink,
            Self::Antikink => Self::Kink,
        }
    }

    /// "kink" or "antikink".
    pub fn name(self) -> &'static str {
        match self {
            Self::Kink => "kink",
            Self::Antikink => "antikink",
        }
    }
}

/// What became of a wave.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", tag = "fate")]
pub enum Fate {
    /// It reached the end of the chain in its direction: block N − 1
    /// (block N turns its own way: `Waves::block_n`), or block 2 for a
    /// wave running up.
    End,
    /// The state proved it stopped (rest at a stable equilibrium, docs/sweeps.md), at its `front`.
    Stopped,
    /// It met wave `with` (index into `waves`) at `block`, time `at`.
    Annihilated { with: usize, at: f64, block: usize },
    /// None of these by the end of the run.
    Undecided,
}

/// One domain wall's record.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Wave {
    pub kind: WaveKind,
    /// Block whose sign change launched it (1 for the drive).
    pub origin: usize,
    /// Time of that sign change, τ.
    pub launched_at: f64,
    /// Per block, the first time this wave's wall crossed it (the
    /// block's sign change), `None` where it never did.
    pub arrival_times: Vec<Option<f64>>,
    /// The block the wave reached last (one-based; its origin at first).
    pub front: usize,
    #[serde(flatten)]
    pub fate: Fate,
}

/// Block N's own fate, beside the waves': the times its polarisation
/// changed sign (the free bottom block turns its own way).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
pub struct BlockN {
    pub sign_changes: Vec<f64>,
    /// θ_N at the end of the run, degrees, wrapped to (−180°, 180°].
    pub final_theta_deg: f64,
}

/// Every wave of a run, in launch order, and block N's fate.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
pub struct Waves {
    pub waves: Vec<Wave>,
    pub block_n: BlockN,
}

/// Follows the walls of one run (see the module's doc).
#[derive(Debug, Clone)]
pub struct WaveTracker {
    /// Current polarisation sign of each block (+1 or −1).
    sign: Vec<f64>,
    /// Whether each block has changed sign yet (its first change takes
    /// its time from the arrival detector when fed coarsely).
    changed: Vec<bool>,
    /// The wave whose wall sits in each gap (N − 1 gaps).
    wall: Vec<Option<usize>>,
    prev_t: f64,
    prev_theta: Vec<f64>,
    prev_omega: Vec<f64>,
    waves: Vec<Wave>,
    /// Per wave, whether it was launched running up the chain.
    upward: Vec<bool>,
    block_n: Vec<f64>,
}

fn sign_of(theta: f64) -> f64 {
    if crate::model::trig::sin_cos(theta).0 >= 0.0 {
        1.0
    } else {
        -1.0
    }
}

/// Time in [t0, t1] at which θ crossed the multiple of π between θ0 and
/// θ1 (the one next to θ1 on θ0's side), from the cubic Hermite
/// interpolant.
fn crossing_time(start: (f64, f64, f64), end: (f64, f64, f64)) -> f64 {
    use std::f64::consts::PI;
    let ((t0, th0, om0), (t1, th1, om1)) = (start, end);
    let c = if th1 < th0 {
        (th1 / PI).ceil() * PI
    } else {
        (th1 / PI).floor() * PI
    };
    let h = t1 - t0;
    if th1 == c {
        return t1;
    }
    t0 + hermite_root(th0 - c, h * om0, th1 - c, h * om1) * h
}

impl WaveTracker {
    /// A tracker starting from state (`q`, `v`) at `t0`: walls wherever
    /// neighbouring blocks start with opposite signs are waves launched at
    /// `t0` from the block below them.
    pub fn new(t0: f64, q: &[f64], v: &[f64]) -> Self {
        let n = q.len() / 3;
        let theta: Vec<f64> = q.chunks_exact(3).map(|b| b[2]).collect();
        let sign: Vec<f64> = theta.iter().map(|&t| sign_of(t)).collect();
        let mut me = Self {
            wall: vec![None; n.saturating_sub(1)],
            changed: vec![false; n],
            prev_t: t0,
            prev_omega: v.chunks_exact(3).map(|b| b[2]).collect(),
            prev_theta: theta,
            waves: Vec::new(),
            upward: Vec::new(),
            block_n: Vec::new(),
            sign,
        };
        for g in 0..n.saturating_sub(1) {
            if me.sign[g] != me.sign[g + 1] {
                let id = me.launch(g, g + 1, t0);
                me.wall[g] = Some(id);
            }
        }
        me
    }

    fn n(&self) -> usize {
        self.sign.len()
    }

    /// A new wave in gap `gap`, launched by block `block` (zero-based).
    fn launch(&mut self, gap: usize, block: usize, t: f64) -> usize {
        let kind = if self.sign[gap] < 0.0 {
            WaveKind::Kink
        } else {
            WaveKind::Antikink
        };
        let mut arrival_times = vec![None; self.n()];
        arrival_times[block] = Some(t);
        self.waves.push(Wave {
            kind,
            origin: block + 1,
            launched_at: t,
            arrival_times,
            front: block + 1,
            fate: Fate::Undecided,
        });
        // A wall above its launching block runs up.
        self.upward.push(gap < block);
        self.waves.len() - 1
    }

    fn arrive(&mut self, id: usize, block: usize, t: f64) {
        let w = &mut self.waves[id];
        w.arrival_times[block].get_or_insert(t);
        w.front = block + 1;
    }

    fn annihilate(&mut self, a: usize, b: usize, block: usize, t: f64) {
        self.waves[a].fate = Fate::Annihilated {
            with: b,
            at: t,
            block: block + 1,
        };
        self.waves[b].fate = Fate::Annihilated {
            with: a,
            at: t,
            block: block + 1,
        };
    }

    /// Block `i` (zero-based) changed sign at `t`.
    fn flip(&mut self, i: usize, t: f64) {
        let n = self.n();
        self.sign[i] = -self.sign[i];
        self.changed[i] = true;
        if i == n - 1 {
            self.block_n.push(t);
        }
        let left = if i > 0 { self.wall[i - 1] } else { None };
        let right = if i + 1 < n { self.wall[i] } else { None };
        if i == 0 {
            // The drive launches a wave; a wall already in gap 1 meets it.
            let id = self.launch(0, 0, t);
            match right {
                Some(old) => {
                    self.wall[0] = None;
                    self.arrive(old, 0, t);
                    self.annihilate(old, id, 0, t);
                }
                None => self.wall[0] = Some(id),
            }
            return;
        }
        match (left, right) {
            (Some(a), Some(b)) => {
                self.arrive(a, i, t);
                self.arrive(b, i, t);
                self.annihilate(a, b, i, t);
                self.wall[i - 1] = None;
                self.wall[i] = None;
            }
            (Some(a), None) => {
                self.arrive(a, i, t);
                self.wall[i - 1] = None;
                if i + 1 < n {
                    self.wall[i] = Some(a);
                }
            }
            (None, Some(b)) => {
                self.arrive(b, i, t);
                self.wall[i] = None;
                self.wall[i - 1] = Some(b);
            }
            (None, None) => {
                // A flip on its own: walls on both sides (one at the bottom).
                let up = self.launch(i - 1, i, t);
                self.wall[i - 1] = Some(up);
                if i + 1 < n {
                    let down = self.launch(i, i, t);
                    self.wall[i] = Some(down);
                }
            }
        }
    }

    /// Feeds the state (`q`, `v`) at `t`, the next observation after the
    /// last one. `first_arrival` (one per block, the arrival detector's
    /// record, or empty) gives the time of a block's first sign change
    /// when it lies in (last observation, `t`].
    pub fn observe(&mut self, t: f64, q: &[f64], v: &[f64], first_arrival: &[Option<f64>]) {
        let t0 = self.prev_t;
        let mut events: Vec<(f64, usize)> = Vec::new();
        for (i, (qb, vb)) in q.chunks_exact(3).zip(v.chunks_exact(3)).enumerate() {
            let (th, om) = (qb[2], vb[2]);
            if sign_of(th) != self.sign[i] {
                let exact = first_arrival
                    .get(i)
                    .copied()
                    .flatten()
                    .filter(|&a| !self.changed[i] && a > t0 && a <= t);
                let at = exact.unwrap_or_else(|| {
                    crossing_time((t0, self.prev_theta[i], self.prev_omega[i]), (t, th, om))
                });
                events.push((at, i));
            }
            (self.prev_theta[i], self.prev_omega[i]) = (th, om);
        }
        self.prev_t = t;
        events.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        for (at, i) in events {
            self.flip(i, at);
        }
    }

    /// The record at the end of the run, at state `q`: a wave that reached
    /// the end of the chain in its direction ends there; the others are
    /// `stopped` when `at_rest` (the state proved at rest at a stable
    /// equilibrium), else `undecided`.
    pub fn finish(&self, q: &[f64], at_rest: bool) -> Waves {
        let n = self.n();
        let mut waves = self.waves.clone();
        for (w, &up) in waves.iter_mut().zip(&self.upward) {
            if matches!(w.fate, Fate::Annihilated { .. }) {
                continue;
            }
            let reached_end = if up {
                w.front <= 2
            } else {
                n >= 2 && w.front >= n - 1
            };
            w.fate = if reached_end {
                Fate::End
            } else if at_rest {
                Fate::Stopped
            } else {
                Fate::Undecided
            };
        }
        Waves {
            waves,
            block_n: BlockN {
                sign_changes: self.block_n.clone(),
                final_theta_deg: q
                    .chunks_exact(3)
                    .last()
                    .map_or(0.0, |b| super::observables::wrap_deg(b[2].to_degrees())),
            },
        }
    }

    /// Whether every wave has a fate other than `undecided` given the rest
    /// test's answer (for `t_end = "auto"`).
    pub fn all_decided(&self, q: &[f64], at_rest: bool) -> bool {
        self.finish(q, at_rest)
            .waves
            .iter()
            .all(|w| w.fate != Fate::Undecided)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A chain of `n` blocks whose angles are set by `theta(t)`; fed every
    /// `dt` up to `t_end`.
    fn run(n: usize, theta: impl Fn(usize, f64) -> f64, dt: f64, t_end: f64) -> WaveTracker {
        let state = |t: f64| {
            let q: Vec<f64> = (0..n).flat_map(|i| [0.0, 0.0, theta(i, t)]).collect();
            let v: Vec<f64> = (0..n)
                .flat_map(|i| [0.0, 0.0, (theta(i, t + 1e-6) - theta(i, t - 1e-6)) / 2e-6])
                .collect();
            (q, v)
        };
        let (q, v) = state(0.0);
        let mut tr = WaveTracker::new(0.0, &q, &v);
        let steps = (t_end / dt).round() as usize;
        for k in 1..=steps {
            let t = k as f64 * dt;
            let (q, v) = state(t);
            tr.observe(t, &q, &v, &[]);
        }
        tr
    }

    /// Block i turns from +1 rad to −1 rad linearly over [t_i − 1, t_i + 1].
    fn turn(t: f64, at: f64) -> f64 {
        1.0 - ((t - (at - 1.0)) / 2.0).clamp(0.0, 1.0) * 2.0
    }

    #[test]
    fn the_naming_rule_is_the_trackers() {
        // Block 1 flips from α to −α: the tracker's first wave is the kind
        // `WaveKind::launched(α)` names, for both signs.
        for alpha in [1.0f64, -1.0] {
            let tr = run(
                4,
                |i, t| if i == 0 { alpha * turn(t, 10.0) } else { alpha },
                0.3,
                20.0,
            );
            let q: Vec<f64> = (0..4)
                .flat_map(|i| [0.0, 0.0, if i == 0 { -alpha } else { alpha }])
                .collect();
            let w = tr.finish(&q, false);
            assert_eq!(w.waves[0].kind, WaveKind::launched(alpha), "α = {alpha}");
            assert_eq!(
                WaveKind::launched(alpha).other(),
                WaveKind::launched(-alpha)
            );
        }
        assert_eq!(WaveKind::launched(60.0).name(), "kink");
        assert_eq!(WaveKind::launched(-60.0).name(), "antikink");
    }

    #[test]
    fn a_kink_crosses_the_chain() {
        let tr = run(5, |i, t| turn(t, 10.0 * (i + 1) as f64), 0.3, 60.0);
        let w = tr.finish(&[0.0; 15], false);
        assert_eq!(w.waves.len(), 1);
        let k = &w.waves[0];
        assert_eq!(k.kind, WaveKind::Kink);
        assert_eq!(k.front, 5);
        assert_eq!(k.fate, Fate::End);
        for (i, a) in k.arrival_times.iter().enumerate() {
            assert!((a.unwrap() - 10.0 * (i + 1) as f64).abs() < 1e-9);
        }
        assert_eq!(w.block_n.sign_changes.len(), 1);
    }

    #[test]
    fn two_walls_meeting_annihilate() {
        // Block 1 at 10, block 5 on its own at 12; block 2 at 20, block 4
        // at 22; block 3 at 30: the two meet at block 3.
        let at = [10.0, 20.0, 30.0, 22.0, 12.0, 1e9, 1e9];
        let tr = run(7, |i, t| turn(t, at[i]), 0.25, 40.0);
        let w = tr.finish(&[0.0; 21], false);
        // The drive's kink, and two from block 5 (one up, one down).
        assert_eq!(w.waves.len(), 3);
        assert_eq!(w.waves[0].kind, WaveKind::Kink);
        let Fate::Annihilated { with, at, block } = w.waves[0].fate else {
            panic!("{:?}", w.waves[0].fate)
        };
        assert_eq!(block, 3);
        assert!((at - 30.0).abs() < 1e-9);
        assert_eq!(w.waves[with].origin, 5);
        assert_eq!(w.waves[with].kind, WaveKind::Antikink);
        // The one running down from block 5 stops short of block 6.
        let down = 3 - with;
        assert_eq!(w.waves[down].fate, Fate::Undecided);
        assert_eq!(tr.finish(&[0.0; 21], true).waves[down].fate, Fate::Stopped);
    }
}
