//! The words every figure prints and every caption says, read as a
//! referee reads them: angles in degrees written as a symbol, γ with its
//! unit, angles in legends to one decimal, captions within a column's
//! budget, no caption calling a panel an inset, and no legend over the
//! data. The pictures are the
//! shared render of the catalogue (`common::catalogue_render`, SVG among
//! its formats), the captions the built-in scenes' with their formulas
//! written out, as the data files, the gallery and the article give them.

use std::path::Path;

use jacobs_ladder::catalog;

/// The most words a caption may have: the longest whose figure, at
/// `paper` with the caption under it, still fits one column of a REVTeX
/// `aps,prl` letter with room to spare (the article test,
/// `article_revtex`, fails on a float too large for its page; the
/// longest caption, figure pinning's, is 190 words). docs/formats.md
/// states it.
const CAPTION_WORDS: usize = 200;

/// Every SVG figure of the shared render: (file name, its texts, each
/// with its markup and runs of white space taken out).
fn svg_texts() -> Vec<(String, Vec<String>)> {
    let (dir, _) = crate::common::catalogue_render();
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir).expect("the render's folder") {
        let path = entry.expect("a file of the render").path();
        if path.extension().and_then(|e| e.to_str()) != Some("svg") {
            continue;
        }
        out.push((name(&path), texts(&std::fs::read_to_string(&path).unwrap())));
    }
    assert!(out.len() >= 20, "the render has {} SVG files", out.len());
    out.sort();
    out
}

fn name(path: &Path) -> String {
    path.file_name().unwrap().to_string_lossy().into_owned()
}

/// The contents of every `<text>` element, tags (a `<tspan>`'s) dropped.
fn texts(svg: &str) -> Vec<String> {
    let mut out = Vec::new();
    for piece in svg.split("<text").skip(1) {
        let Some(start) = piece.find('>') else {
            continue;
        };
        let Some(end) = piece.find("</text>") else {
            continue;
        };
        let mut inner = String::new();
        let mut in_tag = false;
        for ch in piece[start + 1..end].chars() {
            match ch {
                '<' => in_tag = true,
                '>' => in_tag = false,
                c if !in_tag => inner.push(c),
                _ => {}
            }
        }
        out.push(inner.split_whitespace().collect::<Vec<_>>().join(" "));
    }
    out
}

/// Every catalogue entry's caption as a reader gets it: (entry, text).
fn captions() -> Vec<(String, String)> {
    catalog::catalogue()
        .unwrap()
        .iter()
        .map(|e| {
            let caption = e.scene.caption.clone().unwrap_or_default();
            (
                format!("{} {}", e.kind().name(), e.id),
                jacobs_ladder::theory::formulas::expand(&caption),
            )
        })
        .collect()
}

/// Angles read "(°)" on every axis and in every legend: 2c, S3 and the
/// barrier once wrote "(degrees)" where the others wrote "(°)". No text
/// spells the unit out.
#[test]
fn angles_are_in_degrees_written_as_a_symbol() {
    let mut found = Vec::new();
    let mut symbols = 0;
    for (file, texts) in svg_texts() {
        for t in texts {
            let lower = t.to_lowercase();
            if lower.contains("degree") || lower.contains("(deg)") {
                found.push(format!("{file}: {t:?}"));
            }
            symbols += usize::from(t.contains("(°)"));
        }
    }
    assert!(found.is_empty(), "the unit spelled out: {found:#?}");
    assert!(symbols >= 5, "only {symbols} texts read (°)");
}

