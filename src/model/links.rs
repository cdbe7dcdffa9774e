//! The links between the blocks beyond the paper's two-way springs of unit
//! stiffness (docs/experiments.md): a stiffness κ (in the model's unit k),
//! tension-only links (tape, ribbon: energy ½ κ max(0, L − ℓ)²), and
//! Coulomb friction at the pins of a printed linkage.
//!
//! The link σ ∈ {A, B} between blocks n and n + 1 joins their σ-nodes
//! p = X ± r t (A: −, B: +); d = p_{n+1} − p_n, L = |d|, its tension
//! T = κ (L − ℓ_σ) (zero where a tension-only link is slack, L < ℓ_σ).
//!
//! # Pin friction
//!
//! A block turns at the geometric rate Ω_n = −(−1)ⁿ θ̇_n (t_n turns
//! clockwise as θ_n grows when n is even), a link at φ̇ = (d × ḋ)/L². At
//! each of a link's two pins a Coulomb torque
//! τ = −μ_p r_p |T| tanh((Ω − φ̇)/ω_ε) acts on the block (generalised
//! force −(−1)ⁿ τ on θ_n). The massless link takes the opposite torques
//! and balances them by forces ±(τ₁ + τ₂)/L normal to it at its ends: the
//! block at the lower end is pushed by −F n̂, the one at the upper end by
//! +F n̂, with n̂ = ẑ × d/L and F = (τ₁ + τ₂)/L. The friction's power is
//! then Σ τ (Ω − φ̇) = −Σ μ_p r_p |T| tanh(ω/ω_ε) ω ≤ 0.

use super::ladder::{Frames, Ladder, frame, itheta, ix, iy, parity};
use super::params::{M, R};
pub use super::terms::{Links, PinFriction};

/// One link at a state: its nodes, direction and tension.
#[derive(Debug, Clone, Copy)]
pub struct LinkState {
    /// Upper block (zero-based), the lower one is `upper + 1`.
    pub upper: usize,
    /// −1 for an A link, +1 for a B link (the node offset ±r t).
    pub sign: f64,
    /// d = p_lower − p_upper and L = |d|.
    pub d: [f64; 2],
    pub length: f64,
    /// Tension T = κ (L − ℓ) (0 for a slack tension-only link).
    pub tension: f64,
}

impl Links {
    /// Whether these are the paper's springs.
    pub fn is_paper(&self) -> bool {
        *self == Self::default()
    }

    /// Tension of a link of rest length `rest` at length `length`.
    #[inline]
    pub fn tension(&self, length: f64, rest: f64) -> f64 {
        let stretch = length - rest;
        if self.tension_only && stretch < 0.0 {
            0.0
        } else {
            self.stiffness * stretch
        }
    }

