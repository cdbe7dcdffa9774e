//! Where outputs go: a name is one plain path component whatever set it
//! (a flag, a scene file), so no file lands outside `--out`; two outputs
//! of one command never name one file, however the paths are spelt; a
//! title or caption has a length cap, checked before any work.

use crate::common::tempdir::TempDir;
use std::process::{Command, Output};

fn ladder_in(dir: &std::path::Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the ladder binary runs")
}

/// Every file below `dir`, relative to it.
fn tree(dir: &std::path::Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                todo.push(p.clone());
            }
            out.push(p.strip_prefix(dir).unwrap().display().to_string());
        }
    }
    out.sort();
    out
}

fn refused(out: &Output, words: &str) {
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "one line: {err}");
    assert!(err.contains(words), "{err}");
}

#[test]
fn a_flag_name_cannot_climb_out_make_folders_or_be_empty() {
    let dir = TempDir::new("names-climb");
    let work = dir.join("a/b/c");
    std::fs::create_dir_all(&work).unwrap();
    for name in ["../../ESCAPED", "x/y", "", ".hidden", "a b"] {
        for kind in ["figure", "movie"] {
            let mut args = vec![kind, "--name", name, "--t-end", "100", "--out", "o"];
            if kind == "figure" {
                args.extend(["--times", "0,100"]);
            }
            refused(&ladder_in(&work, &args), "--name: must be 1 to 64 letters");
        }
    }
    assert_eq!(tree(dir.path()), ["a", "a/b", "a/b/c"], "nothing written");
}

#[test]
fn two_outputs_of_one_file_are_refused_however_spelt() {
    let dir = TempDir::new("names-one-file");
    let root = dir.path();
    std::fs::create_dir(root.join("d")).unwrap();
    std::os::unix::fs::symlink(root.join("d"), root.join("link")).unwrap();
    for (csv, npz) in [
        ("x", "x"),
        ("x", "./x"),
        ("d/x", "link/x"),
        ("d/../x", "x"),
        ("new/x", "new/./x"),
    ] {
        let out = ladder_in(
            root,
            &["simulate", "--t-end", "10", "--csv", csv, "--npz", npz],
        );
        refused(
            &out,
            "would be written twice by one command (by --csv and by --npz)",
        );
    }
    assert_eq!(tree(root), ["d", "link"], "nothing written");
    // Two files: both written.
    let out = ladder_in(
        root,
        &["simulate", "--t-end", "10", "--csv", "a", "--npz", "b"],
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // The CSV's JSON sidecar beside it (docs/formats.md).
    assert_eq!(tree(root), ["a", "a.json", "b", "d", "link"]);
}

#[test]
fn titles_and_captions_have_a_length_cap() {
    let dir = TempDir::new("names-title-cap");
    let long = "w ".repeat(400);
    let file = dir.file(
        "long.toml",
        &format!("name = \"long\"\ntitle = \"{long}\"\n[output]\nkind = \"filmstrip\"\n"),
    );
    let out = ladder_in(dir.path(), &["render", &file, "--out", "o"]);
    refused(&out, "title: must be at most 300 characters, got 800");
    let caption = "c".repeat(10_001);
    let file = dir.file(
        "cap.toml",
        &format!("name = \"cap\"\ncaption = \"{caption}\"\n"),
    );
    let out = ladder_in(dir.path(), &["render", &file, "--out", "o"]);
    refused(&out, "caption: must be at most 10000 characters, got 10001");
    assert!(!dir.join("o").exists(), "nothing written");
}
