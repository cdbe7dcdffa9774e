//! The equations of motion as a right-hand side for the integrators
//! (supplement, "Details of numerical simulation"):
//! m Ẍ = −∂E/∂X − γẊ, I θ̈ = −∂E/∂θ − γ r² θ̇,
//! with block 1 constrained by the
//! protocol.

use super::budget::Quadrature;
use super::protocol::{Drive, Protocol};
use super::taut::{InverseMass, Taut, Unsolved};
use crate::model::Ladder;
use crate::model::ladder::{ForceScratch, Frames, ix, iy};
use crate::model::media::{self, Terms};
use crate::model::outline::Pose;
use crate::model::params::{M, R};
use crate::model::ribbons::{Ribbons, Span};
use crate::model::tangent::Warm;
use crate::model::terms::PinFriction;

/// Positions q and velocities v, both in the model's layout [X, Y, θ per block].
#[derive(Debug, Clone, PartialEq)]
pub struct State {
    pub q: Vec<f64>,
    pub v: Vec<f64>,
}

impl State {
    /// At rest at `q`.
    pub fn at_rest(q: Vec<f64>) -> Self {
        let v = vec![0.0; q.len()];
        Self { q, v }
    }
}

/// Conservative accelerations −M⁻¹∇E and damping rates, with the protocol's
/// constraint on block 1. Owns its scratch buffer: evaluating it never allocates.
pub struct Rhs<'a> {
    pub ladder: &'a Ladder,
    protocol: &'a Protocol,
    /// Where block 1's centre is clamped.
    clamp: [f64; 2],
    /// 1/m or 1/I for a free coordinate, 0 for one the protocol prescribes.
    inv_mass: Vec<f64>,
    /// Damping rate per free coordinate: γ/m for X and Y, γ r²/I for θ;
    /// 0 for a prescribed one.
    pub damping_rate: Vec<f64>,
    grad: Vec<f64>,
    scratch: ForceScratch,
    /// Number of force (gradient) evaluations so far.
    pub force_evals: u64,
    /// The ladder's terms of docs/experiments.md (`model::media`), and
    /// scratch for their generalised forces.
    terms: Terms,
    force: Vec<f64>,
    /// The blocks' frames (t, ν) at the q of the last evaluation that
    /// needed them: one sine and cosine per block for every term.
    frames: Frames,
    /// The deepest overlap of two blocks in contact seen so far, in s
    /// (`model::contact`; 0 without contact).
    pub deepest_overlap: f64,
    /// The toy as built: the blocks' poses at the q of the last
    /// evaluation (from `frames`) and the ribbons' spans found there, one
    /// search for the ribbons' tension and dashpot alike.
    poses: Vec<Pose>,
    spans: Vec<Span>,
    /// Each ribbon's tangent points at the last evaluation, where the
    /// next one's search starts (`model::tangent::warm_tangent`).
    warm: Vec<Warm>,
    /// The rates Ẇ and Ḋ of the energy budget at the last evaluation
    /// (`sim::budget`), where the run keeps them ([`Rhs::keep_powers`]).
    powers: Option<Quadrature>,
    /// Each block's drag force at the last evaluation with drag, made
    /// once for its acceleration and the budget's powers.
    drag: Vec<[f64; 3]>,
    /// Inextensible ribbons' impulses (`sim::taut`), where the ladder has
    /// them.
    pub taut: Option<Taut>,
    /// The blocks' frames and which are free, for the tensions' solve.
    frame_list: Vec<([f64; 2], [f64; 2])>,
    free: Vec<bool>,
    /// The blocks' poses at the end of a step, for Moreau's touch check.
    touch_poses: Vec<Pose>,
}

