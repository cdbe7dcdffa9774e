//! A sweep over several processes or machines (SPEC section 7): shard K
//! of N runs the points i with i mod N = K − 1 (round robin, so that slow
//! regions of the grid are shared out) and keeps its results in
//! `DIR/shards/sweep-NAME.K-of-N.json`, rewritten atomically after every
//! chunk of runs: a killed shard leaves its last complete file, and a
//! rerun skips the runs it holds (resume). `gather` checks that the shard
//! files of a folder belong to one sweep (same fingerprint) and together
//! hold every run, and returns the records in grid order.

use super::{Plan, Record};
use crate::error::{Error, Result};
use crate::scene::Scene;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
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

    /// `sweep-NAME.K-of-N.json`.
    pub fn file_name(self, name: &str) -> String {
        format!("sweep-{name}.{}-of-{}.json", self.k, self.n)
    }
}

/// The folder of the shard files.
pub fn shards_dir(dir: &Path) -> PathBuf {
    dir.join("shards")
}

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
            runs_in_shard: shard.indices(plan.len()).len(),
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

    /// Reads a shard file; `None` with the reason when it is not one.
    pub fn read(path: &Path) -> std::result::Result<ShardFile, String> {
        let bytes = std::fs::read(path).map_err(|e| e.to_string().to_lowercase())?;
        serde_json::from_slice(&bytes).map_err(|e| format!("not a ladder shard file ({e})"))
    }
}

/// What a rerun can keep: the records of an earlier run of the same shard
/// of the same sweep, or why there are none.
pub enum Earlier {
    None,
    /// Kept: the records that belong to this shard.
    Resumed(Vec<Record>),
    /// A file of another sweep (or unreadable) that will be replaced.
    Stale(String),
}

/// The records already done for `shard` of `plan` under `dir`.
pub fn earlier(plan: &Plan, shard: Shard, dir: &Path) -> Earlier {
    let path = shards_dir(dir).join(shard.file_name(&plan.scene.name));
    if !path.exists() {
        return Earlier::None;
    }
    match ShardFile::read(&path) {
        Ok(f) if f.fingerprint == plan.fingerprint && f.shard == shard => {
            let mine: Vec<usize> = shard.indices(plan.len());
            let records = f
                .records
                .into_iter()
                .filter(|r| mine.binary_search(&r.run).is_ok())
                .collect();
            Earlier::Resumed(records)
        }
        Ok(_) => Earlier::Stale(format!(
            "{} holds another sweep; starting this shard afresh",
            path.display()
        )),
        Err(e) => Earlier::Stale(format!(
            "{}: {e}; starting this shard afresh",
            path.display()
        )),
    }
}

/// Writes `file` for its shard under `dir`, atomically.
pub fn write(dir: &Path, name: &str, file: &ShardFile) -> Result<PathBuf> {
    let path = shards_dir(dir).join(file.shard.file_name(name));
    crate::output::write_atomic(&path, &file.to_bytes()?)?;
    Ok(path)
}

