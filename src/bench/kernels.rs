//! `bench kernels`: the paper's run (symplectic Euler, dt = 0.01,
//! 4 × 10^5 steps, N = 10, α = 60°) timed with every way of stepping it
//! that this CPU offers (`sim::Stepping`), in interleaved rounds so that a
//! shared machine's slow and fast phases fall on all of them alike, and
//! checked to give the portable path's trajectory bit for bit.

use super::median;
use crate::error::{Error, Result};
use crate::model::Params;
use crate::sim::{self, IntegratorConfig, Isa, Scenario, Stepping, Trajectory};
use serde::{Deserialize, Serialize};
use std::time::Instant;

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
    pub steps: u64,
    pub rounds: usize,
    pub kernels: Vec<KernelTiming>,
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

/// How many kernels [`kernels`] times on this CPU.
pub fn kernel_count() -> usize {
    available().len()
}

/// Times the paper's run `rounds` times with each kernel; `progress` is
/// told of every run as it starts.
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
            let traj = sim::simulate_with(&scenario, &[], &config, *stepping)?;
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
    Ok(KernelReport {
        steps: portable.steps,
        rounds,
        kernels: timings,
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
    out
}
