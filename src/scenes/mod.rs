//! Scene → files: runs a scene (`run`) and renders it into the bytes of
//! its files, with the data file beside them. `theory` draws the static
//! figures (geometry, formulas, linear theory); `dynamic` the simulated
//! figures and the movies.

pub mod arrivals;
pub mod cost;
pub mod data;
pub mod dynamic;
pub mod energy;
pub mod experiments;
pub mod kymograph;
pub mod movie;
pub mod options;
pub mod reuse;
pub mod rings;
mod rings_draw;
pub mod run;
pub mod shared;
pub mod stiff;
pub mod theory;
pub mod toy;
pub mod walls;

use crate::encode::{Format, Formats, Kind as FormatKind, Mp4Quality};
use crate::error::{Error, Result};
use crate::render::{Picture, Theme};
use crate::scene::{OutputSpec, Scene, describe};
pub use data::{DataFile, RunData};
pub use options::MovieOptions;

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
    /// The command line that asked for the files, word by word, recorded
    /// in each data file. Default: empty (the library called
    /// directly).
    pub command_line: Vec<String>,
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
            command_line: Vec::new(),
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
    let mut names = outputs.figures.file_names(base);
    if outputs.needs_preview() {
        names.push(format!("{base}{PREVIEW}"));
    }
    names
}

/// Number of kymograph rows of a kymograph figure.
const KYMOGRAPH_ROWS: usize = 400;

/// The file names a scene writes in the default formats, data file last.
pub fn file_names(scene: &Scene) -> Vec<String> {
    file_names_for(scene, &Outputs::default())
}

