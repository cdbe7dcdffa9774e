//! `index.html`: every figure and movie the run wrote, in a grid a reader
//! can scan, each with one caption, the level of the model behind it, its
//! parameters and links to all its files.
//!
//! The HTML and CSS live in template files under `assets/gallery/`; this
//! module only fills their `{{key}}` placeholders with escaped text.

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
        let cards: String = of_kind.iter().map(|it| card(it)).collect();
        sections.push_str(&fill(
            template::SECTION,
            &[("id", id), ("heading", heading), ("cards", &cards)],
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
        ],
    ))
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
/// ("movie-4-kymograph", "png").
fn split_name(file: &str) -> (&str, &str) {
    file.rsplit_once('.').unwrap_or((file, ""))
}

/// The picture to show for each base name: a video where there is one,
/// else an image the browser shows (GIF, PNG, SVG), in the order written.
fn pictures(it: &Item<'_>) -> Vec<(String, bool)> {
    let mut shown: Vec<(String, bool)> = Vec::new();
    for file in &it.files {
        let (base, ext) = split_name(file);
        let rank = match ext {
            "mp4" => 0,
            "gif" => 1,
            "png" => 2,
            "svg" => 3,
            _ => continue,
        };
        match shown.iter_mut().find(|(f, _)| split_name(f).0 == base) {
            Some(entry) => {
                let old = match split_name(&entry.0).1 {
                    "mp4" => 0,
                    "gif" => 1,
                    "png" => 2,
                    _ => 3,
                };
                if rank < old {
                    *entry = (file.clone(), rank == 0);
                }
            }
            None => shown.push((file.clone(), rank == 0)),
        }
    }
    shown
}

/// What a link to `file` says: "PNG", "kymograph (PNG)", "data (JSON)".
fn link_text(scene: &Scene, file: &str) -> String {
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

fn card(it: &Item<'_>) -> String {
    let scene = it.scene;
    let title = describe::title(scene);
    let pictures: String = pictures(it)
        .iter()
        .map(|(file, video)| {
            let what = if split_name(file).0.ends_with("-kymograph") {
                describe::kymograph()
            } else {
                describe::picture(scene)
            };
            let alt = escape(&format!("{title}. {what}."));
            let src = escape(file);
            let template = if *video {
                template::VIDEO
            } else {
                template::IMAGE
            };
            fill(template, &[("src", &src), ("alt", &alt)])
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
            ("level", &escape(&describe::model_level(scene))),
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
        let html = card(&Item {
            scene: &scene,
            files,
        });
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
                ("movie-4.mp4".to_string(), true),
                ("movie-4-kymograph.png".to_string(), false)
            ]
        );
        let html = card(&it);
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
