//! The static figures of the catalogue (README.md): 2b, 2c, 2d, S3, S4,
//! S5, winding, edge-mode and barrier.
//!
//! Each figure is a title, a body (a drawing, snapshots of the model's
//! configurations or charts of `theory::figures` data) and a few lines of
//! notes that say what is drawn and where it departs from the paper
//! (docs/paper-errata.md).

mod configurations;
mod drawn;
mod layout;
mod pen;
mod plots;
mod schematic;

pub use drawn::{Drawn, drawn_numbers};

use crate::error::Result;
use crate::limits::{Limits, Resource};
use crate::model::{Ladder, Params};
use crate::render::compose::{self, Layout, Panel};
use crate::render::palette::{Palette, Role};
use crate::render::snapshot::{self, Snapshot};
use crate::render::style::{self, HAlign, VAlign, size};
use crate::render::{Canvas, Picture, Theme};
use crate::scene::{Model, TheoryFigure, TheorySpec, ZeroMode};
use crate::theory::cost::{self, Work};
use tiny_skia::Pixmap;

/// What a static figure draws: its title, the model's N, b and α, and
/// the lists of the figure's own parameters (all scene data).
#[derive(Debug, Clone, PartialEq)]
pub struct FigureInput {
    pub title: String,
    pub model: Model,
    /// Angles α of the curves (Fig. S5, edge mode), degrees.
    pub alphas: Vec<f64>,
    /// Ratios a/b of the U(θ) curves (Fig. 2c).
    pub a_over_b: Vec<f64>,
    /// Zero modes (Fig. S4).
    pub modes: Vec<ZeroMode>,
    /// The caps the figure's work is checked against ([`check_cost`]).
    /// Default [`Limits::default`]; a scene's figure takes the scene's.
    pub limits: Limits,
}

impl FigureInput {
    pub fn new(title: impl Into<String>, model: &Model, spec: &TheorySpec) -> Self {
        Self {
            title: title.into(),
            model: *model,
            alphas: spec.alphas.clone(),
            a_over_b: spec.a_over_b.clone(),
            modes: spec.modes.clone(),
            limits: Limits::default(),
        }
    }

    /// The input of `scene`'s figure `spec`: its title, model, lists and
    /// caps.
    pub fn of(scene: &crate::scene::Scene, spec: &TheorySpec) -> Self {
        Self {
            limits: scene.limits,
            ..Self::new(crate::scene::describe::title(scene), &scene.model, spec)
        }
    }

    /// The scene's model with another N, b and α (degrees).
    fn params(&self, n: usize, b: f64, alpha_deg: f64) -> Result<Params> {
        let m = crate::scene::Model {
            n,
            b,
            alpha: alpha_deg,
            ..self.model
        };
        m.params()
    }
}

/// The width, in pixels, a figure's body may take at a print style (the
/// composed page less its margins, [`crate::render::Style::fit_box`]);
/// none at screen.
fn body_room(theme: &Theme) -> Option<f32> {
    let (w, _) = theme.style.fit_box()?;
    Some(w - 2.0 * theme.margin)
}

/// The size of each of `columns` cells of a grid whose natural cell is
/// `natural`: unchanged at screen; at a print style narrowed, aspect kept,
/// so that the row fits [`body_room`].
fn cells(theme: &Theme, natural: (u32, u32), columns: usize) -> (u32, u32) {
    let Some(room) = body_room(theme) else {
        return natural;
    };
    let c = columns.max(1) as f32;
    let w = ((room - (c - 1.0) * theme.gap) / c).floor();
    let w = w.min(natural.0 as f32).max(20.0);
    let h = natural.1 as f32 * w / natural.0 as f32;
    // No taller than the page budget leaves after a label and a caption.
    let tall = body_height(theme).map_or(h, |room| room - 4.0 * theme.label);
    let f = (tall / h).min(1.0);
    ((w * f).floor() as u32, (h * f).round() as u32)
}

/// How much a drawing `width` pixels wide is scaled down to fit
/// [`body_room`] (1 at screen or when it fits).
fn drawing_scale(theme: &Theme, width: f32, height: f32) -> f32 {
    let tall = body_height(theme).map_or(1.0, |room| room / height);
    body_room(theme).map_or(1.0, |room| (room / width).min(tall).min(1.0))
}

