//! Data-driven charts: plotters draws an SVG with the bundled font, resvg
//! rasterises it (anti-aliased, the same tiny-skia as the snapshots).
//!
//! [`line_chart`] covers line charts with several series (solid or dashed,
//! optional markers), scatter-plus-line charts, parametric curves with equal
//! aspect, and linear or logarithmic axes (log–log work-precision charts).
//! [`kymograph`] draws a heat map of sin θ_n, blocks across and time down,
//! with a diverging colour map and a colour bar.

use super::style::{self, DARK, FONT_FAMILY, GREY, size};
use crate::encode::Rgb;
use crate::error::{Error, Result};
use plotters::coord::Shift;
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters_backend::{BackendCoord, DrawingErrorKind};
use std::ops::Range;
use std::sync::OnceLock;
use tiny_skia::Pixmap;

/// A rendered chart: the raster image and the SVG it came from.
pub struct Chart {
    pub pixmap: Pixmap,
    pub svg: String,
    /// The SVG parsed with the bundled font (for drawing at other scales).
    tree: OnceLock<Option<resvg::usvg::Tree>>,
}

impl Chart {
    /// A chart already rasterised (`pixmap`) from its `svg`.
    pub fn new(pixmap: Pixmap, svg: String) -> Chart {
        Chart {
            pixmap,
            svg,
            tree: OnceLock::new(),
        }
    }

    /// A chart from its SVG (text markup of [`style::runs`] typeset),
    /// rasterised at `width × height` onto white.
    pub fn from_svg(svg: &str, width: u32, height: u32) -> Result<Chart> {
        let svg = typeset_svg_text(svg);
        let tree = parse_svg(&svg)?;
        let pixmap = rasterize_tree(&tree, width, height)?;
        Ok(Chart {
            pixmap,
            svg,
            tree: OnceLock::from(Some(tree)),
        })
    }

    /// The parsed SVG (`None` only if it cannot be parsed).
    pub fn tree(&self) -> Option<&resvg::usvg::Tree> {
        self.tree.get_or_init(|| parse_svg(&self.svg).ok()).as_ref()
    }
}

impl std::fmt::Debug for Chart {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Chart")
            .field("width", &self.pixmap.width())
            .field("height", &self.pixmap.height())
            .field("svg_bytes", &self.svg.len())
            .finish()
    }
}

/// Rewrites the content of each `<text>` element of plotters' SVG that
/// holds markup (`^{...}`, `_{...}`) into `<tspan>`s with a smaller size
/// and a shifted baseline, sized from the element's `font-size`.
pub fn typeset_svg_text(svg: &str) -> String {
    if !svg.contains("^{") && !svg.contains("_{") {
        return svg.to_string();
    }
    let mut out = String::with_capacity(svg.len() + 256);
    let mut rest = svg;
    while let Some(open) = rest.find("<text") {
        let Some(tag_end) = rest[open..].find('>').map(|i| open + i + 1) else {
            break;
        };
        let Some(close) = rest[tag_end..].find("</text>").map(|i| tag_end + i) else {
            break;
        };
        let tag = &rest[open..tag_end];
        let size = attribute(tag, "font-size")
            .and_then(|v| v.parse::<f32>().ok())
            .unwrap_or(size::TICK);
        out.push_str(&rest[..tag_end]);
        for (shift, run) in style::runs(&rest[tag_end..close]) {
            match shift {
                style::Shift::Base => out.push_str(run),
                _ => out.push_str(&format!(
                    "<tspan font-size=\"{:.2}\" baseline-shift=\"{:.2}\">{run}</tspan>",
                    size * shift.scale(),
                    size * shift.rise()
                )),
            }
        }
        rest = &rest[close..];
    }
    out.push_str(rest);
    out
}

/// The value of `name="..."` in an XML start tag.
fn attribute<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let start = tag.find(&key)? + key.len();
    let end = tag[start..].find('"')? + start;
    Some(&tag[start..end])
}

