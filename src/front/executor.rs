//! A sweep cut into chunks that a front end hands to workers it does not
//! know (docs/python.md: the Python package's `sweep(..., executor=EX)`,
//! for a process pool, dask, submitit or MPI). A chunk is a shard of the
//! sweep ([`crate::sweep::shard`], round robin over the grid), run on this
//! process's cores and handed back as the bytes of its shard file; each
//! chunk is checked against the sweep it was sent for as it comes back
//! ([`check_chunk`]: its fingerprint, its chunk, every record), and the
//! tables are made from the merged records the one way
//! ([`super::sweep::tables`]). So the tables are, byte for byte, those of
//! the sweep run whole in one process.

use crate::error::{Error, Result};
use crate::scene::Scene;
use crate::scene::sweep::Param;
use crate::sweep::shard::{self, Shard, ShardFile};
use crate::sweep::{Plan, Record};

/// Runs a chunk holds when the caller does not say how many chunks: few
/// enough that the batch kernel fills its SIMD lanes on a worker's cores,
/// many enough that the chunks coming back show the sweep's progress.
pub const CHUNK_RUNS: usize = 64;
/// Fewest chunks a sweep is cut into when the caller does not say (fewer
/// only when it has fewer runs): a sweep of 2040 runs cut in 4 showed
/// "processing: 4" on dask's dashboard from start to end.
pub const MIN_CHUNKS: usize = 16;

/// How many chunks a sweep of `runs` runs is cut into when the caller does
/// not say: about [`CHUNK_RUNS`] runs a chunk, at least [`MIN_CHUNKS`]
/// (at most one a run), at most 1000.
pub fn default_chunks(runs: usize) -> usize {
    runs.div_ceil(CHUNK_RUNS)
        .max(runs.min(MIN_CHUNKS))
        .clamp(1, 1000)
}

/// Checks a number of chunks for a sweep of `runs` runs.
pub fn check_chunks(chunks: usize, runs: usize) -> Result<()> {
    if chunks == 0 || chunks > shard::MAX_SHARDS || chunks > runs.max(1) {
        return Err(Error::bad_input(format!(
            "chunks: must be from 1 to the sweep's {} runs (and at most {}), got {chunks}",
            runs,
            shard::MAX_SHARDS
        )));
    }
    Ok(())
}

/// Runs chunk `k` of `chunks` (1-based) of the sweep scene `scene` (its
/// plan refused past `max_runs` runs, as the whole sweep's is) and returns
/// its shard file's bytes. `tick` after each run; `between` between the
/// batches of runs (where a stop asked for is noticed).
pub fn run_chunk(
    scene: &Scene,
    max_runs: usize,
    k: usize,
    chunks: usize,
    tick: &(dyn Fn() + Sync),
    between: &dyn Fn(),
) -> Result<Vec<u8>> {
    let plan = plan(scene, max_runs)?;
    check_chunks(chunks, plan.len())?;
    if k == 0 || k > chunks {
        return Err(Error::bad_input(format!(
            "chunk {k} of {chunks}: chunks are numbered from 1 to {chunks}"
        )));
    }
    let shard = Shard { k, n: chunks };
    shard::check_estimate(&plan, shard)?;
    let todo = shard.indices(plan.len());
    let mut records: Vec<Record> = Vec::with_capacity(todo.len());
    super::sweep::run_in_chunks(&plan, &todo, &mut records, tick, &mut |_| {
        between();
        Ok(())
    })?;
    ShardFile::new(&plan, shard, records).to_bytes()
}

/// The grid points of chunk `chunk`: each run's index and the value of
/// every axis at it (in the axes' order).
pub fn chunk_points(plan: &Plan, chunk: Shard) -> Vec<(usize, Vec<(Param, f64)>)> {
    chunk
        .indices(plan.len())
        .into_iter()
        .map(|i| {
            let at = plan
                .axes
                .iter()
                .map(|(p, _)| *p)
                .zip(plan.points[i].iter().copied());
            (i, at.collect())
        })
        .collect()
}

/// Reads chunk `chunk`'s bytes as a worker returned them and checks them
/// against the sweep `plan` they were sent for: a shard file of this
/// program and version, of this sweep (its fingerprint: a cached chunk of
/// an earlier sweep is refused), of this chunk, complete, every record
/// checked ([`ShardFile::validate`]). The error (a failed run) names the
/// chunk and what is wrong.
pub fn check_chunk(plan: &Plan, chunk: Shard, bytes: &[u8]) -> Result<ShardFile> {
    let Shard { k, n } = chunk;
    let bad = |what: String| Error::failed(format!("chunk {k} of {n}: {what}"));
    let file: ShardFile = serde_json::from_slice(bytes).map_err(|e| {
        bad(format!(
            "what the worker returned is not a chunk of a sweep ({e})"
        ))
    })?;
    let version = env!("CARGO_PKG_VERSION");
    if file.program != "ladder" || file.version != version {
        return Err(bad(format!(
            "made by {} {}, not by this ladder {version}: install one version on every worker",
            file.program, file.version
        )));
    }
    if file.fingerprint != plan.fingerprint {
        return Err(bad(format!(
            "made for another sweep (fingerprint {}; this sweep's is {}): the executor returned \
             an earlier sweep's chunk (a cache?) or an edited one",
            file.fingerprint, plan.fingerprint
        )));
    }
    if file.shard != chunk {
        return Err(bad(format!(
            "holds chunk {} of {}, not the chunk sent",
            file.shard.k, file.shard.n
        )));
    }
    file.validate(plan).map_err(bad)?;
    if !file.complete() {
        return Err(bad(format!(
            "holds {} of its {} runs",
            file.records.len(),
            file.runs_in_shard
        )));
    }
    Ok(file)
}

/// The records of the sweep `plan` from its `chunks` chunks' bytes
/// (chunk number, bytes; in any order), each checked
/// ([`check_chunk`]); every chunk must be there once. In grid order.
pub fn gather_chunks(plan: &Plan, chunks: &[(usize, Vec<u8>)], n: usize) -> Result<Vec<Record>> {
    check_chunks(n, plan.len())?;
    let mut seen = vec![false; n];
    let mut records = Vec::with_capacity(plan.len());
    for (k, bytes) in chunks {
        if *k == 0 || *k > n || std::mem::replace(&mut seen[*k - 1], true) {
            return Err(Error::failed(format!(
                "chunk {k} of {n}: given twice, or not a chunk of {n}"
            )));
        }
        records.extend(check_chunk(plan, Shard { k: *k, n }, bytes)?.records);
    }
    let missing: Vec<String> = (1..=n)
        .filter(|k| !seen[k - 1])
        .map(|k| k.to_string())
        .collect();
    if !missing.is_empty() {
        return Err(Error::failed(format!(
            "chunks {} of {n} are missing",
            missing.join(", ")
        )));
    }
    records.sort_by_key(|r| r.run);
    Ok(records)
}

/// The plan of a sweep scene, refused past `max_runs` runs.
pub fn plan(scene: &Scene, max_runs: usize) -> Result<Plan> {
    super::sweep::plan(scene, max_runs, &|runs| format!("max_runs={runs}"))
}
