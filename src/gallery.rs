//! `index.html`: every figure and movie of the catalogue with its caption,
//! parameters and the fidelity of the model behind it.

use crate::scene::{Kind, Scene, describe};

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// One rendered scene for the page: the scene and the files it wrote.
pub struct Item<'a> {
    pub scene: &'a Scene,
    pub files: Vec<String>,
}

fn item(it: &Item<'_>) -> String {
    let scene = it.scene;
    let has = |ext: &str| it.files.iter().any(|f| f.ends_with(ext));
    let alt = escape(&crate::render::style::plain_text(&describe::title(scene)));
    let images: String = it
        .files
        .iter()
        .filter_map(|f| {
            let f = escape(f);
            // One picture per figure (PNG, else SVG) and per movie (MP4,
            // else GIF); the other formats as links.
            let picture = f.ends_with(".png")
                || (f.ends_with(".svg") && !has(".png"))
                || (f.ends_with(".gif") && !has(".mp4"));
            if picture {
                Some(format!(
                    "<a href=\"{f}\"><img src=\"{f}\" alt=\"{alt}\"></a>"
                ))
            } else if f.ends_with(".mp4") {
                Some(format!(
                    "<video src=\"{f}\" controls loop muted playsinline title=\"{alt}\"></video>"
                ))
            } else {
                None
            }
        })
        .collect();
    let other: String = it
        .files
        .iter()
        .filter(|f| {
            f.ends_with(".pdf")
                || (f.ends_with(".svg") && has(".png"))
                || (f.ends_with(".gif") && has(".mp4"))
        })
        .map(|f| {
            let ext = f.rsplit('.').next().unwrap_or("").to_uppercase();
            format!(" <a href=\"{0}\">{ext}</a>", escape(f))
        })
        .collect();
    let data: String = it
        .files
        .iter()
        .filter(|f| f.ends_with(".json"))
        .map(|f| format!(" <a href=\"{0}\">data</a>", escape(f)))
        .collect::<String>()
        + &other;
    let caption = scene.caption.as_deref().unwrap_or("");
    format!(
        "<figure id=\"{stem}\">{images}<figcaption><b>{title}.</b> {caption}<br>\
         <small>{params}; model: {fidelity}.{data}</small></figcaption></figure>\n",
        stem = escape(&scene.stem()),
        title = escape(&describe::title(scene)),
        caption = crate::render::style::markup_html(caption),
        params = escape(&describe::parameters(scene)),
        fidelity = scene.fidelity().name(),
    )
}

/// The gallery page for `items`.
pub fn index_html(items: &[Item<'_>]) -> String {
    let mut body = String::new();
    for (heading, kind) in [
        ("Figures", Kind::Figure),
        ("Supplemental movies", Kind::Movie),
        ("Data", Kind::Data),
    ] {
        let of_kind: Vec<&Item<'_>> = items.iter().filter(|i| i.scene.kind() == kind).collect();
        if of_kind.is_empty() {
            continue;
        }
        body.push_str(&format!("<h2>{heading}</h2>\n"));
        for it in of_kind {
            body.push_str(&item(it));
        }
    }
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <title>Topological antiqued mechanical toy: figures and movies</title>\n<style>\
         body{{font-family:'DejaVu Sans',sans-serif;max-width:1400px;margin:auto;padding:1em}}\
         figure{{display:inline-block;vertical-align:top;max-width:100%;margin:1em 0;\
         border-top:1px solid #ccc;padding-top:.5em}}\
         img,video{{max-width:100%;margin-right:.5em;vertical-align:top}}\
         figcaption{{max-width:900px}}</style></head><body>\n\
         <h1>Topological antiqued mechanical toy</h1>\n\
         <p>Figures and supplemental movies of Wada, Mizobata, Ueno and Yoneda, \
         rendered by <code>ladder</code>. Units: s = m = k = 1, τ = sqrt(m/k).</p>\n\
         {body}</body></html>\n"
    )
}
