//! Fig. 2b (and supplement Fig. S2b): one unit of the asymmetric ladder,
//! drawn from the model's two-block ground state at θ = α: blocks of length
//! s with their vermillion A and blue B ends, the A link (length a,
//! vermillion, solid) and the B link (length b, blue, dashed), the angle θ from the transverse y axis, and the
//! offsets Δx, Δy of eq:b and eq:del_y. Gravity points down the page.

use super::pen::{self, Pt};
use super::{FigureInput, frame};
use crate::encode::Rgb;
use crate::error::Result;
use crate::model::Ladder;
use crate::model::ladder::nodes;
use crate::render::palette::{Palette, Role};
use crate::render::style::{HAlign, VAlign};
use crate::render::{Canvas, Picture, Theme};

/// Canvas size, pixels per s and the pixel position of block n's centre.
const W: u32 = 880;
const H: u32 = 620;
const SCALE: f64 = 215.0;
const ORIGIN: Pt = (470.0, 150.0);
/// Annotation text size: 19 px, more where the drawing is scaled down to
/// fit a print page (so that it prints at no less than the smallest print
/// text).
fn text_size(theme: &Theme) -> f32 {
    let scale = super::drawing_scale(theme, W as f32, H as f32);
    theme.text_at_least(0.0).max(19.0 * scale) / scale
}

/// Pixel position of the model point [x (down), y (across)].
fn px(p: [f64; 2]) -> Pt {
    (
        ORIGIN.0 + (p[1] * SCALE) as f32,
        ORIGIN.1 + (p[0] * SCALE) as f32,
    )
}

fn add(p: Pt, d: (f32, f32)) -> Pt {
    (p.0 + d.0, p.1 + d.1)
}

fn mid(a: Pt, b: Pt) -> Pt {
    (0.5 * (a.0 + b.0), 0.5 * (a.1 + b.1))
}

fn text(p: &mut Picture, s: &str, at: Pt, c: Rgb, align: (HAlign, VAlign)) {
    let size = text_size(p.theme());
    p.text(s, at, size, c, align);
}

const MIDDLE: (HAlign, VAlign) = (HAlign::Center, VAlign::Middle);
const LEFT: (HAlign, VAlign) = (HAlign::Left, VAlign::Middle);

/// The figure: drawing plus notes.
pub fn unit(theme: &Theme, input: &FigureInput) -> Result<Picture> {
    let (b, alpha) = (input.model.b, input.model.alpha);
    let ladder = Ladder::new(input.params(2, b, alpha)?);
    let q = ladder.ground_state();
    let mut p = Picture::new(theme, W as f32, H as f32);
    let unit = Unit::of(&q);
    draw_links_and_blocks(&mut p, &unit);
    draw_theta(&mut p, &unit);
    draw_s(&mut p, &unit);
    draw_offsets(&mut p, &unit);
    draw_frame_hints(&mut p);
    let notes = format!(
        "Drawn from the model's ground state of two blocks at b/s = {b}, θ = α = {alpha}°, \
         a = √(b² + 4s²cos²α) = {:.3} s. The A link (vermillion, solid) joins the vermillion A ends of \
         the blocks, the B link (blue, dashed) their blue B ends. θ is measured from the transverse y axis \
         (counter-clockwise for even n, clockwise for odd n); Δx is the gap along gravity \
         between the facing ends, Δy the transverse offset of the centres. \
         At θ = α: Δx = b − s sin α, Δy = s cos α, and the B link hangs straight down.",
        ladder.a
    );
    let p = super::scaled(&p, super::drawing_scale(theme, W as f32, H as f32));
    frame(theme, &input.title, &p, &notes, W)
}

/// Pixel positions of the unit's nodes and centres.
struct Unit {
    /// A and B nodes of the upper block n and the lower block n + 1.
    a1: Pt,
    b1: Pt,
    a2: Pt,
    b2: Pt,
    c1: Pt,
    c2: Pt,
}

impl Unit {
    fn of(q: &[f64]) -> Unit {
        let (a1, b1) = nodes(q, 0);
        let (a2, b2) = nodes(q, 1);
        Unit {
            a1: px(a1),
            b1: px(b1),
            a2: px(a2),
            b2: px(b2),
            c1: px([q[0], q[1]]),
            c2: px([q[3], q[4]]),
        }
    }
}

