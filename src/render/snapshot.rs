//! Snapshots of the ladder drawn with tiny-skia.
//!
//! Each block is a dark bar of length s with a red A end and a blue B end, so
//! its orientation is visible; A springs are red and B springs green (paper
//! Fig. 2). Block 1, whose centre is held and whose angle is driven, carries
//! a pin support. Model x (along gravity) points down the image, model y to
//! the right, with equal scales.

use super::blocks::ToPixels;
use super::canvas::{Canvas, Pen, Raster};
use super::picture::Picture;
use super::style::{self, HAlign, VAlign, size};
use super::theme::Theme;
use crate::encode::Rgb;
use crate::error::{Error, Result};
use crate::model::Ladder;
use crate::model::ladder::{ix, iy, nodes};
use crate::model::params::S;
use crate::render::palette::{Palette, Role};
use tiny_skia::Pixmap;

/// Model units added around the fitted states (room for the pin support).
const FIT_PAD: f64 = 0.4;
/// How far the pin support reaches above block 1, in units of s.
const CLAMP_HEIGHT: f64 = 0.55;

/// The part of the model plane shown: `x` (down the image) and `y` (across)
/// ranges in model units. The frame keeps equal scales and centres the
/// window, so the shown region may be larger along one axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// Model x range (top to bottom of the image).
    pub x: (f64, f64),
    /// Model y range (left to right of the image).
    pub y: (f64, f64),
}

impl View {
    /// The smallest window holding every block of every state (plus the pin
    /// support of block 1 and a small pad). Non-finite coordinates are
    /// ignored; with nothing finite the window is the unit square.
    pub fn fit(states: &[&[f64]]) -> View {
        let mut b = Bounds::default();
        for q in states {
            let n = q.len() / 3;
            for i in 0..n {
                let (a, bn) = nodes(q, i);
                b.add(a);
                b.add(bn);
            }
            if n > 0 {
                b.add([q[ix(0)] - CLAMP_HEIGHT * S, q[iy(0)]]);
            }
        }
        b.view(FIT_PAD)
    }

    /// A fixed window (e.g. the same for every frame of a movie, or one that
    /// follows the kink). Reversed ranges are put in order.
    pub fn window(x_range: (f64, f64), y_range: (f64, f64)) -> View {
        let order = |(a, b): (f64, f64)| if a <= b { (a, b) } else { (b, a) };
        View {
            x: order(x_range),
            y: order(y_range),
        }
    }

    /// A window of the given spans centred on (`x`, `y`): a camera.
    pub fn centered(x: f64, y: f64, x_span: f64, y_span: f64) -> View {
        let (hx, hy) = (0.5 * x_span.abs(), 0.5 * y_span.abs());
        View::window((x - hx, x + hx), (y - hy, y + hy))
    }

    /// The union of two windows.
    pub fn union(self, other: View) -> View {
        View {
            x: (self.x.0.min(other.x.0), self.x.1.max(other.x.1)),
            y: (self.y.0.min(other.y.0), self.y.1.max(other.y.1)),
        }
    }

    fn span(r: (f64, f64)) -> f64 {
        let s = r.1 - r.0;
        if s.is_finite() && s > 1e-9 { s } else { 1e-9 }
    }
}

#[derive(Default)]
struct Bounds {
    min: Option<[f64; 2]>,
    max: [f64; 2],
}

impl Bounds {
    fn add(&mut self, p: [f64; 2]) {
        if !(p[0].is_finite() && p[1].is_finite()) {
            return;
        }
        match &mut self.min {
            None => {
                self.min = Some(p);
                self.max = p;
            }
            Some(m) => {
                *m = [m[0].min(p[0]), m[1].min(p[1])];
                self.max = [self.max[0].max(p[0]), self.max[1].max(p[1])];
            }
        }
    }

    fn view(&self, pad: f64) -> View {
        match self.min {
            None => View::window((-0.5, 0.5), (-0.5, 0.5)),
            Some(m) => View::window(
                (m[0] - pad, self.max[0] + pad),
                (m[1] - pad, self.max[1] + pad),
            ),
        }
    }
}

