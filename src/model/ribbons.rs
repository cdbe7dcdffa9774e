//! Ribbons that wrap round blocks with thickness (docs/experiments.md,
//! "The toy as built"; the supplement's "2-1" connection): the links of a
//! Jacob's ladder as built, in place of the paper's springs.
//!
//! A ribbon joins block n (upper) and block n + 1 (lower). On each it is
//! glued at an anchor, a point of the outline (`outline`): edge k at a
//! fraction f along it. From the anchor it may lie along the outline and
//! wrap round corners, then crosses a straight free span to the other
//! block, wraps round its corners and ends at its anchor there. Its
//! length is
//!
//! L = (wrapped length on n) + |E − D| + (wrapped length on n + 1),
//!
//! D and E the points where the free span leaves the two outlines: the
//! span is their common tangent. The ribbon leaves an anchor on a face
//! straight away when the span points out of the face (e · n ≥ 0), an
//! anchor at a corner when the span points out of either edge there, and
//! it leaves a corner it has wrapped when the span does not point back
//! along the edge it came by (e · d_in ≥ 0); else it wraps on (`tangent`:
//! a tie, as where two corners coincide, counts as leaving). The two
//! ways round from an anchor give two candidate paths; the ribbon takes
//! the shorter (where the other block is behind the anchor, a real
//! ribbon keeps the way round it came by: the two agree until the other
//! block crosses the line where both ways are equally long).
//!
//! Penalty contact lets a corner of one block press into the other (by at
//! most a tenth of the thickness, `contact::MAX_OVERLAP`). Where such a
//! corner is the span's end, the tests above would send the ribbon round
//! the far corners (L jumping by a block's length); the ribbon leaves
//! instead from the candidate whose next edge is the one nearest to the
//! point pressed in, so L stays continuous as the point crosses that edge
//! (its residual jump, across a corner's bisector inside the block, is a
//! few times the overlap).
//!
//! The tangent points are corners or anchors, fixed in their blocks, so
//! L is a function of the two poses whose derivative is that of |E − D|
//! with D and E held in their blocks: by the envelope theorem the tension
//! T = κ max(0, L − ℓ) acts along the free span at its two tangent
//! points, on n at D along e = (E − D)/|E − D| and on n + 1 at E along
//! −e. Where the wrap changes, the span lies along the edge it leaves, so
//! L is C¹ there. Energy ½ κ max(0, L − ℓ)² (tension only, as docs/model.md's
//! tape); the rest length ℓ is the ribbon's length in the hanging column
//! of the apparatus (every block at θ = 90°, centres b apart): glued taut.

use super::outline::{Outline, Pose, add_point_force, point_velocity};
use super::params::M;
pub use super::tangent::Warm;
pub use super::tangent::{Anchor, Way, Ways};
use super::tangent::{Candidate, Relative, common_tangent, warm_tangent};

/// One ribbon of every junction: its anchor on the upper and the lower
/// block (in each block's own frame) and its rest length ℓ (in s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ribbon {
    pub upper: Anchor,
    pub lower: Anchor,
    pub rest: f64,
}

/// The ribbons of a ladder as built: two per junction, the same in every
/// junction's frames (the frames alternate, so the junctions alternate
/// as a Jacob's ladder's do), of stiffness κ (in k).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ribbons {
    pub outline: Outline,
    pub ribbons: [Ribbon; 2],
    pub stiffness: f64,
    /// The ribbon's dashpot c (in √(k m)): T = κ (L − ℓ) + c L̇ while
    /// taut, never below 0. An inextensible string jerked taut takes
    /// the jerk without rebound (e = 0, Routh, *Dynamics of a System of
    /// Rigid Bodies*, 1905, §§ on impulsive tensions); the stiff ribbon
    /// does the same with c = 2 √(κ m), critical for one block on it.
    pub damping: f64,
    /// Each ribbon's ways round, made once ([`Ribbons::new`]).
    pub(super) ways: [Ways; 2],
    /// Whether [`Ribbons::find_spans`] starts each common tangent from
    /// the last evaluation's (`tangent::warm_tangent`; the same spans).
    pub warm: bool,
    /// Whether, searching warm, it takes a pair of ways round's tangent
    /// points from an earlier pair that shares them (`twin`; the same
    /// spans).
    pub prune: bool,
    /// Inextensible (`model::taut`): κ = c = 0, lengths held by the run.
    pub inextensible: bool,
}

