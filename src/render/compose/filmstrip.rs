//! Filmstrips: snapshots of a ladder side by side (paper Fig. 1c and
//! Fig. 3), folded into columns when long, with time labels, wall marks
//! and the geometry a caller needs to place its own marks.

use super::grid::*;
pub use super::marks::ChainMark;
use super::marks::{draw_marks, mark_room};
use crate::error::{Error, Result};
use crate::model::Ladder;
use crate::render::canvas::{Canvas, Pen};
use crate::render::fold::{self, Fold};
use crate::render::palette::{Palette, Role};
use crate::render::picture::Picture;
use crate::render::snapshot::{self, Region, Snapshot, View};
use crate::render::style::{self, HAlign, VAlign};
use crate::render::theme::Theme;
use tiny_skia::Pixmap;

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
    /// The shortest a block (s) may be drawn, in pixels (default: none).
    /// A ladder too long to show so in one `frame_size` snapshot is folded
    /// into columns side by side ([`super::fold`]), each snapshot as wide
    /// as its columns need and as tall as `frame_size`, and the snapshots
    /// wrap into rows. Ignored with a fixed `view`.
    pub min_block_pixels: Option<f32>,
    /// The box, in pixels, the whole strip (margins, title and captions
    /// included) must fit at a print style (default: none, the strip is
    /// as wide as its snapshots need). Snapshots then wrap into rows and
    /// shrink, keeping their aspect ratio, so that the strip fits; a time
    /// caption wider than its snapshot goes on two lines.
    pub fit: Option<(u32, u32)>,
}

/// Widest a folded snapshot may be, in pixels; a longer ladder is drawn
/// with shorter blocks than the minimum.
const MAX_FOLDED_WIDTH: f32 = 4000.0;
/// Widest row of folded snapshots, in pixels; further snapshots wrap to
/// the next row.
const MAX_FOLDED_ROW: u32 = 1800;
/// Tallest strip of folded snapshots, in pixels: below
/// [`crate::render::picture::MAX_RASTER_SIDE`] with room for a figure's title.
const MAX_FOLDED_HEIGHT: u32 = 7600;
/// A strip fitted into a box takes the fewest rows that draw the ladder at
/// least this share of the largest any number of rows would.
const FIT_SHARE: f32 = 0.8;

/// Snapshots with marks are drawn at no less than this share of their
/// width: the marks' words need the room beside the chain.
const MARKED_SHARE: f32 = 0.8;

/// The time caption of snapshot `k` of a strip: "t/τ = …" under the
/// first, and under the others (when `once`, at a print style) the time
/// alone, so that "t/τ =" is said once per row of a strip.
fn time_caption(k: usize, time: f64, once: bool) -> String {
    let full = snapshot::time_label(time);
    if once && k > 0 {
        full.rsplit(" = ").next().unwrap_or(&full).to_string()
    } else {
        full
    }
}

/// A time caption, on two lines ("t/τ =" over the time) when `two`.
fn two_lines(caption: &str, two: bool) -> String {
    if two {
        caption.replacen(" = ", " =\n", 1)
    } else {
        caption.to_string()
    }
}

/// One column of a snapshot: blocks `start..start + ladder.n()` of the
/// whole ladder, seen through `view` in `region` of the snapshot.
struct StripColumn {
    start: usize,
    ladder: Ladder,
    view: View,
    region: Region,
}

impl StripColumn {
    fn snapshot<'a>(&'a self, q: &'a [f64]) -> Result<Snapshot<'a>> {
        let q = q
            .get(3 * self.start..3 * (self.start + self.ladder.n()))
            .unwrap_or(q);
        let mut snap = Snapshot::new(&self.ladder, q)?.with_view(self.view);
        snap.clamp = self.start == 0;
        Ok(snap)
    }
}

