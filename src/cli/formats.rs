//! The format, style and kernel flags as the library's options: each
//! checked, its error worded as the flag (`front::options` holds the
//! defaults and the checks both front ends share).

use super::args::{FigureFormat, KernelArg, MixedFormat, MovieFormat, QualityArg, StyleArgs};
use crate::encode;
use crate::error::{Error, Result};
use crate::front;
use crate::render::page_style::parse_length;
use crate::render::{FontChoice, Length, StyleName, StyleSpec, TextMode};
use crate::scene::Scene;
use crate::scenes::{MovieOptions, Outputs};
use crate::sim;

impl MovieFormat {
    /// The movie options, validated ([`front::options::movie_options`]).
    pub fn options(&self) -> Result<MovieOptions> {
        front::options::movie_options(self.frames, self.size, self.fps)
    }

    /// `--quality`, as the encoder's level.
    pub fn mp4_quality(&self) -> encode::Mp4Quality {
        match self.quality {
            QualityArg::Draft => encode::Mp4Quality::Draft,
            QualityArg::Standard => encode::Mp4Quality::Standard,
            QualityArg::High => encode::Mp4Quality::High,
            QualityArg::Best => encode::Mp4Quality::Best,
        }
    }
}

impl FigureFormat {
    /// The figure formats and scale of `ladder figure`.
    pub fn outputs(&self) -> Result<Outputs> {
        if let Some(size) = &self.size {
            return Err(Error::bad_input(format!(
                "--size {size}: a figure keeps its layout and takes no frame size; \
                 use --scale S for S times the PNG's pixels (e.g. --scale 2), \
                 or --format svg,pdf for vector files"
            )));
        }
        front::options::figure_outputs(&self.formats, self.scale, self.style.spec()?)
    }
}

impl MixedFormat {
    /// `ladder render`: every scene has a format of its kind in the list.
    pub fn check_covers(&self, scenes: &[Scene]) -> Result<()> {
        front::options::check_covers(&self.formats, scenes)
    }

    /// The figure and movie formats of `ladder all` and `ladder render`.
    pub fn outputs(&self, movie: &MovieOptions) -> Result<Outputs> {
        front::options::mixed_outputs(&self.formats, self.scale, self.style.spec()?, movie)
    }
}

impl StyleArgs {
    /// The style flags as a [`StyleSpec`], each checked: one line naming
    /// the flag and what it takes.
    pub fn spec(&self) -> Result<StyleSpec> {
        fn named<T>(
            flag: &str,
            v: &Option<String>,
            parse: fn(&str) -> Option<T>,
            names: &[&str],
        ) -> Result<Option<T>> {
            v.as_deref()
                .map(|s| {
                    parse(s).ok_or_else(|| {
                        Error::bad_input(format!("--{flag} {s}: unknown; use {}", names.join(", ")))
                    })
                })
                .transpose()
        }
        let length = |flag: &str, v: &Option<String>| -> Result<Option<Length>> {
            v.as_deref()
                .map(|s| {
                    parse_length(s)
                        .map(Length)
                        .map_err(|e| Error::bad_input(format!("--{flag}: {e}")))
                })
                .transpose()
        };
        let spec = StyleSpec {
            name: named("style", &self.style, StyleName::parse, &StyleName::NAMES)?,
            width: length("width", &self.width)?,
            height: length("height", &self.height)?,
            font_size: self.font_size,
            font: named("font", &self.font, FontChoice::parse, &FontChoice::NAMES)?,
            dpi: self.dpi,
            text: named("text", &self.text, TextMode::parse, &TextMode::NAMES)?,
        };
        // The numbers' ranges, worded as flags (the scene file's table is
        // checked when the scene is drawn).
        spec.resolve()
            .map_err(|e| Error::bad_input(format!("--{e}")))?;
        Ok(spec)
    }
}

impl KernelArg {
    /// The stepping asked for, if this CPU can run it.
    pub fn stepping(self) -> Result<sim::Stepping> {
        let fused = |isa: sim::Isa| {
            if isa.available() {
                Ok(sim::Stepping::Fused(isa))
            } else {
                Err(Error::bad_input(format!(
                    "--kernel {}: this CPU lacks the instruction set; use fastest or portable",
                    isa.name()
                )))
            }
        };
        match self {
            Self::Fastest => Ok(sim::Stepping::Fastest),
            Self::Avx2 => fused(sim::Isa::Avx2),
            Self::Avx512 => fused(sim::Isa::Avx512),
            Self::Portable => Ok(sim::Stepping::Portable),
        }
    }
}
