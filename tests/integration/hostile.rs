//! Hostile files and shared folders: nothing that is not ours
//! is touched, no shard file is trusted, every cost is checked before
//! work, and the user's words are checked where they enter.

use crate::common::tempdir::TempDir;
use std::path::Path;
use std::process::{Command, Output, Stdio};

fn ladder_cmd(args: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_ladder"));
    c.args(args).stdin(Stdio::null());
    c
}

fn ladder(args: &[&str]) -> Output {
    ladder_cmd(args).output().expect("the ladder binary runs")
}

fn stderr_of(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn ok(args: &[&str], out: &Output) {
    assert_eq!(out.status.code(), Some(0), "{args:?}: {}", stderr_of(out));
}

/// Exit `code` with exactly one line on stderr containing every needle.
fn one_line(args: &[&str], out: &Output, code: i32, needles: &[&str]) {
    let err = stderr_of(out);
    assert_eq!(out.status.code(), Some(code), "{args:?}: {err}");
    assert_eq!(err.lines().count(), 1, "{args:?}: one line wanted: {err}");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: '{n}' not in {err}");
    }
}

/// Every file name under `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .map(|rd| {
            rd.flatten()
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

// ------------------------------------------------ 1. files that are not ours

/// The folder-write probe was opened with create+truncate under
/// `.ladder-probe-PID` and followed a symlink planted there, truncating a
/// file outside `--out`. The symlink is planted under the name the old
/// probe would use (the shell's PID, which `exec` hands to ladder) and
/// under a few other names; the victim keeps its bytes.
#[test]
fn a_symlink_planted_under_the_probe_name_is_not_followed() {
    let dir = TempDir::new("probe-link");
    let out = dir.join("out");
    std::fs::create_dir(&out).unwrap();
    let victim = dir.join("victim.txt");
    std::fs::write(&victim, "precious").unwrap();
    let script = format!(
        "ln -s {v} {o}/.ladder-probe-$$ && ln -s {v} {o}/.ladder-probe.tmp-0000000000000000 && \
         exec {bin} figure 3 --out {o}",
        v = victim.display(),
        o = out.display(),
        bin = env!("CARGO_BIN_EXE_ladder")
    );
    let res = Command::new("sh").args(["-c", &script]).output().unwrap();
    assert_eq!(res.status.code(), Some(0), "{}", stderr_of(&res));
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "precious");
    assert!(out.join("figure-3.png").is_file());
    // The links are not ours: left as they were.
    let left = names(&out);
    assert!(
        left.iter().any(|n| n.starts_with(".ladder-probe-")),
        "{left:?}"
    );
}

