//! Chart titles fitted to the chart's width: the title size when the title
//! fits on one line, else wrapped onto two lines, shrunk as far as needed.

use super::{Area, font, plot_error, rgb};
use crate::error::Result;
use crate::render::Theme;
use crate::render::page_style::FontChoice;
use crate::render::palette::{Palette, Role};
use crate::render::style::{self, size};
use plotters::prelude::*;

/// Space kept free left and right of a title, in pixels, at least: a
/// chart keeps its whole [`Theme::chart_margin`] free at its left (a
/// stack's panel labels sit there, `sweep::stack::label_indent`).
const SIDE: f32 = 8.0;

/// The smallest font size tried before a title is shrunk to fit as it is.
const MIN_SIZE: f32 = 10.0;

/// A title laid out for a width: its lines (top to bottom), font size and
/// font.
#[derive(Clone, Debug, PartialEq)]
pub struct FittedTitle {
    pub lines: Vec<String>,
    pub size: f32,
    pub font: FontChoice,
}

impl FittedTitle {
    /// Width in pixels of the widest line.
    pub fn width(&self) -> f32 {
        self.lines
            .iter()
            .map(|l| style::text_width(self.font, l, self.size))
            .fold(0.0, f32::max)
    }
}

/// Lays out `title` for a chart `width` pixels wide: on one line at
/// [`size::TITLE`] if it fits, else on at most two lines at the largest
/// size from `size::TITLE` down to the smallest the theme sets text at
/// that fits; then on as many lines as it takes at that size. A style
/// with a text size of its own (print, slide, a page of the user's)
/// never sets a title smaller than it (docs/formats.md: text never
/// shrinks to fit); on the screen's own pixels a title too wide even
/// then is split into two lines and shrunk until the wider one fits.
pub fn fit_title(theme: &Theme, title: &str, width: u32) -> FittedTitle {
    let font = theme.font();
    let room = (width as f32 - 2.0 * SIDE.max(theme.chart_margin)).max(1.0);
    let fits = |t: &FittedTitle| t.width() <= room;
    let one = FittedTitle {
        lines: vec![title.to_string()],
        size: size::TITLE,
        font,
    };
    if fits(&one) {
        return one;
    }
    let smallest = if theme.min_text > 0.0 {
        theme.min_text.min(size::TITLE)
    } else {
        MIN_SIZE
    };
    let mut size = size::TITLE;
    while size >= smallest {
        let t = FittedTitle {
            lines: style::wrap_text(font, title, room, size),
            size,
            font,
        };
        if t.lines.len() <= 2 && fits(&t) {
            return balanced(t, title, room);
        }
        size -= 0.5;
    }
    let wrapped = FittedTitle {
        lines: style::wrap_text(font, title, room, smallest),
        size: smallest,
        font,
    };
    if theme.min_text > 0.0 || (fits(&wrapped) && wrapped.lines.len() <= 2) {
        return wrapped;
    }
    shrunk_to(title, font, room)
}

