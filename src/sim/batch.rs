//! Many runs at once, for sweeps (docs/sweeps.md): the lanes of a SIMD
//! register hold different runs of the same N, one run per lane, all
//! stepping in lockstep, so no lane waits on a neighbour; a run that ends
//! leaves its lane to the next run in the queue; every core runs such a
//! vector of lanes, taking runs from one shared queue.
//!
//! Every run's trajectory is the one [`sim::run`] gives it on the
//! portable path, bit for bit: the same steps (the same subdivision of the
//! intervals between drive corners and t_end), the same operations in the
//! same order in every lane (`batch/kernel.rs`), the same arrival test, the
//! same divergence checks at the same times with the same messages, and
//! the same stop rule asked at the same times (tests/batch.rs checks it).
//! Runs with another integrator, or on a CPU without AVX2, are run one by
//! one on every core, through [`sim::run`].
//!
//! [`sim::run`]: super::run

#[cfg(target_arch = "x86_64")]
mod kernel;

use super::integrators::{ImplicitDamping, Plan};
use super::observables::ArrivalDetector;
use super::protocol::{Drive, Piece};
use super::waves::WaveTracker;
use super::{
    DivergenceWatch, IntegratorConfig, IntegratorKind, Isa, Rhs, RunOptions, Scenario, State,
    Stepping, StopRule, StopView, Trajectory, check_every, proved_at_rest, stop_times,
};
use crate::error::Result;
use crate::model::params::M;
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Runs every scenario with `config`, each until its t_end or until
/// `options.stop` says its outcome is decided (asked at every divergence
/// check: every 5 τ, at most 512 steps apart, and at every drive corner);
/// results in the order of `scenarios`. The steps are taken as
/// `options.stepping` says: `Fused(isa)` uses the batch kernel for that
/// instruction set (if the CPU has it), `Fastest` the one for the best set
/// this CPU has, except for groups of N too small to fill the lanes, which
/// run one by one with the fastest single-run kernel; `Portable` runs each
/// scenario on the portable path ([`super::run`] without samples, the
/// single-run reference). All give the same trajectories bit for bit.
/// Runs that leave the batch kernel run within `options.limits`.
pub fn simulate_many(
    scenarios: &[Scenario],
    config: &IntegratorConfig,
    options: &RunOptions,
) -> Vec<Result<Trajectory>> {
    let many = Many {
        scenarios,
        config,
        options,
        tally: super::tally::current(),
    };
    let Some(isa) = many.batch_isa(config) else {
        let all: Vec<usize> = (0..scenarios.len()).collect();
        return many.in_order(many.one_by_one(&all, config, options.stepping));
    };
    let config = *config;
    let mut groups: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
    for (i, sc) in scenarios.iter().enumerate() {
        groups.entry(sc.ladder.n()).or_default().push(i);
    }
    let threads = rayon::current_num_threads();
    let (small, full): (Vec<_>, Vec<_>) = groups.into_values().partition(|queue| {
        options.stepping == Stepping::Fastest && queue.len() < SMALL_GROUP_PER_THREAD * threads
    });
    // Too few runs of one N to fill the lanes: one by one on every core,
    // the small groups of every N in one queue, the longest chains first.
    let mut alone: Vec<usize> = small.into_iter().flatten().collect();
    alone.sort_by_key(|&i| std::cmp::Reverse(scenarios[i].ladder.n()));
    let mut done = many.one_by_one(&alone, &config, options.stepping);
    for queue in &full {
        done.extend(many.in_lanes(isa, &config, queue));
    }
    many.in_order(done)
}

/// The runs of one call of [`simulate_many`] and what every part shares.
struct Many<'a> {
    scenarios: &'a [Scenario],
    config: &'a IntegratorConfig,
    options: &'a RunOptions<'a>,
    tally: Option<std::sync::Arc<super::tally::Tally>>,
}