/// A ribbon at a state: where its span leaves each block (frame points),
/// its direction and length, its tension.
#[derive(Debug, Clone, Copy)]
pub struct Span {
    /// Frame points of D (on the upper block) and E (on the lower one).
    pub d: [f64; 2],
    pub e: [f64; 2],
    /// Unit vector from D to E (lab) and |E − D|.
    pub dir: [f64; 2],
    pub free: f64,
    /// Total length L and tension T = κ max(0, L − ℓ).
    pub length: f64,
    pub tension: f64,
    /// Wrapped lengths on the upper and the lower block.
    pub wrapped: [f64; 2],
}

impl Ribbon {
    /// The ribbon's ways round on a block of outline `o`.
    pub fn ways(&self, o: &Outline) -> Ways {
        Ways {
            upper: [Way::new(o, self.upper, 1), Way::new(o, self.upper, -1)],
            lower: [Way::new(o, self.lower, 1), Way::new(o, self.lower, -1)],
        }
    }

    /// The taut ribbon between `upper` and `lower` (poses) with outline
    /// `o`: the shorter of the ways round (module doc).
    pub fn span(&self, o: &Outline, upper: &Pose, lower: &Pose, stiffness: f64) -> Span {
        self.span_with(&self.ways(o), upper, lower, stiffness)
    }

    /// [`Ribbon::span`] with the ways round made beforehand.
    #[inline]
    pub fn span_with(&self, ways: &Ways, upper: &Pose, lower: &Pose, stiffness: f64) -> Span {
        self.span_from(ways, (upper, lower), stiffness, None, false)
    }

    /// [`Ribbon::span_with`], each common tangent started from `warm`'s
    /// (the last evaluation's, updated) where given, and then, where
    /// `prune`, a pair of ways round that has an earlier pair's tangent
    /// points not searched again ([`twin`]) and the last evaluation's
    /// shortest pair measured first ([`Ribbon::span_pruned`]): the same
    /// spans.
    #[inline]
    fn span_from(
        &self,
        ways: &Ways,
        poses: (&Pose, &Pose),
        stiffness: f64,
        warm: Option<&mut Warm>,
        prune: bool,
    ) -> Span {
        match warm {
            Some(w) if prune => self.span_pruned(ways, poses, stiffness, w),
            _ => self.span_searched(ways, poses, stiffness, warm),
        }
    }

    /// [`Ribbon::span_from`] with every pair of ways round searched (warm
    /// from `warm` where given) and measured in turn.
    #[inline]
    fn span_searched(
        &self,
        ways: &Ways,
        (upper, lower): (&Pose, &Pose),
        stiffness: f64,
        mut warm: Option<&mut Warm>,
    ) -> Span {
        let rel = Relative::new(upper, lower);
        let mut pairs = [(0, 0); 4];
        let mut found = [None; 4];
        for p in 0..4 {
            let (wu, wl) = (&ways.upper[p / 2], &ways.lower[p % 2]);
            let t = match warm.as_deref_mut() {
                Some(w) => {
                    let t = warm_tangent(wu, wl, &rel, w.pairs[p]);
                    w.pairs[p] = t.pair;
                    t
                }
                None => common_tangent(wu, wl, &rel),
            };
            (pairs[p], found[p]) = (t.pair, Some(t.found));
        }
        let (length, p) = in_turn(&rel, ways, &pairs, &found);
        if let Some(w) = warm {
            w.shortest = p;
        }
        self.taut_at(ways, (upper, lower), (p, pairs[p]), length, stiffness)
    }

