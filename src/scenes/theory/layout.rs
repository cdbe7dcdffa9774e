//! The sizes and layout of the theory's chart figures at every style: a
//! chart's size on the page ([`fit`]), one column of panels on a narrow
//! page, charts grown into the page budget, panel titles.

use crate::error::Result;
use crate::render::charts::line_chart_growing;
use crate::render::compose::Panel;
use crate::render::style::size;
use crate::render::{ChartSpec, Picture, Theme};

/// A chart of a theory figure, `(w, h)` on the screen page ([`fit`]); a
/// legend under its plot makes it taller, up to its share of the page
/// budget (half on a narrow page, where panels stack two high).
pub(super) fn chart(theme: &Theme, spec: &ChartSpec, w: u32, h: u32) -> Result<Picture> {
    chart_taller(theme, spec, (w, h), 0)
}

/// A chart of a theory figure `(w, h)` pixels on the page as it is (no
/// [`fit`]), growing for a legend under its plot as [`chart`] does.
pub(super) fn chart_sized(theme: &Theme, spec: &ChartSpec, (w, h): (u32, u32)) -> Result<Picture> {
    let share = if narrow(theme) { 0.5 } else { 1.0 };
    let most = theme
        .style
        .fit_box()
        .map_or(u32::MAX, |(_, bh)| (share * bh) as u32);
    Ok(line_chart_growing(theme, spec, w, h, most)?.into())
}

/// [`chart`], `extra` pixels taller than it fits by default.
pub(super) fn chart_taller(
    theme: &Theme,
    spec: &ChartSpec,
    (w, h): (u32, u32),
    extra: u32,
) -> Result<Picture> {
    let (w, h) = fit(theme, (w, h));
    let h = h + extra;
    let share = if narrow(theme) { 0.5 } else { 1.0 };
    let most = theme
        .style
        .fit_box()
        .map_or(u32::MAX, |(_, bh)| (share * bh) as u32);
    Ok(line_chart_growing(theme, spec, w, h, most)?.into())
}

/// Panel `k` of a figure, holding a chart titled `title`: at a journal
/// style (no titles inside the figure, docs/formats.md) the title is the
/// panel's label instead, lettered, "(a) α = 15°"; elsewhere the chart
/// draws its own title.
pub(super) fn titled_panel(theme: &Theme, k: usize, title: &str, image: Picture) -> Panel {
    if theme.titles {
        Panel::new(image)
    } else {
        let letter = char::from(b'a' + (k % 26) as u8);
        Panel::new(image).label(format!("({letter}) {title}"))
    }
}

/// Width of a theory figure's page at the screen style, pixels.
pub(super) const FIGURE_WIDTH: u32 = 900;

/// The size of a chart that is `(w, h)` on the screen page, at the style
/// in force: unchanged at screen; at a narrow print page (one column of
/// panels, [`columns`]) the page's width less the margins, its height in
/// proportion; at a wide one the same share of the page as on screen.
pub(super) fn fit(theme: &Theme, (w, h): (u32, u32)) -> (u32, u32) {
    let style = theme.style;
    if !style.is_print() {
        return (w, h);
    }
    let page = page_width(theme, FIGURE_WIDTH) as f32;
    let f = if narrow(theme) {
        (page - 2.0 * size::MARGIN as f32 - 8.0) / w as f32
    } else {
        // The share of the page the panel has on screen, of the room the
        // margins and gaps leave.
        (page - 2.0 * (size::MARGIN + size::GAP) as f32) / FIGURE_WIDTH as f32
    };
    let s = |v: u32| ((v as f32 * f).round() as u32).max(60);
    if narrow(theme) {
        // Panels stack in one column: each no taller than NARROW_ASPECT of
        // its width, so that two stacked keep the page budget.
        let w = s(w);
        return (w, s(h).min((NARROW_ASPECT * w as f32) as u32));
    }
    // Side by side: no taller than the page budget less the margins.
    let tall = style.fit_box().map_or(u32::MAX, |(_, bh)| {
        (bh - 2.0 * size::MARGIN as f32 - 2.0 * size::LABEL) as u32
    });
    (s(w), s(h).min(tall))
}

/// Tallest a chart is, relative to its width, on a narrow page where
/// panels stack (two such and the margins fit 4.5 in at 3.375 in).
pub(super) const NARROW_ASPECT: f32 = 0.6;

/// The page's width in design pixels: `screen` at the screen style.
pub(super) fn page_width(theme: &Theme, screen: u32) -> u32 {
    theme.style.frame((screen, 1)).0
}

/// Whether the page is too narrow for panels side by side (`paper`).
pub(super) fn narrow(theme: &Theme) -> bool {
    theme.is_print() && page_width(theme, FIGURE_WIDTH) < 600
}

/// A figure of `rows` rows of charts drawn by `draw(extra)`, every chart
/// `extra` pixels taller than its default: on a narrow page the charts
/// grow into the page budget the default leaves (docs/formats.md: the
/// figure grows within the budget so that its plots keep half of it), by
/// at most `most` each; elsewhere, or when the grown figure would not fit,
/// as drawn by default.
pub(super) fn grown(
    theme: &Theme,
    rows: u32,
    most: u32,
    draw: impl Fn(u32) -> Result<Picture>,
) -> Result<Picture> {
    let first = draw(0)?;
    let Some((_, budget)) = theme.style.fit_box().filter(|_| narrow(theme)) else {
        return Ok(first);
    };
    // One pixel short of the budget: the page check allows no more.
    let room = budget - 1.0 - first.pixel_size().1 as f32;
    let extra = ((room / rows.max(1) as f32).floor().max(0.0) as u32).min(most);
    if extra == 0 {
        return Ok(first);
    }
    let tall = draw(extra)?;
    Ok(if tall.misfit(&theme.style).is_none() {
        tall
    } else {
        first
    })
}

/// Columns of a grid of panels: one on a narrow page, else `n`.
pub(super) fn columns(theme: &Theme, n: usize) -> usize {
    if narrow(theme) { 1 } else { n }
}

pub(super) fn pairs(points: &[[f64; 2]]) -> Vec<(f64, f64)> {
    points.iter().map(|p| (p[0], p[1])).collect()
}

/// Fig. 2c: U(θ) for each a/b of the scene at its b/s, the
/// minima at ±α (eq:eq_alpha, U_min = −2mgb), and ladders at both minima
/// `top` above `bottom`, centred, on white.
pub(super) fn stack(top: &Picture, bottom: &Picture) -> Picture {
    let (tw, th) = top.pixel_size();
    let (bw, bh) = bottom.pixel_size();
    let w = tw.max(bw);
    let mut out = Picture::new(top.theme(), w as f32, (th + bh) as f32);
    out.place(top, (((w - tw) / 2) as f32, 0.0));
    out.place(bottom, (((w - bw) / 2) as f32, th as f32));
    out
}
