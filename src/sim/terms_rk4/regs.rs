//! The tank's RK4 step with the whole ladder in registers: the runs without
//! pin friction, N ≤ 16.
//!
//! [`super::TermsRk4`]'s step over arrays writes every stage's (q, v) to
//! memory and reads it back, block j + 1 beside block j by a load that
//! straddles two of the stores just made, in loops whose bounds are known
//! only at run time. Here every quantity of every block is C registers of
//! four lanes (`sim::simd`'s [`Pack`], lane l of register c being block
//! 4c + l): the state and the stages' values and rates stay in registers
//! (or go to the stack as whole registers), the springs take block j + 1
//! by a shuffle ([`Simd::next`]), and every loop is over the C registers,
//! unrolled. Each lane's arithmetic is the array step's, operation for
//! operation in the same order (the sine and cosine are
//! `trig::sin_cos_slice`'s, the drag, added mass and Lagrange's equations
//! [`super::block_acceleration`] itself), so the trajectory is the array
//! step's bit for bit (`tests`), and with the library's frames the
//! portable path's. Arrivals are tested as `sim::fused` tests them: the
//! candidate windows over whole registers, the exact test for candidates
//! only.

use super::{Coeffs, block_acceleration, forces};
use crate::model::ladder::parity;
use crate::model::params::R;
use crate::model::trig::{self, consts::*};
use crate::sim::observables::ArrivalDetector;
use crate::sim::rhs::{Rhs, State};
use crate::sim::simd::{F64x4, MAX_LANES, Pack, Simd, record_arrivals};
use crate::sim::stepping::Plan;
use crate::sim::tableau::RK4;
use std::arch::x86_64::*;

/// One quantity of 4C blocks (or spring pairs).
type Lanes<const C: usize> = Pack<F64x4, C>;

/// Most registers of four per quantity this path takes (N ≤ 16).
pub(super) const MAX_REGS: usize = 4;

/// X, Y and θ (or their rates, or accelerations) of every block; named
/// fields, never indexed at run time, so that they stay in registers.
#[derive(Clone, Copy)]
struct Coords<const C: usize> {
    x: Lanes<C>,
    y: Lanes<C>,
    th: Lanes<C>,
}

impl<const C: usize> Coords<C> {
    /// From the model's layout [X_1, Y_1, θ_1, X_2, …] of `n` blocks; lanes
    /// past the last from `pad(k, lane)`.
    #[inline(always)]
    fn load(table: &[f64], n: usize, pad: fn(usize, usize) -> f64) -> Self {
        let lanes = |k: usize| lanes(|i| if i < n { table[3 * i + k] } else { pad(k, i) });
        Self {
            x: lanes(0),
            y: lanes(1),
            th: lanes(2),
        }
    }

    #[inline(always)]
    fn store(&self, table: &mut [f64], n: usize) {
        for (k, lanes) in [self.x, self.y, self.th].into_iter().enumerate() {
            let mut values = [0.0; 4 * MAX_REGS];
            // SAFETY: `values` holds 4 MAX_REGS ≥ 4C values.
            unsafe { lanes.store(values.as_mut_ptr()) };
            for i in 0..n {
                table[3 * i + k] = values[i];
            }
        }
    }
}

/// The run's constants, as registers.
struct Consts<const C: usize> {
    c: Coeffs,
    /// (−1)ⁿ of every block.
    parity: Lanes<C>,
    /// All bits set for a spring pair between two blocks (j < N − 1).
    pair: Lanes<C>,
    /// −0.0 for a lane without a spring pair, +0.0 for one with.
    no_pair: Lanes<C>,
    /// All bits set for a block whose acceleration is computed (not the
    /// driven block 1, not padding).
    keep: Lanes<C>,
}

impl<const C: usize> Consts<C> {
    #[inline(always)]
    fn new(c: Coeffs) -> Self {
        let ones = f64::from_bits(u64::MAX);
        let first = usize::from(c.driven);
        Self {
            c,
            parity: lanes(parity),
            pair: lanes(|j| if j + 1 < c.n { ones } else { 0.0 }),
            no_pair: lanes(|j| if j + 1 < c.n { 0.0 } else { -0.0 }),
            keep: lanes(|i| if i >= first && i < c.n { ones } else { 0.0 }),
        }
    }
}

