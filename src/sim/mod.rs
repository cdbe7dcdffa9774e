//! Time integration of the ladder: the run loop, sampling at requested
//! times, divergence detection, and the scenes' initial conditions.

pub mod auto;
pub mod batch;
pub mod chain;
pub mod fused;
pub mod integrators;
#[cfg(target_arch = "x86_64")]
mod lanes;
pub mod observables;
pub mod protocol;
pub mod relax;
pub mod rhs;
mod simd;
pub mod step_bounds;
pub mod stepping;
pub mod waves;
pub mod window;

pub use integrators::{IntegratorConfig, IntegratorKind};
pub use protocol::{Drive, Piece, Protocol};
pub use relax::Start;
pub use rhs::{Rhs, State};
pub use stepping::{Isa, Stepping};

use crate::error::{Error, Result, num};
use crate::limits::{Limits, Resource};
use crate::model::ladder::itheta;
use crate::model::params::M;
use crate::model::{Ladder, Params};
use observables::{ArrivalDetector, kink_position};
use waves::{WaveTracker, Waves};

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
                "t_end must be a finite number >= 0, got {}",
                crate::error::num(t_end)
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

/// Refuses an integrator that cannot integrate the ladder's terms
/// (`model::media`): symplectic Euler and velocity Verlet kick with forces
/// of the positions only (their damping is the linear γ, folded into the
/// kick), so added mass (a mass matrix that depends on θ, and velocity
/// terms), quadratic drag and pin friction need a scheme that evaluates
/// a(q, v): explicit Euler, rk4 or dopri5 (`auto` picks rk4 for them).
/// Stiffer or tension-only links are forces of the positions: every
/// scheme takes them.
pub fn check_terms(ladder: &Ladder, config: &IntegratorConfig) -> Result<()> {
    let t = &ladder.terms;
    if !t.velocity_dependent()
        || !matches!(
            config.kind,
            IntegratorKind::SymplecticEuler | IntegratorKind::Verlet
        )
    {
        return Ok(());
    }
    let mut what = Vec::new();
    if t.added_mass != 0.0 || t.added_inertia != 0.0 {
        what.push("added mass (a mass matrix that turns with the block)");
    }
    if t.drag != 0.0 {
        what.push("quadratic drag");
    }
    if t.friction.is_some() {
        what.push("pin friction");
    }
    Err(Error::bad_input(format!(
        "integrator {} cannot integrate {}: its kick takes forces of the positions only; \
         use rk4, dopri5, explicit-euler or auto",
        config.kind.name(),
        what.join(", ")
    )))
}

