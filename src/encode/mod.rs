//! Bytes from pictures. Knows nothing else of the project.
//!
//! Raster: PNG ([`png_bytes`]) and GIF ([`GifWriter`]) from
//! `tiny_skia::Pixmap`s, and MP4 (H.264, [`Mp4Writer`], cargo feature
//! `mp4`). Vector: SVG ([`svg_bytes`]) and PDF ([`pdf_bytes`]) from a parsed
//! SVG tree (`usvg::Tree`), the form in which the renderer hands over the
//! vector description of a picture. [`Format`] names the file formats and
//! checks what each can hold. Arrays: NumPy's `.npz` ([`npz`]), streamed.

mod crc;
mod format;
mod gif;
mod isobmff;
mod lzw;
mod movie;
#[cfg(feature = "mp4")]
mod mp4;
pub mod npz;
mod pdf;
mod pdf_font;
mod png;
mod svg;
mod yuv;

pub use format::{
    Format, FormatError, Formats, Kind, MP4_MAX, Mp4Quality, check_movie_fps, check_movie_frame,
    check_movie_size, parse_mixed,
};
pub use gif::{GIF_MAX_FPS, GIF_RAMP_STEPS, GifWriter, Palette, TRANSPARENT_INDEX};
pub use isobmff::{Mp4Track, annex_b_units, mp4_file};
pub use movie::MovieWriter;
#[cfg(feature = "mp4")]
pub use mp4::Mp4Writer;
pub use pdf::{PdfOptions, creator, pdf_bytes};
pub use png::{png_bytes, png_bytes_titled};
pub use svg::svg_bytes;
pub use yuv::{Yuv420, rgba_to_yuv420};

/// An sRGB colour without alpha.
pub type Rgb = [u8; 3];

/// White: the background every frame is drawn on and the GIF palette's
/// first entry (the colours of the scenes are the renderer's palette,
/// handed to the GIF writer as a [`Palette`]).
pub const WHITE: Rgb = [255, 255, 255];
