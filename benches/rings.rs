//! The ring chain's cost (docs/rings.md, docs/performance.md): the default 30-ring chain (movie
//! 12's, its partner strand taped) for 1 s of chain time, timed three
//! times; prints the time per step and per contact pair tested, the share
//! of the pair searches answered warm (`rings::warm`), and what
//! 10 s of chain time (the movie) takes at that rate. Run with
//! `cargo bench --bench rings`; the machine's other work counts too.

use jacobs_ladder::rings::{self, RingChain};
use std::time::Instant;

fn main() {
    let tapes = (1..28).step_by(2).map(|k| [k, k + 2]).collect();
    let chain = RingChain {
        t_end: 1.0,
        tapes,
        ..Default::default()
    };
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..3 {
        let start = Instant::now();
        let run = rings::run(&chain, &[]).expect("the chain runs");
        best = best.min(start.elapsed().as_secs_f64());
        last = Some(run);
    }
    let run = last.expect("three runs");
    let steps = run.stats.steps as f64;
    let pairs = run.stats.pair_evaluations as f64;
    let warm = 1.0 - run.system.stats.full_searches as f64 / pairs;
    println!(
        "rings/30 taped, 1 s of chain time: {best:.3} s (best of 3), {steps} steps of {:.3e} s, \
         {:.1} µs/step, {:.1} pairs tested per step, {:.2} µs per pair, {:.1} % of the pair searches warm; 10 s of chain time: {:.1} s",
        run.dt,
        best / steps * 1e6,
        pairs / steps,
        best / pairs * 1e6,
        100.0 * warm,
        10.0 * best
    );
}
