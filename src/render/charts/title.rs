//! Chart titles fitted to the chart's width: the title size when the title
//! fits on one line, else wrapped onto two lines, shrunk as far as needed.

use super::{Area, font, plot_error, rgb};
use crate::error::Result;
use crate::render::Theme;
use crate::render::page_style::FontChoice;
use crate::render::style::{self, DARK, size};
use plotters::prelude::*;

/// Space kept free left and right of a title, in pixels.
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
/// size from `size::TITLE` down to 10 px that fits; a title too wide even
/// then is split into two lines and shrunk until the wider one fits.
pub fn fit_title(theme: &Theme, title: &str, width: u32) -> FittedTitle {
    let font = theme.font();
    let room = (width as f32 - 2.0 * SIDE).max(1.0);
    let fits = |t: &FittedTitle| t.width() <= room;
    let one = FittedTitle {
        lines: vec![title.to_string()],
        size: size::TITLE,
        font,
    };
    if fits(&one) {
        return one;
    }
    let mut size = size::TITLE;
    while size >= MIN_SIZE {
        let t = FittedTitle {
            lines: style::wrap_text(font, title, room, size),
            size,
            font,
        };
        if t.lines.len() <= 2 && fits(&t) {
            return t;
        }
        size -= 0.5;
    }
    // Two lines at the smallest size, as balanced as the words allow, then
    // shrunk until the wider one fits.
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
    while !fits(&t) && t.size > 1.0 {
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
                .titled(line, font(theme, fitted.size).into_font().color(&rgb(DARK)))
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
}