/// Whether this machine can run a command in a new user and PID
/// namespace (then a process id of ours means nothing there, as on
/// another machine).
fn unshare_works() -> bool {
    Command::new("unshare")
        .args(["-U", "-p", "-f", "true"])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

const GRID: [&str; 5] = ["--alpha=-50,-56", "--gamma", "0.02,0.04", "--name", "two"];

fn shard_args<'a>(out: &'a str, shard: &'a str) -> Vec<&'a str> {
    let mut a = vec!["sweep"];
    a.extend(GRID);
    a.extend(["--out", out, "--shard", shard]);
    a
}

/// Two shards of one sweep, as if from two machines sharing a folder.
/// Shard 1 (this test, holding the temporary file of its shard file as
/// the program does while writing it) is alive; shard 2 starts in another
/// PID namespace, where shard 1's process id does not exist. The old
/// cleanup judged shard 1's live temporary file stale by the process table
/// and deleted it mid-write; now shard 1 finishes its write, runs, and the
/// gather equals the unsharded sweep.
#[test]
fn two_shards_sharing_a_folder_from_two_machines_keep_each_others_files() {
    use jacobs_ladder::output::temp::TempFile;
    use std::io::Write;
    let dir = TempDir::new("two-machines");
    let d = dir.path().to_str().unwrap();
    let shards = dir.join("shards");
    std::fs::create_dir_all(&shards).unwrap();
    let target = shards.join("sweep-two.1-of-2.json");
    let mut live = TempFile::create(&target).unwrap();
    live.file().write_all(b"{\"half\": ").unwrap();

    let args = shard_args(d, "2/2");
    let apart = crate::common::require::require(
        "hostile::two_shards_sharing_a_folder_from_two_machines_keep_each_others_files",
        unshare_works(),
        "`unshare -U -p -f` does not run here (no user and PID namespaces)",
        "a kernel or container that allows them; shard 2 ran in this PID namespace",
    );
    let out = if apart {
        let mut a = vec!["-U", "-p", "-f", env!("CARGO_BIN_EXE_ladder")];
        a.extend(args.iter().copied());
        Command::new("unshare").args(&a).output().unwrap()
    } else {
        ladder(&args)
    };
    ok(&args, &out);
    assert!(
        live.path().is_file(),
        "shard 2 removed shard 1's live temporary file"
    );
    live.file().write_all(b"1}").unwrap();
    live.persist(&target).expect("shard 1's write completes");

    // Shard 1 runs for real (its file above is not a shard file: replaced).
    let args1 = shard_args(d, "1/2");
    ok(&args1, &ladder(&args1));
    ok(&["gather"], &ladder(&["sweep", "gather", d]));
    let whole = TempDir::new("two-machines-whole");
    let mut a = vec!["sweep"];
    a.extend(GRID);
    a.extend(["--out", whole.path().to_str().unwrap()]);
    ok(&a, &ladder(&a));
    assert_eq!(
        std::fs::read(dir.join("sweep-two.csv")).unwrap(),
        std::fs::read(whole.join("sweep-two.csv")).unwrap()
    );
}

/// A temporary file of our naming that another process holds locked
/// (alive, wherever it runs) is kept; one whose lock is free (its writer
/// is gone) is removed; the old PID naming, a symlink of our naming and a
/// user's file are not provably ours and are kept.
#[test]
fn stale_cleanup_removes_only_what_is_ours_and_dead() {
    use std::os::unix::io::AsRawFd;
    let dir = TempDir::new("stale-lock");
    let dead = ".figure-3.png.tmp-00000000deadbeef";
    let held = ".figure-3.png.tmp-0000000012345678";
    std::fs::write(dir.join(dead), "partial").unwrap();
    std::fs::write(dir.join(held), "being written").unwrap();
    let holder = std::fs::OpenOptions::new()
        .write(true)
        .open(dir.join(held))
        .unwrap();
    // SAFETY: flock on a descriptor we own.
    assert_eq!(
        unsafe { libc::flock(holder.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) },
        0
    );
    let victim = dir.join("victim.txt");
    std::fs::write(&victim, "precious").unwrap();
    let link = ".index.html.tmp-00000000000000aa";
    std::os::unix::fs::symlink(&victim, dir.join(link)).unwrap();
    let keep = [held, ".figure-3.png.tmp-1", "notes.tmp-12", ".hidden", link];
    for k in &keep[1..4] {
        std::fs::write(dir.join(k), "mine").unwrap();
    }
    let args = ["figure", "3", "--out", dir.path().to_str().unwrap()];
    ok(&args, &ladder(&args));
    assert!(!dir.join(dead).exists(), "a dead temporary file was kept");
    for k in keep {
        assert!(
            std::fs::symlink_metadata(dir.join(k)).is_ok(),
            "{k} was removed"
        );
    }
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "precious");
    drop(holder);
}

/// `--out` through a symlink loop: one line naming the loop, exit 2 (it
/// was exit 1, "an I/O error").
#[test]
fn a_symlink_loop_in_the_output_path_is_named() {
    let dir = TempDir::new("loop");
    let l = dir.join("loop");
    std::os::unix::fs::symlink(&l, &l).unwrap();
    let o = l.join("sub");
    let args = ["figure", "3", "--out", o.to_str().unwrap()];
    one_line(&args, &ladder(&args), 2, &["symlink loop"]);
}

