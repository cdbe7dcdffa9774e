//! Impacts between blocks with thickness (docs/formats.md, "Impacts";
//! `model::contact`): the clatter of the toy as built, as events.
//!
//! An impact is a pair of blocks whose contact starts: at the end of a
//! step some corner of one lies inside the other (penetration > 0) and at
//! the end of the step before none did. It is decided from the state the
//! run reaches after every step, not from the sampled frames.
//!
//! Its time and speed are read back from the state before the step, in
//! which the two blocks did not touch (no contact force had acted yet):
//! of the corners inside the other block after the step, the one that
//! reaches its edge first, at t₀ + g/u (g ≥ 0 its gap outside that edge's
//! line at t₀, u its approach speed −v_rel · n there; the step's end where
//! u ≤ 0, a corner that slid in as the other block turned). The impact's
//! speed is that u (0 for a corner that slid in). Both are
//! the free flight's to first order in the step: the time within
//! ½ a dt²/u, the speed within a dt (a the pair's relative acceleration
//! before contact, by gravity and the ribbons).

use crate::model::Ladder;
use crate::model::contact::{Blocks, Contact};
use crate::model::outline::Outline;
use serde::Serialize;

/// One impact: when, which two blocks, how fast.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Impact {
    /// Time of first contact, in τ.
    pub t: f64,
    /// The two blocks, one-based, the upper (lower number) first.
    pub blocks: [usize; 2],
    /// Normal relative speed at the impact, in s per τ.
    pub speed: f64,
}

/// Watches a run of a ladder whose blocks may touch for impacts, step
/// after step ([`ImpactWatch::observe`]).
#[derive(Debug, Clone)]
pub struct ImpactWatch {
    blocks: Blocks,
    outline: Outline,
    contact: Contact,
    prev_t: f64,
    prev_q: Vec<f64>,
    prev_v: Vec<f64>,
    /// Whether pair (i, j), i < j, touched at the last step's end
    /// (index i n + j).
    touching: Vec<bool>,
    now: Vec<bool>,
    pub impacts: Vec<Impact>,
}

impl ImpactWatch {
    /// A watch from the state (q, v) at `t0`, for a ladder with contact;
    /// `None` for any other (nothing to watch, nothing to pay).
    pub fn new(ladder: &Ladder, t0: f64, q: &[f64], v: &[f64]) -> Option<Self> {
        let built = ladder.built?;
        let contact = built.contact?;
        let n = ladder.n();
        let mut w = Self {
            blocks: ladder.blocks(),
            outline: built.ribbons.outline,
            contact,
            prev_t: t0,
            prev_q: q.to_vec(),
            prev_v: v.to_vec(),
            touching: vec![false; n * n],
            now: vec![false; n * n],
            impacts: Vec::new(),
        };
        // Pairs touching at the start are no impacts.
        w.mark(q, v);
        std::mem::swap(&mut w.touching, &mut w.now);
        Some(w)
    }

    /// Marks in `now` every pair touching at (q, v).
    fn mark(&mut self, q: &[f64], v: &[f64]) {
        let n = self.blocks.n;
        self.now.fill(false);
        let now = &mut self.now;
        self.contact
            .for_each_touch(self.blocks, &self.outline, q, v, |t| {
                now[t.a.min(t.b) * n + t.a.max(t.b)] = true;
            });
    }

    /// Feeds the state at the end of a step ending at `t`.
    pub fn observe(&mut self, t: f64, q: &[f64], v: &[f64]) {
        let n = self.blocks.n;
        self.mark(q, v);
        if self.now.iter().zip(&self.touching).any(|(a, b)| *a && !*b) {
            let mut first: Vec<Option<(f64, f64)>> = vec![None; n * n];
            let (o, t0, dt) = (self.outline, self.prev_t, t - self.prev_t);
            let (pq, pv) = (&self.prev_q, &self.prev_v);
            let (now, before) = (&self.now, &self.touching);
            self.contact.for_each_touch(self.blocks, &o, q, v, |c| {
                let k = c.a.min(c.b) * n + c.a.max(c.b);
                if !now[k] || before[k] {
                    return;
                }
                let (gap, u) = Contact::corner_gap(&o, (c.a, c.corner), (c.b, c.edge), pq, pv);
                let at = if u > 0.0 {
                    t0 + (gap.max(0.0) / u).min(dt)
                } else {
                    t
                };
                if first[k].is_none_or(|(t1, _)| at < t1) {
                    first[k] = Some((at, u.max(0.0)));
                }
            });
            let mut new: Vec<Impact> = (0..n * n)
                .filter_map(|k| {
                    first[k].map(|(at, u)| Impact {
                        t: at,
                        blocks: [k / n + 1, k % n + 1],
                        speed: u,
                    })
                })
                .collect();
            new.sort_by(|a, b| a.t.total_cmp(&b.t));
            self.impacts.extend(new);
        }
        std::mem::swap(&mut self.touching, &mut self.now);
        self.prev_t = t;
        self.prev_q.copy_from_slice(q);
        self.prev_v.copy_from_slice(v);
    }
}