/// γ, the damping, is labelled with its unit wherever an axis names it
/// (the sweeps over γ once read "damping γ" alone): every text that is a
/// label of γ (it starts with "γ" or "damping γ"; a title or a level's
/// name that mentions γ in a sentence is not one) carries "(m/τ)".
#[test]
fn the_damping_carries_its_unit() {
    let mut labels = 0;
    let mut bare = Vec::new();
    for (file, texts) in svg_texts() {
        for t in texts
            .iter()
            .filter(|t| t.starts_with('γ') || t.starts_with("damping γ"))
        {
            if t.contains("γ (m/τ)") {
                labels += 1;
            } else {
                bare.push(format!("{file}: {t:?}"));
            }
        }
    }
    assert!(bare.is_empty(), "γ without its unit: {bare:#?}");
    assert!(labels >= 2, "the γ axes (phase, friction) were not found");
}

/// An angle in a legend or a label is given to one decimal at most (the
/// linkage-friction legend once printed "α = +68.865707785°").
#[test]
fn angles_in_words_have_one_decimal_at_most() {
    let mut long = Vec::new();
    let mut seen = 0;
    for (file, texts) in svg_texts() {
        for t in &texts {
            for piece in t.split('°').take(t.matches('°').count()) {
                let number: String = piece
                    .chars()
                    .rev()
                    .take_while(|c| c.is_ascii_digit() || *c == '.')
                    .collect::<Vec<_>>()
                    .into_iter()
                    .rev()
                    .collect();
                if let Some((_, decimals)) = number.split_once('.') {
                    seen += 1;
                    if decimals.len() > 1 {
                        long.push(format!("{file}: {t:?}"));
                    }
                }
            }
        }
    }
    assert!(
        long.is_empty(),
        "angles with more than one decimal: {long:#?}"
    );
    assert!(seen >= 5, "only {seen} angles with a decimal were read");
}

/// Every caption within [`CAPTION_WORDS`] words (they ran to 372).
#[test]
fn every_caption_fits_a_column() {
    let long: Vec<String> = captions()
        .into_iter()
        .map(|(entry, text)| (entry, text.split_whitespace().count()))
        .filter(|(_, words)| *words > CAPTION_WORDS)
        .map(|(entry, words)| format!("{entry}: {words} words"))
        .collect();
    assert!(
        long.is_empty(),
        "captions over {CAPTION_WORDS} words: {long:#?}"
    );
}

/// No caption says "inset": the program draws no insets (every part of a
/// figure is a panel of its grid, `render::compose`), and figure 2c's
/// caption once called its ladders, a panel beside the chart, an inset.
#[test]
fn no_caption_calls_a_panel_an_inset() {
    let insets: Vec<String> = captions()
        .into_iter()
        .filter(|(_, text)| text.to_lowercase().contains("inset"))
        .map(|(entry, text)| format!("{entry}: {text}"))
        .collect();
    assert!(insets.is_empty(), "{insets:#?}");
}

