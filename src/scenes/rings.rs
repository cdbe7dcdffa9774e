//! Scenes of the double ring chain (paper Fig. 4b, SI Movie 12): a scene
//! with a `[rings]` table runs [`crate::rings`] instead of the ladder and
//! draws its movie (with the kymograph beside it), its strip of
//! snapshots, or its kymograph alone; its data file records the chain's
//! constants, every flip, the waves and the linking guard's count.

use super::rings_draw as draw;
use super::{DataFile, Fill, MovieOptions, Outputs, figure_bytes, file_names_for};
use crate::encode::{Format, MovieWriter, Mp4Quality};
use crate::error::{Error, Result};
use crate::render::{Picture, Raster, Theme, style};
use crate::rings::observe::{Flip, Wave};
use crate::rings::{self, RingChain, RingRun};
use crate::scene::{OutputSpec, Scene, describe};
use rayon::prelude::*;
use serde::Serialize;

/// What a ring scene's data file says of its run.
#[derive(Serialize)]
pub struct RingsData<'a> {
    /// Mass of a ring, kg.
    pub mass: f64,
    /// Moments of inertia about a diameter and about the axis, kg m².
    pub inertia: [f64; 2],
    /// Hertz stiffness, N/m^{3/2}; Hunt–Crossley damping, s/m.
    pub stiffness: f64,
    pub damping: f64,
    /// The time step, s, and the steps taken.
    pub dt: f64,
    pub steps: u64,
    /// Pair checks of the linking guard, every one passed.
    pub guard_checks: u64,
    /// Linked pairs (the topology the guard held).
    pub links: &'a [[usize; 2]],
    /// Largest overlap of two tubes, as a fraction of r.
    pub max_overlap: f64,
    /// Contact pairs evaluated, over all steps.
    pub pair_evaluations: u64,
    /// Every flip (n_z changing sign, docs/rings.md).
    pub flips: &'a [Flip],
    /// The longest helical wave of each strand.
    pub waves: &'a [Wave],
    /// (t, total energy) at each sample, s and J.
    pub energy: Vec<[f64; 2]>,
    /// How the leaning start settled (time, steps, the fastest point's
    /// speed at rest); absent for the chain as built.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub settled: Option<rings::settle::Settled>,
    /// Every pass of the hand from the ring it held to another
    /// (`release`, `alternate`: when, the ring let go, the ring taken and
    /// the kinetic energy the hand took by stopping it, J); absent when
    /// the hand keeps its ring.
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    pub passes: &'a [rings::system::Pass],
}

impl<'a> RingsData<'a> {
    pub fn of(run: &'a RingRun) -> Self {
        let sys = &run.system;
        RingsData {
            mass: sys.inertia.m,
            inertia: [sys.inertia.i_d, sys.inertia.i_a],
            stiffness: sys.law.k,
            damping: sys.law.chi,
            dt: run.dt,
            steps: run.stats.steps,
            guard_checks: run.stats.guard_checks,
            links: &sys.links,
            max_overlap: run.stats.max_overlap,
            pair_evaluations: run.stats.pair_evaluations,
            flips: &run.flips,
            waves: &run.waves,
            energy: run.samples.iter().map(|s| [s.t, s.energy]).collect(),
            settled: run.settled,
            passes: &run.system.passes,
        }
    }
}

/// The data file of a ring scene: the common head, then `rings`.
#[derive(Serialize)]
struct RingsFile<'a> {
    #[serde(flatten)]
    head: DataFile<'a>,
    rings: RingsData<'a>,
}

/// The ring chain of a scene, or the refusal of a scene that has none.
pub fn chain_of(scene: &Scene) -> Result<&RingChain> {
    scene
        .rings
        .as_ref()
        .ok_or_else(|| Error::bad_input(format!("{} has no [rings] table", scene.name)))
}

/// Checks a ring scene before its work: the chain builds (its topology is
/// realised, its tapes touch), and its output is one a chain makes.
pub fn check(scene: &Scene, movie: &MovieOptions) -> Result<()> {
    let chain = chain_of(scene)?;
    rings::run::check(chain)?;
    match scene.output {
        OutputSpec::Movie { .. } => scene
            .limits
            .check_movie(movie.frames, movie.width, movie.height)
            .map_err(Into::into),
        OutputSpec::Filmstrip { .. } | OutputSpec::Kymograph => Ok(()),
        _ => Err(Error::bad_input(format!(
            "{}: a ring chain makes a movie, a filmstrip or a kymograph (output.kind)",
            scene.name
        ))),
    }
}

/// The sample times of a filmstrip: its times, or seven over the run.
fn strip_times(scene: &Scene, chain: &RingChain) -> Vec<f64> {
    match &scene.output {
        OutputSpec::Filmstrip { times, .. } if !times.is_empty() => times.clone(),
        _ => rings::run::even_times(chain.t_end, 7),
    }
}

/// The times a ring scene samples its run at: a movie's frames, a
/// filmstrip's snapshots, a kymograph's rows.
pub fn sample_times(scene: &Scene, chain: &RingChain, movie: &MovieOptions) -> Vec<f64> {
    match scene.output {
        OutputSpec::Movie { .. } => rings::run::even_times(chain.t_end, movie.frames),
        OutputSpec::Filmstrip { .. } => strip_times(scene, chain),
        _ => rings::run::even_times(chain.t_end, draw::KYMOGRAPH_ROWS),
    }
}

