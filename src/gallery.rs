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
    let images: String = it
        .files
        .iter()
        .filter(|f| f.ends_with(".png") || f.ends_with(".gif"))
        .map(|f| {
            format!(
                "<a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\"></a>",
                escape(f),
                escape(&describe::title(scene))
            )
        })
        .collect();
    let data: String = it
        .files
        .iter()
        .filter(|f| f.ends_with(".json"))
        .map(|f| format!(" <a href=\"{0}\">data</a>", escape(f)))
        .collect();
    let caption = scene.caption.as_deref().unwrap_or("");
    format!(
        "<figure id=\"{stem}\">{images}<figcaption><b>{title}.</b> {caption}<br>\
         <small>{params}; model: {fidelity}.{data}</small></figcaption></figure>\n",
        stem = escape(&scene.stem()),
        title = escape(&describe::title(scene)),
        caption = escape(caption),
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
         img{{max-width:100%;margin-right:.5em;vertical-align:top}}\
         figcaption{{max-width:900px}}</style></head><body>\n\
         <h1>Topological antiqued mechanical toy</h1>\n\
         <p>Figures and supplemental movies of Wada, Mizobata, Ueno and Yoneda, \
         rendered by <code>ladder</code>. Units: s = m = k = 1, τ = sqrt(m/k).</p>\n\
         {body}</body></html>\n"
    )
}
