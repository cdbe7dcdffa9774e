//! Inextensible ribbons under Moreau's time-stepping (docs/experiments.md,
//! "Inextensible ribbons"): a ribbon is a one-sided length constraint
//! L(q) ≤ ℓ whose tension acts only as impulses P ≥ 0 taken once a step.
//!
//! At the step's midpoint q_m, after the smooth forces' kick, the
//! velocities v are corrected by v ← v − B Gᵀ P, so that each ribbon `k`
//! predicted at or past its length at the step's end (L − ℓ + ½ h L̇ ≥ 0)
//! ends it no longer than its length:
//!
//! w = A P − (L̇ + c) ≥ 0,  P ≥ 0,  P w = 0,  A = G B Gᵀ,
//!
//! c = 2 min(L − ℓ, 0)/h at the midpoint: a slack ribbon may close its
//! gap within the step, and one already past its length (the scheme's
//! drift) is kept from stretching further but not pulled back. Pulling
//! it back, even by a fifth of its stretch a step, turned the drift into
//! rebounds that made the run hang on rounding (docs/experiments.md,
//! "Inextensible ribbons"). G is the ribbons' rows (`model::taut`), B the
//! blocks' inverse mass with added mass. A ribbon that reaches its length
//! while stretching is so stopped without rebound, as an inextensible
//! string's impulsive tension stops it (Routh, *Dynamics of a System of
//! Rigid Bodies*, 1905); a ribbon left slack gets no impulse. The problem
//! is solved exactly by active sets (A is banded: a ribbon's row touches
//! the two blocks of its junction).

use crate::model::media;
use crate::model::outline::Pose;
use crate::model::ribbons::Span;
use crate::model::taut::{Row, row, solve_banded};

/// A ribbon slacker than this (in s) at the midpoint, and not
/// lengthening, is left out of the step's problem: within a step no
/// impulse elsewhere could take it to its length. Leaving in a ribbon
/// that does not pull changes nothing (it gets P = 0), so the margin is
/// generous: a tenth of s, against ribbons that move by ~1e-3 s a step.
pub const SLACK_MARGIN: f64 = 0.1;

/// The blocks' inverse mass: added mass m_a, inertia j (with added
/// inertia), and which blocks are free.
#[derive(Debug, Clone, Copy)]
pub struct InverseMass<'a> {
    pub added_mass: f64,
    pub inertia: f64,
    pub frames: &'a [([f64; 2], [f64; 2])],
    pub free: &'a [bool],
}

impl InverseMass<'_> {
    /// B Q of block `i` (zero for a prescribed block).
    #[inline]
    fn apply(&self, i: usize, q: [f64; 3]) -> [f64; 3] {
        if !self.free[i] {
            return [0.0; 3];
        }
        let (ma, j) = (self.added_mass, self.inertia);
        media::block_acceleration_framed(ma, j, self.frames[i], [0.0; 3], q)
    }
}

/// The ribbons' rows at the last midpoint, the impulses' scratch, and
/// what the run counts.
#[derive(Debug, Clone, Default)]
pub struct Taut {
    rows: Vec<Row>,
    /// The ribbons in the problem (`index`), their A (row major) and
    /// right-hand sides, and scratch for one solve.
    index: Vec<usize>,
    full: Vec<f64>,
    rhs: Vec<f64>,
    active: Vec<bool>,
    a: Vec<f64>,
    b: Vec<f64>,
    /// The active ribbons' positions and their solution (scratch).
    pos: Vec<usize>,
    sol: Vec<f64>,
    /// Ribbon-steps with an impulse, problems A could not solve
    /// (singular), active-set iterations.
    pub impulses: u64,
    pub singular: u64,
    pub iterations: u64,
    /// The largest L − ℓ seen at a midpoint (s): the drift.
    pub max_stretch: f64,
    /// The last step's impulses: (ribbon, P > 0).
    pub last: Vec<(usize, f64)>,
    /// The ribbons that pulled at the last step, where the next step's
    /// active set starts.
    pulled: Vec<bool>,
}

/// Why a step's impulses could not be found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unsolved {
    /// A of the ribbons taken as pulling is singular (the banded
    /// Cholesky met a pivot that is not positive): two taut ribbons
    /// pull along one line.
    Singular,
    /// The active-set search did not settle within its passes.
    Unsettled {
        /// The passes it made (4m + 4 for m ribbons in the problem).
        passes: usize,
    },
}

