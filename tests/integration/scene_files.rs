//! Scene files (docs/scenes.md): every TOML example in the docs parses; a
//! bad file is one line naming file, line, column and key, with exit 2,
//! and `render --check` refuses a value that would fail only when drawn;
//! a sweep file's grid takes the axis text the command line takes; files
//! mutated at random never make the parser panic and always give exit 0
//! or 2.

use crate::common::fuzz;
use crate::common::tempdir::TempDir;
use jacobs_ladder::catalog;
use jacobs_ladder::error::Error;
use jacobs_ladder::scene::{self, file};
use jacobs_ladder::sweep::Plan;
use proptest::prelude::*;
use std::process::{Command, Output};

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn ladder(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .output()
        .expect("the ladder binary runs")
}

/// The ```toml blocks of a Markdown file.
fn toml_blocks(markdown: &str) -> Vec<String> {
    let mut blocks = Vec::new();
    let mut current: Option<String> = None;
    for line in markdown.lines() {
        match (&mut current, line.trim_start()) {
            (None, l) if l.starts_with("```toml") => current = Some(String::new()),
            (Some(_), l) if l.starts_with("```") => blocks.extend(current.take()),
            (Some(b), _) => {
                b.push_str(line);
                b.push('\n');
            }
            _ => {}
        }
    }
    blocks
}

#[test]
fn every_toml_example_in_the_docs_parses() {
    let root = env!("CARGO_MANIFEST_DIR");
    let mut count = 0;
    for doc in ["README.md", "docs/scenes.md", "docs/model.md"] {
        let text = std::fs::read_to_string(format!("{root}/{doc}")).unwrap();
        for (k, block) in toml_blocks(&text).iter().enumerate() {
            let scene = file::parse(block, &format!("{doc} example {}", k + 1), "example")
                .unwrap_or_else(|e| panic!("{e}\n{block}"));
            assert!(!scene::describe::title(&scene).is_empty());
            count += 1;
        }
    }
    assert!(count >= 5, "found only {count} examples");
}

/// (file text, what the one line must contain after `FILE:`).
const BAD_FILES: &[(&str, &str)] = &[
    // A style's numbers are checked as they are read: file, line, column,
    // and the number as written (1e39 is no f32: it used to say "inf").
    (
        "[style]\nfont_size = 1e39\n",
        ":2:13: style.font_size: must be between 4 and 72 pt, got 1e39",
    ),
    (
        "[style]\ndpi = -5\n",
        ":2:7: style.dpi: must be between 36 and 1200, got -5",
    ),
    ("[model]\nn = 20\nalpha = 120\n", ":3:9: model.alpha: "),
    ("[model]\nalpah = 60\n", ":2:1: model.alpah: unknown field"),
    (
        "[model]\nn = \"ten\"\n",
        ":2:5: model.n: expected a whole number",
    ),
    (
        "[model]\nb = -1.3\n",
        ":2:5: model.b: must be a length from 1e-3 to 1e3, got -1.3",
    ),
    (
        "[drive]\nflips = [{ start = 0, duration = 1000 }, { start = 500, duration = 1000 }]\n",
        ":2:42: drive.flips.1: ",
    ),
    (
        "[run]\nt_end = 1000\n\n[output]\nkind = \"filmstrip\"\ntimes = [0, 500, 2000]\n",
        ":6:9: output.times: time 2000 lies outside the window",
    ),
    (
        "[output]\nkind = \"poster\"\n",
        ":2:8: output.kind: unknown variant",
    ),
    (
        "[run]\nintegrator = \"leapfrog\"\n",
        ":2:14: run.integrator: unknown integrator",
    ),
    ("[model\nalpha = 60\n", ":1:7: "),
];

