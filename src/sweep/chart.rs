//! Charts drawn from a sweep's results (docs/sweeps.md):
//!
//! - one varied parameter: how far the wave got (front, coloured by
//!   outcome) and its speed against the parameter; a sweep over α of both
//!   signs is folded onto |α| with kinks and antikinks as two series;
//! - two: a phase diagram, outcome as colour, speed as shade;
//! - with α on the horizontal axis, a panel of the linear-theory
//!   quantities the paper uses to explain pinning, the gap ω₊(0) and the
//!   barrier ΔU, on the same axis.
//!
//! Every panel is a `render` chart (an SVG drawn with the bundled font);
//! the panels are stacked into one SVG and rasterised.

use super::outcome::Outcome;
use super::stack::{LEAST_PANEL, least_for, stacked, width};
use super::{Plan, Record};
use crate::encode::Rgb;
use crate::error::{Error, Result};
use crate::render::Theme;
use crate::render::cells::{Cell, CellChart, ShadeBar, cell_chart};
use crate::render::charts::{Axis, Chart, ChartSpec, Marker, Series, line_chart};
use crate::render::style;
use crate::render::theme::palette;
use crate::scene::describe;
use crate::scene::sweep::Param;
use serde::Serialize;

/// Height of the front panel at the screen style, pixels: room for its
/// six-entry legend inside the plot at every style, so that its |α| axis
/// lines up with the panels below.
const FRONT_HEIGHT: u32 = 380;

/// The colour of each outcome (Okabe–Ito: blue and vermillion stay apart
/// under deuteranopia and protanopia, where green and red are one olive).
pub fn outcome_color(o: Outcome) -> Rgb {
    match o {
        Outcome::Propagated => palette::BLUE,
        Outcome::Stalled => palette::ORANGE,
        Outcome::Pinned => palette::VERMILLION,
        Outcome::Diverged => style::DARK,
        Outcome::Undecided => style::GREY,
        Outcome::Annihilated => palette::REDDISH_PURPLE,
        Outcome::Failed => palette::BLUISH_GREEN,
    }
}

/// The marker of each outcome, the cue besides colour; an antikink's is
/// open or upright where a kink's is filled or diagonal, so that a kink
/// and an antikink at the same point both show.
pub fn outcome_marker(o: Outcome, antikink: bool) -> Marker {
    match (o, antikink) {
        (Outcome::Propagated, false) => Marker::Circle,
        (Outcome::Propagated, true) => Marker::Ring,
        (Outcome::Pinned, false) => Marker::Cross,
        (Outcome::Pinned, true) => Marker::Plus,
        (Outcome::Stalled | Outcome::Annihilated, _) => Marker::Triangle,
        (Outcome::Diverged | Outcome::Undecided | Outcome::Failed, _) => Marker::Square,
    }
}

/// Height the front panel's legend (up to six entries, in rows of two
/// under the plot) may take, pixels.
const FRONT_LEGEND_ROOM: u32 = 80;

/// The linear theory at one α: gap ω₊(0) (1/τ) and barrier ΔU per pair
/// of blocks (m g s), for the base scene's b and I.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TheoryPoint {
    pub alpha: f64,
    pub gap_omega_plus_q0: Option<f64>,
    pub barrier: Option<f64>,
}

/// The theory at every distinct |α| of the grid's α axis (empty when α is
/// not an axis), ascending.
pub fn theory_points(plan: &Plan) -> Vec<TheoryPoint> {
    let Some((_, alphas)) = plan.axes.iter().find(|(p, _)| *p == Param::Alpha) else {
        return Vec::new();
    };
    let mut values: Vec<f64> = alphas.to_vec();
    values.sort_by(f64::total_cmp);
    values.dedup();
    let m = plan.scene.model;
    values
        .into_iter()
        .map(|alpha| {
            let params = crate::scene::Model { alpha, ..m }.params();
            let gap = params.as_ref().ok().and_then(|p| {
                crate::theory::bloch::BlochChain::new(p)
                    .ok()
                    .map(|c| c.gap(crate::theory::dispersion::KineticMetric::Paper))
            });
            TheoryPoint {
                alpha,
                gap_omega_plus_q0: gap.filter(|g| g.is_finite()),
                barrier: crate::theory::gravity::barrier(m.b, alpha.to_radians()),
            }
        })
        .collect()
}

