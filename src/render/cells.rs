//! A chart of coloured cells on a grid of two parameters (a sweep's phase
//! diagram, docs/sweeps.md): one cell per grid point, its colour given,
//! a legend of the colours and, optionally, a shade bar. Cells sit at
//! their index along each axis (uneven spacings such as 0.005, 0.01, 0.02
//! get equal cells), ticks name the values. Drawn like the other charts:
//! plotters writes an SVG with the bundled font, resvg rasterises it.

use super::charts::{
    Area, Chart, Glyph, LineStyle, Marker, dark_axes, font, plot_error, rgb, same_format,
    short_number, titled,
};
use super::palette::{Palette, Role, contrast_on_white};
use super::style::{self, size};
use super::theme::Theme;
use crate::encode::Rgb;
use crate::error::{Error, Result};
use plotters::prelude::*;

/// One cell: its column and row (indices into the axes' values) and colour.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    pub col: usize,
    pub row: usize,
    pub color: Rgb,
    /// A mark drawn at the cell's centre (the cue besides colour:
    /// [`Marker::None`] for none).
    pub marker: Marker,
}

/// A shade bar beside the legend: `label`, from `lo` (colour `from`) to
/// `hi` (colour `to`), shaded linearly in the value or (`log`) in its
/// logarithm; three labelled ticks in one number format.
#[derive(Debug, Clone, PartialEq)]
pub struct ShadeBar {
    pub label: String,
    pub lo: f64,
    pub hi: f64,
    pub log: bool,
    pub from: Rgb,
    pub to: Rgb,
}

/// The chart: axes' values (cell centres, in order), cells, legend.
#[derive(Debug, Clone, PartialEq)]
pub struct CellChart {
    pub title: Option<String>,
    pub x_label: String,
    pub y_label: String,
    pub xs: Vec<f64>,
    pub ys: Vec<f64>,
    pub cells: Vec<Cell>,
    /// (label, colour, marker) of each colour used: the marker, drawn in
    /// every cell of that colour and beside its swatch, is the second cue
    /// ([`Cell::marker`]).
    pub legend: Vec<(String, Rgb, Marker)>,
    pub shade: Option<ShadeBar>,
    /// The cells' left and right edges across the chart, pixels, when
    /// given (stacked panels sharing one x extent); `None` lays them out.
    pub plot_x: Option<(i32, i32)>,
}

/// Width of the legend column, pixels.
const LEGEND_W: u32 = 190;

/// Draws `c` as a `width × height` chart with the sizes and font of
/// `theme`.
pub fn cell_chart(theme: &Theme, c: &CellChart, width: u32, height: u32) -> Result<Chart> {
    if !((200..=8192).contains(&width) && (120..=8192).contains(&height)) {
        return Err(Error::bad_input(format!(
            "chart size must be between 200x120 and 8192x8192 pixels, got {width}x{height}"
        )));
    }
    if c.xs.is_empty() || c.ys.is_empty() {
        return Err(Error::bad_input("a cell chart needs values on both axes"));
    }
    style::register_plotters_font();
    let mut svg = String::new();
    let plot_x;
    {
        let root = SVGBackend::with_string(&mut svg, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_error)?;
        let root = titled(theme, root, c.title.as_deref(), width)?;
        // The legend beside the cells when the cells keep half the width
        // that way, else under them in rows (docs/formats.md: the plot
        // area keeps at least half of its panel each way).
        plot_x = if legend_beside(theme, c, width) {
            let (main, side) = root.split_horizontally(width.saturating_sub(LEGEND_W));
            let x = draw_cells(theme, &main, c)?;
            draw_legend(theme, &side, c)?;
            x
        } else {
            let below = legend_below_height(theme, c, width);
            let h = root.dim_in_pixel().1;
            let (main, bottom) = root.split_vertically(h.saturating_sub(below));
            let x = draw_cells(theme, &main, c)?;
            draw_legend_below(theme, &bottom, c)?;
            x
        };
        root.present().map_err(plot_error)?;
    }
    let svg = svg.replace("<rect ", "<rect shape-rendering=\"crispEdges\" ");
    let mut chart = Chart::from_svg(theme, &svg, width, height)?;
    chart.plot_x = Some(plot_x);
    Ok(chart)
}