    /// [`Ribbon::span_from`] searching warm and pruned: each pair of ways
    /// round searched from `w` (or taken from its [`twin`]), then the pair
    /// that was the shortest at the last evaluation measured first, so
    /// that the others are mostly rejected on their squared free spans
    /// with no square root ([`comes_before`]): the shortest pair, the
    /// first of equal lengths, as [`Ribbon::span_searched`] finds it.
    /// That pair's span through its last tangent points is made before
    /// the search (its square roots and divisions under way while the
    /// search runs) and kept where the search confirms both.
    #[inline]
    fn span_pruned(
        &self,
        ways: &Ways,
        (upper, lower): (&Pose, &Pose),
        stiffness: f64,
        w: &mut Warm,
    ) -> Span {
        let rel = Relative::new(upper, lower);
        let last = (w.shortest, w.pairs[w.shortest]);
        let (cu, cl) = candidates(ways, last.0, last.1);
        let length = cu.arc + free_squared(&rel, (cu, cl)).sqrt() + cl.arc;
        let early = self.taut_at(ways, (upper, lower), last, length, stiffness);
        let found = search_pruned(ways, &rel, w);
        let (length, p) = shortest_first(&rel, ways, w, &found, (last, early.length));
        w.shortest = p;
        if (p, w.pairs[p]) == last && length.to_bits() == early.length.to_bits() {
            return early;
        }
        self.taut_at(ways, (upper, lower), (p, w.pairs[p]), length, stiffness)
    }

    /// [`Ribbon::taut`] through pair p's tangent points `pair`.
    #[inline]
    fn taut_at(
        &self,
        ways: &Ways,
        (upper, lower): (&Pose, &Pose),
        (p, pair): (usize, (usize, usize)),
        length: f64,
        stiffness: f64,
    ) -> Span {
        let (cu, cl) = candidates(ways, p, pair);
        self.taut(
            upper,
            lower,
            (cu.point, cl.point),
            length,
            [cu.arc, cl.arc],
            stiffness,
        )
    }

    /// The span through the tangent points (D, E) (frame points of the
    /// upper and the lower block), of total `length`, wrapped lengths
    /// `wrapped`.
    #[inline]
    fn taut(
        &self,
        upper: &Pose,
        lower: &Pose,
        (dp, ep): ([f64; 2], [f64; 2]),
        length: f64,
        wrapped: [f64; 2],
        stiffness: f64,
    ) -> Span {
        let (d, e) = (upper.point(dp), lower.point(ep));
        let v = [e[0] - d[0], e[1] - d[1]];
        let free = (v[0] * v[0] + v[1] * v[1]).sqrt();
        let dir = if free > 0.0 {
            [v[0] / free, v[1] / free]
        } else {
            [0.0, 0.0]
        };
        Span {
            d: dp,
            e: ep,
            dir,
            free,
            length,
            tension: (stiffness * (length - self.rest)).max(0.0),
            wrapped,
        }
    }
}

/// How much longer than the rounding of a length (in s) a free span must
/// be for [`surely_longer`] to say so without its square root.
const SLACK: f64 = 1e-9;

/// Whether a free span of squared length `f2` is longer than `gap` (the
/// slot's length less the wrapped lengths, ≥ 0) by more than [`SLACK`]:
/// then the rounded whole length is above the slot's, as its square
/// root would have shown (rounding moves lengths of a few s by ~10⁻¹⁵).
#[inline]
fn surely_longer(f2: f64, gap: f64) -> bool {
    let g = gap + SLACK;
    f2 >= g * g
}

/// No fixed point (of [`twin`]'s record): no candidate has this index.
const NOT_FIXED: (usize, usize) = (usize::MAX, usize::MAX);

/// The candidates of pair p's tangent points `(ju, jl)`: upper way
/// p / 2, lower way p % 2.
#[inline]
fn candidates(ways: &Ways, p: usize, (ju, jl): (usize, usize)) -> (&Candidate, &Candidate) {
    (&ways.upper[p / 2].c[ju], &ways.lower[p % 2].c[jl])
}

