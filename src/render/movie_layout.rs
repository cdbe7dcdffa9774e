//! Where a movie frame puts the title, the ladder and the live kymograph,
//! at any frame size.
//!
//! The layout is made for a design frame at least 640 × 480 design pixels
//! and drawn through a uniform scale s = min(W/640, H/480): text, line
//! widths, margins, panels and the kymograph all grow with the frame, so a
//! 1920 × 1080 movie is the 640 × 360 one, only sharper, and the default
//! 640 × 480 movie is drawn at s = 1. Since the design frame is never
//! smaller than 640 × 480, nothing is cut at any size.

use super::canvas::{Canvas, Raster};
use super::page_style::FontChoice;
use super::snapshot::{self, Region, Snapshot};
use super::style::{self, HAlign, VAlign, size};
use super::theme::Theme;
use crate::error::{Error, Result};
use crate::render::palette::{Palette, Role};
use tiny_skia::{Pixmap, Transform};

/// The frame size at which one design pixel is one pixel.
pub const REFERENCE: (f32, f32) = (640.0, 480.0);

/// A line of typeset text of a movie frame, in design pixels.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// The text (markup of [`style::runs`]).
    pub text: String,
    /// Its anchor.
    pub at: (f32, f32),
    /// Font size.
    pub size: f32,
    /// How the text sits on its anchor.
    pub align: (HAlign, VAlign),
    /// The font it is set in.
    pub font: FontChoice,
}

impl Label {
    /// The box the text covers: its advance width across, and from the top
    /// of the highest run's em box to the bottom of the lowest one's (super-
    /// and subscripts included) down, as every backend places it.
    pub fn bounds(&self) -> Region {
        let font = self.font;
        let width = style::text_width(font, &self.text, self.size);
        let (x, baseline) = style::text_origin(font, self.at, width, self.size, self.align);
        let (mut top, mut bottom) = (f32::INFINITY, f32::NEG_INFINITY);
        for (shift, _) in style::runs(font, &self.text) {
            let s = self.size * shift.scale();
            let base = baseline - shift.rise() * self.size;
            // The font's ascent and descent add up to its size.
            let ascent = style::ascent(font, s);
            top = top.min(base - ascent);
            bottom = bottom.max(base + s - ascent);
        }
        if top > bottom {
            (top, bottom) = (baseline, baseline);
        }
        Region {
            x,
            y: top,
            w: width,
            h: bottom - top,
        }
    }
}

/// The layout of one movie's frames.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MovieLayout {
    /// Pixels per design pixel.
    pub scale: f32,
    /// Frame width in pixels.
    pub width: u32,
    /// Frame height in pixels.
    pub height: u32,
    /// Design size (`width / scale × height / scale`).
    pub design: (f32, f32),
    /// The ladder's region, in design pixels.
    pub ladder: Region,
    /// The live kymograph's region, in design pixels.
    pub heat: Region,
    /// The movie's theme (the font of its text).
    pub theme: Theme,
}

impl MovieLayout {
    /// Width of one block's column of the live kymograph, in design
    /// pixels: a narrow panel keeps the changed rectangle of each GIF frame
    /// small.
    pub const COLUMN: f32 = 20.0;

    /// The layout of `width × height` frames of an `n`-block ladder, its
    /// text in `theme`'s font.
    pub fn new(theme: &Theme, width: u32, height: u32, n: usize) -> Self {
        let (fw, fh) = (width.max(1) as f32, height.max(1) as f32);
        let scale = (fw / REFERENCE.0).min(fh / REFERENCE.1);
        let (w, h) = (fw / scale, fh / scale);
        let top = (1.8 * size::TITLE).min(0.2 * h);
        let split = (0.45 * w).round();
        let heat_x = split + (0.1 * w).min(56.0);
        let heat_y = (top + 0.8 * size::TICK).round();
        // Below the kymograph: a gap, "block 1 … N", and the legend line.
        let bottom = 4.0 + 2.6 * size::TICK + 0.6 * size::TICK;
        Self {
            scale,
            width,
            height,
            design: (w, h),
            ladder: Region {
                x: 0.0,
                y: top,
                w: split,
                h: (h - top).max(1.0),
            },
            heat: Region {
                x: heat_x.round(),
                y: heat_y,
                // At least a quarter of the frame, so that a short chain's
                // labels ("block 1", "2") do not run into each other.
                w: (w - heat_x - 0.04 * w)
                    .min((Self::COLUMN * n.max(1) as f32).max(0.25 * w))
                    .max(1.0)
                    .round(),
                h: (h - heat_y - bottom).max(1.0).round(),
            },
            theme: *theme,
        }
    }

