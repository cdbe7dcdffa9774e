//! The divergence watch of the run loop: a run that has left the physics
//! ends with `Error::Diverged`, naming the integrator, its step and the
//! time (no partial result escapes).

use super::{IntegratorConfig, Protocol, Rhs, State};
use crate::error::{Error, Result};
use crate::model::Ladder;
use crate::model::ladder::itheta;
use crate::model::params::M;

/// Runaway thresholds: more than four turns of any block, or an elastic
/// energy beyond one k s² per spring (a stretch of about 1.4 s everywhere).
const MAX_TURNS: f64 = 4.0;
/// Undriven energy growth, per spring, treated as a runaway.
const MAX_UNDRIVEN_GROWTH: f64 = 1e-2;

/// Detects a run that has left the physics: non-finite numbers, runaway
/// angles or stretches, or mechanical energy growing while nothing drives.
pub(super) struct DivergenceWatch {
    name: &'static str,
    step: String,
    drive_end: f64,
    max_elastic: f64,
    max_growth: f64,
    undriven_min: f64,
}

impl DivergenceWatch {
    pub(super) fn new(ladder: &Ladder, protocol: &Protocol, config: &IntegratorConfig) -> Self {
        let springs = 2.0 * (ladder.n() - 1) as f64;
        Self {
            name: config.kind.name(),
            step: config.describe_step(),
            drive_end: protocol.drive_end(),
            max_elastic: springs,
            max_growth: MAX_UNDRIVEN_GROWTH * springs,
            undriven_min: f64::INFINITY,
        }
    }

    pub(super) fn check(&mut self, rhs: &Rhs, st: &State, t: f64) -> Result<()> {
        let finite = st.q.iter().chain(&st.v).all(|x| x.is_finite());
        if !finite {
            return Err(self.diverged(t, "the state became NaN or infinite"));
        }
        let max_theta = (0..rhs.ladder.n())
            .map(|i| st.q[itheta(i)].abs())
            .fold(0.0, f64::max);
        if max_theta > MAX_TURNS * std::f64::consts::TAU {
            return Err(self.diverged(t, "a block turned more than four times"));
        }
        let ladder = rhs.ladder;
        if !ladder.is_paper_model() {
            return self.check_terms(rhs, st, t);
        }
        let elastic = ladder.elastic_energy(&st.q);
        if elastic > self.max_elastic {
            return Err(self.diverged(t, "the springs stretched beyond any physical state"));
        }
        if t >= self.drive_end {
            // `Rhs::mechanical_energy`, with the elastic part computed once.
            let gravity: f64 = st.q.iter().step_by(3).sum();
            let potential = elastic - M * ladder.params.gravity * gravity;
            let e = ladder.kinetic_energy(&st.v) + potential;
            self.undriven_min = self.undriven_min.min(e);
            if e > self.undriven_min + self.max_growth {
                return Err(self.diverged(t, "the energy grew while nothing drove the ladder"));
            }
        }
        Ok(())
    }

    /// [`DivergenceWatch::check`]'s energy tests for a ladder with terms:
    /// the links' elastic energy (per unit stiffness) and the kinetic
    /// energy with added mass.
    fn check_terms(&mut self, rhs: &Rhs, st: &State, t: f64) -> Result<()> {
        let terms = &rhs.ladder.terms;
        if let Some(b) = rhs.ladder.built
            && b.contact.is_some()
            && rhs.deepest_overlap
                > crate::model::contact::MAX_OVERLAP * b.ribbons.outline.thickness()
        {
            return Err(self.diverged(
                t,
                "two blocks overlapped by more than a tenth of their thickness (the contact \
                 is too soft for the impact, or the step too long)",
            ));
        }
        let elastic = terms.links.elastic_energy(rhs.ladder, &st.q);
        if elastic > self.max_elastic * terms.links.stiffness {
            return Err(self.diverged(t, "the springs stretched beyond any physical state"));
        }
        if t >= self.drive_end {
            let e = rhs.mechanical_energy(st);
            self.undriven_min = self.undriven_min.min(e);
            if e > self.undriven_min + self.max_growth {
                return Err(self.diverged(t, "the energy grew while nothing drove the ladder"));
            }
        }
        Ok(())
    }

    fn diverged(&self, t: f64, what: &'static str) -> Error {
        Error::Diverged(Box::new(crate::error::Divergence {
            integrator: self.name,
            step: self.step.clone(),
            t,
            what,
        }))
    }
}
