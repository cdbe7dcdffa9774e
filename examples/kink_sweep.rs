//! A sweep of kinks over α as one process, for timing against the numba
//! peer (benches/peers/): N = 10 by default, α from 40° to 89.5°, the
//! paper's drive, symplectic Euler at dt = 0.01, every core.
//!
//! ```text
//! cargo run --release --example kink_sweep -- --runs 100 [--n 10] [--t-end 4000]
//!     [--dt 0.01] [--alpha-from 40] [--alpha-to 89.5]
//!     [--mode batch|one-by-one|portable] [--stop never|reached]
//!     [--integrator symplectic-euler|verlet]
//! ```
//!
//! `batch` runs the runs as lanes of the batch kernel (`sim::batch`, for
//! symplectic Euler and velocity Verlet),
//! `one-by-one` each with the fused kernel on every core, `portable` each
//! on the portable path. `--stop reached` ends a run once the wave has
//! reached block N − 1 (a crude stand-in for the sweep's outcome rule).
//! Prints one JSON object: each run's α, arrival times, steps and end
//! time, and the wall time.

use jacobs_ladder::model::Params;
use jacobs_ladder::sim::{self, IntegratorConfig, IntegratorKind, Stepping, batch};
use rayon::prelude::*;
use std::time::Instant;

fn main() {
    if let Err(e) = run() {
        eprintln!("kink_sweep: {e}");
        std::process::exit(2);
    }
}

fn run() -> Result<(), String> {
    let mut runs = 100usize;
    let mut n = 10usize;
    let mut t_end = 4000.0;
    let mut dt = 0.01;
    let (mut from, mut to) = (40.0, 89.5);
    let mut mode = "batch".to_string();
    let mut stop_rule = "never".to_string();
    let mut integrator = "symplectic-euler".to_string();
    let args: Vec<String> = std::env::args().skip(1).collect();
    for pair in args.chunks(2) {
        let [flag, value] = pair else {
            return Err(format!("{} needs a value", pair[0]));
        };
        let num = |v: &str| v.parse::<f64>().map_err(|e| format!("{flag}: {e}"));
        match flag.as_str() {
            "--runs" => runs = num(value)? as usize,
            "--n" => n = num(value)? as usize,
            "--t-end" => t_end = num(value)?,
            "--dt" => dt = num(value)?,
            "--alpha-from" => from = num(value)?,
            "--alpha-to" => to = num(value)?,
            "--mode" => mode = value.clone(),
            "--stop" => stop_rule = value.clone(),
            "--integrator" => integrator = value.clone(),
            _ => return Err(format!("unknown flag {flag}")),
        }
    }
    let scenarios: Vec<sim::Scenario> = (0..runs)
        .map(|k| {
            let alpha = from + (to - from) * k as f64 / (runs.max(2) - 1) as f64;
            let params = Params::paper(alpha)?.with(n, 1.3, alpha)?;
            sim::Scenario::single_flip(params, sim::PAPER_DRIVE_TIME, t_end)
        })
        .collect::<Result<_, _>>()
        .map_err(|e| e.to_string())?;
    let kind: IntegratorKind = integrator
        .parse()
        .map_err(|e: jacobs_ladder::Error| e.to_string())?;
    let config = IntegratorConfig::fixed(kind, dt);
    let reached =
        |v: &sim::StopView| v.arrivals.len() >= 2 && v.arrivals[v.arrivals.len() - 2].is_some();
    let stop: &sim::StopRule = match stop_rule.as_str() {
        "never" => &sim::run_to_end,
        "reached" => &reached,
        other => return Err(format!("unknown stop rule {other}")),
    };
    let options = sim::RunOptions::default().stop(stop);
    let start = Instant::now();
    let results = match mode.as_str() {
        "batch" => batch::simulate_many(&scenarios, &config, &options),
        "portable" => {
            batch::simulate_many(&scenarios, &config, &options.stepping(Stepping::Portable))
        }
        "one-by-one" => scenarios
            .par_iter()
            .map(|sc| sim::run(sc, &[], &config, &options.every_step(false)))
            .collect(),
        other => return Err(format!("unknown mode {other}")),
    };
    let wall = start.elapsed().as_secs_f64();
    let mut block_steps = 0u64;
    let mut out = Vec::new();
    for (sc, r) in scenarios.iter().zip(&results) {
        let t = r.as_ref().map_err(|e| e.to_string())?;
        block_steps += t.steps * n as u64;
        out.push(serde_json::json!({
            "alpha_deg": sc.ladder.params.alpha_deg(),
            "arrival_times": t.arrival_times,
            "steps": t.steps,
            "t_final": t.t_final,
            "final_theta_deg": t.final_theta_deg(),
        }));
    }
    let report = serde_json::json!({
        "mode": mode,
        "n": n,
        "runs": out,
        "wall_seconds": wall,
        "ns_per_block_step": wall * 1e9 / block_steps as f64,
    });
    println!("{report}");
    Ok(())
}
