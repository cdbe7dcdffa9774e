//! The movies of simulated scenes and their kymographs: the camera (a
//! followed view or a ladder folded into columns), each frame drawn from
//! the run's states, encoded as it is drawn.

use super::data::RunData;
use super::kymograph::kymograph_picture;
use super::kymograph::{MovieKymograph, frame_times};
use super::options::MovieOptions;
use super::run::{self, SceneRun};
use crate::encode::{Format, MovieWriter, Mp4Quality};
use crate::error::{Error, Result};
use crate::model::Ladder;
use crate::render::fold::{self, Fold};
use crate::render::palette::{Palette, Role};
use crate::render::snapshot::{self, Region, Snapshot, View};
use crate::render::{Canvas, MovieLayout, Theme, style};
use crate::scene::{Camera, MIN_BLOCK_PIXELS, OutputSpec, Scene, describe};
use crate::sim::Trajectory;
use tiny_skia::Pixmap;

/// A window that follows the kink: `x_span` long (along the ladder),
/// as wide as the frame's `aspect` allows, centred on the kink of frame
/// `k` and kept inside `fit` (every block of every frame), so that the
/// ladder fills the window from the first frame to the last.
fn follow_view(
    ladder: &Ladder,
    traj: &Trajectory,
    fit: View,
    k: usize,
    x_span: f64,
    aspect: f64,
) -> View {
    let b = ladder.params.b;
    let half = 0.5 * x_span;
    let centre_x = if fit.x.1 - fit.x.0 > x_span {
        (traj.kink_position[k] * b).clamp(fit.x.0 + half, fit.x.1 - half)
    } else {
        0.5 * (fit.x.0 + fit.x.1)
    };
    let centre_y = 0.5 * (fit.y.0 + fit.y.1);
    View::centered(centre_x, centre_y, x_span, x_span * aspect)
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

/// A long ladder folded into columns side by side (`render::fold`): the
/// number of columns is the one that draws the blocks largest in `region`.
fn folded_columns(ladder: &Ladder, states: &[Vec<f64>], region: Region) -> Vec<Column> {
    let all: Vec<&[f64]> = states.iter().map(|q| q.as_slice()).collect();
    let folded = Fold::best_in(ladder, &all, region, fold::COLUMN_GAP);
    let regions = folded.regions(region, fold::COLUMN_GAP);
    folded
        .segments
        .into_iter()
        .zip(regions)
        .map(|(s, region)| Column {
            start: s.start,
            ladder: s.ladder,
            region,
            views: vec![s.view],
        })
        .collect()
}

/// Height of the band above a folded movie's columns that holds their
/// numbers, design pixels.
const COLUMN_NUMBER_BAND: f32 = 1.3 * style::size::TICK;

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
    /// A following camera's reference fixed in the lab: the rest position
    /// X_n of every block, drawn as a scale behind the ladder.
    lab_scale: Option<Vec<f64>>,
    /// An apparatus movie's clock: τ in seconds, and how many seconds of
    /// the apparatus one second of the movie shows ([`SecondsClock`]).
    clock: Option<SecondsClock>,
    /// Whether the ladder is folded into numbered columns.
    folded: bool,
    /// The toy as built: the impacts each frame marks (`scenes::toy`).
    impacts: Vec<Vec<[usize; 2]>>,
}

/// The clock of a movie of an apparatus (a scene with `[apparatus]`):
/// its time labels count seconds of the apparatus, and say how the
/// movie plays them (in real time, or slowed or sped up by a stated
/// factor).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SecondsClock {
    pub tau_s: f64,
    /// Apparatus seconds per second of the movie: t_end / (frames / fps).
    pub speed_up: f64,
}

impl SecondsClock {
    /// The clock of `scene`'s movie at `opts`, if it is an apparatus.
    pub fn of(scene: &Scene, opts: &MovieOptions) -> Option<Self> {
        let c = scene.apparatus.as_ref()?.conversion.as_ref()?;
        let played_s = opts.frames as f64 / opts.fps;
        Some(Self {
            tau_s: c.tau_s,
            speed_up: scene.run.t_end * c.tau_s / played_s,
        })
    }

    /// "t = 1.23 s", and how the movie plays it: "real time" within 2 %,
    /// else "played 2.1× slower" or "3.0× faster".
    pub fn label(&self, t: f64) -> String {
        format!("t = {:.2} s ({})", t * self.tau_s, self.rate())
    }

    /// How the movie plays the apparatus' seconds.
    pub fn rate(&self) -> String {
        let r = self.speed_up;
        if (r - 1.0).abs() < 0.02 {
            "real time".into()
        } else if r < 1.0 {
            format!("played {:.1}× slower", 1.0 / r)
        } else {
            format!("played {r:.1}× faster")
        }
    }
}

