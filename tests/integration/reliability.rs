//! Reliability under hostile input, one test per row of the
//! issue's table, run against the binary: no hang, no panic, no abort,
//! bounded memory, nothing left behind. A hang is caught by a watchdog
//! that kills the process (a bound on "forever", not a speed assertion).
//! Where the system lacks what a row needs (a device node, a FIFO,
//! /dev/full, a tmpfs mount), that part fails under CI and is reported as
//! skipped elsewhere (`common::require`).

use crate::common;

use crate::common::tempdir::TempDir;
use std::io::Read;
use std::path::Path;
use std::process::{Child, Command, ExitStatus, Output, Stdio};
use std::time::{Duration, Instant};

/// Longer than any of these commands takes, far shorter than "forever".
const WATCHDOG: Duration = Duration::from_secs(120);

fn ladder_cmd(args: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_ladder"));
    c.args(args);
    c
}

/// Waits for `child`, killing it past the watchdog (then the test fails).
fn wait_bounded(child: &mut Child, what: &str) -> ExitStatus {
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return status;
        }
        if start.elapsed() > WATCHDOG {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{what}: still running after {WATCHDOG:?} (a hang)");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Reads `child`'s stderr to its end, then waits for it (bounded).
fn stderr_and_wait(child: &mut Child, what: &str) -> (String, ExitStatus) {
    let mut err = String::new();
    let mut pipe = child.stderr.take().expect("stderr is piped");
    pipe.read_to_string(&mut err).unwrap();
    (err, wait_bounded(child, what))
}

/// Runs `ladder ARGS` with the watchdog; stdout and stderr captured.
fn ladder(args: &[&str]) -> Output {
    let mut child = ladder_cmd(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the ladder binary runs");
    // Drain the pipes in threads so a large output cannot block the child.
    let mut out = child.stdout.take().unwrap();
    let mut err = child.stderr.take().unwrap();
    let t_out = std::thread::spawn(move || {
        let mut v = Vec::new();
        let _ = out.read_to_end(&mut v);
        v
    });
    let t_err = std::thread::spawn(move || {
        let mut v = Vec::new();
        let _ = err.read_to_end(&mut v);
        v
    });
    let status = wait_bounded(&mut child, &format!("ladder {args:?}"));
    Output {
        status,
        stdout: t_out.join().unwrap(),
        stderr: t_err.join().unwrap(),
    }
}

fn stderr_of(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// Exit `code` with exactly one line on stderr containing every needle.
fn assert_one_line(args: &[&str], out: &Output, code: i32, needles: &[&str]) {
    let err = stderr_of(out);
    assert_eq!(out.status.code(), Some(code), "{args:?}: {err}");
    assert_eq!(err.lines().count(), 1, "{args:?}: one line wanted: {err}");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: '{n}' not in {err}");
    }
}

fn is_root() -> bool {
    // SAFETY: geteuid has no preconditions.
    unsafe { libc::geteuid() == 0 }
}

/// The `.tmp-` and probe files of ours left in `dir`.
fn temporaries(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .map(|rd| {
            rd.flatten()
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .filter(|n| n.contains(".tmp-") || n.starts_with(".ladder-probe"))
                .collect()
        })
        .unwrap_or_default()
}

// ------------------------------------------------------------------ rows

/// `ladder theory --b 1e-17` (and 5e-324, 1e308) hung in an SVD without an
/// iteration cap: now one line and exit 2 (lengths outside what the
/// linear algebra can resolve), quickly.
#[test]
fn theory_with_extreme_lengths_ends_with_one_line() {
    for b in ["1e-17", "5e-324", "1e308", "1e-4", "1e4", "inf", "NaN"] {
        let args = ["theory", "--b", b];
        let out = ladder(&args);
        assert_one_line(&args, &out, 2, &["b "]);
    }
    // The edges of the range still work, with every count.
    for b in ["1e-3", "1e3"] {
        let args = ["theory", "--b", b, "--json"];
        let out = ladder(&args);
        assert_eq!(out.status.code(), Some(0), "{b}: {}", stderr_of(&out));
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(v["zero_modes_free"], 12, "{b}");
    }
}

/// `--dt 1e-320`: t + dt == t, so time never advanced: refused before
/// the run (exit 2), whatever the caps.
#[test]
fn a_step_that_cannot_advance_time_is_refused() {
    let args = ["simulate", "--dt", "1e-320", "--t-end", "10"];
    assert_one_line(&args, &ladder(&args), 2, &["dt = 1e-320"]);
    let args = [
        "simulate",
        "--dt",
        "1e-320",
        "--t-end",
        "10",
        "--max-block-steps",
        "inf",
    ];
    assert_one_line(&args, &ladder(&args), 2, &["too small"]);
}

/// `--t-end 1e12` ran for months: refused (exit 2) with the cost, the cap
/// and the flag that raises it.
#[test]
fn a_run_past_the_step_cap_is_refused_with_the_flag_to_raise_it() {
    let args = ["simulate", "--t-end", "1e9"];
    assert_one_line(
        &args,
        &ladder(&args),
        2,
        &["block-steps", "1.0e10", "--max-block-steps"],
    );
    // Adaptive dopri5: its fewest steps already exceed the cap.
    let args = ["simulate", "--integrator", "dopri5", "--t-end", "1e12"];
    assert_one_line(&args, &ladder(&args), 2, &["--max-block-steps"]);
    // Raised on request, the same kind of run goes (a small one here).
    let args = [
        "simulate",
        "--t-end",
        "20",
        "--max-block-steps",
        "100",
        "--json",
    ];
    assert_one_line(&args, &ladder(&args), 2, &["past the cap of 100"]);
    let args = ["simulate", "--t-end", "1e9", "--max-block-steps", "0"];
    assert_one_line(&args, &ladder(&args), 2, &["--max-block-steps"]);
}

/// `--n 100000 --integrator auto` aborted on a 480 GB allocation (dense
/// O(N³) ω_max): now ω_max comes from the band Hessian in O(N).
#[test]
fn auto_runs_a_hundred_thousand_blocks() {
    let args = [
        "simulate",
        "--n",
        "100000",
        "--integrator",
        "auto",
        "--t-end",
        "10",
        "--json",
    ];
    let out = ladder(&args);
    assert_eq!(out.status.code(), Some(0), "{}", stderr_of(&out));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["model"]["n"], 100_000);
    assert_eq!(v["integrator"]["name"], "verlet");
    assert_eq!(v["arrival_times"].as_array().unwrap().len(), 100_000);
    // A ladder past the largest N is one line.
    let args = ["simulate", "--n", "100001", "--integrator", "auto"];
    assert_one_line(&args, &ladder(&args), 2, &["100000"]);
}

/// `--integrator auto --n 5000` took 3 GB and 40 s in ω_max alone.
#[test]
fn auto_at_five_thousand_blocks_needs_no_dense_matrix() {
    let args = [
        "simulate",
        "--n",
        "5000",
        "--integrator",
        "auto",
        "--t-end",
        "5",
        "--json",
    ];
    let out = ladder(&args);
    assert_eq!(out.status.code(), Some(0), "{}", stderr_of(&out));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    // ω_max ≈ 2.57 allows auto's largest step, 0.25, checked at half of it.
    let dt = v["integrator"]["dt"].as_f64().unwrap();
    assert!(dt > 0.1 && dt <= 0.25, "dt = {dt}");
}

/// The CSV sample cap ignored N (480 GB): samples × N is capped, before
/// anything is allocated, and no file is written.
#[test]
fn csv_samples_are_capped_by_samples_times_n() {
    let dir = TempDir::new("csv-cap");
    let csv = dir.join("theta.csv");
    let args = [
        "simulate",
        "--n",
        "1000",
        "--t-end",
        "40",
        "--csv",
        csv.to_str().unwrap(),
        "--sample-every",
        "0.000004",
    ];
    assert_one_line(
        &args,
        &ladder(&args),
        2,
        &["block-samples", "--max-block-samples"],
    );
    assert!(!csv.exists());
    assert!(temporaries(&dir).is_empty(), "{:?}", temporaries(&dir));
}

/// A movie's frames × pixels are capped; a 1920×1080 movie of 1000 frames
/// is within the default cap (checked without rendering it).
#[test]
fn movie_pixels_are_capped() {
    let dir = TempDir::new("pixels");
    let out_dir = dir.to_str().unwrap();
    let args = [
        "movie",
        "4",
        "--out",
        out_dir,
        "--frames",
        "5000",
        "--size",
        "4096x4096",
    ];
    assert_one_line(&args, &ladder(&args), 2, &["pixels", "--max-pixels"]);
    assert!(std::fs::read_dir(&dir).unwrap().next().is_none());
}

/// `ladder list > /dev/full` panicked (exit 101): now exit 1, one line.
#[test]
fn stdout_that_cannot_be_written_exits_1() {
    let full = std::fs::OpenOptions::new().write(true).open("/dev/full");
    if !common::require::require(
        "stdout_that_cannot_be_written_exits_1",
        full.is_ok(),
        "this system has no /dev/full",
        "Linux provides it",
    ) {
        return;
    }
    let full = full.expect("checked above");
    let mut child = ladder_cmd(&["list"])
        .stdout(full)
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let (err, status) = stderr_and_wait(&mut child, "list > /dev/full");
    assert_eq!(status.code(), Some(1), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("standard output") && !err.contains("panicked"),
        "{err}"
    );
}

/// `ladder figure zz 2>/dev/full` panicked: now exit 1 (stderr cannot
/// be written), no abort.
#[test]
fn stderr_that_cannot_be_written_exits_1() {
    let full = std::fs::OpenOptions::new().write(true).open("/dev/full");
    if !common::require::require(
        "stderr_that_cannot_be_written_exits_1",
        full.is_ok(),
        "this system has no /dev/full",
        "Linux provides it",
    ) {
        return;
    }
    let full = full.expect("checked above");
    let mut child = ladder_cmd(&["figure", "zz"])
        .stdout(Stdio::null())
        .stderr(full)
        .spawn()
        .unwrap();
    let status = wait_bounded(&mut child, "figure zz 2>/dev/full");
    assert_eq!(status.code(), Some(1));
}

/// `... --json | head -c1`: a broken pipe ends the program quietly with
/// success, as Unix tools do.
#[test]
fn a_closed_pipe_ends_quietly_with_success() {
    // 100,000 blocks: the JSON (about 2 MB) is far larger than a pipe's
    // buffer, so the program is still writing when the reader goes.
    let mut child = ladder_cmd(&["simulate", "--n", "100000", "--t-end", "1", "--json"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdout = child.stdout.take().unwrap();
    let mut first = [0u8; 1];
    stdout.read_exact(&mut first).unwrap();
    assert_eq!(&first, b"{");
    drop(stdout);
    let (err, status) = stderr_and_wait(&mut child, "simulate --json | head -c1");
    assert_eq!(status.code(), Some(0), "{err}");
    assert!(err.is_empty(), "quietly: {err}");
}

/// As root, `--csv` renamed a regular file over a device node or a
/// symlink: now only regular files are replaced; a device, a FIFO, a
/// symlink or a folder in the way is one line, exit 2, left as it was.
#[test]
fn only_regular_files_are_replaced() {
    let dir = TempDir::new("kinds");
    let target = dir.join("target.csv");
    std::fs::write(&target, "keep").unwrap();
    let mut cases: Vec<(String, &str)> = Vec::new();
    let link = dir.join("link.csv");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    cases.push((link.to_str().unwrap().into(), "symbolic link"));
    let folder = dir.join("folder.csv");
    std::fs::create_dir(&folder).unwrap();
    cases.push((folder.to_str().unwrap().into(), "folder"));
    let fifo = dir.join("fifo.csv");
    let c_fifo = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
    // SAFETY: a valid NUL-terminated path.
    if unsafe { libc::mkfifo(c_fifo.as_ptr(), 0o644) } == 0 {
        cases.push((fifo.to_str().unwrap().into(), "FIFO"));
    } else {
        common::require::require(
            "special files (FIFO case)",
            false,
            "mkfifo failed",
            "a file system with FIFOs",
        );
    }
    let null = dir.join("null");
    let c_null = std::ffi::CString::new(null.to_str().unwrap()).unwrap();
    // SAFETY: a valid path; makedev(1, 3) is /dev/null's device number.
    let made = is_root()
        && unsafe { libc::mknod(c_null.as_ptr(), libc::S_IFCHR | 0o666, libc::makedev(1, 3)) } == 0;
    if made {
        cases.push((null.to_str().unwrap().into(), "device"));
    } else {
        common::require::require(
            "special files (device case)",
            false,
            "cannot mknod (not root, or not allowed)",
            "run as root, as CI does",
        );
    }
    for (path, kind) in &cases {
        let args = ["simulate", "--t-end", "10", "--csv", path];
        assert_one_line(&args, &ladder(&args), 2, &[kind, "regular files"]);
    }
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "keep");
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert!(folder.is_dir());
    if made {
        use std::os::unix::fs::FileTypeExt;
        let kind = std::fs::symlink_metadata(&null).unwrap().file_type();
        assert!(kind.is_char_device(), "the device node is still there");
    }
    assert!(temporaries(&dir).is_empty(), "{:?}", temporaries(&dir));
}

/// Temporary files stayed forever after a kill, and later runs kept them:
/// a later run removes stale files of our naming (no process holds their
/// lock), and keeps everyone else's (tests/integration/hostile.rs checks the locked,
/// linked and foreign cases).
#[test]
fn a_later_run_removes_stale_temporary_files() {
    let dir = TempDir::new("stale");
    let stale = [
        ".figure-3.png.tmp-0123456789abcdef",
        ".index.html.tmp-fedcba9876543210",
        ".ladder-probe.tmp-00000000000000ff",
    ];
    for s in &stale {
        std::fs::write(dir.join(s), "partial").unwrap();
    }
    let keep = ["notes.tmp-12", ".hidden"];
    for k in keep {
        std::fs::write(dir.join(k), "mine").unwrap();
    }
    let args = ["figure", "3", "--out", dir.to_str().unwrap()];
    let out = ladder(&args);
    assert_eq!(out.status.code(), Some(0), "{}", stderr_of(&out));
    for s in &stale {
        assert!(!dir.join(s).exists(), "{s} was not removed");
    }
    for k in keep {
        assert!(dir.join(k).exists(), "{k} was removed");
    }
    assert!(dir.join("figure-3.png").is_file());
}

/// SIGINT and SIGTERM remove the current run's temporary files; after
/// SIGKILL (which no handler sees) the next run removes them. Each signal
/// is sent at several moments of `ladder all`, so some land while files
/// are being written.
#[test]
fn signals_leave_no_temporary_files() {
    let root = TempDir::new("signals");
    let delays_ms = [50u64, 150, 300, 500, 800];
    for (signal, name) in [(libc::SIGINT, "INT"), (libc::SIGTERM, "TERM")] {
        for ms in delays_ms {
            let dir = root.join(format!("{name}-{ms}"));
            let mut child = ladder_cmd(&["all", "--out", dir.to_str().unwrap()])
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .spawn()
                .unwrap();
            std::thread::sleep(Duration::from_millis(ms));
            // SAFETY: a child of ours, still to be waited for.
            unsafe { libc::kill(child.id() as libc::pid_t, signal) };
            let status = wait_bounded(&mut child, "ladder all");
            use std::os::unix::process::ExitStatusExt;
            // Ended by the signal, or finished before it came.
            assert!(
                status.signal() == Some(signal) || status.success(),
                "SIG{name} at {ms} ms: {status:?}"
            );
            assert!(
                temporaries(&dir).is_empty(),
                "SIG{name} at {ms} ms left {:?}",
                temporaries(&dir)
            );
        }
    }
    let dir = root.join("KILL");
    for ms in delays_ms {
        let mut child = ladder_cmd(&["all", "--out", dir.to_str().unwrap()])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(Duration::from_millis(ms));
        let _ = child.kill();
        let _ = child.wait();
    }
    let out = ladder(&["figure", "3", "--out", dir.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr_of(&out));
    assert!(temporaries(&dir).is_empty(), "{:?}", temporaries(&dir));
}

/// `all --out D` with `D/index.html` a folder failed only after rendering
/// everything: now every target is checked first, and nothing is written.
#[test]
fn every_target_is_checked_before_rendering() {
    let dir = TempDir::new("index-folder");
    std::fs::create_dir(dir.join("index.html")).unwrap();
    let args = ["all", "--out", dir.to_str().unwrap()];
    let out = ladder(&args);
    assert_one_line(&args, &out, 2, &["index.html", "folder"]);
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .flatten()
        .map(|e| e.file_name())
        .collect();
    assert_eq!(names, ["index.html"], "nothing rendered");
    // A figure's own target in the way is caught the same way.
    std::fs::create_dir(dir.join("figure-3.png")).unwrap();
    let args = ["figure", "3", "--out", dir.to_str().unwrap()];
    assert_one_line(&args, &ladder(&args), 2, &["figure-3.png", "folder"]);
}

/// A full disk was reported as bad input (exit 2): it is a failure of the
/// machine (exit 1), and the partial file is removed. Shown on a 64 KB
/// tmpfs where the system lets us mount one, and with a file-size limit
/// (`ulimit -f`, EFBIG) everywhere.
#[test]
fn a_full_disk_is_a_failed_run() {
    let dir = TempDir::new("full");
    // File-size limit: 1 block of 512 bytes; SIGXFSZ ignored so that the
    // write fails with EFBIG instead of killing the process.
    let csv = dir.join("big.csv");
    let script = format!(
        "ulimit -f 1 && trap '' XFSZ && exec \"$0\" simulate --t-end 4000 --sample-every 1 --csv '{}'",
        csv.display()
    );
    let mut child = Command::new("sh")
        .args(["-c", &script, env!("CARGO_BIN_EXE_ladder")])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let (err, status) = stderr_and_wait(&mut child, "ulimit -f");
    assert_eq!(status.code(), Some(1), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("big.csv"), "{err}");
    assert!(!csv.exists());
    assert!(temporaries(&dir).is_empty(), "{:?}", temporaries(&dir));

    // A real full file system, where we may mount one.
    let mnt = dir.join("mnt");
    std::fs::create_dir(&mnt).unwrap();
    let mounted = is_root()
        && Command::new("mount")
            .args(["-t", "tmpfs", "-o", "size=64k", "tmpfs"])
            .arg(&mnt)
            .stderr(Stdio::null())
            .status()
            .is_ok_and(|s| s.success());
    if !common::require::require(
        "full file system (tmpfs case)",
        mounted,
        "cannot mount a small tmpfs here",
        "run as root with mount allowed, as CI does",
    ) {
        return;
    }
    let csv = mnt.join("theta.csv");
    let args = [
        "simulate",
        "--t-end",
        "4000",
        "--sample-every",
        "0.1",
        "--csv",
        csv.to_str().unwrap(),
    ];
    let out = ladder(&args);
    let left = temporaries(&mnt);
    let exists = csv.exists();
    let _ = Command::new("umount").arg(&mnt).status();
    assert_one_line(&args, &out, 1, &["no space left on device"]);
    assert!(!exists, "a partial file was left");
    assert!(left.is_empty(), "{left:?}");
}
