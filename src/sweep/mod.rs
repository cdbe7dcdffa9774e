//! Sweeps (docs/sweeps.md): a scene run over a grid of parameters, every
//! run until its outcome is decided, on every core, results in grid order.
//!
//! - `scene::sweep` holds the data (grid, rule, charts) of a scene whose
//!   `[output] kind = "sweep"`;
//! - [`outcome`] decides what a run's wave did from its arrival times;
//! - [`run`] runs one point with the scene's integrator (`auto` verified);
//! - [`results`] writes the CSV and [`json`] the JSON, byte-identical
//!   between runs; the JSON streamed, both estimated before any run;
//! - [`shard`] splits a sweep over processes or machines, resumes, gathers;
//! - [`chart`] draws the results.
//!
//! Floors: this module knows scenes, the simulation, the theory and the
//! charts; it knows no command-line flag.

pub mod chart;
pub mod chunks;
pub mod columns;
pub mod json;
pub mod outcome;
pub mod results;
pub mod run;
pub mod shard;
pub mod stack;

use crate::error::{Error, Result};
use crate::scene::sweep::{Param, Point, SweepSpec};
use crate::scene::{OutputSpec, Scene};
pub use run::RunResult;
use serde::{Deserialize, Serialize};
use std::fmt;

/// A sweep ready to run: its scene, its axes and points, its fingerprint.
#[derive(Debug, Clone)]
pub struct Plan {
    /// The sweep scene (its output is the sweep).
    pub scene: Scene,
    pub spec: SweepSpec,
    pub axes: Vec<(Param, Vec<f64>)>,
    pub points: Vec<Point>,
    /// A hash of everything that decides the results: the program's
    /// version, the base scene's model, drive and run, the grid's values
    /// and the rule.
    pub fingerprint: String,
}

/// The result of one point, with its index in the grid.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Record {
    pub run: usize,
    #[serde(flatten)]
    pub result: RunResult,
}

/// A grid with more runs than the cap allows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TooManyRuns {
    pub runs: usize,
    pub cap: usize,
}

impl fmt::Display for TooManyRuns {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "this sweep has {} runs, past the cap of {} runs",
            self.runs, self.cap
        )
    }
}

impl Plan {
    /// The plan of a sweep scene, refused past `max_runs` runs. The scene
    /// must have passed `Scene::check`.
    pub fn new(scene: &Scene, max_runs: usize) -> Result<std::result::Result<Plan, TooManyRuns>> {
        let OutputSpec::Sweep(spec) = &scene.output else {
            return Err(Error::bad_input(format!(
                "scene {} is not a sweep ([output] kind = \"sweep\")",
                scene.name
            )));
        };
        scene
            .check()
            .map_err(|(k, m)| Error::bad_input(format!("{k}: {m}")))?;
        let axes = spec
            .axes()
            .map_err(|(k, m)| Error::bad_input(format!("{k}: {m}")))?;
        let runs = axes
            .iter()
            .fold(1usize, |n, (_, v)| n.saturating_mul(v.len()));
        if runs > crate::limits::MAX_SWEEP_RUNS {
            return Err(Error::bad_input(format!(
                "this sweep has {} runs; a sweep holds at most {} runs in memory (docs/limits.md), whatever its cap: split the grid into several sweeps",
                crate::limits::count(runs as f64),
                crate::limits::count(crate::limits::MAX_SWEEP_RUNS as f64)
            )));
        }
        if runs > max_runs {
            return Ok(Err(TooManyRuns {
                runs,
                cap: max_runs,
            }));
        }
        let points = spec
            .points()
            .map_err(|(k, m)| Error::bad_input(format!("{k}: {m}")))?;
        let fingerprint = fingerprint(scene, spec, &axes)?;
        Ok(Ok(Plan {
            scene: scene.clone(),
            spec: spec.clone(),
            axes,
            points,
            fingerprint,
        }))
    }

    pub fn len(&self) -> usize {
        self.points.len()
    }

    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The single-run scene of run `i`.
    pub fn scene_at(&self, i: usize) -> Scene {
        self.spec.scene_at(&self.scene, &self.points[i])
    }

    /// The axes with more than one value (what the charts vary).
    pub fn varied(&self) -> Vec<(usize, Param, &[f64])> {
        self.axes
            .iter()
            .enumerate()
            .filter(|(_, (_, v))| v.len() > 1)
            .map(|(k, (p, v))| (k, *p, v.as_slice()))
            .collect()
    }

    /// Runs the points `indices` on every core, many at once through the
    /// batch kernel (`run::run_points`); results in the order of
    /// `indices`. `done` is called once per finished run (progress), when
    /// the whole batch has finished.
    pub fn run(&self, indices: &[usize], done: &(dyn Fn() + Sync)) -> Result<Vec<Record>> {
        let scenes: Vec<Scene> = indices.iter().map(|&i| self.scene_at(i)).collect();
        let results = run::run_points(&scenes, &self.spec)?;
        Ok(indices
            .iter()
            .zip(results)
            .map(|(&i, result)| {
                done();
                Record { run: i, result }
            })
            .collect())
    }
}

