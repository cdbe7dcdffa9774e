//! Samples taken between steps (`RunOptions::samples_between_steps`): the
//! integrator steps on a grid that does not depend on the sample times
//! (only the drive's corners and t_end cut it), and each sample is the
//! cubic Hermite interpolant of the two states around it. Where blocks
//! touch, the clatter is chaotic: a step landing on a frame's time would
//! change the cascade with the number of frames (docs/experiments.md,
//! "The toy in air").
//!
//! On a step from (t₀, q₀, v₀) to (t₁, q₁, v₁), h = t₁ − t₀, s = (t − t₀)/h:
//!
//! q(t) = h₀₀(s) q₀ + h h₁₀(s) v₀ + h₀₁(s) q₁ + h h₁₁(s) v₁,
//!
//! with h₀₀ = 2s³ − 3s² + 1, h₁₀ = s³ − 2s² + s, h₀₁ = −2s³ + 3s²,
//! h₁₁ = s³ − s², and v(t) its derivative: q to fourth order in h, v to
//! third, from the states alone (no force evaluated, so the run's force
//! count and its trajectory are those of a run without samples). Block 1
//! is then put where the drive prescribes it at t.

use super::rhs::{Rhs, State};
use super::{RunOptions, Sample, Scenario};
use crate::error::Result;

/// Whether a run takes its samples between steps rather than landing a
/// step on each: as `options` say, else where blocks may touch (contact).
pub(super) fn wanted(scenario: &Scenario, options: &RunOptions) -> bool {
    let contact = || (scenario.ladder.built.as_ref()).is_some_and(|b| b.contact.is_some());
    options.samples_between_steps.unwrap_or_else(contact)
}

/// The start of the step under way and scratch for one sample.
pub(super) struct Between {
    t0: f64,
    q0: Vec<f64>,
    v0: Vec<f64>,
    dissipated0: Option<f64>,
    q: Vec<f64>,
    v: Vec<f64>,
}

impl Between {
    /// For a run from `st` at t = 0.
    pub(super) fn new(st: &State) -> Self {
        Self {
            t0: 0.0,
            q0: st.q.clone(),
            v0: st.v.clone(),
            dissipated0: None,
            q: st.q.clone(),
            v: st.v.clone(),
        }
    }

    /// Remembers the state at `t` where a step starts.
    pub(super) fn start(&mut self, t: f64, st: &State, dissipated: Option<f64>) {
        self.t0 = t;
        self.q0.copy_from_slice(&st.q);
        self.v0.copy_from_slice(&st.v);
        self.dissipated0 = dissipated;
    }

    /// Hands `sink` every sample after the step's start and not after
    /// `t1`, where the step ended at `st` (the energy dissipated by then
    /// `dissipated`, interpolated linearly).
    pub(super) fn emit(
        &mut self,
        (samples, next): (&[f64], &mut usize),
        (t1, st, dissipated): (f64, &State, Option<f64>),
        rhs: &Rhs,
        sink: &mut dyn FnMut(&Sample) -> Result<()>,
    ) -> Result<()> {
        while *next < samples.len() && samples[*next] <= t1 {
            let t = samples[*next];
            let at_end = t == t1 || t1 <= self.t0;
            let s = if at_end {
                1.0
            } else {
                (t - self.t0) / (t1 - self.t0)
            };
            if at_end {
                self.q.copy_from_slice(&st.q);
                self.v.copy_from_slice(&st.v);
            } else {
                self.interpolate(s, t1 - self.t0, st);
                rhs.constrain(t, &mut self.q, &mut self.v);
            }
            let dissipated = match (self.dissipated0, dissipated) {
                (Some(d0), Some(d1)) => Some(d0 + s * (d1 - d0)),
                _ => dissipated,
            };
            sink(&Sample {
                t,
                q: &self.q,
                v: &self.v,
                dissipated,
            })?;
            *next += 1;
        }
        Ok(())
    }

    /// The cubic Hermite interpolant at fraction `s` of a step of length
    /// `h` that ended at `st`, into the scratch state.
    fn interpolate(&mut self, s: f64, h: f64, st: &State) {
        let (s2, s3) = (s * s, s * s * s);
        let (h00, h10) = (2.0 * s3 - 3.0 * s2 + 1.0, s3 - 2.0 * s2 + s);
        let (h01, h11) = (-2.0 * s3 + 3.0 * s2, s3 - s2);
        // Their derivatives in s.
        let (d00, d10) = (6.0 * s2 - 6.0 * s, 3.0 * s2 - 4.0 * s + 1.0);
        let (d01, d11) = (-6.0 * s2 + 6.0 * s, 3.0 * s2 - 2.0 * s);
        for k in 0..self.q.len() {
            let (q0, v0, q1, v1) = (self.q0[k], self.v0[k], st.q[k], st.v[k]);
            self.q[k] = h00 * q0 + h * h10 * v0 + h01 * q1 + h * h11 * v1;
            self.v[k] = (d00 * q0 + d01 * q1) / h + d10 * v0 + d11 * v1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_interpolant_is_exact_for_a_cubic_and_its_derivative() {
        // q(t) = 1 + 2t − t² + 0.5t³ on a step from 0.3 to 0.8: the
        // Hermite cubic through its ends is the cubic itself.
        let q = |t: f64| 1.0 + 2.0 * t - t * t + 0.5 * t * t * t;
        let v = |t: f64| 2.0 - 2.0 * t + 1.5 * t * t;
        let start = State {
            q: vec![q(0.3)],
            v: vec![v(0.3)],
        };
        let end = State {
            q: vec![q(0.8)],
            v: vec![v(0.8)],
        };
        let mut b = Between::new(&start);
        b.start(0.3, &start, None);
        for s in [0.0, 0.25, 0.5, 0.9, 1.0] {
            b.interpolate(s, 0.5, &end);
            let t = 0.3 + 0.5 * s;
            assert!((b.q[0] - q(t)).abs() < 1e-14, "q at {t}: {}", b.q[0]);
            assert!((b.v[0] - v(t)).abs() < 1e-13, "v at {t}: {}", b.v[0]);
        }
    }
}
