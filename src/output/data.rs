//! The pieces every data file shares, whichever output it belongs to (a
//! figure's, a movie's or a sweep's): what made it ([`MadeBy`]), how it is
//! written ([`write_json`], streamed through [`Fill`]), and the bytes one
//! number takes in it ([`BYTES_PER_VALUE`], for the estimates made before
//! any work).

use serde::Serialize;
use std::io::{self, Write};

/// How a file's bytes are made: written into the writer given (a file
/// being written, or memory), so that a data file is streamed.
pub type Fill<'a> = &'a dyn Fn(&mut dyn std::io::Write) -> std::io::Result<()>;

/// The program that made a data file and the command that asked for it:
/// `program`, `version`, `git_commit` (the commit it was built from, with
/// `-modified` for a work tree with changes; null outside a clone),
/// `build` (`ladder --version`'s words) and `command_line`, word by word
/// (empty when the library was called directly).
#[derive(Debug, Clone, Serialize)]
pub struct MadeBy<'a> {
    pub program: &'static str,
    pub version: &'static str,
    pub git_commit: Option<&'static str>,
    pub build: &'static str,
    pub command_line: &'a [String],
}

impl<'a> MadeBy<'a> {
    pub fn new(command_line: &'a [String]) -> Self {
        Self {
            program: "ladder",
            version: crate::version::VERSION,
            git_commit: crate::version::GIT_COMMIT,
            build: crate::version::LONG,
            command_line,
        }
    }
}

/// Most bytes one number of a frame or of a kymograph row takes in the
/// data file (pretty JSON): up to 12 spaces of indentation, up to 24
/// characters of the number (`-1.2345678901234567e-5`), `,` and a line
/// break.
pub const BYTES_PER_VALUE: f64 = 40.0;

/// Writes `data` as pretty-printed JSON into `w` through a buffer: the
/// data file is never held whole in memory.
pub fn write_json<T: Serialize>(w: &mut dyn Write, data: &T) -> io::Result<()> {
    let mut w = io::BufWriter::with_capacity(1 << 16, w);
    serde_json::to_writer_pretty(&mut w, data).map_err(io::Error::other)?;
    w.flush()
}
