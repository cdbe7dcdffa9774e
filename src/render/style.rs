//! The text and colour helpers under the names the drawing code has
//! imported them by (`render::style::text_width`, `style::mix` …): each
//! lives in the module of its job, [`super::fonts`] (the bundled fonts),
//! [`super::typeset`] (markup, italics, measuring, wrapping),
//! [`super::raster_text`] (canvas text on a pixmap) and [`super::color`]
//! (blends, the diverging map). Colours are the palette's, by role
//! ([`super::Palette`], held by the theme): nothing here names one.

pub use super::color::{color, diverging, hex, mix};
pub use super::fonts::{
    FONT_BYTES, FONT_FAMILY, SERIF_BYTES, SERIF_FAMILY, SERIF_ITALIC_BYTES, face_of, family_of,
    font_bytes, font_of, fontdb, register_plotters_font, usvg_options,
};
pub use super::raster_text::{draw_text, white_pixmap};
pub use super::theme::{SCRIPT_SCALE, size};
pub use super::typeset::{
    HAlign, ITALIC_CORRECTION, Run, SUB_DROP, SUPER_RISE, Shift, VAlign, ascent, italic_chars,
    italic_correction, markup_html, markup_runs, plain_text, runs, scripts_as_markup, text_origin,
    text_width, typeset, wrap_text,
};

/// The colour of a chart's `k`-th series without another role
/// ([`super::palette::Role::Series`]), for the figures not yet drawn by
/// role (the experiment figures).
pub fn series_color(k: usize) -> crate::encode::Rgb {
    super::Palette.color(super::palette::Role::Series(k))
}
