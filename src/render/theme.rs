//! One [`Theme`] value for a figure, built from its [`Style`]: every text
//! size (sub- and superscripts included), line width, marker size, margin,
//! gap and colour the drawing code uses (docs/formats.md).
//!
//! Sizes are in *design pixels*, the unit every layout works in; the style
//! fixes how many design pixels a point is ([`Style::px_per_pt`]), so a
//! theme's sizes print at the style's points. At a print style every text
//! but a title prints at the style's size (tick labels and legends
//! included, 8 pt at `paper`) and sub- and superscripts at no less than
//! [`MIN_SCRIPT_PT`]; the screen keeps its pixel sizes.
//!
//! The theme holds the one palette ([`Theme::palette`],
//! [`super::palette`]): the ladder's springs, every chart series and every
//! categorical mark ask it for the colour and marker of their role
//! ([`Theme::color`], [`Theme::marker`]).
//!
//! Floors: `theme` knows the style ([`super::page_style`]) and the
//! palette; the text and colour helpers know neither.

use super::page_style::{FontChoice, Style, StyleName};
use super::palette::{Marker, Palette, Role};
use crate::encode::Rgb;

/// Sizes at the screen style, in pixels at 100 % zoom: the base every
/// theme is derived from.
pub mod size {
    /// Figure and panel titles.
    pub const TITLE: f32 = 18.0;
    /// Axis labels, captions, time labels: the style's text size
    /// ([`super::super::page_style::DESIGN_TEXT_PX`]).
    pub const LABEL: f32 = super::super::page_style::DESIGN_TEXT_PX;
    /// Tick labels and legends (at the screen style; a print style sets
    /// them at [`LABEL`]).
    pub const TICK: f32 = 13.0;
    /// Panel labels such as "(a1)".
    pub const PANEL_LABEL: f32 = 16.0;
    /// Outer margin of composed images.
    pub const MARGIN: u32 = 12;
    /// Gap between panels.
    pub const GAP: u32 = 10;
}

/// Smallest a sub- or superscript may print, in points (docs/formats.md).
pub const MIN_SCRIPT_PT: f32 = 5.0;

/// Size of super- and subscripts relative to their text.
pub const SCRIPT_SCALE: f32 = 0.7;

