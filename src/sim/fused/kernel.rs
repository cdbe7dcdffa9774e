//! The fused step on whole ladders of 256-bit registers.
//!
//! [`Lanes`] holds one quantity for every block (or spring), four to a
//! register, and does arithmetic lane by lane, so the step below reads like
//! the portable `gradient_body`. Its operations are `#[inline(always)]`
//! wrappers of AVX intrinsics without a `target_feature` of their own: they
//! are only ever inlined into [`run_avx2`] or [`run_avx512`], which carry
//! the instruction set, and there compile to single instructions on
//! registers. Small loops over the C registers of a quantity unroll
//! completely, so the whole state stays in registers across steps.
//!
//! Keep closures and runtime indices out of the step: a closure is not
//! `#[inline(always)]`, and one left out of line compiles without AVX and
//! calls every intrinsic (the run took 220 ms instead of 30 when that
//! happened); an index the compiler cannot resolve sends a whole quantity
//! to the stack.

use super::{Batch, Isa};
use crate::model::ladder::parity;
use crate::model::params::{M, R};
use crate::sim::observables::ArrivalDetector;
use crate::sim::protocol::{Drive, Piece};
use crate::sim::rhs::{Rhs, State};
use crate::sim::simd::{F64x4, Pack, Simd, half_sin_cos, record_arrivals};
use std::arch::x86_64::*;

// r = s/2 is folded into sin and cos below; that is exact only for a power
// of two.
const _: () = assert!(R == 0.5);

/// What one batch needs besides the state.
pub struct Job<'r, 'a> {
    pub rhs: &'r Rhs<'a>,
    pub batch: &'r Batch,
    /// Symplectic Euler's (decay, kick) for X, Y, θ of every free block.
    pub factors: ([f64; 3], [f64; 3]),
}

/// Runs `job` with the kernel for `isa` and `chunks` registers per
/// quantity (N ≤ 4 · chunks); returns the time reached.
///
/// # Safety
/// The CPU must support `isa`.
pub unsafe fn run(
    isa: Isa,
    chunks: usize,
    job: &Job,
    st: &mut State,
    arrivals: &mut ArrivalDetector,
) -> f64 {
    macro_rules! dispatch {
        ($entry:ident) => {
            // SAFETY: the caller guarantees the instruction set.
            unsafe {
                match chunks {
                    1 => $entry::<1>(job, st, arrivals),
                    2 => $entry::<2>(job, st, arrivals),
                    3 => $entry::<3>(job, st, arrivals),
                    4 => $entry::<4>(job, st, arrivals),
                    5 => $entry::<5>(job, st, arrivals),
                    6 => $entry::<6>(job, st, arrivals),
                    7 => $entry::<7>(job, st, arrivals),
                    _ => $entry::<8>(job, st, arrivals),
                }
            }
        };
    }
    match isa {
        Isa::Avx2 => dispatch!(run_avx2),
        Isa::Avx512 => dispatch!(run_avx512),
    }
}

#[target_feature(enable = "avx2")]
unsafe fn run_avx2<const C: usize>(
    job: &Job,
    st: &mut State,
    arrivals: &mut ArrivalDetector,
) -> f64 {
    run_body::<C>(job, st, arrivals)
}

/// The same code with 32 vector registers instead of 16.
#[target_feature(enable = "avx2,avx512f,avx512vl")]
unsafe fn run_avx512<const C: usize>(
    job: &Job,
    st: &mut State,
    arrivals: &mut ArrivalDetector,
) -> f64 {
    run_body::<C>(job, st, arrivals)
}

/// Evaluates intrinsics; sound only inside `run_avx2`/`run_avx512`, into
/// which everything here is inlined.
macro_rules! avx {
    ($e:expr) => {
        // SAFETY: only reached inlined into a function compiled for AVX2.
        unsafe { $e }
    };
}

/// One quantity for 4C blocks: lane l of register c is block 4c + l
/// (`sim::simd`'s [`Pack`] of C AVX2 registers, the type the batch and
/// chain kernels use too).
type Lanes<const C: usize> = Pack<F64x4, C>;

/// What the fused step asks of [`Lanes`] beyond [`Simd`].
trait Blocks: Simd {
    /// The same register in every one of the C.
    fn splat_vec(v: __m256d) -> Self;
    /// `self` with block 1 (lane 0) set to `x`.
    fn with_first(self, x: f64) -> Self;
    /// Bit i set where lane i ≤ `lo` or ≥ `hi` (false for NaN): one mask
    /// per register, as `le_bits | ge_bits` with half the mask moves.
    fn outside_bits(self, lo: Self, hi: Self) -> u64;
}

