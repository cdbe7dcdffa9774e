//! Typesetting of text markup (`^{...}`, `_{...}`) inside plotters' SVG.

use crate::render::Theme;
use crate::render::style;

/// Rewrites the content of each `<text>` element of plotters' SVG that
/// holds markup (`^{...}`, `_{...}`) into `<tspan>`s with a smaller size
/// and a shifted baseline, sized from the element's `font-size` (the
/// theme's tick size where it has none), in the theme's font.
pub fn typeset_svg_text(theme: &Theme, svg: &str) -> String {
    let font = theme.font();
    if !svg.contains("^{") && !svg.contains("_{") && style::scripts_as_markup(font, svg) == svg {
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
        for (shift, run) in style::runs(font, &rest[tag_end..close]) {
            match shift {
                style::Shift::Base => out.push_str(&run),
                _ => out.push_str(&format!(
                    "<tspan font-size=\"{:.2}\" baseline-shift=\"{:.2}\">{run}</tspan>",
                    size * shift.scale(),
                    size * shift.rise()
                )),
            }
        }
        rest = &rest[close..];
    }
    out.push_str(rest);
    out
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
}