impl<'a> Rhs<'a> {
    /// `q0` gives the clamp position of block 1's centre.
    pub fn new(ladder: &'a Ladder, protocol: &'a Protocol, q0: &[f64]) -> Self {
        let p = &ladder.params;
        let dof = p.dof();
        let per_block = |x: f64, th: f64| (0..dof).map(move |k| if k % 3 == 2 { th } else { x });
        let driven = matches!(protocol, Protocol::Driven(_));
        let free = |(k, x): (usize, f64)| if driven && k < 3 { 0.0 } else { x };
        Self {
            ladder,
            protocol,
            clamp: [q0[ix(0)], q0[iy(0)]],
            inv_mass: per_block(1.0 / M, 1.0 / p.inertia)
                .enumerate()
                .map(free)
                .collect(),
            damping_rate: per_block(p.gamma / M, p.gamma * R * R / p.inertia)
                .enumerate()
                .map(free)
                .collect(),
            grad: vec![0.0; dof],
            scratch: ForceScratch::new(p.n),
            force_evals: 0,
            terms: ladder.terms,
            force: vec![0.0; dof],
            frames: Frames::new(p.n, q0),
            deepest_overlap: 0.0,
            poses: Vec::new(),
            spans: Vec::new(),
            warm: Vec::new(),
            powers: None,
            drag: Vec::new(),
            taut: (ladder.built.as_ref())
                .filter(|b| b.ribbons.inextensible)
                .map(|_| Taut::default()),
            frame_list: Vec::new(),
            free: Vec::new(),
            touch_poses: Vec::new(),
        }
    }

    /// From now on, every evaluation of the accelerations with the terms
    /// also gives the energy budget's rates Ẇ and Ḋ there
    /// ([`Rhs::powers`], `sim::budget`); the accelerations are the same
    /// bit for bit.
    pub fn keep_powers(&mut self) {
        self.powers = Some(Quadrature::default());
    }

    /// Ẇ and Ḋ at the last evaluation, where kept.
    pub fn powers(&self) -> Option<Quadrature> {
        self.powers
    }

    /// The ladder's terms beyond the paper's model.
    pub fn terms(&self) -> &Terms {
        &self.terms
    }

