//! Typesetting: a label's markup (`^{…}`, `_{…}`, Unicode scripts the
//! font lacks) and its italic symbols split into runs, measured in the
//! style's font, anchored, and wrapped into lines (docs/formats.md
//! "Typeset labels", "Italic symbols").

use super::fonts::{face_of, font_of};
pub use super::italic::{ITALIC_CORRECTION, italic_chars, italic_correction};
pub use super::markup::{Run, SUB_DROP, SUPER_RISE, Shift, markup_html, markup_runs, plain_text};
use super::page_style::FontChoice;
use ab_glyph::{Font, FontRef, PxScale, ScaleFont};

/// Unicode super- and subscript characters and what they are in markup.
const SCRIPT_CHARS: [(char, Shift, char); 30] = [
    ('⁰', Shift::Super, '0'),
    ('¹', Shift::Super, '1'),
    ('²', Shift::Super, '2'),
    ('³', Shift::Super, '3'),
    ('⁴', Shift::Super, '4'),
    ('⁵', Shift::Super, '5'),
    ('⁶', Shift::Super, '6'),
    ('⁷', Shift::Super, '7'),
    ('⁸', Shift::Super, '8'),
    ('⁹', Shift::Super, '9'),
    ('⁺', Shift::Super, '+'),
    ('⁻', Shift::Super, '−'),
    ('ⁿ', Shift::Super, 'n'),
    ('ᵀ', Shift::Super, 'T'),
    ('₀', Shift::Sub, '0'),
    ('₁', Shift::Sub, '1'),
    ('₂', Shift::Sub, '2'),
    ('₃', Shift::Sub, '3'),
    ('₄', Shift::Sub, '4'),
    ('₅', Shift::Sub, '5'),
    ('₆', Shift::Sub, '6'),
    ('₇', Shift::Sub, '7'),
    ('₈', Shift::Sub, '8'),
    ('₉', Shift::Sub, '9'),
    ('₊', Shift::Sub, '+'),
    ('₋', Shift::Sub, '−'),
    ('ₙ', Shift::Sub, 'n'),
    ('ₓ', Shift::Sub, 'x'),
    ('ₘ', Shift::Sub, 'm'),
    ('ᵢ', Shift::Sub, 'i'),
];

/// `text` with each Unicode super- or subscript character that the style's
/// font has no glyph for written as markup (`ω₊` → `ω_{+}`, `10⁻⁴` →
/// `10^{−4}`), so it is typeset as a smaller, shifted run of the same font
/// (Liberation Serif has Greek but no script digits).
pub fn scripts_as_markup(font: FontChoice, text: &str) -> std::borrow::Cow<'_, str> {
    let script = |c: char| SCRIPT_CHARS.iter().find(|(s, _, _)| *s == c);
    let Some(f) = font_of(font) else {
        return text.into();
    };
    let missing = |c: char| script(c).is_some() && f.glyph_id(c).0 == 0;
    if !text.chars().any(missing) {
        return text.into();
    }
    // Once one script character is missing, every one is typeset as markup,
    // so that a run such as ⁻⁴ keeps one size and one baseline.
    let mut out = String::with_capacity(text.len() + 8);
    let mut open: Option<Shift> = None;
    for c in text.chars() {
        let m = script(c);
        match (m, open) {
            (Some(&(_, shift, plain)), Some(o)) if o == shift => out.push(plain),
            (Some(&(_, shift, plain)), _) => {
                if open.is_some() {
                    out.push('}');
                }
                out.push_str(if shift == Shift::Super { "^{" } else { "_{" });
                out.push(plain);
                open = Some(shift);
            }
            (None, _) => {
                if open.take().is_some() {
                    out.push('}');
                }
                out.push(c);
            }
        }
    }
    if open.is_some() {
        out.push('}');
    }
    out.into()
}

/// Horizontal placement of canvas text relative to the anchor point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HAlign {
    Left,
    Center,
    Right,
}

/// Vertical placement: the anchor is the top of the em box, its middle
/// (half the cap height above the baseline), or the baseline.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VAlign {
    Top,
    Middle,
    Baseline,
}

