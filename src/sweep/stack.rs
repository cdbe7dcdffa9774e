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

/// The least height of a panel whose y axis says `label`: room for the
/// rotated label along the plot, and at least [`LEAST_PANEL`] (less at a
/// print style).
pub(super) fn least_for(theme: &Theme, label: &str) -> u32 {
    // The rotated label's length, within the chart's own margins above
    // and below the plot, and a few pixels of air.
    let along =
        style::text_width(theme.font(), label, theme.label) + 2.0 * theme.chart_margin_y + 4.0;
    // At a print style six lines of tick text (90 px at `paper`): a plot
    // of two or three ticks, so that a stack of four keeps the budget.
    let least = if theme.is_print() {
        ((6.0 * theme.tick).ceil() as u32).min(LEAST_PANEL)
    } else {
        LEAST_PANEL
    };
    (along.ceil() as u32).max(least)
}

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
    // The page's height in the design pixels composed figures are laid
    // out in (a slide's twice its own, Style::fit_box).
    let Some((_, page)) = theme.style.fit_box() else {
        return wanted.to_vec();
    };
    let budget = page.floor();
    let saves = shared_saves(theme);
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

/// Panels of heights fitted to the page ([`fitted_heights`]), drawn by
/// `make` at those heights and at the width it is given, and stacked
/// ([`stack`]). Stacked panels share one x extent: when their plot areas
/// span differently across (a legend right of one plot, wider tick labels
/// left of another), they are drawn again with the plots' edges given,
/// the rightmost left edge and the leftmost right edge of them all
/// (`make`'s third argument), so that one x value is at one place down
/// the stack.
pub(super) fn stacked(
    theme: &Theme,
    wanted: &[u32],
    least: &[u32],
    make: impl Fn(&[u32], u32, Option<(i32, i32)>) -> Result<Vec<(Chart, u32)>>,
) -> Result<Chart> {
    let h = fitted_heights(theme, wanted, least);
    let indent = label_indent(theme, wanted.len());
    let w = width(theme) - indent;
    let mut panels = make(&h, w, None)?;
    if let Some(extent) = shared_extent(&panels) {
        panels = make(&h, w, Some(extent))?;
    }
    stack(theme, &panels, indent)
}

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
    let width = width(theme);
    let mut svg = format!(
        "<svg width=\"{width}\" height=\"{height}\" viewBox=\"0 0 {width} {height}\" \
         xmlns=\"http://www.w3.org/2000/svg\">\n<rect x=\"0\" y=\"0\" width=\"{width}\" \
         height=\"{height}\" fill=\"#ffffff\"/>\n"
    );
    let mut y = 0;
    let mut tops = Vec::new();
    for (chart, h) in panels {
        let inner = strip_prolog(&chart.svg);
        let placed = inner.replacen("<svg ", &format!("<svg x=\"{indent}\" y=\"{y}\" "), 1);
        svg.push_str(&placed);
        svg.push('\n');
        tops.push(y);
        y += h;
    }
    if labelled(theme, panels.len()) {
        let ascent = style::ascent(theme.font(), theme.panel_label);
        for (k, top) in tops.into_iter().enumerate() {
            svg.push_str(&format!(
                "<text x=\"0\" y=\"{}\" font-family=\"{}\" font-size=\"{}\" fill=\"{}\">{}</text>\n",
                top as f32 + ascent,
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
