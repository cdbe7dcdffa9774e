//! The blocks' pass of the tank's force evaluation: each block's
//! generalised forces, strip drag in closed form, the added mass's forces
//! and Munk moment, and Lagrange's equations with M⁻¹ in closed form
//! (`media::block_acceleration_framed`), written once over lanes
//! ([`Lanewise`]): four blocks of the step over arrays or the whole
//! ladder of the step in registers (`terms_rk4::regs`).

use super::Coeffs;
use crate::model::params::{M, R};
use crate::sim::simd::{F64x4, Pack, Simd};

/// The generalised forces −∂E/∂q − γ v (r² γ for θ) of the lanes' blocks from
/// the gradient `g`, as `Rhs::acceleration_with_terms` forms them.
#[inline(always)]
pub(super) fn forces<S: Lanewise>(c: &Coeffs, g: [S; 3], [vx, vy, w]: [S; 3]) -> [S; 3] {
    let sp = S::splat;
    [
        -g[0] - sp(c.gamma) * vx,
        -g[1] - sp(c.gamma) * vy,
        -g[2] - sp(c.gamma_theta) * w,
    ]
}

/// The lanes' blocks' accelerations (Ẍ, Ÿ, θ̈) from their generalised forces
/// `f` before drag, frames (sin θ, cos θ, (−1)ⁿ) and rates: strip drag
/// (`DRAG`), the added mass's forces and Munk moment, M⁻¹ in closed form
/// (`media::block_acceleration_framed`), a lane's arithmetic the scalar
/// IEEE operation in the portable path's order.
#[inline(always)]
pub(super) fn block_acceleration<S: Lanewise, const DRAG: bool, const EXACT: bool>(
    c: &Coeffs,
    [fx, fy, ft]: [S; 3],
    (sn, cs, p): (S, S, S),
    [vx, vy, w]: [S; 3],
) -> [S; 3] {
    let sp = S::splat;
    let (mut fx, mut fy, mut ft) = (fx, fy, ft);
    // p = ±1: its products are its sign bit on the other factor.
    let p = p & sp(-0.0);
    let (t, nu) = ([sn, cs ^ p], [cs, sn ^ p ^ sp(-0.0)]);
    if DRAG {
        let u0 = vx * nu[0] + vy * nu[1];
        let (f, tq) = drag_integrals::<S, EXACT>(u0, w);
        fx = fx + -sp(c.drag) * f * nu[0];
        fy = fy + -sp(c.drag) * f * nu[1];
        ft = ft + -sp(c.drag) * tq;
    }
    let vn = vx * nu[0] + vy * nu[1];
    let vt = vx * t[0] + vy * t[1];
    let fx = fx + sp(c.ma) * w * (vt * nu[0] + vn * t[0]);
    let fy = fy + sp(c.ma) * w * (vt * nu[1] + vn * t[1]);
    let fn_ = fx * nu[0] + fy * nu[1];
    let torque = ft - sp(c.ma) * vn * vt;
    let (x, y) = (fx - sp(c.k_am) * fn_ * nu[0], fy - sp(c.k_am) * fn_ * nu[1]);
    // m = 1: the portable path's division by it is no operation.
    const { assert!(M == 1.0) };
    let th = if EXACT {
        torque / sp(c.j)
    } else {
        torque * sp(c.inv_j)
    };
    [x, y, th]
}

/// `media::drag_integrals(u0, w, r)` at r = R over four lanes without a
/// branch: both closed forms computed as there (`EXACT`), or with the
/// quick arithmetic's multiplications by 1/3 and one reciprocal of w
/// ([`QUICK`]), the one that applies kept (u0 is never NaN: the sign is
/// u0's sign bit on 1, as `signum` gives for every other u0).
#[inline(always)]
pub(super) fn drag_integrals<S: Lanewise, const EXACT: bool>(u0: S, w: S) -> (S, S) {
    let (sp, r) = (S::splat, R);
    // The portable path's sign(u0) · x, and its products by 2r = 1 and
    // (4/3) r r r (powers of two after 4/3), are exact: here u0's sign bit
    // on x, no product by 1, and one constant, the same numbers.
    const { assert!(R == 0.5) };
    let sign = u0 & sp(-0.0);
    let force_a = (u0 * u0 + sp((2.0 / 3.0) * r * r * r) * w * w) ^ sign;
    let torque_a = ((sp(4.0 / 3.0 * r * r * r) ^ sign) * u0) * w;
    let (up, um) = (u0 + w * sp(r), u0 - w * sp(r));
    let dg = cube_third::<S, EXACT>(up) - cube_third::<S, EXACT>(um);
    let rest = fourth_quarter(up) - fourth_quarter(um) - u0 * dg;
    let (force_b, torque_b) = if EXACT {
        (dg / w, rest / (w * w))
    } else {
        let inv_w = sp(1.0) / w;
        (dg * inv_w, rest * (inv_w * inv_w))
    };
    let closed_a = (w * sp(r)).abs().le_mask(u0.abs());
    (
        force_b.select(force_a, closed_a),
        torque_b.select(torque_a, closed_a),
    )
}

/// u²|u|/3, the drag's g(u) (functions, not closures: a closure left out
/// of line would compile without AVX2).
#[inline(always)]
fn cube_third<S: Simd, const EXACT: bool>(u: S) -> S {
    let cube = u * u * u.abs();
    if EXACT {
        cube / S::splat(3.0)
    } else {
        cube * S::splat(THIRD)
    }
}

/// u³|u|/4, the drag's h(u): division by 4 is exact scaling, so the
/// product by 1/4 is the quotient.
#[inline(always)]
fn fourth_quarter<S: Simd>(u: S) -> S {
    u * u * u * u.abs() * S::splat(0.25)
}

/// What the blocks' pass asks of its lanes beyond [`Simd`]: four blocks
/// ([`F64x4`], the pass over arrays) or the whole ladder (`Pack`, the
/// step in registers).
pub(super) trait Lanewise: Simd {
    /// Every bit of a lane set where `self` ≤ `o` (none for NaN): a
    /// selector for [`Simd::select`].
    fn le_mask(self, o: Self) -> Self;
}

impl Lanewise for F64x4 {
    #[inline(always)]
    fn le_mask(self, o: Self) -> Self {
        F64x4::le_mask(self, o)
    }
}

impl<const C: usize> Lanewise for Pack<F64x4, C> {
    #[inline(always)]
    fn le_mask(mut self, o: Self) -> Self {
        for c in 0..C {
            self.0[c] = self.0[c].le_mask(o.0[c]);
        }
        self
    }
}

/// 1/3 rounded: the quick arithmetic's factor for the drag's divisions
/// by 3.
const THIRD: f64 = 1.0 / 3.0;

/// The fused path's arithmetic, a const parameter `EXACT`: [`PORTABLE`],
/// the portable path's divisions (with the library's frames and with pin
/// friction: every run that is the portable one bit for bit), or
/// [`QUICK`], for the tank's runs with
/// the springs' frames: Lagrange's θ equation multiplied by 1/(I + I_a)
/// and the drag's closed form by 1/3 and one reciprocal of w instead of
/// dividing by I + I_a, 3, w and w² (four divisions of five per block on
/// the one divider, docs/performance.md). Each product is within 1.5 ulp
/// of the quotient it replaces; the tests bound what that does to a force
/// evaluation and to the tank's trajectory (`tests`).
pub(super) const QUICK: bool = false;
/// The portable path's arithmetic ([`QUICK`]).
pub(super) const PORTABLE: bool = true;
