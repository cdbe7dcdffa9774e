//! The ring chain's captions against their data files (as
//! `captions.rs`): figure 4b's and movie 12's data files from the shared
//! render of the catalogue (`common::catalogue_render`: `ladder all
//! --frames 20 --size 320x240`), and what their captions say of the run (how many rings, that no ring
//! flips, that no helical wave forms) decided from the data file's
//! `rings` record, so a caption that outlives its data fails.

use serde_json::Value;

/// The data file of `KIND ID` in the shared render of the catalogue.
fn data(kind: &str, id: &str) -> Value {
    let (dir, _) = crate::common::catalogue_render();
    let text = std::fs::read_to_string(dir.join(format!("{kind}-{id}.json"))).unwrap();
    serde_json::from_str(&text).unwrap()
}

/// The caption's claims against the data: the number of rings, flips
/// (none: "no ring flips"), helical waves (none: "no helical wave
/// forms"), and the linking guard's pair checks, as many as the caption
/// quotes (and all held: the run finished, a lost link fails it).
fn check(name: &str, d: &Value) {
    let caption = d["scene"]["caption"].as_str().unwrap();
    let rings = &d["rings"];
    let n = d["scene"]["rings"]["n"].as_u64().unwrap();
    assert!(
        caption.contains(&format!("{n} steel key rings")),
        "{name}: {caption}"
    );
    let flips = rings["flips"].as_array().unwrap();
    let waves = rings["waves"].as_array().unwrap();
    assert_eq!(
        flips.is_empty(),
        caption.contains("no ring flips") || caption.contains("No ring flips"),
        "{name}: {} flips against \"{caption}\"",
        flips.len()
    );
    assert_eq!(
        waves.is_empty(),
        caption.contains("no helical wave forms in this model"),
        "{name}: {} waves against \"{caption}\"",
        waves.len()
    );
    let checks = rings["guard_checks"].as_u64().unwrap();
    assert!(checks > 0, "{name}");
    assert_eq!(
        quoted_checks(caption),
        Some(checks),
        "{name}: the data file's {checks} guard checks against \"{caption}\""
    );
}

/// The number the caption quotes as the linking guard's pair checks
/// ("the linking guard checked 236 640 pairs", at any case; digits
/// grouped by spaces).
fn quoted_checks(caption: &str) -> Option<u64> {
    let caption = caption.to_lowercase();
    let after = caption.split("the linking guard checked ").nth(1)?;
    let digits: String = after
        .split(" pairs")
        .next()?
        .chars()
        .filter(|c| *c != ' ')
        .collect();
    digits.parse().ok()
}

#[test]
fn figure_4b_caption_says_what_its_data_file_does() {
    check("figure 4b", &data("figure", "4b"));
}

/// Small frames: the simulation (and so every flip and wave, observed
/// at every step) is the movie's; only the samples drawn are fewer.
#[test]
fn movie_12_caption_says_what_its_data_file_does() {
    check("movie 12", &data("movie", "12"));
}