fn parse_svg(svg: &str) -> Result<resvg::usvg::Tree> {
    resvg::usvg::Tree::from_str(svg, &style::usvg_options())
        .map_err(|e| Error::failed(format!("internal SVG could not be parsed: {e}")))
}

/// Rasterises a parsed SVG onto a white `width × height` pixmap (scaled
/// to fit).
pub fn rasterize_tree(tree: &resvg::usvg::Tree, width: u32, height: u32) -> Result<Pixmap> {
    let mut pixmap = style::white_pixmap(width, height)
        .ok_or_else(|| super::snapshot::bad_size(width, height))?;
    let s = tree.size();
    let t = tiny_skia::Transform::from_scale(width as f32 / s.width(), height as f32 / s.height());
    resvg::render(tree, t, &mut pixmap.as_mut());
    Ok(pixmap)
}

/// Axis scale.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Scale {
    #[default]
    Linear,
    /// Base-10 logarithmic; non-positive values are left out.
    Log,
}

/// One axis: its label (with units, Greek letters welcome), an optional
/// fixed range, and the scale.
#[derive(Clone, Debug, Default)]
pub struct Axis {
    pub label: String,
    pub range: Option<(f64, f64)>,
    pub scale: Scale,
}

impl Axis {
    /// A linear axis with automatic range.
    pub fn new(label: impl Into<String>) -> Axis {
        Axis {
            label: label.into(),
            ..Axis::default()
        }
    }

    /// Fixes the range.
    pub fn range(mut self, lo: f64, hi: f64) -> Axis {
        self.range = Some((lo, hi));
        self
    }

    /// Makes the axis logarithmic.
    pub fn log(mut self) -> Axis {
        self.scale = Scale::Log;
        self
    }
}

/// How a series' points are joined.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum LineStyle {
    #[default]
    Solid,
    Dashed,
    /// Markers only.
    None,
}

/// Marker drawn at each point of a series.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Marker {
    #[default]
    None,
    Circle,
    Square,
    Triangle,
    /// A diagonal cross, e.g. for diverged runs.
    Cross,
}

/// One data series. Non-finite points (and non-positive ones on log axes)
/// break the line.
#[derive(Clone, Debug)]
pub struct Series {
    /// Legend text; `None` keeps the series out of the legend.
    pub label: Option<String>,
    pub points: Vec<(f64, f64)>,
    pub color: Rgb,
    pub line: LineStyle,
    pub marker: Marker,
    /// Line width in pixels.
    pub width: f64,
}

impl Series {
    /// A solid line.
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>, color: Rgb) -> Series {
        Series {
            label: Some(label.into()).filter(|l: &String| !l.is_empty()),
            points,
            color,
            line: LineStyle::Solid,
            marker: Marker::None,
            width: 2.0,
        }
    }

    /// Markers only, no line.
    pub fn scatter(
        label: impl Into<String>,
        points: Vec<(f64, f64)>,
        color: Rgb,
        marker: Marker,
    ) -> Series {
        Series {
            line: LineStyle::None,
            marker,
            ..Series::line(label, points, color)
        }
    }

    /// Dashed line.
    pub fn dashed(mut self) -> Series {
        self.line = LineStyle::Dashed;
        self
    }

    /// Adds markers at the points.
    pub fn with_marker(mut self, marker: Marker) -> Series {
        self.marker = marker;
        self
    }

    /// Sets the line width in pixels.
    pub fn with_width(mut self, width: f64) -> Series {
        self.width = width;
        self
    }
}

/// Where the legend goes. `Auto` picks an inside position (corners, then
/// top and bottom middle) that covers no data, and reserves a column right
/// of the plot (`Outside`) when every inside position would.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Legend {
    #[default]
    Auto,
    UpperLeft,
    UpperMiddle,
    UpperRight,
    LowerLeft,
    LowerMiddle,
    LowerRight,
    Outside,
    Hidden,
}