/// Everything a figure's drawing code sizes and colours by.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Theme {
    /// The style the theme was built from.
    pub style: Style,
    /// The colours and markers of every role.
    pub palette: Palette,
    /// Whether titles are drawn inside the figure: at `screen` and
    /// `slide`; journal styles leave the title to the caption.
    pub titles: bool,
    /// Design pixels per point.
    pub px_per_pt: f32,
    /// Titles (screen and slide only).
    pub title: f32,
    /// Axis labels, captions, time labels.
    pub label: f32,
    /// Tick labels, legends, marks' words, block numbers.
    pub tick: f32,
    /// Panel labels "(a)", "(b1)".
    pub panel_label: f32,
    /// Least clearance between a panel label and the text of its panel,
    /// design pixels: a quarter of the label's size (3.75 px, 2 pt at
    /// `paper`), so that "(a)" reads apart from the axis label under it.
    pub panel_label_clear: f32,
    /// Smallest text other than scripts, in design pixels: the style's
    /// size at a print style.
    pub min_text: f32,
    /// Smallest a sub- or superscript may be, in design pixels.
    pub min_script: f32,
    /// Data lines.
    pub line: f32,
    /// Axes, frames.
    pub thin: f32,
    /// Marker radius.
    pub marker: f32,
    /// Outer margin.
    pub margin: f32,
    /// Blank margin a chart keeps on each side inside its own box, design
    /// pixels (14 px at every style): room for the half of an end tick
    /// label that reaches past the plot.
    pub chart_margin: f32,
    /// The blank margin above and below a chart's own box, design pixels:
    /// [`Theme::chart_margin`] (14 px) at screen and slide; at a print
    /// style 0.6 of the tick text's size (9 px at `paper`), room for the
    /// half of the top tick label that reaches above the plot, so that
    /// stacked panels give their height to the plots (docs/formats.md).
    pub chart_margin_y: f32,
    /// Least width of a chart's y label area (64 px): tick labels, ticks
    /// and the rotated axis label (wider where the tick labels need it).
    pub y_label_area: u32,
    /// Height of a chart's x label area (50 px): tick labels and the
    /// axis label under them.
    pub x_label_area: u32,
    /// Height of the x label area of a panel whose x axis is shared with
    /// the panel below (4 px: its ticks only, the labels are below).
    pub shared_x_area: u32,
    /// Height of the x label area of a stacked panel whose shared x axis
    /// keeps its numbers ([`crate::render::Axis::shared_numbered`]: the
    /// sweeps' panels): 1.3 tick sizes and 6 px.
    pub numbered_x_area: u32,
    /// Pixels a y tick mark and its gap take beside the tick labels (10).
    pub tick_gap: f32,
    /// The rotated y axis label's line, in ems of [`Theme::label`] (1.3).
    pub axis_label_line_em: f32,
    /// Pixels between the rotated y axis label and the area's edge (6).
    pub axis_label_gap: f32,
    /// A legend row right of the plot or inside it, in ems of
    /// [`Theme::tick`] (1.55: the line and room for a marker).
    pub legend_row_em: f32,
    /// A legend row under the plot, in ems of [`Theme::tick`] (1.45).
    pub below_row_em: f32,
    /// Pixels between a chart's plot and a legend right of it (12).
    pub legend_gap: i32,
    /// Pixels kept beside a legend column right of the plot when its
    /// room is made and when deciding whether it fits (8).
    pub legend_gap_min: u32,
    /// Composed figures' bands, in ems (multiples of the text size they
    /// hold, so that they follow the style's text size): the label band
    /// above a panel, 1.5 panel-label sizes (the label's line and a gap).
    pub label_band_em: f32,
    /// A caption band below a panel: 0.5 em of lead plus
    /// [`Theme::caption_line_em`] per line (see [`Theme::caption_band`]).
    pub caption_lead_em: f32,
    /// Distance between the lines of a caption, 1.2 em (the line height).
    pub caption_line_em: f32,
    /// Where a caption's first line starts below its image, 0.3 em.
    pub caption_top_em: f32,
    /// Pixels a panel label is set in from its cell's left edge (2 px):
    /// clear of the cell's edge, in line with the picture under it.
    pub panel_label_inset: f32,
    /// Words of a filmstrip's marks ("kink", "collision"): 11 px, and at a
    /// print style at least the style's text size (docs/formats.md).
    pub mark_text: f32,
    /// Pixels from the chain to a filmstrip mark's tip (3 px): the
    /// triangle points at the chain without touching it.
    pub mark_clear: f32,
    /// Length of a mark's triangle, tip to base (7 px).
    pub mark_arrow: f32,
    /// Half the height of a mark's triangle at its base (4.5 px: a
    /// triangle 9 px tall, about as tall as a block is thick).
    pub mark_half: f32,
    /// Pixels between a mark's triangle and its words (2 px).
    pub mark_space: f32,
    /// Pixels left beyond a mark's words when room is made for them
    /// beside a folded ladder's columns (2 px).
    pub mark_slack: f32,
    /// Block numbers above the columns of a folded ladder: 10 px, and at a
    /// print style at least the style's text size.
    pub column_number: f32,
    /// The band the block numbers take above a folded snapshot's columns,
    /// in ems of [`Theme::column_number`] (1.5: the line and a gap).
    pub column_number_band_em: f32,
    /// The caption band under a row of folded snapshots when counting how
    /// many rows fit a picture, in ems of [`Theme::label`] (1.7).
    pub folded_caption_em: f32,
    /// Pixels between a folded snapshot's frame and what it holds (4 px).
    pub folded_pad: f32,
    /// Gap between the snapshots of a filmstrip (6 px).
    pub snapshot_gap: u32,
    /// Gap between folded snapshots (24 px): more than between whole
    /// ladders, so that one snapshot's columns group visibly.
    pub folded_snapshot_gap: u32,
    /// Margin of a filmstrip fitted into a box (4 px; its figure has its
    /// own [`Theme::margin`]).
    pub fit_margin: u32,
    /// Smallest width and height of a snapshot of a strip fitted into a
    /// box (8 × 24 px): a way to wrap the snapshots that leaves them
    /// smaller is not taken.
    pub min_snapshot: (f32, f32),
    /// Pixels a time caption may be wider than its snapshot and the gap
    /// beside it fall short by before it goes on two lines (2 px).
    pub caption_slack: f32,
    /// Gap between panels.
    pub gap: f32,
    /// Tallest a figure may print, in points (none at screen).
    pub max_height_pt: Option<f32>,
}

