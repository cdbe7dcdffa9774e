//! Speed against accuracy: work-precision sweeps and stability bisection
//! (SPEC section 5, `bench work-precision` and `bench stability`), and the
//! paper's run timed with each kernel (`bench kernels`).
//!
//! Every error is measured against a reference computed by the program
//! itself at a much tighter setting (dopri5, rtol = 1e-11).

use crate::error::{Error, Result};
use crate::model::Params;
use crate::scene::Scene;
pub use crate::sim::step_bounds::{damping_rate, predicted_dt, stability_function};
use crate::sim::{self, IntegratorConfig, IntegratorKind, Scenario, Trajectory};
use serde::{Deserialize, Serialize};
use std::time::Instant;

pub mod charts;
pub mod kernels;
pub use charts::{stability_caption, stability_chart, work_precision_chart};
pub use kernels::{KernelReport, kernels, kernels_table};

/// The middle of `values` (the upper of the two middle ones for an even
/// count); NaN for none.
pub fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied().unwrap_or(f64::NAN)
}

/// Tolerance of the reference solution.
pub const REFERENCE_RTOL: f64 = 1e-11;

/// A scene of the work-precision and stability studies: a single-run
/// [`Scene`] (the paper's single flip by default) and the times at which θ
/// is compared with the reference.
#[derive(Debug, Clone)]
pub struct BenchScene {
    pub name: String,
    pub scene: Scene,
    pub alpha_deg: f64,
    pub params: Params,
    pub t_end: f64,
    /// Times at which θ is compared with the reference.
    pub frames: Vec<f64>,
}

impl BenchScene {
    /// The paper's kink (α > 0) or antikink (α < 0) scene, N = 10, b = 1.3,
    /// T_d = 1000, t_end = 4000, compared every 20 τ.
    pub fn paper(alpha_deg: f64) -> Result<Self> {
        let mut scene = Scene::default();
        scene.model.alpha = alpha_deg;
        Self::from_scene(
            Scene {
                run: crate::scene::Run {
                    t_end: 4000.0,
                    ..scene.run
                },
                ..scene
            },
            200,
        )
    }

    /// A study scene from any single-run scene, compared at `frames` + 1
    /// evenly spaced times.
    pub fn from_scene(scene: Scene, frames: usize) -> Result<Self> {
        let params = scene.model.params()?;
        let t_end = scene.run.t_end;
        Ok(Self {
            name: crate::scene::describe::wave(&scene.model).replace(", ", " "),
            alpha_deg: scene.model.alpha,
            params,
            t_end,
            frames: (0..=frames.max(1))
                .map(|k| t_end * k as f64 / frames.max(1) as f64)
                .collect(),
            scene,
        })
    }

    pub fn scenario(&self) -> Result<Scenario> {
        self.scene.scenario()
    }

    /// Runs the scene with `config`, sampled at the frames.
    pub fn run(&self, config: &IntegratorConfig) -> Result<Trajectory> {
        sim::simulate(&self.scenario()?, &self.frames, config)
    }

    /// The reference solution (dopri5 at `rtol`).
    pub fn reference(&self, rtol: f64) -> Result<Trajectory> {
        self.run(&IntegratorConfig::adaptive(rtol))
    }
}

/// Largest |θ_n(t) − θ_ref,n(t)| over the frames (radians).
pub fn theta_error(run: &Trajectory, reference: &Trajectory) -> f64 {
    run.states
        .iter()
        .zip(&reference.states)
        .flat_map(|(a, b)| a.iter().zip(b).skip(2).step_by(3))
        .fold(0.0, |m, (x, y)| m.max((x - y).abs()))
}

/// Largest |t_n − t_ref,n| (τ); `None` (infinite) when a block flips in one
/// run and not in the other.
pub fn arrival_error(run: &Trajectory, reference: &Trajectory) -> Option<f64> {
    let mut worst: f64 = 0.0;
    for (a, b) in run.arrival_times.iter().zip(&reference.arrival_times) {
        match (a, b) {
            (Some(a), Some(b)) => worst = worst.max((a - b).abs()),
            (None, None) => {}
            _ => return None,
        }
    }
    Some(worst)
}

