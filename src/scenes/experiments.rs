//! The experiments' figures (SPEC section 12; docs/experiments.md): what
//! each level of model predicts for the paper's water tank and printed
//! linkage, in the apparatus' units (s, cm, cm/s), beside the measurements.
//!
//! Every run is the scene's `[apparatus]` with some of its terms switched,
//! integrated by RK4 at [`STEP`] τ (the scheme that takes every term: a
//! velocity-dependent mass matrix, drag, pin friction); each run's
//! integrator is in the data file. No coefficient is fitted: the levels
//! switch terms of the apparatus on, nothing else.

use super::data::RunData;
use super::run;
use crate::error::{Error, Result};
use crate::render::charts::{self, Axis, ChartSpec, Marker, Series};
use crate::render::compose::{self, Layout, Panel};
use crate::render::{Picture, Theme, style};
use crate::scene::apparatus::{Apparatus, Damping, ExperimentFigure, PaperWord};
use crate::scene::{Method, OutputSpec, Scene, describe};
use crate::sim::IntegratorKind;
use crate::sim::{RunOptions, StopView};
use rayon::prelude::*;
use std::sync::atomic::{AtomicU64, Ordering};

/// The tank's measured kink speed (cm/s; main text and supplement).
pub const MEASURED_KINK_CM_S: f64 = 6.0;
/// The tank's measured c_antikink / c_kink.
pub const MEASURED_RATIO: f64 = 1.75;
/// The motor speeds of the tank's runs (Hz).
pub const MOTORS_HZ: [f64; 3] = [0.1, 0.2, 0.4];
/// The motor speed of the levels' figure (Hz), the middle one.
pub const LEVELS_MOTOR_HZ: f64 = 0.2;
/// The pin friction coefficients μ_p the linkage's figure starts from:
/// its range, coarse; [`refined_fronts`] adds the points between.
pub const PIN_FRICTION: [f64; 4] = [0.0, 0.5, 1.0, 1.5];
/// The linkage's figure halves every interval of μ_p at whose ends a
/// front differs, down to this width.
pub const PIN_FRICTION_RESOLUTION: f64 = 0.125;
/// The RK4 step of every run, in τ (docs/experiments.md: halving it moves
/// the speeds of a running wave by < 10⁻⁶).
pub const STEP: f64 = 0.125;

/// The levels of model of the tank (SPEC 12): name and what it switches on
/// over the bare apparatus (two-way stiff links, gravity g).
pub const LEVELS: [(&str, Level); 5] = [
    (
        "1 paper: linear damping γ",
        Level {
            damping: true,
            buoyancy_and_drag: false,
            added_mass: false,
            tape: false,
        },
    ),
    (
        "2 buoyancy + quadratic drag",
        Level {
            damping: false,
            buoyancy_and_drag: true,
            added_mass: false,
            tape: false,
        },
    ),
    (
        "3 + added mass",
        Level {
            damping: false,
            buoyancy_and_drag: true,
            added_mass: true,
            tape: false,
        },
    ),
    (
        "4 + tension-only tape",
        Level {
            damping: false,
            buoyancy_and_drag: true,
            added_mass: true,
            tape: true,
        },
    ),
    (
        "5 all terms (+ γ)",
        Level {
            damping: true,
            buoyancy_and_drag: true,
            added_mass: true,
            tape: true,
        },
    ),
];

/// The terms one level of model switches on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Level {
    /// The paper's linear damping ("paper": γ/√G kept).
    pub damping: bool,
    pub buoyancy_and_drag: bool,
    pub added_mass: bool,
    pub tape: bool,
}

impl Level {
    fn apply(self, a: &mut Apparatus) {
        a.damping = self.damping.then_some(Damping::Word(PaperWord::Paper));
        a.buoyancy = self.buoyancy_and_drag;
        a.drag = self.buoyancy_and_drag;
        a.added_mass = self.added_mass;
        a.tension_only = self.tape;
    }
}

