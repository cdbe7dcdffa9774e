//! Scene → files: runs a scene (`run`) and renders it into the bytes of
//! its files, with the data file beside them. `theory` draws the static
//! figures (geometry, formulas, linear theory); `dynamic` the simulated
//! figures and the movies.

pub mod dynamic;
pub mod run;
pub mod theory;

use crate::encode::{Format, Formats, Kind as FormatKind, Mp4Quality};
use crate::error::{Error, Result};
use crate::render::Picture;
use crate::scene::{OutputSpec, Scene, describe};
pub use dynamic::{MovieOptions, RunData};
use serde::Serialize;

/// Which files each scene writes (`--format`, `--scale`).
#[derive(Debug, Clone, PartialEq)]
pub struct Outputs {
    /// Formats of figures, a movie's kymograph among them. Default: PNG.
    pub figures: Formats,
    /// Formats of movies. Default: GIF.
    pub movies: Formats,
    /// Whether each figure (and kymograph) asked in formats without PNG
    /// also gets a `<name>-preview.png`, for the gallery to show.
    /// Default: false.
    pub preview: bool,
    /// Pixels per design pixel of PNG figures: 2 gives the same layout
    /// with twice the pixels each way. SVG and PDF are vector and keep the
    /// design size (PDF: 0.75 pt per design pixel). Default: 1.
    pub scale: f32,
    /// Quality of MP4 movies. Default: high (docs/formats.md).
    pub mp4_quality: Mp4Quality,
    /// Style flags (`--style`, `--width` …), over each scene's `[style]`.
    /// Default: none.
    pub style: crate::render::StyleSpec,
}

impl Default for Outputs {
    fn default() -> Self {
        Self {
            figures: Formats::default_for(FormatKind::Figure),
            movies: Formats::default_for(FormatKind::Movie),
            preview: false,
            scale: 1.0,
            mp4_quality: Mp4Quality::default(),
            style: crate::render::StyleSpec::default(),
        }
    }
}

/// Largest and smallest `Outputs::scale`.
pub const SCALE_RANGE: (f32, f32) = (0.25, 8.0);

impl Outputs {
    /// Checks the scale (the formats were checked when parsed).
    pub fn validated(self) -> Result<Self> {
        let (lo, hi) = SCALE_RANGE;
        if !(self.scale.is_finite() && (lo..=hi).contains(&self.scale)) {
            return Err(Error::bad_input(format!(
                "the figure scale must be between {lo} and {hi}, got {}",
                self.scale
            )));
        }
        Ok(self)
    }

    /// Whether figures get a PNG preview: asked for, and no PNG among
    /// the figure formats.
    pub fn needs_preview(&self) -> bool {
        self.preview && !self.figures.contains(Format::Png)
    }

    /// The figure formats to encode: those asked, then PNG for the
    /// preview when [`Outputs::needs_preview`].
    fn encoded_figures(&self) -> Result<Formats> {
        if !self.needs_preview() {
            return Ok(self.figures.clone());
        }
        let mut list = self.figures.as_slice().to_vec();
        list.push(Format::Png);
        Ok(Formats::new(&list, FormatKind::Figure)?)
    }
}

/// What ends the name of a figure's PNG preview (`figure-3-preview.png`).
pub const PREVIEW: &str = "-preview.png";

/// `<base>.<ext>` for each figure format, then the preview's name when
/// [`Outputs::needs_preview`]: the names of the bytes of
/// [`Outputs::encoded_figures`], in order.
fn figure_names(base: &str, outputs: &Outputs) -> Vec<String> {
    let mut names: Vec<String> = outputs
        .figures
        .as_slice()
        .iter()
        .map(|f| format!("{base}.{}", f.extension()))
        .collect();
    if outputs.needs_preview() {
        names.push(format!("{base}{PREVIEW}"));
    }
    names
}

/// Number of kymograph rows of a kymograph figure.
const KYMOGRAPH_ROWS: usize = 400;

/// `<output>.json`: the scene with every parameter, the program that made
/// the output, and the numbers the picture shows (SPEC section 6).
#[derive(Debug, Clone, Serialize)]
pub struct DataFile<'a> {
    pub program: &'static str,
    pub version: &'static str,
    pub title: String,
    pub parameters: String,
    pub fidelity: &'static str,
    pub files: Vec<String>,
    pub scene: &'a Scene,
    /// One entry per simulation drawn (empty for the theory figures).
    pub runs: Vec<RunData>,
}

/// The file names a scene writes in the default formats, data file last.
pub fn file_names(scene: &Scene) -> Vec<String> {
    file_names_for(scene, &Outputs::default())
}

/// The file names a scene writes in `outputs`' formats, data file last.
pub fn file_names_for(scene: &Scene, outputs: &Outputs) -> Vec<String> {
    let stem = scene.stem();
    let mut names: Vec<String> = match scene.output {
        OutputSpec::Movie { .. } => {
            let mut v: Vec<String> = outputs
                .movies
                .as_slice()
                .iter()
                .map(|f| format!("{stem}.{}", f.extension()))
                .collect();
            v.extend(figure_names(&format!("{stem}-kymograph"), outputs));
            v
        }
        OutputSpec::Data => vec![],
        OutputSpec::Sweep(_) => {
            let mut v = figure_names(&stem, outputs);
            v.push(format!("{stem}.csv"));
            v
        }
        _ => figure_names(&stem, outputs),
    };
    names.push(format!("{stem}.json"));
    names
}

