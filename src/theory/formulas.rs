//! The formulas that a picture and its caption both print, each written
//! once here, in the markup of the pictures' typeset text
//! (`render::style::runs`: `^{…}` is a superscript and `_{…}` a
//! subscript). A caption names one as `{{key}}` (`{{edge-decay}}`);
//! [`expand`] puts it in, and the gallery typesets it.

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn captions_name_formulas_by_key() {
        assert_eq!(expand("line: {{edge-decay}}."), "line: e^{−κ(n−1)b}.");
        assert_eq!(expand("{{nothing}}"), "{{nothing}}");
    }
}
