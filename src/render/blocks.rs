//! The toy as built drawn (docs/experiments.md, "The toy as built"):
//! each block as its rectangle s × d, filled and outlined, its A and B
//! ends tinted as the paper's blocks are (Fig. 2); each ribbon along its
//! path: glued at its anchor, along the outline round the corners it
//! wraps, across the straight free span between the two tangent points
//! at which its tension acts, and wrapped on the other block to its
//! anchor there. The tangent points and wrapped lengths are the model's
//! (`model::ribbons`, [`Ribbons::for_each_span`]), not found again here:
//! a wrapped part is the walk of the model's wrapped length from the
//! anchor, the way round that ends at the model's tangent point. An
//! impact is marked by a ring at the point where its two blocks touch.

use super::canvas::{Canvas, Pen};
use super::palette::{Palette, Role};
use super::style;
use crate::encode::Rgb;
use crate::model::built::AsBuilt;
use crate::model::outline::{Outline, Pose};
use crate::model::params::R;
use crate::model::ribbons::{Anchor, Ribbon, Ribbons, Span};

/// Tolerance on a walked length and on a corner's position, in s.
const WALK_TOL: f64 = 1e-9;

/// Model-to-pixel map of the picture the blocks are drawn in (the
/// snapshot's: equal scales, implemented there).
pub(crate) trait ToPixels {
    /// Pixel (horizontal, vertical) of a model point [x, y].
    fn px(&self, p: [f64; 2]) -> (f32, f32);
    /// A model length in pixels, clamped to [lo, hi].
    fn len(&self, l: f64, lo: f32, hi: f32) -> f32;
}

/// The four corners c₀ … c₃ of block `i` (zero-based) at `q`, in the lab.
pub fn block_corners(o: &Outline, q: &[f64], i: usize) -> [[f64; 2]; 4] {
    let pose = Pose::of(q, i);
    [0, 1, 2, 3].map(|k| pose.point(o.corner(k)))
}

/// The frame points of a ribbon's wrapped part on one block: from its
/// `anchor` round the corners to the tangent point `end`, `arc` long (the
/// model's [`Span::wrapped`]). The model's points of departure are the
/// anchor and the corners met walking either way round from it; of the
/// two ways, the one whose walk of `arc` ends at `end`. `None` if neither
/// does (never, for a span of the model: tested).
pub fn wrapped_frame_path(
    o: &Outline,
    anchor: Anchor,
    arc: f64,
    end: [f64; 2],
) -> Option<Vec<[f64; 2]>> {
    let start = o.on_edge(anchor.edge % 4, anchor.along);
    let near = |p: [f64; 2]| (p[0] - end[0]).hypot(p[1] - end[1]) <= WALK_TOL * 10.0;
    if arc.abs() <= WALK_TOL && near(start) {
        return Some(vec![start]);
    }
    [1, -1]
        .into_iter()
        .find_map(|sigma| walk(o, anchor, sigma, arc, near))
}

/// The walk of `arc` from `anchor` round the outline, `sigma` = +1 towards
/// corner k + 1, −1 towards corner k (corner k − 1 from an anchor at
/// corner k), if it stops at a corner that is `near` the end.
fn walk(
    o: &Outline,
    anchor: Anchor,
    sigma: i32,
    arc: f64,
    near: impl Fn([f64; 2]) -> bool,
) -> Option<Vec<[f64; 2]>> {
    let k = anchor.edge % 4;
    let f = anchor.along;
    let mut path = vec![o.on_edge(k, f)];
    let (mut walked, mut m) = if sigma > 0 {
        ((1.0 - f) * o.edge_length(k), k + 1)
    } else if f == 0.0 {
        (o.edge_length(k + 3), k + 3)
    } else {
        (f * o.edge_length(k), k)
    };
    for _ in 0..4 {
        path.push(o.corner(m));
        if (walked - arc).abs() <= WALK_TOL && near(o.corner(m)) {
            return Some(path);
        }
        if walked > arc + WALK_TOL {
            return None;
        }
        let edge = if sigma > 0 { m % 4 } else { (m + 3) % 4 };
        walked += o.edge_length(edge);
        m = if sigma > 0 { m + 1 } else { m + 3 };
    }
    None
}

/// A ribbon's path in the lab: its anchor on the upper block, the corners
/// it wraps there, the tangent points D and E of its free span (`span`,
/// the model's), the corners it wraps on the lower block, its anchor
/// there. `None` if a wrapped part is not a walk of the outline.
pub fn ribbon_path(
    o: &Outline,
    ribbon: &Ribbon,
    upper: &Pose,
    lower: &Pose,
    span: &Span,
) -> Option<Vec<[f64; 2]>> {
    let up = wrapped_frame_path(o, ribbon.upper, span.wrapped[0], span.d)?;
    let low = wrapped_frame_path(o, ribbon.lower, span.wrapped[1], span.e)?;
    let mut path: Vec<[f64; 2]> = up.iter().map(|&p| upper.point(p)).collect();
    path.extend(low.iter().rev().map(|&p| lower.point(p)));
    Some(path)
}

