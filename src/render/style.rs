//! Shared style: the bundled font, colours, sizes, and text on tiny-skia
//! canvases.
//!
//! Two bundled fonts (`assets/fonts/`): DejaVu Sans (screen and slides) and
//! Liberation Serif (print). The figure's theme names one
//! ([`super::Theme::font`]), passed to every text function here, and it is used everywhere: plotters lays chart text out with
//! it, resvg rasterises chart SVGs with it, and canvas text (labels on
//! snapshots and panels) is rasterised from its outlines with `ab_glyph`,
//! which is fast enough for a time label on every movie frame.

use super::page_style::FontChoice;
pub use super::theme::SCRIPT_SCALE;
use super::theme::palette;
pub use super::theme::size;
use crate::encode::Rgb;
use ab_glyph::{Font, FontRef, PxScale, ScaleFont, point};
use std::sync::{Arc, Once, OnceLock};
use tiny_skia::{Color, Pixmap};

/// The bundled sans-serif font file.
pub const FONT_BYTES: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");
/// Its family name (as in the file; SVG text uses it).
pub const FONT_FAMILY: &str = "DejaVu Sans";
/// The bundled serif font file (SIL Open Font License 1.1).
pub const SERIF_BYTES: &[u8] = include_bytes!("../../assets/fonts/LiberationSerif-Regular.ttf");
/// Its family name (as in the file).
pub const SERIF_FAMILY: &str = "Liberation Serif";
/// The italic face of the serif font (same family and licence), for the
/// italic runs of print text ([`italic_chars`]).
pub const SERIF_ITALIC_BYTES: &[u8] =
    include_bytes!("../../assets/fonts/LiberationSerif-Italic.ttf");

/// The family name of `font`.
pub fn family_of(font: FontChoice) -> &'static str {
    match font {
        FontChoice::Sans => FONT_FAMILY,
        FontChoice::Serif => SERIF_FAMILY,
    }
}

/// The bytes of `font`'s file.
pub fn font_bytes(font: FontChoice) -> &'static [u8] {
    match font {
        FontChoice::Sans => FONT_BYTES,
        FontChoice::Serif => SERIF_BYTES,
    }
}

// The colours below are names the drawing code has used; every one is a
// colour of the theme's one palette ([`super::theme::palette`]).

/// Dark grey: blocks, text, axes, the clamp of block 1.
pub const DARK: Rgb = palette::INK;
/// Vermillion: A springs and the A end of each block; ω₊ curves.
pub const RED: Rgb = palette::VERMILLION;
/// Blue: B springs (dashed) and the B end of each block; ω− curves.
pub const BLUE: Rgb = palette::BLUE;
/// Bluish green.
pub const GREEN: Rgb = palette::BLUISH_GREEN;
/// Negative end of the kymograph's diverging map (sin θ = −1).
pub const KYMO_NEG: Rgb = crate::encode::PALETTE_ANCHORS[4];
/// Positive end of the kymograph's diverging map (sin θ = +1).
pub const KYMO_POS: Rgb = crate::encode::PALETTE_ANCHORS[5];
/// Grey: the ground state drawn underneath a deformed state.
pub const GREY: Rgb = palette::GREY;
/// Background.
pub const WHITE: Rgb = crate::encode::WHITE;
/// The palette's colours after ink, vermillion, blue and bluish green:
/// orange, reddish purple, sky blue (then the first ones again).
pub const SERIES_EXTRA: [Rgb; 6] = [
    palette::ORANGE,
    palette::REDDISH_PURPLE,
    palette::SKY_BLUE,
    palette::BLUISH_GREEN,
    palette::VERMILLION,
    palette::BLUE,
];

/// Okabe & Ito's colour-blind-safe qualitative palette, for chart series
/// ([`palette::SERIES`]).
pub const OKABE_ITO: [Rgb; 7] = palette::SERIES;

/// The `i`-th chart series colour, from [`OKABE_ITO`]; series should also
/// differ by dash or marker (the palette repeats after seven).
pub fn series_color(i: usize) -> Rgb {
    OKABE_ITO[i % OKABE_ITO.len()]
}

/// A tiny-skia colour from an [`Rgb`], fully opaque.
pub fn color(c: Rgb) -> Color {
    Color::from_rgba8(c[0], c[1], c[2], 255)
}

