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
pub(super) struct Glyph<C> {
    pub(super) at: C,
    /// Legend line (22 px, starting at the anchor); `None` for data markers.
    pub(super) line: LineStyle,
    pub(super) marker: Marker,
    pub(super) color: Rgb,
    pub(super) width: f64,
    /// Horizontal pixel offset of the marker from the anchor.
    pub(super) offset: i32,
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
            backend.draw_circle((x, y), (r + 3) as u32, &st, false)
        }
        Marker::Plus => {
            let st = rgb(c).stroke_width(2);
            let h = r + 2;
            backend.draw_line((x - h, y), (x + h, y), &st)?;
            backend.draw_line((x, y - h), (x, y + h), &st)
        }
    }
}
