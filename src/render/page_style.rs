//! One [`Style`] for a figure: the page it is printed on (width and height
//! in points), the size of its text, its font, the resolution of its PNG and
//! whether its vector text stays text (docs/formats.md; matplotlib's
//! rcParams and SciencePlots in spirit).
//!
//! Every figure is laid out in *design pixels* with the text sizes of
//! [`super::theme::size`] (axis labels 15 px). A style fixes how many design
//! pixels a point is, `px_per_pt = DESIGN_TEXT_PX / font_pt`, so one scale turns
//! text, line widths, markers and gaps into points together: at `paper`
//! (8 pt text) an axis label of 15 px prints at 8 pt, a 2 px line at 1.07 pt.
//! A print style also fixes the page width, so a chart is laid out in a
//! design frame of `width_pt × px_per_pt` pixels (455 px at `paper`) and
//! printed at exactly `width_pt`.
//!
//! A figure's builder makes one [`super::Theme`] of its style and passes
//! it, as a value, down to every chart, cell, legend and layout it draws:
//! there is no style "in force" to ask for.

/// Design pixels of text at the style's size: the one scale from which a
/// style's points follow (`px_per_pt = DESIGN_TEXT_PX / font_pt`).
pub const DESIGN_TEXT_PX: f32 = 15.0;

/// The named styles of `--style`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum StyleName {
    /// APS/PRL single column: 3.375 in (243 pt) wide, 8 pt text, serif.
    Paper,
    /// APS two columns: 7.0 in (504 pt) wide, 8 pt text, serif.
    PaperWide,
    /// A 16:9 slide: 13.333 × 7.5 in (960 × 540 pt), 20 pt text, sans.
    Slide,
    /// Today's pixel layout at 96 px per inch (the catalogue's default).
    #[default]
    Screen,
}

impl StyleName {
    /// Every style, in the order `--help` lists them.
    pub const ALL: [StyleName; 4] = [
        StyleName::Paper,
        StyleName::PaperWide,
        StyleName::Slide,
        StyleName::Screen,
    ];

    /// The name `--style` and the scene file's `[style] name` take.
    pub fn name(self) -> &'static str {
        match self {
            StyleName::Paper => "paper",
            StyleName::PaperWide => "paper-wide",
            StyleName::Slide => "slide",
            StyleName::Screen => "screen",
        }
    }

    /// The style called `name`, if any.
    pub fn parse(name: &str) -> Option<StyleName> {
        Self::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// The face text is set in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum FontChoice {
    /// DejaVu Sans (the screen look).
    #[default]
    Sans,
    /// Liberation Serif (Times metrics, beside a journal's Times or
    /// LaTeX body text).
    Serif,
}

impl FontChoice {
    pub fn name(self) -> &'static str {
        match self {
            FontChoice::Sans => "sans",
            FontChoice::Serif => "serif",
        }
    }

    pub fn parse(name: &str) -> Option<FontChoice> {
        match name {
            "sans" => Some(FontChoice::Sans),
            "serif" => Some(FontChoice::Serif),
            _ => None,
        }
    }
}

/// How text goes into SVG and PDF files.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum TextMode {
    /// Real text: `<text>` in SVG, the font subset-embedded in PDF.
    #[default]
    Text,
    /// Glyph outlines (`--text outlines`): looks the same everywhere, but
    /// cannot be searched or copied.
    Outlines,
}

impl TextMode {
    pub fn name(self) -> &'static str {
        match self {
            TextMode::Text => "text",
            TextMode::Outlines => "outlines",
        }
    }

    pub fn parse(name: &str) -> Option<TextMode> {
        match name {
            "text" => Some(TextMode::Text),
            "outlines" => Some(TextMode::Outlines),
            _ => None,
        }
    }
}

/// How a figure looks and what page it is printed on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Style {
    /// The named style the rest was taken from. Default: `screen`.
    pub name: StyleName,
    /// Page width in points; `None` (screen): the figure's own design width
    /// at 0.75 pt per pixel.
    pub width_pt: Option<f32>,
    /// Page height in points; `None`: the figure's own aspect ratio.
    pub height_pt: Option<f32>,
    /// Size of axis labels and captions in points; tick labels and
    /// legends are 13/15 of it, titles 18/15. Default (screen): 11.25 pt,
    /// i.e. 15 px at 96 px per inch.
    pub font_pt: f32,
    /// Default: sans (screen, slide), serif (paper, paper-wide).
    pub font: FontChoice,
    /// Pixels per inch of the PNG. Default: 96 (screen), 300 (paper),
    /// 144 (slide: 1920 px wide).
    pub dpi: f32,
    /// Default: real text.
    pub text: TextMode,
}

