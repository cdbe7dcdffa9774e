//! Where a picture's text lies: the box of every text, from the picture's
//! own display list (canvas text measured with the style's font, chart text
//! from the layout of the chart's parsed SVG), in design pixels, with its
//! size; and the layout rules of docs/formats.md checked on them: every box
//! inside the page, no two boxes overlapping, no text under 6 pt at a print
//! style.

use super::page_style::{FontChoice, MIN_PRINT_TEXT_PT, Style};
use super::picture::{Item, Picture};
use super::style;
use resvg::usvg;
use tiny_skia::{Point, Transform};

/// The least width and height of a chart's plot, in tick text sizes
/// (60 px at 15 px ticks): room for two tick labels and the data between.
pub const MIN_PLOT_EM: f32 = 4.0;

/// One text's box on the page, design pixels.
#[derive(Clone, Debug, PartialEq)]
pub struct TextBox {
    /// The text without markup.
    pub text: String,
    /// Left, top, right, bottom.
    pub rect: [f32; 4],
    /// Font size in design pixels (the main run, before super/subscripts).
    pub size: f32,
}

impl TextBox {
    /// Whether the two boxes share more than `slack` pixels each way.
    pub fn overlaps(&self, other: &TextBox, slack: f32) -> bool {
        let [a0, a1, a2, a3] = self.rect;
        let [b0, b1, b2, b3] = other.rect;
        a0.max(b0) + slack < a2.min(b2) && a1.max(b1) + slack < a3.min(b3)
    }
}

impl Picture {
    /// The box of every non-blank text of the picture, in drawing order.
    pub fn text_boxes(&self) -> Vec<TextBox> {
        let mut out = Vec::new();
        collect(
            self.theme().font(),
            self.items(),
            Transform::identity(),
            &mut out,
        );
        out
    }

    /// Whether the picture's layout is too tight to read at its size: a
    /// text leaving the picture, two texts overlapping, or a chart's plot
    /// narrower or shorter than [`MIN_PLOT_EM`] tick sizes (the energy
    /// view 1 in wide once collapsed its plot). A figure drawn on a page
    /// of the user's that is crowded is refused, naming a size at which it
    /// is not ([`super::fitted`]).
    /// `Some(PageSide::Width)` when a text leaves the picture's side,
    /// `Some(PageSide::Height)` when it is crowded otherwise.
    pub fn crowded(&self) -> Option<super::PageSide> {
        let boxes = self.text_boxes();
        let (w, h) = (self.width(), self.height());
        let tol = 0.5;
        let across = boxes
            .iter()
            .any(|b| b.rect[0] < -tol || b.rect[2] > w + tol);
        if across {
            return Some(super::PageSide::Width);
        }
        let down = boxes
            .iter()
            .any(|b| b.rect[1] < -tol || b.rect[3] > h + tol);
        let overlap = boxes
            .iter()
            .enumerate()
            .any(|(i, a)| boxes[i + 1..].iter().any(|b| a.overlaps(b, 1.0)));
        (down || overlap || self.plot_collapsed()).then_some(super::PageSide::Height)
    }

    /// Whether a chart of the picture has a plot narrower or shorter than
    /// [`MIN_PLOT_EM`] of its tick text.
    fn plot_collapsed(&self) -> bool {
        fn any(items: &[Item]) -> bool {
            items.iter().any(|i| match i {
                Item::Chart { chart, .. } => {
                    let least = MIN_PLOT_EM * chart.theme.tick;
                    let short =
                        |s: Option<(i32, i32)>| s.is_some_and(|(a, b)| ((b - a) as f32) < least);
                    short(chart.plot_x) || short(chart.plot_y)
                }
                Item::Group { items, .. } => any(items),
                _ => false,
            })
        }
        any(self.items())
    }

    /// The plot of every chart of the picture (where its data is drawn,
    /// inside the axes) as left, top, right, bottom in the picture's design
    /// pixels, in drawing order.
    pub fn plot_boxes(&self) -> Vec<[f32; 4]> {
        fn walk(items: &[Item], ts: Transform, out: &mut Vec<[f32; 4]>) {
            for i in items {
                match i {
                    Item::Chart { chart, at } => {
                        if let (Some(x), Some(y)) = (chart.plot_x, chart.plot_y) {
                            let ts = ts.pre_translate(at.0, at.1);
                            let mut p = [
                                Point::from_xy(x.0 as f32, y.0 as f32),
                                Point::from_xy(x.1 as f32, y.1 as f32),
                            ];
                            ts.map_points(&mut p);
                            out.push([p[0].x, p[0].y, p[1].x, p[1].y]);
                        }
                    }
                    Item::Group { transform, items } => walk(items, ts.pre_concat(*transform), out),
                    _ => {}
                }
            }
        }
        let mut out = Vec::new();
        walk(self.items(), Transform::identity(), &mut out);
        out
    }