impl<const C: usize> Blocks for Lanes<C> {
    #[inline(always)]
    fn splat_vec(v: __m256d) -> Self {
        Pack([F64x4(v); C])
    }

    #[inline(always)]
    fn with_first(mut self, x: f64) -> Self {
        self.0[0] = F64x4(avx!(_mm256_blend_pd::<0b0001>(
            self.0[0].0,
            _mm256_set1_pd(x)
        )));
        self
    }

    #[inline(always)]
    fn outside_bits(self, lo: Self, hi: Self) -> u64 {
        let mut bits = 0;
        for c in 0..C {
            let (x, lo, hi) = (self.0[c].0, lo.0[c].0, hi.0[c].0);
            let outside = avx!(_mm256_or_pd(
                _mm256_cmp_pd::<_CMP_LE_OQ>(x, lo),
                _mm256_cmp_pd::<_CMP_GE_OQ>(x, hi)
            ));
            bits |= (avx!(_mm256_movemask_pd(outside)) as u64) << (4 * c);
        }
        bits
    }
}

/// Per-lane constants of a batch.
struct Constants<const C: usize> {
    /// −0.0 where (−1)^n = −1, else +0.0, for each block (p0) and the block
    /// below it (p1): xor applies the parity exactly. The pattern repeats
    /// every four blocks, so every register is the same.
    parity_sign: (Lanes<C>, Lanes<C>),
    /// All ones for a spring between two real blocks, zero otherwise.
    spring_mask: Lanes<C>,
    /// Symplectic Euler's decay and kick for X, Y and θ, the same for every
    /// free block (block 1 is overwritten by the drive; the padding lanes
    /// move freely, their springs masked).
    decay: [f64; 3],
    kick: [f64; 3],
    a_rest: f64,
    b_rest: f64,
    /// Whether the last register holds at most two real springs, and the
    /// rest lengths [a, a, b, b] for its packed A and B halves.
    pack_last: bool,
    packed_rest: __m256d,
    minus_g: f64,
}

impl<const C: usize> Constants<C> {
    #[inline(always)]
    fn new(job: &Job, n: usize) -> Self {
        let sign = |from: usize| {
            let p = |l: usize| if parity(from + l) < 0.0 { -0.0 } else { 0.0 };
            Lanes::splat_vec(avx!(_mm256_setr_pd(p(0), p(1), p(2), p(3))))
        };
        let ones = f64::from_bits(u64::MAX);
        let (factors, ladder) = (job.factors, job.rhs.ladder);
        Self {
            parity_sign: (sign(0), sign(1)),
            spring_mask: Lanes::from_fn(|i| if i + 1 < n { ones } else { 0.0 }),
            decay: factors.0,
            kick: factors.1,
            a_rest: ladder.a,
            b_rest: ladder.params.b,
            pack_last: (n - 1) as i64 - 4 * (C as i64 - 1) <= 2,
            packed_rest: avx!(_mm256_setr_pd(
                ladder.a,
                ladder.a,
                ladder.params.b,
                ladder.params.b
            )),
            minus_g: -(M * ladder.params.gravity),
        }
    }
}

/// The x position of padding lane `i`: far from every block.
fn far(i: usize) -> f64 {
    1e3 * i as f64
}

/// X, Y and θ (or their rates, or per-coordinate factors) of every block.
/// Named fields, never indexed at run time, so that they stay in registers.
#[derive(Clone, Copy)]
struct Coords<const C: usize> {
    x: Lanes<C>,
    y: Lanes<C>,
    theta: Lanes<C>,
}

impl<const C: usize> Coords<C> {
    /// From `f(k)` for coordinate k = 0 (X), 1 (Y), 2 (θ).
    #[inline(always)]
    fn from_fn(f: impl Fn(usize) -> Lanes<C>) -> Self {
        Self {
            x: f(0),
            y: f(1),
            theta: f(2),
        }
    }

    /// The model's layout [X_1, Y_1, θ_1, X_2, ...] of `n` blocks; lanes
    /// past the last block from `pad(k, lane)`.
    #[inline(always)]
    fn load(table: &[f64], n: usize, pad: fn(usize, usize) -> f64) -> Self {
        Self::from_fn(|k| Lanes::from_fn(|i| if i < n { table[3 * i + k] } else { pad(k, i) }))
    }

