//! What a newcomer meets outside the program: the inertia's unit
//! in parameter lines, docs/model.md's value of a, no tracked Python
//! caches, a release profile without full debug info, and `src/lib.rs`'s
//! floors those `scripts/check-layers` enforces, and the wheel built on
//! the tests' build of the library (the same features). (Names,
//! messages, completions, man page, gallery and MP4 PSNR: tests/integration/names.rs,
//! tests/integration/messages.rs, tests/integration/cli.rs, tests/integration/gallery.rs, tests/integration/mp4_quality.rs.)

use jacobs_ladder::scene::Model;
use jacobs_ladder::scene::describe;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

#[test]
fn the_inertia_is_written_in_m_s2_not_ms2() {
    let line = describe::model(&Model::default());
    assert!(line.contains("I = 0.25 m s²"), "{line}");
    assert!(
        !line.contains("ms²"),
        "reads as milliseconds squared: {line}"
    );
}

#[test]
fn model_md_gives_a_at_60_degrees_from_its_formula() {
    // a = sqrt(b² + 4 s² cos²α) (docs/model.md), s = 1, b = 1.3, α = 60°.
    let a = (1.3f64.powi(2) + 4.0 * 60f64.to_radians().cos().powi(2)).sqrt();
    let written = format!("{a:.4} at α = 60°, b/s = 1.3");
    let doc = std::fs::read_to_string(format!("{ROOT}/docs/model.md")).unwrap();
    assert!(doc.contains(&written), "docs/model.md should say {written}");
}

#[test]
fn no_python_caches_are_tracked_and_they_are_ignored() {
    let ignore = std::fs::read_to_string(format!("{ROOT}/.gitignore")).unwrap();
    for pattern in ["__pycache__/", "*.nbi", "*.nbc"] {
        assert!(ignore.lines().any(|l| l.trim() == pattern), "{pattern}");
    }
    let test = "docs_and_packaging::no_python_caches_are_tracked_and_they_are_ignored";
    let run = std::process::Command::new("git")
        .args(["ls-files"])
        .current_dir(ROOT)
        .output();
    if !crate::common::require::require(
        test,
        run.as_ref().is_ok_and(|r| r.status.success()),
        "`git ls-files` does not run here (no git, or not a clone)",
        "apt-get install git, and test a git clone",
    ) {
        return;
    }
    let run = run.expect("checked above");
    let files = String::from_utf8_lossy(&run.stdout);
    let cached: Vec<&str> = files
        .lines()
        .filter(|f| f.contains("__pycache__/") || f.ends_with(".nbi") || f.ends_with(".nbc"))
        .collect();
    assert!(cached.is_empty(), "tracked caches: {cached:?}");
}

#[test]
fn the_release_profile_keeps_at_most_line_tables() {
    let text = std::fs::read_to_string(format!("{ROOT}/Cargo.toml")).unwrap();
    let cargo: toml::Table = text.parse().unwrap();
    let debug = &cargo["profile"]["release"].get("debug");
    let ok = match debug {
        None => true,
        Some(toml::Value::Boolean(b)) => !b,
        Some(toml::Value::Integer(i)) => *i <= 1,
        Some(toml::Value::String(s)) => [
            "none",
            "line-directives-only",
            "line-tables-only",
            "limited",
        ]
        .contains(&s.as_str()),
        _ => false,
    };
    assert!(ok, "[profile.release] debug = {debug:?}");
}

/// Each bundled font is in the `ladder` binary once: a font's bytes held
/// in a `const` were copied into every codegen unit that used them, and
/// the release binary carried DejaVu Sans and Liberation Serif twice
/// (1.15 MB of its 16.1 MB).
#[test]
fn the_binary_carries_each_bundled_font_once() {
    let binary = std::fs::read(env!("CARGO_BIN_EXE_ladder")).unwrap();
    let fonts = std::fs::read_dir(format!("{ROOT}/assets/fonts")).unwrap();
    let mut checked = 0;
    for font in fonts.map(|f| f.unwrap().path()) {
        if font.extension().is_none_or(|e| e != "ttf") {
            continue;
        }
        let bytes = std::fs::read(&font).unwrap();
        let head = &bytes[..4096];
        let copies = binary.windows(head.len()).filter(|w| w == &head).count();
        assert_eq!(
            copies,
            1,
            "{} is in the binary {copies} times",
            font.display()
        );
        checked += 1;
    }
    assert_eq!(checked, 3, "the three bundled fonts");
}