/// The least height, pixels, at which `c` drawn `width` wide keeps all
/// it draws inside the chart: its title's lines, the x axis and a line of
/// tick text per row of cells, and its legend (beside the cells: the
/// swatches, the shade bar and its end labels; under them: its rows and
/// the bar).
pub fn least_height(theme: &Theme, c: &CellChart, width: u32) -> u32 {
    let title = c
        .title
        .as_deref()
        .filter(|_| theme.titles)
        .map_or(0.0, |t| {
            let fitted = super::charts::fit_title(theme, t, width);
            // plotters' `titled`: each line's height and 5 px above and below.
            fitted.lines.len() as f32 * (1.3 * fitted.size + 10.0)
        });
    let cells = 2.0 * CELLS_MARGIN + X_AREA as f32 + c.ys.len() as f32 * 1.2 * theme.tick;
    let body = if legend_beside(theme, c, width) {
        cells.max(legend_column_height(theme, c))
    } else {
        cells + legend_below_height(theme, c, width) as f32
    };
    (title + body).ceil() as u32
}

/// The cells' margin and x axis area, pixels.
const CELLS_MARGIN: f32 = 14.0;
const X_AREA: u32 = 50;

/// Height, pixels, of the legend beside the cells ([`draw_legend`]): its
/// rows, and the shade bar's label, the bar and half its end label.
fn legend_column_height(theme: &Theme, c: &CellChart) -> f32 {
    let rows = (LEGEND_TOP + LEGEND_ROW * c.legend.len() as i32) as f32;
    let bar = c.shade.as_ref().map_or(0.0, |_| {
        (BAR_LABEL_GAP + BAR_LABEL_LINE + BAR_HEIGHT) as f32 + 0.5 * theme.tick + 2.0
    });
    rows + bar
}

/// The legend beside the cells, pixels: its first row's top, a row's
/// height, the gap above the shade bar's label, the label's line and the
/// bar's height.
const LEGEND_TOP: i32 = 30;
const LEGEND_ROW: i32 = 26;
const BAR_LABEL_GAP: i32 = 14;
const BAR_LABEL_LINE: i32 = 32;
const BAR_HEIGHT: i32 = 140;

/// Whether the legend goes beside the cells (else under them): when the
/// cells keep half the chart's width that way.
fn legend_beside(theme: &Theme, c: &CellChart, width: u32) -> bool {
    width.saturating_sub(LEGEND_W + y_area(theme, c) + 20) >= width / 2
}

/// The width of the column the cells are drawn in (the chart's width
/// less the legend's beside it): panels stacked under the chart take
/// this width so that their x axes line up with the cells.
pub fn cells_width(theme: &Theme, c: &CellChart, width: u32) -> u32 {
    if legend_beside(theme, c, width) {
        width.saturating_sub(LEGEND_W)
    } else {
        width
    }
}

/// Room left of the cells for the widest tick label, the axis label
/// (turned on its side) and the gaps between them: at least 64 px.
fn y_area(theme: &Theme, c: &CellChart) -> u32 {
    let widest =
        c.ys.iter()
            .map(|&y| style::text_width(theme.font(), &short_number(y), theme.tick))
            .fold(0.0f32, f32::max);
    (widest + size::LABEL + 11.0).floor().max(64.0) as u32
}

