//! Memory and bytes at the documented caps (docs/limits.md, "Data files
//! and memory"), measured with a counting global allocator (live heap
//! bytes of every thread, and their peak):
//!
//! - a sweep's JSON is streamed into its file (the peak while it is
//!   written is a small part of the file), and its JSON and CSV are
//!   estimated from the plan before any run: the estimate bounds the
//!   files written (worst-case records and real runs), within a stated
//!   factor; `ladder sweep` refuses a sweep past `--max-data-bytes`
//!   before any run, and accepts one just under;
//! - a simulation at the cap on samples × N (5 × 10⁷: N = 100 000, 500
//!   samples) stays under the documented bound, and one more sample is
//!   refused before any work;
//! - a sweep holds a bounded number of bytes per run (its points and
//!   records);
//! - a movie's memory does not grow with its frames beyond the encoded
//!   file (the frames are encoded as drawn).
//!
//! The tests of this binary take one lock, so that no other test
//! allocates while a peak is measured.

use jacobs_ladder::error::Error;
use jacobs_ladder::limits::{Limits, Resource};
use jacobs_ladder::scene::{self, Scene};
use jacobs_ladder::scenes::{self, MovieOptions, Outputs};
use jacobs_ladder::sweep::{self, Plan, Record, json};
use std::io::Write as _;
use std::path::{Path, PathBuf};

#[path = "common/heap.rs"]
mod heap;

use heap::{lock, measure};

#[global_allocator]
static GLOBAL: heap::Counting = heap::Counting;

fn tmp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("ladder-memcaps-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn report(line: String) {
    let _ = writeln!(std::io::stderr().lock(), "{line}");
}

/// A sweep scene of `n` blocks over `grid` (the body of `[output.grid]`).
fn sweep_scene(n: usize, grid: &str, drive: &str) -> Scene {
    let text = format!(
        "name = \"m\"\n[model]\nn = {n}\n{drive}[output]\nkind = \"sweep\"\n[output.grid]\n{grid}\n"
    );
    scene::file::parse(&text, "memory_caps.rs", "m").unwrap()
}

fn plan_of(scene: &Scene) -> Plan {
    Plan::new(scene, usize::MAX).unwrap().unwrap()
}

/// Writes `plan`'s files for `records` into `dir` as `ladder sweep`
/// does (each streamed into its file); returns each file's (name, bytes)
/// and the peak heap while they were written.
fn write_sweep(plan: &Plan, records: &[Record], dir: &Path) -> (Vec<(String, u64)>, u64) {
    let formats = Outputs::default().figures;
    let options = sweep::OutputOptions {
        formats: &formats,
        scale: 1.0,
        command_line: &[],
        rename: &|n| n,
    };
    let (names, peak, _) = measure(|| {
        sweep::write_outputs(plan, records, "sweep-m", &options, &mut |name, fill| {
            let mut f = std::fs::File::create(dir.join(name)).unwrap();
            fill(&mut f).unwrap();
            Ok(())
        })
        .unwrap()
    });
    let sizes = names
        .iter()
        .map(|n| (n.clone(), std::fs::metadata(dir.join(n)).unwrap().len()))
        .collect();
    (sizes, peak)
}

fn size_of(files: &[(String, u64)], ext: &str) -> u64 {
    files
        .iter()
        .find(|(n, _)| n.ends_with(ext))
        .map(|(_, b)| *b)
        .unwrap()
}

/// Records for every run of `plan` as large as a run's record can be:
/// every block arrived at a time of 18 characters, `waves` waves each
/// with every block's arrival and an annihilation, block N's sign
/// changed 20 times, a message of 400 characters. Made from one real run
/// (so that they have every field a record has).
fn worst_records(plan: &Plan, waves: usize) -> Vec<Record> {
    let first = plan.scene_at(0);
    let mut small = first.clone();
    small.model.n = 10;
    let mut template = sweep::run::run_point(&small, &plan.spec).unwrap();
    let n = first.model.n;
    let t = 12345.678901234567;
    template.arrival_times = vec![Some(t); n];
    template.speed = Some(0.012345678901234567);
    template.t_decided = Some(t);
    template.arrival_error = Some(1.2345678901234567e-5);
    template.message = Some("m".repeat(400));
    let mut wave = template.waves.waves[0].clone();
    wave.arrival_times = vec![Some(t); n];
    wave.launched_at = t;
    wave.front = n;
    wave.fate = jacobs_ladder::sim::waves::Fate::Annihilated {
        with: 99,
        at: t,
        block: n,
    };
    template.waves.waves = vec![wave; waves];
    template.waves.block_n.sign_changes = vec![t; 20];
    (0..plan.len())
        .map(|run| Record {
            run,
            result: template.clone(),
        })
        .collect()
}

