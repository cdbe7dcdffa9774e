//! A counting global allocator for the memory tests (tests/alloc.rs,
//! tests/memory_caps.rs), included by path by each of them
//! (`#[path = "common/heap.rs"] mod heap;`), which registers it:
//! `#[global_allocator] static GLOBAL: heap::Counting = heap::Counting;`.
//!
//! It forwards to the system allocator and counts two things: live heap
//! bytes of every thread and their peak, while [`measure`] runs; and the
//! number of allocations made by threads that asked for it
//! ([`count_this_thread`]).
#![allow(dead_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

pub struct Counting;

/// Allocations (and reallocations) of the threads that count.
static ALLOCATIONS: AtomicU64 = AtomicU64::new(0);
/// Live heap bytes of every thread, and their peak since the last reset.
static LIVE: AtomicU64 = AtomicU64::new(0);
static PEAK: AtomicU64 = AtomicU64::new(0);
/// Whether [`LIVE`] and [`PEAK`] are kept (off: no cost to other tests).
static MEASURING: AtomicBool = AtomicBool::new(false);

/// One test of a binary at a time, so that no other test allocates while
/// a peak is measured.
static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

thread_local! {
    /// Whether this thread's allocations are counted.
    static COUNTED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Takes the binary's one-test-at-a-time lock.
pub fn lock() -> std::sync::MutexGuard<'static, ()> {
    ONE_AT_A_TIME.lock().unwrap_or_else(|p| p.into_inner())
}

/// Counts (or stops counting) the allocations of the calling thread.
pub fn count_this_thread(on: bool) {
    COUNTED.with(|c| c.set(on));
}

/// Allocations counted so far.
pub fn allocations() -> u64 {
    ALLOCATIONS.load(Ordering::Relaxed)
}

/// The peak of live heap bytes, above what was live before, while `f`
/// runs, and the bytes still live (allocated by `f`, not freed) after.
pub fn measure<R>(f: impl FnOnce() -> R) -> (R, u64, u64) {
    LIVE.store(0, Ordering::Relaxed);
    PEAK.store(0, Ordering::Relaxed);
    MEASURING.store(true, Ordering::Relaxed);
    let r = f();
    MEASURING.store(false, Ordering::Relaxed);
    (
        r,
        PEAK.load(Ordering::Relaxed),
        LIVE.load(Ordering::Relaxed),
    )
}

fn grew(bytes: usize) {
    if COUNTED.with(|c| c.get()) {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
    }
    if MEASURING.load(Ordering::Relaxed) {
        let live = LIVE.fetch_add(bytes as u64, Ordering::Relaxed) + bytes as u64;
        PEAK.fetch_max(live, Ordering::Relaxed);
    }
}

fn shrank(bytes: usize) {
    if MEASURING.load(Ordering::Relaxed) {
        // Saturating: memory allocated before the measure began may be freed.
        let _ = LIVE.fetch_update(Ordering::Relaxed, Ordering::Relaxed, |l| {
            Some(l.saturating_sub(bytes as u64))
        });
    }
}

// SAFETY: forwards to the system allocator; only counts.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        grew(layout.size());
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        shrank(layout.size());
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        grew(new_size);
        // SAFETY: same contract as the caller's.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        shrank(layout.size());
        p
    }
}
