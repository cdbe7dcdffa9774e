//! The paper's figures and movies (SPEC section 4) as scene files: TOML
//! under `assets/scenes/`, built into the binary and read through the same
//! parser as a user's file. A new catalogue entry is a new file in that
//! folder and a line in [`FILES`], not new code.

use crate::error::{Error, Result};
use crate::scene::{self, Kind, Scene};
use std::sync::OnceLock;

/// The built-in scene files, in the paper's order: (file stem, text).
/// The stem is `figure-ID` or `movie-ID`.
pub const FILES: &[(&str, &str)] = &[
    ("figure-1c", include_str!("../assets/scenes/figure-1c.toml")),
    ("figure-2b", include_str!("../assets/scenes/figure-2b.toml")),
    ("figure-2c", include_str!("../assets/scenes/figure-2c.toml")),
    ("figure-2d", include_str!("../assets/scenes/figure-2d.toml")),
    ("figure-3", include_str!("../assets/scenes/figure-3.toml")),
    ("figure-4a", include_str!("../assets/scenes/figure-4a.toml")),
    ("figure-S3", include_str!("../assets/scenes/figure-S3.toml")),
    ("figure-S4", include_str!("../assets/scenes/figure-S4.toml")),
    ("figure-S5", include_str!("../assets/scenes/figure-S5.toml")),
    ("figure-S6", include_str!("../assets/scenes/figure-S6.toml")),
    (
        "figure-winding",
        include_str!("../assets/scenes/figure-winding.toml"),
    ),
    (
        "figure-edge-mode",
        include_str!("../assets/scenes/figure-edge-mode.toml"),
    ),
    (
        "figure-barrier",
        include_str!("../assets/scenes/figure-barrier.toml"),
    ),
    (
        "figure-pinning",
        include_str!("../assets/scenes/figure-pinning.toml"),
    ),
    (
        "figure-phase",
        include_str!("../assets/scenes/figure-phase.toml"),
    ),
    (
        "figure-chain-length",
        include_str!("../assets/scenes/figure-chain-length.toml"),
    ),
    ("movie-3", include_str!("../assets/scenes/movie-3.toml")),
    ("movie-4", include_str!("../assets/scenes/movie-4.toml")),
    ("movie-5", include_str!("../assets/scenes/movie-5.toml")),
    ("movie-6", include_str!("../assets/scenes/movie-6.toml")),
    ("movie-7", include_str!("../assets/scenes/movie-7.toml")),
    ("movie-8", include_str!("../assets/scenes/movie-8.toml")),
    ("movie-9", include_str!("../assets/scenes/movie-9.toml")),
    ("movie-10", include_str!("../assets/scenes/movie-10.toml")),
    ("movie-11", include_str!("../assets/scenes/movie-11.toml")),
];

/// A catalogue entry: its ID ("3", "S5", "edge-mode") and its scene,
/// named by the ID.
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    pub id: String,
    pub scene: Scene,
}

impl Entry {
    pub fn kind(&self) -> Kind {
        self.scene.kind()
    }
}

/// Every entry, parsed once.
pub fn catalogue() -> Result<&'static [Entry]> {
    static CATALOGUE: OnceLock<std::result::Result<Vec<Entry>, String>> = OnceLock::new();
    CATALOGUE
        .get_or_init(|| FILES.iter().map(|(stem, text)| load(stem, text)).collect())
        .as_deref()
        .map_err(|e| Error::failed(format!("a built-in scene is broken: {e}")))
}

fn load(stem: &str, text: &str) -> std::result::Result<Entry, String> {
    let (kind, id) = stem
        .split_once('-')
        .ok_or_else(|| format!("{stem}: the file name must be figure-ID or movie-ID"))?;
    let scene = scene::file::parse(text, &format!("assets/scenes/{stem}.toml"), id)
        .map_err(|e| e.to_string())?;
    if scene.kind().name() != kind {
        return Err(format!("{stem}: the file makes a {}", scene.kind().name()));
    }
    Ok(Entry {
        id: id.to_string(),
        scene,
    })
}

/// Entries of one kind, in catalogue order.
pub fn entries(kind: Kind) -> Result<Vec<&'static Entry>> {
    Ok(catalogue()?.iter().filter(|e| e.kind() == kind).collect())
}

/// The entry of `kind` with this ID.
pub fn find(kind: Kind, id: &str) -> Result<&'static Entry> {
    let all = entries(kind)?;
    all.iter().copied().find(|e| e.id == id).ok_or_else(|| {
        let ids: Vec<&str> = all.iter().map(|e| e.id.as_str()).collect();
        Error::bad_input(format!(
            "unknown {} '{id}'; choose one of {} or all",
            kind.name(),
            ids.join(", ")
        ))
    })
}

/// The entry with this ID, figure or movie (figures first).
pub fn find_any(id: &str) -> Result<&'static Entry> {
    find(Kind::Figure, id)
        .or_else(|_| find(Kind::Movie, id))
        .map_err(|_| {
            let ids: Vec<String> = catalogue()
                .map(|c| c.iter().map(|e| e.id.clone()).collect())
                .unwrap_or_default();
            Error::bad_input(format!(
                "unknown scene '{id}'; choose one of {}",
                ids.join(", ")
            ))
        })
}

/// `ladder list`: one line per entry.
pub fn listing() -> Result<String> {
    let mut s = String::new();
    for e in catalogue()? {
        s.push_str(&format!(
            "{:<6} {:<9} {:<14} {}\n",
            e.kind().name(),
            e.id,
            e.scene.fidelity().name(),
            scene::describe::title(&e.scene)
        ));
    }
    Ok(s)
}
