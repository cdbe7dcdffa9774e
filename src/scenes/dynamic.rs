//! The simulated scenes: filmstrips (figures 1c, 3, 4a), arrival times
//! (figure S6) and the movies with their kymographs. Each simulation runs
//! only to its last frame and is sampled only at the times drawn.

use super::run::{self, IntegratorReport, SceneRun};
use crate::encode::{GifWriter, png_bytes};
use crate::error::{Error, Result};
use crate::model::Ladder;
use crate::render::charts::{self, Axis, ChartSpec, Kymograph, Marker, Series};
use crate::render::compose::{self, FilmstripOptions, Frame, Layout, Panel};
use crate::render::snapshot::{self, Region, Snapshot, View};
use crate::render::style;
use crate::scene::{Camera, DriveSpec, MIN_BLOCK_PIXELS, Model, OutputSpec, Scene, describe};
use crate::sim::{self, Trajectory};
use serde::Serialize;
use tiny_skia::Pixmap;

/// Movie frame count, size and rate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MovieOptions {
    pub frames: usize,
    pub width: u32,
    pub height: u32,
    pub fps: f64,
}

impl Default for MovieOptions {
    fn default() -> Self {
        Self {
            frames: 200,
            width: 640,
            height: 480,
            fps: 25.0,
        }
    }
}

/// Largest frame count and side accepted: bounded memory and time.
pub const MAX_FRAMES: usize = 5000;
pub const MIN_SIDE: u32 = 64;
pub const MAX_SIDE: u32 = 4096;

impl MovieOptions {
    pub fn validated(self) -> Result<Self> {
        if !(2..=MAX_FRAMES).contains(&self.frames) {
            return Err(Error::bad_input(format!(
                "a movie needs between 2 and {MAX_FRAMES} frames, got {}",
                self.frames
            )));
        }
        for side in [self.width, self.height] {
            if !(MIN_SIDE..=MAX_SIDE).contains(&side) {
                return Err(Error::bad_input(format!(
                    "the frame size must be WxH with each side between {MIN_SIDE} and {MAX_SIDE} pixels, got {}x{}",
                    self.width, self.height
                )));
            }
        }
        if !(self.fps.is_finite() && self.fps > 0.0 && self.fps <= 100.0) {
            return Err(Error::bad_input(format!(
                "the frame rate must be a number of frames per second in (0, 100], got {}",
                self.fps
            )));
        }
        Ok(self)
    }
}

/// What the data file says of one run: the scene it ran, the integrator
/// and accuracy, the arrival times, the final angles and, at each drawn
/// time, θ_n (degrees, wrapped to (−180°, 180°]) and the centres.
#[derive(Debug, Clone, Serialize)]
pub struct RunData {
    pub label: String,
    pub model: Model,
    pub drive: DriveSpec,
    pub t_end: f64,
    pub integrator: IntegratorReport,
    pub arrival_times: Vec<Option<f64>>,
    /// Speed of the wave in blocks per τ (least squares over blocks
    /// 2..N−1), when at least three of them flipped.
    pub speed: Option<f64>,
    pub final_theta_deg: Vec<f64>,
    pub frames: Vec<FrameData>,
}

/// The state drawn at one time.
#[derive(Debug, Clone, Serialize)]
pub struct FrameData {
    pub t: f64,
    pub theta_deg: Vec<f64>,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
}

impl RunData {
    pub fn from_run(scene: &Scene, run: &SceneRun) -> Self {
        Self::new("", scene, run)
    }

    fn new(label: &str, scene: &Scene, run: &SceneRun) -> Self {
        let traj = &run.trajectory;
        let frames = traj
            .times
            .iter()
            .zip(&traj.states)
            .map(|(&t, q)| FrameData {
                t,
                theta_deg: sim::observables::angles_deg(q),
                x: (0..q.len() / 3).map(|i| q[3 * i]).collect(),
                y: (0..q.len() / 3).map(|i| q[3 * i + 1]).collect(),
            })
            .collect();
        Self {
            label: label.to_string(),
            model: scene.model,
            drive: scene.drive.clone(),
            t_end: scene.run.t_end,
            integrator: run.integrator.clone(),
            arrival_times: traj.arrival_times.clone(),
            speed: sim::observables::wave_speed(&traj.arrival_times),
            final_theta_deg: traj.final_theta_deg(),
            frames,
        }
    }
}