/// The figure `which` of `scene` (whose `[apparatus]` is the tank's or the
/// linkage's), with every run's data.
pub fn experiment_figure(
    theme: &Theme,
    scene: &Scene,
    which: ExperimentFigure,
) -> Result<(Picture, Vec<RunData>)> {
    let (picture, data) = match which {
        ExperimentFigure::TankPositions => tank_positions(theme, scene)?,
        ExperimentFigure::TankLevels => tank_levels(theme, scene)?,
        ExperimentFigure::LinkageFriction => linkage_friction(theme, scene)?,
    };
    Ok((picture.titled(describe::title(scene)), data))
}

/// One run of the figure: its label, and `scene` as a data scene with its
/// apparatus changed by `change`, its α of sign `sign`, RK4 at [`STEP`].
struct Variant {
    label: String,
    scene: Scene,
}

fn variant(
    scene: &Scene,
    label: String,
    sign: f64,
    change: impl FnOnce(&mut Apparatus),
) -> Result<Variant> {
    let mut s = scene.clone();
    let mut a = scene.apparatus.clone().ok_or_else(|| {
        Error::bad_input(format!(
            "{} {}: an experiment figure needs an [apparatus]",
            scene.kind().name(),
            scene.name
        ))
    })?;
    change(&mut a);
    s.model.alpha = sign * scene.model.alpha.abs();
    let a = a.converted(s.model.alpha);
    if let Some(t) = a.conversion.as_ref().and_then(|c| c.t_end) {
        s.run.t_end = t;
    }
    s.apparatus = Some(a);
    s.output = OutputSpec::Data;
    s.run.integrator = Method::Fixed(IntegratorKind::Rk4);
    s.run.dt = Some(STEP);
    Ok(Variant { label, scene: s })
}

/// A finished run: its arrival times (s), bulk speed (cm/s), the block
/// pitch b (cm), and its data.
struct Done {
    arrivals_s: Vec<Option<f64>>,
    bulk_cm_s: Option<f64>,
    pitch_cm: f64,
    data: RunData,
}

/// A pin turning slower than this many ω_ε is held: the smoothed law's
/// creep under a torque within 0.5 % of the Coulomb limit (atanh 0.995 =
/// 3.0, `model::links`).
pub const HELD_RATE: f64 = 3.0;
/// How long (s) every pin must stay held, after the motor has stopped,
/// for the front to have stopped.
pub const HELD_FOR_S: f64 = 0.5;

/// When a figure's run has decided what it was run for, and ends there
/// (its `[apparatus] duration` is the cap): once every block has flipped
/// (an arrival, once set, never changes); or, with pin friction, once the
/// motor has stopped and every pin has been held ([`HELD_RATE`]) for
/// [`HELD_FOR_S`]: the front has stopped, and what would still move it is
/// the smoothed law's creep, which vanishes as ω_ε → 0 (docs/experiments.md).
struct Decided {
    /// The motor's end and the hold, in τ.
    drive_end: f64,
    hold: f64,
    /// The time the pins were first seen held in the current hold (f64
    /// bits; NaN: not held). The rule is asked in time order by one run.
    since: AtomicU64,
}

impl Decided {
    fn new(drive_end: f64, tau_s: f64) -> Self {
        Self {
            drive_end,
            hold: HELD_FOR_S / tau_s,
            since: AtomicU64::new(f64::NAN.to_bits()),
        }
    }

    fn decided(&self, view: &StopView) -> bool {
        if view.arrivals.iter().all(Option::is_some) {
            return true;
        }
        let Some(friction) = view.ladder.terms.friction else {
            return false;
        };
        let links = &view.ladder.terms.links;
        let held = view.t >= self.drive_end
            && friction.fastest_pin(view.ladder, links, view.q, view.v)
                < HELD_RATE * friction.omega_eps;
        if !held {
            self.since.store(f64::NAN.to_bits(), Ordering::Relaxed);
            return false;
        }
        let since = f64::from_bits(self.since.load(Ordering::Relaxed));
        if since.is_nan() {
            self.since.store(view.t.to_bits(), Ordering::Relaxed);
            return false;
        }
        view.t - since >= self.hold
    }
}

