//! A shard file: which sweep, which shard, and the runs done so far; and
//! the reader that takes only a regular file of bounded size.

use super::Shard;
use crate::error::{Error, Result};
use crate::scene::Scene;
use crate::sweep::{Plan, Record};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// A shard file: which sweep, which shard, and the runs done so far.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ShardFile {
    pub program: String,
    pub version: String,
    pub fingerprint: String,
    pub shard: Shard,
    /// Runs of the whole sweep.
    pub runs_total: usize,
    /// Runs of this shard.
    pub runs_in_shard: usize,
    /// The sweep scene, so that gather needs nothing else.
    pub scene: Scene,
    /// Finished runs, in grid order.
    pub records: Vec<Record>,
}

impl ShardFile {
    pub fn new(plan: &Plan, shard: Shard, mut records: Vec<Record>) -> Self {
        records.sort_by_key(|r| r.run);
        Self {
            program: "ladder".into(),
            version: env!("CARGO_PKG_VERSION").into(),
            fingerprint: plan.fingerprint.clone(),
            shard,
            runs_total: plan.len(),
            runs_in_shard: shard.count(plan.len()),
            scene: plan.scene.clone(),
            records,
        }
    }

    pub fn complete(&self) -> bool {
        self.records.len() == self.runs_in_shard
    }

    pub fn to_bytes(&self) -> Result<Vec<u8>> {
        serde_json::to_vec(self)
            .map_err(|e| Error::failed(format!("cannot encode a shard file: {e}")))
    }

    /// Reads a shard file; the reason when it is not one. Only a regular
    /// file of at most [`MAX_SHARD_BYTES`] is read (a FIFO, a device or a
    /// link to one is refused without blocking).
    pub fn read(path: &Path) -> std::result::Result<ShardFile, String> {
        let bytes = read_bounded(path, MAX_SHARD_BYTES)?;
        serde_json::from_slice(&bytes).map_err(|e| format!("not a ladder shard file ({e})"))
    }
}

/// Largest shard file read: 1 GiB (a shard of 100,000 runs of N = 1000
/// holds about 0.5 GB of arrival times).
pub const MAX_SHARD_BYTES: u64 = 1 << 30;

/// The bytes of `path` when it is a regular file (after links) of at most
/// `max` bytes. Opened without blocking, so a FIFO cannot hang the reader.
pub fn read_bounded(path: &Path, max: u64) -> std::result::Result<Vec<u8>, String> {
    use std::io::Read;
    let mut opts = std::fs::OpenOptions::new();
    opts.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        opts.custom_flags(libc::O_NONBLOCK);
    }
    let file = opts.open(path).map_err(|e| read_error(&e))?;
    let meta = file.metadata().map_err(|e| read_error(&e))?;
    if !meta.is_file() {
        return Err(if meta.is_dir() {
            "is a folder, not a shard file".into()
        } else {
            "is not a regular file (a FIFO, device or socket); only regular files are read".into()
        });
    }
    if meta.len() > max {
        return Err(format!(
            "is {} bytes, larger than any shard file ({max} bytes at most)",
            meta.len()
        ));
    }
    let mut bytes = Vec::new();
    file.take(max + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| read_error(&e))?;
    if bytes.len() as u64 > max {
        return Err(format!("grew past {max} bytes while being read"));
    }
    Ok(bytes)
}

fn read_error(e: &std::io::Error) -> String {
    let text = e.to_string().to_lowercase();
    text.split(" (os error").next().unwrap_or(&text).to_string()
}
