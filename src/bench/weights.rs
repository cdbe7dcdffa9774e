//! `bench cost`: the cost model's numbers (`sim::cost`) measured on this
//! machine. Each force path is timed on the portable path (the fused
//! kernel where it steps the paper's model), at N = 1000 and at each
//! apparatus's own N, in interleaved rounds (a shared machine's slow and
//! fast phases fall on every path alike); the median of the rounds, in ns
//! per block-step, is printed beside the model's number and weight. The
//! table in `sim::cost` is copied from this output.

use super::median;
use crate::error::Result;
use crate::scene::Scene;
use crate::scene::apparatus::{StiffWord, Stiffness};
use crate::sim::cost::{Path, REFERENCE_NS};
use crate::sim::{self, IntegratorConfig, IntegratorKind, Scenario, Stepping};
use serde::{Deserialize, Serialize};
use std::time::Instant;

/// Block-steps of one timed run of each path (a fraction of a second on
/// the slowest).
const BLOCK_STEPS: f64 = 1e6;

/// The ribbons' scene (assets/scenes/movie-water-tank-ribbons.toml), its
/// ribbons made stiff for RK4.
const RIBBONS: &str = "water-tank-ribbons";

/// Moreau's step on the ribbons' scene, in τ: the catalogue movie's.
const MOREAU_DT: f64 = 0.2;

/// One path's measurement.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct PathCost {
    /// The path, as messages name it (`cost::Path::describe`).
    pub path: String,
    /// The scene it was timed on.
    pub scene: String,
    pub n: usize,
    pub steps: u64,
    /// Median over the rounds, ns per block-step.
    pub measured_ns: f64,
    /// The model's ns per block-step (`cost::Path::ns_per_block_step`).
    pub model_ns: f64,
    /// The model's weight (block-steps of the paper's model by Verlet).
    pub weight: f64,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct CostReport {
    pub rounds: usize,
    pub paths: Vec<PathCost>,
}

/// A workload: a scenario stepped by `config` as `stepping` says.
struct Workload {
    scene: String,
    scenario: Scenario,
    config: IntegratorConfig,
    stepping: Stepping,
}

/// `scene` (a catalogue movie's id, or None for the paper's model) at
/// `n` blocks, run by `kind` at `dt` for about [`BLOCK_STEPS`].
fn workload(
    id: Option<&str>,
    n: Option<usize>,
    kind: IntegratorKind,
    dt: f64,
    stepping: Stepping,
) -> Result<Workload> {
    let mut scene = match id {
        Some(id) => crate::catalog::find(crate::scene::Kind::Movie, id)?
            .scene
            .clone(),
        None => Scene::default(),
    };
    if id == Some(RIBBONS) && kind != IntegratorKind::Moreau {
        // The ribbons' force path: the scene's tank with stiff ribbons,
        // which RK4 steps (its own inextensible ones only Moreau does).
        if let Some(a) = scene.apparatus.as_mut() {
            a.stiffness = Stiffness::Word(StiffWord::Stiff);
        }
    }
    if let Some(n) = n {
        scene.model.n = n;
    }
    if let Some(a) = scene.apparatus.as_mut() {
        a.conversion = None;
    }
    let scene = scene.with_conversion();
    let mut scenario = scene.scenario()?;
    // RK4 within the contact's stable step (`sim::check_terms` refuses a
    // longer one): the largest power-of-two fraction of `dt` inside it.
    let mut dt = dt;
    if let Some(bound) = contact_step_bound(&scenario)
        && kind == IntegratorKind::Rk4
    {
        while dt > bound {
            dt /= 2.0;
        }
    }
    let n = scenario.ladder.n() as f64;
    scenario.t_end = (BLOCK_STEPS / n).ceil() * dt;
    Ok(Workload {
        scene: format!("{} N = {}", id.unwrap_or("paper"), n),
        scenario,
        config: IntegratorConfig::fixed(kind, dt),
        stepping,
    })
}

/// The RK4 step bound of a scenario whose blocks touch
/// (`model::contact::Contact::rk4_step_bound`).
fn contact_step_bound(scenario: &Scenario) -> Option<f64> {
    let built = scenario.ladder.built?;
    let contact = built.contact?;
    Some(contact.rk4_step_bound(scenario.ladder.blocks(), &built.ribbons.outline))
}