/// Each pair of ways round's tangent points searched warm from `w`'s
/// (updated), a pair that has an earlier pair's taken from it unsearched
/// ([`twin`]): whether each pair searched found a common tangent, `None`
/// for a twin (its length an earlier pair's: never the first of the
/// shortest).
#[inline]
fn search_pruned(ways: &Ways, rel: &Relative, w: &mut Warm) -> [Option<bool>; 4] {
    // Each pair's tangent points where a fixed point of its search.
    let mut fixed = [NOT_FIXED; 4];
    let mut found = [None; 4];
    for p in 0..4 {
        if let Some(pair) = twin(&fixed, p, w.pairs[p]) {
            fixed[p] = pair;
            continue;
        }
        let t = warm_tangent(&ways.upper[p / 2], &ways.lower[p % 2], rel, w.pairs[p]);
        w.pairs[p] = t.pair;
        if t.fixed {
            fixed[p] = t.pair;
        }
        found[p] = Some(t.found);
    }
    found
}

/// The shortest pair of ways round through `w`'s tangent points (the
/// first of equal lengths) and its length, as [`in_turn`] finds it: the
/// last shortest pair measured first (where it has a common tangent;
/// else the first that has one), then the others against it. `last`:
/// the last shortest pair, its tangent points then, and the length
/// through them, already measured.
#[inline]
fn shortest_first(
    rel: &Relative,
    ways: &Ways,
    w: &Warm,
    found: &[Option<bool>; 4],
    (last, measured): ((usize, (usize, usize)), f64),
) -> (f64, usize) {
    let has_tangent = |p: usize| found[p] == Some(true);
    let first = Some(last.0)
        .filter(|&p| has_tangent(p))
        .or_else(|| (0..4).find(|&p| has_tangent(p)));
    let length = first.and_then(|p| {
        if (p, w.pairs[p]) == last {
            return (measured < f64::INFINITY).then_some(measured);
        }
        comes_before(rel, candidates(ways, p, w.pairs[p]), f64::INFINITY, false)
    });
    // No common tangent, or no finite length: the pairs in turn.
    let (Some(first), Some(length)) = (first, length) else {
        return in_turn(rel, ways, &w.pairs, found);
    };
    let mut best = (length, first);
    for p in (0..4).filter(|&p| p != first && has_tangent(p)) {
        let c = candidates(ways, p, w.pairs[p]);
        if let Some(l) = comes_before(rel, c, best.0, p < best.1) {
            best = (l, p);
        }
    }
    best
}

/// The squared free span between tangent candidates `(cu, cl)`, in the
/// upper block's frame.
#[inline]
fn free_squared(rel: &Relative, (cu, cl): (&Candidate, &Candidate)) -> f64 {
    let e = rel.to_upper(cl.point);
    (e[0] - cu.point[0]).powi(2) + (e[1] - cu.point[1]).powi(2)
}

/// The shortest of the pairs of ways round through tangent points
/// `pairs` measured in turn (the first of equal lengths), among those
/// with a common tangent (`found` `Some(true)`), where none has one
/// (never seen) among the last guesses (`Some(false)`); a pair `None`
/// is not measured. `(∞, 0)` where none has a length below ∞.
fn in_turn(
    rel: &Relative,
    ways: &Ways,
    pairs: &[(usize, usize); 4],
    found: &[Option<bool>; 4],
) -> (f64, usize) {
    let mut best = (f64::INFINITY, 0);
    let mut guess = best;
    for (p, &pair) in pairs.iter().enumerate() {
        let Some(f) = found[p] else { continue };
        let slot = if f { &mut best } else { &mut guess };
        if let Some(length) = comes_before(rel, candidates(ways, p, pair), slot.0, false) {
            *slot = (length, p);
        }
    }
    if best.0.is_finite() { best } else { guess }
}

/// The length through tangent candidates `(cu, cl)` (upper, lower)
/// where it comes before `slot`'s, the shortest so far: shorter, or
/// as long where its pair comes `earlier` (the first of equal lengths is
/// the one kept); else `None`, mostly without a square root.
#[inline]
fn comes_before(
    rel: &Relative,
    (cu, cl): (&Candidate, &Candidate),
    slot: f64,
    earlier: bool,
) -> Option<f64> {
    // The free span is ≥ 0 and rounded addition is monotone: where the
    // wrapped lengths alone pass the slot's, the whole length does.
    let arcs = cu.arc + cl.arc;
    if arcs > slot || (arcs == slot && !earlier) {
        return None;
    }
    let f2 = free_squared(rel, (cu, cl));
    if surely_longer(f2, slot - arcs) {
        return None;
    }
    let length = cu.arc + f2.sqrt() + cl.arc;
    (length < slot || (earlier && length == slot)).then_some(length)
}

