//! [`kymograph`]: a heat map of sin θ_n, blocks across and time down,
//! with a diverging colour map and a colour bar.

use super::ticks::short_number;
use super::title::titled;
use super::{
    Area, Chart, Scale, check_size, dark_axes, end_labels, font, plot_error, rgb, y_label_area,
};
use crate::encode::Rgb;
use crate::error::{Error, Result};
use crate::render::Theme;
use crate::render::palette::{Palette, Role};
use crate::render::style::{self, size};
use plotters::prelude::*;

/// A kymograph: `values` holds one row per time (row-major, `n` columns,
/// column j is block j + 1), e.g. sin θ_n. Values are clamped to [−1, 1].
#[derive(Clone, Debug)]
pub struct Kymograph<'a> {
    pub times: &'a [f64],
    pub values: &'a [f64],
    pub n: usize,
    pub title: Option<&'a str>,
    /// Label of the colour bar, e.g. "sin θₙ".
    pub value_label: &'a str,
    /// Label of the time axis, e.g. "t/τ".
    pub time_label: &'a str,
    /// Events marked on the map by a small ring: (position across, in
    /// blocks, time), e.g. impacts between blocks n and n + 1 at n + ½
    /// (`scenes::toy`). None by default.
    pub marks: &'a [(f64, f64)],
}

impl<'a> Kymograph<'a> {
    /// A kymograph of sin θ_n with the default labels.
    pub fn new(times: &'a [f64], values: &'a [f64], n: usize) -> Kymograph<'a> {
        Kymograph {
            times,
            values,
            n,
            title: None,
            value_label: "sin θₙ",
            time_label: "t/τ",
            marks: &[],
        }
    }

    fn check(&self) -> Result<()> {
        let rows = self.times.len();
        let ok_times =
            self.times.iter().all(|t| t.is_finite()) && self.times.windows(2).all(|w| w[1] >= w[0]);
        if self.n == 0 || rows == 0 || self.values.len() != rows * self.n {
            return Err(Error::bad_input(format!(
                "kymograph needs at least one block and one time and {} x {} values, got {}",
                rows,
                self.n,
                self.values.len()
            )));
        }
        if !ok_times {
            return Err(Error::bad_input(
                "kymograph times must be finite and non-decreasing",
            ));
        }
        Ok(())
    }
}

/// sin θ_n of every block of every state, row-major (the kymograph's input).
pub fn polarisation_rows(states: &[&[f64]]) -> Vec<f64> {
    states
        .iter()
        .flat_map(|q| q.chunks_exact(3).map(|b| b[2].sin()))
        .collect()
}

/// Width of the colour bar column in pixels.
const COLORBAR_W: u32 = 96;

/// Draws a kymograph with a colour bar as a `width × height` chart with
/// the sizes and font of `theme`.
pub fn kymograph(theme: &Theme, k: &Kymograph<'_>, width: u32, height: u32) -> Result<Chart> {
    check_size(width, height)?;
    k.check()?;
    style::register_plotters_font();
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_error)?;
        let root = titled(theme, root, k.title, width)?;
        let (main, bar) = root.split_horizontally(width.saturating_sub(COLORBAR_W));
        draw_heatmap(theme, &main, k)?;
        draw_colorbar(theme, &bar, k.value_label)?;
        root.present().map_err(plot_error)?;
    }
    // Adjacent cells must not show anti-aliasing seams.
    let svg = svg.replace("<rect ", "<rect shape-rendering=\"crispEdges\" ");
    Chart::from_svg(theme, &svg, width, height)
}

/// Colour levels per sign in the heat map (runs of equal colour merge).
const LEVELS: f64 = 64.0;

fn quantised(v: f64) -> Rgb {
    style::diverging((v.clamp(-1.0, 1.0) * LEVELS).round() / LEVELS)
}