impl MoviePlan {
    fn new(theme: &Theme, scene: &Scene, opts: &MovieOptions) -> Result<Self> {
        // `t_end = "auto"` resolved here too, for callers of this function
        // that did not go through `scenes::render_to` (a no-op when resolved).
        let scene = &scene.with_auto_window()?;
        let camera = match scene.output {
            OutputSpec::Movie { camera } => camera,
            _ => Camera::Fixed,
        };
        let times = frame_times(scene.run.t_end, opts.frames);
        let run = run::simulate(scene, &times)?;
        let ladder = super::toy::drawn_ladder(scene)?;
        let impacts = super::toy::impacts_by_frame(run.trajectory.impacts.as_deref(), &times);
        let layout = MovieLayout::new(theme, opts.width, opts.height, ladder.n());
        let region = layout.ladder;
        let aspect = layout.ladder_aspect();
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
                // A band above the columns for their first blocks' numbers.
                let inner = Region {
                    y: region.y + COLUMN_NUMBER_BAND,
                    h: (region.h - band - COLUMN_NUMBER_BAND).max(1.0),
                    ..region
                };
                let time = Region {
                    y: region.y + region.h - band,
                    h: band,
                    ..region
                };
                (folded_columns(&ladder, &traj.states, inner), Some(time))
            }
        };
        let clock = SecondsClock::of(scene, opts);
        let folded = time_band.is_some();
        // An apparatus' clock in seconds is drawn in a band of its own
        // under the ladder, as a folded ladder's time is.
        let (columns, time_band) = match (clock, time_band) {
            (Some(_), None) => with_time_band(columns, region),
            other => (columns, other.1),
        };
        let lab_scale = (camera == Camera::Follow).then(|| {
            let rest = ladder.ground_state();
            (0..ladder.n()).map(|i| rest[3 * i]).collect()
        });
        Ok(Self {
            title: describe::title(scene),
            run,
            ladder,
            layout,
            columns,
            time_band,
            lab_scale,
            clock,
            folded,
            impacts,
        })
    }

    /// The time label of frame time `t` (τ): seconds for an apparatus.
    fn time_text(&self, t: f64) -> String {
        match self.clock {
            Some(c) => c.label(t),
            None => snapshot::time_label(t),
        }
    }

    /// What every frame shares ([`MovieLayout::background`]), with an
    /// apparatus' kymograph time axis in seconds.
    fn background(&self, t_end: f64) -> Result<Pixmap> {
        let n = self.ladder.n();
        let Some(clock) = self.clock else {
            return self.layout.background(&self.title, t_end, n);
        };
        let mut p = style::white_pixmap(self.layout.width, self.layout.height)
            .ok_or_else(|| Error::failed("the movie frame does not fit in memory"))?;
        let ts = self.layout.transform();
        let mut c = crate::render::Raster::with_transform(&mut p, ts, self.layout.theme.font());
        for mut l in self.layout.labels(&self.title, t_end, n) {
            if l.text == "t/τ = 0" {
                l.text = "t = 0 s".into();
            } else if l.text == format!("{t_end:.0}") {
                l.text = format!("{:.1} s", t_end * clock.tau_s);
            }
            c.text(&l.text, l.at, l.size, Palette.color(Role::Ink), l.align);
        }
        Ok(p)
    }

    /// Each column's number (its first block) and where it is drawn, top
    /// centre in design pixels: none unless the ladder is folded.
    fn column_numbers(&self) -> Vec<(String, (f32, f32))> {
        if !self.folded {
            return Vec::new();
        }
        self.columns
            .iter()
            .map(|c| {
                let at = (
                    c.region.x + 0.5 * c.region.w,
                    c.region.y - COLUMN_NUMBER_BAND,
                );
                (format!("{}", c.start + 1), at)
            })
            .collect()
    }

    /// The number of each column's first block above it, when the ladder
    /// is folded (as filmstrips number theirs), onto the frames'
    /// `background`.
    fn number_columns(&self, background: &mut Pixmap) {
        let ts = self.layout.transform();
        let mut canvas =
            crate::render::Raster::with_transform(background, ts, self.layout.theme.font());
        let color = style::mix(Palette.color(Role::Ground), Palette.color(Role::Ink), 0.3);
        let align = (style::HAlign::Center, style::VAlign::Top);
        for (text, at) in self.column_numbers() {
            canvas.text(&text, at, style::size::TICK, color, align);
        }
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
        snap.lab_scale = self.lab_scale.as_deref();
        if c.start == 0 && c.len() == self.ladder.n() {
            snap.impacts = self.impacts.get(k).map_or(&[], |v| v.as_slice());
        }
        Ok(snap)
    }

    /// Frame `k` into `canvas`: the background, every column's snapshot
    /// (and the time label of a folded ladder), and the top `fraction` of
    /// the live kymograph `heat`.
    fn draw_frame(
        &self,
        canvas: &mut Pixmap,
        background: &Pixmap,
        heat: &Pixmap,
        k: usize,
        fraction: f32,
    ) -> Result<()> {
        let snaps = self
            .columns
            .iter()
            .map(|c| Ok((c.region, self.snapshot(c, k)?)))
            .collect::<Result<Vec<_>>>()?;
        let label = self
            .time_band
            .map(|band| (band, self.time_text(self.run.trajectory.times[k])));
        let label = label.as_ref().map(|(band, text)| (*band, text.as_str()));
        self.layout
            .draw_frame(canvas, background, &snaps, label, heat, fraction);
        Ok(())
    }
}

