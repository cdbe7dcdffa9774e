//! The one palette, by role: every figure, chart, movie frame and the GIF
//! encoder's colour table ask it for the colour (and the marker) of a role
//! (a kink, an A spring, a pinned run, the second series …), never for an
//! RGB value or a series index (docs/formats.md "One palette").
//!
//! The colours are Okabe and Ito's colour-blind-safe set ("Color Universal
//! Design", 2008) without its yellow (too pale on paper). Every
//! categorical distinction carries a second cue besides colour: B springs
//! and antikinks are dashed, antikinks' marks open where kinks' are
//! filled, outcomes have a shape each ([`Palette::marker`]).
//!
//! Floors: the palette knows the encoder's colour type and table; the
//! charts draw its [`Marker`] shapes; the theme holds a palette
//! ([`super::Theme::palette`]).

use crate::encode::{self, Rgb};
use std::sync::OnceLock;

/// Okabe and Ito's colours by name (the values the roles take).
pub mod named {
    use crate::encode::Rgb;

    /// Ink: text, axes, blocks (Okabe–Ito's black, softened).
    pub const INK: Rgb = [34, 34, 34];
    pub const VERMILLION: Rgb = [213, 94, 0];
    pub const BLUE: Rgb = [0, 114, 178];
    pub const BLUISH_GREEN: Rgb = [0, 158, 115];
    pub const ORANGE: Rgb = [230, 159, 0];
    pub const SKY_BLUE: Rgb = [86, 180, 233];
    pub const REDDISH_PURPLE: Rgb = [204, 121, 167];
    /// Mid grey: the ground state drawn underneath, undecided runs.
    pub const GREY: Rgb = [150, 150, 150];
    pub const WHITE: Rgb = [255, 255, 255];
    /// The kymograph's diverging map: sin θ = −1 (a ColorBrewer RdBu end).
    pub const KYMO_NEG: Rgb = [33, 102, 172];
    /// The kymograph's diverging map: sin θ = +1.
    pub const KYMO_POS: Rgb = [178, 24, 43];
    /// Pure black (anti-aliased text on the GIF palette).
    pub const BLACK: Rgb = [0, 0, 0];

    /// The series colours in order (yellow left out: too pale on paper).
    pub const SERIES: [Rgb; 7] = [
        INK,
        VERMILLION,
        BLUE,
        BLUISH_GREEN,
        ORANGE,
        SKY_BLUE,
        REDDISH_PURPLE,
    ];
}

/// Marker drawn at each point of a series.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Marker {
    #[default]
    None,
    Circle,
    Square,
    Triangle,
    /// A diagonal cross, e.g. for diverged runs.
    Cross,
    /// An open circle, larger than [`Marker::Circle`]: drawn around a
    /// filled circle at the same point, both stay visible.
    Ring,
    /// An upright cross.
    Plus,
    /// An open triangle, larger than [`Marker::Triangle`] (around it).
    OpenTriangle,
    /// A filled diamond.
    Diamond,
    /// An open diamond, larger than [`Marker::Diamond`] (around it).
    OpenDiamond,
    /// An open square, larger than [`Marker::Square`] (around it).
    OpenSquare,
    /// A filled triangle pointing down.
    TriangleDown,
    /// A six-armed asterisk.
    Star,
}

/// A sweep run's outcome as the palette knows it (docs/sweeps.md): the
/// sweep maps its own outcome type onto these.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OutcomeRole {
    Propagated,
    Stalled,
    Pinned,
    Annihilated,
    Diverged,
    Undecided,
    Failed,
}

/// What a colour stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Role {
    /// Text, axes, blocks, marks of events (collisions, annihilations).
    Ink,
    /// The ground state drawn underneath; grid-like greys.
    Ground,
    /// The page.
    Paper,
    /// A springs and the A end of each block (paper Fig. 2), drawn solid.
    SpringA,
    /// B springs and the B end of each block, drawn dashed.
    SpringB,
    /// A kink, in every figure (filled marks, solid lines).
    Kink,
    /// An antikink, in every figure (open marks, dashed lines).
    Antikink,
    /// A sweep run's outcome.
    Outcome(OutcomeRole),
    /// A measurement of the apparatus (the experiment figures' data).
    Measurement,
    /// The `k`-th series of a chart whose series have no other role
    /// (0 is ink; the palette repeats after seven).
    Series(usize),
    /// The kymograph's map at sin θ = −1.
    Negative,
    /// The kymograph's map at sin θ = +1.
    Positive,
}

