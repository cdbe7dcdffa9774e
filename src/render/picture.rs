//! The vector description of a picture: a small display list of fills,
//! strokes, typeset text, embedded charts (their SVG) and groups with
//! transforms, on a white page of a design size in pixels.
//!
//! Figures are drawn once into a [`Picture`] (it is a [`Canvas`]); then
//! [`Picture::rasterize`] paints it at any scale with tiny-skia (PNG), and
//! [`Picture::to_svg`] / [`Picture::to_tree`] write it as SVG, from which
//! `encode` makes the SVG and PDF files. At scale 1 the raster is the same,
//! pixel for pixel, as drawing straight onto a pixmap with [`Raster`].

use super::canvas::{Canvas, Pen, Raster};
use super::charts::Chart;
use super::page_style::Style;
use super::style::{self, HAlign, VAlign};
use super::theme::Theme;
use crate::encode::Rgb;
use crate::error::{Error, Result};
use std::sync::Arc;
use tiny_skia::{Path, Pixmap, Transform};

/// One element of a picture.
#[derive(Clone, Debug)]
pub enum Item {
    Fill {
        path: Path,
        color: Rgb,
    },
    Stroke {
        path: Path,
        pen: Pen,
    },
    /// Typeset text (markup of [`style::runs`]).
    Text {
        text: String,
        at: (f32, f32),
        size: f32,
        color: Rgb,
        align: (HAlign, VAlign),
    },
    Chart {
        chart: Arc<Chart>,
        at: (f32, f32),
    },
    /// Raster-only content; a picture holding one has no vector form.
    Image {
        image: Arc<Pixmap>,
        at: (f32, f32),
    },
    Group {
        transform: Transform,
        items: Vec<Item>,
    },
}

/// A picture: design size in pixels and the items drawn on white, in
/// order.
#[derive(Clone, Debug)]
pub struct Picture {
    width: f32,
    height: f32,
    items: Vec<Item>,
    /// The figure's theme: its style (page, font, text sizes), passed in
    /// by the figure's builder.
    theme: Theme,
    /// Groups being recorded (their transform and items so far).
    open: Vec<(Transform, Vec<Item>)>,
    /// The document's title (markup of [`style::runs`]), recorded in every
    /// file's metadata, never drawn by the encoders.
    title: Option<String>,
    /// The size of what [`Picture::fit_page`] centred on a wider page
    /// (then the picture would print smaller than the style's text).
    content: Option<(f32, f32)>,
}

/// Largest side of a raster, in pixels.
pub const MAX_RASTER_SIDE: u32 = 8192;

impl Picture {
    /// An empty white picture of `width × height` design pixels, drawn
    /// with `theme` (its text in the theme's font, its files on the
    /// theme's page).
    pub fn new(theme: &Theme, width: f32, height: f32) -> Picture {
        Picture {
            width: width.max(1.0),
            height: height.max(1.0),
            items: Vec::new(),
            theme: *theme,
            open: Vec::new(),
            title: None,
            content: None,
        }
    }

    /// The picture with `title` as its document title (the metadata of its
    /// PDF, SVG and PNG files).
    pub fn titled(mut self, title: impl Into<String>) -> Picture {
        self.title = Some(title.into());
        self
    }

    /// The document title, without markup.
    pub fn title(&self) -> Option<String> {
        self.title.as_deref().map(style::plain_text)
    }

    /// The theme the picture is drawn with.
    pub fn theme(&self) -> &Theme {
        &self.theme
    }

    /// Design width in pixels.
    pub fn width(&self) -> f32 {
        self.width
    }

    /// Design height in pixels.
    pub fn height(&self) -> f32 {
        self.height
    }

    /// The size of what the picture holds, design pixels: its own size, or
    /// when [`Picture::fit_page`] widened it with white, the content it
    /// centred.
    pub fn content_size(&self) -> (f32, f32) {
        self.content.unwrap_or((self.width, self.height))
    }

    /// Design size rounded up to whole pixels.
    pub fn pixel_size(&self) -> (u32, u32) {
        (self.width.ceil() as u32, self.height.ceil() as u32)
    }

    /// The items drawn (groups still open are not included).
    pub fn items(&self) -> &[Item] {
        &self.items
    }

    /// Whether the picture holds raster images (then it has no vector form).
    pub fn has_images(&self) -> bool {
        fn any(items: &[Item]) -> bool {
            items.iter().any(|i| match i {
                Item::Image { .. } => true,
                Item::Group { items, .. } => any(items),
                _ => false,
            })
        }
        any(&self.items)
    }