impl Default for Style {
    fn default() -> Self {
        Style::named(StyleName::Screen)
    }
}

/// Points per inch.
pub const PT_PER_IN: f32 = 72.0;
/// Millimetres per inch.
pub const MM_PER_IN: f32 = 25.4;
/// Smallest text a print style may set, in points (docs/formats.md).
pub const MIN_PRINT_TEXT_PT: f32 = 6.0;
/// Tallest a figure may print at a print style without a page height, in
/// points: 4.5 in, so that a figure with its caption takes at most about
/// half of an APS (Physical Review) page's text block (9.6–10 in) and
/// floats beside text (the paper's Fig. 3, four rows of seven ladders, is
/// one PRL column about that tall).
pub const MAX_FIGURE_HEIGHT_PT: f32 = 4.5 * PT_PER_IN;

impl Style {
    /// The style `name` with its own sizes.
    pub fn named(name: StyleName) -> Style {
        let base = Style {
            name,
            width_pt: None,
            height_pt: None,
            font_pt: DESIGN_TEXT_PX * 0.75,
            font: FontChoice::Sans,
            dpi: 96.0,
            text: TextMode::Text,
        };
        match name {
            StyleName::Screen => base,
            StyleName::Paper => Style {
                width_pt: Some(3.375 * PT_PER_IN),
                font_pt: 8.0,
                font: FontChoice::Serif,
                dpi: 300.0,
                ..base
            },
            StyleName::PaperWide => Style {
                width_pt: Some(7.0 * PT_PER_IN),
                font_pt: 8.0,
                font: FontChoice::Serif,
                dpi: 300.0,
                ..base
            },
            StyleName::Slide => Style {
                width_pt: Some(13.333 * PT_PER_IN),
                height_pt: Some(7.5 * PT_PER_IN),
                font_pt: 20.0,
                dpi: 144.0,
                ..base
            },
        }
    }

    /// Whether this is a print style (a page of a fixed width).
    pub fn is_print(&self) -> bool {
        self.width_pt.is_some()
    }

    /// Design pixels per point: the one scale from which text, lines,
    /// markers and gaps follow (4/3 at screen, 15/8 at paper).
    pub fn px_per_pt(&self) -> f32 {
        DESIGN_TEXT_PX / self.font_pt
    }

    /// The design frame a figure whose own size is `natural` is laid out
    /// in: the page in design pixels for a print style (height from the
    /// natural aspect ratio unless the style fixes it), `natural` at screen.
    pub fn frame(&self, natural: (u32, u32)) -> (u32, u32) {
        let Some(w_pt) = self.width_pt else {
            return natural;
        };
        let w = (w_pt * self.px_per_pt()).round().max(60.0);
        // From the natural aspect ratio, no taller than the page allows.
        let h = match self.height_pt {
            Some(h_pt) => h_pt * self.px_per_pt(),
            None => (w * natural.1 as f32 / natural.0.max(1) as f32)
                .min(MAX_FIGURE_HEIGHT_PT * self.px_per_pt()),
        };
        (w as u32, h.round().max(60.0) as u32)
    }

    /// Tallest a figure may print, in points: the page height where the
    /// style fixes one (a slide: 7.5 in), else [`MAX_FIGURE_HEIGHT_PT`] at a
    /// print style; none at screen.
    pub fn max_height_pt(&self) -> Option<f32> {
        self.is_print()
            .then(|| self.height_pt.unwrap_or(MAX_FIGURE_HEIGHT_PT))
    }

    /// The box, in design pixels, that composed figures (filmstrips,
    /// panels of drawings) are laid out to fit at a print style: the page
    /// width by [`Style::max_height_pt`], at the style's own scale, so that
    /// text prints at the style's size at every style (a slide's 20 pt
    /// too: docs/formats.md, text never shrinks to fit).
    pub fn fit_box(&self) -> Option<(f32, f32)> {
        let (w, h) = (self.width_pt?, self.max_height_pt()?);
        let px = self.px_per_pt();
        Some((w * px, h * px))
    }

    /// Points per design pixel of a picture `design_width` pixels wide: the
    /// page width over the design width at a print style (so the page is
    /// exactly the style's width), 0.75 (96 px per inch) at screen.
    pub fn pt_per_px(&self, design_width: f32) -> f32 {
        match self.width_pt {
            Some(w) => w / design_width.max(1.0),
            None => 1.0 / self.px_per_pt(),
        }
    }

    /// PNG pixels per design pixel of a picture `design_width` wide.
    pub fn png_scale(&self, design_width: f32) -> f32 {
        self.pt_per_px(design_width) * self.dpi / PT_PER_IN
    }
}

