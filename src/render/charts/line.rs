//! [`line_chart`]: lays out and draws a [`ChartSpec`] (linear or log axes,
//! equal aspect, legend placement by a probe pass).

use super::glyph::Glyph;
use super::legend::{
    auto_legend, below_grid, draw_below_legend, draw_legend, draw_outside_legend, has_labels,
    legend_box, outside_too_wide,
};
use super::ranges::{Range2, data_range, equalize, runs};
use super::title::{fit_title, titled};
use super::{
    Area, Chart, ChartSpec, Ctx, Legend, LineStyle, Marker, Scale, Series, check_size, dark_axes,
    end_labels, font, plot_error, rgb, y_label_area,
};
use crate::error::Result;
use crate::render::Theme;
use crate::render::palette::{Palette, Role};
use crate::render::style::{self, size};
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;
use std::ops::Range;

/// Draws `spec` as a `width × height` chart with the sizes, font and
/// habits of `theme` (the figure's, passed down by its builder).
pub fn line_chart(theme: &Theme, spec: &ChartSpec, width: u32, height: u32) -> Result<Chart> {
    check_size(width, height)?;
    let spec = for_theme(theme, spec);
    style::register_plotters_font();
    let (pass, xr, yr) = layout(theme, &spec, width, height)?;
    draw(theme, &spec, (width, height), pass, (xr, yr))
}

/// [`line_chart`] `width` wide and `height` tall, or taller by the
/// legend's band when the legend goes under the plot (up to
/// `max_height`), so that the plot keeps the height it would have had
/// (docs/formats.md: the figure grows within the page budget; the plot
/// keeps at least half of its panel).
pub fn line_chart_growing(
    theme: &Theme,
    spec: &ChartSpec,
    width: u32,
    height: u32,
    max_height: u32,
) -> Result<Chart> {
    check_size(width, height)?;
    let spec = for_theme(theme, spec);
    style::register_plotters_font();
    let (pass, xr, yr) = layout(theme, &spec, width, height)?;
    if pass.legend != Legend::Below {
        return draw(theme, &spec, (width, height), pass, (xr, yr));
    }
    // Laid out again at the new height (the legend's place may change).
    let band = below_grid(theme, &spec, width).4;
    line_chart(
        theme,
        &spec,
        width,
        (height + band).min(max_height.max(height)),
    )
}

/// `spec` as `theme` draws it: journal styles draw no title (the caption
/// is the document's).
fn for_theme<'a>(theme: &Theme, spec: &'a ChartSpec) -> std::borrow::Cow<'a, ChartSpec> {
    if spec.title.is_some() && !theme.titles {
        std::borrow::Cow::Owned(ChartSpec {
            title: None,
            ..spec.clone()
        })
    } else {
        std::borrow::Cow::Borrowed(spec)
    }
}

/// The chart's SVG with the legend placement and ranges of [`layout`].
fn draw(
    theme: &Theme,
    spec: &ChartSpec,
    (width, height): (u32, u32),
    pass: Pass,
    (xr, yr): (Range<f64>, Range<f64>),
) -> Result<Chart> {
    let mut svg = String::new();
    let plot;
    {
        let root = SVGBackend::with_string(&mut svg, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_error)?;
        let probe = draw_any(theme, &root, spec, pass, xr, yr)?;
        plot = probe.plot;
        root.present().map_err(plot_error)?;
    }
    let mut chart = Chart::from_svg(theme, &svg, width, height)?;
    chart.plot_x = Some((plot.0.start, plot.0.end));
    chart.plot_y = Some((plot.1.start, plot.1.end));
    Ok(chart)
}

/// Where the legend goes and the axes' ranges, for `spec` drawn
/// `width × height`.
fn layout(
    theme: &Theme,
    spec: &ChartSpec,
    width: u32,
    height: u32,
) -> Result<(Pass, Range<f64>, Range<f64>)> {
    let (x0, y0) = (data_range(spec, true)?, data_range(spec, false)?);
    let mut pass = Pass {
        legend: if has_labels(spec) {
            spec.legend
        } else {
            Legend::Hidden
        },
        probe: true,
    };
    let (mut xr, mut yr) = (x0.clone(), y0.clone());
    if spec.equal_aspect {
        (xr, yr) = equalized(theme, spec, pass, (width, height), x0.clone(), y0.clone())?;
    }
    if pass.legend == Legend::Auto {
        pass.legend = probe(theme, spec, pass, (width, height), xr.clone(), yr.clone())?.legend;
        // A column right of the plot that would take more than a third of
        // the chart goes under the plot instead, in columns: the plot keeps
        // its width, the text its size.
        if pass.legend == Legend::Outside && outside_too_wide(theme, spec, width) {
            pass.legend = Legend::Below;
        }
        if pass.legend == Legend::Outside && spec.equal_aspect {
            (xr, yr) = equalized(theme, spec, pass, (width, height), x0, y0)?;
        }
    }
    pass.probe = false;
    Ok((pass, xr, yr))
}

