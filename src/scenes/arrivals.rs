//! The arrivals view: each wave's arrival time at every block, with the
//! fitted front speed.

use super::data::RunData;
use super::dynamic::{panel_labels, wave_name};
use super::run::{self};
use crate::error::Result;
use crate::render::charts::{Axis, ChartSpec, Series};
use crate::render::line_chart_figure;
use crate::render::{Palette, Picture, Role, Theme};
use crate::scene::{Scene, describe};
use crate::sim::{self};

/// The wave speed c in blocks per 1000 τ (`sim::speed::wave_speed`,
/// the one definition the program reports).
pub fn fitted_speed(arrivals: &[Option<f64>]) -> Option<f64> {
    crate::sim::speed::wave_speed(arrivals).map(|v| 1000.0 * v)
}

/// The least-squares line t = t̄ + (n − n̄)/c through the arrival times
/// that the wave speed c fits (blocks 3..N−1,
/// `sim::speed::wave_speed_fit`), drawn over the blocks the wave
/// reached: its two ends, or `None` when there is no speed.
fn fitted_line(arrivals: &[Option<f64>]) -> Option<Vec<(f64, f64)>> {
    let fit = crate::sim::speed::wave_speed_fit(arrivals)?;
    let (v, (mn, mt)) = (fit.speed, fit.centroid);
    let reached: Vec<f64> = arrivals
        .iter()
        .enumerate()
        .filter_map(|(i, t)| t.map(|_| i as f64 + 1.0))
        .collect();
    let (lo, hi) = (reached.first()?, reached.last()?);
    Some(vec![(*lo, mt + (lo - mn) / v), (*hi, mt + (hi - mn) / v)])
}

/// The arrival-time chart (figure S6): t_n against n for every wave of
/// every run (from the run's waves record), a kink's marks vermillion and
/// filled, an antikink's blue and open, each wave of a kind its own
/// shape, with its fitted line (solid for a kink, dashed for an
/// antikink) and its fitted speed in the legend; successive waves set
/// [`DODGE`] blocks apart across so that none hides another; drawn with
/// `theme`.
pub fn arrivals_figure(theme: &Theme, scene: &Scene) -> Result<(Picture, Vec<RunData>)> {
    // The runs once; the chart is drawn again only to search a size.
    let (spec, data) = arrivals_chart(scene)?;
    let title = describe::title(scene);
    Ok((line_chart_figure(theme, &spec, (820, 560), &title)?, data))
}

/// What [`arrivals_figure`] draws: the chart's series (each wave's marks,
/// labelled, then its fitted line, unlabelled) and the runs' data.
pub fn arrivals_chart(scene: &Scene) -> Result<(ChartSpec, Vec<RunData>)> {
    // `t_end = "auto"` resolved here too, for callers of this function
    // that did not go through `scenes::render_to` (a no-op when resolved).
    let scene = &scene.with_auto_window()?;
    let runs = scene.runs();
    let labels = panel_labels(scene);
    let n_max = runs.iter().map(|(s, _)| s.model.n).max().unwrap_or(10);
    let spec = ChartSpec::new(
        Axis::new("block n").range(0.5, n_max as f64 + 0.5),
        Axis::new("arrival time tₙ / τ"),
    )
    .title(describe::title(scene));
    // Every wave's marks and fitted line, collected first: each is then
    // set off across by its own small step, so that marks at one block
    // (every run's flip of block 1, a pinned wave's block 2) stand side
    // by side instead of on top of one another.
    let mut drawn: Vec<Arrivals> = Vec::new();
    let mut data = Vec::with_capacity(runs.len());
    for ((s, _), label) in runs.iter().zip(&labels) {
        let run = run::simulate(s, &[])?;
        drawn.extend(run_waves(&run.trajectory, s.model.alpha, label));
        data.push(RunData::new(label, s, &run));
    }
    Ok((with_dodged_waves(spec, drawn), data))
}

