//! The reports of the work-precision and stability studies: running
//! them over their scenes, and their CSV files and tables.

use super::*;
/// Results of one scene of the work-precision study.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct SceneReport {
    pub scene: String,
    pub alpha_deg: f64,
    /// Number of blocks.
    #[serde(default)]
    pub n: usize,
    /// The scene's terms beyond the paper's model ([`BenchScene::terms`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub terms: Option<String>,
    /// Length of the simulated window (τ).
    pub t_end: f64,
    pub integrators: Vec<Sweep>,
}

/// `bench work-precision --json`: the α = 60° kink's sweeps at the top level
/// (README.md), both scenes under `scenes`, and the cheapest setting
/// that keeps every arrival time within 1 τ of the reference.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct WorkPrecisionReport {
    pub integrators: Vec<Sweep>,
    pub scenes: Vec<SceneReport>,
    pub cheapest_within_1tau: Vec<Cheapest>,
    pub reference: String,
}

/// The cheapest setting of one scene within a tolerance on arrival times.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Cheapest {
    pub scene: String,
    pub integrator: String,
    pub step: f64,
    pub force_evals: u64,
    pub arrival_error: f64,
}

/// Runs the whole study on `scenes` (every integrator over its default
/// range); `progress` is told each finished point.
pub fn work_precision(
    scenes: &[BenchScene],
    repeats: usize,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<WorkPrecisionReport> {
    let mut reports = Vec::new();
    let mut cheapest = Vec::new();
    for scene in scenes {
        let reference = scene.reference()?;
        let mut sweeps = Vec::new();
        for kind in IntegratorKind::ALL {
            let mut points = Vec::new();
            for x in default_steps(kind) {
                points.push(measure(scene, &reference, kind, x, repeats)?);
                progress(&format!("{}: {kind} at {x}", scene.name));
            }
            sweeps.push(Sweep {
                name: kind.name().to_string(),
                measured_order: measured_order(&points),
                refused: points.iter().find_map(|p| p.refused.clone()),
                points,
            });
        }
        if let Some((name, p)) = cheapest_within(&sweeps, 1.0) {
            cheapest.push(Cheapest {
                scene: scene.name.clone(),
                integrator: name.to_string(),
                step: p.dt.or(p.rtol).unwrap_or(f64::NAN),
                force_evals: p.force_evals,
                arrival_error: p.arrival_error.unwrap_or(f64::NAN),
            });
        }
        reports.push(SceneReport {
            scene: scene.name.clone(),
            alpha_deg: scene.alpha_deg,
            n: scene.params.n,
            terms: scene.terms(),
            t_end: scene.t_end,
            integrators: sweeps,
        });
    }
    Ok(WorkPrecisionReport {
        integrators: reports
            .first()
            .map(|r| r.integrators.clone())
            .unwrap_or_default(),
        scenes: reports,
        cheapest_within_1tau: cheapest,
        reference: scenes.first().map_or(String::new(), reference_name),
    })
}

/// The reference of `scene` as the report names it: "dopri5, rtol = 1e-11"
/// or "moreau, dt = 0.002 τ".
fn reference_name(scene: &BenchScene) -> String {
    let c = scene.reference_config();
    match c.rtol {
        Some(rtol) => format!("dopri5, rtol = {rtol:e}"),
        None => format!("{}, dt = {} τ", c.kind.name(), c.dt),
    }
}

/// A CSV field, quoted when it holds a comma or a quote.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

fn opt(x: Option<f64>) -> String {
    x.map_or(String::new(), |v| format!("{v:e}"))
}

/// The numbers behind `work-precision.png`, one row per point.
pub fn work_precision_csv(report: &WorkPrecisionReport) -> String {
    let mut s = String::from(
        "scene,integrator,dt,rtol,force_evals,wall_seconds,theta_error,arrival_error,diverged,\
         status,refused\n",
    );
    for scene in &report.scenes {
        for sweep in &scene.integrators {
            for p in &sweep.points {
                s.push_str(&format!(
                    "{},{},{},{},{},{:e},{},{},{},{},{}\n",
                    scene.scene,
                    sweep.name,
                    opt(p.dt),
                    opt(p.rtol),
                    p.force_evals,
                    p.wall_seconds,
                    opt(p.theta_error),
                    opt(p.arrival_error),
                    p.diverged,
                    p.status.name(),
                    csv_field(p.refused.as_deref().unwrap_or(""))
                ));
            }
        }
    }
    s
}

/// A human-readable table of the study.
pub fn work_precision_table(report: &WorkPrecisionReport) -> String {
    let mut s = String::new();
    for scene in &report.scenes {
        s.push_str(&format!(
            "{} (reference: {})\n",
            scene.scene, report.reference
        ));
        s.push_str(
            "integrator        step      force evals  wall (ms)  θ error     arrival error (τ)\n",
        );
        for sweep in &scene.integrators {
            if let Some(reason) = &sweep.refused {
                s.push_str(&format!("{:<17} refused: {reason}\n", sweep.name));
                continue;
            }
            for p in &sweep.points {
                let step = p.dt.or(p.rtol).unwrap_or(f64::NAN);
                let (th, ar) = if p.diverged {
                    ("diverged".to_string(), String::new())
                } else if p.status == Status::Inaccurate {
                    (
                        p.theta_error.map_or(String::new(), |e| format!("{e:.2e}")),
                        format!(
                            "{} (inaccurate)",
                            p.arrival_error
                                .map_or("a flip differs".into(), |e| format!("{e:.3}"))
                        ),
                    )
                } else {
                    (
                        p.theta_error.map_or(String::new(), |e| format!("{e:.2e}")),
                        p.arrival_error
                            .map_or("a flip differs".into(), |e| format!("{e:.3}")),
                    )
                };
                s.push_str(&format!(
                    "{:<17} {:<9} {:>11}  {:>9.2}  {:<11} {}\n",
                    sweep.name,
                    format!("{step}"),
                    p.force_evals,
                    1e3 * p.wall_seconds,
                    th,
                    ar
                ));
            }
            let order = sweep
                .measured_order
                .map_or("n/a".into(), |o| format!("{o:.2}"));
            s.push_str(&format!("{:<17} measured order {order}\n", sweep.name));
        }
        s.push('\n');
    }
    for c in &report.cheapest_within_1tau {
        s.push_str(&format!(
            "cheapest within 1 τ, {}: {} at {} ({} force evaluations, arrival error {:.3} τ)\n",
            c.scene, c.integrator, c.step, c.force_evals, c.arrival_error
        ));
    }
    s
}

/// Observed and predicted critical step of one integrator.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct StabilityRow {
    pub name: String,
    /// Largest dt at which the kink scene stays bounded (bisection).
    pub critical_dt: f64,
    /// Linear prediction from ω_max ([`predicted_dt`]).
    pub predicted_dt: f64,
    /// Why the scheme refused the scene's terms (critical_dt is then 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub refused: Option<String>,
    /// Why no stable step was found (critical_dt is then 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub failed: Option<String>,
}

