//! A picture written as files: SVG (its `<text>` in the bundled font),
//! PNG and PDF, on the page of the picture's style, with the figure's
//! metadata. Apart from the picture model, so that the SVG backend and
//! the picture do not import each other.

use super::page_style::TextMode;
use super::picture::Picture;
use super::style;
use super::svg;
use crate::encode::{self, Format, Formats};
use crate::error::{Error, Result};

impl Picture {
    /// An SVG document of the picture, `scale` times the design size (text
    /// as `<text>` in the bundled font's family).
    pub fn to_svg(&self, scale: f32) -> Result<String> {
        svg::document(self, scale)
    }

    /// The bytes of the picture in each figure format of `formats`, in
    /// order, on the page of its theme's style: PNG
    /// at the style's resolution times `scale`; SVG and PDF vector, their
    /// page the style's width (the design size at 0.75 pt per pixel at
    /// `screen`), text as text or outlines as the style says.
    pub fn encode(&self, formats: &Formats, scale: f32) -> Result<Vec<Vec<u8>>> {
        let style = self.theme().style;
        self.check_print_scale(&style)?;
        let pt_per_px = style.pt_per_px(self.width());
        let real_text = style.text == TextMode::Text;
        let tree = if formats.any_vector() {
            Some(self.to_tree(1.0)?)
        } else {
            None
        };
        let title = self.title();
        let meta = |svg: Vec<u8>| svg::with_metadata(svg, title.as_deref());
        formats
            .as_slice()
            .iter()
            .map(|f| match (f, &tree) {
                (Format::Png, _) => encode::png_bytes_titled(
                    &self.rasterize(style.png_scale(self.width()) * scale)?,
                    title.as_deref(),
                ),
                (Format::Svg, Some(_)) if real_text => {
                    Ok(meta(svg::document_in_points(self, pt_per_px)?.into_bytes()))
                }
                // Outlines: a tree whose pixels are 1/96 in (0.75 pt).
                (Format::Svg, Some(t)) if pt_per_px == 0.75 => Ok(meta(encode::svg_bytes(t))),
                (Format::Svg, Some(_)) => {
                    Ok(meta(encode::svg_bytes(&self.to_tree(pt_per_px / 0.75)?)))
                }
                (Format::Pdf, Some(t)) => encode::pdf_bytes(
                    t,
                    encode::PdfOptions {
                        pt_per_px,
                        real_text,
                        title: title.clone(),
                    },
                ),
                _ => Err(Error::failed(format!("a figure cannot be written as {f}"))),
            })
            .collect()
    }

    /// The picture parsed as an SVG tree with the bundled font: the input
    /// of `encode::svg_bytes` and `encode::pdf_bytes`.
    pub fn to_tree(&self, scale: f32) -> Result<resvg::usvg::Tree> {
        let svg = self.to_svg(scale)?;
        resvg::usvg::Tree::from_str(&svg, &style::usvg_options(self.theme().font()))
            .map_err(|e| Error::failed(format!("internal SVG could not be parsed: {e}")))
    }
}