/// Dispatches on the four combinations of linear and log axes.
fn draw_any(
    theme: &Theme,
    root: &Area<'_>,
    spec: &ChartSpec,
    pass: Pass,
    xr: Range<f64>,
    yr: Range<f64>,
) -> Result<Probe> {
    let y_ends = if spec.y.names.is_empty() {
        end_labels(yr.start, yr.end, spec.y.scale)
    } else {
        spec.y.names.clone()
    };
    let y_area = y_label_area(theme, &y_ends);
    match (spec.x.scale, spec.y.scale) {
        (Scale::Linear, Scale::Linear) => draw_xy(theme, root, spec, pass, (xr, yr), y_area),
        (Scale::Linear, Scale::Log) => {
            draw_xy(theme, root, spec, pass, (xr, yr.log_scale()), y_area)
        }
        (Scale::Log, Scale::Linear) => {
            draw_xy(theme, root, spec, pass, (xr.log_scale(), yr), y_area)
        }
        (Scale::Log, Scale::Log) => draw_xy(
            theme,
            root,
            spec,
            pass,
            (xr.log_scale(), yr.log_scale()),
            y_area,
        ),
    }
}

/// One drawing pass: the legend placement to use, and whether this is a
/// layout probe on a scratch SVG (axes only, no series).
#[derive(Clone, Copy, Debug)]
struct Pass {
    legend: Legend,
    probe: bool,
}

/// What a pass found out: the plotting area and, for `Legend::Auto`, the
/// placement that covers no data.
struct Probe {
    plot: Range2,
    legend: Legend,
}

/// Lays the chart out on a scratch SVG.
fn probe(
    theme: &Theme,
    spec: &ChartSpec,
    pass: Pass,
    (w, h): (u32, u32),
    xr: Range<f64>,
    yr: Range<f64>,
) -> Result<Probe> {
    let mut scratch = String::new();
    let root = SVGBackend::with_string(&mut scratch, (w, h)).into_drawing_area();
    draw_any(
        theme,
        &root,
        spec,
        Pass {
            probe: true,
            ..pass
        },
        xr,
        yr,
    )
}

/// Ranges grown to equal scales for the plotting area of this layout.
fn equalized(
    theme: &Theme,
    spec: &ChartSpec,
    pass: Pass,
    size: (u32, u32),
    xr: Range<f64>,
    yr: Range<f64>,
) -> Result<(Range<f64>, Range<f64>)> {
    let (px, py) = probe(theme, spec, pass, size, xr.clone(), yr.clone())?.plot;
    let (pw, ph) = (
        (px.end - px.start).max(1) as f64,
        (py.end - py.start).max(1) as f64,
    );
    Ok(equalize(xr, yr, pw, ph))
}

fn draw_xy<XS, YS>(
    theme: &Theme,
    root: &Area<'_>,
    spec: &ChartSpec,
    pass: Pass,
    (xs, ys): (XS, YS),
    y_area: u32,
) -> Result<Probe>
where
    XS: AsRangedCoord<Value = f64>,
    YS: AsRangedCoord<Value = f64>,
    XS::CoordDescType: ValueFormatter<f64>,
    YS::CoordDescType: ValueFormatter<f64>,
{
    let below =
        (pass.legend == Legend::Below).then(|| below_grid(theme, spec, root.dim_in_pixel().0).4);
    let (area, width, one_line) = plot_region(theme, root, spec, pass, below)?;
    let mut builder = ChartBuilder::on(&area);
    set_margins(theme, &mut builder, spec, width, y_area);
    if let Some(t) = spec.title.as_ref().filter(|_| one_line) {
        builder.caption(
            t,
            font(theme, size::TITLE)
                .into_font()
                .color(&rgb(Palette.color(Role::Ink))),
        );
    }
    let mut chart = builder.build_cartesian_2d(xs, ys).map_err(plot_error)?;
    let plot = chart.plotting_area().get_pixel_range();
    if pass.probe {
        let legend = match pass.legend {
            Legend::Auto => auto_legend(theme, &chart, spec),
            other => other,
        };
        return Ok(Probe { plot, legend });
    }
    draw_mesh(theme, &mut chart, spec)?;
    if spec.zero_lines {
        draw_zero_lines(&mut chart)?;
    }
    for s in &spec.series {
        draw_series(&mut chart, s, spec)?;
    }
    if pass.legend == Legend::Outside {
        draw_outside_legend(
            theme,
            root,
            spec,
            (plot.0.end + theme.legend_gap, plot.1.start),
        )?;
    } else if let Some(band) = below {
        let top = root.dim_in_pixel().1 as i32 - band as i32;
        draw_below_legend(theme, root, spec, top)?;
    } else {
        draw_legend(theme, &mut chart, spec, pass.legend)?;
    }
    Ok(Probe {
        plot,
        legend: pass.legend,
    })
}

