//! `bench kernels`: three workloads timed with every way of stepping them
//! that this CPU offers (`sim::Stepping`), in interleaved rounds so that a
//! shared machine's slow and fast phases fall on all of them alike, each
//! checked to give the portable path's trajectories bit for bit:
//!
//! - the paper's run (symplectic Euler, dt = 0.01, 4 × 10^5 steps, N = 10,
//!   α = 60°): the fused kernel (`sim::fused`);
//! - a sweep of [`SWEEP_RUNS`] kinks (N = 10, α from 40° to 89.5°): the
//!   batch kernel (`sim::batch`, one run per SIMD lane, every core) against
//!   the runs one by one on every core;
//! - a long chain (N = [`CHAIN_N`]): the chain kernel (`sim::chain`).

use super::median;
use crate::error::{Error, Result};
use crate::model::Params;
use crate::sim::{self, IntegratorConfig, Isa, Scenario, Stepping, Trajectory, batch};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::time::Instant;

/// Runs in the sweep workload.
pub const SWEEP_RUNS: usize = 32;
/// The sweep's runs: N = 10, T_d = 1000 τ, simulated to this time.
pub const SWEEP_T_END: f64 = 1500.0;
/// Blocks of the chain workload.
pub const CHAIN_N: usize = 1000;
/// The chain's run: α = 60°, T_d = 100 τ, simulated to this time.
pub const CHAIN_T_END: f64 = 200.0;

/// One kernel's timings.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct KernelTiming {
    /// `fastest`, `avx2`, `avx512` or `portable` (as `simulate --kernel`).
    pub kernel: String,
    pub median_ms: f64,
    pub min_ms: f64,
    /// The portable path's median over this one's.
    pub speedup: f64,
    /// Whether the final state and arrival times equal the portable path's.
    pub same_as_portable: bool,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct KernelReport {
    /// The paper's run: its steps and each kernel's timing.
    pub steps: u64,
    pub rounds: usize,
    pub kernels: Vec<KernelTiming>,
    /// Many runs at once.
    pub sweep: WorkloadReport,
    /// One long ladder.
    pub chain: WorkloadReport,
}

/// A workload of `runs` runs of N blocks, timed with each way of running it.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct WorkloadReport {
    pub what: String,
    pub runs: usize,
    pub n: usize,
    /// Steps times blocks over all runs.
    pub block_steps: u64,
    pub kernels: Vec<WorkloadTiming>,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct WorkloadTiming {
    pub kernel: String,
    /// Wall-clock time of the whole workload.
    pub median_ms: f64,
    pub min_ms: f64,
    /// The median wall-clock time per block-step, in ns.
    pub ns_per_block_step: f64,
    /// The first kernel's (the portable path's) median over this one's.
    pub speedup: f64,
    /// Whether every run's final state, arrival times and step count equal
    /// the portable path's.
    pub same_as_portable: bool,
}

/// The kernels this CPU runs, by their `--kernel` names.
fn available() -> Vec<(&'static str, Stepping)> {
    let fused = [Isa::Avx2, Isa::Avx512]
        .into_iter()
        .filter(|isa| isa.available())
        .map(|isa| (isa.name(), Stepping::Fused(isa)));
    [
        ("portable", Stepping::Portable),
        ("fastest", Stepping::Fastest),
    ]
    .into_iter()
    .chain(fused)
    .collect()
}

/// How many timed runs [`kernels`] makes per round on this CPU (the
/// paper's run, the sweep and the chain, with each kernel).
pub fn kernel_count() -> usize {
    available().len() + sweep_ways().len() + chain_ways().len()
}

/// Ways to run the sweep: (name, stepping, whether as a batch).
fn sweep_ways() -> Vec<(String, Stepping, bool)> {
    let mut ways = vec![
        ("portable".to_string(), Stepping::Portable, false),
        ("one-by-one".to_string(), Stepping::Fastest, false),
        ("batch".to_string(), Stepping::Fastest, true),
    ];
    for isa in [Isa::Avx2, Isa::Avx512]
        .into_iter()
        .filter(|i| i.available())
    {
        ways.push((format!("batch-{}", isa.name()), Stepping::Fused(isa), true));
    }
    ways
}

