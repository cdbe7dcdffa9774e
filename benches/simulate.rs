//! The paper's run (symplectic Euler, dt = 0.01, 4 × 10^5 steps, N = 10,
//! α = 60°) and one force evaluation.

use criterion::{Criterion, criterion_group, criterion_main};
use jacobs_ladder::model::ladder::ForceScratch;
use jacobs_ladder::model::{Ladder, Params};
use jacobs_ladder::sim::{self, IntegratorConfig, Scenario};
use std::hint::black_box;

fn paper_run(c: &mut Criterion) {
    let params = Params::paper(60.0).unwrap();
    let scenario = Scenario::single_flip(params, sim::PAPER_DRIVE_TIME, 4000.0).unwrap();
    let config = IntegratorConfig::paper();
    let mut group = c.benchmark_group("simulate");
    group.sample_size(10);
    group.bench_function("paper_kink_4e5_steps", |b| {
        b.iter(|| sim::simulate(black_box(&scenario), &[], &config).unwrap())
    });
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

criterion_group!(benches, paper_run, force_evaluation);
criterion_main!(benches);