/// The chart of a sweep, or `None` when it varies more than two
/// parameters (the CSV and JSON hold the results), drawn with `theme`.
pub fn chart(theme: &Theme, plan: &Plan, records: &[Record]) -> Result<Option<Chart>> {
    let varied = plan.varied();
    let title = describe::title(&plan.scene);
    match varied.len() {
        0 | 1 => one_parameter(theme, plan, records, &title).map(Some),
        2 => phase(theme, plan, records, &title).map(Some),
        _ => Ok(None),
    }
}

/// The horizontal axis of a 1-D sweep: (param, axis index, folded onto |α|).
fn x_axis(plan: &Plan) -> (Param, usize, bool) {
    let (k, p) = plan
        .varied()
        .first()
        .map_or((0, plan.axes[0].0), |(k, p, _)| (*k, *p));
    let vals = &plan.axes[k].1;
    let fold = p == Param::Alpha
        && plan.spec.charts.fold_alpha
        && vals.iter().any(|v| *v > 0.0)
        && vals.iter().any(|v| *v < 0.0);
    (p, k, fold)
}

/// A mark of the front panel: its label, its marker, and the block it
/// marks in a run (none: no mark).
type BlockMark<'a> = (&'static str, Marker, &'a dyn Fn(&Record) -> Option<usize>);

/// A wave drawn as its own series: name, marker, which records.
type Wave<'a> = (&'static str, Marker, Box<dyn Fn(&Record) -> bool + 'a>);

