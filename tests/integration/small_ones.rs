//! Smaller behaviours, each as a user met it:
//! a built-in movie whose N is changed keeps a window fitted to the old
//! chain; a sweep file refuses the axis text the command line takes;
//! `sweep` has no `--start`; `render --check` passes a figure that cannot
//! render. (Names and titles: `scene::describe`'s unit tests.)

use crate::common::tempdir::TempDir;
use jacobs_ladder::scene::file;
use jacobs_ladder::sweep::Plan;
use std::process::Output;

use crate::common::ladder_cli as ladder;

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
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

#[test]
fn a_sweep_file_takes_the_axis_text_the_command_line_takes() {
    let toml = r#"
name = "g"
[output]
kind = "sweep"
[output.grid]
alpha = "40:45:1,47:50:1"
"#;
    let scene = file::parse(toml, "g.toml", "g").unwrap();
    let plan = Plan::new(&scene, 100).unwrap().unwrap();
    let alphas: Vec<f64> = plan.points.iter().map(|p| p[0]).collect();
    assert_eq!(
        alphas,
        [40.0, 41.0, 42.0, 43.0, 44.0, 45.0, 47.0, 48.0, 49.0, 50.0]
    );
}

#[test]
fn sweep_takes_start() {
    let dir = TempDir::new("sweep-start");
    let run = |start: Option<&str>| {
        let out = dir.join(start.unwrap_or("default"));
        let mut args = vec![
            "sweep",
            "--alpha",
            "46",
            "--integrator",
            "verlet",
            "--dt",
            "0.25",
            "--name",
            "s",
            "--out",
            out.to_str().unwrap(),
        ];
        if let Some(s) = start {
            args.extend(["--start", s]);
        }
        let o = ladder(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        std::fs::read_to_string(out.join("sweep-s.csv")).unwrap()
    };
    // At 46° the hanging equilibrium is not found (docs/sweeps.md): the
    // relaxed start is honoured, and its point is `failed`.
    assert!(run(Some("relaxed")).contains(",failed,"));
    assert!(!run(None).contains(",failed,"));
    assert!(!run(Some("ground")).contains(",failed,"));
}

#[test]
fn render_check_refuses_a_potential_that_cannot_render() {
    let dir = TempDir::new("check-2c");
    let scene = String::from_utf8(ladder(&["scene", "2c"]).stdout).unwrap();
    assert!(scene.contains("a_over_b = ["), "{scene}");
    let bad = scene
        .lines()
        .map(|l| {
            if l.starts_with("a_over_b") {
                "a_over_b = [1.05, 6]".to_string()
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    let path = dir.file("2c.toml", &bad);
    let o = ladder(&["render", "--check", &path]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("output.a_over_b"), "{}", stderr(&o));
    assert!(stderr(&o).contains("a/b = 6"), "{}", stderr(&o));
    // The catalogue's own passes.
    let good = dir.file("ok.toml", &scene);
    assert!(ladder(&["render", "--check", &good]).status.success());
}
