//! `index.html`: every figure and movie the run wrote, in a grid a reader
//! can scan, each with one caption, its parameters and links to all its
//! files. The level of the model behind each entry is said once per
//! section, in a sentence, and named in a word on each card.
//!
//! The HTML, CSS and the script that packs the grid without holes live in
//! template files under `assets/gallery/`; this module only fills their
//! `{{key}}` placeholders with escaped text.

use crate::catalog;
use crate::error::Result;
use crate::scene::{Kind, Scene, describe};
use crate::theory::formulas;

/// The templates, built into the binary.
mod template {
    pub const PAGE: &str = include_str!("../assets/gallery/page.html");
    pub const STYLE: &str = include_str!("../assets/gallery/style.css");
    pub const SECTION: &str = include_str!("../assets/gallery/section.html");
    pub const CONTENTS: &str = include_str!("../assets/gallery/contents.html");
    pub const CONTENTS_ENTRY: &str = include_str!("../assets/gallery/contents-entry.html");
    pub const CARD: &str = include_str!("../assets/gallery/card.html");
    pub const LEVEL: &str = include_str!("../assets/gallery/level.html");
    pub const SCRIPT: &str = include_str!("../assets/gallery/layout.js");
    pub const IMAGE: &str = include_str!("../assets/gallery/image.html");
    pub const VIDEO: &str = include_str!("../assets/gallery/video.html");
    pub const LINK: &str = include_str!("../assets/gallery/link.html");
}

/// One rendered scene for the page: the scene and the files it wrote
/// (names inside the output folder).
pub struct Item<'a> {
    pub scene: &'a Scene,
    pub files: Vec<String>,
}

/// Text made safe for HTML content and attribute values.
pub fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// `template` with each `{{key}}` replaced by its value (already HTML).
fn fill(template: &str, values: &[(&str, &str)]) -> String {
    let mut out = template.to_string();
    for (key, value) in values {
        out = out.replace(&format!("{{{{{key}}}}}"), value);
    }
    out
}

/// The sections of the page: (anchor, heading, kind).
const SECTIONS: [(&str, &str, Kind); 3] = [
    ("figures", "Figures", Kind::Figure),
    ("movies", "Supplemental movies", Kind::Movie),
    ("data", "Data", Kind::Data),
];

