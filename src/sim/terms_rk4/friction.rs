//! Pin friction over whole arrays (docs/experiments.md, the printed
//! linkage): `PinFriction::add_forces` of `model::links`, the same
//! operations in the same order for every link and every block, as
//! vectorised loops. One pass over the links (lanes: links) finds each
//! link's length, tension, pins' torques and balancing force; one pass
//! over the blocks (lanes: blocks) adds them to the block's generalised
//! forces in the order the link-by-link loop adds them: the link above
//! (its A link, then its B link), then the link below (A, then B), each
//! as the torque of the block's pin, then the node force. With the same
//! frames the result is `add_forces`'s bit for bit (`tests`).

use super::{Coeffs, Soa};
use crate::model::links::{Links, PinFriction};
use crate::model::params::R;
use crate::model::trig::{INV_FACTORIAL, INV_LN2, LN2_HI, LN2_LO, ROUND};
use crate::sim::simd::{F64x4, Simd};

/// The lanes of the links' pass.
type S = F64x4;

/// One sign's links (A: −1, B: +1), link j stored at j + 1 so that block
/// i reads the link above at i and the link below at i + 1; slot 0 and
/// the slots past the last link are never active.
#[derive(Default)]
pub(super) struct LinkForces {
    /// 1.0 where the link pulls or pushes (tension ≠ 0), 0.0 elsewhere.
    active: Vec<f64>,
    /// The torque of the upper block's pin and of the lower block's.
    torque_upper: Vec<f64>,
    torque_lower: Vec<f64>,
    /// f n: the balancing force on the upper node (the lower node's is −f n).
    fx: Vec<f64>,
    fy: Vec<f64>,
}

impl LinkForces {
    pub(super) fn new(len: usize) -> Self {
        let z = || vec![0.0; len + 1];
        Self {
            active: z(),
            torque_upper: z(),
            torque_lower: z(),
            fx: z(),
            fy: z(),
        }
    }
}

/// The links' geometry the friction needs: rest lengths and the law.
#[derive(Clone, Copy)]
pub(super) struct Law {
    pub links: Links,
    pub friction: PinFriction,
    /// Rest lengths of the A and B links.
    pub rest: [f64; 2],
}

/// The generalised forces −∂E/∂q − γ v plus the pins' friction into
/// `forces`, the frames (sine, cosine, parity) given.
#[inline(always)]
pub(super) fn forces(
    (c, law): (&Coeffs, &Law),
    frames: (&[f64], &[f64], &[f64]),
    (q, v): (&Soa, &Soa),
    grad: &Soa,
    links: &mut [LinkForces; 2],
    forces: &mut Soa,
) {
    let np = c.np;
    let rates = [c.gamma, c.gamma, c.gamma_theta];
    for k in 0..3 {
        let (f, g, v) = (&mut forces[k][..np], &grad[k][..np], &v[k][..np]);
        for i in 0..np {
            f[i] = -g[i] - rates[k] * v[i];
        }
    }
    if law.friction.mu_rp == 0.0 {
        return;
    }
    for (side, sign) in [-1.0, 1.0].into_iter().enumerate() {
        // SAFETY: a `TermsRk4` is made only where the CPU has AVX2
        // (`TermsRk4::new`), and only it calls this.
        unsafe { link_pass(c, law, sign, frames, (q, v), &mut links[side]) };
    }
    // SAFETY: as above.
    unsafe { block_pass(c, frames, links, forces) };
}

