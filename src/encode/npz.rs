//! NumPy's `.npz`, written by the program itself: a ZIP archive (stored,
//! no compression) of `.npy` arrays of little-endian f64 (`<f8`), one per
//! name, each streamed into the file as its values are produced, so that
//! no array is ever held in memory as bytes.
//!
//! The `.npy` format (version 1.0) is a magic string, a header length and a
//! Python dict literal `{'descr': '<f8', 'fortran_order': False, 'shape':
//! (R, C), }` padded with spaces to a multiple of 64 bytes, then the values
//! in C order. The ZIP is PKWARE's APPNOTE 6.3: a local file header before
//! each entry (its CRC-32 and sizes patched in once the entry is written,
//! which is why the writer needs [`Seek`]), the central directory and its
//! end record. Entries are limited to 4 GiB (no ZIP64): larger arrays are
//! refused with an error.

use std::io::{self, Seek, SeekFrom, Write};

pub use super::crc::Crc32;

/// The `.npy` header (version 1.0) of a C-order f64 array of `shape`,
/// padded so that the data starts at a multiple of 64 bytes.
pub fn npy_header(shape: &[usize]) -> Vec<u8> {
    npy_header_of("<f8", shape)
}

/// The `.npy` header (version 1.0) of a C-order array of dtype `descr`
/// (`<f8`, `<U12`) and `shape` (empty: a 0-d array).
fn npy_header_of(descr: &str, shape: &[usize]) -> Vec<u8> {
    let dims = match shape {
        [one] => format!("({one},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(|d| d.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
    };
    let mut dict = format!("{{'descr': '{descr}', 'fortran_order': False, 'shape': {dims}, }}");
    // magic (6) + version (2) + length (2) + dict + '\n'
    let unpadded = 10 + dict.len() + 1;
    dict.push_str(&" ".repeat(unpadded.next_multiple_of(64) - unpadded));
    dict.push('\n');
    let mut h = Vec::with_capacity(10 + dict.len());
    h.extend_from_slice(b"\x93NUMPY\x01\x00");
    h.extend_from_slice(&(dict.len() as u16).to_le_bytes());
    h.extend_from_slice(dict.as_bytes());
    h
}

/// One entry of the central directory.
struct Entry {
    name: String,
    crc: u32,
    size: u32,
    offset: u32,
}

/// Largest entry or archive offset without ZIP64.
const ZIP32_MAX: u64 = u32::MAX as u64;

/// A `.npz` being written into `w`: call [`NpzWriter::array`] once per
/// array, then [`NpzWriter::finish`].
pub struct NpzWriter<W: Write + Seek> {
    w: W,
    entries: Vec<Entry>,
    at: u64,
}

/// The values of one array, streamed: [`ArrayWriter::push`] each value in
/// C order (row after row).
pub struct ArrayWriter<'a, W: Write> {
    w: &'a mut W,
    crc: Crc32,
    values: u64,
    buf: Vec<u8>,
}

impl<W: Write> ArrayWriter<'_, W> {
    /// Appends one value.
    pub fn push(&mut self, v: f64) -> io::Result<()> {
        self.buf.extend_from_slice(&v.to_le_bytes());
        self.values += 1;
        if self.buf.len() >= 1 << 16 {
            self.flush_buf()?;
        }
        Ok(())
    }

    fn flush_buf(&mut self) -> io::Result<()> {
        self.crc.update(&self.buf);
        self.w.write_all(&self.buf)?;
        self.buf.clear();
        Ok(())
    }
}

fn invalid(msg: String) -> io::Error {
    io::Error::new(io::ErrorKind::InvalidInput, msg)
}

impl<W: Write + Seek> NpzWriter<W> {
    pub fn new(w: W) -> Self {
        Self {
            w,
            entries: Vec::new(),
            at: 0,
        }
    }

