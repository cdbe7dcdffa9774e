//! The program's error type and its exit codes (README.md).

use thiserror::Error;

/// Every error the library reports. `exit_code` maps it to the CLI contract:
/// 2 for bad input (the user can fix the command line, or raise a cap), 1
/// for a run that failed (a diverging integrator, a full disk).
#[derive(Debug, Error)]
pub enum Error {
    /// Bad input: unknown ID, a parameter out of range, an unwritable folder.
    #[error("{0}")]
    BadInput(String),
    /// A run that failed, e.g. an unverifiable one; the message says what
    /// happened and gives a hint.
    #[error("{0}")]
    Failed(String),
    /// A run whose integrator diverged, as data: the caller words the hint
    /// in its own terms (the CLI names its flags and the measured stable
    /// step; the library knows no flag).
    #[error("{0}")]
    Diverged(Box<Divergence>),
    /// A request past a cost cap (`crate::limits`): bad input that a raised
    /// cap would allow; the command line adds how to raise it.
    #[error("{0}")]
    Limit(crate::limits::LimitExceeded),
    /// Standard output was closed by its reader (a broken pipe): the
    /// program ends quietly with success, as Unix tools do.
    #[error("standard output was closed")]
    Closed,
}

/// What the run loop knows about a diverged run (README.md).
#[derive(Debug, Clone, PartialEq)]
pub struct Divergence {
    /// The integrator that diverged ("symplectic-euler").
    pub integrator: &'static str,
    /// Its step: "dt = 2" or "rtol = 1e-6".
    pub step: String,
    /// When, in τ.
    pub t: f64,
    /// What the run did ("the springs stretched beyond any physical state").
    pub what: &'static str,
}

impl Divergence {
    /// "symplectic-euler diverged at t = 12.00 τ (dt = 2): the springs ...".
    pub fn facts(&self) -> String {
        format!(
            "{} diverged at t = {:.2} τ ({}): {}",
            self.integrator, self.t, self.step, self.what
        )
    }
}

impl std::fmt::Display for Divergence {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}; hint: a smaller step, or the auto integrator, which picks a stable step and \
             checks it",
            self.facts()
        )
    }
}

pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    pub fn bad_input(msg: impl Into<String>) -> Self {
        Self::BadInput(msg.into())
    }

    pub fn failed(msg: impl Into<String>) -> Self {
        Self::Failed(msg.into())
    }

    /// Whether a run failed (exit 1): diverged, or could not be verified.
    pub fn is_failed_run(&self) -> bool {
        matches!(self, Self::Failed(_) | Self::Diverged(_))
    }

    /// Process exit code: 2 for bad input, 1 for a failed run, 0 for a closed
    /// standard output.
    pub fn exit_code(&self) -> i32 {
        match self {
            Self::BadInput(_) | Self::Limit(_) => 2,
            Self::Failed(_) | Self::Diverged(_) => 1,
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

pub use crate::numfmt::plain as num;
