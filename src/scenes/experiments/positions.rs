//! The tank's positions figure: each flipped block's position down the
//! chain (cm) against its arrival time (s), at the three motor speeds.

use super::runs::{run_all, variant};
use super::{MOTORS_HZ, chart_picture, speed_text};
use crate::error::Result;
use crate::render::charts::{Axis, ChartSpec, Marker, Series};
use crate::render::{Picture, Theme, style};
use crate::scene::Scene;
use crate::scenes::data::RunData;

/// Figure 1: the position (n − 1) b of each flipped block (cm) against its
/// arrival time (s), kink and antikink at each motor speed, with the bulk
/// speeds in cm/s (the supplement's apparatus panel).
pub(super) fn tank_positions(theme: &Theme, scene: &Scene) -> Result<(Picture, Vec<RunData>)> {
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
