//! The smallest page a figure fits at its style's text (docs/formats.md: a
//! size that cannot hold the figure is refused, naming the flag and the
//! smallest size that works). A layout moves with the page (a legend goes
//! below, panels re-grid), so the size one layout needs is not the size
//! the figure needs: it is found by drawing the figure again.

use super::charts::{ChartSpec, line_chart_growing};
use super::page_style::PT_PER_IN;
use super::{PageSide, Picture, Style, Theme};
use crate::error::{Error, Result};

/// Hundredths of an inch (the unit a refusal names) in points.
const HUNDREDTH_PT: f32 = 0.72;
/// The largest size searched, in hundredths of an inch: 2000 pt.
const LARGEST: u32 = 2778;

/// `draw(theme)`, or when it does not fit its page at the style's text, a
/// refusal naming the smallest width or height (in hundredths of an inch)
/// at which `draw` fits: at that size the figure is drawn, and a hundredth
/// less is refused. On a page of the user's (`--width`, `--height`) a
/// figure also does not fit when its layout is crowded there
/// ([`Picture::crowded`]: a text off the picture, texts overlapping, a
/// plot collapsed) or a chart of it cannot be drawn that small; the side
/// searched is then the one the user set. `draw` is called again for each
/// size tried (by bisection), so it should not repeat costly work.
pub fn fitted<T>(
    theme: &Theme,
    draw: impl Fn(&Theme) -> Result<(Picture, T)>,
) -> Result<(Picture, T)> {
    let style = theme.style;
    let first = draw(theme);
    let (side, need) = match &first {
        Ok((picture, _)) => match misfit(picture, &style) {
            None => return first,
            Some(m) => {
                if let Some(found) = packed(&style, m.0, &draw)? {
                    return Ok(found);
                }
                m
            }
        },
        // A chart asked smaller than it can be drawn on a page of the
        // user's ("chart size must be between 60x60 …"): searched too.
        Err(Error::BadInput(_)) if user_side(&style).is_some() => {
            let side = user_side(&style).unwrap_or(PageSide::Width);
            (side, 1.25 * asked(&style, side))
        }
        Err(_) => return first,
    };
    // The smallest size of the side that overflows; when no size of it
    // holds the figure (a wider page makes it taller than the height
    // asked), the smallest of the other side at the size asked.
    // The one side the user set is searched first where the other
    // overflows (`--height` given: the smallest height at the style's
    // width, before a wider page than the style's).
    let mine = match only_user_side(&style).filter(|&u| u != side) {
        Some(u) => smallest(&style, u, asked(&style, u) + HUNDREDTH_PT, &draw)?.map(|k| (u, k)),
        None => None,
    };
    let found = match mine {
        Some(found) => Some(found),
        None => match smallest(&style, side, need, &draw)? {
            Some(k) => Some((side, k)),
            None => {
                let other = match side {
                    PageSide::Width => PageSide::Height,
                    PageSide::Height => PageSide::Width,
                };
                let from = asked(&style, other) + HUNDREDTH_PT;
                smallest(&style, other, from, &draw)?.map(|k| (other, k))
            }
        },
    };
    let Some((side, hi)) = found else {
        // The user's two sizes together hold it at no size of either
        // alone: the style's own page, where it holds the figure.
        if user_side(&style).is_some() && own_page_fits(&style, &draw)? {
            return Err(both_sizes_refused(
                &style,
                first.as_ref().ok().map(|f| &f.0),
            ));
        }
        // Crowded at every size (or never drawn): what was drawn, or the
        // refusal of the page's own overflow.
        return match first {
            Ok((picture, extra)) => match picture.misfit(&style) {
                Some((side, need)) => Err(picture.refusal(&style, side, need)),
                None => Ok((picture, extra)),
            },
            Err(e) => Err(e),
        };
    };
    let picture = match first {
        Ok((p, _)) => p,
        Err(_) => draw(&Theme::of(&at(&style, side, hi)))?.0,
    };
    Err(picture.refusal(&style, side, hundredths_pt(hi)))
}

/// Whether `draw` fits the page of `style`'s named style (its own width
/// and height, the user's left out).
fn own_page_fits<T>(style: &Style, draw: &impl Fn(&Theme) -> Result<(Picture, T)>) -> Result<bool> {
    let named = Style::named(style.name);
    let own = Style {
        width_pt: named.width_pt,
        height_pt: named.height_pt,
        ..*style
    };
    match draw(&Theme::of(&own)) {
        Ok((p, _)) => match misfit(&p, &own) {
            None => Ok(true),
            Some((over, _)) => Ok(packed(&own, over, draw)?.is_some()),
        },
        Err(Error::BadInput(_)) => Ok(false),
        Err(e) => Err(e),
    }
}

/// The refusal of a page whose width and height, as the user set them,
/// hold the figure at no larger size of either alone, where the style's
/// own page does.
fn both_sizes_refused(style: &Style, picture: Option<&Picture>) -> Error {
    let inches = |pt: Option<f32>| {
        pt.map_or("its own".to_string(), |pt| {
            format!("{:.2}in", (pt / 72.0 * 100.0).round() / 100.0)
        })
    };
    let what = picture
        .and_then(|p| p.title())
        .filter(|t| !t.is_empty())
        .map_or("the figure".to_string(), |t| format!("\"{t}\""));
    Error::bad_input(format!(
        "--width {} with --height {}: no larger width or height alone holds {what} at {} pt \
         text (it would print its text smaller); --style {}'s own page holds it: give \
         neither --width nor --height",
        inches(style.width_pt),
        inches(style.height_pt),
        style.font_pt,
        style.name.name()
    ))
}

