//! Italic symbols and upright words in a printed figure, read back from
//! the PDF by an independent reader (lopdf: the page's fonts, their
//! BaseFont and ToUnicode map, and the glyphs the content stream shows in
//! each), not from the program's own picture model: at `--style paper` the
//! symbols (α, t, τ) are shown in Liberation Serif Italic and the words
//! (kink) and digits in the regular face; at the screen style nothing is
//! italic.

use crate::common::{ladder_cli, tempdir::TempDir};
use std::collections::BTreeMap;
use std::path::Path;

/// A page font: its BaseFont and its code → text map.
struct PageFont {
    base: String,
    unicode: BTreeMap<u32, String>,
}

/// The entries of a ToUnicode CMap (`bfchar` pairs and `bfrange`s).
fn to_unicode(cmap: &str) -> BTreeMap<u32, String> {
    let hex = |s: &str| -> Vec<u8> {
        (0..s.len() / 2)
            .filter_map(|i| u8::from_str_radix(&s[2 * i..2 * i + 2], 16).ok())
            .collect()
    };
    let utf16 = |b: &[u8]| {
        let units: Vec<u16> = b
            .chunks(2)
            .map(|c| u16::from_be_bytes([c[0], *c.get(1).unwrap_or(&0)]))
            .collect();
        String::from_utf16_lossy(&units)
    };
    let code = |b: &[u8]| b.iter().fold(0u32, |a, &x| a * 256 + x as u32);
    let mut map = BTreeMap::new();
    let mut section = "";
    let mut tokens: Vec<String> = Vec::new();
    for word in cmap.split_whitespace() {
        match word {
            "beginbfchar" | "beginbfrange" => {
                section = if word == "beginbfchar" {
                    "char"
                } else {
                    "range"
                };
                tokens.clear();
            }
            "endbfchar" | "endbfrange" => section = "",
            w if !section.is_empty() => {
                // Hex strings may hold spaces; a token ends with '>'.
                match tokens.last_mut() {
                    Some(t) if !t.ends_with('>') => t.push_str(w),
                    _ => tokens.push(w.to_string()),
                }
                let n = if section == "char" { 2 } else { 3 };
                if tokens.len() == n && tokens[n - 1].ends_with('>') {
                    let v: Vec<Vec<u8>> = tokens
                        .iter()
                        .map(|t| hex(t.trim_matches(['<', '>'])))
                        .collect();
                    if n == 2 {
                        map.insert(code(&v[0]), utf16(&v[1]));
                    } else {
                        let (lo, hi) = (code(&v[0]), code(&v[1]));
                        let first = utf16(&v[2]);
                        for (k, c) in (lo..=hi).enumerate() {
                            let ch = first
                                .chars()
                                .next()
                                .and_then(|f| char::from_u32(f as u32 + k as u32));
                            map.insert(c, ch.map(String::from).unwrap_or_default());
                        }
                    }
                    tokens.clear();
                }
            }
            _ => {}
        }
    }
    map
}

