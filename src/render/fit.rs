//! The smallest page a figure fits at its style's text (docs/formats.md: a
//! size that cannot hold the figure is refused, naming the flag and the
//! smallest size that works). A layout moves with the page (a legend goes
//! below, panels re-grid), so the size one layout needs is not the size
//! the figure needs: it is found by drawing the figure again.

use super::charts::{ChartSpec, line_chart_growing};
use super::{PageSide, Picture, Style, Theme};
use crate::error::Result;

/// Hundredths of an inch (the unit a refusal names) in points.
const HUNDREDTH_PT: f32 = 0.72;
/// The largest size searched, in hundredths of an inch: 2000 pt.
const LARGEST: u32 = 2778;

/// `draw(theme)`, or when it does not fit its page at the style's text, a
/// refusal naming the smallest width or height (in hundredths of an inch)
/// at which `draw` fits: at that size the figure is drawn, and a hundredth
/// less is refused. `draw` is called again for each size tried (by
/// bisection), so it should not repeat costly work.
pub fn fitted<T>(
    theme: &Theme,
    draw: impl Fn(&Theme) -> Result<(Picture, T)>,
) -> Result<(Picture, T)> {
    let (picture, extra) = draw(theme)?;
    let style = theme.style;
    let Some((side, need)) = picture.misfit(&style) else {
        return Ok((picture, extra));
    };
    let at = |k: u32| {
        let pt = Some(k as f32 * HUNDREDTH_PT);
        match side {
            PageSide::Width => Style {
                width_pt: pt,
                ..style
            },
            PageSide::Height => Style {
                height_pt: pt,
                ..style
            },
        }
    };
    let fits = |k: u32| -> Result<bool> {
        let s = at(k);
        Ok(draw(&Theme::of(&s))?.0.misfit(&s).is_none())
    };
    let asked = match side {
        PageSide::Width => style.width_pt,
        PageSide::Height => style.max_height_pt(),
    }
    .unwrap_or(0.0);
    // `lo` does not fit (it is the size asked, or below); `hi` does.
    let mut lo = (asked / HUNDREDTH_PT).floor() as u32;
    let mut hi = ((need / HUNDREDTH_PT).round() as u32).max(lo + 1);
    while !fits(hi)? {
        if hi >= LARGEST {
            return Err(picture.refusal(&style, side, need));
        }
        lo = hi;
        hi = (hi * 2).min(LARGEST);
    }
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if fits(mid)? {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Err(picture.refusal(&style, side, hi as f32 * HUNDREDTH_PT))
}

/// A figure of one line chart, `spec`, `screen` pixels at the screen style
/// (the style's frame elsewhere), taller by its legend's band when the
/// legend goes under the plot (within the page), on the style's page and
/// titled `title`; refused as [`fitted`] says when no layout fits. Only
/// the chart is drawn again while the size is searched.
pub fn line_chart_figure(
    theme: &Theme,
    spec: &ChartSpec,
    screen: (u32, u32),
    title: &str,
) -> Result<Picture> {
    let (picture, ()) = fitted(theme, |t| {
        let (w, h) = t.style.frame(screen);
        let most = t.style.fit_box().map_or(u32::MAX, |(_, bh)| bh as u32);
        let chart = line_chart_growing(t, spec, w, h, most)?;
        Ok((Picture::from(chart).fit_page().titled(title), ()))
    })?;
    Ok(picture)
}
