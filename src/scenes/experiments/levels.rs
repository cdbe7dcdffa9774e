//! The tank's levels figure: c_kink and c_antikink / c_kink for each level
//! of model, beside the measured 6.0 cm/s and 1.75.

use super::runs::{Variant, run_all, variant};
use super::{INEXTENSIBLE_STEP, LEVELS, LEVELS_MOTOR_HZ, MEASURED_KINK_CM_S, MEASURED_RATIO};
use crate::error::{Error, Result};
use crate::render::charts::{self, Axis, ChartSpec, Marker, Series};
use crate::render::compose::{self, Layout, Panel};
use crate::render::palette::Role;
use crate::render::{Picture, Theme};
use crate::scene::Scene;
use crate::scenes::data::RunData;

/// What one level of model gives in the tank: the bulk speeds (cm/s) of
/// the kink and the antikink, and of the kink with the links twice as
/// stiff ("stiff" links: k and 2k must agree, [`STIFF_TOLERANCE`]), or,
/// for inextensible ribbons (no k), of the kink at half the step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelResult {
    pub name: &'static str,
    pub kink_cm_s: Option<f64>,
    pub antikink_cm_s: Option<f64>,
    pub kink_2k_cm_s: Option<f64>,
    /// Inextensible ribbons: `kink_2k_cm_s` is the kink at half the step.
    pub inextensible: bool,
}

impl LevelResult {
    /// c_antikink / c_kink, where both run.
    pub fn ratio(&self) -> Option<f64> {
        self.kink_cm_s.zip(self.antikink_cm_s).map(|(k, a)| a / k)
    }

    /// |c(2k)/c(k) − 1|, where both run (not for inextensible ribbons).
    pub fn stiff_difference(&self) -> Option<f64> {
        if self.inextensible {
            return None;
        }
        self.second_difference()
    }

    /// |c(h/2)/c(h) − 1| of inextensible ribbons' kink, where both run.
    pub fn step_difference(&self) -> Option<f64> {
        if !self.inextensible {
            return None;
        }
        self.second_difference()
    }

    fn second_difference(&self) -> Option<f64> {
        self.kink_cm_s
            .zip(self.kink_2k_cm_s)
            .map(|(k, k2)| (k2 / k - 1.0).abs())
    }
}

pub use crate::scenes::stiff::STIFF_TOLERANCE;

/// Every level of [`LEVELS`] run on `scene`'s apparatus at
/// [`LEVELS_MOTOR_HZ`]: kink, antikink, and kink at 2k.
pub fn levels(scene: &Scene) -> Result<(Vec<LevelResult>, Vec<RunData>)> {
    let done = run_all(&variants(scene)?)?;
    let results = LEVELS
        .iter()
        .enumerate()
        .map(|(k, (name, level))| LevelResult {
            name,
            kink_cm_s: done[3 * k].bulk_cm_s,
            antikink_cm_s: done[3 * k + 1].bulk_cm_s,
            kink_2k_cm_s: done[3 * k + 2].bulk_cm_s,
            inextensible: level.inextensible,
        })
        .collect();
    Ok((results, done.into_iter().map(|d| d.data).collect()))
}

/// The figure's runs: kink, antikink and kink at 2k for every level (for
/// inextensible ribbons, which have no k, the kink at half the step).
pub(super) fn variants(scene: &Scene) -> Result<Vec<Variant>> {
    let mut variants = Vec::new();
    for (name, level) in LEVELS {
        let third = if level.inextensible {
            "kink, half the step"
        } else {
            "kink, links 2k"
        };
        for (sign, word, second) in [
            (1.0, "kink", false),
            (-1.0, "antikink", false),
            (1.0, third, true),
        ] {
            let stiffer = second && !level.inextensible;
            let mut v = variant(scene, format!("{name}, {word}"), sign, |a| {
                level.apply(a);
                a.motor = Some(LEVELS_MOTOR_HZ);
                if stiffer {
                    a.stiff_gravity *= 0.5;
                }
            })?;
            if second && level.inextensible {
                v.scene.run.dt = Some(0.5 * INEXTENSIBLE_STEP);
            }
            variants.push(v);
        }
    }
    Ok(variants)
}

