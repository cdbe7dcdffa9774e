//! Vector primitives for drawn schematics (Fig. 2b): lines, dashed lines,
//! arrows, dimension lines and arcs on a tiny-skia canvas, in pixels.

use crate::encode::Rgb;
use crate::render::style;
use tiny_skia::{FillRule, LineCap, Paint, PathBuilder, Pixmap, Stroke, StrokeDash, Transform};

/// A pixel position (right, down).
pub type Pt = (f32, f32);

fn paint(c: Rgb) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color(style::color(c));
    p.anti_alias = true;
    p
}

fn stroke(width: f32, dashed: bool) -> Stroke {
    Stroke {
        width,
        line_cap: if dashed {
            LineCap::Butt
        } else {
            LineCap::Round
        },
        dash: if dashed {
            StrokeDash::new(vec![6.0, 4.0], 0.0)
        } else {
            None
        },
        ..Stroke::default()
    }
}

/// A polyline through `points`.
pub fn polyline(p: &mut Pixmap, points: &[Pt], width: f32, c: Rgb, dashed: bool) {
    let mut pb = PathBuilder::new();
    for (k, q) in points.iter().enumerate() {
        if k == 0 {
            pb.move_to(q.0, q.1);
        } else {
            pb.line_to(q.0, q.1);
        }
    }
    if let Some(path) = pb.finish() {
        let s = stroke(width, dashed);
        p.stroke_path(&path, &paint(c), &s, Transform::identity(), None);
    }
}

/// A straight segment.
pub fn line(p: &mut Pixmap, a: Pt, b: Pt, width: f32, c: Rgb) {
    polyline(p, &[a, b], width, c, false);
}

/// A dashed segment (construction lines).
pub fn dashed(p: &mut Pixmap, a: Pt, b: Pt, width: f32, c: Rgb) {
    polyline(p, &[a, b], width, c, true);
}

/// A filled disc.
pub fn dot(p: &mut Pixmap, at: Pt, r: f32, c: Rgb) {
    fill(p, PathBuilder::from_circle(at.0, at.1, r), c);
}

/// Fills `path` (if any) in colour `c`.
fn fill(p: &mut Pixmap, path: Option<tiny_skia::Path>, c: Rgb) {
    if let Some(path) = path {
        p.fill_path(
            &path,
            &paint(c),
            FillRule::Winding,
            Transform::identity(),
            None,
        );
    }
}

/// A filled arrowhead with its tip at `tip`, pointing along `from → tip`.
fn head(p: &mut Pixmap, from: Pt, tip: Pt, size: f32, c: Rgb) {
    let (dx, dy) = (tip.0 - from.0, tip.1 - from.1);
    let l = (dx * dx + dy * dy).sqrt().max(1e-3);
    let (ux, uy) = (dx / l, dy / l);
    let base = (tip.0 - size * ux, tip.1 - size * uy);
    let w = 0.45 * size;
    let mut pb = PathBuilder::new();
    pb.move_to(tip.0, tip.1);
    pb.line_to(base.0 - w * uy, base.1 + w * ux);
    pb.line_to(base.0 + w * uy, base.1 - w * ux);
    pb.close();
    fill(p, pb.finish(), c);
}

/// An arrow from `a` to `b`.
pub fn arrow(p: &mut Pixmap, a: Pt, b: Pt, width: f32, c: Rgb) {
    let size = 4.0 * width + 6.0;
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l = (dx * dx + dy * dy).sqrt().max(1e-3);
    let shaft_end = (b.0 - 0.8 * size * dx / l, b.1 - 0.8 * size * dy / l);
    line(p, a, shaft_end, width, c);
    head(p, a, b, size, c);
}

/// A dimension line: a segment with arrowheads at both ends.
pub fn dimension(p: &mut Pixmap, a: Pt, b: Pt, c: Rgb) {
    line(p, a, b, 1.3, c);
    head(p, b, a, 9.0, c);
    head(p, a, b, 9.0, c);
}

/// A circular arc about `centre` of radius `r` from angle `from` to `to`
/// (radians, pixel frame: 0 to the right, positive clockwise on screen).
pub fn arc(p: &mut Pixmap, centre: Pt, r: f32, from: f32, to: f32, width: f32, c: Rgb) {
    let steps = 48;
    let pts: Vec<Pt> = (0..=steps)
        .map(|k| {
            let t = from + (to - from) * k as f32 / steps as f32;
            (centre.0 + r * t.cos(), centre.1 + r * t.sin())
        })
        .collect();
    polyline(p, &pts, width, c, false);
}
