//! The figures as a physicist prints them (docs/formats.md): at
//! `--style paper` and `paper-wide`, as PDF, included at their natural
//! size in a two-column article with 0.75 in margins and compiled by
//! pdflatex, an independent reader. The log must show no float too large
//! for its page, no overfull box and no PDF-version warning. The pinning
//! chart carries its own caption from the catalogue (each character
//! outside ASCII set as one letter), the longest figure with the longest
//! caption: figure and caption together must fit one column.

use crate::common::ladder_cli;
use crate::common::latex::latex_text;
use crate::common::require::require;
use crate::common::tempdir::TempDir;
use std::process::Command;

/// An article of letter paper, two columns, 0.75 in margins: figures 3,
/// 4a and the pinning chart in one column each (`paper`), figure 3 across
/// both (`paper-wide`, `figure*`), each with a caption and text around.
const ARTICLE: &str = r"\documentclass[twocolumn,10pt]{article}
\usepackage[letterpaper,margin=0.75in]{geometry}
\usepackage{graphicx}
\newcommand\para{The blocks turn one after the other as the wave passes
along the chain; the front's speed is set by gravity, the springs and the
damping.\par}
\newcommand\paras{\para\para\para\para\para\para}
\begin{document}
\paras
\begin{figure}\centering\includegraphics{p/figure-3.pdf}
\caption{Kink and antikink at $\alpha=\pm60^\circ$ and $\pm50^\circ$.}\end{figure}
\paras
\begin{figure}\centering\includegraphics{p/figure-4a.pdf}
\caption{Two flips: a kink and an antikink meet.}\end{figure}
\paras
\begin{figure}\centering\includegraphics{p/figure-pinning.pdf}
\caption{PINNING_CAPTION}\end{figure}
\paras
\begin{figure*}\centering\includegraphics{w/figure-3.pdf}
\caption{Figure 3 across both columns.}\end{figure*}
\paras\paras\paras
\end{document}
";

#[test]
fn the_paper_figures_fit_a_two_column_article() {
    let test = "print_article::the_paper_figures_fit_a_two_column_article";
    let present = Command::new("pdflatex")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !require(
        test,
        present,
        "pdflatex is not installed",
        "apt-get install texlive-latex-base",
    ) {
        return;
    }
    let dir = TempDir::new("article");
    let at = |sub: &str| dir.path().join(sub).to_str().unwrap().to_string();
    for (figure, style, sub) in [
        ("3", "paper", "p"),
        ("4a", "paper", "p"),
        ("pinning", "paper", "p"),
        ("3", "paper-wide", "w"),
    ] {
        let out = ladder_cli(&[
            "figure",
            figure,
            "--style",
            style,
            "--format",
            "pdf",
            "--out",
            &at(sub),
        ]);
        assert!(
            out.status.success(),
            "figure {figure} at {style}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let article = ARTICLE.replace("PINNING_CAPTION", &latex_text(&pinning_caption()));
    std::fs::write(dir.path().join("article.tex"), article).unwrap();
    // Twice, as an author does: floats settle on the second pass.
    for _ in 0..2 {
        let out = Command::new("pdflatex")
            .args(["-interaction=nonstopmode", "-halt-on-error", "article.tex"])
            .current_dir(dir.path())
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "pdflatex failed:\n{}",
            String::from_utf8_lossy(&out.stdout)
        );
    }
    let log = std::fs::read_to_string(dir.path().join("article.log")).unwrap();
    let bad: Vec<&str> = log
        .lines()
        .filter(|l| {
            l.contains("Float too large")
                || l.contains("Overfull")
                || l.contains("PDF version")
                || l.contains("LaTeX Warning")
        })
        .collect();
    assert!(bad.is_empty(), "pdflatex warned:\n{}", bad.join("\n"));
    // Every figure made it into the article (the log names each file it
    // includes).
    for f in [
        "p/figure-3.pdf",
        "p/figure-4a.pdf",
        "p/figure-pinning.pdf",
        "w/figure-3.pdf",
    ] {
        assert!(log.contains(&format!("<{f}")), "{f} not included");
    }
}

/// The pinning figure's caption in the catalogue.
fn pinning_caption() -> String {
    jacobs_ladder::catalog::find(jacobs_ladder::scene::Kind::Figure, "pinning")
        .unwrap()
        .scene
        .caption
        .clone()
        .unwrap_or_default()
}
