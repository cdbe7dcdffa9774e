//! Records the git commit the program is built from, when it is built from a
//! clone, so that `--version` and every data file can say it (`src/version.rs`).
//! Built from a source archive (no `.git`), the commit is simply absent.

use std::process::Command;

fn git(args: &[&str]) -> Option<String> {
    // GIT_OPTIONAL_LOCKS=0: `git status` must not rewrite .git/index (which
    // this script watches), or every build would trigger the next one.
    let out = Command::new("git")
        .args(args)
        .env("GIT_OPTIONAL_LOCKS", "0")
        .output()
        .ok()?;
    if !out.status.success() {
        return None;
    }
    let text = String::from_utf8(out.stdout).ok()?;
    let text = text.trim();
    (!text.is_empty()).then(|| text.to_string())
}

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    // Rebuild when HEAD moves (a commit, a checkout) or the index changes.
    if let Some(dir) = git(&["rev-parse", "--git-dir"]) {
        println!("cargo:rerun-if-changed={dir}/HEAD");
        println!("cargo:rerun-if-changed={dir}/index");
        if let Some(head_ref) = git(&["symbolic-ref", "-q", "HEAD"]) {
            println!("cargo:rerun-if-changed={dir}/{head_ref}");
        }
    }
    let version = std::env::var("CARGO_PKG_VERSION").unwrap_or_default();
    let long = match git(&["rev-parse", "--short=12", "HEAD"]) {
        Some(commit) => {
            let dirty = git(&["status", "--porcelain", "--untracked-files=no"]).is_some();
            let commit = if dirty {
                format!("{commit}-modified")
            } else {
                commit
            };
            println!("cargo:rustc-env=LADDER_GIT_COMMIT={commit}");
            format!("{version} (commit {commit})")
        }
        None => version,
    };
    println!("cargo:rustc-env=LADDER_VERSION_LONG={long}");
}
