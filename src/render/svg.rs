//! The SVG backend of [`Picture`]: one `<path>` per fill or stroke, `<text>`
//! in the bundled font with `<tspan>`s for super- and subscripts, charts
//! inlined from their own SVG, groups as `<g transform>`. Text is placed
//! with the same metrics as the raster backend ([`style::text_origin`]),
//! so the two agree.

use super::canvas::{Cap, Pen};
use super::page_style::FontChoice;
use super::picture::{Item, Picture};
use super::style::{self, Shift};
use crate::encode::Rgb;
use crate::error::{Error, Result};
use std::fmt::Write;
use tiny_skia::{Path, PathSegment, Transform};

/// The SVG document of `picture` at `scale` times its design size.
pub fn document(picture: &Picture, scale: f32) -> Result<String> {
    let (w, h) = (picture.width() * scale, picture.height() * scale);
    document_sized(picture, (num(w), num(h)))
}

/// The SVG file of `picture` with real text (`<text>` naming the bundled
/// font), its page `pt_per_px` points per design pixel: width and height
/// in points (`243pt`), the design size as the view box.
pub fn document_in_points(picture: &Picture, pt_per_px: f32) -> Result<String> {
    let (w, h) = (picture.width() * pt_per_px, picture.height() * pt_per_px);
    document_sized(picture, (format!("{}pt", num(w)), format!("{}pt", num(h))))
}

/// `svg` (a document whose root is `<svg ...>`) with a `<title>` (when
/// `title` is given) and a `<metadata>` naming the program, version and
/// commit that made it, as the root's first children.
pub fn with_metadata(svg: Vec<u8>, title: Option<&str>) -> Vec<u8> {
    let Ok(text) = String::from_utf8(svg.clone()) else {
        return svg;
    };
    let Some(open) = text.find("<svg") else {
        return svg;
    };
    let Some(end) = text[open..].find('>').map(|e| open + e + 1) else {
        return svg;
    };
    let mut meta = String::from("\n");
    if let Some(t) = title.filter(|t| !t.is_empty()) {
        let _ = writeln!(meta, "<title>{}</title>", xml_escape(t));
    }
    let _ = write!(
        meta,
        "<metadata><creator xmlns=\"http://purl.org/dc/elements/1.1/\">{}</creator></metadata>",
        xml_escape(&crate::encode::creator())
    );
    let mut out = String::with_capacity(text.len() + meta.len());
    out.push_str(&text[..end]);
    out.push_str(&meta);
    out.push_str(&text[end..]);
    out.into_bytes()
}

fn xml_escape(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn document_sized(picture: &Picture, (width, height): (String, String)) -> Result<String> {
    if picture.has_images() {
        return Err(Error::failed(
            "this picture holds a raster image and has no vector form",
        ));
    }
    let (w, h) = (picture.width(), picture.height());
    let mut out = String::with_capacity(64 * 1024);
    let _ = write!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{height}\" \
         viewBox=\"0 0 {} {}\">\n<rect width=\"{}\" height=\"{}\" fill=\"#ffffff\"/>\n",
        num(w),
        num(h),
        num(w),
        num(h)
    );
    items(&mut out, picture.theme().font(), picture.items());
    out.push_str("</svg>\n");
    Ok(out)
}

fn items(out: &mut String, font: FontChoice, list: &[Item]) {
    for item in list {
        match item {
            Item::Fill { path, color } => {
                let _ = writeln!(
                    out,
                    "<path d=\"{}\" fill=\"{}\"/>",
                    path_data(path),
                    style::hex(*color)
                );
            }
            Item::Stroke { path, pen } => {
                let _ = writeln!(
                    out,
                    "<path d=\"{}\" {}/>",
                    path_data(path),
                    stroke_attrs(pen)
                );
            }
            Item::Text {
                text,
                at,
                size,
                color,
                align,
            } => text_element(out, font, text, *at, *size, *color, *align),
            Item::Chart { chart, at } => {
                let _ = writeln!(
                    out,
                    "<g transform=\"translate({} {})\">",
                    num(at.0),
                    num(at.1)
                );
                out.push_str(svg_body(&chart.svg));
                out.push_str("\n</g>\n");
            }
            // Refused by `document`.
            Item::Image { .. } => {}
            Item::Group {
                transform,
                items: inner,
            } => {
                let _ = writeln!(out, "<g transform=\"{}\">", matrix(*transform));
                items(out, font, inner);
                out.push_str("</g>\n");
            }
        }
    }
}

/// What lies between a document's `<svg ...>` tag and its `</svg>`.
fn svg_body(svg: &str) -> &str {
    let start = svg
        .find("<svg")
        .and_then(|i| svg[i..].find('>').map(|j| i + j + 1))
        .unwrap_or(0);
    let end = svg.rfind("</svg>").unwrap_or(svg.len()).max(start);
    &svg[start..end]
}

