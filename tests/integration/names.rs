//! Names of the user's own outputs (docs/scenes.md, docs/scenes.md): made
//! from what differs from the paper (or from the built-in entry they start
//! from), never a shared `custom`; a scene that replaces the files of a
//! different scene says so; `ladder figure` / `ladder movie` with nothing
//! to make list the catalogue.

use crate::common::tempdir::TempDir;

use crate::common::ladder_cli as ladder;

/// `ladder ARGS --out DIR`, which must exit 0; returns its stderr.
fn ok_in(dir: &TempDir, args: &[&str]) -> String {
    let out_dir = dir.path().to_str().unwrap();
    let mut all = args.to_vec();
    all.extend(["--out", out_dir]);
    let out = ladder(&all);
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(0), "{all:?}: {err}");
    err
}

fn files(dir: &TempDir) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().to_string())
        .collect();
    v.sort();
    v
}

/// The scene recorded in a data file.
fn recorded_scene(dir: &TempDir, file: &str) -> serde_json::Value {
    let text = std::fs::read_to_string(dir.join(file)).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["scene"].clone()
}

const TINY: [&str; 4] = ["--frames", "3", "--size", "64x64"];

#[test]
fn custom_movies_are_named_after_what_differs_from_the_paper() {
    let dir = TempDir::new("names-movie");
    let with = |extra: &[&'static str]| -> Vec<&'static str> {
        extra.iter().copied().chain(TINY).collect()
    };
    ok_in(&dir, &with(&["movie", "--alpha", "70", "--n", "20"]));
    ok_in(&dir, &with(&["movie", "--alpha", "71"]));
    ok_in(&dir, &with(&["movie", "--alpha", "-60", "--gamma", "0.01"]));
    let names = files(&dir);
    for stem in ["movie-a70-n20", "movie-a71", "movie-a-60-gamma0.01"] {
        for ext in [".gif", "-kymograph.png", ".json"] {
            let f = format!("{stem}{ext}");
            assert!(names.contains(&f), "{f} not in {names:?}");
        }
    }
    assert!(
        !names.iter().any(|n| n.contains("custom")),
        "no output is called custom: {names:?}"
    );
    // The data file records the scene the name was made from.
    let s = recorded_scene(&dir, "movie-a70-n20.json");
    assert_eq!(s["model"]["alpha"], 70.0);
    assert_eq!(s["model"]["n"], 20);
}

#[test]
fn a_built_in_movie_and_a_built_in_figure_take_flags_alike() {
    let dir = TempDir::new("names-builtin");
    let mut movie = vec!["movie", "4", "--alpha", "70"];
    movie.extend(TINY);
    ok_in(&dir, &movie);
    ok_in(&dir, &["figure", "3", "--n", "12"]);
    let names = files(&dir);
    assert!(names.contains(&"movie-4-a70.gif".to_string()), "{names:?}");
    assert!(names.contains(&"figure-3-n12.png".to_string()), "{names:?}");
    // Movie 4's window and label are kept (assets/scenes/movie-4.toml:
    // t_end = 2200, label "Movie 4"); the paper's default window is 4000.
    let m = recorded_scene(&dir, "movie-4-a70.json");
    assert_eq!(m["run"]["t_end"], 2200.0);
    assert_eq!(m["label"], "Movie 4");
    assert_eq!(m["model"]["alpha"], 70.0);
    // Figure 3 keeps its four panels, each now with N = 12.
    let f = recorded_scene(&dir, "figure-3-n12.json");
    assert_eq!(f["output"]["panels"].as_array().unwrap().len(), 4);
    assert_eq!(f["model"]["n"], 12);
    assert_eq!(f["label"], "Fig. 3");
}

#[test]
fn a_flag_a_figure_s_panels_set_themselves_is_refused() {
    // Figure 3's panels each set alpha (60, −60, 50, −50) and t_end.
    for (flag, value) in [("--alpha", "70"), ("--t-end", "3000")] {
        let out = ladder(&["figure", "3", flag, value, "--out", "/nonexistent/x"]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(
            err.contains(flag) && err.contains("ladder scene 3"),
            "{err}"
        );
    }
}

#[test]
fn the_files_of_a_different_scene_are_replaced_only_with_a_warning() {
    let dir = TempDir::new("names-replace");
    let with = |extra: &[&'static str]| -> Vec<&'static str> {
        extra.iter().copied().chain(TINY).collect()
    };
    let first = ok_in(&dir, &with(&["movie", "--name", "k", "--alpha", "70"]));
    assert!(!first.contains("warning"), "{first}");
    let same = ok_in(&dir, &with(&["movie", "--name", "k", "--alpha", "70"]));
    assert!(!same.contains("warning"), "the same scene again: {same}");
    let other = ok_in(&dir, &with(&["movie", "--name", "k", "--alpha", "71"]));
    assert!(
        other.contains("warning: replacing the files of movie-k")
            && other.contains("different scene")
            && other.contains("α = 70°"),
        "{other}"
    );
    assert_eq!(recorded_scene(&dir, "movie-k.json")["model"]["alpha"], 71.0);
}

/// A scene whose words (caption, title, label) were edited is the same
/// scene: its files are replaced without a warning; a changed N warns.
#[test]
fn an_edited_caption_replaces_its_own_files_silently() {
    let dir = TempDir::new("names-caption");
    let file = dir.path().join("w.toml");
    let write = |caption: &str, n: usize| {
        std::fs::write(
            &file,
            format!(
                "name = \"w\"\ncaption = \"{caption}\"\ntitle = \"{caption}\"\n\
                 [model]\nn = {n}\n[run]\nt_end = 10\n[output]\nkind = \"data\"\n"
            ),
        )
        .unwrap();
    };
    let path = file.to_str().unwrap().to_string();
    write("one", 4);
    ok_in(&dir, &["render", &path]);
    write("two", 4);
    let same = ok_in(&dir, &["render", &path]);
    assert!(!same.contains("warning"), "only the words changed: {same}");
    write("two", 5);
    let other = ok_in(&dir, &["render", &path]);
    assert!(
        other.contains("warning: replacing the files of data-w"),
        "{other}"
    );
}

#[test]
fn figure_and_movie_without_an_id_list_the_catalogue() {
    for (kind, some_id) in [("movie", "Movie 11"), ("figure", "Fig. 3")] {
        let out = ladder(&[kind]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{kind}: {err}");
        assert!(out.stdout.is_empty());
        assert!(err.contains(some_id), "{kind}: {err}");
        assert!(err.contains(&format!("ladder {kind} ID")), "{err}");
        assert!(err.contains(&format!("ladder {kind} all")), "{err}");
    }
}

#[test]
fn the_camera_flag_takes_auto() {
    let dir = TempDir::new("names-camera");
    let mut args = vec!["movie", "--camera", "auto", "--alpha", "70"];
    args.extend(TINY);
    ok_in(&dir, &args);
    assert!(files(&dir).contains(&"movie-a70.gif".to_string()));
}