/// The sizes of a style's text, design pixels: every text but titles at
/// the style's size at a print style (docs/formats.md), the screen's own
/// sizes there.
struct TextSizes {
    print: bool,
    px_per_pt: f32,
    /// `paper` or `paper-wide`: no titles inside the figure.
    journal: bool,
    title: f32,
    tick: f32,
    panel_label: f32,
    min_text: f32,
    min_script: f32,
}

impl TextSizes {
    fn of(style: &Style) -> TextSizes {
        let print = style.is_print();
        let px_per_pt = style.px_per_pt();
        let pick = |at_print: f32, at_screen: f32| if print { at_print } else { at_screen };
        TextSizes {
            print,
            px_per_pt,
            journal: matches!(style.name, StyleName::Paper | StyleName::PaperWide),
            title: pick(size::LABEL, size::TITLE),
            tick: pick(size::LABEL, size::TICK),
            panel_label: pick(size::LABEL, size::PANEL_LABEL),
            min_text: pick(style.font_pt * px_per_pt, 0.0),
            min_script: pick(MIN_SCRIPT_PT * px_per_pt, 0.0),
        }
    }
}

impl Theme {
    /// The theme of `style`: the sizes of its text ([`TextSizes`]: what
    /// the style decides), then every length, gap and band the figures
    /// derive from them.
    pub fn of(style: &Style) -> Theme {
        let TextSizes {
            print,
            px_per_pt,
            journal,
            title,
            tick,
            panel_label,
            min_text,
            min_script,
        } = TextSizes::of(style);
        Theme {
            style: *style,
            palette: Palette,
            titles: !journal,
            px_per_pt,
            // Titles and panel titles at a print style: the text's size.
            title,
            label: size::LABEL,
            tick,
            panel_label,
            panel_label_clear: 0.25 * panel_label,
            min_text,
            min_script,
            line: 2.0,
            thin: 1.0,
            marker: 4.0,
            margin: size::MARGIN as f32,
            chart_margin: 14.0,
            chart_margin_y: if print {
                (0.6 * tick).ceil().min(14.0)
            } else {
                14.0
            },
            y_label_area: 64,
            x_label_area: 50,
            shared_x_area: 4,
            numbered_x_area: (1.3 * tick + 6.0).ceil() as u32,
            tick_gap: 10.0,
            axis_label_line_em: 1.3,
            axis_label_gap: 6.0,
            legend_row_em: 1.55,
            below_row_em: 1.45,
            legend_gap: 12,
            legend_gap_min: 8,
            label_band_em: 1.5,
            caption_lead_em: 0.5,
            caption_line_em: 1.2,
            caption_top_em: 0.3,
            panel_label_inset: 2.0,
            mark_text: 11.0f32.max(min_text),
            mark_clear: 3.0,
            mark_arrow: 7.0,
            mark_half: 4.5,
            mark_space: 2.0,
            mark_slack: 2.0,
            column_number: 10.0f32.max(min_text),
            column_number_band_em: 1.5,
            folded_caption_em: 1.7,
            folded_pad: 4.0,
            snapshot_gap: 6,
            folded_snapshot_gap: 24,
            fit_margin: 4,
            min_snapshot: (8.0, 24.0),
            caption_slack: 2.0,
            gap: size::GAP as f32,
            max_height_pt: style.max_height_pt(),
        }
    }

    /// Height of the band a title (one line) takes above what it names.
    pub fn title_band(&self) -> f32 {
        if self.is_print() {
            (1.5 * self.title).floor()
        } else {
            (1.8 * self.title).floor()
        }
    }

    /// Height of the label band above a composed panel: [`Theme::label_band_em`]
    /// panel-label sizes, whole pixels.
    pub fn label_band(&self) -> u32 {
        (self.panel_label * self.label_band_em) as u32
    }

