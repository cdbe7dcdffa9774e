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
use super::stack::{LEAST_PANEL, Slot, least_for, stacked};
use super::{Plan, Record};
use crate::encode::Rgb;
use crate::error::{Error, Result};
use crate::render::Theme;
use crate::render::cells::{self, Cell, CellChart, ShadeBar, cell_chart};
use crate::render::charts::{Axis, Chart, ChartSpec, Marker, Series, legend_band, line_chart};
use crate::render::palette::{OutcomeRole, Role};
use crate::render::style;
use crate::scene::describe;
use crate::scene::sweep::Param;
use serde::Serialize;

/// Height of the front panel at the screen style, pixels: room for its
/// six-entry legend inside the plot at every style, so that its |α| axis
/// lines up with the panels below.
const FRONT_HEIGHT: u32 = 380;

/// The palette's role of each outcome (docs/formats.md "One palette").
pub fn outcome_role(o: Outcome) -> Role {
    Role::Outcome(match o {
        Outcome::Propagated => OutcomeRole::Propagated,
        Outcome::Stalled => OutcomeRole::Stalled,
        Outcome::Pinned => OutcomeRole::Pinned,
        Outcome::Diverged => OutcomeRole::Diverged,
        Outcome::Undecided => OutcomeRole::Undecided,
        Outcome::Annihilated => OutcomeRole::Annihilated,
        Outcome::Failed => OutcomeRole::Failed,
    })
}

/// The colour of each outcome.
pub fn outcome_color(theme: &Theme, o: Outcome) -> Rgb {
    theme.color(outcome_role(o))
}

/// The marker of each outcome, the cue besides colour; an antikink's is
/// open where a kink's is filled, so that a kink and an antikink at the
/// same point both show ([`crate::render::Palette::marker`]).
pub fn outcome_marker(theme: &Theme, o: Outcome, antikink: bool) -> Marker {
    theme.marker(outcome_role(o), antikink)
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

/// An event of the front panel: its label, its marker (in ink), and the
/// block it marks in a run (none: no mark).
type BlockMark<'a> = (&'static str, Marker, &'a dyn Fn(&Record) -> Option<usize>);

/// A wave drawn as its own series: name, role, which records.
type Wave<'a> = (
    &'static str,
    Option<Role>,
    Box<dyn Fn(&Record) -> bool + 'a>,
);

/// What the panels of a 1-D sweep share: the plan, the varied axis, the
/// x of a run, and the waves drawn apart.
struct OneAxis<'a> {
    plan: &'a Plan,
    param: Param,
    fold: bool,
    x_label: &'static str,
    x_range: (f64, f64),
    x_of: Box<dyn Fn(&Record) -> f64 + 'a>,
    waves: Vec<Wave<'a>>,
}

