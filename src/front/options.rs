//! The render options of both front ends: the command line's format flags
//! (`--format`, `--frames`, `--size`, `--fps`, `--quality`, `--scale`)
//! and Python's `render`/`save` keywords, with every default in one
//! [`RenderOptions::default`], checked into the library's
//! [`MovieOptions`] and [`Outputs`]. Messages name the flags; Python
//! shows them as they are, since its keywords are the flags' names.

use crate::encode::{self, Formats, Kind as FormatKind, Mp4Quality};
use crate::error::{Error, Result};
use crate::render::StyleSpec;
use crate::scene::{Kind, Scene};
use crate::scenes::{MovieOptions, Outputs};

/// The formats of `ladder render` and `ladder all` when none is asked:
/// PNG figures and GIF movies.
pub const DEFAULT_FORMATS: &str = "png,gif";

/// The movie frame size when none is asked, as `--size` takes it; the
/// same as [`MovieOptions::default`].
pub const DEFAULT_SIZE: &str = "640x480";

/// How a scene's files are drawn beyond the scene itself.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderOptions {
    /// The formats, any mix of png, svg, pdf (figures and a movie's
    /// kymograph) and gif, mp4 (movies). Default [`DEFAULT_FORMATS`].
    pub formats: String,
    /// A movie's frames. Default 200.
    pub frames: usize,
    /// A movie's frame size in pixels, width × height. Default 640 × 480.
    pub size: (u32, u32),
    /// A movie's frames per second. Default 25.
    pub fps: f64,
    /// The H.264 quality of MP4 movies. Default high.
    pub quality: Mp4Quality,
    /// Pixels per design pixel of PNG figures. Default 1.
    pub scale: f32,
    /// The style over each scene's `[style]`. Default none (the scene's).
    pub style: StyleSpec,
}

impl Default for RenderOptions {
    fn default() -> Self {
        let movie = MovieOptions::default();
        let outputs = Outputs::default();
        Self {
            formats: DEFAULT_FORMATS.to_string(),
            frames: movie.frames,
            size: (movie.width, movie.height),
            fps: movie.fps,
            quality: outputs.mp4_quality,
            scale: outputs.scale,
            style: StyleSpec::default(),
        }
    }
}

impl RenderOptions {
    /// The movie options, checked.
    pub fn movie(&self) -> Result<MovieOptions> {
        movie_options(self.frames, self.size, self.fps)
    }

    /// The formats of figures and movies, checked against the movie's
    /// frame size and rate.
    pub fn outputs(&self, movie: &MovieOptions) -> Result<Outputs> {
        Ok(Outputs {
            mp4_quality: self.quality,
            ..mixed_outputs(&self.formats, self.scale, self.style, movie)?
        })
    }
}

/// `WxH` (such as 640x480) as a frame size in pixels.
pub fn parse_size(s: &str) -> std::result::Result<(u32, u32), String> {
    let bad = || format!("expected WxH such as 640x480, got '{s}'");
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    Ok((
        w.trim().parse().map_err(|_| bad())?,
        h.trim().parse().map_err(|_| bad())?,
    ))
}

/// The movie options, validated. Their frames × pixels are checked
/// against each movie scene's cap where it is rendered
/// (`scenes::check`, `scenes::render_to`).
pub fn movie_options(frames: usize, size: (u32, u32), fps: f64) -> Result<MovieOptions> {
    let opts = MovieOptions {
        frames,
        width: size.0,
        height: size.1,
        fps,
    }
    .validated()
    .map_err(|e| Error::bad_input(format!("--frames/--size/--fps: {e}")))?;
    Ok(opts)
}

/// The figure formats and scale of `ladder figure`.
pub fn figure_outputs(list: &str, scale: f32, style: StyleSpec) -> Result<Outputs> {
    let figures = formats_of(list, FormatKind::Figure)?;
    with_scale(
        Outputs {
            figures,
            style,
            ..Outputs::default()
        },
        scale,
    )
}

/// `ladder render`: every scene must have a format of its kind in the
/// list (a list that names only figure formats writes no movie, and one
/// that names only movie formats no figure).
pub fn check_covers(list: &str, scenes: &[Scene]) -> Result<()> {
    let (figures, movies) =
        encode::parse_mixed(list).map_err(|e| Error::bad_input(format!("--format: {e}")))?;
    for s in scenes {
        let missing = match s.kind() {
            Kind::Movie if movies.is_none() => Some("gif or mp4"),
            Kind::Figure if figures.is_none() => Some("png, svg or pdf"),
            _ => None,
        };
        if let Some(formats) = missing {
            return Err(Error::bad_input(format!(
                "--format {list}: {} is a {}, written as {formats}; add one of them to the list",
                s.name,
                s.kind().name()
            )));
        }
    }
    Ok(())
}

/// The figure and movie formats of `ladder all` and `ladder render`,
/// checked against the movie's frame size and rate.
pub fn mixed_outputs(
    list: &str,
    scale: f32,
    style: StyleSpec,
    movie: &MovieOptions,
) -> Result<Outputs> {
    let (figures, movies) =
        encode::parse_mixed(list).map_err(|e| Error::bad_input(format!("--format: {e}")))?;
    let defaults = Outputs::default();
    let outputs = Outputs {
        figures: figures.unwrap_or(defaults.figures),
        movies: movies.unwrap_or(defaults.movies),
        style,
        ..defaults
    };
    check_movie_formats(&outputs.movies, movie)?;
    with_scale(outputs, scale)
}