impl Many<'_> {
    /// The batch kernel's instruction set for these runs and `config`, if
    /// they can take it: the paper's forces only (`model::media`),
    /// symplectic Euler or Verlet, a CPU with the instruction set.
    fn batch_isa(&self, config: &IntegratorConfig) -> Option<Isa> {
        let paper = self.scenarios.iter().all(|sc| sc.ladder.is_paper_model());
        let kind = config.validated().ok()?.kind;
        let euler_or_verlet = matches!(
            kind,
            IntegratorKind::SymplecticEuler | IntegratorKind::Verlet
        );
        batch_isa(self.options.stepping).filter(|_| paper && euler_or_verlet)
    }

    /// One run on its own ([`super::run`] without samples; as the batch
    /// kernel, the wave tracker fed at the checks).
    fn one(
        &self,
        sc: &Scenario,
        config: &IntegratorConfig,
        stepping: Stepping,
    ) -> Result<Trajectory> {
        let options = self.options.stepping(stepping).every_step(false);
        super::tally::within(self.tally.clone(), || super::run(sc, &[], config, &options))
    }

    /// The runs `indices` one by one, every core taking the next of the
    /// list as it finishes one (in the list's order).
    fn one_by_one(
        &self,
        indices: &[usize],
        config: &IntegratorConfig,
        stepping: Stepping,
    ) -> Vec<(usize, Result<Trajectory>)> {
        let next = AtomicUsize::new(0);
        let workers = rayon::current_num_threads().clamp(1, indices.len().max(1));
        let done: Vec<Vec<(usize, Result<Trajectory>)>> = (0..workers)
            .into_par_iter()
            .map(|_| {
                let mut out = Vec::new();
                while let Some(&i) = indices.get(next.fetch_add(1, Ordering::Relaxed)) {
                    out.push((i, self.one(&self.scenarios[i], config, stepping)));
                }
                out
            })
            .collect();
        done.into_iter().flatten().collect()
    }

    /// The runs `queue` (all of one N) in the lanes of the batch kernel,
    /// one vector of lanes per core.
    fn in_lanes(
        &self,
        isa: Isa,
        config: &IntegratorConfig,
        queue: &[usize],
    ) -> Vec<(usize, Result<Trajectory>)> {
        let next = AtomicUsize::new(0);
        let workers = rayon::current_num_threads().clamp(1, queue.len());
        let job = Job {
            isa,
            config: *config,
            stop: self.options.stop,
            scenarios: self.scenarios,
            queue,
            next: &next,
        };
        let done: Vec<Vec<(usize, Result<Trajectory>)>> = (0..workers)
            .into_par_iter()
            .map(|_| super::tally::within(self.tally.clone(), || job.work()))
            .collect();
        done.into_iter().flatten().collect()
    }

    /// The results in the order of the scenarios; a run without one (none
    /// is left out) runs on the portable path.
    fn in_order(&self, done: Vec<(usize, Result<Trajectory>)>) -> Vec<Result<Trajectory>> {
        let mut results: Vec<Option<Result<Trajectory>>> =
            self.scenarios.iter().map(|_| None).collect();
        for (i, result) in done {
            results[i] = Some(result);
        }
        results
            .into_iter()
            .zip(self.scenarios)
            .map(|(r, sc)| r.unwrap_or_else(|| self.one(sc, self.config, Stepping::Portable)))
            .collect()
    }
}

/// With `Stepping::Fastest`, groups of fewer runs of one N than this many
/// per thread run one by one (`benches/kernels.rs`, `block_step_vs_runs`:
/// a vector of lanes costs about as much per step as three single runs in
/// the fused kernel, so it pays from about three runs per vector on).
const SMALL_GROUP_PER_THREAD: usize = 3;

/// The batch kernel's instruction set for `stepping`, if this CPU has it.
fn batch_isa(stepping: Stepping) -> Option<Isa> {
    if !cfg!(target_arch = "x86_64") {
        return None;
    }
    stepping.isa()
}

/// The runs of one N and what every worker shares.
struct Job<'a, 's> {
    isa: Isa,
    config: IntegratorConfig,
    stop: &'a StopRule<'a>,
    scenarios: &'s [Scenario],
    /// Indices into `scenarios`, all of the same N.
    queue: &'a [usize],
    /// The next entry of `queue` to start.
    next: &'a AtomicUsize,
}