#[test]
fn a_bad_file_is_one_line_with_file_line_column_and_key() {
    let dir = TempDir::new("bad-scenes");
    for (k, (text, want)) in BAD_FILES.iter().enumerate() {
        let path = dir.file(&format!("bad{k}.toml"), text);
        let out = ladder(&["render", &path, "--out", dir.path().to_str().unwrap()]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{text}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{text}: {stderr}");
        let expected = format!("ladder: {path}{want}");
        assert!(
            stderr.starts_with(&expected),
            "{text}: want {expected}, got {stderr}"
        );
    }
    let written: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| !e.file_name().to_string_lossy().ends_with(".toml"))
        .collect();
    assert!(written.is_empty(), "bad input wrote {written:?}");
    let missing = dir.join("missing.toml");
    let out = ladder(&["render", missing.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no such file"));
}

#[test]
fn render_check_validates_without_writing() {
    let dir = TempDir::new("check-scenes");
    let path = dir.file("k70.toml", "[model]\nalpha = 70\nn = 20\n");
    let out = ladder(&[
        "render",
        "--check",
        &path,
        "--out",
        dir.path().to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("movie k70 (1 run)"), "{text}");
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        1,
        "nothing written"
    );
}

/// Characters a mutation inserts: TOML syntax, digits, signs, letters.
const ALPHABET: &[u8] = b"[]{}=,.\"'#\n -+0123456789eEinfa_xyz";

/// One random edit of `text` (as bytes, so any UTF-8 damage is tried
/// too): delete, insert, replace, duplicate or drop a line, or put an
/// extreme number in place of one.
fn mutate(text: &str, ops: &[(u8, usize, usize)]) -> Vec<u8> {
    let mut b = text.as_bytes().to_vec();
    for &(op, at, pick) in ops {
        if b.is_empty() {
            b.push(b'x');
        }
        let i = at % b.len();
        match op % 6 {
            0 => {
                b.remove(i);
            }
            1 => b.insert(i, ALPHABET[pick % ALPHABET.len()]),
            2 => b[i] = ALPHABET[pick % ALPHABET.len()],
            3 => {
                let lines: Vec<&[u8]> = b.split(|&c| c == b'\n').collect();
                let l = lines[pick % lines.len()].to_vec();
                b.splice(i..i, l.into_iter().chain([b'\n']));
            }
            4 => {
                let numbers = [
                    "1e308",
                    "-1e308",
                    "nan",
                    "inf",
                    "-inf",
                    "0",
                    "-0.0",
                    "1e-320",
                    "99999999999",
                    "-1",
                    "4294967297",
                    "3.5",
                ];
                let n = numbers[pick % numbers.len()].as_bytes();
                let start = b[i..].iter().position(u8::is_ascii_digit).map(|p| p + i);
                if let Some(s) = start {
                    let end = b[s..]
                        .iter()
                        .position(|c| !(c.is_ascii_digit() || *c == b'.'))
                        .map_or(b.len(), |p| p + s);
                    b.splice(s..end, n.iter().copied());
                }
            }
            _ => b.push(0xC3),
        }
    }
    b
}

/// Parses mutated bytes as the loader does: UTF-8 first, then TOML.
fn parse_bytes(bytes: &[u8]) -> Result<(), Error> {
    let text = String::from_utf8(bytes.to_vec()).map_err(|_| Error::bad_input("not UTF-8"))?;
    file::parse(&text, "mutated.toml", "mutated").map(|_| ())
}

fn mutation_strategy() -> impl Strategy<Value = (usize, Vec<(u8, usize, usize)>)> {
    (
        0..catalog::FILES.len(),
        prop::collection::vec((any::<u8>(), any::<usize>(), any::<usize>()), 1..6),
    )
}

/// Library level, 10 000 cases with a fixed seed: never a panic; every
/// error is bad input (exit 2).
#[test]
fn mutated_scene_files_never_panic_the_parser() {
    let mut runner = fuzz::runner(fuzz::cases(10_000), 7);
    let ok = std::cell::Cell::new(0u32);
    let bad = std::cell::Cell::new(0u32);
    runner
        .run(&mutation_strategy(), |(file, ops)| {
            let bytes = mutate(catalog::FILES[file].1, &ops);
            match parse_bytes(&bytes) {
                Ok(()) => ok.set(ok.get() + 1),
                Err(e) => {
                    prop_assert_eq!(e.exit_code(), 2, "{}", e);
                    prop_assert_eq!(e.to_string().lines().count(), 1, "{}", e);
                    bad.set(bad.get() + 1);
                }
            }
            Ok(())
        })
        .unwrap();
    let (ok, bad) = (ok.get(), bad.get());
    eprintln!("{ok} mutated files accepted, {bad} refused");
    assert!(ok > 0 && bad > 0, "{ok} accepted, {bad} refused");
}

/// The binary, 1000 cases: `ladder render --check` exits 0 or 2, never
/// anything else, with one line on stderr for a refusal.
#[test]
fn mutated_scene_files_exit_0_or_2() {
    let dir = TempDir::new("mutated-scenes");
    let mut runner = fuzz::runner(1000, 11);
    let path = dir.join("m.toml");
    let p = path.to_str().unwrap().to_string();
    runner
        .run(&mutation_strategy(), |(file, ops)| {
            std::fs::write(&path, mutate(catalog::FILES[file].1, &ops)).unwrap();
            let out = ladder(&["render", "--check", &p]);
            let code = out.status.code();
            let stderr = String::from_utf8_lossy(&out.stderr);
            prop_assert!(
                code == Some(0) || code == Some(2),
                "exit {:?}: {}",
                code,
                stderr
            );
            if code == Some(2) {
                prop_assert_eq!(stderr.lines().count(), 1, "{}", stderr);
            }
            Ok(())
        })
        .unwrap();
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
