//! The marks beside a filmstrip's snapshots: a triangle pointing at the
//! chain, its words beyond it, on the side each mark asks for.

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

/// Where a mark goes on a snapshot: the point of the chain it points at
/// and how far the chain reaches from it on either side, in pixels.
struct MarkPlace {
    x: f32,
    y: f32,
    /// Pixels from `x` to the farthest node the tip must clear, leftwards
    /// and rightwards.
    reach: [f32; 2],
    /// Width of the words.
    label_w: f32,
}

impl MarkPlace {
    /// `mark` on a snapshot of `snap` drawn into `region`. The tip clears
    /// the farthest node of the two blocks at the mark from the mark's
    /// point (`side_clear` false: on either side, as the paper's figures
    /// are drawn) or the chain's extent on the mark's side (`side_clear`
    /// true: the mark then stays beside its own column of a folded ladder).
    fn new(
        theme: &Theme,
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
        let label_w = if mark.label.is_empty() {
            0.0
        } else {
            style::text_width(theme.font(), &mark.label, theme.mark_text)
        };
        MarkPlace {
            x,
            y,
            reach: [reach(-1.0), reach(1.0)],
            label_w,
        }
    }

    fn reach(&self, dir: f32) -> f32 {
        self.reach[usize::from(dir > 0.0)]
    }

    /// The tip of the triangle on the side `dir` (−1 left, 1 right).
    fn tip(&self, theme: &Theme, dir: f32) -> f32 {
        self.x + dir * (self.reach(dir) + theme.mark_clear)
    }

    /// The words' span across, left to right, on the side `dir` (empty
    /// words: none).
    fn words(&self, theme: &Theme, dir: f32) -> Option<(f32, f32)> {
        if self.label_w <= 0.0 {
            return None;
        }
        let near = self.tip(theme, dir) + dir * (theme.mark_arrow + theme.mark_space);
        let far = near + dir * self.label_w;
        Some((near.min(far), near.max(far)))
    }

    /// The far end of the mark on the side `dir`: its words' or its
    /// triangle's.
    fn far(&self, theme: &Theme, dir: f32) -> f32 {
        self.tip(theme, dir) + dir * (theme.mark_arrow + theme.mark_space + self.label_w)
    }
}

fn dir_of(side: HAlign) -> f32 {
    if side == HAlign::Left { -1.0 } else { 1.0 }
}

/// Draws `marks` onto a snapshot of `snap` drawn into `region` of
/// `canvas`: each a triangle pointing at the chain ([`MarkPlace::new`]),
/// its words beyond it. A mark whose words would leave the picture on its
/// own side goes to the other side (the last snapshot of a row has no
/// room on its right) when they fit there and clear the words of every
/// other mark; otherwise it keeps its side, its words a little past the
/// snapshot, in the gap beside it.
pub(super) fn draw_marks(
    theme: &Theme,
    canvas: &mut Picture,
    region: Region,
    ladder: &Ladder,
    snap: &Snapshot<'_>,
    marks: &[ChainMark],
    side_clear: bool,
) {
    let places: Vec<MarkPlace> = marks
        .iter()
        .map(|m| MarkPlace::new(theme, region, ladder, snap, m, side_clear))
        .collect();
    let width = canvas.width();
    let fits = |p: &MarkPlace, dir: f32| (0.0..=width).contains(&p.far(theme, dir));
    // The words of two marks meet where they share a line of text.
    let line = theme.mark_text;
    let meets = |a: &MarkPlace, da: f32, b: &MarkPlace, db: f32| match (
        a.words(theme, da),
        b.words(theme, db),
    ) {
        (Some(u), Some(v)) => (a.y - b.y).abs() < line && u.0 < v.1 && v.0 < u.1,
        _ => false,
    };
    let asked: Vec<f32> = marks.iter().map(|m| dir_of(m.side)).collect();
    let dirs: Vec<f32> = places
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let d = asked[k];
            let clear = places
                .iter()
                .enumerate()
                .all(|(o, q)| o == k || !meets(p, -d, q, asked[o]));
            if !fits(p, d) && fits(p, -d) && clear {
                -d
            } else {
                d
            }
        })
        .collect();
    for ((mark, p), dir) in marks.iter().zip(&places).zip(dirs) {
        let tip = p.tip(theme, dir);
        let base = tip + dir * theme.mark_arrow;
        let half = theme.mark_half;
        canvas.polygon(
            &[(tip, p.y), (base, p.y - half), (base, p.y + half)],
            theme.color(mark.role),
        );
        if mark.label.is_empty() {
            continue;
        }
        let align = if dir < 0.0 {
            HAlign::Right
        } else {
            HAlign::Left
        };
        canvas.text(
            &mark.label,
            (base + dir * theme.mark_space, p.y),
            theme.mark_text,
            theme.text_color(mark.role),
            (align, VAlign::Middle),
        );
    }
}

/// Pixels a mark reaches beyond the chain on its side.
pub(super) fn mark_room(theme: &Theme, mark: &ChainMark) -> f32 {
    let label = style::text_width(theme.font(), &mark.label, theme.mark_text);
    theme.mark_clear + theme.mark_arrow + theme.mark_space + label + theme.mark_slack
}