impl<'s> Job<'_, 's> {
    /// One worker: a vector of lanes, filled from the queue until it is
    /// empty and every lane has finished.
    #[cfg(target_arch = "x86_64")]
    fn work(&self) -> Vec<(usize, Result<Trajectory>)> {
        let n = self.scenarios[self.queue[0]].ladder.n();
        let width = kernel::lanes(self.isa);
        let mut state = kernel::LaneState::new(n, width);
        state.verlet = self.config.kind == IntegratorKind::Verlet;
        let mut w = Worker {
            job: self,
            state,
            lanes: (0..width).map(|_| None).collect(),
            idle: State::at_rest(self.scenarios[self.queue[0]].ladder.ground_state()),
            out: Vec::new(),
        };
        for lane in 0..width {
            w.fill(lane);
        }
        loop {
            let count = w
                .lanes
                .iter_mut()
                .flatten()
                .map(|run| run.available(&self.config))
                .min();
            let Some(count) = count else { break };
            for lane in 0..width {
                if let Some(run) = w.lanes[lane].as_mut() {
                    run.prepare(&self.config, count, &mut w.state.params, lane);
                }
            }
            // SAFETY: `batch_isa` checked that the CPU has the instruction
            // set; the state was made for its lanes, with N ≥ 2.
            unsafe { kernel::run(self.isa, &mut w.state, count, &mut Recorders(&mut w.lanes)) };
            for lane in 0..width {
                let Some(run) = w.lanes[lane].as_mut() else {
                    continue;
                };
                if let Some(result) = run.advanced(count, lane, &w.state, self) {
                    w.out.push((run.index, result));
                    w.lanes[lane] = None;
                    w.fill(lane);
                }
            }
        }
        w.out
    }

    #[cfg(not(target_arch = "x86_64"))]
    fn work(&self) -> Vec<(usize, Result<Trajectory>)> {
        unreachable!("batch_isa is None off x86-64")
    }

    /// The next run of the queue, if any.
    fn take(&self) -> Option<usize> {
        let k = self.next.fetch_add(1, Ordering::Relaxed);
        self.queue.get(k).copied()
    }
}

/// A worker's lanes and the runs in them.
#[cfg(target_arch = "x86_64")]
struct Worker<'j, 'a, 's> {
    job: &'j Job<'a, 's>,
    state: kernel::LaneState,
    lanes: Vec<Option<Run<'s>>>,
    /// What an idle lane holds: a ground state at rest, stepped with h = 0.
    idle: State,
    out: Vec<(usize, Result<Trajectory>)>,
}

