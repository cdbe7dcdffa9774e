//! A property test of the print rules (docs/formats.md) over figures the
//! catalogue does not hold: random views (filmstrip, kymograph, arrivals
//! with 1–4 waves, sweeps over one and two axes, theory plots) at every
//! style, at random `--width`/`--height`, drawn by the program as PDFs and
//! read back with an independent reader (lopdf parsing the content stream,
//! not the program's own picture model). For every glyph the printed size
//! is the font size times the scale of its text matrix and of the current
//! transformation (rotated labels as printed), its box is placed from the
//! font's own advance widths.
//!
//! Checked for each figure drawn:
//! - no glyph under 5 pt; every glyph that is not a sub- or superscript (a
//!   run at 0.7 of the run beside it) at least the style's text size at a
//!   journal style (8 pt at `paper`, `paper-wide`), the slide's 20 pt at
//!   `slide` (composed figures once set theirs down to 10 pt there), at
//!   least 11.25 pt at `screen` on a page of the user's;
//! - no two text runs overlap (by more than 0.5 pt each way);
//! - every glyph on the page;
//! - at `paper` and `paper-wide` the page no taller than 4.5 in (324 pt), or
//!   than the `--height` asked;
//! - every two categorical colours on the page (saturated colours, not
//!   tints) at least [`MIN_CVD_DELTA_E`] apart (CIE76 ΔE) under simulated
//!   deuteranopia and protanopia (Machado, Oliveira and Fernandes 2009,
//!   severity 1), where they are apart in normal vision; kymographs and
//!   phase diagrams (colour ramps) are left out of this one.
//!
//! A size the program refuses is a pass when it exits 2 naming the flag and
//! the smallest size that works ("... is --height 2.75in"), a hundredth of
//! an inch less is refused too (it is the smallest), and the size named is
//! then drawn and checked like any other.
//!
//! For charts (every view but the filmstrip) at `paper` and `paper-wide`
//! whose height is the program's (no `--height`), the plot areas, found in
//! the PDF by their axes, span at least half the figure each way
//! ([`MIN_PLOT_FRACTION`]).
//!
//! `LADDER_PROPERTY_SEED` changes the seed (default fixed),
//! `LADDER_PROPERTY_DRAWS` the number of figures (default 48),
//! `LADDER_PROPERTY_BIN` the program tested (default this build's `ladder`;
//! point it at an older build to see the test fail there).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Categorical colours must stay this far apart (CIE76 ΔE) for a dichromat:
/// Okabe–Ito's closest pair (orange, vermillion) keeps 18 under
/// deuteranopia; the old A/B springs (#d62728, #2ca02c) kept 7.
const MIN_CVD_DELTA_E: f64 = 15.0;
/// How far below the style's size a glyph may print, pt: a picture whose
/// design is a pixel wider than the page prints 0.3 % smaller (7.98 pt for
/// 8 pt), invisible; a text scaled to fit is far below (the arrivals
/// title printed at 3.6 pt).
const PRINT_TOLERANCE_PT: f64 = 0.05;
/// The plot area keeps at least this fraction of its figure each way: a
/// legend or a title that takes the room goes elsewhere (the arrivals
/// view's legend once left its plot 30 pt of a 243 pt column).
const MIN_PLOT_FRACTION: f64 = 0.5;
/// A picture may be this much (0.5 %) wider than its page, whole design
/// pixels rounding its size (the program's own slack): 20 pt prints at
/// 19.9 pt then, invisible.
const PRINT_SLACK: f64 = 0.005;
/// Smallest any glyph may print, pt.
const MIN_SCRIPT_PT: f64 = 5.0;

/// xorshift64*: a small, seeded generator (the draws must repeat).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn pick<'a, T>(&mut self, v: &'a [T]) -> &'a T {
        &v[self.below(v.len())]
    }
}

const STYLES: [&str; 4] = ["paper", "paper-wide", "slide", "screen"];

/// One random figure: the command's arguments (without `--out`), the
/// style, whether colours are categorical, and the height asked (pt).
#[derive(Clone, Debug)]
struct Draw {
    args: Vec<String>,
    style: &'static str,
    categorical: bool,
    height_pt: Option<f64>,
    /// A chart (arrivals, kymograph, sweep, theory plot): its plot area is
    /// checked against the page.
    chart: bool,
}