/// "kink α = 60°" or "antikink α = −60°".
fn wave_name(alpha_deg: f64) -> String {
    let kind = if alpha_deg > 0.0 { "kink" } else { "antikink" };
    format!("{kind} α = {}°", describe::num(alpha_deg))
}

/// Snapshot size in a filmstrip for an N-block ladder: 330 pixels tall up
/// to N = 10, taller for longer chains (up to 900), so that blocks stay
/// visible.
pub fn strip_frame(n: usize) -> (u32, u32) {
    let h = (330.0 * (n.max(10) as f64 / 10.0).sqrt()).min(900.0) as u32;
    (96, h)
}

/// One filmstrip: snapshots of a single-run scene at `times`, sharing one
/// scale.
fn strip_image(
    label: &str,
    scene: &Scene,
    times: &[f64],
    frame: Option<(u32, u32)>,
) -> Result<(Pixmap, RunData)> {
    let run = run::simulate(scene, times)?;
    let ladder = Ladder::new(scene.model.params()?);
    let traj = &run.trajectory;
    let frames: Vec<Frame<'_>> = traj
        .times
        .iter()
        .zip(&traj.states)
        .map(|(&time, q)| Frame { time, q })
        .collect();
    let title = (!label.is_empty()).then(|| format!("{label}  {}", wave_name(scene.model.alpha)));
    let opts = FilmstripOptions {
        frame_size: Some(frame.unwrap_or_else(|| strip_frame(scene.model.n))),
        title,
        label: None,
        view: None,
    };
    let image = compose::filmstrip(&ladder, &frames, &opts)?;
    Ok((image, RunData::new(label, scene, &run)))
}

/// A filmstrip figure (figures 1c, 3 and 4a): one strip per panel, two
/// strips a row, with the scene's title; snapshots of `frame` pixels
/// (default [`strip_frame`]).
pub fn filmstrip_figure(
    scene: &Scene,
    frame: Option<(u32, u32)>,
) -> Result<(Pixmap, Vec<RunData>)> {
    let labels = panel_labels(scene);
    let runs = scene.runs();
    let strips = runs
        .iter()
        .zip(&labels)
        .map(|((s, times), label)| strip_image(label, s, times, frame))
        .collect::<Result<Vec<_>>>()?;
    let (panels, data): (Vec<Panel>, Vec<RunData>) =
        strips.into_iter().map(|(p, d)| (Panel::new(p), d)).unzip();
    let layout =
        Layout::columns(if panels.len() > 2 { 2 } else { 1 }).title(describe::title(scene));
    Ok((compose::compose(&panels, &layout)?, data))
}

fn panel_labels(scene: &Scene) -> Vec<String> {
    match &scene.output {
        OutputSpec::Filmstrip { panels, .. } | OutputSpec::Arrivals { curves: panels } => {
            let mut l: Vec<String> = panels.iter().map(|p| p.label.clone()).collect();
            if l.is_empty() {
                l.push(String::new());
            }
            l
        }
        _ => vec![String::new()],
    }
}

/// Speed in blocks per 1000 τ (see `observables::wave_speed`).
pub fn fitted_speed(arrivals: &[Option<f64>]) -> Option<f64> {
    sim::observables::wave_speed(arrivals).map(|v| 1000.0 * v)
}

/// The arrival-time chart (figure S6): t_n against n for each curve; one
/// colour and marker per |α|, antikinks dashed.
pub fn arrivals_figure(scene: &Scene) -> Result<(Pixmap, Vec<RunData>)> {
    let runs = scene.runs();
    let labels = panel_labels(scene);
    let n_max = runs.iter().map(|(s, _)| s.model.n).max().unwrap_or(10);
    let mut spec = ChartSpec::new(
        Axis::new("block n").range(0.5, n_max as f64 + 0.5),
        Axis::new("arrival time tₙ / τ"),
    )
    .title(describe::title(scene));
    let markers = [Marker::Circle, Marker::Square, Marker::Triangle];
    let mut groups: Vec<f64> = Vec::new();
    let mut data = Vec::with_capacity(runs.len());
    for ((s, _), label) in runs.iter().zip(&labels) {
        let run = run::simulate(s, &[])?;
        let alpha = s.model.alpha;
        let k = match groups.iter().position(|g| *g == alpha.abs()) {
            Some(k) => k,
            None => {
                groups.push(alpha.abs());
                groups.len() - 1
            }
        };
        let arrivals = &run.trajectory.arrival_times;
        let pts: Vec<(f64, f64)> = arrivals
            .iter()
            .enumerate()
            .filter_map(|(i, t)| t.map(|t| (i as f64 + 1.0, t)))
            .collect();
        let speed =
            fitted_speed(arrivals).map_or("stalls".to_string(), |v| format!("{v:.1} blocks/1000τ"));
        let name = if label.is_empty() {
            wave_name(alpha)
        } else {
            label.clone()
        };
        let mut series = Series::line(format!("{name}: {speed}"), pts, style::series_color(k + 1))
            .with_marker(markers[k % 3]);
        if alpha < 0.0 {
            series = series.dashed();
        }
        spec = spec.series(series);
        data.push(RunData::new(label, s, &run));
    }
    Ok((charts::line_chart(&spec, 820, 560)?.pixmap, data))
}

