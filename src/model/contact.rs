//! Contact between blocks with thickness (docs/experiments.md, "The toy as
//! built"): a corner of one block against a face of another.
//!
//! A corner of block a inside block b (in b's frame |u| < r, |w| < h)
//! overlaps it by δ, its distance to the nearest edge of b, whose outward
//! normal n (lab) the contact pushes along. With the relative velocity
//! v_rel of a's corner against b's material point there, the approach
//! speed is δ̇ = −v_rel · n and the normal force a Kelvin–Voigt
//! spring-dashpot that only pushes,
//!
//! F_n = max(0, k_c δ + c δ̇),  c = 2 ζ √(k_c m_eff),
//! ζ = −ln e / √(π² + ln² e),
//!
//! which rebounds a pair of effective mass m_eff (1/m_eff = Σ 1/m +
//! (ρ × n)²/I over the two blocks, ρ from the centre to the corner) with
//! the restitution coefficient e. Coulomb friction, smoothed over a slip
//! speed v_ε: F_t = −μ F_n tanh(v_t/v_ε) along the edge, v_t = v_rel · τ.
//! a gets F_n n + F_t τ at its corner, b the opposite at the same point.
//!
//! Energy: ½ k_c δ² per corner in the potential; dissipated power
//! (F_n − k_c δ) δ̇ ≥ 0 (c δ̇² while the dashpot pushes, −k_c δ δ̇ > 0
//! where it would pull) plus μ F_n tanh(v_t/v_ε) v_t ≥ 0.

use super::outline::{Outline, Pose, add_point_force, point_velocity};
use super::params::{M, R};

/// The chain's blocks as contact sees them: how many, and each one's
/// moment of inertia I (mass m = 1).
#[derive(Debug, Clone, Copy)]
pub struct Blocks {
    pub n: usize,
    pub inertia: f64,
}

/// The most two blocks may overlap, as a fraction of their thickness: a
/// run that goes deeper stops with an error (`sim::divergence`).
pub const MAX_OVERLAP: f64 = 0.1;

/// The contact law's coefficients, in model units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// Penalty stiffness k_c, in k per s.
    pub stiffness: f64,
    /// Coefficient of restitution e ∈ (0, 1].
    pub restitution: f64,
    /// Coulomb friction coefficient μ.
    pub friction: f64,
    /// Slip speed v_ε of the smoothed friction, in s/τ.
    pub slip_speed: f64,
}

/// One corner in contact: the blocks (a's corner in b), where, how deep,
/// the normal and the two forces' sizes, and the approach and slip speeds.
#[derive(Debug, Clone, Copy)]
pub struct Touch {
    pub a: usize,
    pub b: usize,
    /// Which corner of a (`outline`), and the edge of b it is nearest to.
    pub corner: usize,
    pub edge: usize,
    pub point: [f64; 2],
    pub depth: f64,
    pub normal: [f64; 2],
    pub approach: f64,
    pub slip: f64,
    pub normal_force: f64,
    pub friction_force: f64,
}

impl Contact {
    /// ζ of the dashpot for the restitution e.
    pub fn damping_ratio(&self) -> f64 {
        let l = self.restitution.ln();
        -l / (std::f64::consts::PI.powi(2) + l * l).sqrt()
    }

    /// The highest frequency of the contact's penalty spring,
    /// ω_c = √(k_c / m_eff,min): the lightest pair is a corner at the
    /// circumradius ρ of both blocks pushed square to ρ, 1/m_eff =
    /// 2 (1/m + ρ²/I). A corner landing on a face rings at this frequency
    /// while it touches; an explicit scheme must step inside its bound.
    pub fn frequency(&self, blocks: Blocks, o: &Outline) -> f64 {
        let rho = o.radius();
        (self.stiffness * 2.0 * (1.0 / M + rho * rho / blocks.inertia)).sqrt()
    }

    /// The longest stable RK4 step for the contact's spring, 2√2/ω_c (its
    /// bound on the imaginary axis, `sim::step_bounds`).
    pub fn rk4_step_bound(&self, blocks: Blocks, o: &Outline) -> f64 {
        2.0 * std::f64::consts::SQRT_2 / self.frequency(blocks, o)
    }

    /// Every corner in contact at (q, v).
    pub fn touches(&self, blocks: Blocks, o: &Outline, q: &[f64], v: &[f64]) -> Vec<Touch> {
        let mut out = Vec::new();
        self.for_each_touch(blocks, o, q, v, |t| out.push(t));
        out
    }