/// How a filmstrip draws each snapshot: the whole ladder in one frame, or
/// folded into columns.
struct StripPlan {
    /// The figure's theme.
    theme: Theme,
    /// Size of every snapshot's picture.
    size: (u32, u32),
    columns: Vec<StripColumn>,
    /// The fold, when the ladder is folded.
    fold: Option<Fold>,
    /// Snapshots per row and the gap between them.
    per_row: usize,
    gap: u32,
    /// Whether the time captions go on two lines ("t/τ =" over the time).
    two_line: bool,
}

/// One way of wrapping a fitted strip's snapshots into rows
/// (`StripPlan::way`): its rows, each snapshot's size, whether the time
/// captions take two lines, and the scale the ladder is drawn at.
struct Way {
    rows: usize,
    width: u32,
    height: u32,
    two_line: bool,
    scale: f32,
}

/// The widths a fitted strip's time captions take: each row's first
/// caption reads "t/τ = …", the others the time alone ([`strip_panels`]);
/// a grid's column is as wide as its snapshot or its widest caption line,
/// whichever is wider.
struct Captions<'a> {
    theme: &'a Theme,
    frames: &'a [Frame<'a>],
    gap: f32,
    margin: f32,
}

impl Captions<'_> {
    /// The widest line of each snapshot's caption with `k` snapshots a
    /// row, on two lines or one.
    fn widths(&self, k: usize, two: bool) -> Vec<f32> {
        let line_w = |c: &str| {
            two_lines(c, two)
                .lines()
                .map(|l| style::text_width(self.theme.font(), l, self.theme.label))
                .fold(0.0f32, f32::max)
        };
        self.frames
            .iter()
            .enumerate()
            .map(|(i, f)| line_w(&time_caption(i % k, f.time, true)))
            .collect()
    }

    /// The strip's width with `k` snapshots `cw` wide a row, each column
    /// widened to its captions' `widths` ([`Self::widths`]), the gaps and
    /// the margins.
    fn strip_width(&self, k: usize, cw: f32, widths: &[f32]) -> f32 {
        let mut col = vec![cw; k];
        for (i, &c) in widths.iter().enumerate() {
            col[i % k] = col[i % k].max(c.ceil());
        }
        col.iter().sum::<f32>() + (k as f32 - 1.0) * self.gap + 2.0 * self.margin
    }
}

/// Pixels per s of `snap` drawn into `region`: the length of every block.
fn block_pixels(region: Region, snap: &Snapshot<'_>) -> f32 {
    let (x0, y0) = snapshot::pixel_of(region, snap, [0.0, 0.0]);
    let (x1, y1) = snapshot::pixel_of(region, snap, [1.0, 0.0]);
    (x1 - x0).hypot(y1 - y0)
}

/// The margin [`snapshot::draw_snapshot_on`] keeps inside a region whose
/// shorter side is at most `side` pixels (at most that margin).
fn margin_within(side: f32) -> f32 {
    (0.03 * side).clamp(2.0, 12.0)
}