/// The waves of one run as drawn, each with its legend: the panel's
/// `label` and, when the run has several waves, the wave's kind and launch.
fn run_waves(traj: &sim::Trajectory, alpha: f64, label: &str) -> Vec<Arrivals> {
    // Each wave of the run; a run without a waves record is one wave.
    let kind_of = |w: &sim::waves::Wave| w.kind == sim::waves::WaveKind::Kink;
    let mut waves: Vec<DrawnWave<'_>> = traj
        .waves
        .waves
        .iter()
        .map(|w| (kind_of(w), w.launched_at, w.arrival_times.clone(), Some(w)))
        .collect();
    if waves.is_empty() {
        waves.push((alpha > 0.0, 0.0, traj.arrival_times.clone(), None));
    }
    let several = waves.len() > 1;
    let mut drawn = Vec::new();
    for (kink, launched, arrivals, wave) in waves {
        let pts: Vec<(f64, f64)> = arrivals
            .iter()
            .enumerate()
            .filter_map(|(i, t)| t.map(|t| (i as f64 + 1.0, t)))
            .collect();
        if pts.is_empty() {
            continue;
        }
        let speed = fitted_speed(&arrivals)
            .map_or_else(|| without_speed(wave), |v| format!("{v:.1} blocks/1000τ"));
        let word = if kink { "kink" } else { "antikink" };
        let launched = describe::num(launched.round());
        let name = match (several, label.is_empty()) {
            (false, true) => wave_name(alpha),
            (false, false) => label.to_string(),
            (true, true) => format!(
                "{word} from t/τ = {launched} (α = {}°)",
                describe::num(alpha)
            ),
            (true, false) => format!("{label}, {word} from t/τ = {launched}"),
        };
        drawn.push(Arrivals {
            label: format!("{name}: {speed}"),
            kink,
            marks: pts,
            line: fitted_line(&arrivals),
        });
    }
    drawn
}

/// `spec` with every wave of `drawn`: its marks and fitted line set off
/// across by [`DODGE`] from the wave before.
fn with_dodged_waves(mut spec: ChartSpec, drawn: Vec<Arrivals>) -> ChartSpec {
    let count = drawn.len();
    let (mut kinks, mut antikinks) = (0, 0);
    for (k, wave) in drawn.into_iter().enumerate() {
        let dx = DODGE * (k as f64 - 0.5 * (count as f64 - 1.0));
        let shift = |p: Vec<(f64, f64)>| p.into_iter().map(|(x, y)| (x + dx, y)).collect();
        // The wave's role colours it (a kink vermillion, an antikink
        // blue, as in every figure); its place among the waves of its
        // kind gives its shape, filled for a kink and open for an
        // antikink.
        let (role, j) = if wave.kink {
            kinks += 1;
            (Role::Kink, kinks - 1)
        } else {
            antikinks += 1;
            (Role::Antikink, antikinks - 1)
        };
        let color = Palette.color(role);
        let marker = Palette.series_marker(j, !wave.kink);
        spec = spec
            .series(Series::scatter(wave.label, shift(wave.marks), color, marker).with_width(1.5));
        if let Some(line) = wave.line {
            let fit = Series::line("", shift(line), color).with_width(1.5);
            spec = spec.series(if wave.kink { fit } else { fit.dashed() });
        }
    }
    spec
}

/// What the legend says of a wave with no fitted speed, from its fate
/// (docs/sweeps.md): where the state proved it stopped (pinned if it never
/// got past block 2, as a sweep says), where it was annihilated, or that
/// it has no speed.
fn without_speed(wave: Option<&sim::waves::Wave>) -> String {
    use sim::waves::Fate;
    match wave.map(|w| (w.fate, w.front)) {
        // The sweeps' words (docs/sweeps.md): pinned if the front never got
        // past block 2, stalled otherwise.
        Some((Fate::Stopped, front)) if front <= 2 => format!("pinned at block {front}"),
        Some((Fate::Stopped, front)) => format!("stalled at block {front}"),
        Some((Fate::Annihilated { block, .. }, _)) => format!("annihilated at block {block}"),
        _ => "no speed".to_string(),
    }
}

/// How far apart across, in blocks, the marks of successive waves are
/// set at one block (0.08: six waves take a third of a block).
const DODGE: f64 = 0.08;

/// One wave as drawn: its legend, kind, marks (block, arrival time) and
/// fitted line.
struct Arrivals {
    label: String,
    kink: bool,
    marks: Vec<(f64, f64)>,
    line: Option<Vec<(f64, f64)>>,
}

/// A wave of the arrivals chart: kink or not, launched at, its arrival
/// times, and its record (none for a run without a waves record).
type DrawnWave<'a> = (bool, f64, Vec<Option<f64>>, Option<&'a sim::waves::Wave>);