/// The page's text in content-stream order, each glyph's text with the
/// BaseFont it is shown in.
fn shown_text(path: &Path) -> Vec<(String, String)> {
    let doc = lopdf::Document::load(path).unwrap_or_else(|e| panic!("{path:?}: {e}"));
    let (_, page_id) = doc.get_pages().into_iter().next().expect("one page");
    let deref = |o: &lopdf::Object| match o {
        lopdf::Object::Reference(r) => doc.get_object(*r).unwrap().clone(),
        other => other.clone(),
    };
    let fonts: BTreeMap<Vec<u8>, PageFont> = doc
        .get_page_fonts(page_id)
        .unwrap()
        .into_iter()
        .map(|(name, dict)| {
            let base = String::from_utf8_lossy(dict.get(b"BaseFont").unwrap().as_name().unwrap())
                .into_owned();
            let unicode = dict
                .get(b"ToUnicode")
                .ok()
                .map(|o| match deref(o) {
                    lopdf::Object::Stream(s) => {
                        let bytes = s.decompressed_content().unwrap_or(s.content.clone());
                        to_unicode(&String::from_utf8_lossy(&bytes))
                    }
                    _ => BTreeMap::new(),
                })
                .unwrap_or_default();
            (name, PageFont { base, unicode })
        })
        .collect();
    let content = lopdf::content::Content::decode(&doc.get_page_content(page_id)).unwrap();
    let mut font: Vec<u8> = Vec::new();
    let mut out = Vec::new();
    for op in &content.operations {
        let a = &op.operands;
        match op.operator.as_str() {
            "Tf" => font = a[0].as_name().unwrap_or(b"").to_vec(),
            "Tj" | "TJ" => {
                let bytes = crate::common::pdf::shown_bytes(&a[0]);
                let f = fonts.get(&font).expect("the shown font is a page font");
                for c in bytes.chunks(2) {
                    let code = c.iter().fold(0u32, |a, &x| a * 256 + x as u32);
                    let text = f.unicode.get(&code).cloned().unwrap_or_default();
                    out.push((text, f.base.clone()));
                }
            }
            _ => {}
        }
    }
    out
}

/// Draws `figure ID` at `style` as a PDF and reads its text back.
fn figure_text(id: &str, style: &str) -> Vec<(String, String)> {
    let dir = TempDir::new(&format!("italic-{id}-{style}"));
    let out = ladder_cli(&[
        "figure",
        id,
        "--style",
        style,
        "--format",
        "pdf",
        "--out",
        dir.path().to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    shown_text(&dir.join(format!("figure-{id}.pdf")))
}

/// The fonts `needle`'s glyphs are shown in, wherever the page's text
/// holds it (glyph by glyph, in content order).
fn fonts_of(text: &[(String, String)], needle: &str) -> Vec<Vec<String>> {
    let n = needle.chars().count();
    let mut found = Vec::new();
    for start in 0..text.len() {
        let window = &text[start..(start + n).min(text.len())];
        let s: String = window.iter().map(|(t, _)| t.as_str()).collect();
        if window.len() == n && s == needle {
            found.push(window.iter().map(|(_, f)| f.clone()).collect());
        }
    }
    found
}

#[test]
fn paper_pdf_shows_symbols_in_the_italic_face_and_words_upright() {
    let text = figure_text("3", "paper");
    let italic = |f: &String| f.contains("Italic");
    // Figure 3's panel titles "(a1)  kink α = 60°" and time labels
    // "t/τ = 0".
    let alphas = fonts_of(&text, "α");
    assert!(!alphas.is_empty(), "no α on the page: {text:?}");
    assert!(
        alphas.iter().flatten().all(italic),
        "α in an upright face: {alphas:?}"
    );
    let kinks = fonts_of(&text, "kink");
    assert!(!kinks.is_empty(), "no 'kink' on the page");
    assert!(
        kinks
            .iter()
            .flatten()
            .all(|f| !italic(f) && f.contains("LiberationSerif")),
        "'kink' not in the regular face: {kinks:?}"
    );
    let times = fonts_of(&text, "t/τ");
    assert!(!times.is_empty(), "no 't/τ' on the page");
    for fonts in &times {
        assert!(
            italic(&fonts[0]) && !italic(&fonts[1]) && italic(&fonts[2]),
            "t/τ: {fonts:?}"
        );
    }
    // Panel labels and digits stay upright.
    for label in ["(a1)", "60°"] {
        let found = fonts_of(&text, label);
        assert!(!found.is_empty(), "no {label}");
        assert!(
            found.iter().flatten().all(|f| !italic(f)),
            "{label}: {found:?}"
        );
    }
}

#[test]
fn screen_pdf_has_no_italic_face() {
    let text = figure_text("3", "screen");
    assert!(!fonts_of(&text, "α").is_empty(), "no α on the page");
    assert!(
        text.iter().all(|(_, f)| !f.contains("Italic")),
        "an italic face at the screen style"
    );
}