/// Every link of one sign, four at a time: `Links::state` and
/// `PinFriction::pins` over [`F64x4`] lanes, the same operations in the
/// same order (a lane's arithmetic is the scalar IEEE operation). Not
/// inlined: its own function compiled for AVX2.
#[cfg_attr(target_arch = "x86_64", target_feature(enable = "avx2"))]
#[inline(never)]
unsafe fn link_pass(
    c: &Coeffs,
    law: &Law,
    sign: f64,
    (sn, cs, p): (&[f64], &[f64], &[f64]),
    (q, v): (&Soa, &Soa),
    out: &mut LinkForces,
) {
    let (np, m) = (c.np, c.n - 1);
    let sp = S::splat;
    let rest = sp(law.rest[usize::from(sign > 0.0)]);
    let (mu_rp, omega_eps) = (sp(law.friction.mu_rp), sp(law.friction.omega_eps));
    let stiffness = sp(law.links.stiffness);
    let sr = sp(sign * R);
    // Four lanes from `a[k..k + 4]` (k + 4 ≤ np + 1 ≤ a's length).
    let ld = |a: &[f64], k: usize| {
        let a = &a[k..k + 4];
        // SAFETY: `a` holds four values.
        unsafe { S::load(a.as_ptr()) }
    };
    let st = |x: S, a: &mut [f64], k: usize| {
        let a = &mut a[k..k + 4];
        // SAFETY: `a` has room for four values.
        unsafe { x.store(a.as_mut_ptr()) }
    };
    for j in (0..np).step_by(4) {
        let (s0, c0, p0) = (ld(sn, j), ld(cs, j), ld(p, j));
        let (s1, c1, p1) = (ld(sn, j + 1), ld(cs, j + 1), ld(p, j + 1));
        let (t0, nu0) = ([s0, p0 * c0], [c0, -p0 * s0]);
        let (t1, nu1) = ([s1, p1 * c1], [c1, -p1 * s1]);
        let dx = (ld(&q[0], j + 1) + sr * t1[0]) - (ld(&q[0], j) + sr * t0[0]);
        let dy = (ld(&q[1], j + 1) + sr * t1[1]) - (ld(&q[1], j) + sr * t0[1]);
        let length = (dx * dx + dy * dy).sqrt();
        let stretch = length - rest;
        let tension = if law.links.tension_only {
            // 0 where the link is shorter than its rest length (or −0:
            // a zero tension either way, which leaves the link out).
            (stiffness * stretch).select(sp(0.0), stretch)
        } else {
            stiffness * stretch
        };
        let (w0, w1) = (ld(&v[2], j), ld(&v[2], j + 1));
        let u0 = [
            ld(&v[0], j) + sr * w0 * nu0[0],
            ld(&v[1], j) + sr * w0 * nu0[1],
        ];
        let u1 = [
            ld(&v[0], j + 1) + sr * w1 * nu1[0],
            ld(&v[1], j + 1) + sr * w1 * nu1[1],
        ];
        let dd = [u1[0] - u0[0], u1[1] - u0[1]];
        let phi_dot = (dx * dd[1] - dy * dd[0]) / (length * length);
        let limit = mu_rp * tension.abs();
        let tq0 = -limit * smooth_sign((-p0 * w0 - phi_dot) / omega_eps);
        let tq1 = -limit * smooth_sign((-p1 * w1 - phi_dot) / omega_eps);
        let f = (tq0 + tq1) / length;
        let n = [-dy / length, dx / length];
        let zero = tension.le_bits(sp(0.0)) & tension.ge_bits(sp(0.0));
        let active = S::from_fn(|l| f64::from(u8::from(zero >> l & 1 == 0 && j + l < m)));
        st(active, &mut out.active, j + 1);
        st(tq0, &mut out.torque_upper, j + 1);
        st(tq1, &mut out.torque_lower, j + 1);
        st(f * n[0], &mut out.fx, j + 1);
        st(f * n[1], &mut out.fy, j + 1);
    }
}

/// `model::links::smooth_sign` over lanes: `model::trig::tanh`'s
/// operations in its order, ±1 where |x| > 22 (where the scalar one
/// clamps x to ±22, whose tanh is ±1).
#[inline(always)]
fn smooth_sign(x: S) -> S {
    let sp = S::splat;
    let sign = x & sp(-0.0);
    let e = expm1_negative(sp(-2.0) * x.abs());
    let t = (-e / (sp(2.0) + e)).abs() | sign;
    t.select(sp(1.0) | sign, sp(22.0) - x.abs())
}

