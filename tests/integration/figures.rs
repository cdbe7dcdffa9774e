//! The static figures (`scenes::theory`): every one renders, is not blank
//! and is deterministic; golden images of Fig. 2c and Fig. S5
//! (`LADDER_BLESS=1 cargo test --release --test integration figures::`
//! regenerates them).
//! `LADDER_FIGURE_DIR=DIR` also writes every figure to DIR for inspection.

use crate::common::golden::check;
use jacobs_ladder::catalog;
use jacobs_ladder::encode::png_bytes;
use jacobs_ladder::scene::{Kind, OutputSpec, TheoryFigure, describe};
use jacobs_ladder::scenes::theory::{FigureInput, render as render_with};
use tiny_skia::Pixmap;

/// Every theory figure of the catalogue.
fn all() -> Vec<TheoryFigure> {
    catalog::entries(Kind::Figure)
        .unwrap()
        .into_iter()
        .filter_map(|e| match &e.scene.output {
            OutputSpec::Theory(t) => Some(t.figure),
            _ => None,
        })
        .collect()
}

/// The figure as the catalogue draws it.
fn render(fig: TheoryFigure) -> jacobs_ladder::Result<Pixmap> {
    let entry = catalog::entries(Kind::Figure)
        .unwrap()
        .into_iter()
        .find(|e| matches!(&e.scene.output, OutputSpec::Theory(t) if t.figure == fig))
        .unwrap();
    let OutputSpec::Theory(spec) = &entry.scene.output else {
        unreachable!()
    };
    let input = FigureInput::new(describe::title(&entry.scene), &entry.scene.model, spec);
    render_with(&crate::common::screen(), fig, &input)
}

#[test]
fn every_figure_renders_non_blank_and_deterministic() {
    let dir = std::env::var("LADDER_FIGURE_DIR").ok();
    let figures = all();
    assert_eq!(figures.len(), 9);
    for fig in figures {
        let p = render(fig).unwrap_or_else(|e| panic!("{fig:?}: {e}"));
        let (w, h) = (p.width(), p.height());
        assert!(
            (400..=1200).contains(&w) && (300..=1000).contains(&h),
            "{fig:?}: {w}x{h}"
        );
        let dark = p.pixels().iter().filter(|c| c.red() < 128).count();
        assert!(dark > (w * h) as usize / 200, "{fig:?} is nearly blank");
        let bytes = png_bytes(&p).unwrap();
        let again = png_bytes(&render(fig).unwrap()).unwrap();
        assert!(bytes == again, "{fig:?} is not deterministic");
        if let Some(d) = &dir {
            std::fs::create_dir_all(d).unwrap();
            std::fs::write(format!("{d}/{fig:?}.png"), &bytes).unwrap();
        }
    }
}

#[test]
fn golden_gravity_potential() {
    check(
        "figure-2c",
        &render(TheoryFigure::GravityPotential).unwrap(),
    );
}

#[test]
fn golden_dispersion() {
    check("figure-S5", &render(TheoryFigure::Dispersion).unwrap());
}