/// Runs every variant, two at a time or more (rayon), in order, each
/// until it has decided ([`Decided`]); each run's data says where it
/// ended (`t_end`).
fn run_all(variants: &[Variant]) -> Result<Vec<Done>> {
    variants
        .par_iter()
        .map(|v| {
            let a = v.scene.apparatus.as_ref().ok_or_else(|| unconverted(v))?;
            let c = a.conversion.as_ref().ok_or_else(|| unconverted(v))?;
            let drive_end = v.scene.scenario()?.protocol.drive_end();
            let decided = Decided::new(drive_end, c.tau_s);
            let stop = |view: &StopView| decided.decided(view);
            let options = RunOptions::default().limits(v.scene.limits).stop(&stop);
            let r = run::simulate_with(&v.scene, &[], &options)?;
            let arrivals = &r.trajectory.arrival_times;
            let mut data = RunData::new(&v.label, &v.scene, &r);
            data.t_end = r.trajectory.t_final;
            Ok(Done {
                arrivals_s: arrivals.iter().map(|t| t.map(|t| t * c.tau_s)).collect(),
                bulk_cm_s: bulk_speed(arrivals).map(|v| v * c.cm_per_s),
                pitch_cm: a.b,
                data,
            })
        })
        .collect()
}

/// The error of a variant without its converted apparatus (never made by
/// [`variant`]).
fn unconverted(v: &Variant) -> Error {
    Error::failed(format!("{}: the run has no converted [apparatus]", v.label))
}

/// The steady wave's speed (blocks per τ) in the lower half of the chain,
/// blocks N/2 + 1 .. N − 1 (one-based), away from the driven block: the
/// least-squares slope of n against t_n, as `sim::speed::wave_speed`
/// fits the whole chain. `None` unless every one of those blocks flipped,
/// each after the one above it (a wave running down): a chain that turns
/// all at once, or from the bottom up, has no speed.
pub fn bulk_speed(arrivals: &[Option<f64>]) -> Option<f64> {
    let n = arrivals.len();
    let times: Vec<f64> = arrivals
        .get(n / 2..n.checked_sub(1)?)?
        .iter()
        .copied()
        .collect::<Option<Vec<f64>>>()?;
    if times.len() < 3 || times.windows(2).any(|w| w[1] <= w[0]) {
        return None;
    }
    let pts: Vec<(f64, f64)> = times
        .iter()
        .enumerate()
        .map(|(i, t)| (i as f64, *t))
        .collect();
    Some(1.0 / crate::sim::observables::least_squares_slope(&pts))
}

/// "12.8 cm/s" or "no wave".
fn speed_text(c: Option<f64>) -> String {
    c.map_or("no wave".into(), |c| format!("{c:.1} cm/s"))
}

/// A chart at the style's frame of `natural` design pixels.
fn chart_picture(theme: &Theme, spec: &ChartSpec, natural: (u32, u32)) -> Result<Picture> {
    let (w, h) = theme.style.frame(natural);
    Ok(Picture::from(charts::line_chart(theme, spec, w, h)?))
}

/// Figure 1: the position (n − 1) b of each flipped block (cm) against its
/// arrival time (s), kink and antikink at each motor speed, with the bulk
/// speeds in cm/s (the supplement's apparatus panel).
fn tank_positions(theme: &Theme, scene: &Scene) -> Result<(Picture, Vec<RunData>)> {
    let mut variants = Vec::new();
    for f in MOTORS_HZ {
        for (sign, word) in [(1.0, "kink"), (-1.0, "antikink")] {
            variants.push(variant(scene, format!("{word}, {f} Hz"), sign, |a| {
                a.motor = Some(f)
            })?);
        }
    }
    let done = run_all(&variants)?;
    let mut spec = ChartSpec::new(
        Axis::new("time t (s)"),
        Axis::new("position (n − 1) b (cm)"),
    );
    let markers = [Marker::Circle, Marker::Square, Marker::Triangle];
    for (k, d) in done.iter().enumerate() {
        let (motor, kink) = (k / 2, k % 2 == 0);
        let pts: Vec<(f64, f64)> = d
            .arrivals_s
            .iter()
            .enumerate()
            .filter_map(|(i, t)| t.map(|t| (t, i as f64 * d.pitch_cm)))
            .collect();
        let color = style::series_color(motor + 1);
        let label = format!("{}: {}", variants[k].label, speed_text(d.bulk_cm_s));
        let s = Series::line(label, pts, color)
            .with_marker(markers[motor])
            .with_width(1.5);
        spec = spec.series(if kink { s } else { s.dashed() });
    }
    let picture = chart_picture(theme, &spec, (820, 600))?.fit_page();
    Ok((picture, done.into_iter().map(|d| d.data).collect()))
}

