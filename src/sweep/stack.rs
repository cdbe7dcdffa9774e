//! Sweep panels stacked into one chart (docs/sweeps.md and docs/formats.md): their
//! heights fitted to the page budget, none below what its rotated y label
//! needs, drawn at the sweep chart's width, and at a print style lettered
//! (a), (b), … in a column of their own at the left.

use crate::error::Result;
use crate::render::Theme;
use crate::render::charts::{Chart, rasterize_svg};
use crate::render::palette::{Palette, Role};
use crate::render::style;

/// Width of a sweep chart at the screen style, pixels.
pub const WIDTH: u32 = 820;

/// Width of a sweep chart at `theme`'s style (the page's design width at
/// a print style).
pub(super) fn width(theme: &Theme) -> u32 {
    theme.style.frame((WIDTH, 1)).0
}

/// The least height of a stacked panel, pixels (a chart's smallest).
pub(super) const LEAST_PANEL: u32 = 110;

/// The least height of a panel whose y axis says `label` and whose
/// shared x axis is numbered: room for the rotated label, centred on the
/// plot, inside the panel, and at least [`LEAST_PANEL`] (less at a print
/// style).
pub(super) fn least_for(theme: &Theme, label: &str) -> u32 {
    // The label is centred on the plot, which the chart's equal margins
    // above and below and the x axis' numbers under it leave: its top is
    // (height − numbers − label) / 2 below the panel's top, its bottom
    // above the panel's foot. A few pixels of air at its ends.
    let along = style::text_width(theme.font(), label, theme.label)
        + theme.numbered_x_area as f32
        + 2.0 * LABEL_AIR;
    // At a print style six lines of tick text (90 px at `paper`): a plot
    // of two or three ticks, so that a stack of four keeps the budget.
    let least = if theme.is_print() {
        ((6.0 * theme.tick).ceil() as u32).min(LEAST_PANEL)
    } else {
        LEAST_PANEL
    };
    (along.ceil() as u32).max(least)
}

/// Pixels kept between a rotated y label's ends and its panel's edges.
const LABEL_AIR: f32 = 0.0;

/// Pixels a panel whose x axis is shared (labelled below) does not need:
/// the axis label's line under its numbers.
fn shared_saves(theme: &Theme) -> u32 {
    theme.x_label_area.saturating_sub(theme.numbered_x_area)
}

/// Heights of stacked panels that want `wanted` pixels each: as asked at
/// screen; at a print style scaled down together, if need be, so that the
/// stack keeps the page budget ([`crate::render::Theme::max_height_pt`]),
/// none below its `least`.
fn fitted_heights(theme: &Theme, wanted: &[u32], least: &[u32]) -> Vec<u32> {
    fitted_saving(theme, wanted, least, shared_saves(theme))
}

/// [`fitted_heights`] of panels that each give up `saves` pixels of the
/// last one's x label area (the panels above it share its axis).
fn fitted_saving(theme: &Theme, wanted: &[u32], least: &[u32], saves: u32) -> Vec<u32> {
    // The page's height in the design pixels composed figures are laid
    // out in (Style::fit_box).
    let Some((_, page)) = theme.style.fit_box() else {
        return wanted.to_vec();
    };
    let budget = page.floor();
    // Panels above the last share its axis and give up their label area.
    let last = wanted.len().saturating_sub(1);
    let wanted: Vec<u32> = wanted
        .iter()
        .enumerate()
        .map(|(k, h)| {
            if k < last {
                h.saturating_sub(saves)
            } else {
                *h
            }
        })
        .collect();
    let sum: u32 = wanted.iter().sum();
    if sum as f32 <= budget {
        return wanted;
    }
    // The last panel keeps its axis' label area whole; none goes below
    // `least` (then the stack is taller than the page, and the figure is
    // refused naming the height that holds it: the same heights again).
    let keep = |k: usize| if k == last { saves } else { 0 };
    let at = |f: f32| -> Vec<u32> {
        wanted
            .iter()
            .enumerate()
            .map(|(k, h)| (((*h - keep(k)) as f32 * f).floor() as u32).max(least[k]) + keep(k))
            .collect()
    };
    // The largest common factor whose heights (each at least `least`)
    // keep the budget; at the smallest the heights no longer change, so a
    // page as tall as they need holds them.
    let mut f = (budget - saves as f32) / (sum - saves) as f32;
    while f > 0.01 && at(f).iter().sum::<u32>() as f32 > budget {
        f *= 0.97;
    }
    at(f)
}

