//! File formats: what each holds (a still figure or a movie), parsing of a
//! comma list such as "png,svg,pdf", and the frame sizes and rates a movie
//! format can take. Errors are structured ([`FormatError`]); the caller
//! words them for its own interface.

use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// A file format the program writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Format {
    /// Raster figure (the default for figures).
    Png,
    /// Vector figure; text converted to outlines.
    Svg,
    /// Vector figure that pdflatex can include; text as outlines.
    Pdf,
    /// Animated GIF (the default for movies): one palette, at most 50 fps.
    Gif,
    /// H.264 (yuv420p) in an MP4 file with the index first; needs the
    /// `mp4` cargo feature.
    Mp4,
}

/// What a format holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    /// A still picture: PNG, SVG or PDF.
    Figure,
    /// A sequence of frames: GIF or MP4.
    Movie,
}

impl Kind {
    /// "figure" or "movie".
    pub fn name(self) -> &'static str {
        match self {
            Kind::Figure => "figure",
            Kind::Movie => "movie",
        }
    }

    /// The formats of this kind, in the order listed to users.
    pub fn formats(self) -> &'static [Format] {
        match self {
            Kind::Figure => &[Format::Png, Format::Svg, Format::Pdf],
            Kind::Movie => &[Format::Gif, Format::Mp4],
        }
    }

    /// The default format: PNG for figures, GIF for movies.
    pub fn default_format(self) -> Format {
        self.formats()[0]
    }

    /// "png, svg, pdf".
    fn list(self) -> String {
        let names: Vec<&str> = self.formats().iter().map(|f| f.name()).collect();
        names.join(", ")
    }
}

impl Format {
    /// Every format, figures first.
    pub const ALL: [Format; 5] = [
        Format::Png,
        Format::Svg,
        Format::Pdf,
        Format::Gif,
        Format::Mp4,
    ];

    /// The lower-case name, which is also the file extension.
    pub fn name(self) -> &'static str {
        match self {
            Format::Png => "png",
            Format::Svg => "svg",
            Format::Pdf => "pdf",
            Format::Gif => "gif",
            Format::Mp4 => "mp4",
        }
    }

    /// The file extension (without the dot).
    pub fn extension(self) -> &'static str {
        self.name()
    }

    /// Figure or movie.
    pub fn kind(self) -> Kind {
        match self {
            Format::Png | Format::Svg | Format::Pdf => Kind::Figure,
            Format::Gif | Format::Mp4 => Kind::Movie,
        }
    }

    /// Whether this build can write the format (MP4 needs the `mp4` feature).
    pub fn is_built(self) -> bool {
        self != Format::Mp4 || cfg!(feature = "mp4")
    }

    /// SVG and PDF: drawn from the vector description of a picture.
    pub fn is_vector(self) -> bool {
        matches!(self, Format::Svg | Format::Pdf)
    }
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Why a format or a list of formats was refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FormatError {
    /// Not a format name; `kind` is what was asked for, if known.
    Unknown { name: String, kind: Option<Kind> },
    /// An empty list.
    Empty { kind: Kind },
    /// A real format of the other kind, such as a movie as PDF.
    WrongKind { format: Format, kind: Kind },
    /// A format this build leaves out (MP4 without the `mp4` feature).
    NotBuilt(Format),
}

impl fmt::Display for FormatError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FormatError::Unknown {
                name,
                kind: Some(k),
            } => write!(
                f,
                "unknown format '{name}'; a {} can be {}",
                k.name(),
                k.list()
            ),
            FormatError::Unknown { name, kind: None } => {
                let all: Vec<&str> = Format::ALL.iter().map(|f| f.name()).collect();
                if name.is_empty() {
                    write!(f, "no format given; choose from {}", all.join(", "))
                } else {
                    write!(f, "unknown format '{name}'; choose from {}", all.join(", "))
                }
            }
            FormatError::Empty { kind } => {
                write!(
                    f,
                    "no format given; a {} can be {}",
                    kind.name(),
                    kind.list()
                )
            }
            FormatError::WrongKind { format, kind } => write!(
                f,
                "a {} cannot be {format}; a {} can be {}",
                kind.name(),
                kind.name(),
                kind.list()
            ),
            FormatError::NotBuilt(format) => write!(
                f,
                "this build of ladder cannot write {format} (it was built without the cargo \
                 feature '{format}')"
            ),
        }
    }
}