    /// Height of the caption band under a composed panel whose caption
    /// has `lines` lines (not rounded).
    pub fn caption_band(&self, lines: f32) -> f32 {
        self.label * (self.caption_lead_em + self.caption_line_em * lines)
    }

    /// The font text is set in.
    pub fn font(&self) -> FontChoice {
        self.style.font
    }

    /// Whether this is a print style.
    pub fn is_print(&self) -> bool {
        self.style.is_print()
    }

    /// `px` pixels, or at a print style at least the style's text size
    /// (for words drawn on pictures: marks, block numbers, time labels).
    pub fn text_at_least(&self, px: f32) -> f32 {
        px.max(self.min_text)
    }

    /// The size of a run of text at `size` shifted into a sub- or
    /// superscript: [`SCRIPT_SCALE`] of it, and at a print style no less
    /// than [`MIN_SCRIPT_PT`].
    pub fn script(&self, size: f32) -> f32 {
        (size * SCRIPT_SCALE).max(self.min_script.min(size))
    }

    /// The colour of `role` ([`Palette::color`]).
    pub fn color(&self, role: Role) -> Rgb {
        self.palette.color(role)
    }

    /// The colour of words in `role`'s colour, readable on white
    /// ([`Palette::text`]).
    pub fn text_color(&self, role: Role) -> Rgb {
        self.palette.text(role)
    }

    /// The marker of `role`, open for an antikink ([`Palette::marker`]).
    pub fn marker(&self, role: Role, antikink: bool) -> Marker {
        self.palette.marker(role, antikink)
    }

    /// Points per design pixel at the style's own scale.
    pub fn pt_per_px(&self) -> f32 {
        1.0 / self.px_per_pt
    }
}

/// CIE 1976 colour difference ΔE*ab of two sRGB colours (D65): about 2.3
/// is a just noticeable difference; categorical colours want 20 or more.
pub fn delta_e(a: Rgb, b: Rgb) -> f64 {
    let (p, q) = (lab(a), lab(b));
    ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
}

/// CIELAB (D65) of an sRGB colour.
fn lab(c: Rgb) -> [f64; 3] {
    let lin = |v: u8| {
        let v = v as f64 / 255.0;
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    let (r, g, b) = (lin(c[0]), lin(c[1]), lin(c[2]));
    let x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
    let y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    let z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
    let f = |t: f64| {
        if t > 216.0 / 24389.0 {
            t.cbrt()
        } else {
            (24389.0 / 27.0 * t + 16.0) / 116.0
        }
    };
    let (fx, fy, fz) = (f(x), f(y), f(z));
    [116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_sets_every_text_at_the_style_size_and_no_title() {
        let t = Theme::of(&Style::named(StyleName::Paper));
        assert!(!t.titles);
        // 15 px at 15/8 px per pt: 8 pt, tick labels included.
        assert!((t.tick * t.pt_per_px() - 8.0).abs() < 1e-4);
        assert!((t.label * t.pt_per_px() - 8.0).abs() < 1e-4);
        // Scripts: 0.7 × 8 = 5.6 pt ≥ 5 pt.
        assert!(t.script(t.tick) * t.pt_per_px() >= MIN_SCRIPT_PT);
        // A 9 pt style's scripts: 6.3 pt; a 6 pt one's: held at 5 pt.
        let mut small = Style::named(StyleName::Paper);
        small.font_pt = 6.0;
        let s = Theme::of(&small);
        assert!((s.script(s.tick) * s.pt_per_px() - 5.0).abs() < 1e-4);
    }

    #[test]
    fn screen_and_slide_keep_titles_and_screen_its_pixels() {
        let screen = Theme::of(&Style::default());
        assert!(screen.titles);
        assert_eq!(screen.tick, size::TICK);
        assert!(Theme::of(&Style::named(StyleName::Slide)).titles);
    }

    #[test]
    fn the_springs_take_two_palette_colours() {
        use crate::render::palette::named::SERIES;
        let t = Theme::of(&Style::default());
        assert!(SERIES.contains(&t.color(Role::SpringA)));
        assert!(SERIES.contains(&t.color(Role::SpringB)));
        assert_ne!(t.color(Role::SpringA), t.color(Role::SpringB));
    }
}
