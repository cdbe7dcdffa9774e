//! The points of a sweep: run each scene until the outcome is decided
//! (`outcome::Rule`), with the scene's integrator; `auto` is verified as
//! for a single scene (`sim::auto`): the run at dt is checked against one
//! at dt/2, both run until decided, and must agree on the outcome and on
//! every arrival time up to the earlier decision within the tolerance;
//! the step is halved until they do.
//!
//! [`run_points`] runs many points at once, in rounds: every point's next
//! integration (its first step, then each halving) is one job of the
//! round, and the jobs that share an integrator configuration and a rule
//! go through `sim::batch::simulate_many` together (one run per SIMD lane,
//! lanes refilled from a queue on every core); a group too small to fill
//! the lanes, such as [`run_point`]'s one point, runs one run at a time
//! through `sim::run` without samples. Both give the same results bit for bit:
//! the batch kernel reproduces the one-run trajectories exactly
//! (tests/integration/sweep.rs runs 30 points at once and each alone).

use super::outcome::{self, Decision, Outcome, Rule};
use crate::error::{Error, Result};
use crate::scene::Scene;
use crate::scene::sweep::SweepSpec;
use crate::sim::waves::Waves;
use crate::sim::{self, IntegratorConfig, IntegratorKind, Scenario, Trajectory};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Most halvings of the step `auto` makes for one point of a sweep (a
/// point still unverified at dt/16 is kept with a message: a sweep runs
/// thousands of points, each possibly to the cap).
pub const MAX_HALVINGS: u32 = 4;

/// What one run did.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunResult {
    pub outcome: Outcome,
    /// Of blocks 1..N − 1, those whose polarisation changed sign
    /// (`outcome::blocks_flipped`).
    pub blocks_flipped: usize,
    /// The last block the wave reached: blocks 1..=front all flipped,
    /// front ≤ N − 1 (block N is kept apart: `block_n_turned_at`).
    pub front: usize,
    /// When block N, the free bottom block, first turned, if it had by
    /// `t_decided` (τ). Before block N − 1's arrival: it fell over on its
    /// own and launched a wall of its own up the chain (at small |α|).
    #[serde(default)]
    pub block_n_turned_at: Option<f64>,
    /// Blocks per τ, least squares over blocks 3..N−1; `None` when fewer
    /// than three of them flipped or they flip in groups
    /// (`outcome::wave_speed`, the one definition of the wave speed).
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
    /// Every wave of the returned run and block N's fate (docs/sweeps.md); the
    /// outcome columns describe the chain's blocks from the top
    /// (the arrival times above), whichever wave flipped them.
    #[serde(default)]
    pub waves: Waves,
    /// What went wrong, for a diverged run.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub message: Option<String>,
}

/// The rule of `scene` (a single-run scene) under `spec`.
pub fn rule(scene: &Scene, spec: &SweepSpec) -> Rule {
    Rule {
        drive_end: scene.drive.end(),
        cap: spec.cap,
        tolerances: Default::default(),
    }
}

/// Runs the single-run `scene` (a point of the sweep) until decided.
/// Bad input is an error; a diverging integration is a `diverged` result.
/// One point alone is too few to fill the batch kernel's lanes: it runs
/// through `sim::run` without samples, the one-run path.
pub fn run_point(scene: &Scene, spec: &SweepSpec) -> Result<RunResult> {
    let mut results = run_points(std::slice::from_ref(scene), spec)?;
    Ok(results.remove(0))
}

fn diverged(scenario: &Scenario, config: &IntegratorConfig, msg: String, evals: u64) -> RunResult {
    RunResult {
        integrator: config.kind.name().into(),
        dt: config.dt,
        force_evals: evals,
        message: Some(msg),
        ..diverged_blank(scenario.ladder.n())
    }
}

/// Largest first step of a sweep's `auto`, τ: twice a single scene's
/// (`IntegratorConfig::auto`), since the check at half of it guards the
/// result; the returned run is at ≤ 0.25 τ, verified against 0.5 τ.
pub const SWEEP_AUTO_DT: f64 = 0.5;
/// Fraction of the stability bound 2/ω_max the first step may reach.
pub const SWEEP_AUTO_STABILITY_FRACTION: f64 = 0.8;

fn verlet(dt: f64) -> IntegratorConfig {
    IntegratorConfig::fixed(IntegratorKind::Verlet, dt)
}

/// How one point is integrated: a fixed configuration, or `auto` from a
/// first step.
#[derive(Debug, Clone, Copy)]
enum Method {
    Fixed(IntegratorConfig),
    Auto { dt: f64, tolerance: f64 },
}

/// One point ready to run.
struct Prepared {
    /// The scene's scenario, to the cap.
    scenario: Scenario,
    rule: Rule,
    method: Method,
    /// The scene's caps (`Scene::limits`).
    limits: crate::limits::Limits,
}