impl std::fmt::Display for Unsolved {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Unsolved::Singular => f.write_str("two taut ribbons pull along the same line"),
            Unsolved::Unsettled { passes } => write!(
                f,
                "the search for the ribbons that pull did not settle in {passes} passes"
            ),
        }
    }
}

fn dot3(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

impl Taut {
    /// Every ribbon's row at (poses, v): rests per ribbon of a junction.
    fn make_rows(&mut self, poses: &[Pose], spans: &[Span], rests: [f64; 2], v: &[f64]) {
        self.rows.clear();
        for (k, s) in spans.iter().enumerate() {
            let i = k / 2;
            let r = row(s, rests[k % 2], (&poses[i], &poses[i + 1]), i, v);
            self.max_stretch = self.max_stretch.max(r.gap);
            self.rows.push(r);
        }
    }

    /// A = G B Gᵀ over the ribbons `index`, into `full`.
    fn assemble(&mut self, inv: &InverseMass) {
        let m = self.index.len();
        self.full.clear();
        self.full.resize(m * m, 0.0);
        for (x, &j) in self.index.iter().enumerate() {
            for (y, &l) in self.index.iter().enumerate().skip(x) {
                let (rj, rl) = (&self.rows[j], &self.rows[l]);
                let (bj, bl) = (j / 2, l / 2);
                let s = if bj == bl {
                    dot3(rj.upper, inv.apply(bj, rl.upper))
                        + dot3(rj.lower, inv.apply(bj + 1, rl.lower))
                } else if bl == bj + 1 {
                    dot3(rj.lower, inv.apply(bl, rl.upper))
                } else {
                    break;
                };
                self.full[x * m + y] = s;
                self.full[y * m + x] = s;
            }
        }
    }

    /// Solves A P = b on the active ribbons (positions in `index`),
    /// leaving P in `b` (position order, 0 where inactive). False where
    /// A is singular there.
    fn solve_active(&mut self) -> bool {
        let m = self.index.len();
        self.pos.clear();
        self.pos.extend((0..m).filter(|&x| self.active[x]));
        let p = self.pos.len();
        self.a.clear();
        for &x in &self.pos {
            self.a
                .extend(self.pos.iter().map(|&y| self.full[x * m + y]));
        }
        self.sol.clear();
        self.sol.extend(self.pos.iter().map(|&x| self.rhs[x]));
        if !solve_banded(&mut self.a, &mut self.sol, p, 3) {
            return false;
        }
        self.b.clear();
        self.b.resize(m, 0.0);
        for (&x, &l) in self.pos.iter().zip(&self.sol) {
            self.b[x] = l;
        }
        true
    }

    /// The complementarity problem P ≥ 0, w = A P − b ≥ 0, P w = 0 over
    /// `index` by active sets (the most negative P out, else the most
    /// negative w in), started from the ribbons that pulled at the last
    /// step. P into `b`.
    fn complementarity(&mut self) -> Result<(), Unsolved> {
        let m = self.index.len();
        self.active.clear();
        let pulled = &self.pulled;
        self.active.extend(self.index.iter().map(|&k| pulled[k]));
        let passes = 4 * m + 4;
        for _ in 0..passes {
            self.iterations += 1;
            if !self.solve_active() {
                return Err(Unsolved::Singular);
            }
            let neg = (0..m).filter(|&x| self.active[x] && self.b[x] < 0.0);
            if let Some(x) = neg.min_by(|&x, &y| self.b[x].total_cmp(&self.b[y])) {
                self.active[x] = false;
                continue;
            }
            let w = |x: usize| -> f64 {
                (0..m)
                    .map(|y| self.full[x * m + y] * self.b[y])
                    .sum::<f64>()
                    - self.rhs[x]
            };
            let viol = (0..m)
                .filter(|&x| !self.active[x])
                .map(|x| (x, w(x), 1e-12 * (1.0 + self.rhs[x].abs())))
                .filter(|&(_, w, tol)| w < -tol);
            match viol.min_by(|a, b| a.1.total_cmp(&b.1)) {
                Some((x, _, _)) => self.active[x] = true,
                None => return Ok(()),
            }
        }
        Err(Unsolved::Unsettled { passes })
    }

    /// The step's impulses (module doc) with the rows at the midpoint
    /// (`poses`, `spans`) and the velocities `v` after the smooth kick,
    /// applied to `v`; why not where the problem could not be solved.
    pub fn impulses(
        &mut self,
        (poses, spans): (&[Pose], &[Span]),
        rests: [f64; 2],
        inv: &InverseMass,
        h: f64,
        v: &mut [f64],
    ) -> Result<(), Unsolved> {
        self.make_rows(poses, spans, rests, v);
        self.last.clear();
        self.pulled.resize(spans.len(), false);
        let mut index = std::mem::take(&mut self.index);
        index.clear();
        let rows = &self.rows;
        let near = |r: &Row| r.gap + h * r.rate.max(0.0) >= -SLACK_MARGIN;
        index.extend((0..rows.len()).filter(|&k| near(&rows[k])));
        self.index = index;
        if self.index.is_empty() {
            return Ok(());
        }
        self.assemble(inv);
        self.rhs.clear();
        for &k in &self.index {
            let g = self.rows[k].gap.min(0.0);
            self.rhs.push(self.rows[k].rate + 2.0 * g / h);
        }
        if let Err(why) = self.complementarity() {
            self.singular += 1;
            return Err(why);
        }
        for x in 0..self.index.len() {
            let (k, p) = (self.index[x], self.b[x]);
            self.pulled[k] = p > 0.0;
            if p > 0.0 {
                self.impulses += 1;
                self.apply(k, p, inv, v);
                self.last.push((k, p));
            }
        }
        Ok(())
    }

    /// v ← v − B Gᵀ P of ribbon `k`'s impulse `p`.
    fn apply(&self, k: usize, p: f64, inv: &InverseMass, v: &mut [f64]) {
        let r = self.rows[k];
        let i = k / 2;
        for (blk, g) in [(i, r.upper), (i + 1, r.lower)] {
            let dv = inv.apply(blk, [-p * g[0], -p * g[1], -p * g[2]]);
            for c in 0..3 {
                v[3 * blk + c] += dv[c];
            }
        }
    }
}

impl Taut {
    /// The last step's impulses' energy (module doc of
    /// `integrators::moreau`): the loss Σ P L̇(v̄) with v̄ = (v₀ + v₁)/2
    /// over every block, and the drive's part, Σ P ∂L/∂θ₁ θ̇₁(v̄) over
    /// the ribbons of junction 1 where block 1 is `driven`. (work, loss).
    pub fn energy(&self, v0: &[f64], v1: &[f64], driven: bool) -> (f64, f64) {
        let (mut work, mut lost) = (0.0, 0.0);
        for &(k, p) in &self.last {
            let r = &self.rows[k];
            let i = 3 * (k / 2);
            let rate = |v: &[f64]| {
                dot3(r.upper, [v[i], v[i + 1], v[i + 2]])
                    + dot3(r.lower, [v[i + 3], v[i + 4], v[i + 5]])
            };
            lost += 0.5 * p * (rate(v0) + rate(v1));
            if k < 2 && driven {
                work += 0.5 * p * r.upper[2] * (v0[2] + v1[2]);
            }
        }
        (work, lost)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A problem over `full` (m × m, row major) and `rhs`, started from
    /// the ribbons `pulled`.
    fn problem(full: Vec<f64>, rhs: Vec<f64>, pulled: Vec<bool>) -> Taut {
        let m = rhs.len();
        Taut {
            index: (0..m).collect(),
            full,
            rhs,
            pulled,
            ..Taut::default()
        }
    }

    /// Two ribbons along one line (A = [1 1; 1 1]) both taken as
    /// pulling: singular, and said so; started from neither, the search
    /// takes one and solves it (P = (1, 0)).
    #[test]
    fn a_singular_problem_is_named_singular() {
        let mut t = problem(vec![1.0, 1.0, 1.0, 1.0], vec![1.0, 1.0], vec![true, true]);
        assert_eq!(t.complementarity(), Err(Unsolved::Singular));
        let mut t = problem(vec![1.0, 1.0, 1.0, 1.0], vec![1.0, 1.0], vec![false, false]);
        assert_eq!(t.complementarity(), Ok(()));
        assert_eq!(t.b, [1.0, 0.0]);
        assert_eq!(
            Unsolved::Singular.to_string(),
            "two taut ribbons pull along the same line"
        );
    }

    /// The other cause names the passes the search made (no positive
    /// definite A built from ribbons has been seen to need them all; the
    /// message is what a run that did would say).
    #[test]
    fn an_unsettled_search_says_its_passes() {
        let why = Unsolved::Unsettled { passes: 8 };
        assert_eq!(
            why.to_string(),
            "the search for the ribbons that pull did not settle in 8 passes"
        );
    }
}