/// One point of a work-precision sweep.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Point {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dt: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rtol: Option<f64>,
    pub force_evals: u64,
    pub wall_seconds: f64,
    pub theta_error: Option<f64>,
    pub arrival_error: Option<f64>,
    pub diverged: bool,
}

/// All points of one integrator, and its order measured from them.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Sweep {
    pub name: String,
    pub measured_order: Option<f64>,
    pub points: Vec<Point>,
}

/// The step sizes (or tolerances, for dopri5) swept for each integrator:
/// from well converged to past the stability limit.
pub fn default_steps(kind: IntegratorKind) -> Vec<f64> {
    match kind {
        IntegratorKind::ExplicitEuler => vec![0.0005, 0.001, 0.002, 0.005, 0.01],
        IntegratorKind::SymplecticEuler => vec![0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4],
        IntegratorKind::Verlet => vec![0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.3, 0.4, 0.6],
        IntegratorKind::Rk4 => vec![0.05, 0.1, 0.2, 0.3, 0.4, 0.6, 0.8],
        IntegratorKind::Dopri5 => vec![1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10],
    }
}

/// The configuration of `kind` at sweep value `x` (dt, or rtol for dopri5).
pub fn config_at(kind: IntegratorKind, x: f64) -> IntegratorConfig {
    match kind {
        IntegratorKind::Dopri5 => IntegratorConfig::adaptive(x),
        _ => IntegratorConfig::fixed(kind, x),
    }
}

/// Runs `kind` at every value of `steps` on `scene`, `repeats` times each
/// (the median wall time is kept), and measures the errors against `reference`.
pub fn sweep(
    scene: &BenchScene,
    reference: &Trajectory,
    kind: IntegratorKind,
    steps: &[f64],
    repeats: usize,
) -> Result<Sweep> {
    let mut points = Vec::with_capacity(steps.len());
    for &x in steps {
        points.push(measure(scene, reference, kind, x, repeats)?);
    }
    Ok(Sweep {
        name: kind.name().to_string(),
        measured_order: measured_order(&points),
        points,
    })
}

fn measure(
    scene: &BenchScene,
    reference: &Trajectory,
    kind: IntegratorKind,
    x: f64,
    repeats: usize,
) -> Result<Point> {
    let config = config_at(kind, x);
    let (dt, rtol) = match kind {
        IntegratorKind::Dopri5 => (None, Some(x)),
        _ => (Some(x), None),
    };
    let mut times = Vec::with_capacity(repeats.max(1));
    let mut outcome = None;
    for _ in 0..repeats.max(1) {
        let start = Instant::now();
        let run = scene.run(&config);
        times.push(start.elapsed().as_secs_f64());
        match run {
            Err(e) if e.is_failed_run() => {
                outcome = None;
                break;
            }
            Err(e) => return Err(e),
            Ok(t) => outcome = Some(t),
        }
    }
    let wall_seconds = median(times);
    Ok(match outcome {
        Some(run) => Point {
            dt,
            rtol,
            force_evals: run.force_evals,
            wall_seconds,
            theta_error: Some(theta_error(&run, reference)),
            arrival_error: arrival_error(&run, reference),
            diverged: false,
        },
        None => Point {
            dt,
            rtol,
            force_evals: 0,
            wall_seconds,
            theta_error: None,
            arrival_error: None,
            diverged: true,
        },
    })
}