/// Lanes from `f(i)` for the 4C blocks by a plain loop (the setup of each
/// call of [`advance`], without `Simd::from_fn`'s array of 32).
#[inline(always)]
fn lanes<const C: usize>(f: impl Fn(usize) -> f64) -> Lanes<C> {
    const { assert!(C <= MAX_REGS) };
    let mut a = [0.0; 4 * MAX_REGS];
    for (i, x) in a.iter_mut().enumerate().take(4 * C) {
        *x = f(i);
    }
    // SAFETY: `a` holds 4 MAX_REGS ≥ 4C values.
    unsafe { Lanes::<C>::load(a.as_ptr()) }
}

/// The x position of padding block `i` (as the array step's).
fn far(i: usize) -> f64 {
    10.0 * i as f64
}

/// sin x and cos x lane by lane: `trig::sin_cos_slice` bit for bit (its
/// reduction, fdlibm's kernels in Estrin's form, the quadrant's swap and
/// signs as sign-bit operations, exact as its products by ±1), arguments
/// beyond the reduction (or NaN) from the library as there.
#[inline(always)]
pub(super) fn sin_cos<S: Simd>(x: S) -> (S, S) {
    const ROUNDING: f64 = 6_755_399_441_055_744.0;
    let shifted = x * S::splat(FRAC_2_PI) + S::splat(ROUNDING);
    let k = shifted - S::splat(ROUNDING);
    let r = ((x - k * S::splat(PIO2_1)) - k * S::splat(PIO2_2)) - k * S::splat(PIO2_2T);
    let z = r * r;
    let z2 = z * z;
    let z4 = z2 * z2;
    let ps = r + (r * z) * estrin([S1, S2, S3, S4, S5, S6], z, z2, z4);
    let pc = (S::splat(1.0) - S::splat(0.5) * z) + z2 * estrin([C1, C2, C3, C4, C5, C6], z, z2, z4);
    let odd = shifted.shift_left(63, 0);
    let sign = S::splat(-0.0);
    let s = ps.select(pc, odd) ^ (shifted.shift_left(62, 0) & sign);
    let c = pc.select(ps, odd) ^ (shifted.shift_left(62, 1) & sign);
    if x.abs().not_le_bits(S::splat(trig::REDUCE_LIMIT)) == 0 {
        (s, c)
    } else {
        library_sin_cos(x)
    }
}

/// (c0 + z c1) + z² (c2 + z c3) + z⁴ (c4 + z c5): `trig::kernels`' Estrin
/// form.
#[inline(always)]
fn estrin<S: Simd>(c: [f64; 6], z: S, z2: S, z4: S) -> S {
    let low = S::splat(c[0]) + z * S::splat(c[1]);
    let mid = S::splat(c[2]) + z * S::splat(c[3]);
    let high = S::splat(c[4]) + z * S::splat(c[5]);
    (low + z2 * mid) + z4 * high
}

#[cold]
#[inline(never)]
fn library_sin_cos<S: Simd>(x: S) -> (S, S) {
    let xs = x.to_array();
    let (mut s, mut c) = ([0.0; MAX_LANES], [0.0; MAX_LANES]);
    trig::sin_cos_slice(&xs[..S::LANES], &mut s, &mut c);
    (S::from_fn(|l| s[l]), S::from_fn(|l| c[l]))
}

/// The C library's sine and cosine of every lane (the frames of
/// `TermsRk4::with_library_frames`).
#[cold]
#[inline(never)]
fn library_frames<S: Simd>(x: S) -> (S, S) {
    let xs = x.to_array();
    let (mut s, mut c) = ([0.0; MAX_LANES], [0.0; MAX_LANES]);
    for l in 0..S::LANES {
        (s[l], c[l]) = xs[l].sin_cos();
    }
    (S::from_fn(|l| s[l]), S::from_fn(|l| c[l]))
}

