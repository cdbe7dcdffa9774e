//! `simulate --npz` (docs/sweeps.md): the archive is read back by a small
//! ZIP and `.npy` reader written here (with its own bitwise CRC-32), and
//! its arrays are checked against the CSV of the same run at the same
//! times (θ in degrees there), against the JSON report's final angles, and
//! against the energies recomputed here from the state. When python3 is
//! present its zipfile module checks the archive; when numpy is present,
//! numpy.load reads it.

use crate::common::require::{numpy, require};
use crate::common::tempdir::TempDir;
use std::collections::BTreeMap;
use std::path::Path;
use std::process::Command;

fn ladder(args: &[&str]) -> std::process::Output {
    let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "ladder {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// CRC-32 bit by bit (the ZIP polynomial, reflected), independent of the
/// program's table.
fn crc32(bytes: &[u8]) -> u32 {
    let mut c = !0u32;
    for &b in bytes {
        c ^= b as u32;
        for _ in 0..8 {
            c = if c & 1 == 1 {
                (c >> 1) ^ 0xEDB8_8320
            } else {
                c >> 1
            };
        }
    }
    !c
}

fn u16_at(b: &[u8], at: usize) -> usize {
    u16::from_le_bytes([b[at], b[at + 1]]) as usize
}

fn u32_at(b: &[u8], at: usize) -> u32 {
    u32::from_le_bytes(b[at..at + 4].try_into().unwrap())
}

/// An array read back: its shape and values (C order).
#[derive(Debug)]
pub(crate) struct Array {
    pub(crate) shape: Vec<usize>,
    pub(crate) values: Vec<f64>,
}

impl Array {
    pub(crate) fn at(&self, row: usize, col: usize) -> f64 {
        self.values[row * self.shape[1] + col]
    }
}

/// Reads a `.npy` of little-endian f64.
fn read_npy(b: &[u8]) -> Array {
    assert_eq!(&b[..8], b"\x93NUMPY\x01\x00", "npy magic and version 1.0");
    let len = u16_at(b, 8);
    let header = std::str::from_utf8(&b[10..10 + len]).unwrap();
    assert_eq!((10 + len) % 64, 0, "data aligned to 64 bytes: {header}");
    assert!(header.contains("'descr': '<f8'"), "{header}");
    assert!(header.contains("'fortran_order': False"), "{header}");
    let dims = header
        .split("'shape': (")
        .nth(1)
        .and_then(|r| r.split(')').next())
        .unwrap();
    let shape: Vec<usize> = dims
        .split(',')
        .map(str::trim)
        .filter(|d| !d.is_empty())
        .map(|d| d.parse().unwrap())
        .collect();
    let data = &b[10 + len..];
    let count: usize = shape.iter().product();
    assert_eq!(data.len(), 8 * count, "{header}");
    let values = data
        .chunks_exact(8)
        .map(|c| f64::from_le_bytes(c.try_into().unwrap()))
        .collect();
    Array { shape, values }
}

/// Reads a stored ZIP through its central directory, checking each local
/// header against it and every CRC.
pub(crate) fn read_npz(path: &Path) -> BTreeMap<String, Array> {
    let b = std::fs::read(path).unwrap();
    let end = b.len() - 22;
    assert_eq!(u32_at(&b, end), 0x0605_4b50, "end of central directory");
    let count = u16_at(&b, end + 10);
    let mut at = u32_at(&b, end + 16) as usize;
    let mut arrays = BTreeMap::new();
    for _ in 0..count {
        assert_eq!(u32_at(&b, at), 0x0201_4b50, "central directory entry");
        assert_eq!(u16_at(&b, at + 10), 0, "stored");
        let crc = u32_at(&b, at + 16);
        let size = u32_at(&b, at + 20) as usize;
        assert_eq!(u32_at(&b, at + 24) as usize, size);
        let name_len = u16_at(&b, at + 28);
        let skip = u16_at(&b, at + 30) + u16_at(&b, at + 32);
        let local = u32_at(&b, at + 42) as usize;
        let name = String::from_utf8(b[at + 46..at + 46 + name_len].to_vec()).unwrap();
        at += 46 + name_len + skip;
        assert_eq!(u32_at(&b, local), 0x0403_4b50, "local header of {name}");
        assert_eq!(u32_at(&b, local + 14), crc, "{name}: local CRC");
        let lname = u16_at(&b, local + 26);
        let start = local + 30 + lname + u16_at(&b, local + 28);
        let data = &b[start..start + size];
        assert_eq!(crc32(data), crc, "{name}: CRC-32");
        let key = name.strip_suffix(".npy").unwrap().to_string();
        if key == "metadata" {
            // The provenance, text (tests/integration/provenance.rs).
            continue;
        }
        arrays.insert(key, read_npy(data));
    }
    arrays
}

pub(crate) fn csv_rows(path: &Path) -> Vec<Vec<f64>> {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect()
}

/// θ in degrees wrapped to (−180°, 180°].
fn wrap_deg(d: f64) -> f64 {
    let w = d.rem_euclid(360.0);
    if w > 180.0 { w - 360.0 } else { w }
}

const RUN: [&str; 10] = [
    "simulate",
    "--alpha",
    "60",
    "--n",
    "7",
    "--t-end",
    "1500",
    "--sample-every",
    "25",
    "--json",
];

#[test]
fn npz_reads_back_equal_to_the_csv_at_the_same_times() {
    let dir = TempDir::new("npz");
    let (csv, npz) = (dir.join("run.csv"), dir.join("run.npz"));
    let mut args: Vec<&str> = RUN.to_vec();
    args.extend([
        "--csv",
        csv.to_str().unwrap(),
        "--npz",
        npz.to_str().unwrap(),
    ]);
    let out = ladder(&args);
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let a = read_npz(&npz);
    let names: Vec<&str> = a.keys().map(String::as_str).collect();
    for want in [
        "t",
        "theta",
        "x",
        "y",
        "vx",
        "vy",
        "omega",
        "kinetic_energy",
        "elastic_energy",
        "gravitational_energy",
        "energy",
    ] {
        assert!(names.contains(&want), "{want} missing from {names:?}");
    }
    let rows = csv_rows(&csv);
    let (samples, n) = (rows.len(), 7);
    assert_eq!(samples, 61, "0, 25, ..., 1500");
    assert_eq!(a["t"].shape, vec![samples]);
    for name in ["theta", "x", "y", "vx", "vy", "omega"] {
        assert_eq!(a[name].shape, vec![samples, n], "{name}");
    }
    let mut flipped = false;
    for (k, row) in rows.iter().enumerate() {
        assert_eq!(a["t"].values[k], row[0], "t at row {k}");
        for i in 0..n {
            let deg = a["theta"].at(k, i).to_degrees();
            // The CSV prints 6 decimals.
            assert!(
                (wrap_deg(deg) - row[1 + i]).abs() < 2e-6,
                "theta[{k}][{i}] = {deg}° against the CSV's {}",
                row[1 + i]
            );
            flipped |= deg < -30.0;
        }
    }
    assert!(flipped, "the kink crossed the chain: some θ went to −α");
    // The last sample is t_end: its angles are the report's final ones.
    let last = samples - 1;
    for (i, th) in report["final_theta_deg"]
        .as_array()
        .unwrap()
        .iter()
        .enumerate()
    {
        let deg = a["theta"].at(last, i).to_degrees();
        assert!((deg - th.as_f64().unwrap()).abs() < 1e-9, "block {i}");
    }
    // Energies from the state (docs/model.md, m = 1): kinetic
    // ½(Ẋ²+Ẏ²)+½Iθ̇², gravitational −GΣX, and the total is their sum with
    // the elastic energy.
    let inertia = report["model"]["inertia"].as_f64().unwrap();
    let gravity = report["model"]["gravity"].as_f64().unwrap();
    let mut moving = false;
    for k in 0..samples {
        let kinetic: f64 = (0..n)
            .map(|i| {
                let (vx, vy, w) = (a["vx"].at(k, i), a["vy"].at(k, i), a["omega"].at(k, i));
                0.5 * (vx * vx + vy * vy) + 0.5 * inertia * w * w
            })
            .sum();
        let grav = -gravity * (0..n).map(|i| a["x"].at(k, i)).sum::<f64>();
        let e = |name: &str| a[name].values[k];
        assert!((e("kinetic_energy") - kinetic).abs() <= 1e-12 * (1.0 + kinetic));
        assert!((e("gravitational_energy") - grav).abs() <= 1e-9 * (1.0 + grav.abs()));
        let sum = e("kinetic_energy") + e("elastic_energy") + e("gravitational_energy");
        assert!((e("energy") - sum).abs() <= 1e-9 * (1.0 + sum.abs()));
        assert!(e("elastic_energy") >= 0.0);
        moving |= kinetic > 1e-6;
    }
    assert!(moving, "the wave moves blocks");

    // python3's zipfile, then numpy, where present.
    let script = "import sys, zipfile; z = zipfile.ZipFile(sys.argv[1]); \
                  assert z.testzip() is None; print(len(z.namelist()))";
    let python = Command::new("python3")
        .arg("-c")
        .arg(script)
        .arg(&npz)
        .output();
    let has_python = python.as_ref().is_ok_and(|o| o.status.code().is_some());
    if require(
        "npz::npz_reads_back_equal_to_the_csv_at_the_same_times",
        has_python,
        "python3 is not installed",
        "apt-get install python3",
    ) {
        let o = python.unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        assert_eq!(String::from_utf8_lossy(&o.stdout).trim(), "13");
    }
    if numpy("npz::npz_reads_back_equal_to_the_csv_at_the_same_times") {
        let numpy = "import sys, numpy; d = numpy.load(sys.argv[1]); \
                     print(d['theta'].shape, repr(float(d['theta'][-1, -1])))";
        let o = Command::new("python3")
            .arg("-c")
            .arg(numpy)
            .arg(&npz)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let text = String::from_utf8_lossy(&o.stdout).to_string();
        assert!(text.starts_with(&format!("({samples}, {n})")), "{text}");
        let value: f64 = text.split_whitespace().last().unwrap().parse().unwrap();
        assert_eq!(
            value,
            a["theta"].at(last, n - 1),
            "numpy reads the same bits"
        );
    }
}

#[test]
fn npz_is_written_atomically_and_never_through_a_link() {
    let dir = TempDir::new("npz-link");
    let target = dir.join("elsewhere.txt");
    std::fs::write(&target, "keep me").unwrap();
    let link = dir.join("run.npz");
    #[cfg(unix)]
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let mut args: Vec<&str> = RUN.to_vec();
    args.extend(["--npz", link.to_str().unwrap()]);
    let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(&args)
        .output()
        .unwrap();
    #[cfg(unix)]
    {
        assert_eq!(
            out.status.code(),
            Some(2),
            "a symlink in the way is refused"
        );
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "keep me");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("symbolic link"), "{err}");
    }
    // Nothing but what we made is left in the folder.
    let left: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert!(left.len() <= 2, "{left:?}");
}