/// The gallery page for `items`.
pub fn index_html(items: &[Item<'_>]) -> Result<String> {
    let mut contents = String::new();
    let mut sections = String::new();
    for (id, heading, kind) in SECTIONS {
        let of_kind: Vec<&Item<'_>> = items.iter().filter(|i| i.scene.kind() == kind).collect();
        if of_kind.is_empty() {
            continue;
        }
        let entries: String = of_kind.iter().map(|it| contents_entry(it.scene)).collect();
        contents.push_str(&fill(
            template::CONTENTS,
            &[("id", id), ("heading", heading), ("entries", &entries)],
        ));
        let levels = levels(&of_kind);
        let level_of = |scene: &Scene| {
            let sentence = describe::model_level(scene);
            let k = levels.iter().position(|(s, _)| *s == sentence).unwrap_or(0);
            format!(
                "<a href=\"#{id}-level-{}\">{}</a>",
                k + 1,
                escape(scene.fidelity().name())
            )
        };
        let cards: String = of_kind
            .iter()
            .map(|it| card(it, &level_of(it.scene)))
            .collect();
        let said: String = levels
            .iter()
            .enumerate()
            .map(|(k, (sentence, labels))| {
                let labels = if levels.len() > 1 {
                    format!("<b>{}:</b> ", escape(&labels.join(", ")))
                } else {
                    String::new()
                };
                fill(
                    template::LEVEL,
                    &[
                        ("id", &format!("{id}-level-{}", k + 1)),
                        ("labels", &labels),
                        ("sentence", &escape(sentence)),
                    ],
                )
            })
            .collect();
        sections.push_str(&fill(
            template::SECTION,
            &[
                ("id", id),
                ("heading", heading),
                ("levels", &said),
                ("cards", &cards),
            ],
        ));
    }
    let version = env!("CARGO_PKG_VERSION");
    Ok(fill(
        template::PAGE,
        &[
            ("style", template::STYLE),
            ("version", version),
            ("absent", &escape(&catalog::absent_summary()?)),
            ("contents", &contents),
            ("sections", &sections),
            ("script", template::SCRIPT),
        ],
    ))
}

/// The model levels of a section's items, each sentence once with the
/// labels of the items it is said of, in the order first met.
fn levels(items: &[&Item<'_>]) -> Vec<(String, Vec<String>)> {
    let mut out: Vec<(String, Vec<String>)> = Vec::new();
    for it in items {
        let sentence = describe::model_level(it.scene);
        let name = label(it.scene);
        match out.iter_mut().find(|(s, _)| *s == sentence) {
            Some((_, labels)) => labels.push(name),
            None => out.push((sentence, vec![name])),
        }
    }
    out
}

/// The bold lead of a caption and of a contents entry: the scene's label
/// ("Fig. 3", "Movie 4"), or its kind and name ("Figure barrier").
fn label(scene: &Scene) -> String {
    scene.label.clone().unwrap_or_else(|| {
        let kind = scene.kind().name();
        let mut k = kind.chars();
        let kind = k
            .next()
            .map(|c| c.to_uppercase().chain(k).collect::<String>())
            .unwrap_or_default();
        format!("{kind} {}", scene.name)
    })
}

/// The title without its label: the words drawn at the top of the picture.
fn title_body(scene: &Scene) -> String {
    scene
        .title
        .clone()
        .unwrap_or_else(|| describe::generated_title(scene))
}

fn contents_entry(scene: &Scene) -> String {
    fill(
        template::CONTENTS_ENTRY,
        &[
            ("anchor", &escape(&scene.stem())),
            ("label", &escape(&label(scene))),
            ("title", &escape(&title_body(scene))),
        ],
    )
}

/// A file's base name and extension: "movie-4-kymograph.png" →
/// ("movie-4-kymograph", "png"). A PNG preview of a figure asked in
/// vector formats only ("figure-3-preview.png") has its figure's base.
fn split_name(file: &str) -> (&str, &str) {
    if let Some(base) = file.strip_suffix(crate::scenes::PREVIEW) {
        return (base, "png");
    }
    file.rsplit_once('.').unwrap_or((file, ""))
}

/// What the page shows of one base name ("movie-4"): the file, whether it
/// is a video, and for a video the image shown until it plays.
#[derive(Debug, Clone, PartialEq)]
struct Shown {
    src: String,
    video: bool,
    poster: Option<String>,
}

/// How much the page prefers showing a file of this extension (lower
/// first): a video, then an image the browser shows; `None` for the rest.
fn show_rank(ext: &str) -> Option<u8> {
    ["mp4", "gif", "png", "svg"]
        .iter()
        .position(|e| *e == ext)
        .map(|p| p as u8)
}

/// The picture to show for each base name, in the order written: a video
/// where there is one (with the base's GIF or PNG as its poster), else an
/// image (GIF, PNG, SVG).
fn pictures(it: &Item<'_>) -> Vec<Shown> {
    let mut bases: Vec<(&str, Vec<&String>)> = Vec::new();
    for file in &it.files {
        let (base, ext) = split_name(file);
        if show_rank(ext).is_none() {
            continue;
        }
        match bases.iter_mut().find(|(b, _)| *b == base) {
            Some((_, files)) => files.push(file),
            None => bases.push((base, vec![file])),
        }
    }
    bases
        .into_iter()
        .filter_map(|(_, mut files)| {
            files.sort_by_key(|f| show_rank(split_name(f).1));
            let first = files.first()?;
            let video = split_name(first).1 == "mp4";
            let poster = files
                .iter()
                .skip(1)
                .find(|f| matches!(split_name(f).1, "gif" | "png"))
                .filter(|_| video)
                .map(|f| f.to_string());
            Some(Shown {
                src: first.to_string(),
                video,
                poster,
            })
        })
        .collect()
}

/// What a link to `file` says: "PNG", "kymograph (PNG)", "data (JSON)",
/// "preview (PNG)".
fn link_text(scene: &Scene, file: &str) -> String {
    if file.ends_with(crate::scenes::PREVIEW) {
        let (base, _) = split_name(file);
        let figure = link_text(scene, &format!("{base}.png"));
        return match figure.strip_suffix(" (PNG)") {
            Some(what) => format!("{what} preview (PNG)"),
            None => "preview (PNG)".into(),
        };
    }
    let (base, ext) = split_name(file);
    let format = match ext {
        "json" => return "data (JSON)".into(),
        "" => return file.into(),
        other => other.to_ascii_uppercase(),
    };
    match base.strip_prefix(&scene.stem()) {
        Some("") | None => format,
        Some(rest) => format!("{} ({format})", rest.trim_start_matches('-')),
    }
}

/// One entry of the page; `level` names the model level in a word (a
/// link to the section's sentence).
fn card(it: &Item<'_>, level: &str) -> String {
    let scene = it.scene;
    let title = describe::title(scene);
    let pictures: String = pictures(it)
        .iter()
        .map(|shown| {
            let what = if scene.rings.is_some() && split_name(&shown.src).0.ends_with("-kymograph")
            {
                crate::rings::RingChain::kymograph_words().into()
            } else if split_name(&shown.src).0.ends_with("-kymograph") {
                describe::kymograph()
            } else {
                describe::picture(scene)
            };
            let alt = escape(&format!("{title}. {what}."));
            let src = escape(&shown.src);
            if shown.video {
                let poster = shown
                    .poster
                    .as_ref()
                    .map_or(String::new(), |p| format!(" poster=\"{}\"", escape(p)));
                fill(
                    template::VIDEO,
                    &[("src", &src), ("alt", &alt), ("poster", &poster)],
                )
            } else {
                fill(template::IMAGE, &[("src", &src), ("alt", &alt)])
            }
        })
        .collect();
    let files: Vec<String> = it
        .files
        .iter()
        .map(|f| {
            fill(
                template::LINK,
                &[
                    ("href", &escape(f)),
                    ("text", &escape(&link_text(scene, f))),
                ],
            )
            .trim_end()
            .to_string()
        })
        .collect();
    // The title is drawn at the top of the picture and listed in the
    // contents: the caption says what the picture shows instead.
    let caption = match &scene.caption {
        Some(c) => crate::render::style::markup_html(&formulas::expand(c)),
        None => escape(&format!("{}.", describe::picture(scene))),
    };
    let wide = matches!(scene.output, crate::scene::OutputSpec::Filmstrip { .. });
    fill(
        template::CARD,
        &[
            ("class", if wide { " wide" } else { "" }),
            ("anchor", &escape(&scene.stem())),
            ("pictures", &pictures),
            ("label", &escape(&label(scene))),
            ("caption", &caption),
            ("level", level),
            ("parameters", &escape(&describe::parameters(scene))),
            ("files", &files.join(" · ")),
        ],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The `{{key}}` placeholders of a template.
    fn keys(template: &str) -> Vec<String> {
        template
            .split("{{")
            .skip(1)
            .filter_map(|s| s.split_once("}}").map(|(k, _)| k.to_string()))
            .collect()
    }

    #[test]
    fn every_placeholder_is_filled() {
        let scenes: Vec<Scene> = catalog::catalogue()
            .unwrap()
            .iter()
            .map(|e| e.scene.clone())
            .collect();
        let items: Vec<Item<'_>> = scenes
            .iter()
            .map(|s| Item {
                scene: s,
                files: crate::scenes::file_names(s),
            })
            .collect();
        let page = index_html(&items).unwrap();
        assert!(!page.contains("{{") && !page.contains("}}"), "unfilled key");
        for t in [
            template::PAGE,
            template::SECTION,
            template::CONTENTS,
            template::CARD,
            template::IMAGE,
        ] {
            assert!(!keys(t).is_empty());
        }
    }

    #[test]
    fn one_caption_and_no_title_twice() {
        let scene = catalog::find(Kind::Movie, "4").unwrap().scene.clone();
        let files = crate::scenes::file_names(&scene);
        let html = card(
            &Item {
                scene: &scene,
                files,
            },
            "simulation",
        );
        assert_eq!(html.matches("<figcaption>").count(), 1);
        let title = title_body(&scene);
        let caption = html.split("<figcaption>").nth(1).unwrap();
        assert!(!caption.contains(&title), "title repeated: {caption}");
        assert!(html.contains("alt=\"Movie 4: kink, α = 60°. Animation"));
    }

    #[test]
    fn video_wins_over_gif_and_every_file_is_linked() {
        let scene = catalog::find(Kind::Movie, "4").unwrap().scene.clone();
        let files: Vec<String> = [
            "movie-4.gif",
            "movie-4.mp4",
            "movie-4-kymograph.png",
            "movie-4-kymograph.svg",
            "movie-4.json",
        ]
        .map(String::from)
        .to_vec();
        let it = Item {
            scene: &scene,
            files: files.clone(),
        };
        assert_eq!(
            pictures(&it),
            vec![
                Shown {
                    src: "movie-4.mp4".into(),
                    video: true,
                    poster: Some("movie-4.gif".into())
                },
                Shown {
                    src: "movie-4-kymograph.png".into(),
                    video: false,
                    poster: None
                }
            ]
        );
        let html = card(&it, "simulation");
        for f in &files {
            assert!(html.contains(&format!("href=\"{f}\"")), "{f} not linked");
        }
        assert!(html.contains(">kymograph (SVG)<") && html.contains(">data (JSON)<"));
    }

    #[test]
    fn escaping() {
        assert_eq!(escape("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
        assert_eq!(fill("x{{a}}y{{a}}", &[("a", "1")]), "x1y1");
    }
}
