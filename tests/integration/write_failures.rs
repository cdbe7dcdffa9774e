//! Where a write cannot happen, the exit code the README states: 2 for
//! what the user can fix before any work (a read-only folder or file
//! system, a device such as /dev/full in place of a file), 1 for a write
//! the machine failed (a full disk: tests/integration/reliability.rs,
//! `a_full_disk_is_a_failed_run`).

use crate::common::require::require;
use crate::common::tempdir::TempDir;
use std::process::{Command, Output};

use crate::common::ladder_cli as ladder;

fn one_line(out: &Output, code: i32, needle: &str) {
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(code), "{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(err.contains(needle), "'{needle}' not in {err}");
}

#[test]
fn the_readme_states_the_codes_the_program_gives() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md"))
        .unwrap()
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    for words in [
        "2 bad input",
        "a read-only folder or file system",
        "a device such as `/dev/full` where a file should go",
        "1 a write that the machine failed (a full disk",
    ] {
        assert!(readme.contains(words), "README: no '{words}'");
    }
}

#[test]
fn a_device_in_place_of_a_file_is_exit_2() {
    if !require(
        "a_device_in_place_of_a_file_is_exit_2",
        std::path::Path::new("/dev/full").exists(),
        "this system has no /dev/full",
        "run on Linux",
    ) {
        return;
    }
    one_line(
        &ladder(&["simulate", "--t-end", "10", "--csv", "/dev/full"]),
        2,
        "device",
    );
}

#[test]
fn a_read_only_folder_is_exit_2() {
    let dir = TempDir::new("read-only");
    let target = dir.join("ro");
    std::fs::create_dir(&target).unwrap();
    // As root, permission bits do not stop a write: a read-only tmpfs does.
    let root = unsafe { libc::geteuid() == 0 };
    let mounted = root
        && Command::new("mount")
            .args(["-t", "tmpfs", "-o", "ro,size=64k", "tmpfs"])
            .arg(&target)
            .status()
            .is_ok_and(|s| s.success());
    if !root {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&target, std::fs::Permissions::from_mode(0o555)).unwrap();
    } else if !require(
        "a_read_only_folder_is_exit_2",
        mounted,
        "cannot mount a read-only tmpfs",
        "run as root where mount works",
    ) {
        return;
    }
    let csv = target.join("run.csv");
    let out = ladder(&["simulate", "--t-end", "10", "--csv", csv.to_str().unwrap()]);
    if mounted {
        let _ = Command::new("umount").arg(&target).status();
        one_line(&out, 2, "read-only");
    } else {
        one_line(&out, 2, "permission denied");
    }
    assert!(!csv.exists());
}

/// A disk that fills while an output's files are written leaves no picture
/// without its data file (before, `ladder all` on a full disk left
/// `figure-chain-length.png` and `.csv` without their `.json`): a scene's
/// files go into place together once all are written, the data first.
/// The disk is a file-size limit (`ulimit -f`) that the movie and its
/// kymograph fit under and the data file (written last) does not.
#[test]
fn a_full_disk_leaves_no_picture_without_its_data() {
    let args = ["movie", "4", "--frames", "200", "--size", "64x64", "--out"];
    let whole = TempDir::new("group-whole");
    let mut a = args.to_vec();
    a.push(whole.path().to_str().unwrap());
    let out = ladder(&a);
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let size = |name: &str| std::fs::metadata(whole.join(name)).unwrap().len();
    let pictures = size("movie-4.gif").max(size("movie-4-kymograph.png"));
    let json = size("movie-4.json");
    assert!(
        json > pictures + 8192,
        "pictures {pictures}, json {json} bytes"
    );
    // A limit in 512-byte blocks between the two sizes.
    let blocks = pictures / 512 + 4;
    let dir = TempDir::new("group-full");
    let script = format!(
        "ulimit -f {blocks} && trap '' XFSZ && exec \"$0\" {} '{}'",
        args.join(" "),
        dir.path().display()
    );
    let out = Command::new("sh")
        .args(["-c", &script, env!("CARGO_BIN_EXE_ladder")])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("movie-4.json"), "{err}");
    let names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(
        !names
            .iter()
            .any(|n| n.ends_with(".png") || n.ends_with(".gif")),
        "a picture without its data: {names:?}"
    );
}