/// The file names a scene writes in `outputs`' formats, data file last.
pub fn file_names_for(scene: &Scene, outputs: &Outputs) -> Vec<String> {
    let stem = scene.stem();
    let mut names: Vec<String> = match scene.output {
        OutputSpec::Movie { .. } => {
            let mut v = outputs.movies.file_names(&stem);
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
pub fn figure_picture(theme: &Theme, scene: &Scene) -> Result<(Picture, Vec<RunData>)> {
    if scene.rings.is_some() && scene.kind() == crate::scene::Kind::Figure {
        return Ok((rings::figure_picture(theme, scene)?, vec![]));
    }
    match &scene.output {
        OutputSpec::Theory(spec) => {
            let input = theory::FigureInput::of(scene, spec);
            crate::render::fitted(theme, |t| {
                Ok((theory::picture(t, spec.figure, &input)?, vec![]))
            })
        }
        // Filmstrips search their own smallest height, without running
        // their scenes again.
        OutputSpec::Filmstrip { .. } => dynamic::filmstrip_figure(theme, scene, None),
        OutputSpec::Arrivals { .. } => arrivals::arrivals_figure(theme, scene),
        OutputSpec::Energy => energy::energy_figure(theme, scene),
        OutputSpec::Kymograph => {
            let (picture, run) = kymograph::kymograph_figure(theme, scene, KYMOGRAPH_ROWS)?;
            Ok((picture, vec![run]))
        }
        OutputSpec::Experiment(e) => experiments::experiment_figure(theme, scene, e.figure),
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
    let mut files = Vec::new();
    render_to(scene, movie, outputs, frame_done, &mut |name, fill| {
        let mut bytes = Vec::new();
        fill(&mut bytes).map_err(|e| Error::failed(format!("cannot encode {name}: {e}")))?;
        files.push((name.to_string(), bytes));
        Ok(())
    })?;
    Ok(files)
}

pub use crate::output::data::Fill;

/// [`render_with`], handing each file to `sink` (its name, how to write
/// it) as soon as it is drawn, in [`file_names_for`] order: the data file,
/// last, is encoded straight into where `sink` writes it, never held whole
/// in memory (docs/limits.md).
pub fn render_to(
    scene: &Scene,
    movie: &MovieOptions,
    outputs: &Outputs,
    frame_done: &(dyn Fn() + Sync),
    sink: &mut dyn FnMut(&str, Fill<'_>) -> Result<()>,
) -> Result<()> {
    if scene.rings.is_some() {
        let theme = Theme::of(&style_of(scene, outputs)?);
        return rings::render_to(&theme, scene, movie, outputs, frame_done, sink);
    }
    // The data file records the scene as asked (`t_end = "auto"` reruns to
    // the same window); everything drawn uses the window found.
    let asked = scene;
    let scene = &scene.with_auto_window()?;
    if matches!(scene.output, OutputSpec::Movie { .. }) {
        scene
            .limits
            .check_movie(movie.frames, movie.width, movie.height)?;
    }
    if !matches!(scene.output, OutputSpec::Sweep(_)) {
        let (bytes, block_samples) = data::estimated_bytes(scene, movie, KYMOGRAPH_ROWS);
        scene.limits.check_data_bytes(bytes, || {
            format!(
                "the data file of {} {}, {} samples × N",
                scene.kind().name(),
                scene.name,
                crate::limits::count(block_samples)
            )
        })?;
    }
    let theme = Theme::of(&style_of(scene, outputs)?);
    render_styled(&theme, asked, scene, movie, outputs, frame_done, sink)
}

/// The style a scene's figures are drawn in: the flags over its `[style]`.
pub fn style_of(scene: &Scene, outputs: &Outputs) -> Result<crate::render::Style> {
    outputs
        .style
        .over(scene.style)
        .resolve()
        .map_err(|e| Error::bad_input(format!("{}: style: {e}", scene.name)))
}

/// Every check [`render_with`] makes before its work, without the work:
/// the style, the list a theory figure draws and its cost
/// (`theory::check_cost`), a movie's frames × pixels, and the cost of
/// each simulation (`run::check_cost`: `auto`'s halvings included) and of
/// a figure's simulations together (`cost::check_runs`).
/// `render --check` runs it; rendering runs it for every scene first.
pub fn check(scene: &Scene, movie: &MovieOptions, outputs: &Outputs) -> Result<()> {
    style_of(scene, outputs)?;
    if scene.rings.is_some() {
        return rings::check(scene, movie);
    }
    match &scene.output {
        OutputSpec::Theory(spec) => {
            let input = theory::FigureInput::of(scene, spec);
            theory::check_cost(spec.figure, &input)?;
            Ok(())
        }
        // Its grid's runs and its files' bytes (`crate::sweep::checked`).
        OutputSpec::Sweep(_) => crate::sweep::checked(scene).map(drop),
        OutputSpec::Movie { .. } => {
            scene
                .limits
                .check_movie(movie.frames, movie.width, movie.height)?;
            run::check_cost(scene, movie.frames).map(drop)
        }
        // Its runs one by one and together (an experiment figure's every
        // variant): `cost::check_runs`.
        _ => cost::check_runs(scene, &cost::planned_runs(scene, movie.frames)?).map(drop),
    }
}

/// [`render_with`] drawn with `theme`, the theme of the scene's style.
fn render_styled(
    theme: &Theme,
    asked: &Scene,
    scene: &Scene,
    movie: &MovieOptions,
    outputs: &Outputs,
    frame_done: &(dyn Fn() + Sync),
    sink: &mut dyn FnMut(&str, Fill<'_>) -> Result<()>,
) -> Result<()> {
    if let OutputSpec::Sweep(_) = scene.output {
        // Its own data file: the sweep's JSON (crate::sweep::json).
        return sweep_files(theme, scene, outputs, sink);
    }
    let (bytes, runs) = match &scene.output {
        OutputSpec::Theory(_)
        | OutputSpec::Filmstrip { .. }
        | OutputSpec::Arrivals { .. }
        | OutputSpec::Energy
        | OutputSpec::Experiment(_)
        | OutputSpec::Kymograph => {
            let (picture, runs) = figure_picture(theme, scene)?;
            (
                figure_bytes(&picture, &outputs.encoded_figures()?, outputs.scale)?,
                runs,
            )
        }
        OutputSpec::Movie { .. } => {
            let (movies, kymo, run) = dynamic::movie_at(
                theme,
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
        OutputSpec::Sweep(_) => unreachable!("a sweep returned above"),
    };
    let names = file_names_for(scene, outputs);
    let data = DataFile {
        made_by: data::MadeBy::new(&outputs.command_line),
        settings: data::Settings::new(scene, movie, outputs),
        title: describe::title(scene),
        parameters: describe::parameters(scene),
        fidelity: scene.fidelity().name(),
        files: names.clone(),
        scene: asked,
        runs,
        drawn: theory_drawn(scene)?,
    };
    let (data_name, pictures) = names.split_last().expect("a data file is always named");
    for (name, b) in pictures.iter().zip(&bytes) {
        sink(name, &|w| w.write_all(b))?;
    }
    drop(bytes);
    sink(data_name, &|w| data::write_json(w, &data))
}

/// The numbers a theory figure plots, for its data file.
fn theory_drawn(scene: &Scene) -> Result<Option<serde_json::Value>> {
    let OutputSpec::Theory(spec) = &scene.output else {
        return Ok(None);
    };
    let input = theory::FigureInput::of(scene, spec);
    theory::drawn_numbers(spec.figure, &input)?
        .map(|d| {
            serde_json::to_value(d).map_err(|e| Error::failed(format!("the drawn numbers: {e}")))
        })
        .transpose()
}

/// A sweep's files ([`crate::sweep::render_to`]), handed to `sink`, its
/// PNG named the preview when the formats asked have none (and so listed
/// in its JSON).
fn sweep_files(
    theme: &Theme,
    scene: &Scene,
    outputs: &Outputs,
    sink: &mut dyn FnMut(&str, Fill<'_>) -> Result<()>,
) -> Result<()> {
    let png = format!("{}.png", scene.stem());
    let preview = format!("{}{PREVIEW}", scene.stem());
    let needs_preview = outputs.needs_preview();
    let rename = |name: String| {
        if needs_preview && name == png {
            preview.clone()
        } else {
            name
        }
    };
    let formats = outputs.encoded_figures()?;
    let options = crate::sweep::OutputOptions {
        formats: &formats,
        scale: outputs.scale,
        command_line: &outputs.command_line,
        rename: &rename,
        theme: *theme,
    };
    crate::sweep::render_to(scene, &options, sink).map(drop)
}
