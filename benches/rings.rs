//! The ring chain's cost (docs/rings.md, docs/performance.md): the default
//! 30-ring chain (the double chain, its partner strand taped: movie 12's
//! until it took the tumbling rings) for 1 s of chain time, with the full
//! contact search and with the warm-started one (`rings::warm`, the
//! default), each timed three times; prints the
//! time per step and per contact pair tested, the share of the pair
//! searches answered warm, and what 10 s of chain time (the movie's
//! simulation) takes at that rate. Run with `cargo bench --bench rings`;
//! the machine's other work counts too.

use jacobs_ladder::rings::system::Search;
use jacobs_ladder::rings::{RingChain, build};
use std::time::Instant;

fn main() {
    let tapes = (1..28).step_by(2).map(|k| [k, k + 2]).collect();
    let chain = RingChain {
        t_end: 1.0,
        tapes,
        ..Default::default()
    };
    for search in [Search::Full, Search::Warm] {
        let mut best = f64::INFINITY;
        let mut last = None;
        for _ in 0..3 {
            let mut sys = build::build(&chain).expect("the chain builds");
            sys.search = search;
            let steps = (chain.t_end / sys.dt).ceil() as u64;
            let start = Instant::now();
            for _ in 0..steps {
                sys.step().expect("the chain steps");
            }
            best = best.min(start.elapsed().as_secs_f64());
            last = Some(sys);
        }
        let sys = last.expect("three runs");
        let steps = sys.stats.steps as f64;
        let pairs = sys.stats.pair_evaluations as f64;
        let warm = 1.0 - sys.stats.full_searches as f64 / pairs;
        println!(
            "rings/30 taped, {search:?} search, 1 s of chain time: {best:.3} s (best of 3), \
             {steps} steps of {:.3e} s, {:.1} µs/step, {:.1} pairs tested per step, \
             {:.2} µs per pair, {:.1} % of the pair searches warm; 10 s of chain time: {:.1} s",
            sys.dt,
            best / steps * 1e6,
            pairs / steps,
            best / pairs * 1e6,
            100.0 * warm,
            10.0 * best
        );
    }
}
