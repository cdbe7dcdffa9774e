//! Drawing helpers for schematics (Fig. 2b) and keys: dashed construction
//! lines, arrows, dimension lines and arcs on any [`Canvas`], in pixels.

use crate::encode::Rgb;
use crate::render::{Canvas, Pen};

/// A pixel position (right, down).
pub type Pt = (f32, f32);

/// Dash of construction lines: on, off in pixels.
const DASH: (f32, f32) = (6.0, 4.0);

/// A polyline through `points` (round caps), or dashed (butt caps).
pub fn polyline(c: &mut impl Canvas, points: &[Pt], width: f32, color: Rgb, dashed: bool) {
    let pen = if dashed {
        Pen::new(width, color).dashed(DASH.0, DASH.1)
    } else {
        Pen::new(width, color).round()
    };
    c.polyline(points, &pen);
}

/// A straight segment with round caps.
pub fn line(c: &mut impl Canvas, a: Pt, b: Pt, width: f32, color: Rgb) {
    polyline(c, &[a, b], width, color, false);
}

/// A dashed segment (construction lines).
pub fn dashed(c: &mut impl Canvas, a: Pt, b: Pt, width: f32, color: Rgb) {
    polyline(c, &[a, b], width, color, true);
}

/// A filled disc.
pub fn dot(c: &mut impl Canvas, at: Pt, r: f32, color: Rgb) {
    c.disc(at, r, color);
}

/// A filled arrowhead with its tip at `tip`, pointing along `from → tip`.
fn head(c: &mut impl Canvas, from: Pt, tip: Pt, size: f32, color: Rgb) {
    let (dx, dy) = (tip.0 - from.0, tip.1 - from.1);
    let l = (dx * dx + dy * dy).sqrt().max(1e-3);
    let (ux, uy) = (dx / l, dy / l);
    let base = (tip.0 - size * ux, tip.1 - size * uy);
    let w = 0.45 * size;
    c.polygon(
        &[
            tip,
            (base.0 - w * uy, base.1 + w * ux),
            (base.0 + w * uy, base.1 - w * ux),
        ],
        color,
    );
}

/// An arrow from `a` to `b`.
pub fn arrow(c: &mut impl Canvas, a: Pt, b: Pt, width: f32, color: Rgb) {
    let size = 4.0 * width + 6.0;
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l = (dx * dx + dy * dy).sqrt().max(1e-3);
    let shaft_end = (b.0 - 0.8 * size * dx / l, b.1 - 0.8 * size * dy / l);
    line(c, a, shaft_end, width, color);
    head(c, a, b, size, color);
}

/// A dimension line: a segment with arrowheads at both ends.
pub fn dimension(c: &mut impl Canvas, a: Pt, b: Pt, color: Rgb) {
    line(c, a, b, 1.3, color);
    head(c, b, a, 9.0, color);
    head(c, a, b, 9.0, color);
}

/// A circular arc about `centre` of radius `r` from angle `from` to `to`
/// (radians, pixel frame: 0 to the right, positive clockwise on screen).
pub fn arc(c: &mut impl Canvas, centre: Pt, r: f32, from: f32, to: f32, width: f32, color: Rgb) {
    let steps = 48;
    let pts: Vec<Pt> = (0..=steps)
        .map(|k| {
            let t = from + (to - from) * k as f32 / steps as f32;
            (centre.0 + r * t.cos(), centre.1 + r * t.sin())
        })
        .collect();
    polyline(c, &pts, width, color, false);
}