// ------------------------------------------- 2. one command, one name twice

/// `ladder render a.toml a.toml`, or two files with one `name`, raced on
/// one temporary file: refused up front, naming the clash, writing nothing.
#[test]
fn two_outputs_of_one_command_with_one_name_are_refused() {
    let dir = TempDir::new("twice");
    let scene = ladder(&["scene", "3"]);
    ok(&["scene", "3"], &scene);
    let a = dir.join("a.toml");
    std::fs::write(&a, &scene.stdout).unwrap();
    let mut named = b"name = \"a\"\n".to_vec();
    named.extend(&scene.stdout);
    let c = dir.join("c.toml");
    std::fs::write(&c, named).unwrap();
    let out = dir.join("out");
    let (a, c, o) = (
        a.to_str().unwrap(),
        c.to_str().unwrap(),
        out.to_str().unwrap(),
    );
    for (args, needle) in [
        (vec!["render", a, a, "--out", o], "given twice"),
        (vec!["render", a, c, "--out", o], "c.toml"),
        (vec!["render", "--check", a, c, "--out", o], "figure-a.png"),
    ] {
        one_line(&args, &ladder(&args), 2, &["written twice", needle]);
        assert!(names(&out).is_empty(), "{args:?} wrote {:?}", names(&out));
    }
}

// ---------------------------------------------- 3. shard files are not trusted

/// A folder with the two shard files of a small sweep (runs 4: alpha and
/// gamma two values each), and the unsharded CSV to compare with.
fn two_shards(name: &str) -> (TempDir, Vec<u8>) {
    let dir = TempDir::new(name);
    let d = dir.path().to_str().unwrap();
    for k in ["1/2", "2/2"] {
        let a = shard_args(d, k);
        ok(&a, &ladder(&a));
    }
    let gathered = ladder(&["sweep", "gather", d]);
    ok(&["gather"], &gathered);
    let csv = std::fs::read(dir.join("sweep-two.csv")).unwrap();
    for f in ["sweep-two.csv", "sweep-two.json", "sweep-two.png"] {
        std::fs::remove_file(dir.join(f)).unwrap();
    }
    (dir, csv)
}

fn edit_shard(dir: &TempDir, file: &str, edit: impl FnOnce(&mut serde_json::Value)) {
    let p = dir.join("shards").join(file);
    let mut v: serde_json::Value = serde_json::from_slice(&std::fs::read(&p).unwrap()).unwrap();
    edit(&mut v);
    std::fs::write(&p, serde_json::to_vec(&v).unwrap()).unwrap();
}

/// Each corruption of a shard file is one line, exit 2, naming the file
/// (a record past the grid panicked; a count that disagrees with the plan
/// wrote a short CSV; a duplicated record was taken; absurd values too).
#[test]
fn gather_checks_every_shard_against_the_plan() {
    type Edit = fn(&mut serde_json::Value);
    let cases: [(&str, Edit, &str); 7] = [
        (
            "past the grid",
            |v| v["records"][0]["run"] = 1000.into(),
            "run 1000",
        ),
        (
            "another shard's run",
            |v| v["records"][0]["run"] = 1.into(),
            "run 1",
        ),
        (
            "a run twice",
            |v| v["records"][1] = v["records"][0].clone(),
            "twice",
        ),
        ("a short count", |v| v["runs_total"] = 3.into(), "3 runs"),
        ("a shard count", |v| v["runs_in_shard"] = 1.into(), "1 runs"),
        (
            "a negative time",
            |v| v["records"][0]["t_decided"] = (-5.0).into(),
            "negative",
        ),
        (
            "too many blocks",
            |v| v["records"][0]["front"] = 1_000_000.into(),
            "front",
        ),
    ];
    for (what, edit, needle) in cases {
        let (dir, _) = two_shards("gather-bad");
        edit_shard(&dir, "sweep-two.1-of-2.json", edit);
        let d = dir.path().to_str().unwrap();
        let args = ["sweep", "gather", d];
        let out = ladder(&args);
        let err = stderr_of(&out);
        assert_eq!(out.status.code(), Some(2), "{what}: {err}");
        assert_eq!(err.lines().count(), 1, "{what}: {err}");
        assert!(err.contains("sweep-two.1-of-2.json"), "{what}: {err}");
        assert!(err.contains(needle), "{what}: '{needle}' not in {err}");
        assert!(!dir.join("sweep-two.csv").exists(), "{what}: wrote a CSV");
    }
}

