//! A sweep cut into chunks that a front end hands to workers it does not
//! know (docs/python.md: the Python package's `sweep(..., executor=EX)`,
//! for a process pool, dask, submitit or MPI). A chunk is a shard of the
//! sweep ([`crate::sweep::shard`], round robin over the grid), run on this
//! process's cores and handed back as the bytes of its shard file; the
//! chunks are merged by the code that gathers shards
//! ([`crate::sweep::shard::gather`]), and the tables made from the merged
//! records the one way ([`super::sweep::tables`]). So the tables are, byte
//! for byte, those of the sweep run whole in one process.

use crate::error::{Error, Result};
use crate::scene::Scene;
use crate::sweep::shard::{self, Shard, ShardFile};
use crate::sweep::{Plan, Record};
use std::path::Path;

/// How many chunks a sweep of `runs` runs is cut into when the caller does
/// not say: about 512 runs a chunk (the batch kernel fills its SIMD lanes
/// on every core of a worker), at least one, at most 1000 and at most one
/// a run.
pub fn default_chunks(runs: usize) -> usize {
    runs.div_ceil(512).clamp(1, 1000).min(runs.max(1))
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

/// Merges the chunks (shard files' bytes, in any order) of one sweep by
/// the code that gathers shards: each is written into `dir/shards/` under
/// its shard's name (`dir` a fresh folder of the caller's), then gathered
/// (checked against the sweep's plan: one sweep, no run missing, none
/// twice and different). Returns the sweep's CSV and JSON as text.
pub fn gather(dir: &Path, chunks: &[Vec<u8>], max_runs: usize) -> Result<(String, String)> {
    let sdir = shard::shards_dir(dir);
    std::fs::create_dir_all(&sdir)
        .map_err(|e| Error::failed(format!("cannot make {}: {e}", sdir.display())))?;
    for bytes in chunks {
        let file: ShardFile = serde_json::from_slice(bytes)
            .map_err(|e| Error::failed(format!("a chunk is not a shard file ({e})")))?;
        let path = sdir.join(file.shard.file_name(&file.scene.name));
        crate::output::write_atomic_with(&path, |f| std::io::Write::write_all(f, bytes))?;
    }
    let (plan, records) = shard::gather(dir, max_runs)?;
    super::sweep::tables(&plan, &records)
}

/// The plan of a sweep scene, refused past `max_runs` runs.
fn plan(scene: &Scene, max_runs: usize) -> Result<Plan> {
    super::sweep::plan(scene, max_runs, &|runs| format!("max_runs={runs}"))
}
