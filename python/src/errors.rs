//! The one place where the library's errors become Python exceptions:
//! bad input → `ValueError` with the CLI's one-line message (key path
//! included), a failed run → `RunError` with its hint, a panic →
//! `InternalError` (never an abort of the interpreter).
//!
//! The exceptions are classes of the public module `jacobs_ladder` (their
//! `__module__`), which re-exports them: they pickle, so an error raised in
//! a pool's worker reaches the parent as itself.

use jacobs_ladder::Error;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;

pyo3::create_exception!(
    jacobs_ladder,
    RunError,
    PyRuntimeError,
    "A run that failed (for example a diverging integrator): the message says what \
     happened and gives a hint, as the command line's exit status 1 does."
);

pyo3::create_exception!(
    jacobs_ladder,
    InternalError,
    PyRuntimeError,
    "A bug of jacobs_ladder (a panic of the engine, caught): please report it with the \
     call that raised it."
);

/// The Python exception of a library error.
pub fn to_py(e: Error) -> PyErr {
    match e {
        Error::BadInput(_) | Error::Limit(_) => PyValueError::new_err(e.to_string()),
        Error::Failed(_) | Error::Diverged(_) | Error::Closed => RunError::new_err(e.to_string()),
    }
}

/// The exception of a panic's payload.
pub fn panicked(payload: Box<dyn std::any::Any + Send>) -> PyErr {
    let what = payload
        .downcast_ref::<String>()
        .cloned()
        .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
        .unwrap_or_else(|| "unknown panic".into());
    InternalError::new_err(format!(
        "internal error in jacobs_ladder (please report it): {what}"
    ))
}

/// Shorthand: a library result as a Python result.
pub trait IntoPy<T> {
    fn py_err(self) -> PyResult<T>;
}

impl<T> IntoPy<T> for Result<T, Error> {
    fn py_err(self) -> PyResult<T> {
        self.map_err(to_py)
    }
}