/// Order p from the slope of log(θ error) against log(force evaluations)
/// (error ∝ evals^(−p)), over converged points whose error lies between
/// 1e-10 (well above the reference's own error, about 1e-12) and 1e-2 (asymptotic regime).
/// Points on a cost plateau (within 30 % of the cheapest, where an adaptive
/// method is held by stability rather than by its tolerance) are left out.
pub fn measured_order(points: &[Point]) -> Option<f64> {
    let floor = points
        .iter()
        .filter(|p| !p.diverged)
        .map(|p| p.force_evals)
        .min()?;
    let plateau = |p: &Point| {
        let tolerance_driven = points.iter().any(|q| q.rtol.is_some());
        tolerance_driven && (p.force_evals as f64) < 1.3 * floor as f64
    };
    let pts: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| !p.diverged && !plateau(p))
        .filter_map(|p| p.theta_error.map(|e| (p.force_evals as f64, e)))
        .filter(|(_, e)| *e > 1e-10 && *e < 1e-2)
        .map(|(n, e)| (n.ln(), e.ln()))
        .collect();
    if pts.len() < 2 {
        return None;
    }
    Some(-slope(&pts))
}

pub use crate::sim::observables::least_squares_slope as slope;

/// The cheapest point (fewest force evaluations) whose arrival times all lie
/// within `tolerance` τ of the reference.
pub fn cheapest_within(sweeps: &[Sweep], tolerance: f64) -> Option<(&str, &Point)> {
    sweeps
        .iter()
        .flat_map(|s| s.points.iter().map(move |p| (s.name.as_str(), p)))
        .filter(|(_, p)| p.arrival_error.is_some_and(|e| e <= tolerance))
        .min_by_key(|(_, p)| p.force_evals)
}

/// Whether the scene stays bounded with `kind` at fixed step `dt`
/// (dopri5 is run at fixed step here).
pub fn is_stable(scene: &BenchScene, kind: IntegratorKind, dt: f64) -> Result<bool> {
    let config = IntegratorConfig::fixed(kind, dt);
    match sim::simulate(&scene.scenario()?, &[], &config) {
        Ok(_) => Ok(true),
        Err(e) if e.is_failed_run() => Ok(false),
        Err(e) => Err(e),
    }
}

