//! Work-precision and stability machinery: speed against accuracy
//! (README.md, `bench work-precision` and `bench stability`).

#![allow(clippy::field_reassign_with_default)]

use jacobs_ladder::bench::{self, BenchScene};
use jacobs_ladder::scene::{DriveSpec, Scene};
use jacobs_ladder::sim::{IntegratorConfig, IntegratorKind};

/// The paper's scene with N = 4 and a drive of 20 τ, to `t_end`.
fn small(t_end: f64) -> Scene {
    let mut scene = Scene::default();
    scene.model.n = 4;
    scene.drive = DriveSpec::flips_at(&[0.0], 20.0);
    scene.run.t_end = t_end;
    scene
}

/// A tiny scene: N = 4, a short drive, 60 τ.
fn tiny() -> BenchScene {
    BenchScene::from_scene(small(60.0), 30).unwrap()
}

#[test]
fn reference_is_converged() {
    let scene = tiny();
    let r1 = scene.reference().unwrap();
    let r2 = scene
        .run(&IntegratorConfig::adaptive(bench::REFERENCE_RTOL / 2.0))
        .unwrap();
    let change = bench::theta_error(&r1, &r2);
    assert!(change < 1e-8, "halving the tolerance moved θ by {change:e}");
}

#[test]
fn sweep_error_falls_monotonically_for_convergent_methods() {
    let scene = tiny();
    let reference = scene.reference().unwrap();
    for (kind, steps) in [
        (IntegratorKind::SymplecticEuler, vec![0.2, 0.1, 0.05, 0.025]),
        (IntegratorKind::Verlet, vec![0.2, 0.1, 0.05, 0.025]),
        (IntegratorKind::Rk4, vec![0.4, 0.2, 0.1, 0.05]),
        (IntegratorKind::Dopri5, vec![1e-4, 1e-6, 1e-8]),
    ] {
        let sweep = bench::sweep(&scene, &reference, kind, &steps, 1).unwrap();
        let errors: Vec<f64> = sweep
            .points
            .iter()
            .map(|p| p.theta_error.unwrap())
            .collect();
        assert!(
            errors.windows(2).all(|w| w[1] < w[0]),
            "{kind}: errors {errors:?} not decreasing"
        );
        let evals: Vec<u64> = sweep.points.iter().map(|p| p.force_evals).collect();
        assert!(evals.windows(2).all(|w| w[1] > w[0]), "{kind}: {evals:?}");
        if kind != IntegratorKind::Dopri5 {
            let order = sweep.measured_order.unwrap();
            let want = kind.order() as f64;
            assert!(
                (order - want).abs() < 0.35,
                "{kind}: order {order}, want {want}"
            );
        }
    }
}

#[test]
fn stability_bisection_matches_the_linear_bound_for_symplectic_euler() {
    let scene = BenchScene::from_scene(small(200.0), 10).unwrap();
    let omega_max = jacobs_ladder::theory::dispersion::omega_max_clamped(&scene.params).unwrap();
    let predicted = bench::predicted_dt(IntegratorKind::SymplecticEuler, omega_max, 0.02);
    let critical = bench::critical_dt(
        &scene,
        IntegratorKind::SymplecticEuler,
        predicted / 3.0,
        0.005,
    )
    .unwrap();
    let ratio = critical / predicted;
    assert!(
        (ratio - 1.0).abs() < 0.05,
        "critical {critical}, predicted {predicted}"
    );
    // Past the bound the run is reported as diverged, not returned.
    assert!(!bench::is_stable(&scene, IntegratorKind::SymplecticEuler, 1.2 * predicted).unwrap());
}