/// Draws the cells, their marks and axes; the plot's span across.
fn draw_cells(theme: &Theme, area: &Area<'_>, c: &CellChart) -> Result<(i32, i32)> {
    let (nx, ny) = (c.xs.len() as f64, c.ys.len() as f64);
    let y_area = y_area(theme, c);
    // As many x labels as fit side by side with a gap (at most 10).
    let widest_x =
        c.xs.iter()
            .map(|&x| style::text_width(theme.font(), &short_number(x), theme.tick))
            .fold(0.0f32, f32::max);
    let plot_w = area.dim_in_pixel().0 as f32 - y_area as f32 - 20.0;
    let x_room = ((plot_w / (widest_x + 12.0)).floor() as usize).clamp(2, 10);
    let mut builder = ChartBuilder::on(area);
    builder
        .margin(CELLS_MARGIN as u32)
        .margin_right(6)
        .x_label_area_size(X_AREA)
        .y_label_area_size(y_area);
    if let Some((left, right)) = c.plot_x {
        let width = area.dim_in_pixel().0 as i32;
        builder
            .y_label_area_size((left - 14).max(0) as u32)
            .margin_right((width - right).max(0) as u32);
    }
    let mut chart = builder
        .build_cartesian_2d(-0.5..nx - 0.5, -0.5..ny - 0.5)
        .map_err(plot_error)?;
    let span = chart.plotting_area().get_pixel_range().0;
    chart
        .draw_series(c.cells.iter().map(|cell| {
            let (x, y) = (cell.col as f64, cell.row as f64);
            Rectangle::new(
                [(x - 0.5, y - 0.5), (x + 0.5, y + 0.5)],
                rgb(cell.color).filled(),
            )
        }))
        .map_err(plot_error)?;
    let label_at = |values: &[f64], v: f64| -> String {
        let i = v.round();
        if (v - i).abs() > 1e-6 || i < 0.0 || i as usize >= values.len() {
            return String::new();
        }
        short_number(values[i as usize])
    };
    let xf = |v: &f64| label_at(&c.xs, *v);
    let yf = |v: &f64| label_at(&c.ys, *v);
    let mut mesh = chart.configure_mesh();
    mesh.disable_mesh()
        .x_desc(c.x_label.as_str())
        .y_desc(c.y_label.as_str())
        .x_labels(ticks(c.xs.len(), x_room))
        .y_labels(ticks(c.ys.len(), 10))
        .x_label_formatter(&xf)
        .y_label_formatter(&yf);
    dark_axes(theme, &mut mesh).draw().map_err(plot_error)?;
    draw_cell_marks(theme, &mut chart, c)?;
    Ok((span.start, span.end))
}

/// Each cell's mark at its centre, in white on a dark fill and in ink on
/// a pale one, so that outcomes differ by shape as well as by colour.
fn draw_cell_marks<X, Y>(
    theme: &Theme,
    chart: &mut ChartContext<'_, SVGBackend<'_>, Cartesian2d<X, Y>>,
    c: &CellChart,
) -> Result<()>
where
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    let marks = c.cells.iter().filter(|cell| cell.marker != Marker::None);
    let glyphs = marks.map(|cell| Glyph {
        at: (cell.col as f64, cell.row as f64),
        line: LineStyle::None,
        marker: cell.marker,
        color: mark_color(theme, cell.color),
        width: CELL_MARK_WIDTH,
        offset: 0,
    });
    chart.draw_series(glyphs).map_err(plot_error)?;
    Ok(())
}

/// A legend swatch's mark (its cells' marker) at pixel `at` of `area`.
fn swatch_mark(
    theme: &Theme,
    area: &Area<'_>,
    at: (i32, i32),
    fill: Rgb,
    marker: Marker,
) -> Result<()> {
    if marker == Marker::None {
        return Ok(());
    }
    let glyph = Glyph {
        at,
        line: LineStyle::None,
        marker,
        color: mark_color(theme, fill),
        width: CELL_MARK_WIDTH,
        offset: 0,
    };
    area.draw(&glyph).map_err(plot_error)
}

/// Line width of the marks in cells and beside the legend's swatches.
const CELL_MARK_WIDTH: f64 = 1.5;

/// The colour of a mark drawn on `fill`: white on a dark fill, ink on a
/// pale one (whichever reads better).
fn mark_color(theme: &Theme, fill: Rgb) -> Rgb {
    let (ink, paper) = (theme.color(Role::Ink), theme.color(Role::Paper));
    if contrast(fill, paper) > contrast(fill, ink) {
        paper
    } else {
        ink
    }
}

