//! What drawing code draws on: the [`Canvas`] trait, with two
//! implementations: [`Raster`] paints pixels straight away (tiny-skia; the
//! path of movie frames), and [`super::Picture`] records a display list that
//! both the raster and the vector (SVG, PDF) backends consume. Drawing code
//! is written once against the trait.
//!
//! Coordinates are pixels of the design size (y down). A group
//! ([`Canvas::push`]) may translate and scale uniformly; text keeps its
//! shape under such transforms in every backend.

use super::charts::Chart;
use super::page_style::FontChoice;
use super::style::{self, HAlign, VAlign};
use crate::encode::Rgb;
use crate::render::palette::{Palette, Role};
use std::sync::Arc;
use tiny_skia::{
    FillRule, FilterQuality, LineCap, Paint, Path, PathBuilder, Pixmap, PixmapPaint, Stroke,
    StrokeDash, Transform,
};

/// How a stroke ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Cap {
    #[default]
    Butt,
    Round,
    Square,
}

/// A stroke: width in pixels, colour, cap and an optional dash (on, off
/// lengths in pixels, starting with "on").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pen {
    pub width: f32,
    pub color: Rgb,
    pub cap: Cap,
    pub dash: Option<[f32; 2]>,
}

impl Pen {
    /// A solid stroke with butt caps.
    pub fn new(width: f32, color: Rgb) -> Pen {
        Pen {
            width,
            color,
            cap: Cap::Butt,
            dash: None,
        }
    }

    /// With round caps.
    pub fn round(mut self) -> Pen {
        self.cap = Cap::Round;
        self
    }

    /// Dashed: `on` pixels drawn, `off` pixels left out.
    pub fn dashed(mut self, on: f32, off: f32) -> Pen {
        self.dash = Some([on, off]);
        self
    }
}

/// A surface to draw on. See the module documentation.
pub trait Canvas {
    /// Fills `path` (non-zero winding).
    fn fill(&mut self, path: &Path, color: Rgb);
    /// Strokes `path`.
    fn stroke(&mut self, path: &Path, pen: &Pen);
    /// Typeset text (markup of [`style::runs`]) anchored at `at`.
    fn text(&mut self, text: &str, at: (f32, f32), size: f32, color: Rgb, align: (HAlign, VAlign));
    /// A chart (its SVG and raster) with its top left at `at`.
    fn chart(&mut self, chart: &Arc<Chart>, at: (f32, f32));
    /// A raster image with its top left at `at`. Raster-only: a picture
    /// holding one has no vector form.
    fn image(&mut self, image: &Arc<Pixmap>, at: (f32, f32));
    /// Starts a group drawn through `transform` (translation and uniform
    /// scale) after the current one.
    fn push(&mut self, transform: Transform);
    /// Ends the innermost group.
    fn pop(&mut self);

    /// A straight segment.
    fn line(&mut self, a: (f32, f32), b: (f32, f32), pen: &Pen) {
        self.polyline(&[a, b], pen);
    }

    /// An open polyline.
    fn polyline(&mut self, points: &[(f32, f32)], pen: &Pen) {
        if let Some(path) = polyline_path(points, false) {
            self.stroke(&path, pen);
        }
    }

    /// A filled polygon.
    fn polygon(&mut self, points: &[(f32, f32)], color: Rgb) {
        if let Some(path) = polyline_path(points, true) {
            self.fill(&path, color);
        }
    }

    /// A filled rectangle (nothing if it is empty).
    fn rect(&mut self, x: f32, y: f32, w: f32, h: f32, color: Rgb) {
        if let Some(r) = tiny_skia::Rect::from_xywh(x, y, w, h) {
            self.fill(&PathBuilder::from_rect(r), color);
        }
    }

    /// A filled disc.
    fn disc(&mut self, at: (f32, f32), r: f32, color: Rgb) {
        if let Some(path) = PathBuilder::from_circle(at.0, at.1, r) {
            self.fill(&path, color);
        }
    }
}

/// The path through `points`, closed if asked; `None` for fewer than two.
pub fn polyline_path(points: &[(f32, f32)], close: bool) -> Option<Path> {
    let mut pb = PathBuilder::new();
    for (k, p) in points.iter().enumerate() {
        if k == 0 {
            pb.move_to(p.0, p.1);
        } else {
            pb.line_to(p.0, p.1);
        }
    }
    if close {
        pb.close();
    }
    pb.finish()
}

/// Draws straight onto a pixmap through a transform (identity: one design
/// pixel is one pixel).
pub struct Raster<'a> {
    pixmap: &'a mut Pixmap,
    ts: Transform,
    stack: Vec<Transform>,
    /// The font text is drawn in.
    font: FontChoice,
}

