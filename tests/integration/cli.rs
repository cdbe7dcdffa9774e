//! The command-line contract (README.md): exit codes, one-line errors,
//! `simulate --json` fields and the CSV file.

use jacobs_ladder::theory::TheoryReport;
use std::process::{Command, Output};

use crate::common::ladder_cli as ladder;

/// `ladder ARGS`, which must exit 0 (its stderr shown if not).
fn ladder_ok(args: &[&str]) -> Output {
    let out = ladder(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
    out
}

fn assert_bad_input(args: &[&str], needle: &str) {
    let out = ladder(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: stderr {stderr}");
    assert_eq!(
        stderr.lines().count(),
        1,
        "{args:?}: one line wanted, got {stderr}"
    );
    assert!(
        stderr.contains(needle),
        "{args:?}: '{needle}' not in {stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(out.stdout.is_empty(), "{args:?}: no result on bad input");
}

/// `ladder ARGS`'s one JSON object on stdout (exit 0), checked to have
/// every one of `keys`.
fn json_with(args: &[&str], keys: &[&str]) -> serde_json::Value {
    let out = ladder_ok(args);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON object");
    for key in keys {
        assert!(v.get(key).is_some(), "{args:?}: missing {key}");
    }
    v
}

#[test]
fn simulate_rejects_bad_input_with_one_line() {
    let short = ["simulate", "--t-end", "10"];
    let with = |extra: &[&'static str]| -> Vec<&'static str> {
        short.iter().copied().chain(extra.iter().copied()).collect()
    };
    assert_bad_input(&with(&["--alpha", "95"]), "alpha");
    assert_bad_input(&with(&["--alpha", "-90"]), "alpha");
    assert_bad_input(&with(&["--alpha", "0"]), "alpha");
    assert_bad_input(&with(&["--alpha", "NaN"]), "alpha");
    assert_bad_input(&with(&["--n", "1"]), "--n");
    assert_bad_input(&with(&["--dt", "0"]), "dt");
    assert_bad_input(&with(&["--dt", "-0.01"]), "dt");
    assert_bad_input(&with(&["--dt", "inf"]), "dt");
    assert_bad_input(&with(&["--b", "0"]), "b");
    assert_bad_input(&with(&["--gamma", "-1"]), "gamma");
    assert_bad_input(&["simulate", "--t-end", "-5"], "--t-end");
    assert_bad_input(&with(&["--integrator", "leapfrog"]), "unknown integrator");
    assert_bad_input(&with(&["--alpha", "sixty"]), "--alpha");
    assert_bad_input(
        &with(&["--csv", "/dev/null/x.csv"]),
        "cannot write to /dev/null",
    );
    assert_bad_input(&with(&["--rtol", "1e-6"]), "rtol");
    assert_bad_input(&["frobnicate"], "frobnicate");
}

#[test]
fn diverging_run_exits_1_with_time_and_hint() {
    let out = ladder(&["simulate", "--integrator", "explicit-euler", "--json"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("diverged at t = ") && stderr.contains("hint"),
        "{stderr}"
    );
    assert!(out.stdout.is_empty(), "a diverged run prints no result");
}

#[test]
fn simulate_json_has_the_spec_fields() {
    let v = json_with(
        &["simulate", "--alpha", "-60", "--t-end", "1200", "--json"],
        &[
            "scene",
            "model",
            "drive",
            "t_end",
            "integrator",
            "wall_seconds",
            "arrival_times",
            "speed",
            "final_theta_deg",
            "waves",
        ],
    );
    assert_eq!(v["model"]["alpha"], -60.0);
    assert_eq!(v["model"]["n"], 10);
    assert_eq!(v["integrator"]["name"], "symplectic-euler");
    assert_eq!(v["integrator"]["steps"], 120_000);
    assert_eq!(v["t_end"], 1200.0);
    let arrivals = v["arrival_times"].as_array().unwrap();
    assert_eq!(arrivals.len(), 10);
    assert!((arrivals[0].as_f64().unwrap() - 500.0).abs() < 1e-6);
    assert!(
        arrivals[9].is_null(),
        "block 10 has not flipped by t = 1200"
    );
}

#[test]
fn csv_has_theta_at_the_sample_times_and_is_reproducible() {
    let dir = std::env::temp_dir().join(format!("ladder-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("theta.csv");
    let p = path.to_str().unwrap();
    let args = [
        "simulate",
        "--t-end",
        "100",
        "--sample-every",
        "25",
        "--csv",
        p,
    ];
    assert_eq!(ladder(&args).status.code(), Some(0));
    let first = std::fs::read_to_string(&path).unwrap();
    let lines: Vec<&str> = first.lines().collect();
    assert_eq!(lines[0].split(',').count(), 11);
    assert_eq!(lines.len(), 6, "header + t = 0, 25, 50, 75, 100");
    assert!(lines[1].starts_with("0,60.000000,"));
    assert_eq!(ladder(&args).status.code(), Some(0));
    assert_eq!(std::fs::read_to_string(&path).unwrap(), first);
    // The CSV and its JSON sidecar (its provenance, docs/formats.md).
    let leftovers = std::fs::read_dir(&dir).unwrap().count();
    assert_eq!(leftovers, 2, "no temporary files left behind");
    assert!(dir.join("theta.csv.json").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn render_commands_reject_bad_input_with_one_line() {
    assert_bad_input(&["figure", "9z"], "unknown figure '9z'");
    assert_bad_input(&["movie", "2"], "movie 2 of the paper is a recording");
    assert_bad_input(&["movie", "4", "--frames", "0"], "--frames");
    assert_bad_input(&["movie", "4", "--frames", "-3"], "--frames");
    assert_bad_input(&["movie", "4", "--frames", "100000000"], "--frames");
    assert_bad_input(&["movie", "4", "--size", "640"], "WxH");
    assert_bad_input(&["movie", "4", "--size", "0x480"], "--size");
    assert_bad_input(&["movie", "4", "--size", "99999x480"], "--size");
    assert_bad_input(&["movie", "4", "--fps", "0"], "--fps");
    assert_bad_input(&["all", "--out", "/dev/null/out"], "cannot write");
    assert_bad_input(&["figure", "3", "--out", "/proc/ladder"], "cannot write");
}

#[test]
fn list_names_every_scene() {
    let out = ladder(&["list"]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    let scenes = jacobs_ladder::catalog::catalogue().unwrap().len();
    assert_eq!(scenes, jacobs_ladder::catalog::FILES.len());
    assert_eq!(text.lines().count(), scenes, "one line per scene");
    assert!(text.contains("movie  11") && text.contains("figure S6"));
    assert!(text.contains("figure pinning") && text.contains("figure chain-length"));
    assert!(text.contains("figure friction"));
}

#[test]
fn movie_command_writes_gif_and_kymograph() {
    let dir = std::env::temp_dir().join(format!("ladder-movie-{}", std::process::id()));
    let d = dir.to_str().unwrap();
    let args = [
        "movie", "4", "--out", d, "--frames", "5", "--size", "200x150",
    ];
    ladder_ok(&args);
    let gif = std::fs::read(dir.join("movie-4.gif")).unwrap();
    assert!(dir.join("movie-4-kymograph.png").exists());
    assert_eq!(ladder(&args).status.code(), Some(0));
    assert_eq!(
        std::fs::read(dir.join("movie-4.gif")).unwrap(),
        gif,
        "byte-identical"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn integrator_auto_is_verlet_at_the_measured_step_and_agrees_with_the_paper_setting() {
    let run = |extra: &[&str]| -> serde_json::Value {
        let mut args = vec!["simulate", "--alpha", "60", "--t-end", "2200", "--json"];
        args.extend_from_slice(extra);
        let out = ladder_ok(&args);
        serde_json::from_slice(&out.stdout).expect("one JSON object")
    };
    let auto = run(&["--integrator", "auto"]);
    let auto_i = &auto["integrator"];
    assert_eq!(auto_i["name"], "verlet");
    assert_eq!(auto_i["requested"], "auto");
    // Verlet at 0.25 τ, verified against a run at twice its step.
    assert_eq!(auto_i["dt"], 0.125);
    assert!(auto_i["rtol"].is_null());
    let err = auto_i["arrival_error"].as_f64().unwrap();
    assert!(err > 0.0 && err <= 0.1 / 3.0, "estimated error {err}");
    // 25 times fewer force evaluations than the paper's setting, and the
    // same arrival times to well within 1 τ.
    let paper = run(&[]);
    let (fa, fp) = (
        auto_i["force_evals"].as_u64().unwrap(),
        paper["integrator"]["force_evals"].as_u64().unwrap(),
    );
    assert!(fa * 10 < fp, "auto {fa} vs paper {fp} force evaluations");
    let (ta, tp) = (
        auto["arrival_times"].as_array().unwrap(),
        paper["arrival_times"].as_array().unwrap(),
    );
    for (n, (a, p)) in ta.iter().zip(tp).enumerate() {
        match (a.as_f64(), p.as_f64()) {
            (Some(a), Some(p)) => assert!((a - p).abs() < 1.0, "block {}: {a} vs {p}", n + 1),
            (a, p) => assert_eq!(a, p, "block {} flips in one run only", n + 1),
        }
    }
    assert_bad_input(
        &["simulate", "--integrator", "auto", "--rtol", "1e-6"],
        "--rtol",
    );
    assert_bad_input(&["simulate", "--integrator", "auto", "--dt", "0.5"], "--dt");
}

#[test]
fn help_documents_integrator_auto() {
    let out = ladder(&["simulate", "--help"]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("auto"), "{text}");
}

#[test]
fn theory_reports_the_spec_fields_and_rejects_bad_angles() {
    let v = json_with(
        &["theory", "--alpha", "-60", "--json"],
        &TheoryReport::SPEC_FIELDS,
    );
    assert_eq!(v["winding_number"], 0);
    assert_eq!(v["alpha_deg"], -60.0);
    let table = ladder(&["theory"]);
    assert_eq!(table.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&table.stdout).contains("winding"));
    assert_bad_input(&["theory", "--alpha", "91"], "alpha");
    assert_bad_input(&["theory", "--alpha", "NaN"], "alpha");
    assert_bad_input(&["theory", "--n", "1"], "N");
    assert_bad_input(&["theory", "--n", "100000"], "400");
    assert_bad_input(
        &["bench", "speed"],
        "choose work-precision, stability, kernels or cost",
    );
}

#[test]
fn every_kernel_prints_the_same_numbers() {
    // The JSON without its wall time and its command line (which names
    // the kernel), for each --kernel this CPU runs.
    let numbers = |kernel: &str| {
        let out = ladder(&["simulate", "--t-end", "1500", "--json", "--kernel", kernel]);
        assert_eq!(out.status.code(), Some(0), "{kernel}");
        let mut v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        v.as_object_mut().unwrap().remove("wall_seconds");
        v.as_object_mut().unwrap().remove("command_line");
        v
    };
    let portable = numbers("portable");
    assert!(portable["arrival_times"][4].is_number(), "{portable}");
    for kernel in ["fastest", "avx2", "avx512"] {
        let out = ladder(&["simulate", "--t-end", "1", "--kernel", kernel]);
        if out.status.code() == Some(2) {
            // This CPU lacks the instruction set: one clear line.
            assert!(String::from_utf8_lossy(&out.stderr).contains("--kernel"));
            continue;
        }
        assert_eq!(numbers(kernel), portable, "--kernel {kernel}");
    }
    assert_bad_input(&["simulate", "--kernel", "sse9"], "kernel");
}

/// `render` with a format list that has nothing for one of its scenes'
/// kinds is refused before anything is written (a movie asked for as PDF
/// used to be written as a GIF without a word).
#[test]
fn render_refuses_a_format_list_with_nothing_for_a_scene() {
    let dir = std::env::temp_dir().join(format!("ladder-cli-cover-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let movie = dir.join("m.toml");
    let figure = dir.join("f.toml");
    std::fs::write(&movie, "[output]\nkind = \"movie\"\n").unwrap();
    std::fs::write(&figure, "[output]\nkind = \"filmstrip\"\n").unwrap();
    let out = dir.join("out");
    let (m, f, o) = (
        movie.to_str().unwrap(),
        figure.to_str().unwrap(),
        out.to_str().unwrap(),
    );
    assert_bad_input(
        &["render", m, "--format", "pdf", "--out", o],
        "m is a movie, written as gif or mp4",
    );
    assert_bad_input(
        &["render", f, m, "--format", "svg", "--out", o],
        "m is a movie",
    );
    assert_bad_input(
        &["render", f, "--format", "mp4", "--out", o],
        "f is a figure, written as png, svg or pdf",
    );
    assert!(!out.exists(), "nothing written");
    // Checking a file takes the same list.
    assert_bad_input(&["render", "--check", m, "--format", "png"], "m is a movie");
    let ok = ladder(&["render", "--check", f, m, "--format", "svg,mp4"]);
    assert_eq!(
        ok.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// `ladder theory`'s table names its sources in words and formulas, not
/// in the paper's LaTeX labels (eq:eq_alpha) or markup (dtheta_{n+1}).
#[test]
fn the_theory_table_has_no_latex_labels() {
    for alpha in ["60", "-89", "0"] {
        let out = ladder(&["theory", "--alpha", alpha]);
        assert_eq!(out.status.code(), Some(0));
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.lines().count() > 20, "{text}");
        for bad in ["eq:", "_{", "^{", "\\", "omega", "kappa", "alpha"] {
            assert!(!text.contains(bad), "'{bad}' in\n{text}");
        }
    }
}

#[test]
fn completions_for_each_shell_name_the_commands_and_flags() {
    for (shell, marker) in [
        ("bash", "complete -F"),
        ("zsh", "#compdef ladder"),
        ("fish", "complete -c ladder"),
        ("powershell", "Register-ArgumentCompleter"),
    ] {
        let out = ladder_ok(&["completions", shell]);
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.contains(marker), "{shell}: no '{marker}'");
        for word in ["movie", "figure", "alpha", "quality"] {
            assert!(text.contains(word), "{shell}: no '{word}'");
        }
    }
    assert_eq!(ladder(&["completions", "tcsh"]).status.code(), Some(2));
}

#[test]
fn the_man_page_is_roff_with_every_command() {
    let out = ladder_ok(&["man"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains(".TH ladder 1"), "a man page title");
    for section in [
        "LADDER MOVIE",
        "LADDER FIGURE",
        "LADDER SIMULATE",
        "LADDER SWEEP",
    ] {
        assert!(text.contains(section), "no section {section}");
    }
    assert!(text.contains("alpha"), "flags are listed");
}

#[test]
fn the_version_names_the_git_commit_when_built_from_a_clone() {
    let out = ladder_ok(&["--version"]);
    let text = String::from_utf8_lossy(&out.stdout);
    // The commit of this checkout, asked of git independently of build.rs.
    let head = Command::new("git")
        .args(["rev-parse", "--short=12", "HEAD"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output();
    match head {
        Ok(h) if h.status.success() => {
            let commit = String::from_utf8_lossy(&h.stdout).trim().to_string();
            assert!(
                text.contains(&format!("commit {commit}")),
                "'{text}' lacks commit {commit}"
            );
        }
        // Not a clone (a crate tarball): the version alone.
        _ => assert!(text.contains(env!("CARGO_PKG_VERSION")), "{text}"),
    }
}

/// `simulate --apparatus FILE --json` reports the values the run used,
/// once: the motor's drive time T_d = 2|α| / (2π f) in τ (not the scene's
/// 1000 τ), and the apparatus's b, γ and I (not the paper's 1.3, 0.02,
/// 0.25), in the run and in the recorded scene alike; and its times in
/// seconds and its speed in cm/s beside τ and blocks per τ, in the JSON
/// and in the table.
#[test]
fn simulate_with_an_apparatus_reports_the_values_it_ran() {
    let dir = crate::common::tempdir::TempDir::new("simulate-apparatus");
    let tank = dir.file(
        "tank.toml",
        "[apparatus]\ns = 5.0\nb = 7.5\nthickness = 0.3\ndensity = 1.2\nmedium = \"water\"\n\
         medium_density = 1.0\ng = 981.0\nbuoyancy = true\nadded_mass = true\ndrag = true\n\
         motor = 0.2\nduration = 20.0\n",
    );
    let args = [
        "simulate",
        "--alpha",
        "86",
        "--n",
        "11",
        "--integrator",
        "rk4",
        "--dt",
        "0.125",
        "--apparatus",
        &tank,
    ];
    let mut json_args = args.to_vec();
    json_args.push("--json");
    let out = ladder_ok(&json_args);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    // τ = √(m/k) with "stiff" links k = m g*/(s G): τ = √(s G / g*),
    // g* = (1 − ρ_m/ρ) g (docs/experiments.md).
    let tau = (5.0 * 2e-4 / ((1.0 - 1.0 / 1.2) * 981.0f64)).sqrt();
    let t_d_s = 2.0 * 86f64.to_radians() / (std::f64::consts::TAU * 0.2);
    let close = |x: &serde_json::Value, want: f64| {
        let x = x.as_f64().unwrap_or(f64::NAN);
        assert!(
            (x - want).abs() <= 1e-9 * want.abs().max(1.0),
            "{x} vs {want}"
        );
    };
    for record in [&v, &v["scene"]] {
        close(&record["drive"]["flips"][0]["duration"], t_d_s / tau);
        close(&record["model"]["b"], 1.5);
        close(&record["model"]["gamma"], 0.0);
        close(
            &record["model"]["inertia"],
            (1.0 + (0.3f64 / 5.0).powi(2)) / 12.0,
        );
    }
    close(&v["t_end"], 20.0 / tau);
    let u = &v["units"];
    close(&u["tau_s"], tau);
    close(&u["t_end_s"], 20.0);
    close(&u["drive_time_s"], t_d_s);
    let speed = v["speed"].as_f64().expect("a wave");
    close(&u["speed_cm_s"], speed * 7.5 / tau);
    let first = v["arrival_times"][1].as_f64().unwrap();
    close(&u["arrival_times_s"][1], first * tau);
    // The table says the same in seconds and cm/s.
    let table = String::from_utf8(ladder_ok(&args).stdout).unwrap();
    let cm_s = format!("{:.2} cm/s", speed * 7.5 / tau);
    assert!(
        table.contains(&cm_s) && table.contains("arrival t (s)"),
        "{table}"
    );
    // Without an apparatus there are no units.
    let plain = json_with(&["simulate", "--t-end", "10", "--json"], &["model"]);
    assert!(plain.get("units").is_none());
}

/// The tank's plates turned by a motor at 0.2 Hz for `duration` s: an
/// `[apparatus]` table, as `simulate --apparatus FILE` reads it.
fn motor_tank(duration: f64) -> String {
    format!(
        "[apparatus]\ns = 5.0\nb = 7.5\nthickness = 0.3\ndensity = 1.2\nmedium = \"water\"\n\
         g = 981.0\nmotor = 0.2\nduration = {duration}\n"
    )
}

/// `simulate --json` of four of the plates of the apparatus file `tank`,
/// RK4 at 0.125 τ, with the flags `extra`.
fn simulate_tank<'a>(tank: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec![
        "simulate",
        "--alpha",
        "86",
        "--n",
        "4",
        "--integrator",
        "rk4",
        "--dt",
        "0.125",
        "--apparatus",
        tank,
        "--json",
    ];
    args.extend(extra);
    args
}

/// `--t-end` is the run's window even where the apparatus gives a
/// `duration`: before, the duration (converted again with the apparatus)
/// silently replaced it, and the recorded scene said both.
#[test]
fn t_end_replaces_the_apparatus_duration() {
    let dir = crate::common::tempdir::TempDir::new("t-end-duration");
    let tank = dir.file("tank.toml", &motor_tank(20.0));
    let given = simulate_tank(&tank, &["--t-end", "300"]);
    let v = json_with(&given, &["t_end", "units"]);
    assert_eq!(v["t_end"].as_f64(), Some(300.0));
    assert_eq!(v["scene"]["run"]["t_end"].as_f64(), Some(300.0));
    assert!(
        v["scene"]["apparatus"].get("duration").is_none(),
        "{}",
        v["scene"]["apparatus"]
    );
    let tau = v["units"]["tau_s"].as_f64().unwrap();
    let t_end_s = v["units"]["t_end_s"].as_f64().unwrap();
    assert!((t_end_s - 300.0 * tau).abs() < 1e-12, "{t_end_s}");
    // Without the flag the duration is the window.
    let v = json_with(&simulate_tank(&tank, &[]), &["t_end"]);
    assert!((v["units"]["t_end_s"].as_f64().unwrap() - 20.0).abs() < 1e-9);
}

/// A built-in scene whose apparatus gives a `duration` (the toy) runs to
/// `--t-end` too, and the movie's data file says the window it ran.
#[test]
fn a_built_in_apparatus_scene_runs_to_the_t_end_given() {
    let dir = crate::common::tempdir::TempDir::new("t-end-toy");
    let out = dir.path().to_str().unwrap().to_string();
    ladder_ok(&[
        "movie", "toy", "--t-end", "120", "--frames", "4", "--size", "160x120", "--name", "short",
        "--out", &out,
    ]);
    let text = std::fs::read_to_string(dir.path().join("movie-short.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["runs"][0]["t_end"].as_f64(), Some(120.0));
    assert!(v["scene"]["apparatus"].get("duration").is_none());
}

/// `--drive-time` is block 1's drive even where the apparatus has a
/// motor: before, the motor's flip silently replaced it.
#[test]
fn drive_time_replaces_the_apparatus_motor() {
    let dir = crate::common::tempdir::TempDir::new("drive-time-motor");
    let tank = dir.file("tank.toml", &motor_tank(2.0));
    let given = simulate_tank(&tank, &["--drive-time", "300"]);
    let v = json_with(&given, &["drive"]);
    for record in [&v, &v["scene"]] {
        assert_eq!(
            record["drive"]["flips"][0]["duration"].as_f64(),
            Some(300.0)
        );
    }
    assert!(v["scene"]["apparatus"].get("motor").is_none());
    // Without the flag the motor turns block 1 (0.2 Hz: far longer).
    let v = json_with(&simulate_tank(&tank, &[]), &["drive"]);
    assert!(v["drive"]["flips"][0]["duration"].as_f64().unwrap() > 2000.0);
}

/// A model flag the apparatus sets (b, gamma, gravity, inertia) is refused
/// with one line naming the flag: before, the apparatus' value replaced
/// it without a word. In a sweep, such an axis (and the drive time beside
/// a motor) is refused the same way.
#[test]
fn a_model_flag_the_apparatus_sets_is_refused() {
    let dir = crate::common::tempdir::TempDir::new("flag-apparatus");
    let text = motor_tank(2.0);
    let tank = dir.file("tank.toml", &text);
    for (flag, value) in [
        ("--b", "2"),
        ("--gamma", "0.1"),
        ("--gravity", "1e-3"),
        ("--inertia", "0.3"),
    ] {
        assert_bad_input(
            &simulate_tank(&tank, &[flag, value]),
            &format!("{flag}: the apparatus sets"),
        );
    }
    assert_bad_input(&["movie", "toy", "--b", "1.2"], "--b: the apparatus sets b");
    // The ribbons start from their hanging column; another start is refused.
    assert_bad_input(
        &["movie", "toy", "--start", "relaxed"],
        "--start: the ribbons' run starts",
    );
    let head =
        format!("[model]\nalpha = 86.0\nn = 4\n{text}[run]\nintegrator = \"rk4\"\ndt = 0.125\n");
    for (axis, needle) in [
        ("b = [1.2, 1.3]", "output.grid.b: the apparatus sets b"),
        (
            "drive_time = [300, 400]",
            "output.grid.drive_time: the apparatus' motor",
        ),
    ] {
        let sweep = dir.file(
            "sweep.toml",
            &format!("{head}[output]\nkind = \"sweep\"\n[output.grid]\n{axis}\n"),
        );
        let out_dir = dir.path().join("out");
        assert_bad_input(
            &["sweep", &sweep, "--out", out_dir.to_str().unwrap()],
            needle,
        );
    }
}

/// `--t-end auto`, which the help offers, is taken (it was refused as
/// "invalid float literal"): a movie of the paper's ladder runs until
/// every wave has a fate. Beside an apparatus, which has no automatic
/// window, and for `simulate`, it is one line and exit 2.
#[test]
fn t_end_auto_is_taken_where_the_help_offers_it() {
    let dir = crate::common::tempdir::TempDir::new("t-end-auto");
    let out = dir.path().to_str().unwrap().to_string();
    ladder_ok(&[
        "movie", "--t-end", "auto", "--n", "6", "--frames", "4", "--size", "160x120", "--name",
        "auto", "--out", &out,
    ]);
    let text = std::fs::read_to_string(dir.path().join("movie-auto.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let t_end = v["runs"][0]["t_end"].as_f64().unwrap();
    let last = v["runs"][0]["arrival_times"][5]
        .as_f64()
        .expect("the wave reaches block 6");
    assert!(t_end.is_finite() && t_end > last, "{t_end} after {last}");
    assert_bad_input(
        &["movie", "toy", "--t-end", "auto", "--out", &out],
        "--t-end: \"auto\" is not a window for an apparatus",
    );
    assert_bad_input(
        &["simulate", "--t-end", "auto"],
        "--t-end: simulate runs to a time",
    );
    assert_bad_input(
        &["movie", "--t-end", "soon"],
        "expected a time in tau or auto",
    );
}

/// The ring chain (movie 12, figure 4b) has no ladder: a model, drive or
/// run flag is one line and exit 2. Before, each was taken, set on the
/// scene's unused ladder, and the same chain was run under a name that
/// claimed the flag (`movie-12-a70.gif`, byte for byte `movie-12.gif`).
#[test]
fn a_ring_scene_refuses_the_ladders_flags() {
    let dir = crate::common::tempdir::TempDir::new("rings-flags");
    let out = dir.path().to_str().unwrap().to_string();
    for (flag, value) in [
        ("--alpha", "70"),
        ("--n", "8"),
        ("--drive-time", "300"),
        ("--start", "relaxed"),
        ("--t-end", "1"),
        ("--integrator", "rk4"),
    ] {
        for (kind, id) in [("movie", "12"), ("figure", "4b")] {
            assert_bad_input(
                &[kind, id, flag, value, "--out", &out],
                &format!("{flag}: the ring chain has no ladder"),
            );
        }
    }
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        0,
        "nothing written"
    );
}

/// A figure that runs no simulation (a drawing, a formula, linear theory)
/// refuses block 1's drive and the run's flags with one line; before,
/// each was taken and the same figure written under a name that claimed
/// it (`figure-2b-to100.png`). Its model flags still draw it anew.
#[test]
fn a_figure_that_runs_no_simulation_refuses_the_run_flags() {
    let dir = crate::common::tempdir::TempDir::new("theory-flags");
    let out = dir.path().to_str().unwrap().to_string();
    for (id, flag, value, kind) in [
        ("2b", "--t-end", "100", "drawing"),
        ("S5", "--integrator", "rk4", "linear theory"),
        ("2c", "--drive-time", "5", "formula"),
        ("2c", "--flips", "0,2000", "formula"),
    ] {
        assert_bad_input(
            &["figure", id, flag, value, "--out", &out],
            &format!("{flag}: this figure is a {kind} and runs no simulation"),
        );
    }
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        0,
        "nothing written"
    );
    ladder_ok(&["figure", "2c", "--alpha", "70", "--out", &out]);
    assert!(dir.path().join("figure-2c-a70.png").exists());
}