/// A chart of x–y series.
#[derive(Clone, Debug, Default)]
pub struct ChartSpec {
    pub title: Option<String>,
    pub x: Axis,
    pub y: Axis,
    pub series: Vec<Series>,
    pub legend: Legend,
    /// Equal scales on both axes (parametric curves, the complex plane).
    pub equal_aspect: bool,
    /// Thin grey lines through x = 0 and y = 0 when in range.
    pub zero_lines: bool,
}

impl ChartSpec {
    /// A chart with the given axes and no series yet.
    pub fn new(x: Axis, y: Axis) -> ChartSpec {
        ChartSpec {
            x,
            y,
            ..ChartSpec::default()
        }
    }

    /// Sets the title.
    pub fn title(mut self, title: impl Into<String>) -> ChartSpec {
        self.title = Some(title.into());
        self
    }

    /// Adds a series.
    pub fn series(mut self, s: Series) -> ChartSpec {
        self.series.push(s);
        self
    }
}

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

fn plot_error<E: std::fmt::Debug>(e: E) -> Error {
    Error::failed(format!("chart drawing failed: {e:?}"))
}

/// Plotters font size that gives a CSS em size of `px` in the SVG (plotters
/// writes its size divided by 1.24).
fn font(px: f32) -> (&'static str, f64) {
    (FONT_FAMILY, f64::from(px) * 1.24)
}

fn rgb(c: Rgb) -> RGBColor {
    RGBColor(c[0], c[1], c[2])
}

/// Rasterises an SVG string with the bundled font onto a white
/// `width × height` pixmap (the SVG is scaled to fit).
pub fn rasterize_svg(svg: &str, width: u32, height: u32) -> Result<Pixmap> {
    rasterize_tree(&parse_svg(svg)?, width, height)
}

/// Draws `spec` as a `width × height` chart.
pub fn line_chart(spec: &ChartSpec, width: u32, height: u32) -> Result<Chart> {
    check_size(width, height)?;
    style::register_plotters_font();
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
        (xr, yr) = equalized(spec, pass, (width, height), x0.clone(), y0.clone())?;
    }
    if pass.legend == Legend::Auto {
        pass.legend = probe(spec, pass, (width, height), xr.clone(), yr.clone())?.legend;
        if pass.legend == Legend::Outside && spec.equal_aspect {
            (xr, yr) = equalized(spec, pass, (width, height), x0, y0)?;
        }
    }
    pass.probe = false;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_error)?;
        draw_any(&root, spec, pass, xr, yr)?;
        root.present().map_err(plot_error)?;
    }
    Chart::from_svg(&svg, width, height)
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

