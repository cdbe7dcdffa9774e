//! Scene → files: runs a scene (`run`) and renders it into the bytes of
//! its files, with the data file beside them. `theory` draws the static
//! figures (geometry, formulas, linear theory); `dynamic` the simulated
//! figures and the movies.

pub mod dynamic;
pub mod run;
pub mod theory;

use crate::encode::png_bytes;
use crate::error::{Error, Result};
use crate::scene::{OutputSpec, Scene, describe};
pub use dynamic::{MovieOptions, RunData};
use serde::Serialize;

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

/// The file names a scene writes, data file last.
pub fn file_names(scene: &Scene) -> Vec<String> {
    let stem = scene.stem();
    let mut names = match scene.output {
        OutputSpec::Movie { .. } => vec![format!("{stem}.gif"), format!("{stem}-kymograph.png")],
        OutputSpec::Data => vec![],
        OutputSpec::Sweep(_) => vec![format!("{stem}.png"), format!("{stem}.csv")],
        _ => vec![format!("{stem}.png")],
    };
    names.push(format!("{stem}.json"));
    names
}

/// The files of one scene, as (file name, bytes), in [`file_names`] order.
pub fn render(scene: &Scene, movie: &MovieOptions) -> Result<Vec<(String, Vec<u8>)>> {
    render_observed(scene, movie, &|| {})
}

/// As [`render`], calling `frame_done` after each movie frame (for a
/// progress bar).
pub fn render_observed(
    scene: &Scene,
    movie: &MovieOptions,
    frame_done: &(dyn Fn() + Sync),
) -> Result<Vec<(String, Vec<u8>)>> {
    if let OutputSpec::Sweep(_) = scene.output {
        // Its own data file: the sweep's JSON (crate::sweep::results).
        return crate::sweep::render(scene);
    }
    let (mut bytes, runs) = match &scene.output {
        OutputSpec::Theory(spec) => {
            let input = theory::FigureInput::new(describe::title(scene), &scene.model, spec);
            (
                vec![png_bytes(&theory::render(spec.figure, &input)?)?],
                vec![],
            )
        }
        OutputSpec::Filmstrip { .. } => {
            let (image, runs) = dynamic::filmstrip_figure(scene, None)?;
            (vec![png_bytes(&image)?], runs)
        }
        OutputSpec::Arrivals { .. } => {
            let (image, runs) = dynamic::arrivals_figure(scene)?;
            (vec![png_bytes(&image)?], runs)
        }
        OutputSpec::Kymograph => {
            let (image, run) = dynamic::kymograph_figure(scene, KYMOGRAPH_ROWS)?;
            (vec![png_bytes(&image)?], vec![run])
        }
        OutputSpec::Movie { .. } => {
            let (gif, kymo, run) = dynamic::movie_observed(scene, movie, frame_done)?;
            (vec![gif, kymo], vec![run])
        }
        OutputSpec::Data => {
            let run = run::simulate(scene, &[])?;
            (vec![], vec![RunData::from_run(scene, &run)])
        }
        OutputSpec::Sweep(_) => return crate::sweep::render(scene),
    };
    let names = file_names(scene);
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