/// The workloads: the paper's model by every scheme (and symplectic
/// Euler on its kernel), then each apparatus by RK4 at 0.125 τ (the
/// experiments' scheme; a power-of-two fraction of it inside the
/// contact's stable step where blocks touch) at its own N and at a
/// larger N, and the tank as built by Moreau at its catalogue step with
/// its own inextensible ribbons.
fn workloads() -> Result<Vec<Workload>> {
    use IntegratorKind::*;
    let mut w = Vec::new();
    // Moreau's steps take inextensible ribbons only: it is timed on the
    // tank as built below, not on the paper's model.
    for kind in IntegratorKind::ALL.into_iter().filter(|k| *k != Moreau) {
        w.push(workload(None, Some(1000), kind, 0.01, Stepping::Portable)?);
    }
    w.push(workload(
        None,
        Some(1000),
        SymplecticEuler,
        0.01,
        Stepping::Fastest,
    )?);
    for id in ["water-tank", "linkage-69", RIBBONS] {
        // The ribbons' contact grows with N: N = 200 shows it.
        let big = if id == RIBBONS { 200 } else { 1000 };
        for n in [None, Some(big)] {
            w.push(workload(Some(id), n, Rk4, 0.125, Stepping::Portable)?);
        }
    }
    for n in [None, Some(200)] {
        w.push(workload(
            Some(RIBBONS),
            n,
            Moreau,
            MOREAU_DT,
            Stepping::Portable,
        )?);
    }
    Ok(w)
}

/// Times every workload `rounds` times, interleaved; `tick` after each run.
pub fn cost(rounds: usize, tick: &(dyn Fn(&str) + Sync)) -> Result<CostReport> {
    let work = workloads()?;
    let mut times = vec![Vec::new(); work.len()];
    let mut steps = vec![0u64; work.len()];
    for _ in 0..rounds {
        for (k, w) in work.iter().enumerate() {
            let options = sim::RunOptions::default()
                .stepping(w.stepping)
                .limits(crate::limits::Limits::none());
            let start = Instant::now();
            let t = sim::run(&w.scenario, &[], &w.config, &options)?;
            times[k].push(start.elapsed().as_secs_f64());
            steps[k] = t.steps;
            tick(&w.scene);
        }
    }
    let paths = work
        .iter()
        .zip(times)
        .zip(steps)
        .map(|((w, t), steps)| {
            let n = w.scenario.ladder.n();
            let path = Path::of(&w.scenario.ladder, w.config.kind, w.stepping);
            PathCost {
                path: path.describe(),
                scene: w.scene.clone(),
                n,
                steps,
                measured_ns: median(t) * 1e9 / (steps as f64 * n as f64),
                model_ns: path.ns_per_block_step(),
                weight: path.weight(),
            }
        })
        .collect();
    Ok(CostReport { rounds, paths })
}

/// The report as a Markdown table (docs/limits.md).
pub fn cost_table(report: &CostReport) -> String {
    let mut s = format!(
        "median of {} rounds; the unit of the cap is the paper's model by Verlet, {} ns in \
         the model\n\n| path | run | measured ns per block-step | model ns | weight |\n\
         |---|---|---|---|---|\n",
        report.rounds, REFERENCE_NS
    );
    for p in &report.paths {
        s += &format!(
            "| {} | {}, {} steps | {:.1} | {:.1} | {:.2} |\n",
            p.path, p.scene, p.steps, p.measured_ns, p.model_ns, p.weight
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_workload_is_one_its_integrator_takes() {
        // `bench cost` stopped at its first refused run (RK4 at 0.125 τ
        // on the tank as built, outside the contact's stable step): each
        // workload must pass the checks a run makes before any work.
        for w in workloads().unwrap() {
            sim::check_terms(&w.scenario.ladder, &w.config)
                .unwrap_or_else(|e| panic!("{}: {e}", w.scene));
        }
    }

    #[test]
    fn moreau_is_timed_on_the_tank_as_built() {
        let kinds: Vec<_> = workloads()
            .unwrap()
            .iter()
            .filter(|w| w.config.kind == IntegratorKind::Moreau)
            .map(|w| w.scene.clone())
            .collect();
        assert_eq!(kinds.len(), 2, "{kinds:?}");
        assert!(kinds.iter().all(|s| s.starts_with(RIBBONS)), "{kinds:?}");
    }
}