/// Dispatches on the four combinations of linear and log axes.
fn draw_any(
    root: &Area<'_>,
    spec: &ChartSpec,
    pass: Pass,
    xr: Range<f64>,
    yr: Range<f64>,
) -> Result<Probe> {
    match (spec.x.scale, spec.y.scale) {
        (Scale::Linear, Scale::Linear) => draw_xy(root, spec, pass, xr, yr),
        (Scale::Linear, Scale::Log) => draw_xy(root, spec, pass, xr, yr.log_scale()),
        (Scale::Log, Scale::Linear) => draw_xy(root, spec, pass, xr.log_scale(), yr),
        (Scale::Log, Scale::Log) => draw_xy(root, spec, pass, xr.log_scale(), yr.log_scale()),
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
    spec: &ChartSpec,
    pass: Pass,
    (w, h): (u32, u32),
    xr: Range<f64>,
    yr: Range<f64>,
) -> Result<Probe> {
    let mut scratch = String::new();
    let root = SVGBackend::with_string(&mut scratch, (w, h)).into_drawing_area();
    draw_any(
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
    spec: &ChartSpec,
    pass: Pass,
    size: (u32, u32),
    xr: Range<f64>,
    yr: Range<f64>,
) -> Result<(Range<f64>, Range<f64>)> {
    let (px, py) = probe(spec, pass, size, xr.clone(), yr.clone())?.plot;
    let (pw, ph) = (
        (px.end - px.start).max(1) as f64,
        (py.end - py.start).max(1) as f64,
    );
    Ok(equalize(xr, yr, pw, ph))
}

/// Pixel ranges (horizontal, vertical) of the plotting area.
type Range2 = (Range<i32>, Range<i32>);

/// Grows one range so that both axes have the same units per pixel.
fn equalize(xr: Range<f64>, yr: Range<f64>, pw: f64, ph: f64) -> (Range<f64>, Range<f64>) {
    let (sx, sy) = ((xr.end - xr.start) / pw, (yr.end - yr.start) / ph);
    let grow = |r: Range<f64>, s: f64, p: f64| {
        let (mid, half) = (0.5 * (r.start + r.end), 0.5 * s * p);
        mid - half..mid + half
    };
    if sx > sy {
        (xr, grow(yr, sx, ph))
    } else {
        (grow(xr, sy, pw), yr)
    }
}

fn axis_ok(scale: Scale, v: f64) -> bool {
    v.is_finite() && (scale == Scale::Linear || v > 0.0)
}

/// The axis range: the given one, or the data's with a 5 % pad (a factor on
/// log axes). Degenerate data get a unit-wide range.
fn data_range(spec: &ChartSpec, is_x: bool) -> Result<Range<f64>> {
    let axis = if is_x { &spec.x } else { &spec.y };
    if let Some((lo, hi)) = axis.range {
        return check_range(axis, lo, hi);
    }
    let vals = spec
        .series
        .iter()
        .flat_map(|s| s.points.iter())
        .filter(|p| axis_ok(spec.x.scale, p.0) && axis_ok(spec.y.scale, p.1))
        .map(|p| if is_x { p.0 } else { p.1 });
    let (lo, hi) = vals.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    Ok(padded(axis.scale, lo, hi))
}

fn check_range(axis: &Axis, lo: f64, hi: f64) -> Result<Range<f64>> {
    let ok =
        lo.is_finite() && hi.is_finite() && lo < hi && (axis.scale == Scale::Linear || lo > 0.0);
    if ok {
        Ok(lo..hi)
    } else {
        Err(Error::bad_input(format!(
            "axis \"{}\" needs a finite range lo < hi (lo > 0 on a log axis), got {lo}..{hi}",
            axis.label
        )))
    }
}

fn padded(scale: Scale, lo: f64, hi: f64) -> Range<f64> {
    match scale {
        _ if !lo.is_finite() => match scale {
            Scale::Linear => 0.0..1.0,
            Scale::Log => 1.0..10.0,
        },
        Scale::Linear => {
            let pad = if hi > lo {
                0.05 * (hi - lo)
            } else {
                0.5 * lo.abs().max(1.0)
            };
            lo - pad..hi + pad
        }
        Scale::Log => {
            let f = if hi > lo { (hi / lo).powf(0.05) } else { 3.0 };
            lo / f..hi * f
        }
    }
}

/// Tick label: powers of ten as 10⁻³ on log axes, otherwise a short number.
pub fn tick_label(v: f64, scale: Scale) -> String {
    if scale == Scale::Log && v > 0.0 {
        let e = v.log10();
        if (e - e.round()).abs() < 1e-9 {
            return format!("10{}", superscript(e.round() as i64));
        }
    }
    short_number(v)
}

/// A number with at most four significant digits and no trailing zeros,
/// negative numbers with a typographic minus sign (U+2212).
pub fn short_number(v: f64) -> String {
    plain_number(v).replace('-', "−")
}

fn plain_number(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return if v.is_finite() {
            "0".into()
        } else {
            format!("{v}")
        };
    }
    let a = v.abs();
    if !(1e-3..1e5).contains(&a) {
        let e = a.log10().floor() as i64;
        let m = v / 10f64.powi(e as i32);
        return format!("{}×10{}", trim(format!("{m:.2}")), superscript(e));
    }
    let decimals = (3 - a.log10().floor() as i64).clamp(0, 6) as usize;
    trim(format!("{v:.decimals$}"))
}

fn trim(s: String) -> String {
    if !s.contains('.') {
        return s;
    }
    let t = s.trim_end_matches('0').trim_end_matches('.');
    if t == "-0" { "0".into() } else { t.into() }
}

fn superscript(e: i64) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::new();
    if e < 0 {
        s.push('⁻');
    }
    for c in e.unsigned_abs().to_string().chars() {
        s.push(DIGITS[c.to_digit(10).unwrap_or(0) as usize]);
    }
    s
}