/// `model::trig`'s e^y − 1 for −44 ≤ y ≤ 0 over lanes, the same
/// operations in the same order.
#[inline(always)]
fn expm1_negative(y: S) -> S {
    let sp = S::splat;
    let k = (y * sp(INV_LN2) + sp(ROUND)) - sp(ROUND);
    let r = (y - k * sp(LN2_HI)) - k * sp(LN2_LO);
    let mut p = sp(INV_FACTORIAL[12]);
    for c in INV_FACTORIAL[..12].iter().rev() {
        p = sp(*c) + r * p;
    }
    let em = r + r * r * p;
    let two_k = (k + sp(1023.0) + sp(ROUND)).shift_left(52, 0);
    two_k * em + (two_k - sp(1.0))
}

/// Every block: the torques of its pins and the links' node forces, in
/// `add_forces`'s order (above A, above B, below A, below B); not
/// inlined, as [`link_pass`].
#[cfg_attr(target_arch = "x86_64", target_feature(enable = "avx2"))]
#[inline(never)]
unsafe fn block_pass(
    c: &Coeffs,
    (sn, cs, p): (&[f64], &[f64], &[f64]),
    links: &[LinkForces; 2],
    forces: &mut Soa,
) {
    let np = c.np;
    let n1 = np + 1;
    let [gx, gy, gt] = forces;
    let (gx, gy, gt) = (&mut gx[..np], &mut gy[..np], &mut gt[..np]);
    let (sn, cs, p) = (&sn[..np], &cs[..np], &p[..np]);
    let (a, b) = (Side::cut(&links[0], n1), Side::cut(&links[1], n1));
    for i in 0..np {
        let nu = [cs[i], -p[i] * sn[i]];
        let mut g = [gx[i], gy[i], gt[i]];
        // The link above (slot i) then the link below (slot i + 1), A
        // before B: the link-by-link loop's order for block i.
        g = a.add(g, i, false, (-1.0, p[i], nu));
        g = b.add(g, i, false, (1.0, p[i], nu));
        g = a.add(g, i + 1, true, (-1.0, p[i], nu));
        g = b.add(g, i + 1, true, (1.0, p[i], nu));
        [gx[i], gy[i], gt[i]] = g;
    }
}

/// One sign's links, cut to their length.
struct Side<'a> {
    active: &'a [f64],
    upper: &'a [f64],
    lower: &'a [f64],
    fx: &'a [f64],
    fy: &'a [f64],
}

impl<'a> Side<'a> {
    fn cut(l: &'a LinkForces, n1: usize) -> Self {
        Self {
            active: &l.active[..n1],
            upper: &l.torque_upper[..n1],
            lower: &l.torque_lower[..n1],
            fx: &l.fx[..n1],
            fy: &l.fy[..n1],
        }
    }

    /// The generalised force `g` of a block with link `slot`'s pin
    /// torque and node force added, as `add_forces` adds them (the
    /// block is that link's `upper` one or its lower one; `sign` the
    /// link's, `p` the block's parity, `nu` its normal).
    #[inline(always)]
    fn add(
        &self,
        g: [f64; 3],
        slot: usize,
        upper: bool,
        (sign, p, nu): (f64, f64, [f64; 2]),
    ) -> [f64; 3] {
        let torque = if upper {
            self.upper[slot]
        } else {
            self.lower[slot]
        };
        // The lower node takes −f n: `-f * n[k]`, the negation exact.
        let (fx, fy) = if upper {
            (self.fx[slot], self.fy[slot])
        } else {
            (-self.fx[slot], -self.fy[slot])
        };
        let t = g[2] + -p * torque;
        let added = [
            g[0] + fx,
            g[1] + fy,
            t + sign * R * (fx * nu[0] + fy * nu[1]),
        ];
        if self.active[slot] != 0.0 { added } else { g }
    }
}