/// Ways to run the chain: the kernels of the paper's run.
fn chain_ways() -> Vec<(String, Stepping, bool)> {
    available()
        .into_iter()
        .map(|(name, stepping)| (name.to_string(), stepping, false))
        .collect()
}

/// The sweep workload's scenarios: kinks, N = 10, α from 40° to 89.5°.
pub fn sweep_scenarios(runs: usize, n: usize, t_end: f64) -> Result<Vec<Scenario>> {
    (0..runs)
        .map(|k| {
            let alpha = 40.0 + 49.5 * k as f64 / (runs.max(2) - 1) as f64;
            let params = Params::paper(alpha)?.with(n, 1.3, alpha)?;
            Scenario::single_flip(params, sim::PAPER_DRIVE_TIME, t_end)
        })
        .collect()
}

/// Times `scenarios` with each of `ways`, interleaved, `rounds` times.
fn workload(
    what: &str,
    scenarios: &[Scenario],
    ways: &[(String, Stepping, bool)],
    rounds: usize,
    progress: &dyn Fn(&str),
) -> Result<WorkloadReport> {
    let config = IntegratorConfig::paper();
    let mut times = vec![Vec::with_capacity(rounds); ways.len()];
    let mut results: Vec<Vec<Option<Trajectory>>> = vec![Vec::new(); ways.len()];
    for round in 0..rounds {
        for (k, (name, stepping, as_batch)) in ways.iter().enumerate() {
            progress(&format!("round {} of {rounds}, {what}, {name}", round + 1));
            let start = Instant::now();
            let runs = if *as_batch || *stepping == Stepping::Portable {
                batch::simulate_many(
                    scenarios,
                    &config,
                    &sim::RunOptions::default().stepping(*stepping),
                )
            } else {
                scenarios
                    .par_iter()
                    .map(|sc| {
                        let options = sim::RunOptions::default()
                            .stepping(*stepping)
                            .every_step(false);
                        sim::run(sc, &[], &config, &options)
                    })
                    .collect()
            };
            times[k].push(start.elapsed().as_secs_f64() * 1e3);
            results[k] = runs.into_iter().map(|r| r.ok()).collect();
        }
    }
    let same = |a: &Option<Trajectory>, b: &Option<Trajectory>| match (a, b) {
        (Some(a), Some(b)) => {
            a.final_state == b.final_state
                && a.arrival_times == b.arrival_times
                && a.steps == b.steps
        }
        _ => false,
    };
    let portable = &results[0];
    let block_steps: u64 = portable
        .iter()
        .zip(scenarios)
        .map(|(r, sc)| r.as_ref().map_or(0, |t| t.steps) * sc.ladder.n() as u64)
        .sum();
    let base = median(times[0].clone());
    let kernels = ways
        .iter()
        .zip(&times)
        .zip(&results)
        .map(|(((name, _, _), t), runs)| {
            let med = median(t.clone());
            WorkloadTiming {
                kernel: name.clone(),
                median_ms: med,
                min_ms: t.iter().copied().fold(f64::INFINITY, f64::min),
                ns_per_block_step: med * 1e6 / block_steps as f64,
                speedup: base / med,
                same_as_portable: !runs.is_empty()
                    && runs.len() == portable.len()
                    && runs.iter().zip(portable).all(|(a, b)| same(a, b)),
            }
        })
        .collect();
    Ok(WorkloadReport {
        what: what.to_string(),
        runs: scenarios.len(),
        n: scenarios.first().map_or(0, |sc| sc.ladder.n()),
        block_steps,
        kernels,
    })
}