/// `src/lib.rs`'s list of floors is the one `scripts/check-layers`
/// enforces (`FLOORS`, ground first): the doc cannot drift from the rule.
#[test]
fn the_floors_lib_rs_lists_are_the_ones_check_layers_enforces() {
    let script = std::fs::read_to_string(format!("{ROOT}/scripts/check-layers")).unwrap();
    let block = script
        .split("FLOORS = [")
        .nth(1)
        .and_then(|b| b.split("\n]").next())
        .expect("FLOORS = [ ... ] in scripts/check-layers");
    let enforced: Vec<Vec<&str>> = block
        .lines()
        .filter(|l| l.trim_start().starts_with('['))
        .map(|l| {
            l.split('"')
                .skip(1)
                .step_by(2)
                .filter(|n| !n.is_empty() && *n != "main")
                .collect()
        })
        .collect();
    let lib = std::fs::read_to_string(format!("{ROOT}/src/lib.rs")).unwrap();
    let listed: Vec<Vec<&str>> = lib
        .lines()
        .filter_map(|l| l.strip_prefix("//! "))
        .filter(|l| l.starts_with(|c: char| c.is_ascii_digit()) && l.contains(". `"))
        .map(|l| {
            let names = l.split(':').next().unwrap();
            names.split('`').skip(1).step_by(2).collect()
        })
        .collect();
    assert!(enforced.len() > 5, "{enforced:?}");
    assert_eq!(
        listed, enforced,
        "src/lib.rs's floors against scripts/check-layers's"
    );
}

/// Each package's features as `cargo tree` resolves them for `manifest`
/// with the edge kinds `edges`: "name version" → "f1,f2".
fn resolved_features(
    manifest: &str,
    edges: &str,
) -> Option<std::collections::BTreeMap<String, String>> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let out = std::process::Command::new(cargo)
        .args(["tree", "--manifest-path", manifest, "-e", edges])
        .args(["-f", "{p}|{f}", "--prefix", "none", "--no-dedupe"])
        .output()
        .ok()
        .filter(|o| o.status.success())?;
    let text = String::from_utf8(out.stdout).ok()?;
    let row = |l: &str| {
        let (p, f) = l.split_once('|')?;
        let p = p.split(" (").next()?.trim().to_string();
        Some((p, f.trim().to_string()))
    };
    Some(text.lines().filter_map(row).collect())
}

/// The Python binding's crate (python/, a member of the root's workspace,
/// so one Cargo.lock and one library unit serve both) and the main
/// crate's tests resolve every shared dependency with the same features,
/// so that the wheel `scripts/test` builds into the same target/ reuses
/// the tests' build of the library (the pins in both Cargo.toml files)
/// instead of compiling it and its dependencies again.
#[test]
fn the_wheel_shares_the_tests_build_of_the_library() {
    let main = resolved_features(&format!("{ROOT}/Cargo.toml"), "normal,build,dev");
    let python = resolved_features(&format!("{ROOT}/python/Cargo.toml"), "normal,build");
    let (Some(main), Some(python)) = (main, python) else {
        let test = "the_wheel_shares_the_tests_build_of_the_library";
        let what = "`cargo tree` could not resolve both workspaces";
        let hint = "it needs the crates.io index or the crates in the cargo cache";
        crate::common::require::require(test, false, what, hint);
        return;
    };
    let differ: Vec<String> = main
        .iter()
        .filter_map(|(p, f)| python.get(p).filter(|g| *g != f).map(|g| (p, f, g)))
        .map(|(p, f, g)| format!("{p}: tests [{f}], wheel [{g}]"))
        .collect();
    assert!(python.contains_key("jacobs-ladder v0.1.0"), "{python:?}");
    assert!(differ.is_empty(), "features differ: {differ:#?}");
}
