//! Time integration of the ladder: the run loop, sampling at requested
//! times, divergence detection, and the scenes' initial conditions.

pub mod auto;
pub mod fused;
pub mod integrators;
pub mod observables;
pub mod protocol;
pub mod rhs;
mod until;

pub use fused::{Isa, Stepping};
pub use integrators::{IntegratorConfig, IntegratorKind};
pub use protocol::{Drive, Piece, Protocol};
pub use rhs::{Rhs, State};
pub use until::{StopRule, simulate_until};

use crate::error::{Error, Result};
use crate::model::ladder::itheta;
use crate::model::{Ladder, Params};
use observables::{ArrivalDetector, kink_position};

/// The paper's drive time T_d = 1000 τ (10^5 steps of 0.01).
pub const PAPER_DRIVE_TIME: f64 = 1000.0;

/// What to simulate: a model, what happens to block 1, a start and an end.
#[derive(Debug, Clone)]
pub struct Scenario {
    pub ladder: Ladder,
    pub protocol: Protocol,
    pub initial: State,
    pub t_end: f64,
}

impl Scenario {
    /// The kink (α > 0) or antikink (α < 0) scene of SPEC section 1: start at
    /// rest in the ground state of sign α, not pre-relaxed; block 1 flips
    /// α → −α over [0, T_d].
    pub fn single_flip(params: Params, t_d: f64, t_end: f64) -> Result<Self> {
        check_simulable(&params)?;
        Self::with_drive(params, Drive::single_flip(params.alpha, t_d)?, t_end)
    }

    /// Ground-state start with an arbitrary drive of block 1.
    pub fn with_drive(params: Params, drive: Drive, t_end: f64) -> Result<Self> {
        check_simulable(&params)?;
        if !(t_end.is_finite() && t_end >= 0.0) {
            return Err(Error::bad_input(format!(
                "t_end must be a finite number >= 0, got {t_end}"
            )));
        }
        let ladder = Ladder::new(params);
        let initial = State::at_rest(ladder.ground_state());
        Ok(Self {
            ladder,
            protocol: Protocol::Driven(drive),
            initial,
            t_end,
        })
    }
}

/// `simulate` needs 0 < |α| < 90° (SPEC section 5).
pub fn check_simulable(params: &Params) -> Result<()> {
    let deg = params.alpha_deg();
    if deg.is_finite() && deg.abs() > 0.0 && deg.abs() < 90.0 {
        Ok(())
    } else {
        Err(Error::bad_input(format!(
            "alpha must satisfy 0 < |alpha| < 90 degrees for a simulation, got {deg}"
        )))
    }
}

/// The result of a run: states at the sample times, observables and cost.
#[derive(Debug, Clone)]
pub struct Trajectory {
    /// Sample times (sorted, within [0, t_end]).
    pub times: Vec<f64>,
    /// Positions q at each sample time.
    pub states: Vec<Vec<f64>>,
    /// Velocities at each sample time.
    pub velocities: Vec<Vec<f64>>,
    /// Kink position (blocks flipped, see `observables::kink_position`) at each sample.
    pub kink_position: Vec<f64>,
    /// Arrival time per block: the first sign change of its polarisation
    /// sin θ_n (SPEC section 1), `None` where it never flipped.
    pub arrival_times: Vec<Option<f64>>,
    /// State at t_end.
    pub final_state: State,
    pub steps: u64,
    pub force_evals: u64,
}

impl Trajectory {
    /// θ_n at t_end, in degrees, wrapped to (−180°, 180°] (SPEC section 1).
    pub fn final_theta_deg(&self) -> Vec<f64> {
        observables::angles_deg(&self.final_state.q)
    }

    /// θ_n at t_end, in degrees, as integrated (not wrapped).
    pub fn final_theta_deg_unwrapped(&self) -> Vec<f64> {
        observables::angles_deg_unwrapped(&self.final_state.q)
    }

