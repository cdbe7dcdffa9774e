//! The program's error type and its exit codes (SPEC section 5).

use thiserror::Error;

/// Every error the library reports. `exit_code` maps it to the CLI contract:
/// 2 for bad input (the user can fix the command line, or raise a cap), 1
/// for a run that failed (a diverging integrator, a full disk).
#[derive(Debug, Error)]
pub enum Error {
    /// Bad input: unknown ID, a parameter out of range, an unwritable folder.
    #[error("{0}")]
    BadInput(String),
    /// A run that failed, e.g. a diverging integrator; the message says when
    /// and gives a hint.
    #[error("{0}")]
    Failed(String),
    /// A request past a cost cap (`crate::limits`): bad input that a raised
    /// cap would allow; the command line adds how to raise it.
    #[error("{0}")]
    Limit(crate::limits::LimitExceeded),
    /// Standard output was closed by its reader (a broken pipe): the
    /// program ends quietly with success, as Unix tools do.
    #[error("standard output was closed")]
    Closed,
}

pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    pub fn bad_input(msg: impl Into<String>) -> Self {
        Self::BadInput(msg.into())
    }

    pub fn failed(msg: impl Into<String>) -> Self {
        Self::Failed(msg.into())
    }

    /// Process exit code: 2 for bad input, 1 for a failed run, 0 for a closed
    /// standard output.
    pub fn exit_code(&self) -> i32 {
        match self {
            Self::BadInput(_) | Self::Limit(_) => 2,
            Self::Failed(_) => 1,
            Self::Closed => 0,
        }
    }
}

impl From<crate::limits::LimitExceeded> for Error {
    fn from(e: crate::limits::LimitExceeded) -> Self {
        Self::Limit(e)
    }
}

impl From<crate::model::ParamError> for Error {
    fn from(e: crate::model::ParamError) -> Self {
        Self::BadInput(e.0)
    }
}

/// A user's number for a message: as typed for ordinary magnitudes, in
/// exponent form when tiny or huge (so that 1e308 does not print 309
/// digits).
pub fn num(x: f64) -> String {
    let a = x.abs();
    if x.is_finite() && a != 0.0 && !(1e-4..1e9).contains(&a) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}
