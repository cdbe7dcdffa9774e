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
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
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
/// was interrupted, and the work's progress so far (simulated time, runs
/// or frames done) for the caller's callback ([`Report`]).
#[derive(Clone)]
pub struct Stop {
    stopped: Arc<AtomicBool>,
    /// The progress so far, an `f64` as bits.
    done: Arc<AtomicU64>,
}

impl Stop {
    /// Unwinds out of the work once the call was interrupted (or its
    /// progress callback raised).
    pub fn check(&self) {
        if self.stopped.load(Ordering::Relaxed) {
            resume_unwind(Box::new(Cancelled));
        }
    }

    /// For the run loop's `progress` hook: records that the work reached
    /// `t` (the furthest of the runs, as the command line's bar does), then
    /// [`Stop::check`].
    pub fn at(&self, t: f64) {
        let _ = self
            .done
            .fetch_update(Ordering::Relaxed, Ordering::Relaxed, |old| {
                (t > f64::from_bits(old)).then_some(t.to_bits())
            });
        self.check();
    }

    /// Records `dx` more done (a run of a sweep, a frame), then
    /// [`Stop::check`].
    pub fn add(&self, dx: f64) {
        let _ = self
            .done
            .fetch_update(Ordering::Relaxed, Ordering::Relaxed, |old| {
                Some((f64::from_bits(old) + dx).to_bits())
            });
        self.check();
    }

    fn done(&self) -> f64 {
        f64::from_bits(self.done.load(Ordering::Relaxed))
    }
}

/// A progress callback: `callback(done, total)` (both whole numbers when
/// `whole`: runs, frames; else τ), called from the waiting thread with the
/// GIL every [`POLL`] while the progress moved, and once at the end.
pub struct Report {
    pub callback: Py<PyAny>,
    pub total: Option<f64>,
    pub whole: bool,
}

impl Report {
    /// The callback, if the caller gave one (None is no callback).
    pub fn new(
        callback: Option<&Bound<'_, PyAny>>,
        total: Option<f64>,
        whole: bool,
    ) -> Option<Self> {
        callback.filter(|c| !c.is_none()).map(|c| Self {
            callback: c.clone().unbind(),
            total,
            whole,
        })
    }

    fn call(&self, py: Python<'_>, done: f64) -> PyResult<()> {
        let cb = self.callback.bind(py);
        if self.whole {
            let total = self.total.map(|t| t as u64);
            cb.call1((done as u64, total)).map(|_| ())
        } else {
            cb.call1((done, self.total)).map(|_| ())
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
    run_reporting(py, None, work)
}

/// [`run`], and `report` told of the work's progress (the progress the
/// work records on its [`Stop`]) while it runs and once when it is done.
/// An exception the callback raises stops the work as Ctrl-C does and is
/// the call's exception.
pub fn run_reporting<T, F>(py: Python<'_>, report: Option<Report>, work: F) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce(&Stop) -> Result<T, Error> + Send + 'static,
{
    let stop = Stop {
        stopped: Arc::new(AtomicBool::new(false)),
        done: Arc::new(AtomicU64::new(0.0f64.to_bits())),
    };
    let (tx, rx) = channel();
    let worker_stop = stop.clone();
    let watch = stop.clone();
    let mut shown = f64::NAN;
    let shown_to = &report;
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
                    let done = watch.done();
                    let checked = Python::attach(|py| {
                        py.check_signals()?;
                        match shown_to {
                            Some(r) if done != shown => r.call(py, done),
                            _ => Ok(()),
                        }
                    });
                    shown = done;
                    if let Err(interrupt) = checked {
                        watch.stopped.store(true, Ordering::Relaxed);
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
        Ok(Ok(value)) => {
            if let Some(r) = &report {
                r.call(py, stop.done())?;
            }
            Ok(value)
        }
        Ok(Err(e)) => Err(to_py(e)),
        Err(payload) if payload.is::<Cancelled>() => Err(
            pyo3::exceptions::PyKeyboardInterrupt::new_err("interrupted"),
        ),
        Err(payload) => Err(panicked(payload)),
    }
}
