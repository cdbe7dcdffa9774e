//! The `auto` integrator with verified accuracy (docs/scenes.md).
//!
//! Velocity Verlet (second order, symplectic, one force evaluation a step)
//! starts at dt = min(0.25, 0.4 · 2/ω_max), well inside its stability
//! bound 2/ω_max (`IntegratorConfig::auto`). The run is then checked
//! against one at half the step: both must flip the same blocks, and every
//! arrival time must agree within the tolerance. Until they do, the step
//! is halved again. For a second-order method the finer run's error is
//! about a third of the difference (Richardson), so accepting a difference
//! of at most the tolerance keeps the returned run's arrival times within
//! about a third of it; that estimate is what is reported.
//!
//! What `auto` may spend is decided before any run starts ([`worst_case`]):
//! the first pair of runs must fit under the cap on steps × N (else the
//! run is refused at once), and only the halvings whose runs keep the total
//! under the cap are made. A run that would need a finer step than the
//! budget allows ends with the cap's error naming what it needs, so `auto`
//! never computes past the cap. Every halving down to dt / 2^[`MAX_HALVINGS`]
//! would be about 2^11 − 1 = 2047 times the first run.

use super::integrators::AUTO_DT;
use super::{Cost, IntegratorConfig, IntegratorKind, RunOptions, Scenario, Trajectory, check_cost};
use crate::error::{Error, Result, num};
use crate::limits::{Limits, Resource};

/// Most halvings of the step before `auto` gives up (dt / 2^10).
pub const MAX_HALVINGS: u32 = 10;

/// A run whose arrival times were checked against a run at half its step.
#[derive(Debug, Clone)]
pub struct Verified {
    /// The finer of the last two runs, sampled as asked.
    pub trajectory: Trajectory,
    /// The integrator of that run.
    pub config: IntegratorConfig,
    /// Estimated largest error of its arrival times, in τ (a third of
    /// the largest difference to the run at twice the step).
    pub arrival_error: f64,
    /// Largest difference of arrival times between the last two runs, τ.
    pub arrival_difference: f64,
    /// Force evaluations of every run made, the check included.
    pub total_force_evals: u64,
}

/// Runs `scenario` with velocity Verlet, halving the step from the one
/// `omega_max` (highest normal mode of the clamped chain) allows until two
/// successive runs flip the same blocks and agree on every arrival time
/// within `tolerance` (τ). Samples are recorded on the returned run only.
/// Every run is made as `options` say (its caps, progress and stepping;
/// the stop rule should be `run_to_end`, as a run ended early cannot be
/// compared).
pub fn simulate_verified(
    scenario: &Scenario,
    sample_times: &[f64],
    tolerance: f64,
    omega_max: f64,
    options: &RunOptions,
) -> Result<Verified> {
    let simulate = |scenario: &Scenario, samples: &[f64], config: &IntegratorConfig| {
        super::run(scenario, samples, config, options)
    };
    let limits = &options.limits;
    let budget = worst_case(scenario, sample_times.len(), omega_max, limits)?;
    // The samples' memory asked for once, before any run: a run refused
    // for it inside the loop would pass for a diverged one.
    super::ensure_memory(sample_times.len(), scenario.ladder.n())?;
    let mut dt = budget.dt;
    let (mut coarse, first_fine) = first_pair(scenario, sample_times, dt, &simulate)?;
    let mut total = coarse.as_ref().map_or(0, |c| c.force_evals);
    let mut first_fine = Some(first_fine);
    let mut last_difference = f64::INFINITY;
    // Halvings in a row whose difference did not shrink ([`diverging`]).
    let mut shrinks = 0usize;
    for _ in 0..budget.pairs {
        let config = scheme(scenario, 0.5 * dt);
        let run = match first_fine.take() {
            Some(r) => r,
            None => simulate(scenario, sample_times, &config),
        };
        let fine = match run {
            Ok(t) => t,
            Err(e) if e.is_failed_run() => {
                dt *= 0.5;
                coarse = None;
                continue;
            }
            Err(e) => return Err(e),
        };
        total += fine.force_evals;
        if let Some(c) = &coarse {
            let difference = arrival_difference(
                &c.arrival_times,
                &fine.arrival_times,
                scenario.t_end,
                tolerance,
            );
            if difference <= tolerance {
                return Ok(Verified {
                    trajectory: fine,
                    config,
                    arrival_error: difference / f64::from((1u32 << config.kind.order()) - 1),
                    arrival_difference: difference,
                    total_force_evals: total,
                });
            }
            if diverging(&mut shrinks, last_difference, difference) {
                return Err(not_converging(last_difference, difference, dt, tolerance));
            }
            last_difference = difference;
        }
        coarse = Some(Coarse::of(fine));
        dt *= 0.5;
    }
    Err(not_verified(
        &budget,
        limits,
        last_difference,
        dt,
        tolerance,
    ))
}

