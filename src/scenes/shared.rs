//! Runs that several outputs of one render make alike, made once: a
//! render (`front::render`, `ladder all`) lists every run each output
//! will make ([`planned`]), makes each run that two or more outputs plan
//! before any output starts, charged to the first of them, and holds it
//! (`scenes::reuse`) for every output to take instead of making it again.
//! Movies 3 and 4 (one scene, two cameras) and the tank's positions at
//! 0.2 Hz and its level 3 ("+ added mass", the scene's own terms) are the
//! catalogue's such runs (docs/performance.md). A run taken is the one
//! the output would have made, bit for bit: two runs are one when
//! everything that decides them is equal (`reuse::key`).
//!
//! The shared runs are made before the outputs start, not when the first
//! output asks: an output that waited for another's run while rayon ran
//! other outputs' tasks on its thread could wait for itself.
//!
//! Ring chains that differ in their end only (figure 4b is movie 12's
//! first 2 s) share one run too ([`ring_groups`], [`make_ring_runs`]),
//! but not before the outputs start: the run is several seconds on one
//! core, which would leave the other idle. The render makes it in the
//! first output of the group (the latest end), renders the group's
//! outputs one after the other in that task, and nothing waits.

use super::reuse::{self, Entry, Held, Stop};
use super::run::{self, SceneRun};
use super::{MovieOptions, experiments};
use crate::error::Result;
use crate::rings::RingChain;
use crate::rings::run::Asked;
use crate::scene::{AUTO_T_END, OutputSpec, Scene};
use crate::sim::tally::{self, Tally};
use std::collections::HashMap;
use std::sync::Arc;

/// One run an output will make: its scene, sample times and stop rule.
#[derive(Debug, Clone)]
pub struct Planned {
    pub scene: Scene,
    pub samples: Vec<f64>,
    pub stop: Stop,
}

/// Every run `scene` is sure to make when rendered with `movie`'s frames
/// and whose key is known before it runs: a movie's one run (the frames'
/// times), a filmstrip's panels, an experiment figure's first variants
/// (`experiments::certain_runs`). None for a ring chain or an automatic
/// window (found by a run of its own), nor for the outputs whose runs
/// nothing else makes.
pub fn planned(scene: &Scene, movie: &MovieOptions) -> Result<Vec<Planned>> {
    if scene.rings.is_some() || scene.run.t_end == AUTO_T_END {
        return Ok(Vec::new());
    }
    let to_end = |(scene, samples): (Scene, Vec<f64>)| Planned {
        scene,
        samples,
        stop: Stop::ToEnd,
    };
    Ok(match &scene.output {
        OutputSpec::Movie { .. } => vec![to_end((
            scene.clone(),
            super::kymograph::frame_times(scene.run.t_end, movie.frames),
        ))],
        OutputSpec::Filmstrip { .. } => scene.runs().into_iter().map(to_end).collect(),
        OutputSpec::Experiment(e) => experiments::certain_runs(scene, e.figure)?
            .into_iter()
            .map(|scene| Planned {
                scene,
                samples: Vec::new(),
                stop: Stop::Decided,
            })
            .collect(),
        _ => Vec::new(),
    })
}

/// The runs two or more of `scenes` plan ([`planned`]), each with its
/// key and the index of the first scene that plans it, in the order
/// first planned.
pub fn shared_runs(
    scenes: &[Scene],
    movie: &MovieOptions,
) -> Result<Vec<(String, Planned, usize)>> {
    // key → (the run, the scenes that plan it).
    let mut plans: HashMap<String, (Planned, Vec<usize>)> = HashMap::new();
    let mut order: Vec<String> = Vec::new();
    for (i, s) in scenes.iter().enumerate() {
        for p in planned(s, movie)? {
            let k = reuse::key(&p.scene, &p.samples, p.stop);
            let entry = plans.entry(k.clone()).or_insert_with(|| {
                order.push(k);
                (p, Vec::new())
            });
            if entry.1.last() != Some(&i) {
                entry.1.push(i);
            }
        }
    }
    Ok(order
        .into_iter()
        .filter_map(|k| {
            let (p, by) = plans.remove(&k)?;
            (by.len() > 1).then(|| (k, p, by[0]))
        })
        .collect())
}

/// Makes every run that two or more of `scenes` plan, in parallel
/// (rayon), each charged to `tallies`' tally of the first scene that
/// plans it, and holds them while the returned value lives. A run that
/// fails is not held: each output makes it again and reports it.
pub fn prepare(scenes: &[Scene], movie: &MovieOptions, tallies: &[Arc<Tally>]) -> Result<Held> {
    use rayon::prelude::*;
    let made: Vec<(String, Entry)> = shared_runs(scenes, movie)?
        .into_par_iter()
        .filter_map(|(k, p, owner)| {
            let own = Arc::new(Tally::default());
            let run = tally::within(Some(own.clone()), || make(&p)).ok()?;
            let owner = tallies[owner].clone();
            owner.absorb(&own);
            let entry = Entry {
                made: Arc::new(run),
                runs: own.runs(),
                owner,
            };
            Some((k, entry))
        })
        .collect();
    Ok(Held::hold(made))
}