/// `style` with `side` set to `k` hundredths of an inch.
fn at(style: &Style, side: PageSide, k: u32) -> Style {
    let pt = Some(hundredths_pt(k));
    match side {
        PageSide::Width => Style {
            width_pt: pt,
            ..*style
        },
        PageSide::Height => Style {
            height_pt: pt,
            ..*style
        },
    }
}

/// The smallest size of `side`, in hundredths of an inch above the size
/// asked, at which `draw` fits (found by doubling from `need`, pt, then
/// bisection: that size fits and a hundredth less does not); `None` when
/// none up to [`LARGEST`] does.
fn smallest<T>(
    style: &Style,
    side: PageSide,
    need: f32,
    draw: &impl Fn(&Theme) -> Result<(Picture, T)>,
) -> Result<Option<u32>> {
    let fits = |k: u32| -> Result<bool> {
        let s = at(style, side, k);
        match draw(&Theme::of(&s)) {
            Ok((p, _)) => match misfit(&p, &s) {
                None => Ok(true),
                Some((over, _)) => Ok(packed(&s, over, draw)?.is_some()),
            },
            Err(Error::BadInput(_)) => Ok(false),
            Err(e) => Err(e),
        }
    };
    // `lo` does not fit (it is the size asked, or below); `hi` does.
    let mut lo = (asked(style, side) / HUNDREDTH_PT).floor() as u32;
    let mut hi = ((need / HUNDREDTH_PT).round() as u32).max(lo + 1);
    while !fits(hi)? {
        if hi >= LARGEST {
            return Ok(None);
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
    Ok(Some(hi))
}

/// `k` hundredths of an inch in points, exactly as `--width` reads the
/// size a refusal names ("6.36in"): a layout on a knife edge is searched at
/// the size the user will ask, not at one an ulp apart.
fn hundredths_pt(k: u32) -> f32 {
    let typed = format!("{}.{:02}", k / 100, k % 100);
    typed
        .parse::<f32>()
        .map_or(k as f32 * HUNDREDTH_PT, |v| v * PT_PER_IN)
}

/// Fractions of the page a figure that overflows it is laid out for
/// instead, largest first ([`packed`]).
const PACKED: [f32; 3] = [0.85, 0.7, 0.55];

/// A figure that overflows `side` of `style`'s page laid out for a page
/// [`PACKED`] times as long that way (its drawings and plots smaller, its
/// text the same size), the first that fits `style`'s page, if any: a
/// slide's composed figures fit the slide at 20 pt this way, where they
/// once set their text down to 10 pt. The figure is then put on
/// `style`'s page ([`repaged`]).
fn packed<T>(
    style: &Style,
    side: PageSide,
    draw: &impl Fn(&Theme) -> Result<(Picture, T)>,
) -> Result<Option<(Picture, T)>> {
    for f in PACKED {
        let s = match side {
            PageSide::Width => Style {
                width_pt: style.width_pt.map(|w| w * f),
                ..*style
            },
            PageSide::Height => Style {
                height_pt: style.max_height_pt().map(|h| h * f),
                ..*style
            },
        };
        match draw(&Theme::of(&s)) {
            // Its content fits the page asked: put on that page.
            Ok((p, extra)) if misfit(&p, style).is_none() => {
                return Ok(Some((repaged(&p, style), extra)));
            }
            Ok(_) | Err(Error::BadInput(_)) => {}
            Err(e) => return Err(e),
        }
    }
    Ok(None)
}

/// The content of `p`, laid out for a smaller page, on `style`'s page
/// (centred across, as every picture narrower than its page), at the
/// style's own scale.
fn repaged(p: &Picture, style: &Style) -> Picture {
    let theme = Theme::of(style);
    let (cw, ch) = p.content_size();
    let left = (0.5 * (p.width() - cw)).floor();
    let mut out = Picture::new(&theme, cw, ch);
    out.place(p, (-left, 0.0));
    let out = match p.title() {
        Some(t) => out.titled(t),
        None => out,
    };
    out.fit_page()
}

/// The side of the page and the size it needs when `picture` does not
/// fit `style`: its own overflow ([`Picture::misfit`]), or on a page of
/// the user's a crowded layout (a hundredth of an inch more than asked,
/// on the side the user set).
fn misfit(picture: &Picture, style: &Style) -> Option<(PageSide, f32)> {
    picture.misfit(style).or_else(|| {
        let set = user_side(style)?;
        let crowd = picture.crowded()?;
        // A text off the side of a page whose width the user set needs a
        // wider page; anything else a taller one, where the user set it.
        let side =
            if crowd == PageSide::Width && Style::named(style.name).width_pt != style.width_pt {
                PageSide::Width
            } else {
                set
            };
        Some((side, asked(style, side) + HUNDREDTH_PT))
    })
}

/// The side of the page the user set (`--height` before `--width`), if
/// either differs from the named style's.
fn user_side(style: &Style) -> Option<PageSide> {
    let named = Style::named(style.name);
    if style.height_pt != named.height_pt {
        Some(PageSide::Height)
    } else if style.width_pt != named.width_pt {
        Some(PageSide::Width)
    } else {
        None
    }
}

/// The side of the page the user set where they set only one.
fn only_user_side(style: &Style) -> Option<PageSide> {
    let named = Style::named(style.name);
    match (
        style.height_pt != named.height_pt,
        style.width_pt != named.width_pt,
    ) {
        (true, false) => Some(PageSide::Height),
        (false, true) => Some(PageSide::Width),
        _ => None,
    }
}

/// The size of `side` asked at `style`, pt (0 when it has none).
fn asked(style: &Style, side: PageSide) -> f32 {
    match side {
        PageSide::Width => style.width_pt,
        PageSide::Height => style.max_height_pt(),
    }
    .unwrap_or(0.0)
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