fn draw(rng: &mut Rng, k: usize) -> Draw {
    let style = STYLES[k % STYLES.len()];
    let s = |v: &str| v.to_string();
    let name = format!("p{k}");
    let mut categorical = true;
    let mut chart = true;
    let mut args: Vec<String> = match rng.below(6) {
        // Filmstrip, kymograph or arrivals of the user's own ladder.
        v @ 0..=2 => {
            let view = ["filmstrip", "kymograph", "arrivals"][v];
            categorical = view != "kymograph";
            chart = view != "filmstrip";
            let n = 6 + rng.below(if view == "arrivals" { 25 } else { 9 });
            let sign = if rng.below(2) == 0 { 1.0 } else { -1.0 };
            let alpha = sign * rng.range(52.0, 80.0).round();
            let waves = if view == "filmstrip" {
                1 + rng.below(2)
            } else {
                1 + rng.below(4)
            };
            let flips: Vec<String> = (0..waves).map(|w| format!("{}", w * 1500)).collect();
            let t_end = 1500.0 * waves as f64 + 60.0 * n as f64 + rng.range(500.0, 1500.0);
            vec![
                s("figure"),
                s("--view"),
                s(view),
                format!("--alpha={alpha}"),
                s("--n"),
                format!("{n}"),
                s("--flips"),
                flips.join(","),
                s("--t-end"),
                format!("{}", t_end.round()),
                s("--name"),
                name,
            ]
        }
        // A sweep over α, or over α and b (a phase diagram).
        3 => {
            let two = rng.below(2) == 0;
            categorical = !two;
            let lo = rng.range(40.0, 60.0).round();
            let mut a = vec![
                s("sweep"),
                format!("--alpha={lo}:{}:10", lo + 20.0),
                s("--n"),
                format!("{}", 6 + rng.below(4)),
                s("--name"),
                name,
            ];
            if two {
                a.extend([s("--b"), s("1.2:1.4:0.1")]);
            } else if rng.below(2) == 0 {
                // Both signs: kinks and antikinks folded onto |α|.
                // Four values, none of them 0: ±hi, ±hi/3.
                let hi = lo + 20.0;
                a[1] = format!("--alpha=-{hi}:{hi}:{}", 2.0 * hi / 3.0);
            }
            a
        }
        // A theory plot of the catalogue.
        _ => {
            let id = *rng.pick(&[
                "S5",
                "barrier",
                "edge-mode",
                "winding",
                "2c",
                "S3",
                "2d",
                "S4",
            ]);
            // Schematics of ladders have no axes; figure 2c's chart shares
            // its figure with drawings of ladders (a panel of their own),
            // which the figure-wide measure would count against it.
            chart = !matches!(id, "S4" | "2d" | "2c");
            vec![s("figure"), s(id)]
        }
    };
    args.extend([s("--style"), s(style), s("--format"), s("pdf")]);
    let mut height_pt = None;
    // Half the time a width of the user's, a third of the time a height
    // (at `screen` a height needs a width): journal widths at `paper`
    // and `paper-wide`, a window's or a slide's widths at `screen` and
    // `slide` (docs/formats.md: text never leaves the page nor shrinks).
    let (widths, heights) = match style {
        "slide" => ((3.0, 14.0), (2.0, 8.0)),
        "screen" => ((2.5, 10.0), (2.0, 7.0)),
        _ => ((2.5, 7.5), (1.5, 6.0)),
    };
    let sized = rng.below(2) == 0;
    if sized {
        let w = rng.range(widths.0, widths.1);
        args.extend([s("--width"), format!("{w:.2}in")]);
    }
    if rng.below(3) == 0 && (sized || style != "screen") {
        let h = rng.range(heights.0, heights.1);
        args.extend([s("--height"), format!("{h:.2}in")]);
        height_pt = Some((h * 100.0).round() / 100.0 * 72.0);
    }
    Draw {
        args,
        style,
        categorical,
        height_pt,
        chart,
    }
}

/// The smallest text, pt, other than sub- and superscripts, of a figure
/// drawn with `args` at `style`: the style's size (8 pt at `paper` and
/// `paper-wide`, 20 pt at `slide`, 11.25 pt at `screen` on a page of the
/// user's), never less (docs/formats.md: text never shrinks to fit); at
/// `screen` on its own pixels, the smallest size its design sets (block
/// numbers, 10 px = 7.5 pt).
fn min_text_pt(style: &str, args: &[String]) -> f64 {
    let sized = args.iter().any(|a| a == "--width");
    match style {
        "paper" | "paper-wide" => 8.0,
        "slide" => 20.0,
        _ if sized => 11.25,
        _ => 7.5,
    }
}

fn ladder() -> PathBuf {
    std::env::var_os("LADDER_PROPERTY_BIN")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_BIN_EXE_ladder")))
}

/// A 2-D affine map as PDF writes it, [a b c d e f].
type M = [f64; 6];

fn mul(p: &M, q: &M) -> M {
    // p then q (row vectors: x' = x·p·q).
    [
        p[0] * q[0] + p[1] * q[2],
        p[0] * q[1] + p[1] * q[3],
        p[2] * q[0] + p[3] * q[2],
        p[2] * q[1] + p[3] * q[3],
        p[4] * q[0] + p[5] * q[2] + q[4],
        p[4] * q[1] + p[5] * q[3] + q[5],
    ]
}

fn apply(m: &M, (x, y): (f64, f64)) -> (f64, f64) {
    (x * m[0] + y * m[2] + m[4], x * m[1] + y * m[3] + m[5])
}

/// One glyph as printed: its size (pt), its box on the page, and the text
/// run (BT … ET block) it belongs to.
#[derive(Clone, Debug)]
struct Glyph {
    size: f64,
    rect: [f64; 4],
    run: usize,
}

/// What a page holds: its size, glyphs, and fill and stroke colours.
struct Page {
    width: f64,
    height: f64,
    glyphs: Vec<Glyph>,
    colors: Vec<[u8; 3]>,
    /// Stroked straight lines drawn as a path of one segment (axes, grid
    /// lines, ticks; not the outlines of legend frames or markers), in
    /// page points: (x0, y0, x1, y1).
    lines: Vec<[f64; 4]>,
}

fn num(o: &lopdf::Object) -> f64 {
    match o {
        lopdf::Object::Integer(i) => *i as f64,
        lopdf::Object::Real(r) => *r as f64,
        _ => f64::NAN,
    }
}