/// The springs' gradient ∂E/∂q: the array step's `springs`, the same
/// operations in the same order, block j + 1 by [`Simd::next`]; the pairs
/// past the last masked, the sums at the chain's ends exact as there
/// (−0.0 added where the array step has no term).
#[inline(always)]
fn gradient<const C: usize>(k: &Consts<C>, q: &Coords<C>, sn: Lanes<C>, cs: Lanes<C>) -> Coords<C> {
    let s = Lanes::<C>::splat;
    let (c, p) = (&k.c, k.parity);
    let end = 4 * C;
    let (sn1, cs1, p1) = (sn.next(s(0.0)), cs.next(s(1.0)), p.next(s(parity(end))));
    // p = ±1: its products are its sign bit on the other factor.
    let (p, p1) = (p & s(-0.0), p1 & s(-0.0));
    let (tx0, ty0, tx1, ty1) = (sn, cs ^ p, sn1, cs1 ^ p1);
    let (ex, ey) = (q.x.next(s(far(end))) - q.x, q.y.next(s(0.0)) - q.y);
    let (ux, uy) = (s(R) * (tx1 - tx0), s(R) * (ty1 - ty0));
    let (ax, ay, bx, by) = (ex - ux, ey - uy, ex + ux, ey + uy);
    let ka = s(1.0) - s(c.a_rest) / (ax * ax + ay * ay).sqrt();
    let kb = s(1.0) - s(c.b_rest) / (bx * bx + by * by).sqrt();
    let (fax, fay, fbx, fby) = (ka * ax, ka * ay, kb * bx, kb * by);
    let fx = (fax + fbx) & k.pair;
    let fy = (fay + fby) & k.pair;
    let (dx, dy) = (s(R) * (fbx - fax), s(R) * (fby - fay));
    let tu = (dx * cs1 - (dy ^ p1) * sn1) & k.pair;
    let tl = ((-(dx * cs - (dy ^ p) * sn)) & k.pair) | k.no_pair;
    // Block i feels pair i − 1 from above (−0.0 above block 1) and pair i
    // from below.
    let none = s(-0.0);
    Coords {
        x: (s(-c.g) + fx.prev(none)) - fx,
        y: fy.prev(none) - fy,
        th: tu.prev(none) + tl,
    }
}

/// What the accelerations take from the positions alone: the frames
/// (sin θ, cos θ: the springs', or the library's for `EXACT`) and the
/// springs' gradient.
#[derive(Clone, Copy)]
struct AtQ<const C: usize> {
    sin: Lanes<C>,
    cos: Lanes<C>,
    gradient: Coords<C>,
}

/// The part of the array step's `acceleration` that reads q alone; in the
/// portable path's arithmetic (`EXACT`) with the library's frames for the
/// drag and added mass, as `TermsRk4::with_library_frames`.
#[inline(always)]
fn at_q<const C: usize, const EXACT: bool>(k: &Consts<C>, q: &Coords<C>) -> AtQ<C> {
    let (sn, cs) = sin_cos(q.th);
    let gradient = gradient(k, q, sn, cs);
    let (sin, cos) = if EXACT {
        library_frames(q.th)
    } else {
        (sn, cs)
    };
    AtQ { sin, cos, gradient }
}

/// The accelerations at (q, v) from q's part `at`: the rest of the array
/// step's `acceleration`.
#[inline(always)]
fn acceleration<const C: usize, const DRAG: bool, const EXACT: bool>(
    k: &Consts<C>,
    at: &AtQ<C>,
    v: &Coords<C>,
) -> Coords<C> {
    let (g, v) = (at.gradient, [v.x, v.y, v.th]);
    let f = forces(&k.c, [g.x, g.y, g.th], v);
    let frames = (at.sin, at.cos, k.parity);
    let [x, y, th] = block_acceleration::<Lanes<C>, DRAG, EXACT>(&k.c, f, frames, v);
    Coords {
        x: x & k.keep,
        y: y & k.keep,
        th: th & k.keep,
    }
}

/// y0 + h Σ w_j k_j, the sum from 0.0 in order of j (the array step's
/// `combine`), for X, Y and θ.
#[inline(always)]
fn combine<const C: usize, const S: usize>(
    y0: &Coords<C>,
    h: f64,
    w: [f64; S],
    ks: [&Coords<C>; S],
) -> Coords<C> {
    let (mut x, mut y, mut th) = ([y0.x; S], [y0.y; S], [y0.th; S]);
    for j in 0..S {
        (x[j], y[j], th[j]) = (ks[j].x, ks[j].y, ks[j].th);
    }
    Coords {
        x: sum(y0.x, h, w, x),
        y: sum(y0.y, h, w, y),
        th: sum(y0.th, h, w, th),
    }
}