/// Frame times of a movie: `frames` times evenly over [0, t_end].
pub fn frame_times(t_end: f64, frames: usize) -> Vec<f64> {
    crate::scene::even_times(t_end, frames)
}

/// A window that follows the kink: `x_span` long (along the ladder),
/// as wide as the frame's `aspect` allows, centred on the kink of frame
/// `k` and kept inside the ladder `fit`.
fn follow_view(
    ladder: &Ladder,
    traj: &Trajectory,
    fit: View,
    k: usize,
    x_span: f64,
    aspect: f64,
) -> View {
    let b = ladder.params.b;
    let half = 0.5 * x_span / b;
    let last = (ladder.n() as f64 - 1.0).max(0.0);
    let centre_blocks = if last > 2.0 * half {
        traj.kink_position[k].clamp(half, last - half)
    } else {
        0.5 * last
    };
    let centre_y = 0.5 * (fit.y.0 + fit.y.1);
    View::centered(centre_blocks * b, centre_y, x_span, x_span * aspect)
}

/// One column of a movie's ladder: blocks `start..start + len` drawn into
/// `region`, through one window (`views` of length 1) or one per frame.
struct Column {
    start: usize,
    ladder: Ladder,
    region: Region,
    views: Vec<View>,
}

impl Column {
    fn view(&self, k: usize) -> View {
        self.views[k.min(self.views.len() - 1)]
    }

    fn len(&self) -> usize {
        self.ladder.n()
    }
}

/// Gap between the columns of a folded ladder, pixels.
const COLUMN_GAP: f32 = 8.0;

/// A long ladder folded into columns side by side, like lines of text,
/// so that every block stays in the frame and at least as large as the
/// frame allows: segments start at even blocks (the parity of t_n is
/// kept) and overlap by one block, so every spring is drawn. The number of
/// columns is the one that draws the blocks largest.
fn fold(ladder: &Ladder, states: &[Vec<f64>], region: Region) -> Result<Vec<Column>> {
    let n = ladder.n();
    let b = ladder.params.b;
    let all: Vec<&[f64]> = states.iter().map(|q| q.as_slice()).collect();
    let whole = View::fit(&all);
    let across = (whole.y.1 - whole.y.0).max(1e-9);
    let columns_of = |stride: usize| (n - 1).div_ceil(stride).max(1);
    let scale_of = |stride: usize| {
        let cols = columns_of(stride) as f32;
        let w = (region.w - COLUMN_GAP * (cols - 1.0)) / cols;
        let along = stride as f64 * b + 2.0;
        (region.h as f64 / along).min(w as f64 / across)
    };
    let stride = (2..n)
        .step_by(2)
        .max_by(|&p, &q| scale_of(p).total_cmp(&scale_of(q)))
        .unwrap_or(n);
    let cols = columns_of(stride);
    let w = (region.w - COLUMN_GAP * (cols as f32 - 1.0)) / cols as f32;
    let mut out = Vec::with_capacity(cols);
    for j in 0..cols {
        let start = j * stride;
        let end = (start + stride + 1).min(n);
        let seg: Vec<&[f64]> = states.iter().map(|q| &q[3 * start..3 * end]).collect();
        let fit = View::fit(&seg);
        let along = stride as f64 * b + 2.0;
        // Every column at one scale (the same spans), its first block at
        // the top, like lines of text.
        let y_mid = 0.5 * (whole.y.0 + whole.y.1);
        let view = View::window(
            (fit.x.0, fit.x.0 + along),
            (y_mid - 0.5 * across, y_mid + 0.5 * across),
        );
        let params = crate::model::Params {
            n: end - start,
            ..ladder.params
        };
        out.push(Column {
            start,
            ladder: Ladder::new(params),
            region: Region {
                x: (region.x + j as f32 * (w + COLUMN_GAP)).round(),
                y: region.y,
                w: w.floor().max(1.0),
                h: region.h,
            },
            views: vec![view],
        });
    }
    Ok(out)
}

