//! What a newcomer meets outside the program: the inertia's unit
//! in parameter lines, docs/model.md's value of a, no tracked Python
//! caches, and a release profile without full debug info. (Names,
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
    let Ok(run) = std::process::Command::new("git")
        .args(["ls-files"])
        .current_dir(ROOT)
        .output()
    else {
        eprintln!("skipped: no git");
        return;
    };
    if !run.status.success() {
        eprintln!("skipped: not a git clone");
        return;
    }
    let files = String::from_utf8_lossy(&run.stdout);
    let cached: Vec<&str> = files
        .lines()
        .filter(|f| f.contains("__pycache__/") || f.ends_with(".nbi") || f.ends_with(".nbc"))
        .collect();
    assert!(cached.is_empty(), "tracked caches: {cached:?}");
    let ignore = std::fs::read_to_string(format!("{ROOT}/.gitignore")).unwrap();
    for pattern in ["__pycache__/", "*.nbi", "*.nbc"] {
        assert!(ignore.lines().any(|l| l.trim() == pattern), "{pattern}");
    }
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