/// y0 + h Σ w_j k_j of one coordinate.
#[inline(always)]
fn sum<const C: usize, const S: usize>(
    y0: Lanes<C>,
    h: f64,
    w: [f64; S],
    ks: [Lanes<C>; S],
) -> Lanes<C> {
    let s = Lanes::<C>::splat;
    let mut d = s(0.0);
    for j in 0..S {
        d = d + s(w[j]) * ks[j];
    }
    y0 + s(h) * d
}

/// Lane 0 (block 1) of `x` set to `value`.
#[inline(always)]
fn with_first<const C: usize>(mut x: Lanes<C>, value: f64) -> Lanes<C> {
    // SAFETY: only reached inlined into `advance_avx2` (AVX2 checked).
    x.0[0] = F64x4(unsafe { _mm256_blend_pd::<0b0001>(x.0[0].0, _mm256_set1_pd(value)) });
    x
}

/// Block 1's prescribed position (`which` = 0) or velocity (1), if
/// driven, set in `y`: `Rhs::constrain`'s half for q or for v.
#[inline(always)]
fn constrain<const C: usize>(at: Option<&([f64; 3], [f64; 3])>, which: usize, y: &mut Coords<C>) {
    if let Some(p) = at {
        let p = if which == 0 { p.0 } else { p.1 };
        (y.x, y.y, y.th) = (
            with_first(y.x, p[0]),
            with_first(y.y, p[1]),
            with_first(y.th, p[2]),
        );
    }
}

/// One RK4 step of (q0, v0) from `t`, `at0` being q0's part of the
/// accelerations: the array step's `step`, its operations in the same
/// order for each quantity; only independent work is reordered, each
/// stage's (and the next step's) positions and their frames and springs
/// before the previous stage's drag and Lagrange's equations, so that the
/// processor overlaps the two chains. Returns q's part at the new q0.
#[inline(always)]
fn step<const C: usize, const DRAG: bool, const EXACT: bool>(
    (k, rhs): (&Consts<C>, &Rhs),
    (q0, v0, at0): (&mut Coords<C>, &mut Coords<C>, &AtQ<C>),
    (t, h, t_new): (f64, f64, f64),
) -> AtQ<C> {
    let (a, b) = (RK4.a, [RK4.b[0], RK4.b[1], RK4.b[2], RK4.b[3]]);
    // Three calls, not an array's `map` (which was left out of line: about
    // 3 % of the tank's run).
    let p = [
        rhs.prescribed(t + RK4.c[1] * h),
        rhs.prescribed(t + RK4.c[2] * h),
        rhs.prescribed(t + RK4.c[3] * h),
    ];
    let kq0 = *v0;
    let mut q1 = combine(q0, h, [a[1][0]], [&kq0]);
    constrain(p[0].as_ref(), 0, &mut q1);
    let at1 = at_q::<C, EXACT>(k, &q1);
    let kv0 = acceleration::<C, DRAG, EXACT>(k, at0, &kq0);
    let mut kq1 = combine(v0, h, [a[1][0]], [&kv0]);
    constrain(p[0].as_ref(), 1, &mut kq1);
    let w2 = [a[2][0], a[2][1]];
    let mut q2 = combine(q0, h, w2, [&kq0, &kq1]);
    constrain(p[1].as_ref(), 0, &mut q2);
    let at2 = at_q::<C, EXACT>(k, &q2);
    let kv1 = acceleration::<C, DRAG, EXACT>(k, &at1, &kq1);
    let mut kq2 = combine(v0, h, w2, [&kv0, &kv1]);
    constrain(p[1].as_ref(), 1, &mut kq2);
    let w3 = [a[3][0], a[3][1], a[3][2]];
    let mut q3 = combine(q0, h, w3, [&kq0, &kq1, &kq2]);
    constrain(p[2].as_ref(), 0, &mut q3);
    let at3 = at_q::<C, EXACT>(k, &q3);
    let kv2 = acceleration::<C, DRAG, EXACT>(k, &at2, &kq2);
    let mut kq3 = combine(v0, h, w3, [&kv0, &kv1, &kv2]);
    constrain(p[2].as_ref(), 1, &mut kq3);
    let end = rhs.prescribed(t_new);
    *q0 = combine(q0, h, b, [&kq0, &kq1, &kq2, &kq3]);
    constrain(end.as_ref(), 0, q0);
    let at_new = at_q::<C, EXACT>(k, q0);
    let kv3 = acceleration::<C, DRAG, EXACT>(k, &at3, &kq3);
    *v0 = combine(v0, h, b, [&kv0, &kv1, &kv2, &kv3]);
    constrain(end.as_ref(), 1, v0);
    at_new
}

