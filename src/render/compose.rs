//! Composition: panels in a grid with labels such as "(a1)" and captions,
//! a common margin and title; filmstrips of snapshots side by side (paper
//! Fig. 1c and Fig. 3).

use super::canvas::Canvas;
use super::picture::Picture;
use super::snapshot::{self, Region, Snapshot, View};
use super::style::{DARK, HAlign, VAlign, size};
use crate::error::{Error, Result};
use crate::model::Ladder;
use tiny_skia::{Pixmap, PixmapPaint, Transform};

/// One picture of a composition with an optional label above it (drawn at
/// its top left, e.g. "(a1)") and an optional caption centred below it.
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
}

impl Layout {
    /// `columns` panels per row, the default margin and gap, no title.
    pub fn columns(columns: usize) -> Layout {
        Layout {
            columns,
            title: None,
            margin: size::MARGIN,
            gap: size::GAP,
        }
    }

    /// One row holding every panel.
    pub fn row(count: usize) -> Layout {
        Layout::columns(count.max(1))
    }

    /// Sets the title.
    pub fn title(mut self, title: impl Into<String>) -> Layout {
        self.title = Some(title.into());
        self
    }
}

/// Heights of the label band above and the caption band below each image.
fn bands(panels: &[Panel]) -> (u32, u32) {
    let label = panels.iter().any(|p| p.label.is_some());
    let caption = panels.iter().any(|p| p.caption.is_some());
    let l = if label {
        (size::PANEL_LABEL * 1.5) as u32
    } else {
        0
    };
    let c = if caption {
        (size::LABEL * 1.7) as u32
    } else {
        0
    };
    (l, c)
}

/// Places panels in a grid (row-major) and rasterises the result at 100 %.
pub fn compose(panels: &[Panel], layout: &Layout) -> Result<Pixmap> {
    compose_picture(panels, layout)?.to_pixmap()
}

/// Where a grid puts its panels: the picture's size, the title band's
/// height, and for each panel its cell's top left corner and size.
struct Grid {
    width: u32,
    height: u32,
    cells: Vec<((u32, u32), (u32, u32))>,
    bands: (u32, u32),
}

impl Grid {
    fn new(panels: &[Panel], layout: &Layout) -> Result<Grid> {
        if panels.is_empty() || layout.columns == 0 {
            return Err(Error::bad_input(
                "a composition needs at least one panel and one column",
            ));
        }
        let cols = layout.columns.min(panels.len());
        let rows = panels.len().div_ceil(cols);
        let mut col_w = vec![0u32; cols];
        let mut row_h = vec![0u32; rows];
        for (k, p) in panels.iter().enumerate() {
            let (w, h) = p.image.pixel_size();
            col_w[k % cols] = col_w[k % cols].max(w);
            row_h[k / cols] = row_h[k / cols].max(h);
        }
        let (label_h, caption_h) = bands(panels);
        let title_h = layout
            .title
            .as_ref()
            .map_or(0, |_| (size::TITLE * 1.8) as u32);
        let (m, g) = (layout.margin, layout.gap);
        let width = 2 * m + col_w.iter().sum::<u32>() + (cols as u32 - 1) * g;
        let cells_h: u32 = row_h.iter().map(|h| h + label_h + caption_h).sum();
        let height = 2 * m + title_h + cells_h + (rows as u32 - 1) * g;
        if width > super::picture::MAX_RASTER_SIDE || height > super::picture::MAX_RASTER_SIDE {
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
        })
    }

    /// Top left corner of panel `k`'s image, centred in its cell.
    fn image_origin(&self, k: usize, image: (u32, u32)) -> (u32, u32) {
        let ((x, y), (cw, ih)) = self.cells[k];
        (x + (cw - image.0) / 2, y + self.bands.0 + (ih - image.1) / 2)
    }
}

/// Places panels in a grid (row-major). Each column is as wide as its
/// widest picture and each row as tall as its tallest; pictures are
/// centred in their cells.
pub fn compose_picture(panels: &[Panel], layout: &Layout) -> Result<Picture> {
    let grid = Grid::new(panels, layout)?;
    let (width, m) = (grid.width, layout.margin);
    let mut out = Picture::new(width as f32, grid.height as f32);
    if let Some(t) = &layout.title {
        let at = (0.5 * width as f32, m as f32);
        out.text(t, at, size::TITLE, DARK, (HAlign::Center, VAlign::Top));
    }
    for (k, p) in panels.iter().enumerate() {
        let at = grid.image_origin(k, p.image.pixel_size());
        draw_panel(&mut out, p, at, grid.cells[k], grid.bands);
    }
    Ok(out)
}

