//! The common tangent of two blocks' outlines, the search behind a
//! ribbon's free span (`ribbons`; docs/experiments.md, "The toy as
//! built"): from each anchor the places the ribbon may leave its block
//! (the anchor, then the corners in turn: a way round), the test that
//! lets it leave at one, and the alternating search for the pair where
//! both leave towards each other.
//!
//! The test is a sign, e · a ≥ 0, and where the two blocks touch at the
//! tangent points it is a tie: two corners that coincide (a free span of
//! zero length, as at the strap hinge's pivot, `strap`) give e of the
//! size of the rounding of the poses, and a span along the edge it leaves
//! gives e ⟂ a. Either answer gives the same length there (the length is
//! continuous), but a tie lost sends the ribbon on round the next corner
//! where it should leave, and past a coinciding corner the search finds a
//! path round the far end that is no ribbon's. A tie counts as leaving:
//! e · a ≥ −[`TIE`].
//!
//! Where the blocks overlap at the tangent points the two blocks' tests
//! may send each other round and round: [`common_tangent`] takes the
//! longest pair of such a cycle.

use super::outline::{Outline, Pose};
use super::params::R;

/// How far (in s) the span may point back along the edge it came by and
/// still leave: rounding of the poses, far below any real wrap.
pub const TIE: f64 = 1e-12;

/// A ribbon's glue point on a block: edge k (0..4) at fraction f ∈ [0, 1)
/// from corner k towards corner k + 1 (`outline`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Anchor {
    pub edge: usize,
    pub along: f64,
}

/// Where a ribbon may leave a block: a frame point, the length wrapped to
/// reach it, and the test on the span's direction e (in this block's
/// frame, pointing away from it) that lets it leave there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Candidate {
    pub(super) point: [f64; 2],
    pub(super) arc: f64,
    /// Leaves where e · a ≥ 0 or (at a corner anchor) e · b ≥ 0 (a tie,
    /// within [`TIE`], counts as leaving: module doc).
    a: [f64; 2],
    b: Option<[f64; 2]>,
    /// The edge the ribbon would wrap along next (whose outward normal is
    /// a) and, at a corner anchor, the other edge there (normal b).
    next: usize,
    other: Option<usize>,
}

impl Candidate {
    /// Whether the span leaves here towards `target` (this block's frame),
    /// `inside` the edge nearest to the target where the target lies inside
    /// this block (the other block's corner pressed into it, as penalty
    /// contact allows: module doc).
    #[inline]
    fn leaves(&self, target: [f64; 2], inside: Option<usize>) -> bool {
        let e = [target[0] - self.point[0], target[1] - self.point[1]];
        e[0] * self.a[0] + e[1] * self.a[1] >= -TIE
            || self.b.is_some_and(|b| e[0] * b[0] + e[1] * b[1] >= -TIE)
            || inside.is_some_and(|k| k == self.next || Some(k) == self.other)
    }
}

/// The edge of the outline (half thickness `h`) nearest to `target`
/// (frame), where the target lies inside the block; `None` outside.
#[inline]
fn nearest_edge_inside(h: f64, target: [f64; 2]) -> Option<usize> {
    let [u, w] = target;
    if u.abs() >= R || w.abs() >= h {
        return None;
    }
    // Depth to each edge: w = −h, u = r, w = h, u = −r (edges 0..3).
    let depths = [h + w, R - u, h - w, R + u];
    (0..4).min_by(|&i, &j| depths[i].total_cmp(&depths[j]))
}

/// One way round (σ = ±1) from an anchor: the anchor itself, then the
/// four corners in turn (fixed in the block: made once).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Way {
    pub(super) c: [Candidate; 5],
    /// The block's half thickness h.
    h: f64,
}