/// A length of `--width`/`--height` in points: a number with `in`, `mm`,
/// `cm`, `pt` or `px` (1/96 in); what is wrong otherwise.
pub fn parse_length(s: &str) -> Result<f32, String> {
    let s = s.trim();
    let split = s
        .find(|c: char| c.is_ascii_alphabetic())
        .ok_or_else(|| format!("'{s}' has no unit: use in, mm, cm, pt or px, e.g. 3.375in"))?;
    let (num, unit) = s.split_at(split);
    let v: f32 = num
        .trim()
        .parse()
        .map_err(|_| format!("'{s}' is not a number followed by a unit such as 3.375in"))?;
    let pt = match unit.trim() {
        "in" => v * PT_PER_IN,
        "mm" => v / MM_PER_IN * PT_PER_IN,
        "cm" => v * 10.0 / MM_PER_IN * PT_PER_IN,
        "pt" => v,
        "px" => v * 0.75,
        u => {
            return Err(format!(
                "unknown unit '{u}' in '{s}': use in, mm, cm, pt or px"
            ));
        }
    };
    if !(pt.is_finite() && (36.0..=2000.0).contains(&pt)) {
        return Err(format!(
            "'{s}' is {pt:.1} pt: a figure must be between 36 pt (0.5 in) and 2000 pt wide or tall"
        ));
    }
    Ok(pt)
}

/// Serde as the names `--style`, `--font` and `--text` take.
macro_rules! serde_by_name {
    ($t:ty, $what:literal) => {
        impl serde::Serialize for $t {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                s.serialize_str(self.name())
            }
        }
        impl<'de> serde::Deserialize<'de> for $t {
            fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                let name = String::deserialize(d)?;
                <$t>::parse(&name).ok_or_else(|| {
                    serde::de::Error::custom(format!(
                        "unknown {} '{name}': use {}",
                        $what,
                        <$t>::NAMES.join(", ")
                    ))
                })
            }
        }
    };
}

impl StyleName {
    /// The names, for messages.
    pub const NAMES: [&'static str; 4] = ["paper", "paper-wide", "slide", "screen"];
}
impl FontChoice {
    pub const NAMES: [&'static str; 2] = ["sans", "serif"];
}
impl TextMode {
    pub const NAMES: [&'static str; 2] = ["text", "outlines"];
}
serde_by_name!(StyleName, "style");
serde_by_name!(FontChoice, "font");
serde_by_name!(TextMode, "text mode");

/// A length in points, written with a unit (`"3.375in"`, `"86mm"`,
/// `"243pt"`, `"640px"`) in scene files.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Length(pub f32);

impl serde::Serialize for Length {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&format!("{}pt", self.0))
    }
}

impl<'de> serde::Deserialize<'de> for Length {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let s = String::deserialize(d)?;
        parse_length(&s)
            .map(Length)
            .map_err(serde::de::Error::custom)
    }
}

/// A number of a `[style]` table within `lo..=hi`, checked as it is read
/// (so that a scene file's error keeps its file, line and column) and said
/// as it was written, before it is narrowed to `f32`.
fn ranged<'de, D: serde::Deserializer<'de>>(
    d: D,
    (lo, hi, unit): (f64, f64, &str),
) -> Result<Option<f32>, D::Error> {
    let x = <f64 as serde::Deserialize>::deserialize(d)?;
    if x.is_finite() && (lo..=hi).contains(&x) {
        Ok(Some(x as f32))
    } else {
        Err(serde::de::Error::custom(format!(
            "must be between {lo} and {hi}{unit}, got {}",
            crate::numfmt::plain(x)
        )))
    }
}

fn font_size_pt<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<f32>, D::Error> {
    ranged(d, (4.0, 72.0, " pt"))
}

fn dpi<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<f32>, D::Error> {
    ranged(d, (36.0, 1200.0, ""))
}

/// What a scene file's `[style]` table or the command line asks for; each
/// field left out keeps the named style's value (docs/formats.md).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct StyleSpec {
    /// `paper`, `paper-wide`, `slide` or `screen`. Default: screen.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<StyleName>,
    /// Page width (`"3.375in"`, `"86mm"`, `"243pt"`, `"640px"`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub width: Option<Length>,
    /// Page height; default: the figure's own aspect ratio.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub height: Option<Length>,
    /// Text size in points (axis labels), 4 to 72.
    #[serde(
        skip_serializing_if = "Option::is_none",
        deserialize_with = "font_size_pt"
    )]
    pub font_size: Option<f32>,
    /// `sans` or `serif`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub font: Option<FontChoice>,
    /// PNG pixels per inch, 36 to 1200.
    #[serde(skip_serializing_if = "Option::is_none", deserialize_with = "dpi")]
    pub dpi: Option<f32>,
    /// `text` or `outlines`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub text: Option<TextMode>,
}

