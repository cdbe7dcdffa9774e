//! What the runs cost, counted for `ladder all --timings`: each finished
//! run adds one run and its block-steps (steps × blocks) to the tally of
//! the output being rendered on this thread, and to the process's total.
//!
//! Under rayon a task may run on any thread, so the code that spreads a
//! scene's runs over the cores carries the tally into each task
//! ([`current`], [`within`]); a run made where no tally is set counts in
//! the total only.
//!
//! The CPU time of a tally is the time its threads spent with it set:
//! each thread reads its own CPU clock (`CLOCK_THREAD_CPUTIME_ID`) where a
//! tally is set or put back ([`within`]) and charges the time since the
//! last such point to the tally that was set, so a thread that picks up
//! another output's task charges that task to the other output. Work in a
//! task that was not given the tally (an encoder's own parallel loop)
//! counts in no output's time.
//!
//! A run is counted where its loop finishes (`Trajectory::finished`: the
//! portable loop, each lane of the batch kernels; the ring chain's loop):
//! once, whoever called it. A run that fails (diverges, is refused by a
//! cap) is not counted, though its steps took time: the halvings of an
//! automatic step that diverge, for one.

use std::cell::RefCell;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

/// The runs and block-steps counted for one output.
#[derive(Debug, Default)]
pub struct Tally {
    runs: AtomicU64,
    block_steps: AtomicU64,
    /// CPU time spent with this tally set, ns (module doc).
    cpu_ns: AtomicU64,
    /// Runs another output made for this one (`scenes::shared`): taken,
    /// not made, so counted in no total.
    reused: AtomicU64,
}

impl Tally {
    /// Runs finished so far.
    pub fn runs(&self) -> u64 {
        self.runs.load(Ordering::Relaxed)
    }

    /// Steps × blocks of those runs.
    pub fn block_steps(&self) -> u64 {
        self.block_steps.load(Ordering::Relaxed)
    }

    /// CPU seconds spent with this tally set on some thread (module doc).
    pub fn cpu_s(&self) -> f64 {
        self.cpu_ns.load(Ordering::Relaxed) as f64 * 1e-9
    }

    /// Runs another output made for this one (`scenes::shared`).
    pub fn reused(&self) -> u64 {
        self.reused.load(Ordering::Relaxed)
    }

    fn add(&self, block_steps: u64) {
        self.runs.fetch_add(1, Ordering::Relaxed);
        self.block_steps.fetch_add(block_steps, Ordering::Relaxed);
    }

    /// Adds what `other` counted (its runs, block-steps, CPU time and
    /// reused runs) to this tally: work done under a tally of its own,
    /// then charged to this one.
    pub fn absorb(&self, other: &Tally) {
        self.runs.fetch_add(other.runs(), Ordering::Relaxed);
        self.block_steps
            .fetch_add(other.block_steps(), Ordering::Relaxed);
        self.cpu_ns
            .fetch_add(other.cpu_ns.load(Ordering::Relaxed), Ordering::Relaxed);
        self.reused.fetch_add(other.reused(), Ordering::Relaxed);
    }
}

thread_local! {
    static CURRENT: RefCell<Option<Arc<Tally>>> = const { RefCell::new(None) };
    /// This thread's CPU clock (ns) when the tally set was last charged.
    static CHARGED_AT: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

/// This thread's CPU time, ns (0 where the clock cannot be read).
fn thread_cpu_ns() -> u64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: clock_gettime writes one timespec into the valid `ts`.
    let ok = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) } == 0;
    if !ok {
        return 0;
    }
    (ts.tv_sec as u64).saturating_mul(1_000_000_000) + ts.tv_nsec as u64
}

/// Charges this thread's CPU time since the last charge to the tally set
/// on it (if any), and swaps in `next` as the tally set.
fn switch_to(next: Option<Arc<Tally>>) -> Option<Arc<Tally>> {
    let now = thread_cpu_ns();
    let since = now.saturating_sub(CHARGED_AT.with(|c| c.replace(now)));
    CURRENT.with(|c| {
        let previous = c.replace(next);
        if let Some(t) = previous.as_ref() {
            t.cpu_ns.fetch_add(since, Ordering::Relaxed);
        }
        previous
    })
}

