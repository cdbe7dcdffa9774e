//! The data file beside every output (`<output>.json`, SPEC section 6):
//! what made it and the numbers its picture shows, one [`RunData`] per
//! simulation drawn.

use super::run::{IntegratorReport, SceneRun};
use crate::scene::{DriveSpec, Model, Scene};
use crate::sim;
use serde::Serialize;

/// `<output>.json`: the scene with every parameter, the program that made
/// the output, and the numbers the picture shows (SPEC section 6).
#[derive(Debug, Clone, Serialize)]
pub struct DataFile<'a> {
    pub program: &'static str,
    pub version: &'static str,
    pub title: String,
    pub parameters: String,
    pub fidelity: &'static str,
    pub files: Vec<String>,
    pub scene: &'a Scene,
    /// One entry per simulation drawn (empty for the theory figures).
    pub runs: Vec<RunData>,
}

/// What the data file says of one run: the scene it ran, the integrator
/// and accuracy, the arrival times, the final angles and, at each drawn
/// time, θ_n (degrees, wrapped to (−180°, 180°]) and the centres.
#[derive(Debug, Clone, Serialize)]
pub struct RunData {
    pub label: String,
    pub model: Model,
    pub drive: DriveSpec,
    pub t_end: f64,
    pub integrator: IntegratorReport,
    pub arrival_times: Vec<Option<f64>>,
    /// Speed of the wave in blocks per τ (least squares over blocks
    /// 2..N−1), when at least three of them flipped.
    pub speed: Option<f64>,
    pub final_theta_deg: Vec<f64>,
    /// Every wave of the run and block N's fate (SPEC section 9).
    pub waves: sim::waves::Waves,
    pub frames: Vec<FrameData>,
}

/// The state drawn at one time.
#[derive(Debug, Clone, Serialize)]
pub struct FrameData {
    pub t: f64,
    pub theta_deg: Vec<f64>,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
}

impl RunData {
    pub fn from_run(scene: &Scene, run: &SceneRun) -> Self {
        Self::new("", scene, run)
    }

    pub(super) fn new(label: &str, scene: &Scene, run: &SceneRun) -> Self {
        let traj = &run.trajectory;
        let frames = traj
            .times
            .iter()
            .zip(&traj.states)
            .map(|(&t, q)| FrameData {
                t,
                theta_deg: sim::observables::angles_deg(q),
                x: (0..q.len() / 3).map(|i| q[3 * i]).collect(),
                y: (0..q.len() / 3).map(|i| q[3 * i + 1]).collect(),
            })
            .collect();
        Self {
            label: label.to_string(),
            model: scene.model,
            drive: scene.drive.clone(),
            t_end: scene.run.t_end,
            integrator: run.integrator.clone(),
            arrival_times: traj.arrival_times.clone(),
            speed: sim::observables::wave_speed(&traj.arrival_times),
            final_theta_deg: traj.final_theta_deg(),
            waves: traj.waves.clone(),
            frames,
        }
    }
}

