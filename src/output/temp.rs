//! Temporary files of atomic writes: named `.NAME.tmp-TOKEN` beside their
//! target (TOKEN: 16 random hexadecimal digits), created new (`O_EXCL`,
//! which never follows a symlink planted under the name) and held under
//! an exclusive advisory lock (`flock`) from creation until they are
//! renamed into place or removed. They are removed when the write fails,
//! when the program is interrupted (SIGINT, SIGTERM, SIGHUP: a handler
//! thread removes every live one, then lets the signal end the process),
//! and when a later run finds them stale.
//!
//! Stale means provably ours and provably dead: a regular file of our
//! naming, owned by our user, whose lock a non-blocking `flock` attempt
//! obtains (the process that wrote it is gone, wherever it ran: the lock
//! is held by the open file, so a live writer on another machine sharing
//! the folder, or in another PID namespace, keeps its file). A name alone,
//! or a process id, never decides.

use std::ffi::OsStr;
use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, Once};

/// The live temporary files of this process, and whether it is being
/// terminated (then no new one may be created). Files are created and
/// removed with this lock held, so the signal handler sees every file
/// that exists.
struct Registry {
    live: Vec<PathBuf>,
    terminating: bool,
}

static REGISTRY: Mutex<Registry> = Mutex::new(Registry {
    live: Vec::new(),
    terminating: false,
});

fn registry() -> MutexGuard<'static, Registry> {
    // A panic elsewhere while holding the lock leaves the list intact.
    REGISTRY.lock().unwrap_or_else(|p| p.into_inner())
}

/// How many random names [`TempFile::create`] tries before it gives up
/// (each clash is a file of that name already there, ours or not).
const ATTEMPTS: usize = 16;

/// A fresh random token: 16 hexadecimal digits. The hasher's keys come
/// from the operating system's randomness (once per process, then
/// stepped); the process id, a counter and the clock are mixed in.
fn token() -> String {
    use std::hash::{BuildHasher, Hasher};
    use std::sync::atomic::{AtomicU64, Ordering};
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let mut h = std::collections::hash_map::RandomState::new().build_hasher();
    h.write_u32(std::process::id());
    h.write_u64(COUNTER.fetch_add(1, Ordering::Relaxed));
    if let Ok(t) = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH) {
        h.write_u128(t.as_nanos());
    }
    format!("{:016x}", h.finish())
}

/// `.NAME.tmp-TOKEN` beside `path`, with a fresh random token.
pub fn temp_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "output".into());
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    dir.join(format!(".{name}.tmp-{}", token()))
}

/// A registered temporary file, locked while it lives, removed on drop
/// unless persisted.
pub struct TempFile {
    path: PathBuf,
    file: fs::File,
    done: bool,
}

impl TempFile {
    /// Creates a temporary file for `target`: a new file under a random
    /// name (`create_new`: an existing file or a symlink under that name
    /// is never opened; another name is tried), locked before it is
    /// registered. A file whose lock cannot be taken at once, or whose
    /// name no longer leads to it once locked (a cleaner of another
    /// process judged it in between), is given up for another name.
    pub fn create(target: &Path) -> io::Result<Self> {
        let mut last = io::Error::new(io::ErrorKind::AlreadyExists, "no free temporary name");
        for _ in 0..ATTEMPTS {
            let path = temp_path(target);
            let mut reg = registry();
            if reg.terminating {
                return Err(io::Error::new(io::ErrorKind::Interrupted, "interrupted"));
            }
            let file = match fs::OpenOptions::new()
                .write(true)
                .create_new(true)
                .open(&path)
            {
                Ok(f) => f,
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {
                    last = e;
                    continue;
                }
                Err(e) => return Err(e),
            };
            match lock::try_exclusive(&file) {
                Ok(true) if lock::same_file(&file, &path) => {
                    reg.live.push(path.clone());
                    return Ok(Self {
                        path,
                        file,
                        done: false,
                    });
                }
                Ok(_) => {
                    // Someone else holds it or removed it: leave it to them.
                    last = io::Error::new(io::ErrorKind::AlreadyExists, "temporary file taken");
                }
                Err(e) => {
                    let _ = fs::remove_file(&path);
                    return Err(e);
                }
            }
        }
        Err(last)
    }

    /// The temporary file's path.
    pub fn path(&self) -> &Path {
        &self.path
    }

    pub fn file(&mut self) -> &mut fs::File {
        &mut self.file
    }

    /// Syncs the file, then renames it onto `target` (the lock goes with
    /// the file when it is closed).
    pub fn persist(mut self, target: &Path) -> io::Result<()> {
        self.file.sync_all()?;
        let mut reg = registry();
        if reg.terminating {
            return Err(io::Error::new(io::ErrorKind::Interrupted, "interrupted"));
        }
        fs::rename(&self.path, target)?;
        reg.live.retain(|p| p != &self.path);
        self.done = true;
        Ok(())
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if self.done {
            return;
        }
        let mut reg = registry();
        // Best effort: it may already be gone.
        let _ = fs::remove_file(&self.path);
        reg.live.retain(|p| p != &self.path);
    }
}

/// Removes every live temporary file and stops new ones (the signal
/// handler's work). Returns how many were removed.
pub fn remove_all_live() -> usize {
    let mut reg = registry();
    reg.terminating = true;
    reg.live
        .drain(..)
        .filter(|p| fs::remove_file(p).is_ok())
        .count()
}