/// One panel's place in a stack: its height and width, pixels, the x
/// edges of its plot (shared with the panels of its column; `None`: its
/// own), its column (0 at the left), whether it is the last of its
/// column, which labels the x axis the panels above it share, and
/// whether a shared x axis keeps its numbers (else its ticks only: the
/// right column of [`two_columns`] where numbers would not fit).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Slot {
    pub h: u32,
    pub w: u32,
    pub plot_x: Option<(i32, i32)>,
    pub column: usize,
    pub last: bool,
    pub numbers: bool,
}

/// What a stack's caller draws: each panel at its [`Slot`].
pub(super) type Make<'a> = dyn Fn(&[Slot]) -> Result<Vec<(Chart, u32)>> + 'a;

/// Panels of heights fitted to the page ([`fitted_heights`]), drawn by
/// `make` at their [`Slot`]s, and stacked ([`stack`]); `least(k, w)` is
/// the least height of panel `k` drawn `w` wide. Stacked panels share one
/// x extent: when their plot areas span differently across (a legend
/// right of one plot, wider tick labels left of another), they are drawn
/// again with the plots' edges given, the rightmost left edge and the
/// leftmost right edge of them all, so that one x value is at one place
/// down the stack. On a wide page too short for the stack (a slide at its
/// 20 pt text) and where the caller allows it (`columns`), the first
/// panel goes left and the others are stacked right of it
/// ([`two_columns`]).
pub(super) fn stacked(
    theme: &Theme,
    wanted: &[u32],
    least: &dyn Fn(usize, u32) -> u32,
    columns: bool,
    make: &Make<'_>,
) -> Result<Chart> {
    let full = width(theme);
    let least_full: Vec<u32> = (0..wanted.len()).map(|k| least(k, full)).collect();
    let h = fitted_heights(theme, wanted, &least_full);
    if columns && let Some(chart) = two_columns(theme, wanted, least, h.iter().sum(), make)? {
        return Ok(chart);
    }
    let indent = label_indent(theme, wanted.len());
    let w = full - indent;
    let last = h.len().saturating_sub(1);
    let slots = |plot_x| -> Vec<Slot> {
        h.iter()
            .enumerate()
            .map(|(k, &h)| Slot {
                h,
                w,
                plot_x,
                column: 0,
                last: k == last,
                numbers: true,
            })
            .collect()
    };
    let mut panels = make(&slots(None))?;
    if let Some(extent) = shared_extent(&panels) {
        panels = make(&slots(Some(extent)))?;
    }
    stack(theme, &panels, indent)
}

/// The share of the page's width the first panel takes when the panels
/// go in two columns.
const LEFT_SHARE: f32 = 0.6;