/// `simulate` needs 0 < |α| < 90° (SPEC section 5).
/// α is read to 1e-9° (`Params::alpha_deg`), so a smaller |α| counts as 0.
pub fn check_simulable(params: &Params) -> Result<()> {
    let deg = params.alpha_deg();
    if deg.is_finite() && deg.abs() > 0.0 && deg.abs() < 90.0 {
        Ok(())
    } else {
        Err(Error::bad_input(format!(
            "alpha must satisfy 1e-9 <= |alpha| < 90 degrees for a simulation, got {}",
            crate::error::num(params.alpha.to_degrees())
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
    /// Every domain wall of the run as a wave, and block N's fate
    /// (`waves`, SPEC section 9).
    pub waves: Waves,
    /// State at the end of the run: at t_end, or at `t_final` where a stop
    /// rule ended it earlier ([`simulate_until`]).
    pub final_state: State,
    /// The time the run reached (t_end unless a stop rule ended it).
    pub t_final: f64,
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

    /// Stores a sample (the sink of [`simulate_with`]).
    fn push(&mut self, sample: &Sample, alpha: f64) {
        self.times.push(sample.t);
        self.states.push(sample.q.to_vec());
        self.velocities.push(sample.v.to_vec());
        self.kink_position.push(kink_position(sample.q, alpha));
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

/// The state at one sample time, as the run loop hands it to a sink.
#[derive(Debug, Clone, Copy)]
pub struct Sample<'a> {
    pub t: f64,
    /// Positions, in the model's layout [X, Y, θ per block].
    pub q: &'a [f64],
    /// Velocities, same layout.
    pub v: &'a [f64],
}

/// What a stop rule sees: the time reached, the arrival times so far and
/// the state.
#[derive(Debug, Clone, Copy)]
pub struct StopView<'a> {
    pub t: f64,
    pub arrivals: &'a [Option<f64>],
    pub ladder: &'a Ladder,
    pub q: &'a [f64],
    pub v: &'a [f64],
    /// The waves so far (`waves`).
    pub waves: &'a WaveTracker,
}

/// A stop rule: true once the run has decided what it was run for (a
/// sweep's outcome, SPEC section 7). Asked at every divergence check
/// (every 5 τ, at most 512 steps apart, and at every sample time and
/// drive corner).
pub type StopRule<'a> = dyn Fn(&StopView) -> bool + Sync + 'a;

/// The stop rule that never stops a run before its t_end.
pub fn run_to_end(_view: &StopView) -> bool {
    false
}

/// Whether the state at the end of a run proves the ladder at rest at a
/// linearly stable equilibrium (`theory::stability`, default tolerances),
/// not before the drive has ended.
pub fn proved_at_rest(ladder: &Ladder, protocol: &Protocol, t: f64, st: &State) -> bool {
    t >= protocol.drive_end()
        && crate::theory::stability::rest_proof(
            ladder,
            &st.q,
            &st.v,
            &crate::theory::stability::RestTolerances::default(),
        )
        .proved
}

/// Integrates `scenario` to its end, recording the state at `sample_times`
/// (each in [0, t_end]) and observing arrival times at every step.
/// A diverging run returns `Error::Diverged` naming the integrator, its
/// step and the time; no partial result escapes.
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
/// Within the caps in force ([`Limits::active`]).
pub fn simulate_observed(
    scenario: &Scenario,
    sample_times: &[f64],
    config: &IntegratorConfig,
    stepping: Stepping,
    progress: &(dyn Fn(f64) + Sync),
) -> Result<Trajectory> {
    let limits = Limits::active();
    simulate_limited(scenario, sample_times, config, stepping, &limits, progress)
}

/// The cost of a run, computed before it starts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cost {
    /// Steps of a fixed-step run (each interval between stops subdivided
    /// into steps of at most dt); for adaptive dopri5, the fewest it can
    /// take (steps of `DOPRI5_MAX_STEP`); it is bounded while it runs.
    pub steps: f64,
    /// Steps × N.
    pub block_steps: f64,
    /// Samples × N.
    pub block_samples: f64,
}

/// The cost of running `scenario` with `samples` sample times (after
/// deduplication) and `config`: refuses, before any work, a run past
/// `limits` (`Error::Limit`: samples × N, then steps × N) and a step that
/// cannot advance time (`Error::BadInput`, `limits::MAX_STEPS_PER_ULP_SPAN`;
/// checked before steps × N, as no cap can allow it).
pub fn check_cost(
    scenario: &Scenario,
    samples: usize,
    config: &IntegratorConfig,
    limits: &Limits,
) -> Result<Cost> {
    use crate::limits::{MAX_STEPS_PER_ULP_SPAN, count};
    let config = config.validated()?;
    let n = scenario.ladder.n();
    let t_end = scenario.t_end;
    limits.check_samples(samples as f64, n)?;
    let adaptive = config.kind == IntegratorKind::Dopri5 && config.rtol.is_some();
    let corners = scenario.protocol.drive().map_or(0, |d| d.corners().count());
    let intervals = (samples + corners + 1) as f64;
    let step = if adaptive {
        integrators::DOPRI5_MAX_STEP
    } else {
        config.dt
    };
    let steps = (t_end / step).ceil() + intervals;
    let cost = Cost {
        steps,
        block_steps: steps * n as f64,
        block_samples: samples as f64 * n as f64,
    };
    if !adaptive && t_end / config.dt > MAX_STEPS_PER_ULP_SPAN {
        return Err(Error::bad_input(format!(
            "dt = {} is too small for t_end = {}: each step must exceed the rounding of t \
             a thousandfold, so dt >= {} (or a shorter t_end)",
            num(config.dt),
            num(t_end),
            num(t_end / MAX_STEPS_PER_ULP_SPAN)
        )));
    }
    limits.check(Resource::BlockSteps, cost.block_steps, || {
        let least = if adaptive { "at least " } else { "" };
        format!(
            "{least}{} steps of dt = {} up to t_end = {}, times N = {n}",
            count(steps),
            num(step),
            num(t_end),
        )
    })?;
    Ok(cost)
}

/// As [`simulate_observed`], within `limits` (checked before the run by
/// [`check_cost`], and while it runs).
pub fn simulate_limited(
    scenario: &Scenario,
    sample_times: &[f64],
    config: &IntegratorConfig,
    stepping: Stepping,
    limits: &Limits,
    progress: &(dyn Fn(f64) + Sync),
) -> Result<Trajectory> {
    let alpha = scenario.ladder.params.alpha;
    let mut kept = Trajectory::unsampled(State::at_rest(Vec::new()), 0.0, Vec::new(), 0, 0);
    let mut traj = simulate_streaming(
        scenario,
        sample_times,
        config,
        stepping,
        &Hooks {
            stop: &run_to_end,
            progress,
            limits,
            // One flip launches one driven wave, whose arrival times the
            // arrival detector times exactly inside the fused kernel's
            // chunks (the paper's run stays at its ~50 ms; stepping one
            // step per call made it 6.6 times slower). With several flips
            // every later wall's sign changes are timed step by step.
            every_step: scenario.protocol.drive().is_some_and(|d| d.flips() > 1),
        },
        &mut |sample: &Sample| {
            kept.push(sample, alpha);
            Ok(())
        },
    )?;
    (traj.times, traj.states, traj.velocities, traj.kink_position) =
        (kept.times, kept.states, kept.velocities, kept.kink_position);
    Ok(traj)
}

/// As [`simulate_with`] without samples, ending the run early once `stop`
/// says so (t_end is then the cap): the single-run reference of
/// [`batch::simulate_many`], which gives the same trajectories bit for bit.
pub fn simulate_until(
    scenario: &Scenario,
    config: &IntegratorConfig,
    stepping: Stepping,
    stop: &StopRule,
) -> Result<Trajectory> {
    let limits = Limits::active();
    let hooks = Hooks {
        stop,
        progress: &|_| {},
        limits: &limits,
        every_step: false,
    };
    simulate_streaming(scenario, &[], config, stepping, &hooks, &mut |_| Ok(()))
}

/// What the run loop asks and tells at every divergence check.
pub struct Hooks<'a> {
    /// Ends the run once it says so (t_end is then the cap).
    pub stop: &'a StopRule<'a>,
    /// Told the simulated time at every check (every 5 τ, or 512 steps
    /// at most), after the check: for a progress bar.
    pub progress: &'a (dyn Fn(f64) + Sync),
    /// The caps the run must stay within (`limits`).
    pub limits: &'a Limits,
    /// Feed the wave tracker after every step (exact times of every sign
    /// change), not only at the checks (`waves`' module doc).
    pub every_step: bool,
}

/// The run loop. Hands the state at every sample time to `sink` as it
/// passes (memory stays proportional to N, however many samples: the
/// returned trajectory holds none) and ends at t_end or where
/// `hooks.stop` says. An error from `sink` ends the run with that error.
pub fn simulate_streaming(
    scenario: &Scenario,
    sample_times: &[f64],
    config: &IntegratorConfig,
    stepping: Stepping,
    hooks: &Hooks,
    sink: &mut dyn FnMut(&Sample) -> Result<()>,
) -> Result<Trajectory> {
    let config = config.validated()?;
    check_terms(&scenario.ladder, &config)?;
    // The fused and chain kernels compute the paper's forces only: a
    // ladder with any term of SPEC section 12 takes the portable path.
    let stepping = if scenario.ladder.terms.is_paper() {
        stepping
    } else {
        Stepping::Portable
    };
    let samples = sorted_samples(sample_times, scenario.t_end)?;
    let limits = hooks.limits;
    check_cost(scenario, samples.len(), &config, limits)?;
    let max_steps = limits.block_steps / scenario.ladder.n() as f64;
    let stops = stop_times(&samples, &scenario.protocol, scenario.t_end);
    let ladder = &scenario.ladder;
    let mut rhs = Rhs::new(ladder, &scenario.protocol, &scenario.initial.q);
    let mut st = scenario.initial.clone();
    rhs.constrain(0.0, &mut st.q, &mut st.v);
    let mut integrator = config.build(rhs.dof(), stepping);
    let mut watch = DivergenceWatch::new(ladder, &scenario.protocol, &config);
    let check_every = check_every(&config);
    let mut arrivals = ArrivalDetector::new(0.0, &st.q, &st.v);
    let mut tracker = WaveTracker::new(0.0, &st.q, &st.v);
    let mut steps = 0;
    let mut t = 0.0;
    let mut next_sample = 0;
    emit_due(&samples, &mut next_sample, t, &st, sink)?;
    'run: for &stop_at in &stops {
        while t < stop_at {
            let budget = if hooks.every_step {
                1
            } else {
                check_every - steps % check_every
            };
            let (t_new, taken) =
                integrator.advance_many(&mut rhs, &mut st, (t, stop_at), budget, &mut arrivals)?;
            if taken > 0 && t_new <= t {
                return Err(Error::failed(format!(
                    "time stopped advancing at t = {} τ ({}): the step is below the rounding of t",
                    num(t),
                    config.describe_step()
                )));
            }
            t = t_new;
            steps += taken;
            if hooks.every_step {
                tracker.observe(t, &st.q, &st.v, &arrivals.arrival);
            }
            if steps.is_multiple_of(check_every) {
                if !hooks.every_step {
                    tracker.observe(t, &st.q, &st.v, &arrivals.arrival);
                }
                watch.check(&rhs, &st, t)?;
                (hooks.progress)(t);
                if steps as f64 > max_steps {
                    return Err(Error::Limit(crate::limits::LimitExceeded {
                        resource: Resource::BlockSteps,
                        value: steps as f64 * ladder.n() as f64,
                        cap: limits.block_steps,
                        detail: format!(
                            "{} steps by t = {} of t_end = {} × N = {}, and counting",
                            steps,
                            num(t),
                            num(scenario.t_end),
                            ladder.n()
                        ),
                    }));
                }
                let view = StopView {
                    t,
                    arrivals: &arrivals.arrival,
                    ladder,
                    q: &st.q,
                    v: &st.v,
                    waves: &tracker,
                };
                if (hooks.stop)(&view) {
                    break 'run;
                }
            }
        }
        if !hooks.every_step {
            tracker.observe(t, &st.q, &st.v, &arrivals.arrival);
        }
        watch.check(&rhs, &st, t)?;
        emit_due(&samples, &mut next_sample, t, &st, sink)?;
        let view = StopView {
            t,
            arrivals: &arrivals.arrival,
            ladder,
            q: &st.q,
            v: &st.v,
            waves: &tracker,
        };
        if (hooks.stop)(&view) {
            break;
        }
    }
    let at_rest = proved_at_rest(ladder, &scenario.protocol, t, &st);
    let waves = tracker.finish(&st.q, at_rest);
    let mut traj = Trajectory::unsampled(st, t, arrivals.arrival, steps, rhs.force_evals);
    traj.waves = waves;
    Ok(traj)
}

impl Trajectory {
    /// A trajectory without samples.
    fn unsampled(
        final_state: State,
        t_final: f64,
        arrival_times: Vec<Option<f64>>,
        steps: u64,
        force_evals: u64,
    ) -> Self {
        Self {
            times: Vec::new(),
            states: Vec::new(),
            velocities: Vec::new(),
            kink_position: Vec::new(),
            arrival_times,
            waves: Waves::default(),
            final_state,
            t_final,
            steps,
            force_evals,
        }
    }
}

/// Hands `sink` the state for every sample time not after `t` not yet
/// handed over.
fn emit_due(
    samples: &[f64],
    next: &mut usize,
    t: f64,
    st: &State,
    sink: &mut dyn FnMut(&Sample) -> Result<()>,
) -> Result<()> {
    while *next < samples.len() && samples[*next] <= t {
        sink(&Sample {
            t: samples[*next],
            q: &st.q,
            v: &st.v,
        })?;
        *next += 1;
    }
    Ok(())
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
        let ladder = rhs.ladder;
        if !ladder.terms.is_paper() {
            return self.check_terms(rhs, st, t);
        }
        let elastic = ladder.elastic_energy(&st.q);
        if elastic > self.max_elastic {
            return Err(self.diverged(t, "the springs stretched beyond any physical state"));
        }
        if t >= self.drive_end {
            // `Rhs::mechanical_energy`, with the elastic part computed once.
            let gravity: f64 = st.q.iter().step_by(3).sum();
            let potential = elastic - M * ladder.params.gravity * gravity;
            let e = ladder.kinetic_energy(&st.v) + potential;
            self.undriven_min = self.undriven_min.min(e);
            if e > self.undriven_min + self.max_growth {
                return Err(self.diverged(t, "the energy grew while nothing drove the ladder"));
            }
        }
        Ok(())
    }

    /// [`DivergenceWatch::check`]'s energy tests for a ladder with terms:
    /// the links' elastic energy (per unit stiffness) and the kinetic
    /// energy with added mass.
    fn check_terms(&mut self, rhs: &Rhs, st: &State, t: f64) -> Result<()> {
        let terms = &rhs.ladder.terms;
        let elastic = terms.links.elastic_energy(rhs.ladder, &st.q);
        if elastic > self.max_elastic * terms.links.stiffness {
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

    fn diverged(&self, t: f64, what: &'static str) -> Error {
        Error::Diverged(Box::new(crate::error::Divergence {
            integrator: self.name,
            step: self.step.clone(),
            t,
            what,
        }))
    }
}