/// The height, in pixels, a figure's body may take at a print style (the
/// page budget less the margins); none at screen.
fn body_height(theme: &Theme) -> Option<f32> {
    let (_, h) = theme.style.fit_box()?;
    Some(h - 2.0 * theme.margin)
}

/// `body` scaled by `scale` (a drawing laid out for the screen, on a
/// narrower page).
fn scaled(body: &Picture, scale: f32) -> Picture {
    if scale >= 1.0 {
        return body.clone();
    }
    let (w, h) = (body.width() * scale, body.height() * scale);
    let mut out = Picture::new(body.theme(), w.ceil(), h.ceil());
    out.push(tiny_skia::Transform::from_scale(scale, scale));
    body.draw(&mut out);
    out.pop();
    out
}

/// Renders one static figure at 100 %, drawn with `theme`.
pub fn render(theme: &Theme, figure: TheoryFigure, input: &FigureInput) -> Result<Pixmap> {
    picture(theme, figure, input)?.to_pixmap()
}

/// What drawing `figure` for `input` costs (`theory::cost`).
pub fn work(figure: TheoryFigure, input: &FigureInput) -> Work {
    let n = input.model.n;
    match figure {
        TheoryFigure::GroundStates => Work::configurations(n, 3),
        TheoryFigure::Gapless => Work::configurations(n, 1),
        TheoryFigure::ZeroModes => Work::zero_modes(n, input.modes.len()),
        // Each angle at both signs (the two panels).
        TheoryFigure::EdgeMode => Work::surface_modes(n, 2 * input.alphas.len()),
        TheoryFigure::UnitSchematic
        | TheoryFigure::GravityPotential
        | TheoryFigure::Dispersion
        | TheoryFigure::Winding
        | TheoryFigure::Barrier => Work::fixed(),
    }
}

/// Refuses, before any work, a figure whose estimated cost
/// ([`work`]) is past the input's cap on theory work, or whose dense
/// matrices would not fit in [`cost::MAX_DENSE_BYTES`].
pub fn check_cost(figure: TheoryFigure, input: &FigureInput) -> Result<Work> {
    let w = work(figure, input);
    let n = input.model.n;
    if w.dense_bytes > cost::MAX_DENSE_BYTES {
        return Err(crate::error::Error::bad_input(format!(
            "this figure would hold {:.1e} bytes of dense matrices at N = {n}, past the {:.0e} \
             a theory figure may hold (docs/limits.md); ask for fewer blocks",
            w.dense_bytes,
            cost::MAX_DENSE_BYTES
        )));
    }
    input.limits.check(Resource::TheoryWork, w.operations, || {
        // The scene file's word for the figure ("ground-states").
        let name = serde_json::to_string(&figure).unwrap_or_default();
        format!("figure = {name} at N = {n}")
    })?;
    Ok(w)
}

/// One static figure as a picture (PNG at any scale, SVG, PDF), its cost
/// checked first ([`check_cost`]), drawn with `theme`.
pub fn picture(theme: &Theme, figure: TheoryFigure, input: &FigureInput) -> Result<Picture> {
    check_cost(figure, input)?;
    Ok(drawn(theme, figure, input)?
        .fit_page()
        .titled(input.title.clone()))
}

fn drawn(theme: &Theme, figure: TheoryFigure, input: &FigureInput) -> Result<Picture> {
    match figure {
        TheoryFigure::UnitSchematic => schematic::unit(theme, input),
        TheoryFigure::GravityPotential => plots::gravity_potential(theme, input),
        TheoryFigure::GroundStates => configurations::ground_states(theme, input),
        TheoryFigure::Gapless => configurations::gapless(theme, input),
        TheoryFigure::ZeroModes => configurations::zero_modes(theme, input),
        TheoryFigure::Dispersion => plots::dispersion(theme, input),
        TheoryFigure::Winding => plots::winding(theme, input),
        TheoryFigure::EdgeMode => plots::edge_mode(theme, input),
        TheoryFigure::Barrier => plots::barrier(theme, input),
    }
}

