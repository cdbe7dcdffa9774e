//! A sweep's JSON (docs/sweeps.md): the sweep (scene, axes, rule,
//! fingerprint), the count of each outcome, the linear theory along α,
//! and every run with its arrival times and waves. It is written record by
//! record into the writer given (the output's temporary file), never held
//! whole in memory; and its size, and the CSV's, are estimated from the
//! plan before any run, against the cap on a data file's bytes
//! (docs/limits.md, "Data files and memory").

use super::results::counts;
use super::{Plan, Record};
use crate::limits::LimitExceeded;
use crate::scene::describe;
use crate::scene::sweep::Param;
use serde::{Serialize, Serializer};
use std::io::{self, Write};

#[derive(Serialize)]
struct Axis<'a> {
    param: &'static str,
    values: &'a [f64],
}

#[derive(Serialize)]
struct RunEntry<'a> {
    #[serde(flatten)]
    record: &'a Record,
    /// The varied parameters' values.
    point: serde_json::Map<String, serde_json::Value>,
}

/// The runs, serialized one [`RunEntry`] at a time (each made only as it
/// is written).
struct Runs<'a> {
    plan: &'a Plan,
    records: &'a [Record],
}

impl Serialize for Runs<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.records.iter().map(|r| {
            RunEntry {
                record: r,
                point: self
                    .plan
                    .axes
                    .iter()
                    .zip(&self.plan.points[r.run])
                    .map(|((p, _), v)| (p.name().to_string(), json_number(*v)))
                    .collect(),
            }
        }))
    }
}

#[derive(Serialize)]
struct Rule {
    t_end: f64,
    cap: f64,
    kinetic_tolerance: f64,
    force_tolerance: f64,
    stability_margin: f64,
    description: &'static str,
}

#[derive(Serialize)]
struct SweepData<'a> {
    /// The program, its build and the command line.
    #[serde(flatten)]
    made_by: crate::output::data::MadeBy<'a>,
    title: String,
    parameters: String,
    files: &'a [String],
    fingerprint: &'a str,
    scene: &'a crate::scene::Scene,
    axes: Vec<Axis<'a>>,
    rule: Rule,
    outcomes: serde_json::Map<String, serde_json::Value>,
    /// The linear theory at each α of the grid (when α varies).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    theory: Vec<super::chart::TheoryPoint>,
    runs: Runs<'a>,
}

fn data<'a>(
    plan: &'a Plan,
    records: &'a [Record],
    files: &'a [String],
    command_line: &'a [String],
) -> SweepData<'a> {
    let outcomes = counts(records)
        .into_iter()
        .map(|(o, c)| (o.name().to_string(), c.into()))
        .collect();
    let tol = crate::theory::stability::RestTolerances::default();
    SweepData {
        made_by: crate::output::data::MadeBy::new(command_line),
        title: describe::title(&plan.scene),
        parameters: describe::parameters(&plan.scene),
        files,
        fingerprint: &plan.fingerprint,
        scene: &plan.scene,
        axes: plan
            .axes
            .iter()
            .map(|(p, v)| Axis {
                param: p.name(),
                values: v,
            })
            .collect(),
        rule: Rule {
            t_end: plan.scene.run.t_end,
            cap: plan.spec.cap,
            kinetic_tolerance: tol.kinetic,
            force_tolerance: tol.force,
            stability_margin: tol.margin,
            description: "propagated: the driven wave reached block N-1 (blocks 1 to N-1 \
                          flipped); annihilated: the driven wave (the first from block 1) met a \
                          wall running the other way; otherwise, after the drive, pinned \
                          (front <= 2) or stalled once the state is proved at rest (kinetic \
                          energy and largest residual force under the tolerances) at a linearly \
                          stable equilibrium (smallest mass-weighted eigenvalue of the clamped \
                          Hessian above the margin); undecided at the cap; diverged when the \
                          integration blew up; failed when the run could not start (message) \
                          (docs/sweeps.md). The outcome columns describe blocks 1 to N-1 from \
                          the top (front <= N-1, blocks_flipped of those N-1); speed is the wave \
                          speed c over blocks 3 to N-1; block_n_turned_at is when the free block \
                          N first turned; `waves` has every wave",
        },
        outcomes,
        theory: super::chart::theory_points(plan),
        runs: Runs { plan, records },
    }
}

/// Writes the JSON beside the CSV (`files`: the names of the sweep's
/// files) into `w` as pretty-printed JSON, one run at a time through a
/// buffer.
pub fn write(
    w: &mut dyn Write,
    plan: &Plan,
    records: &[Record],
    files: &[String],
    command_line: &[String],
) -> io::Result<()> {
    crate::output::data::write_json(w, &data(plan, records, files, command_line))
}

/// The exact size of [`write`]'s JSON, counted without keeping it.
pub fn size(
    plan: &Plan,
    records: &[Record],
    files: &[String],
    command_line: &[String],
) -> io::Result<u64> {
    let mut counter = Counter(0);
    write(&mut counter, plan, records, files, command_line)?;
    Ok(counter.0)
}

/// A writer that only counts.
struct Counter(u64);

impl Write for Counter {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.0 += buf.len() as u64;
        Ok(buf.len())
    }
    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

fn json_number(v: f64) -> serde_json::Value {
    serde_json::Number::from_f64(v).map_or(serde_json::Value::Null, serde_json::Value::Number)
}

