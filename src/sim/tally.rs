//! What the runs cost, counted for `ladder all --timings`: each finished
//! run adds one run and its block-steps (steps × blocks) to the tally of
//! the output being rendered on this thread, and to the process's total.
//!
//! Under rayon a task may run on any thread, so the code that spreads a
//! scene's runs over the cores carries the tally into each task
//! ([`current`], [`within`]); a run made where no tally is set counts in
//! the total only.
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

    fn add(&self, block_steps: u64) {
        self.runs.fetch_add(1, Ordering::Relaxed);
        self.block_steps.fetch_add(block_steps, Ordering::Relaxed);
    }
}

thread_local! {
    static CURRENT: RefCell<Option<Arc<Tally>>> = const { RefCell::new(None) };
}

/// Every run of the process, attributed or not.
static TOTAL: Tally = Tally {
    runs: AtomicU64::new(0),
    block_steps: AtomicU64::new(0),
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
            let previous = self.0.take();
            CURRENT.with(|c| *c.borrow_mut() = previous);
        }
    }
    let _restore = Restore(CURRENT.with(|c| c.replace(tally)));
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
}
