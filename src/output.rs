//! Atomic file writes and the output folder.
//!
//! Every file is written to a temporary file in its own folder and renamed
//! into place, so a reader never sees a partial file and a failure half-way
//! leaves nothing behind. Errors are one line naming the path, mapped to
//! [`Error::BadInput`] (the user picked an unwritable place).

use crate::error::{Error, Result};
use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// Creates `dir` and its parents if needed.
pub fn ensure_dir(dir: &Path) -> Result<()> {
    fs::create_dir_all(dir).map_err(|e| io_error(dir, &e))?;
    if dir.is_dir() {
        Ok(())
    } else {
        Err(Error::bad_input(format!(
            "cannot write to {}: not a directory",
            dir.display()
        )))
    }
}

/// Writes `bytes` to `path` atomically, creating the parent folder.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    write_atomic_with(path, |f| f.write_all(bytes))
}

/// Writes to `path` atomically through `fill`, which streams into the
/// temporary file. If `fill` fails, the temporary file is removed and `path`
/// is left as it was.
pub fn write_atomic_with<F>(path: &Path, fill: F) -> Result<()>
where
    F: FnOnce(&mut fs::File) -> io::Result<()>,
{
    let dir = parent_dir(path);
    ensure_dir(&dir)?;
    let tmp = temp_path(path);
    let result = write_temp(&tmp, fill).and_then(|()| fs::rename(&tmp, path));
    result.map_err(|e| {
        // Best effort: the temporary file may not exist.
        let _ = fs::remove_file(&tmp);
        io_error(path, &e)
    })
}

/// Fails early, before any work, when the folder of `path` cannot be
/// created or written: creates it, then creates and removes a probe file.
pub fn check_writable(path: &Path) -> Result<()> {
    let dir = parent_dir(path);
    ensure_dir(&dir)?;
    let probe = dir.join(format!(".ladder-probe-{}", std::process::id()));
    fs::File::create(&probe).map_err(|e| io_error(&dir, &e))?;
    // Best effort: the probe is empty and hidden.
    let _ = fs::remove_file(probe);
    Ok(())
}

/// `path` joined onto `dir` after creating `dir`.
pub fn file_in(dir: &Path, name: &str) -> Result<PathBuf> {
    ensure_dir(dir)?;
    Ok(dir.join(name))
}

fn write_temp<F>(tmp: &Path, fill: F) -> io::Result<()>
where
    F: FnOnce(&mut fs::File) -> io::Result<()>,
{
    let mut f = fs::File::create(tmp)?;
    fill(&mut f)?;
    f.flush()?;
    f.sync_all()
}

fn parent_dir(path: &Path) -> PathBuf {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// `.NAME.tmp-PID` beside `path` (hidden, unique per process).
fn temp_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "output".into());
    parent_dir(path).join(format!(".{name}.tmp-{}", std::process::id()))
}

/// One line: "cannot write to PATH: REASON".
fn io_error(path: &Path, e: &io::Error) -> Error {
    let reason = match e.kind() {
        io::ErrorKind::PermissionDenied => "permission denied".to_string(),
        io::ErrorKind::NotFound => "no such file or directory".to_string(),
        io::ErrorKind::AlreadyExists => "a file with that name exists".to_string(),
        io::ErrorKind::NotADirectory => "a parent is not a directory".to_string(),
        io::ErrorKind::StorageFull => "no space left on device".to_string(),
        io::ErrorKind::ReadOnlyFilesystem => "read-only file system".to_string(),
        _ => first_line(&e.to_string()),
    };
    Error::bad_input(format!("cannot write to {}: {reason}", path.display()))
}

fn first_line(s: &str) -> String {
    s.lines().next().unwrap_or("").trim().to_lowercase()
}
