//! The auto window (`t_end = "auto"`, docs/scenes.md): long enough for
//! every wave's fate, with a margin after the last arrival; refitted to
//! the chain when a built-in movie's N is changed, kept when the user sets
//! it; a bad `t_end` is exit 2 with the file, line and key.
//!
//! Run in release: `cargo test --release --test integration auto_window::`.

#![allow(clippy::field_reassign_with_default)]

use crate::common::ladder_cli as ladder;
use crate::common::tempdir::TempDir;
use jacobs_ladder::scene::Scene;
use jacobs_ladder::sim::{self, IntegratorConfig, IntegratorKind};
use std::process::Output;

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn an_auto_window_contains_every_waves_fate() {
    // N = 60 at α = 60°: the kink crosses in about 8000 τ, twice the old
    // default window of 4000 τ. The window must hold every wave's fate:
    // run to it, and no wave is undecided; the last arrival lies inside.
    let mut s = Scene::default();
    s.model.alpha = 60.0;
    s.model.n = 60;
    s.output = jacobs_ladder::scene::OutputSpec::Movie {
        camera: Default::default(),
    };
    s.run.t_end = jacobs_ladder::scene::AUTO_T_END;
    s.run.integrator = jacobs_ladder::scene::Method::Fixed(IntegratorKind::Verlet);
    s.run.dt = Some(0.25);
    let resolved = s.with_auto_window().unwrap();
    let t_end = resolved.run.t_end;
    assert!(t_end.is_finite() && t_end > 4000.0, "window {t_end}");
    let run = sim::simulate(
        &resolved.scenario().unwrap(),
        &[],
        &IntegratorConfig::fixed(IntegratorKind::Verlet, 0.25),
    )
    .unwrap();
    assert!(!run.waves.waves.is_empty());
    for w in &run.waves.waves {
        assert_ne!(w.fate, sim::waves::Fate::Undecided, "{w:?}");
        let last = w
            .arrival_times
            .iter()
            .flatten()
            .fold(0.0f64, |m, &x| m.max(x));
        // The margin: at least 200 τ after the wave's last arrival.
        assert!(last + 200.0 <= t_end, "last arrival {last}, window {t_end}");
    }
    assert_eq!(run.waves.waves[0].fate, sim::waves::Fate::End);
    // A number stays as written.
    let mut fixed = s.clone();
    fixed.run.t_end = 1234.0;
    assert_eq!(fixed.with_auto_window().unwrap().run.t_end, 1234.0);
}

#[test]
fn a_bad_t_end_is_exit_2_with_file_line_and_key() {
    let dir = TempDir::new("bad-t-end");
    for (text, at) in [
        (
            "[model]\nn = 12\n\n[run]\nt_end = \"soon\"\n",
            ":5:9: run.t_end: ",
        ),
        ("[run]\nt_end = true\n", ":2:9: run.t_end: "),
        ("[run]\nt_end = -5\n", ":2:9: run.t_end: "),
    ] {
        let path = dir.file("bad.toml", text);
        let out = ladder(&["render", &path, "--out", dir.path().to_str().unwrap()]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{text}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(
            stderr.starts_with(&format!("ladder: {path}{at}")),
            "{text}: {stderr}"
        );
        assert!(stderr.contains("auto"), "{text}: {stderr}");
    }
    // "auto" reads and prints back as "auto".
    let s = jacobs_ladder::scene::file::parse("[run]\nt_end = \"auto\"\n", "t", "t").unwrap();
    assert_eq!(s.run.t_end, jacobs_ladder::scene::AUTO_T_END);
    assert!(
        jacobs_ladder::scene::file::to_toml(&s)
            .unwrap()
            .contains("t_end = \"auto\"")
    );
}

#[test]
fn movie_4_on_20_blocks_shows_the_whole_crossing() {
    let dir = TempDir::new("tour");
    let d = dir.path().to_str().unwrap();
    let o = ladder(&[
        "movie", "4", "--n", "20", "--frames", "4", "--size", "160x120", "--out", d,
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    // Named for what the user changed only (no `toauto`).
    let json = dir.join("movie-4-n20.json");
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&json).unwrap()).unwrap();
    let run = &v["runs"][0];
    let kink = &run["waves"]["waves"][0];
    assert_eq!(kink["fate"], "end", "{kink}");
    assert_eq!(kink["front"], 20, "{kink}");
    assert!(run["t_end"].as_f64().unwrap() > 2200.0);
    // A window the user sets is kept.
    let o = ladder(&[
        "movie", "4", "--n", "20", "--t-end", "2200", "--frames", "4", "--size", "160x120",
        "--out", d,
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value =
        serde_json::from_slice(&std::fs::read(dir.join("movie-4-n20-to2200.json")).unwrap())
            .unwrap();
    assert_eq!(v["runs"][0]["t_end"], 2200.0);
}