/// What one level of model gives in the tank: the bulk speeds (cm/s) of
/// the kink and the antikink, and of the kink with the links twice as
/// stiff ("stiff" links: k and 2k must agree, [`STIFF_TOLERANCE`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelResult {
    pub name: &'static str,
    pub kink_cm_s: Option<f64>,
    pub antikink_cm_s: Option<f64>,
    pub kink_2k_cm_s: Option<f64>,
}

impl LevelResult {
    /// c_antikink / c_kink, where both run.
    pub fn ratio(&self) -> Option<f64> {
        self.kink_cm_s.zip(self.antikink_cm_s).map(|(k, a)| a / k)
    }

    /// |c(2k)/c(k) − 1|, where both run.
    pub fn stiff_difference(&self) -> Option<f64> {
        self.kink_cm_s
            .zip(self.kink_2k_cm_s)
            .map(|(k, k2)| (k2 / k - 1.0).abs())
    }
}

pub use crate::scenes::stiff::STIFF_TOLERANCE;

/// Every level of [`LEVELS`] run on `scene`'s apparatus at
/// [`LEVELS_MOTOR_HZ`]: kink, antikink, and kink at 2k.
pub fn levels(scene: &Scene) -> Result<(Vec<LevelResult>, Vec<RunData>)> {
    let mut variants = Vec::new();
    for (name, level) in LEVELS {
        for (sign, word, stiffer) in [
            (1.0, "kink", 1.0),
            (-1.0, "antikink", 1.0),
            (1.0, "kink, links 2k", 0.5),
        ] {
            variants.push(variant(scene, format!("{name}, {word}"), sign, |a| {
                level.apply(a);
                a.motor = Some(LEVELS_MOTOR_HZ);
                a.stiff_gravity *= stiffer;
            })?);
        }
    }
    let done = run_all(&variants)?;
    let results = LEVELS
        .iter()
        .enumerate()
        .map(|(k, (name, _))| LevelResult {
            name,
            kink_cm_s: done[3 * k].bulk_cm_s,
            antikink_cm_s: done[3 * k + 1].bulk_cm_s,
            kink_2k_cm_s: done[3 * k + 2].bulk_cm_s,
        })
        .collect();
    Ok((results, done.into_iter().map(|d| d.data).collect()))
}