/// One run of a scenario at the given sample times and integrator.
type RunFn<'a> = dyn Fn(&Scenario, &[f64], &IntegratorConfig) -> Result<Trajectory> + Sync + 'a;

/// The first pair of runs (at `dt`, unsampled, and at dt/2, sampled), on
/// both cores: they are independent. Of the coarser run only its arrival
/// times are kept (`None` when it failed); the finer is returned whole.
fn first_pair(
    scenario: &Scenario,
    sample_times: &[f64],
    dt: f64,
    simulate: &RunFn<'_>,
) -> Result<(Option<Coarse>, Result<Trajectory>)> {
    let tally = super::tally::current();
    let (first_coarse, first_fine) = rayon::join(
        || {
            super::tally::within(tally.clone(), || {
                simulate(scenario, &[], &scheme(scenario, dt))
            })
        },
        || {
            super::tally::within(tally.clone(), || {
                simulate(scenario, sample_times, &scheme(scenario, 0.5 * dt))
            })
        },
    );
    // Its samples (none: it records none) are dropped at once, so a
    // halving never holds two sampled trajectories.
    let coarse = match first_coarse {
        Ok(t) => Some(Coarse::of(t)),
        Err(e) if e.is_failed_run() => None,
        Err(e) => return Err(e),
    };
    Ok((coarse, first_fine))
}

/// Why `auto` ended without a verified run after spending `budget`:
/// the cap's error when one more halving would pass it (raising the cap
/// is the remedy), else a failed run.
fn not_verified(
    budget: &Budget,
    limits: &Limits,
    last_difference: f64,
    dt: f64,
    tolerance: f64,
) -> Error {
    let what = if last_difference.is_finite() {
        format!("arrival times still differ by {last_difference:.3} τ")
    } else {
        "the runs still disagree on which blocks flip".to_string()
    };
    if let Some(next) = budget.next_block_steps {
        return Error::Limit(crate::limits::LimitExceeded {
            resource: Resource::BlockSteps,
            value: next,
            cap: limits.cap(Resource::BlockSteps),
            detail: format!(
                "the auto integrator's runs with one more halving of the step, to verify this \
                 run within {tolerance} τ: at dt = {} τ {what}; or raise the tolerance, or name \
                 an integrator and step",
                num(dt)
            ),
        });
    }
    Error::failed(format!(
        "the auto integrator could not verify this run within {tolerance} τ: at dt = {} τ {what}; \
         hint: raise the tolerance, or name an integrator and step",
        num(dt)
    ))
}

/// Halvings in a row whose arrival-time difference did not at least halve
/// after which `auto` stops: a second-order scheme's difference shrinks
/// fourfold a halving once the step resolves the run, so two halvings in
/// a row that do not even halve it say the arrivals do not converge in
/// the step (an undamped apparatus whose motion is chaotic: `--medium air`
/// or tension-only links), and more halvings would only spend the budget.
pub const NOT_SHRINKING_HALVINGS: usize = 2;

