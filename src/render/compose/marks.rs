//! Marks beside a filmstrip's snapshots (paper Fig. 4a): where each sits
//! on the chain, the side its words go on, and the drawing.

use crate::model::Ladder;
use crate::render::canvas::Canvas;
use crate::render::palette::Role;
use crate::render::picture::Picture;
use crate::render::snapshot::{self, Region, Snapshot};
use crate::render::style::{self, HAlign, VAlign};
use crate::render::theme::Theme;

/// A labelled pointer beside a filmstrip snapshot at a point of the chain.
#[derive(Clone, Debug, PartialEq)]
pub struct ChainMark {
    /// Where along the chain, in blocks: 1 is the centre of block 1, 2.5
    /// halfway between the centres of blocks 2 and 3.
    pub at: f64,
    /// The words beside the triangle (none when empty).
    pub label: String,
    /// What the mark points at (a kink, an antikink, an event): the
    /// triangle takes the role's colour, the words its readable shade
    /// ([`Theme::text_color`]).
    pub role: Role,
    /// The side of the ladder the pointer and its label go on (`Left` or
    /// `Right`).
    pub side: HAlign,
}

/// Where a mark sits on a snapshot of `snap` drawn into `region`: the
/// pixel of its point on the chain, and how far the chain reaches from
/// that point towards the left and towards the right (`side_clear` false:
/// the farthest node of the two blocks at the mark on either side, as the
/// paper's figures are drawn; true: the chain's extent on each side, so
/// that a mark stays beside its own column of a folded ladder).
pub(super) struct MarkPlace {
    pub(super) x: f32,
    pub(super) y: f32,
    reach: [f32; 2],
}

impl MarkPlace {
    pub(super) fn new(
        region: Region,
        ladder: &Ladder,
        snap: &Snapshot<'_>,
        mark: &ChainMark,
        side_clear: bool,
    ) -> MarkPlace {
        use crate::model::ladder::{ix, iy, nodes};
        let n = ladder.n();
        let q = snap.q;
        let at = mark.at.clamp(1.0, n as f64);
        let i = (at.floor() as usize).clamp(1, n) - 1;
        let j = (i + 1).min(n - 1);
        let f = at - (i + 1) as f64;
        let point = [
            q[ix(i)] + f * (q[ix(j)] - q[ix(i)]),
            q[iy(i)] + f * (q[iy(j)] - q[iy(i)]),
        ];
        let (x, y) = snapshot::pixel_of(region, snap, point);
        let ends: Vec<f32> = [i, j]
            .into_iter()
            .flat_map(|k| {
                let (a, b) = nodes(q, k);
                [a, b]
            })
            .map(|p| snapshot::pixel_of(region, snap, p).0 - x)
            .collect();
        // Clear of the chain: beyond the farthest node of the two blocks.
        let reach = |dir: f32| {
            if side_clear {
                ends.iter().map(|d| dir * d).fold(0.0f32, f32::max)
            } else {
                ends.iter().map(|d| d.abs()).fold(0.0f32, f32::max)
            }
        };
        MarkPlace {
            x,
            y,
            reach: [reach(-1.0), reach(1.0)],
        }
    }

    /// How far the chain reaches from the mark's point towards `dir`
    /// (−1 left, +1 right).
    fn reach(&self, dir: f32) -> f32 {
        if dir < 0.0 {
            self.reach[0]
        } else {
            self.reach[1]
        }
    }

    /// The far end of `mark`'s words (their near end when it has none)
    /// when drawn towards `dir`.
    fn far(&self, theme: &Theme, mark: &ChainMark, dir: f32) -> f32 {
        let label_w = style::text_width(theme.font(), &mark.label, theme.mark_text);
        let room = theme.mark_clear + theme.mark_arrow + theme.mark_space + label_w;
        self.x + dir * (self.reach(dir) + room)
    }

    /// Whether `mark` drawn towards `dir` stays within `0..=width`.
    pub(super) fn fits(&self, theme: &Theme, mark: &ChainMark, dir: f32, width: f32) -> bool {
        (0.0..=width).contains(&self.far(theme, mark, dir))
    }
}

