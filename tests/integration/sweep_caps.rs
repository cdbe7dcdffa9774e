//! A sweep's bytes bounded as its runs come in: runs with more
//! waves than the estimate before work assumed stop the sweep at the cap
//! on a data file's bytes, with their runs kept, and a rerun with a
//! raised cap resumes them without running them again; a shard file is
//! never written past what its reader takes.

use jacobs_ladder::scene::file;
use jacobs_ladder::sweep::shard::{self, Shard, ShardFile};
use jacobs_ladder::sweep::{Plan, json};
use std::path::{Path, PathBuf};
use std::process::Output;

use crate::common::ladder_cli as ladder;

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ladder-caps-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// 151 runs of N = 40 under strong gravity and weak damping: about 31
/// waves a run (walls born all along the chain), where the estimate
/// before work assumes 3, so the JSON (5.7 MB) is about 4 times its
/// estimate (1.4 MB).
fn many_waves(out: &Path, cap: &str) -> Output {
    ladder(&[
        "sweep",
        "--n",
        "40",
        "--gravity",
        "3e-3",
        "--gamma",
        "0.002",
        "--integrator",
        "verlet",
        "--dt",
        "0.1",
        "--alpha",
        "15:30:0.1",
        "--name",
        "m",
        "--format",
        "svg",
        "--max-data-bytes",
        cap,
        "--out",
        out.to_str().unwrap(),
    ])
}

fn shard_records(out: &Path) -> usize {
    ShardFile::read(&out.join("shards/sweep-m.1-of-1.json"))
        .unwrap()
        .records
        .len()
}

#[test]
fn a_sweep_with_more_waves_than_estimated_stops_at_the_cap_and_resumes() {
    let out = tmp("waves");
    // 3e6 bytes: over the estimate (1.4e6), so the check before work
    // passes; the runs' own JSON passes it within the first chunk.
    let o = many_waves(&out, "3e6");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let msg = stderr(&o);
    assert!(msg.contains("runs done so far of 151"), "{msg}");
    assert!(msg.contains("--max-data-bytes"), "names the flag: {msg}");
    assert_eq!(msg.trim().lines().count(), 1, "one line: {msg}");
    let kept = shard_records(&out);
    assert!(
        kept > 0 && kept < 151,
        "stopped before the end: {kept} runs kept"
    );
    assert!(!out.join("sweep-m.csv").exists() && !out.join("sweep-m.json").exists());

    // Raised: the runs kept are not run again, and the files are the
    // same bytes as a sweep run in one go.
    let again = many_waves(&out, "1e7");
    assert!(again.status.success(), "{}", stderr(&again));
    assert!(
        stderr(&again).contains(&format!("{kept} of 151 runs already done")),
        "{}",
        stderr(&again)
    );
    let fresh = tmp("waves-fresh");
    let once = many_waves(&fresh, "1e7");
    assert!(once.status.success(), "{}", stderr(&once));
    for f in ["sweep-m.csv", "sweep-m.json", "sweep-m.svg"] {
        assert_eq!(
            std::fs::read(out.join(f)).unwrap(),
            std::fs::read(fresh.join(f)).unwrap(),
            "{f}"
        );
    }
    let json = std::fs::metadata(fresh.join("sweep-m.json")).unwrap().len() as f64;
    assert!(json > 3e6, "the JSON ({json} bytes) is past the first cap");
    let _ = std::fs::remove_dir_all(&out);
    let _ = std::fs::remove_dir_all(&fresh);
}

#[test]
fn no_shard_file_is_written_past_what_its_reader_takes() {
    let toml = r#"
name = "w"
[run]
integrator = "verlet"
dt = 0.25
[output]
kind = "sweep"
[output.grid]
alpha = [55, 60, 65, 70]
"#;
    let scene = file::parse(toml, "w.toml", "w").unwrap();
    let plan = Plan::new(&scene, 10).unwrap().unwrap();
    let all: Vec<usize> = (0..plan.len()).collect();
    let records = plan.run(&all, &|| {}).unwrap();
    let dir = tmp("shard-cap");
    let path = shard::write_records(&dir, &plan, Shard::WHOLE, &records[..2]).unwrap();
    let two = std::fs::read(&path).unwrap();
    // A cap a byte short of the file of all four: refused, and the file
    // of two stays as it was (its runs are kept), with no temporary left.
    let whole = {
        let other = tmp("shard-cap-whole");
        let p = shard::write_records(&other, &plan, Shard::WHOLE, &records).unwrap();
        let n = std::fs::metadata(&p).unwrap().len();
        let _ = std::fs::remove_dir_all(&other);
        n
    };
    let e = shard::write_records_within(&dir, &plan, Shard::WHOLE, &records, whole - 1)
        .unwrap_err()
        .to_string();
    assert!(e.contains("a shard file may hold"), "{e}");
    assert!(e.contains("--shard K/"), "{e}");
    assert_eq!(std::fs::read(&path).unwrap(), two);
    let left: Vec<_> = std::fs::read_dir(path.parent().unwrap())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left.len(), 1, "{left:?}");
    // At the cap exactly: written, and read back within the same cap.
    shard::write_records_within(&dir, &plan, Shard::WHOLE, &records, whole).unwrap();
    assert_eq!(ShardFile::read(&path).unwrap().records.len(), 4);
    assert!(shard::read_bounded(&path, whole).is_ok());
    // The estimate before work still holds for these one-wave runs.
    assert!(json::estimate(&plan).json > whole as f64);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The first chunk of a sweep counted against a cap on bytes is one run a
/// core, and the chunks grow within the room the cap leaves, so the sweep
/// stops soon after the run that passes the cap (before, the first chunk
/// was the whole sweep: the many-waves sweep stopped only after all its
/// runs, 33 times past its estimate).
#[test]
fn a_sweep_stops_soon_after_the_run_that_passes_the_cap() {
    let fresh = tmp("waves-whole");
    let once = many_waves(&fresh, "1e8");
    assert!(once.status.success(), "{}", stderr(&once));
    let json = std::fs::metadata(fresh.join("sweep-m.json")).unwrap().len() as f64;
    let per_run = json / 151.0;
    let out = tmp("waves-first-chunk");
    // Past the estimate before work (1.4e6), so the runs start.
    let cap = 2e6;
    let o = many_waves(&out, "2e6");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let kept = shard_records(&out) as f64;
    // The runs the cap holds, and a few runs more (the runs a run's bytes
    // differ by, and one chunk of one run a core).
    let holds = cap / per_run;
    println!("kept {kept} runs; the cap holds about {holds:.0} at {per_run:.0} bytes a run");
    assert!(
        kept <= 2.0 * holds + 8.0,
        "kept {kept}, the cap holds {holds:.0}"
    );
    let _ = std::fs::remove_dir_all(&out);
    let _ = std::fs::remove_dir_all(&fresh);
}
