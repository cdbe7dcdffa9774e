//! Which characters of a label are set in italic at the print styles: a
//! journal's habit (TeX's conventions) of italic symbols, upright units,
//! words and digits ([`italic_chars`] states the rule), and the italic
//! correction between an italic letter and an upright delimiter.

use super::markup::{Run, Shift};

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::markup::markup_runs;

    /// A label's runs ([`markup_runs`]: markup, not Unicode scripts), italic
    /// ones between asterisks, scripts as markup.
    fn marked(label: &str) -> String {
        let parts = markup_runs(label);
        let mask = italic_chars(&parts);
        let mut out = String::new();
        for ((shift, t), m) in parts.into_iter().zip(mask) {
            let mut run = String::new();
            let mut open = false;
            for (c, italic) in t.chars().zip(m) {
                if italic != open {
                    run.push('*');
                    open = italic;
                }
                run.push(c);
            }
            if open {
                run.push('*');
            }
            out.push_str(&match shift {
                Shift::Base => run,
                Shift::Super => format!("^{{{run}}}"),
                Shift::Sub => format!("_{{{run}}}"),
            });
        }
        out
    }

    #[test]
    fn symbols_are_italic_units_and_words_upright() {
        let table = [
            ("t/τ = 300", "*t*/*τ* = 300"),
            ("springs A and B", "springs A and B"),
            ("|α| (°)", "|*α*| (°)"),
            ("gap ω_{+}(0) τ", "gap *ω*_{+}(0) *τ*"),
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
    }
}