/// Times the paper's run, the sweep and the chain `rounds` times with each
/// kernel; `progress` is told of every run as it starts.
pub fn kernels(rounds: usize, progress: &dyn Fn(&str)) -> Result<KernelReport> {
    let params = Params::paper(60.0)?;
    let scenario = Scenario::single_flip(params, sim::PAPER_DRIVE_TIME, 4000.0)?;
    let config = IntegratorConfig::paper();
    let kernels = available();
    let mut times = vec![Vec::with_capacity(rounds); kernels.len()];
    let mut results: Vec<Option<Trajectory>> = vec![None; kernels.len()];
    for round in 0..rounds {
        for (k, (name, stepping)) in kernels.iter().enumerate() {
            progress(&format!("round {} of {rounds}, {name}", round + 1));
            let start = Instant::now();
            let traj = sim::run(
                &scenario,
                &[],
                &config,
                &sim::RunOptions::default().stepping(*stepping),
            )?;
            times[k].push(start.elapsed().as_secs_f64() * 1e3);
            results[k] = Some(traj);
        }
    }
    let portable = results[0]
        .clone()
        .ok_or_else(|| Error::bad_input("bench kernels needs at least one round"))?;
    let portable_median = median(times[0].clone());
    let timings = kernels
        .iter()
        .zip(times)
        .zip(&results)
        .map(|(((name, _), t), traj)| {
            let same = traj.as_ref().is_some_and(|tr| {
                tr.final_state == portable.final_state && tr.arrival_times == portable.arrival_times
            });
            let med = median(t.clone());
            KernelTiming {
                kernel: name.to_string(),
                median_ms: med,
                min_ms: t.iter().copied().fold(f64::INFINITY, f64::min),
                speedup: portable_median / med,
                same_as_portable: same,
            }
        })
        .collect();
    let sweep = workload(
        "sweep",
        &sweep_scenarios(SWEEP_RUNS, 10, SWEEP_T_END)?,
        &sweep_ways(),
        rounds,
        progress,
    )?;
    let chain_params = Params::paper(60.0)?.with(CHAIN_N, 1.3, 60.0)?;
    let chain = workload(
        "chain",
        &[Scenario::single_flip(chain_params, 100.0, CHAIN_T_END)?],
        &chain_ways(),
        rounds,
        progress,
    )?;
    Ok(KernelReport {
        steps: portable.steps,
        rounds,
        kernels: timings,
        sweep,
        chain,
    })
}

/// The report as a table.
pub fn kernels_table(report: &KernelReport) -> String {
    let mut out = format!(
        "the paper's run: symplectic Euler, dt = 0.01, {} steps, N = 10, α = 60° \
         ({} interleaved rounds)\n",
        report.steps, report.rounds
    );
    out.push_str("kernel     median (ms)  min (ms)  speed-up  same trajectory as portable\n");
    for k in &report.kernels {
        out.push_str(&format!(
            "{:<10} {:>11.1} {:>9.1} {:>8.2}×  {}\n",
            k.kernel,
            k.median_ms,
            k.min_ms,
            k.speedup,
            if k.same_as_portable {
                "yes, bit for bit"
            } else {
                "NO"
            }
        ));
    }
    for (w, title) in [
        (
            &report.sweep,
            format!(
                "a sweep: {} kinks, N = {}, α from 40° to 89.5°, to {} τ, every core",
                report.sweep.runs, report.sweep.n, SWEEP_T_END
            ),
        ),
        (
            &report.chain,
            format!(
                "a long chain: N = {}, α = 60°, to {} τ, one core",
                report.chain.n, CHAIN_T_END
            ),
        ),
    ] {
        out.push_str(&format!(
            "\n{title} ({:.2e} block-steps)\n",
            w.block_steps as f64
        ));
        out.push_str(
            "kernel        median (ms)  min (ms)  ns/block-step  speed-up  same as portable\n",
        );
        for k in &w.kernels {
            out.push_str(&format!(
                "{:<13} {:>11.1} {:>9.1} {:>14.2} {:>8.2}×  {}\n",
                k.kernel,
                k.median_ms,
                k.min_ms,
                k.ns_per_block_step,
                k.speedup,
                if k.same_as_portable {
                    "yes, bit for bit"
                } else {
                    "NO"
                }
            ));
        }
    }
    out
}
