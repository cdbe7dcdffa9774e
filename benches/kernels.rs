//! Cost per block-step of symplectic Euler at the paper's dt = 0.01:
//!
//! - `block_step_vs_n/{fastest,portable}/N`: one run of N blocks (N = 2 to
//!   100 000) with the fastest kernel this CPU has (the fused kernel in
//!   registers for N ≤ 32, the chain kernel beyond) and on the portable
//!   path, on one core;
//! - `block_step_vs_runs/{batch,one_by_one}/R`: a sweep of R kinks of
//!   N = 10 (α from 40° to 89.5°, 100 τ each) as lanes of the batch
//!   kernel, and one by one with the fused kernel, on every core.
//!
//! Criterion's throughput is in block-steps ("elements") per second:
//! ns per block-step = 1e9 / that.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use jacobs_ladder::bench::kernels::sweep_scenarios;
use jacobs_ladder::model::Params;
use jacobs_ladder::sim::RunOptions;
use jacobs_ladder::sim::{self, IntegratorConfig, Scenario, Stepping, batch};
use rayon::prelude::*;
use std::hint::black_box;
use std::time::Duration;

/// About this many block-steps per iteration of the N scan.
const BLOCK_STEPS: f64 = 2e6;

fn block_step_vs_n(c: &mut Criterion) {
    let config = IntegratorConfig::paper();
    let mut group = c.benchmark_group("block_step_vs_n");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    for n in [2, 4, 10, 32, 33, 100, 1000, 10_000, 100_000] {
        let steps = (BLOCK_STEPS / n as f64).ceil().max(100.0);
        let params = Params::paper(60.0).unwrap().with(n, 1.3, 60.0).unwrap();
        let scenario = Scenario::single_flip(params, 1000.0, steps * config.dt).unwrap();
        let per_run = sim::run(
            &scenario,
            &[],
            &config,
            &RunOptions::default()
                .stepping(Stepping::Portable)
                .every_step(false),
        )
        .unwrap()
        .steps;
        group.throughput(Throughput::Elements(per_run * n as u64));
        for (name, stepping) in [
            ("fastest", Stepping::Fastest),
            ("portable", Stepping::Portable),
        ] {
            group.bench_function(format!("{name}/{n}"), |b| {
                b.iter(|| {
                    sim::run(
                        black_box(&scenario),
                        &[],
                        &config,
                        &RunOptions::default().stepping(stepping).every_step(false),
                    )
                    .unwrap()
                })
            });
        }
    }
    group.finish();
}

fn block_step_vs_runs(c: &mut Criterion) {
    let config = IntegratorConfig::paper();
    let mut group = c.benchmark_group("block_step_vs_runs");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    for runs in [1, 2, 8, 16, 64, 256, 1000] {
        let scenarios = sweep_scenarios(runs, 10, 100.0).unwrap();
        // One run alone, as the batch kernel runs it (the wave tracker fed
        // at the checks).
        let alone = RunOptions::default()
            .stepping(Stepping::Fastest)
            .every_step(false);
        let steps: u64 = scenarios
            .iter()
            .map(|sc| sim::run(sc, &[], &config, &alone).unwrap().steps)
            .sum();
        group.throughput(Throughput::Elements(steps * 10));
        group.bench_function(format!("batch/{runs}"), |b| {
            b.iter(|| batch::simulate_many(black_box(&scenarios), &config, &RunOptions::default()))
        });
        group.bench_function(format!("one_by_one/{runs}"), |b| {
            b.iter(|| {
                black_box(&scenarios)
                    .par_iter()
                    .map(|sc| sim::run(sc, &[], &config, &alone))
                    .collect::<Vec<_>>()
            })
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    // No HTML plots: criterion's plotters backend finds no system font here.
    config = Criterion::default().without_plots();
    targets = block_step_vs_n, block_step_vs_runs
}
criterion_main!(benches);
