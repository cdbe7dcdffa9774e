//! Typesetting of text markup (`^{...}`, `_{...}`) inside plotters' SVG.

use crate::render::Theme;
use crate::render::page_style::FontChoice;
use crate::render::style;
use crate::render::svg::runs_markup;

/// Rewrites the content of each `<text>` element of plotters' SVG into
/// typeset runs ([`style::typeset`]): markup (`^{...}`, `_{...}`) into
/// `<tspan>`s with a smaller size and a shifted baseline, sized from the
/// element's `font-size` (the theme's tick size where it has none), and at
/// the print styles the italic symbols into `<tspan font-style="italic">`,
/// in the theme's font. Texts that stay one upright run are left as they
/// are.
pub fn typeset_svg_text(theme: &Theme, svg: &str) -> String {
    let font = theme.font();
    if font == FontChoice::Sans
        && !svg.contains("^{")
        && !svg.contains("_{")
        && style::scripts_as_markup(font, svg) == svg
    {
        return svg.to_string();
    }
    let mut out = String::with_capacity(svg.len() + 256);
    let mut rest = svg;
    while let Some(open) = rest.find("<text") {
        let Some(tag_end) = rest[open..].find('>').map(|i| open + i + 1) else {
            break;
        };
        let Some(close) = rest[tag_end..].find("</text>").map(|i| tag_end + i) else {
            break;
        };
        let tag = &rest[open..tag_end];
        let size = attribute(tag, "font-size")
            .and_then(|v| v.parse::<f32>().ok())
            .unwrap_or(theme.tick);
        out.push_str(&rest[..tag_end]);
        let content = &rest[tag_end..close];
        let runs = style::typeset(font, &unescape(content));
        if runs.len() <= 1
            && runs
                .iter()
                .all(|r| r.shift == style::Shift::Base && !r.italic)
        {
            out.push_str(content);
        } else {
            out.push_str(&runs_markup(&runs, size, &|v| format!("{v:.2}"), &escape));
        }
        rest = &rest[close..];
    }
    out.push_str(rest);
    out
}

/// The text of an XML element's content (the entities plotters writes).
fn unescape(t: &str) -> String {
    t.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
}

/// `t` escaped for XML content.
fn escape(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// The value of `name="..."` in an XML start tag.
fn attribute<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let start = tag.find(&key)? + key.len();
    let end = tag[start..].find('"')? + start;
    Some(&tag[start..end])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::{Style, StyleName};

    #[test]
    fn chart_text_markup_becomes_tspans() {
        let svg = "<svg><text x=\"1\" font-size=\"10\" fill=\"#000\">e^{−κ}, x_{n}\n</text>\
                   <text font-size=\"8\">plain</text></svg>";
        let out = typeset_svg_text(&Theme::of(&Default::default()), svg);
        assert!(
            out.contains("e<tspan font-size=\"7.00\" baseline-shift=\"3.80\">−κ</tspan>, x<tspan"),
            "{out}"
        );
        assert!(out.contains("<text font-size=\"8\">plain</text>"));
    }

    #[test]
    fn print_chart_text_sets_symbols_in_italic() {
        let paper = Style::named(StyleName::Paper);
        let svg = "<svg><text font-size=\"10\">|α| (°)\n</text>\
                   <text font-size=\"10\">kink &amp; antikink</text></svg>";
        let out = typeset_svg_text(&Theme::of(&paper), svg);
        assert!(
            out.contains(
                "|<tspan font-style=\"italic\">α</tspan><tspan dx=\"0.60\">| (°)\n</tspan>"
            ),
            "{out}"
        );
        // All-upright text is left as plotters wrote it (entities included).
        assert!(out.contains(">kink &amp; antikink</text>"), "{out}");
    }
}
