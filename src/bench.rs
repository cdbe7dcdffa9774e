//! Speed against accuracy: work-precision sweeps and stability bisection
//! (README.md, `bench work-precision` and `bench stability`), and the
//! paper's run timed with each kernel (`bench kernels`).
//!
//! Every error is measured against a reference computed by the program
//! itself at a much tighter setting (dopri5, rtol = 1e-11).

use crate::error::{Error, Result};
use crate::model::Params;
use crate::scene::Scene;
pub use crate::sim::step_bounds::{damping_rate, predicted_dt, stability_function};
use crate::sim::{self, IntegratorConfig, IntegratorKind, Scenario, Trajectory};
use serde::{Deserialize, Serialize};
use std::time::Instant;

pub mod charts;
pub mod cost;
pub mod kernels;
pub mod report;
pub mod weights;
pub use charts::{stability_caption, stability_chart, work_precision_chart};
pub use cost::{check_stability_cost, check_work_precision_cost};
pub use kernels::{KernelReport, kernels, kernels_table};
pub use report::*;

/// The middle of `values` (the upper of the two middle ones for an even
/// count); NaN for none.
pub fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied().unwrap_or(f64::NAN)
}

/// Tolerance of the reference solution.
pub const REFERENCE_RTOL: f64 = 1e-11;

/// The step of the reference of a scene with inextensible ribbons, which
/// only Moreau's first-order time-stepping integrates: a fifth of the
/// finest step of its sweep. Its chain's free end still moves by tens of
/// τ between such steps (docs/experiments.md, "Inextensible ribbons").
pub const MOREAU_REFERENCE_DT: f64 = 0.002;

/// A scene of the work-precision and stability studies: a single-run
/// [`Scene`] (the paper's single flip by default, or a built-in movie such
/// as the water tank, whose `[apparatus]` adds terms some integrators
/// refuse), its simulation, and the times at which θ is compared with the
/// reference.
#[derive(Debug, Clone)]
pub struct BenchScene {
    pub name: String,
    pub scene: Scene,
    /// The simulation of `scene` (for an apparatus, in the model's units).
    pub scenario: Scenario,
    pub alpha_deg: f64,
    pub params: Params,
    pub t_end: f64,
    /// Times at which θ is compared with the reference.
    pub frames: Vec<f64>,
}

impl BenchScene {
    /// The paper's kink (α > 0) or antikink (α < 0) scene, N = 10, b = 1.3,
    /// T_d = 1000, t_end = 4000, compared every 20 τ.
    pub fn paper(alpha_deg: f64) -> Result<Self> {
        let mut scene = Scene::default();
        scene.model.alpha = alpha_deg;
        Self::from_scene(
            Scene {
                run: crate::scene::Run {
                    t_end: 4000.0,
                    ..scene.run
                },
                ..scene
            },
            200,
        )
    }

    /// A built-in movie's scene by its ID (`water-tank`, `linkage-69`,
    /// `4`, ...), its window cut to `t_end` τ if given, compared at
    /// `frames` + 1 evenly spaced times. An unknown ID, or a movie of more
    /// than one run, is bad input.
    pub fn movie(id: &str, t_end: Option<f64>, frames: usize) -> Result<Self> {
        let entry = crate::catalog::find(crate::scene::Kind::Movie, id)?;
        let mut scene = entry.scene.clone().with_auto_window()?;
        if scene.runs().len() > 1 {
            return Err(Error::bad_input(format!(
                "movie {id} has more than one run; the studies take a single run"
            )));
        }
        if let Some(t) = t_end {
            scene.run.t_end = t;
            // An apparatus' duration (s) sets the window: set it in τ.
            if let Some(a) = scene.apparatus.as_mut() {
                let tau = a.convert(scene.model.alpha).tau_s;
                a.duration = Some(t * tau);
            }
        }
        let mut s = Self::from_scene(scene, frames)?;
        s.name = entry.id.clone();
        if let Some(t) = t_end {
            // Exactly `t`, not its round trip through seconds.
            s.scenario.t_end = t;
            s.t_end = t;
            s.frames = even_frames(t, frames);
        }
        Ok(s)
    }