/// A rectangle of pixels on a canvas.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Region {
    /// Left edge in pixels.
    pub x: f32,
    /// Top edge in pixels.
    pub y: f32,
    /// Width in pixels.
    pub w: f32,
    /// Height in pixels.
    pub h: f32,
}

impl Region {
    /// The whole of a `width × height` canvas.
    pub fn full(width: u32, height: u32) -> Region {
        Region {
            x: 0.0,
            y: 0.0,
            w: width as f32,
            h: height as f32,
        }
    }
}

/// Model-to-pixel map: equal scales, window centred in the region.
#[derive(Clone, Copy, Debug)]
struct Mapping {
    scale: f64,
    x_mid: f64,
    y_mid: f64,
    px_mid: f64,
    py_mid: f64,
}

impl Mapping {
    fn new(view: &View, r: Region) -> Mapping {
        let (w, h) = (r.w.max(1.0) as f64, r.h.max(1.0) as f64);
        let scale = (w / View::span(view.y)).min(h / View::span(view.x));
        Mapping {
            scale,
            x_mid: 0.5 * (view.x.0 + view.x.1),
            y_mid: 0.5 * (view.y.0 + view.y.1),
            px_mid: r.x as f64 + 0.5 * w,
            py_mid: r.y as f64 + 0.5 * h,
        }
    }
}

impl ToPixels for Mapping {
    /// Pixel (horizontal, vertical) of a model point [x, y].
    fn px(&self, p: [f64; 2]) -> (f32, f32) {
        (
            (self.px_mid + (p[1] - self.y_mid) * self.scale) as f32,
            (self.py_mid + (p[0] - self.x_mid) * self.scale) as f32,
        )
    }

    /// A model length in pixels, clamped to [lo, hi].
    fn len(&self, l: f64, lo: f32, hi: f32) -> f32 {
        ((l * self.scale) as f32).clamp(lo, hi)
    }
}

/// One snapshot of the ladder: a state, and what to draw with it.
#[derive(Clone, Copy, Debug)]
pub struct Snapshot<'a> {
    /// The state q = [X_1, Y_1, θ_1, X_2, ...].
    pub q: &'a [f64],
    /// A second state drawn in grey underneath (e.g. the ground state).
    pub ghost: Option<&'a [f64]>,
    /// Time in units of τ, shown as "t/τ = 1234" centred at the bottom.
    pub time: Option<f64>,
    /// Title shown at the top.
    pub title: Option<&'a str>,
    /// Window in model units; `None` fits the state (and the ghost).
    pub view: Option<View>,
    /// Draw the pin support of the driven block 1.
    pub clamp: bool,
    /// A scale fixed in the lab behind the ladder: a faint line across the
    /// window at each of these positions along the ladder (model x),
    /// numbered 1, 2, ... at the left edge. Under a moving camera (movie 3)
    /// it scrolls through the frame and shows the camera's motion.
    pub lab_scale: Option<&'a [f64]>,
    /// The toy as built (`render::blocks`): blocks drawn as rectangles
    /// and ribbons along their paths; the ladder's, none for the paper's
    /// model.
    pub built: Option<crate::model::built::AsBuilt>,
    /// Pairs of blocks (zero-based) whose impact is marked at the point
    /// where they touch (`render::blocks`): none by default.
    pub impacts: &'a [[usize; 2]],
}

impl<'a> Snapshot<'a> {
    /// A snapshot of `q`, checked against the ladder's number of blocks.
    pub fn new(ladder: &Ladder, q: &'a [f64]) -> Result<Self> {
        check_state(ladder, q, "state")?;
        Ok(Snapshot {
            q,
            ghost: None,
            time: None,
            title: None,
            view: None,
            clamp: true,
            lab_scale: None,
            built: ladder.built,
            impacts: &[],
        })
    }

    /// Draws `ghost` (same ladder) in grey underneath.
    pub fn with_ghost(mut self, ladder: &Ladder, ghost: &'a [f64]) -> Result<Self> {
        check_state(ladder, ghost, "ghost state")?;
        self.ghost = Some(ghost);
        Ok(self)
    }

    /// Shows the time label "t/τ = …".
    pub fn with_time(mut self, t: f64) -> Self {
        self.time = Some(t);
        self
    }