    /// Every link at `q`: A_1, B_1, A_2, B_2, ...
    pub fn states<'q>(
        &self,
        ladder: &'q Ladder,
        q: &'q [f64],
    ) -> impl Iterator<Item = LinkState> + 'q {
        let links = *self;
        (0..ladder.n() - 1).flat_map(move |i| {
            [-1.0, 1.0].map(move |sign| {
                let (t0, _) = frame(i, q[itheta(i)]);
                let (t1, _) = frame(i + 1, q[itheta(i + 1)]);
                links.state(ladder, q, i, sign, [t0, t1])
            })
        })
    }

    /// The link of sign `sign` (−1: A, +1: B) below block `i`, the blocks'
    /// directions t_i and t_{i+1} given.
    #[inline(always)]
    fn state(
        &self,
        ladder: &Ladder,
        q: &[f64],
        i: usize,
        sign: f64,
        t: [[f64; 2]; 2],
    ) -> LinkState {
        let [t0, t1] = t;
        let dx = (q[ix(i + 1)] + sign * R * t1[0]) - (q[ix(i)] + sign * R * t0[0]);
        let dy = (q[iy(i + 1)] + sign * R * t1[1]) - (q[iy(i)] + sign * R * t0[1]);
        let length = (dx * dx + dy * dy).sqrt();
        let rest = if sign < 0.0 {
            ladder.a
        } else {
            ladder.params.b
        };
        LinkState {
            upper: i,
            sign,
            d: [dx, dy],
            length,
            tension: self.tension(length, rest),
        }
    }

    /// Elastic energy Σ ½ κ (L − ℓ)², the slack tension-only links left out.
    pub fn elastic_energy(&self, ladder: &Ladder, q: &[f64]) -> f64 {
        if let Some(b) = &ladder.built {
            return b.elastic_energy(ladder.blocks(), q);
        }
        self.states(ladder, q)
            .map(|s| 0.5 * s.tension * s.tension / self.stiffness)
            .sum()
    }

    /// ∂E/∂q of the links' energy and of gravity (−m G per X_n) written
    /// into `grad`: ∂E/∂d = T d/L, the node moving with X and turning
    /// with ∂p/∂θ = ±r ν.
    /// A ladder as built (`built`) has ribbons in place of the links.
    pub fn gradient(&self, ladder: &Ladder, q: &[f64], grad: &mut [f64]) {
        if let Some(b) = &ladder.built {
            return b
                .ribbons
                .gradient(ladder.n(), ladder.params.gravity, q, grad);
        }
        self.gradient_framed(ladder, &Frames::new(ladder.n(), q), q, grad);
    }

    /// [`Links::gradient`] of a ladder without ribbons, the blocks' frames
    /// at `q` given (the same numbers, bit for bit).
    pub fn gradient_framed(&self, ladder: &Ladder, frames: &Frames, q: &[f64], grad: &mut [f64]) {
        let g = M * ladder.params.gravity;
        for (k, x) in grad.iter_mut().enumerate().take(3 * ladder.n()) {
            *x = if k % 3 == 0 { -g } else { 0.0 };
        }
        for i in 0..ladder.n() - 1 {
            let ((t0, nu0), (t1, nu1)) = (frames.get(i), frames.get(i + 1));
            for sign in [-1.0, 1.0] {
                let s = self.state(ladder, q, i, sign, [t0, t1]);
                if s.tension == 0.0 {
                    continue;
                }
                let f = [s.tension * s.d[0] / s.length, s.tension * s.d[1] / s.length];
                add_node_force(grad, nu1, i + 1, sign, [f[0], f[1]]);
                add_node_force(grad, nu0, i, sign, [-f[0], -f[1]]);
            }
        }
    }
}

/// Adds the generalised force of a force `f` at the ±-node of block `i`
/// (sign −1: A, +1: B; `nu` its normal ν) to `out`: f on (X, Y),
/// f·(±r ν) on θ.
#[inline(always)]
fn add_node_force(out: &mut [f64], nu: [f64; 2], i: usize, sign: f64, f: [f64; 2]) {
    out[ix(i)] += f[0];
    out[iy(i)] += f[1];
    out[itheta(i)] += sign * R * (f[0] * nu[0] + f[1] * nu[1]);
}

/// A pin's relative turning rate and the torque on its block.
struct Pin {
    /// Ω − φ̇.
    omega: f64,
    /// τ on the block (geometric, counter-clockwise positive).
    torque: f64,
}

/// Coulomb's law smoothed, tanh(x): `model::trig::tanh` (within 3 ulp of
/// the C library's, and branch-free, so that the fused path's loop over
/// the links stays in registers) on x clamped to ±22, where tanh rounds
/// to ±1 (1 − tanh 22 < 2⁻⁶³). NaN stays NaN.
#[inline(always)]
pub fn smooth_sign(x: f64) -> f64 {
    super::trig::tanh(x.clamp(-22.0, 22.0))
}