    #[inline(always)]
    fn store(&self, table: &mut [f64], n: usize) {
        for (k, lanes) in [self.x, self.y, self.theta].into_iter().enumerate() {
            let values = lanes.to_array();
            table[k..]
                .iter_mut()
                .step_by(3)
                .zip(&values[..n])
                .for_each(|(t, v)| *t = *v);
        }
    }
}

/// The state in registers: positions and velocities. Lanes past the last
/// block hold blocks at rest, far apart, whose springs are masked out.
#[derive(Clone, Copy)]
struct Regs<const C: usize> {
    q: Coords<C>,
    v: Coords<C>,
}

impl<const C: usize> Regs<C> {
    #[inline(always)]
    fn load(st: &State, n: usize) -> Self {
        Self {
            q: Coords::load(&st.q, n, |k, i| if k == 0 { far(i) } else { 0.0 }),
            v: Coords::load(&st.v, n, |_, _| 0.0),
        }
    }

    #[inline(always)]
    fn store(&self, st: &mut State, n: usize) {
        self.q.store(&mut st.q, n);
        self.v.store(&mut st.v, n);
    }
}

/// 1 − a/√(L_A²) and 1 − b/√(L_B²) for every spring: `k (L − ℓ)/L`.
///
/// The square roots and divisions share one unit, the narrowest of the
/// step; where the last register holds at most two real springs, its A and
/// B halves go through that unit together (same operations on the same
/// numbers, so the same results).
#[inline(always)]
fn stretch<const C: usize>(la2: Lanes<C>, lb2: Lanes<C>, k: &Constants<C>) -> (Lanes<C>, Lanes<C>) {
    let one = avx!(_mm256_set1_pd(1.0));
    let factor = |rest: __m256d, l2: __m256d| {
        avx!(_mm256_sub_pd(one, _mm256_div_pd(rest, _mm256_sqrt_pd(l2))))
    };
    let (a, b) = (
        avx!(_mm256_set1_pd(k.a_rest)),
        avx!(_mm256_set1_pd(k.b_rest)),
    );
    let (mut ka, mut kb) = (la2, lb2);
    if k.pack_last {
        for c in 0..C - 1 {
            ka.0[c].0 = factor(a, la2.0[c].0);
            kb.0[c].0 = factor(b, lb2.0[c].0);
        }
        let last = C - 1;
        // [A0, A1, B0, B1] → [kA0, kA1, kB0, kB1].
        let both = avx!(_mm256_permute2f128_pd::<0x20>(la2.0[last].0, lb2.0[last].0));
        let f = factor(k.packed_rest, both);
        ka.0[last].0 = f;
        kb.0[last].0 = avx!(_mm256_permute2f128_pd::<0x11>(f, f));
    } else {
        for c in 0..C {
            ka.0[c].0 = factor(a, la2.0[c].0);
            kb.0[c].0 = factor(b, lb2.0[c].0);
        }
    }
    (ka, kb)
}

/// ∂E/∂q for every block: `Ladder::gradient_with`, operation for
/// operation, with (r sin θ, r cos θ) in place of (sin θ, cos θ): the spring
/// offsets r(t_{n+1} − t_n) and the torque arms r t' need no multiplication
/// by r, and the parity (−1)^n is a sign flip.
#[inline(always)]
fn gradient<const C: usize>(r: &Regs<C>, k: &Constants<C>) -> Coords<C> {
    let Coords { x, y, theta } = r.q;
    let (rs0, rc0) = half_sin_cos(theta);
    let (p0, p1) = k.parity_sign;
    // Spring j joins block j (…0) to block j + 1 (…1).
    let pad = Lanes::splat;
    let (rs1, rc1) = (rs0.next(pad(0.0)), rc0.next(pad(R)));
    let (ex, ey) = (x.next(pad(far(4 * C))) - x, y.next(pad(0.0)) - y);
    let (ux, uy) = (rs1 - rs0, (rc1 ^ p1) - (rc0 ^ p0));
    let (ax, ay, bx, by) = (ex - ux, ey - uy, ex + ux, ey + uy);
    let (ka, kb) = stretch(ax * ax + ay * ay, bx * bx + by * by, k);
    let (fax, fay, fbx, fby) = (ka * ax, ka * ay, kb * bx, kb * by);
    let (dfx, dfy) = (fbx - fax, fby - fay);
    let mask = k.spring_mask;
    let fx = (fax + fbx) & mask;
    let fy = (fay + fby) & mask;
    // Torques of spring j on its lower block (tu) and its upper block (tl).
    let tu = (dfx * rc1 - (dfy ^ p1) * rs1) & mask;
    let tl = ((dfx * rc0 - (dfy ^ p0) * rs0) ^ Lanes::splat(-0.0)) & mask;
    // Block i feels spring i − 1 from above and spring i from below.
    // Zero before the first block.
    let above = |s: Lanes<C>| s.prev(pad(0.0));
    Coords {
        x: (above(fx) + pad(k.minus_g)) - fx,
        y: above(fy) - fy,
        theta: above(tu) + tl,
    }
}

