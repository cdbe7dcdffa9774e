//! Figures at print size (docs/formats.md): the layout rules over the whole
//! catalogue at every style, read from the program's own picture model
//! (`Picture::text_boxes`); and PDFs read by an independent reader,
//! poppler's `pdffonts`, `pdftotext` and `pdfinfo` (Debian: poppler-utils,
//! installed by .ci/run): fonts embedded, every label's words found, the
//! page as wide as the style says, to the point.

use jacobs_ladder::render::{Picture, Style, StyleName, Theme};
use jacobs_ladder::scene::{Kind, OutputSpec, Scene};
use jacobs_ladder::{catalog, scenes, sweep};
use std::path::Path;
use std::process::Command;

/// The picture of a catalogue figure at `style` (a sweep's runs are made
/// once, in `runs`, and drawn at every style).
fn picture(
    scene: &Scene,
    style: &Style,
    runs: &mut Option<(sweep::Plan, Vec<sweep::Record>)>,
) -> Picture {
    let theme = Theme::of(style);
    {
        if let OutputSpec::Sweep(_) = scene.output {
            let (plan, records) = runs.get_or_insert_with(|| {
                let plan = sweep::Plan::new(scene, jacobs_ladder::scene::sweep::DEFAULT_MAX_RUNS)
                    .unwrap()
                    .unwrap();
                let all: Vec<usize> = (0..plan.len()).collect();
                let records = plan.run(&all, &|| {}).unwrap();
                (plan, records)
            });
            // As `sweep::outputs` puts it on the style's page.
            Picture::from(sweep::chart::chart(&theme, plan, records).unwrap().unwrap()).fit_page()
        } else {
            scenes::figure_picture(&theme, scene).unwrap().0
        }
    }
}

/// The runs figure `scene` is sure to make, made now and held (as `ladder
/// all` holds the runs two outputs share, `scenes::shared`) until the
/// value returned is dropped: drawing the figure again, at any style,
/// takes them instead of simulating again (the same runs, bit for bit).
fn held_runs(scene: &Scene) -> jacobs_ladder::scenes::reuse::Held {
    use jacobs_ladder::scenes::{MovieOptions, shared};
    let tally = std::sync::Arc::new(jacobs_ladder::sim::tally::Tally::default());
    let twice = [scene.clone(), scene.clone()];
    shared::prepare(&twice, &MovieOptions::default(), &[tally.clone(), tally]).unwrap()
}

/// Every catalogue figure drawn at every style, as (id, style, picture):
/// made once, by the first test that asks, figures side by side (a sweep's
/// runs made once for all its styles, every other figure's held).
fn catalogue_pictures() -> &'static [(String, StyleName, Picture)] {
    use rayon::prelude::*;
    static ALL: std::sync::OnceLock<Vec<(String, StyleName, Picture)>> = std::sync::OnceLock::new();
    ALL.get_or_init(|| {
        let entries = catalog::entries(Kind::Figure).unwrap();
        let each: Vec<Vec<_>> = entries
            .par_iter()
            .map(|entry| {
                let mut runs = None;
                let _held = held_runs(&entry.scene);
                StyleName::ALL
                    .into_iter()
                    .map(|name| {
                        let pic = picture(&entry.scene, &Style::named(name), &mut runs);
                        (entry.id.clone(), name, pic)
                    })
                    .collect()
            })
            .collect();
        each.into_iter().flatten().collect()
    })
}

/// Figures (id, style) that still break a rule, each with what is left to
/// do. The test fails when another figure breaks a rule, and when one of
/// these no longer does (then take it off the list). Empty: every figure
/// keeps every rule at every style.
const NOT_YET: &[(&str, &str)] = &[];