/// A legend drawn inside a plot covers none of the data: no point of a
/// curve or a marker (drawn before the legend, in its panel) falls inside
/// the legend's box, except a legend's own sample lines, which lie wholly
/// inside it. Every figure of the shared render (screen) and figure
/// winding at every style, where a legend once covered the det C circle.
#[test]
fn no_legend_covers_the_data() {
    let mut covered = Vec::new();
    let (dir, _) = crate::common::catalogue_render();
    let mut files: Vec<(String, String)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().and_then(|e| e.to_str()) == Some("svg"))
        .map(|p| (name(&p), std::fs::read_to_string(&p).unwrap()))
        .collect();
    let tmp = crate::common::tempdir::TempDir::new("legend-cover");
    for style in ["paper", "paper-wide", "screen", "slide"] {
        let out = tmp.join(style);
        let run = crate::common::ladder_cli(&[
            "figure",
            "winding",
            "--style",
            style,
            "--format",
            "svg",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(
            run.status.success(),
            "{}",
            String::from_utf8_lossy(&run.stderr)
        );
        let svg = std::fs::read_to_string(out.join("figure-winding.svg")).unwrap();
        files.push((format!("figure-winding.svg at {style}"), svg));
    }
    let mut legends = 0;
    for (file, svg) in &files {
        let (n, found) = legend_covers(svg);
        legends += n;
        covered.extend(found.into_iter().map(|f| format!("{file}: {f}")));
    }
    assert!(legends >= 4, "only {legends} legend boxes were found");
    assert!(covered.is_empty(), "legends over data: {covered:#?}");
}

/// (legend boxes found, the data points inside one) of one SVG: its
/// elements in order, a panel starting at its white background, a legend
/// box its translucent white rectangle.
fn legend_covers(svg: &str) -> (usize, Vec<String>) {
    let attr = |el: &str, key: &str| -> Option<f64> {
        let at = el.find(&format!(" {key}=\""))? + key.len() + 3;
        el[at..].split('"').next()?.parse().ok()
    };
    let mut points: Vec<Vec<(f64, f64)>> = Vec::new();
    let (mut boxes, mut found) = (0, Vec::new());
    for piece in svg.split('<').skip(1) {
        let el = piece.split('>').next().unwrap_or("");
        if el.starts_with("rect")
            && el.contains("fill=\"#FFFFFF\"")
            && el.contains("stroke=\"none\"")
        {
            let (x, y) = (attr(el, "x").unwrap_or(0.0), attr(el, "y").unwrap_or(0.0));
            let (w, h) = (
                attr(el, "width").unwrap_or(0.0),
                attr(el, "height").unwrap_or(0.0),
            );
            if el.contains("opacity=\"1\"") {
                points.clear(); // a panel's background: a new panel
                continue;
            }
            boxes += 1;
            let inside = |&(px, py): &(f64, f64)| {
                px > x + 1.0 && px < x + w - 1.0 && py > y + 1.0 && py < y + h - 1.0
            };
            for curve in &points {
                if curve.iter().all(inside) {
                    continue; // a legend's own sample
                }
                if let Some(p) = curve.iter().find(|p| inside(p)) {
                    found.push(format!(
                        "({:.0}, {:.0}) under the legend at ({x}, {y})",
                        p.0, p.1
                    ));
                }
            }
        } else if el.starts_with("polyline") {
            let list = el
                .split("points=\"")
                .nth(1)
                .and_then(|s| s.split('"').next());
            let curve = list
                .unwrap_or("")
                .split_whitespace()
                .filter_map(|xy| xy.split_once(','))
                .filter_map(|(a, b)| Some((a.parse().ok()?, b.parse().ok()?)))
                .collect();
            points.push(curve);
        } else if el.starts_with("line") && el.contains("opacity=\"1\"") {
            let ends = ["x1", "y1", "x2", "y2"].map(|k| attr(el, k).unwrap_or(f64::NAN));
            // A marker's stroke (an origin's cross), not a grid or an axis.
            if (ends[2] - ends[0]).hypot(ends[3] - ends[1]) < 20.0 {
                points.push(vec![(ends[0], ends[1]), (ends[2], ends[3])]);
            }
        }
    }
    (boxes, found)
}

/// The check above sees a curve under a legend, and lets a legend's own
/// sample line (wholly inside its box) pass.
#[test]
fn the_legend_check_sees_a_covered_curve() {
    let svg = |curve: &str| {
        format!(
            "<svg><rect x=\"0\" y=\"0\" width=\"300\" height=\"200\" opacity=\"1\" fill=\"#FFFFFF\" \
             stroke=\"none\"/><polyline fill=\"none\" points=\"{curve}\"/><rect x=\"40\" y=\"40\" \
             width=\"100\" height=\"30\" opacity=\"0.9\" fill=\"#FFFFFF\" stroke=\"none\"/></svg>"
        )
    };
    let (boxes, found) = legend_covers(&svg("10,50 90,50 200,50"));
    assert_eq!((boxes, found.len()), (1, 1), "{found:?}");
    let (_, found) = legend_covers(&svg("50,55 80,55"));
    assert!(found.is_empty(), "{found:?}");
    let (_, found) = legend_covers(&svg("10,150 200,150"));
    assert!(found.is_empty(), "{found:?}");
}