/// Left, right, top, bottom label areas and margins in pixels.
const Y_LABEL_AREA: u32 = 64;
const X_LABEL_AREA: u32 = 50;

fn draw_xy<XS, YS>(root: &Area<'_>, spec: &ChartSpec, pass: Pass, xs: XS, ys: YS) -> Result<Probe>
where
    XS: AsRangedCoord<Value = f64>,
    YS: AsRangedCoord<Value = f64>,
    XS::CoordDescType: ValueFormatter<f64>,
    YS::CoordDescType: ValueFormatter<f64>,
{
    let area = if pass.legend == Legend::Outside {
        root.margin(0, 0, 0, legend_box(spec).0 as u32 + 8)
    } else {
        root.clone()
    };
    let mut builder = ChartBuilder::on(&area);
    builder
        .margin(14)
        .x_label_area_size(X_LABEL_AREA)
        .y_label_area_size(Y_LABEL_AREA);
    if let Some(t) = &spec.title {
        builder.caption(t, font(size::TITLE).into_font().color(&rgb(DARK)));
    }
    let mut chart = builder.build_cartesian_2d(xs, ys).map_err(plot_error)?;
    let plot = chart.plotting_area().get_pixel_range();
    if pass.probe {
        let legend = match pass.legend {
            Legend::Auto => auto_legend(&chart, spec),
            other => other,
        };
        return Ok(Probe { plot, legend });
    }
    draw_mesh(&mut chart, spec)?;
    if spec.zero_lines {
        draw_zero_lines(&mut chart)?;
    }
    for s in &spec.series {
        draw_series(&mut chart, s, spec)?;
    }
    if pass.legend == Legend::Outside {
        draw_outside_legend(root, spec, (plot.0.end + 12, plot.1.start))?;
    } else {
        draw_legend(&mut chart, spec, pass.legend)?;
    }
    Ok(Probe {
        plot,
        legend: pass.legend,
    })
}

type Ctx<'a, 'b, X, Y> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<X, Y>>;

fn draw_mesh<X, Y>(chart: &mut Ctx<'_, '_, X, Y>, spec: &ChartSpec) -> Result<()>
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let (xscale, yscale) = (spec.x.scale, spec.y.scale);
    let xf = move |v: &f64| tick_label(*v, xscale);
    let yf = move |v: &f64| tick_label(*v, yscale);
    chart
        .configure_mesh()
        .x_desc(spec.x.label.as_str())
        .y_desc(spec.y.label.as_str())
        .x_label_formatter(&xf)
        .y_label_formatter(&yf)
        .x_labels(7)
        .y_labels(7)
        .label_style(font(size::TICK).into_font().color(&rgb(DARK)))
        .axis_desc_style(font(size::LABEL).into_font().color(&rgb(DARK)))
        .axis_style(rgb(DARK).stroke_width(1))
        .bold_line_style(rgb(DARK).mix(0.12))
        .light_line_style(rgb(DARK).mix(0.05))
        .draw()
        .map_err(plot_error)
}

fn draw_zero_lines<X, Y>(chart: &mut Ctx<'_, '_, X, Y>) -> Result<()>
where
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    let (xr, yr) = (chart.x_range(), chart.y_range());
    let grey = rgb(GREY).stroke_width(1);
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