/// The palette: a colour and a marker per role.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Palette;

impl Palette {
    /// The colour of `role`.
    pub const fn color(&self, role: Role) -> Rgb {
        use named::*;
        match role {
            Role::Ink => INK,
            Role::Ground => GREY,
            Role::Paper => WHITE,
            Role::SpringA | Role::Kink => VERMILLION,
            Role::SpringB | Role::Antikink => BLUE,
            Role::Outcome(o) => outcome_color(o),
            Role::Measurement => INK,
            Role::Series(k) => SERIES[k % SERIES.len()],
            Role::Negative => KYMO_NEG,
            Role::Positive => KYMO_POS,
        }
    }

    /// The colour words of `role` are set in on white: the role's colour
    /// where it reads at WCAG's 4.5:1 contrast, else the role's colour
    /// darkened toward ink until it does (vermillion "kink" at 3.9:1
    /// becomes a darker vermillion), so that a mark's word keeps its
    /// wave's hue and reads at text size.
    pub fn text(&self, role: Role) -> Rgb {
        let c = self.color(role);
        (0..=20)
            .map(|k| mix(c, named::INK, k as f64 / 20.0))
            .find(|t| contrast_on_white(*t) >= MIN_TEXT_CONTRAST)
            .unwrap_or(named::INK)
    }

    /// The marker of `role`: a shape per outcome (propagated circle,
    /// stalled triangle, pinned cross, annihilated diamond, the rest a
    /// square), filled for a kink and open for an antikink (`antikink`),
    /// so that a kink and an antikink at the same point both show; a kink
    /// alone a filled circle, an antikink an open one.
    pub fn marker(&self, role: Role, antikink: bool) -> Marker {
        match (role, antikink) {
            (Role::Kink, _) => Marker::Circle,
            (Role::Antikink, _) => Marker::Ring,
            (Role::Outcome(o), open) => outcome_marker(o, open),
            (_, false) => Marker::Circle,
            (_, true) => Marker::Ring,
        }
    }

    /// The marker of the `k`-th of several series of one role (circle,
    /// square, triangle, diamond, then again), filled or `open` (an
    /// antikink's), so that series of one colour differ by shape.
    pub fn series_marker(&self, k: usize, open: bool) -> Marker {
        let (filled, hollow) = [
            (Marker::Circle, Marker::Ring),
            (Marker::Square, Marker::OpenSquare),
            (Marker::Triangle, Marker::OpenTriangle),
            (Marker::Diamond, Marker::OpenDiamond),
        ][k % 4];
        if open { hollow } else { filled }
    }

    /// The GIF colour table every movie is encoded with: ramps from white
    /// to ink, the springs' colours, bluish green and the kymograph's two
    /// ends, and mid grey and black verbatim (built once).
    pub fn gif(&self) -> &'static encode::Palette {
        static GIF: OnceLock<encode::Palette> = OnceLock::new();
        GIF.get_or_init(|| {
            let anchors = [
                self.color(Role::Ink),
                self.color(Role::SpringA),
                self.color(Role::SpringB),
                named::BLUISH_GREEN,
                self.color(Role::Negative),
                self.color(Role::Positive),
            ];
            let extras = [self.color(Role::Ground), named::BLACK];
            encode::Palette::new(&anchors, encode::GIF_RAMP_STEPS, &extras)
                .unwrap_or_else(|_| unreachable!("the scene palette has 255 colours"))
        })
    }
}

/// Least contrast of words on white (WCAG 2 AA for text).
pub const MIN_TEXT_CONTRAST: f64 = 4.5;

/// The outcomes' colours. Adjacent outcomes of a phase diagram stay apart
/// for dichromats: propagated blue, stalled orange, pinned reddish purple
/// (ΔE00 36 from orange under deuteranopia, 43 under protanopia, where
/// vermillion and orange were 12.5 and 18 apart), annihilated vermillion;
/// each outcome's cells also carry its marker (the second cue).
const fn outcome_color(o: OutcomeRole) -> Rgb {
    use named::*;
    match o {
        OutcomeRole::Propagated => BLUE,
        OutcomeRole::Stalled => ORANGE,
        OutcomeRole::Pinned => REDDISH_PURPLE,
        OutcomeRole::Annihilated => VERMILLION,
        OutcomeRole::Diverged => INK,
        OutcomeRole::Undecided => GREY,
        OutcomeRole::Failed => BLUISH_GREEN,
    }
}