impl StyleSpec {
    /// Whether nothing is asked (the scene file had no `[style]`).
    pub fn is_empty(&self) -> bool {
        *self == StyleSpec::default()
    }

    /// Each field of `self`, or `base`'s where `self` has none (flags over
    /// a scene file's table).
    pub fn over(self, base: StyleSpec) -> StyleSpec {
        StyleSpec {
            name: self.name.or(base.name),
            width: self.width.or(base.width),
            height: self.height.or(base.height),
            font_size: self.font_size.or(base.font_size),
            font: self.font.or(base.font),
            dpi: self.dpi.or(base.dpi),
            text: self.text.or(base.text),
        }
    }

    /// The style: the named one with the fields asked for, checked.
    /// The error names the key and what is allowed.
    pub fn resolve(&self) -> Result<Style, String> {
        let mut s = Style::named(self.name.unwrap_or_default());
        if let Some(w) = self.width {
            s.width_pt = Some(w.0);
        }
        if let Some(h) = self.height {
            if s.width_pt.is_none() {
                return Err(
                    "height: a height needs a width (or a print style such as paper)".into(),
                );
            }
            s.height_pt = Some(h.0);
        }
        if let Some(f) = self.font_size {
            if !(f.is_finite() && (4.0..=72.0).contains(&f)) {
                return Err(format!("font-size: must be between 4 and 72 pt, got {f}"));
            }
            s.font_pt = f;
        }
        if let Some(f) = self.font {
            s.font = f;
        }
        if let Some(d) = self.dpi {
            if !(d.is_finite() && (36.0..=1200.0).contains(&d)) {
                return Err(format!("dpi: must be between 36 and 1200, got {d}"));
            }
            s.dpi = d;
        }
        if let Some(t) = self.text {
            s.text = t;
        }
        Ok(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_is_the_aps_column() {
        let p = Style::named(StyleName::Paper);
        // 3.375 in × 72 pt/in = 243 pt (APS single column).
        assert_eq!(p.width_pt, Some(243.0));
        // 15 px labels at 8 pt: 15/8 px per pt; the frame is 243 × 15/8.
        assert_eq!(
            p.frame((820, 560)).0,
            (243.0f32 * 15.0 / 8.0).round() as u32
        );
        let w = p.frame((820, 560)).0 as f32;
        assert!((p.pt_per_px(w) * w - 243.0).abs() < 1e-3);
        // 300 dpi: 3.375 in → 1012.5 px.
        assert!((p.png_scale(w) * w - 1012.5).abs() < 0.01);
    }

    #[test]
    fn screen_keeps_the_pixel_layout() {
        let s = Style::default();
        assert_eq!(s.frame((820, 560)), (820, 560));
        assert!((s.pt_per_px(820.0) - 0.75).abs() < 1e-6);
        assert!((s.png_scale(820.0) - 1.0).abs() < 1e-6);
    }

    #[test]
    fn lengths() {
        assert_eq!(parse_length("3.375in"), Ok(243.0));
        assert!((parse_length("86mm").unwrap() - 86.0 / 25.4 * 72.0).abs() < 1e-3);
        assert_eq!(parse_length("243pt"), Ok(243.0));
        assert_eq!(parse_length("640px"), Ok(480.0));
        assert!(parse_length("3").is_err());
        assert!(parse_length("3 furlongs").is_err());
        assert!(parse_length("0.1in").is_err());
    }

    #[test]
    fn fit_boxes() {
        let p = Style::named(StyleName::Paper);
        // 4.5 in = 324 pt; 15/8 px per pt at 8 pt text.
        assert_eq!(p.max_height_pt(), Some(324.0));
        let (w, h) = p.fit_box().unwrap();
        assert!((w - 243.0 * 15.0 / 8.0).abs() < 1e-3 && (h - 324.0 * 15.0 / 8.0).abs() < 1e-3);
        let s = Style::named(StyleName::Slide);
        assert_eq!(s.max_height_pt(), Some(540.0));
        // 20 pt text at 20 pt: the 0.75 px per pt frame (it was twice
        // that, and slides set 20 pt text down to 10 pt).
        let (w, h) = s.fit_box().unwrap();
        assert!(
            (w - 960.0 * 0.75).abs() < 0.1 && (h - 540.0 * 0.75).abs() < 0.1,
            "{w} {h}"
        );
        assert_eq!(Style::default().fit_box(), None);
    }
}