impl std::error::Error for FormatError {}

impl From<FormatError> for Error {
    fn from(e: FormatError) -> Self {
        Error::bad_input(e.to_string())
    }
}

impl FromStr for Format {
    type Err = FormatError;

    /// A format name, case-insensitive, surrounding spaces ignored.
    fn from_str(s: &str) -> std::result::Result<Self, Self::Err> {
        let name = s.trim().to_ascii_lowercase();
        Format::ALL
            .into_iter()
            .find(|f| f.name() == name)
            .ok_or(FormatError::Unknown {
                name: s.trim().to_string(),
                kind: None,
            })
    }
}

/// A non-empty list of formats of one kind, without repeats, in the order
/// given.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Formats {
    kind: Kind,
    list: Vec<Format>,
}

impl Formats {
    /// Parses a comma list such as "png,svg" for outputs of `kind`.
    pub fn parse(list: &str, kind: Kind) -> std::result::Result<Formats, FormatError> {
        let mut out = Vec::new();
        for name in list.split(',').map(str::trim).filter(|n| !n.is_empty()) {
            let format: Format = name.parse().map_err(|_| FormatError::Unknown {
                name: name.to_string(),
                kind: Some(kind),
            })?;
            Formats::check(format, kind)?;
            if !out.contains(&format) {
                out.push(format);
            }
        }
        if out.is_empty() {
            return Err(FormatError::Empty { kind });
        }
        Ok(Formats { kind, list: out })
    }

    /// The given formats (checked like [`Formats::parse`]).
    pub fn new(formats: &[Format], kind: Kind) -> std::result::Result<Formats, FormatError> {
        let names: Vec<&str> = formats.iter().map(|f| f.name()).collect();
        Formats::parse(&names.join(","), kind)
    }

    /// The one default format of `kind` (PNG or GIF).
    pub fn default_for(kind: Kind) -> Formats {
        Formats {
            kind,
            list: vec![kind.default_format()],
        }
    }

    fn check(format: Format, kind: Kind) -> std::result::Result<(), FormatError> {
        if format.kind() != kind {
            Err(FormatError::WrongKind { format, kind })
        } else if !format.is_built() {
            Err(FormatError::NotBuilt(format))
        } else {
            Ok(())
        }
    }

    /// Figure or movie.
    pub fn kind(&self) -> Kind {
        self.kind
    }

    /// The formats in order.
    pub fn as_slice(&self) -> &[Format] {
        &self.list
    }

    /// `<base>.<ext>` for each format, in order.
    pub fn file_names(&self, base: &str) -> Vec<String> {
        self.list
            .iter()
            .map(|f| format!("{base}.{}", f.extension()))
            .collect()
    }

    /// Whether `format` is in the list.
    pub fn contains(&self, format: Format) -> bool {
        self.list.contains(&format)
    }

    /// Whether any format needs the vector description (SVG, PDF).
    pub fn any_vector(&self) -> bool {
        self.list.iter().any(|f| f.is_vector())
    }
}

impl fmt::Display for Formats {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<&str> = self.list.iter().map(|f| f.name()).collect();
        f.write_str(&names.join(","))
    }
}