/// The outcomes' shapes, filled (a kink) or open (an antikink).
fn outcome_marker(o: OutcomeRole, open: bool) -> Marker {
    match (o, open) {
        (OutcomeRole::Propagated, false) => Marker::Circle,
        (OutcomeRole::Propagated, true) => Marker::Ring,
        (OutcomeRole::Stalled, false) => Marker::Triangle,
        (OutcomeRole::Stalled, true) => Marker::OpenTriangle,
        (OutcomeRole::Pinned, false) => Marker::Cross,
        (OutcomeRole::Pinned, true) => Marker::Plus,
        (OutcomeRole::Annihilated, false) => Marker::Diamond,
        (OutcomeRole::Annihilated, true) => Marker::OpenDiamond,
        (_, false) => Marker::Square,
        (_, true) => Marker::OpenSquare,
    }
}

/// Linear blend from `a` (f = 0) to `b` (f = 1).
fn mix(a: Rgb, b: Rgb, f: f64) -> Rgb {
    let f = f.clamp(0.0, 1.0);
    [0, 1, 2].map(|k| (a[k] as f64 + (b[k] as f64 - a[k] as f64) * f).round() as u8)
}

/// WCAG 2 relative luminance of an sRGB colour.
fn luminance(c: Rgb) -> f64 {
    let lin = |v: u8| {
        let v = v as f64 / 255.0;
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    0.2126 * lin(c[0]) + 0.7152 * lin(c[1]) + 0.0722 * lin(c[2])
}

/// WCAG 2 contrast ratio of `c` on white (1 to 21).
pub fn contrast_on_white(c: Rgb) -> f64 {
    1.05 / (luminance(c) + 0.05)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kink_and_antikink_take_the_springs_colours_and_differ() {
        let p = Palette;
        assert_eq!(p.color(Role::Kink), named::VERMILLION);
        assert_eq!(p.color(Role::Antikink), named::BLUE);
        assert_eq!(p.color(Role::SpringA), p.color(Role::Kink));
        assert_ne!(p.marker(Role::Kink, false), p.marker(Role::Antikink, true));
    }

    /// Words in a role's colour read at 4.5:1 on white (4a's orange
    /// "kink" read at 2.25:1), and keep their hue where they can.
    #[test]
    fn words_in_every_role_colour_read_on_white() {
        let p = Palette;
        let roles = [
            Role::Ink,
            Role::Kink,
            Role::Antikink,
            Role::Outcome(OutcomeRole::Stalled),
            Role::Outcome(OutcomeRole::Pinned),
            Role::Series(4),
            Role::Series(5),
        ];
        for r in roles {
            let t = p.text(r);
            assert!(contrast_on_white(t) >= MIN_TEXT_CONTRAST, "{r:?}: {t:?}");
        }
        assert_eq!(p.text(Role::Antikink), named::BLUE, "blue reads as it is");
        assert_ne!(p.text(Role::Kink), named::INK, "vermillion keeps its hue");
        assert!((contrast_on_white(named::ORANGE) - 2.25).abs() < 0.01);
    }

    #[test]
    fn every_outcome_has_its_own_shape_filled_and_open() {
        use OutcomeRole::*;
        let p = Palette;
        let shapes: Vec<Marker> = [Propagated, Stalled, Pinned, Annihilated, Diverged]
            .into_iter()
            .flat_map(|o| [false, true].map(|open| p.marker(Role::Outcome(o), open)))
            .collect();
        for i in 0..shapes.len() {
            for j in i + 1..shapes.len() {
                assert_ne!(shapes[i], shapes[j], "{i} {j}");
            }
        }
    }

    #[test]
    fn the_gif_table_holds_every_role_colour_exactly() {
        let p = Palette;
        let gif = p.gif();
        for r in [
            Role::Ink,
            Role::Ground,
            Role::Paper,
            Role::SpringA,
            Role::SpringB,
            Role::Negative,
            Role::Positive,
        ] {
            let c = p.color(r);
            assert_eq!(gif.color(gif.index(c)), c, "{r:?}");
        }
    }
}