/// What one call of [`advance`] is given.
pub(super) struct Job<'j, 'a> {
    pub c: Coeffs,
    pub rhs: &'j Rhs<'a>,
    pub st: &'j mut State,
    pub plan: (&'j mut Plan, f64),
    pub span: (f64, f64),
    pub max_steps: u64,
    pub arrivals: &'j mut ArrivalDetector,
}

/// Up to `max_steps` steps of the plan towards `t_stop` with the ladder in
/// C registers per quantity (N ≤ 4C ≤ 16), `DRAG` and `EXACT` as in
/// `block_accelerations`: the time reached and the steps taken.
///
/// # Safety
/// The CPU must have AVX2.
#[target_feature(enable = "avx2")]
pub(super) unsafe fn advance_avx2<const C: usize, const DRAG: bool, const EXACT: bool>(
    job: Job,
) -> (f64, u64) {
    advance::<C, DRAG, EXACT>(job)
}

/// The same code with 32 vector registers instead of 16 (fewer values
/// spilled to the stack; the same 256-bit operations, so the same
/// numbers).
///
/// # Safety
/// The CPU must have AVX2, AVX-512F and AVX-512VL.
#[target_feature(enable = "avx2,avx512f,avx512vl")]
pub(super) unsafe fn advance_avx512<const C: usize, const DRAG: bool, const EXACT: bool>(
    job: Job,
) -> (f64, u64) {
    advance::<C, DRAG, EXACT>(job)
}

#[inline(always)]
fn advance<const C: usize, const DRAG: bool, const EXACT: bool>(job: Job) -> (f64, u64) {
    let Job {
        c,
        rhs,
        st,
        plan: (plan, dt),
        span: (mut t, t_stop),
        max_steps,
        arrivals,
    } = job;
    let (n, k) = (c.n, Consts::<C>::new(c));
    let mut q0 = Coords::<C>::load(&st.q, n, |k, i| if k == 0 { far(i) } else { 0.0 });
    let mut v0 = Coords::<C>::load(&st.v, n, |_, _| 0.0);
    let lo = lanes::<C>(|i| if i < n { arrivals.window(i)[0] } else { 0.0 });
    let hi = lanes::<C>(|i| if i < n { arrivals.window(i)[1] } else { 0.0 });
    let mut pending = arrivals.pending_mask();
    let mut taken = 0;
    // The state is constrained at `t` already (the array step constrains it
    // again at the start of every step: the same values).
    let start = rhs.prescribed(t);
    constrain(start.as_ref(), 0, &mut q0);
    constrain(start.as_ref(), 1, &mut v0);
    let mut at0 = at_q::<C, EXACT>(&k, &q0);
    while taken < max_steps && t < t_stop {
        let (h, last) = plan.next(t, t_stop, dt);
        let t_new = if last { t_stop } else { t + h };
        let before = (t, q0.th, v0.th);
        let state = (&mut q0, &mut v0, &at0);
        at0 = step::<C, DRAG, EXACT>((&k, rhs), state, (t, h, t_new));
        // `ArrivalDetector::observe`'s candidates, every pending block at once.
        let candidates = (q0.th.le_bits(lo) | q0.th.ge_bits(hi)) & pending;
        if candidates != 0 {
            pending &= !record_arrivals(arrivals, candidates, before, (t_new, q0.th, v0.th));
        }
        t = t_new;
        taken += 1;
    }
    q0.store(&mut st.q, n);
    v0.store(&mut st.v, n);
    arrivals.restart(t, &st.q, &st.v);
    (t, taken)
}
