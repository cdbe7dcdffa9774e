//! Merging the shard files of a folder into one sweep's records.

use super::{Shard, ShardFile, parse_file_name, shards_dir};
use crate::error::{Error, Result};
use crate::sweep::{Plan, Record};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The shard files of `dir/shards`, merged: the sweep's plan (rebuilt
/// from the first shard's scene, refused past `max_runs` runs) and every
/// record in grid order. Every file is checked against that plan (its
/// fingerprint, counts and records; its file name's K/N); refuses a folder
/// without shards, shards of two sweeps, two shards that disagree on a
/// run, and a sweep with a shard missing or unfinished (naming it).
pub fn gather(dir: &Path, max_runs: usize) -> Result<(Plan, Vec<Record>)> {
    let sdir = shards_dir(dir);
    let read = read_shards(dir, &sdir)?;
    let bad = |path: &Path, m: &str| Error::bad_input(format!("{}: {m}", path.display()));
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
    let plan = Plan::new(&first.scene, max_runs)
        .map_err(|e| bad(first_path, &format!("its sweep scene is not valid: {e}")))?
        .map_err(|e| {
            bad(
                first_path,
                &format!("{e}; raise the cap with --max-runs {}", e.runs),
            )
        })?;
    if first.fingerprint != plan.fingerprint {
        return Err(Error::bad_input(format!(
            "the shards in {} were made by another version of ladder, or edited (fingerprint {}, this one computes {} from their scene); rerun them with this version",
            sdir.display(),
            first.fingerprint,
            plan.fingerprint
        )));
    }
    for (path, f) in &read {
        f.validate(&plan).map_err(|m| bad(path, &m))?;
    }
    let records = merge(&sdir, &plan, &read)?;
    Ok((plan, records))
}

/// The records of `read` (checked against `plan`) by run, every run once:
/// two shards that disagree on a run, or a run in none, are bad input.
fn merge(sdir: &Path, plan: &Plan, read: &[(PathBuf, ShardFile)]) -> Result<Vec<Record>> {
    let bad = |path: &Path, m: &str| Error::bad_input(format!("{}: {m}", path.display()));
    let total = plan.len();
    let mut by_run: BTreeMap<usize, (&Path, &Record)> = BTreeMap::new();
    for (path, f) in read {
        for r in &f.records {
            if let Some((other, earlier)) = by_run.insert(r.run, (path, r))
                && earlier != r
            {
                return Err(bad(
                    path,
                    &format!(
                        "run {} differs from the same run in {}; remove the wrong shard and rerun it",
                        r.run,
                        file_name(other)
                    ),
                ));
            }
        }
    }
    if by_run.len() < total {
        return Err(Error::bad_input(missing_message(
            sdir,
            &plan.scene.name,
            read,
            by_run.len(),
            total,
        )));
    }
    Ok(by_run.into_values().map(|(_, r)| r.clone()).collect())
}

/// The shard files of `sdir` (the shards folder of `dir`), each read
/// (a regular file of bounded size) and its name's K/N checked against
/// its content, in the order of sweep and shard.
fn read_shards(dir: &Path, sdir: &Path) -> Result<Vec<(PathBuf, ShardFile)>> {
    let entries = std::fs::read_dir(sdir).map_err(|_| {
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
    let bad = |path: &Path, m: &str| Error::bad_input(format!("{}: {m}", path.display()));
    let mut read: Vec<(PathBuf, ShardFile)> = Vec::with_capacity(files.len());
    for (path, _, shard) in &files {
        let f = ShardFile::read(path).map_err(|e| bad(path, &e))?;
        if f.shard != *shard {
            return Err(bad(
                path,
                &format!(
                    "holds shard {}/{}, not the {}/{} its name says",
                    f.shard.k, f.shard.n, shard.k, shard.n
                ),
            ));
        }
        read.push((path.clone(), f));
    }
    Ok(read)
}

/// Which shard is missing or unfinished.
fn missing_message(
    sdir: &Path,
    name: &str,
    read: &[(PathBuf, ShardFile)],
    done: usize,
    total: usize,
) -> String {
    let missing_runs = total - done;
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
    if unfinished.is_empty() {
        return format!(
            "{missing_runs} of {total} runs of sweep {name} are in no shard file of {}; rerun the shards, then gather again",
            sdir.display()
        );
    }
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
