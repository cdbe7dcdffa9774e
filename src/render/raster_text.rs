//! Canvas text on a tiny-skia pixmap: typeset text rasterised from the
//! bundled font's outlines with `ab_glyph` (fast enough for a time label
//! on every movie frame) and blended source-over, and the white pixmap
//! every drawing starts from.

use super::fonts::face_of;
use super::page_style::FontChoice;
use super::typeset::{
    HAlign, Run, VAlign, italic_correction, px_scale, text_origin, text_width, typeset,
};
use crate::encode::Rgb;
use ab_glyph::{Font, ScaleFont, point};
use tiny_skia::{Color, Pixmap};

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::palette::named::INK as DARK;

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
        // In the serif font's italic face too.
        let mut p = white_pixmap(80, 30).unwrap();
        draw_text(
            &mut p,
            FontChoice::Serif,
            "t/τ = 1",
            (2.0, 2.0),
            16.0,
            DARK,
            (HAlign::Left, VAlign::Top),
        );
        assert!(p.pixels().iter().any(|c| c.red() < 100));
    }
}
