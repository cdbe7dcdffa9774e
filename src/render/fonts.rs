//! The two bundled fonts (`assets/fonts/`): DejaVu Sans (screen and
//! slides) and Liberation Serif with its italic face (print), and where
//! each text path gets them: the font database resvg and usvg lay text out
//! with, plotters' registered families, and the faces `ab_glyph` draws
//! canvas text from (docs/formats.md "Fonts").

use super::page_style::FontChoice;
use ab_glyph::FontRef;
use std::sync::{Arc, Once, OnceLock};

/// The bundled sans-serif font file. The font files are statics, not
/// consts: a const is copied into each codegen unit that uses it, and the
/// release binary carried DejaVu Sans and Liberation Serif twice (1.15 MB).
pub static FONT_BYTES: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");
/// Its family name (as in the file; SVG text uses it).
pub const FONT_FAMILY: &str = "DejaVu Sans";
/// The bundled serif font file (SIL Open Font License 1.1).
pub static SERIF_BYTES: &[u8] = include_bytes!("../../assets/fonts/LiberationSerif-Regular.ttf");
/// Its family name (as in the file).
pub const SERIF_FAMILY: &str = "Liberation Serif";
/// The italic face of the serif font (same family and licence), for the
/// italic runs of print text ([`italic_chars`]).
pub static SERIF_ITALIC_BYTES: &[u8] =
    include_bytes!("../../assets/fonts/LiberationSerif-Italic.ttf");

/// The family name of `font`.
pub fn family_of(font: FontChoice) -> &'static str {
    match font {
        FontChoice::Sans => FONT_FAMILY,
        FontChoice::Serif => SERIF_FAMILY,
    }
}

/// The bytes of `font`'s file.
pub fn font_bytes(font: FontChoice) -> &'static [u8] {
    match font {
        FontChoice::Sans => FONT_BYTES,
        FontChoice::Serif => SERIF_BYTES,
    }
}

/// The font database for resvg: the bundled fonts only, loaded once.
pub fn fontdb() -> Arc<resvg::usvg::fontdb::Database> {
    static DB: OnceLock<Arc<resvg::usvg::fontdb::Database>> = OnceLock::new();
    DB.get_or_init(|| {
        let mut db = resvg::usvg::fontdb::Database::new();
        db.load_font_data(FONT_BYTES.to_vec());
        db.load_font_data(SERIF_BYTES.to_vec());
        db.load_font_data(SERIF_ITALIC_BYTES.to_vec());
        db.set_sans_serif_family(FONT_FAMILY);
        db.set_serif_family(SERIF_FAMILY);
        Arc::new(db)
    })
    .clone()
}

/// usvg options that resolve every font to the bundled ones (`font`
/// where a text names none).
pub fn usvg_options(font: FontChoice) -> resvg::usvg::Options<'static> {
    resvg::usvg::Options {
        font_family: family_of(font).to_string(),
        fontdb: fontdb(),
        ..Default::default()
    }
}

/// Registers the bundled fonts with plotters under their family names
/// (and DejaVu Sans as "sans-serif"), once per process.
pub fn register_plotters_font() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        for (name, bytes) in [
            (FONT_FAMILY, FONT_BYTES),
            ("sans-serif", FONT_BYTES),
            (SERIF_FAMILY, SERIF_BYTES),
        ] {
            // The bytes are the bundled, valid fonts; a failure would only
            // make plotters fall back to its own layout estimate.
            let _ = plotters::style::register_font(name, plotters::style::FontStyle::Normal, bytes);
        }
    });
}

/// The bundled font of `choice` for canvas text, parsed once.
pub fn font_of(choice: FontChoice) -> Option<&'static FontRef<'static>> {
    face_of(choice, false)
}

/// The bundled face of `choice` for canvas text, italic or upright, parsed
/// once. Only the serif font has an italic face; the sans font's text is
/// all upright ([`super::typeset::typeset`] never marks it italic).
pub fn face_of(choice: FontChoice, italic: bool) -> Option<&'static FontRef<'static>> {
    static FONTS: OnceLock<[Option<FontRef<'static>>; 3]> = OnceLock::new();
    let fonts = FONTS.get_or_init(|| {
        [
            FontRef::try_from_slice(FONT_BYTES).ok(),
            FontRef::try_from_slice(SERIF_BYTES).ok(),
            FontRef::try_from_slice(SERIF_ITALIC_BYTES).ok(),
        ]
    });
    match (choice, italic) {
        (FontChoice::Serif, true) => fonts[2].as_ref(),
        _ => fonts[choice as usize].as_ref(),
    }
}