    fn current(&mut self) -> &mut Vec<Item> {
        match self.open.last_mut() {
            Some((_, items)) => items,
            None => &mut self.items,
        }
    }

    /// Replays the picture's items onto `canvas` (without the white page).
    pub fn draw(&self, canvas: &mut impl Canvas) {
        draw_items(&self.items, canvas);
    }

    /// Draws `other` with its top left at `at` (its items are copied).
    pub fn place(&mut self, other: &Picture, at: (f32, f32)) {
        self.push(Transform::from_translate(at.0, at.1));
        other.draw(self);
        self.pop();
    }

    /// The picture on the page of its theme's style:
    /// unchanged at screen; at a print style widened with white, the
    /// picture centred, to the page's width in design pixels, and further
    /// when it would print taller than [`Style::max_height_pt`] (then the
    /// whole picture prints smaller, centred on a page of that height).
    pub fn fit_page(self) -> Picture {
        let style = self.theme.style;
        let (Some(w_pt), Some(max_h)) = (style.width_pt, style.max_height_pt()) else {
            return self;
        };
        let page = w_pt * style.px_per_pt();
        let tall = self.height * w_pt / max_h;
        let width = self.width.max(page).max(tall);
        if width <= self.width + 0.5 {
            return self;
        }
        let mut out = Picture::new(&self.theme, width, self.height);
        out.place(&self, ((0.5 * (width - self.width)).floor(), 0.0));
        out.content = Some(self.content.unwrap_or((self.width, self.height)));
        out.title = self.title;
        out
    }

    /// The picture at 100 %: `pixel_size()` pixels.
    pub fn to_pixmap(&self) -> Result<Pixmap> {
        self.rasterize(1.0)
    }

    /// The picture scaled by `scale` (e.g. 2 for a sharper PNG of the same
    /// layout): the design size times `scale`, rounded up.
    pub fn rasterize(&self, scale: f32) -> Result<Pixmap> {
        let (w, h) = self.scaled_size(scale)?;
        let mut pixmap = style::white_pixmap(w, h)
            .ok_or_else(|| Error::bad_input(format!("a {w}x{h} image does not fit in memory")))?;
        let ts = if scale == 1.0 {
            Transform::identity()
        } else {
            Transform::from_scale(scale, scale)
        };
        self.draw(&mut Raster::with_transform(
            &mut pixmap,
            ts,
            self.theme.font(),
        ));
        Ok(pixmap)
    }

    /// The raster size at `scale`, checked against [`MAX_RASTER_SIDE`].
    pub fn scaled_size(&self, scale: f32) -> Result<(u32, u32)> {
        if !(scale.is_finite() && scale > 0.0) {
            return Err(Error::bad_input(format!(
                "the scale must be a number above 0, got {scale}"
            )));
        }
        // Rounding error (243 pt at 200 dpi is 675.00006 px) is no pixel.
        let up = |v: f32| (v - 1e-3).ceil().max(1.0);
        let (w, h) = (up(self.width * scale), up(self.height * scale));
        let max = MAX_RASTER_SIDE as f32;
        if w > max || h > max {
            return Err(Error::bad_input(format!(
                "at scale {scale} the image would be {w}x{h} pixels, more than \
                 {MAX_RASTER_SIDE} on a side"
            )));
        }
        Ok((w as u32, h as u32))
    }

    /// Refuses (exit 2) a picture that would print its text smaller than
    /// the style's size: one whose content is wider than the page, or
    /// taller than the page allows, at the style's scale (docs/formats.md:
    /// text is never scaled to fit). The message names the flag and the
    /// smallest size that holds this layout (a layout that moves with the
    /// size is searched by [`super::fitted`]). No style sets its text
    /// smaller (a slide's 20 pt included).
    pub fn check_print_scale(&self, style: &Style) -> Result<()> {
        match self.misfit(style) {
            None => Ok(()),
            Some((side, need)) => Err(self.refusal(style, side, need)),
        }
    }

    /// The side of the page this picture overflows at `style`'s scale, and
    /// the smallest that side may be, pt, in whole hundredths of an inch
    /// (the unit a refusal names): at that size it fits, a hundredth less
    /// it does not. `None` when it fits (or the style has no page).
    pub fn misfit(&self, style: &Style) -> Option<(PageSide, f32)> {
        let (w_pt, max_h) = (style.width_pt?, style.max_height_pt()?);
        let px_per_pt = style.px_per_pt();
        let (cw, ch) = self.content.unwrap_or((self.width, self.height));
        let (need_w, need_h) = (cw / px_per_pt, ch / px_per_pt);
        let smallest = |need_pt: f32| (need_pt / PRINT_SLACK / 0.72).ceil() * 0.72;
        if need_w > w_pt * PRINT_SLACK {
            Some((PageSide::Width, smallest(need_w)))
        } else if need_h > max_h * PRINT_SLACK {
            Some((PageSide::Height, smallest(need_h)))
        } else {
            None
        }
    }

