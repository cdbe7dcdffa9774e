//! `ladder sweep` (docs/sweeps.md): outcomes decided on real runs, files
//! byte-identical between runs and between a sharded and an unsharded
//! sweep, resume, gather, and bad input.

use crate::common;

use jacobs_ladder::scene::sweep::{Grid, Param, SweepSpec, Values};
use jacobs_ladder::scene::{OutputSpec, Scene};
use jacobs_ladder::sweep::outcome::Outcome;
use jacobs_ladder::sweep::run::{run_point, run_points};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::common::ladder_cli as ladder;

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ladder-sweep-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn ok(out: &Output) {
    assert!(
        out.status.success(),
        "exit {:?}: {}",
        out.status.code(),
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Everything under `dir`, recursively (relative paths).
fn files_under(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        if let Ok(rd) = std::fs::read_dir(&d) {
            for e in rd.flatten() {
                let p = e.path();
                if p.is_dir() {
                    stack.push(p);
                } else {
                    out.push(p.strip_prefix(dir).unwrap().display().to_string());
                }
            }
        }
    }
    out.sort();
    out
}

/// Exit 2, one line naming `needle`, and nothing written under `dir`.
fn assert_bad(args: &[&str], dir: &Path, needle: &str) {
    let out = ladder(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert_eq!(stderr.lines().count(), 1, "{args:?}: one line: {stderr}");
    assert!(
        stderr.contains(needle),
        "{args:?}: '{needle}' not in {stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(
        files_under(dir).is_empty(),
        "{args:?} wrote {:?}",
        files_under(dir)
    );
}

const GRID: [&str; 4] = ["--alpha=-50,-53,-56,-60", "--gamma", "0.02,0.04", "--name"];

fn sweep_args<'a>(out: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut a = vec!["sweep"];
    a.extend(GRID);
    a.push("g");
    a.extend(["--out", out]);
    a.extend(extra);
    a
}

/// A sweep file's bytes, as they are: they depend on the sweep only (not
/// on the folder, the program's path or the shards), so the JSON records
/// no command line.
fn recorded(path: &std::path::Path) -> Vec<u8> {
    let bytes = std::fs::read(path).unwrap();
    if path.extension().is_some_and(|e| e == "json") {
        let v: serde_json::Value = serde_json::from_slice(&bytes).unwrap();
        assert_eq!(
            v["command_line"],
            serde_json::json!([]),
            "{}",
            path.display()
        );
    }
    bytes
}

#[test]
fn three_concurrent_shards_gather_into_the_unsharded_files_byte_for_byte() {
    let whole = tmp("whole");
    let w = whole.to_str().unwrap();
    ok(&ladder(&sweep_args(w, &[])));
    let csv = std::fs::read_to_string(whole.join("sweep-g.csv")).unwrap();
    assert_eq!(csv.lines().count(), 9, "{csv}");
    assert!(csv.starts_with(
        "run,alpha,n,b,gamma,gravity,inertia,drive_time,outcome,blocks_flipped,front,speed,t_decided,block_n_turned_at,waves\n"
    ));
    assert!(whole.join("sweep-g.png").is_file());

    // Again, elsewhere: byte-identical.
    let again = tmp("again");
    ok(&ladder(&sweep_args(again.to_str().unwrap(), &[])));
    for f in ["sweep-g.csv", "sweep-g.json", "sweep-g.png"] {
        assert_eq!(
            recorded(&whole.join(f)),
            recorded(&again.join(f)),
            "{f} differs between two runs"
        );
    }

    // Three shards as separate processes at the same time.
    let sharded = tmp("sharded");
    let s = sharded.to_str().unwrap();
    let procs: Vec<_> = (1..=3)
        .map(|k| {
            let shard = format!("{k}/3");
            Command::new(env!("CARGO_BIN_EXE_ladder"))
                .args(sweep_args(s, &["--shard", &shard]))
                .stderr(std::process::Stdio::piped())
                .spawn()
                .expect("spawn a shard")
        })
        .collect();
    for p in procs {
        ok(&p.wait_with_output().unwrap());
    }
    assert!(
        !sharded.join("sweep-g.csv").exists(),
        "a shard writes only its shard file"
    );
    ok(&ladder(&["sweep", "gather", s]));
    for f in ["sweep-g.csv", "sweep-g.json", "sweep-g.png"] {
        assert_eq!(
            recorded(&whole.join(f)),
            recorded(&sharded.join(f)),
            "{f}: gathered differs from unsharded"
        );
    }
    for d in [whole, again, sharded] {
        let _ = std::fs::remove_dir_all(d);
    }
}

#[test]
fn a_rerun_redoes_only_what_is_missing() {
    let dir = tmp("resume");
    let d = dir.to_str().unwrap();
    ok(&ladder(&sweep_args(d, &["--shard", "1/2"])));
    let shard = dir.join("shards/sweep-g.1-of-2.json");
    let full = std::fs::read(&shard).unwrap();
    // Keep one of its four runs, as a killed shard would have left it.
    let mut v: serde_json::Value = serde_json::from_slice(&full).unwrap();
    let records = v["records"].as_array_mut().unwrap();
    assert_eq!(records.len(), 4);
    records.truncate(1);
    std::fs::write(&shard, serde_json::to_vec(&v).unwrap()).unwrap();
    let out = ladder(&sweep_args(d, &["--shard", "1/2"]));
    ok(&out);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("1 of 4 runs already done"), "{err}");
    assert!(err.contains("(3 new)"), "{err}");
    assert_eq!(std::fs::read(&shard).unwrap(), full);
    // A finished shard reruns nothing.
    let out = ladder(&sweep_args(d, &["--shard", "1/2"]));
    assert!(String::from_utf8_lossy(&out.stderr).contains("(0 new)"));
    // No temporary files are left behind.
    assert!(
        files_under(&dir).iter().all(|f| !f.contains(".tmp")),
        "{:?}",
        files_under(&dir)
    );
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn gather_refuses_an_empty_folder_two_sweeps_and_a_missing_shard() {
    let dir = tmp("gather");
    let d = dir.to_str().unwrap();
    std::fs::create_dir_all(dir.join("shards")).unwrap();
    let out = ladder(&["sweep", "gather", d]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no shard files"));

    ok(&ladder(&sweep_args(d, &["--shard", "1/3"])));
    ok(&ladder(&sweep_args(d, &["--shard", "3/3"])));
    let before = files_under(&dir);
    let out = ladder(&["sweep", "gather", d]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("shard 2/3") && err.contains("not found"),
        "{err}"
    );
    assert_eq!(files_under(&dir), before, "nothing written");

    // A shard of another sweep (another grid) in the same folder.
    ok(&ladder(&[
        "sweep",
        "--alpha=-50,-53,-56,-61",
        "--gamma",
        "0.02,0.04",
        "--name",
        "g",
        "--out",
        d,
        "--shard",
        "2/3",
    ]));
    let before = files_under(&dir);
    let out = ladder(&["sweep", "gather", d]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("two different sweeps"), "{err}");
    assert_eq!(files_under(&dir), before, "nothing written");
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn bad_input_exits_2_with_one_line_and_writes_nothing() {
    let dir = tmp("bad");
    let d = dir.to_str().unwrap();
    let cases: &[(&[&str], &str)] = &[
        (&["--alpha", "1:2:0"], "must not be 0"),
        (&["--alpha=-45:-60:0.5"], "never reaches -60"),
        (&["--alpha", "40:NaN:1"], "not a finite number"),
        (&["--gamma", "0.01,nan"], "not a finite number"),
        (&["--alpha=-45:-95:-5"], "--alpha: the value -90"),
        (&["--n", "3:10:1"], "N >= 4"),
        (&["--gamma=0.1:-0.1:-0.1"], "--gamma: the value -0.1"),
        (
            &["--alpha", "40:89:0.001", "--gamma", "0.01:0.5:0.01"],
            "past the cap of 100000 runs",
        ),
        (&["--alpha", "50", "--shard", "0/3"], "--shard"),
        (&["--alpha", "50", "--shard", "4/3"], "from 1 to N = 3"),
        (&["--alpha", "50", "--cap", "10"], "--cap"),
        (&[], "grid flag"),
    ];
    for (args, needle) in cases {
        let mut a = vec!["sweep"];
        a.extend(*args);
        a.extend(["--out", d]);
        assert_bad(&a, &dir, needle);
    }
    let out = ladder(&[
        "sweep",
        "--alpha",
        "40:89:0.001",
        "--gamma",
        "0.01:0.5:0.01",
        "--out",
        d,
    ]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("--max-runs"));
    // A malformed sweep file names the file, line and key.
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("s.toml");
    std::fs::write(
        &f,
        "[model]\nn = 10\n[output]\nkind = \"sweep\"\n[output.grid]\nalpha = \"-45:-60:0.5\"\n",
    )
    .unwrap();
    let out = ladder(&["sweep", f.to_str().unwrap(), "--out", d]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("s.toml:6:9"), "{err}");
    assert!(err.contains("never reaches"), "{err}");
    std::fs::write(
        &f,
        "[output]\nkind = \"sweep\"\n[output.grid]\nalpah = [50, 60]\n",
    )
    .unwrap();
    let out = ladder(&["sweep", f.to_str().unwrap(), "--out", d]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("unknown parameter 'alpah'"), "{err}");
    assert_eq!(files_under(&dir), vec!["s.toml".to_string()]);
    let _ = std::fs::remove_dir_all(dir);
}

fn scene_at(alpha: f64) -> (Scene, SweepSpec) {
    let spec = SweepSpec {
        grid: Grid::new(vec![(
            Param::Alpha,
            Values::parse(&alpha.to_string()).unwrap(),
        )]),
        ..SweepSpec::default()
    };
    let mut s = Scene::default();
    s.model.alpha = alpha;
    s.output = OutputSpec::Data;
    (s, spec)
}

/// Near the antikink's transition (N = 10, b = 1.3, the paper's γ and G):
/// a wave that takes longer than the paper's window is still called
/// propagated, and one that stops in the bulk is called stalled — and it
/// really stopped: run on to 4 × its decision time, nothing more flips.
#[test]
fn slow_and_stopped_waves_are_told_apart_on_real_runs() {
    let (s, spec) = scene_at(-52.5);
    let r = run_point(&s, &spec).unwrap();
    assert_eq!(r.outcome, Outcome::Propagated, "{r:?}");
    let t = r.t_decided.unwrap();
    assert!(t > 3.0 * 4000.0, "slower than the paper's window: {t}");

    let (s, spec) = scene_at(-52.0);
    let r = run_point(&s, &spec).unwrap();
    assert_eq!(r.outcome, Outcome::Stalled, "{r:?}");
    assert_eq!(r.front, 6, "{r:?}");
    // Its longest gap is several thousand τ, far past the paper's window.
    let t_stop = r.t_decided.unwrap();
    let long = {
        let mut s2 = s.clone();
        s2.run.t_end = 4.0 * t_stop;
        jacobs_ladder::scenes::run::simulate(&s2, &[]).unwrap()
    };
    let flipped = long
        .trajectory
        .arrival_times
        .iter()
        .filter(|a| a.is_some())
        .count();
    assert_eq!(
        flipped, 6,
        "the stalled wave moved on: {:?}",
        long.trajectory.arrival_times
    );

    let (s, spec) = scene_at(-50.0);
    let r = run_point(&s, &spec).unwrap();
    assert_eq!(r.outcome, Outcome::Pinned, "{r:?}");
    assert!(r.front <= 2);
    assert_eq!(r.speed, None);

    let (s, spec) = scene_at(60.0);
    let r = run_point(&s, &spec).unwrap();
    assert_eq!(r.outcome, Outcome::Propagated);
    assert!(r.t_decided.unwrap() < 4000.0, "stopped early: {r:?}");
    assert!(r.arrival_error.unwrap() <= 0.1 / 3.0 + 1e-12);
}

/// Many points at once (`run_points`: rounds through the batch kernel)
/// give every point exactly what running it alone gives (`run_point`: one
/// point is too few for the lanes and runs on the one-run path), bit for
/// bit: kinks and antikinks that propagate, stall and stay pinned,
/// two chain lengths, two drive times (two stop rules), a fixed Verlet
/// step, a diverging fixed step, and points still undecided at a low cap.
#[test]
fn many_points_at_once_equal_each_point_alone() {
    use jacobs_ladder::scene::Method;
    use jacobs_ladder::sim::IntegratorKind;
    let (_, spec) = scene_at(60.0);
    let mut scenes = Vec::new();
    for alpha in [
        -40.0, -50.0, -52.0, -52.5, -55.0, -60.0, -75.0, -89.0, 40.0, 52.0, 60.0, 75.0, 89.0,
    ] {
        let (s, _) = scene_at(alpha);
        scenes.push(s);
    }
    for (alpha, n) in [
        (60.0, 12),
        (-60.0, 12),
        (65.0, 12),
        (70.0, 12),
        (-70.0, 12),
        (80.0, 12),
    ] {
        let (mut s, _) = scene_at(alpha);
        s.model.n = n;
        scenes.push(s);
    }
    for t_d in [200.0, 200.0, 200.0, 200.0, 200.0, 200.0, 500.0] {
        let (mut s, _) = scene_at(65.0);
        s.drive.flips[0].duration = t_d;
        scenes.push(s);
    }
    for (kind, dt, alpha) in [
        (IntegratorKind::Verlet, 0.25, 60.0),
        (IntegratorKind::Verlet, 0.25, -60.0),
        (IntegratorKind::SymplecticEuler, 0.95, 60.0),
        (IntegratorKind::SymplecticEuler, 0.95, 70.0),
    ] {
        let (mut s, _) = scene_at(alpha);
        s.run.integrator = Method::Fixed(kind);
        s.run.dt = Some(dt);
        scenes.push(s);
    }
    let alone: Vec<_> = scenes
        .iter()
        .map(|s| run_point(s, &spec).unwrap())
        .collect();
    let together = run_points(&scenes, &spec).unwrap();
    assert_eq!(together.len(), alone.len());
    for (k, (a, b)) in alone.iter().zip(&together).enumerate() {
        assert_eq!(
            a, b,
            "point {k} ({} at alpha {})",
            scenes[k].name, scenes[k].model.alpha
        );
    }
    let outcomes: std::collections::BTreeSet<_> = alone.iter().map(|r| r.outcome.name()).collect();
    for o in ["propagated", "stalled", "pinned", "diverged"] {
        assert!(outcomes.contains(o), "the set covers {o}: {outcomes:?}");
    }

    // A cap below the slow antikinks' decision: undecided, alike.
    let low = SweepSpec {
        cap: 3000.0,
        ..spec.clone()
    };
    let slow: Vec<Scene> = [-52.0, -52.5, -53.0, -54.0, -60.0, -70.0, -80.0]
        .iter()
        .map(|&a| scene_at(a).0)
        .collect();
    let alone: Vec<_> = slow.iter().map(|s| run_point(s, &low).unwrap()).collect();
    assert_eq!(run_points(&slow, &low).unwrap(), alone);
    assert!(
        alone.iter().any(|r| r.outcome == Outcome::Undecided),
        "{alone:?}"
    );
}

#[test]
fn a_diverging_fixed_step_is_a_diverged_row_not_a_failed_sweep() {
    let dir = tmp("diverged");
    let d = dir.to_str().unwrap();
    ok(&ladder(&[
        "sweep",
        "--alpha",
        "60",
        "--gamma",
        "0.02,0.04",
        "--integrator",
        "symplectic-euler",
        "--dt",
        "0.95",
        "--name",
        "x",
        "--out",
        d,
    ]));
    let csv = std::fs::read_to_string(dir.join("sweep-x.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().skip(1).collect();
    assert_eq!(rows.len(), 2);
    for r in rows {
        // outcome, blocks flipped, front, speed, t_decided,
        // block_n_turned_at, waves.
        assert!(r.ends_with(",diverged,0,0,,,,0"), "{r}");
    }
    let json = std::fs::read_to_string(dir.join("sweep-x.json")).unwrap();
    assert!(json.contains("diverged at t ="), "the message says when");
    let _ = std::fs::remove_dir_all(dir);
}

/// docs/cluster.md's GNU parallel line, run as written, when GNU parallel
/// is installed.
#[test]
fn the_documented_gnu_parallel_line_works() {
    if !common::require::require(
        "the_documented_gnu_parallel_line_works",
        common::require::runs("parallel", "--version", "GNU parallel"),
        "GNU parallel is not installed",
        "install Debian's parallel; .ci/run does",
    ) {
        return;
    }
    let doc =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/cluster.md")).unwrap();
    let line = doc
        .lines()
        .find(|l| l.trim_start().starts_with("parallel "))
        .expect("docs/cluster.md has a line starting with `parallel `")
        .trim();
    let dir = with_example_sweep("parallel");
    let out = Command::new("bash")
        .arg("-c")
        .arg(format!("{line} && ladder sweep gather out"))
        .current_dir(&dir)
        .env("PATH", path_with_ladder())
        .output()
        .unwrap();
    ok(&out);
    assert_gathered_equals_unsharded(&dir);
}

/// A fresh folder holding examples/slurm/sweep.toml.
fn with_example_sweep(name: &str) -> PathBuf {
    let dir = tmp(name);
    std::fs::create_dir_all(&dir).unwrap();
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/slurm/sweep.toml");
    std::fs::copy(file, dir.join("sweep.toml")).unwrap();
    dir
}

/// PATH with the folder of the `ladder` under test first.
fn path_with_ladder() -> String {
    let bin = Path::new(env!("CARGO_BIN_EXE_ladder")).parent().unwrap();
    format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    )
}

/// The CSV gathered in `dir/out` equals an unsharded run of
/// `dir/sweep.toml`, byte for byte; then `dir` is removed.
fn assert_gathered_equals_unsharded(dir: &Path) {
    let whole = dir.join("whole");
    ok(&ladder(&[
        "sweep",
        dir.join("sweep.toml").to_str().unwrap(),
        "--out",
        whole.to_str().unwrap(),
    ]));
    assert_eq!(
        std::fs::read(dir.join("out/sweep-antikink-damping.csv")).unwrap(),
        std::fs::read(whole.join("sweep-antikink-damping.csv")).unwrap()
    );
    let _ = std::fs::remove_dir_all(dir);
}

/// examples/slurm/sweep.sbatch, run as Slurm would run three array tasks
/// (its environment variables), all at once, then gathered.
#[test]
fn the_slurm_array_script_runs_its_shard() {
    let dir = with_example_sweep("slurm");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let path = path_with_ladder();
    let tasks: Vec<_> = (0..3)
        .map(|id| {
            Command::new("bash")
                .arg(root.join("examples/slurm/sweep.sbatch"))
                .current_dir(&dir)
                .env("PATH", &path)
                .env("SLURM_ARRAY_TASK_ID", id.to_string())
                .env("SLURM_ARRAY_TASK_COUNT", "3")
                .env("SHARDS", "3")
                .env("SLURM_CPUS_PER_TASK", "1")
                .stderr(std::process::Stdio::piped())
                .spawn()
                .unwrap()
        })
        .collect();
    for t in tasks {
        ok(&t.wait_with_output().unwrap());
    }
    ok(&ladder(&[
        "sweep",
        "gather",
        dir.join("out").to_str().unwrap(),
    ]));
    assert_gathered_equals_unsharded(&dir);
}

/// The supplement's 3D-printed linkage model (a = 7 cm, b = 6 cm, s = 5 cm,
/// 8 blocks, α ≈ 69°): the paper says the antikink "stops halfway". In the
/// model of docs/model.md it reaches block N − 1, at the paper's γ and G, with
/// little damping and with a stiffer chain (docs/paper-errata.md).
#[test]
fn the_printed_linkage_model_does_not_stop_halfway() {
    let (b, a): (f64, f64) = (6.0 / 5.0, 7.0 / 5.0);
    let alpha = ((a * a - b * b).sqrt() / 2.0).acos().to_degrees();
    assert!((alpha - 68.87).abs() < 0.01, "{alpha}");
    for (gamma, gravity) in [(0.02, 2e-4), (0.005, 2e-4), (0.02, 5e-5), (0.16, 8e-4)] {
        for sign in [-1.0, 1.0] {
            let (mut s, spec) = scene_at(sign * alpha);
            s.model.n = 8;
            s.model.b = b;
            s.model.gamma = gamma;
            s.model.gravity = gravity;
            let r = run_point(&s, &spec).unwrap();
            assert_eq!(
                (r.outcome, r.front),
                (Outcome::Propagated, 7),
                "α = {}, γ = {gamma}, G = {gravity}: {r:?}",
                sign * alpha
            );
        }
    }
}

/// The catalogue's `friction` figure, and what its caption says the data
/// show: friction against gravity sets the antikink's speed where γ is
/// large against G (equal G/γ, equal speed; speed ∝ G/γ), and not at low
/// damping.
#[test]
fn the_friction_figure_shows_what_its_caption_says() {
    use jacobs_ladder::sweep::Plan;
    let entry = jacobs_ladder::catalog::find_any("friction").unwrap();
    let plan = Plan::new(&entry.scene, 1000).unwrap().unwrap();
    let all: Vec<usize> = (0..plan.len()).collect();
    let records = plan.run(&all, &|| {}).unwrap();
    assert_eq!(records.len(), 25);
    let (kg, kgamma) = (
        plan.axes
            .iter()
            .position(|(p, _)| *p == Param::Gravity)
            .unwrap(),
        plan.axes
            .iter()
            .position(|(p, _)| *p == Param::Gamma)
            .unwrap(),
    );
    // Speeds by G/γ (rounded to 1e-9 to group equal ratios).
    let mut by_ratio: std::collections::BTreeMap<i64, Vec<f64>> = Default::default();
    for r in &records {
        assert_eq!(r.result.outcome, Outcome::Propagated, "{r:?}");
        let p = &plan.points[r.run];
        let ratio = p[kg] / p[kgamma];
        by_ratio
            .entry((ratio * 1e9).round() as i64)
            .or_default()
            .push(r.result.speed.unwrap());
    }
    let spread = |v: &[f64]| {
        let (lo, hi) = v
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(a, b), x| (a.min(*x), b.max(*x)));
        hi / lo - 1.0
    };
    for (&key, speeds) in &by_ratio {
        let ratio = key as f64 * 1e-9;
        let mean = speeds.iter().sum::<f64>() / speeds.len() as f64;
        if ratio <= 0.005 + 1e-12 {
            assert!(spread(speeds) <= 0.06, "G/γ = {ratio}: {speeds:?}");
            // About 0.30 G/γ blocks per τ.
            assert!((mean / ratio - 0.30).abs() < 0.015, "G/γ = {ratio}: {mean}");
        }
        if (ratio - 0.02).abs() < 1e-12 {
            assert!(spread(speeds) > 0.3, "inertia at low damping: {speeds:?}");
            assert!(
                mean < 0.9 * 0.30 * ratio,
                "below the proportional law: {mean}"
            );
        }
        if (ratio - 0.01).abs() < 1e-12 {
            let s = spread(speeds);
            assert!((0.15..0.25).contains(&s), "the paper's G/γ: {speeds:?}");
        }
    }
}

/// A sweep whose drive flips block 1 twice has two waves per run: the CSV
/// says how many and gives each wave's kind, launch, front and fate in its
/// own columns (docs/sweeps.md, "The files"); the outcome columns stay the
/// first wave's. Expected: the first flip launches a kink at α > 0, the
/// second (block 1 turned back) an antikink (the tracker's definition,
/// `sim::waves`), launched at the second flip's midpoint or later. (The
/// second flip starts before the first wave is decided: a sweep's run
/// ends at its outcome.)
#[test]
fn a_two_flip_sweep_has_per_wave_columns() {
    let dir = tmp("two-flips");
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("two.toml");
    std::fs::write(
        &scene,
        "name = \"two\"\n[model]\nn = 10\n[drive]\nflips = [{ start = 0, duration = 1000 }, \
         { start = 1000, duration = 1000 }]\n[run]\nt_end = 6000\nintegrator = \"verlet\"\n\
         dt = 0.25\n[output]\nkind = \"sweep\"\n[output.grid]\nalpha = [60, 70]\n",
    )
    .unwrap();
    ok(&ladder(&[
        "render",
        scene.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ]));
    let csv = std::fs::read_to_string(dir.join("figure-two.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| {
        header
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("no column {name}: {header:?}"))
    };
    for line in lines {
        let row: Vec<&str> = line.split(',').collect();
        assert_eq!(row.len(), header.len(), "{line}");
        assert_eq!(row[col("waves")], "2", "{line}");
        assert_eq!(row[col("wave1_kind")], "kink", "{line}");
        assert_eq!(row[col("wave2_kind")], "antikink", "{line}");
        assert_eq!(row[col("wave1_launched_at")], "500", "{line}");
        let second: f64 = row[col("wave2_launched_at")].parse().unwrap();
        assert!(second >= 1500.0, "{line}");
        for k in [1, 2] {
            let fate = row[col(&format!("wave{k}_fate"))];
            assert!(
                ["end", "stopped", "annihilated", "undecided"].contains(&fate),
                "{line}"
            );
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The pinning chart draws the front up to N − 1 and block N's own turn
/// apart (docs/sweeps.md): in the CSV, `front` never passes N − 1 and
/// `block_n_turned_at` is filled exactly where block N fell over first; in
/// the chart, the legend names both marks.
#[test]
fn the_sweep_keeps_block_n_apart_from_the_front() {
    let dir = tmp("block-n");
    let d = dir.to_str().unwrap();
    ok(&ladder(&[
        "sweep",
        "--alpha",
        "40,48,49,60",
        "--n",
        "10",
        "--integrator",
        "verlet",
        "--dt",
        "0.25",
        "--name",
        "b",
        "--format",
        "svg",
        "--out",
        d,
    ]));
    let csv = std::fs::read_to_string(dir.join("sweep-b.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    for line in lines {
        let row: Vec<&str> = line.split(',').collect();
        let alpha: f64 = row[col("alpha")].parse().unwrap();
        // Up to 48° the wall block N launched meets the driven kink: the
        // chain ends flipped, but the driven wave was annihilated.
        let word = if alpha <= 48.0 {
            "annihilated"
        } else {
            "propagated"
        };
        assert_eq!(row[col("outcome")], word, "{line}");
        assert_eq!(row[col("front")], "9", "{line}");
        // Blocks 1..N − 1 counted, as the front: block N is apart.
        assert_eq!(row[col("blocks_flipped")], "9", "{line}");
        assert_eq!(
            !row[col("block_n_turned_at")].is_empty(),
            alpha <= 48.0,
            "{line}"
        );
    }
    let svg = std::fs::read_to_string(dir.join("sweep-b.svg")).unwrap();
    assert!(svg.contains("block N turned first"), "no block N mark");
    assert!(svg.contains("annihilated at"), "no meeting mark");
    let _ = std::fs::remove_dir_all(&dir);
}
