//! The printed linkage's figure: how far the kink and the antikink get
//! against the pin friction μ_p.

use super::runs::{Done, Variant, run_all, variant};
use super::{PIN_FRICTION, PIN_FRICTION_RESOLUTION, chart_picture};
use crate::error::Result;
use crate::render::charts::{Axis, ChartSpec, Series};
use crate::render::palette::Role;
use crate::render::{Picture, Theme};
use crate::scene::Scene;
use crate::scenes::data::RunData;

/// μ_p, and the blocks the kink and the antikink flipped.
pub type Front = (f64, usize, usize);

/// How far the kink and the antikink get (blocks flipped) at each pin
/// friction of `mu` on `scene`'s linkage: (μ_p, kink, antikink).
pub fn fronts(scene: &Scene, mu: &[f64]) -> Result<(Vec<Front>, Vec<RunData>)> {
    let done = run_all(&variants(scene, mu)?)?;
    let flipped = |d: &Done| d.arrivals_s.iter().flatten().count();
    let rows = mu
        .iter()
        .enumerate()
        .map(|(i, m)| (*m, flipped(&done[2 * i]), flipped(&done[2 * i + 1])))
        .collect();
    Ok((rows, done.into_iter().map(|d| d.data).collect()))
}

/// The runs of [`fronts`] at `mu`: kink and antikink at each μ_p.
pub(super) fn variants(scene: &Scene, mu: &[f64]) -> Result<Vec<Variant>> {
    let mut variants = Vec::new();
    for &m in mu {
        for (sign, word) in [(1.0, "kink"), (-1.0, "antikink")] {
            variants.push(variant(scene, format!("{word}, μ_p = {m}"), sign, |a| {
                a.pin_friction = m
            })?);
        }
    }
    Ok(variants)
}

/// The most μ_p [`refined_fronts`] can run: every multiple of
/// [`PIN_FRICTION_RESOLUTION`] over the range of [`PIN_FRICTION`] (its
/// halvings land on them), for the check of the figure's runs before any.
pub fn most_pin_frictions() -> Vec<f64> {
    let (lo, hi) = (PIN_FRICTION[0], PIN_FRICTION[PIN_FRICTION.len() - 1]);
    let steps = ((hi - lo) / PIN_FRICTION_RESOLUTION).round() as usize;
    (0..=steps)
        .map(|i| lo + i as f64 * PIN_FRICTION_RESOLUTION)
        .collect()
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
/// of N) against the pin friction μ_p: a point per run, and each front
/// as a step function that changes halfway between two points whose
/// fronts differ (the threshold is known to within half their distance).
/// The kink is drawn under the antikink, wider, in filled marks; the
/// antikink in open rings around them, dashed: where both flip as many
/// blocks, both stay visible.
pub(super) fn linkage_friction(theme: &Theme, scene: &Scene) -> Result<(Picture, Vec<RunData>)> {
    let (rows, data) = refined_fronts(scene)?;
    let n = scene.model.n as f64;
    let mut spec = ChartSpec::new(
        Axis::new("pin friction μ_{p}"),
        Axis::new("blocks flipped (front)").range(0.0, n + 0.5),
    );
    for (j, (word, role)) in [("kink", Role::Kink), ("antikink", Role::Antikink)]
        .into_iter()
        .enumerate()
    {
        let marker = theme.marker(role, j == 1);
        let pts: Vec<(f64, f64)> = rows
            .iter()
            .map(|(mu, k, a)| (*mu, if j == 0 { *k } else { *a } as f64))
            .collect();
        let sign = if j == 0 { "+" } else { "−" };
        let label = format!("{word} (α = {sign}{:.1}°)", scene.model.alpha.abs());
        let color = theme.color(role);
        let width = if j == 0 { 3.0 } else { 1.5 };
        let line = Series::line("", steps(&pts), color).with_width(width);
        spec = spec.series(if j == 0 { line } else { line.dashed() });
        spec = spec.series(Series::scatter(label, pts, color, marker).with_width(1.5));
    }
    let picture = chart_picture(theme, &spec, (820, 560))?.fit_page();
    Ok((picture, data))
}

/// The step function through `pts` (sorted by x): each value held to
/// halfway to the next point, where it jumps.
pub fn steps(pts: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(3 * pts.len());
    for (i, &(x, y)) in pts.iter().enumerate() {
        if i > 0 {
            let mid = 0.5 * (pts[i - 1].0 + x);
            out.push((mid, pts[i - 1].1));
            out.push((mid, y));
        }
        out.push((x, y));
    }
    out
}
