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

/// Work of drawing and encoding one pixel of a movie frame, in block-steps
/// of the paper's model: about 0.8 ms for a 640 × 480 frame of a paper
/// movie (drawing, GIF palette and LZW), against 8 ns a block-step in the
/// kernels (docs/performance.md, "The order in which outputs start").
const WORK_PER_PIXEL: f64 = 0.3;

/// The most work rendering `scene` may take, in block-steps of the paper's
/// model (`sim::cost`, each run weighed by its force path): every run it
/// may make to its window (a sweep's to its cap, an experiment figure's
/// every variant), and a movie's frames. Only an order for starting the
/// outputs, the largest first (`front::render`); nothing is refused by it
/// (`check` has refused what passes a cap), so a scene whose runs cannot
/// be weighed counts as none.
pub fn expected_work(scene: &Scene, movie: &super::MovieOptions) -> f64 {
    let weigh = |runs: &[(Scene, usize)]| -> f64 {
        runs.iter()
            .map(|(s, samples)| run::check_cost(s, *samples).unwrap_or(0.0))
            .sum()
    };
    match &scene.output {
        OutputSpec::Sweep(spec) => crate::sweep::checked(scene).map_or(0.0, |plan| {
            let to_cap: Vec<(Scene, usize)> = (0..plan.len())
                .map(|i| {
                    let mut s = plan.scene_at(i);
                    s.run.t_end = spec.cap.max(s.run.t_end);
                    (s, 0)
                })
                .collect();
            weigh(&to_cap)
        }),
        OutputSpec::Movie { .. } => {
            let pixels = f64::from(movie.width) * f64::from(movie.height);
            weigh(&[(scene.clone(), movie.frames)]) + movie.frames as f64 * pixels * WORK_PER_PIXEL
        }
        OutputSpec::Theory(_) => 0.0,
        _ => planned_runs(scene, movie.frames).map_or(0.0, |runs| weigh(&runs)),
    }
}
