//! Writing a shard file within the bytes its reader takes, and the check
//! of its estimate before any run.

use super::{MAX_SHARD_BYTES, Shard, shards_dir};
use crate::error::{Error, Result};
use crate::scene::Scene;
use crate::sweep::{Plan, Record};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// Checks, before any run, that `shard`'s file fits what a reader takes
/// ([`MAX_SHARD_BYTES`]): its estimate is the sweep JSON's estimate
/// (`json::estimate`, a bound for runs of the waves it assumes) shared
/// out by runs. Runs with more waves are caught as the file is written
/// ([`write_records_within`]). Past it, the
/// message names the fewest shards that fit.
pub fn check_estimate(plan: &Plan, shard: Shard) -> Result<()> {
    let runs = plan.len().max(1) as f64;
    let whole = crate::sweep::json::estimate(plan).json;
    let mine = whole * shard.count(plan.len()) as f64 / runs;
    if mine <= MAX_SHARD_BYTES as f64 {
        return Ok(());
    }
    let fewest = (whole / MAX_SHARD_BYTES as f64).ceil() as usize + 1;
    Err(Error::bad_input(format!(
        "shard {}/{} of sweep {} would write about {:.1e} bytes of records, past the {} GiB \
         a shard file may hold; split the sweep into at least {fewest} shards (--shard K/{fewest})",
        shard.k,
        shard.n,
        plan.scene.name,
        mine,
        MAX_SHARD_BYTES >> 30
    )))
}

/// The shard file of `records` (in grid order) for `shard` of `plan`,
/// borrowed: the same fields, in the same order, as [`ShardFile`].
#[derive(Serialize)]
struct ShardRef<'a> {
    program: &'static str,
    version: &'static str,
    fingerprint: &'a str,
    shard: Shard,
    runs_total: usize,
    runs_in_shard: usize,
    scene: &'a Scene,
    records: &'a [Record],
}

/// Writes the shard file of `records` (sorted by run) for `shard` of
/// `plan` under `dir`, atomically, the same bytes as
/// [`ShardFile::new`]'s [`ShardFile::to_bytes`], streamed into the file: neither the records nor
/// the encoded file are copied in memory (a sweep rewrites it after every
/// chunk of runs). A file that would pass [`MAX_SHARD_BYTES`], the most a
/// reader takes, is not written ([`write_records_within`]).
pub fn write_records(dir: &Path, plan: &Plan, shard: Shard, records: &[Record]) -> Result<PathBuf> {
    write_records_within(dir, plan, shard, records, MAX_SHARD_BYTES)
}

/// [`write_records`] with a file of at most `max` bytes: the bytes are
/// counted as they are written, and past `max` the writing stops, the
/// temporary file is removed and the file written before (with the runs
/// of the chunks before) stays, so that no shard file is ever one its
/// reader refuses (a 1.09 GB shard was written, then read as
/// stale and all its runs done again). The error (bad input, exit 2) says
/// how many shards would hold the runs.
pub fn write_records_within(
    dir: &Path,
    plan: &Plan,
    shard: Shard,
    records: &[Record],
    max: u64,
) -> Result<PathBuf> {
    debug_assert!(records.windows(2).all(|w| w[0].run < w[1].run));
    let file = ShardRef {
        program: "ladder",
        version: env!("CARGO_PKG_VERSION"),
        fingerprint: &plan.fingerprint,
        shard,
        runs_total: plan.len(),
        runs_in_shard: shard.count(plan.len()),
        scene: &plan.scene,
        records,
    };
    let path = shards_dir(dir).join(shard.file_name(&plan.scene.name));
    let written = std::cell::Cell::new(0u64);
    let result = crate::output::write_atomic_with(&path, |f| {
        let capped = Capped {
            inner: f,
            written: &written,
            max,
        };
        let mut w = std::io::BufWriter::with_capacity(1 << 16, capped);
        serde_json::to_writer(&mut w, &file).map_err(std::io::Error::other)?;
        std::io::Write::flush(&mut w)
    });
    if written.get() > max {
        return Err(too_large(
            dir,
            plan,
            shard,
            records.len(),
            written.get(),
            max,
        ));
    }
    result?;
    Ok(path)
}

/// A writer that counts and refuses to pass `max` bytes.
struct Capped<'a, W> {
    inner: W,
    written: &'a std::cell::Cell<u64>,
    max: u64,
}

impl<W: std::io::Write> std::io::Write for Capped<'_, W> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        let total = self.written.get() + buf.len() as u64;
        self.written.set(total);
        if total > self.max {
            return Err(std::io::Error::other("the shard file passes its cap"));
        }
        self.inner.write_all(buf)?;
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        self.inner.flush()
    }
}

/// The error of a shard file that would pass `max` bytes with `runs`
/// records (at least `written` bytes): the fewest shards that would hold
/// the whole sweep at the bytes a run took so far.
fn too_large(dir: &Path, plan: &Plan, shard: Shard, runs: usize, written: u64, max: u64) -> Error {
    let per_run = written as f64 / runs.max(1) as f64;
    let whole = per_run * plan.len() as f64;
    let fewest = ((whole / max as f64).ceil() as usize + 1).max(shard.n + 1);
    Error::bad_input(format!(
        "shard {}/{} of sweep {} would pass the {} bytes a shard file may hold with {runs} runs \
         (over {:.1e} bytes a run: more waves than estimated); the runs saved before this \
         chunk, if any, stay in {}; split the sweep into more shards, at least {fewest} (--shard K/{fewest})",
        shard.k,
        shard.n,
        plan.scene.name,
        crate::limits::count(max as f64),
        per_run,
        shards_dir(dir)
            .join(shard.file_name(&plan.scene.name))
            .display(),
    ))
}