/// Counts in `run` the halvings in a row whose difference `now` is not
/// under half of `before` (both finite); true once there are
/// [`NOT_SHRINKING_HALVINGS`].
fn diverging(run: &mut usize, before: f64, now: f64) -> bool {
    if before.is_finite() && now.is_finite() && now > 0.5 * before {
        *run += 1;
    } else {
        *run = 0;
    }
    *run >= NOT_SHRINKING_HALVINGS
}

/// The failed run of arrivals that do not converge in the step.
fn not_converging(before: f64, now: f64, dt: f64, tolerance: f64) -> Error {
    Error::failed(format!(
        "the auto integrator could not verify this run within {tolerance} τ: halving the step \
         does not bring the arrival times together ({before:.3} τ, then {now:.3} τ at dt = {} τ; \
         a second-order step shrinks the difference fourfold once it resolves the run), so the \
         motion is not resolved by any step the budget holds; hint: name an integrator and \
         step (--integrator rk4 --dt 0.125), or add damping",
        num(dt)
    ))
}

/// What `auto` keeps of the coarser run of a pair: what the comparison
/// needs, not its samples.
struct Coarse {
    arrival_times: Vec<Option<f64>>,
    force_evals: u64,
}

impl Coarse {
    fn of(run: Trajectory) -> Self {
        Self {
            arrival_times: run.arrival_times,
            force_evals: run.force_evals,
        }
    }
}

/// What `auto` may spend on `scenario`, decided before any run: its first
/// pair of runs (dt from `omega_max` and dt/2) and then as many further
/// halvings, down to dt / 2^[`MAX_HALVINGS`], as keep the total of steps ×
/// N under `limits`' cap (each run counted with the samples' stops, an
/// upper bound).
#[derive(Debug, Clone, PartialEq)]
pub struct Budget {
    /// Pairs of runs compared at most (1 = the first pair only).
    pub pairs: u32,
    /// Steps and steps × N of every run within the budget.
    pub total: Cost,
    /// Steps × N (weighed by the path, `cost::weight`) with one pair more
    /// (`None`: every halving fits).
    pub next_block_steps: Option<f64>,
    /// The first step, τ.
    pub dt: f64,
    /// Steps × N of the first pair alone, weighed (`cost::weight`): the
    /// least `auto` spends.
    pub first_pair: f64,
}

/// The [`Budget`] of `auto` for `scenario` with `samples` sample times.
/// Refuses, before any work, a first pair of runs past `limits`' cap on
/// steps × N ([`Error::Limit`]) or a single run that is itself refused
/// ([`check_cost`]). Halvings that would pass the cap are left out of the
/// budget: the runs never compute past the cap, and a run that needs them
/// ends with [`Error::Limit`] saying so ([`simulate_verified`]).
pub fn worst_case(
    scenario: &Scenario,
    samples: usize,
    omega_max: f64,
    limits: &Limits,
) -> Result<Budget> {
    refuse_inextensible(scenario)?;
    let dt = IntegratorConfig::auto(omega_max).dt;
    let mut total = check_cost(scenario, samples, &scheme(scenario, dt), limits)?;
    let second = check_cost(scenario, samples, &scheme(scenario, 0.5 * dt), limits)?;
    total.steps += second.steps;
    total.block_steps += second.block_steps;
    total.equivalent += second.equivalent;
    limits
        .check(Resource::BlockSteps, total.equivalent, || {
            let path = super::cost::Path::of(
                &scenario.ladder,
                scheme(scenario, dt).kind,
                super::Stepping::Fastest,
            );
            format!(
                "the auto integrator's first two runs, at dt = {} and {}, to t_end = {}, times \
                 N = {}{}; or name an integrator and step",
                num(dt),
                num(0.5 * dt),
                crate::numfmt::brief(scenario.t_end),
                scenario.ladder.n(),
                super::cost::weighed(&path, total.equivalent)
            )
        })
        .map_err(Error::Limit)?;
    let first_pair = total.equivalent;
    let mut pairs = 1;
    let mut next_block_steps = None;
    for k in 2..=MAX_HALVINGS {
        let step = dt / f64::from(1u32 << k);
        let c = match check_cost(scenario, samples, &scheme(scenario, step), &Limits::none()) {
            Ok(c) => c,
            // A step too small to advance time: `auto` stops there.
            Err(Error::BadInput(_)) => break,
            Err(e) => return Err(e),
        };
        let with = total.equivalent + c.equivalent;
        if with > limits.cap(Resource::BlockSteps) {
            next_block_steps = Some(with);
            break;
        }
        total.steps += c.steps;
        total.block_steps += c.block_steps;
        total.equivalent = with;
        pairs += 1;
    }
    Ok(Budget {
        pairs,
        total,
        next_block_steps,
        dt,
        first_pair,
    })
}