    /// Calls `f` for every corner in contact at (q, v).
    pub fn for_each_touch(
        &self,
        blocks: Blocks,
        o: &Outline,
        q: &[f64],
        v: &[f64],
        f: impl FnMut(Touch),
    ) {
        let poses: Vec<Pose> = (0..blocks.n).map(|i| Pose::of(q, i)).collect();
        self.for_each_touch_posed(blocks, o, &poses, v, f);
    }

    /// [`Contact::for_each_touch`] at the blocks' `poses` (one per block,
    /// as [`Pose::of`] gives them at q).
    pub fn for_each_touch_posed(
        &self,
        blocks: Blocks,
        o: &Outline,
        poses: &[Pose],
        v: &[f64],
        mut f: impl FnMut(Touch),
    ) {
        let n = blocks.n;
        let reach = 2.0 * o.radius();
        let reach2 = reach * reach;
        for i in 0..n {
            let ci = poses[i].centre;
            for j in i + 1..n {
                // The centres first, from the poses in place: most pairs
                // are out of reach, and copying each pose showed in the
                // profile.
                let cj = poses[j].centre;
                let (dx, dy) = (ci[0] - cj[0], ci[1] - cj[1]);
                if dx * dx + dy * dy >= reach2 {
                    continue;
                }
                let (pi, pj) = (&poses[i], &poses[j]);
                for (a, pa, b, pb) in [(i, pi, j, pj), (j, pj, i, pi)] {
                    for k in 0..4 {
                        if let Some(t) = self.touch(blocks, o, (a, pa), (b, pb), k, v) {
                            f(t);
                        }
                    }
                }
            }
        }
    }

    /// Corner k of block a against block b, if inside it.
    fn touch(
        &self,
        blocks: Blocks,
        o: &Outline,
        (a, pa): (usize, &Pose),
        (b, pb): (usize, &Pose),
        k: usize,
        v: &[f64],
    ) -> Option<Touch> {
        let h = o.half_thickness;
        let x = pa.point(o.corner(k));
        let l = pb.local(x);
        if l[0].abs() >= R || l[1].abs() >= h {
            return None;
        }
        // Depth to each edge of b: w = −h, u = r, w = h, u = −r (edges 0..3).
        let depths = [h + l[1], R - l[0], h - l[1], R + l[0]];
        let (edge, depth) = (0..4)
            .map(|e| (e, depths[e]))
            .fold((0, f64::INFINITY), |m, d| if d.1 < m.1 { d } else { m });
        let normal = pb.vector(o.normal(edge));
        let va = point_velocity(pa, a, o.corner(k), v);
        let vb = point_velocity(pb, b, l, v);
        let rel = [va[0] - vb[0], va[1] - vb[1]];
        let approach = -(rel[0] * normal[0] + rel[1] * normal[1]);
        let tangent = [-normal[1], normal[0]];
        let slip = rel[0] * tangent[0] + rel[1] * tangent[1];
        let m_eff = 1.0
            / (self.inverse_mass(blocks, pa, x, normal) + self.inverse_mass(blocks, pb, x, normal));
        let c = 2.0 * self.damping_ratio() * (self.stiffness * m_eff).sqrt();
        let normal_force = (self.stiffness * depth + c * approach).max(0.0);
        let friction_force = -self.friction * normal_force * (slip / self.slip_speed).tanh();
        Some(Touch {
            a,
            b,
            corner: k,
            edge,
            point: x,
            depth,
            normal,
            approach,
            slip,
            normal_force,
            friction_force,
        })
    }

    /// Corner `k` of block `a` against edge `edge` of block `b` at (q, v):
    /// its signed distance outside that edge's line (negative once past
    /// it) and its approach speed towards it, −v_rel · n, as [`Touch`]
    /// measures them. The impacts (`sim::impacts`) look back with it.
    pub fn corner_gap(
        o: &Outline,
        (a, k): (usize, usize),
        (b, edge): (usize, usize),
        q: &[f64],
        v: &[f64],
    ) -> (f64, f64) {
        let (pa, pb) = (Pose::of(q, a), Pose::of(q, b));
        let x = pa.point(o.corner(k));
        let l = pb.local(x);
        let nf = o.normal(edge);
        // The edge's line lies at R along u (ends) or h along w (faces).
        let extent = if edge % 2 == 1 { R } else { o.half_thickness };
        let gap = l[0] * nf[0] + l[1] * nf[1] - extent;
        let n = pb.vector(nf);
        let va = point_velocity(&pa, a, o.corner(k), v);
        let vb = point_velocity(&pb, b, l, v);
        let approach = -((va[0] - vb[0]) * n[0] + (va[1] - vb[1]) * n[1]);
        (gap, approach)
    }