    /// Shows a title at the top.
    pub fn with_title(mut self, title: &'a str) -> Self {
        self.title = Some(title);
        self
    }

    /// Uses a fixed window instead of fitting.
    pub fn with_view(mut self, view: View) -> Self {
        self.view = Some(view);
        self
    }

    /// The window used: the given one or the fit of state and ghost.
    pub fn view(&self) -> View {
        self.view.unwrap_or_else(|| match self.ghost {
            Some(g) => View::fit(&[self.q, g]),
            None => View::fit(&[self.q]),
        })
    }
}

fn check_state(ladder: &Ladder, q: &[f64], what: &str) -> Result<()> {
    if q.len() == 3 * ladder.n() {
        Ok(())
    } else {
        Err(Error::bad_input(format!(
            "the {what} has {} coordinates, a ladder of {} blocks needs {}",
            q.len(),
            ladder.n(),
            3 * ladder.n()
        )))
    }
}

/// The time label text, e.g. "t/τ = 1234".
pub fn time_label(t: f64) -> String {
    if t.abs() >= 100.0 || t == t.round() {
        format!("t/τ = {t:.0}")
    } else {
        format!("t/τ = {t:.1}")
    }
}

/// Renders a snapshot into a new `width × height` image, its text in
/// `theme`'s font.
pub fn render_snapshot(
    theme: &Theme,
    snap: &Snapshot<'_>,
    width: u32,
    height: u32,
) -> Result<Pixmap> {
    let mut p = style::white_pixmap(width, height).ok_or_else(|| bad_size(width, height))?;
    draw_snapshot(theme, &mut p, Region::full(width, height), snap);
    Ok(p)
}

/// A snapshot as a `width × height` picture (vector) drawn with `theme`.
pub fn snapshot_picture(
    theme: &Theme,
    snap: &Snapshot<'_>,
    width: u32,
    height: u32,
) -> Result<Picture> {
    if width == 0 || height == 0 {
        return Err(bad_size(width, height));
    }
    let mut p = Picture::new(theme, width as f32, height as f32);
    draw_snapshot_on(&mut p, Region::full(width, height), snap);
    Ok(p)
}

/// Clears `pixmap` to white and renders a snapshot over all of it (reuses
/// the allocation: the per-frame path of movies).
pub fn render_snapshot_into(theme: &Theme, pixmap: &mut Pixmap, snap: &Snapshot<'_>) {
    pixmap.fill(style::color(Palette.color(Role::Paper)));
    let r = Region::full(pixmap.width(), pixmap.height());
    draw_snapshot(theme, pixmap, r, snap);
}

pub(crate) fn bad_size(width: u32, height: u32) -> Error {
    Error::bad_input(format!(
        "image size must be at least 1x1 pixels and fit in memory, got {width}x{height}"
    ))
}

/// Draws a snapshot into `region` of `pixmap` at 100 %, its text in
/// `theme`'s font.
pub fn draw_snapshot(theme: &Theme, pixmap: &mut Pixmap, region: Region, snap: &Snapshot<'_>) {
    draw_snapshot_on(&mut Raster::new(pixmap, theme.font()), region, snap);
}

/// Draws a snapshot into `region` of `canvas` (title band on top, time band
/// at the bottom, ladder in between). The background is left as it is.
pub fn draw_snapshot_on(canvas: &mut impl Canvas, region: Region, snap: &Snapshot<'_>) {
    let (margin, top, bottom) = bands(region, snap);
    let inner = inner_region(region, snap);
    let map = Mapping::new(&snap.view(), inner);
    if let Some(xs) = snap.lab_scale {
        draw_lab_scale(canvas, &map, inner, xs);
    }
    if let Some(g) = snap.ghost {
        match &snap.built {
            Some(b) => super::blocks::draw_built(canvas, &map, g, b, true),
            None => draw_ladder(canvas, &map, g, &LadderInks::ghost()),
        }
    }
    if snap.clamp && snap.q.len() >= 3 {
        draw_clamp(canvas, &map, [snap.q[ix(0)], snap.q[iy(0)]]);
    }
    match &snap.built {
        Some(b) => {
            super::blocks::draw_built(canvas, &map, snap.q, b, false);
            let o = &b.ribbons.outline;
            let at: Vec<[f64; 2]> = (snap.impacts.iter())
                .map(|&[i, j]| super::blocks::contact_point(o, snap.q, i, j))
                .collect();
            super::blocks::draw_impacts(canvas, &map, &at);
        }
        None => draw_ladder(canvas, &map, snap.q, &LadderInks::live()),
    }
    if snap.clamp && snap.q.len() >= 3 {
        draw_pivot(canvas, &map, [snap.q[ix(0)], snap.q[iy(0)]]);
    }
    // A fixed window (a camera) may cut the ladder: clear the label bands.
    if snap.view.is_some() {
        canvas.rect(
            region.x,
            region.y,
            region.w,
            margin + top,
            Palette.color(Role::Paper),
        );
        canvas.rect(
            region.x,
            inner.y + inner.h,
            region.w,
            margin + bottom,
            Palette.color(Role::Paper),
        );
    }
    draw_labels(canvas, region, margin, snap);
}

