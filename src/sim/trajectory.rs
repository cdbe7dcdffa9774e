//! The result of a run ([`Trajectory`]) and its energies at the samples
//! ([`Energies`], docs/model.md).

use super::observables::{self, kink_position};
use super::waves::Waves;
use super::{Sample, State};
use crate::model::Ladder;
use crate::model::ladder::itheta;
use crate::model::media;
use crate::model::params::M;

/// The result of a run: states at the sample times, observables and cost.
#[derive(Debug, Clone)]
pub struct Trajectory {
    /// Sample times (sorted, within [0, t_end]).
    pub times: Vec<f64>,
    /// Positions q at each sample time.
    pub states: Vec<Vec<f64>>,
    /// Velocities at each sample time.
    pub velocities: Vec<Vec<f64>>,
    /// Kink position (blocks flipped, see `observables::kink_position`) at each sample.
    pub kink_position: Vec<f64>,
    /// Energy dissipated by every dissipative term from t = 0 to each
    /// sample, in units of k s² (`RunOptions::dissipation`; empty unless
    /// asked for).
    pub dissipated: Vec<f64>,
    /// Arrival time per block: the first sign change of its polarisation
    /// sin θ_n (docs/model.md), `None` where it never flipped.
    pub arrival_times: Vec<Option<f64>>,
    /// Every domain wall of the run as a wave, and block N's fate
    /// (`waves`, docs/sweeps.md).
    pub waves: Waves,
    /// Every impact between two blocks (`impacts`), in time order, for a
    /// ladder whose blocks may touch; `None` for any other.
    pub impacts: Option<Vec<super::impacts::Impact>>,
    /// The energy budget from t = 0 to the end of the run, W and D
    /// accumulated inside the integrator (`budget`,
    /// `RunOptions::budget`); `None` where the run kept none.
    pub budget: Option<super::budget::Budget>,
    /// State at the end of the run: at t_end, or at `t_final` where a stop
    /// rule ended it earlier (`RunOptions::stop`).
    pub final_state: State,
    /// The time the run reached (t_end unless a stop rule ended it).
    pub t_final: f64,
    pub steps: u64,
    pub force_evals: u64,
}

impl Trajectory {
    /// θ_n at t_end, in degrees, wrapped to (−180°, 180°] (docs/model.md).
    pub fn final_theta_deg(&self) -> Vec<f64> {
        observables::angles_deg(&self.final_state.q)
    }

    /// θ_n at t_end, in degrees, as integrated (not wrapped).
    pub fn final_theta_deg_unwrapped(&self) -> Vec<f64> {
        observables::angles_deg_unwrapped(&self.final_state.q)
    }

    /// Stores a sample (the sink of [`super::run`]).
    pub(super) fn push(&mut self, sample: &Sample, alpha: f64) {
        self.times.push(sample.t);
        self.states.push(sample.q.to_vec());
        self.velocities.push(sample.v.to_vec());
        self.kink_position.push(kink_position(sample.q, alpha));
        if let Some(d) = sample.dissipated {
            self.dissipated.push(d);
        }
    }
}

impl Trajectory {
    /// The result of a finished run of `steps` steps, without samples,
    /// counted once in the run tally ([`super::tally`], `--timings`):
    /// every run loop (the portable one and each lane of the batch
    /// kernels) ends here exactly once.
    pub(super) fn finished(
        final_state: State,
        t_final: f64,
        arrival_times: Vec<Option<f64>>,
        steps: u64,
        force_evals: u64,
    ) -> Self {
        super::tally::record(steps, arrival_times.len());
        Self::unsampled(final_state, t_final, arrival_times, steps, force_evals)
    }

    /// A trajectory without samples (not counted as a run).
    pub(super) fn unsampled(
        final_state: State,
        t_final: f64,
        arrival_times: Vec<Option<f64>>,
        steps: u64,
        force_evals: u64,
    ) -> Self {
        Self {
            times: Vec::new(),
            states: Vec::new(),
            velocities: Vec::new(),
            kink_position: Vec::new(),
            dissipated: Vec::new(),
            arrival_times,
            waves: Waves::default(),
            impacts: None,
            budget: None,
            final_state,
            t_final,
            steps,
            force_evals,
        }
    }
}

/// The energies of a trajectory at its samples, in units of k s²
/// (docs/model.md): one value per sample each.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Energies {
    /// ½ m (Ẋ² + Ẏ²) + ½ I θ̇² summed over the blocks (with the added mass
    /// and added inertia of a ladder in water, `model::media`).
    pub kinetic: Vec<f64>,
    /// Σ ½ k [(L_A − a)² + (L_B − b)²] (or the links' own elastic energy,
    /// `model::links`).
    pub elastic: Vec<f64>,
    /// −m G Σ X_n (X runs down the ladder, along gravity).
    pub gravitational: Vec<f64>,
    /// The energy dissipated from t = 0 to the sample
    /// (`Trajectory::dissipated`); empty unless the run recorded it.
    pub dissipated: Vec<f64>,
}

impl Energies {
    /// Kinetic + elastic + gravitational at each sample.
    pub fn total(&self) -> Vec<f64> {
        (0..self.kinetic.len())
            .map(|k| self.kinetic[k] + self.elastic[k] + self.gravitational[k])
            .collect()
    }
}

impl Trajectory {
    /// The energies at every sample of this run of `ladder` (the ladder it
    /// was run with).
    pub fn energies(&self, ladder: &Ladder) -> Energies {
        let terms = &ladder.terms;
        let mut e = Energies {
            dissipated: self.dissipated.clone(),
            ..Energies::default()
        };
        for (q, v) in self.states.iter().zip(&self.velocities) {
            let (kinetic, elastic) = if ladder.is_paper_model() {
                (ladder.kinetic_energy(v), ladder.elastic_energy(q))
            } else {
                (
                    media::kinetic_energy(ladder, terms, q, v, false),
                    terms.links.elastic_energy(ladder, q),
                )
            };
            e.kinetic.push(kinetic);
            e.elastic.push(elastic);
            e.gravitational
                .push(-M * ladder.params.gravity * q.iter().step_by(3).sum::<f64>());
        }
        e
    }

    /// θ_n(t) of block `i` at every sample.
    pub fn theta_series(&self, i: usize) -> Vec<f64> {
        self.states.iter().map(|q| q[itheta(i)]).collect()
    }
}

/// Power dissipated at (q, v) by every dissipative term of `ladder`
/// (linear damping, quadratic drag, pin friction: `media::dissipation`),
/// over every block.
pub fn dissipated_power(ladder: &Ladder, q: &[f64], v: &[f64]) -> f64 {
    let (linear, drag, friction) = media::dissipation(ladder, &ladder.terms, q, v, 0);
    let contact = ladder
        .built
        .map_or(0.0, |b| b.dissipation(ladder.blocks(), q, v));
    linear + drag + friction + contact
}
