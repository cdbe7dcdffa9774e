//! PNG bytes from a pixmap.

use crate::error::{Error, Result};
use tiny_skia::Pixmap;

/// PNG bytes of an opaque or translucent pixmap (alpha is demultiplied).
pub fn png_bytes(pixmap: &Pixmap) -> Result<Vec<u8>> {
    let (w, h) = (pixmap.width(), pixmap.height());
    let mut rgba = Vec::with_capacity((w * h * 4) as usize);
    for p in pixmap.pixels() {
        let c = p.demultiply();
        rgba.extend_from_slice(&[c.red(), c.green(), c.blue(), c.alpha()]);
    }
    let mut out = Vec::new();
    let encoder = image::codecs::png::PngEncoder::new(&mut out);
    image::ImageEncoder::write_image(encoder, &rgba, w, h, image::ExtendedColorType::Rgba8)
        .map_err(|e| Error::failed(format!("PNG encoding failed: {e}")))?;
    Ok(out)
}
