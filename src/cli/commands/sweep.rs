//! `ladder sweep` (docs/sweeps.md): run a sweep, or one shard of it, with
//! resume; `ladder sweep gather DIR` merges the shards. Everything the
//! user typed is validated before anything is written.

use crate::cli::args::{SweepArgs, SweepCommand};
use crate::cli::commands::Call;
use crate::cli::convert;
use crate::error::{Error, Result};
use crate::front;
use crate::scenes::Outputs;
use crate::sweep::shard::{self, Earlier, Shard};
use crate::sweep::{Plan, Record};
use std::path::Path;
use std::time::Instant;

pub fn sweep(args: &SweepArgs, call: &Call<'_>) -> Result<()> {
    let recorded = |outputs: Outputs| Outputs {
        command_line: call.command_line.to_vec(),
        ..outputs
    };
    if let Some(SweepCommand::Gather {
        dir, figure_format, ..
    }) = &args.command
    {
        return gather(
            dir,
            &recorded(figure_format.outputs()?),
            args.max_runs,
            call,
        );
    }
    let outputs = recorded(args.figure_format.outputs()?);
    let scene = call.capped_one(convert::sweep_scene(args)?);
    let plan = front::sweep::plan(&scene, args.max_runs, &|runs| format!("--max-runs {runs}"))?;
    let shard = match &args.shard {
        Some(s) => Shard::parse(s).map_err(|m| Error::bad_input(format!("--shard: {m}")))?,
        None => Shard::WHOLE,
    };
    let out = &args.out.out;
    let sdir = shard::shards_dir(out);
    // Every target before any run: the shard file, and (unsharded) the
    // results.
    let mut targets = vec![sdir.join(shard.file_name(&plan.scene.name))];
    if args.shard.is_none() {
        targets.extend(
            front::sweep::result_names(&plan, &outputs)
                .iter()
                .map(|n| out.join(n)),
        );
    }
    let fresh = !sdir.exists();
    let result = check_and_run(args, &plan, shard, &targets, &outputs);
    if result.is_err() && fresh {
        // A refused or failed sweep leaves no empty shards/ of ours.
        let _ = std::fs::remove_dir(&sdir);
    }
    result
}

fn check_and_run(
    args: &SweepArgs,
    plan: &Plan,
    shard: Shard,
    targets: &[std::path::PathBuf],
    outputs: &Outputs,
) -> Result<()> {
    if args.shard.is_none() {
        // The CSV and JSON this process will write, before anything.
        crate::sweep::json::check_estimate(plan)?;
    }
    // Every sweep keeps its runs in a shard file (one for the whole).
    shard::check_estimate(plan, shard)?;
    crate::output::check_targets(targets)?;
    let out = &args.out.out;
    let mine = shard.indices(plan.len());
    let mut done: Vec<Record> = match shard::earlier(plan, shard, out)? {
        Earlier::None => Vec::new(),
        Earlier::Resumed(r) => {
            if !r.is_empty() {
                eprintln!(
                    "ladder: resuming shard {}/{}: {} of {} runs already done",
                    shard.k,
                    shard.n,
                    r.len(),
                    mine.len()
                );
            }
            r
        }
        Earlier::Stale(why) => {
            eprintln!("ladder: {why}");
            Vec::new()
        }
    };
    let start = Instant::now();
    let todo: Vec<usize> = mine
        .iter()
        .copied()
        .filter(|i| done.binary_search_by_key(i, |r| r.run).is_err())
        .collect();
    // The whole sweep's files are counted as the runs come in; a shard's
    // file is checked as it is written.
    let note = format!(
        "; they are kept in {}, and a rerun with a higher cap resumes them",
        shard::shards_dir(out).display()
    );
    run_in_chunks(
        plan,
        shard,
        out,
        &todo,
        &mut done,
        args.shard.is_none().then_some(note.as_str()),
    )?;
    let path = shard::write_records(out, plan, shard, &done)?;
    if args.shard.is_some() {
        eprintln!(
            "ladder: shard {}/{} of sweep {}: {} runs ({} new) in {:.2} s → {}; when every shard is done: ladder sweep gather {}",
            shard.k,
            shard.n,
            plan.scene.name,
            mine.len(),
            todo.len(),
            start.elapsed().as_secs_f64(),
            path.display(),
            out.display()
        );
        return Ok(());
    }
    write_outputs(plan, &done, out, outputs, start)
}

/// Runs `todo` in chunks ([`front::sweep::run_in_chunks_within`],
/// counting the sweep's files with `count_files`), rewriting the shard
/// file after each (so that a killed run loses at most one chunk), with a
/// progress bar.
fn run_in_chunks(
    plan: &Plan,
    shard: Shard,
    out: &Path,
    todo: &[usize],
    done: &mut Vec<Record>,
    count_files: Option<&str>,
) -> Result<()> {
    let bar = crate::cli::progress::progress_bar(todo.len() as u64, "sweep");
    let result = front::sweep::run_in_chunks_within(
        plan,
        todo,
        done,
        &|| bar.inc(1),
        &mut |done| shard::write_records(out, plan, shard, done).map(drop),
        count_files,
    );
    bar.finish_and_clear();
    result
}

/// The result files of a whole sweep, and what they say.
fn write_outputs(
    plan: &Plan,
    records: &[Record],
    out: &Path,
    outputs: &Outputs,
    start: Instant,
) -> Result<()> {
    let names = front::sweep::write_outputs(plan, records, out, outputs)?;
    let counts: Vec<String> = crate::sweep::results::counts(records)
        .iter()
        .map(|(o, c)| format!("{c} {o}"))
        .collect();
    eprintln!(
        "ladder: sweep {}: {} runs ({}) in {:.2} s; wrote {} into {}",
        plan.scene.name,
        records.len(),
        counts.join(", "),
        start.elapsed().as_secs_f64(),
        names.join(", "),
        out.display()
    );
    if plan.varied().len() > 2 {
        eprintln!(
            "ladder: no chart: {} parameters vary (a chart shows one or two)",
            plan.varied().len()
        );
    }
    Ok(())
}

/// `ladder sweep gather DIR`.
fn gather(dir: &Path, outputs: &Outputs, max_runs: usize, call: &Call<'_>) -> Result<()> {
    let start = Instant::now();
    let (mut plan, records) = shard::gather(dir, max_runs)?;
    // The shards' scene, within this command's caps.
    plan.scene = call.capped_one(plan.scene);
    write_outputs(&plan, &records, dir, outputs, start)
}