fn one_parameter(theme: &Theme, plan: &Plan, records: &[Record], title: &str) -> Result<Chart> {
    let (param, k, fold) = x_axis(plan);
    let x_of = |r: &Record| {
        let v = plan.points[r.run][k];
        if fold { v.abs() } else { v }
    };
    let x_label = if fold { "|α| (°)" } else { param.label() };
    // One horizontal range for every panel, so that they line up.
    let (x_lo, x_hi) = records
        .iter()
        .map(x_of)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    let pad = if x_hi > x_lo {
        0.04 * (x_hi - x_lo)
    } else {
        0.5 * x_lo.abs().max(1.0)
    };
    let x_range = (x_lo - pad, x_hi + pad);
    let x_axis = || Axis::new(x_label).range(x_range.0, x_range.1);
    let n_max = records
        .iter()
        .map(|r| r.result.arrival_times.len())
        .max()
        .unwrap_or(plan.scene.model.n);
    // Which waves: kinks and antikinks apart when folded.
    let waves: Vec<Wave> = if fold {
        vec![
            (
                "kink",
                Marker::Circle,
                Box::new(|r: &Record| plan.points[r.run][k] > 0.0),
            ),
            (
                "antikink",
                Marker::Square,
                Box::new(|r: &Record| plan.points[r.run][k] < 0.0),
            ),
        ]
    } else {
        vec![("", Marker::Circle, Box::new(|_: &Record| true))]
    };
    let mut front = ChartSpec::new(
        x_axis().shared(),
        Axis::new("front (last block)").range(-0.3, n_max as f64 + 0.6),
    )
    .title(title);
    // Every mark at its value (the CSV's front): folded, a wave's colour
    // is its kind's (the same as in the speed panel) and its marker its
    // outcome, a kink's filled, an antikink's open, so that both show where
    // they coincide; unfolded, the colour is the outcome's.
    let offsets = [0.0, 0.0];
    for (i, ((wave, _, keep), dy)) in waves.iter().zip(offsets).enumerate() {
        for o in Outcome::ALL {
            let pts: Vec<(f64, f64)> = records
                .iter()
                .filter(|r| keep(r) && r.result.outcome == o)
                .map(|r| (x_of(r), r.result.front as f64 + dy))
                .collect();
            if pts.is_empty() {
                continue;
            }
            let label = if wave.is_empty() {
                o.name().to_string()
            } else {
                format!("{wave}: {o}")
            };
            let color = if fold {
                wave_color(i)
            } else {
                outcome_color(o)
            };
            let marker = outcome_marker(o, fold && i == 1);
            front = front.series(Series::scatter(label, pts, color, marker));
        }
    }
    // Beside the front, what is not the front: the free block N's own turn
    // (at N), and where the wave the drive launched met a wall coming the
    // other way (outcome::front, docs/sweeps.md "Spontaneous flips").
    let dy_of = |r: &Record| {
        waves
            .iter()
            .zip(offsets)
            .find(|((_, _, keep), _)| keep(r))
            .map_or(0.0, |(_, dy)| dy)
    };
    // Each mark at the block it names, for the runs that have one.
    let marks: [BlockMark<'_>; 2] = [
        ("block N turned first", Marker::Triangle, &|r: &Record| {
            r.result
                .block_n_turned_at
                .map(|_| r.result.arrival_times.len())
        }),
        ("annihilated at", Marker::Cross, &driven_wave_met_at),
    ];
    for (label, marker, block_of) in marks {
        let pts: Vec<(f64, f64)> = records
            .iter()
            .filter_map(|r| Some((x_of(r), block_of(r)? as f64 + dy_of(r))))
            .collect();
        if !pts.is_empty() {
            front = front.series(Series::scatter(label, pts, style::DARK, marker));
        }
    }
    // A log axis when the speeds span more than a decade (near 90° the
    // whole chain flips at once), else linear, so that ticks show.
    let (s_lo, s_hi) = records
        .iter()
        .filter_map(|r| r.result.speed)
        .fold((f64::INFINITY, 0.0f64), |(a, b), v| (a.min(v), b.max(v)));
    let log = s_hi > 10.0 * s_lo;
    // Linear speeds in 10⁻³ blocks/τ, so that tick labels stay short.
    let unit = if log { 1.0 } else { 1e3 };
    let speed_axis = if log {
        Axis::new("speed (blocks/τ)").log()
    } else {
        Axis::new("speed (10⁻³ blocks/τ)")
    };
    let theory = param == Param::Alpha && plan.spec.charts.theory;
    let speed_x = if theory { x_axis().shared() } else { x_axis() };
    let mut speed = ChartSpec::new(speed_x, speed_axis);
    for (i, (wave, marker, keep)) in waves.iter().enumerate() {
        let mut pts: Vec<(f64, f64)> = records
            .iter()
            .filter(|r| keep(r))
            .map(|r| (x_of(r), r.result.speed.map_or(f64::NAN, |v| unit * v)))
            .collect();
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        let color = if fold { wave_color(i) } else { palette::BLUE };
        let label = if wave.is_empty() { "speed" } else { wave };
        let mut s = Series::line(label, pts, color).with_marker(*marker);
        if i == 1 {
            s = s.dashed();
        }
        speed = speed.series(s);
    }
    if speed
        .series
        .iter()
        .all(|s| s.points.iter().all(|p| !p.1.is_finite()))
    {
        speed.y = speed.y.range(1e-4, 1.0);
        speed.series.clear();
        speed.title = Some("no run propagated far enough to measure a speed".into());
    }
    let wanted: Vec<u32> = if theory {
        vec![FRONT_HEIGHT, 260, THEORY_PANEL_HEIGHT, THEORY_PANEL_HEIGHT]
    } else {
        vec![FRONT_HEIGHT, 260]
    };
    let mut least: Vec<u32> = [front.y.label.as_str(), speed.y.label.as_str()]
        .into_iter()
        .chain(["gap ω₊(0) τ", "ΔU / mgs"])
        .map(|l| least_for(theme, l))
        .collect();
    // The front panel's legend may go under its plot: room for its rows.
    least[0] += if width(theme) < 400 {
        2 * FRONT_LEGEND_ROOM
    } else {
        FRONT_LEGEND_ROOM
    };
    stacked(theme, &wanted, &least, |h, w| {
        let mut panels = vec![
            (line_chart(theme, &front, w, h[0])?, h[0]),
            (line_chart(theme, &speed, w, h[1])?, h[1]),
        ];
        if theory {
            panels.extend(theory_panel(
                theme,
                plan,
                x_label,
                fold,
                (w, Some(x_range)),
                (h[2], h[3]),
            )?);
        }
        Ok(panels)
    })
}

/// The colour of wave kind `i` (0: kink, 1: antikink) in every panel.
fn wave_color(i: usize) -> Rgb {
    if i == 0 {
        palette::KINK
    } else {
        palette::ANTIKINK
    }
}

/// The block where the wave the drive launched (the first wave from block
/// 1) was annihilated by a wall coming the other way, if it was.
fn driven_wave_met_at(r: &Record) -> Option<usize> {
    use crate::sim::waves::Fate;
    let w = r.result.waves.waves.iter().find(|w| w.origin == 1)?;
    match w.fate {
        Fate::Annihilated { block, .. } => Some(block),
        _ => None,
    }
}