/// The run of a ring scene sampled at `times`: the one the render holds
/// for it (made with another output's, `scenes::shared::make_ring_runs`),
/// else its own.
fn run_of(scene: &Scene, chain: &RingChain, times: &[f64]) -> Result<RingRun> {
    super::reuse::or_run(scene, times, super::reuse::Stop::ToEnd, || {
        rings::run(chain, times)
    })
}

/// A ring scene's title: its own, or one made from the chain (the
/// ladder's generated title, "kink, α = 60°", is no chain's).
fn ring_title(scene: &Scene, chain: &RingChain) -> String {
    if scene.title.is_some() {
        return describe::title(scene);
    }
    let body = format!("a ring chain: {}", chain.parameters());
    match &scene.label {
        Some(l) => format!("{l}: {body}"),
        None => body,
    }
}

/// The files of a ring scene, handed to `sink` in [`file_names_for`] order.
pub fn render_to(
    theme: &Theme,
    scene: &Scene,
    movie: &MovieOptions,
    outputs: &Outputs,
    frame_done: &(dyn Fn() + Sync),
    sink: &mut dyn FnMut(&str, Fill<'_>) -> Result<()>,
) -> Result<()> {
    check(scene, movie)?;
    let chain = chain_of(scene)?;
    let title = ring_title(scene, chain);
    let formats = outputs.encoded_figures()?;
    let run = run_of(scene, chain, &sample_times(scene, chain, movie))?;
    let bytes = match scene.output {
        OutputSpec::Movie { .. } => {
            let mut v = movie_bytes(
                theme,
                chain,
                &run,
                &title,
                movie,
                outputs.movies.as_slice(),
                outputs.mp4_quality,
                frame_done,
            )?;
            let kymo_title = scene
                .label
                .as_ref()
                .map_or("kymograph".to_string(), |l| format!("{l}: kymograph"));
            let kymo = draw::kymograph_picture(theme, chain, &run, &kymo_title);
            v.extend(figure_bytes(&kymo, &formats, outputs.scale)?);
            v
        }
        OutputSpec::Filmstrip { .. } => {
            let picture = draw::strip_picture(theme, chain, &run, &title);
            picture.check_print_scale(&theme.style)?;
            figure_bytes(&picture, &formats, outputs.scale)?
        }
        _ => {
            let picture = draw::kymograph_picture(theme, chain, &run, &title);
            figure_bytes(&picture, &formats, outputs.scale)?
        }
    };
    let names = file_names_for(scene, outputs);
    let head = DataFile {
        made_by: super::data::MadeBy::new(&outputs.command_line),
        settings: super::data::Settings::new(scene, movie, outputs),
        title,
        parameters: chain.parameters(),
        fidelity: "simulation",
        files: names.clone(),
        scene,
        runs: Vec::new(),
        drawn: None,
    };
    let file = RingsFile {
        head,
        rings: RingsData::of(&run),
    };
    let (data_name, pictures) = names.split_last().expect("a data file is always named");
    for (name, b) in pictures.iter().zip(&bytes) {
        sink(name, &|w| w.write_all(b))?;
    }
    sink(data_name, &|w| super::data::write_json(w, &file))
}

/// The movie's files: frames drawn in parallel (in order), encoded once.
#[allow(clippy::too_many_arguments)]
fn movie_bytes(
    theme: &Theme,
    chain: &RingChain,
    run: &RingRun,
    title: &str,
    movie: &MovieOptions,
    formats: &[Format],
    quality: Mp4Quality,
    frame_done: &(dyn Fn() + Sync),
) -> Result<Vec<Vec<u8>>> {
    let (w, h) = (movie.width as f32, movie.height as f32);
    let band = if theme.titles {
        theme.title_band()
    } else {
        0.0
    };
    let view = draw::fixed_view(
        theme,
        chain,
        &run.samples,
        (8.0, band),
        w - 16.0,
        h - band - 2.0 * theme.label,
    );
    let mut writer = MovieWriter::with_quality(
        formats,
        (movie.width, movie.height),
        movie.fps,
        theme.palette.gif(),
        quality,
    )?;
    for chunk in run.samples.chunks(32) {
        let frames: Vec<Result<tiny_skia::Pixmap>> = chunk
            .par_iter()
            .map(|s| {
                let mut pixmap = style::white_pixmap(movie.width, movie.height)
                    .ok_or_else(|| Error::failed("cannot allocate a movie frame"))?;
                let mut canvas = Raster::new(&mut pixmap, theme.font());
                draw::draw_frame(&mut canvas, theme, chain, s, &view, title, (w, h));
                frame_done();
                Ok(pixmap)
            })
            .collect();
        for f in frames {
            writer.push_frame(&f?)?;
        }
    }
    Ok(writer.finish()?.into_iter().map(|(_, b)| b).collect())
}

/// A picture of a ring scene (for callers that draw figures themselves).
pub fn figure_picture(theme: &Theme, scene: &Scene) -> Result<Picture> {
    let chain = chain_of(scene)?;
    let title = ring_title(scene, chain);
    match scene.output {
        OutputSpec::Filmstrip { .. } => Ok(draw::strip_picture(
            theme,
            chain,
            &rings::run(chain, &strip_times(scene, chain))?,
            &title,
        )),
        _ => {
            let run = rings::run(
                chain,
                &rings::run::even_times(chain.t_end, draw::KYMOGRAPH_ROWS),
            )?;
            Ok(draw::kymograph_picture(theme, chain, &run, &title))
        }
    }
}