impl PinFriction {
    /// The two pins of link `s`: (upper, lower), `nu` the normals ν of
    /// its upper and lower block.
    #[inline(always)]
    fn pins(&self, s: &LinkState, nu: [[f64; 2]; 2], v: &[f64]) -> (Pin, Pin) {
        let node_velocity = |i: usize| {
            let nu = nu[i - s.upper];
            let w = v[itheta(i)];
            [
                v[ix(i)] + s.sign * R * w * nu[0],
                v[iy(i)] + s.sign * R * w * nu[1],
            ]
        };
        let (u0, u1) = (node_velocity(s.upper), node_velocity(s.upper + 1));
        let dd = [u1[0] - u0[0], u1[1] - u0[1]];
        let phi_dot = (s.d[0] * dd[1] - s.d[1] * dd[0]) / (s.length * s.length);
        let limit = self.mu_rp * s.tension.abs();
        let pin = |i: usize| {
            let omega = -parity(i) * v[itheta(i)] - phi_dot;
            Pin {
                omega,
                torque: -limit * smooth_sign(omega / self.omega_eps),
            }
        };
        (pin(s.upper), pin(s.upper + 1))
    }

    /// Adds the friction's generalised forces at (q, v) to `out`: the
    /// torques on the blocks and the link's balancing forces; `frames`
    /// the blocks' frames at `q` (`Frames::at`).
    pub fn add_forces(
        &self,
        ladder: &Ladder,
        links: &Links,
        frames: &Frames,
        (q, v): (&[f64], &[f64]),
        out: &mut [f64],
    ) {
        if self.mu_rp == 0.0 {
            return;
        }
        for i in 0..ladder.n() - 1 {
            let ((t0, nu0), (t1, nu1)) = (frames.get(i), frames.get(i + 1));
            for sign in [-1.0, 1.0] {
                let s = links.state(ladder, q, i, sign, [t0, t1]);
                if s.tension == 0.0 {
                    continue;
                }
                let (p0, p1) = self.pins(&s, [nu0, nu1], v);
                out[itheta(i)] += -parity(i) * p0.torque;
                out[itheta(i + 1)] += -parity(i + 1) * p1.torque;
                let f = (p0.torque + p1.torque) / s.length;
                let n = [-s.d[1] / s.length, s.d[0] / s.length];
                add_node_force(out, nu1, i + 1, sign, [-f * n[0], -f * n[1]]);
                add_node_force(out, nu0, i, sign, [f * n[0], f * n[1]]);
            }
        }
    }

    /// The pins of link `s` at (q, v), the blocks' frames from `q`.
    fn pins_at(&self, s: &LinkState, q: &[f64], v: &[f64]) -> (Pin, Pin) {
        let nu = |i: usize| frame(i, q[itheta(i)]).1;
        self.pins(s, [nu(s.upper), nu(s.upper + 1)], v)
    }

    /// The fastest pin, max |Ω − φ̇| over the pins of the links under
    /// tension (a slack link's pins pass no torque), in 1/τ; 0 with none.
    /// Where it stays below a few ω_ε every pin is held in Coulomb's sense
    /// (a held pin of the smoothed law creeps at ω_ε atanh(τ/τ_max)).
    pub fn fastest_pin(&self, ladder: &Ladder, links: &Links, q: &[f64], v: &[f64]) -> f64 {
        links
            .states(ladder, q)
            .filter(|s| s.tension != 0.0)
            .map(|s| {
                let (p0, p1) = self.pins_at(&s, q, v);
                p0.omega.abs().max(p1.omega.abs())
            })
            .fold(0.0, f64::max)
    }

