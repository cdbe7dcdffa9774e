//! A sweep over several processes or machines (docs/sweeps.md): shard K
//! of N runs the points i with i mod N = K − 1 (round robin, so that slow
//! regions of the grid are shared out) and keeps its results in
//! `DIR/shards/sweep-NAME.K-of-N.json`, rewritten atomically after every
//! chunk of runs: a killed shard leaves its last complete file, and a
//! rerun skips the runs it holds (resume). `gather` checks that the shard
//! files of a folder belong to one sweep (same fingerprint) and together
//! hold every run, and returns the records in grid order.
//!
//! Files, one job each: this one names shards (K/N, their files and
//! folder); `file` is the shard file and its bounded reader; `check` what
//! a file's every field must be for its plan (its fingerprint, version,
//! counts, and each record against its own arrival times and the outcome
//! rule); `write` writes a shard file within its cap; `resume` what a
//! rerun keeps; `gather` merges a folder's shards.

mod check;
mod file;
mod gather;
mod resume;
mod write;

pub use check::check_record;
pub use file::{MAX_SHARD_BYTES, ShardFile, read_bounded};
pub use gather::gather;
pub use resume::{Earlier, earlier};
pub use write::{check_estimate, write_records, write_records_within};

use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// Shard K of N (1-based).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Shard {
    pub k: usize,
    pub n: usize,
}

/// Most shards of one sweep.
pub const MAX_SHARDS: usize = 100_000;

impl Shard {
    /// The whole sweep in one process.
    pub const WHOLE: Shard = Shard { k: 1, n: 1 };

    /// Parses `K/N` with 1 ≤ K ≤ N.
    pub fn parse(text: &str) -> std::result::Result<Shard, String> {
        let bad = || format!("'{text}' is not K/N with whole numbers 1 <= K <= N (e.g. 2/3)");
        let (k, n) = text.split_once('/').ok_or_else(bad)?;
        let (k, n): (usize, usize) = (
            k.trim().parse().map_err(|_| bad())?,
            n.trim().parse().map_err(|_| bad())?,
        );
        if n == 0 || n > MAX_SHARDS {
            return Err(format!(
                "'{text}': the number of shards N must be from 1 to {MAX_SHARDS}"
            ));
        }
        if k == 0 || k > n {
            return Err(format!(
                "'{text}': shard K must be from 1 to N = {n} (shards are numbered from 1)"
            ));
        }
        Ok(Shard { k, n })
    }

    /// The runs of this shard, in grid order.
    pub fn indices(self, runs: usize) -> Vec<usize> {
        (self.k - 1..runs).step_by(self.n).collect()
    }

    /// How many runs of a grid of `runs` this shard has (the length of
    /// [`Shard::indices`], without building it).
    pub fn count(self, runs: usize) -> usize {
        if self.k > runs {
            0
        } else {
            (runs - self.k) / self.n + 1
        }
    }

    /// `sweep-NAME.K-of-N.json`.
    pub fn file_name(self, name: &str) -> String {
        format!("sweep-{name}.{}-of-{}.json", self.k, self.n)
    }
}

/// The folder of the shard files.
pub fn shards_dir(dir: &Path) -> PathBuf {
    dir.join("shards")
}

/// `sweep-NAME.K-of-N.json` → (NAME, K/N).
pub fn parse_file_name(name: &str) -> Option<(String, Shard)> {
    let stem = name.strip_prefix("sweep-")?.strip_suffix(".json")?;
    let (sweep, kn) = stem.rsplit_once('.')?;
    let (k, n) = kn.split_once("-of-")?;
    let shard = Shard {
        k: k.parse().ok()?,
        n: n.parse().ok()?,
    };
    (shard.k >= 1 && shard.k <= shard.n && !sweep.is_empty()).then(|| (sweep.to_string(), shard))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_parse_and_split_round_robin() {
        assert_eq!(Shard::parse("2/3").unwrap(), Shard { k: 2, n: 3 });
        assert!(Shard::parse("0/3").unwrap_err().contains("from 1 to N = 3"));
        assert!(Shard::parse("4/3").unwrap_err().contains("from 1 to N = 3"));
        assert!(Shard::parse("1/0").is_err());
        assert!(Shard::parse("x").is_err());
        let s = Shard { k: 2, n: 3 };
        assert_eq!(s.indices(8), vec![1, 4, 7]);
        let all: usize = (1..=3).map(|k| Shard { k, n: 3 }.indices(8).len()).sum();
        assert_eq!(all, 8);
    }

    #[test]
    fn file_names_round_trip() {
        let s = Shard { k: 12, n: 40 };
        let f = s.file_name("phase.v2");
        assert_eq!(f, "sweep-phase.v2.12-of-40.json");
        assert_eq!(parse_file_name(&f), Some(("phase.v2".into(), s)));
        assert_eq!(parse_file_name("sweep-x.json"), None);
        assert_eq!(parse_file_name("sweep-x.3-of-2.json"), None);
    }
}
