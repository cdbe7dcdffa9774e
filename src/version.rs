//! What build of the program this is: the crate version and, when built from
//! a git clone, the commit (`build.rs`), with `-modified` when the work tree
//! had uncommitted changes.

/// The crate version, e.g. `0.1.0`.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// The git commit the program was built from, when built from a clone.
pub const GIT_COMMIT: Option<&str> = option_env!("LADDER_GIT_COMMIT");

/// `0.1.0 (commit 1a2b3c4d5e6f)`, or just `0.1.0` outside a clone: what
/// `ladder --version` prints after the name.
pub const LONG: &str = env!("LADDER_VERSION_LONG");