/// What a movie draws before any pixel: its run, its layout and the
/// columns of its ladder with their cameras.
struct MoviePlan {
    title: String,
    run: SceneRun,
    ladder: Ladder,
    layout: MovieLayout,
    columns: Vec<Column>,
    /// Where the time label goes when the ladder is folded.
    time_band: Option<Region>,
}

impl MoviePlan {
    fn new(scene: &Scene, opts: &MovieOptions) -> Result<Self> {
        let camera = match scene.output {
            OutputSpec::Movie { camera } => camera,
            _ => Camera::Fixed,
        };
        let times = frame_times(scene.run.t_end, opts.frames);
        let run = run::simulate(scene, &times)?;
        let ladder = Ladder::new(scene.model.params()?);
        let layout = MovieLayout::new(opts.width, opts.height, ladder.n());
        let region = layout.ladder;
        let aspect = region.w as f64 / region.h as f64;
        let traj = &run.trajectory;
        let all: Vec<&[f64]> = traj.states.iter().map(|q| q.as_slice()).collect();
        let fixed = View::fit(&all);
        // Pixels per s when the whole ladder is shown (it runs down the
        // frame: its length against the region's height).
        let along = fixed.x.1 - fixed.x.0;
        let across = fixed.y.1 - fixed.y.0;
        let scale = (region.h as f64 / along).min(region.w as f64 / across);
        let whole = |views: Vec<View>| Column {
            start: 0,
            ladder,
            region,
            views,
        };
        let (columns, time_band) = match camera {
            Camera::Fixed => (vec![whole(vec![fixed])], None),
            Camera::Auto if scale >= MIN_BLOCK_PIXELS => (vec![whole(vec![fixed])], None),
            Camera::Follow => {
                let span = 5.0 * ladder.params.b;
                let views = (0..traj.states.len())
                    .map(|k| follow_view(&ladder, traj, fixed, k, span, aspect))
                    .collect();
                (vec![whole(views)], None)
            }
            Camera::Auto => {
                let band = 1.6 * style::size::LABEL;
                let inner = Region {
                    h: (region.h - band).max(1.0),
                    ..region
                };
                let time = Region {
                    y: region.y + region.h - band,
                    h: band,
                    ..region
                };
                (fold(&ladder, &traj.states, inner)?, Some(time))
            }
        };
        Ok(Self {
            title: describe::title(scene),
            run,
            ladder,
            layout,
            columns,
            time_band,
        })
    }

    /// The snapshot of column `c` at frame `k`.
    fn snapshot(&self, c: &Column, k: usize) -> Result<Snapshot<'_>> {
        let traj = &self.run.trajectory;
        let q = &traj.states[k][3 * c.start..3 * (c.start + c.len())];
        let mut snap = Snapshot::new(&c.ladder, q)?.with_view(c.view(k));
        if self.time_band.is_none() {
            snap = snap.with_time(traj.times[k]);
        }
        snap.clamp = c.start == 0;
        Ok(snap)
    }

    /// Draws frame `k`'s ladder (every column, and the time label of a
    /// folded ladder).
    fn draw(&self, canvas: &mut Pixmap, k: usize) -> Result<()> {
        for c in &self.columns {
            snapshot::draw_snapshot(canvas, c.region, &self.snapshot(c, k)?);
        }
        if let Some(band) = self.time_band {
            style::draw_text(
                canvas,
                &snapshot::time_label(self.run.trajectory.times[k]),
                (band.x + 0.5 * band.w, band.y + 0.5 * band.h),
                style::size::LABEL,
                style::DARK,
                (style::HAlign::Center, style::VAlign::Middle),
            );
        }
        Ok(())
    }
}

/// Pixel positions of both ends of every block, one list per frame.
pub type BlockPixels = Vec<Vec<(f32, f32)>>;

/// For a test of the camera: the ladder's region of a movie frame and the
/// pixel positions of both ends of every block at every frame, as the
/// movie draws them (a block in two columns of a folded ladder twice).
pub fn movie_block_pixels(scene: &Scene, opts: &MovieOptions) -> Result<(Region, BlockPixels)> {
    let plan = MoviePlan::new(scene, &opts.validated()?)?;
    let mut frames = Vec::new();
    for k in 0..plan.run.trajectory.states.len() {
        let mut px = Vec::new();
        for c in &plan.columns {
            let snap = plan.snapshot(c, k)?;
            for i in 0..c.len() {
                let (a, b) = crate::model::ladder::nodes(snap.q, i);
                px.push(snapshot::pixel_of(c.region, &snap, a));
                px.push(snapshot::pixel_of(c.region, &snap, b));
            }
        }
        frames.push(px);
    }
    Ok((plan.layout.ladder, frames))
}

