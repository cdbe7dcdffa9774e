//! Legends: inside (plotters' series labels) or in a column right of the
//! plot, and the automatic placement that covers no data.

use super::glyph::{Glyph, LEGEND_LINE};
use super::ranges::runs;
use super::{Area, ChartSpec, Ctx, Legend, LineStyle, font, plot_error, rgb};
use crate::error::Result;
use crate::render::Theme;
use crate::render::palette::{Palette, Role};
use crate::render::style;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

pub(super) fn has_labels(spec: &ChartSpec) -> bool {
    spec.series.iter().any(|s| s.label.is_some())
}

pub(super) fn draw_legend<'a, 'b: 'a, X, Y>(
    theme: &Theme,
    chart: &mut Ctx<'a, 'b, X, Y>,
    spec: &ChartSpec,
    legend: Legend,
) -> Result<()>
where
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    let Some(pos) = label_position(legend) else {
        return Ok(());
    };
    // Re-register labelled series as empty draws that only carry a legend.
    for s in spec.series.iter().filter(|s| s.label.is_some()) {
        let label = s.label.clone().unwrap_or_default();
        let (line, marker, color, width) = (s.line, s.marker, s.color, s.width);
        chart
            .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
            .map_err(plot_error)?
            .label(label)
            .legend(move |at| Glyph {
                at,
                line,
                marker,
                color,
                width,
                offset: LEGEND_LINE / 2,
            });
    }
    chart
        .configure_series_labels()
        .position(pos)
        .margin(8)
        .legend_area_size(28)
        .label_font(
            font(theme, theme.tick)
                .into_font()
                .color(&rgb(Palette.color(Role::Ink))),
        )
        .background_style(WHITE.mix(0.9))
        .border_style(rgb(Palette.color(Role::Ink)).mix(0.4))
        .draw()
        .map_err(plot_error)
}

/// A legend right of the plot: one row per labelled series, glyph then
/// text, starting at pixel `(x, y)` of the whole chart.
pub(super) fn draw_outside_legend(
    theme: &Theme,
    root: &Area<'_>,
    spec: &ChartSpec,
    (x, y): (i32, i32),
) -> Result<()> {
    let row = (theme.tick * theme.legend_row_em) as i32;
    draw_entries(theme, root, spec, |k| (x, y + row / 2 + k as i32 * row))
}

/// The grid of a legend under the plot of a chart `width` pixels wide:
/// (columns, rows, column width, row height, height of the band).
pub(super) fn below_grid(
    theme: &Theme,
    spec: &ChartSpec,
    width: u32,
) -> (usize, usize, i32, i32, u32) {
    let labels: Vec<&String> = spec
        .series
        .iter()
        .filter_map(|s| s.label.as_ref())
        .collect();
    let text = labels
        .iter()
        .map(|l| style::text_width(theme.font(), l, theme.tick))
        .fold(0.0, f32::max);
    let col_w = (text + LEGEND_LINE as f32 + 6.0 + 14.0).ceil() as i32;
    let room = (width as i32 - 16).max(col_w);
    let cols = ((room / col_w.max(1)) as usize).clamp(1, labels.len().max(1));
    let rows = labels.len().div_ceil(cols);
    let row = (theme.tick * theme.below_row_em).ceil() as i32;
    (cols, rows, col_w, row, (rows as i32 * row + 6) as u32)
}

/// Whether a legend column right of the plot of a chart `width` wide
/// would take more than a third of it: `Legend::Auto` then puts the
/// legend under the plot instead, in columns (the plot keeps its width,
/// the text its size).
pub(super) fn outside_too_wide(theme: &Theme, spec: &ChartSpec, width: u32) -> bool {
    legend_box(theme, spec).0 as u32 + theme.legend_gap_min > width / 3
}

/// The band, pixels, that `spec`'s legend may take under the plot of a
/// chart `width` wide: [`below_grid`]'s when it is put there, or may be
/// (`Legend::Auto` where a column right of the plot is too wide: it goes
/// under the plot unless a place inside is free of data); 0 when it goes
/// inside or right of the plot, or there is none. A stack of panels keeps
/// this room in a panel's least height, so that its plot, and the rotated
/// y label centred on it, keep theirs.
pub fn legend_band(theme: &Theme, spec: &ChartSpec, width: u32) -> u32 {
    let below = match spec.legend {
        _ if !has_labels(spec) => false,
        Legend::Below => true,
        Legend::Auto => outside_too_wide(theme, spec, width),
        _ => false,
    };
    if below {
        below_grid(theme, spec, width).4
    } else {
        0
    }
}

/// A legend under the plot: [`below_grid`]'s columns, filled row by row,
/// the band's top at pixel `y` of a chart `width` wide.
pub(super) fn draw_below_legend(
    theme: &Theme,
    root: &Area<'_>,
    spec: &ChartSpec,
    y: i32,
) -> Result<()> {
    let width = root.dim_in_pixel().0;
    let (cols, _, col_w, row, _) = below_grid(theme, spec, width);
    let used = cols as i32 * col_w;
    let x0 = ((width as i32 - used) / 2).max(4);
    draw_entries(theme, root, spec, |k| {
        let (c, r) = ((k % cols) as i32, (k / cols) as i32);
        (x0 + c * col_w, y + row / 2 + r * row)
    })
}

