//! Work-precision and stability machinery: speed against accuracy
//! (README.md, `bench work-precision` and `bench stability`).

#![allow(clippy::field_reassign_with_default)]

use jacobs_ladder::bench::{self, BenchScene};
use jacobs_ladder::scene::{DriveSpec, Scene};
use jacobs_ladder::sim::IntegratorKind;

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
    let r1 = scene.reference(bench::REFERENCE_RTOL).unwrap();
    let r2 = scene.reference(bench::REFERENCE_RTOL / 2.0).unwrap();
    let change = bench::theta_error(&r1, &r2);
    assert!(change < 1e-8, "halving the tolerance moved θ by {change:e}");
}

#[test]
fn sweep_error_falls_monotonically_for_convergent_methods() {
    let scene = tiny();
    let reference = scene.reference(bench::REFERENCE_RTOL).unwrap();
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
