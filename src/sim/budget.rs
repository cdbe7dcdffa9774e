//! The energy budget of a run (docs/experiments.md, "The energy budget
//! of the toy as built"): the work W done on the free blocks through
//! block 1 and the energy D the dissipative terms took, accumulated
//! inside the integrator, so that the change of energy closes as
//! ΔE = W − D to the integrator's accuracy.
//!
//! E is the free blocks' kinetic energy (with added mass) plus the
//! potential energy of every block (the links' or ribbons' and the
//! contacts' overlaps, gravity). Block 1 is driven: its motion is given,
//! so the motor does whatever work its own inertia asks, and what it
//! passes on to the rest is W, at the rate Ẇ = θ̇₁ (∂U/∂θ₁ − Q₁), Q₁
//! every non-conservative generalised force on θ₁ (the ribbons' dashpots
//! and the contacts on block 1, its damping and drag). D grows at the
//! rate Ḋ ≥ 0 that every dissipative term dissipates, over every block:
//! linear damping, drag, pin friction, the ribbons' dashpots, the
//! contacts' dashpots and friction.
//!
//! Ẇ and Ḋ are evaluated at every stage of the step, where the forces
//! are (`Rhs`: the same forces the state's rates are made of, so the
//! trajectory is the same bit for bit with the budget or without), and
//! summed with the scheme's weights: W and D are two more components of
//! the integrated state, y' = (v, a, Ẇ, Ḋ). Sampling the powers between
//! steps and integrating them afterwards misses what happens within a
//! step (a ribbon going taut, a corner landing).

use super::protocol::Protocol;
use crate::model::Ladder;
use crate::model::media;
use serde::Serialize;

/// The work done on the free blocks through block 1 and the energy
/// dissipated (or their rates Ẇ and Ḋ at one stage), in k s² (per τ).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Quadrature {
    pub work: f64,
    pub dissipated: f64,
    /// The potential energy a position projection put in (Moreau's,
    /// `integrators::moreau`): part of the scheme's error, `None` for a
    /// scheme without one.
    pub projected: Option<f64>,
}

impl Quadrature {
    /// Adds to `total` (from 0 where `None`) `h` Σ w_j p_j over the
    /// stages' rates `p` with weights `w` (the scheme's b), summed in
    /// order of j.
    pub fn step(total: &mut Option<Self>, h: f64, w: &[f64], p: &[Quadrature]) {
        let (mut dw, mut dd) = (0.0, 0.0);
        for (wj, pj) in w.iter().zip(p) {
            dw += wj * pj.work;
            dd += wj * pj.dissipated;
        }
        let t = total.unwrap_or_default();
        *total = Some(Self {
            work: t.work + h * dw,
            dissipated: t.dissipated + h * dd,
            ..t
        });
    }
}

/// A run's energy budget, in k s²: W, D and ΔE from its start to its end.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Budget {
    /// W: the work done on the free blocks through block 1.
    pub work: f64,
    /// D: the energy the dissipative terms took.
    pub dissipated: f64,
    /// ΔE: the change of the free blocks' kinetic and every block's
    /// potential energy.
    pub energy_change: f64,
    /// ΔE − (W − D): zero but for the integrator's error.
    pub residual: f64,
    /// The part of ΔE (and so of the residual) Moreau's projection put
    /// in: the potential energy of the positions it moved back onto the
    /// ribbons' lengths. Absent for every other integrator.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub projected: Option<f64>,
}

impl Budget {
    /// The budget of W and D accumulated by the integrator and the
    /// change `energy_change` of E.
    pub fn new(q: Quadrature, energy_change: f64) -> Self {
        Self {
            work: q.work,
            dissipated: q.dissipated,
            energy_change,
            residual: energy_change - (q.work - q.dissipated),
            projected: q.projected,
        }
    }
}

/// E at (q, v): the free blocks' kinetic energy (block 1 left out
/// where `protocol` drives it) plus the potential energy.
pub fn energy(ladder: &Ladder, protocol: &Protocol, (q, v): (&[f64], &[f64])) -> f64 {
    let driven = protocol.drive().is_some();
    let terms = &ladder.terms;
    media::kinetic_energy(ladder, terms, q, v, driven) + media::potential_energy(ladder, terms, q)
}

/// Whether a run of `ladder` keeps its budget: as `asked`, by default
/// for the toy as built (whose ribbons' search makes the stage powers'
/// cost small), and only where the forces depend on the velocities (the
/// path that evaluates every term at once, `Rhs::acceleration`).
pub fn kept(ladder: &Ladder, asked: Option<bool>) -> bool {
    asked.unwrap_or(ladder.built.is_some()) && ladder.velocity_dependent()
}
