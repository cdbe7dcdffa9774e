//! A rendered chart and the SVG → pixmap path: parse with the bundled
//! font (`style::usvg_options`), rasterise with resvg onto white.

use super::svg_text::typeset_svg_text;
use crate::error::{Error, Result};
use crate::render::page_style::FontChoice;
use crate::render::style;
use crate::render::theme::Theme;
use std::sync::OnceLock;
use tiny_skia::Pixmap;

/// A rendered chart: the raster image and the SVG it came from.
pub struct Chart {
    pub pixmap: Pixmap,
    pub svg: String,
    /// The theme it was drawn with (its font parses the SVG).
    pub theme: Theme,
    /// Where its plot area spans across, pixels from its left edge (left,
    /// right): set by the charts that have one axis of numbers across, so
    /// that stacked panels can share one x extent.
    pub plot_x: Option<(i32, i32)>,
    /// Where its plot area spans down, pixels from its top (top, bottom),
    /// where the chart has one.
    pub plot_y: Option<(i32, i32)>,
    /// The SVG parsed with the bundled font (for drawing at other scales).
    tree: OnceLock<Option<resvg::usvg::Tree>>,
}

impl Chart {
    /// A chart already rasterised (`pixmap`) from its `svg`.
    pub fn new(theme: &Theme, pixmap: Pixmap, svg: String) -> Chart {
        Chart {
            pixmap,
            svg,
            theme: *theme,
            plot_x: None,
            plot_y: None,
            tree: OnceLock::new(),
        }
    }

    /// A chart from its SVG (text markup of [`style::runs`] typeset),
    /// rasterised at `width × height` onto white.
    pub fn from_svg(theme: &Theme, svg: &str, width: u32, height: u32) -> Result<Chart> {
        let svg = typeset_svg_text(theme, svg);
        let tree = parse_svg(theme.font(), &svg)?;
        let pixmap = rasterize_tree(&tree, width, height)?;
        Ok(Chart {
            pixmap,
            svg,
            theme: *theme,
            plot_x: None,
            plot_y: None,
            tree: OnceLock::from(Some(tree)),
        })
    }

    /// The parsed SVG (`None` only if it cannot be parsed).
    pub fn tree(&self) -> Option<&resvg::usvg::Tree> {
        self.tree
            .get_or_init(|| parse_svg(self.theme.font(), &self.svg).ok())
            .as_ref()
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

pub(super) fn parse_svg(font: FontChoice, svg: &str) -> Result<resvg::usvg::Tree> {
    resvg::usvg::Tree::from_str(svg, &style::usvg_options(font))
        .map_err(|e| Error::failed(format!("internal SVG could not be parsed: {e}")))
}

/// Rasterises a parsed SVG onto a white `width × height` pixmap (scaled
/// to fit).
pub fn rasterize_tree(tree: &resvg::usvg::Tree, width: u32, height: u32) -> Result<Pixmap> {
    let mut pixmap = style::white_pixmap(width, height)
        .ok_or_else(|| crate::render::snapshot::bad_size(width, height))?;
    let s = tree.size();
    let t = tiny_skia::Transform::from_scale(width as f32 / s.width(), height as f32 / s.height());
    resvg::render(tree, t, &mut pixmap.as_mut());
    Ok(pixmap)
}

/// Rasterises an SVG string with the bundled `font` onto a white
/// `width × height` pixmap (the SVG is scaled to fit).
pub fn rasterize_svg(font: FontChoice, svg: &str, width: u32, height: u32) -> Result<Pixmap> {
    rasterize_tree(&parse_svg(font, svg)?, width, height)
}