fn stroke_attrs(pen: &Pen) -> String {
    let mut s = format!(
        "fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"",
        style::hex(pen.color),
        num(pen.width)
    );
    match pen.cap {
        Cap::Butt => {}
        Cap::Round => s.push_str(" stroke-linecap=\"round\""),
        Cap::Square => s.push_str(" stroke-linecap=\"square\""),
    }
    if let Some([on, off]) = pen.dash {
        let _ = write!(s, " stroke-dasharray=\"{} {}\"", num(on), num(off));
    }
    s
}

fn text_element(
    out: &mut String,
    font: FontChoice,
    text: &str,
    at: (f32, f32),
    size: f32,
    color: Rgb,
    align: (style::HAlign, style::VAlign),
) {
    let width = style::text_width(font, text, size);
    let (left, baseline) = style::text_origin(font, at, width, size, align);
    let _ = write!(
        out,
        "<text x=\"{}\" y=\"{}\" font-family=\"{}\" font-size=\"{}\" fill=\"{}\" \
         xml:space=\"preserve\">",
        num(left),
        num(baseline),
        style::family_of(font),
        num(size),
        style::hex(color)
    );
    out.push_str(&runs_markup(
        &style::typeset(font, text),
        size,
        &num,
        &escape,
    ));
    out.push_str("</text>\n");
}

/// The content of a `<text>` of `size` holding `runs`: upright text on the
/// baseline as it is, and a `<tspan>` for each run that is shifted
/// (`font-size`, `baseline-shift`), italic (`font-style="italic"`) or moved
/// right by an italic correction (`dx`), each run's text through `escape`
/// and each number through `num`. Shared with the chart typesetter.
pub(super) fn runs_markup(
    runs: &[style::Run],
    size: f32,
    num: &dyn Fn(f32) -> String,
    escape: &dyn Fn(&str) -> String,
) -> String {
    let mut out = String::new();
    let mut dx = 0.0;
    for (k, run) in runs.iter().enumerate() {
        let mut attrs = String::new();
        if run.shift != Shift::Base {
            let _ = write!(
                attrs,
                " font-size=\"{}\" baseline-shift=\"{}\"",
                num(size * run.shift.scale()),
                num(size * run.shift.rise())
            );
        }
        if run.italic {
            attrs.push_str(" font-style=\"italic\"");
        }
        if dx > 0.0 {
            let _ = write!(attrs, " dx=\"{}\"", num(dx));
        }
        if attrs.is_empty() {
            out.push_str(&escape(&run.text));
        } else {
            let _ = write!(out, "<tspan{attrs}>{}</tspan>", escape(&run.text));
        }
        dx = runs
            .get(k + 1)
            .map_or(0.0, |next| style::italic_correction(run, next) * size);
    }
    out
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// `d` of a path, coordinates to 1/1000 pixel.
fn path_data(path: &Path) -> String {
    let mut d = String::new();
    for seg in path.segments() {
        let _ = match seg {
            PathSegment::MoveTo(p) => write!(d, "M{} {}", num(p.x), num(p.y)),
            PathSegment::LineTo(p) => write!(d, "L{} {}", num(p.x), num(p.y)),
            PathSegment::QuadTo(c, p) => {
                write!(d, "Q{} {} {} {}", num(c.x), num(c.y), num(p.x), num(p.y))
            }
            PathSegment::CubicTo(c1, c2, p) => write!(
                d,
                "C{} {} {} {} {} {}",
                num(c1.x),
                num(c1.y),
                num(c2.x),
                num(c2.y),
                num(p.x),
                num(p.y)
            ),
            PathSegment::Close => write!(d, "Z"),
        };
    }
    d
}

fn matrix(t: Transform) -> String {
    let n = |v: f32| {
        let s = format!("{v:.6}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        if s == "-0" || s.is_empty() {
            "0".to_string()
        } else {
            s.to_string()
        }
    };
    format!(
        "matrix({} {} {} {} {} {})",
        n(t.sx),
        n(t.ky),
        n(t.kx),
        n(t.sy),
        n(t.tx),
        n(t.ty)
    )
}

/// A number with at most three decimals and no trailing zeros.
fn num(v: f32) -> String {
    let s = format!("{:.3}", v);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" || s.is_empty() {
        "0".into()
    } else {
        s.into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(-0.0001), "0");
        assert_eq!(num(2.5), "2.5");
        assert_eq!(num(1.23456), "1.235");
    }

    #[test]
    fn body_of_a_document() {
        let svg = "<?xml version=\"1.0\"?>\n<svg width=\"2\" a=\"b\">\n<rect/>\n</svg>\n";
        assert_eq!(svg_body(svg), "\n<rect/>\n");
    }
}
