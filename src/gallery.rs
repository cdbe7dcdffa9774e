//! `index.html`: every figure and movie of the catalogue with its caption,
//! parameters and the fidelity of the model behind it.

use crate::catalog::{Entry, Output};

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn item(e: &Entry) -> String {
    let images: String = e
        .files()
        .iter()
        .map(|f| {
            format!(
                "<a href=\"{0}\"><img src=\"{0}\" alt=\"{0}\"></a>",
                escape(f)
            )
        })
        .collect();
    format!(
        "<figure id=\"{kind}-{id}\">{images}<figcaption><b>{title}.</b> {caption}<br>\
         <small>{params}</small></figcaption></figure>\n",
        kind = if e.output == Output::Figure {
            "figure"
        } else {
            "movie"
        },
        id = escape(e.id),
        title = escape(e.title),
        caption = escape(e.caption),
        params = escape(&e.parameters()),
    )
}

/// The gallery page for `entries` (files named as `Entry::files`).
pub fn index_html(entries: &[&Entry]) -> String {
    let mut body = String::new();
    for (heading, kind) in [
        ("Figures", Output::Figure),
        ("Supplemental movies", Output::Movie),
    ] {
        body.push_str(&format!("<h2>{heading}</h2>\n"));
        for e in entries.iter().filter(|e| e.output == kind) {
            body.push_str(&item(e));
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