/// `#rrggbb` for SVG.
pub fn hex(c: Rgb) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

/// Linear blend from `a` (f = 0) to `b` (f = 1).
pub fn mix(a: Rgb, b: Rgb, f: f64) -> Rgb {
    let f = f.clamp(0.0, 1.0);
    [0, 1, 2].map(|k| (a[k] as f64 + (b[k] as f64 - a[k] as f64) * f).round() as u8)
}

/// The kymograph's diverging map: −1 → [`KYMO_NEG`], 0 → white, +1 →
/// [`KYMO_POS`], linear in between (so every colour lies on a GIF palette
/// ramp). NaN maps to grey.
pub fn diverging(v: f64) -> Rgb {
    if v.is_nan() {
        GREY
    } else if v < 0.0 {
        mix(WHITE, KYMO_NEG, -v)
    } else {
        mix(WHITE, KYMO_POS, v)
    }
}

/// The font database for resvg: the bundled fonts only, loaded once.
pub fn fontdb() -> Arc<resvg::usvg::fontdb::Database> {
    static DB: OnceLock<Arc<resvg::usvg::fontdb::Database>> = OnceLock::new();
    DB.get_or_init(|| {
        let mut db = resvg::usvg::fontdb::Database::new();
        db.load_font_data(FONT_BYTES.to_vec());
        db.load_font_data(SERIF_BYTES.to_vec());
        db.load_font_data(SERIF_ITALIC_BYTES.to_vec());
        db.set_sans_serif_family(FONT_FAMILY);
        db.set_serif_family(SERIF_FAMILY);
        Arc::new(db)
    })
    .clone()
}

/// usvg options that resolve every font to the bundled ones (`font`
/// where a text names none).
pub fn usvg_options(font: FontChoice) -> resvg::usvg::Options<'static> {
    resvg::usvg::Options {
        font_family: family_of(font).to_string(),
        fontdb: fontdb(),
        ..Default::default()
    }
}

/// Registers the bundled fonts with plotters under their family names
/// (and DejaVu Sans as "sans-serif"), once per process.
pub fn register_plotters_font() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        for (name, bytes) in [
            (FONT_FAMILY, FONT_BYTES),
            ("sans-serif", FONT_BYTES),
            (SERIF_FAMILY, SERIF_BYTES),
        ] {
            // The bytes are the bundled, valid fonts; a failure would only
            // make plotters fall back to its own layout estimate.
            let _ = plotters::style::register_font(name, plotters::style::FontStyle::Normal, bytes);
        }
    });
}

/// The bundled font of `choice` for canvas text, parsed once.
pub fn font_of(choice: FontChoice) -> Option<&'static FontRef<'static>> {
    face_of(choice, false)
}