/// Splits a comma list that may name figure and movie formats (e.g.
/// "pdf,mp4") into its figure formats and its movie formats; either part
/// is `None` when the list names none of that kind.
pub fn parse_mixed(
    list: &str,
) -> std::result::Result<(Option<Formats>, Option<Formats>), FormatError> {
    let mut parts: [Vec<Format>; 2] = [Vec::new(), Vec::new()];
    let mut any = false;
    for name in list.split(',').map(str::trim).filter(|n| !n.is_empty()) {
        let f: Format = name.parse()?;
        any = true;
        parts[(f.kind() == Kind::Movie) as usize].push(f);
    }
    if !any {
        return Err(FormatError::Unknown {
            name: list.trim().to_string(),
            kind: None,
        });
    }
    let part = |v: &[Format], kind| -> std::result::Result<Option<Formats>, FormatError> {
        if v.is_empty() {
            Ok(None)
        } else {
            Formats::new(v, kind).map(Some)
        }
    };
    Ok((
        part(&parts[0], Kind::Figure)?,
        part(&parts[1], Kind::Movie)?,
    ))
}

/// Largest MP4 frame: the bundled H.264 encoder stops at level 5.2
/// (3840 × 2160, either way round).
pub const MP4_MAX: (u32, u32) = (3840, 2160);

/// Checks, before any work, that a movie of `width × height` frames at
/// `fps` frames per second can be written as `format`.
///
/// GIF: sides up to 65535 and at most 50 frames per second (see
/// [`super::gif::GIF_MAX_FPS`]). MP4: even width and height (4:2:0 chroma
/// halves both), at least 16 pixels, at most 3840 × 2160 either way round.
/// Odd sizes are refused, not rounded, so the file has the size asked for.
pub fn check_movie_frame(format: Format, width: u32, height: u32, fps: f64) -> Result<()> {
    check_movie_size(format, width, height)?;
    check_movie_fps(format, fps)
}

/// The size part of [`check_movie_frame`].
pub fn check_movie_size(format: Format, width: u32, height: u32) -> Result<()> {
    match format {
        Format::Gif => super::gif::check_gif_size(width, height),
        Format::Mp4 if !format.is_built() => Err(FormatError::NotBuilt(format).into()),
        Format::Mp4 => check_mp4_size(width, height),
        other => Err(FormatError::WrongKind {
            format: other,
            kind: Kind::Movie,
        }
        .into()),
    }
}

/// Quality of an MP4 movie: the H.264 quantiser (QP) of every frame,
/// lower being finer. Each level halves the error of the one below it
/// (6 QP steps double the quantiser step) at about 1.5 to 2 times the
/// bytes; docs/formats.md gives sizes and PSNR against the GIF.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mp4Quality {
    /// QP 30: small files for a preview; faint ghosts near moving blocks.
    Draft,
    /// QP 24: thin lines and small text clean; ghosts visible on a still.
    Standard,
    /// QP 18 (default): at least 40 dB PSNR against the GIF on every
    /// frame of movie 4 (40.5 dB measured; tests/mp4_quality.rs).
    #[default]
    High,
    /// QP 12: for editing the movie further.
    Best,
}

impl Mp4Quality {
    /// Every level, from the smallest files.
    pub const ALL: [Mp4Quality; 4] = [Self::Draft, Self::Standard, Self::High, Self::Best];

    /// The level's H.264 quantiser (0–51).
    pub fn qp(self) -> u8 {
        match self {
            Self::Draft => 30,
            Self::Standard => 24,
            Self::High => 18,
            Self::Best => 12,
        }
    }

    /// The level's name, as typed after `--quality`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Draft => "draft",
            Self::Standard => "standard",
            Self::High => "high",
            Self::Best => "best",
        }
    }
}

impl std::str::FromStr for Mp4Quality {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        Self::ALL
            .into_iter()
            .find(|q| q.name().eq_ignore_ascii_case(s.trim()))
            .ok_or_else(|| {
                Error::bad_input(format!(
                    "unknown MP4 quality '{s}'; choose draft, standard, high (the default) or best"
                ))
            })
    }
}

