//! Scene → trajectory: runs a single-run scene with its integrator, the
//! verified `auto` by default (`sim::auto`), and keeps what the data file
//! reports about it.

use crate::error::Result;
use crate::scene::{Method, Scene};
use crate::sim::{self, IntegratorConfig, Stepping, Trajectory};
use serde::Serialize;

/// A simulated scene: its trajectory and how it was computed.
#[derive(Debug, Clone)]
pub struct SceneRun {
    pub trajectory: Trajectory,
    pub integrator: IntegratorReport,
}

/// The integrator a run used and the accuracy it reached.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct IntegratorReport {
    /// `auto`, or the integrator the scene named.
    pub requested: String,
    /// The scheme that made the returned trajectory.
    pub name: String,
    pub dt: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rtol: Option<f64>,
    /// `auto` only: the scene's tolerance on arrival times, τ.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// `auto` only: estimated largest arrival-time error, τ (a third of the
    /// largest difference to the run at twice the step).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub arrival_error: Option<f64>,
    /// `auto` only: largest arrival-time difference between the returned
    /// run and the one at twice its step, τ.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub arrival_difference: Option<f64>,
    pub steps: u64,
    /// Force evaluations of the returned run.
    pub force_evals: u64,
    /// Force evaluations of every run made (the check included).
    pub total_force_evals: u64,
}

impl IntegratorReport {
    /// "verlet, dt = 0.125 τ, arrival times within 0.004 τ (auto)".
    pub fn describe(&self) -> String {
        let step = match self.rtol {
            Some(r) => format!("rtol = {r:e}"),
            None => format!("dt = {} τ", self.dt),
        };
        match self.arrival_error {
            Some(e) => format!(
                "{} {step}, chosen by auto; arrival times within about {} τ (checked against a run at twice the step)",
                self.name,
                short(e)
            ),
            None => format!("{} {step}", self.name),
        }
    }
}

fn short(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if x < 1e-3 {
        format!("{x:.0e}")
    } else {
        format!("{x:.3}")
    }
}

/// Runs a single-run scene, recording the state at `samples`.
pub fn simulate(scene: &Scene, samples: &[f64]) -> Result<SceneRun> {
    simulate_with(scene, samples, Stepping::Fastest, &|_| {})
}

/// As [`simulate`], with symplectic Euler's steps taken as `stepping`
/// says (the same numbers whatever it is; `sim::fused`), telling
/// `progress` the simulated time as the runs go.
pub fn simulate_with(
    scene: &Scene,
    samples: &[f64],
    stepping: Stepping,
    progress: &(dyn Fn(f64) + Sync),
) -> Result<SceneRun> {
    let scenario = scene.scenario()?;
    match scene.run.fixed_config()? {
        Some(config) => {
            let trajectory =
                sim::simulate_observed(&scenario, samples, &config, stepping, progress)?;
            Ok(SceneRun {
                integrator: fixed_report(scene, &config, &trajectory),
                trajectory,
            })
        }
        None => {
            let params = scene.model.params()?;
            let omega_max = crate::theory::dispersion::omega_max_clamped(&params)?;
            let v = sim::auto::simulate_verified_observed(
                &scenario,
                samples,
                scene.run.tolerance,
                omega_max,
                progress,
            )?;
            Ok(SceneRun {
                integrator: IntegratorReport {
                    requested: Method::Auto.to_string(),
                    name: v.config.kind.name().into(),
                    dt: v.config.dt,
                    rtol: None,
                    tolerance: Some(scene.run.tolerance),
                    arrival_error: Some(v.arrival_error),
                    arrival_difference: Some(v.arrival_difference),
                    steps: v.trajectory.steps,
                    force_evals: v.trajectory.force_evals,
                    total_force_evals: v.total_force_evals,
                },
                trajectory: v.trajectory,
            })
        }
    }
}

fn fixed_report(scene: &Scene, config: &IntegratorConfig, t: &Trajectory) -> IntegratorReport {
    IntegratorReport {
        requested: scene.run.integrator.to_string(),
        name: config.kind.name().into(),
        dt: config.dt,
        rtol: config.rtol,
        tolerance: None,
        arrival_error: None,
        arrival_difference: None,
        steps: t.steps,
        force_evals: t.force_evals,
        total_force_evals: t.force_evals,
    }
}
