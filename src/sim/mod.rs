//! Time integration of the ladder: the run loop, sampling at requested
//! times, divergence detection, and the scenes' initial conditions.

pub mod auto;
pub mod batch;
mod between;
pub mod budget;
pub mod chain;
pub mod cost;
mod divergence;
pub mod fused;
pub mod impacts;
pub mod integrators;
#[cfg(target_arch = "x86_64")]
mod lanes;
pub mod observables;
pub mod protocol;
pub mod relax;
pub mod rhs;
pub mod run_options;
mod samples;
mod simd;
pub mod speed;
pub mod step_bounds;
pub mod stepping;
pub mod strap;
mod tableau;
pub mod tally;
pub mod taut;
pub mod terms_rk4;
pub mod trajectory;
pub mod waves;
pub mod window;

use divergence::DivergenceWatch;
pub use integrators::{IntegratorConfig, IntegratorKind};
pub use protocol::{Drive, Piece, Protocol};
pub use relax::Start;
pub use rhs::{Rhs, State};
pub use run_options::{RunOptions, run_to_end};
pub use stepping::{Isa, Stepping};
pub use trajectory::{Energies, Trajectory};

use crate::error::{Error, Result, num};
use crate::limits::{Limits, Resource};
use crate::model::{Ladder, Params};
use observables::ArrivalDetector;
use samples::{emit_due, sorted_samples, stop_times};
use waves::WaveTracker;

/// The paper's drive time T_d = 1000 τ (10^5 steps of 0.01), the
/// parameter table's default (`model::table`).
pub const PAPER_DRIVE_TIME: f64 = crate::model::Param::DriveTime.default_value();

/// What to simulate: a model, what happens to block 1, a start and an end.
#[derive(Debug, Clone)]
pub struct Scenario {
    pub ladder: Ladder,
    pub protocol: Protocol,
    pub initial: State,
    pub t_end: f64,
}

