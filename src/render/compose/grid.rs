//! Panels in a grid with labels such as "(a1)" and captions, a common
//! margin and title.

use crate::error::{Error, Result};
use crate::render::canvas::Canvas;
use crate::render::palette::{Palette, Role};
use crate::render::picture::Picture;
use crate::render::snapshot::{self, Region, Snapshot};
use crate::render::style::{HAlign, VAlign, text_width};
use crate::render::theme::Theme;
use tiny_skia::{Pixmap, PixmapPaint, Transform};

/// One picture of a composition with an optional label above it (drawn at
/// its top left, e.g. "(a1)") and an optional caption centred below it
/// (one line per `\n`).
pub struct Panel {
    pub image: Picture,
    pub label: Option<String>,
    pub caption: Option<String>,
}

impl Panel {
    /// A panel without label or caption: a [`Picture`], a chart, or a
    /// raster image (which keeps the composition raster-only).
    pub fn new(image: impl Into<Picture>) -> Panel {
        Panel {
            image: image.into(),
            label: None,
            caption: None,
        }
    }

    /// Sets the label drawn above the image.
    pub fn label(mut self, label: impl Into<String>) -> Panel {
        self.label = Some(label.into());
        self
    }

    /// Sets the caption drawn below the image.
    pub fn caption(mut self, caption: impl Into<String>) -> Panel {
        self.caption = Some(caption.into());
        self
    }
}

/// Grid layout options.
#[derive(Clone, Debug)]
pub struct Layout {
    /// Panels per row (at least 1).
    pub columns: usize,
    /// Title centred above everything.
    pub title: Option<String>,
    /// Outer margin in pixels.
    pub margin: u32,
    /// Gap between panels in pixels.
    pub gap: u32,
    /// The figure's theme: the sizes of titles, labels and captions, the
    /// font of the composed picture.
    pub theme: Theme,
}

impl Layout {
    /// `columns` panels per row, the margin and gap of `theme`, no title.
    pub fn columns(theme: &Theme, columns: usize) -> Layout {
        Layout {
            columns,
            title: None,
            margin: theme.margin as u32,
            gap: theme.gap as u32,
            theme: *theme,
        }
    }

    /// One row holding every panel.
    pub fn row(theme: &Theme, count: usize) -> Layout {
        Layout::columns(theme, count.max(1))
    }

    /// Sets the title.
    pub fn title(mut self, title: impl Into<String>) -> Layout {
        self.title = Some(title.into());
        self
    }
}

/// Heights of the label band above and the caption band below each image.
fn bands(theme: &Theme, panels: &[Panel]) -> (u32, u32) {
    let label = panels.iter().any(|p| p.label.is_some());
    let caption = panels.iter().any(|p| p.caption.is_some());
    let l = if label { theme.label_band() } else { 0 };
    let lines = panels
        .iter()
        .filter_map(|p| p.caption.as_ref())
        .map(|c| c.lines().count().max(1))
        .max()
        .unwrap_or(0);
    let c = if caption {
        theme.caption_band(lines as f32) as u32
    } else {
        0
    };
    (l, c)
}

/// Places panels in a grid (row-major) and rasterises the result at 100 %.
pub fn compose(panels: &[Panel], layout: &Layout) -> Result<Pixmap> {
    compose_picture(panels, layout)?.to_pixmap()
}

/// The distance between a wrapped title's lines, in ems.
const LINE_EM: f32 = 1.2;

/// Where a grid puts its panels: the picture's size, the title band's
/// height, and for each panel its cell's top left corner and size.
pub(super) struct Grid {
    pub(super) width: u32,
    pub(super) height: u32,
    cells: Vec<((u32, u32), (u32, u32))>,
    bands: (u32, u32),
    /// The title's lines, wrapped to the grid's width (never shrunk).
    title: Vec<String>,
}