/// Most bytes one number of a run's lists (an arrival time, `null`)
/// takes in the JSON: up to 14 spaces of indentation (a wave's arrival
/// times; 8 for the run's own), up to 24 characters, a comma and a line
/// break (`crate::output::data::BYTES_PER_VALUE`; measured: 28 and 34
/// bytes for times of 18 characters).
pub const BYTES_PER_VALUE: f64 = crate::output::data::BYTES_PER_VALUE;

/// Bytes of one run's entry beyond its lists of N numbers: its fields,
/// its point and block N's fate (measured: 0.75 kB at N = 10), with room
/// for a message of a few hundred characters (an unverified `auto` run's
/// is 0.12 kB) and a few sign changes of block N.
pub const BYTES_PER_RUN: f64 = 1500.0;

/// Bytes of one wave's entry beyond its arrival times: kind, origin,
/// launch, front and fate (measured: under 0.3 kB).
pub const BYTES_PER_WAVE: f64 = 300.0;

/// Bytes per value of an axis: the value itself, and the linear theory
/// at it when it is an α (measured: under 0.15 kB).
pub const BYTES_PER_AXIS_VALUE: f64 = 200.0;

/// Bytes of the JSON beyond its runs and axes: the program, the command
/// line, the scene, the rule (measured: under 5 kB).
pub const BYTES_FIXED: f64 = 16e3;

/// Bytes of one CSV row with one wave (measured: 73 at N = 10; room for
/// every parameter printed to 17 digits and more columns), and per
/// further wave's five columns (measured: under 70).
pub const CSV_BYTES_PER_RUN: f64 = 400.0;
pub const CSV_BYTES_PER_WAVE: f64 = 100.0;

/// Waves a run is estimated to have: one per flip of the drive, and one
/// pair born elsewhere (the free bottom block's own flip). A run can have
/// more (about 31 a run at N = 40, G = 3e-3, γ = 0.002), and how many is
/// not known before it runs: the files are counted as the runs come in
/// (`front::sweep::run_in_chunks_within`) and when they are written
/// ([`check_size`]), which is where the cap is a bound.
pub fn waves_per_run(plan: &Plan) -> f64 {
    plan.scene.drive.flips.len() as f64 + 2.0
}

/// The estimated bytes of a sweep's files, before any run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// The JSON.
    pub json: f64,
    /// The CSV.
    pub csv: f64,
    /// N summed over the runs.
    pub blocks: f64,
}

/// An estimate of the bytes of `plan`'s JSON and CSV, from the plan alone,
/// an upper bound for runs with at most [`waves_per_run`] waves
/// (docs/limits.md): per run, N × (1 + W) numbers of
/// [`BYTES_PER_VALUE`] (its arrival times and each wave's, W =
/// [`waves_per_run`]), plus [`BYTES_PER_RUN`] and W × [`BYTES_PER_WAVE`];
/// plus [`BYTES_PER_AXIS_VALUE`] per value of the axes and
/// [`BYTES_FIXED`]. The CSV: per run, [`CSV_BYTES_PER_RUN`] plus
/// [`CSV_BYTES_PER_WAVE`] per further wave.
pub fn estimate(plan: &Plan) -> Estimate {
    let n_axis = plan.axes.iter().position(|(p, _)| *p == Param::N);
    let blocks: f64 = match n_axis {
        Some(k) => plan.points.iter().map(|p| p[k]).sum(),
        None => plan.len() as f64 * plan.scene.model.n as f64,
    };
    let runs = plan.len() as f64;
    let waves = waves_per_run(plan);
    let axis_values: f64 = plan.axes.iter().map(|(_, v)| v.len() as f64).sum();
    let json = BYTES_FIXED
        + axis_values * BYTES_PER_AXIS_VALUE
        + runs * (BYTES_PER_RUN + waves * BYTES_PER_WAVE)
        + blocks * (1.0 + waves) * BYTES_PER_VALUE;
    let csv = 1e3 + runs * (CSV_BYTES_PER_RUN + (waves - 1.0) * CSV_BYTES_PER_WAVE);
    Estimate { json, csv, blocks }
}

/// Checks `plan`'s estimated files against its scene's cap on a data
/// file's bytes (`Scene::limits`), before any run.
pub fn check_estimate(plan: &Plan) -> Result<(), LimitExceeded> {
    let limits = &plan.scene.limits;
    let e = estimate(plan);
    let detail = |what: &str| {
        format!(
            "the {what} of sweep {}, {} runs of {} blocks in all",
            plan.scene.name,
            crate::limits::count(plan.len() as f64),
            crate::limits::count(e.blocks)
        )
    };
    limits.check_data_bytes(e.json, || detail("JSON"))?;
    limits.check_data_bytes(e.csv, || detail("CSV"))
}

/// Checks the files about to be written, their sizes counted from the
/// records (`json` and `csv` bytes), against the same cap: runs with
/// more waves than [`estimate`] assumed can pass it after the check
/// before work.
pub fn check_size(plan: &Plan, json: u64, csv: u64) -> Result<(), LimitExceeded> {
    let limits = &plan.scene.limits;
    let detail = |what: &str| {
        format!(
            "the {what} of sweep {}, counted from its {} runs and their waves",
            plan.scene.name,
            crate::limits::count(plan.len() as f64)
        )
    };
    limits.check_data_bytes(json as f64, || detail("JSON"))?;
    limits.check_data_bytes(csv as f64, || detail("CSV"))
}
