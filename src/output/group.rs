//! The files of one output written together: each streamed into its own
//! temporary file as it is made, and renamed into place only when every
//! one is complete, its data files first (docs/scenes.md: every picture
//! has its data file beside it). A failure while any of them is written
//! (a full disk) leaves none of them; the renames, which need no space,
//! put the data files (`.json`, `.csv`, `.npz`) in place before the
//! pictures and movies, so no picture is ever in place without its data.

use super::files::{check_kind, ensure_dir, io_error, parent_dir};
use super::temp::TempFile;
use crate::error::Result;
use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// Files written but not yet in place.
#[derive(Default)]
pub struct Group {
    staged: Vec<(PathBuf, TempFile)>,
}

/// Whether `path` is a data file (renamed into place first).
fn is_data(path: &Path) -> bool {
    matches!(
        path.extension().and_then(|e| e.to_str()),
        Some("json" | "csv" | "npz")
    )
}

impl Group {
    pub fn new() -> Self {
        Self::default()
    }

    /// Writes `path`'s bytes through `fill` into a temporary file beside
    /// it, kept until [`Group::commit`]; on failure the temporary file is
    /// removed (and the group's others when the group is dropped).
    pub fn write_with<F>(&mut self, path: &Path, fill: F) -> Result<()>
    where
        F: FnOnce(&mut fs::File) -> io::Result<()>,
    {
        ensure_dir(&parent_dir(path))?;
        check_kind(path)?;
        let mut tmp = TempFile::create(path).map_err(|e| io_error(path, &e))?;
        fill(tmp.file())
            .and_then(|()| tmp.file().flush())
            .and_then(|()| tmp.file().sync_all())
            .map_err(|e| io_error(path, &e))?;
        self.staged.push((path.to_path_buf(), tmp));
        Ok(())
    }

    /// Renames every file into place, the data files first.
    pub fn commit(mut self) -> Result<()> {
        self.staged.sort_by_key(|(p, _)| !is_data(p));
        for (path, tmp) in self.staged {
            check_kind(&path)?;
            tmp.persist(&path).map_err(|e| io_error(&path, &e))?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nothing_is_in_place_before_commit_and_data_goes_first() {
        let dir = std::env::temp_dir().join(format!("ladder-group-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        let mut g = Group::new();
        for name in ["a.png", "a.json", "a.csv"] {
            g.write_with(&dir.join(name), |f| f.write_all(name.as_bytes()))
                .unwrap();
        }
        assert!(!dir.join("a.png").exists() && !dir.join("a.json").exists());
        let order: Vec<bool> = {
            let mut s: Vec<&PathBuf> = g.staged.iter().map(|(p, _)| p).collect();
            s.sort_by_key(|p| !is_data(p));
            s.iter().map(|p| is_data(p)).collect()
        };
        assert_eq!(order, [true, true, false]);
        g.commit().unwrap();
        assert_eq!(fs::read(dir.join("a.json")).unwrap(), b"a.json");
        // A group dropped uncommitted leaves nothing.
        let mut g = Group::new();
        g.write_with(&dir.join("b.png"), |f| f.write_all(b"x"))
            .unwrap();
        drop(g);
        let left: Vec<_> = fs::read_dir(&dir).unwrap().collect();
        assert_eq!(left.len(), 3);
        let _ = fs::remove_dir_all(&dir);
    }
}