/// The part of `root` the chart's axes and title take: without the
/// legend's room (beside or `below`, pixels), and under a title too long
/// for one line (wrapped and shrunk to the chart's width by `fit_title`,
/// never cut); with its width, pixels, and whether the title (if any) is
/// on one line, when it is the chart's caption.
fn plot_region<'a>(
    theme: &Theme,
    root: &Area<'a>,
    spec: &ChartSpec,
    pass: Pass,
    below: Option<u32>,
) -> Result<(Area<'a>, u32, bool)> {
    let area = if spec.plot_x.is_some() {
        // The plot's edges are given: the legend goes right of them.
        root.margin(0, below.unwrap_or(0), 0, 0)
    } else if pass.legend == Legend::Outside {
        root.margin(
            0,
            0,
            0,
            legend_box(theme, spec).0 as u32 + theme.legend_gap_min,
        )
    } else if let Some(band) = below {
        root.margin(0, band, 0, 0)
    } else {
        root.clone()
    };
    let width = area.dim_in_pixel().0;
    let one_line = spec.title.as_deref().is_none_or(|t| {
        fit_title(theme, t, width).lines.len() == 1
            && fit_title(theme, t, width).size == size::TITLE
    });
    if one_line {
        Ok((area, width, true))
    } else {
        let area = titled(theme, area, spec.title.as_deref(), width)?;
        Ok((area, width, false))
    }
}

/// The chart's margins and the room of its axes' labels (`y_area` at the
/// left), on a region `width` pixels wide; a chart whose plot's edges are
/// given (`spec.plot_x`) puts them there.
fn set_margins<DB: DrawingBackend>(
    theme: &Theme,
    builder: &mut ChartBuilder<'_, '_, DB>,
    spec: &ChartSpec,
    width: u32,
    y_area: u32,
) {
    // A shared x axis is labelled by the panel below: room for its
    // numbers only.
    let x_area = if spec.x.numbered {
        theme.numbered_x_area
    } else if spec.x.shared {
        theme.shared_x_area
    } else {
        theme.x_label_area
    };
    builder
        .margin(theme.chart_margin as u32)
        .margin_top(theme.chart_margin_y as u32)
        .margin_bottom(theme.chart_margin_y as u32)
        .x_label_area_size(x_area)
        .y_label_area_size(y_area);
    if let Some(right) = x_label_right_margin(theme, spec, width, y_area) {
        builder.margin_right(right);
    }
    if let Some((left, right)) = spec.plot_x {
        let m = theme.chart_margin as i32;
        builder
            .y_label_area_size((left - m).max(0) as u32)
            .margin_right((width as i32 - right).max(0) as u32);
    }
}

/// The right margin, pixels, that keeps the x axis' label (centred under
/// the plot) inside a chart `width` wide whose y label area is `y_area`,
/// where the usual margin does not: a label wider than the plot and its
/// margin (long row names at the left push a narrow plot right) would
/// otherwise end past the chart's edge. `None`: the usual margin holds it
/// (or the plot's edges are given, or the axis is labelled elsewhere).
fn x_label_right_margin(theme: &Theme, spec: &ChartSpec, width: u32, y_area: u32) -> Option<u32> {
    if spec.plot_x.is_some() || spec.x.shared || spec.x.label.is_empty() {
        return None;
    }
    let label = style::text_width(theme.font(), &spec.x.label, size::LABEL);
    let m = theme.chart_margin;
    // The label's right end, (left + right) / 2 + label / 2, at most the
    // chart's width less the margin's air: the plot's left edge is
    // m + y_area, its right edge width − r.
    let r = (m + y_area as f32 + label + 2.0 * LABEL_AIR - width as f32).ceil();
    (r > m).then_some(r as u32)
}

/// Air, pixels, kept between an x axis label and the chart's edge.
const LABEL_AIR: f32 = 2.0;