/// Figure 2: c_kink (cm/s) and c_antikink / c_kink for each level of
/// model at [`LEVELS_MOTOR_HZ`], one row per level named on the axis,
/// beside the measured 6.0 cm/s and 1.75; a level without a wave says
/// "no wave" in its name and has no point on the value axis.
pub(super) fn tank_levels(theme: &Theme, scene: &Scene) -> Result<(Picture, Vec<RunData>)> {
    let (results, data) = levels(scene)?;
    if let Some(r) = results
        .iter()
        .find(|r| r.step_difference().is_some_and(|d| d > STIFF_TOLERANCE))
    {
        return Err(Error::failed(format!(
            "{}: the kink's speed moves by {:.1} % at half of Moreau's step, more than {} %: \
             the run is not converged in its step",
            r.name,
            100.0 * r.step_difference().unwrap_or(0.0),
            100.0 * STIFF_TOLERANCE
        )));
    }
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
    let names = level_names(&results);
    let speed = |names: &[String]| {
        level_chart(
            theme,
            Axis::new("c_{kink} (cm/s)"),
            Axis::new("").names(names.iter().rev().cloned().collect()),
            (
                MEASURED_KINK_CM_S,
                format!("measured {MEASURED_KINK_CM_S:.1} cm/s"),
            ),
            &results,
            |r| r.kink_cm_s,
        )
    };
    let ratio = |y: Axis| {
        level_chart(
            theme,
            Axis::new("c_{antikink} / c_{kink}"),
            y,
            (MEASURED_RATIO, format!("measured {MEASURED_RATIO}")),
            &results,
            LevelResult::ratio,
        )
    };
    // Side by side on a wide print page (paper-wide, slide), where two
    // charts stacked would be taller than the page allows; stacked on a
    // column (paper) and at screen.
    let w_frame = theme.style.frame(LEVEL_CHART);
    let side_by_side = theme.is_print() && w_frame.0 >= WIDE_PAGE_PX;
    let panels = if side_by_side {
        // Panel (b) beside (a) shares its rows: it numbers them, and the
        // width the names would take goes to its plot.
        let numbers = level_numbers(&results);
        let y = Axis::new("level").names(numbers.into_iter().rev().collect());
        side_by_side_charts(theme, w_frame.0, &speed(&names), &ratio(y))?
    } else {
        let y = Axis::new("").names(names.iter().rev().cloned().collect());
        let chart = |spec: &ChartSpec| -> Result<Picture> {
            Ok(Picture::from(charts::line_chart(
                theme, spec, w_frame.0, w_frame.1,
            )?))
        };
        [chart(&speed(&names))?, chart(&ratio(y))?]
    };
    let [a, b] = panels;
    let panels = [Panel::new(a).label("(a)"), Panel::new(b).label("(b)")];
    let mut layout = Layout::columns(theme, if side_by_side { 2 } else { 1 });
    if theme.is_print() {
        layout.margin = 0;
    }
    let picture = compose::compose_picture(&panels, &layout)?.fit_page();
    Ok((picture, data))
}

/// The two charts side by side on a page `w` pixels wide, as tall as
/// [`SIDE_BY_SIDE_ASPECT`] of half of it: the page's width shared so that
/// their plots are equally wide (each drawn at half first, then again
/// with the difference of their plots moved from one to the other).
fn side_by_side_charts(
    theme: &Theme,
    w: u32,
    a: &ChartSpec,
    b: &ChartSpec,
) -> Result<[Picture; 2]> {
    let half = w.saturating_sub(theme.gap as u32) / 2;
    let h = (half as f32 * SIDE_BY_SIDE_ASPECT) as u32;
    let plot_w = |spec: &ChartSpec| -> Result<i32> {
        let c = charts::line_chart(theme, spec, half, h)?;
        Ok(c.plot_x.map_or(0, |(l, r)| r - l))
    };
    let d = (plot_w(b)? - plot_w(a)?) / 2;
    let (wa, wb) = (
        half.saturating_add_signed(d),
        half.saturating_add_signed(-d),
    );
    Ok([
        Picture::from(charts::line_chart(theme, a, wa, h)?),
        Picture::from(charts::line_chart(theme, b, wb, h)?),
    ])
}

/// The natural size of one chart of the levels' figure (design pixels).
const LEVEL_CHART: (u32, u32) = (820, 420);
/// The page width (design pixels) from which the levels' two charts go
/// side by side.
const WIDE_PAGE_PX: u32 = 600;
/// Height over width of each of the two charts side by side.
const SIDE_BY_SIDE_ASPECT: f32 = 0.75;

/// The name of each level on the axis, "no wave" added where its
/// kink has no speed.
pub fn level_names(results: &[LevelResult]) -> Vec<String> {
    results
        .iter()
        .map(|r| match r.kink_cm_s {
            Some(_) => r.name.to_string(),
            None => format!("{}: no wave", r.name),
        })
        .collect()
}

/// The number of each level, the first word of its name ("1" of "1 paper:
/// linear damping γ"): the rows of a panel beside the one that names them.
pub fn level_numbers(results: &[LevelResult]) -> Vec<String> {
    results
        .iter()
        .map(|r| {
            r.name
                .split_whitespace()
                .next()
                .unwrap_or(r.name)
                .to_string()
        })
        .collect()
}

/// One panel of the levels' figure: one row per level (the first at the
/// top, named on the `y` axis, the last name first), `value` of each level
/// where it has one (a level without a wave has no point: its name says
/// "no wave"), beside the `measured` value (a dashed line across the rows).
fn level_chart(
    theme: &Theme,
    x: Axis,
    y: Axis,
    measured: (f64, String),
    results: &[LevelResult],
    value: impl Fn(&LevelResult) -> Option<f64>,
) -> ChartSpec {
    let n = results.len() as f64;
    let top = results.iter().filter_map(&value).fold(measured.0, f64::max);
    let row = |k: usize| n - k as f64;
    let mut spec = ChartSpec::new(x.range(0.0, 1.15 * top), y);
    spec = spec.series(
        Series::line(
            measured.1,
            vec![(measured.0, 0.5), (measured.0, n + 0.5)],
            theme.color(Role::Measurement),
        )
        .dashed(),
    );
    let points: Vec<(f64, f64)> = results
        .iter()
        .enumerate()
        .filter_map(|(k, r)| value(r).map(|v| (v, row(k))))
        .collect();
    if !points.is_empty() {
        spec = spec.series(
            Series::scatter(
                "model",
                points,
                theme.color(Role::Series(1)),
                Marker::Circle,
            )
            .with_width(2.0),
        );
    }
    spec
}