/// Runs of consecutive drawable points (a gap wherever a point is not).
fn runs(s: &Series, spec: &ChartSpec) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for &p in &s.points {
        if axis_ok(spec.x.scale, p.0) && axis_ok(spec.y.scale, p.1) {
            if let Some(last) = out.last_mut() {
                last.push(p);
            }
        } else if out.last().is_some_and(|r| !r.is_empty()) {
            out.push(Vec::new());
        }
    }
    out.retain(|r| !r.is_empty());
    out
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

/// A marker, optionally behind a short legend line, drawn straight on the
/// backend at the pixel of its anchor point (a data point, or the legend
/// entry's position).
#[derive(Clone, Copy, Debug)]
struct Glyph<C> {
    at: C,
    /// Legend line (22 px, starting at the anchor); `None` for data markers.
    line: LineStyle,
    marker: Marker,
    color: Rgb,
    width: f64,
    /// Horizontal pixel offset of the marker from the anchor.
    offset: i32,
}

impl<'a, C: 'a> PointCollection<'a, C> for &'a Glyph<C> {
    type Point = &'a C;
    type IntoIter = std::iter::Once<&'a C>;
    fn point_iter(self) -> Self::IntoIter {
        std::iter::once(&self.at)
    }
}

/// Legend line length in pixels.
const LEGEND_LINE: i32 = 22;

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
    }
}

fn has_labels(spec: &ChartSpec) -> bool {
    spec.series.iter().any(|s| s.label.is_some())
}

fn draw_legend<'a, 'b: 'a, X, Y>(
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
        .label_font(font(size::TICK).into_font().color(&rgb(DARK)))
        .background_style(WHITE.mix(0.9))
        .border_style(rgb(DARK).mix(0.4))
        .draw()
        .map_err(plot_error)
}

/// A legend right of the plot: one row per labelled series, glyph then
/// text, starting at pixel `(x, y)` of the whole chart.
fn draw_outside_legend(root: &Area<'_>, spec: &ChartSpec, (x, y): (i32, i32)) -> Result<()> {
    let row = (size::TICK * 1.55) as i32;
    let text_style = font(size::TICK)
        .into_font()
        .color(&rgb(DARK))
        .pos(Pos::new(HPos::Left, VPos::Center));
    let labelled = spec
        .series
        .iter()
        .filter_map(|s| s.label.as_ref().map(|l| (s, l)));
    for (k, (s, label)) in labelled.enumerate() {
        let at = (x, y + row / 2 + k as i32 * row);
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
        Legend::Outside | Legend::Hidden => return None,
    })
}

/// The first inside placement whose legend box covers no sampled data
/// pixel (upper right, upper left, lower right, lower left, upper middle,
/// lower middle), else `Outside`.
fn auto_legend<X, Y>(chart: &Ctx<'_, '_, X, Y>, spec: &ChartSpec) -> Legend
where
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    let (px, py) = chart.plotting_area().get_pixel_range();
    let (bw, bh) = legend_box(spec);
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
    let free = |x0: i32, y0: i32| {
        !pts.iter()
            .any(|p| p.0 >= x0 && p.0 <= x0 + bw && p.1 >= y0 && p.1 <= y0 + bh)
    };
    candidates
        .into_iter()
        .find(|(_, x0, y0)| free(*x0, *y0))
        .map_or(Legend::Outside, |c| c.0)
}

/// Estimated legend box in pixels (with its margin).
fn legend_box(spec: &ChartSpec) -> (i32, i32) {
    let labels: Vec<&String> = spec
        .series
        .iter()
        .filter_map(|s| s.label.as_ref())
        .collect();
    let text = labels
        .iter()
        .map(|l| style::text_width(l, size::TICK))
        .fold(0.0, f32::max);
    let w = text + 28.0 + 34.0;
    let h = labels.len() as f32 * (size::TICK * 1.55) + 24.0;
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
                    ((w[1].0 - w[0].0).abs().max((w[1].1 - w[0].1).abs()) / 4).clamp(1, 200);
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

/// Draws a kymograph with a colour bar as a `width × height` chart.
pub fn kymograph(k: &Kymograph<'_>, width: u32, height: u32) -> Result<Chart> {
    check_size(width, height)?;
    k.check()?;
    style::register_plotters_font();
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_error)?;
        let root = match k.title {
            Some(t) => root
                .titled(t, font(size::TITLE).into_font().color(&rgb(DARK)))
                .map_err(plot_error)?,
            None => root,
        };
        let (main, bar) = root.split_horizontally(width.saturating_sub(COLORBAR_W));
        draw_heatmap(&main, k)?;
        draw_colorbar(&bar, k.value_label)?;
        root.present().map_err(plot_error)?;
    }
    // Adjacent cells must not show anti-aliasing seams.
    let svg = svg.replace("<rect ", "<rect shape-rendering=\"crispEdges\" ");
    Chart::from_svg(&svg, width, height)
}

