//! Panel labels on the stacked sweep charts: at a print style the pinning
//! chart's four stacked panels carry (a), (b), (c), (d), top to bottom,
//! at the style's text size, each clear of every other text (read from
//! the program's own picture model, `Picture::text_boxes`); the screen
//! names its panels by their titles and draws no letters.

use jacobs_ladder::render::{Picture, Style, StyleName, TextBox, Theme};
use jacobs_ladder::scene::Kind;
use jacobs_ladder::{catalog, sweep};

/// The pinning sweep's chart at `styles`, its runs made once.
fn pinning(styles: &[StyleName]) -> Vec<Picture> {
    let entry = catalog::find(Kind::Figure, "pinning").unwrap();
    let plan = sweep::Plan::new(&entry.scene, jacobs_ladder::scene::sweep::DEFAULT_MAX_RUNS)
        .unwrap()
        .unwrap();
    let all: Vec<usize> = (0..plan.len()).collect();
    let records = plan.run(&all, &|| {}).unwrap();
    styles
        .iter()
        .map(|name| {
            let theme = Theme::of(&Style::named(*name));
            Picture::from(
                sweep::chart::chart(&theme, &plan, &records)
                    .unwrap()
                    .unwrap(),
            )
            .fit_page()
        })
        .collect()
}

fn is_label(b: &TextBox) -> bool {
    let t = b.text.trim();
    t.len() == 3 && t.starts_with('(') && t.ends_with(')')
}

/// What is wrong with the panel labels among `boxes` (empty: nothing):
/// the four letters in order top to bottom, each at least `min_px` in
/// size, none overlapping another text.
fn label_problems(boxes: &[TextBox], min_px: f32) -> Vec<String> {
    let mut out = Vec::new();
    let labels: Vec<&TextBox> = boxes.iter().filter(|b| is_label(b)).collect();
    let names: Vec<&str> = labels.iter().map(|b| b.text.trim()).collect();
    if names != ["(a)", "(b)", "(c)", "(d)"] {
        out.push(format!("labels {names:?}, not (a) to (d)"));
    }
    if labels.windows(2).any(|w| w[0].rect[1] >= w[1].rect[1]) {
        out.push("labels not in order top to bottom".into());
    }
    for l in &labels {
        if l.size < min_px - 0.01 {
            out.push(format!("{} at {} px, under {min_px}", l.text, l.size));
        }
        for b in boxes {
            if !std::ptr::eq(*l, b) && l.overlaps(b, 0.0) {
                out.push(format!(
                    "{} {:?} overlaps \"{}\" {:?}",
                    l.text, l.rect, b.text, b.rect
                ));
            }
        }
    }
    out
}

#[test]
fn pinning_chart_at_paper_labels_its_four_panels_clear_of_every_text() {
    let [paper, wide, screen] = <[Picture; 3]>::try_from(pinning(&[
        StyleName::Paper,
        StyleName::PaperWide,
        StyleName::Screen,
    ]))
    .ok()
    .unwrap();
    for (name, pic) in [(StyleName::Paper, &paper), (StyleName::PaperWide, &wide)] {
        let style = Style::named(name);
        let theme = Theme::of(&style);
        let boxes = pic.text_boxes();
        // The style's text size: 8 pt at paper.
        let problems = label_problems(&boxes, style.font_pt * theme.px_per_pt);
        assert!(problems.is_empty(), "{}: {problems:?}", name.name());
        assert!(
            pic.layout_problems(&style).is_empty(),
            "{:?}",
            pic.layout_problems(&style)
        );
    }
    // The screen names its panels by title and axis: no letters.
    assert!(!screen.text_boxes().iter().any(is_label));

    // The check itself: it fails with a label removed, and with one moved
    // onto a tick label.
    let boxes = paper.text_boxes();
    let min = 8.0 * Theme::of(&Style::named(StyleName::Paper)).px_per_pt;
    let removed: Vec<TextBox> = boxes.iter().filter(|b| b.text != "(c)").cloned().collect();
    assert!(!label_problems(&removed, min).is_empty());
    let tick = boxes
        .iter()
        .find(|b| b.text == "10")
        .expect("the front panel's top tick label")
        .rect;
    let moved: Vec<TextBox> = boxes
        .iter()
        .map(|b| {
            let mut b = b.clone();
            if b.text == "(a)" {
                let (w, h) = (b.rect[2] - b.rect[0], b.rect[3] - b.rect[1]);
                b.rect = [tick[0], tick[1], tick[0] + w, tick[1] + h];
            }
            b
        })
        .collect();
    assert!(!label_problems(&moved, min).is_empty());
}
