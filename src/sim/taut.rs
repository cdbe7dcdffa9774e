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
//!
//! Before the impulses, the midpoint is moved back onto the stretched
//! ribbons' lengths (`Taut::project`): the same problem on the gaps,
//! μ ≥ 0, A μ − (L − ℓ) ≥ 0, complementary, q_m ← q_m − B Gᵀ μ, the
//! velocities untouched. The gaps the impulses see are the moved ones.

use crate::model::media;
use crate::model::outline::Pose;
use crate::model::ribbons::Span;
use crate::model::taut::{Row, factor_banded, row, solve_factored};

/// A ribbon slacker than this (in s) at the midpoint, and not
/// lengthening, is left out of the step's problem: within a step no
/// impulse elsewhere could take it to its length. Leaving in a ribbon
/// that does not pull changes nothing (it gets P = 0), so the margin is
/// generous: a tenth of s, against ribbons that move by ~1e-3 s a step.
pub const SLACK_MARGIN: f64 = 0.1;

/// A's half bandwidth in the ribbons' order: ribbon k's row touches the
/// blocks k/2 and k/2 + 1, which no ribbon more than 3 away touches.
const BAND: usize = 3;

/// The positions within A's band of position `x` among `m`.
fn band(x: usize, m: usize) -> std::ops::Range<usize> {
    x.saturating_sub(BAND)..(x + BAND + 1).min(m)
}

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
    /// B Gᵀ of each ribbon in the problem (by ribbon): its row's parts
    /// on the upper and the lower block, each times that block's B.
    bg: Vec<([f64; 3], [f64; 3])>,
    full: Vec<f64>,
    rhs: Vec<f64>,
    active: Vec<bool>,
    a: Vec<f64>,
    b: Vec<f64>,
    /// The active ribbons' positions and their solution (scratch).
    pos: Vec<usize>,
    /// The positions whose A `a` holds factored, where `full` has not
    /// changed since (the projection's last set is most often the
    /// impulses' first).
    factored: Option<Vec<usize>>,
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
    /// The projection's multipliers μ (scratch), and whether the last
    /// step moved any position.
    mu: Vec<f64>,
    pub projected: bool,
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

    /// A = G B Gᵀ over the ribbons `index`, into `full`, and each one's
    /// B Gᵀ into `bg`.
    fn assemble(&mut self, inv: &InverseMass) {
        let m = self.index.len();
        self.factored = None;
        self.bg.resize(self.rows.len(), ([0.0; 3], [0.0; 3]));
        for &k in &self.index {
            let (r, i) = (&self.rows[k], k / 2);
            self.bg[k] = (inv.apply(i, r.upper), inv.apply(i + 1, r.lower));
        }
        self.full.clear();
        self.full.resize(m * m, 0.0);
        for (x, &j) in self.index.iter().enumerate() {
            for (y, &l) in self.index.iter().enumerate().skip(x) {
                let (rj, bl) = (&self.rows[j], &self.bg[l]);
                let s = if j / 2 == l / 2 {
                    dot3(rj.upper, bl.0) + dot3(rj.lower, bl.1)
                } else if l / 2 == j / 2 + 1 {
                    dot3(rj.lower, bl.0)
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
        if self.factored.as_deref() != Some(&self.pos[..]) {
            // Only the band is read by the solve: two active positions
            // i, j more than BAND apart are at least as far apart among all.
            self.a.resize(p * p, 0.0);
            for (i, &x) in self.pos.iter().enumerate() {
                for j in band(i, p) {
                    self.a[i * p + j] = self.full[x * m + self.pos[j]];
                }
            }
            if !factor_banded(&mut self.a, p, BAND) {
                self.factored = None;
                return false;
            }
            let f = self.factored.get_or_insert_with(Vec::new);
            f.clear();
            f.extend_from_slice(&self.pos);
        }
        self.sol.clear();
        self.sol.extend(self.pos.iter().map(|&x| self.rhs[x]));
        solve_factored(&self.a, &mut self.sol, p, BAND);
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
                band(x, m)
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

    /// The step's projection and impulses (module doc) with the rows at
    /// the midpoint `qm` (`poses`, `spans`) and the velocities `v` after
    /// the smooth kick: `qm` moved back onto the stretched ribbons'
    /// lengths, the impulses applied to `v`; why not where a problem
    /// could not be solved.
    pub fn impulses(
        &mut self,
        (poses, spans): (&[Pose], &[Span]),
        rests: [f64; 2],
        inv: &InverseMass,
        h: f64,
        qm: &mut [f64],
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
        self.project(qm)?;
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
                self.apply(k, p, v);
                self.last.push((k, p));
            }
        }
        Ok(())
    }

    /// The midpoint q_m moved by −B Gᵀ μ, the least displacement (in
    /// the metric B⁻¹) that takes every stretched ribbon back to its
    /// length to first order, no ribbon in the problem stretched by it:
    /// μ ≥ 0, A μ − (L − ℓ) ≥ 0, complementary (the impulses' problem on
    /// the gaps). The velocities are not touched, so no ribbon rebounds;
    /// the gaps the impulses then see are the moved ones, A μ less.
    fn project(&mut self, qm: &mut [f64]) -> Result<(), Unsolved> {
        self.projected = false;
        if !self.index.iter().any(|&k| self.rows[k].gap > 0.0) {
            return Ok(());
        }
        self.rhs.clear();
        self.rhs
            .extend(self.index.iter().map(|&k| self.rows[k].gap));
        self.complementarity()?;
        let m = self.index.len();
        self.mu.clear();
        self.mu.extend_from_slice(&self.b);
        for x in 0..m {
            let k = self.index[x];
            if self.mu[x] > 0.0 {
                self.projected = true;
                self.apply(k, self.mu[x], qm);
            }
            let moved: f64 = band(x, m).map(|y| self.full[x * m + y] * self.mu[y]).sum();
            self.rows[k].gap -= moved;
        }
        Ok(())
    }

    /// v ← v − B Gᵀ P of ribbon `k`'s impulse `p` (or q ← q − B Gᵀ μ),
    /// with its B Gᵀ from `assemble` (zero on a prescribed block).
    fn apply(&self, k: usize, p: f64, v: &mut [f64]) {
        let (upper, lower) = self.bg[k];
        let i = 3 * (k / 2);
        for c in 0..3 {
            v[i + c] -= p * upper[c];
            v[i + 3 + c] -= p * lower[c];
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

    /// A problem of two ribbons of one junction (blocks 0 and 1, B = 1)
    /// with rows `g` and gaps `gap`, all in the problem, none pulled.
    fn junction(g: [[f64; 6]; 2], gap: [f64; 2]) -> Taut {
        let rows: Vec<Row> = (0..2)
            .map(|k| Row {
                upper: [g[k][0], g[k][1], g[k][2]],
                lower: [g[k][3], g[k][4], g[k][5]],
                rate: 0.0,
                gap: gap[k],
            })
            .collect();
        let dot6 = |a: &[f64; 6], b: &[f64; 6]| (0..6).map(|c| a[c] * b[c]).sum::<f64>();
        let full = vec![
            dot6(&g[0], &g[0]),
            dot6(&g[0], &g[1]),
            dot6(&g[1], &g[0]),
            dot6(&g[1], &g[1]),
        ];
        let bg = (0..2).map(|k| (rows[k].upper, rows[k].lower)).collect();
        Taut {
            rows,
            bg,
            index: vec![0, 1],
            full,
            pulled: vec![false, false],
            ..Taut::default()
        }
    }

    /// The projection takes a stretched ribbon back to its length (to
    /// first order: G Δq = −(L − ℓ)) by Δq = −B Gᵀ μ, leaves a slack one
    /// that it does not stretch out of the problem, and takes both where
    /// moving one would stretch the other; the velocities are not its.
    #[test]
    fn the_projection_takes_a_stretched_ribbon_back_to_its_length() {
        let g = [
            [1.0, 0.0, 0.0, -1.0, 0.0, 0.0],
            [-0.5, 0.5, 0.0, 0.5, -0.5, 0.0],
        ];
        // Ribbon 0 stretched by 2e-3, ribbon 1 slack by 5e-3: A = [2 −1; −1
        // 1], μ = (1e-3, 0), ribbon 1 then slack by 4e-3.
        let mut t = junction(g, [2e-3, -5e-3]);
        let mut q = [0.0; 6];
        t.project(&mut q).unwrap();
        let near = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-18);
        assert!(t.projected);
        assert!(near(&t.mu, &[1e-3, 0.0]), "{:?}", t.mu);
        assert!(near(&q, &[-1e-3, 0.0, 0.0, 1e-3, 0.0, 0.0]), "{q:?}");
        let gaps = [t.rows[0].gap, t.rows[1].gap];
        assert!(near(&gaps, &[0.0, -4e-3]), "{gaps:?}");
        // Ribbon 1 slack by only 5e-4: moving ribbon 0 alone would stretch
        // it (by 5e-4), so both are taken back: A μ = (2e-3, −5e-4), μ =
        // (1.5e-3, 1e-3).
        let mut t = junction(g, [2e-3, -5e-4]);
        let mut q = [0.0; 6];
        t.project(&mut q).unwrap();
        assert!(near(&t.mu, &[1.5e-3, 1e-3]), "{:?}", t.mu);
        for r in &t.rows {
            assert!(r.gap.abs() < 1e-18, "{}", r.gap);
        }
        // Nothing stretched: nothing moves.
        let mut t = junction(g, [-1e-3, -5e-4]);
        let mut q = [0.0; 6];
        t.project(&mut q).unwrap();
        assert!(!t.projected);
        assert_eq!(q, [0.0; 6]);
    }
}
