//! A run that ends once its outcome is decided (SPEC section 7): the run
//! loop of [`super::simulate_with`] without samples, asking a stop rule at
//! every divergence check; t_end is then the cap.
//!
//! The same signature as the batch stepper's scalar reference (branch
//! `perf`, `sim::simulate_until`); when that lands, this file goes.

use super::observables::ArrivalDetector;
use super::{
    DivergenceWatch, IntegratorConfig, Rhs, Scenario, Stepping, Trajectory, check_every, stop_times,
};
use crate::error::Result;

/// A stop rule: given the time reached and the arrival times so far, true
/// once the run has decided what it was run for. Asked at every
/// divergence check (every 5 τ, at most 512 steps apart, and at every
/// drive corner).
pub type StopRule<'a> = dyn Fn(f64, &[Option<f64>]) -> bool + Sync + 'a;

/// Integrates `scenario` until `stop` says so or t_end, whichever comes
/// first; the trajectory holds no samples, its final state is the one
/// where the run ended. A diverging run returns `Error::Failed`.
pub fn simulate_until(
    scenario: &Scenario,
    config: &IntegratorConfig,
    stepping: Stepping,
    stop: &StopRule,
) -> Result<Trajectory> {
    let config = config.validated()?;
    let stops = stop_times(&[], &scenario.protocol, scenario.t_end);
    let ladder = &scenario.ladder;
    let mut rhs = Rhs::new(ladder, &scenario.protocol, &scenario.initial.q);
    let mut st = scenario.initial.clone();
    rhs.constrain(0.0, &mut st.q, &mut st.v);
    let mut integrator = config.build(rhs.dof(), stepping);
    let mut watch = DivergenceWatch::new(ladder, &scenario.protocol, &config);
    let check_every = check_every(&config);
    let mut arrivals = ArrivalDetector::new(0.0, &st.q, &st.v);
    let mut steps = 0;
    let mut t = 0.0;
    'run: for &stop_at in &stops {
        while t < stop_at {
            let budget = check_every - steps % check_every;
            let (t_new, taken) =
                integrator.advance_many(&mut rhs, &mut st, (t, stop_at), budget, &mut arrivals)?;
            t = t_new;
            steps += taken;
            if steps.is_multiple_of(check_every) {
                watch.check(&rhs, &st, t)?;
                if stop(t, &arrivals.arrival) {
                    break 'run;
                }
            }
        }
        watch.check(&rhs, &st, t)?;
        if stop(t, &arrivals.arrival) {
            break;
        }
    }
    Ok(Trajectory {
        times: Vec::new(),
        states: Vec::new(),
        velocities: Vec::new(),
        kink_position: Vec::new(),
        arrival_times: arrivals.arrival,
        final_state: st,
        steps,
        force_evals: rhs.force_evals,
    })
}
