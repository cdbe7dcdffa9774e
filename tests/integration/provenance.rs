//! Provenance in the data files of `simulate` (docs/python.md): the
//! `.npz` carries a `metadata` array (JSON text: program,
//! version, commit, build, command line, scene); the CSV stays plain and
//! its provenance is its JSON sidecar, `FILE.json` (docs/formats.md).

use crate::common::tempdir::TempDir;
use std::path::Path;
use std::process::Command;

fn u16_at(b: &[u8], at: usize) -> usize {
    u16::from_le_bytes([b[at], b[at + 1]]) as usize
}

fn u32_at(b: &[u8], at: usize) -> usize {
    u32::from_le_bytes(b[at..at + 4].try_into().unwrap()) as usize
}

/// The bytes of entry `name` of a stored ZIP, found through its central
/// directory.
fn entry(path: &Path, name: &str) -> Vec<u8> {
    let b = std::fs::read(path).unwrap();
    let end = b.len() - 22;
    let mut at = u32_at(&b, end + 16);
    for _ in 0..u16_at(&b, end + 10) {
        let size = u32_at(&b, at + 20);
        let name_len = u16_at(&b, at + 28);
        let skip = u16_at(&b, at + 30) + u16_at(&b, at + 32);
        let local = u32_at(&b, at + 42);
        let this = std::str::from_utf8(&b[at + 46..at + 46 + name_len]).unwrap();
        if this == name {
            let start = local + 30 + u16_at(&b, local + 26) + u16_at(&b, local + 28);
            return b[start..start + size].to_vec();
        }
        at += 46 + name_len + skip;
    }
    panic!("no {name} in {}", path.display())
}

/// A 0-d `<Un` array's text (UTF-32 little-endian).
fn npy_text(b: &[u8]) -> String {
    assert_eq!(&b[..8], b"\x93NUMPY\x01\x00");
    let len = u16_at(b, 8);
    let header = std::str::from_utf8(&b[10..10 + len]).unwrap();
    let chars = header
        .split("'descr': '<U")
        .nth(1)
        .and_then(|r| r.split('\'').next())
        .unwrap_or_else(|| panic!("not a unicode array: {header}"));
    assert!(header.contains("'shape': ()"), "{header}");
    let data = &b[10 + len..];
    assert_eq!(data.len(), 4 * chars.parse::<usize>().unwrap());
    data.chunks_exact(4)
        .map(|c| char::from_u32(u32::from_le_bytes(c.try_into().unwrap())).unwrap())
        .collect()
}

fn simulate(dir: &TempDir) -> (std::path::PathBuf, std::path::PathBuf) {
    let (npz, csv) = (dir.join("run.npz"), dir.join("run.csv"));
    let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args([
            "simulate",
            "--alpha",
            "55",
            "--n",
            "6",
            "--t-end",
            "200",
            "--npz",
            npz.to_str().unwrap(),
            "--csv",
            csv.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    (npz, csv)
}

fn check_made_by(m: &serde_json::Value, what: &str) {
    assert_eq!(m["program"], "ladder", "{what}");
    assert_eq!(m["version"], env!("CARGO_PKG_VERSION"), "{what}");
    assert!(m.get("git_commit").is_some(), "{what}: no git_commit");
    assert!(
        m["build"]
            .as_str()
            .unwrap()
            .contains(env!("CARGO_PKG_VERSION"))
    );
    assert_eq!(m["scene"]["model"]["alpha"], 55.0, "{what}");
    assert_eq!(m["scene"]["model"]["n"], 6, "{what}");
    assert_eq!(m["command_line"][1], "simulate", "{what}");
}

#[test]
fn the_npz_carries_its_provenance() {
    let dir = TempDir::new("provenance-npz");
    let (npz, _) = simulate(&dir);
    let text = npy_text(&entry(&npz, "metadata.npy"));
    let m: serde_json::Value = serde_json::from_str(&text).unwrap();
    check_made_by(&m, "npz metadata");
    // numpy reads it as the docs say, where numpy is there.
    let script = "import sys, json, numpy; d = numpy.load(sys.argv[1]); \
                  m = json.loads(str(d['metadata'])); print(m['version'], m['scene']['model']['n'])";
    if crate::common::require::numpy("provenance::the_npz_carries_its_provenance") {
        let o = Command::new("python3")
            .arg("-c")
            .arg(script)
            .arg(&npz)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let line = String::from_utf8_lossy(&o.stdout).trim().to_string();
        assert_eq!(line, format!("{} 6", env!("CARGO_PKG_VERSION")));
    }
}

#[test]
fn the_csv_stays_plain_and_its_sidecar_names_the_run() {
    let dir = TempDir::new("provenance-csv");
    let (_, csv) = simulate(&dir);
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.starts_with("t,theta_1_deg,"), "a plain header");
    assert!(!text.contains('#'), "no comment lines");
    let sidecar = dir.join("run.csv.json");
    let first = std::fs::read(&sidecar).expect("the CSV's JSON sidecar");
    let m: serde_json::Value = serde_json::from_slice(&first).unwrap();
    check_made_by(&m, "CSV sidecar");
    assert!(m.get("wall_seconds").is_none(), "no wall time");
    assert!(m.get("speed").is_some() && m["arrival_times"].is_array());
    // Byte-identical on a second run.
    let again = TempDir::new("provenance-csv-again");
    simulate(&again);
    let second = std::fs::read(again.join("run.csv.json")).unwrap();
    let strip = |b: &[u8]| {
        // The command line names each run's own folder.
        let mut v: serde_json::Value = serde_json::from_slice(b).unwrap();
        v.as_object_mut().unwrap().remove("command_line");
        v
    };
    assert_eq!(strip(&first), strip(&second));
}

#[test]
fn a_sidecar_that_would_overwrite_another_output_is_refused() {
    let dir = TempDir::new("provenance-clash");
    let csv = dir.join("run.csv");
    let npz = dir.join("run.csv.json");
    let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args([
            "simulate",
            "--t-end",
            "10",
            "--csv",
            csv.to_str().unwrap(),
            "--npz",
            npz.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(!csv.exists() && !npz.exists());
}