/// Figure 2: c_kink (cm/s) and c_antikink / c_kink for each level of
/// model at [`LEVELS_MOTOR_HZ`], beside the measured 6.0 cm/s and 1.75; a
/// level without a wave is drawn at zero and named "no wave". The legend
/// gives how far each level lands, and how much the kink moves when the
/// "stiff" links are made twice as stiff.
fn tank_levels(theme: &Theme, scene: &Scene) -> Result<(Picture, Vec<RunData>)> {
    let (results, data) = levels(scene)?;
    if let Some(r) = results
        .iter()
        .find(|r| r.stiff_difference().is_some_and(|d| d > STIFF_TOLERANCE))
    {
        return Err(Error::failed(format!(
            "{}: the kink's speed moves by {:.1} % between k and 2k, more than the {} % of \
             \"stiff\" links: give the links' stiffness in N/m or a smaller stiff_gravity",
            r.name,
            100.0 * r.stiff_difference().unwrap_or(0.0),
            100.0 * STIFF_TOLERANCE
        )));
    }
    let n = LEVELS.len() as f64;
    let x_axis = || Axis::new("level of model (caption)").range(0.5, n + 0.5);
    let speed = level_chart(
        x_axis(),
        Axis::new("c_{kink} (cm/s)"),
        (
            MEASURED_KINK_CM_S,
            format!("measured {MEASURED_KINK_CM_S:.1} cm/s"),
        ),
        &results,
        |r| r.kink_cm_s,
    );
    let ratio = level_chart(
        x_axis(),
        Axis::new("c_{antikink} / c_{kink}"),
        (MEASURED_RATIO, format!("measured {MEASURED_RATIO}")),
        &results,
        LevelResult::ratio,
    );
    // Side by side on a wide print page (paper-wide, slide), where two
    // charts stacked would be taller than the page allows; stacked on a
    // column (paper) and at screen.
    let w_frame = theme.style.frame(LEVEL_CHART);
    let w = w_frame.0;
    let side_by_side = theme.is_print() && w >= WIDE_PAGE_PX;
    let size = if side_by_side {
        let half = w.saturating_sub(theme.gap as u32) / 2;
        (half, (half as f32 * SIDE_BY_SIDE_ASPECT) as u32)
    } else {
        w_frame
    };
    let chart = |spec: &ChartSpec| -> Result<Picture> {
        Ok(Picture::from(charts::line_chart(
            theme, spec, size.0, size.1,
        )?))
    };
    let panels = [
        Panel::new(chart(&speed)?).label("(a)"),
        Panel::new(chart(&ratio)?).label("(b)"),
    ];
    let mut layout = Layout::columns(theme, if side_by_side { 2 } else { 1 });
    if theme.is_print() {
        layout.margin = 0;
    }
    let picture = compose::compose_picture(&panels, &layout)?.fit_page();
    Ok((picture, data))
}

/// The natural size of one chart of the levels' figure (design pixels).
const LEVEL_CHART: (u32, u32) = (820, 420);
/// The page width (design pixels) from which the levels' two charts go
/// side by side.
const WIDE_PAGE_PX: u32 = 600;
/// Height over width of each of the two charts side by side.
const SIDE_BY_SIDE_ASPECT: f32 = 0.75;

/// One panel of the levels' figure: `value` of each level (the model's
/// points; a level without a wave drawn at zero, as its own series)
/// beside the `measured` value (dashed). Short legend entries: the
/// caption names the levels and gives their numbers.
fn level_chart(
    x: Axis,
    y: Axis,
    measured: (f64, String),
    results: &[LevelResult],
    value: impl Fn(&LevelResult) -> Option<f64>,
) -> ChartSpec {
    let n = results.len() as f64;
    let top = results.iter().filter_map(&value).fold(measured.0, f64::max);
    let y = y.range(0.0, 1.15 * top);
    let (runs, none): (Vec<_>, Vec<_>) = results
        .iter()
        .enumerate()
        .map(|(k, r)| (k as f64 + 1.0, value(r)))
        .partition(|(_, v)| v.is_some());
    let mut spec = ChartSpec::new(x, y).series(
        Series::line(
            measured.1,
            vec![(0.5, measured.0), (n + 0.5, measured.0)],
            style::series_color(0),
        )
        .dashed(),
    );
    let points = |v: Vec<(f64, Option<f64>)>| -> Vec<(f64, f64)> {
        v.into_iter().map(|(x, y)| (x, y.unwrap_or(0.0))).collect()
    };
    if !runs.is_empty() {
        spec = spec.series(
            Series::scatter(
                "model",
                points(runs),
                style::series_color(1),
                Marker::Circle,
            )
            .with_width(2.0),
        );
    }
    if !none.is_empty() {
        spec = spec.series(
            Series::scatter(
                "model: no wave (at 0)",
                points(none),
                style::series_color(2),
                Marker::Cross,
            )
            .with_width(2.0),
        );
    }
    spec
}