impl Scenario {
    /// The kink (α > 0) or antikink (α < 0) scene of docs/model.md: start at
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

impl Scenario {
    /// The toy as built (`model::built`) at rest in its hanging column
    /// (the ground state of α = ±90°, which ribbons allow), block 1
    /// driven by `drive`.
    pub fn as_built(
        params: Params,
        drive: Drive,
        t_end: f64,
        terms: crate::model::media::Terms,
        built: crate::model::built::AsBuilt,
    ) -> Result<Self> {
        if !(t_end.is_finite() && t_end >= 0.0) {
            return Err(Error::bad_input(format!(
                "t_end must be a finite number >= 0, got {}",
                crate::error::num(t_end)
            )));
        }
        let ladder = Ladder::new(params).with_terms(terms).with_built(built);
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
    check_inextensible(ladder, config)?;
    check_contact_step(ladder, config)?;
    let t = &ladder.terms;
    if !ladder.velocity_dependent()
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
    if ladder.built.is_some_and(|b| b.ribbons.damping != 0.0) {
        what.push("the ribbons' dashpots");
    }
    if ladder.built.is_some_and(|b| b.contact.is_some()) {
        what.push("contact between blocks (a dashpot and friction)");
    }
    Err(Error::bad_input(format!(
        "integrator {} cannot integrate {}: its kick takes forces of the positions only; \
         use rk4, dopri5, explicit-euler or auto",
        config.kind.name(),
        what.join(", ")
    )))
}

/// Inextensible ribbons act only through impulses between steps
/// (`sim::taut`): `moreau` takes them, and takes nothing else.
fn check_inextensible(ladder: &Ladder, config: &IntegratorConfig) -> Result<()> {
    let inextensible = ladder.built.is_some_and(|b| b.ribbons.inextensible);
    let moreau = config.kind == IntegratorKind::Moreau;
    if inextensible && !moreau {
        return Err(Error::bad_input(format!(
            "integrator {} cannot integrate inextensible ribbons: they pull only by \
             impulses between steps; use moreau",
            config.kind.name()
        )));
    }
    if moreau && !inextensible {
        return Err(Error::bad_input(
            "integrator moreau cannot integrate a ladder without inextensible ribbons: it \
             steps only their impulses (stiffness = \"inextensible\" with ribbons); use rk4, \
             dopri5 or auto"
                .to_string(),
        ));
    }
    Ok(())
}

/// A fixed RK4 step longer than the contact's stable step
/// (`model::contact::Contact::rk4_step_bound`) is refused before the run:
/// every landing corner would ring up until the blocks pass through one
/// another (docs/experiments.md, "The toy in air").
fn check_contact_step(ladder: &Ladder, config: &IntegratorConfig) -> Result<()> {
    let Some(b) = ladder.built else { return Ok(()) };
    let Some(c) = b.contact else { return Ok(()) };
    let bound = c.rk4_step_bound(ladder.blocks(), &b.ribbons.outline);
    if config.kind == IntegratorKind::Rk4 && config.dt > bound {
        return Err(Error::bad_input(format!(
            "dt = {} is longer than the contact's stable step for rk4, 2√2/ω_c = {bound:.4} τ \
             (ω_c = √(k_c/m_eff) = {:.1} per τ at k_c = {}): a corner landing on a face would \
             ring up until the blocks pass through each other; use dt <= {bound:.4} or auto",
            num(config.dt),
            c.frequency(ladder.blocks(), &b.ribbons.outline),
            num(c.stiffness),
        )));
    }
    Ok(())
}

/// `simulate` needs 0 < |α| < 90° (README.md).
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
/// The state at one sample time, as the run loop hands it to a sink.
#[derive(Debug, Clone, Copy)]
pub struct Sample<'a> {
    pub t: f64,
    /// Positions, in the model's layout [X, Y, θ per block].
    pub q: &'a [f64],
    /// Velocities, same layout.
    pub v: &'a [f64],
    /// The energy dissipated from t = 0 to this sample, in units of k s²,
    /// where the run records it (`RunOptions::dissipation`).
    pub dissipated: Option<f64>,
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
/// sweep's outcome, docs/sweeps.md). Asked at every divergence check
/// (every 5 τ, at most 512 steps apart, and at every sample time and
/// drive corner).
pub type StopRule<'a> = dyn Fn(&StopView) -> bool + Sync + 'a;

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

/// Integrates `scenario` to its end with the default [`RunOptions`],
/// recording the state at `sample_times` (each in [0, t_end]) and
/// observing arrival times at every step: [`run`] with
/// `RunOptions::default()`. A diverging run returns `Error::Diverged`
/// naming the integrator, its step and the time; no partial result escapes.
pub fn simulate(
    scenario: &Scenario,
    sample_times: &[f64],
    config: &IntegratorConfig,
) -> Result<Trajectory> {
    run(scenario, sample_times, config, &RunOptions::default())
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
    /// What one block-step of this run's force path costs in block-steps
    /// of the paper's model by Verlet (`cost::weight`).
    pub weight: f64,
    /// Steps × N × weight: what the cap on steps × N counts.
    pub equivalent: f64,
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
    check_cost_stepped(scenario, samples, config, limits, Stepping::Fastest)
}

/// [`check_cost`] of a run stepped as `stepping` says (its force path's
/// weight, `cost::Path`).
pub fn check_cost_stepped(
    scenario: &Scenario,
    samples: usize,
    config: &IntegratorConfig,
    limits: &Limits,
    stepping: Stepping,
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
    let path = cost::Path::of(&scenario.ladder, config.kind, stepping);
    let weight = path.weight();
    let cost = Cost {
        steps,
        block_steps: steps * n as f64,
        block_samples: samples as f64 * n as f64,
        weight,
        equivalent: steps * n as f64 * weight,
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
    limits.check(Resource::BlockSteps, cost.equivalent, || {
        let least = if adaptive { "at least " } else { "" };
        format!(
            "{least}{} steps of dt = {} up to t_end = {}, times N = {n}{}",
            count(steps),
            num(step),
            crate::numfmt::brief(t_end),
            cost::weighed(&path, cost.equivalent)
        )
    })?;
    Ok(cost)
}

/// Bytes a run kept per block and sample: its positions and velocities
/// (3 + 3 numbers of 8 bytes).
pub const SAMPLE_BYTES_PER_BLOCK: u64 = 48;
/// What a run needs beside its samples (its state, forces, buffers):
/// counted with them when the samples' memory is asked for.
const WORKING_BYTES: u64 = 64 << 20;
/// Samples of fewer bytes than this are not asked for ahead.
const SMALL_SAMPLES: u64 = 16 << 20;

/// Refuses, before the run, samples that the process could not hold:
/// their bytes (and the run's working memory) are asked of the allocator
/// as one reservation (address space only: no page is touched) and given
/// back at once. So a process under an address-space limit (RLIMIT_AS,
/// `ulimit -v`) gets a failed run with a hint instead of an abort when a
/// sample is stored halfway through.
pub fn ensure_memory(samples: usize, n: usize) -> Result<()> {
    reserve(samples, n, WORKING_BYTES)
}

/// [`ensure_memory`] with `beside` bytes of working memory.
fn reserve(samples: usize, n: usize, beside: u64) -> Result<()> {
    let needed = (samples as u64)
        .saturating_mul(n as u64)
        .saturating_mul(SAMPLE_BYTES_PER_BLOCK);
    if needed < SMALL_SAMPLES {
        return Ok(());
    }
    let total = needed.saturating_add(beside);
    let refused = || {
        Error::failed(format!(
            "not enough memory for the run: {} samples × N = {n} take {} MB, which this process \
             cannot allocate; hint: keep fewer samples (a larger sample interval or fewer sample \
             times), fewer blocks, or give the process more memory (ulimit -v)",
            samples,
            num(needed as f64 / 1e6)
        ))
    };
    let bytes = usize::try_from(total).map_err(|_| refused())?;
    let mut probe: Vec<u8> = Vec::new();
    probe.try_reserve_exact(bytes).map_err(|_| refused())?;
    Ok(())
}

/// Integrates `scenario` as `options` say, keeping the state at
/// `sample_times` (each in [0, t_end]; sorted and deduplicated) in the
/// returned trajectory: [`run_streaming`] with a sink that keeps every
/// sample. Within `options.limits` (checked before the run by
/// [`check_cost`], and while it runs).
pub fn run(
    scenario: &Scenario,
    sample_times: &[f64],
    config: &IntegratorConfig,
    options: &RunOptions,
) -> Result<Trajectory> {
    let alpha = scenario.ladder.params.alpha;
    let (count, n) = (sample_times.len(), scenario.ladder.n());
    let mut asked = false;
    let mut kept = Trajectory::unsampled(State::at_rest(Vec::new()), 0.0, Vec::new(), 0, 0);
    let mut traj = run_streaming(scenario, sample_times, config, options, &mut |sample| {
        // The samples' memory, asked for at the first one: after every
        // check of the run (its caps refuse first), with the run's own
        // buffers already allocated.
        if !asked {
            asked = true;
            reserve(count, n, 0)?;
        }
        kept.push(sample, alpha);
        Ok(())
    })?;
    (
        traj.times,
        traj.states,
        traj.velocities,
        traj.kink_position,
        traj.dissipated,
    ) = (
        kept.times,
        kept.states,
        kept.velocities,
        kept.kink_position,
        kept.dissipated,
    );
    Ok(traj)
}

/// The run loop. Hands the state at every sample time to `sink` as it
/// passes (memory stays proportional to N, however many samples: the
/// returned trajectory holds none) and ends at t_end or where
/// `options.stop` says. An error from `sink` ends the run with that error.
///
/// Over 80 lines on purpose: one loop over the stop times with its checks
/// inline (divergence, progress, cap, stop rule), the hot path, where a
/// split would pass the integrator, the state, the detectors and the watch
/// from call to call; its prelude and its errors are functions.
pub fn run_streaming(
    scenario: &Scenario,
    sample_times: &[f64],
    config: &IntegratorConfig,
    options: &RunOptions,
    sink: &mut dyn FnMut(&Sample) -> Result<()>,
) -> Result<Trajectory> {
    let config = config.validated()?;
    check_terms(&scenario.ladder, &config)?;
    let stepping = stepping_for(scenario, options);
    let samples = sorted_samples(sample_times, scenario.t_end)?;
    let limits = &options.limits;
    let cost = check_cost_stepped(scenario, samples.len(), &config, limits, stepping)?;
    let every_step = steps_one_by_one(scenario, options);
    // The cap in this path's own steps (`cost::weight`).
    let max_steps = limits.block_steps / (scenario.ladder.n() as f64 * cost.weight);
    // Samples between steps: the stops are the drive's corners and t_end.
    let between = between::wanted(scenario, options);
    let stop_at_samples: &[f64] = if between { &[] } else { &samples };
    let stops = stop_times(stop_at_samples, &scenario.protocol, scenario.t_end);
    let ladder = &scenario.ladder;
    let mut rhs = Rhs::new(ladder, &scenario.protocol, &scenario.initial.q);
    let mut st = scenario.initial.clone();
    rhs.constrain(0.0, &mut st.q, &mut st.v);
    // The energy budget's E at the start, where the run keeps it.
    let e0 = budget::kept(ladder, options.budget).then(|| {
        rhs.keep_powers();
        budget::energy(ladder, &scenario.protocol, (&st.q, &st.v))
    });
    // A fluid's terms take RK4's fused path (`terms_rk4`) where it applies.
    let kernels = scenario.ladder.velocity_dependent();
    let mut integrator = config.build(rhs.dof(), if kernels { options.stepping } else { stepping });
    let mut watch = DivergenceWatch::new(ladder, &scenario.protocol, &config);
    let check_every = check_every(&config);
    let mut arrivals = ArrivalDetector::new(0.0, &st.q, &st.v);
    let mut tracker = WaveTracker::new(0.0, &st.q, &st.v);
    // Blocks that may touch: every step is watched for impacts.
    let mut impacts = impacts::ImpactWatch::new(ladder, 0.0, &st.q, &st.v);
    let mut steps = 0;
    let mut t = 0.0;
    let mut next_sample = 0;
    let mut dissipated = Dissipated::new(ladder, options.dissipation, &st);
    let mut dense = between.then(|| between::Between::new(&st));
    // There a fixed step keeps the grid k·dt, whatever t_end (`stepping::Grid`).
    let adaptive = config.kind == IntegratorKind::Dopri5 && config.rtol.is_some();
    let mut grid = (between && !adaptive).then(|| stepping::Grid::new(config.dt));
    // The stop rule, asked at every check and at every stop time.
    let stop_here = |t, st: &State, arrivals: &ArrivalDetector, waves: &WaveTracker| {
        (options.stop)(&StopView {
            t,
            arrivals: &arrivals.arrival,
            ladder,
            q: &st.q,
            v: &st.v,
            waves,
        })
    };
    emit_due(&samples, &mut next_sample, t, &st, dissipated.total, sink)?;
    'run: for &stop_at in &stops {
        while t < stop_at {
            let budget = if every_step || impacts.is_some() || dense.is_some() {
                1
            } else {
                check_every - steps % check_every
            };
            // Only a step that may reach a sample needs its start kept.
            let due = samples.get(next_sample).is_some_and(|&s| s <= stop_at);
            if let Some(d) = dense.as_mut().filter(|_| due) {
                d.start(t, &st, dissipated.total);
            }
            let to = grid.as_mut().map_or(stop_at, |g| g.target(t, stop_at));
            let (t_new, taken) =
                integrator.advance_many(&mut rhs, &mut st, (t, to), budget, &mut arrivals)?;
            if taken > 0 && t_new <= t {
                return Err(stalled(t, &config));
            }
            dissipated.step(&st, t_new - t);
            if let Some(d) = dense.as_mut().filter(|_| due) {
                let now = (t_new, &st, dissipated.total);
                d.emit((&samples, &mut next_sample), now, &rhs, sink)?;
            }
            if let Some(w) = impacts.as_mut() {
                w.observe(t_new, &st.q, &st.v);
            }
            t = t_new;
            steps += taken;
            if every_step {
                tracker.observe(t, &st.q, &st.v, &arrivals.arrival);
            }
            if steps.is_multiple_of(check_every) {
                if !every_step {
                    tracker.observe(t, &st.q, &st.v, &arrivals.arrival);
                }
                watch.check(&rhs, &st, t)?;
                (options.progress)(t);
                if steps as f64 > max_steps {
                    let path = cost::Path::of(ladder, config.kind, stepping);
                    return Err(over_cap(scenario, &path, cost.weight, steps, t, limits));
                }
                if stop_here(t, &st, &arrivals, &tracker) {
                    break 'run;
                }
            }
        }
        if !every_step {
            tracker.observe(t, &st.q, &st.v, &arrivals.arrival);
        }
        watch.check(&rhs, &st, t)?;
        emit_due(&samples, &mut next_sample, t, &st, dissipated.total, sink)?;
        if stop_here(t, &st, &arrivals, &tracker) {
            break;
        }
    }
    let at_rest = proved_at_rest(ladder, &scenario.protocol, t, &st);
    let waves = tracker.finish(&st.q, at_rest);
    let e1 = budget::energy(ladder, &scenario.protocol, (&st.q, &st.v));
    let budget = e0.and_then(|e0| Some(budget::Budget::new(integrator.budget()?, e1 - e0)));
    let mut traj = Trajectory::finished(st, t, arrivals.arrival, steps, rhs.force_evals);
    traj.waves = waves;
    traj.impacts = impacts.map(|w| w.impacts);
    traj.budget = budget;
    Ok(traj)
}

/// The energy dissipated so far (`None` when not asked for): the
/// trapezoidal rule over each step of the dissipated power at its ends.
struct Dissipated<'a> {
    ladder: &'a Ladder,
    total: Option<f64>,
    /// The power at the last step's end.
    last_power: f64,
}

impl<'a> Dissipated<'a> {
    fn new(ladder: &'a Ladder, on: bool, st: &State) -> Self {
        let last_power = if on { Self::power(ladder, st) } else { 0.0 };
        Self {
            ladder,
            total: on.then_some(0.0),
            last_power,
        }
    }