    /// Power dissipated at every pin, Σ μ_p r_p |T| tanh(ω/ω_ε) ω ≥ 0.
    pub fn dissipation(&self, ladder: &Ladder, links: &Links, q: &[f64], v: &[f64]) -> f64 {
        links
            .states(ladder, q)
            .filter(|s| s.tension != 0.0)
            .map(|s| {
                let (p0, p1) = self.pins_at(&s, q, v);
                -(p0.torque * p0.omega + p1.torque * p1.omega)
            })
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Params;

    fn bent(alpha: f64) -> (Ladder, Vec<f64>) {
        let ladder = Ladder::new(Params::paper(alpha).unwrap());
        let mut q = ladder.ground_state();
        for (k, x) in q.iter_mut().enumerate() {
            *x += 0.05 * ((k as f64) * 1.7).sin();
        }
        (ladder, q)
    }

    #[test]
    fn unit_two_way_links_are_the_papers_springs() {
        let (ladder, q) = bent(60.0);
        let (mut a, mut b) = (vec![0.0; q.len()], vec![0.0; q.len()]);
        ladder.gradient(&q, &mut a);
        Links::default().gradient(&ladder, &q, &mut b);
        for (x, y) in a.iter().zip(&b) {
            assert!((x - y).abs() < 1e-14, "{x} {y}");
        }
        let e = Links::default().elastic_energy(&ladder, &q);
        assert!((e - ladder.elastic_energy(&q)).abs() < 1e-15);
    }

    #[test]
    fn link_forces_are_the_energy_gradient() {
        for links in [
            Links {
                stiffness: 3.0,
                tension_only: false,
            },
            Links {
                stiffness: 50.0,
                tension_only: true,
            },
        ] {
            let (ladder, q) = bent(-60.0);
            let mut grad = vec![0.0; q.len()];
            links.gradient(&ladder, &q, &mut grad);
            let energy = |q: &[f64]| {
                let x: f64 = q.iter().step_by(3).sum();
                links.elastic_energy(&ladder, q) - ladder.params.gravity * x
            };
            let h = 1e-6;
            for k in 0..q.len() {
                let (mut qp, mut qm) = (q.clone(), q.clone());
                qp[k] += h;
                qm[k] -= h;
                let fd = (energy(&qp) - energy(&qm)) / (2.0 * h);
                assert!(
                    (fd - grad[k]).abs() < 1e-7 * links.stiffness,
                    "{k}: {fd} {}",
                    grad[k]
                );
            }
        }
    }

    /// ±1 from |x| = 22 on (and at ±∞), odd, monotone, and the library's
    /// tanh within 3 ulp below.
    #[test]
    fn smooth_sign_is_the_librarys_tanh_within_three_ulp() {
        let ulps = |a: f64, b: f64| (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs();
        let mut x = 1e-6f64;
        let mut last = 0.0;
        while x < 1e4 {
            for y in [x, 22.0 * (1.0 + x * 1e-7), 19.0 + x.fract() * 6.0] {
                assert!(ulps(smooth_sign(y), y.tanh()) <= 3, "{y}");
                assert_eq!(
                    smooth_sign(-y).to_bits(),
                    (-smooth_sign(y)).to_bits(),
                    "{y}"
                );
            }
            assert!(smooth_sign(x) >= last, "{x}");
            last = smooth_sign(x);
            x *= 1.001;
        }
        for y in [22.0, 30.0, 1e300, f64::INFINITY] {
            assert_eq!(smooth_sign(y), 1.0, "{y}");
            assert_eq!(smooth_sign(-y), -1.0, "{y}");
        }
        assert_eq!(smooth_sign(0.0).to_bits(), 0.0f64.to_bits());
        assert_eq!(smooth_sign(-0.0).to_bits(), (-0.0f64).to_bits());
        assert!(smooth_sign(f64::NAN).is_nan());
    }

    #[test]
    fn friction_dissipates_and_its_power_is_its_forces_power() {
        let (ladder, q) = bent(69.0);
        let links = Links {
            stiffness: 1.0,
            tension_only: false,
        };
        let f = PinFriction {
            mu_rp: 0.03,
            omega_eps: 0.01,
        };
        let v: Vec<f64> = (0..q.len())
            .map(|k| 0.02 * ((k as f64) * 0.9).cos())
            .collect();
        let mut out = vec![0.0; q.len()];
        let frames = Frames::new(ladder.n(), &q);
        f.add_forces(&ladder, &links, &frames, (&q, &v), &mut out);
        let power: f64 = out.iter().zip(&v).map(|(a, b)| a * b).sum();
        let d = f.dissipation(&ladder, &links, &q, &v);
        assert!(d > 0.0);
        assert!((power + d).abs() < 1e-12 * d.max(1e-12), "{power} {d}");
    }
}