fn draw_links_and_blocks(p: &mut Picture, u: &Unit) {
    pen::line(p, u.a1, u.a2, 3.5, Palette.color(Role::SpringA));
    // The B link as the ladder drawings draw it: blue and dashed.
    pen::dashed(p, u.b1, u.b2, 3.5, Palette.color(Role::SpringB));
    for (a, b) in [(u.a1, u.b1), (u.a2, u.b2)] {
        let at = |f: f32| (a.0 + (b.0 - a.0) * f, a.1 + (b.1 - a.1) * f);
        pen::line(p, a, b, 14.0, Palette.color(Role::Ink));
        pen::line(p, a, at(0.22), 14.0, Palette.color(Role::SpringA));
        pen::line(p, at(0.78), b, 14.0, Palette.color(Role::SpringB));
    }
    for c in [u.c1, u.c2] {
        pen::dot(p, c, 4.0, Palette.color(Role::Paper));
    }
    let ma = mid(u.a1, u.a2);
    text(
        p,
        "a",
        add(ma, (-22.0, -6.0)),
        Palette.color(Role::SpringA),
        MIDDLE,
    );
    text(
        p,
        "A",
        add(u.a1, (16.0, -10.0)),
        Palette.color(Role::SpringA),
        LEFT,
    );
    let mb = mid(u.b1, u.b2);
    text(
        p,
        "b",
        add(mb, (16.0, 0.0)),
        Palette.color(Role::SpringB),
        LEFT,
    );
    text(
        p,
        "B",
        add(u.b1, (-26.0, 4.0)),
        Palette.color(Role::SpringB),
        MIDDLE,
    );
    text(
        p,
        "block n",
        add(u.c1, (120.0, -60.0)),
        Palette.color(Role::Ink),
        LEFT,
    );
    let at = add(u.c2, (-60.0, -30.0));
    text(
        p,
        "block n + 1",
        at,
        Palette.color(Role::Ink),
        (HAlign::Right, VAlign::Middle),
    );
}

/// θ between the transverse axis (dashed, through block n's centre) and
/// the upper half of block n.
fn draw_theta(p: &mut Picture, u: &Unit) {
    let r = 0.36 * SCALE as f32;
    pen::dashed(
        p,
        u.c1,
        add(u.c1, (1.35 * r, 0.0)),
        1.3,
        Palette.color(Role::Ground),
    );
    let up = ((u.a1.1 - u.c1.1).atan2(u.a1.0 - u.c1.0), 0.0);
    pen::arc(p, u.c1, r, up.0, up.1, 1.6, Palette.color(Role::Ink));
    let half = 0.5 * up.0;
    let at = add(u.c1, (1.28 * r * half.cos(), 1.28 * r * half.sin()));
    text(p, "θ", at, Palette.color(Role::Ink), MIDDLE);
}

/// The block length s as a dimension line beside block n + 1.
fn draw_s(p: &mut Picture, u: &Unit) {
    let (dx, dy) = (u.b2.0 - u.a2.0, u.b2.1 - u.a2.1);
    let l = (dx * dx + dy * dy).sqrt();
    // The side of block n + 1 away from the links: left and down.
    let nrm = (-dy / l, dx / l);
    let off = (0.16 * SCALE) as f32;
    let o = (nrm.0 * off, nrm.1 * off);
    let (a, b) = (add(u.a2, o), add(u.b2, o));
    pen::dimension(p, a, b, Palette.color(Role::Ink));
    let m = add(mid(a, b), (nrm.0 * 18.0, nrm.1 * 18.0));
    text(p, "s", m, Palette.color(Role::Ink), MIDDLE);
}

/// Δx (gap along gravity between the facing block ends) to the right, Δy
/// (transverse offset of the centres) below the unit.
fn draw_offsets(p: &mut Picture, u: &Unit) {
    let right = u.c1.0 + (0.62 * SCALE) as f32;
    let (top, bottom) = (u.b1.1, u.a2.1);
    pen::dashed(
        p,
        u.b1,
        (right + 12.0, top),
        1.2,
        Palette.color(Role::Ground),
    );
    pen::dashed(
        p,
        u.a2,
        (right + 12.0, bottom),
        1.2,
        Palette.color(Role::Ground),
    );
    pen::dimension(p, (right, top), (right, bottom), Palette.color(Role::Ink));
    text(
        p,
        "Δx",
        (right + 14.0, 0.5 * (top + bottom)),
        Palette.color(Role::Ink),
        LEFT,
    );
    let low = u.b2.1 + (0.32 * SCALE) as f32;
    pen::dashed(
        p,
        u.c1,
        (u.c1.0, low + 12.0),
        1.2,
        Palette.color(Role::Ground),
    );
    pen::dashed(
        p,
        u.c2,
        (u.c2.0, low + 12.0),
        1.2,
        Palette.color(Role::Ground),
    );
    pen::dimension(p, (u.c2.0, low), (u.c1.0, low), Palette.color(Role::Ink));
    text(
        p,
        "Δy",
        (0.5 * (u.c1.0 + u.c2.0), low + 22.0),
        Palette.color(Role::Ink),
        MIDDLE,
    );
}

/// Axes (x down along gravity, y across) and the gravity arrow, top left.
fn draw_frame_hints(p: &mut Picture) {
    let o = (60.0, 40.0);
    pen::arrow(p, o, (o.0, o.1 + 70.0), 1.6, Palette.color(Role::Ink));
    pen::arrow(p, o, (o.0 + 70.0, o.1), 1.6, Palette.color(Role::Ink));
    text(
        p,
        "x",
        (o.0 - 16.0, o.1 + 62.0),
        Palette.color(Role::Ink),
        MIDDLE,
    );
    text(
        p,
        "y",
        (o.0 + 66.0, o.1 - 14.0),
        Palette.color(Role::Ink),
        MIDDLE,
    );
    let g = (o.0 + 8.0, o.1 + 160.0);
    pen::arrow(p, g, (g.0, g.1 + 110.0), 3.0, Palette.color(Role::Ink));
    text(
        p,
        "g",
        (g.0 + 14.0, g.1 + 50.0),
        Palette.color(Role::Ink),
        LEFT,
    );
}