/// One step of symplectic Euler: v ← v d − ∂E/∂q · (h M⁻¹ d), q ← q + h v.
#[inline(always)]
fn step<const C: usize>(r: &mut Regs<C>, k: &Constants<C>, h: f64) {
    let g = gradient(r, k);
    let s = Lanes::<C>::splat;
    let ([dx, dy, dt], [kx, ky, kt]) = (k.decay, k.kick);
    r.v.x = r.v.x * s(dx) - g.x * s(kx);
    r.v.y = r.v.y * s(dy) - g.y * s(ky);
    r.v.theta = r.v.theta * s(dt) - g.theta * s(kt);
    r.q.x = r.q.x + r.v.x * s(h);
    r.q.y = r.q.y + r.v.y * s(h);
    r.q.theta = r.q.theta + r.v.theta * s(h);
}

/// Block 1's drive with the piece last used.
struct DriveAt<'d> {
    drive: &'d Drive,
    clamp: [f64; 2],
    piece: Piece,
}

impl DriveAt<'_> {
    /// Sets block 1 to the protocol's state at `t`, as `Rhs::constrain`,
    /// looking the drive's piece up again only when `t` leaves it.
    #[inline(always)]
    fn constrain<const C: usize>(&mut self, r: &mut Regs<C>, t: f64) {
        if !self.piece.contains(t) {
            self.piece = self.drive.piece(t);
        }
        r.q.x = r.q.x.with_first(self.clamp[0]);
        r.q.y = r.q.y.with_first(self.clamp[1]);
        r.q.theta = r.q.theta.with_first(self.piece.theta(t));
        r.v.x = r.v.x.with_first(0.0);
        r.v.y = r.v.y.with_first(0.0);
        r.v.theta = r.v.theta.with_first(self.piece.omega());
    }
}

/// The batch of `job` on `st`: load, step with the drive and the arrival
/// check after each step, store. Returns the time reached.
#[inline(always)]
fn run_body<const C: usize>(job: &Job, st: &mut State, arrivals: &mut ArrivalDetector) -> f64 {
    let n = st.q.len() / 3;
    let k = Constants::<C>::new(job, n);
    // Candidate windows (lo, hi) of `ArrivalDetector::is_candidate`; the
    // padding lanes are never pending.
    let window_lo = Lanes::<C>::from_fn(|i| if i < n { arrivals.window(i)[0] } else { 0.0 });
    let window_hi = Lanes::<C>::from_fn(|i| if i < n { arrivals.window(i)[1] } else { 0.0 });
    let mut pending = arrivals.pending_mask();
    let mut r = Regs::<C>::load(st, n);
    let batch = job.batch;
    let mut t = batch.t;
    let mut drive = job.rhs.drive().map(|(drive, clamp)| DriveAt {
        drive,
        clamp,
        piece: drive.piece(t),
    });
    for step_k in 0..batch.count {
        let before = (t, r.q.theta, r.v.theta);
        step(&mut r, &k, batch.h);
        let t_new = batch.after(step_k, t);
        if let Some(d) = drive.as_mut() {
            d.constrain(&mut r, t_new);
        }
        // As `ArrivalDetector::is_candidate`, for every pending block; the
        // exact test (the sign of sin θ) in scalar code for candidates only.
        let candidates = r.q.theta.outside_bits(window_lo, window_hi) & pending;
        if candidates != 0 {
            pending &=
                !record_arrivals(arrivals, candidates, before, (t_new, r.q.theta, r.v.theta));
        }
        t = t_new;
    }
    r.store(st, n);
    arrivals.restart(t, &st.q, &st.v);
    t
}