    /// What happens to block 1.
    pub fn protocol(&self) -> &'a Protocol {
        self.protocol
    }

    pub fn dof(&self) -> usize {
        self.grad.len()
    }

    /// Sets block 1's position and velocity to the protocol's values at `t`.
    #[inline]
    pub fn constrain(&self, t: f64, q: &mut [f64], v: &mut [f64]) {
        if let Some((qp, vp)) = self.prescribed(t) {
            q[..3].copy_from_slice(&qp);
            v[..3].copy_from_slice(&vp);
        }
    }

    /// Block 1's prescribed (X, Y, θ) and their rates at `t`, if driven:
    /// the centre clamped, the angle from the drive.
    #[inline]
    pub fn prescribed(&self, t: f64) -> Option<([f64; 3], [f64; 3])> {
        self.protocol.drive().map(|d| {
            (
                [self.clamp[0], self.clamp[1], d.theta(t)],
                [0.0, 0.0, d.omega(t)],
            )
        })
    }

    /// Block 1's drive and where its centre is clamped, if driven.
    pub fn drive(&self) -> Option<(&'a Drive, [f64; 2])> {
        self.protocol.drive().map(|d| (d, self.clamp))
    }

    /// M⁻¹ per coordinate: 1/m or 1/I, 0 for a prescribed one.
    pub fn inv_mass(&self) -> &[f64] {
        &self.inv_mass
    }

    /// Counts `n` force evaluations made outside [`Rhs::gradient`] (by a
    /// fused stepper).
    pub fn count_evals(&mut self, n: u64) {
        self.force_evals += n;
    }

    /// Conservative acceleration −M⁻¹ ∂E/∂q at `q` (already constrained);
    /// zero for prescribed coordinates.
    #[inline]
    pub fn conservative(&mut self, q: &[f64], acc: &mut [f64]) {
        self.gradient(q);
        for ((a, g), im) in acc.iter_mut().zip(&self.grad).zip(&self.inv_mass) {
            *a = -g * im;
        }
    }

    /// ∂E/∂q at `q` (already constrained), with M⁻¹ for free coordinates
    /// (zero for prescribed ones): the pieces of a fused update.
    #[inline]
    pub fn gradient(&mut self, q: &[f64]) -> (&[f64], &[f64]) {
        self.force_evals += 1;
        if self.terms.links.is_paper() && self.ladder.built.is_none() {
            self.ladder
                .gradient_with(q, &mut self.grad, &mut self.scratch);
        } else {
            self.terms_gradient(q, false);
        }
        (&self.grad, &self.inv_mass)
    }

    /// ∂E/∂q of the links beyond the paper's springs (or the ribbons) and
    /// gravity into `grad`; `framed`: `frames` already hold the blocks'
    /// frames at `q`. Kept out of line, so that the paper's path above
    /// stays small enough to inline into the integrators' loops.
    #[inline(never)]
    fn terms_gradient(&mut self, q: &[f64], framed: bool) {
        let ladder = self.ladder;
        if ladder.built.is_some() {
            self.terms.links.gradient(ladder, q, &mut self.grad);
        } else {
            if !framed {
                self.frames.at(ladder.n(), q);
            }
            let links = self.terms.links;
            links.gradient_framed(ladder, &self.frames, q, &mut self.grad);
        }
    }

    /// The toy as built at `q` (`frames` already there): the blocks'
    /// poses, the ribbons' spans (found once for the evaluation) and from
    /// them the ribbons' and gravity's gradient, the same numbers, bit
    /// for bit, as [`Links::gradient`](crate::model::terms::Links::gradient).
    fn built_gradient(&mut self, ribbons: &Ribbons, q: &[f64]) {
        self.poses.clear();
        for i in 0..self.ladder.n() {
            let (t, nu) = self.frames.get(i);
            let centre = [q[ix(i)], q[iy(i)]];
            self.poses.push(Pose { centre, t, nu });
        }
        ribbons.find_spans(&self.poses, &mut self.spans, &mut self.warm);
        let g = self.ladder.params.gravity;
        ribbons.gradient_of(g, &self.poses, &self.spans, &mut self.grad);
    }

    /// Full acceleration including damping, −M⁻¹(∂E/∂q + Γ v).
    #[inline]
    pub fn acceleration(&mut self, q: &[f64], v: &[f64], acc: &mut [f64]) {
        if self.ladder.velocity_dependent() {
            return self.acceleration_with_terms(q, v, acc);
        }
        self.conservative(q, acc);
        for k in 0..acc.len() {
            acc[k] -= self.damping_rate[k] * v[k];
        }
    }

    /// The accelerations with added mass, drag and pin friction
    /// (`model::media`): the generalised forces (links, gravity, linear
    /// damping, pin friction, drag) through Lagrange's equations of each
    /// free block, with its velocity terms and M⁻¹ in closed form. Where
    /// the run keeps its budget, Ẇ and Ḋ from the same forces
    /// ([`Rhs::stage_powers`]).
    fn acceleration_with_terms(&mut self, q: &[f64], v: &[f64], acc: &mut [f64]) {
        let ladder = self.ladder;
        self.frames.at(ladder.n(), q);
        self.force_evals += 1;
        // By reference: the apparatus, with its ribbons' ways round, is
        // 3.7 kB, and a copy of it each evaluation showed in the profile.
        if let Some(b) = &ladder.built {
            self.built_gradient(&b.ribbons, q);
        } else if self.terms.links.is_paper() {
            ladder.gradient_with(q, &mut self.grad, &mut self.scratch);
        } else {
            self.terms_gradient(q, true);
        }
        let t = self.terms;
        let gamma = ladder.params.gamma;
        self.force.resize(self.grad.len(), 0.0);
        for (k, (f, g)) in self.force.iter_mut().zip(&self.grad).enumerate() {
            let rate = if k % 3 == 2 { gamma * R * R } else { gamma };
            *f = -g - rate * v[k];
        }
        // The power the dashpots, contacts and pin friction dissipate.
        let mut lost = 0.0;
        if let Some(friction) = t.friction {
            lost = self.add_friction(&friction, q, v);
        }
        if let Some(b) = &ladder.built {
            lost += b
                .ribbons
                .add_damping_of(&self.poses, &self.spans, v, &mut self.force);
        }
        if let Some(b) = &ladder.built
            && let Some(c) = &b.contact
        {
            let o = b.ribbons.outline;
            let (deepest, d) =
                c.add_forces_posed(ladder.blocks(), &o, &self.poses, v, &mut self.force);
            self.deepest_overlap = self.deepest_overlap.max(deepest);
            lost += d;
        }
        let j = ladder.params.inertia + t.added_inertia;
        let keep = self.powers.is_some();
        self.drag.resize(ladder.n(), [0.0; 3]);
        for i in 0..ladder.n() {
            let k = 3 * i;
            let free = self.inv_mass[k] != 0.0;
            let vi = [v[k], v[k + 1], v[k + 2]];
            let frame = self.frames.get(i);
            // The budget's powers read every block's drag, the prescribed
            // block's too.
            if t.drag != 0.0 && (free || keep) {
                self.drag[i] = media::drag_force_framed(t.drag, frame.1, vi);
            }
            if !free {
                acc[k..k + 3].fill(0.0);
                continue;
            }
            let mut qi = [self.force[k], self.force[k + 1], self.force[k + 2]];
            if t.drag != 0.0 {
                for (a, b) in qi.iter_mut().zip(self.drag[i]) {
                    *a += b;
                }
            }
            let a = media::block_acceleration_framed(t.added_mass, j, frame, vi, qi);
            acc[k..k + 3].copy_from_slice(&a);
        }
        if self.powers.is_some() {
            self.stage_powers(v, lost);
        }
    }

    /// Moreau's projection and impulses (`sim::taut`) over a step `h`,
    /// with the last evaluation's poses and spans (the midpoint's): the
    /// midpoint `qm` moved back onto the stretched ribbons' lengths, the
    /// impulses into `v`; why not where the ribbons' problem could not be
    /// solved.
    pub fn taut_impulses(&mut self, h: f64, qm: &mut [f64], v: &mut [f64]) -> Result<(), Unsolved> {
        let Some(b) = &self.ladder.built else {
            return Ok(());
        };
        let n = self.ladder.n();
        self.frame_list.clear();
        self.frame_list.extend((0..n).map(|i| self.frames.get(i)));
        self.free.clear();
        self.free
            .extend((0..n).map(|i| self.inv_mass[3 * i] != 0.0));
        let inv = InverseMass {
            added_mass: self.terms.added_mass,
            inertia: self.ladder.params.inertia + self.terms.added_inertia,
            frames: &self.frame_list,
            free: &self.free,
        };
        let rests = b.ribbons.ribbons.map(|r| r.rest);
        let Some(taut) = self.taut.as_mut() else {
            return Ok(());
        };
        taut.impulses((&self.poses[..], &self.spans[..]), rests, &inv, h, qm, v)
    }

    /// Whether the last step's projection moved any position.
    pub fn taut_projected(&self) -> bool {
        self.taut.as_ref().is_some_and(|t| t.projected)
    }

    /// Gravity's potential energy at `q` (`model::media::gravity_energy`):
    /// a run by Moreau has no other (its ribbons are inextensible, and a
    /// touch between blocks stops it).
    pub fn gravity_energy(&self, q: &[f64]) -> f64 {
        media::gravity_energy(self.ladder, q)
    }

    /// The last step's ribbon impulses' (work through block 1, loss)
    /// between the velocities `v0` before the step and `v1` after it
    /// (`Taut::energy`).
    pub fn taut_energy(&self, v0: &[f64], v1: &[f64]) -> (f64, f64) {
        let driven = self.inv_mass[2] == 0.0;
        self.taut
            .as_ref()
            .map_or((0.0, 0.0), |t| t.energy(v0, v1, driven))
    }

    /// The first pair of blocks (upper, lower; 0-based) in contact at
    /// (q, v), where the ladder as built has contact.
    pub fn first_touch(&mut self, q: &[f64], v: &[f64]) -> Option<(usize, usize)> {
        let b = self.ladder.built.as_ref()?;
        let c = b.contact.as_ref()?;
        // The poses at q in scratch kept for it (`poses` holds the last
        // evaluation's, the midpoint's).
        self.touch_poses.clear();
        self.touch_poses
            .extend((0..self.ladder.n()).map(|i| Pose::of(q, i)));
        let mut first = None;
        let (blocks, outline) = (self.ladder.blocks(), &b.ribbons.outline);
        c.for_each_touch_posed(blocks, outline, &self.touch_poses, v, |t| {
            first.get_or_insert((t.a.min(t.b), t.a.max(t.b)));
        });
        first
    }

    /// Pin friction's forces at (q, v) added to `force`; where the run
    /// keeps its budget, returns the power they take (else 0).
    fn add_friction(&mut self, friction: &PinFriction, q: &[f64], v: &[f64]) -> f64 {
        let keep = self.powers.is_some();
        let before = if keep { dot(&self.force, v) } else { 0.0 };
        let links = &self.terms.links;
        friction.add_forces(self.ladder, links, &self.frames, (q, v), &mut self.force);
        if keep {
            before - dot(&self.force, v)
        } else {
            0.0
        }
    }

    /// The energy budget's rates at this evaluation (`sim::budget`) from
    /// its generalised forces before drag (`force`), `lost` the power the
    /// dashpots, contacts and pin friction dissipate: Ẇ = −θ̇₁ Q_θ₁
    /// (block 1's centre is clamped; Q with its drag), Ḋ = `lost` plus
    /// linear damping's and drag's power over every block (the drag
    /// forces `drag` the accelerations were made of).
    #[inline(never)]
    fn stage_powers(&mut self, v: &[f64], lost: f64) {
        let t = self.terms;
        let gamma = self.ladder.params.gamma;
        let mut dissipated = lost;
        for (k, w) in v.iter().enumerate() {
            let rate = if k % 3 == 2 { gamma * R * R } else { gamma };
            dissipated += rate * w * w;
        }
        let mut work = 0.0;
        for i in 0..self.ladder.n() {
            let k = 3 * i;
            let vi = [v[k], v[k + 1], v[k + 2]];
            let mut qi = [self.force[k], self.force[k + 1], self.force[k + 2]];
            if t.drag != 0.0 {
                // The drag force the acceleration took, made once.
                let d = self.drag[i];
                dissipated -= dot(&vi, &d);
                for (a, b) in qi.iter_mut().zip(d) {
                    *a += b;
                }
            }
            if self.inv_mass[k] == 0.0 {
                work -= dot(&vi, &qi);
            }
        }
        self.powers = Some(Quadrature {
            work,
            dissipated,
            projected: None,
        });
    }

    /// Mechanical energy: kinetic plus potential (with the terms'
    /// kinetic and elastic energies where the ladder has them).
    pub fn mechanical_energy(&self, s: &State) -> f64 {
        if self.ladder.is_paper_model() {
            return self.ladder.kinetic_energy(&s.v) + self.ladder.energy(&s.q);
        }
        media::kinetic_energy(self.ladder, &self.terms, &s.q, &s.v, false)
            + media::potential_energy(self.ladder, &self.terms, &s.q)
    }
}