fn draw_mesh<X, Y>(theme: &Theme, chart: &mut Ctx<'_, '_, X, Y>, spec: &ChartSpec) -> Result<()>
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let shared = spec.x.shared;
    // A shared axis keeps its numbers when asked (every stacked sweep
    // panel can be read); its label is left to the panel below.
    let bare = shared && !spec.x.numbered;
    let (x_axis, y_axis) = (spec.x.clone(), spec.y.clone());
    let xf = move |v: &f64| {
        if bare {
            String::new()
        } else {
            x_axis.tick_text(*v)
        }
    };
    let yf = move |v: &f64| y_axis.tick_text(*v);
    let x_count = x_label_count(theme, chart, spec);
    // As many y labels as fit one above the other with a line between
    // them, at most 7, at a print style.
    let plot_h = {
        let (_, py) = chart.plotting_area().get_pixel_range();
        (py.end - py.start) as f32
    };
    let y_count = if !spec.y.names.is_empty() {
        spec.y.names.len()
    } else if theme.is_print() {
        ((plot_h / (2.2 * theme.tick)).floor() as usize).clamp(2, 7)
    } else {
        7
    };
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(if shared { "" } else { spec.x.label.as_str() })
        .y_desc(spec.y.label.as_str())
        .x_label_formatter(&xf)
        .y_label_formatter(&yf)
        .x_labels(x_count)
        .y_labels(y_count);
    // At a print style the minor grid is one faint line between major
    // ones (a full minor mesh prints as a grey fog at column width).
    if theme.is_print() {
        mesh.max_light_lines(1);
    }
    dark_axes(theme, &mut mesh)
        .bold_line_style(rgb(Palette.color(Role::Ink)).mix(0.12))
        .light_line_style(rgb(Palette.color(Role::Ink)).mix(0.05))
        .draw()
        .map_err(plot_error)
}

/// How many x labels to ask plotters for: the names of a named axis; at a
/// print style as many as fit side by side with a gap (at most 7), and
/// then at least two labelled ticks where two fit (`--style paper` once
/// labelled S5's qb axis, −π to π, at 0 alone: asked for two, plotters
/// steps by 5); seven at screen (and its goldens).
fn x_label_count<X, Y>(theme: &Theme, chart: &Ctx<'_, '_, X, Y>, spec: &ChartSpec) -> usize
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    if !spec.x.names.is_empty() {
        return spec.x.names.len();
    }
    if !theme.is_print() {
        return 7;
    }
    let plot_w = {
        let (px, _) = chart.plotting_area().get_pixel_range();
        (px.end - px.start) as f32
    };
    let xr = chart.x_range();
    let width = |t: &str| style::text_width(theme.font(), t, theme.tick);
    let widest = end_labels(xr.start, xr.end, spec.x.scale)
        .iter()
        .map(|t| width(t))
        .fold(0.0f32, f32::max);
    let count = ((plot_w / (widest + 14.0)).floor() as usize).clamp(2, 7);
    let x = chart.as_coord_spec().x_spec();
    let read = |n: usize| {
        let at: Vec<f64> = x.key_points(n);
        let room: f32 = at.iter().map(|v| width(&spec.x.tick_text(*v)) + 14.0).sum();
        at.len() >= 2 && room <= plot_w
    };
    if read(count) {
        return count;
    }
    (count + 1..=7).find(|&n| read(n)).unwrap_or(count)
}

fn draw_zero_lines<X, Y>(chart: &mut Ctx<'_, '_, X, Y>) -> Result<()>
where
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    let (xr, yr) = (chart.x_range(), chart.y_range());
    let grey = rgb(Palette.color(Role::Ground)).stroke_width(1);
    if xr.start < 0.0 && xr.end > 0.0 {
        let l = PathElement::new(vec![(0.0, yr.start), (0.0, yr.end)], grey);
        chart.draw_series(std::iter::once(l)).map_err(plot_error)?;
    }
    if yr.start < 0.0 && yr.end > 0.0 {
        let l = PathElement::new(vec![(xr.start, 0.0), (xr.end, 0.0)], grey);
        chart.draw_series(std::iter::once(l)).map_err(plot_error)?;
    }
    Ok(())
}

fn draw_series<'a, 'b: 'a, X, Y>(
    chart: &mut Ctx<'a, 'b, X, Y>,
    s: &Series,
    spec: &ChartSpec,
) -> Result<()>
where
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    let style = rgb(s.color).stroke_width(s.width.round().max(1.0) as u32);
    let dash = (4.0 * s.width).round() as u32;
    for run in runs(s, spec) {
        match s.line {
            LineStyle::Solid => {
                chart
                    .draw_series(LineSeries::new(run.clone(), style))
                    .map_err(plot_error)?;
            }
            LineStyle::Dashed => {
                let series = DashedLineSeries::new(run.clone(), dash, dash, style);
                chart.draw_series(series).map_err(plot_error)?;
            }
            LineStyle::None => {}
        }
        if s.marker != Marker::None {
            let markers = run.iter().map(|&p| Glyph {
                at: p,
                line: LineStyle::None,
                marker: s.marker,
                color: s.color,
                width: s.width,
                offset: 0,
            });
            chart.draw_series(markers).map_err(plot_error)?;
        }
    }
    Ok(())
}