    /// Records the state for every sample time not after `t` not yet recorded.
    fn record_due(&mut self, samples: &[f64], next: &mut usize, t: f64, st: &State, alpha: f64) {
        while *next < samples.len() && samples[*next] <= t {
            self.times.push(samples[*next]);
            self.states.push(st.q.clone());
            self.velocities.push(st.v.clone());
            self.kink_position.push(kink_position(&st.q, alpha));
            *next += 1;
        }
    }

    /// θ_n(t) of block `i` at every sample.
    pub fn theta_series(&self, i: usize) -> Vec<f64> {
        self.states.iter().map(|q| q[itheta(i)]).collect()
    }
}

/// How often, in τ, the run loop looks for divergence (every sample time
/// and drive corner is checked as well): often enough to catch the
/// transient stretches of a run at its stability limit whatever its step.
const CHECK_INTERVAL: f64 = 5.0;
/// The most steps between two checks (the fused stepper's batch).
const CHECK_MAX_STEPS: u64 = 512;

/// Steps between divergence checks: [`CHECK_INTERVAL`] in steps of `dt`
/// (64 for adaptive dopri5, whose steps vary), at least 1 and at most
/// [`CHECK_MAX_STEPS`].
fn check_every(config: &IntegratorConfig) -> u64 {
    if config.kind == IntegratorKind::Dopri5 && config.rtol.is_some() {
        return 64;
    }
    ((CHECK_INTERVAL / config.dt).ceil() as u64).clamp(1, CHECK_MAX_STEPS)
}
/// Runaway thresholds: more than four turns of any block, or an elastic
/// energy beyond one k s² per spring (a stretch of about 1.4 s everywhere).
const MAX_TURNS: f64 = 4.0;
/// Undriven energy growth, per spring, treated as a runaway.
const MAX_UNDRIVEN_GROWTH: f64 = 1e-2;

/// Integrates `scenario` to its end, recording the state at `sample_times`
/// (each in [0, t_end]) and observing arrival times at every step.
/// A diverging run returns `Error::Failed` naming the integrator, its step
/// and the time; no partial result escapes.
pub fn simulate(
    scenario: &Scenario,
    sample_times: &[f64],
    config: &IntegratorConfig,
) -> Result<Trajectory> {
    simulate_with(scenario, sample_times, config, Stepping::Fastest)
}

/// As [`simulate`], with symplectic Euler's steps taken as `stepping`
/// says: every choice gives the same trajectory bit for bit (the portable
/// path is the reference of the fused kernels and the baseline of their
/// benchmark).
pub fn simulate_with(
    scenario: &Scenario,
    sample_times: &[f64],
    config: &IntegratorConfig,
    stepping: Stepping,
) -> Result<Trajectory> {
    simulate_observed(scenario, sample_times, config, stepping, &|_| {})
}

/// As [`simulate_with`], telling `progress` the simulated time at every
/// divergence check (every 5 τ, or 512 steps at most): for a progress bar.
pub fn simulate_observed(
    scenario: &Scenario,
    sample_times: &[f64],
    config: &IntegratorConfig,
    stepping: Stepping,
    progress: &(dyn Fn(f64) + Sync),
) -> Result<Trajectory> {
    let config = config.validated()?;
    let samples = sorted_samples(sample_times, scenario.t_end)?;
    let stops = stop_times(&samples, &scenario.protocol, scenario.t_end);
    let ladder = &scenario.ladder;
    let mut rhs = Rhs::new(ladder, &scenario.protocol, &scenario.initial.q);
    let mut st = scenario.initial.clone();
    rhs.constrain(0.0, &mut st.q, &mut st.v);
    let mut integrator = config.build(rhs.dof(), stepping);
    let mut watch = DivergenceWatch::new(ladder, &scenario.protocol, &config);
    let check_every = check_every(&config);
    let mut arrivals = ArrivalDetector::new(0.0, &st.q, &st.v);
    let mut traj = Trajectory {
        times: Vec::with_capacity(samples.len()),
        states: Vec::with_capacity(samples.len()),
        velocities: Vec::with_capacity(samples.len()),
        kink_position: Vec::with_capacity(samples.len()),
        arrival_times: Vec::new(),
        final_state: st.clone(),
        steps: 0,
        force_evals: 0,
    };
    let mut t = 0.0;
    let mut next_sample = 0;
    traj.record_due(&samples, &mut next_sample, t, &st, ladder.params.alpha);
    for &stop in &stops {
        while t < stop {
            let budget = check_every - traj.steps % check_every;
            let (t_new, taken) =
                integrator.advance_many(&mut rhs, &mut st, (t, stop), budget, &mut arrivals)?;
            t = t_new;
            traj.steps += taken;
            if traj.steps.is_multiple_of(check_every) {
                watch.check(&rhs, &st, t)?;
                progress(t);
            }
        }
        watch.check(&rhs, &st, t)?;
        traj.record_due(&samples, &mut next_sample, t, &st, ladder.params.alpha);
    }
    traj.arrival_times = arrivals.arrival;
    traj.final_state = st;
    traj.force_evals = rhs.force_evals;
    Ok(traj)
}