/// Every ribbon's path at `q` of `n` blocks: (junction, ribbon 0 or 1,
/// lab points), junction after junction.
pub fn ribbon_paths(ribbons: &Ribbons, n: usize, q: &[f64]) -> Vec<(usize, usize, Vec<[f64; 2]>)> {
    let mut out = Vec::new();
    let mut count = 0;
    ribbons.for_each_span(n, q, |i, pu, pl, span| {
        let r = count % 2;
        count += 1;
        let ribbon = &ribbons.ribbons[r];
        let path = ribbon_path(&ribbons.outline, ribbon, pu, pl, span)
            .unwrap_or_else(|| vec![pu.point(span.d), pl.point(span.e)]);
        out.push((i, r, path));
    });
    out
}

/// Where blocks `a` and `b` (zero-based) touch at `q`: the corner of one
/// deepest inside the other's outline, or, when none is inside, nearest
/// to it (the lab point).
pub fn contact_point(o: &Outline, q: &[f64], a: usize, b: usize) -> [f64; 2] {
    let h = o.half_thickness;
    let (pa, pb) = (Pose::of(q, a), Pose::of(q, b));
    let mut best = (f64::INFINITY, pa.centre);
    for (p, other) in [(&pa, &pb), (&pb, &pa)] {
        for k in 0..4 {
            let x = p.point(o.corner(k));
            let l = other.local(x);
            // Signed distance to the rectangle |u| ≤ r, |w| ≤ h.
            let (du, dw) = (l[0].abs() - R, l[1].abs() - h);
            let outside = du.max(0.0).hypot(dw.max(0.0));
            let d = if outside > 0.0 { outside } else { du.max(dw) };
            if d < best.0 {
                best = (d, x);
            }
        }
    }
    best.1
}

/// The colours of the toy as built: live, or a grey ghost underneath.
struct Inks {
    fill: Rgb,
    a_end: Rgb,
    b_end: Rgb,
    edge: Rgb,
    ribbon: [Rgb; 2],
}

impl Inks {
    fn new(ghost: bool) -> Self {
        let paper = Palette.color(Role::Paper);
        if ghost {
            let g = style::mix(paper, Palette.color(Role::Ground), 0.35);
            let e = Palette.color(Role::Ground);
            return Self {
                fill: g,
                a_end: g,
                b_end: g,
                edge: e,
                ribbon: [e, e],
            };
        }
        Self {
            fill: style::mix(paper, Palette.color(Role::Ground), 0.3),
            a_end: style::mix(paper, Palette.color(Role::SpringA), 0.55),
            b_end: style::mix(paper, Palette.color(Role::SpringB), 0.55),
            edge: Palette.color(Role::Ink),
            ribbon: [Palette.color(Role::SpringA), Palette.color(Role::SpringB)],
        }
    }
}

/// The blocks of `q` as rectangles and the ribbons of `built` along their
/// paths, through `map`; grey when `ghost`. Ribbon 2 is dashed, as the B
/// springs are (a cue besides colour in grey print).
pub(crate) fn draw_built(
    canvas: &mut impl Canvas,
    map: &impl ToPixels,
    q: &[f64],
    built: &AsBuilt,
    ghost: bool,
) {
    let inks = Inks::new(ghost);
    let o = &built.ribbons.outline;
    let n = q.len() / 3;
    let edge = Pen::new(map.len(0.012, 0.75, 2.0), inks.edge);
    for i in 0..n {
        draw_block(canvas, map, o, q, i, &inks, &edge);
    }
    let w = map.len(0.02, 1.0, 3.0);
    let pens = [
        Pen::new(w, inks.ribbon[0]).round(),
        Pen::new(w, inks.ribbon[1]).dashed((3.0 * w).max(2.5), (2.0 * w).max(1.5)),
    ];
    for (_, r, path) in ribbon_paths(&built.ribbons, n, q) {
        let px: Vec<(f32, f32)> = path.iter().map(|&p| map.px(p)).collect();
        canvas.polyline(&px, &pens[r]);
    }
}