/// The tangent points pair p of [`Ribbon::span_from`] (upper way p / 2,
/// lower way p % 2) takes without a search, from `fixed` (the earlier
/// pairs' where a fixed point of their search, else [`NOT_FIXED`]): an
/// earlier pair q's that differs from p in one way round (the lower,
/// q = p − 1, or the upper, q = p − 2), with its tangent point on that
/// block the anchor (candidate 0: the same point, wrapped length and test
/// in both ways round, `tangent::Way::new`), and equal to p's `last`.
/// Then p's tests are q's, and [`warm_tangent`] started from `last` would
/// return them: through its two tests, or (at the anchors, (0, 0)) at
/// the search's first step.
#[inline]
fn twin(fixed: &[(usize, usize); 4], p: usize, last: (usize, usize)) -> Option<(usize, usize)> {
    let by_lower = p % 2 == 1 && fixed[p - 1] == last && last.1 == 0;
    let by_upper = p >= 2 && fixed[p - 2] == last && last.0 == 0;
    (by_lower || by_upper).then_some(last)
}

impl Ribbons {
    /// The ribbons with their ways round made.
    pub fn new(outline: Outline, ribbons: [Ribbon; 2], stiffness: f64) -> Self {
        Self {
            outline,
            ways: ribbons.map(|r| r.ways(&outline)),
            ribbons,
            stiffness,
            damping: 2.0 * (stiffness * M).sqrt(),
            warm: true,
            prune: true,
            inextensible: false,
        }
    }

    /// These ribbons without their dashpot (forces of the positions only).
    pub fn undamped(self) -> Self {
        Self {
            damping: 0.0,
            ..self
        }
    }

    /// The dashpot's tension c L̇ of a taut ribbon (`span` at poses
    /// `pu`, `pl` of blocks i, i + 1), clamped so the total stays ≥ 0.
    #[inline]
    fn dashpot(&self, i: usize, pu: &Pose, pl: &Pose, s: &Span, v: &[f64]) -> (f64, f64) {
        if s.tension == 0.0 {
            return (0.0, 0.0);
        }
        let vd = point_velocity(pu, i, s.d, v);
        let ve = point_velocity(pl, i + 1, s.e, v);
        let rate = s.dir[0] * (ve[0] - vd[0]) + s.dir[1] * (ve[1] - vd[1]);
        let extra = (self.damping * rate).max(-s.tension);
        (extra, rate)
    }

    /// Adds the ribbons' dashpot forces at (q, v) to `out` (forces).
    pub fn add_damping(&self, n: usize, q: &[f64], v: &[f64], out: &mut [f64]) {
        if self.damping == 0.0 {
            return;
        }
        self.for_each_span(n, q, |i, pu, pl, s| {
            self.add_dashpot(i, pu, pl, s, v, out);
        });
    }

    /// One ribbon's dashpot force at v into `out` (forces); returns the
    /// power it dissipates, extra · L̇ (as [`Ribbons::dissipation`]).
    #[inline]
    fn add_dashpot(
        &self,
        i: usize,
        pu: &Pose,
        pl: &Pose,
        s: &Span,
        v: &[f64],
        out: &mut [f64],
    ) -> f64 {
        let (extra, rate) = self.dashpot(i, pu, pl, s, v);
        if extra == 0.0 {
            return 0.0;
        }
        let f = [extra * s.dir[0], extra * s.dir[1]];
        add_point_force(out, pu, i, s.d, f);
        add_point_force(out, pl, i + 1, s.e, [-f[0], -f[1]]);
        extra * rate
    }

