//! A scene's runs checked together before the first (docs/limits.md): a
//! figure's runs, an experiment figure's variants, and a run with its
//! "stiff" links' second run are one cost, in block-steps of the paper's
//! model (`sim::cost`), against the cap on steps × N.

use super::{experiments, run, stiff};
use crate::error::Result;
use crate::limits::{Resource, count};
use crate::scene::{OutputSpec, Scene};
use crate::sim::cost::about;

/// Every simulation `scene` may run when rendered, with the sample times
/// each keeps: its panels or curves (`Scene::runs`), a movie's one run of
/// `frames` frames, or every variant an experiment figure may run.
pub fn planned_runs(scene: &Scene, frames: usize) -> Result<Vec<(Scene, usize)>> {
    Ok(match &scene.output {
        OutputSpec::Experiment(e) => experiments::planned_runs(scene, e.figure)?
            .into_iter()
            .map(|s| (s, 0))
            .collect(),
        OutputSpec::Movie { .. } => vec![(scene.clone(), frames)],
        _ => scene
            .runs()
            .into_iter()
            .map(|(s, t)| (s, t.len()))
            .collect(),
    })
}

/// Refuses, before any run, `runs` of `scene` past its caps: each run
/// alone (`run::check_cost`: its samples, its step, `auto`'s first pair),
/// then all of them together. Returns their cost.
pub fn check_runs(scene: &Scene, runs: &[(Scene, usize)]) -> Result<f64> {
    let mut total = 0.0;
    for (s, samples) in runs {
        total += run::check_cost(s, *samples)?;
    }
    if runs.len() > 1 {
        scene.limits.check(Resource::BlockSteps, total, || {
            format!(
                "the {} runs of {} {} together, each to its window, weighed by its force path \
                 (block-steps of the paper's model by Verlet), {} of computing",
                runs.len(),
                scene.kind().name(),
                scene.name,
                about(total)
            )
        })?;
    }
    Ok(total)
}

/// Refuses, before any run, a run of `scene` with `samples` sample times
/// whose cost with its "stiff" links' check (a second run with the links
/// at 2k over the same seconds: √2 more steps, `scenes::stiff`) passes
/// the cap: the two are one cost, so the first run is never made only
/// for the second to be refused.
pub fn check_with_stiff(scene: &Scene, samples: usize) -> Result<f64> {
    let first = run::check_cost(scene, samples)?;
    let Some(second) = stiff::cost(scene, samples)? else {
        return Ok(first);
    };
    let total = first + second;
    scene.limits.check(Resource::BlockSteps, total, || {
        format!(
            "the run, {}, and the \"stiff\" links' check, a second run with the links twice as \
             stiff (2k) over the same seconds (√2 more steps), {}, in block-steps of the paper's \
             model by Verlet, {} of computing; or give the links' stiffness in N/m, which makes \
             no second run",
            count(first),
            count(second),
            about(total)
        )
    })?;
    Ok(total)
}
