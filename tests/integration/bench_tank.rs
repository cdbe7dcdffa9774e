//! The integrators on the water tank ("Integrators"): the
//! work-precision and stability studies run on a scene whose terms some
//! schemes refuse, and say so point by point instead of failing.

use crate::common::{ladder_cli, tempdir::TempDir};
use jacobs_ladder::bench::{self, BenchScene, Status};
use jacobs_ladder::sim::IntegratorKind;

/// The built-in water tank (buoyancy, added mass, quadratic drag, motor),
/// cut to 300 τ: block 1 is still turning (T_d = 966 τ at 0.2 Hz), which
/// moves every block, so the errors are not trivially zero.
fn tank() -> BenchScene {
    BenchScene::movie("water-tank", Some(300.0), 60).unwrap()
}

/// Moreau's time-stepping takes inextensible ribbons only, which the tank
/// has not: refused, saying so.
fn assert_refused_without_ribbons(reason: &str) {
    assert!(
        reason.contains("moreau") && reason.contains("without inextensible ribbons"),
        "{reason}"
    );
}

/// The refusals name the terms: symplectic Euler and Verlet kick with
/// forces of the positions only.
fn assert_refused_for_terms(reason: &str) {
    assert!(
        reason.contains("added mass") && reason.contains("quadratic drag"),
        "{reason}"
    );
}

#[test]
fn work_precision_on_the_tank_has_a_row_per_method_and_rk4_converges_at_order_4() {
    let scene = tank();
    assert_eq!(scene.t_end, 300.0);
    let report = bench::work_precision(std::slice::from_ref(&scene), 1, &|_| {}).unwrap();
    let sweeps = &report.scenes[0].integrators;
    let names: Vec<&str> = sweeps.iter().map(|s| s.name.as_str()).collect();
    let all: Vec<&str> = IntegratorKind::ALL.iter().map(|k| k.name()).collect();
    assert_eq!(names, all, "one row per method");
    for sweep in sweeps {
        let refuses = matches!(
            sweep.name.as_str(),
            "symplectic-euler" | "verlet" | "moreau"
        );
        assert_eq!(sweep.refused.is_some(), refuses, "{}", sweep.name);
        for p in &sweep.points {
            if refuses {
                assert_eq!(p.status, Status::Refused, "{}", sweep.name);
                let reason = p.refused.as_deref().unwrap();
                if sweep.name == "moreau" {
                    assert_refused_without_ribbons(reason);
                } else {
                    assert_refused_for_terms(reason);
                }
            } else {
                assert!(p.refused.is_none() && p.force_evals > 0, "{p:?}");
            }
        }
    }
    // RK4: error ∝ dt⁴ over its accurate points (between 1e-10 and 1e-2).
    let rk4 = &sweeps[3];
    let order = bench::order_in_step(&rk4.points).unwrap();
    assert!((order - 4.0).abs() < 0.3, "RK4 order {order}");
    // Explicit Euler: first order where accurate, and dt = 0.01 is marked
    // inaccurate (θ off by most of a radian) without failing the study.
    let euler = &sweeps[0];
    let order = bench::order_in_step(&euler.points).unwrap();
    assert!((order - 1.0).abs() < 0.2, "explicit Euler order {order}");
    let last = euler.points.last().unwrap();
    assert_eq!(last.dt, Some(0.01));
    assert_eq!(last.status, Status::Inaccurate, "{last:?}");
    // The reference is dopri5 at rtol 1e-11: dopri5 at 1e-10 lies within
    // 1e-9 rad of it.
    let tight = sweeps[4].points.last().unwrap();
    assert!(tight.theta_error.unwrap() < 1e-9, "{tight:?}");

    // The table, the CSV and the chart carry the refusals.
    let table = bench::work_precision_table(&report);
    assert!(table.contains("verlet            refused: integrator verlet cannot integrate"));
    assert!(table.contains("(inaccurate)"), "{table}");
    let csv = bench::work_precision_csv(&report);
    let refused_rows = csv.lines().filter(|l| l.contains(",refused,")).count();
    let steps = bench::default_steps(IntegratorKind::SymplecticEuler).len()
        + bench::default_steps(IntegratorKind::Verlet).len()
        + bench::default_steps(IntegratorKind::Moreau).len();
    assert_eq!(refused_rows, steps, "{csv}");
    assert!(csv.lines().any(|l| l.contains(",inaccurate,")), "{csv}");
    let image = bench::work_precision_chart(&report).unwrap();
    assert!(image.width() > 1000);
    assert_eq!(
        bench::charts::refusal_terms(sweeps[2].refused.as_deref().unwrap()),
        "added mass, quadratic drag"
    );
}

#[test]
fn stability_on_the_tank_refuses_the_kick_schemes_and_bounds_rk4_near_its_prediction() {
    let scene = tank();
    let report = bench::stability_of_scene(&scene, &|_| {}).unwrap();
    assert_eq!(report.scene.as_deref(), Some("water-tank"));
    assert!(report.terms.as_deref().unwrap().contains("added mass"));
    assert_eq!(report.integrators.len(), IntegratorKind::ALL.len());
    for r in &report.integrators {
        match r.name.as_str() {
            "symplectic-euler" | "verlet" => {
                assert_refused_for_terms(r.refused.as_deref().unwrap());
                assert_eq!(r.critical_dt, 0.0);
            }
            "moreau" => {
                assert_refused_without_ribbons(r.refused.as_deref().unwrap());
                assert_eq!(r.critical_dt, 0.0);
            }
            _ => assert!(r.refused.is_none() && r.critical_dt > 0.0, "{r:?}"),
        }
    }
    // RK4's bound 2√2/ω_max is computed without the added mass, which
    // only lowers the frequencies: observed ≥ predicted, and not far off
    // (the stiffest mode is along the plate, where the water adds no mass).
    let rk4 = &report.integrators[3];
    let ratio = rk4.critical_dt / rk4.predicted_dt;
    assert!((0.95..1.3).contains(&ratio), "RK4 ratio {ratio}");
    let table = bench::stability_table(&report);
    assert!(table.contains("symplectic-euler  refused"), "{table}");
    bench::stability_chart(&report).unwrap();
}

#[test]
fn bench_takes_the_tank_from_the_command_line() {
    let dir = TempDir::new("bench-tank");
    let out = dir.path().to_str().unwrap();
    let run = ladder_cli(&[
        "bench",
        "work-precision",
        "--scene",
        "water-tank",
        "--t-end",
        "100",
        "--repeats",
        "1",
        "--out",
        out,
        "--json",
    ]);
    assert_eq!(run.status.code(), Some(0), "{run:?}");
    let v: serde_json::Value = serde_json::from_slice(&run.stdout).unwrap();
    let verlet = &v["scenes"][0]["integrators"][2];
    assert_eq!(verlet["name"], "verlet");
    assert_eq!(verlet["points"][0]["status"], "refused");
    let csv = std::fs::read_to_string(dir.join("work-precision.csv")).unwrap();
    assert!(csv.contains("water-tank,verlet,") && csv.contains(",refused,"));
    assert!(dir.join("work-precision.png").exists());

    for (args, word) in [
        (&["bench", "stability", "--scene", "nowhere"][..], "nowhere"),
        (&["bench", "stability", "--t-end", "100"][..], "--t-end"),
        (
            &[
                "bench",
                "work-precision",
                "--scene",
                "water-tank",
                "--t-end",
                "-1",
            ][..],
            "--t-end",
        ),
    ] {
        let run = ladder_cli(args);
        let err = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains(word), "{err}");
    }
}