/// A FIFO named like a shard hung gather forever; a link to /dev/zero was
/// read until memory ran out. Only regular files are read.
#[test]
fn gather_reads_only_regular_files() {
    let (dir, _) = two_shards("gather-fifo");
    let shards = dir.join("shards");
    let fifo = shards.join("sweep-two.1-of-2.json");
    std::fs::remove_file(&fifo).unwrap();
    let c = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
    // SAFETY: a valid C string path.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
    let d = dir.path().to_str().unwrap();
    let mut child = ladder_cmd(&["sweep", "gather", d])
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed().as_secs() > 20 {
            let _ = child.kill();
            panic!("gather hangs on a FIFO");
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    let out = child.wait_with_output().unwrap();
    one_line(
        &["gather"],
        &out,
        2,
        &["sweep-two.1-of-2.json", "regular file"],
    );

    std::fs::remove_file(&fifo).unwrap();
    std::os::unix::fs::symlink("/dev/zero", &fifo).unwrap();
    let args = ["sweep", "gather", d];
    one_line(
        &args,
        &ladder(&args),
        2,
        &["sweep-two.1-of-2.json", "regular file"],
    );
}

/// Resume took duplicated records and wrote contradictory rows: a shard
/// file of this sweep whose records do not check out is refused, naming it.
#[test]
fn resume_refuses_a_shard_file_with_a_duplicated_run() {
    let (dir, _) = two_shards("resume-dup");
    edit_shard(&dir, "sweep-two.2-of-2.json", |v| {
        let recs = v["records"].as_array_mut().unwrap();
        let r = recs[0].clone();
        recs.truncate(1);
        recs.push(r);
    });
    let d = dir.path().to_str().unwrap();
    let args = shard_args(d, "2/2");
    one_line(
        &args,
        &ladder(&args),
        2,
        &["sweep-two.2-of-2.json", "twice"],
    );
}

/// `--max-runs` takes `1e7` and `inf` as the other caps do; a refused sweep
/// leaves no empty `shards/`.
#[test]
fn max_runs_reads_like_the_other_caps_and_a_refused_sweep_leaves_nothing() {
    let dir = TempDir::new("max-runs");
    let d = dir.path().to_str().unwrap();
    for cap in ["1e7", "inf"] {
        let mut a = vec!["sweep"];
        a.extend(GRID);
        a.extend(["--out", d, "--max-runs", cap]);
        ok(&a, &ladder(&a));
    }
    let refused = dir.join("refused");
    let r = refused.to_str().unwrap();
    let args = [
        "sweep",
        "--alpha=-50,-56,-60",
        "--max-runs",
        "2",
        "--out",
        r,
    ];
    one_line(&args, &ladder(&args), 2, &["--max-runs"]);
    let args = ["sweep", "--alpha=-50,-56", "--n", "1", "--out", r];
    let out = ladder(&args);
    assert_eq!(out.status.code(), Some(2), "{}", stderr_of(&out));
    assert!(!refused.join("shards").exists(), "{:?}", names(&refused));
}

// ------------------------------------------------------- 5. the machine says no

/// `ladder ARGS` with no thread to spare: RLIMIT_NPROC of 1, set in the
/// child before it runs ladder (as root the limit is not enforced, so the
/// child first becomes user `nobody`; `dir` must be writable for it).
fn ladder_without_threads(args: &[&str], dir: &TempDir) -> Output {
    use std::os::unix::fs::PermissionsExt;
    use std::os::unix::process::CommandExt;
    std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o777)).unwrap();
    let mut cmd = ladder_cmd(args);
    // SAFETY: only async-signal-safe calls between fork and exec.
    unsafe {
        cmd.pre_exec(|| {
            if libc::geteuid() == 0 && (libc::setgid(65534) != 0 || libc::setuid(65534) != 0) {
                return Err(std::io::Error::last_os_error());
            }
            let one = libc::rlimit {
                rlim_cur: 1,
                rlim_max: 1,
            };
            if libc::setrlimit(libc::RLIMIT_NPROC, &one) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    cmd.output().unwrap()
}

/// When no thread can be created the rayon pool panicked ("The global
/// thread pool has not been initialized"): now ladder runs on the threads
/// it can get (here its own) and says so in one note.
#[test]
fn no_threads_to_spare_is_not_a_panic() {
    let dir = TempDir::new("nproc");
    let d = dir.path().to_str().unwrap();
    let out = ladder_without_threads(&["figure", "3", "--out", d], &dir);
    let err = stderr_of(&out);
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("running with"), "{err}");
    assert!(dir.join("figure-3.png").is_file());
}

/// The GIF and MP4 encoders each ran on a thread of their own, started
/// with `std::thread::spawn`, which panics when the machine refuses it:
/// now they encode on the caller's thread, and the movie is the same.
#[test]
fn movie_encoders_without_threads_encode_inline() {
    let formats = if cfg!(feature = "mp4") {
        "gif,mp4"
    } else {
        "gif"
    };
    let dir = TempDir::new("nproc-movie");
    let d = dir.path().to_str().unwrap();
    let args = [
        "movie", "4", "--frames", "4", "--size", "64x64", "--format", formats, "--out", d,
    ];
    let out = ladder_without_threads(&args, &dir);
    let err = stderr_of(&out);
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(out.status.code(), Some(0), "{err}");
    // The same bytes as with threads.
    let free = TempDir::new("free-movie");
    let f = free.path().to_str().unwrap();
    let mut a = args.to_vec();
    *a.last_mut().unwrap() = f;
    ok(&a, &ladder(&a));
    for ext in formats.split(',') {
        let name = format!("movie-4.{ext}");
        let inline = std::fs::read(dir.join(&name)).unwrap();
        assert_eq!(inline, std::fs::read(free.join(&name)).unwrap(), "{name}");
    }
}

// ------------------------------------------------------- 6. the user's words

/// A file in `dir` with a figure scene: `extra` lines at the top, then
/// `output` as its `[output]` table.
fn scene_file(dir: &TempDir, name: &str, top: &str, output: &str) -> String {
    let p = dir.join(format!("{name}.toml"));
    std::fs::write(
        &p,
        format!("name = \"{name}\"\n{top}\n[output]\n{output}\n"),
    )
    .unwrap();
    p.to_str().unwrap().to_string()
}

/// A control character in a title or a label became "internal SVG could
/// not be parsed", exit 1: it is the user's input, refused where it is
/// written (file, key), exit 2, by `render` and `render --check`.
#[test]
fn a_control_character_in_a_title_is_located() {
    let dir = TempDir::new("control");
    let o = dir.join("out");
    let o = o.to_str().unwrap();
    let theory = "kind = \"theory\"\nfigure = \"unit-schematic\"";
    for (name, top, key) in [
        ("bell", "title = \"ring\\u0007 ring\"", "title"),
        ("esc", "label = \"Fig.\\u001b[31m\"", "label"),
    ] {
        let f = scene_file(&dir, name, top, theory);
        for args in [
            vec!["render", &f, "--out", o],
            vec!["render", "--check", &f],
        ] {
            one_line(
                &args,
                &ladder(&args),
                2,
                &[&format!("{name}.toml"), key, "control"],
            );
        }
    }
}

/// A GIF's delays are 16-bit counts of 1/100 s: `--fps 0.001` asked for a
/// frame every 1000 s, and the GIF showed each for 655.35 s. Refused, with
/// the range that is honoured.
#[test]
fn a_frame_rate_past_the_gifs_delays_is_refused_with_the_range() {
    let dir = TempDir::new("fps");
    let d = dir.path().to_str().unwrap();
    let args = ["movie", "4", "--fps", "0.001", "--frames", "2", "--out", d];
    one_line(&args, &ladder(&args), 2, &["0.0016", "50", "0.001"]);
    assert!(names(dir.path()).is_empty());
    let args = ["movie", "4", "--fps", "0.002", "--frames", "2", "--out", d];
    ok(&args, &ladder(&args));
}

/// `render --check` passed theory files that rendering then refused (a
/// figure without the list it draws one curve of): both run the same
/// checks now, and refuse the same files with the same located line.
#[test]
fn render_check_refuses_what_render_refuses() {
    let dir = TempDir::new("check");
    let o = dir.join("out");
    let o = o.to_str().unwrap();
    for (name, output, key) in [
        (
            "nolist",
            "kind = \"theory\"\nfigure = \"dispersion\"",
            "output.alphas",
        ),
        (
            "noedge",
            "kind = \"theory\"\nfigure = \"edge-mode\"\nalphas = []",
            "output.alphas",
        ),
        (
            "nocurve",
            "kind = \"theory\"\nfigure = \"gravity-potential\"",
            "output.a_over_b",
        ),
        (
            "nomode",
            "kind = \"theory\"\nfigure = \"zero-modes\"",
            "output.modes",
        ),
        (
            "ab",
            "kind = \"theory\"\nfigure = \"gravity-potential\"\na_over_b = [0.5]",
            "output.a_over_b",
        ),
    ] {
        let f = scene_file(&dir, name, "", output);
        let check = ["render", "--check", f.as_str()];
        let render = ["render", f.as_str(), "--out", o];
        let (c, r) = (ladder(&check), ladder(&render));
        one_line(&check, &c, 2, &[&format!("{name}.toml"), key]);
        assert_eq!(
            stderr_of(&c),
            stderr_of(&r),
            "{name}: check and render differ"
        );
    }
}

/// A newline in `--name` split the error line; the per-axis bound named no
/// way out.
#[test]
fn names_and_axes_are_refused_in_one_line() {
    let dir = TempDir::new("words");
    let d = dir.path().to_str().unwrap();
    let args = ["sweep", "--name", "a\nb", "--alpha=-50", "--out", d];
    one_line(&args, &ladder(&args), 2, &["--name", "a\\nb"]);
    let args = ["sweep", "--alpha=0:2000000:1", "--out", d];
    one_line(
        &args,
        &ladder(&args),
        2,
        &["1000000", "no flag raises", "coarser step"],
    );
}

/// `ladder scene 3` prints figure 3; movie 3 was out of reach. Now
/// `ladder scene movie 3` (or `movie-3`) prints it.
#[test]
fn scene_prints_a_movie_whose_id_is_also_a_figures() {
    let figure = ladder(&["scene", "3"]);
    ok(&["scene", "3"], &figure);
    let movie = ladder(&["scene", "movie", "3"]);
    ok(&["scene", "movie", "3"], &movie);
    assert_ne!(figure.stdout, movie.stdout);
    let text = String::from_utf8_lossy(&movie.stdout);
    assert!(text.contains("Movie 3"), "{text}");
    assert_eq!(ladder(&["scene", "movie-3"]).stdout, movie.stdout);
    assert_eq!(ladder(&["scene", "figure", "3"]).stdout, figure.stdout);
    let args = ["scene", "film", "3"];
    one_line(&args, &ladder(&args), 2, &["film", "movie 3"]);
}