/// The stability study at one α.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct StabilityPoint {
    pub alpha_deg: f64,
    pub omega_max: f64,
    pub integrators: Vec<StabilityRow>,
}

/// `bench stability --json`: the α = 60° rows at the top level (README.md)
/// and the sweep over α.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct StabilityReport {
    pub alpha_deg: f64,
    pub omega_max: f64,
    pub damping_rate: f64,
    pub integrators: Vec<StabilityRow>,
    pub sweep: Vec<StabilityPoint>,
    /// The built-in movie studied instead of the paper's kink (`--scene`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scene: Option<String>,
    /// Its terms beyond the paper's model ([`BenchScene::terms`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub terms: Option<String>,
}

/// The stability study of one scene (a built-in movie, `--scene`): each
/// scheme's largest stable fixed step on it, by bisection from the linear
/// prediction (ω_max of the clamped chain without its added mass, which
/// only lowers the frequencies, so the prediction errs small); a scheme
/// that refuses the scene's terms is a refused row.
pub fn stability_of_scene(
    scene: &BenchScene,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<StabilityReport> {
    let omega_max = crate::theory::dispersion::omega_max_clamped(&scene.params)?;
    check_window(scene.t_end, omega_max)?;
    let c = damping_rate(&scene.params);
    let mut rows = Vec::new();
    for kind in IntegratorKind::ALL {
        let predicted = predicted_dt(kind, omega_max, c);
        // Without linear damping the damped bound of explicit Euler and
        // dopri5 is 0: start the bracket from a hundredth of 2/ω_max.
        let guess = predicted.clamp(0.02 / omega_max, 10.0 / omega_max);
        rows.push(stability_row(scene, kind, guess, predicted)?);
        progress(&format!("{}: {kind}", scene.name));
    }
    let point = StabilityPoint {
        alpha_deg: scene.alpha_deg,
        omega_max,
        integrators: rows,
    };
    Ok(StabilityReport {
        alpha_deg: scene.alpha_deg,
        omega_max,
        damping_rate: c,
        integrators: point.integrators.clone(),
        sweep: vec![point],
        scene: Some(scene.name.clone()),
        terms: scene.terms(),
    })
}

/// The fewest periods of the chain's highest normal mode (2π/ω_max) a
/// stability study's window must hold. Every scheme's bound is set by that
/// mode (docs/performance.md), and past its bound the mode grows by a
/// factor per step; over fewer periods a step just past the bound shows
/// no growth, and the study would report a limit of the window, not of
/// the scheme.
pub const MIN_WINDOW_PERIODS: f64 = 50.0;

/// Refuses (bad input) a window of `t_end` τ shorter than
/// [`MIN_WINDOW_PERIODS`] periods of the highest mode.
pub fn check_window(t_end: f64, omega_max: f64) -> Result<()> {
    let period = std::f64::consts::TAU / omega_max;
    let least = MIN_WINDOW_PERIODS * period;
    if t_end >= least {
        return Ok(());
    }
    Err(Error::bad_input(format!(
        "a window of {} τ is too short to decide stability: it needs at least \
         {MIN_WINDOW_PERIODS} periods of the chain's highest mode (2π/ω_max = {} τ), \
         --t-end {}",
        crate::error::num(t_end),
        crate::error::num(period),
        crate::error::num(least.ceil())
    )))
}

/// `kind`'s row on `scene`: its critical dt bisected from `guess`, or why
/// it refused the scene's terms (not run), or why its run failed.
fn stability_row(
    scene: &BenchScene,
    kind: IntegratorKind,
    guess: f64,
    predicted: f64,
) -> Result<StabilityRow> {
    let refused = scene.refusal(&IntegratorConfig::fixed(kind, guess));
    let (critical, failed) = match refused {
        Some(_) => (0.0, None),
        None => match critical_dt(scene, kind, guess, STABILITY_PRECISION) {
            Ok(dt) => (dt, None),
            Err(e) if e.is_failed_run() => (0.0, Some(e.to_string())),
            Err(e) => return Err(e),
        },
    };
    Ok(StabilityRow {
        name: kind.name().to_string(),
        critical_dt: critical,
        predicted_dt: predicted,
        refused,
        failed,
    })
}

/// Relative precision of the stability bisection.
pub const STABILITY_PRECISION: f64 = 0.02;

/// Critical and predicted dt of every integrator on the kink scene at α.
pub fn stability_at(alpha_deg: f64) -> Result<StabilityPoint> {
    let scene = BenchScene::paper(alpha_deg)?;
    let omega_max = crate::theory::dispersion::omega_max_clamped(&scene.params)?;
    let c = damping_rate(&scene.params);
    let mut rows = Vec::new();
    for kind in IntegratorKind::ALL {
        let predicted = predicted_dt(kind, omega_max, c);
        // Moreau's time-stepping takes inextensible ribbons only: refused
        // here with its reason, as on any scene whose terms a scheme
        // cannot take.
        rows.push(stability_row(&scene, kind, predicted, predicted)?);
    }
    Ok(StabilityPoint {
        alpha_deg,
        omega_max,
        integrators: rows,
    })
}

/// The α values of the stability chart.
pub const STABILITY_ALPHAS: [f64; 11] = [
    5.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0, 85.0, 89.0,
];

/// The whole study: α = 60° and the sweep over `alphas` (in parallel).
pub fn stability(alphas: &[f64], progress: &(dyn Fn(&str) + Sync)) -> Result<StabilityReport> {
    use rayon::prelude::*;
    let sweep: Vec<StabilityPoint> = alphas
        .par_iter()
        .map(|&a| {
            let p = stability_at(a);
            progress(&format!("α = {a}°"));
            p
        })
        .collect::<Result<_>>()?;
    let at60 = match sweep.iter().find(|p| p.alpha_deg == 60.0) {
        Some(p) => p.clone(),
        None => stability_at(60.0)?,
    };
    Ok(StabilityReport {
        alpha_deg: 60.0,
        omega_max: at60.omega_max,
        damping_rate: damping_rate(&Params::paper(60.0)?),
        integrators: at60.integrators,
        sweep,
        scene: None,
        terms: None,
    })
}

/// The numbers behind `stability.png`.
pub fn stability_csv(report: &StabilityReport) -> String {
    let mut s = String::from("alpha_deg,omega_max,integrator,critical_dt,predicted_dt,refused\n");
    for p in &report.sweep {
        for r in &p.integrators {
            s.push_str(&format!(
                "{},{:.6},{},{:.6e},{:.6e},{}\n",
                p.alpha_deg,
                p.omega_max,
                r.name,
                r.critical_dt,
                r.predicted_dt,
                csv_field(r.refused.as_deref().unwrap_or(""))
            ));
        }
    }
    s
}

/// A human-readable table of the α = 60° rows.
pub fn stability_table(report: &StabilityReport) -> String {
    let what = match (&report.scene, &report.terms) {
        (Some(name), Some(terms)) => format!("{name} ({terms}), α = {}°", report.alpha_deg),
        (Some(name), None) => format!("{name}, α = {}°", report.alpha_deg),
        _ => format!("kink α = {}°", report.alpha_deg),
    };
    let mut s = format!(
        "{what}: ω_max = {:.4} /τ (block 1 clamped), damping rate {} /τ\n\
         integrator        critical dt   predicted dt   ratio\n",
        report.omega_max, report.damping_rate
    );
    for r in &report.integrators {
        if let Some(reason) = &r.refused {
            s.push_str(&format!("{:<17} refused: {reason}\n", r.name));
            continue;
        }
        if let Some(why) = &r.failed {
            s.push_str(&format!("{:<17} no stable step: {why}\n", r.name));
            continue;
        }
        if r.predicted_dt <= 1e-4 {
            // A damped bound with (almost) no linear damping: the linear
            // prediction, as the CSV has it, and no ratio (the terms'
            // own dissipation, not in the prediction, sets the bound).
            s.push_str(&format!(
                "{:<17} {:<13.5} {:<14} n/a\n",
                r.name,
                r.critical_dt,
                format!("{:.3e}", r.predicted_dt)
            ));
            continue;
        }
        s.push_str(&format!(
            "{:<17} {:<13.5} {:<14.5} {:.2}\n",
            r.name,
            r.critical_dt,
            r.predicted_dt,
            r.critical_dt / r.predicted_dt
        ));
    }
    s
}