/// A sweep of 72 runs of N = 2000 (three varied parameters: no chart),
/// with worst-case records of one and of three waves: the JSON is
/// written as it is encoded (the peak while writing is under a tenth of
/// the file; held in memory, it would be the whole file and more), and
/// the estimate made from the plan bounds both files.
#[test]
fn a_sweeps_json_is_streamed_and_bounded_by_its_estimate() {
    let _one = lock();
    let dir = tmp("stream");
    let scene = sweep_scene(
        2000,
        "alpha = \"50:60:2\"\ngamma = [0.01, 0.02, 0.03, 0.04]\nb = [1.2, 1.3, 1.4]",
        "",
    );
    let plan = plan_of(&scene);
    assert_eq!(plan.len(), 72);
    let estimate = json::estimate(&plan);
    assert_eq!(estimate.blocks, 72.0 * 2000.0);
    // One wave each, then the most the estimate assumes.
    let assumed = json::waves_per_run(&plan) as usize;
    for waves in [1, assumed] {
        let records = worst_records(&plan, waves);
        let (files, peak) = write_sweep(&plan, &records, &dir);
        let (json_bytes, csv_bytes) = (size_of(&files, ".json"), size_of(&files, ".csv"));
        report(format!(
            "sweep of 72 runs of N = 2000, {waves} wave(s) a run (worst-case records): JSON {:.2} MB (estimate {:.2} MB), CSV {} bytes (estimate {:.0}), peak heap while writing {:.2} MB",
            json_bytes as f64 / 1e6,
            estimate.json / 1e6,
            csv_bytes,
            estimate.csv,
            peak as f64 / 1e6
        ));
        assert!(
            json_bytes as f64 <= estimate.json,
            "{waves} waves: JSON {json_bytes} bytes past the estimate {}",
            estimate.json
        );
        assert!(csv_bytes as f64 <= estimate.csv, "CSV {csv_bytes}");
        assert!(json_bytes > 5_000_000, "a large file: {json_bytes}");
        assert!(
            peak < json_bytes / 10,
            "{waves} waves: peak {peak} bytes while writing a JSON of {json_bytes}: held in memory"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Real runs (N = 10 and N = 40, one and two flips of the drive, 100
/// runs and more): the files are under the estimate and the JSON at least
/// a quarter of it (the estimate's factor, docs/limits.md).
#[test]
fn the_estimate_of_real_sweeps_is_an_upper_bound_within_four() {
    let _one = lock();
    let dir = tmp("real");
    let two_flips = "[[drive.flips]]\nstart = 0.0\nduration = 1000.0\n\
                     [[drive.flips]]\nstart = 3000.0\nduration = 1000.0\n";
    for (n, grid, drive) in [
        (
            10,
            "alpha = \"-50:-60:-0.5\"\ngamma = [0.01, 0.02, 0.03, 0.04, 0.05]",
            "",
        ),
        (40, "alpha = \"50:70:1\"\ngamma = [0.02, 0.04]", ""),
        (
            10,
            "alpha = \"50:62:0.25\"\ngamma = [0.02, 0.04]",
            two_flips,
        ),
    ] {
        let scene = sweep_scene(n, grid, drive);
        let plan = plan_of(&scene);
        assert!(plan.len() >= 40, "{}", plan.len());
        let estimate = json::estimate(&plan);
        let all: Vec<usize> = (0..plan.len()).collect();
        let records = plan.run(&all, &|| {}).unwrap();
        let most_waves = records
            .iter()
            .map(|r| r.result.waves.waves.len())
            .max()
            .unwrap();
        let (files, _) = write_sweep(&plan, &records, &dir);
        let (json_bytes, csv_bytes) = (size_of(&files, ".json"), size_of(&files, ".csv"));
        report(format!(
            "real sweep, {} runs of N = {n}, {} flip(s), up to {most_waves} waves a run: JSON {} bytes (estimate {:.0}, {:.2}×), CSV {} bytes (estimate {:.0})",
            plan.len(),
            scene.drive.flips.len(),
            json_bytes,
            estimate.json,
            estimate.json / json_bytes as f64,
            csv_bytes,
            estimate.csv
        ));
        assert!(json_bytes as f64 <= estimate.json);
        assert!(csv_bytes as f64 <= estimate.csv);
        assert!(
            json_bytes as f64 * 4.0 >= estimate.json,
            "N = {n}: the estimate {} is more than 4 times the JSON {json_bytes}",
            estimate.json
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

fn ladder(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .output()
        .unwrap()
}

/// `ladder sweep` with `--max-data-bytes` just under the estimate of its
/// files is refused before any run (exit 2, one line naming the flag,
/// nothing written, no shards/); at the estimate it runs and writes files
/// within it. `sweep gather` takes the flag too, and checks the files'
/// real sizes.
#[test]
fn a_sweep_past_its_data_cap_is_refused_before_any_run() {
    let _one = lock();
    let dir = tmp("cli");
    let file = dir.join("s.toml");
    let grid = "alpha = \"-50:-60:-2\"\ngamma = [0.01, 0.02, 0.04]";
    std::fs::write(
        &file,
        format!(
            "name = \"s\"\n[model]\nn = 10\n[output]\nkind = \"sweep\"\n[output.grid]\n{grid}\n"
        ),
    )
    .unwrap();
    let plan = plan_of(&sweep_scene(10, grid, ""));
    let cap = json::estimate(&plan).json;
    let out = dir.join("out");
    let out_s = out.to_str().unwrap();
    let sweep_with_cap = |cap: f64| {
        ladder(&[
            "sweep",
            file.to_str().unwrap(),
            "--out",
            out_s,
            "--max-data-bytes",
            &format!("{cap}"),
        ])
    };
    let o = sweep_with_cap((cap * (1.0 - 1e-9)).floor());
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("--max-data-bytes") && err.contains("JSON of sweep s"),
        "{err}"
    );
    assert!(
        !out.join("shards").exists() && !out.join("sweep-s.json").exists(),
        "refused before any run: nothing written"
    );
    let at = format!("{}", cap.ceil());
    let o = sweep_with_cap(cap.ceil());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let written = std::fs::metadata(out.join("sweep-s.json")).unwrap().len();
    assert!(written as f64 <= cap, "{written} past the estimate {cap}");
    // Gather counts the files it is about to write.
    let o = ladder(&["sweep", "gather", out_s, "--max-data-bytes", "1000"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("--max-data-bytes"), "{err}");
    let o = ladder(&["sweep", "gather", out_s, "--max-data-bytes", &at]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let _ = std::fs::remove_dir_all(&dir);
}

/// docs/limits.md's bound on a simulation's memory: 0.4 kB per block and
/// 48 bytes per block and kept sample (state and velocity), plus 64 MB.
fn simulation_bound(n: usize, samples: usize) -> f64 {
    400.0 * n as f64 + 48.0 * (n * samples) as f64 + 64e6
}

/// At the default cap on samples × N (5 × 10⁷): N = 100 000 kept at 500
/// samples, one step of dt apart. The peak heap is under the documented
/// bound (2.5 GB); 501 samples are refused before any work.
#[test]
fn a_simulation_at_the_cap_on_samples_stays_within_its_bound() {
    use jacobs_ladder::model::Params;
    use jacobs_ladder::sim::RunOptions;
    use jacobs_ladder::sim::{self, IntegratorConfig, IntegratorKind, Scenario};
    let _one = lock();
    let limits = Limits::default();
    let n = 100_000;
    let samples = (limits.block_samples / n as f64) as usize;
    assert_eq!(samples, 500);
    let dt = 0.05;
    let t_end = dt * samples as f64;
    let params = Params::paper(60.0).unwrap().with(n, 1.3, 60.0).unwrap();
    let scenario = Scenario::single_flip(params, 1000.0, t_end).unwrap();
    let config = IntegratorConfig::fixed(IntegratorKind::Verlet, dt);
    let times = |k: usize| -> Vec<f64> { (1..=k).map(|i| t_end * i as f64 / k as f64).collect() };
    // One more sample: refused before any work.
    let (refused, peak, _) = measure(|| {
        sim::run(
            &scenario,
            &times(samples + 1),
            &config,
            &RunOptions::default().limits(limits),
        )
    });
    match refused {
        Err(Error::Limit(l)) => assert_eq!(l.resource, Resource::BlockSamples),
        other => panic!(
            "expected the cap on samples × N, got {:?}",
            other.map(|t| t.steps)
        ),
    }
    assert!(peak < 10_000_000, "refused before any work: {peak} bytes");
    let start = std::time::Instant::now();
    let (traj, peak, _) = measure(|| {
        sim::run(
            &scenario,
            &times(samples),
            &config,
            &RunOptions::default().limits(limits),
        )
        .unwrap()
    });
    assert_eq!(traj.states.len(), samples);
    let bound = simulation_bound(n, samples);
    report(format!(
        "simulation at the cap on samples × N (N = {n}, {samples} samples): peak heap {:.3} GB, bound {:.3} GB, {:.1} s",
        peak as f64 / 1e9,
        bound / 1e9,
        start.elapsed().as_secs_f64()
    ));
    assert!(
        peak as f64 <= bound,
        "peak {peak} bytes past the documented {bound}"
    );
    // Not a loose bound: the samples themselves are most of it.
    assert!(peak as f64 >= 48.0 * 5e7, "{peak}");
}

/// A movie's frames are encoded as they are drawn: four times the frames
/// add to the peak heap no more than the encoded files grew (and the
/// samples, 48 bytes per block and frame), far less than the raw frames
/// (320 × 240 × 4 bytes each) would be if they were kept. This is what
/// makes the cap on frames × pixels a cap on time, not on memory.
#[test]
fn a_movies_memory_does_not_grow_with_its_frames() {
    let _one = lock();
    let dir = tmp("movie");
    let text = "name = \"mem\"\n[model]\nn = 10\n[[drive.flips]]\nstart = 0.0\nduration = 20.0\n\
                [run]\nt_end = 40.0\nintegrator = \"verlet\"\ndt = 0.05\n[output]\nkind = \"movie\"\n";
    let scene = scene::file::parse(text, "memory_caps.rs", "mem").unwrap();
    let (width, height) = (320u32, 240u32);
    let mut seen = Vec::new();
    for frames in [20usize, 80] {
        let movie = MovieOptions {
            frames,
            width,
            height,
            fps: 10.0,
        };
        let ((), peak, _) = measure(|| {
            scenes::render_to(
                &scene,
                &movie,
                &Outputs::default(),
                &|| {},
                &mut |name, fill| {
                    let mut f = std::fs::File::create(dir.join(name)).unwrap();
                    fill(&mut f).unwrap();
                    Ok(())
                },
            )
            .unwrap()
        });
        let encoded: u64 = std::fs::read_dir(&dir)
            .unwrap()
            .flatten()
            .filter(|e| !e.file_name().to_string_lossy().ends_with(".json"))
            .map(|e| e.metadata().unwrap().len())
            .sum();
        report(format!(
            "movie of {frames} frames of {width}×{height}, N = 10: peak heap {:.2} MB, encoded files {:.2} MB",
            peak as f64 / 1e6,
            encoded as f64 / 1e6
        ));
        seen.push((frames, peak, encoded));
    }
    let (f0, p0, e0) = seen[0];
    let (f1, p1, e1) = seen[1];
    let raw_frames = ((f1 - f0) as u64) * u64::from(width * height) * 4;
    let allowed = e1.saturating_sub(e0) + 48 * 10 * (f1 - f0) as u64 + 1_000_000;
    assert!(
        p1 <= p0 + allowed,
        "the peak grew from {p0} to {p1} bytes for {f0} → {f1} frames (allowed {allowed})"
    );
    assert!(allowed < raw_frames / 3, "{allowed} vs {raw_frames}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// What a sweep holds per run (its point and its record, N = 10 and 40):
/// the bytes still live after its runs, at two grid sizes, against
/// docs/limits.md's words (0.4 kB a run, plus 16 bytes per
/// block for each list of arrival times: the run's and each wave's).
/// Measured: 678 bytes a run at N = 10 with one wave a run.
#[test]
fn a_sweep_holds_a_bounded_number_of_bytes_per_run() {
    let _one = lock();
    // Warm the thread pool and the caches once.
    let warm = plan_of(&sweep_scene(10, "alpha = \"50:52:1\"", ""));
    let _ = warm.run(&[0, 1, 2], &|| {}).unwrap();
    for (n, small, large) in [
        (10, "alpha = \"50:59.5:0.5\"", "alpha = \"50:69.9:0.1\""),
        (40, "alpha = \"50:59.5:0.5\"", "alpha = \"50:69.9:0.1\""),
    ] {
        let held = |grid: &str| {
            let ((plan, records), _, live) = measure(|| {
                let plan = plan_of(&sweep_scene(n, grid, ""));
                let all: Vec<usize> = (0..plan.len()).collect();
                let records = plan.run(&all, &|| {}).unwrap();
                (plan, records)
            });
            let lists: usize = records.iter().map(|r| 1 + r.result.waves.waves.len()).sum();
            (plan.len(), live, lists)
        };
        let (r0, l0, w0) = held(small);
        let (r1, l1, w1) = held(large);
        let per_run = (l1 as f64 - l0 as f64) / (r1 - r0) as f64;
        let lists_per_run = (w1 - w0) as f64 / (r1 - r0) as f64;
        let documented = 400.0 + 16.0 * n as f64 * lists_per_run;
        report(format!(
            "sweep at N = {n}: {:.0} bytes held per run ({r0} and {r1} runs; {lists_per_run:.2} lists of arrival times a run), documented {documented:.0}",
            per_run
        ));
        assert!(
            per_run <= documented,
            "N = {n}: {per_run} bytes a run, past the documented {documented}"
        );
    }
}