/// `auto` does not take inextensible ribbons: Moreau's step converges at
/// first order at best, and the arrivals at the free end move by tens of
/// τ between steps, so halving until they agree within a tolerance would
/// spend the budget and fail (docs/experiments.md, "Inextensible
/// ribbons"). Refused before any run, naming the step that holds.
fn refuse_inextensible(scenario: &Scenario) -> Result<()> {
    if scheme(scenario, AUTO_DT).kind != IntegratorKind::Moreau {
        return Ok(());
    }
    Err(Error::bad_input(
        "the auto integrator cannot verify inextensible ribbons' runs (Moreau's step \
         converges at first order at best, and the free end's arrivals move by tens of τ \
         between steps); name the integrator and its step: moreau at 0.05 τ holds the tank's \
         speeds within 2 % (docs/experiments.md)"
            .to_string(),
    ))
}

/// The scheme `auto` runs at step `dt`: velocity Verlet, or classical RK4
/// where the ladder has velocity-dependent terms (added mass, quadratic
/// drag, pin friction: `sim::check_terms`), which Verlet cannot take. RK4
/// is fourth order, so its error estimate is the difference / 15.
/// Inextensible ribbons take Moreau's time-stepping (first order: the
/// estimate is the difference itself).
pub fn scheme(scenario: &Scenario, dt: f64) -> IntegratorConfig {
    let inextensible = (scenario.ladder.built.as_ref()).is_some_and(|b| b.ribbons.inextensible);
    let kind = if inextensible {
        IntegratorKind::Moreau
    } else if scenario.ladder.velocity_dependent() {
        IntegratorKind::Rk4
    } else {
        IntegratorKind::Verlet
    };
    IntegratorConfig::fixed(kind, dt)
}

/// Largest |a_n − b_n| over the blocks; infinite when a block flips in one
/// run and not in the other, unless its flip lies within `tolerance` of
/// the window's end (where the other run may flip just after it).
pub fn arrival_difference(a: &[Option<f64>], b: &[Option<f64>], t_end: f64, tolerance: f64) -> f64 {
    a.iter()
        .zip(b)
        .map(|pair| match pair {
            (Some(x), Some(y)) => (x - y).abs(),
            (None, None) => 0.0,
            (Some(t), None) | (None, Some(t)) => {
                if t_end - t <= tolerance {
                    t_end - t
                } else {
                    f64::INFINITY
                }
            }
        })
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_lost_flip_is_an_infinite_difference() {
        let a = [Some(500.0), Some(900.0), None];
        let b = [Some(500.01), None, None];
        assert_eq!(arrival_difference(&a, &b, 4000.0, 0.1), f64::INFINITY);
        let c = [Some(500.0), Some(900.05), None];
        assert!((arrival_difference(&a, &c, 4000.0, 0.1) - 0.05).abs() < 1e-9);
        // A flip at the very end of the window may be missed by the other run.
        let d = [Some(500.0), Some(3999.95)];
        let e = [Some(500.0), None];
        assert!(arrival_difference(&d, &e, 4000.0, 0.1) < 0.1);
    }
}