    /// Design pixels to pixels.
    pub fn transform(&self) -> Transform {
        Transform::from_scale(self.scale, self.scale)
    }

    /// Width over height of the ladder's region (for a camera window).
    pub fn ladder_aspect(&self) -> f64 {
        self.ladder.w as f64 / self.ladder.h as f64
    }

    /// The live kymograph's rectangle in pixels: x, y, width, height.
    pub fn heat_pixels(&self) -> (u32, u32, u32, u32) {
        let s = self.scale;
        let x0 = (self.heat.x * s).round() as u32;
        let y0 = (self.heat.y * s).round() as u32;
        let x1 = (((self.heat.x + self.heat.w) * s).round() as u32).min(self.width);
        let y1 = (((self.heat.y + self.heat.h) * s).round() as u32).min(self.height);
        (
            x0,
            y0,
            x1.saturating_sub(x0).max(1),
            y1.saturating_sub(y0).max(1),
        )
    }

    /// Rows of pixels the title band covers.
    fn title_rows(&self) -> usize {
        ((self.ladder.y * self.scale).ceil() as usize).min(self.height as usize)
    }

    /// What every frame shares: white, the title across the frame, and the
    /// kymograph's time axis, block numbers and colour legend.
    pub fn background(&self, title: &str, t_end: f64, n: usize) -> Result<Pixmap> {
        let mut p = style::white_pixmap(self.width, self.height)
            .ok_or_else(|| Error::bad_input("the movie frame does not fit in memory"))?;
        let mut c = Raster::with_transform(&mut p, self.transform(), self.theme.font());
        self.decorate(&mut c, title, t_end, n);
        Ok(p)
    }

    fn decorate(&self, c: &mut impl Canvas, title: &str, t_end: f64, n: usize) {
        for l in self.labels(title, t_end, n) {
            c.text(&l.text, l.at, l.size, Palette.color(Role::Ink), l.align);
        }
    }

    /// Every line of text that every frame shares, in design pixels: the
    /// title across the top (smaller if it would not fit the frame's width),
    /// the kymograph's first and last time beside it, the block numbers
    /// under it and the colour legend below them.
    pub fn labels(&self, title: &str, t_end: f64, n: usize) -> Vec<Label> {
        let tick = size::TICK;
        let top = (HAlign::Center, VAlign::Top);
        let room = 0.96 * self.design.0;
        let font = self.theme.font();
        let full = style::text_width(font, title, size::TITLE);
        let title_size = if full > room {
            size::TITLE * room / full
        } else {
            size::TITLE
        };
        let r = self.heat;
        let left = r.x - 4.0;
        let below = r.y + r.h + 4.0;
        let label = |text: String, at: (f32, f32), size: f32, align| Label {
            text,
            at,
            size,
            align,
            font,
        };
        vec![
            label(
                title.to_string(),
                (0.5 * self.design.0, 6.0),
                title_size,
                top,
            ),
            label(
                "t/τ = 0".into(),
                (left, r.y),
                tick,
                (HAlign::Right, VAlign::Top),
            ),
            label(
                format!("{t_end:.0}"),
                (left, r.y + r.h),
                tick,
                (HAlign::Right, VAlign::Baseline),
            ),
            label(
                "block 1".into(),
                (r.x, below),
                tick,
                (HAlign::Left, VAlign::Top),
            ),
            label(
                format!("{n}"),
                (r.x + r.w, below),
                tick,
                (HAlign::Right, VAlign::Top),
            ),
            label(
                "sin θ_{n}: red +1, blue −1".into(),
                (r.x + 0.5 * r.w, below + 1.3 * tick),
                tick,
                top,
            ),
        ]
    }