    /// What breaks the layout rules at `style`, one line each (empty: none).
    /// Text is measured in the picture's font, as it was laid out.
    pub fn layout_problems(&self, style: &Style) -> Vec<String> {
        let boxes = self.text_boxes();
        let (w, h) = (self.width(), self.height());
        let pt = style.pt_per_px(w);
        let mut problems = Vec::new();
        if let Some(max) = style.max_height_pt()
            && h * pt > max + 0.5
        {
            problems.push(format!(
                "the page is {:.0} pt tall, more than {max:.0} pt",
                h * pt
            ));
        }
        let tol = 0.5;
        for b in &boxes {
            let [x0, y0, x1, y1] = b.rect;
            if x0 < -tol || y0 < -tol || x1 > w + tol || y1 > h + tol {
                problems.push(format!(
                    "\"{}\" leaves the page: box {:?}, page {w}×{h}",
                    b.text, b.rect
                ));
            }
            if style.is_print() && b.size * pt < MIN_PRINT_TEXT_PT - 0.01 {
                problems.push(format!(
                    "\"{}\" prints at {:.1} pt, under {MIN_PRINT_TEXT_PT} pt",
                    b.text,
                    b.size * pt
                ));
            }
        }
        for (i, a) in boxes.iter().enumerate() {
            for b in &boxes[i + 1..] {
                if a.overlaps(b, 1.0) {
                    problems.push(format!(
                        "\"{}\" {:?} overlaps \"{}\" {:?}",
                        a.text, a.rect, b.text, b.rect
                    ));
                }
            }
        }
        problems
    }
}

fn collect(font: FontChoice, items: &[Item], ts: Transform, out: &mut Vec<TextBox>) {
    for item in items {
        match item {
            Item::Text {
                text,
                at,
                size,
                align,
                ..
            } => {
                let plain = style::plain_text(text);
                if plain.trim().is_empty() {
                    continue;
                }
                let width = style::text_width(font, text, *size);
                let (left, baseline) = style::text_origin(font, *at, width, *size, *align);
                let has = |mark: &str| text.contains(mark);
                let top = baseline
                    - style::ascent(font, *size).max(if has("^{") {
                        (style::SUPER_RISE + 0.75 * style::SCRIPT_SCALE) * size
                    } else {
                        0.0
                    });
                let bottom = baseline
                    + if has("_{") {
                        (style::SUB_DROP + 0.25 * style::SCRIPT_SCALE) * size
                    } else {
                        0.24 * size
                    };
                out.push(placed(plain, [left, top, left + width, bottom], *size, ts));
            }
            Item::Chart { chart, at } => {
                if let Some(tree) = chart.tree() {
                    let ts = ts.pre_translate(at.0, at.1);
                    chart_text(tree.root(), ts, out);
                }
            }
            Item::Group { transform, items } => {
                collect(font, items, ts.pre_concat(*transform), out)
            }
            Item::Fill { .. } | Item::Stroke { .. } | Item::Image { .. } => {}
        }
    }
}

/// The boxes of a chart's texts (their layout in the parsed SVG).
fn chart_text(group: &usvg::Group, ts: Transform, out: &mut Vec<TextBox>) {
    for node in group.children() {
        match node {
            usvg::Node::Group(g) => chart_text(g, ts, out),
            usvg::Node::Text(t) => {
                let text: String = t.chunks().iter().map(|c| c.text()).collect();
                if text.trim().is_empty() {
                    continue;
                }
                let size = t.layouted().first().map_or(0.0, |s| s.font_size.get())
                    * t.abs_transform()
                        .get_scale()
                        .1
                        .max(t.abs_transform().get_scale().0);
                let r = t.abs_bounding_box();
                out.push(placed(
                    text,
                    [r.left(), r.top(), r.right(), r.bottom()],
                    size,
                    ts,
                ));
            }
            usvg::Node::Path(_) | usvg::Node::Image(_) => {}
        }
    }
}

/// A box under `ts` (translation and uniform scale in our pictures).
fn placed(text: String, [x0, y0, x1, y1]: [f32; 4], size: f32, ts: Transform) -> TextBox {
    let mut p = [Point::from_xy(x0, y0), Point::from_xy(x1, y1)];
    ts.map_points(&mut p);
    let scale = ts.get_scale().0.max(ts.get_scale().1);
    TextBox {
        text,
        rect: [
            p[0].x.min(p[1].x),
            p[0].y.min(p[1].y),
            p[0].x.max(p[1].x),
            p[0].y.max(p[1].y),
        ],
        size: size * scale,
    }
}