/// A movie: the GIF, the kymograph PNG and the run's data. Each frame
/// shows the ladder on the left and, on the right, the kymograph of
/// sin θ_n up to that frame.
pub fn movie(scene: &Scene, opts: &MovieOptions) -> Result<(Vec<u8>, Vec<u8>, RunData)> {
    movie_observed(scene, opts, &|| {})
}

/// As [`movie`], calling `frame_done` after each frame is encoded.
pub fn movie_observed(
    scene: &Scene,
    opts: &MovieOptions,
    frame_done: &(dyn Fn() + Sync),
) -> Result<(Vec<u8>, Vec<u8>, RunData)> {
    let opts = opts.validated()?;
    let plan = MoviePlan::new(scene, &opts)?;
    let traj = &plan.run.trajectory;
    let n = plan.ladder.n();
    let layout = &plan.layout;
    let heat = heat_map(traj, n, layout.heat)?;
    let mut gif = GifWriter::new(opts.width, opts.height, opts.fps)?;
    let blank = || {
        style::white_pixmap(opts.width, opts.height)
            .ok_or_else(|| Error::failed("the movie frame does not fit in memory"))
    };
    // What every frame shares is drawn once; each frame starts from a copy.
    let mut background = blank()?;
    layout.decorate(&mut background, &plan.title, scene.run.t_end, n);
    let mut canvas = blank()?;
    for k in 0..traj.states.len() {
        canvas.data_mut().copy_from_slice(background.data());
        plan.draw(&mut canvas, k)?;
        layout.restore_title(&mut canvas, &background);
        reveal_rows(
            &mut canvas,
            &heat,
            layout.heat,
            (k + 1) as f32 / traj.states.len() as f32,
        );
        gif.push_frame(&canvas)?;
        frame_done();
    }
    let kymo = kymograph_image(
        &plan.title,
        traj,
        n,
        opts.width.max(480),
        opts.height.max(360),
    )?;
    let data = RunData::new("", scene, &plan.run);
    Ok((gif.finish()?, png_bytes(&kymo)?, data))
}

/// A kymograph figure: sin θ_n of the scene's run over `frames` rows.
pub fn kymograph_figure(scene: &Scene, frames: usize) -> Result<(Pixmap, RunData)> {
    let times = frame_times(scene.run.t_end, frames);
    let run = run::simulate(scene, &times)?;
    let title = describe::title(scene);
    let image = kymograph_image(&title, &run.trajectory, scene.model.n, 820, 560)?;
    Ok((image, RunData::new("", scene, &run)))
}

/// Where a movie frame puts the title, the ladder and the live kymograph.
struct MovieLayout {
    width: f32,
    ladder: Region,
    heat: Region,
}

impl MovieLayout {
    /// Width of one block's column of the live kymograph, in pixels: a
    /// narrow panel keeps the changed rectangle of each GIF frame small.
    const COLUMN: f32 = 20.0;

    fn new(width: u32, height: u32, n: usize) -> Self {
        let (w, h) = (width as f32, height as f32);
        let top = (1.8 * style::size::TITLE).min(0.2 * h);
        let split = (0.45 * w).round();
        let heat_x = split + (0.1 * w).min(56.0);
        let bottom = (2.6 * style::size::TICK).min(0.15 * h);
        Self {
            width: w,
            ladder: Region {
                x: 0.0,
                y: top,
                w: split,
                h: (h - top).max(1.0),
            },
            heat: Region {
                x: heat_x.round(),
                y: (top + 0.8 * style::size::TICK).round(),
                w: (w - heat_x - 0.04 * w)
                    .min((Self::COLUMN * n as f32).max(0.25 * w))
                    .max(1.0)
                    .round(),
                h: (h - top - bottom - 0.8 * style::size::TICK)
                    .max(1.0)
                    .round(),
            },
        }
    }

    /// Copies the title band back from `background` (a camera window may
    /// draw the ladder over it).
    fn restore_title(&self, canvas: &mut Pixmap, background: &Pixmap) {
        let bytes = 4 * canvas.width() as usize * self.ladder.y as usize;
        canvas.data_mut()[..bytes].copy_from_slice(&background.data()[..bytes]);
    }