impl Way {
    pub(super) fn new(o: &Outline, anchor: Anchor, sigma: i32) -> Self {
        let k = anchor.edge % 4;
        let f = anchor.along;
        let at_corner = f == 0.0;
        let first = Candidate {
            point: o.on_edge(k, f),
            arc: 0.0,
            a: o.normal(k),
            b: at_corner.then(|| o.normal(k + 3)),
            next: k,
            other: at_corner.then_some((k + 3) % 4),
        };
        let mut c = [first; 5];
        let (mut arc, mut m) = if sigma > 0 {
            ((1.0 - f) * o.edge_length(k), k + 1)
        } else if at_corner {
            // The anchor is corner k: the next one back is k − 1.
            (o.edge_length(k + 3), k + 3)
        } else {
            (f * o.edge_length(k), k)
        };
        for slot in c.iter_mut().skip(1) {
            // Arriving at corner m along the edge from the previous corner.
            let prev = if sigma > 0 { m + 3 } else { m + 1 };
            let (p, q) = (o.corner(m), o.corner(prev));
            let len = ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt();
            let next_edge = if sigma > 0 { m % 4 } else { (m + 3) % 4 };
            *slot = Candidate {
                point: p,
                arc,
                a: [(p[0] - q[0]) / len, (p[1] - q[1]) / len],
                b: None,
                next: next_edge,
                other: None,
            };
            arc += o.edge_length(next_edge);
            m = if sigma > 0 { m + 1 } else { m + 3 };
        }
        Self {
            c,
            h: o.half_thickness,
        }
    }

    /// The first candidate that leaves towards `target` (the last if none).
    #[inline]
    fn first_leaving(&self, target: [f64; 2]) -> usize {
        let inside = nearest_edge_inside(self.h, target);
        self.c
            .iter()
            .position(|c| c.leaves(target, inside))
            .unwrap_or(self.c.len() - 1)
    }
}

/// The lower block's frame seen from the upper one's: x_U = m x_L + o
/// (m orthogonal, so x_L = mᵀ (x_U − o)).
#[derive(Debug, Clone, Copy)]
pub(super) struct Relative {
    m: [[f64; 2]; 2],
    o: [f64; 2],
}

impl Relative {
    #[inline]
    pub(super) fn new(u: &Pose, l: &Pose) -> Self {
        let dot = |a: [f64; 2], b: [f64; 2]| a[0] * b[0] + a[1] * b[1];
        let d = [l.centre[0] - u.centre[0], l.centre[1] - u.centre[1]];
        Self {
            m: [
                [dot(l.t, u.t), dot(l.nu, u.t)],
                [dot(l.t, u.nu), dot(l.nu, u.nu)],
            ],
            o: [dot(d, u.t), dot(d, u.nu)],
        }
    }
    #[inline]
    pub(super) fn to_upper(self, p: [f64; 2]) -> [f64; 2] {
        [
            self.m[0][0] * p[0] + self.m[0][1] * p[1] + self.o[0],
            self.m[1][0] * p[0] + self.m[1][1] * p[1] + self.o[1],
        ]
    }
    #[inline]
    fn to_lower(self, p: [f64; 2]) -> [f64; 2] {
        let d = [p[0] - self.o[0], p[1] - self.o[1]];
        [
            self.m[0][0] * d[0] + self.m[1][0] * d[1],
            self.m[0][1] * d[0] + self.m[1][1] * d[1],
        ]
    }
}

/// A ribbon's four ways round (two from each anchor), made once.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ways {
    pub(super) upper: [Way; 2],
    pub(super) lower: [Way; 2],
}

/// What a common tangent search gives: the tangent points (upper, lower)
/// as candidates' indices in the two ways round, whether they are a
/// common tangent (else the last guesses), and whether they are a fixed
/// point of the search (each the first candidate that leaves towards the
/// other: what [`warm_tangent`] confirms; not the longest pair of a cycle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Tangent {
    pub(super) pair: (usize, usize),
    pub(super) found: bool,
    pub(super) fixed: bool,
}

impl Tangent {
    /// A fixed point of the search.
    #[inline]
    fn fixed(pair: (usize, usize)) -> Self {
        Self {
            pair,
            found: true,
            fixed: true,
        }
    }
}

