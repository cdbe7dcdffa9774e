//! PNG bytes from a pixmap, with the figure's metadata as `tEXt` chunks
//! (`Title`, `Software`: the program, version and commit).

use crate::error::{Error, Result};
use tiny_skia::Pixmap;

/// PNG bytes of an opaque or translucent pixmap (alpha is demultiplied),
/// with a `Software` text chunk naming the program that made it.
pub fn png_bytes(pixmap: &Pixmap) -> Result<Vec<u8>> {
    png_bytes_titled(pixmap, None)
}

/// [`png_bytes`] with a `Title` text chunk too, when `title` is given and
/// not empty.
pub fn png_bytes_titled(pixmap: &Pixmap, title: Option<&str>) -> Result<Vec<u8>> {
    let (w, h) = (pixmap.width(), pixmap.height());
    let mut rgba = Vec::with_capacity((w * h * 4) as usize);
    for p in pixmap.pixels() {
        let c = p.demultiply();
        rgba.extend_from_slice(&[c.red(), c.green(), c.blue(), c.alpha()]);
    }
    let out = encode_rgba8(&rgba, w, h)
        .map_err(|e| Error::failed(format!("PNG encoding failed: {e}")))?;
    let mut chunks = Vec::new();
    if let Some(t) = title.filter(|t| !t.is_empty()) {
        chunks.extend(text_chunk("Title", t));
    }
    chunks.extend(text_chunk("Software", &super::pdf::creator()));
    Ok(with_chunks_after_header(out, &chunks))
}

/// PNG bytes of straight 8-bit RGBA pixels, row by row: the `png` crate's
/// encoder with fast deflate and the adaptive filter (each row the filter
/// that makes it smallest).
fn encode_rgba8(rgba: &[u8], w: u32, h: u32) -> std::result::Result<Vec<u8>, png::EncodingError> {
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, w, h);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::Fast);
    encoder.set_filter(png::Filter::Adaptive);
    let mut writer = encoder.write_header()?;
    writer.write_image_data(rgba)?;
    writer.finish()?;
    Ok(out)
}

/// The 8-byte PNG signature and the IHDR chunk (4 length + 4 type + 13
/// data + 4 CRC): text chunks go right after it.
const HEADER_END: usize = 8 + 4 + 4 + 13 + 4;

fn with_chunks_after_header(png: Vec<u8>, chunks: &[u8]) -> Vec<u8> {
    if png.len() < HEADER_END || &png[12..16] != b"IHDR" {
        return png;
    }
    let mut out = Vec::with_capacity(png.len() + chunks.len());
    out.extend_from_slice(&png[..HEADER_END]);
    out.extend_from_slice(chunks);
    out.extend_from_slice(&png[HEADER_END..]);
    out
}

/// A text chunk: `tEXt` (keyword, NUL, Latin-1 text) when the text is
/// Latin-1, else `iTXt` (UTF-8), as titles with α, τ or ω need.
fn text_chunk(key: &str, text: &str) -> Vec<u8> {
    let latin1 = text.chars().all(|c| (c as u32) < 256 && c != '\0');
    let (kind, data): (&[u8; 4], Vec<u8>) = if latin1 {
        let mut d = key.as_bytes().to_vec();
        d.push(0);
        d.extend(text.chars().map(|c| c as u8));
        (b"tEXt", d)
    } else {
        // iTXt: keyword, NUL, compression flag 0, method 0, empty language
        // tag, NUL, empty translated keyword, NUL, UTF-8 text.
        let mut d = key.as_bytes().to_vec();
        d.extend_from_slice(&[0, 0, 0, 0, 0]);
        d.extend_from_slice(text.replace('\0', "").as_bytes());
        (b"iTXt", d)
    };
    let mut chunk = Vec::with_capacity(data.len() + 12);
    chunk.extend_from_slice(&(data.len() as u32).to_be_bytes());
    chunk.extend_from_slice(kind);
    chunk.extend_from_slice(&data);
    let crc = crc32(&chunk[4..]);
    chunk.extend_from_slice(&crc.to_be_bytes());
    chunk
}

/// CRC-32 (ISO 3309, as PNG chunks use it).
fn crc32(bytes: &[u8]) -> u32 {
    super::crc::Crc32::of(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crc_of_iend_is_the_known_one() {
        // Every PNG ends with IEND and this CRC.
        assert_eq!(crc32(b"IEND"), 0xae42_6082);
    }

    /// The chunks of a PNG file: (type, data), each CRC checked.
    fn chunks(png: &[u8]) -> Vec<([u8; 4], Vec<u8>)> {
        let mut out = Vec::new();
        let mut i = 8;
        while i + 12 <= png.len() {
            let n = u32::from_be_bytes(png[i..i + 4].try_into().unwrap()) as usize;
            let kind: [u8; 4] = png[i + 4..i + 8].try_into().unwrap();
            let data = png[i + 8..i + 8 + n].to_vec();
            let crc = u32::from_be_bytes(png[i + 8 + n..i + 12 + n].try_into().unwrap());
            assert_eq!(crc, crc32(&png[i + 4..i + 8 + n]), "{kind:?}");
            out.push((kind, data));
            i += 12 + n;
        }
        out
    }

    #[test]
    fn text_chunks_carry_title_and_program_and_the_image_still_decodes() {
        let p = tiny_skia::Pixmap::new(4, 3).unwrap();
        let bytes = png_bytes_titled(&p, Some("Kink, α = 60°")).unwrap();
        let decoder = png::Decoder::new(std::io::Cursor::new(&bytes));
        let info = decoder.read_info().unwrap().info().clone();
        assert_eq!((info.width, info.height), (4, 3));
        let c = chunks(&bytes);
        assert_eq!(&c[0].0, b"IHDR");
        assert_eq!(&c.last().unwrap().0, b"IEND");
        let title = c.iter().find(|(k, _)| k == b"iTXt").unwrap();
        assert_eq!(title.1, "Title\0\0\0\0\0Kink, α = 60°".as_bytes());
        let software = c.iter().find(|(k, _)| k == b"tEXt").unwrap();
        let text = format!("Software\0{}", crate::encode::pdf::creator());
        assert_eq!(software.1, text.as_bytes());
        assert!(text.contains(crate::version::VERSION));
        // Without a title: only the program.
        let plain = png_bytes(&p).unwrap();
        assert_eq!(
            chunks(&plain).iter().filter(|(k, _)| k == b"iTXt").count(),
            0
        );
    }
}
