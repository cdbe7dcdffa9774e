//! The state arrays checked against each other: each velocity
//! against its position's rate of change between close samples, vx
//! against ΔX/Δt, vy against ΔY/Δt, ω against Δθ/Δt, in the `.npz` and,
//! for θ, in the CSV of the same run. The energies alone cannot tell vx
//! from vy (the kinetic energy is symmetric in them): these checks can,
//! and each test shows it, by running the same check on the columns
//! swapped and requiring it to fail.

use crate::common::tempdir::TempDir;
use crate::npz::{Array, csv_rows, read_npz};
use std::process::Command;

/// The run: the paper's kink on 7 blocks, rk4 at dt = 0.01 τ, sampled
/// every 0.05 τ (central differences over 0.1 τ: error ~ Δt² x‴/6, about
/// 4e-7 of velocities up to 5e-3 here).
const RUN: [&str; 14] = [
    "simulate",
    "--alpha",
    "60",
    "--n",
    "7",
    "--t-end",
    "1500",
    "--integrator",
    "rk4",
    "--dt",
    "0.01",
    "--sample-every",
    "0.05",
    "--json",
];

/// The drive's corners (θ₁ turns at a constant rate from t = 0 to the
/// drive time 1000 τ: ω₁ jumps there), where no difference is a rate.
const CORNERS: [f64; 2] = [0.0, 1000.0];

/// Largest mismatch |v_k − (p_{k+1} − p_{k−1})/(t_{k+1} − t_{k−1})| over
/// the samples k and blocks, with `wrap` for an angle; the differences
/// that straddle a drive corner are left out.
fn mismatch(t: &[f64], p: &Array, v: &Array, wrap: bool) -> f64 {
    let n = p.shape[1];
    let mut worst: f64 = 0.0;
    for k in 1..t.len() - 1 {
        if CORNERS.iter().any(|&c| t[k - 1] <= c && c <= t[k + 1]) {
            continue;
        }
        for i in 0..n {
            let mut d = p.at(k + 1, i) - p.at(k - 1, i);
            if wrap {
                use std::f64::consts::{PI, TAU};
                d = (d + PI).rem_euclid(TAU) - PI;
            }
            let rate = d / (t[k + 1] - t[k - 1]);
            worst = worst.max((v.at(k, i) - rate).abs());
        }
    }
    worst
}

fn largest(a: &Array) -> f64 {
    a.values.iter().fold(0.0, |m, v| m.max(v.abs()))
}

/// The tolerance: a thousandth of the largest velocity, ten times the
/// measured difference error (4e-7 of 5e-3 for X, Y), a hundred times
/// below what swapping vx and vy gives (7e-3).
fn agrees(t: &[f64], p: &Array, v: &Array, wrap: bool) -> Result<(), String> {
    let (worst, scale) = (mismatch(t, p, v, wrap), largest(v));
    if worst <= 1e-3 * scale {
        Ok(())
    } else {
        Err(format!(
            "mismatch {worst:e} against velocities up to {scale:e}"
        ))
    }
}

#[test]
fn each_velocity_of_the_npz_is_its_position_s_rate_of_change() {
    let dir = TempDir::new("state");
    let (npz, csv) = (dir.join("run.npz"), dir.join("run.csv"));
    let mut args: Vec<&str> = RUN.to_vec();
    args.extend([
        "--npz",
        npz.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
    ]);
    let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(&args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let a = read_npz(&npz);
    let t = &a["t"].values;
    assert!(t.len() > 20_000, "close samples");
    for (p, v, wrap) in [
        ("x", "vx", false),
        ("y", "vy", false),
        ("theta", "omega", true),
    ] {
        agrees(t, &a[p], &a[v], wrap).unwrap_or_else(|e| panic!("{v} against d{p}/dt: {e}"));
    }
    // The planted probe: vx and vy swapped fail the same check.
    assert!(
        agrees(t, &a["x"], &a["vy"], false).is_err(),
        "vy passes as vx"
    );
    assert!(
        agrees(t, &a["y"], &a["vx"], false).is_err(),
        "vx passes as vy"
    );
    // The blocks moved: the check is not of a chain at rest.
    assert!(largest(&a["vx"]) > 1e-3 && largest(&a["omega"]) > 1e-3);

    // The CSV: θ in degrees (6 decimals) at the same times, against the
    // npz's ω, the same way.
    let rows = csv_rows(&csv);
    assert_eq!(rows.len(), t.len());
    let n = a["theta"].shape[1];
    let theta = Array {
        shape: vec![rows.len(), n],
        values: rows
            .iter()
            .flat_map(|r| r[1..].iter().map(|d| d.to_radians()))
            .collect(),
    };
    let times: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    assert_eq!(&times, t);
    agrees(t, &theta, &a["omega"], true).unwrap_or_else(|e| panic!("CSV θ against ω: {e}"));
    // And a probe: ω of the blocks shifted by one does not pass.
    let shifted = Array {
        shape: a["omega"].shape.clone(),
        values: a["omega"]
            .values
            .chunks(n)
            .flat_map(|r| {
                r.iter()
                    .cycle()
                    .skip(1)
                    .take(n)
                    .copied()
                    .collect::<Vec<_>>()
            })
            .collect(),
    };
    assert!(
        agrees(t, &theta, &shifted, true).is_err(),
        "shifted ω passes"
    );
}