/// The formats of `ladder movie`: the movie formats of `list` (gif, mp4),
/// checked against the frame size and rate, and its figure formats (png,
/// svg, pdf; PNG if none) for the movie's kymograph, whose PNG is
/// `scale` times the movie's pixels.
pub fn movie_outputs(list: &str, movie: &MovieOptions, scale: f32) -> Result<Outputs> {
    let (figures, movies) =
        encode::parse_mixed(list).map_err(|e| Error::bad_input(format!("--format: {e}")))?;
    let movies = movies.ok_or_else(|| {
        Error::bad_input(format!(
            "--format {list}: no movie format; a movie is gif or mp4 (and its kymograph \
             png, svg or pdf), e.g. --format gif,pdf"
        ))
    })?;
    check_movie_formats(&movies, movie)?;
    let outputs = Outputs {
        figures: figures.unwrap_or_else(|| Formats::default_for(FormatKind::Figure)),
        movies,
        ..Outputs::default()
    };
    with_scale(outputs, scale)
}

/// For a `--format` list of `ladder movie` that names figure formats as
/// well as movie formats: one line saying which file takes which (the
/// movie the movie formats, its kymograph the figure formats).
pub fn movie_formats_line(list: &str, outputs: &Outputs) -> Option<String> {
    let (figures, _) = encode::parse_mixed(list).ok()?;
    figures?;
    let names = |f: &Formats| {
        let v: Vec<String> = f
            .as_slice()
            .iter()
            .map(|f| f.name().to_uppercase())
            .collect();
        v.join(" and ")
    };
    Some(format!(
        "--format {list}: writing the movie as {} and its kymograph as {}",
        names(&outputs.movies),
        names(&outputs.figures)
    ))
}

/// Every movie format can take the frame size and rate (before any work).
fn check_movie_formats(formats: &Formats, movie: &MovieOptions) -> Result<()> {
    for &f in formats.as_slice() {
        encode::check_movie_size(f, movie.width, movie.height)
            .map_err(|e| Error::bad_input(format!("--size: {e}")))?;
        encode::check_movie_fps(f, movie.fps)
            .map_err(|e| Error::bad_input(format!("--fps: {e}")))?;
    }
    Ok(())
}

/// `--format` of a kind, worded as the flag.
fn formats_of(list: &str, kind: FormatKind) -> Result<Formats> {
    Formats::parse(list, kind).map_err(|e| Error::bad_input(format!("--format: {e}")))
}

/// `--scale`, checked.
fn with_scale(outputs: Outputs, scale: f32) -> Result<Outputs> {
    Outputs { scale, ..outputs }
        .validated()
        .map_err(|e| Error::bad_input(format!("--scale: {e}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_size_is_the_movies() {
        let d = MovieOptions::default();
        assert_eq!(parse_size(DEFAULT_SIZE), Ok((d.width, d.height)));
        assert_eq!(RenderOptions::default().size, (d.width, d.height));
        assert!(parse_size("640").is_err());
        assert_eq!(parse_size("800X600"), Ok((800, 600)));
    }

    #[test]
    fn default_options_check() {
        let o = RenderOptions::default();
        let movie = o.movie().unwrap();
        let outputs = o.outputs(&movie).unwrap();
        assert_eq!(outputs.figures, Outputs::default().figures);
        assert_eq!(outputs.movies, Outputs::default().movies);
    }

    #[test]
    fn formats_are_checked_before_work() {
        let movie = MovieOptions::default();
        let e = movie_outputs("pdf", &movie, 1.0).unwrap_err().to_string();
        assert!(e.starts_with("--format pdf: no movie format"), "{e}");
        let o = movie_outputs("gif,mp4,png,pdf", &movie, 2.0).unwrap();
        assert_eq!(
            (o.movies.to_string(), o.figures.to_string()),
            ("gif,mp4".into(), "png,pdf".into())
        );
        assert_eq!(
            movie_formats_line("gif,mp4,png,pdf", &o).unwrap(),
            "--format gif,mp4,png,pdf: writing the movie as GIF and MP4 and its kymograph \
             as PNG and PDF"
        );
        assert_eq!(movie_formats_line("gif", &o), None);
        let fast = MovieOptions { fps: 60.0, ..movie };
        let e = movie_outputs("gif", &fast, 1.0).unwrap_err().to_string();
        assert!(e.starts_with("--fps: a GIF plays at most 50"), "{e}");
        let o = mixed_outputs("pdf,gif", 2.0, StyleSpec::default(), &movie).unwrap();
        assert_eq!(o.figures.to_string(), "pdf");
        assert_eq!(o.movies.to_string(), "gif");
        assert_eq!(o.scale, 2.0);
        assert!(
            mixed_outputs("png", 100.0, StyleSpec::default(), &movie)
                .unwrap_err()
                .to_string()
                .starts_with("--scale: ")
        );
    }
}
