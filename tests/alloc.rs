//! No allocation inside the step loop: a run ten times longer makes exactly
//! as many allocations (counted by a global allocator in this test binary,
//! on the thread that runs the simulation only: the test harness's own
//! thread may allocate at any time).

use jacobs_ladder::model::Params;
use jacobs_ladder::sim::{self, IntegratorConfig, IntegratorKind, Scenario, Stepping};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicU64, Ordering};

struct Counting;

static ALLOCATIONS: AtomicU64 = AtomicU64::new(0);

thread_local! {
    /// Whether this thread's allocations are counted.
    static COUNTED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

// SAFETY: forwards to the system allocator; only counts.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if COUNTED.with(|c| c.get()) {
            ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        }
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

/// Allocations made by one run of the kink scene of `n` blocks to `t_end`.
fn allocations(n: usize, t_end: f64, config: &IntegratorConfig, stepping: Stepping) -> u64 {
    let params = Params::paper(60.0).unwrap().with(n, 1.3, 60.0).unwrap();
    let scenario = Scenario::single_flip(params, 100.0, t_end).unwrap();
    COUNTED.with(|c| c.set(true));
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
            let short = allocations(10, 200.0, &config, stepping);
            let long = allocations(10, 2000.0, &config, stepping);
            assert_eq!(short, long, "{config:?}, {stepping:?}");
        }
    }
    // The chain kernel (N > 32).
    let config = IntegratorConfig::paper();
    let short = allocations(40, 200.0, &config, Stepping::Fastest);
    let long = allocations(40, 2000.0, &config, Stepping::Fastest);
    assert_eq!(short, long, "chain kernel");
}