impl<'a> OneAxis<'a> {
    fn new(plan: &'a Plan, records: &[Record]) -> OneAxis<'a> {
        let (param, k, fold) = x_axis(plan);
        let x_of = move |r: &Record| {
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
        // Which waves: kinks and antikinks apart when folded.
        let waves: Vec<Wave<'a>> = if fold {
            vec![
                (
                    "kink",
                    Some(Role::Kink),
                    Box::new(move |r: &Record| plan.points[r.run][k] > 0.0),
                ),
                (
                    "antikink",
                    Some(Role::Antikink),
                    Box::new(move |r: &Record| plan.points[r.run][k] < 0.0),
                ),
            ]
        } else {
            vec![("", None, Box::new(|_: &Record| true))]
        };
        OneAxis {
            plan,
            param,
            fold,
            x_label,
            x_range: (x_lo - pad, x_hi + pad),
            x_of: Box::new(x_of),
            waves,
        }
    }

    fn x_axis(&self) -> Axis {
        Axis::new(self.x_label).range(self.x_range.0, self.x_range.1)
    }
}

/// The front panel: every run's front at its value (the CSV's front),
/// marked by its outcome's shape; folded, a wave's colour is its role's
/// (as in the speed panel) and an antikink's marks open, so that both
/// show where they coincide; unfolded, the colour is the outcome's. Beside
/// the front, in ink, what is not the front: the free block N's own turn
/// (at N, ▼) and where the wave the drive launched met a wall coming the
/// other way (✱; outcome::front, docs/sweeps.md "Spontaneous flips").
fn front_panel(theme: &Theme, a: &OneAxis<'_>, records: &[Record], title: &str) -> ChartSpec {
    let n_max = records
        .iter()
        .map(|r| r.result.arrival_times.len())
        .max()
        .unwrap_or(a.plan.scene.model.n);
    let mut front = ChartSpec::new(
        a.x_axis().shared_numbered(),
        Axis::new("front (last block)").range(-0.3, n_max as f64 + 0.6),
    )
    .title(title);
    for (wave, role, keep) in &a.waves {
        for o in Outcome::ALL {
            let pts: Vec<(f64, f64)> = records
                .iter()
                .filter(|r| keep(r) && r.result.outcome == o)
                .map(|r| ((a.x_of)(r), r.result.front as f64))
                .collect();
            if pts.is_empty() {
                continue;
            }
            let label = if wave.is_empty() {
                o.name().to_string()
            } else {
                format!("{wave}: {o}")
            };
            let color = theme.color(role.unwrap_or(outcome_role(o)));
            let marker = outcome_marker(theme, o, *role == Some(Role::Antikink));
            front = front.series(Series::scatter(label, pts, color, marker));
        }
    }
    let marks: [BlockMark<'_>; 2] = [
        (
            "block N turned first",
            Marker::TriangleDown,
            &|r: &Record| {
                r.result
                    .block_n_turned_at
                    .map(|_| r.result.arrival_times.len())
            },
        ),
        ("annihilated at", Marker::Star, &driven_wave_met_at),
    ];
    for (label, marker, block_of) in marks {
        let pts: Vec<(f64, f64)> = records
            .iter()
            .filter_map(|r| Some(((a.x_of)(r), block_of(r)? as f64)))
            .collect();
        if !pts.is_empty() {
            let ink = theme.color(Role::Ink);
            front = front.series(Series::scatter(label, pts, ink, marker));
        }
    }
    front
}

/// The speed panel: each wave's speeds against the parameter, a kink's
/// solid with filled circles, an antikink's dashed with open ones; a log
/// axis when the speeds span more than a decade (near 90° the whole
/// chain flips at once), else linear in 10⁻³ blocks/τ.
fn speed_panel(theme: &Theme, a: &OneAxis<'_>, records: &[Record], shared: bool) -> ChartSpec {
    let (s_lo, s_hi) = records
        .iter()
        .filter_map(|r| r.result.speed)
        .fold((f64::INFINITY, 0.0f64), |(a, b), v| (a.min(v), b.max(v)));
    let log = s_hi > 10.0 * s_lo;
    let unit = if log { 1.0 } else { 1e3 };
    let speed_axis = if log {
        Axis::new("speed (blocks/τ)").log()
    } else {
        Axis::new("speed (10⁻³ blocks/τ)")
    };
    let x = if shared {
        a.x_axis().shared_numbered()
    } else {
        a.x_axis()
    };
    let mut speed = ChartSpec::new(x, speed_axis);
    for (wave, role, keep) in &a.waves {
        let mut pts: Vec<(f64, f64)> = records
            .iter()
            .filter(|r| keep(r))
            .map(|r| ((a.x_of)(r), r.result.speed.map_or(f64::NAN, |v| unit * v)))
            .collect();
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        let role = role.unwrap_or(outcome_role(Outcome::Propagated));
        let antikink = role == Role::Antikink;
        let label = if wave.is_empty() { "speed" } else { wave };
        let marker = theme.marker(role, antikink);
        let mut s = Series::line(label, pts, theme.color(role)).with_marker(marker);
        if antikink {
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
    speed
}

fn one_parameter(theme: &Theme, plan: &Plan, records: &[Record], title: &str) -> Result<Chart> {
    let a = OneAxis::new(plan, records);
    let theory = a.param == Param::Alpha && plan.spec.charts.theory;
    let front = front_panel(theme, &a, records, title);
    let speed = speed_panel(theme, &a, records, theory);
    let wanted: Vec<u32> = if theory {
        vec![FRONT_HEIGHT, 260, THEORY_PANEL_HEIGHT, THEORY_PANEL_HEIGHT]
    } else {
        vec![FRONT_HEIGHT, 260]
    };
    let labels = [
        front.y.label.as_str(),
        speed.y.label.as_str(),
        "gap ω₊(0) τ",
        "ΔU / mgs",
    ];
    // The front panel's legend may go under its plot, and the speed
    // panel's where it is narrow (a slide's right column): room for
    // their rows, so that the plot keeps the length of its rotated label.
    let least = |k: usize, w: u32| {
        let legend = match k {
            0 if w < 400 => 2 * FRONT_LEGEND_ROOM,
            0 => FRONT_LEGEND_ROOM,
            1 => legend_band(theme, &speed, w),
            _ => 0,
        };
        least_for(theme, labels[k]) + legend
    };
    // On a page too short for one column (a slide at its 20 pt text) the
    // front goes left, the others stacked right of it (stack::two_columns).
    stacked(theme, &wanted, &least, true, &|slots: &[Slot]| {
        let mut panels = vec![
            drawn(theme, &front, &slots[0])?,
            drawn(theme, &speed, &slots[1])?,
        ];
        if theory {
            let (gap, barrier) = (slots[2], slots[3]);
            panels.extend(theory_panel(
                theme,
                plan,
                (a.x_label, a.fold),
                (gap.w, Some(a.x_range), gap.plot_x),
                (gap, barrier),
            )?);
        }
        Ok(panels)
    })
}

/// `spec` drawn at `slot`: its plot's edges given, its x axis labelled
/// where it is the last of its column (the panels above share it).
fn drawn(theme: &Theme, spec: &ChartSpec, slot: &Slot) -> Result<(Chart, u32)> {
    let mut spec = ChartSpec {
        plot_x: slot.plot_x,
        ..spec.clone()
    };
    if slot.last {
        spec.x.shared = false;
        spec.x.numbered = false;
    } else if !slot.numbers {
        spec.x.numbered = false;
    }
    Ok((line_chart(theme, &spec, slot.w, slot.h)?, slot.h))
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

/// A theory panel's width, its pinned x range and its plots' x edges.
type PanelSpan = (u32, Option<(f64, f64)>, Option<(i32, i32)>);

/// One axis of the phase diagram: the plan's axis index and its values.
type GridAxis<'a> = (usize, &'a [f64]);

/// ω₊(0) and ΔU against α (or |α|, `fold`), one panel each, `width`
/// wide, at the heights of their slots (the gap's x axis shared with the
/// barrier's below it, numbered where its slot keeps numbers); `range`
/// pins the axis and `plot_x` the plots' edges (the stack's shared x
/// extent).
fn theory_panel(
    theme: &Theme,
    plan: &Plan,
    (x_label, fold): (&str, bool),
    (width, range, plot_x): PanelSpan,
    (gap, barrier): (Slot, Slot),
) -> Result<Vec<(Chart, u32)>> {
    let pts = theory_points(plan);
    let x = |a: f64| if fold { a.abs() } else { a };
    let curve = |y: &dyn Fn(&TheoryPoint) -> Option<f64>| {
        let mut c: Vec<(f64, f64)> = pts
            .iter()
            .map(|p| (x(p.alpha), y(p).unwrap_or(f64::NAN)))
            .collect();
        c.sort_by(|a, b| a.0.total_cmp(&b.0));
        c.dedup_by(|a, b| a.0 == b.0);
        c
    };
    let mut xa = Axis::new(x_label);
    if let Some((lo, hi)) = range {
        xa = xa.range(lo, hi);
    }
    // Two quantities in two units: one panel each (never one axis for
    // both), each named by its y axis, so no legend covers the curves.
    let ink = theme.color(Role::Ink);
    let panel = |label: &str, pts: Vec<(f64, f64)>, dashed: bool, shared: bool, h: u32| {
        let top = pts
            .iter()
            .map(|p| p.1)
            .filter(|v| v.is_finite())
            .fold(0.0, f64::max);
        let mut series = Series::line("", pts, ink);
        if dashed {
            series = series.dashed();
        }
        let x = if shared {
            Axis {
                numbered: gap.numbers,
                ..xa.clone().shared_numbered()
            }
        } else {
            xa.clone()
        };
        let mut spec =
            ChartSpec::new(x, Axis::new(label).range(0.0, 1.1 * top.max(1e-3))).series(series);
        spec.legend = crate::render::charts::Legend::Hidden;
        spec.plot_x = plot_x;
        line_chart(theme, &spec, width, h).map(|c| (c, h))
    };
    Ok(vec![
        panel(
            "gap ω₊(0) τ",
            curve(&|p| p.gap_omega_plus_q0),
            false,
            true,
            gap.h,
        )?,
        panel("ΔU / mgs", curve(&|p| p.barrier), true, false, barrier.h)?,
    ])
}

/// Height of each linear-theory panel under a sweep chart, pixels.
const THEORY_PANEL_HEIGHT: u32 = 170;

/// The phase diagram's cells: outcome as colour (a propagated run's
/// shaded by its speed) and, the second cue, as the outcome's marker in
/// each cell but the propagated ones (whose shade is their speed).
fn phase_cells(
    theme: &Theme,
    plan: &Plan,
    records: &[Record],
    (x, y): (GridAxis<'_>, GridAxis<'_>),
) -> (Vec<Cell>, Option<ShadeBar>) {
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
    let pale = |c: Rgb| style::mix(theme.color(Role::Paper), c, 0.35);
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
    let propagated = outcome_color(theme, Outcome::Propagated);
    let shade = |o: Outcome, v: Option<f64>| -> Rgb {
        let c = outcome_color(theme, o);
        match v {
            Some(v) if o == Outcome::Propagated && hi > lo => style::mix(pale(c), c, fraction(v)),
            _ => c,
        }
    };
    let index = |vals: &[f64], v: f64| vals.iter().position(|x| *x == v).unwrap_or(0);
    let cells = records
        .iter()
        .map(|r| Cell {
            col: index(x.1, plan.points[r.run][x.0]),
            row: index(y.1, plan.points[r.run][y.0]),
            color: shade(r.result.outcome, r.result.speed),
            marker: cell_marker(theme, r.result.outcome),
        })
        .collect();
    let bar = (hi > lo).then(|| ShadeBar {
        label: if log {
            "speed, blocks/τ (log)".into()
        } else {
            "speed, blocks/τ".into()
        },
        lo,
        hi,
        log,
        from: pale(propagated),
        to: propagated,
    });
    (cells, bar)
}

/// The mark of an outcome's cells: none for a propagated run (its shade
/// is its speed), else the outcome's filled marker.
fn cell_marker(theme: &Theme, o: Outcome) -> Marker {
    if o == Outcome::Propagated {
        Marker::None
    } else {
        outcome_marker(theme, o, false)
    }
}

/// The phase diagram's cells (α across when it is one of the two
/// parameters varied), with the parameters across and up.
fn phase_chart(
    theme: &Theme,
    plan: &Plan,
    records: &[Record],
    title: &str,
) -> (CellChart, Param, Param) {
    let varied = plan.varied();
    let alpha_second = varied[1].1 == Param::Alpha;
    let (ix, iy) = if alpha_second { (1, 0) } else { (0, 1) };
    let (kx, px, xs) = varied[ix];
    let (ky, py, ys) = varied[iy];
    let sorted = |v: &[f64]| {
        let mut s = v.to_vec();
        s.sort_by(f64::total_cmp);
        s.dedup();
        s
    };
    let (xs, ys) = (sorted(xs), sorted(ys));
    let (cells, shade) = phase_cells(theme, plan, records, ((kx, &xs), (ky, &ys)));
    let present: Vec<Outcome> = Outcome::ALL
        .into_iter()
        .filter(|o| records.iter().any(|r| r.result.outcome == *o))
        .collect();
    let chart = CellChart {
        title: Some(title.to_string()),
        x_label: px.label().into(),
        y_label: py.label().into(),
        xs,
        ys,
        cells,
        legend: present
            .iter()
            .map(|o| {
                let (c, m) = (outcome_color(theme, *o), cell_marker(theme, *o));
                (o.name().to_string(), c, m)
            })
            .collect(),
        shade,
        plot_x: None,
    };
    (chart, px, py)
}

fn phase(theme: &Theme, plan: &Plan, records: &[Record], title: &str) -> Result<Chart> {
    let (chart, px, py) = phase_chart(theme, plan, records, title);
    let xs = &chart.xs;
    let theory = px == Param::Alpha && plan.spec.charts.theory;
    let wanted: Vec<u32> = if theory {
        vec![480, THEORY_PANEL_HEIGHT, THEORY_PANEL_HEIGHT]
    } else {
        vec![480]
    };
    // The phase diagram keeps room for its colour bar's three ticks, and
    // for all its legend at the width it is drawn.
    let least = |k: usize, w: u32| match k {
        0 => least_for(theme, py.label())
            .max(2 * LEAST_PANEL)
            .max(cells::least_height(theme, &chart, w)),
        1 => least_for(theme, "gap ω₊(0) τ"),
        _ => least_for(theme, "ΔU / mgs"),
    };
    // Evenly spaced α: the theory panels' axis runs over the cells' span
    // (cells sit at their index, so uneven values have no common axis).
    let even = xs.len() > 1
        && xs
            .windows(2)
            .all(|w| (w[1] - w[0] - (xs[1] - xs[0])).abs() < 1e-9 * (1.0 + xs[1].abs()));
    stacked(theme, &wanted, &least, true, &|slots: &[Slot]| {
        let first = slots[0];
        let cells = CellChart {
            plot_x: first.plot_x.filter(|_| even),
            ..chart.clone()
        };
        let mut panels = vec![(cell_chart(theme, &cells, first.w, first.h)?, first.h)];
        if theory {
            let (gap, barrier) = (slots[1], slots[2]);
            // Under the cells the panels take the cells' width (the
            // legend's column is beside the cells); in a column of their
            // own, all of it.
            let range = if even {
                let h = 0.5 * (xs[1] - xs[0]);
                let w = if gap.column == first.column {
                    cells::cells_width(theme, &chart, gap.w)
                } else {
                    gap.w
                };
                let span = (xs[0] - h, xs[xs.len() - 1] + h);
                (w, Some(span), gap.plot_x.filter(|_| even))
            } else {
                (gap.w, None, None)
            };
            let label = (px.label(), false);
            panels.extend(theory_panel(theme, plan, label, range, (gap, barrier))?);
        }
        if !even {
            panels.iter_mut().for_each(|(c, _)| c.plot_x = None);
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