/// The files of one scene in the default formats, as (file name, bytes),
/// in [`file_names`] order.
pub fn render(scene: &Scene, movie: &MovieOptions) -> Result<Vec<(String, Vec<u8>)>> {
    render_with(scene, movie, &Outputs::default(), &|| {})
}

/// The bytes of a figure in each of `formats` (see [`Picture::encode`]).
pub fn figure_bytes(picture: &Picture, formats: &Formats, scale: f32) -> Result<Vec<Vec<u8>>> {
    picture.encode(formats, scale)
}

/// A figure scene drawn once, as a picture (the vector description every
/// figure format is made from), with the runs it simulated. Movie and data
/// scenes have no picture.
pub fn figure_picture(scene: &Scene) -> Result<(Picture, Vec<RunData>)> {
    match &scene.output {
        OutputSpec::Theory(spec) => {
            let input = theory::FigureInput::new(describe::title(scene), &scene.model, spec);
            Ok((theory::picture(spec.figure, &input)?, vec![]))
        }
        OutputSpec::Filmstrip { .. } => dynamic::filmstrip_figure(scene, None),
        OutputSpec::Arrivals { .. } => dynamic::arrivals_figure(scene),
        OutputSpec::Kymograph => {
            let (picture, run) = dynamic::kymograph_figure(scene, KYMOGRAPH_ROWS)?;
            Ok((picture, vec![run]))
        }
        OutputSpec::Movie { .. } | OutputSpec::Data | OutputSpec::Sweep(_) => {
            Err(Error::bad_input(format!(
                "{} {} is not a figure",
                scene.kind().name(),
                scene.name
            )))
        }
    }
}

/// The files of one scene in `outputs`' formats, as (file name, bytes), in
/// [`file_names_for`] order; `frame_done` is called after each movie frame
/// (for a progress bar).
pub fn render_with(
    scene: &Scene,
    movie: &MovieOptions,
    outputs: &Outputs,
    frame_done: &(dyn Fn() + Sync),
) -> Result<Vec<(String, Vec<u8>)>> {
    style_of(scene, outputs)?.apply(|| render_styled(scene, movie, outputs, frame_done))
}

/// The style a scene's figures are drawn in: the flags over its `[style]`.
pub fn style_of(scene: &Scene, outputs: &Outputs) -> Result<crate::render::Style> {
    outputs
        .style
        .over(scene.style)
        .resolve()
        .map_err(|e| Error::bad_input(format!("{}: style: {e}", scene.name)))
}

/// [`render_with`] with the scene's style in force.
fn render_styled(
    scene: &Scene,
    movie: &MovieOptions,
    outputs: &Outputs,
    frame_done: &(dyn Fn() + Sync),
) -> Result<Vec<(String, Vec<u8>)>> {
    if let OutputSpec::Sweep(_) = scene.output {
        // Its own data file: the sweep's JSON (crate::sweep::results).
        return sweep_files(scene, outputs);
    }
    let (mut bytes, runs) = match &scene.output {
        OutputSpec::Theory(_)
        | OutputSpec::Filmstrip { .. }
        | OutputSpec::Arrivals { .. }
        | OutputSpec::Kymograph => {
            let (picture, runs) = figure_picture(scene)?;
            (
                figure_bytes(&picture, &outputs.encoded_figures()?, outputs.scale)?,
                runs,
            )
        }
        OutputSpec::Movie { .. } => {
            let (movies, kymo, run) = dynamic::movie_at(
                scene,
                movie,
                outputs.movies.as_slice(),
                outputs.mp4_quality,
                frame_done,
            )?;
            let mut v: Vec<Vec<u8>> = movies.into_iter().map(|(_, b)| b).collect();
            // The kymograph is a figure: every figure format, its PNG at
            // the movie's pixels times `--scale`.
            v.extend(figure_bytes(
                &kymo.picture,
                &outputs.encoded_figures()?,
                kymo.png_scale * outputs.scale,
            )?);
            (v, vec![run])
        }
        OutputSpec::Data => {
            let run = run::simulate(scene, &[])?;
            (vec![], vec![RunData::from_run(scene, &run)])
        }
        OutputSpec::Sweep(_) => return sweep_files(scene, outputs),
    };
    let names = file_names_for(scene, outputs);
    let data = DataFile {
        program: "ladder",
        version: env!("CARGO_PKG_VERSION"),
        title: describe::title(scene),
        parameters: describe::parameters(scene),
        fidelity: scene.fidelity().name(),
        files: names.clone(),
        scene,
        runs,
    };
    let json = serde_json::to_vec_pretty(&data)
        .map_err(|e| Error::failed(format!("cannot encode the data file: {e}")))?;
    bytes.push(json);
    Ok(names.into_iter().zip(bytes).collect())
}

/// A sweep's files ([`crate::sweep::render`]), its PNG renamed the
/// preview when the formats asked have none.
fn sweep_files(scene: &Scene, outputs: &Outputs) -> Result<Vec<(String, Vec<u8>)>> {
    let mut files = crate::sweep::render(scene, &outputs.encoded_figures()?, outputs.scale)?;
    if outputs.needs_preview() {
        let (png, preview) = (
            format!("{}.png", scene.stem()),
            format!("{}{PREVIEW}", scene.stem()),
        );
        let json = format!("{}.json", scene.stem());
        for (name, bytes) in &mut files {
            if *name == png {
                name.clone_from(&preview);
            } else if *name == json {
                // Its list of files names the preview as written.
                let text = String::from_utf8_lossy(bytes)
                    .replace(&format!("\"{png}\""), &format!("\"{preview}\""));
                *bytes = text.into_bytes();
            }
        }
    }
    Ok(files)
}