fn prepare(scene: &Scene, spec: &SweepSpec) -> Result<Prepared> {
    let rule = rule(scene, spec);
    let mut capped = scene.clone();
    capped.run.t_end = spec.cap;
    let scenario = capped.scenario()?;
    let method = match scene.run.fixed_config()? {
        Some(config) => Method::Fixed(config),
        None => {
            let omega_max = crate::scene::run::omega_max(&scenario)?;
            Method::Auto {
                dt: first_auto_dt(omega_max),
                tolerance: scene.run.tolerance,
            }
        }
    };
    Ok(Prepared {
        scenario,
        rule,
        method,
        limits: scene.limits,
    })
}

/// `verified`'s first step for a chain whose highest frequency is
/// `omega_max`.
fn first_auto_dt(omega_max: f64) -> f64 {
    let bound = SWEEP_AUTO_STABILITY_FRACTION * 2.0 / omega_max;
    if bound.is_finite() && bound > 0.0 {
        SWEEP_AUTO_DT.min(bound)
    } else {
        IntegratorConfig::auto(omega_max).dt
    }
}

/// An integration until decided, kept between rounds: its decision, the
/// arrival times and the force evaluations it took.
struct Decided {
    decision: Decision,
    arrival_times: Vec<Option<f64>>,
    force_evals: u64,
    waves: Waves,
}

/// One job of a round: point `point` integrated with `config`.
struct Job {
    point: usize,
    config: IntegratorConfig,
}

/// Runs the jobs of one round: those with the same configuration and rule
/// together through the batch kernel. Bad input is the outer error; a
/// diverging integration the inner one (its message).
fn round(points: &[Prepared], jobs: &[Job]) -> Result<Vec<std::result::Result<Decided, String>>> {
    let key = |j: &Job| {
        let c = &j.config;
        let r = &points[j.point].rule;
        (
            c.kind.name(),
            c.dt.to_bits(),
            c.rtol.map(f64::to_bits),
            [r.drive_end, r.cap].map(f64::to_bits),
        )
    };
    let mut groups: BTreeMap<_, Vec<usize>> = BTreeMap::new();
    for (k, job) in jobs.iter().enumerate() {
        groups.entry(key(job)).or_default().push(k);
    }
    // The groups side by side on every core (a group of one run, as each
    // N of a chain-length sweep is, would otherwise hold one core), the
    // longest chains first.
    let mut groups: Vec<Vec<usize>> = groups.into_values().collect();
    groups.sort_by_key(|m| std::cmp::Reverse(points[jobs[m[0]].point].scenario.ladder.n()));
    let tally = sim::tally::current();
    let done: Vec<Result<Vec<GroupRun>>> = groups
        .par_iter()
        .with_max_len(1)
        .map(|members| sim::tally::within(tally.clone(), || round_group(points, jobs, members)))
        .collect();
    let mut out: Vec<Option<std::result::Result<Decided, String>>> =
        jobs.iter().map(|_| None).collect();
    for group in done {
        for (k, run) in group? {
            out[k] = Some(run);
        }
    }
    Ok(out
        .into_iter()
        .map(|r| r.expect("every job belongs to one group"))
        .collect())
}

/// A job of a group (its index into a round's jobs) and how it ended.
type GroupRun = (usize, std::result::Result<Decided, String>);

/// The jobs `members` of one group of [`round`] (one configuration and
/// rule) through the batch kernel, with their indices into `jobs`.
fn round_group(points: &[Prepared], jobs: &[Job], members: &[usize]) -> Result<Vec<GroupRun>> {
    let first = &jobs[members[0]];
    let rule = points[first.point].rule;
    let scenarios: Vec<Scenario> = members
        .iter()
        .map(|&k| points[jobs[k].point].scenario.clone())
        .collect();
    // The rest proof only once the arrivals alone do not decide (it
    // returns at once while the ladder moves).
    let stop = |v: &sim::StopView| {
        rule.decide(v.arrivals, v.t, false).is_some()
            || (v.t >= rule.drive_end && rule.at_rest(v.ladder, v.q, v.v))
    };
    let options = sim::RunOptions::default()
        .limits(points[first.point].limits)
        .stop(&stop);
    let runs = sim::batch::simulate_many(&scenarios, &first.config, &options);
    let mut out = Vec::with_capacity(members.len());
    for (&k, run) in members.iter().zip(runs) {
        out.push((
            k,
            match run {
                Ok(traj) => Ok(decided(&rule, &points[jobs[k].point].scenario, traj)),
                Err(Error::Failed(msg)) => Err(msg),
                Err(Error::Diverged(d)) => Err(d.facts()),
                Err(e) => return Err(e),
            },
        ));
    }
    Ok(out)
}