    /// A study scene from any single-run scene, compared at `frames` + 1
    /// evenly spaced times.
    pub fn from_scene(scene: Scene, frames: usize) -> Result<Self> {
        let scenario = scene.scenario()?;
        let params = scenario.ladder.params;
        let t_end = scenario.t_end;
        if t_end.is_nan() || t_end <= 0.0 {
            return Err(Error::bad_input(format!(
                "the study's window must be longer than 0 τ, got {}",
                crate::error::num(t_end)
            )));
        }
        Ok(Self {
            name: crate::scene::describe::wave(&scene.model).replace(", ", " "),
            alpha_deg: params.alpha_deg(),
            params,
            t_end,
            frames: even_frames(t_end, frames),
            scenario,
            scene,
        })
    }

    pub fn scenario(&self) -> Result<Scenario> {
        Ok(self.scenario.clone())
    }

    /// Why `config`'s scheme cannot integrate this scene's terms
    /// (`sim::check_terms`), or `None` if it can.
    pub fn refusal(&self, config: &IntegratorConfig) -> Option<String> {
        sim::check_terms(&self.scenario.ladder, config)
            .err()
            .map(|e| e.to_string())
    }

    /// The scene's terms beyond the paper's model, as its apparatus sets
    /// them ("water: buoyancy, added mass, quadratic drag"); `None` for
    /// the paper's model.
    pub fn terms(&self) -> Option<String> {
        let a = self.scene.apparatus.as_ref()?;
        let medium = match a.medium {
            crate::scene::apparatus::Medium::Air => "air",
            crate::scene::apparatus::Medium::Water => "water",
        };
        let mut terms = Vec::new();
        for (on, what) in [
            (a.buoyancy, "buoyancy"),
            (a.added_mass, "added mass"),
            (a.drag, "quadratic drag"),
            (a.tension_only, "tension-only links"),
            (a.pin_friction > 0.0, "pin friction"),
            (a.motor.is_some(), "motor"),
        ] {
            if on {
                terms.push(what);
            }
        }
        use crate::scene::apparatus::{StiffWord, Stiffness};
        let word = match a.stiffness {
            Stiffness::Word(w) => Some(w),
            Stiffness::NewtonPerMetre(_) => None,
        };
        match (a.ribbons, word) {
            (true, Some(StiffWord::Inextensible)) => terms.push("inextensible ribbons"),
            (true, Some(StiffWord::Stiff)) => terms.push("stiff ribbons"),
            (true, None) => terms.push("ribbons"),
            (false, Some(_)) => terms.push("stiff links"),
            (false, None) => {}
        }
        if a.contact.is_some() {
            terms.push("contact");
        }
        Some(format!("{medium}: {}", terms.join(", ")))
    }

    /// Runs the scene with `config`, sampled at the frames.
    pub fn run(&self, config: &IntegratorConfig) -> Result<Trajectory> {
        sim::simulate(&self.scenario, &self.frames, config)
    }

    /// The reference's configuration: dopri5 at [`REFERENCE_RTOL`], or,
    /// for inextensible ribbons (which dopri5 refuses), Moreau at
    /// [`MOREAU_REFERENCE_DT`].
    pub fn reference_config(&self) -> IntegratorConfig {
        let inextensible =
            (self.scenario.ladder.built.as_ref()).is_some_and(|b| b.ribbons.inextensible);
        if inextensible {
            IntegratorConfig::fixed(IntegratorKind::Moreau, MOREAU_REFERENCE_DT)
        } else {
            IntegratorConfig::adaptive(REFERENCE_RTOL)
        }
    }

    /// The reference solution ([`BenchScene::reference_config`]).
    pub fn reference(&self) -> Result<Trajectory> {
        self.run(&self.reference_config())
    }
}

/// `frames` + 1 evenly spaced times over [0, t_end] (at least 2).
fn even_frames(t_end: f64, frames: usize) -> Vec<f64> {
    (0..=frames.max(1))
        .map(|k| t_end * k as f64 / frames.max(1) as f64)
        .collect()
}

/// Largest |θ_n(t) − θ_ref,n(t)| over the frames (radians).
pub fn theta_error(run: &Trajectory, reference: &Trajectory) -> f64 {
    run.states
        .iter()
        .zip(&reference.states)
        .flat_map(|(a, b)| a.iter().zip(b).skip(2).step_by(3))
        .fold(0.0, |m, (x, y)| m.max((x - y).abs()))
}