/// The direction of `side`: −1 left, +1 right.
pub(super) fn direction(side: HAlign) -> f32 {
    if side == HAlign::Left { -1.0 } else { 1.0 }
}

/// The other side.
fn opposite(side: HAlign) -> HAlign {
    if side == HAlign::Left {
        HAlign::Right
    } else {
        HAlign::Left
    }
}

/// Words of two marks closer than this many text sizes apart vertically
/// may touch (a text's box is 1.17 sizes tall).
const MARK_WORDS_APART: f32 = 1.25;

/// Whether the words of `a` drawn towards `da` and those of `b` drawn
/// towards `db` could share a pixel.
fn words_meet(
    theme: &Theme,
    (pa, a, da): (&MarkPlace, &ChainMark, f32),
    (pb, b, db): (&MarkPlace, &ChainMark, f32),
) -> bool {
    let span = |p: &MarkPlace, m: &ChainMark, d: f32| {
        let far = p.far(theme, m, d);
        let near = far - d * style::text_width(theme.font(), &m.label, theme.mark_text);
        (near.min(far), near.max(far))
    };
    let ((a0, a1), (b0, b1)) = (span(pa, a, da), span(pb, b, db));
    (pa.y - pb.y).abs() < MARK_WORDS_APART * theme.mark_text && a0.max(b0) < a1.min(b1)
}

/// The marks of one snapshot `width` pixels wide, each with where it sits
/// and the side its words go on: its own side, or the other where its
/// words would leave the snapshot on its own side and fit on the other
/// clear of every other mark's words (on either side of theirs). Else its
/// own side, its words past the snapshot's edge: a fitted strip makes
/// room so that this does not happen (`StripPlan::room_for_words` (the filmstrip's plan)).
pub(super) fn mark_sides<'m>(
    theme: &Theme,
    places: Vec<MarkPlace>,
    marks: &'m [ChainMark],
    width: f32,
) -> Vec<(MarkPlace, &'m ChainMark, HAlign)> {
    let flip = |k: usize| {
        let (p, m) = (&places[k], &marks[k]);
        let own = direction(m.side);
        if p.fits(theme, m, own, width) || !p.fits(theme, m, -own, width) {
            return false;
        }
        let clear = |j: usize| {
            let (q, n) = (&places[j], &marks[j]);
            j == k
                || n.label.is_empty()
                || [-1.0, 1.0]
                    .iter()
                    .all(|&d| !words_meet(theme, (p, m, -own), (q, n, d)))
        };
        m.label.is_empty() || (0..marks.len()).all(clear)
    };
    let sides: Vec<HAlign> = (0..marks.len())
        .map(|k| {
            if flip(k) {
                opposite(marks[k].side)
            } else {
                marks[k].side
            }
        })
        .collect();
    places
        .into_iter()
        .zip(marks)
        .zip(sides)
        .map(|((p, m), s)| (p, m, s))
        .collect()
}

/// Draws `mark` at `place` on `canvas`, towards `side`: a triangle
/// pointing at the chain, clear of it as [`MarkPlace`] says, its words
/// beyond it.
pub(super) fn draw_mark(
    theme: &Theme,
    canvas: &mut Picture,
    place: &MarkPlace,
    mark: &ChainMark,
    side: HAlign,
) {
    let (x, y) = (place.x, place.y);
    let dir = direction(side);
    let tip = x + dir * (place.reach(dir) + theme.mark_clear);
    let base = tip + dir * theme.mark_arrow;
    let half = theme.mark_half;
    canvas.polygon(
        &[(tip, y), (base, y - half), (base, y + half)],
        theme.color(mark.role),
    );
    if mark.label.is_empty() {
        return;
    }
    canvas.text(
        &mark.label,
        (base + dir * theme.mark_space, y),
        theme.mark_text,
        theme.text_color(mark.role),
        (opposite(side), VAlign::Middle),
    );
}