/// WCAG contrast of two colours.
fn contrast(a: Rgb, b: Rgb) -> f64 {
    let (la, lb) = (
        1.05 / contrast_on_white(a) - 0.05,
        1.05 / contrast_on_white(b) - 0.05,
    );
    (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
}

/// Tick count that lands on whole cell indices: the number of cells when
/// few, else about `most`.
fn ticks(cells: usize, most: usize) -> usize {
    if cells <= most {
        return cells.max(2);
    }
    // plotters spaces labels evenly over the range; pick a count whose
    // spacing is a whole number of cells.
    let step = cells.div_ceil(most);
    (cells - 1) / step + 1
}

/// The shade bar's three tick labels, at its ends and its middle
/// (geometric on a log bar), in one number format.
fn bar_ticks(bar: &ShadeBar) -> Vec<String> {
    let mid = if bar.log && bar.lo > 0.0 {
        (bar.lo * bar.hi).sqrt()
    } else {
        0.5 * (bar.lo + bar.hi)
    };
    same_format(&[bar.lo, mid, bar.hi])
}

fn draw_legend(theme: &Theme, area: &Area<'_>, c: &CellChart) -> Result<()> {
    let text = font(theme, theme.tick)
        .into_font()
        .color(&rgb(Palette.color(Role::Ink)));
    let mut y = LEGEND_TOP;
    for (label, color, marker) in &c.legend {
        area.draw(&Rectangle::new(
            [(8, y), (26, y + 18)],
            rgb(*color).filled(),
        ))
        .map_err(plot_error)?;
        swatch_mark(theme, area, (17, y + 9), *color, *marker)?;
        area.draw(&Text::new(label.clone(), (32, y + 2), text.clone()))
            .map_err(plot_error)?;
        y += LEGEND_ROW;
    }
    if let Some(bar) = &c.shade {
        y += BAR_LABEL_GAP;
        area.draw(&Text::new(bar.label.clone(), (8, y), text.clone()))
            .map_err(plot_error)?;
        // The label's line, then half a tick label above the bar's top.
        y += BAR_LABEL_LINE;
        let steps = 32;
        let (h, w) = (BAR_HEIGHT, 18);
        for i in 0..steps {
            let f = i as f64 / (steps - 1) as f64;
            let y0 = y + h - (i + 1) * h / steps;
            let y1 = y + h - i * h / steps;
            area.draw(&Rectangle::new(
                [(8, y0), (8 + w, y1)],
                rgb(style::mix(bar.from, bar.to, f)).filled(),
            ))
            .map_err(plot_error)?;
        }
        // Ticks at the ends and the middle, their labels centred on them.
        let labels = bar_ticks(bar);
        for (k, label) in labels.into_iter().enumerate() {
            let ty = y + h - (k as i32) * h / 2;
            area.draw(&PathElement::new(
                vec![(8 + w, ty), (8 + w + 4, ty)],
                rgb(Palette.color(Role::Ink)).stroke_width(1),
            ))
            .map_err(plot_error)?;
            let anchored = text.clone().pos(plotters::style::text_anchor::Pos::new(
                plotters::style::text_anchor::HPos::Left,
                plotters::style::text_anchor::VPos::Center,
            ));
            area.draw(&Text::new(label, (8 + w + 7, ty), anchored))
                .map_err(plot_error)?;
        }
    }
    Ok(())
}

/// The legend under the cells: its entries side by side, wrapped into
/// rows of `width`, then the shade bar across, its label above and its
/// three tick labels under it. Sizes follow the tick text (`theme.tick`).
struct Below {
    /// Each entry's (x, row) and the number of rows.
    entries: Vec<(i32, i32)>,
    rows: i32,
    /// Height of a row of entries, and of the swatch.
    row_h: i32,
    swatch: i32,
    /// The shade bar's left end and length, and its height.
    bar: (i32, i32),
    bar_h: i32,
    /// Whether the bar's label stands left of the bar (else above it).
    label_beside: bool,
}

fn below_layout(theme: &Theme, c: &CellChart, width: u32) -> Below {
    let t = theme.tick;
    let (row_h, swatch, gap) = ((2.0 * t) as i32, (1.4 * t) as i32, (1.2 * t) as i32);
    let left = 8;
    let (mut x, mut row) = (left, 0);
    let mut entries = Vec::new();
    for (label, _, _) in &c.legend {
        let w = swatch + (0.5 * t) as i32 + style::text_width(theme.font(), label, t).ceil() as i32;
        if x > left && x + w > width as i32 - left {
            x = left;
            row += 1;
        }
        entries.push((x, row));
        x += w + gap;
    }
    let rows = if c.legend.is_empty() { 0 } else { row + 1 };
    // The bar inset by half its widest tick label at each end.
    let half_label = c
        .shade
        .as_ref()
        .map(|b| {
            same_format(&[b.lo, b.hi])
                .iter()
                .map(|l| style::text_width(theme.font(), l, t))
                .fold(0.0f32, f32::max)
        })
        .unwrap_or(0.0)
        .ceil() as i32
        / 2
        + 2;
    // The bar's label left of the bar when a bar of 4 em still fits
    // beside it, else on a line of its own above the bar.
    let label_w = c.shade.as_ref().map_or(0, |b| {
        style::text_width(theme.font(), &b.label, t).ceil() as i32
    });
    let room = width as i32 - 2 * left;
    let beside_at = label_w + gap + 2 * half_label;
    let label_beside = beside_at + (4.0 * t) as i32 <= room;
    let start = left + half_label + if label_beside { label_w + gap } else { 0 };
    let bar_len = (width as i32 - left - half_label - start).clamp(40, (16.0 * t) as i32);
    Below {
        entries,
        rows,
        row_h,
        swatch,
        bar: (start, bar_len),
        bar_h: (1.1 * t) as i32,
        label_beside,
    }
}

/// Height, pixels, of the legend under the cells.
fn legend_below_height(theme: &Theme, c: &CellChart, width: u32) -> u32 {
    let b = below_layout(theme, c, width);
    let t = theme.tick as i32;
    let bar = if c.shade.is_some() {
        // Label line (unless beside), bar, tick and tick label.
        let label = if b.label_beside { t / 2 } else { 2 * t };
        label + b.bar_h + 2 * t
    } else {
        0
    };
    (b.rows * b.row_h + bar + t / 2).max(0) as u32
}

fn draw_legend_below(theme: &Theme, area: &Area<'_>, c: &CellChart) -> Result<()> {
    let text = font(theme, theme.tick)
        .into_font()
        .color(&rgb(Palette.color(Role::Ink)));
    let b = below_layout(theme, c, area.dim_in_pixel().0);
    let t = theme.tick as i32;
    let left_middle = text.clone().pos(plotters::style::text_anchor::Pos::new(
        plotters::style::text_anchor::HPos::Left,
        plotters::style::text_anchor::VPos::Center,
    ));
    for ((label, color, marker), (x, row)) in c.legend.iter().zip(&b.entries) {
        let y = row * b.row_h + (b.row_h - b.swatch) / 2;
        area.draw(&Rectangle::new(
            [(*x, y), (x + b.swatch, y + b.swatch)],
            rgb(*color).filled(),
        ))
        .map_err(plot_error)?;
        let centre = (x + b.swatch / 2, y + b.swatch / 2);
        swatch_mark(theme, area, centre, *color, *marker)?;
        let at = (x + b.swatch + t / 2, y + b.swatch / 2);
        area.draw(&Text::new(label.clone(), at, left_middle.clone()))
            .map_err(plot_error)?;
    }
    if let Some(bar) = &c.shade {
        let (x0, len) = b.bar;
        let y = if b.label_beside {
            let y = b.rows * b.row_h + t / 2;
            let at = (8, y + b.bar_h / 2);
            area.draw(&Text::new(bar.label.clone(), at, left_middle.clone()))
                .map_err(plot_error)?;
            y
        } else {
            let y = b.rows * b.row_h + t;
            area.draw(&Text::new(bar.label.clone(), (x0, y), left_middle.clone()))
                .map_err(plot_error)?;
            y + t
        };
        let steps = 32;
        for i in 0..steps {
            let f = i as f64 / (steps - 1) as f64;
            let (a, z) = (x0 + i * len / steps, x0 + (i + 1) * len / steps);
            area.draw(&Rectangle::new(
                [(a, y), (z, y + b.bar_h)],
                rgb(style::mix(bar.from, bar.to, f)).filled(),
            ))
            .map_err(plot_error)?;
        }
        let labels = bar_ticks(bar);
        let ty = y + b.bar_h;
        for (k, label) in labels.into_iter().enumerate() {
            let tx = x0 + (k as i32) * len / 2;
            area.draw(&PathElement::new(
                vec![(tx, ty), (tx, ty + 4)],
                rgb(Palette.color(Role::Ink)).stroke_width(1),
            ))
            .map_err(plot_error)?;
            let anchored = text.clone().pos(plotters::style::text_anchor::Pos::new(
                plotters::style::text_anchor::HPos::Center,
                plotters::style::text_anchor::VPos::Top,
            ));
            area.draw(&Text::new(label, (tx, ty + 6), anchored))
                .map_err(plot_error)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The y axis's label (turned on its side) stays clear of its widest
    /// tick label, for short (0.005) and wide (4×10⁻⁴) ticks alike.
    #[test]
    fn the_y_label_clears_the_tick_labels() {
        for ys in [vec![0.005, 0.01, 0.02], vec![1e-4, 2e-4, 4e-4]] {
            let c = CellChart {
                title: None,
                x_label: "damping γ".into(),
                y_label: "gravity G = mg/(ks)".into(),
                xs: vec![0.01, 0.02],
                cells: (0..2)
                    .flat_map(|col| {
                        (0..3).map(move |row| Cell {
                            col,
                            row,
                            color: Palette.color(Role::Ink),
                            marker: Marker::None,
                        })
                    })
                    .collect(),
                ys,
                legend: vec![],
                shade: None,
                plot_x: None,
            };
            let theme = Theme::of(&Default::default());
            let chart = cell_chart(&theme, &c, 820, 480).unwrap();
            // The rotated label's right reach, and the left edge of each
            // tick label (anchored at its right end).
            let mut label_right = None;
            let mut ticks_left = f32::INFINITY;
            for t in chart.svg.split("<text").skip(1) {
                let attr = |name: &str| -> Option<f32> {
                    let i = t.find(&format!(" {name}=\""))? + name.len() + 3;
                    t[i..].split('"').next()?.parse().ok()
                };
                let body = t
                    .split('>')
                    .nth(1)
                    .unwrap_or("")
                    .split('<')
                    .next()
                    .unwrap_or("")
                    .trim();
                if t.contains("rotate(") && body.starts_with("gravity") {
                    // Turned a quarter left and moved 0.76 em down (to
                    // the right): its glyphs reach x + 1 em at most.
                    label_right = Some(attr("x").unwrap() + size::LABEL);
                } else if c.ys.iter().any(|&y| short_number(y) == body) {
                    let right = attr("x").unwrap();
                    ticks_left =
                        ticks_left.min(right - style::text_width(theme.font(), body, theme.tick));
                }
            }
            let label_right = label_right.expect("the y label is drawn");
            assert!(ticks_left.is_finite(), "tick labels found in {}", chart.svg);
            assert!(
                label_right <= ticks_left,
                "{:?}: label up to {label_right}, ticks from {ticks_left}",
                c.ys
            );
        }
    }

    #[test]
    fn ticks_land_on_cells() {
        assert_eq!(ticks(5, 10), 5);
        assert_eq!(ticks(31, 10), 8);
        assert_eq!(ticks(1, 10), 2);
    }
}