/// The decision a run stopped on: propagation from its arrival times,
/// else the rest proof at the state it ended in, else `undecided` (it ran
/// to the cap).
fn decided(rule: &Rule, scenario: &Scenario, traj: Trajectory) -> Decided {
    let st = &traj.final_state;
    let at_rest = rule.at_rest(&scenario.ladder, &st.q, &st.v);
    let decision = rule
        .decide(&traj.arrival_times, traj.t_final, at_rest)
        .unwrap_or(Decision {
            outcome: Outcome::Undecided,
            t_decided: rule.cap,
        });
    Decided {
        decision,
        arrival_times: traj.arrival_times,
        force_evals: traj.force_evals,
        waves: traj.waves,
    }
}

/// Where a point stands between rounds of `auto` (the state of the loop
/// of `verified`).
struct AutoState {
    dt: f64,
    tolerance: f64,
    coarse: Option<Decided>,
    total: u64,
    last_error: String,
    halvings: u32,
}

/// Runs the single-run `scenes` (points of one sweep under `spec`) until
/// each is decided, many at once (see the module's doc); results in the
/// order of `scenes`, equal to [`run_point`]'s.
///
/// A point that cannot start (a relaxed start that finds no hanging
/// equilibrium: a failed run, not bad input) is a `failed` record with
/// the reason, and the other points run on.
pub fn run_points(scenes: &[Scene], spec: &SweepSpec) -> Result<Vec<RunResult>> {
    let prepared: Vec<Result<Prepared>> = scenes.par_iter().map(|s| prepare(s, spec)).collect();
    let mut results: Vec<Option<RunResult>> = scenes.iter().map(|_| None).collect();
    let mut points = Vec::with_capacity(scenes.len());
    let mut at = Vec::with_capacity(scenes.len());
    for (k, p) in prepared.into_iter().enumerate() {
        match p {
            Ok(p) => {
                points.push(p);
                at.push(k);
            }
            Err(e) if e.is_failed_run() => results[k] = Some(failed(&scenes[k], e.to_string())),
            Err(e) => return Err(e),
        }
    }
    for (k, r) in at.into_iter().zip(run_prepared(points)?) {
        results[k] = Some(r);
    }
    Ok(results
        .into_iter()
        .map(|r| r.expect("every point has a result"))
        .collect())
}

/// The record of a point that could not start: outcome `failed`, its
/// reason in the message.
fn failed(scene: &Scene, msg: String) -> RunResult {
    let integrator = scene.run.integrator.to_string();
    RunResult {
        outcome: Outcome::Failed,
        dt: scene.run.dt.filter(|_| integrator != "auto").unwrap_or(0.0),
        integrator,
        message: Some(msg),
        ..diverged_blank(scene.model.n)
    }
}

/// A record with nothing run: no arrival, no decision.
fn diverged_blank(n: usize) -> RunResult {
    RunResult {
        outcome: Outcome::Diverged,
        blocks_flipped: 0,
        front: 0,
        block_n_turned_at: None,
        speed: None,
        t_decided: None,
        arrival_times: vec![None; n],
        integrator: String::new(),
        dt: 0.0,
        arrival_error: None,
        force_evals: 0,
        waves: Waves::default(),
        message: None,
    }
}

/// Each point's result so far (`None`: not yet decided) and, for an
/// `auto` point, its verification's state.
type Progress = (Vec<Option<RunResult>>, Vec<Option<AutoState>>);

/// [`run_points`] for the points that started.
fn run_prepared(points: Vec<Prepared>) -> Result<Vec<RunResult>> {
    let (mut results, mut auto) = first_round(&points)?;
    // Rounds 1..: each unverified point's run at half its step.
    while halving_round(&points, &mut results, &mut auto)? {}
    finish_unverified(&points, &mut results, auto);
    Ok(results
        .into_iter()
        .map(|r| r.expect("every point has a result"))
        .collect())
}

/// Round 0: every point's first integration. A fixed-step point is then
/// decided; an `auto` point holds its coarse run for the next round.
fn first_round(points: &[Prepared]) -> Result<Progress> {
    let mut results: Vec<Option<RunResult>> = points.iter().map(|_| None).collect();
    let mut auto: Vec<Option<AutoState>> = points.iter().map(|_| None).collect();
    let jobs: Vec<Job> = points
        .iter()
        .enumerate()
        .map(|(point, p)| Job {
            point,
            config: match p.method {
                Method::Fixed(c) => c,
                Method::Auto { dt, .. } => verlet(dt),
            },
        })
        .collect();
    for (job, attempt) in jobs.iter().zip(round(points, &jobs)?) {
        let p = &points[job.point];
        match p.method {
            Method::Fixed(config) => {
                results[job.point] = Some(match attempt {
                    Ok(d) => from_decided(&d, &config, None, d.force_evals),
                    Err(msg) => diverged(&p.scenario, &config, msg, 0),
                });
            }
            Method::Auto { dt, tolerance } => {
                let mut state = AutoState {
                    dt,
                    tolerance,
                    coarse: None,
                    total: 0,
                    last_error: String::new(),
                    halvings: 0,
                };
                match attempt {
                    Ok(d) => {
                        state.total += d.force_evals;
                        state.coarse = Some(d);
                    }
                    Err(m) => state.last_error = m,
                }
                auto[job.point] = Some(state);
            }
        }
    }
    Ok((results, auto))
}

