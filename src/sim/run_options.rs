//! How a run is carried out, apart from what is simulated ([`Scenario`])
//! and how it is stepped ([`IntegratorConfig`]): one value with every
//! default in one `impl Default` (as rapier's `IntegrationParameters`).
//!
//! [`Scenario`]: super::Scenario
//! [`IntegratorConfig`]: super::IntegratorConfig

use super::{Stepping, StopRule, StopView};
use crate::limits::Limits;

/// The stop rule that never stops a run before its t_end.
pub fn run_to_end(_view: &StopView) -> bool {
    false
}

/// The progress callback that tells no one.
fn silent(_t: f64) {}

/// Options of one run (`sim::run`, `sim::run_streaming`,
/// `auto::simulate_verified`, `batch::simulate_many`, `window::auto_window`).
/// None of them changes the trajectory, except `stop`, which may end it
/// early, `limits`, which may refuse it, and `samples_between_steps`,
/// which takes the steps on a grid of their own.
#[derive(Clone, Copy)]
pub struct RunOptions<'a> {
    /// Which kernel takes symplectic Euler's and Verlet's steps. Default
    /// [`Stepping::Fastest`]: the fused kernel for the best instruction set
    /// of this CPU. Every choice gives the same trajectory bit for bit.
    pub stepping: Stepping,
    /// The caps the run must stay within, checked before it starts and
    /// while it runs. Default [`Limits::default`] (docs/limits.md); the
    /// front ends pass the caps their user set.
    pub limits: Limits,
    /// Ends the run once it says so (t_end is then the cap): asked at every
    /// divergence check (every 5 τ, at most 512 steps apart) and at every
    /// sample time and drive corner. Default [`run_to_end`].
    pub stop: &'a StopRule<'a>,
    /// Told the simulated time at every divergence check, for a progress
    /// bar. Default: tells no one.
    pub progress: &'a (dyn Fn(f64) + Sync),
    /// Feed the wave tracker after every step (exact times of every sign
    /// change) rather than at the checks (`waves`' module doc). Default
    /// `None`: every step when the drive flips block 1 more than once (a
    /// single flip's one driven wave is timed exactly by the arrival
    /// detector inside the fused kernel's chunks, which keeps the paper's
    /// run at its ~50 ms; stepping one step per call made it 6.6 times
    /// slower).
    pub every_step: Option<bool>,
    /// Record the energy dissipated so far at every sample
    /// (`Trajectory::dissipated`): the power of every dissipative term
    /// (`model::media::dissipation`) integrated by the trapezoidal rule
    /// over every step, which takes the steps one per call. Default
    /// `false`. The trajectory is the same bit for bit either way.
    pub dissipation: bool,
    /// Keep the energy budget (`Trajectory::budget`, `sim::budget`): the
    /// work done through block 1 and the energy dissipated, accumulated
    /// inside the integrator from the powers at every stage. Default
    /// `None`: kept for the toy as built (its ribbons' search makes the
    /// powers' cost small), not for other ladders. Only where the forces
    /// depend on the velocities and the scheme accumulates it (explicit
    /// Euler, RK4 on the portable path, dopri5). The trajectory is the
    /// same bit for bit either way.
    pub budget: Option<bool>,
    /// Step on a grid the sample times do not cut (only the drive's
    /// corners and t_end do) and take each sample from the two states
    /// around it by cubic Hermite interpolation (`sim::between`), so that
    /// the trajectory is the same whatever the run is sampled at; else a
    /// step lands on every sample time. Default `None`: between steps
    /// where blocks may touch (contact: the clatter is chaotic, and a step
    /// landing on a frame's time changes it with the number of frames),
    /// on them elsewhere. Takes the steps one per call.
    pub samples_between_steps: Option<bool>,
}

impl Default for RunOptions<'static> {
    fn default() -> Self {
        Self {
            stepping: Stepping::Fastest,
            limits: Limits::default(),
            stop: &run_to_end,
            progress: &silent,
            every_step: None,
            dissipation: false,
            budget: None,
            samples_between_steps: None,
        }
    }
}

impl<'a> RunOptions<'a> {
    /// These options with `stepping`.
    pub fn stepping(self, stepping: Stepping) -> Self {
        Self { stepping, ..self }
    }

    /// These options within `limits`.
    pub fn limits(self, limits: Limits) -> Self {
        Self { limits, ..self }
    }

    /// These options with the stop rule `stop`.
    pub fn stop<'b>(self, stop: &'b StopRule<'b>) -> RunOptions<'b>
    where
        'a: 'b,
    {
        RunOptions { stop, ..self }
    }

    /// These options telling `progress` the simulated time.
    pub fn progress<'b>(self, progress: &'b (dyn Fn(f64) + Sync)) -> RunOptions<'b>
    where
        'a: 'b,
    {
        RunOptions { progress, ..self }
    }

    /// These options recording the energy dissipated so far.
    pub fn dissipation(self, dissipation: bool) -> Self {
        Self {
            dissipation,
            ..self
        }
    }

    /// These options keeping the energy budget (or not).
    pub fn budget(self, budget: bool) -> Self {
        Self {
            budget: Some(budget),
            ..self
        }
    }

    /// These options taking the samples between steps (or on them).
    pub fn samples_between_steps(self, between: bool) -> Self {
        Self {
            samples_between_steps: Some(between),
            ..self
        }
    }

    /// These options feeding the wave tracker after every step (or not).
    pub fn every_step(self, every_step: bool) -> Self {
        Self {
            every_step: Some(every_step),
            ..self
        }
    }
}

impl std::fmt::Debug for RunOptions<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RunOptions")
            .field("stepping", &self.stepping)
            .field("limits", &self.limits)
            .field("every_step", &self.every_step)
            .field("dissipation", &self.dissipation)
            .field("budget", &self.budget)
            .field("samples_between_steps", &self.samples_between_steps)
            .finish_non_exhaustive()
    }
}