/// The shard files of `dir/shards`, merged: the sweep scene and every
/// record in grid order. Refuses a folder without shards, shards of two
/// sweeps, and a sweep with a shard missing or unfinished (naming it).
pub fn gather(dir: &Path) -> Result<(Scene, String, Vec<Record>)> {
    // (the sweep scene, the shards' fingerprint, the records)
    let sdir = shards_dir(dir);
    let entries = std::fs::read_dir(&sdir).map_err(|_| {
        Error::bad_input(format!(
            "{} holds no shards: run `ladder sweep ... --shard K/N --out {}` first",
            sdir.display(),
            dir.display()
        ))
    })?;
    let mut files: Vec<(PathBuf, String, Shard)> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter_map(|p| {
            let name = p.file_name()?.to_str()?.to_string();
            let (sweep, shard) = parse_file_name(&name)?;
            Some((p, sweep, shard))
        })
        .collect();
    files.sort_by(|a, b| (&a.1, a.2.n, a.2.k).cmp(&(&b.1, b.2.n, b.2.k)));
    if files.is_empty() {
        return Err(Error::bad_input(format!(
            "{} holds no shard files (sweep-NAME.K-of-N.json)",
            sdir.display()
        )));
    }
    let mut read: Vec<(PathBuf, ShardFile)> = Vec::with_capacity(files.len());
    for (path, _, _) in &files {
        let f = ShardFile::read(path)
            .map_err(|e| Error::bad_input(format!("{}: {e}", path.display())))?;
        read.push((path.clone(), f));
    }
    let (first_path, first) = &read[0];
    if let Some((path, other)) = read
        .iter()
        .find(|(_, f)| f.fingerprint != first.fingerprint || f.scene.name != first.scene.name)
    {
        return Err(Error::bad_input(format!(
            "{} holds shards of two different sweeps: {} (sweep {}, fingerprint {}) and {} (sweep {}, fingerprint {}); gather one sweep per folder",
            sdir.display(),
            file_name(first_path),
            first.scene.name,
            first.fingerprint,
            file_name(path),
            other.scene.name,
            other.fingerprint
        )));
    }
    let total = first.runs_total;
    let mut by_run: BTreeMap<usize, Record> = BTreeMap::new();
    for (_, f) in &read {
        for r in &f.records {
            if r.run < total {
                by_run.entry(r.run).or_insert_with(|| r.clone());
            }
        }
    }
    if by_run.len() < total {
        return Err(Error::bad_input(missing_message(
            &sdir,
            &first.scene.name,
            &read,
            &by_run,
            total,
        )));
    }
    Ok((
        first.scene.clone(),
        first.fingerprint.clone(),
        by_run.into_values().collect(),
    ))
}

/// Which shard is missing or unfinished.
fn missing_message(
    sdir: &Path,
    name: &str,
    read: &[(PathBuf, ShardFile)],
    by_run: &BTreeMap<usize, Record>,
    total: usize,
) -> String {
    let missing_runs = total - by_run.len();
    // The split with most shard files present names what is missing.
    let mut splits: BTreeMap<usize, Vec<&ShardFile>> = BTreeMap::new();
    for (_, f) in read {
        splits.entry(f.shard.n).or_default().push(f);
    }
    let (n, present) = splits
        .iter()
        .max_by_key(|(_, v)| v.len())
        .map(|(n, v)| (*n, v.clone()))
        .unwrap_or((1, Vec::new()));
    let absent: Vec<String> = (1..=n)
        .filter(|k| !present.iter().any(|f| f.shard.k == *k))
        .map(|k| format!("{k}/{n}"))
        .collect();
    if !absent.is_empty() {
        let files: Vec<String> = absent
            .iter()
            .take(1)
            .map(|s| {
                let (k, _) = s.split_once('/').unwrap_or(("1", ""));
                Shard {
                    k: k.parse().unwrap_or(1),
                    n,
                }
                .file_name(name)
            })
            .collect();
        return format!(
            "{missing_runs} of {total} runs are missing: shard{} {} of sweep {name} not found in {} (no {}); run it with --shard, then gather again",
            if absent.len() > 1 { "s" } else { "" },
            list(&absent),
            sdir.display(),
            files.join(", ")
        );
    }
    let unfinished: Vec<String> = present
        .iter()
        .filter(|f| !f.complete())
        .map(|f| {
            format!(
                "{}/{} ({} of {} runs done)",
                f.shard.k,
                f.shard.n,
                f.records.len(),
                f.runs_in_shard
            )
        })
        .collect();
    format!(
        "{missing_runs} of {total} runs are missing: shard{} {} of sweep {name} did not finish; rerun {} with the same --shard to resume, then gather again",
        if unfinished.len() > 1 { "s" } else { "" },
        list(&unfinished),
        if unfinished.len() > 1 { "them" } else { "it" }
    )
}

fn list(items: &[String]) -> String {
    if items.len() <= 6 {
        items.join(", ")
    } else {
        format!("{}, ... ({} in all)", items[..6].join(", "), items.len())
    }
}

fn file_name(p: &Path) -> String {
    p.file_name()
        .map_or_else(|| p.display().to_string(), |n| n.to_string_lossy().into())
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
