//! Standard output and standard error without panics: `print!` panics
//! when the stream cannot be written (a closed pipe, a full disk); these
//! return an error instead. A reader that went away (broken pipe) is
//! [`Error::Closed`]: the program ends quietly with success, as Unix tools
//! do. Any other failure is [`Error::Failed`] (exit 1).

use crate::error::{Error, Result};
use std::io::{self, Write};

/// Writes `text` to standard output and flushes it.
pub fn print(text: &str) -> Result<()> {
    write_all(io::stdout().lock(), text).map_err(|e| stream_error("output", &e))
}

/// Writes `text` to standard error.
pub fn eprint(text: &str) -> Result<()> {
    write_all(io::stderr().lock(), text).map_err(|e| stream_error("error", &e))
}

fn write_all(mut w: impl Write, text: &str) -> io::Result<()> {
    w.write_all(text.as_bytes())?;
    w.flush()
}

/// [`Error::Closed`] for a broken pipe, else a one-line [`Error::Failed`].
pub fn stream_error(which: &str, e: &io::Error) -> Error {
    if e.kind() == io::ErrorKind::BrokenPipe {
        return Error::Closed;
    }
    let reason = match e.kind() {
        io::ErrorKind::StorageFull => "no space left on device".to_string(),
        _ => e.to_string().lines().next().unwrap_or("").to_lowercase(),
    };
    Error::failed(format!("cannot write to standard {which}: {reason}"))
}