fn draw_heatmap(theme: &Theme, area: &Area<'_>, k: &Kymograph<'_>) -> Result<()> {
    let (t0, t1) = (k.times[0], k.times[k.times.len() - 1]);
    let t1 = if t1 > t0 { t1 } else { t0 + 1.0 };
    let n = k.n as f64;
    let mut chart = ChartBuilder::on(area)
        .margin(theme.chart_margin as u32)
        .margin_right(4)
        .x_label_area_size(theme.x_label_area)
        .y_label_area_size(y_label_area(theme, &end_labels(t0, t1, Scale::Linear)))
        .build_cartesian_2d(0.5..n + 0.5, -t1..-t0)
        .map_err(plot_error)?;
    let rows = chart.plotting_area().get_pixel_range().1.len().max(1);
    chart
        .draw_series(heat_cells(k, rows, t1))
        .map_err(plot_error)?;
    if !k.marks.is_empty() {
        let ink = rgb(Palette.color(Role::Ink));
        let r = (0.35 * size::TICK).max(3.0) as i32;
        let ring = ShapeStyle::from(&ink).stroke_width(1);
        chart
            .draw_series(k.marks.iter().map(|&(x, t)| Circle::new((x, -t), r, ring)))
            .map_err(plot_error)?;
    }
    let yf = |v: &f64| short_number(-*v);
    let xf = |v: &f64| {
        if (v - v.round()).abs() < 1e-9 {
            format!("{}", v.round())
        } else {
            String::new()
        }
    };
    let mut mesh = chart.configure_mesh();
    mesh.disable_mesh()
        .x_desc("block n")
        .y_desc(k.time_label)
        .x_labels(k.n.min(12))
        .y_labels(8)
        .x_label_formatter(&xf)
        .y_label_formatter(&yf);
    dark_axes(theme, &mut mesh).draw().map_err(plot_error)
}

/// Rectangles of the heat map: at most `rows` time bins (nearest sample per
/// bin), equal colours merged down each column. Time t is drawn at −t.
fn heat_cells(k: &Kymograph<'_>, rows: usize, t_end: f64) -> Vec<Rectangle<(f64, f64)>> {
    let m = k.times.len();
    let bins = m.min(rows);
    let pick: Vec<usize> = (0..bins)
        .map(|j| ((j as f64 + 0.5) * m as f64 / bins as f64) as usize)
        .map(|i| i.min(m - 1))
        .collect();
    let t = |j: usize| k.times[pick[j]];
    let edge = |j: usize| match j {
        0 => k.times[0],
        _ if j >= bins => t_end,
        _ => 0.5 * (t(j - 1) + t(j)),
    };
    let mut cells = Vec::new();
    for col in 0..k.n {
        let mut start = 0;
        for j in 1..=bins {
            let c = quantised(k.values[pick[start] * k.n + col]);
            if j < bins && quantised(k.values[pick[j] * k.n + col]) == c {
                continue;
            }
            let x = col as f64 + 1.0;
            let corners = [(x - 0.5, -edge(start)), (x + 0.5, -edge(j))];
            cells.push(Rectangle::new(corners, rgb(c).filled()));
            start = j;
        }
    }
    cells
}

fn draw_colorbar(theme: &Theme, area: &Area<'_>, label: &str) -> Result<()> {
    let mut chart = ChartBuilder::on(area)
        .margin(theme.chart_margin as u32)
        .margin_left(8)
        .margin_right(4)
        .caption(
            label,
            font(theme, size::LABEL)
                .into_font()
                .color(&rgb(Palette.color(Role::Ink))),
        )
        // Room under the caption for the upper half of the top tick label.
        .set_label_area_size(
            plotters::chart::LabelAreaPosition::Top,
            (0.7 * theme.tick).ceil() as u32,
        )
        .x_label_area_size(theme.x_label_area)
        .right_y_label_area_size(48)
        .build_cartesian_2d(0.0..1.0, -1.0..1.0)
        .map_err(plot_error)?;
    let steps = 128;
    let cells = (0..steps).map(|i| {
        let (a, b) = (
            -1.0 + 2.0 * i as f64 / steps as f64,
            -1.0 + 2.0 * (i + 1) as f64 / steps as f64,
        );
        Rectangle::new(
            [(0.0, a), (1.0, b)],
            rgb(style::diverging(0.5 * (a + b))).filled(),
        )
    });
    chart.draw_series(cells).map_err(plot_error)?;
    let yf = |v: &f64| short_number(*v);
    chart
        .configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_labels(5)
        .y_label_formatter(&yf)
        .label_style(
            font(theme, theme.tick)
                .into_font()
                .color(&rgb(Palette.color(Role::Ink))),
        )
        .axis_style(rgb(Palette.color(Role::Ink)).stroke_width(1))
        .draw()
        .map_err(plot_error)
}