/// The ring scenes of `scenes` whose chains differ in their end only
/// (figure 4b is movie 12's first 2 s: docs/rings.md), in groups of two
/// or more, each by the scenes' indices, the latest end first (the
/// output its one run is made for), ties in the order given.
pub fn ring_groups(scenes: &[Scene]) -> Vec<Vec<usize>> {
    let but_end = |s: &Scene| {
        s.rings.as_ref().map(|c| RingChain {
            t_end: 0.0,
            ..c.clone()
        })
    };
    let end = |i: usize| scenes[i].rings.as_ref().map_or(0.0, |c| c.t_end);
    let mut groups: Vec<(RingChain, Vec<usize>)> = Vec::new();
    for (i, s) in scenes.iter().enumerate() {
        let Some(chain) = but_end(s) else { continue };
        match groups.iter_mut().find(|g| g.0 == chain) {
            Some(g) => g.1.push(i),
            None => groups.push((chain, vec![i])),
        }
    }
    groups
        .into_iter()
        .filter(|g| g.1.len() > 1)
        .map(|(_, mut g)| {
            g.sort_by(|&a, &b| end(b).total_cmp(&end(a)));
            g
        })
        .collect()
}

/// Makes one run of the chain for a group of [`ring_groups`] (`group`,
/// the latest end first), to its latest end (`rings::run::runs`), on this
/// thread, charged to the tally set here, which `owner` is (the first
/// scene's), and holds each scene's run by the key its output asks with
/// (`scenes::rings`), counted as reused by the others. A run that fails
/// holds nothing: each output makes its own and reports it.
pub fn make_ring_runs(group: &[&Scene], movie: &MovieOptions, owner: &Arc<Tally>) -> Held {
    let chains: Option<Vec<&RingChain>> = group.iter().map(|s| s.rings.as_ref()).collect();
    let Some(chains) = chains.filter(|c| !c.is_empty()) else {
        return Held::hold(Vec::new());
    };
    let times: Vec<Vec<f64>> = group
        .iter()
        .zip(&chains)
        .map(|(s, c)| super::rings::sample_times(s, c, movie))
        .collect();
    let asked: Vec<Asked<'_>> = chains
        .iter()
        .zip(&times)
        .map(|(c, t)| Asked {
            t_end: c.t_end,
            times: t,
        })
        .collect();
    let Ok(made) = crate::rings::run::runs(chains[0], &asked) else {
        return Held::hold(Vec::new());
    };
    let entries = group
        .iter()
        .zip(&times)
        .zip(made)
        .map(|((s, t), run)| {
            let entry = Entry {
                made: Arc::new(run),
                runs: 1,
                owner: owner.clone(),
            };
            (reuse::key(s, t, Stop::ToEnd), entry)
        })
        .collect();
    Held::hold(entries)
}

/// A planned run made as its output makes it.
fn make(p: &Planned) -> Result<SceneRun> {
    match p.stop {
        Stop::ToEnd => run::simulate_unshared(&p.scene, &p.samples),
        Stop::Decided => experiments::decided_run(&p.scene),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalog;
    use crate::scene::Kind;

    fn find(kind: Kind, id: &str) -> Scene {
        catalog::find(kind, id).unwrap().scene.clone()
    }

    /// A movie plans its frames' run; an automatic window and a ring
    /// chain plan none (their keys are not known before a run).
    #[test]
    fn a_movie_plans_its_frames_run() {
        let opts = MovieOptions {
            frames: 5,
            ..MovieOptions::default()
        };
        let p = planned(&find(Kind::Movie, "4"), &opts).unwrap();
        assert_eq!(p.len(), 1);
        assert_eq!(p[0].samples, vec![0.0, 550.0, 1100.0, 1650.0, 2200.0]);
        let mut auto = find(Kind::Movie, "4");
        auto.run.t_end = AUTO_T_END;
        assert!(planned(&auto, &opts).unwrap().is_empty());
        assert!(planned(&find(Kind::Movie, "12"), &opts).unwrap().is_empty());
    }

    /// Of the whole catalogue, the runs planned twice are movie 4's (made
    /// for movie 3) and the tank's kink and antikink at 0.2 Hz with its own
    /// terms (made for its positions' figure, taken by its levels'), and
    /// the same of its ribbons' level (made for `tank-positions-ribbons`).
    #[test]
    fn the_catalogue_shares_movie_4_and_the_tanks_level_3() {
        let scenes: Vec<Scene> = catalog::catalogue()
            .unwrap()
            .iter()
            .map(|e| e.scene.clone())
            .collect();
        let shared = shared_runs(&scenes, &MovieOptions::default()).unwrap();
        let owners: Vec<&str> = shared.iter().map(|s| scenes[s.2].name.as_str()).collect();
        assert_eq!(
            owners,
            [
                "tank-positions",
                "tank-positions",
                "tank-positions-ribbons",
                "tank-positions-ribbons",
                "3"
            ],
            "{owners:?}"
        );
    }

    /// The catalogue's ring chains that differ in their end only are
    /// figure 4b's and movie 12's: one group, movie 12 (3 s) first.
    #[test]
    fn figure_4b_and_movie_12_share_a_chain() {
        let scenes: Vec<Scene> = catalog::catalogue()
            .unwrap()
            .iter()
            .map(|e| e.scene.clone())
            .collect();
        let groups = ring_groups(&scenes);
        let names: Vec<Vec<String>> = groups
            .iter()
            .map(|g| g.iter().map(|&i| scenes[i].stem()).collect())
            .collect();
        assert_eq!(names, [["movie-12", "figure-4b"]], "{names:?}");
        let mut other = find(Kind::Figure, "4b");
        other.rings.as_mut().unwrap().guard_every += 1;
        assert!(ring_groups(&[find(Kind::Movie, "12"), other]).is_empty());
    }
}
