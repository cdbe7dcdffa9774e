//! Every figure of the catalogue as a referee gets it (docs/formats.md,
//! "In an article"): a REVTeX 4.2 `aps,prl` two-column letter that
//! includes each figure at `--style paper` in one column and at
//! `paper-wide` across both, each with the caption its data file
//! records, compiled twice by pdflatex. The log must show no float too
//! large for its page (figure and caption together fit a column), no
//! overfull box and no PDF-version warning, and it must name every
//! figure. The article is kept under target/tmp/revtex-article/ to be
//! looked at page by page.

use crate::common::latex::latex_text;
use crate::common::print_render;
use crate::common::require::require;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Paragraphs of running text between the floats, as in an article.
const TEXT: &str = "The blocks turn one after the other as the wave passes along \
the chain; the front's speed is set by gravity, the springs and the damping. ";

#[test]
fn every_figure_fits_a_revtex_prl_article() {
    let test = "article_revtex::every_figure_fits_a_revtex_prl_article";
    let revtex = Command::new("kpsewhich")
        .arg("revtex4-2.cls")
        .output()
        .is_ok_and(|o| o.status.success() && !o.stdout.is_empty());
    if !require(
        test,
        revtex,
        "REVTeX 4.2 (revtex4-2.cls) is not installed",
        "apt-get install texlive-publishers",
    ) {
        return;
    }
    let paper = figures(print_render("paper"));
    let wide = figures(print_render("paper-wide"));
    let catalogue = jacobs_ladder::catalog::entries(jacobs_ladder::scene::Kind::Figure)
        .unwrap()
        .len();
    assert_eq!(paper.len(), catalogue, "every figure at paper");
    assert_eq!(wide.len(), catalogue, "every figure at paper-wide");
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("revtex-article");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("article.tex"), article(&paper, &wide)).unwrap();
    // Twice, as an author does: floats settle on the second pass.
    for _ in 0..2 {
        let out = Command::new("pdflatex")
            .args(["-interaction=nonstopmode", "-halt-on-error", "article.tex"])
            .current_dir(&dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "pdflatex failed:\n{}",
            String::from_utf8_lossy(&out.stdout)
        );
    }
    let log = std::fs::read_to_string(dir.join("article.log")).unwrap();
    // `floatfix` reports floats it had to flush ("stuck"): the article's
    // text is short for 44 floats; that is the article, not a figure.
    let bad: Vec<&str> = log
        .lines()
        .filter(|l| {
            l.contains("Float too large") || l.contains("Overfull") || l.contains("PDF version")
        })
        .collect();
    assert!(bad.is_empty(), "pdflatex warned:\n{}", bad.join("\n"));
    // pdflatex breaks long log lines at 79 characters: join them first.
    let joined: String = log.lines().collect();
    for f in paper.iter().chain(&wide) {
        let name = f.display().to_string();
        assert!(joined.contains(&format!("<{name}")), "{name} not included");
    }
}

/// The figures' PDFs in `dir`, by name.
fn figures(dir: &Path) -> Vec<PathBuf> {
    let mut pdfs: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| {
            let name = p.file_name().unwrap().to_string_lossy();
            name.starts_with("figure-") && name.ends_with(".pdf")
        })
        .collect();
    pdfs.sort();
    pdfs
}

/// The article: the `paper` figures as column floats, the `paper-wide`
/// ones as page-wide floats, each with its data file's caption.
fn article(paper: &[PathBuf], wide: &[PathBuf]) -> String {
    let mut tex = String::from(
        "\\documentclass[aps,prl,twocolumn,reprint,floatfix]{revtex4-2}\n\
         \\usepackage{graphicx}\n\\begin{document}\n\
         \\title{Every figure at print size}\n\\maketitle\n",
    );
    for (pdfs, env) in [(paper, "figure"), (wide, "figure*")] {
        for pdf in pdfs {
            tex += &TEXT.repeat(6);
            tex += &format!(
                "\n\n\\begin{{{env}}}\\includegraphics{{{}}}\\caption{{{}}}\\end{{{env}}}\n\n",
                pdf.display(),
                latex_text(&caption(pdf))
            );
        }
    }
    tex + "\\end{document}\n"
}

/// The caption the figure's data file records, its formulas written out
/// as the gallery writes them.
fn caption(pdf: &Path) -> String {
    let json = std::fs::read_to_string(pdf.with_extension("json")).unwrap();
    let data: serde_json::Value = serde_json::from_str(&json).unwrap();
    let caption = data["scene"]["caption"]
        .as_str()
        .unwrap_or_else(|| panic!("{} has no caption", pdf.display()));
    jacobs_ladder::theory::formulas::expand(caption)
}