    /// Title across the frame; time axis and block labels of the kymograph.
    fn decorate(&self, canvas: &mut Pixmap, title: &str, t_end: f64, n: usize) {
        use style::{DARK, HAlign, VAlign, draw_text, size};
        let tick = size::TICK;
        draw_text(
            canvas,
            title,
            (0.5 * self.width, 6.0),
            size::TITLE,
            DARK,
            (HAlign::Center, VAlign::Top),
        );
        let r = self.heat;
        let left = r.x - 4.0;
        draw_text(
            canvas,
            "t/τ = 0",
            (left, r.y),
            tick,
            DARK,
            (HAlign::Right, VAlign::Top),
        );
        let end = format!("{t_end:.0}");
        draw_text(
            canvas,
            &end,
            (left, r.y + r.h),
            tick,
            DARK,
            (HAlign::Right, VAlign::Baseline),
        );
        let below = r.y + r.h + 4.0;
        draw_text(
            canvas,
            "block 1",
            (r.x, below),
            tick,
            DARK,
            (HAlign::Left, VAlign::Top),
        );
        let last = format!("{n}");
        draw_text(
            canvas,
            &last,
            (r.x + r.w, below),
            tick,
            DARK,
            (HAlign::Right, VAlign::Top),
        );
        let legend = "sin θₙ: red +1, blue −1";
        let mid = (r.x + 0.5 * r.w, below + 1.3 * tick);
        draw_text(
            canvas,
            legend,
            mid,
            tick,
            DARK,
            (HAlign::Center, VAlign::Top),
        );
    }
}

/// The whole kymograph as a `region`-sized image: one row per frame, one
/// column per block, sin θ_n in the diverging map (no anti-aliasing).
fn heat_map(traj: &Trajectory, n: usize, region: Region) -> Result<Pixmap> {
    let (w, h) = (region.w as u32, region.h as u32);
    let mut map = style::white_pixmap(w, h)
        .ok_or_else(|| Error::bad_input("the movie frame is too small"))?;
    let rows = traj.states.len();
    let mut paint = tiny_skia::Paint {
        anti_alias: false,
        ..Default::default()
    };
    for (k, q) in traj.states.iter().enumerate() {
        let (y0, y1) = (
            k as f32 * h as f32 / rows as f32,
            (k + 1) as f32 * h as f32 / rows as f32,
        );
        for j in 0..n {
            let (x0, x1) = (
                j as f32 * w as f32 / n as f32,
                (j + 1) as f32 * w as f32 / n as f32,
            );
            let v = q[crate::model::ladder::itheta(j)].sin();
            paint.set_color(style::color(style::diverging(v)));
            if let Some(rect) =
                tiny_skia::Rect::from_ltrb(x0.floor(), y0.floor(), x1.ceil(), y1.ceil())
            {
                map.fill_rect(rect, &paint, tiny_skia::Transform::identity(), None);
            }
        }
    }
    Ok(map)
}

/// Copies the top `fraction` of `heat` into `canvas` at `region`.
fn reveal_rows(canvas: &mut Pixmap, heat: &Pixmap, region: Region, fraction: f32) {
    let rows = ((fraction * heat.height() as f32).round() as u32).min(heat.height());
    let (cw, hw) = (canvas.width() as usize, heat.width() as usize);
    let (x0, y0) = (region.x as usize, region.y as usize);
    let src = heat.data();
    let dst = canvas.data_mut();
    for y in 0..rows as usize {
        let from = &src[4 * y * hw..4 * (y + 1) * hw];
        let start = 4 * ((y0 + y) * cw + x0);
        if let Some(to) = dst.get_mut(start..start + from.len()) {
            to.copy_from_slice(from);
        }
    }
}

/// The kymograph of sin θ_n of `traj`: blocks across, time down.
pub fn kymograph_image(
    title: &str,
    traj: &Trajectory,
    n: usize,
    width: u32,
    height: u32,
) -> Result<Pixmap> {
    let states: Vec<&[f64]> = traj.states.iter().map(|q| q.as_slice()).collect();
    let values = charts::polarisation_rows(&states);
    let kymo_title = if title.ends_with("sin θₙ") {
        title.to_string()
    } else {
        format!("{title}: sin θₙ")
    };
    let mut k = Kymograph::new(&traj.times, &values, n);
    k.title = Some(&kymo_title);
    Ok(charts::kymograph(&k, width, height)?.pixmap)
}
