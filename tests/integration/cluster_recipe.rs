//! docs/cluster.md's recipes run as written: the Slurm job array through a
//! stand-in `sbatch` (tests/integration/fake_sbatch.sh) that runs each task
//! with the variables Slurm sets, a lost task resubmitted alone, and the
//! GNU parallel line's threads against the machine's cores.

use std::path::Path;
use std::process::{Command, Output};

use crate::common::tempdir::TempDir;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

fn docs() -> String {
    std::fs::read_to_string(Path::new(ROOT).join("docs/cluster.md")).unwrap()
}

/// The fenced code blocks of the section of docs/cluster.md that starts
/// with `heading`, in order.
fn blocks(heading: &str) -> Vec<String> {
    let doc = docs();
    let start = doc.find(heading).unwrap_or_else(|| panic!("no {heading}"));
    let section = &doc[start + heading.len()..];
    let section = &section[..section.find("\n## ").unwrap_or(section.len())];
    section
        .split("```")
        .skip(1)
        .step_by(2)
        .map(|b| b.trim_start_matches('\n').to_string())
        .collect()
}

/// A folder holding the example sweep as `sweep.toml` and the Slurm
/// script at the path the docs give, and a `bin/` with the stand-in
/// `sbatch`.
fn slurm_folder() -> TempDir {
    let dir = TempDir::new("cluster-recipe");
    std::fs::copy(
        Path::new(ROOT).join("examples/slurm/sweep.toml"),
        dir.join("sweep.toml"),
    )
    .unwrap();
    std::fs::create_dir_all(dir.join("examples/slurm")).unwrap();
    std::fs::copy(
        Path::new(ROOT).join("examples/slurm/sweep.sbatch"),
        dir.join("examples/slurm/sweep.sbatch"),
    )
    .unwrap();
    for d in ["bin", "slurm"] {
        std::fs::create_dir_all(dir.join(d)).unwrap();
    }
    std::fs::copy(
        Path::new(ROOT).join("tests/integration/fake_sbatch.sh"),
        dir.join("bin/sbatch"),
    )
    .unwrap();
    chmod_x(&dir.join("bin/sbatch"));
    dir
}

fn chmod_x(p: &Path) {
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(p, std::fs::Permissions::from_mode(0o755)).unwrap();
}

/// PATH with `extra` and the folder of the `ladder` under test first.
fn path_with(extra: &Path) -> String {
    let bin = Path::new(env!("CARGO_BIN_EXE_ladder")).parent().unwrap();
    format!(
        "{}:{}:{}",
        extra.display(),
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    )
}

/// Runs `script` with bash in `dir`, the stand-in sbatch on PATH.
fn bash(dir: &Path, script: &str, env: &[(&str, &str)]) -> Output {
    let mut c = Command::new("bash");
    c.arg("-c")
        .arg(format!("set -e\n{script}"))
        .current_dir(dir)
        .env("PATH", path_with(&dir.join("bin")))
        .env("FAKE_SLURM_DIR", dir.join("slurm"));
    for (k, v) in env {
        c.env(k, v);
    }
    c.output().unwrap()
}