/// Two columns of panels, on a page ([`crate::render::Style::fit_box`]) at least
/// [`WIDE_PAGE`] times as wide as tall whose budget one column of
/// `stack_height` pixels overruns: the first panel at the left, as tall
/// as the page, the others stacked at the right, sharing one x extent
/// among them; each column's last panel labels its x axis, and the
/// panels above it in the right column keep their numbers where the
/// column then fits the page, else their ticks only ([`right_column`]).
/// `None` where one column fits, the page is not wide, or two columns
/// would be no shorter than one (then one column is refused naming the
/// height that holds it, and the height it names holds it).
fn two_columns(
    theme: &Theme,
    wanted: &[u32],
    least: &dyn Fn(usize, u32) -> u32,
    stack_height: u32,
    make: &Make<'_>,
) -> Result<Option<Chart>> {
    let Some((page_w, page_h)) = theme.style.fit_box() else {
        return Ok(None);
    };
    let budget = page_h.floor();
    let n = wanted.len();
    // One column that the page holds (to its slack: the picture is not
    // refused) stays one column.
    let holds = stack_height as f32 <= page_h * crate::render::picture::PRINT_SLACK;
    if n < 2 || holds || page_w < WIDE_PAGE * page_h {
        return Ok(None);
    }
    let indent = label_indent(theme, n);
    let full = width(theme);
    let left = (LEFT_SHARE * full as f32).round() as u32;
    let columns = [(0, left), (left, full - left)];
    let h0 = fitted_heights(theme, &[wanted[0].max(budget as u32)], &[least(0, left)]);
    let least_right: Vec<u32> = (1..n).map(|k| least(k, full - left)).collect();
    let (mut h1, numbers) = right_column(theme, &wanted[1..], &least_right);
    let tallest = h0[0].max(h1.iter().sum());
    if tallest as f32 > budget && tallest >= stack_height {
        return Ok(None);
    }
    // The right column as tall as the left, its panels grown alike.
    let right: u32 = h1.iter().sum();
    if right < h0[0] {
        let grow = h0[0] as f32 / right as f32;
        h1.iter_mut()
            .for_each(|h| *h = (*h as f32 * grow).floor() as u32);
        let short = h0[0] - h1.iter().sum::<u32>();
        if let Some(last) = h1.last_mut() {
            *last += short;
        }
    }
    let slot = |k: usize, h: u32, plot_x| {
        let column = usize::from(k > 0);
        Slot {
            h,
            w: columns[column].1 - indent,
            plot_x,
            column,
            last: k == 0 || k == n - 1,
            numbers: k == 0 || numbers,
        }
    };
    let heights: Vec<u32> = h0.iter().chain(&h1).copied().collect();
    let slots = |right: Option<(i32, i32)>| -> Vec<Slot> {
        let at = |k: usize| if k == 0 { None } else { right };
        (0..n).map(|k| slot(k, heights[k], at(k))).collect()
    };
    let mut panels = make(&slots(None))?;
    if let Some(extent) = shared_extent(&panels[1..]) {
        panels = make(&slots(Some(extent)))?;
    }
    let mut placed = Vec::with_capacity(n);
    let mut y = 0;
    for (k, (chart, h)) in panels.iter().enumerate() {
        let x = columns[usize::from(k > 0)].0;
        if k == 1 {
            y = 0;
        }
        placed.push((chart, (x, y)));
        y += h;
    }
    let height = h0[0].max(h1.iter().sum());
    compose(theme, &placed, indent, (full, height)).map(Some)
}

/// The heights of the right column's panels, which want `wanted` pixels
/// and need `least` each with their shared x axes numbered, and whether
/// those axes keep their numbers: they do where the column then fits the
/// page; else the panels above the last draw their ticks only (the last
/// panel's numbers read for them all, one x extent down the column),
/// each giving up the numbers' line.
fn right_column(theme: &Theme, wanted: &[u32], least: &[u32]) -> (Vec<u32>, bool) {
    let numbered = fitted_heights(theme, wanted, least);
    let budget = theme
        .style
        .fit_box()
        .map_or(f32::INFINITY, |(_, h)| h.floor());
    if numbered.iter().sum::<u32>() as f32 <= budget {
        return (numbered, true);
    }
    // The numbers' line each panel above the last gives up; the last
    // keeps its axis' label area whole (`fitted_saving` adds back what
    // the panels above it save).
    let line = theme.numbered_x_area.saturating_sub(theme.shared_x_area);
    let bare: Vec<u32> = least.iter().map(|l| l.saturating_sub(line)).collect();
    let saves = theme.x_label_area.saturating_sub(theme.shared_x_area);
    (fitted_saving(theme, wanted, &bare, saves), false)
}

/// A page at least this many times as wide as tall takes a stack too
/// tall for it in two columns ([`two_columns`]): a slide (16:9).
const WIDE_PAGE: f32 = 1.5;

/// The one x extent of stacked panels whose plots span differently across
/// (the rightmost left edge, the leftmost right edge), or `None` when they
/// already share one.
pub(super) fn shared_extent(panels: &[(Chart, u32)]) -> Option<(i32, i32)> {
    let spans: Vec<(i32, i32)> = panels.iter().filter_map(|(c, _)| c.plot_x).collect();
    let left = spans.iter().map(|s| s.0).max()?;
    let right = spans.iter().map(|s| s.1).min()?;
    spans
        .iter()
        .any(|s| *s != (left, right))
        .then_some((left, right))
}