/// The largest stable dt, by geometric bisection from a bracket around
/// `guess`, to a relative precision `rel`.
pub fn critical_dt(scene: &BenchScene, kind: IntegratorKind, guess: f64, rel: f64) -> Result<f64> {
    let (mut lo, mut hi) = (guess, guess);
    while !is_stable(scene, kind, lo)? {
        lo /= 2.0;
        if lo < 1e-6 {
            return Err(Error::failed(format!("{kind}: no stable dt above 1e-6")));
        }
    }
    hi = hi.max(lo * 2.0);
    while is_stable(scene, kind, hi)? {
        hi *= 2.0;
        if hi > scene.t_end {
            return Ok(hi);
        }
    }
    while hi / lo > 1.0 + rel {
        let mid = (lo * hi).sqrt();
        if is_stable(scene, kind, mid)? {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(lo)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_is_the_middle_value() {
        assert_eq!(median(vec![3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(vec![4.0, 1.0, 3.0, 2.0]), 3.0);
        assert!(median(Vec::new()).is_nan());
    }

    #[test]
    fn slope_of_a_power_law() {
        let pts: Vec<(f64, f64)> = (1..6).map(|k| (k as f64, -3.0 * k as f64 + 1.0)).collect();
        assert!((slope(&pts) + 3.0).abs() < 1e-12);
    }
}

/// Results of one scene of the work-precision study.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct SceneReport {
    pub scene: String,
    pub alpha_deg: f64,
    /// Length of the simulated window (τ).
    pub t_end: f64,
    pub integrators: Vec<Sweep>,
}

/// `bench work-precision --json`: the α = 60° kink's sweeps at the top level
/// (SPEC section 5), both scenes under `scenes`, and the cheapest setting
/// that keeps every arrival time within 1 τ of the reference.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct WorkPrecisionReport {
    pub integrators: Vec<Sweep>,
    pub scenes: Vec<SceneReport>,
    pub cheapest_within_1tau: Vec<Cheapest>,
    pub reference: String,
}

/// The cheapest setting of one scene within a tolerance on arrival times.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Cheapest {
    pub scene: String,
    pub integrator: String,
    pub step: f64,
    pub force_evals: u64,
    pub arrival_error: f64,
}

/// Runs the whole study on `scenes` (every integrator over its default
/// range); `progress` is told each finished point.
pub fn work_precision(
    scenes: &[BenchScene],
    repeats: usize,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<WorkPrecisionReport> {
    let mut reports = Vec::new();
    let mut cheapest = Vec::new();
    for scene in scenes {
        let reference = scene.reference(REFERENCE_RTOL)?;
        let mut sweeps = Vec::new();
        for kind in IntegratorKind::ALL {
            let mut points = Vec::new();
            for x in default_steps(kind) {
                points.push(measure(scene, &reference, kind, x, repeats)?);
                progress(&format!("{}: {kind} at {x}", scene.name));
            }
            sweeps.push(Sweep {
                name: kind.name().to_string(),
                measured_order: measured_order(&points),
                points,
            });
        }
        if let Some((name, p)) = cheapest_within(&sweeps, 1.0) {
            cheapest.push(Cheapest {
                scene: scene.name.clone(),
                integrator: name.to_string(),
                step: p.dt.or(p.rtol).unwrap_or(f64::NAN),
                force_evals: p.force_evals,
                arrival_error: p.arrival_error.unwrap_or(f64::NAN),
            });
        }
        reports.push(SceneReport {
            scene: scene.name.clone(),
            alpha_deg: scene.alpha_deg,
            t_end: scene.t_end,
            integrators: sweeps,
        });
    }
    Ok(WorkPrecisionReport {
        integrators: reports
            .first()
            .map(|r| r.integrators.clone())
            .unwrap_or_default(),
        scenes: reports,
        cheapest_within_1tau: cheapest,
        reference: format!("dopri5, rtol = {REFERENCE_RTOL:e}"),
    })
}

fn opt(x: Option<f64>) -> String {
    x.map_or(String::new(), |v| format!("{v:e}"))
}

/// The numbers behind `work-precision.png`, one row per point.
pub fn work_precision_csv(report: &WorkPrecisionReport) -> String {
    let mut s = String::from(
        "scene,integrator,dt,rtol,force_evals,wall_seconds,theta_error,arrival_error,diverged\n",
    );
    for scene in &report.scenes {
        for sweep in &scene.integrators {
            for p in &sweep.points {
                s.push_str(&format!(
                    "{},{},{},{},{},{:e},{},{},{}\n",
                    scene.scene,
                    sweep.name,
                    opt(p.dt),
                    opt(p.rtol),
                    p.force_evals,
                    p.wall_seconds,
                    opt(p.theta_error),
                    opt(p.arrival_error),
                    p.diverged
                ));
            }
        }
    }
    s
}

/// A human-readable table of the study.
pub fn work_precision_table(report: &WorkPrecisionReport) -> String {
    let mut s = String::new();
    for scene in &report.scenes {
        s.push_str(&format!(
            "{} (reference: {})\n",
            scene.scene, report.reference
        ));
        s.push_str(
            "integrator        step      force evals  wall (ms)  θ error     arrival error (τ)\n",
        );
        for sweep in &scene.integrators {
            for p in &sweep.points {
                let step = p.dt.or(p.rtol).unwrap_or(f64::NAN);
                let (th, ar) = if p.diverged {
                    ("diverged".to_string(), String::new())
                } else {
                    (
                        p.theta_error.map_or(String::new(), |e| format!("{e:.2e}")),
                        p.arrival_error
                            .map_or("a flip differs".into(), |e| format!("{e:.3}")),
                    )
                };
                s.push_str(&format!(
                    "{:<17} {:<9} {:>11}  {:>9.2}  {:<11} {}\n",
                    sweep.name,
                    format!("{step}"),
                    p.force_evals,
                    1e3 * p.wall_seconds,
                    th,
                    ar
                ));
            }
            let order = sweep
                .measured_order
                .map_or("n/a".into(), |o| format!("{o:.2}"));
            s.push_str(&format!("{:<17} measured order {order}\n", sweep.name));
        }
        s.push('\n');
    }
    for c in &report.cheapest_within_1tau {
        s.push_str(&format!(
            "cheapest within 1 τ, {}: {} at {} ({} force evaluations, arrival error {:.3} τ)\n",
            c.scene, c.integrator, c.step, c.force_evals, c.arrival_error
        ));
    }
    s
}

/// Observed and predicted critical step of one integrator.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct StabilityRow {
    pub name: String,
    /// Largest dt at which the kink scene stays bounded (bisection).
    pub critical_dt: f64,
    /// Linear prediction from ω_max ([`predicted_dt`]).
    pub predicted_dt: f64,
}

/// The stability study at one α.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct StabilityPoint {
    pub alpha_deg: f64,
    pub omega_max: f64,
    pub integrators: Vec<StabilityRow>,
}