/// Every catalogue figure at every style: each text box inside the page,
/// no two overlapping, none under 6 pt at a print style, and no page taller
/// than the style allows (9.5 in at paper and paper-wide, the 7.5 in of a
/// slide).
#[test]
fn every_figure_keeps_the_layout_rules_at_every_style() {
    let mut problems = Vec::new();
    let mut broken = std::collections::BTreeSet::new();
    let pictures = catalogue_pictures();
    let figures = catalog::entries(Kind::Figure).unwrap().len();
    assert_eq!(pictures.len(), figures * StyleName::ALL.len());
    for (id, name, pic) in pictures {
        let style = Style::named(*name);
        assert!(
            !pic.text_boxes().is_empty(),
            "figure {id} has no text at all?"
        );
        let found = pic.layout_problems(&style);
        if !found.is_empty() {
            broken.insert((id.clone(), name.name().to_string()));
        }
        if !NOT_YET.contains(&(id.as_str(), name.name())) {
            for p in found {
                problems.push(format!("figure {id} at {}: {p}", name.name()));
            }
        }
    }
    let mended: Vec<_> = NOT_YET
        .iter()
        .filter(|(id, st)| !broken.contains(&(id.to_string(), st.to_string())))
        .collect();
    assert!(
        mended.is_empty(),
        "these now keep every rule; take them off NOT_YET: {mended:?}"
    );
    assert!(
        problems.is_empty(),
        "{} layout problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// The kymograph's time axis: its label "t/τ" is placed from the measured
/// width of its tick labels, so it clears "15000" (it collided before).
#[test]
fn kymograph_time_label_clears_its_tick_labels() {
    let entry = catalog::find(Kind::Figure, "S6")
        .ok()
        .filter(|e| matches!(e.scene.output, OutputSpec::Kymograph));
    let scene = match entry {
        Some(e) => e.scene.clone(),
        None => {
            let mut s = catalog::find(Kind::Figure, "1c").unwrap().scene.clone();
            s.output = OutputSpec::Kymograph;
            s.run.t_end = 15000.0;
            s
        }
    };
    let style = Style::default();
    let pic = scenes::figure_picture(&Theme::of(&style), &scene)
        .unwrap()
        .0;
    let boxes = pic.text_boxes();
    let label = boxes
        .iter()
        .find(|b| b.text.contains("t/τ"))
        .expect("the time axis label");
    let ticks: Vec<_> = boxes
        .iter()
        .filter(|b| b.text.chars().all(|c| c.is_ascii_digit()) && b.text.len() >= 5)
        .collect();
    assert!(!ticks.is_empty(), "5-digit time ticks expected: {boxes:?}");
    for t in ticks {
        assert!(
            !label.overlaps(t, 0.0),
            "\"t/τ\" {:?} overlaps \"{}\" {:?}",
            label.rect,
            t.text,
            t.rect
        );
    }
}

/// Whether poppler's readers are here: a missing one fails `test` under
/// CI and is a listed skip elsewhere (docs/testing.md).
fn poppler(test: &str) -> bool {
    ["pdffonts", "pdfinfo", "pdftotext"]
        .iter()
        .all(|name| crate::common::require::tool(test, name, "-v", "poppler-utils"))
}

fn tool(name: &str) -> Command {
    Command::new(name)
}

fn run(cmd: &mut Command) -> String {
    let out = cmd.output().unwrap();
    assert!(
        out.status.success(),
        "{cmd:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// Text without white space, super- and subscript characters as plain ones
/// (the PDF's text of "ω₊" in a font without ₊ is "ω" and a smaller "+").
fn squeezed(s: &str) -> String {
    const SCRIPTS: [(&str, &str); 30] = [
        ("⁰", "0"),
        ("¹", "1"),
        ("²", "2"),
        ("³", "3"),
        ("⁴", "4"),
        ("⁵", "5"),
        ("⁶", "6"),
        ("⁷", "7"),
        ("⁸", "8"),
        ("⁹", "9"),
        ("⁺", "+"),
        ("⁻", "−"),
        ("ⁿ", "n"),
        ("ᵀ", "T"),
        ("₀", "0"),
        ("₁", "1"),
        ("₂", "2"),
        ("₃", "3"),
        ("₄", "4"),
        ("₅", "5"),
        ("₆", "6"),
        ("₇", "7"),
        ("₈", "8"),
        ("₉", "9"),
        ("₊", "+"),
        ("₋", "−"),
        ("ₙ", "n"),
        ("ₓ", "x"),
        ("ₘ", "m"),
        ("ᵢ", "i"),
    ];
    let mut out: String = s.chars().filter(|c| !c.is_whitespace()).collect();
    for (a, b) in SCRIPTS {
        out = out.replace(a, b);
    }
    out
}

fn ladder(dir: &Path, args: &[&str]) {
    let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .args(["--out", dir.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "ladder {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// `ladder figure ID --style paper --format pdf`: poppler finds the
/// embedded fonts, every text of the picture model and a 243 pt page.
#[test]
fn paper_pdfs_carry_embedded_text_and_the_column_width() {
    if !poppler("print::paper_pdfs_carry_embedded_text_and_the_column_width") {
        return;
    }
    let dir = tempdir("paper-pdf");
    for id in ["barrier", "S5", "edge-mode"] {
        ladder(&dir, &["figure", id, "--style", "paper", "--format", "pdf"]);
        let pdf = dir.join(format!("figure-{id}.pdf"));
        let fonts = run(tool("pdffonts").arg(&pdf));
        let rows: Vec<&str> = fonts.lines().skip(2).collect();
        assert!(!rows.is_empty(), "no font in {pdf:?}:\n{fonts}");
        for r in &rows {
            let cols: Vec<&str> = r.split_whitespace().collect();
            // name type encoding emb sub uni object ID
            let n = cols.len();
            assert!(n >= 7, "{r}");
            assert_eq!(
                &cols[n - 5..n - 2],
                &["yes", "yes", "yes"],
                "emb sub uni: {r}"
            );
            assert!(cols[0].contains("LiberationSerif"), "paper is serif: {r}");
        }
        let info = run(tool("pdfinfo").arg(&pdf));
        let size = info
            .lines()
            .find(|l| l.starts_with("Page size:"))
            .unwrap_or_else(|| panic!("{info}"));
        let w: f64 = size.split_whitespace().nth(2).unwrap().parse().unwrap();
        // 3.375 in × 72 pt/in = 243 pt (APS single column).
        assert!((w - 243.0).abs() < 0.01, "{size}");
        let text = squeezed(&run(tool("pdftotext").arg(&pdf).arg("-")));
        let style = Style::named(StyleName::Paper);
        let scene = catalog::find(Kind::Figure, id).unwrap().scene.clone();
        let pic = picture(&scene, &style, &mut None);
        for b in pic.text_boxes() {
            let want = squeezed(&b.text);
            assert!(
                text.contains(&want),
                "figure {id}: pdftotext lacks \"{}\"; it has:\n{text}",
                b.text
            );
        }
    }
}

/// `--text outlines` keeps today's outlines: no font, no text.
#[test]
fn outlines_leave_no_font() {
    let dir = tempdir("outlines-pdf");
    ladder(
        &dir,
        &[
            "figure", "barrier", "--style", "paper", "--text", "outlines", "--format", "pdf,svg",
        ],
    );
    let pdf = dir.join("figure-barrier.pdf");
    if poppler("print::outlines_leave_no_font") {
        let fonts = run(tool("pdffonts").arg(&pdf));
        assert_eq!(fonts.lines().count(), 2, "{fonts}");
        let text = run(tool("pdftotext").arg(&pdf).arg("-"));
        assert!(text.trim().is_empty(), "{text}");
    }
    let svg = std::fs::read_to_string(dir.join("figure-barrier.svg")).unwrap();
    assert!(!svg.contains("<text"));
    assert!(svg.contains("width=\"324\""), "243 pt = 324 px at 96 px/in");
}

/// SVG at a print style: `<text>` naming the font, page in points.
#[test]
fn paper_svg_has_text_in_the_bundled_serif() {
    let dir = tempdir("paper-svg");
    ladder(
        &dir,
        &["figure", "barrier", "--style", "paper", "--format", "svg"],
    );
    let svg = std::fs::read_to_string(dir.join("figure-barrier.svg")).unwrap();
    assert!(
        svg.contains("width=\"243pt\""),
        "{}",
        &svg[..300.min(svg.len())]
    );
    assert!(svg.contains("<text"));
    assert!(svg.contains("font-family=\"Liberation Serif\""));
}

/// Bad style flags: one line, exit 2.
#[test]
fn bad_style_flags_are_refused() {
    for (flag, value, says) in [
        ("--style", "poster", "paper, paper-wide, slide, screen"),
        ("--width", "3", "unit"),
        ("--font", "comic", "sans, serif"),
        ("--font-size", "1", "between 4 and 72"),
        ("--text", "glyphs", "text, outlines"),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
            .args([
                "figure",
                "barrier",
                flag,
                value,
                "--out",
                "/nonexistent-dir-never",
            ])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{flag} {value}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(err.contains(flag) && err.contains(says), "{flag}: {err}");
    }
}

/// A fresh folder for one test, removed when the test ends.
fn tempdir(name: &str) -> crate::common::tempdir::TempDir {
    crate::common::tempdir::TempDir::new(&format!("print-{name}"))
}

/// A print page is never taller than the style allows, and no figure is
/// printed smaller than its design to get there: at `paper` and
/// `paper-wide` every catalogue figure is at most 4.5 in (324 pt) tall
/// (Fig. 3, four strips of seven ladders, was 645 pt at paper; 4a 682 pt;
/// the pinning sweep 522 pt), exactly the style's width, and drawn at the
/// style's own scale; a slide's Fig. 3 keeps the slide's 7.5 in.
#[test]
fn print_pages_fit_a_journal_page_and_a_slide() {
    let mut checks: Vec<(String, StyleName, f32)> = Vec::new();
    for entry in catalog::entries(Kind::Figure).unwrap() {
        for name in [StyleName::Paper, StyleName::PaperWide] {
            checks.push((entry.id.to_string(), name, 4.5 * 72.0));
        }
    }
    checks.push(("3".into(), StyleName::Slide, 7.5 * 72.0));
    for (id, name, cap) in checks {
        let style = Style::named(name);
        let (_, _, pic) = catalogue_pictures()
            .iter()
            .find(|(i, n, _)| *i == id && *n == name)
            .expect("every figure at every style");
        let pt = style.pt_per_px(pic.width());
        let (w, h) = (pic.width() * pt, pic.height() * pt);
        assert!(h <= cap + 0.5, "figure {id} at {}: {w}×{h} pt", name.name());
        // The page keeps the style's width.
        let want = style.width_pt.unwrap();
        assert!(
            (w - want).abs() < 0.5,
            "figure {id} at {}: {w} pt wide, want {want}",
            name.name()
        );
        // Not printed smaller than designed (text never scaled to fit).
        if let Err(e) = pic.check_print_scale(&style) {
            panic!("figure {id} at {}: {e}", name.name());
        }
    }
}

/// A size that cannot hold a figure at the style's text is refused with
/// exit 2, naming the flag and the smallest size that works; that size is
/// then accepted. (Fig. 3 at `--height 4in` printed every label at about
/// 2.5 pt, with no word on stderr.)
#[test]
fn too_small_a_page_is_refused_naming_the_flag_and_the_size_that_works() {
    let dir = tempdir("refused");
    let ladder = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_ladder"))
            .args(args)
            .arg("--out")
            .arg(&dir)
            .output()
            .unwrap()
    };
    let out = ladder(&[
        "figure", "3", "--style", "paper", "--height", "1.5in", "--format", "pdf",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(
        err.contains("--height 1.50in") && err.contains("smallest"),
        "{err}"
    );
    // "... the smallest height that holds it is --height X.XXin": X works.
    let smallest = err
        .trim()
        .rsplit("--height ")
        .next()
        .unwrap()
        .trim_end_matches("in")
        .to_string();
    let asked: f32 = smallest.parse().unwrap();
    assert!(asked > 1.5 && asked < 4.5, "{err}");
    let ok = ladder(&[
        "figure",
        "3",
        "--style",
        "paper",
        "--height",
        &format!("{smallest}in"),
        "--format",
        "pdf",
    ]);
    assert!(
        ok.status.success(),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
    // Too narrow a page: the width named.
    let out = ladder(&[
        "figure", "3", "--style", "paper", "--width", "1in", "--format", "pdf",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("--width 1.00in") && err.contains("smallest width"),
        "{err}"
    );
}

/// PDF 1.5 (pdflatex's default `\pdfminorversion` includes it without
/// "found PDF version <1.7>, but at most version <1.5> allowed") with an Info
/// dictionary; SVG with `<title>` and `<metadata>`; PNG with text chunks:
/// each names the figure and the program, version and commit.
#[test]
fn figure_files_are_pdf_1_5_and_carry_their_metadata() {
    let dir = tempdir("meta");
    let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args([
            "figure",
            "barrier",
            "--style",
            "paper",
            "--format",
            "pdf,svg,png",
            "--out",
        ])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let made_by = format!("ladder {}", jacobs_ladder::version::LONG);
    let title = {
        let json: serde_json::Value =
            serde_json::from_slice(&std::fs::read(dir.join("figure-barrier.json")).unwrap())
                .unwrap();
        jacobs_ladder::render::style::plain_text(json["title"].as_str().unwrap())
    };
    assert!(!title.is_empty());
    // PDF: the header, and the Info dictionary read back by lopdf.
    let pdf = std::fs::read(dir.join("figure-barrier.pdf")).unwrap();
    assert!(pdf.starts_with(b"%PDF-1.5"), "{:?}", &pdf[..8]);
    let doc = lopdf::Document::load_mem(&pdf).unwrap();
    assert_eq!(doc.version, "1.5");
    let info = doc.trailer.get(b"Info").unwrap().as_reference().unwrap();
    let info = doc.get_dictionary(info).unwrap();
    let text = |key: &[u8]| lopdf::decode_text_string(info.get(key).unwrap()).unwrap();
    assert_eq!(text(b"Title"), title);
    assert_eq!(text(b"Creator"), made_by);
    assert!(made_by.contains(jacobs_ladder::version::VERSION));
    // SVG.
    let svg = std::fs::read_to_string(dir.join("figure-barrier.svg")).unwrap();
    let escaped = title.replace('&', "&amp;").replace('<', "&lt;");
    assert!(
        svg.contains(&format!("<title>{escaped}</title>")),
        "{}",
        &svg[..400.min(svg.len())]
    );
    assert!(svg.contains("<metadata>") && svg.contains(&made_by));
    // PNG: a Software text chunk, and the title (UTF-8: iTXt).
    let png = std::fs::read(dir.join("figure-barrier.png")).unwrap();
    let has = |needle: &[u8]| png.windows(needle.len()).any(|w| w == needle);
    assert!(has(format!("tEXtSoftware\0{made_by}").as_bytes()));
    assert!(has(title.as_bytes()));
}

/// The arrivals chart (Fig. S6): one labelled series per wave of every run,
/// each its own colour, kinks and antikinks each with a fitted line of
/// their colour (solid for a kink, dashed for an antikink) whose slope is
/// the least-squares slope of t_n against n over blocks 2..N−1, computed
/// here; the title names kinks and antikinks when both are drawn.
#[test]
fn arrivals_draw_every_wave_with_its_fitted_line() {
    use jacobs_ladder::render::LineStyle;
    let scene = catalog::find(Kind::Figure, "S6").unwrap().scene.clone();
    let (spec, data) = scenes::arrivals::arrivals_chart(&scene).unwrap();
    let waves: usize = data.iter().map(|d| d.waves.waves.len().max(1)).sum();
    let labelled: Vec<_> = spec.series.iter().filter(|s| s.label.is_some()).collect();
    assert_eq!(labelled.len(), waves, "one labelled series per wave");
    // Each wave its own look: its kind's colour (a kink vermillion, an
    // antikink blue, the palette's roles) and its own marker.
    let mut looks: Vec<_> = labelled
        .iter()
        .map(|s| (s.color, format!("{:?}", s.marker)))
        .collect();
    looks.sort();
    looks.dedup();
    assert_eq!(looks.len(), labelled.len(), "distinct colour and marker");
    use jacobs_ladder::render::{Palette, Role};
    for s in &labelled {
        let kink = s.label.as_ref().unwrap().starts_with("kink");
        let role = if kink { Role::Kink } else { Role::Antikink };
        assert_eq!(s.color, Palette.color(role), "{:?}", s.label);
    }
    let mut fits = 0;
    for pair in spec.series.windows(2) {
        let (marks, line) = (&pair[0], &pair[1]);
        if marks.label.is_none() || line.label.is_some() {
            continue;
        }
        fits += 1;
        assert_eq!(line.color, marks.color);
        let kink = marks.label.as_ref().unwrap().starts_with("kink");
        let want = if kink {
            LineStyle::Solid
        } else {
            LineStyle::Dashed
        };
        assert_eq!(line.line, want, "{:?}", marks.label);
        // Least squares over blocks 3..N−1 (the wave speed c,
        // docs/sweeps.md "The wave speed").
        let n_max = data[0].model.n as f64;
        // The marks are set a little off their block across (so that
        // none hides another): the block is the nearest whole number.
        let pts: Vec<(f64, f64)> = marks
            .points
            .iter()
            .copied()
            .filter(|p| p.0.round() >= 3.0 && p.0.round() <= n_max - 1.0)
            .collect();
        let k = pts.len() as f64;
        let mx = pts.iter().map(|p| p.0).sum::<f64>() / k;
        let my = pts.iter().map(|p| p.1).sum::<f64>() / k;
        let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
        let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
        let slope = sxy / sxx;
        let (a, b) = (line.points[0], line.points[1]);
        let drawn = (b.1 - a.1) / (b.0 - a.0);
        assert!(
            (drawn - slope).abs() < 1e-9 * slope.abs().max(1.0),
            "{drawn} vs {slope}"
        );
        // The line passes through the points' centroid.
        let at = a.1 + (mx - a.0) * drawn;
        assert!((at - my).abs() < 1e-6 * my.abs().max(1.0));
        // And its speed is the one the legend states.
        let v = 1000.0 / slope;
        assert!(
            marks
                .label
                .as_ref()
                .unwrap()
                .contains(&format!("{v:.1} blocks/1000τ"))
        );
    }
    // Every wave that travels has its line; one that stops (the antikink
    // at α = −50°, proved pinned at block 2) has none, and says so.
    let travels = labelled
        .iter()
        .filter(|s| s.label.as_ref().unwrap().contains("blocks/1000τ"))
        .count();
    assert!(
        labelled.iter().any(|s| s
            .label
            .as_ref()
            .unwrap()
            .ends_with("α = −50°: pinned at block 2")),
        "{:?}",
        labelled.iter().map(|s| &s.label).collect::<Vec<_>>()
    );
    assert!(travels >= 4, "{travels} of {waves} waves travel");
    assert_eq!(fits, travels, "every travelling wave has its fitted line");
    let title = spec.title.unwrap();
    assert!(title.contains("kinks and antikinks"), "{title}");
    // A scene of one sign without a title says which wave.
    let mut one = scene.clone();
    one.title = None;
    one.label = None;
    if let jacobs_ladder::scene::OutputSpec::Arrivals { curves } = &mut one.output {
        curves.retain(|c| c.model.alpha.is_some_and(|a| a > 0.0));
    }
    let t = jacobs_ladder::scene::describe::title(&one);
    assert!(t.contains("kink") && !t.contains("antikink"), "{t}");
    let mut both = scene.clone();
    both.title = None;
    let t = jacobs_ladder::scene::describe::title(&both);
    assert!(t.contains("kinks and antikinks"), "{t}");
}

/// A folded movie numbers its columns as filmstrips do: one number per
/// column, the first block of each (1, then a stride further each time),
/// drawn (dark pixels under each number) above every block.
#[test]
fn folded_movies_number_their_columns() {
    use jacobs_ladder::scenes::MovieOptions;
    use jacobs_ladder::scenes::dynamic;
    let mut s = Scene {
        name: "n150".into(),
        ..Default::default()
    };
    s.model.n = 150;
    s.run.t_end = 300.0;
    let opts = MovieOptions {
        frames: 4,
        width: 640,
        height: 480,
        fps: 10.0,
    };
    let numbers = dynamic::movie_column_numbers(&crate::common::screen(), &s, &opts).unwrap();
    assert!(numbers.len() >= 2, "a 150-block ladder folds: {numbers:?}");
    let firsts: Vec<usize> = numbers.iter().map(|(t, _)| t.parse().unwrap()).collect();
    assert_eq!(firsts[0], 1);
    let stride = firsts[1] - firsts[0];
    for w in firsts.windows(2) {
        assert_eq!(w[1] - w[0], stride, "{firsts:?}");
    }
    let frame = dynamic::movie_frame(&crate::common::screen(), &s, &opts, 3).unwrap();
    let (_, blocks) = dynamic::movie_block_pixels(&crate::common::screen(), &s, &opts).unwrap();
    let top_block = blocks[3].iter().map(|p| p.1).fold(f32::MAX, f32::min);
    for (text, (x, y)) in &numbers {
        assert!(
            *y < top_block,
            "number {text} at y = {y} is not above the blocks ({top_block})"
        );
        // Some dark pixel in the text's box (13 px type, a digit ~8 px wide each).
        let half = 4.0 * text.len() as f32;
        let mut dark = 0;
        for py in (*y as u32)..(*y as u32 + 12) {
            for px in ((x - half) as u32)..((x + half) as u32) {
                if let Some(c) = frame.pixel(px, py)
                    && (c.red() as u32 + c.green() as u32 + c.blue() as u32) < 3 * 160
                {
                    dark += 1;
                }
            }
        }
        assert!(dark > 3, "no number {text} drawn at ({x}, {y})");
    }
}

/// Everything the catalogue makes renders at the print styles, a movie's
/// kymograph included (laid out at the page's size, its text at the
/// style's): `ladder all --style paper` once refused movie 5's kymograph
/// as too narrow.
#[test]
fn the_whole_catalogue_renders_at_the_print_styles() {
    for style in ["paper", "paper-wide"] {
        let dir = crate::common::print_render(style);
        assert!(dir.join("movie-5-kymograph.pdf").is_file(), "{style}");
    }
}

/// A one-parameter sweep at `slide` is drawn at the slide's own size,
/// never refused there (docs/formats.md "Two columns on a slide"): the
/// pinning and chain-length sweeps and a plain sweep over α were refused
/// naming 11.01 in and 11.71 in of height, one column of four panels at
/// 20 pt being taller than the 7.5 in page. The front goes left, the
/// other panels are stacked right of it.
#[test]
fn one_parameter_sweeps_at_slide_are_drawn_at_the_slides_size() {
    let dir = tempdir("slide-sweeps");
    let runs: [&[&str]; 3] = [
        &["figure", "pinning", "--style", "slide", "--format", "pdf"],
        &[
            "figure",
            "chain-length",
            "--style",
            "slide",
            "--format",
            "pdf",
        ],
        &[
            "sweep",
            "--alpha=48:68:10",
            "--n",
            "9",
            "--style",
            "slide",
            "--format",
            "pdf",
        ],
    ];
    for args in runs {
        let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
            .args(args)
            .arg("--out")
            .arg(&dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

/// `ladder ARGS` with `--out dir`: the refusal's message on exit 2,
/// `None` when drawn (any other exit fails the test).
fn refusal(dir: &Path, args: &[String]) -> Option<String> {
    let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .args(["--out", dir.to_str().unwrap(), "--format", "svg"])
        .output()
        .unwrap();
    match out.status.code() {
        Some(0) => None,
        Some(2) => Some(String::from_utf8_lossy(&out.stderr).trim().to_string()),
        c => panic!(
            "ladder {args:?}: exit {c:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        ),
    }
}

/// A filmstrip (figures 1c, 3 and 4a) on a page too narrow or too short
/// for its text is refused naming a size of the side that overflows: at
/// that size it is drawn, and a hundredth of an inch less is refused
/// (filmstrips once named the width of the layout drawn at the width
/// asked: `figure 3 --style slide --width 4in` named 13.64 in where 8 in
/// drew, and a width of 23.18 in drew where 23.19 in was named).
#[test]
fn a_filmstrips_refusal_names_a_size_that_draws() {
    let dir = tempdir("filmstrip-refusal");
    let cases: [(&str, &str, &[&str]); 6] = [
        ("1c", "--width", &["--width", "2in"]),
        ("3", "--width", &["--width", "4in"]),
        ("4a", "--width", &["--width", "2in"]),
        ("3", "--height", &["--height", "1in"]),
        ("4a", "--height", &["--height", "1in"]),
        (
            "3",
            "--height",
            &["--width", "23.18in", "--height", "2.96in"],
        ),
    ];
    for (id, side, sizes) in cases {
        let mut args: Vec<String> = ["figure", id, "--style", "slide"]
            .iter()
            .chain(sizes)
            .map(|s| s.to_string())
            .collect();
        let msg = refusal(&dir, &args).unwrap_or_else(|| panic!("{args:?} was drawn"));
        let named = msg
            .rsplit(&format!("{side} "))
            .next()
            .and_then(|v| v.strip_suffix("in"))
            .and_then(|v| v.parse::<f64>().ok())
            .unwrap_or_else(|| panic!("{args:?}: no {side} named: {msg}"));
        let at = match args.iter().position(|a| a == side) {
            Some(i) => i + 1,
            None => {
                args.extend([side.to_string(), String::new()]);
                args.len() - 1
            }
        };
        args[at] = format!("{named:.2}in");
        assert_eq!(refusal(&dir, &args), None, "{args:?}: the size named");
        args[at] = format!("{:.2}in", named - 0.01);
        assert!(
            refusal(&dir, &args).is_some(),
            "{args:?}: a hundredth below the size named is drawn"
        );
    }
}

/// Fig. S3 on a narrow column (`--style paper --width 3.18in`, where its
/// legend goes under the chart on two lines): the chart grows by its
/// legend's band, so that its plot keeps at least 40 % of the figure's
/// height (it was 32 %, the rotated axis label then taller than the plot
/// and over the panel's label), and neither it nor the default column
/// is crowded.
#[test]
fn s3s_plot_keeps_its_share_of_a_narrow_column() {
    let scene = catalog::find(Kind::Figure, "S3").unwrap().scene.clone();
    for width_in in [3.18f32, 3.375] {
        let style = Style {
            width_pt: Some(width_in * 72.0),
            ..Style::named(StyleName::Paper)
        };
        let pic = scenes::figure_picture(&Theme::of(&style), &scene)
            .unwrap()
            .0;
        let plots = pic.plot_boxes();
        assert_eq!(plots.len(), 1, "{width_in} in: {plots:?}");
        let [_, top, _, bottom] = plots[0];
        let share = (bottom - top) / pic.height();
        assert!(
            share >= 0.4,
            "{width_in} in: the plot is {:.0} % of the figure's height",
            100.0 * share
        );
        assert_eq!(pic.crowded(), None, "{width_in} in");
    }
}

/// WCAG 2 contrast of `#rrggbb` on white.
fn contrast_on_white(hex: &str) -> f64 {
    let lin = |i: usize| {
        let c = u8::from_str_radix(&hex[1 + 2 * i..3 + 2 * i], 16).unwrap() as f64 / 255.0;
        if c <= 0.03928 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    };
    let l = 0.2126 * lin(0) + 0.7152 * lin(1) + 0.0722 * lin(2);
    1.05 / (l + 0.05)
}

/// The fills of an SVG's shapes that are not grey (ink, grid, white):
/// the colours of its roles.
fn chromatic_fills(svg: &str) -> std::collections::BTreeSet<String> {
    svg.split("<")
        .filter(|e| !e.starts_with("text"))
        .filter_map(|e| e.split("fill=\"#").nth(1))
        .map(|f| format!("#{}", &f[..6]).to_lowercase())
        .filter(|c| !(c[1..3] == c[3..5] && c[3..5] == c[5..7]))
        .collect()
}

/// One colour per role across the simulated figures (the theme's
/// palette roles): figure 4a marks its kinks and antikinks with the
/// vermillion and blue of figure 3's (it once drew them orange and
/// purple), read from the SVG files drawn; 4a's "kink" and "antikink"
/// words are at least 4.5:1 on white (the orange "kink" was 2.25:1).
#[test]
fn figure_4a_marks_kinks_and_antikinks_in_figure_3s_colours() {
    let dir = tempdir("roles");
    ladder(&dir, &["figure", "3", "--format", "svg"]);
    ladder(&dir, &["figure", "4a", "--format", "svg"]);
    let read = |id: &str| std::fs::read_to_string(dir.join(format!("figure-{id}.svg"))).unwrap();
    let (three, four) = (read("3"), read("4a"));
    let roles: std::collections::BTreeSet<String> = ["#d55e00", "#0072b2"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    assert_eq!(chromatic_fills(&three), roles, "figure 3's role colours");
    assert_eq!(chromatic_fills(&four), roles, "figure 4a's role colours");
    // The words beside 4a's chains, and their colours.
    let words: Vec<(String, String)> = four
        .split("<text")
        .skip(1)
        .filter_map(|t| {
            let fill = t.split("fill=\"").nth(1)?[..7].to_lowercase();
            let word = t.split('>').nth(1)?.split('<').next()?.trim().to_string();
            Some((word, fill))
        })
        .filter(|(w, _)| w == "kink" || w == "antikink")
        .collect();
    for want in ["kink", "antikink"] {
        assert!(words.iter().any(|(w, _)| w == want), "no \"{want}\" in 4a");
    }
    for (word, fill) in &words {
        let c = contrast_on_white(fill);
        assert!(c >= 4.5, "4a's \"{word}\" in {fill}: contrast {c:.2}:1");
        // Its hue is its role's: red over blue for a kink, blue over red
        // for an antikink.
        let (r, b) = (
            u8::from_str_radix(&fill[1..3], 16).unwrap(),
            u8::from_str_radix(&fill[5..7], 16).unwrap(),
        );
        assert_eq!(word == "kink", r > b, "4a's \"{word}\" in {fill}");
    }
}

/// The tank's levels side by side on a slide: panel (b) numbers the rows
/// that (a) names, and the two plots are equally wide and each at least a
/// fifth of the figure (with the level names on both, (b)'s plot was 5 %
/// of it and (a)'s 7 %).
#[test]
fn tank_levels_plots_share_a_slide() {
    let scene = catalog::find(Kind::Figure, "tank-levels")
        .unwrap()
        .scene
        .clone();
    let style = Style::named(StyleName::Slide);
    let pic = scenes::figure_picture(&Theme::of(&style), &scene)
        .unwrap()
        .0;
    let plots = pic.plot_boxes();
    assert_eq!(plots.len(), 2, "{plots:?}");
    let w: Vec<f32> = plots.iter().map(|p| p[2] - p[0]).collect();
    assert!((w[0] - w[1]).abs() <= 0.03 * w[0], "plot widths {w:?}");
    for x in &w {
        assert!(*x >= 0.2 * pic.width(), "plot {x} of {}", pic.width());
    }
    assert!(pic.crowded().is_none());
    let texts: Vec<String> = pic.text_boxes().into_iter().map(|b| b.text).collect();
    for k in 1..=scenes::experiments::LEVELS.len() {
        let n = texts
            .iter()
            .filter(|t| t.starts_with(&format!("{k}")))
            .count();
        assert!(
            n >= 2,
            "level {k} named in (a) and numbered in (b): {texts:?}"
        );
    }
}

/// A filmstrip that draws at one width draws at every wider one, up to
/// the widest slide (docs/formats.md: a refusal names the smallest size
/// that works, so every larger one must work too). Figure 1c at `slide`
/// drew at 4.63–5 in and was refused at 5.5–7.77 in: its plan let a caption
/// line spill into the gap beside its snapshot ("t/τ = 2000" wider than
/// the snapshot) where the grid makes the column as wide as the caption,
/// and it counted "t/τ =" only under the first snapshot, not under the
/// first of every row. Figure 4a at `slide` drew at 9.1 in and was refused
/// at 9.15–9.25 in: a mark whose words missed their side of a snapshot by
/// less than a pixel went to the other side, onto the other mark's words.
/// Every filmstrip of the catalogue at every print style, a twentieth of an
/// inch apart from its smallest width to the widest page (1746 widths),
/// laid out in-process on runs made once per figure.
#[test]
fn a_filmstrip_that_draws_at_one_width_draws_at_every_wider_one() {
    for id in ["1c", "3", "4a", "toy"] {
        // The figure's runs made once and held for every width (as `ladder
        // all` holds the runs two outputs share): what is checked is the
        // layout, which the runs do not depend on.
        let scene = catalog::find(Kind::Figure, id).unwrap().scene.clone();
        let scene = scene.with_auto_window().unwrap();
        let _held = held_runs(&scene);
        for (style, widest) in [
            (StyleName::Slide, 14.0),
            (StyleName::Paper, 7.5),
            (StyleName::PaperWide, 7.5),
        ] {
            // The smallest width: the one a 1 in page's refusal names.
            let smallest = match drawn_at(&scene, style, 1.0) {
                Ok(()) => 1.0,
                Err(msg) => msg
                    .rsplit("--width ")
                    .next()
                    .and_then(|v| v.strip_suffix("in"))
                    .and_then(|v| v.parse::<f64>().ok())
                    .unwrap_or_else(|| panic!("figure {id} at {style:?}: no width named: {msg}")),
            };
            // In hundredths of an inch, so that steps add up exactly.
            let (first, last) = ((smallest * 100.0).round() as u32, (widest * 100.0) as u32);
            let (mut k, mut widths) = (first, 0);
            while k <= last {
                let w = f64::from(k) / 100.0;
                widths += 1;
                if let Err(msg) = drawn_at(&scene, style, w) {
                    panic!(
                        "figure {id} at {style:?}: {smallest:.2} in draws, {w:.2} in is refused: {msg}"
                    );
                }
                k += 5;
            }
            println!("figure {id} at {style:?}: draws at {widths} widths from {smallest:.2} in");
        }
    }
}

/// Whether figure `scene` draws at `style` on a page `w_in` inches wide
/// (the width written in hundredths and read as `--width` reads it), as
/// `ladder figure ID --style S --width W` decides before it writes a file;
/// else the refusal's words. A failure that is not a refusal fails.
fn drawn_at(scene: &Scene, style: StyleName, w_in: f64) -> Result<(), String> {
    use jacobs_ladder::render::page_style::parse_length;
    let spec = jacobs_ladder::render::StyleSpec {
        name: Some(style),
        width: Some(jacobs_ladder::render::Length(
            parse_length(&format!("{w_in:.2}in")).unwrap(),
        )),
        ..Default::default()
    };
    let theme = Theme::of(&spec.over(scene.style).resolve().unwrap());
    let drawn = scenes::figure_picture(&theme, scene)
        .and_then(|(picture, _)| picture.check_print_scale(&theme.style));
    match drawn {
        Ok(()) => Ok(()),
        Err(e) if e.exit_code() == 2 => Err(e.to_string()),
        Err(e) => panic!("{} at {style:?}, {w_in:.2} in: {e}", scene.name),
    }
}

/// Fig. S5 at `paper`: each bottom panel's qb axis (−π to π) reads at two
/// ticks or more, −2, 0 and 2 (it was labelled at 0 alone: asked for two
/// labels, the chart library stepped by 5).
#[test]
fn s5s_qb_axis_reads_at_more_than_zero() {
    let dir = tempdir("s5-qb");
    let args: Vec<String> = ["figure", "S5", "--style", "paper"]
        .map(String::from)
        .to_vec();
    assert_eq!(refusal(&dir, &args), None);
    let svg = std::fs::read_to_string(dir.join("figure-S5.svg")).unwrap();
    // The ω axes run from 0 up: a "−2" is a qb tick, one per bottom panel.
    let minus_two = svg.lines().filter(|l| l.trim() == "−2").count();
    assert!(minus_two >= 2, "{minus_two} qb ticks read −2");
}