    /// Every ribbon's span at the blocks' `poses` (one per block, as
    /// [`Pose::of`] gives them) into `out`, in the order of
    /// [`Ribbons::for_each_span`]: the one search of a force evaluation,
    /// for [`Ribbons::gradient_of`] and [`Ribbons::add_damping_of`].
    /// Each common tangent starts from `warm`'s (the last call's, kept by
    /// the caller) where [`Ribbons::warm`].
    pub fn find_spans(&self, poses: &[Pose], out: &mut Vec<Span>, warm: &mut Vec<Warm>) {
        out.clear();
        let junctions = poses.len().saturating_sub(1);
        warm.resize(2 * junctions, Warm::default());
        let mut last = warm.iter_mut();
        for w in poses.windows(2) {
            for (r, ways) in self.ribbons.iter().zip(&self.ways) {
                let start = last.next().filter(|_| self.warm);
                let pair = (&w[0], &w[1]);
                out.push(r.span_from(ways, pair, self.stiffness, start, self.prune));
            }
        }
    }

    /// [`Ribbons::gradient`] from the spans [`Ribbons::find_spans`] found
    /// at `poses`: the same numbers, bit for bit.
    pub fn gradient_of(&self, gravity: f64, poses: &[Pose], spans: &[Span], grad: &mut [f64]) {
        self.gravity_gradient(poses.len(), gravity, grad);
        for (k, s) in spans.iter().enumerate() {
            let i = k / 2;
            add_tension(grad, &poses[i], &poses[i + 1], i, s);
        }
    }

    /// [`Ribbons::add_damping`] from the spans [`Ribbons::find_spans`]
    /// found at `poses`: the same numbers, bit for bit. Returns the power
    /// the dashpots dissipate (≥ 0), as [`Ribbons::dissipation`].
    pub fn add_damping_of(
        &self,
        poses: &[Pose],
        spans: &[Span],
        v: &[f64],
        out: &mut [f64],
    ) -> f64 {
        let mut d = 0.0;
        if self.damping == 0.0 {
            return d;
        }
        for (k, s) in spans.iter().enumerate() {
            let i = k / 2;
            d += self.add_dashpot(i, &poses[i], &poses[i + 1], s, v, out);
        }
        d
    }

    /// Power the dashpots dissipate at (q, v), Σ −extra · L̇ ≥ 0.
    pub fn dissipation(&self, n: usize, q: &[f64], v: &[f64]) -> f64 {
        let mut d = 0.0;
        if self.damping == 0.0 {
            return d;
        }
        self.for_each_span(n, q, |i, pu, pl, s| {
            let (extra, rate) = self.dashpot(i, pu, pl, s, v);
            d += extra * rate;
        });
        d
    }

    /// Every ribbon at `q`: junction after junction, ribbon 0 then 1, with
    /// the two poses.
    #[inline]
    pub fn for_each_span(
        &self,
        n: usize,
        q: &[f64],
        mut f: impl FnMut(usize, &Pose, &Pose, &Span),
    ) {
        if n < 2 {
            return;
        }
        let mut pu = Pose::of(q, 0);
        for i in 0..n - 1 {
            let pl = Pose::of(q, i + 1);
            for (r, w) in self.ribbons.iter().zip(&self.ways) {
                f(i, &pu, &pl, &r.span_with(w, &pu, &pl, self.stiffness));
            }
            pu = pl;
        }
    }

    /// Every ribbon at `q`: (junction, span).
    pub fn spans(&self, n: usize, q: &[f64]) -> Vec<(usize, Span)> {
        let mut out = Vec::new();
        self.for_each_span(n, q, |i, _, _, s| out.push((i, *s)));
        out
    }

    /// Elastic energy Σ ½ κ max(0, L − ℓ)².
    pub fn elastic_energy(&self, n: usize, q: &[f64]) -> f64 {
        let mut e = 0.0;
        if self.inextensible {
            return e;
        }
        self.for_each_span(n, q, |_, _, _, s| {
            e += 0.5 * s.tension * s.tension / self.stiffness;
        });
        e
    }

    /// ∂E/∂q of the ribbons' energy and gravity (−m G per X_n) into
    /// `grad`: T e at D on the upper block, −T e at E on the lower one,
    /// with the sign of a gradient (the force is −grad).
    pub fn gradient(&self, n: usize, gravity: f64, q: &[f64], grad: &mut [f64]) {
        self.gravity_gradient(n, gravity, grad);
        self.for_each_span(n, q, |i, pu, pl, s| add_tension(grad, pu, pl, i, s));
    }