fn draw_panel(
    out: &mut Picture,
    p: &Panel,
    (ix, iy): (u32, u32),
    ((x, y), (cw, ih)): ((u32, u32), (u32, u32)),
    (lh, _ch): (u32, u32),
) {
    out.place(&p.image, (ix as f32, iy as f32));
    if let Some(l) = &p.label {
        let at = (x as f32 + 2.0, y as f32);
        out.text(l, at, size::PANEL_LABEL, DARK, (HAlign::Left, VAlign::Top));
    }
    if let Some(c) = &p.caption {
        let at = (
            x as f32 + 0.5 * cw as f32,
            (y + lh + ih) as f32 + 0.3 * size::LABEL,
        );
        out.text(c, at, size::LABEL, DARK, (HAlign::Center, VAlign::Top));
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

/// One frame of a filmstrip: a time and the state at that time.
#[derive(Clone, Copy, Debug)]
pub struct Frame<'a> {
    pub time: f64,
    pub q: &'a [f64],
}

/// Options of a filmstrip.
#[derive(Clone, Debug, Default)]
pub struct FilmstripOptions {
    /// Size of each snapshot in pixels (default 110 × 330).
    pub frame_size: Option<(u32, u32)>,
    /// Title above the strip.
    pub title: Option<String>,
    /// Label at the top left of the strip, e.g. "(a1)".
    pub label: Option<String>,
    /// A fixed window; by default one window fits every frame, so all
    /// snapshots share one scale.
    pub view: Option<View>,
    /// Marks beside each snapshot (`marks[k]` for frame k; none if absent),
    /// such as the kink and the antikink of Fig. 4a.
    pub marks: Vec<Vec<ChainMark>>,
}

/// A labelled pointer beside a filmstrip snapshot at a point of the chain.
#[derive(Clone, Debug, PartialEq)]
pub struct ChainMark {
    /// Where along the chain, in blocks: 1 is the centre of block 1, 2.5
    /// halfway between the centres of blocks 2 and 3.
    pub at: f64,
    pub label: String,
    pub color: crate::encode::Rgb,
    /// The side of the ladder the pointer and its label go on (`Left` or
    /// `Right`).
    pub side: HAlign,
}

/// Font size of a [`ChainMark`]'s label.
const MARK_TEXT: f32 = 11.0;

/// Draws `mark` onto a snapshot picture of `snap` (drawn over all of it):
/// a triangle pointing at the chain, its label beyond it.
fn draw_mark(canvas: &mut Picture, ladder: &Ladder, snap: &Snapshot<'_>, mark: &ChainMark) {
    use crate::model::ladder::{ix, iy, nodes};
    let n = ladder.n();
    let q = snap.q;
    let at = mark.at.clamp(1.0, n as f64);
    let i = (at.floor() as usize).clamp(1, n) - 1;
    let j = (i + 1).min(n - 1);
    let f = at - (i + 1) as f64;
    let point = [
        q[ix(i)] + f * (q[ix(j)] - q[ix(i)]),
        q[iy(i)] + f * (q[iy(j)] - q[iy(i)]),
    ];
    let (w, h) = canvas.pixel_size();
    let region = Region::full(w, h);
    let (x, y) = snapshot::pixel_of(region, snap, point);
    // Clear of the chain: beyond the farthest node of the two blocks.
    let reach = [i, j]
        .iter()
        .flat_map(|&k| {
            let (a, b) = nodes(q, k);
            [a, b]
        })
        .map(|p| (snapshot::pixel_of(region, snap, p).0 - x).abs())
        .fold(0.0f32, f32::max);
    let dir = if mark.side == HAlign::Left { -1.0 } else { 1.0 };
    let tip = x + dir * (reach + 3.0);
    let base = tip + dir * 7.0;
    canvas.polygon(&[(tip, y), (base, y - 4.5), (base, y + 4.5)], mark.color);
    let align = if mark.side == HAlign::Left {
        HAlign::Right
    } else {
        HAlign::Left
    };
    canvas.text(
        &mark.label,
        (base + dir * 2.0, y),
        MARK_TEXT,
        mark.color,
        (align, VAlign::Middle),
    );
}

/// Snapshots side by side in time order (left to right), each captioned
/// "t/τ = …", sharing one scale; rasterised at 100 %.
pub fn filmstrip(ladder: &Ladder, frames: &[Frame<'_>], opts: &FilmstripOptions) -> Result<Pixmap> {
    filmstrip_picture(ladder, frames, opts)?.to_pixmap()
}

/// Snapshots side by side in time order (left to right), each captioned
/// "t/τ = …", sharing one scale.
pub fn filmstrip_picture(
    ladder: &Ladder,
    frames: &[Frame<'_>],
    opts: &FilmstripOptions,
) -> Result<Picture> {
    if frames.is_empty() {
        return Err(Error::bad_input("a filmstrip needs at least one frame"));
    }
    let (w, h) = opts.frame_size.unwrap_or((110, 330));
    let states: Vec<&[f64]> = frames.iter().map(|f| f.q).collect();
    let view = opts.view.unwrap_or_else(|| View::fit(&states));
    let mut panels = Vec::with_capacity(frames.len());
    for (k, f) in frames.iter().enumerate() {
        let snap = Snapshot::new(ladder, f.q)?.with_view(view);
        let mut img = snapshot::snapshot_picture(&snap, w, h)?;
        for mark in opts.marks.get(k).into_iter().flatten() {
            draw_mark(&mut img, ladder, &snap, mark);
        }
        panels.push(Panel::new(img).caption(snapshot::time_label(f.time)));
    }
    let mut layout = Layout::row(panels.len());
    layout.gap = 6;
    // A label without a title still gets the title band, above the frames.
    layout.title = opts
        .title
        .clone()
        .or_else(|| opts.label.as_ref().map(|_| String::new()));
    let mut strip = compose_picture(&panels, &layout)?;
    if let Some(l) = &opts.label {
        let at = (layout.margin as f32, layout.margin as f32);
        strip.text(l, at, size::PANEL_LABEL, DARK, (HAlign::Left, VAlign::Top));
    }
    Ok(strip)
}

/// Draws several snapshots into one canvas region by region (no captions):
/// the building block for custom layouts.
pub fn draw_snapshots(canvas: &mut Pixmap, items: &[(Region, Snapshot<'_>)]) {
    for (r, s) in items {
        snapshot::draw_snapshot(canvas, *r, s);
    }
}
