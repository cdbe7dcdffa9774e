//! The tank's positions figure: each flipped block's position down the
//! chain (cm) against the time since block 1 flipped (s), at the three
//! motor speeds, with each run's fitted bulk line and the measured kink
//! speed as a line of its own.

use super::runs::{Done, Variant, run_all, variant};
use super::{MEASURED_KINK_CM_S, MOTORS_HZ, chart_picture, speed_text};
use crate::error::Result;
use crate::render::charts::{Axis, ChartSpec, Marker, Series};
use crate::render::palette::Role;
use crate::render::{Picture, Theme};
use crate::scene::Scene;
use crate::scenes::data::{BulkFit, RunData};

/// The marker of the `k`-th motor speed's points: the palette's `k`-th
/// shape of a series, filled for the kink, open for the antikink.
pub fn motor_marker(theme: &Theme, k: usize, antikink: bool) -> Marker {
    theme.palette.series_marker(k, antikink)
}

/// The figure's runs: kink and antikink at each motor speed.
pub(super) fn variants(scene: &Scene) -> Result<Vec<Variant>> {
    let mut variants = Vec::new();
    for f in MOTORS_HZ {
        for (sign, word) in [(1.0, "kink"), (-1.0, "antikink")] {
            variants.push(variant(scene, format!("{word}, {f} Hz"), sign, |a| {
                a.motor = Some(f)
            })?);
        }
    }
    Ok(variants)
}

/// Figure 1: the position (n − 1) b of each flipped block (cm) against
/// t_n − t_1, the time since block 1 flipped (s), kink and antikink at
/// each motor speed; each run's bulk line (fitted over the lower half of
/// the chain) through its points, and the measured 6.0 cm/s as a line
/// from block 1's flip (the supplement's apparatus panel).
pub(super) fn tank_positions(theme: &Theme, scene: &Scene) -> Result<(Picture, Vec<RunData>)> {
    let variants = variants(scene)?;
    let done = run_all(&variants)?;
    let bottom = done
        .iter()
        .map(|d| (d.arrivals_s.len() - 1) as f64 * d.pitch_cm)
        .fold(0.0, f64::max);
    let mut spec = ChartSpec::new(
        Axis::new("time since block 1 flipped, t − t_{1} (s)"),
        Axis::new("position (n − 1) b (cm)").range(0.0, 1.05 * bottom),
    );
    spec = spec.series(
        Series::line(
            format!("measured kink: {MEASURED_KINK_CM_S:.1} cm/s"),
            vec![(0.0, 0.0), (bottom / MEASURED_KINK_CM_S, bottom)],
            theme.color(Role::Measurement),
        )
        .dashed()
        .with_width(1.0),
    );
    for (k, d) in done.iter().enumerate() {
        let (motor, kink) = (k / 2, k % 2 == 0);
        let color = theme.color(if kink { Role::Kink } else { Role::Antikink });
        let label = format!("{}: {}", variants[k].label, speed_text(d.bulk_cm_s));
        spec = spec.series(
            Series::scatter(
                label,
                since_block_1(d),
                color,
                motor_marker(theme, motor, !kink),
            )
            .with_width(1.5),
        );
        if let Some(fit) = d.data.apparatus.as_ref().and_then(|a| a.bulk) {
            let line = Series::line("", fit_line(&fit, d.pitch_cm), color).with_width(1.0);
            spec = spec.series(if kink { line } else { line.dashed() });
        }
    }
    let picture = chart_picture(theme, &spec, (820, 600))?.fit_page();
    Ok((picture, done.into_iter().map(|d| d.data).collect()))
}

/// Each flipped block's (t_n − t_1 in s, (n − 1) b in cm).
fn since_block_1(d: &Done) -> Vec<(f64, f64)> {
    let Some(t1) = d.arrivals_s.first().copied().flatten() else {
        return Vec::new();
    };
    d.arrivals_s
        .iter()
        .enumerate()
        .filter_map(|(i, t)| t.map(|t| (t - t1, i as f64 * d.pitch_cm)))
        .collect()
}

/// The bulk line from half a block above its first block to half a block
/// below its last.
fn fit_line(fit: &BulkFit, pitch_cm: f64) -> Vec<(f64, f64)> {
    let at = |x: f64| (fit.centroid_s + (x - fit.centroid_cm) / fit.speed_cm_s, x);
    let (first, last) = (fit.blocks[0] as f64 - 1.0, fit.blocks[1] as f64 - 1.0);
    vec![at((first - 0.5) * pitch_cm), at((last + 0.5) * pitch_cm)]
}
