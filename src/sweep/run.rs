//! One point of a sweep: run its scene until the outcome is decided
//! (`outcome::Rule`), with the scene's integrator; `auto` is verified as
//! for a single scene (`sim::auto`): the run at dt is checked against one
//! at dt/2, both run until decided, and must agree on the outcome and on
//! every arrival time up to the earlier decision within the tolerance;
//! the step is halved until they do.

use super::outcome::{self, Decision, Outcome, Rule};
use crate::error::{Error, Result};
use crate::scene::Scene;
use crate::scene::sweep::SweepSpec;
use crate::sim::{self, IntegratorConfig, IntegratorKind, Scenario, Stepping, Trajectory};
use serde::{Deserialize, Serialize};

/// Most halvings of the step `auto` makes for one point of a sweep (a
/// point still unverified at dt/16 is kept with a message: a sweep runs
/// thousands of points, each possibly to the cap).
pub const MAX_HALVINGS: u32 = 4;

/// What one run did.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunResult {
    pub outcome: Outcome,
    /// Blocks whose polarisation changed sign.
    pub blocks_flipped: usize,
    /// The last block the wave reached (blocks 1..=front all flipped).
    pub front: usize,
    /// Blocks per τ, least squares over blocks 3..N−1; `None` when fewer
    /// than three of them flipped.
    pub speed: Option<f64>,
    /// When the outcome was decided (`None` for a diverged run).
    pub t_decided: Option<f64>,
    /// Arrival time of each block, `None` where it never flipped before
    /// the run ended.
    pub arrival_times: Vec<Option<f64>>,
    /// The integrator of the returned run.
    pub integrator: String,
    pub dt: f64,
    /// `auto` only: estimated largest arrival-time error, τ.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub arrival_error: Option<f64>,
    /// Force evaluations of every run made for this point.
    pub force_evals: u64,
    /// What went wrong, for a diverged run.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub message: Option<String>,
}

/// The rule of `scene` (a single-run scene) under `spec`.
pub fn rule(scene: &Scene, spec: &SweepSpec) -> Rule {
    Rule {
        drive_start: scene.drive.flips.first().map_or(0.0, |f| f.start),
        drive_end: scene.drive.end(),
        t_end: scene.run.t_end,
        quiet: spec.quiet,
        cap: spec.cap,
    }
}

/// Runs the single-run `scene` (a point of the sweep) until decided.
/// Bad input is an error; a diverging integration is a `diverged` result.
pub fn run_point(scene: &Scene, spec: &SweepSpec) -> Result<RunResult> {
    let rule = rule(scene, spec);
    let mut capped = scene.clone();
    capped.run.t_end = spec.cap;
    let scenario = capped.scenario()?;
    match scene.run.fixed_config()? {
        Some(config) => fixed(&scenario, &config, &rule),
        None => {
            let params = scene.model.params()?;
            let omega_max = crate::theory::dispersion::omega_max_clamped(&params)?;
            verified(&scenario, omega_max, scene.run.tolerance, &rule)
        }
    }
}

/// One integration until decided: its decision and trajectory, or (inner
/// error) the divergence message; bad input is the outer error.
type Attempt = std::result::Result<(Decision, Trajectory), String>;

fn until_decided(scenario: &Scenario, config: &IntegratorConfig, rule: &Rule) -> Result<Attempt> {
    let stop = |t: f64, arrivals: &[Option<f64>]| rule.decide(arrivals, t).is_some();
    match sim::simulate_until(scenario, config, Stepping::Fastest, &stop) {
        Ok(traj) => {
            // Replaying the history at the cap gives the decision the run
            // stopped on (or `undecided` if it ran to the cap).
            let d = rule
                .decide(&traj.arrival_times, rule.cap)
                .unwrap_or(Decision {
                    outcome: Outcome::Undecided,
                    t_decided: rule.cap,
                });
            Ok(Ok((d, traj)))
        }
        Err(Error::Failed(msg)) => Ok(Err(msg)),
        Err(e) => Err(e),
    }
}

fn fixed(scenario: &Scenario, config: &IntegratorConfig, rule: &Rule) -> Result<RunResult> {
    Ok(match until_decided(scenario, config, rule)? {
        Ok((d, traj)) => result(d, &traj, config, None, traj.force_evals),
        Err(msg) => diverged(scenario, config, msg, 0),
    })
}