/// Block `i`: its rectangle filled, the quarter at each end tinted by the
/// end (A: u < 0, B: u > 0), outlined.
fn draw_block(
    canvas: &mut impl Canvas,
    map: &impl ToPixels,
    o: &Outline,
    q: &[f64],
    i: usize,
    inks: &Inks,
    edge: &Pen,
) {
    let pose = Pose::of(q, i);
    let h = o.half_thickness;
    let quad =
        |u0: f64, u1: f64| [[u0, -h], [u1, -h], [u1, h], [u0, h]].map(|p| map.px(pose.point(p)));
    canvas.polygon(&quad(-R, R), inks.fill);
    canvas.polygon(&quad(-R, -0.5 * R), inks.a_end);
    canvas.polygon(&quad(0.5 * R, R), inks.b_end);
    let mut outline = quad(-R, R).to_vec();
    outline.push(outline[0]);
    canvas.polyline(&outline, edge);
}

/// A ring round each of `points` (lab), the mark of an impact.
pub(crate) fn draw_impacts(canvas: &mut impl Canvas, map: &impl ToPixels, points: &[[f64; 2]]) {
    let r = map.len(0.12, 4.0, 14.0);
    let pen = Pen::new((0.22 * r).clamp(1.2, 3.0), Palette.color(Role::Ink));
    for &p in points {
        let at = map.px(p);
        if let Some(path) = tiny_skia::PathBuilder::from_circle(at.0, at.1, r) {
            canvas.stroke(&path, &pen);
        }
        canvas.disc(at, 0.25 * r, Palette.color(Role::Ink));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ribbons::Ribbons;

    fn column_ribbons(d: f64) -> Ribbons {
        let o = Outline::new(d);
        let glue = |f| (Anchor { edge: 2, along: f }, Anchor { edge: 2, along: f });
        let other = |f| (Anchor { edge: 0, along: f }, Anchor { edge: 0, along: f });
        Ribbons::glued_in_column(o, [glue(0.0), other(0.0)], 1.2)
    }

    /// The polyline's length.
    fn length(path: &[[f64; 2]]) -> f64 {
        path.windows(2)
            .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
            .sum()
    }

    #[test]
    fn a_drawn_ribbon_is_as_long_as_the_model_says_and_ends_at_its_tangent_points() {
        let ribbons = column_ribbons(0.12);
        let n = 4;
        // A bent chain: the ribbons wrap.
        let mut q = vec![0.0; 3 * n];
        for i in 0..n {
            q[3 * i] = 1.2 * i as f64;
            q[3 * i + 2] = 1.5 - 0.6 * i as f64;
        }
        let mut spans = Vec::new();
        ribbons.for_each_span(n, &q, |_, pu, pl, s| {
            spans.push((pu.point(s.d), pl.point(s.e), s.length))
        });
        let paths = ribbon_paths(&ribbons, n, &q);
        assert_eq!(paths.len(), spans.len());
        for ((_, r, path), (d, e, len)) in paths.iter().zip(&spans) {
            let ribbon = &ribbons.ribbons[*r];
            assert!(path.len() >= 2);
            assert!(
                (length(path) - len).abs() < 1e-9,
                "{} vs {len}",
                length(path)
            );
            // D and E are consecutive points of the path.
            let has = |p: [f64; 2]| {
                path.iter()
                    .position(|x| (x[0] - p[0]).hypot(x[1] - p[1]) < 1e-9)
            };
            let (i, j) = (has(*d).unwrap(), has(*e).unwrap());
            assert!(j == i + 1 || (i == j && len.abs() < 1e-9), "{i} {j}");
            let _ = ribbon;
        }
    }

    #[test]
    fn a_wrapped_part_follows_the_outline_either_way_round() {
        let o = Outline::new(0.2);
        let a = Anchor {
            edge: 2,
            along: 0.5,
        };
        // +1: to corner 3 (half the face), then corner 0 (the end).
        let p = wrapped_frame_path(&o, a, 0.5 + 0.2, o.corner(0)).unwrap();
        assert_eq!(p, vec![o.on_edge(2, 0.5), o.corner(3), o.corner(0)]);
        // −1: to corner 2.
        let p = wrapped_frame_path(&o, a, 0.5, o.corner(2)).unwrap();
        assert_eq!(p, vec![o.on_edge(2, 0.5), o.corner(2)]);
        assert!(wrapped_frame_path(&o, a, 0.3, o.corner(2)).is_none());
    }

    #[test]
    fn the_contact_point_is_the_corner_pressed_in() {
        let o = Outline::new(0.1);
        // Block 2 lying across below block 1's B end, a corner of block 1
        // pressed into its face.
        let q = [0.0, 0.0, std::f64::consts::FRAC_PI_2, 0.54, 0.0, 0.0];
        let p = contact_point(&o, &q, 0, 1);
        let corners = block_corners(&o, &q, 0);
        assert!(corners.contains(&p), "{p:?} {corners:?}");
        assert!((p[0] - 0.5).abs() < 1e-12, "{p:?}");
    }
}