impl Grid {
    pub(super) fn new(panels: &[Panel], layout: &Layout) -> Result<Grid> {
        if panels.is_empty() || layout.columns == 0 {
            return Err(Error::bad_input(
                "a composition needs at least one panel and one column",
            ));
        }
        let cols = layout.columns.min(panels.len());
        let rows = panels.len().div_ceil(cols);
        let mut col_w = vec![0u32; cols];
        let mut row_h = vec![0u32; rows];
        let theme = &layout.theme;
        for (k, p) in panels.iter().enumerate() {
            let (w, h) = p.image.pixel_size();
            // A column holds its widest picture and its widest caption
            // line (with a gap's room between neighbours' captions): a
            // caption never runs under the next panel's.
            let caption_w = p
                .caption
                .iter()
                .flat_map(|c| c.lines())
                .fold(0.0f32, |a, l| {
                    a.max(text_width(theme.font(), l, theme.label))
                });
            let w = w.max(caption_w.ceil() as u32);
            col_w[k % cols] = col_w[k % cols].max(w);
            row_h[k / cols] = row_h[k / cols].max(h);
        }
        let (label_h, caption_h) = bands(&layout.theme, panels);
        let (m, g) = (layout.margin, layout.gap);
        let width = 2 * m + col_w.iter().sum::<u32>() + (cols as u32 - 1) * g;
        // A title wider than the grid goes on more lines (a title once
        // left a narrow page on both sides).
        let title = layout.title.as_ref().map_or_else(Vec::new, |t| {
            let room = width.saturating_sub(2 * m).max(1) as f32;
            if text_width(theme.font(), t, theme.title) <= room {
                vec![t.clone()]
            } else {
                crate::render::style::wrap_text(theme.font(), t, room, theme.title)
            }
        });
        let title_h = match title.len() {
            0 => 0,
            k => (theme.title_band() + (k - 1) as f32 * LINE_EM * theme.title) as u32,
        };
        let cells_h: u32 = row_h.iter().map(|h| h + label_h + caption_h).sum();
        let height = 2 * m + title_h + cells_h + (rows as u32 - 1) * g;
        if width > crate::render::picture::MAX_RASTER_SIDE
            || height > crate::render::picture::MAX_RASTER_SIDE
        {
            return Err(snapshot::bad_size(width, height));
        }
        let offsets = |sizes: &[u32], extra: u32| -> Vec<u32> {
            sizes
                .iter()
                .scan(0, |acc, s| {
                    let at = *acc;
                    *acc += s + extra + g;
                    Some(at)
                })
                .collect()
        };
        let (xs, ys) = (offsets(&col_w, 0), offsets(&row_h, label_h + caption_h));
        let cells = (0..panels.len())
            .map(|k| {
                let (c, r) = (k % cols, k / cols);
                ((m + xs[c], m + title_h + ys[r]), (col_w[c], row_h[r]))
            })
            .collect();
        Ok(Grid {
            width,
            height,
            cells,
            bands: (label_h, caption_h),
            title,
        })
    }

    /// Top left corner of panel `k`'s image, centred in its cell.
    pub(super) fn image_origin(&self, k: usize, image: (u32, u32)) -> (u32, u32) {
        let ((x, y), (cw, ih)) = self.cells[k];
        (
            x + (cw - image.0) / 2,
            y + self.bands.0 + (ih - image.1) / 2,
        )
    }
}

/// Places panels in a grid (row-major). Each column is as wide as its
/// widest picture and each row as tall as its tallest; pictures are
/// centred in their cells.
pub fn compose_picture(panels: &[Panel], layout: &Layout) -> Result<Picture> {
    let grid = Grid::new(panels, layout)?;
    let (width, m) = (grid.width, layout.margin);
    let theme = &layout.theme;
    let mut out = Picture::new(theme, width as f32, grid.height as f32);
    for (k, t) in grid.title.iter().enumerate() {
        let at = (
            0.5 * width as f32,
            m as f32 + k as f32 * LINE_EM * theme.title,
        );
        let size = theme.title;
        out.text(
            t,
            at,
            size,
            theme.color(Role::Ink),
            (HAlign::Center, VAlign::Top),
        );
    }
    for (k, p) in panels.iter().enumerate() {
        let at = grid.image_origin(k, p.image.pixel_size());
        draw_panel(theme, &mut out, p, at, grid.cells[k], grid.bands);
    }
    Ok(out)
}

fn draw_panel(
    theme: &Theme,
    out: &mut Picture,
    p: &Panel,
    (ix, iy): (u32, u32),
    ((x, y), (cw, ih)): ((u32, u32), (u32, u32)),
    (lh, _ch): (u32, u32),
) {
    out.place(&p.image, (ix as f32, iy as f32));
    if let Some(l) = &p.label {
        let at = (x as f32 + theme.panel_label_inset, y as f32);
        out.text(
            l,
            at,
            theme.panel_label,
            Palette.color(Role::Ink),
            (HAlign::Left, VAlign::Top),
        );
    }
    if let Some(c) = &p.caption {
        // One text per line, each centred under the image.
        for (k, line) in c.lines().enumerate() {
            let at = (
                x as f32 + 0.5 * cw as f32,
                (y + lh + ih) as f32
                    + (theme.caption_top_em + theme.caption_line_em * k as f32) * theme.label,
            );
            out.text(
                line,
                at,
                theme.label,
                Palette.color(Role::Ink),
                (HAlign::Center, VAlign::Top),
            );
        }
    }
}

/// Copies `src` onto `dst` with its top left at (`x`, `y`).
pub fn blit(dst: &mut Pixmap, src: &Pixmap, x: u32, y: u32) {
    dst.draw_pixmap(
        x as i32,
        y as i32,
        src.as_ref(),
        &PixmapPaint::default(),
        Transform::identity(),
        None,
    );
}

/// A composition's size and the top left corner of each panel's image.
pub type Placement = ((u32, u32), Vec<(u32, u32)>);

/// The top left corners of `panels` composed with `layout`, and the size
/// of the composition (see [`compose_picture`]).
pub fn panel_origins(panels: &[Panel], layout: &Layout) -> Result<Placement> {
    let grid = Grid::new(panels, layout)?;
    let origins = panels
        .iter()
        .enumerate()
        .map(|(k, p)| grid.image_origin(k, p.image.pixel_size()))
        .collect();
    Ok(((grid.width, grid.height), origins))
}

/// Draws several snapshots into one canvas region by region (no captions):
/// the building block for custom layouts, their text in `theme`'s font.
pub fn draw_snapshots(theme: &Theme, canvas: &mut Pixmap, items: &[(Region, Snapshot<'_>)]) {
    for (r, s) in items {
        snapshot::draw_snapshot(theme, canvas, *r, s);
    }
}
