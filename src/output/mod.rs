//! Everything the program writes: files (atomic, regular files only),
//! their temporary files (removed on failure, on SIGINT/SIGTERM, and when
//! a later run finds them stale), and the standard streams.
//!
//! Exit codes follow README.md: a write that fails because of the
//! user's choice (no permission, not a folder, a device or a symlink in
//! the way) is [`crate::Error::BadInput`] (exit 2); one that fails because
//! of the machine (disk full, I/O error) is [`crate::Error::Failed`] (exit
//! 1); standard output closed by its reader (a broken pipe) is
//! [`crate::Error::Closed`], which ends the program quietly with success.

pub mod data;
pub mod files;
pub mod group;
pub mod stream;
pub mod temp;

pub use files::{
    check_distinct, check_targets, check_writable, ensure_dir, write_atomic, write_atomic_with,
};
pub use stream::{eprint, print};