/// `bench stability --json`: the α = 60° rows at the top level (SPEC
/// section 5) and the sweep over α.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct StabilityReport {
    pub alpha_deg: f64,
    pub omega_max: f64,
    pub damping_rate: f64,
    pub integrators: Vec<StabilityRow>,
    pub sweep: Vec<StabilityPoint>,
}

/// Relative precision of the stability bisection.
pub const STABILITY_PRECISION: f64 = 0.02;

/// Critical and predicted dt of every integrator on the kink scene at α.
pub fn stability_at(alpha_deg: f64) -> Result<StabilityPoint> {
    let scene = BenchScene::paper(alpha_deg)?;
    let omega_max = crate::theory::dispersion::omega_max_clamped(&scene.params)?;
    let c = damping_rate(&scene.params);
    let mut rows = Vec::new();
    for kind in IntegratorKind::ALL {
        let predicted = predicted_dt(kind, omega_max, c);
        let critical = critical_dt(&scene, kind, predicted, STABILITY_PRECISION)?;
        rows.push(StabilityRow {
            name: kind.name().to_string(),
            critical_dt: critical,
            predicted_dt: predicted,
        });
    }
    Ok(StabilityPoint {
        alpha_deg,
        omega_max,
        integrators: rows,
    })
}

/// The α values of the stability chart.
pub const STABILITY_ALPHAS: [f64; 11] = [
    5.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0, 85.0, 89.0,
];

/// The whole study: α = 60° and the sweep over `alphas` (in parallel).
pub fn stability(alphas: &[f64], progress: &(dyn Fn(&str) + Sync)) -> Result<StabilityReport> {
    use rayon::prelude::*;
    let sweep: Vec<StabilityPoint> = alphas
        .par_iter()
        .map(|&a| {
            let p = stability_at(a);
            progress(&format!("α = {a}°"));
            p
        })
        .collect::<Result<_>>()?;
    let at60 = match sweep.iter().find(|p| p.alpha_deg == 60.0) {
        Some(p) => p.clone(),
        None => stability_at(60.0)?,
    };
    Ok(StabilityReport {
        alpha_deg: 60.0,
        omega_max: at60.omega_max,
        damping_rate: damping_rate(&Params::paper(60.0)?),
        integrators: at60.integrators,
        sweep,
    })
}

/// The numbers behind `stability.png`.
pub fn stability_csv(report: &StabilityReport) -> String {
    let mut s = String::from("alpha_deg,omega_max,integrator,critical_dt,predicted_dt\n");
    for p in &report.sweep {
        for r in &p.integrators {
            s.push_str(&format!(
                "{},{:.6},{},{:.6e},{:.6e}\n",
                p.alpha_deg, p.omega_max, r.name, r.critical_dt, r.predicted_dt
            ));
        }
    }
    s
}

/// A human-readable table of the α = 60° rows.
pub fn stability_table(report: &StabilityReport) -> String {
    let mut s = format!(
        "kink α = {}°: ω_max = {:.4} /τ (block 1 clamped), damping rate {} /τ\n\
         integrator        critical dt   predicted dt   ratio\n",
        report.alpha_deg, report.omega_max, report.damping_rate
    );
    for r in &report.integrators {
        s.push_str(&format!(
            "{:<17} {:<13.5} {:<14.5} {:.2}\n",
            r.name,
            r.critical_dt,
            r.predicted_dt,
            r.critical_dt / r.predicted_dt
        ));
    }
    s
}