/// Whether a stack of `n` panels labels them: at a print style, where the
/// caption names the panels by letter (the screen names them by their
/// titles and axes), and when there are two or more.
fn labelled(theme: &Theme, n: usize) -> bool {
    theme.is_print() && n > 1
}

/// The label of the `k`-th stacked panel: "(a)", "(b)", …
pub fn panel_label(k: usize) -> String {
    format!("({})", char::from(b'a' + (k % 26) as u8))
}

/// How far a stack of `n` panels is moved right so that its labels have a
/// column of their own at the left: the widest label and
/// [`Theme::panel_label_clear`], less the blank margin each chart keeps
/// at its left ([`Theme::chart_margin`]). A label in its own column at
/// the top of its band overlaps no text, tick label or data of any panel,
/// at every panel height, and costs the plots only the indent's width.
fn label_indent(theme: &Theme, n: usize) -> u32 {
    if !labelled(theme, n) {
        return 0;
    }
    let widest = (0..n)
        .map(|k| style::text_width(theme.font(), &panel_label(k), theme.panel_label))
        .fold(0.0f32, f32::max);
    (widest + theme.panel_label_clear - theme.chart_margin)
        .ceil()
        .max(0.0) as u32
}

/// Panels stacked top to bottom into one SVG (nested `<svg>` elements),
/// `indent` pixels from the left, rasterised at their own size; when the
/// stack is [`labelled`], each panel's label at the top left of its band
/// (drawn after the panels, over their blank left margin).
pub(super) fn stack(theme: &Theme, panels: &[(Chart, u32)], indent: u32) -> Result<Chart> {
    let height: u32 = panels.iter().map(|(_, h)| *h).sum();
    let mut placed = Vec::with_capacity(panels.len());
    let mut y = 0;
    for (chart, h) in panels {
        placed.push((chart, (0, y)));
        y += h;
    }
    compose(theme, &placed, indent, (width(theme), height))
}

/// Panels, each at its (x, y), its chart `indent` pixels right of that,
/// in one SVG `size` pixels (nested `<svg>` elements), rasterised at its
/// own size; when [`labelled`], each panel's label at its top left.
fn compose(
    theme: &Theme,
    placed: &[(&Chart, (u32, u32))],
    indent: u32,
    (width, height): (u32, u32),
) -> Result<Chart> {
    let mut svg = format!(
        "<svg width=\"{width}\" height=\"{height}\" viewBox=\"0 0 {width} {height}\" \
         xmlns=\"http://www.w3.org/2000/svg\">\n<rect x=\"0\" y=\"0\" width=\"{width}\" \
         height=\"{height}\" fill=\"#ffffff\"/>\n"
    );
    for (chart, (x, y)) in placed {
        let inner = strip_prolog(&chart.svg);
        let at = format!("<svg x=\"{}\" y=\"{y}\" ", x + indent);
        svg.push_str(&inner.replacen("<svg ", &at, 1));
        svg.push('\n');
    }
    if labelled(theme, placed.len()) {
        let ascent = style::ascent(theme.font(), theme.panel_label);
        for (k, (_, (x, top))) in placed.iter().enumerate() {
            svg.push_str(&format!(
                "<text x=\"{x}\" y=\"{}\" font-family=\"{}\" font-size=\"{}\" fill=\"{}\">{}</text>\n",
                *top as f32 + ascent,
                style::family_of(theme.font()),
                theme.panel_label,
                style::hex(Palette.color(Role::Ink)),
                panel_label(k)
            ));
        }
    }
    svg.push_str("</svg>\n");
    let pixmap = rasterize_svg(theme.font(), &svg, width, height)?;
    Ok(Chart::new(theme, pixmap, svg))
}

fn strip_prolog(svg: &str) -> &str {
    match svg.find("<svg") {
        Some(i) => &svg[i..],
        None => svg,
    }
}
