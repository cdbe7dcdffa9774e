//! A sweep's runs made a chunk at a time (docs/sweeps.md), its files
//! counted against the cap on a data file's bytes after each chunk, so
//! that a sweep whose runs take more bytes than estimated stops after the
//! first chunk that passes the cap, not after all its runs.

use super::{Plan, Record};
use crate::error::{Error, Result};
use std::time::{Duration, Instant};

/// Runs `todo` (run indices of `plan`) in chunks, adding each chunk's
/// records to `done` (kept in run order) and handing `done` to
/// `checkpoint` after every chunk but the last; `tick` after each run.
/// With `count_files` (a process that writes the
/// sweep's CSV and JSON, not one shard of it; the text is added to the
/// message, e.g. where the runs are kept), after every chunk the
/// JSON and the CSV of the runs done so far are counted (encoded into a
/// counter, not kept) against the cap on a data file's bytes
/// (`--max-data-bytes`, the plan's `Scene::limits`). Runs can have more
/// waves than the estimate before work assumed (walls born in the bulk),
/// and no bound on the waves is known before a run, so this is where the
/// bound holds: past the cap, `done` is handed to `checkpoint` (the runs
/// are kept, and a rerun with a raised cap resumes them) and the sweep
/// stops with the cap's error. The records held in memory take about the
/// bytes of that JSON (16 bytes a number, 14 to 34 in the JSON: at most
/// 16/14 of it), so the cap bounds the sweep's memory too, up to one
/// chunk; near the cap
/// the chunks shrink to the runs that the room left holds at the largest
/// bytes a run has taken.
pub fn run_in_chunks_within(
    plan: &Plan,
    todo: &[usize],
    done: &mut Vec<Record>,
    tick: &(dyn Fn() + Sync),
    checkpoint: &mut dyn FnMut(&[Record]) -> Result<()>,
    count_files: Option<&str>,
) -> Result<()> {
    let limits = plan.scene.limits;
    let cap = limits.cap(crate::limits::Resource::DataBytes);
    let threads = rayon::current_num_threads().max(1);
    // Runs go through the batch kernel a chunk at a time (one run per SIMD
    // lane): start with enough to fill every core's lanes several times;
    // where the files are counted against a cap on bytes, with one run a
    // core, as no run's bytes are known before it (a run can hold many
    // times the waves the estimate assumes), so that the first chunk
    // to pass the cap is a small one; later chunks grow (doubling) within
    // the room the cap leaves at the most bytes a run has taken.
    let mut chunk = if count_files.is_some() && cap.is_finite() {
        threads
    } else {
        (64 * threads).max(128)
    };
    let mut at = 0;
    // The largest JSON bytes one run has taken so far.
    let mut per_run: f64 = 0.0;
    while at < todo.len() {
        let end = (at + chunk).min(todo.len());
        let t0 = Instant::now();
        let records = plan.run(&todo[at..end], tick)?;
        done.extend(records);
        done.sort_by_key(|r| r.run);
        at = end;
        let mut room = usize::MAX;
        if let Some(note) = count_files {
            let (json, csv) = counted(plan, done)?;
            per_run = per_run.max(json as f64 / done.len().max(1) as f64);
            let detail = |what: &str| {
                format!(
                    "the {what} of sweep {}, counted from the {} runs done so far of {}{note}",
                    plan.scene.name,
                    done.len(),
                    plan.len()
                )
            };
            let over = limits
                .check_data_bytes(json as f64, || detail("JSON"))
                .and_then(|()| limits.check_data_bytes(csv as f64, || detail("CSV")));
            if let Err(e) = over {
                checkpoint(done)?;
                return Err(e.into());
            }
            if cap.is_finite() && per_run > 0.0 {
                room = ((cap - json as f64) / per_run).floor().max(1.0) as usize;
            }
        }
        if at < todo.len() {
            checkpoint(done)?;
            // Chunks of a few seconds: frequent checkpoints, few rewrites.
            if t0.elapsed() < Duration::from_secs(2) {
                chunk = (2 * chunk).min(4096);
            }
            // Near the cap, no chunk larger than the room left holds.
            chunk = chunk.min(room).max(1);
        }
    }
    Ok(())
}

/// The bytes of the JSON and the CSV of `records` (the sweep's files,
/// counted, not kept).
fn counted(plan: &Plan, records: &[Record]) -> Result<(u64, u64)> {
    let stem = format!("sweep-{}", plan.scene.name);
    let names = [
        format!("{stem}.png"),
        format!("{stem}.csv"),
        format!("{stem}.json"),
    ];
    let json = crate::sweep::json::size(plan, records, &names, &[])
        .map_err(|e| Error::failed(format!("cannot encode the sweep's data file: {e}")))?;
    Ok((json, crate::sweep::results::csv(plan, records).len() as u64))
}