#[cfg(target_arch = "x86_64")]
impl Worker<'_, '_, '_> {
    /// Puts the next run of the queue into `lane`, or leaves it idle.
    fn fill(&mut self, lane: usize) {
        while let Some(index) = self.job.take() {
            let scenario = &self.job.scenarios[index];
            let mut run = Run::start(index, scenario, &self.job.config);
            if run.stops.is_empty() {
                // t_end = 0: nothing to step.
                let st = run.start_state();
                self.out.push((index, Ok(run.finish(st))));
                continue;
            }
            let st = run.start_state();
            self.put(lane, &st, &run.arrivals, Some(&run));
            if self.state.verlet {
                // Verlet's acceleration at the start (its first step
                // computes it; every later step reuses the last one's).
                let mut acc = vec![0.0; st.q.len()];
                run.rhs.conservative(&st.q, &mut acc);
                let s = &mut self.state;
                for i in 0..s.n {
                    let at = i * s.lanes + lane;
                    (s.ax[at], s.ay[at], s.atheta[at]) =
                        (acc[3 * i], acc[3 * i + 1], acc[3 * i + 2]);
                }
            }
            self.lanes[lane] = Some(run);
            return;
        }
        let idle = self.idle.clone();
        self.put(
            lane,
            &idle,
            &ArrivalDetector::new(0.0, &idle.q, &idle.v),
            None,
        );
    }

    /// Writes a run's state, windows and constants into `lane`; `None`
    /// makes the lane idle (h = 0, nothing pending, not driven).
    fn put(&mut self, lane: usize, st: &State, arrivals: &ArrivalDetector, run: Option<&Run>) {
        let s = &mut self.state;
        let w = s.lanes;
        for i in 0..s.n {
            let at = i * w + lane;
            (s.x[at], s.y[at], s.theta[at]) = (st.q[3 * i], st.q[3 * i + 1], st.q[3 * i + 2]);
            (s.vx[at], s.vy[at], s.vtheta[at]) = (st.v[3 * i], st.v[3 * i + 1], st.v[3 * i + 2]);
            let [lo, hi] = match run {
                Some(_) => arrivals.window(i),
                None => [f64::NEG_INFINITY, f64::INFINITY],
            };
            (s.window_lo[at], s.window_hi[at]) = (lo, hi);
            (s.ax[at], s.ay[at], s.atheta[at]) = (0.0, 0.0, 0.0);
        }
        let p = &mut s.params;
        let ladder = run.map(|r| r.rhs.ladder);
        p.a_rest[lane] = ladder.map_or(1.0, |l| l.a);
        p.b_rest[lane] = ladder.map_or(1.0, |l| l.params.b);
        p.minus_g[lane] = ladder.map_or(0.0, |l| -(M * l.params.gravity));
        let clamp = run.and_then(|r| r.drive).map(|(_, c)| c);
        p.driven[lane] = if clamp.is_some() { -0.0 } else { 0.0 };
        [p.clamp_x[lane], p.clamp_y[lane]] = clamp.unwrap_or([0.0; 2]);
        (p.t[lane], p.t_stop[lane], p.lands[lane]) = (0.0, 0.0, 0.0);
        (p.h[lane], p.decay_xy[lane], p.kick_xy[lane]) = (0.0, 1.0, 0.0);
        (p.decay_theta[lane], p.kick_theta[lane]) = (1.0, 0.0);
        (p.half[lane], p.rate_xy[lane], p.rate_theta[lane]) = (0.0, 0.0, 0.0);
        (p.inv_mass_xy[lane], p.inv_mass_theta[lane]) = (0.0, 0.0);
        (p.div_xy[lane], p.div_theta[lane]) = (1.0, 1.0);
        let hold = Piece::Hold {
            theta: 0.0,
            from: 0.0,
            until: f64::INFINITY,
        };
        set_piece(&mut p.piece, lane, &hold);
        set_piece(&mut p.next_piece, lane, &hold);
        p.until[lane] = f64::INFINITY;
        (p.land_theta[lane], p.land_omega[lane]) = (0.0, 0.0);
    }
}

/// A drive piece into a lane's parameters.
#[cfg(target_arch = "x86_64")]
fn set_piece(p: &mut kernel::PieceLanes, lane: usize, piece: &Piece) {
    match *piece {
        Piece::Hold { theta, .. } => {
            p.ramp[lane] = 0.0;
            p.hold_theta[lane] = theta;
            (p.theta_start[lane], p.theta_delta[lane]) = (0.0, 0.0);
            (p.t0[lane], p.span[lane]) = (0.0, 1.0);
            p.omega[lane] = 0.0;
        }
        Piece::Ramp { start, end, slope } => {
            p.ramp[lane] = -0.0;
            p.hold_theta[lane] = 0.0;
            (p.theta_start[lane], p.theta_delta[lane]) = (start.1, end.1 - start.1);
            (p.t0[lane], p.span[lane]) = (start.0, end.0 - start.0);
            p.omega[lane] = slope;
        }
    }
}

/// The time a drive piece ends (the next one starts).
fn piece_end(piece: &Piece) -> f64 {
    match *piece {
        Piece::Hold { until, .. } => until,
        Piece::Ramp { end, .. } => end.0,
    }
}

/// One run in a lane: what the portable run loop keeps for it.
struct Run<'s> {
    index: usize,
    rhs: Rhs<'s>,
    drive: Option<(&'s Drive, [f64; 2])>,
    watch: DivergenceWatch,
    arrivals: ArrivalDetector,
    /// The waves, fed at every check (`waves`' module doc).
    tracker: WaveTracker,
    /// The times to land on, and the next of them.
    stops: Vec<f64>,
    next_stop: usize,
    plan: Plan,
    damping: ImplicitDamping,
    check_every: u64,
    steps: u64,
    t: f64,
    /// Reused to gather the lane's state for checks.
    scratch: State,
}