#[test]
fn charts_draw_from_reports() {
    let report = bench::work_precision(&[tiny()], 1, &|_| {}).unwrap();
    assert_eq!(report.scenes[0].t_end, 60.0);
    let image = bench::work_precision_chart(&report).unwrap();
    assert!(
        image.width() > 1000 && image.height() > 400,
        "one row per scene"
    );
    // Not blank: a good share of the pixels is not white.
    let inked = image.pixels().iter().filter(|p| p.red() < 200).count();
    assert!(inked > 10_000, "{inked} dark pixels");

    let row = |name: &str, critical: f64, predicted: f64| bench::StabilityRow {
        name: name.into(),
        critical_dt: critical,
        predicted_dt: predicted,
        refused: None,
        failed: None,
    };
    let point = |alpha: f64| bench::StabilityPoint {
        alpha_deg: alpha,
        omega_max: 2.5,
        integrators: vec![
            row("explicit-euler", 0.0057, 0.0031),
            row("symplectic-euler", 0.78, 0.79),
            row("verlet", 0.77, 0.79),
            row("rk4", 1.12, 1.11),
            row("dopri5", 0.72, 0.645),
        ],
    };
    let stability = bench::StabilityReport {
        alpha_deg: 60.0,
        omega_max: 2.5,
        damping_rate: 0.02,
        integrators: point(60.0).integrators,
        sweep: vec![point(30.0), point(60.0)],
        scene: None,
        terms: None,
    };
    let caption = bench::stability_caption(&stability);
    assert!(caption.contains("ratio 1.84 at 60°"), "{caption}");
    // dopri5's growth at its limit: (4000/0.72) ln|R(0.72 (−0.01 + 2.5i))| = 37.07.
    assert!(
        caption.contains("about e^37 at the observed limit"),
        "{caption}"
    );
    let image = bench::stability_chart(&stability).unwrap();
    assert!(image.width() >= 800 && image.height() > 1000);
}

#[test]
fn every_kernel_gives_the_portable_trajectory() {
    let report = bench::kernels(1, &|_| {}).unwrap();
    assert_eq!(report.steps, 400_000);
    let names: Vec<_> = report.kernels.iter().map(|k| k.kernel.as_str()).collect();
    assert!(names.starts_with(&["portable", "fastest"]), "{names:?}");
    for k in &report.kernels {
        assert!(k.same_as_portable, "{}", k.kernel);
        assert!(k.median_ms > 0.0 && k.speedup.is_finite(), "{k:?}");
    }
    // The sweep (batch kernel) and the chain (chain kernel), each way.
    let sweep: Vec<_> = report
        .sweep
        .kernels
        .iter()
        .map(|k| k.kernel.as_str())
        .collect();
    assert!(
        sweep.starts_with(&["portable", "one-by-one", "batch"]),
        "{sweep:?}"
    );
    assert_eq!(report.sweep.runs, bench::kernels::SWEEP_RUNS);
    assert_eq!(report.chain.n, bench::kernels::CHAIN_N);
    for w in [&report.sweep, &report.chain] {
        assert!(w.block_steps > 0);
        for k in &w.kernels {
            assert!(k.same_as_portable, "{}: {}", w.what, k.kernel);
            assert!(k.ns_per_block_step > 0.0 && k.speedup.is_finite(), "{k:?}");
        }
    }
    let table = bench::kernels_table(&report);
    assert!(
        table.contains("bit for bit") && !table.contains("NO"),
        "{table}"
    );
    assert!(
        table.contains("a sweep") && table.contains("a long chain"),
        "{table}"
    );
}

