//! A sweep as both front ends run it (docs/sweeps.md): planned within the
//! cap on runs, its files' bytes estimated before any run, run in chunks
//! (each chunk handed back, for a shard file to keep it or a stop to be
//! noticed between chunks), and its tables made the one way.

use crate::error::{Error, Result};
use crate::scene::Scene;
use crate::scenes::Outputs;
use crate::sweep::{Plan, Record};
use std::path::Path;

/// The plan of `scene`'s sweep, refused past `max_runs` runs with a hint
/// that raises the cap in the front end's words (`raise` gets the runs
/// asked: `--max-runs 120`, `max_runs=120`).
pub fn plan(scene: &Scene, max_runs: usize, raise: &dyn Fn(usize) -> String) -> Result<Plan> {
    Plan::new(scene, max_runs)?.map_err(|e| {
        Error::bad_input(format!(
            "{e}; ask for fewer, or raise the cap with {}",
            raise(e.runs)
        ))
    })
}

/// The names of a sweep's result files (`crate::sweep::outputs`): the
/// chart in each format when one or two parameters vary, the CSV, the
/// JSON.
pub fn result_names(plan: &Plan, outputs: &Outputs) -> Vec<String> {
    let stem = format!("sweep-{}", plan.scene.name);
    let mut names: Vec<String> = if plan.varied().len() <= 2 {
        outputs.figures.file_names(&stem)
    } else {
        Vec::new()
    };
    names.push(format!("{stem}.csv"));
    names.push(format!("{stem}.json"));
    names
}

/// Runs `todo` (run indices of `plan`) in chunks, adding each chunk's
/// records to `done` (kept in run order) and handing `done` to
/// `checkpoint` after every chunk but the last (a shard file rewritten,
/// or a stop asked for noticed); `tick` after each run. The sweep's
/// files are counted as the runs come in ([`run_in_chunks_within`]).
pub fn run_in_chunks(
    plan: &Plan,
    todo: &[usize],
    done: &mut Vec<Record>,
    tick: &(dyn Fn() + Sync),
    checkpoint: &mut dyn FnMut(&[Record]) -> Result<()>,
) -> Result<()> {
    run_in_chunks_within(plan, todo, done, tick, checkpoint, Some(""))
}

pub use crate::sweep::chunks::run_in_chunks_within;

/// Writes the result files of a whole sweep into `out` (`sweep-NAME.png`,
/// or .svg, .pdf, when one or two parameters vary; `.csv`; `.json`), each
/// atomically; returns their names. The files depend on the sweep only:
/// not on the program's path, the output folder, or whether the runs came
/// from shards, so their JSON records no command line (its scene reruns
/// it: `ladder sweep FILE`).
pub fn write_outputs(
    plan: &Plan,
    records: &[Record],
    out: &Path,
    outputs: &Outputs,
) -> Result<Vec<String>> {
    let stem = format!("sweep-{}", plan.scene.name);
    let options = crate::sweep::OutputOptions {
        formats: &outputs.figures,
        scale: outputs.scale,
        command_line: &[],
        rename: &|name| name,
        theme: crate::render::Theme::of(&crate::scenes::style_of(&plan.scene, outputs)?),
    };
    crate::sweep::write_outputs(plan, records, &stem, &options, &mut |name, fill| {
        crate::output::write_atomic_with(&out.join(name), |f| fill(f))
    })
}

/// The CSV and the JSON of a whole sweep as text, the bytes
/// [`write_outputs`] writes into files (for a front end that hands them
/// over in memory).
pub fn tables(plan: &Plan, records: &[Record]) -> Result<(String, String)> {
    let stem = format!("sweep-{}", plan.scene.name);
    let names = [format!("{stem}.csv"), format!("{stem}.json")];
    let mut bytes = Vec::new();
    crate::sweep::json::write(&mut bytes, plan, records, &names, &[])
        .map_err(|e| Error::failed(format!("cannot encode the sweep's data file: {e}")))?;
    let json = String::from_utf8(bytes)
        .map_err(|_| Error::failed("the sweep's data file is not UTF-8"))?;
    Ok((crate::sweep::results::csv(plan, records), json))
}