/// `t` (a title on more than one line) wrapped again at the narrowest
/// room that keeps its number of lines, so that no line is a widow of a
/// word or two: found by bisection on the room, to a pixel.
fn balanced(t: FittedTitle, title: &str, room: f32) -> FittedTitle {
    if t.lines.len() < 2 {
        return t;
    }
    let lines = |r: f32| style::wrap_text(t.font, title, r, t.size);
    let (mut lo, mut hi) = (0.5 * room / t.lines.len() as f32, room);
    while hi - lo > 1.0 {
        let mid = 0.5 * (lo + hi);
        if lines(mid).len() <= t.lines.len() {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    FittedTitle {
        lines: lines(hi),
        ..t
    }
}

/// Two lines at [`MIN_SIZE`], as balanced as the words allow, shrunk until
/// the wider one fits `room` (the screen's own pixels only).
fn shrunk_to(title: &str, font: FontChoice, room: f32) -> FittedTitle {
    let mut wrap = 0.5 * style::text_width(font, title, MIN_SIZE);
    let mut t = FittedTitle {
        lines: style::wrap_text(font, title, wrap, MIN_SIZE),
        size: MIN_SIZE,
        font,
    };
    while t.lines.len() > 2 {
        wrap *= 1.05;
        t.lines = style::wrap_text(font, title, wrap, MIN_SIZE);
    }
    t.size *= room / t.width().max(1.0);
    // Text width is not exactly linear in size (hinting, rounding).
    while t.width() > room && t.size > 1.0 {
        t.size *= 0.98;
    }
    t
}

/// The area of `root` below `title` (if any, and if the style draws
/// titles: journal styles leave them to the caption) drawn centred on top
/// in [`fit_title`]'s lines for a chart `width` pixels wide.
pub(in crate::render) fn titled<'a>(
    theme: &Theme,
    root: Area<'a>,
    title: Option<&str>,
    width: u32,
) -> Result<Area<'a>> {
    let mut root = root;
    let title = title.filter(|_| theme.titles);
    if let Some(t) = title {
        let fitted = fit_title(theme, t, width);
        for line in &fitted.lines {
            root = root
                .titled(
                    line,
                    font(theme, fitted.size)
                        .into_font()
                        .color(&rgb(Palette.color(Role::Ink))),
                )
                .map_err(plot_error)?;
        }
    }
    Ok(root)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_short_title_keeps_its_size_and_line() {
        let t = fit_title(&Theme::of(&Default::default()), "kink, α = 60°", 360);
        assert_eq!(t.lines, vec!["kink, α = 60°".to_string()]);
        assert_eq!(t.size, size::TITLE);
    }

    /// At a slide a title wraps onto more lines rather than shrink below
    /// the slide's text size (it was set down to 10 px, 13 pt).
    #[test]
    fn a_slide_title_wraps_and_never_shrinks() {
        use crate::render::{Style, StyleName};
        let theme = Theme::of(&Style::named(StyleName::Slide));
        let title = "Movie 3: the kink of movie 4 in the frame moving with it: sin θₙ";
        for width in [200, 320, 480] {
            let t = fit_title(&theme, title, width);
            assert!(t.size >= theme.min_text, "{width}: {t:?}");
            assert!(t.width() <= width as f32 - 2.0 * SIDE, "{width}: {t:?}");
            assert_eq!(t.lines.join(" "), title, "{width}");
        }
    }

    #[test]
    fn a_long_title_fits_any_width() {
        let title = "Movie 3: the kink of movie 4 in the frame moving with it: sin θₙ";
        for width in [60, 100, 200, 320, 480, 640] {
            let t = fit_title(&Theme::of(&Default::default()), title, width);
            assert!(t.width() <= width as f32 - 2.0 * SIDE, "{width}: {t:?}");
            assert!(t.lines.len() <= 2, "{width}: {t:?}");
            assert_eq!(t.lines.join(" "), title, "{width}");
        }
    }

    /// A title on two lines keeps the chart's left margin free (a stack's
    /// panel labels sit there) and puts no word or two alone on its last
    /// line: the water-tank kymograph's title left "θₙ" alone.
    #[test]
    fn a_wrapped_title_keeps_the_margin_and_balances_its_lines() {
        let theme = Theme::of(&Default::default());
        let title = "Water tank: a kink, motor at 0.2 Hz, the closest level of model: sin θₙ";
        let t = fit_title(&theme, title, 640);
        assert_eq!(t.lines.len(), 2, "{t:?}");
        assert!(t.width() <= 640.0 - 2.0 * theme.chart_margin, "{t:?}");
        let w = |l: &str| style::text_width(t.font, l, t.size);
        assert!(w(&t.lines[1]) >= 0.5 * w(&t.lines[0]), "{t:?}");
        assert_eq!(t.lines.join(" "), title);
    }
}