/// μ_p, and the blocks the kink and the antikink flipped.
pub type Front = (f64, usize, usize);

/// How far the kink and the antikink get (blocks flipped) at each pin
/// friction of `mu` on `scene`'s linkage: (μ_p, kink, antikink).
pub fn fronts(scene: &Scene, mu: &[f64]) -> Result<(Vec<Front>, Vec<RunData>)> {
    let mut variants = Vec::new();
    for &m in mu {
        for (sign, word) in [(1.0, "kink"), (-1.0, "antikink")] {
            variants.push(variant(scene, format!("{word}, μ_p = {m}"), sign, |a| {
                a.pin_friction = m
            })?);
        }
    }
    let done = run_all(&variants)?;
    let flipped = |d: &Done| d.arrivals_s.iter().flatten().count();
    let rows = mu
        .iter()
        .enumerate()
        .map(|(i, m)| (*m, flipped(&done[2 * i]), flipped(&done[2 * i + 1])))
        .collect();
    Ok((rows, done.into_iter().map(|d| d.data).collect()))
}

/// The fronts at [`PIN_FRICTION`], then at the middle of every interval
/// whose two ends differ in either front, round after round until those
/// intervals are [`PIN_FRICTION_RESOLUTION`] wide: the points go where the
/// fronts change. Rows and data in order of μ_p.
pub fn refined_fronts(scene: &Scene) -> Result<(Vec<Front>, Vec<RunData>)> {
    let (rows, data) = fronts(scene, &PIN_FRICTION)?;
    let pairs = |rows: Vec<Front>, data: Vec<RunData>| {
        rows.into_iter()
            .zip(data.chunks(2).map(<[RunData]>::to_vec))
            .collect::<Vec<_>>()
    };
    let mut all = pairs(rows, data);
    loop {
        all.sort_by(|x, y| x.0.0.total_cmp(&y.0.0));
        let middles: Vec<f64> = all
            .windows(2)
            .filter(|w| {
                let ((m0, k0, a0), (m1, k1, a1)) = (w[0].0, w[1].0);
                (k0, a0) != (k1, a1) && m1 - m0 > 1.5 * PIN_FRICTION_RESOLUTION
            })
            .map(|w| 0.5 * (w[0].0.0 + w[1].0.0))
            .collect();
        if middles.is_empty() {
            break;
        }
        let (rows, data) = fronts(scene, &middles)?;
        all.extend(pairs(rows, data));
    }
    let (rows, data): (Vec<Front>, Vec<Vec<RunData>>) = all.into_iter().unzip();
    Ok((rows, data.into_iter().flatten().collect()))
}

/// Figure 3: how far the linkage's kink and antikink get (blocks flipped,
/// of N) against the pin friction μ_p.
fn linkage_friction(theme: &Theme, scene: &Scene) -> Result<(Picture, Vec<RunData>)> {
    let (rows, data) = refined_fronts(scene)?;
    let n = scene.model.n as f64;
    let mut spec = ChartSpec::new(
        Axis::new("pin friction μ_{p}"),
        Axis::new("blocks flipped (front)").range(0.0, n + 0.5),
    );
    for (j, (word, marker)) in [("kink", Marker::Circle), ("antikink", Marker::Square)]
        .into_iter()
        .enumerate()
    {
        let pts: Vec<(f64, f64)> = rows
            .iter()
            .map(|(mu, k, a)| (*mu, if j == 0 { *k } else { *a } as f64))
            .collect();
        let sign = if j == 0 { "+" } else { "−" };
        let label = format!(
            "{word} (α = {sign}{}°)",
            describe::num(scene.model.alpha.abs())
        );
        let s = Series::line(label, pts, style::series_color(j + 1))
            .with_marker(marker)
            .with_width(1.5);
        spec = spec.series(if j == 0 { s } else { s.dashed() });
    }
    let picture = chart_picture(theme, &spec, (820, 560))?.fit_page();
    Ok((picture, data))
}