fn result(
    d: Decision,
    traj: &Trajectory,
    config: &IntegratorConfig,
    arrival_error: Option<f64>,
    force_evals: u64,
) -> RunResult {
    // Arrivals after the decision belong to no outcome: drop them, so the
    // record does not depend on how long after it the run was stopped.
    let arrivals: Vec<Option<f64>> = traj
        .arrival_times
        .iter()
        .map(|a| a.filter(|&t| t <= d.t_decided))
        .collect();
    RunResult {
        outcome: d.outcome,
        blocks_flipped: outcome::blocks_flipped(&arrivals),
        front: outcome::front(&arrivals),
        speed: outcome::speed(&arrivals),
        t_decided: Some(d.t_decided),
        arrival_times: arrivals,
        integrator: config.kind.name().into(),
        dt: config.dt,
        arrival_error,
        force_evals,
        message: None,
    }
}

fn diverged(scenario: &Scenario, config: &IntegratorConfig, msg: String, evals: u64) -> RunResult {
    RunResult {
        outcome: Outcome::Diverged,
        blocks_flipped: 0,
        front: 0,
        speed: None,
        t_decided: None,
        arrival_times: vec![None; scenario.ladder.n()],
        integrator: config.kind.name().into(),
        dt: config.dt,
        arrival_error: None,
        force_evals: evals,
        message: Some(msg),
    }
}

/// Largest first step of a sweep's `auto`, τ: twice a single scene's
/// (`IntegratorConfig::auto`), since the check at half of it guards the
/// result; the returned run is at ≤ 0.25 τ, verified against 0.5 τ.
pub const SWEEP_AUTO_DT: f64 = 0.5;
/// Fraction of the stability bound 2/ω_max the first step may reach.
pub const SWEEP_AUTO_STABILITY_FRACTION: f64 = 0.8;

/// `auto`: velocity Verlet from [`SWEEP_AUTO_DT`] (or less, as ω_max
/// allows), halved until two successive runs agree (`sim::auto`'s rule,
/// with the stop rule).
fn verified(scenario: &Scenario, omega_max: f64, tolerance: f64, rule: &Rule) -> Result<RunResult> {
    let bound = SWEEP_AUTO_STABILITY_FRACTION * 2.0 / omega_max;
    let mut dt = if bound.is_finite() && bound > 0.0 {
        SWEEP_AUTO_DT.min(bound)
    } else {
        IntegratorConfig::auto(omega_max).dt
    };
    let mut total = 0;
    let mut last_error = String::new();
    let mut coarse = match until_decided(scenario, &verlet(dt), rule)? {
        Ok(c) => {
            total += c.1.force_evals;
            Some(c)
        }
        Err(m) => {
            last_error = m;
            None
        }
    };
    for _ in 0..MAX_HALVINGS {
        let config = verlet(0.5 * dt);
        let fine = match until_decided(scenario, &config, rule)? {
            Ok(f) => f,
            Err(m) => {
                last_error = m;
                dt *= 0.5;
                coarse = None;
                continue;
            }
        };
        total += fine.1.force_evals;
        if let Some((dc, tc)) = &coarse {
            let (df, tf) = &fine;
            let upto = dc.t_decided.min(df.t_decided);
            let difference = sim::auto::arrival_difference(
                &tc.arrival_times,
                &tf.arrival_times,
                upto,
                tolerance,
            );
            if dc.outcome == df.outcome && difference <= tolerance {
                return Ok(result(*df, tf, &config, Some(difference / 3.0), total));
            }
        }
        coarse = Some(fine);
        dt *= 0.5;
    }
    match coarse {
        None => Ok(diverged(scenario, &verlet(dt), last_error, total)),
        Some((d, traj)) => {
            // Kept, with the disagreement said: one hard point must not
            // sink a sweep of thousands.
            let mut r = result(d, &traj, &verlet(dt), None, total);
            r.message = Some(format!(
                "auto could not verify this run within {tolerance} τ down to dt = {dt} τ; \
                 its outcome may depend on the step"
            ));
            Ok(r)
        }
    }
}

fn verlet(dt: f64) -> IntegratorConfig {
    IntegratorConfig::fixed(IntegratorKind::Verlet, dt)
}