/// The lines and numbers of [`Snapshot::lab_scale`] inside `inner`.
fn draw_lab_scale(canvas: &mut impl Canvas, map: &Mapping, inner: Region, xs: &[f64]) {
    let line = Pen::new(
        1.0,
        style::mix(
            Palette.color(Role::Ground),
            Palette.color(Role::Paper),
            0.55,
        ),
    );
    let number = style::mix(Palette.color(Role::Ground), Palette.color(Role::Ink), 0.3);
    let label_size = 0.8 * size::TICK;
    for (i, &x) in xs.iter().enumerate() {
        let (_, py) = map.px([x, map.y_mid]);
        if py < inner.y || py > inner.y + inner.h {
            continue;
        }
        canvas.line(
            (inner.x + 1.4 * label_size, py),
            (inner.x + inner.w, py),
            &line,
        );
        canvas.text(
            &format!("{}", i + 1),
            (inner.x + 1.1 * label_size, py),
            label_size,
            number,
            (HAlign::Right, VAlign::Middle),
        );
    }
}

/// Margin, title band and time band of a snapshot drawn into `region`.
fn bands(region: Region, snap: &Snapshot<'_>) -> (f32, f32, f32) {
    let margin = (0.03 * region.w.min(region.h)).clamp(2.0, 12.0);
    let top = snap.title.map_or(0.0, |_| 1.5 * size::TITLE);
    let bottom = snap.time.map_or(0.0, |_| 1.5 * size::LABEL);
    (margin, top, bottom)
}

/// The part of `region` the ladder is drawn in (inside the label bands).
pub fn inner_region(region: Region, snap: &Snapshot<'_>) -> Region {
    let (margin, top, bottom) = bands(region, snap);
    Region {
        x: region.x + margin,
        y: region.y + margin + top,
        w: (region.w - 2.0 * margin).max(1.0),
        h: (region.h - 2.0 * margin - top - bottom).max(1.0),
    }
}

/// Pixel (horizontal, vertical) of the model point `p` = [x, y] when
/// `snap` is drawn into `region` by [`draw_snapshot`].
pub fn pixel_of(region: Region, snap: &Snapshot<'_>, p: [f64; 2]) -> (f32, f32) {
    Mapping::new(&snap.view(), inner_region(region, snap)).px(p)
}

fn draw_labels(canvas: &mut impl Canvas, region: Region, margin: f32, snap: &Snapshot<'_>) {
    if let Some(title) = snap.title {
        let at = (region.x + 0.5 * region.w, region.y + margin);
        canvas.text(
            title,
            at,
            size::TITLE,
            Palette.color(Role::Ink),
            (HAlign::Center, VAlign::Top),
        );
    }
    if let Some(t) = snap.time {
        // Centred under the ladder: in movies the changed rectangle of each
        // frame then stays narrow (see `encode::GifWriter`).
        let at = (region.x + 0.5 * region.w, region.y + region.h - margin);
        let label = time_label(t);
        canvas.text(
            &label,
            at,
            size::LABEL,
            Palette.color(Role::Ink),
            (HAlign::Center, VAlign::Baseline),
        );
    }
}

