//! Series markers and legend glyphs drawn straight on the backend.

use super::{LineStyle, Marker, rgb};
use crate::encode::Rgb;
use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters_backend::{BackendCoord, DrawingErrorKind};

/// A marker, optionally behind a short legend line, drawn straight on the
/// backend at the pixel of its anchor point (a data point, or the legend
/// entry's position).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Glyph<C> {
    pub(crate) at: C,
    /// Legend line (22 px, starting at the anchor); `None` for data markers.
    pub(crate) line: LineStyle,
    pub(crate) marker: Marker,
    pub(crate) color: Rgb,
    pub(crate) width: f64,
    /// Horizontal pixel offset of the marker from the anchor.
    pub(crate) offset: i32,
}

impl<'a, C: 'a> PointCollection<'a, C> for &'a Glyph<C> {
    type Point = &'a C;
    type IntoIter = std::iter::Once<&'a C>;
    fn point_iter(self) -> Self::IntoIter {
        std::iter::once(&self.at)
    }
}

/// Legend line length in pixels.
pub(super) const LEGEND_LINE: i32 = 22;

impl<C, DB: DrawingBackend> Drawable<DB> for Glyph<C> {
    fn draw<I: Iterator<Item = BackendCoord>>(
        &self,
        mut pos: I,
        backend: &mut DB,
        _: (u32, u32),
    ) -> std::result::Result<(), DrawingErrorKind<DB::ErrorType>> {
        let Some((x, y)) = pos.next() else {
            return Ok(());
        };
        let style = rgb(self.color).stroke_width(self.width.round().max(1.0) as u32);
        match self.line {
            LineStyle::Solid => backend.draw_line((x, y), (x + LEGEND_LINE, y), &style)?,
            LineStyle::Dashed => {
                for k in (0..LEGEND_LINE).step_by(9) {
                    backend.draw_line((x + k, y), (x + (k + 5).min(LEGEND_LINE), y), &style)?;
                }
            }
            LineStyle::None => {}
        }
        draw_marker(
            backend,
            (x + self.offset, y),
            self.marker,
            self.color,
            self.width,
        )
    }
}

/// Marker radius in pixels for a series of line width `w`.
fn marker_radius(w: f64) -> i32 {
    (1.5 * w + 2.0).round() as i32
}

fn draw_marker<DB: DrawingBackend>(
    backend: &mut DB,
    (x, y): BackendCoord,
    m: Marker,
    c: Rgb,
    w: f64,
) -> std::result::Result<(), DrawingErrorKind<DB::ErrorType>> {
    let r = marker_radius(w);
    let fill = rgb(c).filled();
    match m {
        Marker::None => Ok(()),
        Marker::Circle => backend.draw_circle((x, y), r as u32, &fill, true),
        Marker::Square => backend.draw_rect((x - r, y - r), (x + r, y + r), &fill, true),
        Marker::Triangle => {
            let h = r + 1;
            backend.fill_polygon(
                [(x, y - h), (x - h, y + h * 2 / 3), (x + h, y + h * 2 / 3)],
                &fill,
            )
        }
        Marker::Cross => {
            let st = rgb(c).stroke_width(2);
            let h = r + 1;
            backend.draw_line((x - h, y - h), (x + h, y + h), &st)?;
            backend.draw_line((x - h, y + h), (x + h, y - h), &st)
        }
        Marker::Ring => {
            let st = rgb(c).stroke_width(2);
            backend.draw_circle((x, y), (r + 2) as u32, &st, false)
        }
        Marker::Plus => {
            let st = rgb(c).stroke_width(2);
            let h = r + 2;
            backend.draw_line((x - h, y), (x + h, y), &st)?;
            backend.draw_line((x, y - h), (x, y + h), &st)
        }
        Marker::OpenTriangle => {
            let h = r + 2;
            outline(backend, &triangle((x, y), h, false), c)
        }
        Marker::TriangleDown => backend.fill_polygon(triangle((x, y), r + 1, true), &fill),
        Marker::Diamond => backend.fill_polygon(diamond((x, y), r + 1), &fill),
        Marker::OpenDiamond => outline(backend, &diamond((x, y), r + 2), c),
        Marker::OpenSquare => {
            let st = rgb(c).stroke_width(2);
            let h = r + 2;
            backend.draw_rect((x - h, y - h), (x + h, y + h), &st, false)
        }
        Marker::Star => {
            let st = rgb(c).stroke_width(2);
            let h = r + 1;
            let d = (h as f64 * 0.866).round() as i32;
            let k = h / 2;
            backend.draw_line((x, y - h), (x, y + h), &st)?;
            backend.draw_line((x - d, y - k), (x + d, y + k), &st)?;
            backend.draw_line((x - d, y + k), (x + d, y - k), &st)
        }
    }
}

/// A triangle of half-width `h` about `(x, y)`, apex up (or `down`).
fn triangle((x, y): BackendCoord, h: i32, down: bool) -> [BackendCoord; 3] {
    let s = if down { -1 } else { 1 };
    [
        (x, y - s * h),
        (x - h, y + s * h * 2 / 3),
        (x + h, y + s * h * 2 / 3),
    ]
}

/// A diamond of half-diagonal `h` about `(x, y)`.
fn diamond((x, y): BackendCoord, h: i32) -> [BackendCoord; 4] {
    [(x, y - h), (x + h, y), (x, y + h), (x - h, y)]
}

/// The closed outline of `points`, 2 px wide, in `c`.
fn outline<DB: DrawingBackend>(
    backend: &mut DB,
    points: &[BackendCoord],
    c: Rgb,
) -> std::result::Result<(), DrawingErrorKind<DB::ErrorType>> {
    let st = rgb(c).stroke_width(2);
    let closed: Vec<BackendCoord> = points.iter().chain(points.first()).copied().collect();
    backend.draw_path(closed, &st)
}