impl<'s> Run<'s> {
    /// As the portable run loop starts `scenario`.
    fn start(index: usize, scenario: &'s Scenario, config: &IntegratorConfig) -> Self {
        let ladder = &scenario.ladder;
        let rhs = Rhs::new(ladder, &scenario.protocol, &scenario.initial.q);
        let mut st = scenario.initial.clone();
        rhs.constrain(0.0, &mut st.q, &mut st.v);
        let arrivals = ArrivalDetector::new(0.0, &st.q, &st.v);
        let tracker = WaveTracker::new(0.0, &st.q, &st.v);
        Self {
            index,
            tracker,
            drive: rhs.drive(),
            watch: DivergenceWatch::new(ladder, &scenario.protocol, config),
            arrivals,
            stops: stop_times(&[], &scenario.protocol, scenario.t_end),
            next_stop: 0,
            plan: Plan::default(),
            damping: ImplicitDamping::default(),
            check_every: check_every(config),
            steps: 0,
            t: 0.0,
            scratch: st,
            rhs,
        }
    }

    /// The constrained initial state.
    fn start_state(&self) -> State {
        self.scratch.clone()
    }

    /// How many steps this run can take in one call: to its next stop time
    /// or divergence check, whichever comes first.
    fn available(&mut self, config: &IntegratorConfig) -> u64 {
        let budget = self.check_every - self.steps % self.check_every;
        let stop_at = self.stops[self.next_stop];
        let (_, count, _) = self.plan.take(self.t, stop_at, config.dt, budget);
        self.plan.give_back(count);
        count
    }

    /// Sets `lane`'s step, factors, drive and landing for `count` steps.
    #[cfg(target_arch = "x86_64")]
    fn prepare(
        &mut self,
        config: &IntegratorConfig,
        count: u64,
        p: &mut kernel::LaneParams,
        lane: usize,
    ) {
        let stop_at = self.stops[self.next_stop];
        let (h, taken, lands) = self.plan.take(self.t, stop_at, config.dt, count);
        debug_assert_eq!(taken, count);
        p.h[lane] = h;
        if config.kind == IntegratorKind::Verlet {
            // `FixedStep::verlet`'s factors, for a free block (block 1,
            // where driven, is set by the drive).
            let half = 0.5 * h;
            let (rate, inv_mass) = (&self.rhs.damping_rate, self.rhs.inv_mass());
            p.half[lane] = half;
            (p.rate_xy[lane], p.rate_theta[lane]) = (rate[3], rate[5]);
            (p.inv_mass_xy[lane], p.inv_mass_theta[lane]) = (inv_mass[3], inv_mass[5]);
            p.div_xy[lane] = 1.0 + half * rate[3];
            p.div_theta[lane] = 1.0 + half * rate[5];
        } else {
            if h != self.damping.h {
                self.damping.set(&self.rhs, h);
            }
            let (decay, kick) = self
                .damping
                .uniform
                .expect("the ladder's free blocks share their damping factors");
            debug_assert!(decay[0] == decay[1] && kick[0] == kick[1]);
            (p.decay_xy[lane], p.kick_xy[lane]) = (decay[0], kick[0]);
            (p.decay_theta[lane], p.kick_theta[lane]) = (decay[2], kick[2]);
        }
        p.t[lane] = self.t;
        p.t_stop[lane] = stop_at;
        p.lands[lane] = if lands { -0.0 } else { 0.0 };
        if let Some((drive, _)) = self.drive {
            // Every step but a landing one ends inside the interval, hence
            // inside the piece in force just after its start; a landing
            // step's t + h may fall just past its end, in the next piece.
            let piece = drive.piece(self.t + h);
            let until = piece_end(&piece);
            set_piece(&mut p.piece, lane, &piece);
            let next = if until.is_finite() {
                drive.piece(until)
            } else {
                piece
            };
            set_piece(&mut p.next_piece, lane, &next);
            p.until[lane] = until;
            (p.land_theta[lane], p.land_omega[lane]) = (drive.theta(stop_at), drive.omega(stop_at));
        }
    }