    /// The refusal of this picture at `style` for overflowing `side`, the
    /// smallest size that holds it being `smallest_pt`.
    pub fn refusal(&self, style: &Style, side: PageSide, smallest_pt: f32) -> Error {
        let what = self
            .title()
            .filter(|t| !t.is_empty())
            .map_or("the figure".to_string(), |t| format!("\"{t}\""));
        let size = |pt: f32| format!("{:.2}in", (pt / 72.0 * 100.0).round() / 100.0);
        match side {
            PageSide::Width => Error::bad_input(format!(
                "--width {}: too narrow for {what} at {} pt text (it would print its text \
                 smaller); the smallest width that holds it is --width {}",
                size(style.width_pt.unwrap_or(0.0)),
                style.font_pt,
                size(smallest_pt)
            )),
            PageSide::Height => {
                let asked = match style.height_pt {
                    Some(h) => format!("--height {}", size(h)),
                    None => format!(
                        "the {} page budget of --style {}",
                        size(style.max_height_pt().unwrap_or(0.0)),
                        style.name.name()
                    ),
                };
                Error::bad_input(format!(
                    "{asked}: too short for {what} at {} pt text (it would print its text \
                     smaller); the smallest height that holds it is --height {}",
                    style.font_pt,
                    size(smallest_pt)
                ))
            }
        }
    }
}

/// A side of the page: what `--width` or `--height` sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PageSide {
    Width,
    Height,
}

/// Rounding of whole design pixels is no shrinking: a picture may be this
/// much larger than its page (a pixel in 200).
pub(crate) const PRINT_SLACK: f32 = 1.005;

fn draw_items(items: &[Item], canvas: &mut impl Canvas) {
    for item in items {
        match item {
            Item::Fill { path, color } => canvas.fill(path, *color),
            Item::Stroke { path, pen } => canvas.stroke(path, pen),
            Item::Text {
                text,
                at,
                size,
                color,
                align,
            } => canvas.text(text, *at, *size, *color, *align),
            Item::Chart { chart, at } => canvas.chart(chart, *at),
            Item::Image { image, at } => canvas.image(image, *at),
            Item::Group { transform, items } => {
                canvas.push(*transform);
                draw_items(items, canvas);
                canvas.pop();
            }
        }
    }
}

impl Canvas for Picture {
    fn fill(&mut self, path: &Path, color: Rgb) {
        self.current().push(Item::Fill {
            path: path.clone(),
            color,
        });
    }

    fn stroke(&mut self, path: &Path, pen: &Pen) {
        self.current().push(Item::Stroke {
            path: path.clone(),
            pen: *pen,
        });
    }

    fn text(&mut self, text: &str, at: (f32, f32), size: f32, color: Rgb, align: (HAlign, VAlign)) {
        if text.is_empty() {
            return;
        }
        self.current().push(Item::Text {
            text: text.to_string(),
            at,
            size,
            color,
            align,
        });
    }

    fn chart(&mut self, chart: &Arc<Chart>, at: (f32, f32)) {
        self.current().push(Item::Chart {
            chart: chart.clone(),
            at,
        });
    }

    fn image(&mut self, image: &Arc<Pixmap>, at: (f32, f32)) {
        self.current().push(Item::Image {
            image: image.clone(),
            at,
        });
    }

    fn push(&mut self, transform: Transform) {
        self.open.push((transform, Vec::new()));
    }

    fn pop(&mut self) {
        if let Some((transform, items)) = self.open.pop()
            && !items.is_empty()
        {
            self.current().push(Item::Group { transform, items });
        }
    }
}

impl From<Chart> for Picture {
    /// A picture of the chart's size holding the chart.
    fn from(chart: Chart) -> Picture {
        let (w, h) = (chart.pixmap.width() as f32, chart.pixmap.height() as f32);
        let mut p = Picture::new(&chart.theme, w, h);
        p.chart(&Arc::new(chart), (0.0, 0.0));
        p
    }
}

impl Picture {
    /// A raster-only picture of the image's size.
    pub fn of_image(theme: &Theme, image: Pixmap) -> Picture {
        let (w, h) = (image.width() as f32, image.height() as f32);
        let mut p = Picture::new(theme, w, h);
        p.image(&Arc::new(image), (0.0, 0.0));
        p
    }
}