fn ok(out: &Output) {
    assert!(
        out.status.success(),
        "exit {:?}: {}{}",
        out.status.code(),
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Every task the stand-in ran: (job_task, exit status, output).
fn tasks(dir: &Path) -> Vec<(String, String, String)> {
    let mut v: Vec<_> = std::fs::read_dir(dir.join("slurm"))
        .unwrap()
        .filter_map(|e| {
            let p = e.unwrap().path();
            let name = p.file_name()?.to_str()?.strip_suffix(".rc")?.to_string();
            let rc = std::fs::read_to_string(&p).unwrap().trim().to_string();
            let out = std::fs::read_to_string(p.with_extension("out")).unwrap_or_default();
            Some((name, rc, out))
        })
        .collect();
    v.sort();
    v
}

/// The gathered CSV in `dir/out` equals an unsharded run of the sweep.
fn assert_gathered_equals_unsharded(dir: &Path) {
    let whole = dir.join("whole");
    ok(&crate::common::ladder_cli(&[
        "sweep",
        dir.join("sweep.toml").to_str().unwrap(),
        "--out",
        whole.to_str().unwrap(),
    ]));
    assert_eq!(
        std::fs::read(dir.join("out/sweep-antikink-damping.csv")).unwrap(),
        std::fs::read(whole.join("sweep-antikink-damping.csv")).unwrap()
    );
}

/// The docs' submission (array of 10, then a gather) with task 4 lost:
/// the gather runs anyway (`afterany`), refuses naming shard 5/10 and
/// writes nothing; the docs' resubmission of task 4 alone (where Slurm
/// sets SLURM_ARRAY_TASK_COUNT=1) runs shard 5/10, and its gather writes
/// the unsharded sweep's CSV byte for byte.
#[test]
fn a_failed_slurm_task_resubmitted_as_the_docs_say_completes_the_sweep() {
    let b = blocks("## Slurm job array");
    let submit = b.iter().find(|s| s.contains("--array=0-9")).unwrap();
    let resubmit = b.iter().find(|s| s.contains("--array=4 ")).unwrap();
    let dir = slurm_folder();
    ok(&bash(&dir, submit, &[("FAKE_SLURM_LOSE", "4")]));
    let first = tasks(&dir);
    assert_eq!(first.len(), 11, "10 tasks and the gather: {first:?}");
    let lost: Vec<&str> = first
        .iter()
        .filter(|t| t.1 == "1")
        .map(|t| t.0.as_str())
        .collect();
    assert_eq!(lost, ["1001_4"], "task 4 lost: {first:?}");
    let gather = &first.last().unwrap();
    assert_eq!(gather.1, "2", "{gather:?}");
    assert!(gather.2.contains("shard 5/10"), "{gather:?}");
    assert!(!dir.join("out/sweep-antikink-damping.csv").exists());

    ok(&bash(&dir, resubmit, &[]));
    let after = tasks(&dir);
    let new: Vec<_> = after.iter().filter(|t| !first.contains(t)).collect();
    assert_eq!(new.len(), 2, "{new:?}");
    assert!(new.iter().all(|t| t.1 == "0"), "{new:?}");
    assert!(
        dir.join("out/shards/sweep-antikink-damping.5-of-10.json")
            .exists()
    );
    assert_gathered_equals_unsharded(&dir);
}

/// The stand-in follows Slurm: a gather submitted with `afterok` on an
/// array with a failed task never runs (so the docs' first gather is
/// `afterany`).
#[test]
fn an_afterok_gather_never_runs_after_a_failed_task() {
    let b = blocks("## Slurm job array");
    let submit = b.iter().find(|s| s.contains("--array=0-9")).unwrap();
    assert!(submit.contains("--dependency=afterany:"), "{submit}");
    let dir = slurm_folder();
    ok(&bash(
        &dir,
        &submit.replace("afterany", "afterok"),
        &[("FAKE_SLURM_LOSE", "4")],
    ));
    let gather = tasks(&dir).pop().unwrap();
    assert_eq!(gather.1, "never", "{gather:?}");
}

/// The script refuses, exit 2 and one line, a task past SHARDS and a
/// SHARDS that differs from the shards already in OUT; and a task run as a
/// resubmitted one (SLURM_ARRAY_TASK_COUNT=1) without SHARDS in its
/// environment still runs its shard of the script's own count.
#[test]
fn the_slurm_script_takes_its_shard_count_from_itself_not_the_array() {
    let dir = slurm_folder();
    let script = dir.join("examples/slurm/sweep.sbatch");
    let run = |env: &[(&str, &str)]| {
        let mut c = Command::new("bash");
        c.arg(&script)
            .current_dir(&dir)
            .env("PATH", path_with(&dir.join("bin")))
            .env_remove("SHARDS")
            .env("SLURM_CPUS_PER_TASK", "1");
        for (k, v) in env {
            c.env(k, v);
        }
        c.output().unwrap()
    };
    let resubmitted = [
        ("SLURM_ARRAY_TASK_ID", "4"),
        ("SLURM_ARRAY_TASK_COUNT", "1"),
        ("SLURM_ARRAY_TASK_MIN", "4"),
        ("SLURM_ARRAY_TASK_MAX", "4"),
    ];
    ok(&run(&resubmitted));
    assert!(
        dir.join("out/shards/sweep-antikink-damping.5-of-10.json")
            .exists()
    );
    let refused = |out: Output, says: &str| {
        let err = String::from_utf8_lossy(&out.stderr).to_string();
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(says), "{err}");
    };
    refused(
        run(&[("SLURM_ARRAY_TASK_ID", "10")]),
        "past the sweep's 10 shards",
    );
    refused(
        run(&[("SLURM_ARRAY_TASK_ID", "1"), ("SHARDS", "3")]),
        "SHARDS=10",
    );
    refused(run(&[("SHARDS", "3")]), "not an array task");
}

/// docs/cluster.md's GNU parallel line, run with a `ladder` that records
/// the threads it was given: jobs at once × threads per job is at most
/// the machine's cores (GNU parallel runs one job per core unless `-j`
/// says otherwise).
#[test]
fn the_gnu_parallel_line_does_not_oversubscribe_the_cores() {
    if !crate::common::require::require(
        "the_gnu_parallel_line_does_not_oversubscribe_the_cores",
        crate::common::require::runs("parallel", "--version", "GNU parallel"),
        "GNU parallel is not installed",
        "install Debian's parallel; .ci/run does",
    ) {
        return;
    }
    let b = blocks("## GNU parallel");
    let line = b[0]
        .lines()
        .find(|l| l.starts_with("parallel "))
        .unwrap()
        .to_string();
    let dir = slurm_folder();
    let log = dir.join("threads.log");
    let real = env!("CARGO_BIN_EXE_ladder");
    let shim = dir.join("bin/ladder");
    std::fs::write(
        &shim,
        format!(
            "#!/bin/bash\necho \"${{RAYON_NUM_THREADS:-unset}}\" >> '{}'\nexec '{real}' \"$@\"\n",
            log.display()
        ),
    )
    .unwrap();
    chmod_x(&shim);
    ok(&bash(&dir, &line, &[]));
    let cores = std::thread::available_parallelism().unwrap().get();
    let jobs = jobs_at_once(&line).unwrap_or(cores);
    let seen = std::fs::read_to_string(&log).unwrap();
    assert_eq!(seen.lines().count(), 3, "{seen}");
    for t in seen.lines() {
        let threads: usize = match t.parse() {
            Ok(0) | Err(_) => cores, // rayon's default: every core
            Ok(t) => t,
        };
        assert!(
            jobs.min(3) * threads <= cores,
            "{line}: {jobs} jobs × {threads} threads on {cores} cores"
        );
    }
}

/// The `-j N` / `--jobs N` of a GNU parallel line, if it gives one.
fn jobs_at_once(line: &str) -> Option<usize> {
    let words: Vec<&str> = line.split_whitespace().collect();
    let k = words.iter().position(|w| *w == "-j" || *w == "--jobs")?;
    words.get(k + 1)?.parse().ok()
}