    /// One frame into `canvas`: a copy of `background`, each snapshot in
    /// its region (the ladder's region, or the columns of a folded ladder;
    /// design pixels), an optional time label centred in its band, the
    /// title band kept clear of a camera's ladder, and the top `fraction`
    /// of `heat` revealed.
    pub fn draw_frame(
        &self,
        canvas: &mut Pixmap,
        background: &Pixmap,
        snaps: &[(Region, Snapshot<'_>)],
        time_label: Option<(Region, &str)>,
        heat: &Pixmap,
        fraction: f32,
    ) {
        canvas.data_mut().copy_from_slice(background.data());
        {
            let mut c = Raster::with_transform(canvas, self.transform(), self.theme.font());
            for (region, snap) in snaps {
                snapshot::draw_snapshot_on(&mut c, *region, snap);
            }
            if let Some((band, text)) = time_label {
                let centre = (band.x + 0.5 * band.w, band.y + 0.5 * band.h);
                let middle = (HAlign::Center, VAlign::Middle);
                c.text(text, centre, size::LABEL, Palette.color(Role::Ink), middle);
            }
        }
        let bytes = 4 * canvas.width() as usize * self.title_rows();
        canvas.data_mut()[..bytes].copy_from_slice(&background.data()[..bytes]);
        self.reveal_rows(canvas, heat, fraction);
    }

    /// The whole kymograph at its pixel size: one row band per state, one
    /// column per block, sin θ_n in the diverging map (no anti-aliasing).
    pub fn heat_map(&self, states: &[Vec<f64>], n: usize) -> Result<Pixmap> {
        let (_, _, w, h) = self.heat_pixels();
        let mut map = style::white_pixmap(w, h)
            .ok_or_else(|| Error::bad_input("the movie frame is too small"))?;
        let rows = states.len().max(1);
        let mut paint = tiny_skia::Paint {
            anti_alias: false,
            ..Default::default()
        };
        for (k, q) in states.iter().enumerate() {
            let (y0, y1) = (
                k as f32 * h as f32 / rows as f32,
                (k + 1) as f32 * h as f32 / rows as f32,
            );
            for j in 0..n.min(q.len() / 3) {
                let (x0, x1) = (
                    j as f32 * w as f32 / n as f32,
                    (j + 1) as f32 * w as f32 / n as f32,
                );
                let v = q[crate::model::ladder::itheta(j)].sin();
                paint.set_color(style::color(style::diverging(v)));
                if let Some(rect) =
                    tiny_skia::Rect::from_ltrb(x0.floor(), y0.floor(), x1.ceil(), y1.ceil())
                {
                    map.fill_rect(rect, &paint, Transform::identity(), None);
                }
            }
        }
        Ok(map)
    }

    /// Copies the top `fraction` of `heat` into its rectangle of `canvas`.
    pub fn reveal_rows(&self, canvas: &mut Pixmap, heat: &Pixmap, fraction: f32) {
        let (x0, y0, _, _) = self.heat_pixels();
        let rows = ((fraction * heat.height() as f32).round() as u32).min(heat.height());
        let (cw, hw) = (canvas.width() as usize, heat.width() as usize);
        let (x0, y0) = (x0 as usize, y0 as usize);
        let copy = hw.min(cw.saturating_sub(x0));
        let src = heat.data();
        let dst = canvas.data_mut();
        for y in 0..rows as usize {
            let from = &src[4 * y * hw..4 * (y * hw + copy)];
            let start = 4 * ((y0 + y) * cw + x0);
            if let Some(to) = dst.get_mut(start..start + from.len()) {
                to.copy_from_slice(from);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scale_and_design_size() {
        let l = MovieLayout::new(&Theme::of(&Default::default()), 640, 480, 10);
        assert_eq!(l.scale, 1.0);
        let big = MovieLayout::new(&Theme::of(&Default::default()), 1920, 1080, 10);
        let small = MovieLayout::new(&Theme::of(&Default::default()), 640, 360, 10);
        assert!((big.scale / small.scale - 3.0).abs() < 1e-6);
        assert_eq!(big.design, small.design);
        assert_eq!(big.heat, small.heat);
        for (w, h) in [(320, 240), (640, 360), (3840, 2160), (480, 1200)] {
            let l = MovieLayout::new(&Theme::of(&Default::default()), w, h, 10);
            assert!(l.design.0 >= 639.9 && l.design.1 >= 479.9, "{w}x{h}");
            let (x, y, hw, hh) = l.heat_pixels();
            assert!(x + hw <= w && y + hh <= h, "{w}x{h}");
        }
    }
}