/// Every run of the process, attributed or not.
static TOTAL: Tally = Tally {
    runs: AtomicU64::new(0),
    block_steps: AtomicU64::new(0),
    cpu_ns: AtomicU64::new(0),
    reused: AtomicU64::new(0),
};

/// The process's total so far.
pub fn total() -> &'static Tally {
    &TOTAL
}

/// The tally set on this thread, to carry into a parallel task.
pub fn current() -> Option<Arc<Tally>> {
    CURRENT.with(|c| c.borrow().clone())
}

/// Runs `f` with `tally` set on this thread, then puts back what was set
/// (a thread that steals another output's task while it waits keeps its
/// own tally).
pub fn within<R>(tally: Option<Arc<Tally>>, f: impl FnOnce() -> R) -> R {
    struct Restore(Option<Arc<Tally>>);
    impl Drop for Restore {
        fn drop(&mut self) {
            switch_to(self.0.take());
        }
    }
    let _restore = Restore(switch_to(tally));
    f()
}

/// Counts one finished run of `steps` steps of `blocks` blocks.
pub(crate) fn record(steps: u64, blocks: usize) {
    let block_steps = steps.saturating_mul(blocks as u64);
    TOTAL.add(block_steps);
    CURRENT.with(|c| {
        if let Some(t) = c.borrow().as_ref() {
            t.add(block_steps);
        }
    });
}

/// Counts `runs` runs that another output made for the output whose
/// tally is set on this thread (`scenes::shared`): in its tally only.
pub fn record_reused(runs: u64) {
    CURRENT.with(|c| {
        if let Some(t) = c.borrow().as_ref() {
            t.reused.fetch_add(runs, Ordering::Relaxed);
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_run_counts_in_the_tally_set_on_its_thread_and_no_other() {
        let (a, b) = (Arc::new(Tally::default()), Arc::new(Tally::default()));
        within(Some(a.clone()), || {
            record(10, 3);
            within(Some(b.clone()), || record(5, 2));
            record(1, 3);
        });
        record(7, 7);
        assert_eq!((a.runs(), a.block_steps()), (2, 33));
        assert_eq!((b.runs(), b.block_steps()), (1, 10));
        assert!(current().is_none(), "within puts back what was set");
    }

    #[test]
    fn a_tally_carried_into_rayon_tasks_counts_their_runs() {
        use rayon::prelude::*;
        let a = Arc::new(Tally::default());
        within(Some(a.clone()), || {
            let t = current();
            (0..64u64)
                .into_par_iter()
                .for_each(|k| within(t.clone(), || record(k, 1)));
        });
        assert_eq!((a.runs(), a.block_steps()), (64, (0..64).sum()));
    }

    /// Burns about `ms` milliseconds of this thread's CPU.
    fn spin(ms: u64) {
        let start = thread_cpu_ns();
        let mut x = 1.0f64;
        while thread_cpu_ns() - start < ms * 1_000_000 {
            x = std::hint::black_box(x * 1.000_000_1);
        }
    }

    #[test]
    fn cpu_time_goes_to_the_tally_set_while_it_was_spent() {
        let (a, b) = (Arc::new(Tally::default()), Arc::new(Tally::default()));
        within(Some(a.clone()), || {
            spin(30);
            within(Some(b.clone()), || spin(60));
            spin(30);
        });
        spin(20);
        let (ca, cb) = (a.cpu_s(), b.cpu_s());
        assert!(
            (0.055..0.09).contains(&ca),
            "a: {ca} s (60 ms spent with it set)"
        );
        assert!(
            (0.055..0.09).contains(&cb),
            "b: {cb} s (60 ms spent with it set)"
        );
    }
}