/// Largest |t_n − t_ref,n| (τ); `None` (infinite) when a block flips in one
/// run and not in the other.
pub fn arrival_error(run: &Trajectory, reference: &Trajectory) -> Option<f64> {
    let mut worst: f64 = 0.0;
    for (a, b) in run.arrival_times.iter().zip(&reference.arrival_times) {
        match (a, b) {
            (Some(a), Some(b)) => worst = worst.max((a - b).abs()),
            (None, None) => {}
            _ => return None,
        }
    }
    Some(worst)
}

/// One point of a work-precision sweep.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Point {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dt: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rtol: Option<f64>,
    pub force_evals: u64,
    pub wall_seconds: f64,
    pub theta_error: Option<f64>,
    pub arrival_error: Option<f64>,
    pub diverged: bool,
    /// What the run came to: ok, inaccurate, diverged or refused.
    #[serde(default)]
    pub status: Status,
    /// Why the scheme refused the scene's terms (`sim::check_terms`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub refused: Option<String>,
}

/// What one point of a study came to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Status {
    /// Ran to the end within [`INACCURATE_THETA`] of the reference, every
    /// block flipping as in it.
    #[default]
    Ok,
    /// Ran to the end, but θ is off by more than [`INACCURATE_THETA`] or a
    /// block flips in one run and not in the other.
    Inaccurate,
    /// The run blew up (`Error::Diverged`) or failed.
    Diverged,
    /// The scheme cannot integrate the scene's terms: not run.
    Refused,
}

impl Status {
    pub fn name(self) -> &'static str {
        match self {
            Self::Ok => "ok",
            Self::Inaccurate => "inaccurate",
            Self::Diverged => "diverged",
            Self::Refused => "refused",
        }
    }
}

/// A θ error above which a run that reached the end is called inaccurate
/// (radians): a tenth of a radian, far above every converged point.
pub const INACCURATE_THETA: f64 = 0.1;

/// All points of one integrator, and its order measured from them.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Sweep {
    pub name: String,
    pub measured_order: Option<f64>,
    pub points: Vec<Point>,
    /// Why the scheme refused the scene (every point is then refused).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub refused: Option<String>,
}

/// The step sizes (or tolerances, for dopri5) swept for each integrator:
/// from well converged to past the stability limit.
pub fn default_steps(kind: IntegratorKind) -> Vec<f64> {
    match kind {
        IntegratorKind::ExplicitEuler => vec![0.0005, 0.001, 0.002, 0.005, 0.01],
        IntegratorKind::SymplecticEuler => vec![0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4],
        IntegratorKind::Verlet | IntegratorKind::Moreau => {
            vec![0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.3, 0.4, 0.6]
        }
        IntegratorKind::Rk4 => vec![0.05, 0.1, 0.2, 0.3, 0.4, 0.6, 0.8],
        IntegratorKind::Dopri5 => vec![1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10],
    }
}

/// The configuration of `kind` at sweep value `x` (dt, or rtol for dopri5).
pub fn config_at(kind: IntegratorKind, x: f64) -> IntegratorConfig {
    match kind {
        IntegratorKind::Dopri5 => IntegratorConfig::adaptive(x),
        _ => IntegratorConfig::fixed(kind, x),
    }
}

/// Runs `kind` at every value of `steps` on `scene`, `repeats` times each
/// (the median wall time is kept), and measures the errors against `reference`.
pub fn sweep(
    scene: &BenchScene,
    reference: &Trajectory,
    kind: IntegratorKind,
    steps: &[f64],
    repeats: usize,
) -> Result<Sweep> {
    let mut points = Vec::with_capacity(steps.len());
    for &x in steps {
        points.push(measure(scene, reference, kind, x, repeats)?);
    }
    Ok(Sweep {
        name: kind.name().to_string(),
        measured_order: measured_order(&points),
        refused: points.iter().find_map(|p| p.refused.clone()),
        points,
    })
}