/// Advance widths (1/1000 em) by glyph code of a Type 0 font's descendant.
fn widths(doc: &lopdf::Document, font: &lopdf::Dictionary) -> BTreeMap<u32, f64> {
    let mut out = BTreeMap::new();
    let resolve = |o: &lopdf::Object| -> Option<lopdf::Object> {
        match o {
            lopdf::Object::Reference(r) => doc.get_object(*r).ok().cloned(),
            other => Some(other.clone()),
        }
    };
    let Some(desc) = font
        .get(b"DescendantFonts")
        .ok()
        .and_then(&resolve)
        .and_then(|o| o.as_array().ok().cloned())
    else {
        return out;
    };
    let Some(cid) = desc
        .first()
        .and_then(&resolve)
        .and_then(|o| o.as_dict().ok().cloned())
    else {
        return out;
    };
    let Some(w) = cid
        .get(b"W")
        .ok()
        .and_then(&resolve)
        .and_then(|o| o.as_array().ok().cloned())
    else {
        return out;
    };
    let mut i = 0;
    while i < w.len() {
        let first = num(&w[i]) as u32;
        match w.get(i + 1).and_then(&resolve) {
            Some(lopdf::Object::Array(ws)) => {
                for (k, v) in ws.iter().enumerate() {
                    out.insert(first + k as u32, num(v));
                }
                i += 2;
            }
            Some(o) => {
                let last = num(&o) as u32;
                let v = w.get(i + 2).map_or(0.0, num);
                for c in first..=last {
                    out.insert(c, v);
                }
                i += 3;
            }
            None => break,
        }
    }
    out
}

fn read_pdf(path: &Path) -> Page {
    let doc = lopdf::Document::load(path).unwrap_or_else(|e| panic!("{path:?}: {e}"));
    let (_, page_id) = doc.get_pages().into_iter().next().expect("one page");
    let media = doc
        .get_dictionary(page_id)
        .unwrap()
        .get(b"MediaBox")
        .unwrap()
        .as_array()
        .unwrap()
        .iter()
        .map(num)
        .collect::<Vec<_>>();
    let fonts: BTreeMap<Vec<u8>, BTreeMap<u32, f64>> = doc
        .get_page_fonts(page_id)
        .unwrap()
        .into_iter()
        .map(|(name, dict)| (name, widths(&doc, dict)))
        .collect();
    let content = lopdf::content::Content::decode(&doc.get_page_content(page_id)).unwrap();
    let mut ctm: M = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0];
    let mut stack = Vec::new();
    let (mut tm, mut font, mut size, mut run) = (ctm, Vec::new(), 1.0, 0usize);
    let mut glyphs = Vec::new();
    let mut colors = Vec::new();
    let mut lines = Vec::new();
    // The current path's points (page space), and whether it is still one
    // straight segment.
    let mut path: Vec<(f64, f64)> = Vec::new();
    let mut straight = true;
    for op in &content.operations {
        let a = &op.operands;
        match op.operator.as_str() {
            "m" | "l" => {
                if op.operator == "m" && !path.is_empty() {
                    straight = false;
                }
                path.push(apply(&ctm, (num(&a[0]), num(&a[1]))));
            }
            "c" | "v" | "y" | "re" | "h" => straight = false,
            "S" | "s" | "B" | "B*" | "b" | "b*" | "f" | "F" | "f*" | "n" => {
                let stroked = matches!(op.operator.as_str(), "S" | "B" | "B*");
                if stroked && straight && path.len() == 2 {
                    let ((x0, y0), (x1, y1)) = (path[0], path[1]);
                    lines.push([x0, y0, x1, y1]);
                }
                path.clear();
                straight = true;
            }
            "q" => stack.push(ctm),
            "Q" => ctm = stack.pop().unwrap_or(ctm),
            "cm" => {
                let m: Vec<f64> = a.iter().map(num).collect();
                ctm = mul(&[m[0], m[1], m[2], m[3], m[4], m[5]], &ctm);
            }
            "BT" => {
                run += 1;
                tm = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0];
            }
            "Tf" => {
                font = a[0].as_name().unwrap_or(b"").to_vec();
                size = num(&a[1]);
            }
            "Tm" => {
                let m: Vec<f64> = a.iter().map(num).collect();
                tm = [m[0], m[1], m[2], m[3], m[4], m[5]];
            }
            "Tj" | "TJ" => {
                let bytes = crate::common::pdf::shown_bytes(&a[0]);
                let m = mul(&tm, &ctm);
                let scale = (m[0] * m[3] - m[1] * m[2]).abs().sqrt();
                let w = fonts.get(&font);
                let mut pen = 0.0;
                for code in bytes.chunks(2) {
                    let c = if code.len() == 2 {
                        u16::from_be_bytes([code[0], code[1]]) as u32
                    } else {
                        code[0] as u32
                    };
                    let adv = w.and_then(|w| w.get(&c)).copied().unwrap_or(500.0) / 1000.0;
                    // The glyph's box from its advance, 0.2 em below the
                    // baseline to 0.7 em above (the ink of most glyphs).
                    let corners = [(pen, -0.2), (pen + adv, -0.2), (pen, 0.7), (pen + adv, 0.7)]
                        .map(|(x, y)| apply(&m, (x * size, y * size)));
                    let xs = corners.map(|p| p.0);
                    let ys = corners.map(|p| p.1);
                    let min = |v: [f64; 4]| v.iter().copied().fold(f64::INFINITY, f64::min);
                    let max = |v: [f64; 4]| v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                    glyphs.push(Glyph {
                        size: size * scale,
                        rect: [min(xs), min(ys), max(xs), max(ys)],
                        run,
                    });
                    pen += adv;
                }
                tm = [
                    tm[0],
                    tm[1],
                    tm[2],
                    tm[3],
                    tm[4] + pen * size * tm[0],
                    tm[5] + pen * size * tm[1],
                ];
            }
            "rg" | "RG" => {
                let c: Vec<f64> = a.iter().map(num).collect();
                if c.len() == 3 {
                    colors.push([0, 1, 2].map(|k| (c[k] * 255.0).round() as u8));
                }
            }
            _ => {}
        }
    }
    colors.sort();
    colors.dedup();
    Page {
        width: media[2] - media[0],
        height: media[3] - media[1],
        glyphs,
        colors,
        lines,
    }
}