    /// Writes the array `name` (stored as `name.npy`) of `shape`; `fill`
    /// pushes exactly `shape`'s product of values.
    pub fn array<F>(&mut self, name: &str, shape: &[usize], fill: F) -> io::Result<()>
    where
        F: FnOnce(&mut ArrayWriter<'_, W>) -> io::Result<()>,
    {
        let count: u64 = shape.iter().map(|&d| d as u64).product();
        let header = npy_header(shape);
        let size = header.len() as u64 + 8 * count;
        let file = format!("{name}.npy");
        if size > ZIP32_MAX || self.at > ZIP32_MAX {
            return Err(invalid(format!(
                "the array {name} ({size} bytes) would make the .npz larger than 4 GiB"
            )));
        }
        let offset = self.at;
        // The local header, CRC patched below.
        let local = local_header(&file, 0, size as u32);
        self.w.write_all(&local)?;
        let mut array = ArrayWriter {
            w: &mut self.w,
            crc: Crc32::new(),
            values: 0,
            buf: Vec::with_capacity(1 << 16),
        };
        array.crc.update(&header);
        array.w.write_all(&header)?;
        fill(&mut array)?;
        array.flush_buf()?;
        if array.values != count {
            return Err(invalid(format!(
                "the array {name} got {} values for shape {shape:?}",
                array.values
            )));
        }
        let crc = array.crc.value();
        let end = offset + local.len() as u64 + size;
        // CRC-32 sits 14 bytes into the local header.
        self.w.seek(SeekFrom::Start(offset + 14))?;
        self.w.write_all(&crc.to_le_bytes())?;
        self.w.seek(SeekFrom::Start(end))?;
        self.entries.push(Entry {
            name: file,
            crc,
            size: size as u32,
            offset: offset as u32,
        });
        self.at = end;
        Ok(())
    }

    /// Writes `text` as the 0-d unicode array `name` (dtype `<Un`, UTF-32,
    /// n its characters): numpy reads it as `str(npz[name])`. For a
    /// file's metadata (a few kB), made in memory.
    pub fn text(&mut self, name: &str, text: &str) -> io::Result<()> {
        let chars: Vec<u32> = text.chars().map(u32::from).collect();
        let header = npy_header_of(&format!("<U{}", chars.len().max(1)), &[]);
        let mut bytes = header;
        bytes.extend(chars.iter().flat_map(|c| c.to_le_bytes()));
        if chars.is_empty() {
            bytes.extend_from_slice(&[0; 4]);
        }
        let file = format!("{name}.npy");
        let size = bytes.len() as u64;
        if size + self.at > ZIP32_MAX {
            return Err(invalid(format!(
                "the array {name} would make the .npz larger than 4 GiB"
            )));
        }
        let crc = Crc32::of(&bytes);
        let local = local_header(&file, crc, size as u32);
        self.w.write_all(&local)?;
        self.w.write_all(&bytes)?;
        self.entries.push(Entry {
            name: file,
            crc,
            size: size as u32,
            offset: self.at as u32,
        });
        self.at += local.len() as u64 + size;
        Ok(())
    }

    /// Writes the central directory; returns the writer.
    pub fn finish(mut self) -> io::Result<W> {
        let start = self.at;
        if start > ZIP32_MAX {
            return Err(invalid("the .npz would be larger than 4 GiB".into()));
        }
        let mut dir = Vec::new();
        for e in &self.entries {
            dir.extend_from_slice(&0x0201_4b50u32.to_le_bytes());
            dir.extend_from_slice(&20u16.to_le_bytes()); // made by
            dir.extend_from_slice(&20u16.to_le_bytes()); // needed
            dir.extend_from_slice(&[0; 4]); // flags, method (stored)
            dir.extend_from_slice(&DOS_TIME_DATE);
            dir.extend_from_slice(&e.crc.to_le_bytes());
            dir.extend_from_slice(&e.size.to_le_bytes());
            dir.extend_from_slice(&e.size.to_le_bytes());
            dir.extend_from_slice(&(e.name.len() as u16).to_le_bytes());
            dir.extend_from_slice(&[0; 6]); // extra, comment, disk
            dir.extend_from_slice(&[0; 2]); // internal attributes
            dir.extend_from_slice(&0o100644u32.wrapping_shl(16).to_le_bytes());
            dir.extend_from_slice(&e.offset.to_le_bytes());
            dir.extend_from_slice(e.name.as_bytes());
        }
        let count = self.entries.len() as u16;
        dir.extend_from_slice(&0x0605_4b50u32.to_le_bytes());
        dir.extend_from_slice(&[0; 4]); // disk numbers
        dir.extend_from_slice(&count.to_le_bytes());
        dir.extend_from_slice(&count.to_le_bytes());
        dir.extend_from_slice(&((dir.len() - 12) as u32).to_le_bytes());
        dir.extend_from_slice(&(start as u32).to_le_bytes());
        dir.extend_from_slice(&[0; 2]); // comment
        self.w.write_all(&dir)?;
        self.w.flush()?;
        Ok(self.w)
    }
}

/// 1980-01-01 00:00, the earliest DOS time: the archive does not depend
/// on when it was made.
const DOS_TIME_DATE: [u8; 4] = [0, 0, 0x21, 0];

fn local_header(name: &str, crc: u32, size: u32) -> Vec<u8> {
    let mut h = Vec::with_capacity(30 + name.len());
    h.extend_from_slice(&0x0403_4b50u32.to_le_bytes());
    h.extend_from_slice(&20u16.to_le_bytes()); // version needed
    h.extend_from_slice(&[0; 4]); // flags, method (stored)
    h.extend_from_slice(&DOS_TIME_DATE);
    h.extend_from_slice(&crc.to_le_bytes());
    h.extend_from_slice(&size.to_le_bytes());
    h.extend_from_slice(&size.to_le_bytes());
    h.extend_from_slice(&(name.len() as u16).to_le_bytes());
    h.extend_from_slice(&[0; 2]); // extra
    h.extend_from_slice(name.as_bytes());
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn npy_headers_align_to_64_bytes() {
        for shape in [&[3usize][..], &[1000, 7], &[0, 0], &[123_456_789, 100_000]] {
            let h = npy_header(shape);
            assert_eq!(h.len() % 64, 0, "{shape:?}");
            assert_eq!(*h.last().unwrap(), b'\n');
            let len = u16::from_le_bytes([h[8], h[9]]) as usize;
            assert_eq!(len + 10, h.len());
        }
        let h = npy_header(&[3]);
        assert!(String::from_utf8_lossy(&h).contains("'shape': (3,), }"));
    }

    #[test]
    fn central_directory_entries_are_46_bytes_and_the_name() {
        let mut w = NpzWriter::new(io::Cursor::new(Vec::new()));
        w.array("ab", &[1], |a| a.push(1.5)).unwrap();
        let b = w.finish().unwrap().into_inner();
        let end = b.len() - 22;
        let size = u32::from_le_bytes(b[end + 12..end + 16].try_into().unwrap());
        assert_eq!(size as usize, 46 + "ab.npy".len());
        let at = u32::from_le_bytes(b[end + 16..end + 20].try_into().unwrap()) as usize;
        assert_eq!(&b[at + 46..at + 52], b"ab.npy");
        assert_eq!(at + size as usize, end);
    }

    #[test]
    fn a_wrong_count_of_values_is_an_error() {
        let mut w = NpzWriter::new(io::Cursor::new(Vec::new()));
        let err = w
            .array("a", &[2, 2], |a| (0..3).try_for_each(|k| a.push(k as f64)))
            .unwrap_err();
        assert!(err.to_string().contains("3 values"), "{err}");
    }
}