/// Line height of the notes.
const NOTE_LINE: f32 = 1.35 * size::LABEL;

/// Puts `body` under a centred title with wrapped `notes` below it, on a
/// white page at least `min_width` pixels wide.
fn frame(
    theme: &Theme,
    title: &str,
    body: &Picture,
    notes: &str,
    min_width: u32,
) -> Result<Picture> {
    // Journal styles carry neither title nor notes: the caption is the
    // document's; a slide keeps its title and leaves the notes (a
    // paragraph at 20 pt) to the speaker.
    let title = if theme.titles { title } else { "" };
    let notes = if theme.style.name == crate::render::StyleName::Screen {
        notes
    } else {
        ""
    };
    let m = size::MARGIN;
    let (bw, bh) = body.pixel_size();
    let min_width = theme.style.frame((min_width, 1)).0;
    let width = (bw + 2 * m).max(min_width);
    let lines = if notes.is_empty() {
        Vec::new()
    } else {
        style::wrap_text(theme.font(), notes, (width - 2 * m) as f32, size::LABEL)
    };
    // The title wrapped to the page, never shrunk below the style's text
    // (a title wider than a narrow page once left it on both sides).
    let fitted = crate::render::charts::fit_title(theme, title, width);
    let title_lines = if title.is_empty() {
        Vec::new()
    } else {
        fitted.lines.clone()
    };
    let title_h = match title_lines.len() {
        0 => 0,
        1 => (1.8 * fitted.size) as u32,
        k => ((1.2 * k as f32 + 0.6) * fitted.size) as u32,
    };
    let notes_h = if lines.is_empty() {
        0
    } else {
        (lines.len() as f32 * NOTE_LINE + 0.5 * size::LABEL) as u32
    };
    let height = m + title_h + bh + notes_h + m;
    let mut out = Picture::new(theme, width as f32, height as f32);
    let centre = 0.5 * width as f32;
    let top = (centre, m as f32);
    for (k, line) in title_lines.iter().enumerate() {
        let at = (top.0, top.1 + 1.2 * k as f32 * fitted.size);
        out.text(line, at, fitted.size, theme.color(Role::Ink), TOP_CENTRE);
    }
    out.place(body, (((width - bw) / 2) as f32, (m + title_h) as f32));
    let y0 = (m + title_h + bh) as f32 + 0.4 * size::LABEL;
    for (k, l) in lines.iter().enumerate() {
        let at = (m as f32, y0 + k as f32 * NOTE_LINE);
        out.text(l, at, size::LABEL, Palette.color(Role::Ink), TOP_LEFT);
    }
    Ok(out)
}

const TOP_CENTRE: (HAlign, VAlign) = (HAlign::Center, VAlign::Top);
const TOP_LEFT: (HAlign, VAlign) = (HAlign::Left, VAlign::Top);

/// Panels in a grid without a title (the figure frame carries it), and at
/// a print style without a margin of its own (the frame's is the page's).
fn grid(theme: &Theme, panels: &[Panel], columns: usize) -> Result<Picture> {
    let mut layout = Layout::columns(theme, columns);
    if theme.is_print() {
        layout.margin = 0;
    }
    compose::compose_picture(panels, &layout)
}

/// A snapshot of `q` on `ladder` without the pin support of block 1 (these
/// configurations are not driven), over an optional grey `ghost`.
fn configuration(
    theme: &Theme,
    ladder: &Ladder,
    q: &[f64],
    ghost: Option<&[f64]>,
    (w, h): (u32, u32),
) -> Result<Picture> {
    let mut snap = Snapshot::new(ladder, q)?;
    if let Some(g) = ghost {
        snap = snap.with_ghost(ladder, g)?;
    }
    snap.clamp = false;
    snapshot::snapshot_picture(theme, &snap, w, h)
}

/// "+75°", "−75°", "0°" with a true minus sign.
fn signed_deg(x: f64) -> String {
    let v = crate::render::charts::short_number(x.abs());
    if x > 0.0 {
        format!("+{v}°")
    } else if x < 0.0 {
        format!("−{v}°")
    } else {
        format!("{v}°")
    }
}
