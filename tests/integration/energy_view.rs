//! The energy view (`--view energy`) and the npz's `dissipated_energy`:
//! once the drive has ended nothing works on the ladder, so kinetic +
//! elastic + gravitational + dissipated must stay flat to the
//! integrator's accuracy, and without the dissipated energy it must not.
//!
//! Tolerance: a ten-thousandth of the energy dissipated after the drive.
//! Velocity Verlet (the view's `auto`, dt = 0.125 τ here) is second order
//! and does not drift in energy beyond O((ω dt)²) oscillations: measured
//! 1.9e-9 against 1.44e-3 dissipated (1.3e-6 of it), so the tolerance
//! leaves a margin of about 75, and leaving out the dissipated energy
//! (a drift of all of it) misses it ten thousandfold. Symplectic Euler
//! (the npz's run, dt = 0.01) is first order: 1e-3 of it.

use crate::common::tempdir::TempDir;
use crate::npz::read_npz;
use std::process::Command;

fn ladder(args: &[&str]) {
    let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Largest departure of `v` from its value at the first time ≥ `from`.
fn drift(t: &[f64], v: &[f64], from: f64) -> f64 {
    let k = t.iter().position(|&x| x >= from).unwrap();
    v[k..].iter().map(|x| (x - v[k]).abs()).fold(0.0, f64::max)
}

/// (drift of total + dissipated, drift of the total alone, energy
/// dissipated after `from`).
fn budget(t: &[f64], total: &[f64], dissipated: &[f64], from: f64) -> (f64, f64, f64) {
    let with: Vec<f64> = total.iter().zip(dissipated).map(|(a, b)| a + b).collect();
    let k = t.iter().position(|&x| x >= from).unwrap();
    (
        drift(t, &with, from),
        drift(t, total, from),
        dissipated.last().unwrap() - dissipated[k],
    )
}

fn flat(t: &[f64], total: &[f64], dissipated: &[f64], from: f64, tol: f64) -> bool {
    let (with, _, lost) = budget(t, total, dissipated, from);
    with <= tol * lost
}

#[test]
fn the_energy_view_draws_a_budget_that_is_flat_after_the_drive() {
    let dir = TempDir::new("energy");
    ladder(&[
        "figure",
        "--view",
        "energy",
        "--t-end",
        "2500",
        "--name",
        "e",
        "--out",
        dir.path().to_str().unwrap(),
    ]);
    assert!(dir.join("figure-e.png").exists());
    let d: serde_json::Value =
        serde_json::from_slice(&std::fs::read(dir.join("figure-e.json")).unwrap()).unwrap();
    let e = &d["runs"][0]["energies"];
    let list = |k: &str| -> Vec<f64> {
        e[k].as_array()
            .unwrap_or_else(|| panic!("no {k}"))
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect()
    };
    let (t, total, dissipated) = (list("times"), list("total"), list("dissipated"));
    let (kinetic, elastic, grav) = (list("kinetic"), list("elastic"), list("gravitational"));
    for k in 0..t.len() {
        let sum = kinetic[k] + elastic[k] + grav[k];
        assert!((total[k] - sum).abs() <= 1e-12 * (1.0 + sum.abs()));
    }
    let drive_end = 1000.0;
    let (with, without, lost) = budget(&t, &total, &dissipated, drive_end);
    println!(
        "energy view: total + dissipated drifts {with:e}, the total {without:e}, {lost:e} dissipated after the drive"
    );
    assert!(lost > 1e-4, "the kink dissipates after the drive: {lost}");
    assert!(
        flat(&t, &total, &dissipated, drive_end, 1e-4),
        "{with:e} of {lost:e}"
    );
    // The probe: without the dissipated energy the budget is not flat.
    let zero = vec![0.0; t.len()];
    assert!(!flat(&t, &total, &zero, drive_end, 1e-4));
    assert!(without > 0.5 * lost);
    // During the drive it is not flat either: the drive works.
    assert!(!flat(&t, &total, &dissipated, 0.0, 1e-4));
}

#[test]
fn the_npz_carries_the_dissipated_energy() {
    let dir = TempDir::new("energy-npz");
    let npz = dir.join("run.npz");
    ladder(&[
        "simulate",
        "--t-end",
        "2500",
        "--sample-every",
        "5",
        "--npz",
        npz.to_str().unwrap(),
    ]);
    let a = read_npz(&npz);
    let t = &a["t"].values;
    let (total, dissipated) = (&a["energy"].values, &a["dissipated_energy"].values);
    assert_eq!(dissipated.len(), t.len());
    assert_eq!(dissipated[0], 0.0);
    assert!(
        dissipated.windows(2).all(|w| w[1] >= w[0]),
        "never decreases"
    );
    let (with, _, lost) = budget(t, total, dissipated, 1000.0);
    assert!(
        flat(t, total, dissipated, 1000.0, 1e-3),
        "{with:e} of {lost:e}"
    );
    assert!(!flat(t, total, &vec![0.0; t.len()], 1000.0, 1e-3));
}
