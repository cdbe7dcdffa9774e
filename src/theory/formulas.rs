//! The formulas that a picture and its caption both print, each written
//! once here, in the markup of the pictures' typeset text: `^{…}` is a
//! superscript and `_{…}` a subscript. A caption names one as `{{key}}`
//! (`{{edge-decay}}`); [`expand`] puts it in.

/// The surface zero mode's decay down the chain, normalised to 1 at the
/// top block (supplement eq. for |c₂/c₁|^{n−1}, with κ of
/// [`crate::theory::edge`]).
pub const EDGE_DECAY: &str = "e^{−κ(n−1)b}";

/// Every formula a caption may name: (key, markup).
pub const FORMULAS: &[(&str, &str)] = &[("edge-decay", EDGE_DECAY)];

/// `text` with each `{{key}}` of [`FORMULAS`] replaced by its markup; an
/// unknown key stays as written.
pub fn expand(text: &str) -> String {
    let mut out = text.to_string();
    for (key, markup) in FORMULAS {
        out = out.replace(&format!("{{{{{key}}}}}"), markup);
    }
    out
}

/// Markup split into (shift, text) runs: 0 base, 1 superscript, −1
/// subscript. A `^` or `_` not followed by `{…}` is literal text.
fn runs(text: &str) -> Vec<(i8, &str)> {
    let mut out = Vec::new();
    let mut rest = text;
    while !rest.is_empty() {
        let next = rest
            .match_indices(['^', '_'])
            .find(|(i, _)| rest[i + 1..].starts_with('{') && rest[i + 2..].contains('}'));
        let Some((i, mark)) = next else {
            out.push((0, rest));
            break;
        };
        if i > 0 {
            out.push((0, &rest[..i]));
        }
        let body = &rest[i + 2..];
        let close = body.find('}').unwrap_or(body.len());
        out.push((if mark == "^" { 1 } else { -1 }, &body[..close]));
        rest = &body[(close + 1).min(body.len())..];
    }
    out
}

/// Markup as HTML: `<sup>`/`<sub>`, and `&`, `<`, `>`, `"` escaped.
pub fn html(markup: &str) -> String {
    let esc = |t: &str| {
        t.replace('&', "&amp;")
            .replace('<', "&lt;")
            .replace('>', "&gt;")
            .replace('"', "&quot;")
    };
    runs(markup)
        .into_iter()
        .map(|(shift, t)| match shift {
            1 => format!("<sup>{}</sup>", esc(t)),
            -1 => format!("<sub>{}</sub>", esc(t)),
            _ => esc(t),
        })
        .collect()
}

/// Markup as one line of plain text, for text drawn without typesetting
/// and for alt text: "e^(−κ(n−1)b)", "δθₙ" stays "δθ_n".
pub fn plain(markup: &str) -> String {
    runs(markup)
        .into_iter()
        .map(|(shift, t)| {
            let mark = if shift > 0 { "^" } else { "_" };
            match (shift, t.chars().count()) {
                (0, _) => t.to_string(),
                (_, 1) => format!("{mark}{t}"),
                _ => format!("{mark}({t})"),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_formula_three_ways() {
        assert_eq!(expand("line: {{edge-decay}}."), "line: e^{−κ(n−1)b}.");
        assert_eq!(expand("{{nothing}}"), "{{nothing}}");
        assert_eq!(html(EDGE_DECAY), "e<sup>−κ(n−1)b</sup>");
        assert_eq!(html("a < b_{n}"), "a &lt; b<sub>n</sub>");
        assert_eq!(plain(EDGE_DECAY), "e^(−κ(n−1)b)");
        assert_eq!(plain("δθ_{n}, x^2"), "δθ_n, x^2");
    }
}
