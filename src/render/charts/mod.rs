//! Data-driven charts: plotters draws an SVG with the bundled font, resvg
//! rasterises it (anti-aliased, the same tiny-skia as the snapshots).
//!
//! [`line_chart`] covers line charts with several series (solid or dashed,
//! optional markers), scatter-plus-line charts, parametric curves with equal
//! aspect, and linear or logarithmic axes (log–log work-precision charts).
//! [`kymograph`] draws a heat map of sin θ_n, blocks across and time down,
//! with a diverging colour map and a colour bar.

mod glyph;
mod kymograph;
mod legend;
mod line;
mod ranges;
mod rasterize;
mod spec;
mod svg_text;
mod ticks;
mod title;

pub(super) use glyph::Glyph;
pub use kymograph::{Kymograph, kymograph, polarisation_rows};
pub use legend::legend_band;
pub use line::{line_chart, line_chart_growing};
pub use rasterize::{Chart, rasterize_svg, rasterize_tree};
pub use spec::{Axis, ChartSpec, Legend, LineStyle, Marker, Scale, Series};
pub use svg_text::typeset_svg_text;
pub use ticks::{same_format, short_number, tick_label};
pub(super) use title::titled;
pub use title::{FittedTitle, fit_title};

use crate::encode::Rgb;
use crate::error::{Error, Result};
use crate::render::palette::{Palette, Role};
use plotters::coord::Shift;
use plotters::prelude::*;

/// A plotters drawing area on an SVG (shared with `render::cells`).
pub(super) type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

pub(super) fn plot_error<E: std::fmt::Debug>(e: E) -> Error {
    Error::failed(format!("chart drawing failed: {e:?}"))
}

/// Plotters font size that gives a CSS em size of `px` in the SVG (plotters
/// writes its size divided by 1.24).
pub(super) fn font(theme: &crate::render::Theme, px: f32) -> (&'static str, f64) {
    (super::style::family_of(theme.font()), f64::from(px) * 1.24)
}

pub(super) fn rgb(c: Rgb) -> RGBColor {
    RGBColor(c[0], c[1], c[2])
}

/// The axes' look every chart shares: dark tick labels, axis labels and
/// axis lines.
pub(super) fn dark_axes<'m, 'a, 'b, X, Y, DB>(
    theme: &crate::render::Theme,
    mesh: &'m mut plotters::chart::MeshStyle<'a, 'b, X, Y, DB>,
) -> &'m mut plotters::chart::MeshStyle<'a, 'b, X, Y, DB>
where
    X: Ranged,
    Y: Ranged,
    DB: DrawingBackend,
{
    use super::style::size;
    mesh.label_style(
        font(theme, theme.tick)
            .into_font()
            .color(&rgb(Palette.color(Role::Ink))),
    )
    .axis_desc_style(
        font(theme, size::LABEL)
            .into_font()
            .color(&rgb(Palette.color(Role::Ink))),
    )
    .axis_style(rgb(Palette.color(Role::Ink)).stroke_width(1))
}

fn check_size(width: u32, height: u32) -> Result<()> {
    if (60..=8192).contains(&width) && (60..=8192).contains(&height) {
        Ok(())
    } else {
        Err(Error::bad_input(format!(
            "chart size must be between 60x60 and 8192x8192 pixels, got {width}x{height}"
        )))
    }
}

/// Width of a y label area that holds tick labels as wide as the widest of
/// `ticks` (measured in the style's font), the tick marks, and the rotated
/// axis label beside them with a gap: at least [`Theme::y_label_area`](crate::render::Theme::y_label_area). Placing
/// the axis label from the measured tick labels keeps "t/τ" clear of
/// "15000" (plotters puts the label at the area's outer edge).
pub(super) fn y_label_area(theme: &crate::render::Theme, ticks: &[String]) -> u32 {
    use super::style;
    let widest = ticks
        .iter()
        .map(|t| style::text_width(theme.font(), t, theme.tick))
        .fold(0.0f32, f32::max);
    // Tick mark and its gap, the label's line, a gap.
    let need =
        widest + theme.tick_gap + theme.axis_label_line_em * theme.label + theme.axis_label_gap;
    (need.ceil() as u32).max(theme.y_label_area)
}

/// The tick labels a linear or log axis over `lo..hi` can show at its ends
/// and middle (the widest of them sets [`y_label_area`]).
pub(super) fn end_labels(lo: f64, hi: f64, scale: Scale) -> Vec<String> {
    let mid = match scale {
        Scale::Log if lo > 0.0 && hi > 0.0 => (lo * hi).sqrt(),
        _ => 0.5 * (lo + hi),
    };
    // Rounded as a tick would be: 3 significant digits of the span.
    let span = (hi - lo).abs().max(f64::MIN_POSITIVE);
    let step = 10f64.powf(span.log10().floor() - 1.0);
    [lo, mid, hi]
        .into_iter()
        .map(|v| match scale {
            Scale::Log => tick_label(10f64.powf(v.max(f64::MIN_POSITIVE).log10().floor()), scale),
            Scale::Linear => tick_label((v / step).round() * step, scale),
        })
        .collect()
}

type Ctx<'a, 'b, X, Y> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<X, Y>>;
