//! The paper's run (symplectic Euler, dt = 0.01, 4 × 10^5 steps, N = 10,
//! α = 60°) with each way of stepping it (the fused kernel for the best
//! instruction set, for AVX2, and the portable path), and one force
//! evaluation.

use criterion::{Criterion, criterion_group, criterion_main};
use jacobs_ladder::model::ladder::ForceScratch;
use jacobs_ladder::model::{Ladder, Params};
use jacobs_ladder::sim::RunOptions;
use jacobs_ladder::sim::{self, IntegratorConfig, Isa, Scenario, Stepping};
use std::hint::black_box;

fn paper_run(c: &mut Criterion) {
    let params = Params::paper(60.0).unwrap();
    let scenario = Scenario::single_flip(params, sim::PAPER_DRIVE_TIME, 4000.0).unwrap();
    let config = IntegratorConfig::paper();
    let mut group = c.benchmark_group("simulate");
    group.sample_size(10);
    let steppings = [
        ("fastest", Stepping::Fastest),
        ("avx2", Stepping::Fused(Isa::Avx2)),
        ("portable", Stepping::Portable),
    ];
    for (name, stepping) in steppings {
        group.bench_function(format!("paper_kink_4e5_steps/{name}"), |b| {
            b.iter(|| {
                sim::run(
                    black_box(&scenario),
                    &[],
                    &config,
                    &RunOptions::default().stepping(stepping),
                )
                .unwrap()
            })
        });
    }
    group.finish();
}

fn force_evaluation(c: &mut Criterion) {
    let ladder = Ladder::new(Params::paper(60.0).unwrap());
    let q = ladder.ground_state();
    let mut grad = vec![0.0; q.len()];
    let mut scratch = ForceScratch::new(ladder.n());
    c.bench_function("gradient_n10", |b| {
        b.iter(|| ladder.gradient_with(black_box(&q), &mut grad, &mut scratch))
    });
}

criterion_group! {
    name = benches;
    // No HTML plots: criterion's plotters backend finds no system font here.
    config = Criterion::default().without_plots();
    targets = paper_run, force_evaluation
}
criterion_main!(benches);