/// Each labelled series of `spec` as a legend entry, glyph then text, the
/// `k`-th centred vertically at pixel `at(k)` of the whole chart.
fn draw_entries(
    theme: &Theme,
    root: &Area<'_>,
    spec: &ChartSpec,
    at: impl Fn(usize) -> (i32, i32),
) -> Result<()> {
    let text_style = font(theme, theme.tick)
        .into_font()
        .color(&rgb(Palette.color(Role::Ink)))
        .pos(Pos::new(HPos::Left, VPos::Center));
    let labelled = spec
        .series
        .iter()
        .filter_map(|s| s.label.as_ref().map(|l| (s, l)));
    for (k, (s, label)) in labelled.enumerate() {
        let at = at(k);
        let glyph = Glyph {
            at,
            line: s.line,
            marker: s.marker,
            color: s.color,
            width: s.width,
            offset: LEGEND_LINE / 2,
        };
        root.draw(&glyph).map_err(plot_error)?;
        let text = Text::new(
            label.as_str(),
            (at.0 + LEGEND_LINE + 6, at.1),
            text_style.clone(),
        );
        root.draw(&text).map_err(plot_error)?;
    }
    Ok(())
}

/// Plotters' placement for a resolved legend; `None` draws no legend.
fn label_position(legend: Legend) -> Option<SeriesLabelPosition> {
    use SeriesLabelPosition as P;
    Some(match legend {
        Legend::UpperLeft => P::UpperLeft,
        Legend::UpperMiddle => P::UpperMiddle,
        Legend::UpperRight | Legend::Auto => P::UpperRight,
        Legend::LowerLeft => P::LowerLeft,
        Legend::LowerMiddle => P::LowerMiddle,
        Legend::LowerRight => P::LowerRight,
        Legend::Outside | Legend::Below | Legend::Hidden => return None,
    })
}

/// The first inside placement whose legend box covers no sampled data
/// pixel (upper right, upper left, lower right, lower left, upper middle,
/// lower middle), else `Outside`.
pub(super) fn auto_legend<X, Y>(
    theme: &Theme,
    chart: &Ctx<'_, '_, X, Y>,
    spec: &ChartSpec,
) -> Legend
where
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    let (px, py) = chart.plotting_area().get_pixel_range();
    let (bw, bh) = legend_box(theme, spec);
    let pts = sampled_pixels(chart, spec);
    let mid = (px.start + px.end - bw) / 2;
    let candidates = [
        (Legend::UpperRight, px.end - bw, py.start),
        (Legend::UpperLeft, px.start, py.start),
        (Legend::LowerRight, px.end - bw, py.end - bh),
        (Legend::LowerLeft, px.start, py.end - bh),
        (Legend::UpperMiddle, mid, py.start),
        (Legend::LowerMiddle, mid, py.end - bh),
    ];
    // The box as drawn sits a margin in from the plot's corner and may
    // be a little larger than estimated: a band of LEGEND_CLEAR pixels
    // round it must be free of data too (winding's legend once touched
    // the det C circle).
    let c = LEGEND_CLEAR;
    let free = |x0: i32, y0: i32| {
        !pts.iter()
            .any(|p| p.0 >= x0 - c && p.0 <= x0 + bw + c && p.1 >= y0 - c && p.1 <= y0 + bh + c)
    };
    candidates
        .into_iter()
        .find(|(_, x0, y0)| free(*x0, *y0))
        .map_or(Legend::Outside, |c| c.0)
}

/// Pixels round an inside legend's estimated box that must hold no data.
const LEGEND_CLEAR: i32 = 10;

/// Estimated legend box in pixels (with its margin).
pub(super) fn legend_box(theme: &Theme, spec: &ChartSpec) -> (i32, i32) {
    let labels: Vec<&String> = spec
        .series
        .iter()
        .filter_map(|s| s.label.as_ref())
        .collect();
    let text = labels
        .iter()
        .map(|l| style::text_width(theme.font(), l, theme.tick))
        .fold(0.0, f32::max);
    let w = text + 28.0 + 34.0;
    let h = labels.len() as f32 * (theme.tick * theme.legend_row_em) + 24.0;
    (w as i32, h as i32)
}

/// Pixel positions of every point and of points interpolated along lines.
fn sampled_pixels<X, Y>(chart: &Ctx<'_, '_, X, Y>, spec: &ChartSpec) -> Vec<(i32, i32)>
where
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    let mut out = Vec::new();
    for s in &spec.series {
        for run in runs(s, spec) {
            let pix: Vec<(i32, i32)> = run.iter().map(|p| chart.backend_coord(p)).collect();
            out.extend(&pix);
            if s.line == LineStyle::None {
                continue;
            }
            for w in pix.windows(2) {
                let steps =
                    ((w[1].0 - w[0].0).abs().max((w[1].1 - w[0].1).abs()) / 2).clamp(1, 400);
                for k in 1..steps {
                    let f = k as f64 / steps as f64;
                    let lerp = |a: i32, b: i32| a + ((b - a) as f64 * f).round() as i32;
                    out.push((lerp(w[0].0, w[1].0), lerp(w[0].1, w[1].1)));
                }
            }
        }
    }
    out
}