/// Colour levels per sign in the heat map (runs of equal colour merge).
const LEVELS: f64 = 64.0;

fn quantised(v: f64) -> Rgb {
    style::diverging((v.clamp(-1.0, 1.0) * LEVELS).round() / LEVELS)
}

fn draw_heatmap(area: &Area<'_>, k: &Kymograph<'_>) -> Result<()> {
    let (t0, t1) = (k.times[0], k.times[k.times.len() - 1]);
    let t1 = if t1 > t0 { t1 } else { t0 + 1.0 };
    let n = k.n as f64;
    let mut chart = ChartBuilder::on(area)
        .margin(14)
        .margin_right(4)
        .x_label_area_size(X_LABEL_AREA)
        .y_label_area_size(Y_LABEL_AREA)
        .build_cartesian_2d(0.5..n + 0.5, -t1..-t0)
        .map_err(plot_error)?;
    let rows = chart.plotting_area().get_pixel_range().1.len().max(1);
    chart
        .draw_series(heat_cells(k, rows, t1))
        .map_err(plot_error)?;
    let yf = |v: &f64| short_number(-*v);
    let xf = |v: &f64| {
        if (v - v.round()).abs() < 1e-9 {
            format!("{}", v.round())
        } else {
            String::new()
        }
    };
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc("block n")
        .y_desc(k.time_label)
        .x_labels(k.n.min(12))
        .y_labels(8)
        .x_label_formatter(&xf)
        .y_label_formatter(&yf)
        .label_style(font(size::TICK).into_font().color(&rgb(DARK)))
        .axis_desc_style(font(size::LABEL).into_font().color(&rgb(DARK)))
        .axis_style(rgb(DARK).stroke_width(1))
        .draw()
        .map_err(plot_error)
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

fn draw_colorbar(area: &Area<'_>, label: &str) -> Result<()> {
    let mut chart = ChartBuilder::on(area)
        .margin(14)
        .margin_left(8)
        .margin_right(4)
        .caption(label, font(size::LABEL).into_font().color(&rgb(DARK)))
        .x_label_area_size(X_LABEL_AREA)
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
        .label_style(font(size::TICK).into_font().color(&rgb(DARK)))
        .axis_style(rgb(DARK).stroke_width(1))
        .draw()
        .map_err(plot_error)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short() {
        assert_eq!(short_number(0.5), "0.5");
        assert_eq!(short_number(1200.0), "1200");
        assert_eq!(short_number(-2.0), "−2");
        assert_eq!(short_number(1e-6), "1×10⁻⁶");
        assert_eq!(tick_label(1e-3, Scale::Log), "10⁻³");
        assert_eq!(tick_label(100.0, Scale::Log), "10²");
    }

    #[test]
    fn chart_text_markup_becomes_tspans() {
        let svg = "<svg><text x=\"1\" font-size=\"10\" fill=\"#000\">e^{−κ}, x_{n}\n</text>\
                   <text font-size=\"8\">plain</text></svg>";
        let out = typeset_svg_text(svg);
        assert!(
            out.contains("e<tspan font-size=\"7.00\" baseline-shift=\"3.80\">−κ</tspan>, x<tspan"),
            "{out}"
        );
        assert!(out.contains("<text font-size=\"8\">plain</text>"));
    }
}