/// One round of `auto`: each point not yet verified (and with halvings
/// left) runs at half its step; a point whose two runs agree is decided.
/// Whether any point ran.
fn halving_round(
    points: &[Prepared],
    results: &mut [Option<RunResult>],
    auto: &mut [Option<AutoState>],
) -> Result<bool> {
    let jobs: Vec<Job> = auto
        .iter()
        .enumerate()
        .filter_map(|(point, a)| {
            let a = a.as_ref()?;
            (results[point].is_none() && a.halvings < MAX_HALVINGS).then(|| Job {
                point,
                config: verlet(0.5 * a.dt),
            })
        })
        .collect();
    if jobs.is_empty() {
        return Ok(false);
    }
    for (job, attempt) in jobs.iter().zip(round(points, &jobs)?) {
        let state = auto[job.point].as_mut().expect("an auto point");
        state.halvings += 1;
        match attempt {
            Ok(fine) => {
                if let Some(r) = compare_halves(state, fine, &job.config) {
                    results[job.point] = Some(r);
                }
            }
            Err(m) => {
                state.last_error = m;
                state.dt *= 0.5;
                state.coarse = None;
            }
        }
    }
    Ok(true)
}

/// `fine` (the run at half the step of `state`'s coarse run) against the
/// coarse run: the verified record when they agree (same outcome,
/// arrivals within the tolerance), else `None` with `fine` kept as the
/// next round's coarse run.
fn compare_halves(
    state: &mut AutoState,
    fine: Decided,
    config: &IntegratorConfig,
) -> Option<RunResult> {
    state.total += fine.force_evals;
    if let Some(coarse) = &state.coarse {
        let upto = coarse.decision.t_decided.min(fine.decision.t_decided);
        let difference = sim::auto::arrival_difference(
            &coarse.arrival_times,
            &fine.arrival_times,
            upto,
            state.tolerance,
        );
        if coarse.decision.outcome == fine.decision.outcome && difference <= state.tolerance {
            return Some(from_decided(
                &fine,
                config,
                Some(difference / 3.0),
                state.total,
            ));
        }
    }
    state.coarse = Some(fine);
    state.dt *= 0.5;
    None
}

/// The points `auto` could not verify, recorded as `verified` ends them.
fn finish_unverified(
    points: &[Prepared],
    results: &mut [Option<RunResult>],
    auto: Vec<Option<AutoState>>,
) {
    for (point, state) in auto.into_iter().enumerate() {
        let Some(state) = state else { continue };
        if results[point].is_some() {
            continue;
        }
        let config = verlet(state.dt);
        results[point] = Some(match &state.coarse {
            None => diverged(
                &points[point].scenario,
                &config,
                state.last_error,
                state.total,
            ),
            Some(d) => unverified(
                from_decided(d, &config, None, state.total),
                state.tolerance,
                state.dt,
            ),
        });
    }
}

/// The record of a decided run.
fn from_decided(
    d: &Decided,
    config: &IntegratorConfig,
    arrival_error: Option<f64>,
    force_evals: u64,
) -> RunResult {
    let (decision, arrival_times) = (d.decision, &d.arrival_times);
    // Arrivals after the decision belong to no outcome: drop them, so the
    // record does not depend on how long after it the run was stopped.
    let arrivals: Vec<Option<f64>> = arrival_times
        .iter()
        .map(|a| a.filter(|&t| t <= decision.t_decided))
        .collect();
    RunResult {
        outcome: outcome::of_driven_wave(decision.outcome, &d.waves),
        blocks_flipped: outcome::blocks_flipped(&arrivals),
        front: outcome::front(&arrivals),
        block_n_turned_at: outcome::block_n_turned_at(&arrivals),
        speed: outcome::wave_speed(&arrivals),
        t_decided: Some(decision.t_decided),
        arrival_times: arrivals,
        integrator: config.kind.name().into(),
        dt: config.dt,
        arrival_error,
        force_evals,
        waves: d.waves.clone(),
        message: None,
    }
}

/// `r`, kept with the disagreement said: one hard point must not sink a
/// sweep of thousands.
fn unverified(mut r: RunResult, tolerance: f64, dt: f64) -> RunResult {
    r.message = Some(format!(
        "auto could not verify this run within {tolerance} τ down to dt = {dt} τ; \
         its outcome may depend on the step"
    ));
    r
}