/// Colours of one drawn ladder.
struct LadderInks {
    block: Rgb,
    a_end: Rgb,
    b_end: Rgb,
    a_spring: Rgb,
    b_spring: Rgb,
}

impl LadderInks {
    fn live() -> LadderInks {
        LadderInks {
            block: Palette.color(Role::Ink),
            a_end: Palette.color(Role::SpringA),
            b_end: Palette.color(Role::SpringB),
            a_spring: Palette.color(Role::SpringA),
            b_spring: Palette.color(Role::SpringB),
        }
    }

    fn ghost() -> LadderInks {
        let light = style::mix(Palette.color(Role::Paper), Palette.color(Role::Ground), 0.6);
        LadderInks {
            block: Palette.color(Role::Ground),
            a_end: Palette.color(Role::Ground),
            b_end: Palette.color(Role::Ground),
            a_spring: light,
            b_spring: light,
        }
    }
}

/// Springs first, then the blocks on top of them. B springs are dashed
/// (dashes three spring widths long, gaps two): the cue besides colour that
/// tells them from the A springs in grey print and to colour-blind eyes.
fn draw_ladder(canvas: &mut impl Canvas, map: &Mapping, q: &[f64], pal: &LadderInks) {
    let n = q.len() / 3;
    let spring_w = map.len(0.045, 1.0, 4.0);
    let block_w = map.len(0.16, 2.5, 14.0);
    let (a_pen, b_pen) = (
        Pen::new(spring_w, pal.a_spring),
        Pen::new(spring_w, pal.b_spring)
            .dashed((3.0 * spring_w).max(2.5), (2.0 * spring_w).max(1.5)),
    );
    let mut prev = None;
    for i in 0..n {
        let (a1, b1) = nodes(q, i);
        if let Some((a0, b0)) = prev {
            canvas.line(map.px(a0), map.px(a1), &a_pen);
            canvas.line(map.px(b0), map.px(b1), &b_pen);
        }
        prev = Some((a1, b1));
    }
    for i in 0..n {
        let (a, b) = nodes(q, i);
        draw_block(canvas, map, a, b, block_w, pal);
    }
}

/// A bar from the A node to the B node, the last quarter at each end
/// coloured by the node it carries.
fn draw_block(
    canvas: &mut impl Canvas,
    map: &Mapping,
    a: [f64; 2],
    b: [f64; 2],
    w: f32,
    pal: &LadderInks,
) {
    let at = |f: f64| map.px([a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f]);
    canvas.line(at(0.0), at(1.0), &Pen::new(w, pal.block));
    canvas.line(at(0.0), at(0.25), &Pen::new(w, pal.a_end));
    canvas.line(at(0.75), at(1.0), &Pen::new(w, pal.b_end));
}

/// A dark triangle from a base line above block 1 down to its centre.
fn draw_clamp(canvas: &mut impl Canvas, map: &Mapping, centre: [f64; 2]) {
    let h = CLAMP_HEIGHT * S;
    let apex = map.px(centre);
    let l = map.px([centre[0] - h, centre[1] - 0.22 * S]);
    let r = map.px([centre[0] - h, centre[1] + 0.22 * S]);
    canvas.polygon(
        &[apex, l, r],
        style::mix(Palette.color(Role::Paper), Palette.color(Role::Ink), 0.55),
    );
    let wl = map.px([centre[0] - h, centre[1] - 0.32 * S]);
    let wr = map.px([centre[0] - h, centre[1] + 0.32 * S]);
    canvas.line(
        wl,
        wr,
        &Pen::new(map.len(0.06, 1.5, 4.0), Palette.color(Role::Ink)),
    );
}

/// A white pin with a dark rim at the centre of block 1.
fn draw_pivot(canvas: &mut impl Canvas, map: &Mapping, centre: [f64; 2]) {
    let (x, y) = map.px(centre);
    let r = map.len(0.06, 1.5, 6.0);
    if let Some(path) = tiny_skia::PathBuilder::from_circle(x, y, r) {
        canvas.fill(&path, Palette.color(Role::Paper));
        canvas.stroke(
            &path,
            &Pen::new((0.5 * r).max(1.0), Palette.color(Role::Ink)),
        );
    }
}
