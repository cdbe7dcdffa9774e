//! What a study costs, checked against the caps before any run (docs/limits.md):
//! its runs together, in steps × N, as one simulation is.

use super::{BenchScene, config_at, default_steps};
use crate::error::Result;
use crate::limits::{Limits, Resource, count};
use crate::sim::cost::about;
use crate::sim::integrators::DOPRI5_MAX_STEP;
use crate::sim::{IntegratorKind, Stepping};

/// Steps × N of one run of `scene` at sweep value `x` of `kind`: t_end/dt
/// steps at a fixed step, the fewest an adaptive dopri5 can take (t_end /
/// its largest step) otherwise; weighed by the run's force path, in
/// block-steps of the paper's model by Verlet (`sim::cost`).
fn run_cost(scene: &BenchScene, kind: IntegratorKind, x: f64) -> f64 {
    let config = config_at(kind, x);
    let step = if config.rtol.is_some() {
        DOPRI5_MAX_STEP
    } else {
        config.dt
    };
    (scene.t_end / step).ceil() * scene.params.n as f64 * weight(scene, kind)
}

/// The weight of a block-step of `scene` by `kind` (`sim::cost`).
fn weight(scene: &BenchScene, kind: IntegratorKind) -> f64 {
    crate::sim::cost::weight(&scene.scenario.ladder, kind, Stepping::Fastest)
}

/// Refuses, before any run, a work-precision study whose runs together
/// (every integrator at every step, `repeats` times, and each scene's
/// reference) pass the cap on steps × N.
pub fn check_work_precision_cost(
    scenes: &[BenchScene],
    repeats: usize,
    limits: &Limits,
) -> Result<()> {
    let mut total = 0.0;
    // The dearest single run: (its cost, what it is).
    let mut dearest = (0.0, String::new());
    for scene in scenes {
        let reference = scene.reference_config();
        let x = reference.rtol.unwrap_or(reference.dt);
        total += run_cost(scene, reference.kind, x);
        for kind in IntegratorKind::ALL {
            for x in default_steps(kind) {
                // A refused point is not run.
                if scene.refusal(&config_at(kind, x)).is_some() {
                    continue;
                }
                let run = run_cost(scene, kind, x);
                total += repeats as f64 * run;
                if run > dearest.0 {
                    dearest = (run, format!("{kind} at {x}"));
                }
            }
        }
    }
    let window = scenes.first().map_or(0.0, |s| s.t_end);
    limits.check(Resource::BlockSteps, total, || {
        format!(
            "the work-precision study's runs together: {} steps × N over a window of {} τ, \
             weighed by each run's force path (block-steps of the paper's model by Verlet), {} \
             of computing (its dearest run, {}, alone is {})",
            count(total),
            crate::error::num(window),
            about(total),
            dearest.1,
            count(dearest.0)
        )
    })?;
    Ok(())
}

/// Runs a stability bisection makes, at most, per scheme (a bracket of a
/// few doublings, then halvings to 2 % in the step).
pub const BISECTION_RUNS: f64 = 16.0;

/// Refuses, before any run, a stability study of `scene` whose bisections
/// would pass the cap on steps × N: [`BISECTION_RUNS`] runs a scheme, each
/// at half the step its bracket starts from (the linear prediction, at
/// least 0.02/ω_max), an estimate.
pub fn check_stability_cost(scene: &BenchScene, limits: &Limits) -> Result<()> {
    let omega_max = crate::theory::dispersion::omega_max_clamped(&scene.params)?;
    let c = super::damping_rate(&scene.params);
    // A scheme that refuses the scene's terms at every step makes no
    // bisection (the contact's refusal of a long RK4 step is not one).
    let total: f64 = IntegratorKind::ALL
        .iter()
        .filter(|&&kind| scene.refusal(&config_at(kind, 1e-9)).is_none())
        .map(|&kind| {
            let guess =
                super::predicted_dt(kind, omega_max, c).clamp(0.02 / omega_max, 10.0 / omega_max);
            BISECTION_RUNS
                * (2.0 * scene.t_end / guess).ceil()
                * scene.params.n as f64
                * weight(scene, kind)
        })
        .sum();
    limits.check(Resource::BlockSteps, total, || {
        format!(
            "the stability study's bisections, about {} steps × N over a window of {} τ, \
             weighed by each scheme's force path (block-steps of the paper's model by Verlet), \
             {} of computing",
            count(total),
            crate::error::num(scene.t_end),
            about(total)
        )
    })?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ribbon tank's inextensible ribbons refuse every scheme but
    /// Moreau: the studies count Moreau's runs alone (with every scheme
    /// counted, over 10⁶ τ its stability study would need 1.6e12
    /// block-steps and its work-precision study about 1.5e12 a repeat;
    /// Moreau's alone, 1.4e10 and about 1.2e11).
    #[test]
    fn a_study_counts_only_the_schemes_that_run() {
        let scene = BenchScene::movie("water-tank-ribbons", Some(1e6), 2).unwrap();
        let mut limits = Limits::none();
        limits.set(Resource::BlockSteps, 2e10);
        assert!(check_stability_cost(&scene, &limits).is_ok());
        limits.set(Resource::BlockSteps, 1e10);
        assert!(check_stability_cost(&scene, &limits).is_err());
        limits.set(Resource::BlockSteps, 4e11);
        assert!(check_work_precision_cost(&[scene], 1, &limits).is_ok());
    }
}
