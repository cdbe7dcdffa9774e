//! Output formats (SPEC section 8): every figure as PNG, SVG and PDF that
//! look alike; PDFs that hold vector drawing and no page-sized raster; MP4s
//! that an independent reader parses and that decode back to the GIF's
//! frames; movie layouts that scale with the frame.
//!
//! `LADDER_FORMATS_DIR=DIR` also writes every file made here to DIR for
//! inspection (`pdftoppm`, a browser, a video player).

mod common;

use common::golden::check;
use jacobs_ladder::catalog;
use jacobs_ladder::encode::{self, Format, Formats, Kind};
use jacobs_ladder::render::Picture;
use jacobs_ladder::scene;
use jacobs_ladder::scenes;
use std::sync::OnceLock;
use tiny_skia::Pixmap;

fn dump(name: &str, bytes: &[u8]) {
    if let Ok(dir) = std::env::var("LADDER_FORMATS_DIR") {
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(format!("{dir}/{name}"), bytes).unwrap();
    }
}

/// Every figure of the catalogue, drawn once (shared by the tests).
fn figures() -> &'static [(String, Picture)] {
    static ALL: OnceLock<Vec<(String, Picture)>> = OnceLock::new();
    ALL.get_or_init(|| {
        let entries = catalog::entries(scene::Kind::Figure).unwrap();
        let all: Vec<(String, Picture)> = entries
            .iter()
            .map(|e| {
                let (p, _) = scenes::figure_picture(&e.scene)
                    .unwrap_or_else(|err| panic!("{}: {err}", e.id));
                (e.scene.stem(), p)
            })
            .collect();
        assert_eq!(all.len(), 13, "every figure of the catalogue");
        all
    })
}

/// Rasterises SVG bytes (text already outlines: no fonts given) onto white.
fn rasterize_svg_file(svg: &[u8], width: u32, height: u32) -> Pixmap {
    let tree = resvg::usvg::Tree::from_data(svg, &resvg::usvg::Options::default()).unwrap();
    let mut p = Pixmap::new(width, height).unwrap();
    p.fill(tiny_skia::Color::WHITE);
    let s = tree.size();
    let t = tiny_skia::Transform::from_scale(width as f32 / s.width(), height as f32 / s.height());
    resvg::render(&tree, t, &mut p.as_mut());
    p
}

/// Mean absolute difference per channel (0–255) and the fraction of pixels
/// where some channel differs by more than `big`.
fn difference(a: &Pixmap, b: &Pixmap, big: u8) -> (f64, f64) {
    assert_eq!((a.width(), a.height()), (b.width(), b.height()));
    let (mut sum, mut bad) = (0u64, 0usize);
    for (p, q) in a.data().chunks_exact(4).zip(b.data().chunks_exact(4)) {
        let d: Vec<u8> = (0..3).map(|k| p[k].abs_diff(q[k])).collect();
        sum += d.iter().map(|&v| v as u64).sum::<u64>();
        if d.iter().any(|&v| v > big) {
            bad += 1;
        }
    }
    let n = (a.width() * a.height()) as f64;
    (sum as f64 / (3.0 * n), bad as f64 / n)
}

#[test]
fn svg_of_every_figure_matches_its_png() {
    for (name, pic) in figures() {
        let png = pic.to_pixmap().unwrap();
        let tree = pic.to_tree(1.0).unwrap();
        let svg = encode::svg_bytes(&tree);
        assert!(
            !String::from_utf8_lossy(&svg).contains("<text"),
            "{name}: SVG text should be outlines"
        );
        dump(&format!("{name}.svg"), &svg);
        dump(&format!("{name}.png"), &encode::png_bytes(&png).unwrap());
        let back = rasterize_svg_file(&svg, png.width(), png.height());
        dump(&format!("{name}-from-svg.png"), &encode::png_bytes(&back).unwrap());
        let (mean, frac) = difference(&png, &back, 64);
        eprintln!("{name}: mean {mean:.3}, {:.3} % of pixels off by > 64", 100.0 * frac);
        assert!(mean < 1.0 && frac < 0.01, "{name}: mean {mean}, fraction {frac}");
    }
}

/// Operators of a PDF content stream, in order.
fn pdf_operators(doc: &lopdf::Document) -> Vec<String> {
    let mut ops = Vec::new();
    for (_, page) in doc.get_pages() {
        let content = doc.get_page_content(page);
        let parsed = lopdf::content::Content::decode(&content).expect("content parses");
        ops.extend(parsed.operations.into_iter().map(|o| o.operator));
    }
    ops
}

#[test]
fn pdf_of_every_figure_is_vector() {
    for (name, pic) in figures() {
        let tree = pic.to_tree(1.0).unwrap();
        let pdf = encode::pdf_bytes(&tree).unwrap();
        dump(&format!("{name}.pdf"), &pdf);
        assert!(pdf.starts_with(b"%PDF-1."), "{name}");
        let doc = lopdf::Document::load_mem(&pdf).unwrap();
        assert_eq!(doc.get_pages().len(), 1, "{name}");
        let ops = pdf_operators(&doc);
        let count = |op: &str| ops.iter().filter(|o| *o == op).count();
        // Paths (m, l, c), fills (f) and strokes (S): the drawing is vector.
        assert!(count("m") > 100 && count("l") > 100, "{name}: too few path operators");
        assert!(count("c") > 100, "{name}: no curves (glyph outlines)");
        assert!(count("f") >= 10 && count("S") >= 10, "{name}: fills {} strokes {}", count("f"), count("S"));
        // No images at all: nothing is drawn as a raster (`Do` paints XObjects).
        assert_eq!(count("Do"), 0, "{name}: draws an XObject");
        assert_eq!(count("BI"), 0, "{name}: has an inline image");
        for (_, obj) in doc.objects.iter() {
            if let Ok(stream) = obj.as_stream() {
                let subtype = stream.dict.get(b"Subtype").and_then(|s| s.as_name()).ok();
                assert!(subtype != Some(b"Image".as_slice()), "{name}: image XObject");
            }
        }
        // The page is the picture's size at 96 px per inch.
        let (_, page) = doc.get_pages().into_iter().next().unwrap();
        let media = doc.get_dictionary(page).unwrap().get(b"MediaBox").unwrap().as_array().unwrap().clone();
        let w = media[2].as_float().unwrap();
        assert!((w - 0.75 * pic.width()).abs() < 0.01, "{name}: width {w}");
    }
}
