//! The simulated scenes: filmstrips (figures 1c, 3, 4a), arrival times
//! (figure S6) and the movies with their kymographs. Each simulation runs
//! only to its last frame and is sampled only at the times drawn.

use crate::catalog::{SCENE_INTEGRATOR, SimSpec, StripSpec};
use crate::encode::{GifWriter, png_bytes};
use crate::error::{Error, Result};
use crate::model::Ladder;
use crate::render::charts::{self, Axis, ChartSpec, Kymograph, Marker, Series};
use crate::render::compose::{self, FilmstripOptions, Frame, Layout, Panel};
use crate::render::snapshot::{self, Region, Snapshot, View};
use crate::render::style;
use crate::sim::{self, Trajectory};
use tiny_skia::Pixmap;

/// Movie frame count, size and rate (`--frames`, `--size`, `--fps`).
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
                "--frames must be between 2 and {MAX_FRAMES}, got {}",
                self.frames
            )));
        }
        for side in [self.width, self.height] {
            if !(MIN_SIDE..=MAX_SIDE).contains(&side) {
                return Err(Error::bad_input(format!(
                    "--size must be WxH with each side between {MIN_SIDE} and {MAX_SIDE} pixels, got {}x{}",
                    self.width, self.height
                )));
            }
        }
        if !(self.fps.is_finite() && self.fps > 0.0 && self.fps <= 100.0) {
            return Err(Error::bad_input(format!(
                "--fps must be a number in (0, 100], got {}",
                self.fps
            )));
        }
        Ok(self)
    }
}

/// Runs `spec` with the scenes' integrator, sampled at `times`.
pub fn run(spec: &SimSpec, times: &[f64]) -> Result<Trajectory> {
    sim::simulate(&spec.scenario()?, times, &SCENE_INTEGRATOR)
}

/// "kink α = 60°" or "antikink α = −60°".
fn wave_name(alpha_deg: f64) -> String {
    let kind = if alpha_deg > 0.0 { "kink" } else { "antikink" };
    format!("{kind} α = {}°", signed(alpha_deg))
}

/// A number with a typographic minus sign.
fn signed(x: f64) -> String {
    format!("{x}").replace('-', "−")
}

/// Snapshot size in a filmstrip for an N-block ladder.
pub const STRIP_FRAME: (u32, u32) = (96, 330);

/// One filmstrip: snapshots of `strip` at its times, sharing one scale.
fn strip_image(strip: &StripSpec, frame: (u32, u32)) -> Result<Pixmap> {
    let traj = run(&strip.sim, strip.times)?;
    let ladder = Ladder::new(strip.sim.params()?);
    let frames: Vec<Frame<'_>> = traj
        .times
        .iter()
        .zip(&traj.states)
        .map(|(&time, q)| Frame { time, q })
        .collect();
    let title = if strip.label.is_empty() {
        None
    } else {
        Some(format!(
            "{}  {}",
            strip.label,
            wave_name(strip.sim.alpha_deg)
        ))
    };
    let opts = FilmstripOptions {
        frame_size: Some(frame),
        title,
        label: None,
        view: None,
    };
    compose::filmstrip(&ladder, &frames, &opts)
}

/// Figures 1c, 3 and 4a: one filmstrip per strip (snapshots of `frame`
/// pixels), two strips a row, with a title.
pub fn strips_figure(title: &str, strips: &[StripSpec], frame: (u32, u32)) -> Result<Pixmap> {
    let panels = strips
        .iter()
        .map(|s| strip_image(s, frame).map(Panel::new))
        .collect::<Result<Vec<_>>>()?;
    let layout = Layout::columns(if panels.len() > 2 { 2 } else { 1 }).title(title);
    compose::compose(&panels, &layout)
}

/// Simulated window of the arrival-time figure S6.
const ARRIVAL_T_END: f64 = 4000.0;

/// Speed in blocks per 1000 τ (see `observables::wave_speed`).
pub fn fitted_speed(arrivals: &[Option<f64>]) -> Option<f64> {
    sim::observables::wave_speed(arrivals).map(|v| 1000.0 * v)
}

