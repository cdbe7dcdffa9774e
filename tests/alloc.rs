//! No allocation inside the step loop: a run twice as long makes at most a
//! few hundred more allocations (the wave tracker allocates per event, a
//! launched wave or a sign change of block N, never per step), against the
//! tens of thousands of extra steps it takes (counted by a global allocator in this test binary,
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
    let scenario = Scenario::single_flip(params, 1000.0, t_end).unwrap();
    COUNTED.with(|c| c.set(true));
    let before = ALLOCATIONS.load(Ordering::Relaxed);
    let traj = sim::simulate_with(&scenario, &[], config, stepping).unwrap();
    let after = ALLOCATIONS.load(Ordering::Relaxed);
    assert!(traj.steps > 0);
    after - before
}

/// Allocations a longer run may add for events (a wave launched, a sign
/// change of block N recorded), not steps: the longer runs below take at
/// least 4 × 10⁴ more steps, so one allocation per step (or per hundred)
/// exceeds this by far.
const EVENTS: u64 = 400;

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
            let short = allocations(10, 8000.0, &config, stepping);
            let long = allocations(10, 16000.0, &config, stepping);
            assert!(
                long - short <= EVENTS,
                "{config:?}, {stepping:?}: {short} then {long}"
            );
        }
    }
    // The chain kernel (N > 32).
    let config = IntegratorConfig::paper();
    let short = allocations(40, 24000.0, &config, Stepping::Fastest);
    let long = allocations(40, 48000.0, &config, Stepping::Fastest);
    assert!(long - short <= EVENTS, "chain kernel: {short} then {long}");
}
