//! Scene → trajectory: runs a single-run scene with its integrator, the
//! verified `auto` by default (`sim::auto`), and keeps what the data file
//! reports about it.

use crate::error::Result;
use crate::scene::{Method, Scene};
use crate::sim::{self, IntegratorConfig, RunOptions, Trajectory};
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

/// Refuses, before any work, a run of `scene` with `samples` sample
/// times past the scene's caps (`Scene::limits`): its integrator's
/// steps × N (weighed by its force path, `sim::cost`) and samples × N,
/// and for `auto` every halving it may make (`sim::auto::worst_case`).
/// Returns the least the run will spend, in block-steps of the paper's
/// model (`auto`: its first pair), for a check of several runs together
/// (`scenes::cost`).
///
/// With `t_end = "auto"` the window is not known before its own run
/// (`sim::window`), so that run is what is checked here: one run to the
/// automatic window's cap at the integrator's first step. The runs drawn
/// after it are checked again, with the window found, before they start.
pub fn check_cost(scene: &Scene, samples: usize) -> Result<f64> {
    let limits = scene.limits;
    if scene.run.t_end == crate::scene::AUTO_T_END {
        let mut capped = scene.clone();
        capped.run.t_end = sim::window::AUTO_CAP;
        let scenario = capped.scenario()?;
        let config = match scene.run.fixed_config()? {
            Some(config) => config,
            None => crate::scene::run::auto_config(&scenario)?,
        };
        return Ok(sim::check_cost(&scenario, 0, &config, &limits)?.equivalent);
    }
    let scenario = scene.scenario()?;
    match scene.run.fixed_config()? {
        Some(config) => Ok(sim::check_cost(&scenario, samples, &config, &limits)?.equivalent),
        None => {
            let omega_max = crate::scene::run::omega_max(&scenario)?;
            Ok(sim::auto::worst_case(&scenario, samples, omega_max, &limits)?.first_pair)
        }
    }
}

/// Runs a single-run scene, recording the state at `samples`, with the
/// default run options within the scene's caps (`Scene::limits`); where
/// the render under way has made this very run for another output too,
/// that run (`scenes::shared`: the same bits).
pub fn simulate(scene: &Scene, samples: &[f64]) -> Result<SceneRun> {
    super::reuse::or_run(scene, samples, super::reuse::Stop::ToEnd, || {
        simulate_unshared(scene, samples)
    })
}

/// [`simulate`] made here, never taken from another output's.
pub fn simulate_unshared(scene: &Scene, samples: &[f64]) -> Result<SceneRun> {
    let options = RunOptions::default().limits(scene.limits);
    simulate_with(scene, samples, &options)
}

/// As [`simulate`], as `options` say (their stepping, caps, progress and
/// whether the dissipated energy is recorded; `sim::RunOptions`). The
/// stop rule should be `run_to_end`: a scene runs to its t_end.
pub fn simulate_with(scene: &Scene, samples: &[f64], options: &RunOptions) -> Result<SceneRun> {
    // `t_end = "auto"` resolved here for callers that did not (a no-op
    // when it is a number).
    let scene = &scene.with_auto_window()?;
    let scenario = scene.scenario()?;
    match scene.run.fixed_config()? {
        Some(config) => {
            let trajectory = sim::run(&scenario, samples, &config, options)?;
            Ok(SceneRun {
                integrator: fixed_report(scene, &config, &trajectory),
                trajectory,
            })
        }
        None => {
            let omega_max = crate::scene::run::omega_max(&scenario)?;
            let v = sim::auto::simulate_verified(
                &scenario,
                samples,
                scene.run.tolerance,
                omega_max,
                options,
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

/// Largest cost of [`critical_step`]'s trial runs, in block-steps (steps
/// times blocks): under a second.
const CRITICAL_STEP_BUDGET: f64 = 2e7;

/// The largest fixed step of `kind` at which every run of `scene` stays
/// bounded, measured by bisection to 5 % (as `bench stability` does for
/// the paper's scene), starting from the linear prediction (2/ω_max for
/// symplectic Euler and Verlet, README.md). `None` where measuring
/// would cost more than [`CRITICAL_STEP_BUDGET`], or no step down to a
/// thousandth of the prediction stays bounded; `predicted` is returned
/// either way.
pub fn critical_step(scene: &Scene, kind: sim::IntegratorKind) -> Result<CriticalStep> {
    let runs: Vec<Scene> = match scene.runs() {
        r if r.is_empty() => vec![scene.clone()],
        r => r.into_iter().map(|(s, _)| s).collect(),
    };
    let mut predicted = f64::INFINITY;
    let mut scenarios = Vec::new();
    for s in &runs {
        let scenario = s.scenario()?;
        let omega_max = crate::scene::run::omega_max(&scenario)?;
        let damping = sim::step_bounds::damping_rate(&scenario.ladder.params);
        predicted = predicted.min(sim::step_bounds::predicted_dt(kind, omega_max, damping));
        scenarios.push(scenario);
    }
    let bounded = |dt: f64| -> Result<bool> {
        let config = IntegratorConfig::fixed(kind, dt);
        for sc in &scenarios {
            match sim::simulate(sc, &[], &config) {
                Ok(_) => {}
                Err(e) if e.is_failed_run() => return Ok(false),
                Err(e) => return Err(e),
            }
        }
        Ok(true)
    };
    let cost_per_unit_step: f64 = runs.iter().map(|s| s.run.t_end * s.model.n as f64).sum();
    let mut spent = 0.0;
    let affordable = |dt: f64| {
        spent += cost_per_unit_step / dt;
        spent <= CRITICAL_STEP_BUDGET
    };
    Ok(CriticalStep {
        measured: largest_bounded(predicted, bounded, affordable)?,
        predicted,
    })
}

/// The largest step found bounded, by bisection to 5 % from the
/// prediction: first a bracket [lo, hi] (lo bounded, hi not) by halving
/// or doubling, within a thousandth to a thousand times the prediction;
/// `None` where no bracket is found or `affordable` refuses a trial
/// before one is.
fn largest_bounded(
    predicted: f64,
    bounded: impl Fn(f64) -> Result<bool>,
    mut affordable: impl FnMut(f64) -> bool,
) -> Result<Option<f64>> {
    if !predicted.is_finite() || predicted <= 0.0 {
        return Ok(None);
    }
    let (mut lo, mut hi) = (predicted, predicted);
    loop {
        if !affordable(lo) {
            return Ok(None);
        }
        if bounded(lo)? {
            break;
        }
        hi = lo;
        lo *= 0.5;
        if lo < 1e-3 * predicted {
            return Ok(None);
        }
    }
    if hi == lo {
        loop {
            hi *= 2.0;
            if !affordable(hi) {
                return Ok(None);
            }
            if !bounded(hi)? {
                break;
            }
            lo = hi;
            if hi > 1e3 * predicted {
                return Ok(None);
            }
        }
    }
    while hi / lo > 1.05 {
        let mid = (lo * hi).sqrt();
        if !affordable(mid) {
            break;
        }
        if bounded(mid)? {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(Some(lo))
}

/// The stable step of a scene: measured (the largest step found bounded)
/// and predicted by the linear theory, in τ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CriticalStep {
    pub measured: Option<f64>,
    pub predicted: f64,
}
