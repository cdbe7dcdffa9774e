//! Atomic writes of regular files, and the checks a run makes on its
//! targets before any work.
//!
//! Every file is written to a temporary file in its own folder
//! (`output::temp`) and renamed into place, so a reader never sees a
//! partial file and a failure half-way leaves nothing behind. Only regular
//! files are ever replaced: a device, FIFO, socket, symlink or folder in
//! the way is refused (so `--csv /dev/null` cannot replace /dev/null).
//! Errors are one line naming the path: the user's mistakes (permission,
//! not a folder, not a regular file) are [`Error::BadInput`], the
//! machine's (disk full, I/O error) [`Error::Failed`].

use super::temp::{self, TempFile};
use crate::error::{Error, Result};
use std::collections::BTreeSet;
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
/// is left as it was. `path` must be a regular file or not exist.
pub fn write_atomic_with<F>(path: &Path, fill: F) -> Result<()>
where
    F: FnOnce(&mut fs::File) -> io::Result<()>,
{
    ensure_dir(&parent_dir(path))?;
    check_kind(path)?;
    let mut tmp = TempFile::create(path).map_err(|e| io_error(path, &e))?;
    fill(tmp.file())
        .and_then(|()| tmp.file().flush())
        .map_err(|e| io_error(path, &e))?;
    // The target may have changed while we wrote.
    check_kind(path)?;
    tmp.persist(path).map_err(|e| io_error(path, &e))
}

/// Fails early, before any work, when `path` cannot be written: its folder
/// cannot be created or written (a probe, a new temporary file, is created
/// and removed), or
/// something other than a regular file is in the way. Removes stale
/// temporary files of ours from the folder.
pub fn check_writable(path: &Path) -> Result<()> {
    check_targets(&[path.to_path_buf()])
}

/// [`check_writable`] for every target of a run, before anything is
/// rendered: each folder once, then each file.
pub fn check_targets(paths: &[PathBuf]) -> Result<()> {
    let dirs: BTreeSet<PathBuf> = paths.iter().map(|p| parent_dir(p)).collect();
    for dir in &dirs {
        ensure_dir(dir)?;
        temp::remove_stale(dir);
        // A new file under a random name (never through a symlink planted
        // in the folder), removed at once.
        drop(TempFile::create(&dir.join("ladder-probe")).map_err(|e| io_error(dir, &e))?);
    }
    paths.iter().try_for_each(|p| check_kind(p))
}

/// Refuses (exit 2) a command whose outputs name one file: `targets` are
/// (path, what makes it), e.g. the scene file; `hint` says how to part
/// them. Two writers of one file
/// would race on it and leave one's picture beside the other's data.
/// Paths are compared as files, not as text: `x`, `./x` and `link/x`
/// (a link to this folder) are one file ([`file_identity`]).
pub fn check_distinct(targets: &[(PathBuf, String)], hint: &str) -> Result<()> {
    let mut seen: std::collections::BTreeMap<PathBuf, &str> = std::collections::BTreeMap::new();
    for (path, source) in targets {
        if let Some(first) = seen.insert(file_identity(path), source.as_str()) {
            let by = if first == source.as_str() {
                format!("{source} is given twice")
            } else {
                format!("by {first} and by {source}")
            };
            return Err(Error::bad_input(format!(
                "{} would be written twice by one command ({by}); {hint}",
                path.display()
            )));
        }
    }
    Ok(())
}

/// The file `path` names, as one path: its folder with every link and
/// `.`/`..` resolved (as far as the folder exists), then its name.
fn file_identity(path: &Path) -> PathBuf {
    let absolute = if path.is_absolute() {
        path.to_path_buf()
    } else {
        std::env::current_dir().unwrap_or_default().join(path)
    };
    let (Some(dir), Some(name)) = (absolute.parent(), absolute.file_name()) else {
        return absolute;
    };
    // The deepest existing ancestor, resolved; the rest appended as typed.
    let mut existing = dir.to_path_buf();
    let mut rest = Vec::new();
    loop {
        if let Ok(real) = fs::canonicalize(&existing) {
            let mut out = real;
            for part in rest.iter().rev() {
                out.push(part);
            }
            out.push(name);
            return out;
        }
        match (
            existing.file_name().map(|n| n.to_os_string()),
            existing.parent(),
        ) {
            (Some(last), Some(parent)) => {
                rest.push(last);
                existing = parent.to_path_buf();
            }
            _ => return absolute,
        }
    }
}

/// `Ok` when `path` does not exist or is a regular file (not a symlink).
pub(super) fn check_kind(path: &Path) -> Result<()> {
    let meta = match fs::symlink_metadata(path) {
        Ok(m) => m,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(()),
        Err(e) => return Err(io_error(path, &e)),
    };
    let kind = meta.file_type();
    if kind.is_file() {
        return Ok(());
    }
    let what = if kind.is_dir() {
        "a folder"
    } else if kind.is_symlink() {
        "a symbolic link"
    } else {
        special_kind(&kind)
    };
    Err(Error::bad_input(format!(
        "cannot write to {}: it is {what}, and ladder replaces only regular files",
        path.display()
    )))
}

#[cfg(unix)]
fn special_kind(kind: &fs::FileType) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    if kind.is_char_device() || kind.is_block_device() {
        "a device"
    } else if kind.is_fifo() {
        "a FIFO (named pipe)"
    } else if kind.is_socket() {
        "a socket"
    } else {
        "not a regular file"
    }
}

#[cfg(not(unix))]
fn special_kind(_: &fs::FileType) -> &'static str {
    "not a regular file"
}

pub(super) fn parent_dir(path: &Path) -> PathBuf {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// One line, "cannot write to PATH: REASON": [`Error::BadInput`] for what
/// the user can fix (permission, a missing or wrong folder, a read-only
/// place), [`Error::Failed`] for the machine (disk full, I/O error).
pub fn io_error(path: &Path, e: &io::Error) -> Error {
    use io::ErrorKind as K;
    let user =
        |reason: &str| Error::bad_input(format!("cannot write to {}: {reason}", path.display()));
    #[cfg(unix)]
    if e.raw_os_error() == Some(libc::ELOOP) {
        return user("too many levels of symbolic links (a symlink loop in the path)");
    }
    match e.kind() {
        K::PermissionDenied => user("permission denied"),
        K::NotFound => user("no such file or directory"),
        K::AlreadyExists => user("a file with that name exists"),
        K::NotADirectory => user("a parent is not a directory"),
        K::IsADirectory => user("it is a folder"),
        K::ReadOnlyFilesystem => user("read-only file system"),
        K::InvalidFilename => user("invalid file name"),
        K::StorageFull | K::QuotaExceeded => Error::failed(format!(
            "cannot write to {}: no space left on device; free some space and run again",
            path.display()
        )),
        K::FileTooLarge => Error::failed(format!(
            "cannot write to {}: the file is larger than this system allows (a file-size \
             limit, ulimit -f, or the file system's)",
            path.display()
        )),
        K::Interrupted => Error::failed(format!("cannot write to {}: interrupted", path.display())),
        _ => Error::failed(format!(
            "cannot write to {}: {} (an I/O error of the machine)",
            path.display(),
            first_line(&e.to_string())
        )),
    }
}

fn first_line(s: &str) -> String {
    s.lines().next().unwrap_or("").trim().to_lowercase()
}