/// ω₊(0) and ΔU against α (or |α|), one panel each; `x_range` pins the
/// axis.
fn theory_panel(
    theme: &Theme,
    plan: &Plan,
    x_label: &str,
    fold: bool,
    (width, range): (u32, Option<(f64, f64)>),
    (gap_h, barrier_h): (u32, u32),
) -> Result<Vec<(Chart, u32)>> {
    let pts = theory_points(plan);
    let x = |a: f64| if fold { a.abs() } else { a };
    let mut gap: Vec<(f64, f64)> = pts
        .iter()
        .map(|p| (x(p.alpha), p.gap_omega_plus_q0.unwrap_or(f64::NAN)))
        .collect();
    let mut barrier: Vec<(f64, f64)> = pts
        .iter()
        .map(|p| (x(p.alpha), p.barrier.unwrap_or(f64::NAN)))
        .collect();
    gap.sort_by(|a, b| a.0.total_cmp(&b.0));
    gap.dedup_by(|a, b| a.0 == b.0);
    barrier.sort_by(|a, b| a.0.total_cmp(&b.0));
    barrier.dedup_by(|a, b| a.0 == b.0);
    let mut xa = Axis::new(x_label);
    if let Some((lo, hi)) = range {
        xa = xa.range(lo, hi);
    }
    // Two quantities in two units: one panel each (never one axis for
    // both), each named by its y axis, so no legend covers the curves.
    let panel = |label: &str, pts: Vec<(f64, f64)>, color, dashed: bool, shared: bool, h: u32| {
        let top = pts
            .iter()
            .map(|p| p.1)
            .filter(|v| v.is_finite())
            .fold(0.0, f64::max);
        let mut series = Series::line("", pts, color);
        if dashed {
            series = series.dashed();
        }
        let x = if shared {
            xa.clone().shared()
        } else {
            xa.clone()
        };
        let mut spec =
            ChartSpec::new(x, Axis::new(label).range(0.0, 1.1 * top.max(1e-3))).series(series);
        spec.legend = crate::render::charts::Legend::Hidden;
        line_chart(theme, &spec, width, h).map(|c| (c, h))
    };
    Ok(vec![
        panel("gap ω₊(0) τ", gap, palette::INK, false, true, gap_h)?,
        panel("ΔU / mgs", barrier, palette::INK, true, false, barrier_h)?,
    ])
}

/// Height of each linear-theory panel under a sweep chart, pixels.
const THEORY_PANEL_HEIGHT: u32 = 170;