/// One point: `kind` at `x` (dt, or rtol for dopri5) on `scene`, timed
/// over `repeats` runs; a scheme that cannot take the scene's terms is a
/// refused point (not run), a run that blows up a diverged one.
pub fn measure(
    scene: &BenchScene,
    reference: &Trajectory,
    kind: IntegratorKind,
    x: f64,
    repeats: usize,
) -> Result<Point> {
    let config = config_at(kind, x);
    let (dt, rtol) = match kind {
        IntegratorKind::Dopri5 => (None, Some(x)),
        _ => (Some(x), None),
    };
    if let Some(reason) = scene.refusal(&config) {
        return Ok(Point {
            dt,
            rtol,
            force_evals: 0,
            wall_seconds: 0.0,
            theta_error: None,
            arrival_error: None,
            diverged: false,
            status: Status::Refused,
            refused: Some(reason),
        });
    }
    let mut times = Vec::with_capacity(repeats.max(1));
    let mut outcome = None;
    for _ in 0..repeats.max(1) {
        let start = Instant::now();
        let run = scene.run(&config);
        times.push(start.elapsed().as_secs_f64());
        match run {
            Err(e) if e.is_failed_run() => {
                outcome = None;
                break;
            }
            Err(e) => return Err(e),
            Ok(t) => outcome = Some(t),
        }
    }
    let wall_seconds = median(times);
    Ok(match outcome {
        Some(run) => {
            let theta = theta_error(&run, reference);
            let arrival = arrival_error(&run, reference);
            let status = if theta.is_finite() && theta <= INACCURATE_THETA && arrival.is_some() {
                Status::Ok
            } else {
                Status::Inaccurate
            };
            Point {
                dt,
                rtol,
                force_evals: run.force_evals,
                wall_seconds,
                theta_error: Some(theta),
                arrival_error: arrival,
                diverged: false,
                status,
                refused: None,
            }
        }
        None => Point {
            dt,
            rtol,
            force_evals: 0,
            wall_seconds,
            theta_error: None,
            arrival_error: None,
            diverged: true,
            status: Status::Diverged,
            refused: None,
        },
    })
}

/// Order p from the slope of log(θ error) against log(force evaluations)
/// (error ∝ evals^(−p)), over converged points whose error lies between
/// 1e-10 (well above the reference's own error, about 1e-12) and 1e-2 (asymptotic regime).
/// Points on a cost plateau (within 30 % of the cheapest, where an adaptive
/// method is held by stability rather than by its tolerance) are left out.
pub fn measured_order(points: &[Point]) -> Option<f64> {
    let floor = points
        .iter()
        .filter(|p| !p.diverged && p.refused.is_none())
        .map(|p| p.force_evals)
        .min()?;
    let plateau = |p: &Point| {
        let tolerance_driven = points.iter().any(|q| q.rtol.is_some());
        tolerance_driven && (p.force_evals as f64) < 1.3 * floor as f64
    };
    let pts: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| !p.diverged && !plateau(p))
        .filter_map(|p| p.theta_error.map(|e| (p.force_evals as f64, e)))
        .filter(|(_, e)| *e > 1e-10 && *e < 1e-2)
        .map(|(n, e)| (n.ln(), e.ln()))
        .collect();
    if pts.len() < 2 {
        return None;
    }
    Some(-slope(&pts))
}

/// Order p from the slope of log(θ error) against log(dt) (error ∝ dt^p)
/// over a fixed-step sweep's accurate points ([`Status::Ok`]) whose error
/// lies between 1e-10 and 1e-2; `None` with fewer than two.
pub fn order_in_step(points: &[Point]) -> Option<f64> {
    let pts: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| p.status == Status::Ok)
        .filter_map(|p| Some((p.dt?, p.theta_error?)))
        .filter(|(_, e)| *e > 1e-10 && *e < 1e-2)
        .map(|(h, e)| (h.ln(), e.ln()))
        .collect();
    (pts.len() >= 2).then(|| slope(&pts))
}

pub use crate::sim::observables::least_squares_slope as slope;

/// The cheapest point (fewest force evaluations) whose arrival times all lie
/// within `tolerance` τ of the reference.
pub fn cheapest_within(sweeps: &[Sweep], tolerance: f64) -> Option<(&str, &Point)> {
    sweeps
        .iter()
        .flat_map(|s| s.points.iter().map(move |p| (s.name.as_str(), p)))
        .filter(|(_, p)| p.arrival_error.is_some_and(|e| e <= tolerance))
        .min_by_key(|(_, p)| p.force_evals)
}