/// The frame-rate part of [`check_movie_frame`].
pub fn check_movie_fps(format: Format, fps: f64) -> Result<()> {
    match format {
        Format::Gif => super::gif::check_gif_fps(fps),
        Format::Mp4 if !(fps.is_finite() && fps > 0.0 && fps <= 240.0) => Err(Error::bad_input(
            format!("an MP4 frame rate must be above 0 and at most 240, got {fps}"),
        )),
        Format::Mp4 => Ok(()),
        other => Err(FormatError::WrongKind {
            format: other,
            kind: Kind::Movie,
        }
        .into()),
    }
}

/// Even sides between 16 and 3840 × 2160 (either orientation).
pub(crate) fn check_mp4_size(width: u32, height: u32) -> Result<()> {
    if width % 2 == 1 || height % 2 == 1 {
        // An odd side is as near the even number below as the one above:
        // below (1921 → 1920, the size meant), unless that is under 16.
        let even = |v: u32| {
            if v.is_multiple_of(2) {
                v
            } else if v > 16 {
                v - 1
            } else {
                v + 1
            }
        };
        return Err(Error::bad_input(format!(
            "an MP4 (H.264, 4:2:0) needs an even width and height, got {width}x{height}; \
             try {}x{}",
            even(width),
            even(height)
        )));
    }
    let (long, short) = (width.max(height), width.min(height));
    if short < 16 || long > MP4_MAX.0 || short > MP4_MAX.1 {
        return Err(Error::bad_input(format!(
            "an MP4 frame must be between 16x16 and {}x{} (or {}x{}) pixels, got {width}x{height}",
            MP4_MAX.0, MP4_MAX.1, MP4_MAX.1, MP4_MAX.0
        )));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_lists() {
        let f = Formats::parse(" PNG, svg,png ,pdf", Kind::Figure).unwrap();
        assert_eq!(f.as_slice(), &[Format::Png, Format::Svg, Format::Pdf]);
        assert_eq!(f.to_string(), "png,svg,pdf");
        assert!(f.any_vector());
    }

    #[test]
    fn refuses_bad_lists() {
        let e = Formats::parse("png,jpg", Kind::Figure).unwrap_err();
        assert_eq!(
            e.to_string(),
            "unknown format 'jpg'; a figure can be png, svg, pdf"
        );
        let e = Formats::parse("pdf", Kind::Movie).unwrap_err();
        assert_eq!(
            e.to_string(),
            "a movie cannot be pdf; a movie can be gif, mp4"
        );
        assert!(matches!(
            Formats::parse(" , ", Kind::Movie),
            Err(FormatError::Empty { .. })
        ));
    }

    #[test]
    fn mixed_lists() {
        let (f, m) = parse_mixed("pdf, mp4,png").unwrap();
        assert_eq!(f.unwrap().as_slice(), &[Format::Pdf, Format::Png]);
        assert_eq!(m.unwrap().as_slice(), &[Format::Mp4]);
        let (f, m) = parse_mixed("gif").unwrap();
        assert!(f.is_none() && m.is_some());
        assert!(parse_mixed("tiff").is_err());
        assert!(parse_mixed("").is_err());
    }

    #[test]
    fn movie_frames() {
        assert!(check_movie_frame(Format::Gif, 640, 480, 50.0).is_ok());
        assert!(check_movie_frame(Format::Gif, 640, 480, 60.0).is_err());
        assert!(check_movie_frame(Format::Png, 640, 480, 25.0).is_err());
        let odd = check_mp4_size(641, 480).unwrap_err().to_string();
        assert!(odd.contains("try 640x480"), "{odd}");
        let odd = check_mp4_size(1921, 1080).unwrap_err().to_string();
        assert!(odd.contains("try 1920x1080"), "{odd}");
        let small = check_mp4_size(15, 17).unwrap_err().to_string();
        assert!(small.contains("try 16x16"), "{small}");
        assert!(check_mp4_size(2160, 3840).is_ok());
        assert!(check_mp4_size(4096, 2160).is_err());
    }
}