// ---- colour: sRGB → CIELAB, and Machado et al. (2009) dichromacy ----

fn linear(v: u8) -> f64 {
    let v = v as f64 / 255.0;
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

fn lab_of_linear([r, g, b]: [f64; 3]) -> [f64; 3] {
    let (r, g, b) = (r.clamp(0.0, 1.0), g.clamp(0.0, 1.0), b.clamp(0.0, 1.0));
    let x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
    let y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    let z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
    let f = |t: f64| {
        if t > 216.0 / 24389.0 {
            t.cbrt()
        } else {
            (24389.0 / 27.0 * t + 16.0) / 116.0
        }
    };
    [
        116.0 * f(y) - 16.0,
        500.0 * (f(x) - f(y)),
        200.0 * (f(y) - f(z)),
    ]
}

/// Machado 2009, severity 1.0, on linear RGB.
const DEUTAN: [[f64; 3]; 3] = [
    [0.367322, 0.860646, -0.227968],
    [0.280085, 0.672501, 0.047413],
    [-0.011820, 0.042940, 0.968881],
];
const PROTAN: [[f64; 3]; 3] = [
    [0.152286, 1.052583, -0.204868],
    [0.114503, 0.786281, 0.099216],
    [-0.003882, -0.048116, 1.051998],
];

/// Machado 2009, tritanomaly at severity 1.0, on linear RGB.
const TRITAN: [[f64; 3]; 3] = [
    [1.255528, -0.076749, -0.178779],
    [-0.078411, 0.930809, 0.147602],
    [0.004733, 0.691367, 0.303900],
];

/// The outcomes a phase diagram draws side by side (propagated, stalled,
/// pinned, annihilated) keep [`MIN_CVD_DELTA_E`] apart in their fills
/// under simulated deuteranopia, protanopia and tritanopia, every pair
/// (measured: 17.2 for stalled against pinned under tritanopia, 18.3 for
/// stalled against annihilated under deuteranopia; the first palette's
/// stalled and pinned were 12.5 apart under deuteranopia), and each
/// keeps a marker of its own (the second cue, `render::palette`'s test).
/// The random views above leave phase diagrams out (colour ramps), so
/// the palette is checked here.
#[test]
fn the_outcomes_fills_stay_apart_for_dichromats() {
    use jacobs_ladder::render::{OutcomeRole, Role};
    let theme = crate::common::screen();
    let outcomes = [
        OutcomeRole::Propagated,
        OutcomeRole::Stalled,
        OutcomeRole::Pinned,
        OutcomeRole::Annihilated,
    ];
    let mut worst = (f64::INFINITY, String::new());
    for (i, a) in outcomes.iter().enumerate() {
        for b in &outcomes[i + 1..] {
            let (ca, cb) = (
                theme.color(Role::Outcome(*a)),
                theme.color(Role::Outcome(*b)),
            );
            for (name, m) in [
                ("deuteranopia", &DEUTAN),
                ("protanopia", &PROTAN),
                ("tritanopia", &TRITAN),
            ] {
                let e = delta_e(lab(ca, Some(m)), lab(cb, Some(m)));
                if e < worst.0 {
                    worst = (e, format!("{a:?} and {b:?} under {name}"));
                }
            }
        }
    }
    assert!(
        worst.0 >= MIN_CVD_DELTA_E,
        "{} are {:.1} ΔE apart (at least {MIN_CVD_DELTA_E})",
        worst.1,
        worst.0
    );
}

fn lab(c: [u8; 3], sim: Option<&[[f64; 3]; 3]>) -> [f64; 3] {
    let l = c.map(linear);
    let l = match sim {
        None => l,
        Some(m) => [0, 1, 2].map(|i| m[i][0] * l[0] + m[i][1] * l[1] + m[i][2] * l[2]),
    };
    lab_of_linear(l)
}

fn delta_e(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// Categorical colours: saturated (chroma ≥ 30) and neither dark nor a
/// pale tint (25 ≤ L ≤ 80).
fn categorical(colors: &[[u8; 3]]) -> Vec<[u8; 3]> {
    colors
        .iter()
        .copied()
        .filter(|c| {
            let l = lab(*c, None);
            l[1].hypot(l[2]) >= 30.0 && (25.0..=80.0).contains(&l[0])
        })
        .collect()
}

/// Whether two colours are shades of one hue (CIELAB hue angles within
/// 6°): one category, told apart by lightness on purpose (a mark's words
/// in a darker shade of its colour, so that they read on white).
fn shades(a: [u8; 3], b: [u8; 3]) -> bool {
    let (p, q) = (lab(a, None), lab(b, None));
    let d = (p[2].atan2(p[1]) - q[2].atan2(q[1])).to_degrees().abs();
    d.min(360.0 - d) < 6.0
}

/// Everything wrong with one drawn figure.
fn problems(d: &Draw, page: &Page) -> (Vec<String>, f64) {
    let mut out = Vec::new();
    let min_text = min_text_pt(d.style, &d.args);
    let mut smallest = f64::INFINITY;
    // Sizes by run: a run is a script when it is 0.7 of a run beside it.
    let mut run_size: BTreeMap<usize, f64> = BTreeMap::new();
    for g in &page.glyphs {
        run_size.insert(g.run, g.size);
    }
    let is_script = |run: usize, size: f64| {
        [run.wrapping_sub(1), run + 1].iter().any(|r| {
            run_size
                .get(r)
                .is_some_and(|b| (size / b - 0.7).abs() < 0.03)
        })
    };
    let mut off = 0;
    for g in &page.glyphs {
        smallest = smallest.min(g.size);
        if g.size < MIN_SCRIPT_PT - 0.01 {
            out.push(format!(
                "a glyph prints at {:.2} pt (< {MIN_SCRIPT_PT})",
                g.size
            ));
        } else if g.size < min_text * (1.0 - PRINT_SLACK) - PRINT_TOLERANCE_PT
            && !is_script(g.run, g.size)
        {
            out.push(format!("text prints at {:.2} pt (< {min_text})", g.size));
        }
        let r = g.rect;
        if r[0] < -0.5 || r[1] < -0.5 || r[2] > page.width + 0.5 || r[3] > page.height + 0.5 {
            off += 1;
            out.push(format!(
                "a glyph at {r:?} leaves the {}×{} page",
                page.width, page.height
            ));
        }
    }
    if off > 0 {
        out.insert(0, format!("{off} glyphs off the page"));
    }
    // Runs' boxes, pairwise.
    let mut runs: BTreeMap<usize, [f64; 4]> = BTreeMap::new();
    for g in &page.glyphs {
        let b = runs.entry(g.run).or_insert(g.rect);
        *b = [
            b[0].min(g.rect[0]),
            b[1].min(g.rect[1]),
            b[2].max(g.rect[2]),
            b[3].max(g.rect[3]),
        ];
    }
    let boxes: Vec<[f64; 4]> = runs.into_values().collect();
    for i in 0..boxes.len() {
        for j in i + 1..boxes.len() {
            let (a, b) = (boxes[i], boxes[j]);
            let w = a[2].min(b[2]) - a[0].max(b[0]);
            let h = a[3].min(b[3]) - a[1].max(b[1]);
            if w > 0.5 && h > 0.5 {
                out.push(format!("text runs at {a:?} and {b:?} overlap"));
            }
        }
    }
    // A slide is no taller than asked (whole design pixels may round it
    // up by 0.5 %, as the program allows).
    if d.style == "slide" && page.height > 1.005 * d.height_pt.unwrap_or(540.0) + 0.5 {
        out.push(format!("the slide is {:.1} pt tall", page.height));
    }
    if d.style == "paper" || d.style == "paper-wide" {
        let cap = d.height_pt.unwrap_or(324.0);
        if page.height > cap + 0.5 {
            out.push(format!(
                "the page is {:.1} pt tall (> {cap:.1})",
                page.height
            ));
        }
    }
    // The figure grows within the page budget to keep its plots half of
    // it; a --height of the user's leaves it no room to grow (the program
    // honours it and refuses only a height at which text would shrink), so
    // the share is checked where the height is the program's.
    if d.chart && (d.style == "paper" || d.style == "paper-wide") && d.height_pt.is_none() {
        match plot_extent(page) {
            None => out.push("no plot area (no axes) found in a chart".into()),
            Some(((w, h), (fw, fh))) => {
                if w < MIN_PLOT_FRACTION * fw || h < MIN_PLOT_FRACTION * fh {
                    out.push(format!(
                        "the plot area spans {w:.0} × {h:.0} pt of a {fw:.0} × {fh:.0} pt \
                         figure (less than {MIN_PLOT_FRACTION} of it one way)"
                    ));
                }
            }
        }
    }
    if d.categorical {
        let cats = categorical(&page.colors);
        for i in 0..cats.len() {
            for j in i + 1..cats.len() {
                let (a, b) = (cats[i], cats[j]);
                if delta_e(lab(a, None), lab(b, None)) <= 10.0 || shades(a, b) {
                    continue;
                }
                for (name, m) in [("deuteranopia", &DEUTAN), ("protanopia", &PROTAN)] {
                    let e = delta_e(lab(a, Some(m)), lab(b, Some(m)));
                    if e < MIN_CVD_DELTA_E {
                        out.push(format!(
                            "colours {a:?} and {b:?} are {e:.1} ΔE apart under {name}"
                        ));
                    }
                }
            }
        }
    }
    out.dedup();
    (out, smallest)
}

/// The plot areas' extent across and down the figure, pt, and the
/// figure's own extent (its text and lines; a slide centres a figure on a
/// wider page). A plot area is found by its axes: a horizontal and a
/// vertical line (10 pt or more) that meet at an end. Plot areas that
/// share a column (overlap across) count once, by the widest, and those
/// in different columns add up; the same down the rows. `None` when the
/// page has no axes (a schematic of ladders).
fn plot_extent(page: &Page) -> Option<((f64, f64), (f64, f64))> {
    let long = |l: &&[f64; 4], across: bool| {
        let (d_along, d_off) = if across {
            (l[2] - l[0], l[3] - l[1])
        } else {
            (l[3] - l[1], l[2] - l[0])
        };
        d_off.abs() < 0.2 && d_along.abs() >= 10.0
    };
    let ends = |l: &[f64; 4]| [(l[0], l[1]), (l[2], l[3])];
    let near = |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).hypot(a.1 - b.1) < 1.5;
    // Plot rectangles: [x0, y0, x1, y1].
    let mut plots: Vec<[f64; 4]> = Vec::new();
    for h in page.lines.iter().filter(|l| long(l, true)) {
        for v in page.lines.iter().filter(|l| long(l, false)) {
            if ends(h).iter().any(|&a| ends(v).iter().any(|&b| near(a, b))) {
                plots.push([
                    h[0].min(h[2]),
                    v[1].min(v[3]),
                    h[0].max(h[2]),
                    v[1].max(v[3]),
                ]);
            }
        }
    }
    if plots.is_empty() {
        return None;
    }
    // Sum over clusters of overlapping intervals of each cluster's longest.
    let spread = |lo: usize, hi: usize| {
        let mut spans: Vec<(f64, f64)> = plots.iter().map(|p| (p[lo], p[hi])).collect();
        spans.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (mut total, mut end, mut best) = (0.0, f64::NEG_INFINITY, 0.0f64);
        for (a, b) in spans {
            if a >= end {
                total += best;
                best = 0.0;
            }
            best = best.max(b - a);
            end = end.max(b);
        }
        total + best
    };
    let (mut x0, mut y0, mut x1, mut y1) = (
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    );
    let boxes = page
        .glyphs
        .iter()
        .map(|g| g.rect)
        .chain(page.lines.iter().map(|l| {
            [
                l[0].min(l[2]),
                l[1].min(l[3]),
                l[0].max(l[2]),
                l[1].max(l[3]),
            ]
        }));
    for r in boxes {
        (x0, y0, x1, y1) = (x0.min(r[0]), y0.min(r[1]), x1.max(r[2]), y1.max(r[3]));
    }
    Some(((spread(0, 2), spread(1, 3)), (x1 - x0, y1 - y0)))
}

/// Runs `args` into `dir`; the PDF written, or the refusal's message.
fn run(args: &[String], dir: &Path) -> Result<PathBuf, (Option<i32>, String)> {
    let _ = std::fs::remove_dir_all(dir);
    let out = Command::new(ladder())
        .args(args)
        .arg("--out")
        .arg(dir)
        .output()
        .unwrap();
    if !out.status.success() {
        return Err((
            out.status.code(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        ));
    }
    std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .find(|p| p.extension().is_some_and(|x| x == "pdf"))
        .ok_or((Some(0), "no PDF written".into()))
}

/// The size a refusal names ("... the smallest height that holds it is
/// --height 2.75in"): the flag and its value.
fn named_size(message: &str) -> Option<(String, String)> {
    let tail = message.trim().rsplit(" is ").next()?;
    let mut words = tail.split_whitespace();
    let flag = words.next()?.to_string();
    let value = words.next()?.to_string();
    (flag == "--height" || flag == "--width").then_some((flag, value))
}

/// Draws `d` into `dir`: the PDF written, or when the program refuses
/// the size asked, the PDF of the size its refusal names (then `d` says
/// that size). A refusal must be exit 2, one line, naming the flag and
/// the smallest size in inches, a hundredth of an inch less refused too;
/// every way it is not is pushed to `failures`. `None`: nothing to read.
fn draw_following_refusal(
    d: &mut Draw,
    dir: &Path,
    refused: &mut usize,
    failures: &mut Vec<String>,
) -> Option<PathBuf> {
    let msg = match run(&d.args, dir) {
        Ok(p) => return Some(p),
        Err((Some(2), msg)) => msg,
        Err((code, msg)) => {
            failures.push(format!("{:?}: exit {code:?}: {msg}", d.args));
            return None;
        }
    };
    // Refused: one line naming the flag and a size that works.
    *refused += 1;
    // At its own size (no --width or --height of the user's) a figure
    // keeps the page budget: refusing it is a failure.
    let sized = d.args.iter().any(|a| a == "--width" || a == "--height");
    if !sized && d.style != "screen" {
        failures.push(format!("{:?}: refused at its own size: {msg}", d.args));
    }
    let Some((flag, value)) = named_size(&msg) else {
        // Both sizes set and neither alone can grow to hold it: the
        // style's own page must then hold it.
        if msg.contains("give neither --width nor --height") {
            return own_page(d, dir, failures, &msg);
        }
        failures.push(format!("{:?}: refused without a size: {msg}", d.args));
        return None;
    };
    if msg.trim().lines().count() != 1 {
        failures.push(format!("{:?}: refusal is not one line: {msg}", d.args));
    }
    let at = d.args.iter().position(|a| *a == flag);
    let n = d.args.len();
    let set = |args: &mut Vec<String>, v: &str| match at {
        Some(i) => args[i + 1] = v.to_string(),
        None => {
            args.truncate(n);
            args.extend([flag.clone(), v.to_string()]);
        }
    };
    // The size named is the smallest: a hundredth of an inch less is
    // refused too.
    if let Some(v) = value.strip_suffix("in").and_then(|v| v.parse::<f64>().ok()) {
        let mut below = d.args.clone();
        set(&mut below, &format!("{:.2}in", v - 0.01));
        match run(&below, dir) {
            Err((Some(2), _)) => {}
            other => failures.push(format!(
                "{below:?}: a hundredth below the size named ({value}) is not refused: {:?}",
                other.map(|_| "drawn")
            )),
        }
    } else {
        failures.push(format!(
            "{:?}: the size named is not in inches: {msg}",
            d.args
        ));
    }
    let mut args = d.args.clone();
    set(&mut args, &value);
    d.args = args;
    if flag == "--height" {
        d.height_pt = value
            .trim_end_matches("in")
            .parse::<f64>()
            .ok()
            .map(|h| h * 72.0);
    }
    match run(&d.args, dir) {
        Ok(p) => Some(p),
        Err((_, msg)) => {
            failures.push(format!("{:?}: the size named fails too: {msg}", d.args));
            None
        }
    }
}

/// `d` drawn without the user's `--width` and `--height` (which the
/// refusal `msg` told to drop): it must be drawn.
fn own_page(d: &mut Draw, dir: &Path, failures: &mut Vec<String>, msg: &str) -> Option<PathBuf> {
    let mut args = Vec::new();
    let mut it = d.args.iter();
    while let Some(a) = it.next() {
        if a == "--width" || a == "--height" {
            it.next();
        } else {
            args.push(a.clone());
        }
    }
    d.args = args;
    d.height_pt = None;
    match run(&d.args, dir) {
        Ok(p) => Some(p),
        Err((_, again)) => {
            failures.push(format!("{:?}: after \"{msg}\" fails too: {again}", d.args));
            None
        }
    }
}

/// Reads the PDF of `d` and pushes what breaks the rules to `failures`;
/// the smallest glyph, pt.
fn check_drawn(d: &Draw, pdf: &Path, failures: &mut Vec<String>) -> f64 {
    let page = read_pdf(pdf);
    assert!(!page.glyphs.is_empty(), "{:?}: no text read", d.args);
    let (found, small) = problems(d, &page);
    if !found.is_empty() {
        let shown: Vec<_> = found.iter().take(4).cloned().collect();
        failures.push(format!(
            "{} (+{} more) in `ladder {}`",
            shown.join("; "),
            found.len().saturating_sub(4),
            d.args.join(" ")
        ));
    }
    small
}

#[test]
fn random_figures_keep_the_print_rules() {
    let seed: u64 = std::env::var("LADDER_PROPERTY_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0x5eed_1adde5);
    let count: usize = std::env::var("LADDER_PROPERTY_DRAWS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(48);
    let mut rng = Rng(seed | 1);
    let root = std::env::temp_dir().join(format!("ladder-property-{}", std::process::id()));
    let (mut drawn, mut refused, mut smallest) = (0, 0, f64::INFINITY);
    let mut failures = Vec::new();
    let mut failed_figures = 0;
    for k in 0..count {
        let mut d = draw(&mut rng, k);
        let dir = root.join(format!("{k}"));
        let before = failures.len();
        if let Some(pdf) = draw_following_refusal(&mut d, &dir, &mut refused, &mut failures) {
            drawn += 1;
            smallest = smallest.min(check_drawn(&d, &pdf, &mut failures));
        }
        failed_figures += usize::from(failures.len() > before);
    }
    let _ = std::fs::remove_dir_all(&root);
    eprintln!(
        "print property: seed {seed:#x}, {count} figures asked, {drawn} drawn and read \
         ({refused} first refused with a size that works), {failed_figures} break a rule, \
         smallest glyph {smallest:.2} pt"
    );
    assert!(
        drawn >= count * 3 / 4,
        "only {drawn} of {count} figures were drawn"
    );
    assert!(
        failures.is_empty(),
        "{failed_figures} of {count} figures break the print rules:\n{}",
        failures.join("\n")
    );
}

/// The sizes a referee tried at `paper` (docs/formats.md "Text never
/// leaves the page"): S6 at the width its refusal once named (0.51 in,
/// 193 glyphs off a 36.7 pt page) and at a 0.51 in height (the legend
/// overprinted), the energy view 1 in wide (the plot collapsed), the
/// kymograph 0.6 in tall (tick labels overprinted), S5 1.2 in wide
/// (refused as "chart size must be between 60x60 …"). Each is drawn
/// keeping every rule, or refused in one line naming a size that is
/// then drawn keeping every rule.
#[test]
fn the_sizes_a_referee_tried_draw_or_name_one_that_does() {
    let view = |v: &str, flag: &str, size: &str| -> Vec<String> {
        let mut a: Vec<String> = ["figure", "--view", v, "--alpha=60", "--n", "10"]
            .map(String::from)
            .to_vec();
        a.extend(
            [
                "--t-end", "3000", "--name", "v", "--style", "paper", "--format", "pdf",
            ]
            .map(String::from),
        );
        a.extend([flag.to_string(), size.to_string()]);
        a
    };
    let figure = |id: &str, flag: &str, size: &str| -> Vec<String> {
        [
            "figure", id, "--style", "paper", "--format", "pdf", flag, size,
        ]
        .map(String::from)
        .to_vec()
    };
    let cases = [
        figure("S6", "--width", "0.51in"),
        figure("S6", "--height", "0.51in"),
        view("energy", "--width", "1in"),
        view("kymograph", "--height", "0.6in"),
        figure("S5", "--width", "1.2in"),
    ];
    let root = std::env::temp_dir().join(format!("ladder-referee-sizes-{}", std::process::id()));
    let mut failures = Vec::new();
    let mut refused = 0;
    for (k, args) in cases.into_iter().enumerate() {
        let height_pt = args
            .iter()
            .position(|a| a == "--height")
            .and_then(|i| args[i + 1].trim_end_matches("in").parse::<f64>().ok())
            .map(|h| h * 72.0);
        // A kymograph's colours are a ramp, not categories.
        let categorical = !args.iter().any(|a| a == "kymograph");
        let mut d = Draw {
            args,
            style: "paper",
            categorical,
            height_pt,
            chart: false,
        };
        let dir = root.join(k.to_string());
        if let Some(pdf) = draw_following_refusal(&mut d, &dir, &mut refused, &mut failures) {
            check_drawn(&d, &pdf, &mut failures);
        }
    }
    let _ = std::fs::remove_dir_all(&root);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The two figures seed 12345 drew that broke the rules: figure 2d's
/// captions wider than their pictures ran into each other, and a
/// filmstrip's last snapshot put its mark's word past the page's right
/// edge. Columns now hold their captions; a mark whose word would leave
/// its snapshot goes to the chain's other side.
#[test]
fn captions_and_marks_stay_apart_and_on_the_page() {
    let cases: [(&[&str], &str); 2] = [
        (
            &[
                "figure",
                "2d",
                "--style",
                "paper-wide",
                "--format",
                "pdf",
                "--height",
                "1.88in",
            ],
            "paper-wide",
        ),
        (
            &[
                "figure",
                "--view",
                "filmstrip",
                "--alpha=64",
                "--n",
                "6",
                "--flips",
                "0,1500",
                "--t-end",
                "4838",
                "--name",
                "p21",
                "--style",
                "paper-wide",
                "--format",
                "pdf",
                "--width",
                "4.51in",
            ],
            "paper-wide",
        ),
    ];
    let root = std::env::temp_dir().join(format!("ladder-property-12345-{}", std::process::id()));
    for (k, (args, style)) in cases.iter().enumerate() {
        let d = Draw {
            args: args.iter().map(|a| a.to_string()).collect(),
            style,
            categorical: true,
            height_pt: None,
            chart: false,
        };
        let pdf =
            run(&d.args, &root.join(k.to_string())).unwrap_or_else(|e| panic!("{args:?}: {e:?}"));
        let page = read_pdf(&pdf);
        let (found, _) = problems(&d, &page);
        assert!(found.is_empty(), "{args:?}: {found:?}");
    }
    let _ = std::fs::remove_dir_all(&root);
}

/// Figure pinning at `paper-wide` (docs/formats.md "Stacked panels"): its
/// stacked panels share one x extent (panel (a)'s plot once spanned
/// 58.7–386.7 pt and the others 62.4–487.5 pt, so that its 88° read as
/// 77°), and every panel's x axis carries its numbers. Read from the PDF:
/// the long horizontal lines (axes and grid lines, each as wide as its
/// plot) all start and end at one x, and under each panel's x axis (the
/// foot of each y axis, the leftmost long vertical lines) stand at least
/// three tick numbers.
#[test]
fn stacked_panels_share_one_x_extent_and_each_axis_reads() {
    let dir = std::env::temp_dir().join(format!("ladder-pinning-x-{}", std::process::id()));
    let args: Vec<String> = [
        "figure",
        "pinning",
        "--style",
        "paper-wide",
        "--format",
        "pdf",
    ]
    .map(String::from)
    .to_vec();
    let pdf = run(&args, &dir).unwrap_or_else(|e| panic!("{e:?}"));
    let page = read_pdf(&pdf);
    let _ = std::fs::remove_dir_all(&dir);
    let wide: Vec<[f64; 4]> = page
        .lines
        .iter()
        .filter(|l| (l[1] - l[3]).abs() < 0.2 && (l[2] - l[0]).abs() > 0.5 * page.width)
        .map(|l| [l[0].min(l[2]), l[1], l[0].max(l[2]), l[3]])
        .collect();
    assert!(wide.len() >= 8, "{} long horizontal lines", wide.len());
    let (lo, hi) = (wide[0][0], wide[0][2]);
    for l in &wide {
        assert!(
            (l[0] - lo).abs() < 0.6 && (l[2] - hi).abs() < 0.6,
            "a plot spans {:.1}–{:.1} pt, another {lo:.1}–{hi:.1} pt",
            l[0],
            l[2]
        );
    }
    // The y axes: long vertical lines at the plots' left edge.
    let mut axes: Vec<(f64, f64)> = page
        .lines
        .iter()
        .filter(|l| (l[0] - l[2]).abs() < 0.2 && (l[0] - lo).abs() < 0.6)
        .filter(|l| (l[1] - l[3]).abs() > 20.0)
        .map(|l| (l[1].min(l[3]), l[1].max(l[3])))
        .collect();
    axes.sort_by(|a, b| a.0.total_cmp(&b.0));
    axes.dedup_by(|a, b| (a.0 - b.0).abs() < 1.0);
    assert_eq!(axes.len(), 4, "four panels: {axes:?}");
    let mut runs: BTreeMap<usize, [f64; 4]> = BTreeMap::new();
    for g in &page.glyphs {
        let b = runs.entry(g.run).or_insert(g.rect);
        *b = [
            b[0].min(g.rect[0]),
            b[1].min(g.rect[1]),
            b[2].max(g.rect[2]),
            b[3].max(g.rect[3]),
        ];
    }
    for (foot, _) in &axes {
        let under = runs
            .values()
            .filter(|r| r[3] <= foot + 0.5 && r[3] > foot - 14.0)
            .filter(|r| r[0] >= lo - 8.0 && r[2] <= hi + 8.0)
            .count();
        assert!(
            under >= 3,
            "the panel whose x axis is at {foot:.1} pt has {under} numbers under it"
        );
    }
}