    /// 1/m + (ρ × n)²/I of a block at lab point x along n.
    fn inverse_mass(&self, blocks: Blocks, p: &Pose, x: [f64; 2], n: [f64; 2]) -> f64 {
        let rho = [x[0] - p.centre[0], x[1] - p.centre[1]];
        let cross = rho[0] * n[1] - rho[1] * n[0];
        1.0 / M + cross * cross / blocks.inertia
    }

    /// Adds the contact forces at (q, v) to the generalised forces `out`
    /// (forces, not a gradient); returns the deepest overlap (in s).
    pub fn add_forces(
        &self,
        blocks: Blocks,
        o: &Outline,
        q: &[f64],
        v: &[f64],
        out: &mut [f64],
    ) -> f64 {
        let poses: Vec<Pose> = (0..blocks.n).map(|i| Pose::of(q, i)).collect();
        self.add_forces_posed(blocks, o, &poses, v, out).0
    }

    /// [`Contact::add_forces`] at the blocks' `poses` (one per block, as
    /// [`Pose::of`] gives them at q). Returns the deepest overlap and the
    /// power the contacts dissipate, as [`Contact::dissipation`].
    pub fn add_forces_posed(
        &self,
        blocks: Blocks,
        o: &Outline,
        poses: &[Pose],
        v: &[f64],
        out: &mut [f64],
    ) -> (f64, f64) {
        let (mut deepest, mut dissipated) = (0.0_f64, 0.0);
        self.for_each_touch_posed(blocks, o, poses, v, |t| {
            deepest = deepest.max(t.depth);
            dissipated += self.dissipated_at(&t);
            let tangent = [-t.normal[1], t.normal[0]];
            let f = [
                t.normal_force * t.normal[0] + t.friction_force * tangent[0],
                t.normal_force * t.normal[1] + t.friction_force * tangent[1],
            ];
            let (pa, pb) = (poses[t.a], poses[t.b]);
            add_point_force(out, &pa, t.a, pa.local(t.point), f);
            add_point_force(out, &pb, t.b, pb.local(t.point), [-f[0], -f[1]]);
        });
        (deepest, dissipated)
    }

    /// Power one touch dissipates: its dashpot's (the normal force beyond
    /// the spring k_c δ, times the approach δ̇) and its friction's.
    #[inline]
    fn dissipated_at(&self, t: &Touch) -> f64 {
        (t.normal_force - self.stiffness * t.depth) * t.approach - t.friction_force * t.slip
    }

    /// Elastic energy Σ ½ k_c δ² of the overlaps at q.
    pub fn elastic_energy(&self, blocks: Blocks, o: &Outline, q: &[f64]) -> f64 {
        let v = vec![0.0; q.len()];
        let mut e = 0.0;
        self.for_each_touch(blocks, o, q, &v, |t| {
            e += 0.5 * self.stiffness * t.depth * t.depth
        });
        e
    }