/// Scale for a CSS-like font size (em size in pixels).
pub(super) fn px_scale(font: &FontRef<'_>, size: f32) -> PxScale {
    let upem = font.units_per_em().unwrap_or(2048.0);
    PxScale::from(size * font.height_unscaled() / upem)
}

/// Splits typeset text into runs. Markup: `^{...}` is a superscript and
/// `_{...}` a subscript (e.g. "e^{−κ(n−1)b}", "δθ_{n}"); anything else,
/// including a `^` or `_` not followed by `{`, is literal text. An
/// unclosed brace makes the rest of the text literal.
pub fn runs(font: FontChoice, text: &str) -> Vec<(Shift, String)> {
    let text = scripts_as_markup(font, text);
    markup_runs(&text)
        .into_iter()
        .map(|(s, t)| (s, t.to_string()))
        .collect()
}

/// Splits typeset text into [`Run`]s: the markup of [`runs`], and in the
/// serif (print) font each of those split further where [`italic_chars`]
/// sets symbols in italic. In the sans font every run is upright.
pub fn typeset(font: FontChoice, text: &str) -> Vec<Run> {
    let text = scripts_as_markup(font, text);
    let parts = markup_runs(&text);
    let mask = match font {
        FontChoice::Serif => italic_chars(&parts),
        FontChoice::Sans => parts
            .iter()
            .map(|(_, t)| vec![false; t.chars().count()])
            .collect(),
    };
    let mut out: Vec<Run> = Vec::new();
    for ((shift, t), m) in parts.into_iter().zip(mask) {
        let first = out.len();
        for (c, italic) in t.chars().zip(m) {
            let len = out.len();
            match out.last_mut() {
                Some(r) if len > first && r.italic == italic => r.text.push(c),
                _ => out.push(Run {
                    shift,
                    italic,
                    text: c.to_string(),
                }),
            }
        }
    }
    out
}

/// Width in pixels of plain `text` (no markup) at font size `size`, with
/// kerning.
fn plain_width(font: &FontRef<'_>, text: &str, size: f32) -> f32 {
    let sf = font.as_scaled(px_scale(font, size));
    let mut prev = None;
    let mut w = 0.0;
    for ch in text.chars() {
        let id = sf.glyph_id(ch);
        if let Some(p) = prev {
            w += sf.kern(p, id);
        }
        w += sf.h_advance(id);
        prev = Some(id);
    }
    w
}

/// Width in pixels of typeset `text` (see [`runs`]) at font size `size`.
pub fn text_width(font: FontChoice, text: &str, size: f32) -> f32 {
    let runs = typeset(font, text);
    let mut w = 0.0;
    for (k, run) in runs.iter().enumerate() {
        let Some(f) = face_of(font, run.italic) else {
            return 0.0;
        };
        w += plain_width(f, &run.text, size * run.shift.scale());
        if let Some(next) = runs.get(k + 1) {
            w += italic_correction(run, next) * size;
        }
    }
    w
}

/// The font's ascent at font size `size` (top of the em box to baseline).
pub fn ascent(font: FontChoice, size: f32) -> f32 {
    font_of(font).map_or(0.8 * size, |f| f.as_scaled(px_scale(f, size)).ascent())
}

/// Left end and baseline of text of width `width` anchored at (`x`, `y`)
/// with `align`: shared by every backend so that they place text alike.
pub fn text_origin(
    font: FontChoice,
    (x, y): (f32, f32),
    width: f32,
    size: f32,
    (h, v): (HAlign, VAlign),
) -> (f32, f32) {
    let left = match h {
        HAlign::Left => x,
        HAlign::Center => x - 0.5 * width,
        HAlign::Right => x - width,
    };
    let baseline = match v {
        VAlign::Top => y + ascent(font, size),
        VAlign::Middle => y + 0.36 * size,
        VAlign::Baseline => y,
    };
    (left, baseline)
}