/// Figure S6: t_n against n for the kink and antikink at each |α|.
pub fn arrivals_figure(title: &str, alphas: &[f64]) -> Result<Pixmap> {
    let mut spec = ChartSpec::new(
        Axis::new("block n").range(0.5, 10.5),
        Axis::new("arrival time tₙ / τ"),
    )
    .title(title);
    let markers = [Marker::Circle, Marker::Square, Marker::Triangle];
    for (k, &a) in alphas.iter().enumerate() {
        let color = style::series_color(k + 1);
        for alpha in [a, -a] {
            let sim = SimSpec {
                alpha_deg: alpha,
                ..SimSpec::paper(alpha, ARRIVAL_T_END)
            };
            let traj = run(&sim, &[])?;
            let pts: Vec<(f64, f64)> = traj
                .arrival_times
                .iter()
                .enumerate()
                .filter_map(|(i, t)| t.map(|t| (i as f64 + 1.0, t)))
                .collect();
            let speed = fitted_speed(&traj.arrival_times)
                .map_or("stalls".to_string(), |v| format!("{v:.1} blocks/1000τ"));
            let label = format!("{}: {speed}", wave_name(alpha));
            let mut s = Series::line(label, pts, color).with_marker(markers[k % 3]);
            if alpha < 0.0 {
                s = s.dashed();
            }
            spec = spec.series(s);
        }
    }
    Ok(charts::line_chart(&spec, 820, 560)?.pixmap)
}

/// Frame times of a movie: `frames` times evenly over [0, t_end].
pub fn frame_times(t_end: f64, frames: usize) -> Vec<f64> {
    let last = (frames - 1).max(1) as f64;
    (0..frames).map(|k| t_end * k as f64 / last).collect()
}

/// The camera of a movie: one fixed window fitting every frame, or a window
/// that follows the kink (movie 3), `blocks` blocks tall.
fn movie_view(ladder: &Ladder, traj: &Trajectory, k: usize, follow: bool, aspect: f64) -> View {
    let all: Vec<&[f64]> = traj.states.iter().map(|q| q.as_slice()).collect();
    let fit = View::fit(&all);
    if !follow {
        return fit;
    }
    let b = ladder.params.b;
    let x_span = 5.0 * b;
    let centre_x = traj.kink_position[k].clamp(1.5, ladder.n() as f64 - 1.5) * b;
    let centre_y = 0.5 * (fit.y.0 + fit.y.1);
    View::centered(centre_x, centre_y, x_span, x_span * aspect)
}

/// A movie: the GIF and the kymograph PNG. Each frame shows the ladder on
/// the left and, on the right, the kymograph of sin θ_n up to that frame.
pub fn movie(
    title: &str,
    sim: &SimSpec,
    follow: bool,
    opts: &MovieOptions,
) -> Result<(Vec<u8>, Vec<u8>)> {
    let opts = opts.validated()?;
    let times = frame_times(sim.t_end, opts.frames);
    let traj = run(sim, &times)?;
    let ladder = Ladder::new(sim.params()?);
    let layout = MovieLayout::new(opts.width, opts.height, sim.n);
    let aspect = layout.ladder.w as f64 / layout.ladder.h as f64;
    let fixed = movie_view(&ladder, &traj, 0, false, aspect);
    let heat = heat_map(&traj, ladder.n(), layout.heat)?;
    let mut gif = GifWriter::new(opts.width, opts.height, opts.fps)?;
    let blank = || {
        style::white_pixmap(opts.width, opts.height)
            .ok_or_else(|| Error::bad_input("the movie frame does not fit in memory"))
    };
    // What every frame shares is drawn once; each frame starts from a copy.
    let mut background = blank()?;
    layout.decorate(&mut background, title, sim.t_end, ladder.n());
    let mut canvas = blank()?;
    for (k, q) in traj.states.iter().enumerate() {
        let view = if follow {
            movie_view(&ladder, &traj, k, true, aspect)
        } else {
            fixed
        };
        let snap = Snapshot::new(&ladder, q)?
            .with_time(traj.times[k])
            .with_view(view);
        canvas.data_mut().copy_from_slice(background.data());
        snapshot::draw_snapshot(&mut canvas, layout.ladder, &snap);
        layout.restore_title(&mut canvas, &background);
        reveal_rows(
            &mut canvas,
            &heat,
            layout.heat,
            (k + 1) as f32 / traj.states.len() as f32,
        );
        gif.push_frame(&canvas)?;
    }
    let kymo = kymograph_image(
        title,
        &traj,
        ladder.n(),
        opts.width.max(480),
        opts.height.max(360),
    )?;
    Ok((gif.finish()?, png_bytes(&kymo)?))
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
                    .min(Self::COLUMN * n as f32)
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
    let kymo_title = format!("{title}: sin θₙ");
    let mut k = Kymograph::new(&traj.times, &values, n);
    k.title = Some(&kymo_title);
    Ok(charts::kymograph(&k, width, height)?.pixmap)
}
