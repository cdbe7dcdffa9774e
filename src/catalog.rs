//! The paper's figures and movies (README.md) as scene files: TOML
//! under `assets/scenes/`, built into the binary and read through the same
//! parser as a user's file. A new catalogue entry is a new file in that
//! folder and a line in [`FILES`], not new code.

use crate::error::{Error, Result};
use crate::scene::{self, Kind, Scene};
use std::sync::OnceLock;

/// The built-in scene files, in the paper's order: (file stem, text);
/// the toy as built first, as the paper's Fig. 1a photographs it.
/// The stem is `figure-ID` or `movie-ID`.
pub const FILES: &[(&str, &str)] = &[
    (
        "figure-toy",
        include_str!("../assets/scenes/figure-toy.toml"),
    ),
    ("figure-1c", include_str!("../assets/scenes/figure-1c.toml")),
    ("figure-2b", include_str!("../assets/scenes/figure-2b.toml")),
    ("figure-2c", include_str!("../assets/scenes/figure-2c.toml")),
    ("figure-2d", include_str!("../assets/scenes/figure-2d.toml")),
    ("figure-3", include_str!("../assets/scenes/figure-3.toml")),
    ("figure-4a", include_str!("../assets/scenes/figure-4a.toml")),
    ("figure-4b", include_str!("../assets/scenes/figure-4b.toml")),
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
    (
        "figure-friction",
        include_str!("../assets/scenes/figure-friction.toml"),
    ),
    (
        "figure-tank-positions",
        include_str!("../assets/scenes/figure-tank-positions.toml"),
    ),
    (
        "figure-tank-positions-ribbons",
        include_str!("../assets/scenes/figure-tank-positions-ribbons.toml"),
    ),
    (
        "figure-tank-levels",
        include_str!("../assets/scenes/figure-tank-levels.toml"),
    ),
    (
        "figure-linkage-friction",
        include_str!("../assets/scenes/figure-linkage-friction.toml"),
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
    ("movie-12", include_str!("../assets/scenes/movie-12.toml")),
    (
        "movie-water-tank",
        include_str!("../assets/scenes/movie-water-tank.toml"),
    ),
    (
        "movie-linkage-69",
        include_str!("../assets/scenes/movie-linkage-69.toml"),
    ),
    (
        "movie-water-tank-ribbons",
        include_str!("../assets/scenes/movie-water-tank-ribbons.toml"),
    ),
    ("movie-toy", include_str!("../assets/scenes/movie-toy.toml")),
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

/// The entry of `kind` with this ID; case does not matter (`s5` is S5).
/// An unknown ID is bad input whose message names the closest IDs, or
/// says that the paper's item is a photograph or recording.
pub fn find(kind: Kind, id: &str) -> Result<&'static Entry> {
    entries(kind)?
        .into_iter()
        .find(|e| e.id.eq_ignore_ascii_case(id))
        .ok_or_else(|| unknown(Some(kind), id))
}

/// The entry with this ID, figure or movie (figures first).
pub fn find_any(id: &str) -> Result<&'static Entry> {
    find(Kind::Figure, id)
        .or_else(|_| find(Kind::Movie, id))
        .map_err(|_| unknown(None, id))
}

/// "figures 1c, 2b, 2c or all": the IDs of one kind.
fn id_list(kind: Kind) -> String {
    let ids: Vec<String> = entries(kind)
        .map(|all| all.iter().map(|e| e.id.clone()).collect())
        .unwrap_or_default();
    format!(
        "{}s {}",
        kind.name(),
        or_list(&ids).replace(" or ", " and ")
    )
}

/// The message for an ID that is not in the catalogue (of `kind`, or of
/// either kind): what the paper's item is if the program does not make
/// it, else the closest IDs, then what there is.
fn unknown(kind: Option<Kind>, id: &str) -> Error {
    let kinds: Vec<Kind> = kind.map_or(vec![Kind::Figure, Kind::Movie], |k| vec![k]);
    let what = kind.map_or("scene", Kind::name);
    let makes = format!(
        "It makes {}, and {}",
        id_list(Kind::Figure),
        id_list(Kind::Movie)
    );
    if let Some(a) = absent()
        .unwrap_or_default()
        .iter()
        .find(|a| kinds.contains(&a.kind) && a.id.eq_ignore_ascii_case(id))
    {
        let nearest = a
            .nearest
            .as_ref()
            .map_or(String::new(), |n| format!(" (the nearest it makes: {n})"));
        return Error::bad_input(format!(
            "{} {} of the paper is {}; this program does not make it: it simulates and draws \
             the paper's model, and makes no photographs or recordings of real toys{nearest}. \
             {makes} (`ladder list`)",
            a.kind.name(),
            a.id,
            a.what
        ));
    }
    let close = closest(kind, id);
    let hint = if close.is_empty() {
        String::new()
    } else {
        format!("; did you mean {}?", or_list(&close))
    };
    let choose = match kind {
        Some(k) => {
            let ids: Vec<String> = entries(k)
                .map(|all| all.iter().map(|e| e.id.clone()).collect())
                .unwrap_or_default();
            format!("choose one of {} or all", ids.join(", "))
        }
        None => format!(
            "choose one of {} or {}",
            id_list(Kind::Figure),
            id_list(Kind::Movie)
        ),
    };
    Error::bad_input(format!("unknown {what} '{id}'{hint} ({choose})"))
}

/// "a, b or c".
fn or_list(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} or {last}", init.join(", ")),
    }
}

