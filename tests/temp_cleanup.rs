//! The work of the SIGINT/SIGTERM handler (`output::temp`), without the
//! signal: every live temporary file is removed, and none can be created
//! or renamed into place afterwards. In a test binary of its own: it
//! leaves this process "terminating" (every later temporary file of the
//! process refused), and it counts every live temporary file of the
//! process, which in the integration binary would include other tests'.
//! (`tests/integration/reliability.rs` sends the real signals to the
//! binary.)

#[allow(dead_code)] // the helpers this test does not use
#[path = "integration/common/tempdir.rs"]
mod tempdir;

use jacobs_ladder::output::temp::{TempFile, remove_all_live};
use std::io::Write;

#[test]
fn the_handler_removes_every_live_temporary_file_and_stops_new_ones() {
    let dir = tempdir::TempDir::new("live");
    let targets: Vec<_> = ["a.png", "b.gif", "c.csv"]
        .iter()
        .map(|n| dir.join(n))
        .collect();
    let mut live: Vec<TempFile> = targets
        .iter()
        .map(|t| TempFile::create(t).unwrap())
        .collect();
    for f in &mut live {
        f.file().write_all(b"half a file").unwrap();
    }
    let paths: Vec<_> = live.iter().map(|f| f.path().to_path_buf()).collect();
    for p in &paths {
        assert!(p.is_file());
    }
    assert_eq!(remove_all_live(), 3);
    for p in &paths {
        assert!(!p.exists(), "{} left", p.display());
    }
    // No new file, and no rename of a file written before the signal.
    assert!(TempFile::create(&dir.join("d.png")).is_err());
    let last = live.pop().unwrap();
    assert!(last.persist(&targets[2]).is_err());
    assert!(!targets[2].exists());
    drop(live);
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
}