fn phase(theme: &Theme, plan: &Plan, records: &[Record], title: &str) -> Result<Chart> {
    let varied = plan.varied();
    // α across when it is one of the two.
    let (ix, iy) = if varied[1].1 == Param::Alpha {
        (1, 0)
    } else {
        (0, 1)
    };
    let (kx, px, xs) = varied[ix];
    let (ky, py, ys) = varied[iy];
    let sorted = |v: &[f64]| {
        let mut s = v.to_vec();
        s.sort_by(f64::total_cmp);
        s.dedup();
        s
    };
    let (xs, ys) = (sorted(xs), sorted(ys));
    let speeds: Vec<f64> = records
        .iter()
        .filter(|r| r.result.outcome == Outcome::Propagated)
        .filter_map(|r| r.result.speed)
        .collect();
    let (lo, hi) = speeds
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(*v), b.max(*v))
        });
    let pale = |c: Rgb| style::mix(style::WHITE, c, 0.35);
    // Speeds over more than a decade are shaded on a log scale, so that
    // equal ratios look equally far apart (and runs of equal speed alike).
    let log = lo > 0.0 && hi > 10.0 * lo;
    let fraction = |v: f64| {
        if log {
            (v / lo).ln() / (hi / lo).ln()
        } else {
            (v - lo) / (hi - lo)
        }
    };
    let shade = |o: Outcome, v: Option<f64>| -> Rgb {
        let c = outcome_color(o);
        match v {
            Some(v) if o == Outcome::Propagated && hi > lo => style::mix(pale(c), c, fraction(v)),
            _ => c,
        }
    };
    let index = |vals: &[f64], v: f64| vals.iter().position(|x| *x == v).unwrap_or(0);
    let cells = records
        .iter()
        .map(|r| Cell {
            col: index(&xs, plan.points[r.run][kx]),
            row: index(&ys, plan.points[r.run][ky]),
            color: shade(r.result.outcome, r.result.speed),
        })
        .collect();
    let present: Vec<Outcome> = Outcome::ALL
        .into_iter()
        .filter(|o| records.iter().any(|r| r.result.outcome == *o))
        .collect();
    let chart = CellChart {
        title: Some(title.to_string()),
        x_label: px.label().into(),
        y_label: py.label().into(),
        xs: xs.clone(),
        ys,
        cells,
        legend: present
            .iter()
            .map(|o| (o.name().to_string(), outcome_color(*o)))
            .collect(),
        shade: (hi > lo).then(|| ShadeBar {
            label: if log {
                "speed, blocks/τ (log)".into()
            } else {
                "speed, blocks/τ".into()
            },
            lo,
            hi,
            log,
            from: pale(outcome_color(Outcome::Propagated)),
            to: outcome_color(Outcome::Propagated),
        }),
    };
    let theory = px == Param::Alpha && plan.spec.charts.theory;
    let wanted: Vec<u32> = if theory {
        vec![480, THEORY_PANEL_HEIGHT, THEORY_PANEL_HEIGHT]
    } else {
        vec![480]
    };
    // The phase diagram keeps room for its colour bar's three ticks.
    let least = [
        least_for(theme, py.label()).max(2 * LEAST_PANEL),
        least_for(theme, "gap ω₊(0) τ"),
        least_for(theme, "ΔU / mgs"),
    ];
    stacked(theme, &wanted, &least, |h, w| {
        let main = cell_chart(theme, &chart, w, h[0])?;
        let mut panels = vec![(main, h[0])];
        if theory {
            let even = xs
                .windows(2)
                .all(|w| (w[1] - w[0] - (xs[1] - xs[0])).abs() < 1e-9 * (1.0 + xs[1].abs()));
            let range = if even && xs.len() > 1 {
                let h = 0.5 * (xs[1] - xs[0]);
                let cells = crate::render::cells::cells_width(theme, &chart, w);
                (cells, Some((xs[0] - h, xs[xs.len() - 1] + h)))
            } else {
                (w, None)
            };
            panels.extend(theory_panel(
                theme,
                plan,
                px.label(),
                false,
                range,
                (h[1], h[2]),
            )?);
        }
        Ok(panels)
    })
}

/// A short account of a 1-D sweep over α, measured: where each wave stops
/// propagating (for the captions and the report). `None` when α is not
/// the one varied parameter.
pub fn transitions(plan: &Plan, records: &[Record]) -> Vec<String> {
    let (param, k, _) = x_axis(plan);
    if plan.varied().len() != 1 {
        return Vec::new();
    }
    let mut out = Vec::new();
    for sign in [1.0, -1.0] {
        let mut rs: Vec<(f64, &Record)> = records
            .iter()
            .map(|r| (plan.points[r.run][k], r))
            .filter(|(v, _)| param != Param::Alpha || v * sign > 0.0)
            .collect();
        if rs.is_empty() {
            continue;
        }
        rs.sort_by(|a, b| a.0.abs().total_cmp(&b.0.abs()));
        let wave = if param != Param::Alpha {
            String::new()
        } else if sign > 0.0 {
            "kink: ".into()
        } else {
            "antikink: ".into()
        };
        let mut changes = Vec::new();
        for w in rs.windows(2) {
            let (a, b) = (w[0].1.result.outcome, w[1].1.result.outcome);
            if a != b {
                changes.push(format!(
                    "{a} at {} → {b} at {}",
                    describe::num(w[0].0),
                    describe::num(w[1].0)
                ));
            }
        }
        if changes.is_empty() {
            changes.push(format!("all {}", rs[0].1.result.outcome));
        }
        out.push(format!("{wave}{}", changes.join("; ")));
        if param != Param::Alpha {
            break;
        }
    }
    out
}

/// An error for a chart asked of a sweep that varies more than two
/// parameters.
pub fn too_many_axes(plan: &Plan) -> Error {
    Error::bad_input(format!(
        "sweep {} varies {} parameters; its chart needs one or two (the CSV and JSON hold every run)",
        plan.scene.name,
        plan.varied().len()
    ))
}
