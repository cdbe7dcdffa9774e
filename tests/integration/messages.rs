//! What the user reads: IDs in any case, the closest ID or subcommand for a
//! typo, the paper's photographs and recordings named as such, clap's
//! whole message for a missing argument, a divergence hint that names a
//! step that works, and a summary line that says what was written.

use crate::common::ladder_cli as ladder;
use crate::common::tempdir::TempDir;

/// A fresh folder for one test, removed when the test ends.
fn temp_dir(tag: &str) -> TempDir {
    TempDir::new(&format!("msg-{tag}"))
}

/// Exit 2, one line on stderr containing every needle, nothing on stdout.
fn bad_input(args: &[&str], needles: &[&str]) -> String {
    let out = ladder(args);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert_eq!(stderr.lines().count(), 1, "{args:?}: one line: {stderr}");
    for n in needles {
        assert!(stderr.contains(n), "{args:?}: '{n}' not in {stderr}");
    }
    assert!(out.stdout.is_empty());
    stderr
}

#[test]
fn ids_are_case_insensitive() {
    let dir = temp_dir("case");
    let out = ladder(&["figure", "s5", "--out", dir.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    assert!(dir.join("figure-S5.png").is_file());
    let scene = ladder(&["scene", "s6"]);
    assert_eq!(scene.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&scene.stdout).contains("label = \"Fig. S6\""));
}

#[test]
fn an_unknown_id_suggests_the_closest() {
    bad_input(
        &["figure", "S7"],
        &["unknown figure 'S7'", "did you mean S3, S4, S5 or S6?"],
    );
    bad_input(&["figure", "edge"], &["did you mean edge-mode?"]);
    bad_input(&["figure", "windng"], &["did you mean winding?"]);
    bad_input(&["figure", "4"], &["did you mean 4a, 4b or movie 4?"]);
    bad_input(&["movie", "13"], &["did you mean 3, 10, 11 or 12?"]);
    let far = bad_input(
        &["movie", "zzz"],
        &["unknown movie 'zzz'", "choose one of 3, 4"],
    );
    assert!(!far.contains("did you mean"), "{far}");
    bad_input(&["scene", "S9"], &["unknown scene 'S9'", "figure S3"]);
}

#[test]
fn a_mistyped_subcommand_suggests_the_closest() {
    bad_input(&["simulat"], &["'simulat'", "'simulate'"]);
    bad_input(&["figures", "3"], &["'figures'", "'figure'"]);
}

#[test]
fn photographs_and_recordings_are_named_as_such() {
    for (kind, id, what) in [
        ("movie", "1", "recording"),
        ("movie", "2", "recording"),
        ("figure", "1a", "photograph"),
        ("figure", "1b", "photograph"),
        ("figure", "2A", "photograph"),
        ("figure", "S1", "photograph"),
        ("figure", "s2", "drawing of the 3D-printed"),
    ] {
        let line = bad_input(
            &[kind, id],
            &[
                what,
                "this program does not make it",
                "no photographs or recordings of real toys",
                "figures toy, 1c, 2b",
                "movies 3, 4",
            ],
        );
        assert!(
            line.contains(&format!("{kind} {}", id.to_lowercase()))
                || line.contains(&format!("{kind} {}", id.to_uppercase()))
        );
    }
    bad_input(&["figure", "2a"], &["the nearest it makes: figure 2b"]);
    bad_input(&["scene", "2"], &["movie 2 of the paper"]);
}

#[test]
fn a_missing_argument_gets_clap_s_whole_message() {
    for (args, arg) in [(&["bench"][..], "<STUDY>"), (&["render"][..], "<FILE>")] {
        let out = ladder(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(
            stderr.starts_with("ladder: the following required arguments were not provided:"),
            "{stderr}"
        );
        for needle in [arg, "Usage: ladder", "--help"] {
            assert!(stderr.contains(needle), "'{needle}' not in {stderr}");
        }
    }
}

#[test]
fn a_diverged_run_hints_a_step_that_works() {
    let out = ladder(&["simulate", "--dt", "2", "--t-end", "1500"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.contains("symplectic-euler diverged at t = ")
            && stderr.contains("--integrator auto"),
        "{stderr}"
    );
    assert!(!stderr.contains("such as symplectic-euler"), "{stderr}");
    // The measured step is a step at which the same run stays bounded.
    let marker = "stays bounded up to dt ≈ ";
    let critical: f64 = stderr
        .split(marker)
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .and_then(|x| x.parse().ok())
        .unwrap_or_else(|| panic!("no measured step in {stderr}"));
    assert!(critical > 0.1 && critical < 2.0, "{critical}");
    let at = critical.to_string();
    let ok = ladder(&["simulate", "--dt", &at, "--t-end", "1500"]);
    assert_eq!(
        ok.status.code(),
        Some(0),
        "--dt {at}: {}",
        String::from_utf8_lossy(&ok.stderr)
    );
    let over = (critical * 1.3).to_string();
    let fails = ladder(&["simulate", "--dt", &over, "--t-end", "1500"]);
    assert_eq!(fails.status.code(), Some(1), "--dt {over} should diverge");
}

#[test]
fn a_scene_file_s_hint_names_its_keys() {
    let dir = temp_dir("keys");
    let file = dir.join("fast.toml");
    std::fs::write(
        &file,
        "name = \"fast\"\n[run]\nt_end = 1200.0\nintegrator = \"verlet\"\ndt = 2.0\n\
         [output]\nkind = \"kymograph\"\n",
    )
    .unwrap();
    let out = ladder(&[
        "render",
        file.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("verlet diverged")
            && stderr.contains("[run] dt below that")
            && stderr.contains("[run] integrator = \"auto\""),
        "{stderr}"
    );
    assert!(!stderr.contains("--dt"), "{stderr}");
}

#[test]
fn values_are_reported_as_typed() {
    bad_input(&["simulate", "--alpha", "120"], &["--alpha", "got 120"]);
}

#[test]
fn the_summary_names_what_was_written() {
    let dir = temp_dir("summary");
    let d = dir.to_str().unwrap();
    let out = ladder(&["figure", "2d", "--out", d]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.starts_with("ladder: wrote figure-2d.png and figure-2d.json (figure 2d) into "),
        "{stderr}"
    );
    let out = ladder(&[
        "movie",
        "7",
        "--frames",
        "4",
        "--size",
        "160x120",
        "--out",
        d,
        "--verbose",
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 4, "{stderr}");
    for (line, f) in lines
        .iter()
        .zip(["movie-7.gif", "movie-7-kymograph.png", "movie-7.json"])
    {
        assert_eq!(*line, dir.join(f).display().to_string());
        assert!(dir.join(f).is_file());
    }
    assert!(lines[3].contains("wrote movie-7.gif, movie-7-kymograph.png and movie-7.json"));
}

/// Writes `text` to the scene file `s.toml` in a fresh folder; returns the
/// folder (removed when dropped) and the file's path.
fn scene_file(tag: &str, text: &str) -> (TempDir, String) {
    let dir = temp_dir(tag);
    let path = dir.file("s.toml", text);
    (dir, path)
}

#[test]
fn scene_file_types_are_said_in_words_with_an_example() {
    let (_dir, f) = scene_file("flips", "[drive]\nflips = [0, 1500]\n");
    let e = bad_input(
        &["render", "--check", &f],
        &[
            ":2:10: drive.flips.0: expected a flip",
            "got the whole number 0",
            "flips = [{ start = 0, duration = 1000 }",
        ],
    );
    assert!(!e.contains("struct Flip"), "{e}");
    let (_dir, f) = scene_file("whole", "[model]\nn = 2.5\n");
    let e = bad_input(
        &["render", "--check", &f],
        &[
            "model.n: expected a whole number of 0 or more, got the number 2.5",
            "n = 20",
        ],
    );
    assert!(!e.contains("usize"), "{e}");
    let (_dir, f) = scene_file("number", "[model]\nalpha = \"sixty\"\n");
    let e = bad_input(
        &["render", "--check", &f],
        &["model.alpha: expected a number"],
    );
    assert!(!e.contains("f64"), "{e}");
}

#[test]
fn an_output_table_without_kind_takes_the_kind_its_keys_say() {
    // docs/scenes.md: `times` or `panels` make a filmstrip.
    let (_dir, f) = scene_file("nokind", "[run]\nt_end = 100\n[output]\ntimes = [0, 50]\n");
    let out = ladder(&["render", "--check", &f]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(text.contains(": figure s (1 run)"), "{text}");
}

#[test]
fn an_unknown_key_in_output_is_named_with_its_table_at_its_line() {
    let (_dir, f) = scene_file(
        "unknown-output",
        "[output]\nkind = \"filmstrip\"\ntimez = [0, 900]\n",
    );
    bad_input(
        &["render", "--check", &f],
        &[":3:1: output.timez: unknown field `timez`"],
    );
}

#[test]
fn a_wrong_type_in_output_names_file_line_key_and_form() {
    // serde reads `[output]` as a whole: its message named no key.
    let (_dir, f) = scene_file("times5", "[model]\nn = 10\n\n[output]\ntimes = 5\n");
    bad_input(
        &["render", "--check", &f],
        &[
            "s.toml:5:9: output.times: expected a list [ ... ], got the whole number 5",
            "for example times = [0, 900, 1100, 1350]",
        ],
    );
}

#[test]
fn a_mixed_movie_format_says_what_each_file_takes() {
    // png and pdf were dropped without a word: now the kymograph takes
    // them, at --scale, and one line says so.
    let dir = temp_dir("mixed");
    let d = dir.to_str().unwrap();
    let out = ladder(&[
        "movie",
        "7",
        "--frames",
        "4",
        "--size",
        "160x120",
        "--format",
        "gif,png,pdf,svg",
        "--scale",
        "2",
        "--out",
        d,
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert_eq!(
        stderr.lines().next().unwrap(),
        "ladder: --format gif,png,pdf,svg: writing the movie as GIF and its kymograph as PNG \
         and PDF and SVG"
    );
    for f in [
        "movie-7.gif",
        "movie-7-kymograph.png",
        "movie-7-kymograph.pdf",
        "movie-7-kymograph.svg",
    ] {
        assert!(dir.join(f).is_file(), "{f} not written: {stderr}");
    }
    assert!(
        std::fs::read(dir.join("movie-7-kymograph.pdf"))
            .unwrap()
            .starts_with(b"%PDF")
    );
    // --scale 2: the kymograph PNG has twice the pixels of --scale 1's
    // (480 × 360, the smallest kymograph, at 160 × 120 frames).
    let png = std::fs::read(dir.join("movie-7-kymograph.png")).unwrap();
    let size = |b: &[u8]| {
        (
            u32::from_be_bytes(b[16..20].try_into().unwrap()),
            u32::from_be_bytes(b[20..24].try_into().unwrap()),
        )
    };
    assert_eq!(size(&png), (960, 720));
    bad_input(
        &["movie", "7", "--format", "pdf", "--out", d],
        &["--format pdf: no movie format"],
    );
}

#[test]
fn an_odd_mp4_size_suggests_the_nearest_even_size_below() {
    bad_input(
        &["movie", "4", "--format", "mp4", "--size", "1921x1080"],
        &["try 1920x1080"],
    );
}

#[test]
fn the_max_flags_belong_to_the_commands_they_limit() {
    // Not on commands that neither simulate nor write movies...
    for args in [
        ["list", "--max-pixels", "5"],
        ["theory", "--max-block-steps", "5"],
    ] {
        let out = ladder(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
    }
    // ... nor --max-pixels on a command that writes no movie.
    assert_eq!(
        ladder(&["simulate", "--max-pixels", "5"]).status.code(),
        Some(2)
    );
    // On a simulating command the cap applies (and is named).
    bad_input(
        &["simulate", "--t-end", "1000", "--max-block-steps", "10"],
        &["--max-block-steps"],
    );
}

/// The linkage's scene file with `key = value` set in `[apparatus]` (added
/// where the file has no such key), written into `dir`.
fn apparatus_with(dir: &std::path::Path, edits: &[(&str, &str)]) -> String {
    let base = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/assets/scenes/movie-linkage-69.toml"
    ))
    .unwrap();
    let mut lines: Vec<String> = base.lines().map(String::from).collect();
    for (key, value) in edits {
        let set = format!("{key} = {value}");
        match lines
            .iter()
            .position(|l| l.starts_with(&format!("{key} = ")))
        {
            Some(i) => lines[i] = set,
            None => {
                let at = lines.iter().position(|l| l == "[apparatus]").unwrap();
                lines.insert(at + 1, set);
            }
        }
    }
    std::fs::create_dir_all(dir).unwrap();
    let path = dir.join("hostile.toml");
    std::fs::write(&path, lines.join("\n") + "\n").unwrap();
    path.to_str().unwrap().to_string()
}

/// An apparatus case: the keys edited, the key blamed, what the message says.
type Case = (
    &'static [(&'static str, &'static str)],
    &'static str,
    &'static [&'static str],
);

/// Every apparatus value that passes its own check but not what it gives
/// in the model's units is named by file:line:col and the key the user
/// wrote, with advice that fits (before: "the added mass must be a finite
/// number >= 0, got inf" with no file or key for a 5e-324 thickness; a
/// message about T_d for a 5e-324 motor; "dt = 0.125 is too small ... use
/// dt >= 89.78", 85 times RK4's stability limit, for g or stiffness =
/// 1e300 with duration = 1e12; g = 5e-324 blamed on the stiffness; 369
/// characters of zeros for s = 1e300).
#[test]
fn apparatus_values_that_break_the_conversion_name_their_key() {
    let dir = temp_dir("apparatus-keys");
    let cases: [Case; 8] = [
        (
            &[("thickness", "5e-324")],
            "apparatus.thickness",
            &["block mass"],
        ),
        (&[("motor", "5e-324")], "apparatus.motor", &["T_d", "Hz"]),
        (&[("g", "1e300")], "apparatus.g", &["τ"]),
        (&[("stiffness", "1e300")], "apparatus.stiffness", &["τ"]),
        (
            &[("g", "1e300"), ("duration", "1e12")],
            "apparatus.duration",
            &["no step that any scheme keeps stable", "at most"],
        ),
        (&[("g", "5e-324")], "apparatus.g", &["τ"]),
        (
            &[("stiffness", "1.0"), ("g", "5e-324")],
            "apparatus.g",
            &["G = m g/(k s) = 0"],
        ),
        (&[("s", "1e300")], "apparatus.b", &["b/s", "6e-300"]),
    ];
    for (edits, key, needles) in cases {
        let file = apparatus_with(&dir, edits);
        let err = bad_input(&["render", &file, "--check"], needles);
        let located = "hostile.toml:";
        assert!(
            err.contains(located) && err.contains(&format!(": {key}: ")),
            "{edits:?}: {err}"
        );
        assert!(!err.contains("dt = "), "{edits:?}: advice about dt: {err}");
        assert!(
            err.len() < 600,
            "{edits:?}: {} characters: {err}",
            err.len()
        );
    }
}