/// Sample times sorted and deduplicated; each must lie in [0, t_end].
fn sorted_samples(sample_times: &[f64], t_end: f64) -> Result<Vec<f64>> {
    if let Some(bad) = sample_times
        .iter()
        .find(|t| !(t.is_finite() && **t >= 0.0 && **t <= t_end))
    {
        return Err(Error::bad_input(format!(
            "sample time {bad} lies outside [0, t_end = {t_end}]"
        )));
    }
    let mut s = sample_times.to_vec();
    s.sort_by(f64::total_cmp);
    s.dedup();
    Ok(s)
}

/// Every time the integrator must land on: samples, drive corners, t_end.
fn stop_times(samples: &[f64], protocol: &Protocol, t_end: f64) -> Vec<f64> {
    let mut stops: Vec<f64> = samples.to_vec();
    if let Some(d) = protocol.drive() {
        stops.extend(d.corners().filter(|&c| c > 0.0 && c < t_end));
    }
    stops.push(t_end);
    stops.retain(|&t| t > 0.0);
    stops.sort_by(f64::total_cmp);
    stops.dedup();
    stops
}

/// Detects a run that has left the physics: non-finite numbers, runaway
/// angles or stretches, or mechanical energy growing while nothing drives.
struct DivergenceWatch {
    name: &'static str,
    step: String,
    drive_end: f64,
    max_elastic: f64,
    max_growth: f64,
    undriven_min: f64,
}

impl DivergenceWatch {
    fn new(ladder: &Ladder, protocol: &Protocol, config: &IntegratorConfig) -> Self {
        let springs = 2.0 * (ladder.n() - 1) as f64;
        Self {
            name: config.kind.name(),
            step: config.describe_step(),
            drive_end: protocol.drive_end(),
            max_elastic: springs,
            max_growth: MAX_UNDRIVEN_GROWTH * springs,
            undriven_min: f64::INFINITY,
        }
    }

    fn check(&mut self, rhs: &Rhs, st: &State, t: f64) -> Result<()> {
        let finite = st.q.iter().chain(&st.v).all(|x| x.is_finite());
        if !finite {
            return Err(self.diverged(t, "the state became NaN or infinite"));
        }
        let max_theta = (0..rhs.ladder.n())
            .map(|i| st.q[itheta(i)].abs())
            .fold(0.0, f64::max);
        if max_theta > MAX_TURNS * std::f64::consts::TAU {
            return Err(self.diverged(t, "a block turned more than four times"));
        }
        let elastic = rhs.ladder.elastic_energy(&st.q);
        if elastic > self.max_elastic {
            return Err(self.diverged(t, "the springs stretched beyond any physical state"));
        }
        if t >= self.drive_end {
            let e = rhs.mechanical_energy(st);
            self.undriven_min = self.undriven_min.min(e);
            if e > self.undriven_min + self.max_growth {
                return Err(self.diverged(t, "the energy grew while nothing drove the ladder"));
            }
        }
        Ok(())
    }

    fn diverged(&self, t: f64, what: &str) -> Error {
        Error::failed(format!(
            "{} diverged at t = {t:.2} τ ({}): {what}; hint: use a smaller --dt or a stable \
             integrator such as symplectic-euler, verlet or dopri5",
            self.name, self.step
        ))
    }
}