/// The one column of an unfolded ladder with a band for the time label
/// taken from the bottom of `region`.
fn with_time_band(mut columns: Vec<Column>, region: Region) -> (Vec<Column>, Option<Region>) {
    let band = 1.6 * style::size::LABEL;
    let time = Region {
        y: region.y + region.h - band,
        h: band,
        ..region
    };
    for c in &mut columns {
        c.region.h = (c.region.h - band).max(1.0);
    }
    (columns, Some(time))
}

/// Pixel positions of both ends of every block, one list per frame.
pub type BlockPixels = Vec<Vec<(f32, f32)>>;

/// For a test of the camera: the ladder's region of a movie frame and the
/// pixel positions of both ends of every block at every frame, as the
/// movie draws them (a block in two columns of a folded ladder twice).
pub fn movie_block_pixels(
    theme: &Theme,
    scene: &Scene,
    opts: &MovieOptions,
) -> Result<(Region, BlockPixels)> {
    let plan = MoviePlan::new(theme, scene, &opts.validated()?)?;
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

/// For a test of folded movies: each column's number and where its text's
/// top centre is, in the frame's pixels (none when the ladder is not
/// folded).
pub fn movie_column_numbers(
    theme: &Theme,
    scene: &Scene,
    opts: &MovieOptions,
) -> Result<Vec<(String, (f32, f32))>> {
    let plan = MoviePlan::new(theme, scene, &opts.validated()?)?;
    let s = plan.layout.scale;
    Ok(plan
        .column_numbers()
        .into_iter()
        .map(|(t, (x, y))| (t, (x * s, y * s)))
        .collect())
}

/// A movie's files: its bytes in each format, its kymograph (a figure,
/// written in the figure formats asked for), its data.
pub type MovieFiles = (Vec<(Format, Vec<u8>)>, MovieKymograph, RunData);

/// A movie: its bytes in each of `formats` (GIF, MP4: the same frames),
/// its kymograph and the run's data. Each frame shows the ladder on
/// the left and, on the right, the kymograph of sin θ_n up to that frame;
/// the layout scales with the frame size (`render::MovieLayout`);
/// `frame_done` is called after each frame (for a progress bar).
pub fn movie(
    theme: &Theme,
    scene: &Scene,
    opts: &MovieOptions,
    formats: &[Format],
    frame_done: &(dyn Fn() + Sync),
) -> Result<MovieFiles> {
    movie_at(
        theme,
        scene,
        opts,
        formats,
        Mp4Quality::default(),
        frame_done,
    )
}

/// [`movie`] with the MP4 at `quality`.
pub fn movie_at(
    theme: &Theme,
    scene: &Scene,
    opts: &MovieOptions,
    formats: &[Format],
    quality: Mp4Quality,
    frame_done: &(dyn Fn() + Sync),
) -> Result<MovieFiles> {
    let opts = opts.validated()?;
    let mut writer = MovieWriter::with_quality(
        formats,
        (opts.width, opts.height),
        opts.fps,
        theme.palette.gif(),
        quality,
    )?;
    let plan = MoviePlan::new(theme, scene, &opts)?;
    let traj = &plan.run.trajectory;
    let n = plan.ladder.n();
    let layout = &plan.layout;
    let heat = layout.heat_map(&traj.states, n)?;
    // What every frame shares is drawn once; each frame starts from a copy.
    let mut background = plan.background(scene.run.t_end)?;
    plan.number_columns(&mut background);
    let mut canvas = style::white_pixmap(opts.width, opts.height)
        .ok_or_else(|| Error::failed("the movie frame does not fit in memory"))?;
    let frames = traj.states.len();
    for k in 0..frames {
        let shown = (k + 1) as f32 / frames as f32;
        plan.draw_frame(&mut canvas, &background, &heat, k, shown)?;
        writer.push_frame(&canvas)?;
        frame_done();
    }
    let kymo = kymograph_picture(
        theme,
        &plan.title,
        traj,
        n,
        opts.width.max(480),
        opts.height.max(360),
    )?;
    let data = RunData::with_kymograph(scene, plan.run);
    Ok((writer.finish()?, kymo, data))
}

/// Frame `k` of a movie exactly as [`movie`] draws it (for tests and
/// thumbnails).
pub fn movie_frame(theme: &Theme, scene: &Scene, opts: &MovieOptions, k: usize) -> Result<Pixmap> {
    let opts = opts.validated()?;
    let plan = MoviePlan::new(theme, scene, &opts)?;
    let traj = &plan.run.trajectory;
    let frames = traj.states.len();
    if k >= frames {
        return Err(Error::bad_input(format!(
            "the movie has {frames} frames, no frame {k}"
        )));
    }
    let n = plan.ladder.n();
    let layout = &plan.layout;
    let heat = layout.heat_map(&traj.states, n)?;
    let mut background = plan.background(scene.run.t_end)?;
    plan.number_columns(&mut background);
    let mut canvas = background.clone();
    let shown = (k + 1) as f32 / frames as f32;
    plan.draw_frame(&mut canvas, &background, &heat, k, shown)?;
    Ok(canvas)
}