/// Σ a_k b_k, in order of k.
fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Params;
    use crate::model::ladder::{frame, itheta, parity};
    use crate::model::terms::{Links, PinFriction};

    /// Adds f at the ±-node of block `i`, its normal from `frame`.
    fn node_force(out: &mut [f64], q: &[f64], i: usize, sign: f64, f: [f64; 2]) {
        let (_, nu) = frame(i, q[itheta(i)]);
        out[ix(i)] += f[0];
        out[iy(i)] += f[1];
        out[itheta(i)] += sign * R * (f[0] * nu[0] + f[1] * nu[1]);
    }

    /// Pin friction as it was computed before `Frames`: link by link, every
    /// frame from `frame(i, θ_i)` where it is used.
    fn friction_reference(ladder: &Ladder, f: &PinFriction, q: &[f64], v: &[f64], out: &mut [f64]) {
        for s in ladder.terms.links.states(ladder, q) {
            if s.tension == 0.0 || f.mu_rp == 0.0 {
                continue;
            }
            let node_velocity = |i: usize| {
                let (_, nu) = frame(i, q[itheta(i)]);
                let w = v[itheta(i)];
                [
                    v[ix(i)] + s.sign * R * w * nu[0],
                    v[iy(i)] + s.sign * R * w * nu[1],
                ]
            };
            let (u0, u1) = (node_velocity(s.upper), node_velocity(s.upper + 1));
            let dd = [u1[0] - u0[0], u1[1] - u0[1]];
            let phi_dot = (s.d[0] * dd[1] - s.d[1] * dd[0]) / (s.length * s.length);
            let limit = f.mu_rp * s.tension.abs();
            let torque = |i: usize| {
                let omega = -parity(i) * v[itheta(i)] - phi_dot;
                -limit * crate::model::links::smooth_sign(omega / f.omega_eps)
            };
            let (p0, p1) = (torque(s.upper), torque(s.upper + 1));
            out[itheta(s.upper)] += -parity(s.upper) * p0;
            out[itheta(s.upper + 1)] += -parity(s.upper + 1) * p1;
            let g = (p0 + p1) / s.length;
            let n = [-s.d[1] / s.length, s.d[0] / s.length];
            node_force(out, q, s.upper + 1, s.sign, [-g * n[0], -g * n[1]]);
            node_force(out, q, s.upper, s.sign, [g * n[0], g * n[1]]);
        }
    }

    /// The accelerations with the terms as computed before `Frames`.
    fn reference(ladder: &Ladder, q: &[f64], v: &[f64]) -> Vec<f64> {
        let t = ladder.terms;
        let mut grad = vec![0.0; q.len()];
        if t.links.is_paper() {
            ladder.gradient(q, &mut grad);
        } else {
            let g = M * ladder.params.gravity;
            for (k, x) in grad.iter_mut().enumerate() {
                *x = if k % 3 == 0 { -g } else { 0.0 };
            }
            for s in t.links.states(ladder, q).filter(|s| s.tension != 0.0) {
                let f = [s.tension * s.d[0] / s.length, s.tension * s.d[1] / s.length];
                node_force(&mut grad, q, s.upper + 1, s.sign, f);
                node_force(&mut grad, q, s.upper, s.sign, [-f[0], -f[1]]);
            }
        }
        let gamma = ladder.params.gamma;
        let mut force: Vec<f64> = (0..q.len())
            .map(|k| -grad[k] - if k % 3 == 2 { gamma * R * R } else { gamma } * v[k])
            .collect();
        if let Some(f) = t.friction {
            friction_reference(ladder, &f, q, v, &mut force);
        }
        let j = ladder.params.inertia + t.added_inertia;
        let mut acc = vec![0.0; q.len()];
        for i in 0..ladder.n() {
            let k = 3 * i;
            let vi = [v[k], v[k + 1], v[k + 2]];
            let mut qi = [force[k], force[k + 1], force[k + 2]];
            let d = media::drag_force(t.drag, i, q[itheta(i)], vi);
            for (a, b) in qi.iter_mut().zip(d) {
                *a += b;
            }
            let a = media::block_acceleration(t.added_mass, j, i, q[itheta(i)], vi, qi);
            acc[k..k + 3].copy_from_slice(&a);
        }
        acc
    }

    /// The accelerations from each block's frame computed once are the
    /// ones computed frame by frame where used, bit for bit: stiff and
    /// tension-only links (some slack), the paper's springs, pin friction
    /// with pins both below and beyond |ω/ω_ε| = 22 (`smooth_sign`), added
    /// mass, drag; every block free.
    #[test]
    fn terms_from_frames_are_the_frame_by_frame_terms_bit_for_bit() {
        let links = [
            Links::default(),
            Links {
                stiffness: 30.0,
                tension_only: true,
            },
        ];
        for (case, links) in links.into_iter().enumerate() {
            let terms = Terms {
                added_mass: 6.3,
                added_inertia: 0.2,
                drag: 8.1,
                links,
                friction: Some(PinFriction {
                    mu_rp: 0.05,
                    omega_eps: 0.01,
                }),
            };
            let mut params = Params::paper(69.0).unwrap();
            params.gamma = 0.003;
            let ladder = Ladder::new(params).with_terms(terms);
            let mut q = ladder.ground_state();
            for (k, x) in q.iter_mut().enumerate() {
                *x += 0.04 * ((k as f64) * 1.7).sin();
            }
            let v: Vec<f64> = (0..q.len())
                .map(|k| 0.3 * ((k as f64) * 1.3).sin() * 0.5f64.powi(k as i32 % 7))
                .collect();
            let protocol = Protocol::Free;
            let mut rhs = Rhs::new(&ladder, &protocol, &q);
            let mut acc = vec![0.0; q.len()];
            rhs.acceleration(&q, &v, &mut acc);
            let want = reference(&ladder, &q, &v);
            for (k, (a, b)) in acc.iter().zip(&want).enumerate() {
                assert_eq!(
                    a.to_bits(),
                    b.to_bits(),
                    "case {case}, coordinate {k}: {a} {b}"
                );
            }
            // A second evaluation at another state reuses the buffers.
            let q2: Vec<f64> = q.iter().map(|x| x * 1.01).collect();
            rhs.acceleration(&q2, &v, &mut acc);
            assert_eq!(acc, reference(&ladder, &q2, &v), "case {case}");
        }
    }
}