/// Installs, once, a thread that on SIGINT, SIGTERM or SIGHUP removes the
/// live temporary files and then ends the process as the signal would
/// have (so the exit status still says which signal). Without a handler
/// (the installation failed) the files are left for the stale sweep.
pub fn install_signal_cleanup() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        #[cfg(unix)]
        {
            use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
            let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP])
            else {
                return;
            };
            let spawned = std::thread::Builder::new()
                .name("ladder-signals".into())
                .spawn(move || {
                    if let Some(sig) = signals.forever().next() {
                        remove_all_live();
                        // Keep the registry locked: no thread may create a
                        // file between the sweep and the end.
                        let _held = registry();
                        let _ = signal_hook::low_level::emulate_default_handler(sig);
                        std::process::exit(128 + sig);
                    }
                });
            drop(spawned);
        }
    });
}

/// Whether `name` is one of our temporary names, `.NAME.tmp-TOKEN` with
/// a token of 16 hexadecimal digits.
pub fn is_our_temp_name(name: &OsStr) -> bool {
    let Some(name) = name.to_str() else {
        return false;
    };
    let Some((stem, token)) = name
        .strip_prefix('.')
        .and_then(|rest| rest.rsplit_once(".tmp-"))
    else {
        return false;
    };
    !stem.is_empty() && token.len() == 16 && token.bytes().all(|b| b.is_ascii_hexdigit())
}

/// Removes the stale temporary files in `dir`: those of our naming,
/// regular files of our user, not live in this process, whose lock is
/// free (see the module's notes). Returns the paths removed. Errors
/// reading the folder are ignored (the write that follows reports them).
pub fn remove_stale(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut removed = Vec::new();
    for entry in entries.flatten() {
        if !is_our_temp_name(&entry.file_name()) {
            continue;
        }
        let path = entry.path();
        if registry().live.contains(&path) {
            continue;
        }
        if lock::remove_if_dead(&path) {
            removed.push(path);
        }
    }
    removed
}

/// Advisory locks on temporary files (Unix `flock`; elsewhere no file is
/// ever judged dead).
mod lock {
    use std::fs;
    use std::io;
    use std::path::Path;

    /// Takes the exclusive lock on `file` without waiting: `Ok(false)`
    /// when another open file holds it.
    #[cfg(unix)]
    pub fn try_exclusive(file: &fs::File) -> io::Result<bool> {
        use std::os::unix::io::AsRawFd;
        // SAFETY: flock on a file descriptor we own.
        let r = unsafe { libc::flock(file.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) };
        if r == 0 {
            return Ok(true);
        }
        let e = io::Error::last_os_error();
        match e.raw_os_error() {
            Some(libc::EWOULDBLOCK) => Ok(false),
            // A file system without locks: the file is ours (created new),
            // but no later run will ever judge it dead.
            Some(libc::ENOLCK) | Some(libc::EOPNOTSUPP) => Ok(true),
            _ => Err(e),
        }
    }

    #[cfg(not(unix))]
    pub fn try_exclusive(_: &fs::File) -> io::Result<bool> {
        Ok(true)
    }

    /// Whether `path` (not followed) is the very file `file` is open on.
    #[cfg(unix)]
    pub fn same_file(file: &fs::File, path: &Path) -> bool {
        use std::os::unix::fs::MetadataExt;
        match (file.metadata(), fs::symlink_metadata(path)) {
            (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
            _ => false,
        }
    }

    #[cfg(not(unix))]
    pub fn same_file(_: &fs::File, path: &Path) -> bool {
        path.is_file()
    }

    /// Removes `path` when it is provably a dead temporary file of ours:
    /// opened without following a link and without blocking (a FIFO
    /// does not hang us), a regular file owned by this user, its lock
    /// obtained, and the name still leading to it. The lock is held while
    /// the file is removed.
    #[cfg(unix)]
    pub fn remove_if_dead(path: &Path) -> bool {
        use std::os::unix::fs::{MetadataExt, OpenOptionsExt};
        let Ok(file) = fs::OpenOptions::new()
            .read(true)
            .custom_flags(libc::O_NOFOLLOW | libc::O_NONBLOCK)
            .open(path)
        else {
            return false;
        };
        let Ok(meta) = file.metadata() else {
            return false;
        };
        // SAFETY: geteuid has no preconditions.
        let me = unsafe { libc::geteuid() };
        if !meta.is_file() || meta.uid() != me {
            return false;
        }
        // ENOLCK / EOPNOTSUPP say "true" for a writer; a cleaner must
        // not take that as dead.
        use std::os::unix::io::AsRawFd;
        // SAFETY: flock on a file descriptor we own.
        let r = unsafe { libc::flock(file.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) };
        if r != 0 || !same_file(&file, path) {
            return false;
        }
        fs::remove_file(path).is_ok()
    }

    #[cfg(not(unix))]
    pub fn remove_if_dead(_: &Path) -> bool {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn our_names_and_only_ours() {
        let ours = |s: &str| is_our_temp_name(OsStr::new(s));
        assert!(ours(".figure-3.png.tmp-0123456789abcdef"));
        assert!(ours(
            &temp_path(Path::new("out/a.gif"))
                .file_name()
                .unwrap()
                .to_string_lossy()
        ));
        assert!(!ours("figure-3.png.tmp-0123456789abcdef"));
        assert!(
            !ours(".figure-3.png.tmp-31979"),
            "the old PID naming is not ours"
        );
        assert!(!ours(".figure-3.png.tmp-0123456789abcdeg"));
        assert!(!ours("..tmp-0123456789abcdef"));
        assert!(!ours(".notes.txt"));
    }

    #[test]
    fn tokens_differ() {
        let a = temp_path(Path::new("x"));
        let b = temp_path(Path::new("x"));
        assert_ne!(a, b);
    }
}