/// Greedy word wrap: the words of `text` (paragraphs split at newlines) in
/// lines at most `width` pixels wide at font `size`. Spaces inside markup
/// braces (`^{...}`) do not break a line.
pub fn wrap_text(font: FontChoice, text: &str, width: f32, size: f32) -> Vec<String> {
    let mut lines = Vec::new();
    for paragraph in text.split('\n') {
        let mut line = String::new();
        for word in words(paragraph) {
            let candidate = if line.is_empty() {
                word.to_string()
            } else {
                format!("{line} {word}")
            };
            if !line.is_empty() && text_width(font, &candidate, size) > width {
                lines.push(std::mem::replace(&mut line, word.to_string()));
            } else {
                line = candidate;
            }
        }
        lines.push(line);
    }
    lines
}

/// Words separated by whitespace outside braces.
fn words(text: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let (mut depth, mut start) = (0i32, None);
    for (i, c) in text.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth = (depth - 1).max(0),
            _ => {}
        }
        if c.is_whitespace() && depth == 0 {
            if let Some(s) = start.take() {
                out.push(&text[s..i]);
            }
        } else if start.is_none() {
            start = Some(i);
        }
    }
    if let Some(s) = start {
        out.push(&text[s..]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::fonts::face_of;

    #[test]
    fn markup_runs_split_scripts() {
        assert_eq!(
            markup_runs("e^{−κ(n−1)b}, κb"),
            vec![
                (Shift::Base, "e"),
                (Shift::Super, "−κ(n−1)b"),
                (Shift::Base, ", κb")
            ]
        );
        assert_eq!(markup_runs("a_b ^x"), vec![(Shift::Base, "a_b ^x")]);
        assert_eq!(
            markup_runs("δθ_{n}"),
            vec![(Shift::Base, "δθ"), (Shift::Sub, "n")]
        );
        assert_eq!(plain_text("10^{−3} s"), "10−3 s");
        assert_eq!(markup_html("x^{2} < y"), "x<sup>2</sup> &lt; y");
        let sans = FontChoice::Sans;
        assert!(text_width(sans, "e^{−κ}", 14.0) < text_width(sans, "e−κ", 14.0));
        assert_eq!(
            wrap_text(sans, "aa e^{−κ n b} bb", 1000.0, 14.0),
            vec!["aa e^{−κ n b} bb"]
        );
        assert_eq!(words(" a^{x y}  b "), vec!["a^{x y}", "b"]);
    }

    #[test]
    fn script_characters_the_font_lacks_become_markup() {
        // DejaVu Sans has ₊ and ⁻: the text stays as it is.
        assert_eq!(scripts_as_markup(FontChoice::Sans, "ω₊, 10⁻⁴"), "ω₊, 10⁻⁴");
        // Liberation Serif (the paper style's font) has neither: the same
        // text as markup.
        let serif = FontChoice::Serif;
        assert_eq!(
            scripts_as_markup(serif, "ω₊(0), 10⁻⁴ s"),
            "ω_{+}(0), 10^{−4} s"
        );
        assert_eq!(
            runs(serif, "ω₊"),
            vec![
                (Shift::Base, "ω".to_string()),
                (Shift::Sub, "+".to_string())
            ]
        );
    }

    #[test]
    fn the_screen_and_slide_font_stays_upright() {
        assert!(
            typeset(FontChoice::Sans, "t/τ = 300 (s)")
                .iter()
                .all(|r| !r.italic)
        );
        assert!(
            typeset(FontChoice::Serif, "t/τ = 300 (s)")
                .iter()
                .any(|r| r.italic)
        );
    }

    #[test]
    fn italic_runs_are_measured_and_drawn_in_the_italic_face() {
        let serif = FontChoice::Serif;
        let (up, it) = (
            face_of(serif, false).unwrap(),
            face_of(serif, true).unwrap(),
        );
        // The two faces differ (an italic α is narrower than an upright one).
        assert_ne!(plain_width(up, "α", 20.0), plain_width(it, "α", 20.0));
        assert_eq!(text_width(serif, "α", 20.0), plain_width(it, "α", 20.0));
        assert_eq!(
            text_width(serif, "kink", 20.0),
            plain_width(up, "kink", 20.0)
        );
        // The italic correction before a closing bar.
        let w = text_width(serif, "|α|", 20.0);
        let parts = plain_width(up, "|", 20.0) * 2.0 + plain_width(it, "α", 20.0);
        assert!(
            (w - parts - ITALIC_CORRECTION * 20.0).abs() < 1e-3,
            "{w} {parts}"
        );
    }
}
