//! A sweep over several processes or machines (docs/sweeps.md): shard K
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

    /// Checks this file against the sweep `plan` it claims to belong to:
    /// its fingerprint, its counts, and every record (index unique, in
    /// range and of this shard; values sane for the run's N).
    pub fn validate(&self, plan: &Plan) -> std::result::Result<(), String> {
        if self.fingerprint != plan.fingerprint {
            return Err(format!(
                "made for another sweep (fingerprint {}, this sweep's is {})",
                self.fingerprint, plan.fingerprint
            ));
        }
        let Shard { k, n } = self.shard;
        if n == 0 || n > MAX_SHARDS || k == 0 || k > n {
            return Err(format!("names shard {k}/{n}, which does not exist"));
        }
        if self.runs_total != plan.len() {
            return Err(format!(
                "says the sweep has {} runs; its plan has {}",
                self.runs_total,
                plan.len()
            ));
        }
        let in_shard = self.shard.count(plan.len());
        if self.runs_in_shard != in_shard {
            return Err(format!(
                "says shard {k}/{n} has {} runs; the plan gives it {in_shard}",
                self.runs_in_shard
            ));
        }
        if self.records.len() > in_shard {
            return Err(format!(
                "holds {} records for a shard of {in_shard} runs",
                self.records.len()
            ));
        }
        let mut last: Option<usize> = None;
        for r in &self.records {
            if r.run >= plan.len() || r.run % n != k - 1 {
                return Err(format!(
                    "holds run {}, which is not a run of shard {k}/{n} of {} runs",
                    r.run,
                    plan.len()
                ));
            }
            if last.is_some_and(|l| l >= r.run) {
                return Err(format!("holds run {} twice (or out of order)", r.run));
            }
            last = Some(r.run);
            let blocks = plan.scene_at(r.run).model.n;
            sane(&r.result, blocks).map_err(|m| format!("run {}: {m}", r.run))?;
        }
        Ok(())
    }
}

/// Largest shard file read: 1 GiB (a shard of 100,000 runs of N = 1000
/// holds about 0.5 GB of arrival times).
pub const MAX_SHARD_BYTES: u64 = 1 << 30;

/// Checks, before any run, that `shard`'s file fits what a reader takes
/// ([`MAX_SHARD_BYTES`]): its estimate is the sweep JSON's estimate
/// (`json::estimate`, a bound for runs of the waves it assumes) shared
/// out by runs. Runs with more waves are caught as the file is written
/// ([`write_records_within`]). Past it, the
/// message names the fewest shards that fit.
pub fn check_estimate(plan: &Plan, shard: Shard) -> Result<()> {
    let runs = plan.len().max(1) as f64;
    let whole = super::json::estimate(plan).json;
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

/// Whether a record's values can be a run of `blocks` blocks: counts
/// within the chain, times finite and not negative, a short integrator
/// name.
fn sane(r: &super::RunResult, blocks: usize) -> std::result::Result<(), String> {
    let time = |t: f64| t.is_finite() && t >= 0.0;
    if r.arrival_times.len() != blocks {
        return Err(format!(
            "{} arrival times for a chain of N = {blocks}",
            r.arrival_times.len()
        ));
    }
    if r.blocks_flipped > blocks || r.front > blocks {
        return Err(format!(
            "blocks_flipped {} or front {} past N = {blocks}",
            r.blocks_flipped, r.front
        ));
    }
    if r.arrival_times.iter().flatten().any(|&t| !time(t)) {
        return Err("an arrival time that is negative or not finite".into());
    }
    if r.t_decided.is_some_and(|t| !time(t))
        || r.arrival_error.is_some_and(|t| !time(t))
        || !time(r.dt)
    {
        return Err("a time (t_decided, dt, arrival_error) that is negative or not finite".into());
    }
    if r.speed.is_some_and(|v| !v.is_finite()) {
        return Err("a speed that is not finite".into());
    }
    let name_ok = !r.integrator.is_empty()
        && r.integrator.len() <= 64
        && r.integrator
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'-' || b == b'_' || b == b' ');
    if !name_ok {
        return Err("an integrator name that is not one".into());
    }
    if r.message.as_ref().is_some_and(|m| m.len() > 4096) {
        return Err("a message longer than 4096 bytes".into());
    }
    Ok(())
}

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

/// The shard files of `dir/shards`, merged: the sweep's plan (rebuilt
/// from the first shard's scene, refused past `max_runs` runs) and every
/// record in grid order. Every file is checked against that plan (its
/// fingerprint, counts and records; its file name's K/N); refuses a folder
/// without shards, shards of two sweeps, two shards that disagree on a
/// run, and a sweep with a shard missing or unfinished (naming it).
pub fn gather(dir: &Path, max_runs: usize) -> Result<(Plan, Vec<Record>)> {
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
    let total = plan.len();
    let mut by_run: BTreeMap<usize, (&Path, &Record)> = BTreeMap::new();
    for (path, f) in &read {
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
            &sdir,
            &plan.scene.name,
            &read,
            by_run.len(),
            total,
        )));
    }
    let records = by_run.into_values().map(|(_, r)| r.clone()).collect();
    Ok((plan, records))
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
