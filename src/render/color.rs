//! Colour arithmetic the drawing code shares: tiny-skia and SVG forms of
//! an [`Rgb`], blends, and the kymograph's diverging map (whose ends are
//! the palette's [`Role::Negative`] and [`Role::Positive`]).

use super::palette::{Palette, Role};
use crate::encode::Rgb;
use tiny_skia::Color;

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

/// The kymograph's diverging map: −1 → [`Role::Negative`], 0 → white,
/// +1 → [`Role::Positive`], linear in between (so every colour lies on a
/// GIF palette ramp). NaN maps to [`Role::Ground`] grey.
pub fn diverging(v: f64) -> Rgb {
    let p = Palette;
    let white = p.color(Role::Paper);
    if v.is_nan() {
        p.color(Role::Ground)
    } else if v < 0.0 {
        mix(white, p.color(Role::Negative), -v)
    } else {
        mix(white, p.color(Role::Positive), v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn diverging_ends() {
        let p = Palette;
        assert_eq!(diverging(-1.0), p.color(Role::Negative));
        assert_eq!(diverging(1.0), p.color(Role::Positive));
        assert_eq!(diverging(0.0), p.color(Role::Paper));
    }
}
