//! The energy view (`--view energy`, `[output] kind = "energy"`): the
//! energies of the scene's run against t/τ (docs/python.md), with the
//! numbers in its data file.
//!
//! Each energy is drawn as its change from t = 0, in units of k s²
//! (docs/model.md; the supplement's equations of motion, "Details of
//! numerical simulation"): the kinetic ½m(Ẋ² + Ẏ²) + ½Iθ̇², the elastic
//! Σ½k[(L_A − a)² + (L_B − b)²], the gravitational −mGΣX_n, the energy
//! the damping has dissipated so far (∫ γ(Ẋ² + Ẏ² + r²θ̇²) dt, recorded
//! in the run loop: `sim::RunOptions::dissipation`), their total
//! (kinetic + elastic + gravitational) and the total plus the dissipated
//! energy. While block 1 is driven the drive works on the chain; once it
//! has ended nothing does, so the total plus the dissipated energy is
//! flat to the integrator's accuracy (tests/integration/energy_view.rs).

use super::data::RunData;
pub use super::data::{ENERGY_SAMPLES, EnergyData};
use super::run;
use crate::error::{Error, Result};
use crate::render::charts::{Axis, ChartSpec, Series};
use crate::render::line_chart_figure;
use crate::render::palette::{Palette, Role};
use crate::render::{Picture, Theme};
use crate::scene::{Scene, describe};
use crate::sim::RunOptions;

/// `n + 1` times evenly over [0, t_end].
fn even(t_end: f64, n: usize) -> Vec<f64> {
    (0..=n).map(|k| t_end * k as f64 / n as f64).collect()
}

/// The energy figure of `scene` and its run's data (with `energies`),
/// drawn with `theme`.
pub fn energy_figure(theme: &Theme, scene: &Scene) -> Result<(Picture, Vec<RunData>)> {
    // `t_end = "auto"` resolved here too, for callers that did not go
    // through `scenes::render_to` (a no-op when resolved).
    let scene = &scene.with_auto_window()?;
    let times = even(scene.run.t_end, ENERGY_SAMPLES - 1);
    let options = RunOptions::default().limits(scene.limits).dissipation(true);
    let run = run::simulate_with(scene, &times, &options)?;
    let scenario = scene.scenario()?;
    let e = run.trajectory.energies(&scenario.ladder);
    if e.dissipated.len() != run.trajectory.times.len() {
        return Err(Error::failed(
            "the run did not record the energy dissipated at every sample",
        ));
    }
    let data = EnergyData {
        times: run.trajectory.times.clone(),
        total: e.total(),
        kinetic: e.kinetic,
        elastic: e.elastic,
        gravitational: e.gravitational,
        dissipated: e.dissipated,
    };
    let spec = energy_chart(scene, &data);
    // The run once; the chart is drawn again only to search a size.
    let picture = line_chart_figure(theme, &spec, (820, 560), &describe::title(scene))?;
    let mut record = RunData::from_run(scene, &run);
    record.energies = Some(data);
    Ok((picture, vec![record]))
}

/// The chart: each energy's change from t = 0 against t/τ.
pub fn energy_chart(scene: &Scene, e: &EnergyData) -> ChartSpec {
    let change = |v: &[f64]| -> Vec<(f64, f64)> {
        let v0 = v.first().copied().unwrap_or(0.0);
        e.times.iter().zip(v).map(|(&t, &x)| (t, x - v0)).collect()
    };
    let with = e.total_with_dissipated();
    let drive_end = scene.drive.end();
    let mut spec = ChartSpec::new(
        Axis::new("t/τ"),
        Axis::new("energy − its value at t = 0 (k s²)"),
    );
    let lines: [(&str, &[f64], crate::encode::Rgb, bool); 6] = [
        ("kinetic", &e.kinetic, Palette.color(Role::Series(5)), false),
        ("elastic", &e.elastic, Palette.color(Role::Series(3)), false),
        (
            "gravitational",
            &e.gravitational,
            Palette.color(Role::Series(4)),
            false,
        ),
        (
            "dissipated so far",
            &e.dissipated,
            Palette.color(Role::Series(6)),
            true,
        ),
        ("total", &e.total, Palette.color(Role::Series(1)), false),
        (
            "total + dissipated",
            &with,
            Palette.color(Role::Series(2)),
            false,
        ),
    ];
    for (label, values, color, dashed) in lines {
        let s = Series::line(label, change(values), color).with_width(1.5);
        spec = spec.series(if dashed { s.dashed() } else { s });
    }
    if drive_end > 0.0 && drive_end < scene.run.t_end {
        let span: Vec<f64> = e
            .kinetic
            .iter()
            .zip(&e.elastic)
            .zip(&e.gravitational)
            .flat_map(|((a, b), c)| {
                [
                    *a - e.kinetic[0],
                    *b - e.elastic[0],
                    *c - e.gravitational[0],
                ]
            })
            .chain(with.iter().map(|x| x - with[0]))
            .collect();
        let lo = span.iter().copied().fold(0.0, f64::min);
        let hi = span.iter().copied().fold(0.0, f64::max);
        spec = spec.series(
            Series::line(
                format!("drive ends, t/τ = {}", describe::num(drive_end)),
                vec![(drive_end, lo), (drive_end, hi)],
                Palette.color(Role::Ground),
            )
            .dashed(),
        );
    }
    spec
}