    /// After `count` steps: the run loop's checks. Returns the run's
    /// result once it has ended.
    #[cfg(target_arch = "x86_64")]
    fn advanced(
        &mut self,
        count: u64,
        lane: usize,
        state: &kernel::LaneState,
        job: &Job,
    ) -> Option<Result<Trajectory>> {
        self.steps += count;
        self.t = state.params.t[lane];
        let landed = self.plan.left() == 0;
        if self.steps.is_multiple_of(self.check_every) {
            gather(state, lane, &mut self.scratch);
            if let Err(e) = self.watch.check(&self.rhs, &self.scratch, self.t) {
                return Some(Err(e));
            }
            if self.observe_and_stop(job) {
                return Some(Ok(self.finish_from(state, lane)));
            }
        }
        if landed {
            gather(state, lane, &mut self.scratch);
            if let Err(e) = self.watch.check(&self.rhs, &self.scratch, self.t) {
                return Some(Err(e));
            }
            if self.observe_and_stop(job) {
                return Some(Ok(self.finish_from(state, lane)));
            }
            self.next_stop += 1;
            if self.next_stop == self.stops.len() {
                return Some(Ok(self.finish_from(state, lane)));
            }
        }
        None
    }

    /// At a check, with the state gathered: feeds the wave tracker and
    /// asks the stop rule.
    #[cfg(target_arch = "x86_64")]
    fn observe_and_stop(&mut self, job: &Job) -> bool {
        let st = &self.scratch;
        self.tracker
            .observe(self.t, &st.q, &st.v, &self.arrivals.arrival);
        (job.stop)(&StopView {
            t: self.t,
            arrivals: &self.arrivals.arrival,
            ladder: self.rhs.ladder,
            q: &st.q,
            v: &st.v,
            waves: &self.tracker,
        })
    }

    #[cfg(target_arch = "x86_64")]
    fn finish_from(&mut self, state: &kernel::LaneState, lane: usize) -> Trajectory {
        gather(state, lane, &mut self.scratch);
        let st = self.scratch.clone();
        self.finish(st)
    }

    /// The run's result, ending in `st`.
    fn finish(&mut self, st: State) -> Trajectory {
        // One force evaluation per step, and Verlet's first acceleration.
        let evals = self.steps + self.rhs.force_evals.min(self.steps);
        let at_rest = proved_at_rest(self.rhs.ladder, self.rhs.protocol(), self.t, &st);
        let waves = self.tracker.finish(&st.q, at_rest);
        let mut traj = Trajectory::finished(
            st,
            self.t,
            std::mem::take(&mut self.arrivals.arrival),
            self.steps,
            evals,
        );
        traj.waves = waves;
        traj
    }
}

/// `lane`'s state in the model's layout.
#[cfg(target_arch = "x86_64")]
fn gather(s: &kernel::LaneState, lane: usize, st: &mut State) {
    let w = s.lanes;
    for i in 0..s.n {
        let at = i * w + lane;
        (st.q[3 * i], st.q[3 * i + 1], st.q[3 * i + 2]) = (s.x[at], s.y[at], s.theta[at]);
        (st.v[3 * i], st.v[3 * i + 1], st.v[3 * i + 2]) = (s.vx[at], s.vy[at], s.vtheta[at]);
    }
}

/// The lanes' arrival detectors, for the kernel's exact test.
#[cfg(target_arch = "x86_64")]
struct Recorders<'a, 's>(&'a mut [Option<Run<'s>>]);

#[cfg(target_arch = "x86_64")]
impl kernel::Recorder for Recorders<'_, '_> {
    fn try_record(
        &mut self,
        lane: usize,
        block: usize,
        before: (f64, f64, f64),
        after: (f64, f64, f64),
    ) -> bool {
        self.0[lane]
            .as_mut()
            .is_some_and(|run| run.arrivals.try_record(block, before, after))
    }
}
