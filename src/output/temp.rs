//! Temporary files of atomic writes: named `.NAME.tmp-PID` beside their
//! target, registered while they live, and removed when the write fails,
//! when the program is interrupted (SIGINT, SIGTERM, SIGHUP: a handler
//! thread removes every live one, then lets the signal end the process),
//! and when a later run finds them stale (their process is gone).

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

/// `.NAME.tmp-PID` beside `path` (hidden, one per target and process).
pub fn temp_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "output".into());
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    dir.join(format!(".{name}.tmp-{}", std::process::id()))
}

/// A registered temporary file, removed on drop unless persisted.
pub struct TempFile {
    path: PathBuf,
    file: fs::File,
    done: bool,
}

impl TempFile {
    /// Creates the temporary file for `target` (a fresh file: a stale one
    /// of this name is removed first; `create_new` never follows a
    /// symlink planted there).
    pub fn create(target: &Path) -> io::Result<Self> {
        let path = temp_path(target);
        let mut reg = registry();
        if reg.terminating {
            return Err(io::Error::new(io::ErrorKind::Interrupted, "interrupted"));
        }
        match fs::remove_file(&path) {
            Err(e) if e.kind() != io::ErrorKind::NotFound => return Err(e),
            _ => {}
        }
        let file = fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&path)?;
        reg.live.push(path.clone());
        Ok(Self {
            path,
            file,
            done: false,
        })
    }

    pub fn file(&mut self) -> &mut fs::File {
        &mut self.file
    }

    /// Syncs and closes the file, then renames it onto `target`.
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

/// Whether `name` is one of our temporary names, `.NAME.tmp-PID` (or the
/// writability probe `.ladder-probe-PID`); returns the PID.
pub fn our_temp_pid(name: &OsStr) -> Option<u32> {
    let name = name.to_str()?;
    let rest = name.strip_prefix('.')?;
    let digits = match rest.strip_prefix("ladder-probe-") {
        Some(d) => d,
        None => {
            let (stem, d) = rest.rsplit_once(".tmp-")?;
            if stem.is_empty() {
                return None;
            }
            d
        }
    };
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    digits.parse().ok()
}

/// Whether process `pid` is running (on Unix, `kill(pid, 0)`; elsewhere
/// assumed running, so nothing is removed).
pub fn process_alive(pid: u32) -> bool {
    #[cfg(unix)]
    {
        let Ok(pid) = libc::pid_t::try_from(pid) else {
            return false;
        };
        if pid <= 0 {
            return true;
        }
        // SAFETY: signal 0 only checks that the process exists.
        let r = unsafe { libc::kill(pid, 0) };
        r == 0 || io::Error::last_os_error().raw_os_error() == Some(libc::EPERM)
    }
    #[cfg(not(unix))]
    {
        let _ = pid;
        true
    }
}

/// Removes the stale temporary files in `dir`: regular files of our
/// naming whose process is gone, or of this process's PID but not live
/// here (left by an earlier process that had the same PID). Returns the
/// paths removed. Errors reading the folder are ignored (the write that
/// follows reports them).
pub fn remove_stale(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = fs::read_dir(dir) else {
        return Vec::new();
    };
    let me = std::process::id();
    let mut removed = Vec::new();
    for entry in entries.flatten() {
        let Some(pid) = our_temp_pid(&entry.file_name()) else {
            continue;
        };
        let regular = entry.file_type().map(|t| t.is_file()).unwrap_or(false);
        if !regular {
            continue;
        }
        let path = entry.path();
        let stale = if pid == me {
            !registry().live.contains(&path)
        } else {
            !process_alive(pid)
        };
        if stale && fs::remove_file(&path).is_ok() {
            removed.push(path);
        }
    }
    removed
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn our_names_and_only_ours() {
        let pid = |s: &str| our_temp_pid(OsStr::new(s));
        assert_eq!(pid(".figure-3.png.tmp-31979"), Some(31979));
        assert_eq!(pid(".ladder-probe-12"), Some(12));
        assert_eq!(pid("figure-3.png.tmp-31979"), None);
        assert_eq!(pid(".figure-3.png.tmp-"), None);
        assert_eq!(pid(".figure-3.png.tmp-12a"), None);
        assert_eq!(pid("..tmp-5"), None);
        assert_eq!(pid(".notes.txt"), None);
    }

    #[test]
    fn this_process_is_alive() {
        assert!(process_alive(std::process::id()));
    }
}