impl StripPlan {
    fn new(
        theme: &Theme,
        ladder: &Ladder,
        frames: &[Frame<'_>],
        opts: &FilmstripOptions,
    ) -> Result<StripPlan> {
        let (w, h) = opts.frame_size.unwrap_or((110, 330));
        let states: Vec<&[f64]> = frames.iter().map(|f| f.q).collect();
        let view = opts.view.unwrap_or_else(|| View::fit(&states));
        let whole = StripPlan {
            theme: *theme,
            size: (w, h),
            columns: vec![StripColumn {
                start: 0,
                ladder: *ladder,
                view,
                region: Region::full(w, h),
            }],
            fold: None,
            per_row: frames.len().max(1),
            gap: theme.snapshot_gap,
            two_line: false,
        };
        let Some(min) = opts.min_block_pixels.filter(|_| opts.view.is_none()) else {
            return Ok(whole.fitted(frames, opts));
        };
        let probe = whole.columns[0].snapshot(frames[0].q)?;
        if block_pixels(whole.columns[0].region, &probe) >= min {
            return Ok(whole.fitted(frames, opts));
        }
        Self::folded(theme, ladder, frames, opts, h, min)
    }

    /// The plan of a ladder too long to show with blocks of `min` pixels
    /// in one snapshot `h` pixels tall: folded into columns side by side
    /// ([`Fold::readable`]), room for the marks beside them, and the
    /// snapshots wrapped into rows of at most [`MAX_FOLDED_ROW`] (or the
    /// fit box's width).
    fn folded(
        theme: &Theme,
        ladder: &Ladder,
        frames: &[Frame<'_>],
        opts: &FilmstripOptions,
        h: u32,
        min: f32,
    ) -> Result<StripPlan> {
        let states: Vec<&[f64]> = frames.iter().map(|f| f.q).collect();
        // Room for the marks beside every column, on their sides.
        let room = |side: HAlign| {
            opts.marks
                .iter()
                .flatten()
                .filter(|m| m.side == side)
                .map(|m| mark_room(theme, m))
                .fold(0.0f32, f32::max)
                .ceil()
        };
        let (left, right) = (room(HAlign::Left), room(HAlign::Right));
        let gap = fold::COLUMN_GAP.max(left + right);
        let (left, right) = (left + theme.folded_pad, right + theme.folded_pad);
        let top = (theme.folded_pad + theme.column_number_band_em * theme.column_number).ceil();
        let column_h = (h as f32 - top - theme.folded_pad).max(1.0);
        // The ladder's window inside each column, after the margin.
        let height = (column_h - 2.0 * margin_within(column_h)) as f64;
        let across = {
            let fit = View::fit(&states);
            fit.y.1 - fit.y.0
        };
        let narrowest = (across * min as f64) as f32 + 4.0;
        let max_columns = ((MAX_FOLDED_WIDTH - left - right + gap) / (narrowest + gap))
            .floor()
            .max(1.0) as usize;
        let folded = Fold::readable(ladder, &states, height, min as f64, max_columns);
        let inner_w = (folded.across * folded.scale_along(height)) as f32;
        let column_w = (inner_w + 2.0 * margin_within(inner_w + 25.0)).ceil();
        let columns: Vec<StripColumn> = folded
            .segments
            .iter()
            .enumerate()
            .map(|(j, s)| StripColumn {
                start: s.start,
                ladder: s.ladder,
                view: s.view,
                region: Region {
                    x: left + j as f32 * (column_w + gap),
                    y: top,
                    w: column_w,
                    h: column_h,
                },
            })
            .collect();
        let cols = columns.len() as f32;
        let width = (left + cols * column_w + (cols - 1.0) * gap + right).ceil() as u32;
        let row = opts
            .fit
            .map_or(MAX_FOLDED_ROW, |(w, _)| w.min(MAX_FOLDED_ROW))
            .saturating_sub(2 * theme.margin as u32);
        let fits = ((row + theme.folded_snapshot_gap) / (width + theme.folded_snapshot_gap)).max(1)
            as usize;
        // Many snapshots: rows wider than MAX_FOLDED_ROW rather than a
        // strip taller than a picture may be.
        let row_h = h + (theme.label * theme.folded_caption_em) as u32 + theme.folded_snapshot_gap;
        let max_rows = (MAX_FOLDED_HEIGHT / row_h).max(1) as usize;
        let rows = frames.len().div_ceil(fits).min(max_rows);
        Ok(StripPlan {
            theme: *theme,
            size: (width, h),
            columns,
            fold: Some(folded),
            per_row: frames.len().div_ceil(rows.max(1)).max(1),
            gap: theme.folded_snapshot_gap,
            two_line: false,
        })
    }

    /// The whole-ladder plan fitted into `opts.fit`: of the ways to wrap
    /// the snapshots into rows (each snapshot at most its natural size,
    /// its aspect ratio kept, and as tall as the box leaves room for), the
    /// one with the fewest rows that draws the ladder at least
    /// [`FIT_SHARE`] as large as the best does. Snapshots with marks keep
    /// [`MARKED_SHARE`] of their width (the marks' words need it; marks
    /// without words do not).
    /// Unchanged without a box.
    fn fitted(self, frames: &[Frame<'_>], opts: &FilmstripOptions) -> StripPlan {
        let Some(fit) = opts.fit else {
            return self;
        };
        let title = if opts.title.is_some() || opts.label.is_some() {
            self.theme.title_band()
        } else {
            0.0
        };
        let captions = Captions {
            theme: &self.theme,
            frames,
            gap: self.gap as f32,
            margin: self.theme.fit_margin as f32,
        };
        // Words beside the chain need the room; a bare triangle does not.
        let marked = opts.marks.iter().flatten().any(|m| !m.label.is_empty());
        let n = frames.len().max(1);
        let ways: Vec<Way> = (1..=n)
            .filter_map(|rows| self.way(&captions, rows, n, fit, title, marked))
            .collect();
        let best = ways.iter().map(|w| w.scale).fold(0.0f32, f32::max);
        let Some(way) = ways.iter().find(|w| w.scale >= FIT_SHARE * best) else {
            return self;
        };
        let mut plan = self;
        plan.size = (way.width, way.height);
        plan.columns[0].region = Region::full(way.width, way.height);
        plan.per_row = n.div_ceil(way.rows);
        plan.two_line = way.two_line;
        plan
    }

    /// The way of wrapping `n` snapshots into `rows` rows in the box `fit`
    /// (below a title band `title` tall): each snapshot as wide as the
    /// strip with its captions allows, at most its natural size, its
    /// captions on one line where they fit beside their neighbours and
    /// within the box, on two otherwise; none when no snapshot of these
    /// rows is as large as the theme's least (or, `marked`, keeps
    /// [`MARKED_SHARE`] of its width).
    fn way(
        &self,
        captions: &Captions<'_>,
        rows: usize,
        n: usize,
        (box_w, box_h): (u32, u32),
        title: f32,
        marked: bool,
    ) -> Option<Way> {
        let (w, h) = self.size;
        let (theme, m, gap) = (&self.theme, captions.margin, captions.gap);
        let k = n.div_ceil(rows);
        let room = (box_w as f32 - 2.0 * m - (k as f32 - 1.0) * gap) / k as f32;
        let most = room.min(w as f32).floor();
        // A caption wider than its snapshot widens its column: the widest
        // snapshot, at most `most`, whose strip fits the box with its
        // captions on `two` lines (so that a wider box never takes a
        // narrower snapshot).
        // The captions' widths measured once for each `two`, not at every
        // width tried.
        let fitting = |widths: &[f32]| {
            let mut cw = most;
            while cw > 0.0 && captions.strip_width(k, cw, widths) > box_w as f32 {
                cw -= 1.0;
            }
            cw
        };
        [false, true].into_iter().find_map(|two| {
            let widths = captions.widths(k, two);
            let cw = fitting(&widths);
            if cw < theme.min_snapshot.0 || (marked && cw < MARKED_SHARE * w as f32) {
                return None;
            }
            let widest = widths.iter().copied().fold(0.0f32, f32::max);
            if widest > cw + gap - theme.caption_slack {
                return None;
            }
            let lines = if two { 2.0 } else { 1.0 };
            let caption = theme.caption_band(lines).floor();
            let tall = (box_h as f32 - 2.0 * m - title - (rows as f32 - 1.0) * gap) / rows as f32
                - caption;
            let ch = (h as f32 * cw / w as f32).min(tall).floor();
            if ch < theme.min_snapshot.1 {
                return None;
            }
            Some(Way {
                rows,
                width: cw as u32,
                height: ch as u32,
                two_line: two,
                scale: (cw / w as f32).min(ch / h as f32),
            })
        })
    }

    /// The snapshot of `frame` with its `marks`.
    fn picture(&self, frame: &Frame<'_>, marks: &[ChainMark]) -> Result<Picture> {
        let (w, h) = self.size;
        let theme = &self.theme;
        let Some(folded) = &self.fold else {
            let c = &self.columns[0];
            let snap = c.snapshot(frame.q)?;
            let mut img = snapshot::snapshot_picture(theme, &snap, w, h)?;
            draw_marks(theme, &mut img, c.region, &c.ladder, &snap, marks, false);
            return Ok(img);
        };
        let mut img = Picture::new(theme, w as f32, h as f32);
        let number = style::mix(Palette.color(Role::Ground), Palette.color(Role::Ink), 0.3);
        for c in &self.columns {
            snapshot::draw_snapshot_on(&mut img, c.region, &c.snapshot(frame.q)?);
            let at = (c.region.x + 0.5 * c.region.w, theme.folded_pad);
            let first = format!("{}", c.start + 1);
            let top = (HAlign::Center, VAlign::Top);
            img.text(&first, at, theme.column_number, number, top);
        }
        // Each column's marks together, so that one may see the others'.
        for (j, c) in self.columns.iter().enumerate() {
            let local: Vec<ChainMark> = marks
                .iter()
                .filter_map(|m| {
                    let (k, at) = folded.locate(m.at);
                    (k == j).then(|| ChainMark { at, ..m.clone() })
                })
                .collect();
            if local.is_empty() {
                continue;
            }
            let snap = c.snapshot(frame.q)?;
            draw_marks(theme, &mut img, c.region, &c.ladder, &snap, &local, true);
        }
        // A light frame holds each snapshot's columns together.
        let (w, h) = (w as f32, h as f32);
        let corners = [
            (0.5, 0.5),
            (w - 0.5, 0.5),
            (w - 0.5, h - 0.5),
            (0.5, h - 0.5),
        ];
        if let Some(path) = crate::render::canvas::polyline_path(&corners, true) {
            let pen = Pen::new(
                1.0,
                style::mix(
                    Palette.color(Role::Paper),
                    Palette.color(Role::Ground),
                    0.45,
                ),
            );
            img.stroke(&path, &pen);
        }
        Ok(img)
    }

    /// Both ends of every block of `frame`, in pixels of its snapshot (a
    /// block shared by two columns twice).
    fn block_ends(&self, frame: &Frame<'_>) -> Result<Vec<[(f32, f32); 2]>> {
        let mut out = Vec::new();
        for c in &self.columns {
            let snap = c.snapshot(frame.q)?;
            for i in 0..c.ladder.n() {
                let (a, b) = crate::model::ladder::nodes(snap.q, i);
                out.push([
                    snapshot::pixel_of(c.region, &snap, a),
                    snapshot::pixel_of(c.region, &snap, b),
                ]);
            }
        }
        Ok(out)
    }
}

/// Snapshots side by side in time order (left to right), each captioned
/// "t/τ = …", sharing one scale, drawn with `theme`; rasterised at 100 %.
pub fn filmstrip(
    theme: &Theme,
    ladder: &Ladder,
    frames: &[Frame<'_>],
    opts: &FilmstripOptions,
) -> Result<Pixmap> {
    filmstrip_picture(theme, ladder, frames, opts)?.to_pixmap()
}

/// The plan, the captioned snapshots and the layout of a filmstrip.
fn strip_panels(
    theme: &Theme,
    ladder: &Ladder,
    frames: &[Frame<'_>],
    opts: &FilmstripOptions,
) -> Result<(StripPlan, Vec<Panel>, Layout)> {
    if frames.is_empty() {
        return Err(Error::bad_input("a filmstrip needs at least one frame"));
    }
    let plan = StripPlan::new(theme, ladder, frames, opts)?;
    let mut panels = Vec::with_capacity(frames.len());
    for (k, f) in frames.iter().enumerate() {
        let marks = opts.marks.get(k).map_or(&[][..], |m| m.as_slice());
        let img = plan.picture(f, marks)?;
        // Fitted at a print style: "t/τ =" once, at the start of each row.
        let once = opts.fit.is_some() && plan.fold.is_none();
        let first_of_row = if once { k % plan.per_row.max(1) } else { k };
        let text = time_caption(first_of_row, f.time, once);
        let caption = two_lines(&text, plan.two_line);
        panels.push(Panel::new(img).caption(caption));
    }
    let mut layout = Layout::columns(theme, plan.per_row);
    layout.gap = plan.gap;
    if opts.fit.is_some() {
        layout.margin = theme.fit_margin;
    }
    // A label without a title still gets the title band, above the frames.
    layout.title = opts
        .title
        .clone()
        .or_else(|| opts.label.as_ref().map(|_| String::new()));
    Ok((plan, panels, layout))
}

/// Snapshots side by side in time order (left to right), each captioned
/// "t/τ = …", sharing one scale. With [`FilmstripOptions::min_block_pixels`]
/// a long ladder is folded into columns in each snapshot. Drawn with
/// `theme`, the figure's.
pub fn filmstrip_picture(
    theme: &Theme,
    ladder: &Ladder,
    frames: &[Frame<'_>],
    opts: &FilmstripOptions,
) -> Result<Picture> {
    let (_, panels, layout) = strip_panels(theme, ladder, frames, opts)?;
    let mut strip = compose_picture(&panels, &layout)?;
    if let Some(l) = &opts.label {
        let at = (layout.margin as f32, layout.margin as f32);
        let size = theme.panel_label;
        strip.text(
            l,
            at,
            size,
            Palette.color(Role::Ink),
            (HAlign::Left, VAlign::Top),
        );
    }
    Ok(strip)
}

/// Where a filmstrip draws: its size, each snapshot's rectangle, and both
/// ends of every block of each snapshot, in the strip's pixels (for tests).
#[derive(Clone, Debug)]
pub struct StripGeometry {
    pub size: (u32, u32),
    pub snapshots: Vec<Region>,
    pub blocks: Vec<Vec<[(f32, f32); 2]>>,
}

impl StripGeometry {
    /// The same, moved by (`dx`, `dy`) pixels into a picture of `size`.
    pub fn placed(mut self, (dx, dy): (u32, u32), size: (u32, u32)) -> StripGeometry {
        let (dx, dy) = (dx as f32, dy as f32);
        self.size = size;
        for r in &mut self.snapshots {
            r.x += dx;
            r.y += dy;
        }
        for p in self.blocks.iter_mut().flatten().flatten() {
            p.0 += dx;
            p.1 += dy;
        }
        self
    }
}

/// Where [`filmstrip_picture`] draws every block.
pub fn filmstrip_geometry(
    theme: &Theme,
    ladder: &Ladder,
    frames: &[Frame<'_>],
    opts: &FilmstripOptions,
) -> Result<StripGeometry> {
    let (plan, panels, layout) = strip_panels(theme, ladder, frames, opts)?;
    let grid = Grid::new(&panels, &layout)?;
    let mut out = StripGeometry {
        size: (grid.width, grid.height),
        snapshots: Vec::new(),
        blocks: Vec::new(),
    };
    for (k, f) in frames.iter().enumerate() {
        let (x, y) = grid.image_origin(k, plan.size);
        let (w, h) = plan.size;
        let (x, y) = (x as f32, y as f32);
        out.snapshots.push(Region {
            x,
            y,
            w: w as f32,
            h: h as f32,
        });
        let ends = plan.block_ends(f)?;
        out.blocks.push(
            ends.into_iter()
                .map(|[a, b]| [(a.0 + x, a.1 + y), (b.0 + x, b.1 + y)])
                .collect(),
        );
    }
    Ok(out)
}