    fn power(ladder: &Ladder, st: &State) -> f64 {
        trajectory::dissipated_power(ladder, &st.q, &st.v)
    }

    /// Adds the step of length `dt` just taken, which ended at `st`.
    fn step(&mut self, st: &State, dt: f64) {
        if let Some(d) = self.total.as_mut() {
            let p = Self::power(self.ladder, st);
            *d += 0.5 * (self.last_power + p) * dt;
            self.last_power = p;
        }
    }
}

/// The path a run takes: the fused and chain kernels compute the paper's
/// forces only, so a ladder with any term of docs/experiments.md takes the
/// portable path whatever `options` ask.
fn stepping_for(scenario: &Scenario, options: &RunOptions) -> Stepping {
    if scenario.ladder.is_paper_model() {
        options.stepping
    } else {
        Stepping::Portable
    }
}

/// Whether the run loop goes one step per call: where every wave's sign
/// changes are timed step by step (a drive of several flips) or the
/// dissipated power is integrated.
fn steps_one_by_one(scenario: &Scenario, options: &RunOptions) -> bool {
    options.dissipation
        || options
            .every_step
            .unwrap_or_else(|| scenario.protocol.drive().is_some_and(|d| d.flips() > 1))
}

/// The error of a run whose time no longer advances at `t`.
fn stalled(t: f64, config: &IntegratorConfig) -> Error {
    Error::failed(format!(
        "time stopped advancing at t = {} τ ({}): the step is below the rounding of t",
        num(t),
        config.describe_step()
    ))
}

/// The cap's error of a run that has taken `steps` steps of `weight`
/// (`cost::weight`) on `path` by `t`, past the cap on block-steps.
fn over_cap(
    scenario: &Scenario,
    path: &cost::Path,
    weight: f64,
    steps: u64,
    t: f64,
    limits: &Limits,
) -> Error {
    let n = scenario.ladder.n();
    let value = steps as f64 * n as f64 * weight;
    Error::Limit(crate::limits::LimitExceeded {
        resource: Resource::BlockSteps,
        value,
        cap: limits.block_steps,
        detail: format!(
            "{} steps by t = {} of t_end = {} × N = {}{}, and counting",
            steps,
            crate::numfmt::brief(t),
            crate::numfmt::brief(scenario.t_end),
            n,
            cost::weighed(path, value)
        ),
    })
}
