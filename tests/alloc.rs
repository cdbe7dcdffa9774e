//! No allocation inside the step loop: a run ten times longer makes exactly
//! as many allocations (counted by a global allocator in this test binary).

use jacobs_ladder::model::Params;
use jacobs_ladder::sim::{self, IntegratorConfig, IntegratorKind, Scenario, Stepping};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicU64, Ordering};

struct Counting;

static ALLOCATIONS: AtomicU64 = AtomicU64::new(0);

// SAFETY: forwards to the system allocator; only counts.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Allocations made by one run of the paper's kink scene to `t_end`.
fn allocations(t_end: f64, config: &IntegratorConfig, stepping: Stepping) -> u64 {
    let params = Params::paper(60.0).unwrap();
    let scenario = Scenario::single_flip(params, 100.0, t_end).unwrap();
    let before = ALLOCATIONS.load(Ordering::Relaxed);
    let traj = sim::simulate_with(&scenario, &[], config, stepping).unwrap();
    let after = ALLOCATIONS.load(Ordering::Relaxed);
    assert!(traj.steps > 0);
    after - before
}

#[test]
fn step_loop_does_not_allocate() {
    let configs = [
        IntegratorConfig::paper(),
        IntegratorConfig::fixed(IntegratorKind::ExplicitEuler, 0.002),
        IntegratorConfig::fixed(IntegratorKind::Verlet, 0.1),
        IntegratorConfig::fixed(IntegratorKind::Rk4, 0.1),
        IntegratorConfig::adaptive(1e-6),
    ];
    for config in configs {
        for stepping in [Stepping::Fastest, Stepping::Portable] {
            // The fewest of three runs each: the test harness's own threads
            // allocate now and then while a run is timed (seen on a loaded
            // machine, a few allocations either way), which a minimum
            // filters out; an allocation per step or per check would not be.
            let fewest = |t_end| (0..3).map(|_| allocations(t_end, &config, stepping)).min();
            let short = fewest(200.0).unwrap();
            let long = fewest(2000.0).unwrap();
            assert_eq!(short, long, "{config:?}, {stepping:?}");
        }
    }
}