/// The bundled face of `choice` for canvas text, italic or upright, parsed
/// once. Only the serif font has an italic face; the sans font's text is
/// all upright ([`typeset`] never marks it italic).
pub fn face_of(choice: FontChoice, italic: bool) -> Option<&'static FontRef<'static>> {
    static FONTS: OnceLock<[Option<FontRef<'static>>; 3]> = OnceLock::new();
    let fonts = FONTS.get_or_init(|| {
        [
            FontRef::try_from_slice(FONT_BYTES).ok(),
            FontRef::try_from_slice(SERIF_BYTES).ok(),
            FontRef::try_from_slice(SERIF_ITALIC_BYTES).ok(),
        ]
    });
    match (choice, italic) {
        (FontChoice::Serif, true) => fonts[2].as_ref(),
        _ => fonts[choice as usize].as_ref(),
    }
}

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
fn px_scale(font: &FontRef<'_>, size: f32) -> PxScale {
    let upem = font.units_per_em().unwrap_or(2048.0);
    PxScale::from(size * font.height_unscaled() / upem)
}

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

/// A run of typeset text: one baseline shift, one face (italic or
/// upright), and its characters (no markup).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Run {
    /// Where it sits relative to the baseline.
    pub shift: Shift,
    /// Set in the italic face ([`italic_chars`]).
    pub italic: bool,
    /// Its text.
    pub text: String,
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

/// Units (and unit-like words) a label may print: always upright, and
/// what a trailing units group may hold ([`italic_chars`]). No capital
/// letters alone (N is the number of blocks, not newtons).
const UNIT_WORDS: [&str; 15] = [
    "s", "ms", "m", "cm", "mm", "km", "g", "kg", "Hz", "kHz", "rad", "deg", "degrees", "blocks",
    "block",
];

/// Single-letter units that are upright only in a units context: after a
/// number and a space (`2 s`), after a unit and a slash (`cm/s`), or in a
/// trailing units group (`t (s)`); elsewhere they are symbols (`s`, `m`,
/// `g` of the model).
const SHORT_UNITS: [&str; 3] = ["s", "m", "g"];

/// Whether `c` is a lowercase Greek letter (italic, as in TeX).
fn lowercase_greek(c: char) -> bool {
    matches!(c, 'α'..='ω' | 'ϑ' | 'ϕ' | 'ϖ' | 'ϵ' | 'ϱ')
}

/// Which characters of a label (its markup runs, each a list of flags in
/// character order) are set in italic at the print styles. The rule, as a
/// journal sets a figure's text (TeX's conventions):
///
/// - **Greek**: lowercase letters (α κ τ ω θ φ μ ε …) italic; uppercase
///   (Δ Θ Ω) upright. τ, the paper's unit of time, is a symbol like the
///   others: italic also in a units group ("speed (blocks/τ)").
/// - **Latin**: words are maximal runs of ASCII letters; anything else
///   (digits, spaces, operators, `/ = ( ) | , .`, Greek letters and markup
///   boundaries) separates them. A single letter standing alone is a symbol,
///   italic (t, N, n, x, b, k, c, m, e, g, C, U). Exceptions, upright: the
///   article "a"/"A" (followed by a space and a word: "a kink", "a single
///   minimum"; "a/b" and a lone "a" are the length a); a unit letter (s, m,
///   g) after a number and a space or after a unit and a slash ("12.7 cm/s");
///   the springs' names A and B (labels, upright in the paper's text).
/// - Words of two or more letters are upright (kink, block, speed, det, Re,
///   max, and descriptive subscripts: the "kink" of `c_{kink}`, the "min"
///   of `U_{min}`), except products of symbols, italic: a lowercase word
///   without a vowel (a e i o u y) that is not a unit (mg, mgs, mgb, ks,
///   qb; but cm, Hz, mm upright), or any word in a superscript (the iqb of
///   `e^{iqb}`, an exponent). Units of [`UNIT_WORDS`] are upright wherever
///   they stand.
/// - **Units group**: the last parenthesized group of a label, when it
///   reads as units (only unit words, τ, digits, °, %, `/ · × −` and
///   spaces: "(°)", "(s)", "(cm/s)", "(blocks/τ)", "(10^{−3} blocks/τ)"),
///   is upright but for τ.
/// - **Panel labels**: a leading parenthesized group of one to four
///   lowercase letters, then digits or primes ("(a)", "(a1)", "(b′)",
///   "(iii)"), is upright.
/// - Everything else (digits, punctuation, operators, °) is upright.
pub fn italic_chars(parts: &[(Shift, &str)]) -> Vec<Vec<bool>> {
    // Every character with its part, in order; markup boundaries separate
    // words (the runs of Latin letters below never cross parts).
    let flat: Vec<(char, usize)> = parts
        .iter()
        .enumerate()
        .flat_map(|(k, (_, t))| t.chars().map(move |c| (c, k)))
        .collect();
    let n = flat.len();
    let ch = |i: usize| flat[i].0;
    let mut upright = vec![false; n];
    if let Some(end) = panel_label_end(&flat) {
        upright[..end].iter_mut().for_each(|u| *u = true);
    }
    if let Some((a, b)) = units_group(&flat) {
        upright[a..b].iter_mut().for_each(|u| *u = true);
    }
    let mut italic: Vec<bool> = (0..n).map(|i| lowercase_greek(ch(i))).collect();
    let mut i = 0;
    while i < n {
        if !ch(i).is_ascii_alphabetic() {
            i += 1;
            continue;
        }
        let part = flat[i].1;
        let mut j = i;
        while j < n && ch(j).is_ascii_alphabetic() && flat[j].1 == part {
            j += 1;
        }
        let word: String = flat[i..j].iter().map(|&(c, _)| c).collect();
        let before: Vec<char> = flat[..i].iter().map(|&(c, _)| c).collect();
        let after: Vec<char> = flat[j..].iter().map(|&(c, _)| c).collect();
        let symbol = !upright[i]
            && if word.len() == 1 {
                let article = (word == "a" || word == "A")
                    && before.last().is_none_or(|c| c.is_whitespace() || *c == '(')
                    && after.first() == Some(&' ')
                    && after.get(1).is_some_and(|c| c.is_alphabetic());
                let unit = SHORT_UNITS.contains(&word.as_str()) && unit_context(&before);
                // The springs' names, upright as the paper sets them ("the
                // springs A and B").
                let spring = word == "A" || word == "B";
                !article && !unit && !spring
            } else if parts[part].0 == Shift::Super {
                true
            } else if UNIT_WORDS.contains(&word.as_str()) {
                false
            } else {
                let ordinal = ["th", "st", "nd", "rd"].contains(&word.as_str())
                    && before.last().is_some_and(|c| c.is_ascii_digit());
                word.chars()
                    .all(|c| c.is_ascii_lowercase() && !"aeiouy".contains(c))
                    && !ordinal
            };
        if symbol {
            italic[i..j].iter_mut().for_each(|f| *f = true);
        }
        i = j;
    }
    let mut out: Vec<Vec<bool>> = parts.iter().map(|_| Vec::new()).collect();
    for (&(_, k), f) in flat.iter().zip(italic) {
        out[k].push(f);
    }
    out
}

/// Whether a unit letter after `before` is a unit: after a number and one
/// space ("2 s"), or after a unit and a slash ("cm/s").
fn unit_context(before: &[char]) -> bool {
    match before {
        [.., d, ' '] if d.is_ascii_digit() => true,
        [rest @ .., '/'] => {
            let start = rest
                .iter()
                .rposition(|c| !c.is_ascii_alphabetic())
                .map_or(0, |p| p + 1);
            let w: String = rest[start..].iter().collect();
            UNIT_WORDS.contains(&w.as_str())
        }
        _ => false,
    }
}

/// The end (exclusive) of a leading panel label: `(` one to four lowercase
/// letters, digits or primes, `)`, then a space or the end.
fn panel_label_end(flat: &[(char, usize)]) -> Option<usize> {
    let c: Vec<char> = flat.iter().map(|&(c, _)| c).collect();
    if c.first() != Some(&'(') {
        return None;
    }
    let letters = c[1..].iter().take_while(|c| c.is_ascii_lowercase()).count();
    if !(1..=4).contains(&letters) {
        return None;
    }
    let tail = c[1 + letters..]
        .iter()
        .take_while(|c| c.is_ascii_digit() || matches!(c, '′' | '\'' | '″'))
        .count();
    let close = 1 + letters + tail;
    (c.get(close) == Some(&')') && c.get(close + 1).is_none_or(|c| c.is_whitespace()))
        .then_some(close + 1)
}

/// The span (open to close parenthesis, inclusive) of the label's last
/// parenthesized group when it ends the label and reads as units.
fn units_group(flat: &[(char, usize)]) -> Option<(usize, usize)> {
    let c: Vec<char> = flat.iter().map(|&(c, _)| c).collect();
    let close = c.iter().rposition(|c| !c.is_whitespace())?;
    if c[close] != ')' {
        return None;
    }
    let mut depth = 0;
    let mut open = None;
    for i in (0..=close).rev() {
        match c[i] {
            ')' => depth += 1,
            '(' => {
                depth -= 1;
                if depth == 0 {
                    open = Some(i);
                    break;
                }
            }
            _ => {}
        }
    }
    let open = open?;
    let inner = &c[open + 1..close];
    let mut has_unit = false;
    let mut k = 0;
    while k < inner.len() {
        let x = inner[k];
        if x.is_ascii_alphabetic() {
            let end = k + inner[k..]
                .iter()
                .take_while(|c| c.is_ascii_alphabetic())
                .count();
            let w: String = inner[k..end].iter().collect();
            if !UNIT_WORDS.contains(&w.as_str()) {
                return None;
            }
            has_unit = true;
            k = end;
            continue;
        }
        if matches!(x, '°' | '%') {
            has_unit = true;
        } else if !(x.is_ascii_digit() || x.is_whitespace() || "τ/·×−-+.,′".contains(x)) {
            return None;
        }
        k += 1;
    }
    has_unit.then_some((open, close + 1))
}

/// Space added after italic run `prev` before `next`, in units of the
/// text's size: TeX's italic correction, so that an italic letter's
/// overhang does not touch an upright `)`, `|`, `]`, `/` or a superscript
/// that follows it.
pub fn italic_correction(prev: &Run, next: &Run) -> f32 {
    let touching = next.shift == Shift::Super
        || (!next.italic
            && next
                .text
                .starts_with([')', '|', ']', '/', '}', '²', '³', '′']));
    if prev.italic && touching {
        ITALIC_CORRECTION * prev.shift.scale()
    } else {
        0.0
    }
}

/// The italic correction of [`italic_correction`], in units of the size.
pub const ITALIC_CORRECTION: f32 = 0.06;

/// [`runs`] of text already free of script characters.
fn markup_runs(text: &str) -> Vec<(Shift, &str)> {
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

/// Draws typeset `text` (see [`runs`]) onto `pixmap` anti-aliased,
/// anchored at (`x`, `y`) pixels.
pub fn draw_text(
    pixmap: &mut Pixmap,
    choice: FontChoice,
    text: &str,
    at: (f32, f32),
    size: f32,
    rgb: Rgb,
    align: (HAlign, VAlign),
) {
    let width = text_width(choice, text, size);
    let (mut pen, baseline) = text_origin(choice, at, width, size, align);
    let runs = typeset(choice, text);
    for (
        k,
        Run {
            shift,
            italic,
            text: run,
        },
    ) in runs.iter().enumerate()
    {
        let Some(font) = face_of(choice, *italic) else {
            return;
        };
        let shift = *shift;
        let run_size = size * shift.scale();
        let sf = font.as_scaled(px_scale(font, run_size));
        let y = baseline - shift.rise() * size;
        let mut prev = None;
        for ch in run.chars() {
            let id = sf.glyph_id(ch);
            if let Some(p) = prev {
                pen += sf.kern(p, id);
            }
            let glyph = id.with_scale_and_position(sf.scale(), point(pen, y));
            if let Some(outline) = font.outline_glyph(glyph) {
                let b = outline.px_bounds();
                outline.draw(|gx, gy, cov| {
                    blend(
                        pixmap,
                        b.min.x as i32 + gx as i32,
                        b.min.y as i32 + gy as i32,
                        rgb,
                        cov,
                    );
                });
            }
            pen += sf.h_advance(id);
            prev = Some(id);
        }
        if let Some(next) = runs.get(k + 1) {
            pen += italic_correction(&runs[k], next) * size;
        }
    }
}

/// Source-over of `rgb` with coverage `cov` onto one premultiplied pixel.
#[inline]
fn blend(pixmap: &mut Pixmap, x: i32, y: i32, rgb: Rgb, cov: f32) {
    let (w, h) = (pixmap.width() as i32, pixmap.height() as i32);
    if x < 0 || y < 0 || x >= w || y >= h || cov <= 0.0 {
        return;
    }
    let a = cov.min(1.0);
    let i = ((y * w + x) * 4) as usize;
    let px = &mut pixmap.data_mut()[i..i + 4];
    for k in 0..3 {
        px[k] = (rgb[k] as f32 * a + px[k] as f32 * (1.0 - a)).round() as u8;
    }
    px[3] = (255.0 * a + px[3] as f32 * (1.0 - a)).round() as u8;
}

/// A new pixmap filled with white; `None` for a zero or huge size.
pub fn white_pixmap(width: u32, height: u32) -> Option<Pixmap> {
    let mut p = Pixmap::new(width, height)?;
    p.fill(Color::WHITE);
    Some(p)
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

    #[test]
    fn text_draws_something() {
        let mut p = white_pixmap(80, 30).unwrap();
        draw_text(
            &mut p,
            FontChoice::Sans,
            "t/τ = 12",
            (2.0, 2.0),
            14.0,
            DARK,
            (HAlign::Left, VAlign::Top),
        );
        assert!(p.pixels().iter().any(|c| c.red() < 100));
        assert!(text_width(FontChoice::Sans, "θ", 14.0) > 3.0);
    }

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

    /// A label's runs at the serif font, italic ones between asterisks,
    /// scripts as markup.
    fn marked(label: &str) -> String {
        typeset(FontChoice::Serif, label)
            .into_iter()
            .map(|r| {
                let t = if r.italic {
                    format!("*{}*", r.text)
                } else {
                    r.text
                };
                match r.shift {
                    Shift::Base => t,
                    Shift::Super => format!("^{{{t}}}"),
                    Shift::Sub => format!("_{{{t}}}"),
                }
            })
            .collect()
    }

    #[test]
    fn symbols_are_italic_units_and_words_upright() {
        let table = [
            ("t/τ = 300", "*t*/*τ* = 300"),
            ("springs A and B", "springs A and B"),
            ("|α| (°)", "|*α*| (°)"),
            ("gap ω₊(0) τ", "gap *ω*_{+}(0) *τ*"),
            ("ΔU / mgs", "Δ*U* / *mgs*"),
            ("c_{kink}", "*c*_{kink}"),
            ("c_{kink} (cm/s)", "*c*_{kink} (cm/s)"),
            ("(a1)  kink α = 60°", "(a1)  kink *α* = 60°"),
            ("(b′) as printed", "(b′) as printed"),
            ("(i) over (ii) in grey", "(i) over (ii) in grey"),
            ("block N turned first", "block *N* turned first"),
            ("a kink", "a kink"),
            ("a single minimum at θ = 0", "a single minimum at *θ* = 0"),
            ("a/b = 1.2 (α = ±66.5°)", "*a*/*b* = 1.2 (*α* = ±66.5°)"),
            ("a", "*a*"),
            ("U(θ), a² = b² + 4s²", "*U*(*θ*), *a*² = *b*² + 4*s*²"),
            ("x_{n} (cm)", "*x*_{*n*} (cm)"),
            ("time t (s)", "time *t* (s)"),
            ("speed (blocks/τ)", "speed (blocks/*τ*)"),
            ("speed (10^{−3} blocks/τ)", "speed (10^{−3} blocks/*τ*)"),
            ("kink, 0.1 Hz: 12.7 cm/s", "kink, 0.1 Hz: 12.7 cm/s"),
            ("kink: propagated", "kink: propagated"),
            ("gravity G = mg/(ks)", "gravity *G* = *mg*/(*ks*)"),
            ("U_{min} = −2mgb", "*U*_{min} = −2*mgb*"),
            ("det C / (e^{iqb} − 1)", "det *C* / (*e*^{*iqb*} − 1)"),
            ("Re det C", "Re det *C*"),
            ("|δθ_{n}| / max", "|*δθ*_{*n*}| / max"),
            ("position (n − 1) b (cm)", "position (*n* − 1) *b* (cm)"),
            (
                "equilibrium angle α (degrees)",
                "equilibrium angle *α* (degrees)",
            ),
            ("α = +60°: κb = 1.95", "*α* = +60°: *κb* = 1.95"),
            ("pin friction μ_{p}", "pin friction *μ*_{*p*}"),
            ("Δx", "Δ*x*"),
            ("ΩΘ ωθ", "ΩΘ *ωθ*"),
            ("model: no wave (at 0)", "model: no wave (at 0)"),
            ("the 5th block", "the 5th block"),
            ("chain length (N)", "chain length (*N*)"),
        ];
        for (label, want) in table {
            assert_eq!(marked(label), want, "{label}");
        }
        // The screen and slide font stays upright.
        assert!(
            typeset(FontChoice::Sans, "t/τ = 300 (s)")
                .iter()
                .all(|r| !r.italic)
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
        let mut p = white_pixmap(80, 30).unwrap();
        draw_text(
            &mut p,
            serif,
            "t/τ = 1",
            (2.0, 2.0),
            16.0,
            DARK,
            (HAlign::Left, VAlign::Top),
        );
        assert!(p.pixels().iter().any(|c| c.red() < 100));
    }

    #[test]
    fn diverging_ends() {
        assert_eq!(diverging(-1.0), KYMO_NEG);
        assert_eq!(diverging(1.0), KYMO_POS);
        assert_eq!(diverging(0.0), WHITE);
    }
}
