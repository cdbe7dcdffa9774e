//! Text markup: `^{...}` superscripts and `_{...}` subscripts, the runs
//! typeset text is split into, and the text as plain words or HTML.

use super::theme::SCRIPT_SCALE;

/// Where a run of text sits relative to the baseline.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shift {
    /// On the baseline, full size.
    Base,
    /// Raised and smaller: `^{...}` in markup.
    Super,
    /// Lowered and smaller: `_{...}` in markup.
    Sub,
}

impl Shift {
    /// Font size of the run relative to the text's size.
    pub fn scale(self) -> f32 {
        match self {
            Shift::Base => 1.0,
            Shift::Super | Shift::Sub => SCRIPT_SCALE,
        }
    }

    /// How far the run's baseline sits above the text's baseline, in units
    /// of the text's size (negative: below).
    pub fn rise(self) -> f32 {
        match self {
            Shift::Base => 0.0,
            Shift::Super => SUPER_RISE,
            Shift::Sub => -SUB_DROP,
        }
    }
}

/// Rise of a superscript's baseline, in units of the text's size.
pub const SUPER_RISE: f32 = 0.38;
/// Drop of a subscript's baseline, in units of the text's size.
pub const SUB_DROP: f32 = 0.16;

/// A run of typeset text: one baseline shift, one face (italic or
/// upright), and its characters (no markup).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Run {
    /// Where it sits relative to the baseline.
    pub shift: Shift,
    /// Set in the italic face ([`super::italic::italic_chars`]).
    pub italic: bool,
    /// Its text.
    pub text: String,
}

/// The runs of markup text (`^{...}` a superscript, `_{...}` a
/// subscript; anything else, including a `^` or `_` not followed by `{`,
/// literal; an unclosed brace makes the rest literal), for text already
/// free of Unicode script characters.
pub fn markup_runs(text: &str) -> Vec<(Shift, &str)> {
    let mut out = Vec::new();
    let mut rest = text;
    while !rest.is_empty() {
        let next = rest
            .match_indices(['^', '_'])
            .find(|(i, _)| rest[i + 1..].starts_with('{') && rest[i + 2..].contains('}'));
        let Some((i, mark)) = next else {
            out.push((Shift::Base, rest));
            break;
        };
        if i > 0 {
            out.push((Shift::Base, &rest[..i]));
        }
        let body = &rest[i + 2..];
        let close = body.find('}').unwrap_or(body.len());
        let shift = if mark == "^" {
            Shift::Super
        } else {
            Shift::Sub
        };
        if close > 0 {
            out.push((shift, &body[..close]));
        }
        rest = &body[(close + 1).min(body.len())..];
    }
    out
}

/// The text without markup (what a reader would type), e.g. for HTML
/// attributes and searching.
pub fn plain_text(text: &str) -> String {
    markup_runs(text).into_iter().map(|(_, t)| t).collect()
}

/// The text as HTML: markup to `<sup>`/`<sub>`, `&`, `<`, `>` escaped.
pub fn markup_html(text: &str) -> String {
    let esc = |t: &str| {
        t.replace('&', "&amp;")
            .replace('<', "&lt;")
            .replace('>', "&gt;")
    };
    markup_runs(text)
        .into_iter()
        .map(|(shift, t)| match shift {
            Shift::Base => esc(t),
            Shift::Super => format!("<sup>{}</sup>", esc(t)),
            Shift::Sub => format!("<sub>{}</sub>", esc(t)),
        })
        .collect()
}