/// Whether the scene stays bounded with `kind` at fixed step `dt`
/// (dopri5 is run at fixed step here).
pub fn is_stable(scene: &BenchScene, kind: IntegratorKind, dt: f64) -> Result<bool> {
    let config = IntegratorConfig::fixed(kind, dt);
    match sim::simulate(&scene.scenario()?, &[], &config) {
        Ok(_) => Ok(true),
        Err(e) if e.is_failed_run() => Ok(false),
        Err(e) => Err(e),
    }
}

/// The fewest steps a window must hold for a step to be judged stable
/// ([`critical_dt`] reports no step longer than the window over this).
pub const MIN_STEPS_IN_WINDOW: f64 = 20.0;

/// The largest stable dt, by geometric bisection from a bracket around
/// `guess`, to a relative precision `rel`; a failed run (`Error::failed`)
/// where the scheme is stable at every step the window can judge (at most
/// the window over [`MIN_STEPS_IN_WINDOW`]): never a step longer than
/// that.
pub fn critical_dt(scene: &BenchScene, kind: IntegratorKind, guess: f64, rel: f64) -> Result<f64> {
    let (mut lo, mut hi) = (guess, guess);
    while !is_stable(scene, kind, lo)? {
        lo /= 2.0;
        if lo < 1e-6 {
            return Err(Error::failed(format!("{kind}: no stable dt above 1e-6")));
        }
    }
    hi = hi.max(lo * 2.0);
    // A step the window holds fewer than MIN_STEPS_IN_WINDOW of is not
    // judged: the run would end before any growth showed.
    let longest = scene.t_end / MIN_STEPS_IN_WINDOW;
    while is_stable(scene, kind, hi)? {
        if hi >= longest {
            return Err(Error::failed(format!(
                "{kind}: stable at every step up to {} τ ({MIN_STEPS_IN_WINDOW} steps in the \
                 window of {} τ): the window cannot decide its limit; give a longer --t-end",
                crate::error::num(longest),
                crate::error::num(scene.t_end)
            )));
        }
        hi = (hi * 2.0).min(longest);
    }
    while hi / lo > 1.0 + rel {
        let mid = (lo * hi).sqrt();
        if is_stable(scene, kind, mid)? {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(lo)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_is_the_middle_value() {
        assert_eq!(median(vec![3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(vec![4.0, 1.0, 3.0, 2.0]), 3.0);
        assert!(median(Vec::new()).is_nan());
    }

    #[test]
    fn slope_of_a_power_law() {
        let pts: Vec<(f64, f64)> = (1..6).map(|k| (k as f64, -3.0 * k as f64 + 1.0)).collect();
        assert!((slope(&pts) + 3.0).abs() < 1e-12);
    }

    /// The terms a study's header names are the scene's: the ribbon tank's
    /// inextensible ribbons and contact, the spring tank's stiff links.
    #[test]
    fn a_study_names_the_scenes_links() {
        let terms = |id: &str| {
            BenchScene::movie(id, Some(1.0), 2)
                .unwrap()
                .terms()
                .unwrap()
        };
        let ribbons = terms("water-tank-ribbons");
        assert!(
            ribbons.ends_with("motor, inextensible ribbons, contact"),
            "{ribbons}"
        );
        assert!(terms("water-tank").ends_with("motor, stiff links"));
    }

    /// The ribbon tank's inextensible ribbons, which dopri5 refuses, are
    /// measured against Moreau at a fine step; every other scene against
    /// dopri5. On a short window its points run and the refused schemes
    /// say why.
    #[test]
    fn inextensible_ribbons_are_measured_against_a_fine_moreau_run() {
        let ribbons = BenchScene::movie("water-tank-ribbons", Some(200.0), 4).unwrap();
        let c = ribbons.reference_config();
        assert_eq!(
            (c.kind, c.dt),
            (IntegratorKind::Moreau, MOREAU_REFERENCE_DT)
        );
        let tank = BenchScene::movie("water-tank", Some(1.0), 2).unwrap();
        assert_eq!(tank.reference_config().rtol, Some(REFERENCE_RTOL));
        let reference = ribbons.reference().unwrap();
        let p = measure(&ribbons, &reference, IntegratorKind::Moreau, 0.2, 1).unwrap();
        assert_eq!(p.status, Status::Ok, "{p:?}");
        let p = measure(&ribbons, &reference, IntegratorKind::Rk4, 0.2, 1).unwrap();
        assert_eq!(p.status, Status::Refused);
        assert!(p.refused.unwrap().contains("inextensible"));
    }
}
