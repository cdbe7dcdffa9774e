//! Preconditions of a test (a tool, a device, a CPU feature), never
//! skipped in silence (docs/testing.md).
//!
//! [`require`] says whether a precondition holds. When it does not:
//! - under CI (`CI` set to anything but `false`/`0`, or
//!   `LADDER_REQUIRE_ALL=1`) the test fails: a CI log never shows a green
//!   run that did not test;
//! - elsewhere the test goes on without the part that needs it, and the
//!   skip is said where the runner shows it: one `SKIPPED` line written
//!   straight to the process's standard error (not through `eprintln!`,
//!   which the test harness captures and hides for a passing test), and
//!   one line appended to the file `LADDER_SKIP_LOG` names, from which
//!   `scripts/test` prints a summary of every skip at the end of the run.
//!
//! [`note`] says, the same uncaptured way, what a test did run (for
//! example which kernels), so that a log shows it.

use std::io::Write;

/// Whether this run is CI's: every precondition must hold.
pub fn strict() -> bool {
    let set = |k: &str, off: &[&str]| std::env::var(k).is_ok_and(|v| !off.contains(&v.as_str()));
    set("CI", &["", "false", "0"]) || set("LADDER_REQUIRE_ALL", &["", "0"])
}

/// A line the test harness does not capture: it shows in `cargo test`'s
/// own output whether the test passes or fails.
pub fn note(line: &str) {
    let mut err = std::io::stderr().lock();
    let _ = writeln!(err, "{line}");
}

/// Records that `test` skipped `part` because `what` is missing.
fn record_skip(test: &str, what: &str, hint: &str) {
    let line = format!("SKIPPED {test}: {what} ({hint})");
    note(&line);
    if let Some(log) = std::env::var_os("LADDER_SKIP_LOG") {
        // One short write per line in append mode: lines from tests
        // running in parallel do not interleave.
        if let Ok(mut f) = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(log)
        {
            let _ = f.write_all(format!("{line}\n").as_bytes());
        }
    }
}

/// Whether the precondition of `test` described by `what` (e.g. "GNU
/// parallel is not installed") holds (`present`). If it does not: fails
/// the test under CI ([`strict`]), else reports the skip (module doc) and
/// returns `false`. `hint` says how to provide it.
pub fn require(test: &str, present: bool, what: &str, hint: &str) -> bool {
    if present {
        return true;
    }
    if strict() {
        panic!(
            "{test}: {what}; under CI every precondition must hold ({hint}). \
             Outside CI (CI unset) the test would be reported as skipped."
        );
    }
    record_skip(test, what, hint);
    false
}

/// Reports a skip that even CI cannot remedy (a CPU feature this machine
/// lacks): never fails, always recorded. `LADDER_REQUIRE_CPU=FEATURE`
/// (e.g. `avx512`) turns it into a failure on a machine meant to have it.
pub fn cpu_lacks(test: &str, feature: &str, what: &str) {
    let wanted = std::env::var("LADDER_REQUIRE_CPU")
        .is_ok_and(|v| v.split(',').any(|f| f.trim() == feature));
    if wanted {
        panic!("{test}: {what}, and LADDER_REQUIRE_CPU asks for {feature}");
    }
    record_skip(
        test,
        what,
        "a CPU feature this machine lacks; no install can add it",
    );
}

/// Whether the program `name` starts (on PATH and executable: `name arg`
/// runs, whatever its exit status); if not, [`require`] with the hint to
/// install `package` (what `.ci/run` installs). For example
/// `tool(test, "pdffonts", "-v", "poppler-utils")`.
pub fn tool(test: &str, name: &str, arg: &str, package: &str) -> bool {
    let present = std::process::Command::new(name)
        .arg(arg)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status()
        .is_ok();
    require(
        test,
        present,
        &format!("{name} is not installed"),
        &format!("apt-get install {package}; .ci/run installs it"),
    )
}

/// Whether `python3` on PATH imports numpy; if not, [`require`] with the
/// hint to install it (`.ci/run` does).
pub fn numpy(test: &str) -> bool {
    let present = std::process::Command::new("python3")
        .args(["-c", "import numpy"])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    require(
        test,
        present,
        "python3 with numpy is not installed",
        "apt-get install python3-numpy, or pip install numpy; .ci/run installs it",
    )
}

/// Whether `program` runs with `arg` and prints `marker` on stdout.
pub fn runs(program: &str, arg: &str, marker: &str) -> bool {
    std::process::Command::new(program)
        .arg(arg)
        .output()
        .map(|o| o.status.success() && String::from_utf8_lossy(&o.stdout).contains(marker))
        .unwrap_or(false)
}