    /// Gravity's gradient, −m G per X_n, written into `grad`.
    fn gravity_gradient(&self, n: usize, gravity: f64, grad: &mut [f64]) {
        let g = M * gravity;
        for (k, x) in grad.iter_mut().enumerate().take(3 * n) {
            *x = if k % 3 == 0 { -g } else { 0.0 };
        }
    }

    /// The ribbons' rest lengths in the hanging column: every block at
    /// θ = 90°, centres `b` apart (in s), each ribbon glued taut.
    pub fn glued_in_column(outline: Outline, anchors: [(Anchor, Anchor); 2], b: f64) -> Self {
        let half_pi = std::f64::consts::FRAC_PI_2;
        let q = [0.0, 0.0, half_pi, b, 0.0, half_pi];
        let (pu, pl) = (Pose::of(&q, 0), Pose::of(&q, 1));
        let ribbons = anchors.map(|(upper, lower)| {
            let r = Ribbon {
                upper,
                lower,
                rest: 0.0,
            };
            Ribbon {
                rest: r.span(&outline, &pu, &pl, 1.0).length,
                ..r
            }
        });
        Self::new(outline, ribbons, 1.0)
    }
}

/// One taut ribbon's tension into the gradient `grad`: T e at D on the
/// upper block (pose `pu`, block i), −T e at E on the lower one.
#[inline]
fn add_tension(grad: &mut [f64], pu: &Pose, pl: &Pose, i: usize, s: &Span) {
    if s.tension == 0.0 {
        return;
    }
    let f = [s.tension * s.dir[0], s.tension * s.dir[1]];
    // The force on the upper block is +T e at D: its gradient −T e.
    add_point_force(grad, pu, i, s.d, [-f[0], -f[1]]);
    add_point_force(grad, pl, i + 1, s.e, f);
}

#[cfg(test)]
pub(crate) mod tests;

#[cfg(test)]
mod dashpot_tests {
    use super::tests::{column, tank_ribbons};
    use super::{Pose, Span};

    #[test]
    fn spans_found_once_give_the_forces_bit_for_bit() {
        // The gradient and the dashpots from one search (`find_spans`)
        // against each searching on its own, at states bent every way.
        let r = tank_ribbons(1.5);
        for seed in 0..100 {
            let mut q = column(5, 1.5);
            let s = seed as f64;
            for (k, x) in q.iter_mut().enumerate() {
                let amp = if k % 3 == 2 { 1.5 } else { 0.3 };
                *x += amp * ((k as f64) * 1.3 + s * 0.41).sin();
            }
            let v: Vec<f64> = (0..q.len()).map(|k| 0.01 * (k as f64 + s).cos()).collect();
            let poses: Vec<Pose> = (0..5).map(|i| Pose::of(&q, i)).collect();
            let mut spans: Vec<Span> = Vec::new();
            r.find_spans(&poses, &mut spans, &mut Vec::new());
            let (mut a, mut b) = (vec![0.0; 15], vec![0.0; 15]);
            r.gradient(5, 2e-4, &q, &mut a);
            r.gradient_of(2e-4, &poses, &spans, &mut b);
            r.add_damping(5, &q, &v, &mut a);
            r.add_damping_of(&poses, &spans, &v, &mut b);
            let bits = |x: &[f64]| x.iter().map(|y| y.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&a), bits(&b), "seed {seed}");
        }
    }

    #[test]
    fn the_dashpot_dissipates_what_its_forces_take() {
        let b = 1.5;
        let r = tank_ribbons(b);
        let mut q = column(3, b);
        q[3] += 0.01;
        q[6] += 0.013;
        q[5] += 0.05;
        for s in [1.0, -1.0, 0.2] {
            let v: Vec<f64> = (0..q.len())
                .map(|k| s * 0.01 * ((k as f64) * 0.7).sin())
                .collect();
            let mut f = vec![0.0; q.len()];
            r.add_damping(3, &q, &v, &mut f);
            let power: f64 = f.iter().zip(&v).map(|(a, b)| a * b).sum();
            let d = r.dissipation(3, &q, &v);
            assert!(d >= 0.0 && (power + d).abs() < 1e-14, "{power} {d}");
        }
    }
}