/// What a sweep's results depend on, hashed (FNV-1a, 64 bits, hex).
fn fingerprint(scene: &Scene, spec: &SweepSpec, axes: &[(Param, Vec<f64>)]) -> Result<String> {
    #[derive(Serialize)]
    struct Key<'a> {
        version: &'static str,
        model: &'a crate::scene::Model,
        drive: &'a crate::scene::DriveSpec,
        run: &'a crate::scene::Run,
        axes: Vec<(&'static str, &'a [f64])>,
        rule: &'static str,
        cap: f64,
    }
    let key = Key {
        version: env!("CARGO_PKG_VERSION"),
        model: &scene.model,
        drive: &scene.drive,
        run: &scene.run,
        axes: axes.iter().map(|(p, v)| (p.name(), v.as_slice())).collect(),
        rule: "rest-proof; driven wave; failed points",
        cap: spec.cap,
    };
    let text = serde_json::to_string(&key)
        .map_err(|e| Error::failed(format!("cannot encode the sweep's fingerprint: {e}")))?;
    Ok(format!("{:016x}", fnv1a(text.as_bytes())))
}

/// FNV-1a, 64 bits.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// The files of a sweep's results under `stem` (`sweep-NAME` or
/// `figure-NAME`), each handed to `sink` (its name, how to write it): the
/// chart in each of `formats` (when one or two parameters vary; PNG at
/// `scale`), the CSV and the JSON, in that order, every name passed
/// through `rename` first. The JSON is written straight into where `sink`
/// writes it, never held whole in memory. Before anything is handed over,
/// the CSV's and the JSON's sizes (counted from the records) are checked
/// against the cap on a data file's bytes. Returns the names.
pub fn write_outputs(
    plan: &Plan,
    records: &[Record],
    stem: &str,
    output: &OutputOptions<'_>,
    sink: &mut dyn FnMut(&str, crate::output::data::Fill<'_>) -> Result<()>,
) -> Result<Vec<String>> {
    // On the style's page (a slide: no taller than the slide); too small
    // a page is refused naming the smallest that holds the chart.
    let (picture, charted) = crate::render::fitted(&output.theme, |theme| {
        Ok(match chart::chart(theme, plan, records)? {
            Some(c) => (
                crate::render::Picture::from(c)
                    .fit_page()
                    .titled(crate::scene::describe::title(&plan.scene)),
                true,
            ),
            None => (crate::render::Picture::new(theme, 1.0, 1.0), false),
        })
    })?;
    let mut names = Vec::new();
    let mut pictures = Vec::new();
    if charted {
        for (f, bytes) in output
            .formats
            .as_slice()
            .iter()
            .zip(picture.encode(output.formats, output.scale)?)
        {
            names.push((output.rename)(format!("{stem}.{}", f.extension())));
            pictures.push(bytes);
        }
    }
    names.push((output.rename)(format!("{stem}.csv")));
    names.push((output.rename)(format!("{stem}.json")));
    let csv = results::csv(plan, records);
    let json_bytes = json::size(plan, records, &names, output.command_line)
        .map_err(|e| Error::failed(format!("cannot encode the sweep's data file: {e}")))?;
    json::check_size(plan, json_bytes, csv.len() as u64)?;
    for (name, bytes) in names.iter().zip(&pictures) {
        sink(name, &|w| w.write_all(bytes))?;
    }
    drop(pictures);
    let [.., csv_name, json_name] = names.as_slice() else {
        unreachable!("the CSV and the JSON are always named")
    };
    sink(csv_name, &|w| w.write_all(csv.as_bytes()))?;
    sink(json_name, &|w| {
        json::write(w, plan, records, &names, output.command_line)
    })?;
    Ok(names)
}

/// How a sweep's files are drawn and named ([`write_outputs`]).
pub struct OutputOptions<'a> {
    /// The chart's formats.
    pub formats: &'a crate::encode::Formats,
    /// The PNG's scale.
    pub scale: f32,
    /// The command line the JSON records.
    pub command_line: &'a [String],
    /// What each file is called (the catalogue renames a preview PNG).
    pub rename: &'a dyn Fn(String) -> String,
    /// The theme the chart is drawn with (its style's page, font and sizes).
    pub theme: crate::render::Theme,
}

/// The plan of a sweep scene rendered as a figure ([`render_to`]), with
/// every check made before its runs: its runs against the default cap,
/// its files' estimated bytes against the scene's cap. `render --check`
/// makes them too.
pub fn checked(scene: &Scene) -> Result<Plan> {
    let plan = Plan::new(scene, crate::scene::sweep::DEFAULT_MAX_RUNS)?.map_err(|e| {
        Error::bad_input(format!(
            "{e}; run it with `ladder sweep FILE --max-runs N` to raise the cap"
        ))
    })?;
    json::check_estimate(&plan)?;
    Ok(plan)
}

/// Runs a whole sweep scene in this process (no shards, no resume) and
/// hands its files under `figure-NAME` (a catalogue figure) to `sink`
/// ([`write_outputs`]). Its runs and its files' estimated bytes are
/// checked against their caps before any run.
pub fn render_to(
    scene: &Scene,
    output: &OutputOptions<'_>,
    sink: &mut dyn FnMut(&str, crate::output::data::Fill<'_>) -> Result<()>,
) -> Result<Vec<String>> {
    let plan = checked(scene)?;
    let all: Vec<usize> = (0..plan.len()).collect();
    // A chunk at a time, its files counted against the cap after each
    // (`chunks`): the runs may take more bytes than estimated.
    let mut records = Vec::new();
    chunks::run_in_chunks_within(&plan, &all, &mut records, &|| {}, &mut |_| Ok(()), Some(""))?;
    write_outputs(&plan, &records, &scene.stem(), output, sink)
}
