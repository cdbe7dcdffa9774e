//! What a rerun of a shard keeps of its earlier file.

use super::{Shard, ShardFile, shards_dir};
use crate::error::{Error, Result};
use crate::sweep::{Plan, Record};
use std::path::Path;

/// What a rerun can keep: the records of an earlier run of the same shard
/// of the same sweep, or why there are none.
pub enum Earlier {
    None,
    /// Kept: the records that belong to this shard.
    Resumed(Vec<Record>),
    /// A file of another sweep (or not a shard file) that will be replaced.
    Stale(String),
}

/// The records already done for `shard` of `plan` under `dir`. A file of
/// this sweep and shard whose records do not check out (a run twice, a run
/// of another shard, absurd values), or a path that is not a regular file,
/// is bad input naming the file: it is not ours to replace.
pub fn earlier(plan: &Plan, shard: Shard, dir: &Path) -> Result<Earlier> {
    let path = shards_dir(dir).join(shard.file_name(&plan.scene.name));
    match std::fs::symlink_metadata(&path) {
        Err(_) => return Ok(Earlier::None),
        Ok(m) if !m.is_file() => {
            return Err(Error::bad_input(format!(
                "{}: not a regular file; ladder reads and replaces only regular shard files",
                path.display()
            )));
        }
        Ok(_) => {}
    }
    let f = match ShardFile::read(&path) {
        Ok(f) => f,
        Err(e) => {
            return Ok(Earlier::Stale(format!(
                "{}: {e}; starting this shard afresh",
                path.display()
            )));
        }
    };
    if f.fingerprint != plan.fingerprint || f.shard != shard {
        return Ok(Earlier::Stale(format!(
            "{} holds another sweep; starting this shard afresh",
            path.display()
        )));
    }
    f.validate(plan).map_err(|m| {
        Error::bad_input(format!(
            "{}: {m}; remove it to run this shard afresh",
            path.display()
        ))
    })?;
    Ok(Earlier::Resumed(f.records))
}
