//! Running the engine with the GIL released, stoppable by Ctrl-C.
//!
//! The work runs on a thread of its own while the calling thread, without
//! the GIL, waits for it and every 0.1 s takes the GIL back for a moment
//! to let Python look at its signals (`check_signals`, which runs the
//! SIGINT handler on the main thread). On KeyboardInterrupt the call
//! returns at once with that exception and raises a flag: a simulation
//! reads it in the run loop's progress hook (every 5 τ of simulated time)
//! and unwinds, so its thread ends too; a save unwinds at a movie's next
//! frame or before its next file is written or put in place; other work
//! (drawing a figure in memory, encoding) finishes in the background and
//! its result is dropped. A
//! panic of the work becomes a Python exception (`errors::panicked`).
//!
//! The work runs inside a thread pool of this process ([`pool`]), never
//! rayon's global one: after `os.fork()` the child has none of the
//! parent's threads, and a global pool made before the fork would wait
//! forever for them (`multiprocessing` with the fork context). The pool
//! is made on first use in each process (its pid recorded), so a forked
//! child builds its own. Its size is rayon's default: `RAYON_NUM_THREADS`,
//! else one thread a core.

use crate::errors::{panicked, to_py};
use jacobs_ladder::Error;
use pyo3::prelude::*;
use std::panic::{AssertUnwindSafe, catch_unwind, resume_unwind};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{RecvTimeoutError, channel};
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// How often the waiting thread lets Python handle its signals.
const POLL: Duration = Duration::from_millis(100);
/// How long an interrupted call waits for its work to unwind. Work that
/// takes longer (a figure being drawn) goes on in the background until
/// its next hook (a frame, a file about to be written) and unwinds there,
/// writing nothing: the call need not wait for it.
const UNWIND_WAIT: Duration = Duration::from_millis(80);

/// The thread pool of this process and the pid it was made in.
static POOL: Mutex<Option<(u32, &'static rayon::ThreadPool)>> = Mutex::new(None);

/// This process's thread pool, made on first use, and made again in a
/// child forked after it was made (whose copy has no threads behind it:
/// it is left alone, never dropped, as dropping would signal them).
fn pool() -> Result<&'static rayon::ThreadPool, Error> {
    let pid = std::process::id();
    let mut slot = POOL.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((owner, pool)) = *slot
        && owner == pid
    {
        return Ok(pool);
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .thread_name(|i| format!("jl-pool-{i}"))
        // The work runs on a worker: give it a main thread's stack.
        .stack_size(8 << 20)
        .build()
        .map_err(|e| Error::failed(format!("cannot start the engine's threads: {e}")))?;
    let pool: &'static rayon::ThreadPool = Box::leak(Box::new(pool));
    *slot = Some((pid, pool));
    Ok(pool)
}

/// The unwinding payload of cancelled work (not a panic: no message).
struct Cancelled;

/// What the work is given: a progress hook that stops it once the caller
/// was interrupted.
#[derive(Clone)]
pub struct Stop(Arc<AtomicBool>);

impl Stop {
    /// For the run loop's `progress` hook: unwinds out of the work once
    /// the call was interrupted.
    pub fn check(&self, _t: f64) {
        if self.0.load(Ordering::Relaxed) {
            resume_unwind(Box::new(Cancelled));
        }
    }
}

/// Runs `work` without the GIL, on its own thread; Ctrl-C raises
/// KeyboardInterrupt within [`POLL`].
pub fn run<T, F>(py: Python<'_>, work: F) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce(&Stop) -> Result<T, Error> + Send + 'static,
{
    let stop = Stop(Arc::new(AtomicBool::new(false)));
    let (tx, rx) = channel();
    let worker_stop = stop.clone();
    std::thread::Builder::new()
        .name("jacobs-ladder".into())
        .spawn(move || {
            let result = catch_unwind(AssertUnwindSafe(|| {
                pool().and_then(|pool| pool.install(|| work(&worker_stop)))
            }));
            let _ = tx.send(result);
        })
        .map_err(|e| {
            pyo3::exceptions::PyRuntimeError::new_err(format!("cannot start a thread: {e}"))
        })?;
    let outcome = py.detach(move || {
        loop {
            match rx.recv_timeout(POLL) {
                Ok(result) => return Ok(result),
                Err(RecvTimeoutError::Timeout) => {
                    if let Err(interrupt) = Python::attach(|py| py.check_signals()) {
                        stop.0.store(true, Ordering::Relaxed);
                        let _ = rx.recv_timeout(UNWIND_WAIT);
                        return Err(interrupt);
                    }
                }
                Err(RecvTimeoutError::Disconnected) => {
                    return Err(pyo3::exceptions::PyRuntimeError::new_err(
                        "the engine's thread ended without a result",
                    ));
                }
            }
        }
    })?;
    match outcome {
        Ok(Ok(value)) => Ok(value),
        Ok(Err(e)) => Err(to_py(e)),
        Err(payload) if payload.is::<Cancelled>() => Err(
            pyo3::exceptions::PyKeyboardInterrupt::new_err("interrupted"),
        ),
        Err(payload) => Err(panicked(payload)),
    }
}