    /// Power dissipated (≥ 0) by the contacts at (q, v): the dashpot's and
    /// the friction's.
    pub fn dissipation(&self, blocks: Blocks, o: &Outline, q: &[f64], v: &[f64]) -> f64 {
        let mut d = 0.0;
        self.for_each_touch(blocks, o, q, v, |t| d += self.dissipated_at(&t));
        d
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn setup() -> (Blocks, Outline, Contact, Vec<f64>) {
        let p = Blocks {
            n: 3,
            inertia: (1.0 + 0.1f64.powi(2)) / 12.0,
        };
        let o = Outline::new(0.1);
        let c = Contact {
            stiffness: 1000.0,
            restitution: 0.5,
            friction: 0.3,
            slip_speed: 1e-3,
        };
        // Block 2 lying on block 1's face, tilted, a corner 0.004 s deep;
        // block 3 far away.
        let q = vec![0.0, 0.0, 0.0, 0.096, 0.3, 0.01, 3.0, 3.0, 0.0];
        (p, o, c, q)
    }

    #[test]
    fn contact_forces_at_rest_are_minus_the_overlap_energy_gradient() {
        let (l, o, c, q) = setup();
        let v = vec![0.0; q.len()];
        assert!(!c.touches(l, &o, &q, &v).is_empty());
        let mut f = vec![0.0; q.len()];
        c.add_forces(l, &o, &q, &v, &mut f);
        let h = 1e-7;
        for k in 0..q.len() {
            let (mut qp, mut qm) = (q.clone(), q.clone());
            qp[k] += h;
            qm[k] -= h;
            let fd = (c.elastic_energy(l, &o, &qp) - c.elastic_energy(l, &o, &qm)) / (2.0 * h);
            assert!((fd + f[k]).abs() < 1e-5, "{k}: {fd} {}", f[k]);
        }
    }

    #[test]
    fn contact_power_is_elastic_rate_minus_dissipation() {
        // Power of the contact forces = −d/dt(½ k δ²) − dissipation, and
        // the dissipation is ≥ 0, moving in and out, sliding either way.
        let (l, o, c, q) = setup();
        for s in [1.0, -1.0, 0.3, -0.05] {
            let v: Vec<f64> = (0..q.len())
                .map(|k| s * 0.01 * ((k as f64) * 1.3).cos())
                .collect();
            let mut f = vec![0.0; q.len()];
            c.add_forces(l, &o, &q, &v, &mut f);
            let power: f64 = f.iter().zip(&v).map(|(a, b)| a * b).sum();
            let h = 1e-7;
            let shift =
                |sg: f64| -> Vec<f64> { q.iter().zip(&v).map(|(x, w)| x + sg * h * w).collect() };
            let de = (c.elastic_energy(l, &o, &shift(1.0)) - c.elastic_energy(l, &o, &shift(-1.0)))
                / (2.0 * h);
            let d = c.dissipation(l, &o, &q, &v);
            assert!(d >= 0.0);
            assert!((power + de + d).abs() < 1e-8, "{power} {de} {d}");
        }
    }

    #[test]
    fn a_block_dropped_on_its_end_rebounds_as_its_dashpots_say() {
        // Block 2 upright on block 1's face, closing at 0.02 s/τ, no
        // gravity: its end's two corners touch at once, each a dashpot
        // c = 2ζ√(k m_eff); the pair moves as one mass 1/2 on 2k, so it
        // would rebound with e' = exp(−π ζ'/√(1 − ζ'²)), ζ' = 2ζ/√(m_eff⁻¹)
        // (e = 0.5 for one corner alone gives e' = 0.37) if the dashpot
        // could pull; clamped at 0 it lets go early and rebounds faster:
        // measured 0.45, between e' and e' + 0.1.
        let l = Blocks {
            n: 2,
            inertia: (1.0 + 0.1f64.powi(2)) / 12.0,
        };
        let p = l;
        let o = Outline::new(0.1);
        let c = Contact {
            stiffness: 1000.0,
            restitution: 0.5,
            friction: 0.0,
            slip_speed: 1e-3,
        };
        let half_pi = std::f64::consts::FRAC_PI_2;
        let mut q = vec![0.0, 0.0, half_pi, 0.0, 0.5505, 0.0];
        let mut v = vec![0.0, 0.0, 0.0, 0.0, -0.02, 0.0];
        let dt = 1e-4;
        let acc = |q: &[f64], v: &[f64]| {
            let mut f = vec![0.0; 6];
            c.add_forces(l, &o, q, v, &mut f);
            let im = |k: usize| if k % 3 == 2 { 1.0 / p.inertia } else { 1.0 };
            (0..6).map(|k| f[k] * im(k)).collect::<Vec<_>>()
        };
        for _ in 0..20_000 {
            let a = acc(&q, &v);
            for k in 0..6 {
                v[k] += dt * a[k];
                q[k] += dt * v[k];
            }
        }
        let e = (v[4] - v[1]) / 0.02;
        let inv = 2.0 + 2.0 * 0.05f64.powi(2) / p.inertia;
        let zeta = 2.0 * c.damping_ratio() / inv.sqrt();
        let expect = (-std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
        assert!(e > expect && e < expect + 0.1, "{e} {expect}");
        assert!(v[2].abs() < 1e-9 && v[5].abs() < 1e-9);
    }
}