/// The common tangent of one way round on each block: alternately the
/// first candidate on each that leaves towards the other's point, until
/// neither changes; with whether it got there.
///
/// Where the blocks overlap at the tangent points (two corners pressed
/// into each other, as at the strap hinge's pivot once the stretched
/// ribbons let the blocks move; ends pressed into each other by penalty
/// contact) the two blocks' tests need not agree, and the guesses cycle
/// (docs/experiments.md, "The strap hinge"): at the toy's pivot, corners
/// 7 × 10⁻⁵ s into each other, a pair wrapped 0.95 + 0.05 s and one
/// wrapped 1.061 + 0 s, lengths 1.11133 and 1.11130 s. Every pair of
/// such a cycle runs round the overlapping corners, within the overlap
/// of the taut path; a shorter one may cut through a block (a way round
/// with no common tangent cycles too, its shortest guess a straight line
/// through a block): the longest is the length. Dropping the way instead
/// sent the ribbon round the other way, 0.085 s longer. The search is a
/// map of the last pair, so a pair met again closes a cycle; a search
/// that neither settles nor cycles in ten rounds (never seen) has no
/// common tangent.
#[inline]
pub(super) fn common_tangent(wu: &Way, wl: &Way, rel: &Relative) -> Tangent {
    // The anchors, then the guesses.
    let mut seen = [(0, 0); 11];
    for k in 1..seen.len() {
        let jl = seen[k - 1].1;
        let nu = wu.first_leaving(rel.to_upper(wl.c[jl].point));
        let nl = wl.first_leaving(rel.to_lower(wu.c[nu].point));
        if (nu, nl) == seen[k - 1] {
            return Tangent::fixed((nu, nl));
        }
        if let Some(from) = seen[..k].iter().position(|&p| p == (nu, nl)) {
            let pair = longest(wu, wl, rel, &seen[from..k]);
            return Tangent {
                pair,
                found: true,
                fixed: false,
            };
        }
        seen[k] = (nu, nl);
    }
    Tangent {
        pair: seen[seen.len() - 1],
        found: false,
        fixed: false,
    }
}

/// Of pairs of tangent points, the one whose path is the longest (the
/// first of equally long ones).
fn longest(wu: &Way, wl: &Way, rel: &Relative, pairs: &[(usize, usize)]) -> (usize, usize) {
    let mut best = (f64::NEG_INFINITY, pairs[0]);
    for &p in pairs {
        let l = pair_length(wu, wl, rel, p);
        if l > best.0 {
            best = (l, p);
        }
    }
    best.1
}

/// The ribbon's length through tangent points `(ju, jl)`: the wrapped
/// lengths and the free span between.
fn pair_length(wu: &Way, wl: &Way, rel: &Relative, (ju, jl): (usize, usize)) -> f64 {
    let (cu, cl) = (wu.c[ju], wl.c[jl]);
    let e = rel.to_upper(cl.point);
    let free = ((e[0] - cu.point[0]).powi(2) + (e[1] - cu.point[1]).powi(2)).sqrt();
    cu.arc + free + cl.arc
}

/// A ribbon's search at the last evaluation: the tangent points (upper,
/// lower) of each of its four pairs of ways round (upper way a, lower way
/// b at 2a + b), where [`warm_tangent`] starts, and which pair was the
/// shortest, measured first (`ribbons`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Warm {
    pub(super) pairs: [(usize, usize); 4],
    pub(super) shortest: usize,
}

/// [`common_tangent`] started from the last evaluation's tangent points
/// `last`: where they are still the common tangent (each the first
/// candidate that leaves towards the other), that with two tests in
/// place of the four or more of a search from the anchors; else the
/// search from the anchors. The same answer as [`common_tangent`] where
/// a way round has one common tangent (a test compares the two over
/// whole runs of the tank and the toy, bit for bit).
#[inline]
pub(super) fn warm_tangent(wu: &Way, wl: &Way, rel: &Relative, last: (usize, usize)) -> Tangent {
    let (ju, jl) = last;
    if (ju, jl) != (0, 0)
        && wu.first_leaving(rel.to_upper(wl.c[jl].point)) == ju
        && wl.first_leaving(rel.to_lower(wu.c[ju].point)) == jl
    {
        return Tangent::fixed(last);
    }
    common_tangent(wu, wl, rel)
}