impl<'a> Raster<'a> {
    /// Draws at 100 %, text in `font`.
    pub fn new(pixmap: &'a mut Pixmap, font: FontChoice) -> Raster<'a> {
        Raster::with_transform(pixmap, Transform::identity(), font)
    }

    /// Draws through `ts` (e.g. a scale for a larger frame), text in `font`.
    pub fn with_transform(pixmap: &'a mut Pixmap, ts: Transform, font: FontChoice) -> Raster<'a> {
        Raster {
            pixmap,
            ts,
            stack: Vec::new(),
            font,
        }
    }

    /// The current transform.
    pub fn transform(&self) -> Transform {
        self.ts
    }

    /// The pixmap drawn on.
    pub fn pixmap(&mut self) -> &mut Pixmap {
        self.pixmap
    }

    /// Whether the transform only moves by whole pixels.
    fn whole_pixel_shift(&self, at: (f32, f32)) -> Option<(i32, i32)> {
        let t = self.ts;
        let (x, y) = (t.tx + at.0, t.ty + at.1);
        let whole = |v: f32| (v - v.round()).abs() < 1e-4;
        (t.sx == 1.0 && t.sy == 1.0 && t.kx == 0.0 && t.ky == 0.0 && whole(x) && whole(y))
            .then(|| (x.round() as i32, y.round() as i32))
    }
}

fn paint(c: Rgb) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color(style::color(c));
    p.anti_alias = true;
    p
}

impl Canvas for Raster<'_> {
    fn fill(&mut self, path: &Path, color: Rgb) {
        self.pixmap
            .fill_path(path, &paint(color), FillRule::Winding, self.ts, None);
    }

    fn stroke(&mut self, path: &Path, pen: &Pen) {
        let stroke = Stroke {
            width: pen.width,
            line_cap: match pen.cap {
                Cap::Butt => LineCap::Butt,
                Cap::Round => LineCap::Round,
                Cap::Square => LineCap::Square,
            },
            dash: pen.dash.and_then(|d| StrokeDash::new(d.to_vec(), 0.0)),
            ..Stroke::default()
        };
        self.pixmap
            .stroke_path(path, &paint(pen.color), &stroke, self.ts, None);
    }

    fn text(&mut self, text: &str, at: (f32, f32), size: f32, color: Rgb, align: (HAlign, VAlign)) {
        let p = tiny_skia::Point::from_xy(at.0, at.1);
        let mut q = [p];
        self.ts.map_points(&mut q);
        let scale = self.ts.sx.hypot(self.ts.ky);
        style::draw_text(
            self.pixmap,
            self.font,
            text,
            (q[0].x, q[0].y),
            size * scale,
            color,
            align,
        );
    }

    fn chart(&mut self, chart: &Arc<Chart>, at: (f32, f32)) {
        if let Some((x, y)) = self.whole_pixel_shift(at) {
            // At 100 % the chart's own raster is exact: copy it.
            self.pixmap.draw_pixmap(
                x,
                y,
                chart.pixmap.as_ref(),
                &PixmapPaint::default(),
                Transform::identity(),
                None,
            );
        } else if let Some(tree) = chart.tree() {
            let ts = self.ts.pre_translate(at.0, at.1);
            // resvg paints over what is there: clear the chart's box first.
            let size = tree.size();
            if let Some(r) = tiny_skia::Rect::from_xywh(0.0, 0.0, size.width(), size.height()) {
                self.pixmap.fill_path(
                    &PathBuilder::from_rect(r),
                    &paint(Palette.color(Role::Paper)),
                    FillRule::Winding,
                    ts,
                    None,
                );
            }
            resvg::render(tree, ts, &mut self.pixmap.as_mut());
        }
    }

    fn image(&mut self, image: &Arc<Pixmap>, at: (f32, f32)) {
        if let Some((x, y)) = self.whole_pixel_shift(at) {
            self.pixmap.draw_pixmap(
                x,
                y,
                image.as_ref().as_ref(),
                &PixmapPaint::default(),
                Transform::identity(),
                None,
            );
        } else {
            let paint = PixmapPaint {
                quality: FilterQuality::Bicubic,
                ..PixmapPaint::default()
            };
            let ts = self.ts.pre_translate(at.0, at.1);
            self.pixmap
                .draw_pixmap(0, 0, image.as_ref().as_ref(), &paint, ts, None);
        }
    }

    fn push(&mut self, transform: Transform) {
        self.stack.push(self.ts);
        self.ts = self.ts.pre_concat(transform);
    }

    fn pop(&mut self) {
        if let Some(t) = self.stack.pop() {
            self.ts = t;
        }
    }
}