/// The catalogue's IDs closest to `id`, as "figure S6" or, when `kind` is
/// given, the bare ID of that kind: IDs that start with what was typed,
/// else those at the smallest edit distance (at most 2, and less than the
/// length of what was typed). An ID of the other kind that matches exactly
/// ("figure 4" → "movie 4") is named too.
fn closest(kind: Option<Kind>, id: &str) -> Vec<String> {
    let typed = id.to_lowercase();
    let Ok(all) = catalogue() else {
        return Vec::new();
    };
    let name = |e: &Entry| match kind {
        Some(k) if e.kind() == k => e.id.clone(),
        _ => format!("{} {}", e.kind().name(), e.id),
    };
    let own: Vec<&Entry> = all
        .iter()
        .filter(|e| kind.is_none_or(|k| e.kind() == k))
        .collect();
    let mut close: Vec<String> = own
        .iter()
        .filter(|e| !typed.is_empty() && e.id.to_lowercase().starts_with(&typed))
        .map(|e| name(e))
        .collect();
    if close.is_empty() {
        let distance = |e: &&Entry| strsim::levenshtein(&typed, &e.id.to_lowercase());
        if let Some(best) = own.iter().map(distance).min()
            && best <= 2
            && best < typed.chars().count()
        {
            close = own
                .iter()
                .filter(|e| distance(e) == best)
                .map(|e| name(e))
                .collect();
        }
    }
    if kind.is_some() {
        close.extend(
            all.iter()
                .filter(|e| kind != Some(e.kind()) && e.id.eq_ignore_ascii_case(id))
                .map(name),
        );
    }
    close
}

/// An item of the paper that the program does not make: a photograph or
/// a recording of a real toy or experiment (`assets/not-made.toml`).
#[derive(Debug, Clone, PartialEq)]
pub struct Absent {
    pub kind: Kind,
    /// The paper's number: "1a", "S2", "12".
    pub id: String,
    /// What it shows: "a photograph of ...".
    pub what: String,
    /// The built-in output closest to it ("figure 2b"), if any.
    pub nearest: Option<String>,
}

/// `assets/not-made.toml`: the items of the paper the program does not make.
pub const ABSENT_FILE: &str = include_str!("../assets/not-made.toml");

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct AbsentFile {
    figure: Vec<AbsentEntry>,
    movie: Vec<AbsentEntry>,
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct AbsentEntry {
    id: String,
    what: String,
    nearest: Option<String>,
}

/// The paper's items the program does not make, figures first, parsed once.
pub fn absent() -> Result<&'static [Absent]> {
    static ABSENT: OnceLock<std::result::Result<Vec<Absent>, String>> = OnceLock::new();
    ABSENT
        .get_or_init(|| {
            let file: AbsentFile =
                toml::from_str(ABSENT_FILE).map_err(|e| format!("assets/not-made.toml: {e}"))?;
            let tagged = |kind: Kind, list: Vec<AbsentEntry>| {
                list.into_iter().map(move |a| Absent {
                    kind,
                    id: a.id,
                    what: a.what,
                    nearest: a.nearest,
                })
            };
            Ok(tagged(Kind::Figure, file.figure)
                .chain(tagged(Kind::Movie, file.movie))
                .collect())
        })
        .as_deref()
        .map_err(|e| Error::failed(format!("a built-in file is broken: {e}")))
}

/// One sentence for the gallery: what of the paper is not made, and why.
pub fn absent_summary() -> Result<String> {
    let ids = |kind: Kind| -> Result<Vec<String>> {
        Ok(absent()?
            .iter()
            .filter(|a| a.kind == kind)
            .map(|a| a.id.clone())
            .collect())
    };
    Ok(format!(
        "Not made here: figures {} and movies {} of the paper. They are photographs and \
         recordings of real toys and experiments, and this program simulates the model; where \
         the paper shows an experiment that the model describes (figures 1c, 4a and S6, movies \
         3, 10 and 11), the page shows its simulated analogue.",
        or_list(&ids(Kind::Figure)?).replace(" or ", " and "),
        or_list(&ids(Kind::Movie)?).replace(" or ", " and ")
    ))
}

/// `ladder list`: one line per entry.
pub fn listing() -> Result<String> {
    let all = catalogue()?;
    let width = all.iter().map(|e| e.id.chars().count()).max().unwrap_or(0);
    let mut s = String::new();
    for e in all {
        s.push_str(&format!(
            "{:<6} {:<width$} {:<14} {}\n",
            e.kind().name(),
            e.id,
            e.scene.fidelity().name(),
            scene::describe::title(&e.scene)
        ));
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn what_is_not_made_is_not_in_the_catalogue_and_points_at_what_is() {
        let absent = absent().unwrap();
        assert_eq!(absent.len(), 7, "five figures and two movies");
        for a in absent {
            assert!(
                find(a.kind, &a.id).is_err(),
                "{} {} is made",
                a.kind.name(),
                a.id
            );
            if let Some(n) = &a.nearest {
                let (kind, id) = n.split_once(' ').unwrap();
                let kind = if kind == "figure" {
                    Kind::Figure
                } else {
                    Kind::Movie
                };
                assert!(
                    find(kind, id).is_ok(),
                    "nearest {n} is not in the catalogue"
                );
            }
        }
    }

    #[test]
    fn closest_ids() {
        assert_eq!(closest(Some(Kind::Figure), "s6"), ["S6"]);
        assert_eq!(closest(Some(Kind::Figure), "edge"), ["edge-mode"]);
        assert_eq!(closest(Some(Kind::Movie), "3"), ["3", "figure 3"]);
        assert!(closest(Some(Kind::Movie), "qqq").is_empty());
        assert_eq!(or_list(&["a".into(), "b".into(), "c".into()]), "a, b or c");
    }
}