/// `bench stability` on a window too short to decide is refused (before,
/// `--t-end 1e-300` gave "rk4 4.05 ... ratio 4.00", the real limit being
/// 1.047; `--t-end 10` an explicit-Euler critical step of 14.68 τ, longer
/// than the window); a window long enough never reports a step longer
/// than the window over `MIN_STEPS_IN_WINDOW`.
#[test]
fn stability_refuses_a_window_too_short_and_no_step_passes_the_window() {
    let dir = crate::common::tempdir::TempDir::new("stability-window");
    let d = dir.path().to_str().unwrap();
    for t in ["1e-300", "10"] {
        let out = crate::common::ladder_cli(&[
            "bench",
            "stability",
            "--scene",
            "water-tank",
            "--t-end",
            t,
            "--out",
            d,
        ]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{t}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{t}: {err}");
        assert!(
            err.contains("too short to decide stability") && err.contains("--t-end"),
            "{err}"
        );
    }
    // The library refuses it too (the check is not the command line's).
    let short = BenchScene::movie("water-tank", Some(10.0), 0).unwrap();
    assert!(bench::stability_of_scene(&short, &|_| {}).is_err());
    // The bisection of an undamped scheme on a short window says it
    // cannot decide instead of returning a step past the window.
    let scene = BenchScene::from_scene(small(40.0), 10).unwrap();
    match bench::critical_dt(&scene, IntegratorKind::Rk4, 30.0, 0.02) {
        Ok(dt) => assert!(dt <= 40.0 / bench::MIN_STEPS_IN_WINDOW, "{dt}"),
        Err(e) => assert!(
            e.is_failed_run() && e.to_string().contains("cannot decide"),
            "{e}"
        ),
    }
}

/// The table prints the prediction the CSV holds: a damped bound with
/// little damping is a small number, not "0 (undamped)".
#[test]
fn the_stability_table_says_what_the_csv_says() {
    let row = bench::StabilityRow {
        name: "explicit-euler".into(),
        critical_dt: 0.0123,
        predicted_dt: 3.58e-7,
        refused: None,
        failed: None,
    };
    let report = bench::StabilityReport {
        alpha_deg: 86.0,
        omega_max: 2.7,
        damping_rate: 0.0,
        integrators: vec![row.clone()],
        sweep: vec![bench::StabilityPoint {
            alpha_deg: 86.0,
            omega_max: 2.7,
            integrators: vec![row],
        }],
        scene: Some("water-tank".into()),
        terms: None,
    };
    let table = bench::stability_table(&report);
    assert!(!table.contains("0 (undamped)"), "{table}");
    assert!(table.contains("3.580e-7"), "{table}");
    assert!(bench::stability_csv(&report).contains("3.580000e-7"));
}

/// `bench` has the caps of the commands that simulate, checked for the
/// study's runs together before any run (before, `bench work-precision
/// --scene water-tank --t-end 1e6` started silently: about 10¹¹ steps × N).
#[test]
fn bench_studies_are_capped_before_any_run() {
    for args in [
        &[
            "bench",
            "work-precision",
            "--scene",
            "water-tank",
            "--t-end",
            "1e6",
        ][..],
        &[
            "bench",
            "stability",
            "--scene",
            "water-tank",
            "--t-end",
            "1e6",
        ][..],
        &[
            "bench",
            "work-precision",
            "--scene",
            "water-tank",
            "--t-end",
            "300",
            "--max-block-steps",
            "1e5",
        ][..],
    ] {
        let dir = crate::common::tempdir::TempDir::new("bench-caps");
        let mut a = args.to_vec();
        a.extend(["--out", dir.path().to_str().unwrap()]);
        let started = std::time::Instant::now();
        let out = crate::common::ladder_cli(&a);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(
            err.contains("--max-block-steps") && err.contains("past the cap"),
            "{err}"
        );
        assert!(
            started.elapsed().as_secs() < 60,
            "{args:?}: refused only after work"
        );
    }
}

/// The paper's stability study (`ladder bench stability`, the default
/// scene) lists Moreau's time-stepping, which takes inextensible ribbons
/// only, as refused with its reason, and measures every other scheme
/// (it stopped at Moreau with exit 2 before).
#[test]
fn the_papers_stability_study_lists_moreau_as_refused() {
    let point = bench::stability_at(60.0).unwrap();
    for r in &point.integrators {
        if r.name == "moreau" {
            let why = r.refused.as_deref().expect("moreau refused");
            assert!(why.contains("inextensible ribbons"), "{why}");
        } else {
            assert!(r.refused.is_none() && r.critical_dt > 0.0, "{r:?}");
        }
    }
    assert!(point.integrators.iter().any(|r| r.name == "moreau"));
}
