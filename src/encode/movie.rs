//! One stream of frames into every movie format asked for (GIF, MP4): the
//! formats get the very same frames.

use super::format::{Format, Kind, Mp4Quality, check_movie_frame};
use super::gif::{GifWriter, Palette};

#[cfg(feature = "mp4")]
use super::mp4::Mp4Writer;
use crate::error::{Error, Result};
use tiny_skia::Pixmap;

/// Frames in, one file per movie format out.
pub struct MovieWriter {
    formats: Vec<Format>,
    gif: Option<GifWriter>,
    #[cfg(feature = "mp4")]
    mp4: Option<Mp4Writer>,
}

impl MovieWriter {
    /// A writer of `width × height` frames at `fps` for each of `formats`
    /// (movie formats only; each is checked with [`check_movie_frame`]),
    /// in the colours of `palette` (the GIF's table, which the MP4 shows
    /// too).
    pub fn new(
        formats: &[Format],
        (width, height): (u32, u32),
        fps: f64,
        palette: &'static Palette,
    ) -> Result<Self> {
        Self::with_quality(
            formats,
            (width, height),
            fps,
            palette,
            Mp4Quality::default(),
        )
    }

    /// [`MovieWriter::new`] with the MP4 at `quality` (the GIF is lossless
    /// within its palette and has no quality).
    pub fn with_quality(
        formats: &[Format],
        (width, height): (u32, u32),
        fps: f64,
        palette: &'static Palette,
        quality: Mp4Quality,
    ) -> Result<Self> {
        if formats.is_empty() {
            return Err(Error::bad_input("a movie needs at least one format"));
        }
        #[cfg(not(feature = "mp4"))]
        let _ = quality;
        for &f in formats {
            if f.kind() != Kind::Movie {
                return Err(super::FormatError::WrongKind {
                    format: f,
                    kind: Kind::Movie,
                }
                .into());
            }
            check_movie_frame(f, width, height, fps)?;
        }
        let gif = if formats.contains(&Format::Gif) {
            Some(GifWriter::new(width, height, fps, palette)?)
        } else {
            None
        };
        #[cfg(feature = "mp4")]
        let mp4 = if formats.contains(&Format::Mp4) {
            // The MP4 shows the GIF's colours, whether or not a GIF is
            // written (the same MP4 either way).
            Some(Mp4Writer::with_quality(width, height, fps, quality)?.showing(palette))
        } else {
            None
        };
        let mut unique = Vec::new();
        for &f in formats {
            if !unique.contains(&f) {
                unique.push(f);
            }
        }
        Ok(Self {
            formats: unique,
            gif,
            #[cfg(feature = "mp4")]
            mp4,
        })
    }

    /// Appends one frame to every format.
    pub fn push_frame(&mut self, pixmap: &Pixmap) -> Result<()> {
        if let Some(g) = &mut self.gif {
            g.push_frame(pixmap)?;
        }
        #[cfg(feature = "mp4")]
        if let Some(m) = &mut self.mp4 {
            m.push_frame(pixmap)?;
        }
        Ok(())
    }

    /// The bytes of each format, in the order the formats were given.
    pub fn finish(self) -> Result<Vec<(Format, Vec<u8>)>> {
        let mut gif = self.gif.map(GifWriter::finish).transpose()?;
        #[cfg(feature = "mp4")]
        let mut mp4 = self.mp4.map(Mp4Writer::finish).transpose()?;
        #[cfg(not(feature = "mp4"))]
        let mut mp4: Option<Vec<u8>> = None;
        let mut out = Vec::with_capacity(self.formats.len());
        for f in self.formats {
            let bytes = match f {
                Format::Gif => gif.take(),
                Format::Mp4 => mp4.take(),
                _ => None,
            };
            let bytes = bytes.ok_or_else(|| Error::failed(format!("no {f} was written")))?;
            out.push((f, bytes));
        }
        Ok(out)
    }
}
