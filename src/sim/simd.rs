//! Vectors of f64 lanes for the fused, batch and chain kernels
//! (`sim::fused`, `sim::batch`, `sim::chain`): [`F64x4`] (AVX2), [`F64x8`]
//! (AVX-512F) and [`Pack`] (G of either, for more independent work per
//! instruction stream, or a whole ladder of blocks in the fused kernel),
//! behind one trait, [`Simd`], so that each kernel is written once and
//! compiled for both instruction sets; and the one vector sine and cosine
//! of them all, [`half_sin_cos`].
//!
//! Every operation is `#[inline(always)]` and has no `target_feature` of
//! its own: it is sound only inlined into a function compiled for the
//! instruction set (the kernels' `run_avx2` / `run_avx512` entry points,
//! which their callers reach only after checking the CPU), where each
//! compiles to one or two instructions. Every lane's arithmetic is the
//! scalar IEEE operation, without fused multiply-adds, so a kernel that
//! applies the portable path's operations in the portable path's order
//! gets its results bit for bit.

#![cfg(target_arch = "x86_64")]

use crate::model::params::R;
use crate::model::trig::{self, consts::*};
use std::arch::x86_64::*;
use std::ops::{Add, BitAnd, BitOr, BitXor, Div, Mul, Neg, Sub};

/// Evaluates intrinsics; sound only inside a function compiled for the
/// instruction set (see the module documentation).
macro_rules! simd {
    ($e:expr) => {
        // SAFETY: only reached inlined into a function compiled for the
        // instruction set, which its caller checked the CPU has.
        unsafe { $e }
    };
}

/// Most lanes of one [`Simd`] value: the fused kernel's eight registers of
/// four (N ≤ 32).
pub const MAX_LANES: usize = 32;

/// A vector of `LANES` (≤ [`MAX_LANES`]) f64 lanes with lane-wise IEEE
/// arithmetic.
pub trait Simd:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + BitAnd<Output = Self>
    + BitOr<Output = Self>
    + BitXor<Output = Self>
    + Neg<Output = Self>
{
    const LANES: usize;
    fn splat(x: f64) -> Self;
    /// Lanes from `p[0..LANES]`.
    ///
    /// # Safety
    /// `p` must be valid for `LANES` reads.
    unsafe fn load(p: *const f64) -> Self;
    /// Writes the lanes to `p[0..LANES]`.
    ///
    /// # Safety
    /// `p` must be valid for `LANES` writes.
    unsafe fn store(self, p: *mut f64);
    fn sqrt(self) -> Self;
    /// `other` where the sign bit of `selector`'s lane is set, else `self`.
    fn select(self, other: Self, selector: Self) -> Self;
    /// Each lane's bits as a 64-bit integer plus `add`, shifted left by
    /// `by`: bit b of a lane becomes its sign bit for `by` = 63 − b.
    fn shift_left(self, by: i32, add: i64) -> Self;
    /// Bit l set where lane l of `self` ≤ `o` (false for NaN).
    fn le_bits(self, o: Self) -> u64;
    /// Bit l set where lane l of `self` ≥ `o` (false for NaN).
    fn ge_bits(self, o: Self) -> u64;
    /// Bit l set where lane l of `self` > `o` or either is NaN.
    fn not_le_bits(self, o: Self) -> u64;
    /// [a1, …, a(L−1), f0]: each lane's successor, `following` after the last.
    fn next(self, following: Self) -> Self;
    /// [p(L−1), a0, …, a(L−2)]: each lane's predecessor, `preceding` before
    /// the first.
    fn prev(self, preceding: Self) -> Self;

    #[inline(always)]
    fn abs(self) -> Self {
        let sign = Self::splat(-0.0);
        (self | sign) ^ sign
    }

    /// The lanes in an array of [`MAX_LANES`], zeros past `LANES`.
    #[inline(always)]
    fn to_array(self) -> [f64; MAX_LANES] {
        const { assert!(Self::LANES <= MAX_LANES) };
        let mut out = [0.0; MAX_LANES];
        // SAFETY: LANES ≤ MAX_LANES (asserted above).
        unsafe { self.store(out.as_mut_ptr()) };
        out
    }

    /// Lane `i`.
    #[inline(always)]
    fn lane(self, i: usize) -> f64 {
        self.to_array()[i]
    }

    /// Lanes from `f(l)`.
    #[inline(always)]
    fn from_fn(f: impl Fn(usize) -> f64) -> Self {
        const { assert!(Self::LANES <= MAX_LANES) };
        let a: [f64; MAX_LANES] = std::array::from_fn(|l| if l < Self::LANES { f(l) } else { 0.0 });
        // SAFETY: LANES ≤ MAX_LANES (asserted above).
        unsafe { Self::load(a.as_ptr()) }
    }
}

/// Four lanes in a 256-bit AVX2 register.
#[derive(Clone, Copy)]
pub struct F64x4(pub(crate) __m256d);

/// Eight lanes in a 512-bit AVX-512F register.
#[derive(Clone, Copy)]
pub struct F64x8(__m512d);

macro_rules! binary_ops {
    ($t:ident, $($trait:ident $method:ident $f:expr;)*) => {
        $(impl $trait for $t {
            type Output = Self;
            #[inline(always)]
            fn $method(self, o: Self) -> Self {
                Self(simd!($f(self.0, o.0)))
            }
        })*
    };
}

binary_ops!(F64x4,
    Add add _mm256_add_pd;
    Sub sub _mm256_sub_pd;
    Mul mul _mm256_mul_pd;
    Div div _mm256_div_pd;
    BitAnd bitand _mm256_and_pd;
    BitOr bitor _mm256_or_pd;
    BitXor bitxor _mm256_xor_pd;
);

impl F64x4 {
    /// Every bit of lane l set where lane l of `self` ≤ `o` (none for
    /// NaN): a selector for [`Simd::select`].
    #[inline(always)]
    pub fn le_mask(self, o: Self) -> Self {
        Self(simd!(_mm256_cmp_pd::<_CMP_LE_OQ>(self.0, o.0)))
    }
}

impl Neg for F64x4 {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self ^ Self::splat(-0.0)
    }
}

impl Simd for F64x4 {
    const LANES: usize = 4;

    #[inline(always)]
    fn splat(x: f64) -> Self {
        Self(simd!(_mm256_set1_pd(x)))
    }
    #[inline(always)]
    unsafe fn load(p: *const f64) -> Self {
        Self(simd!(_mm256_loadu_pd(p)))
    }
    #[inline(always)]
    unsafe fn store(self, p: *mut f64) {
        simd!(_mm256_storeu_pd(p, self.0))
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Self(simd!(_mm256_sqrt_pd(self.0)))
    }
    #[inline(always)]
    fn select(self, other: Self, selector: Self) -> Self {
        Self(simd!(_mm256_blendv_pd(self.0, other.0, selector.0)))
    }
    #[inline(always)]
    fn shift_left(self, by: i32, add: i64) -> Self {
        let bits = simd!(_mm256_add_epi64(
            _mm256_castpd_si256(self.0),
            _mm256_set1_epi64x(add)
        ));
        let moved = simd!(_mm256_sll_epi64(bits, _mm_cvtsi32_si128(by)));
        Self(simd!(_mm256_castsi256_pd(moved)))
    }
    #[inline(always)]
    fn le_bits(self, o: Self) -> u64 {
        simd!(_mm256_movemask_pd(_mm256_cmp_pd::<_CMP_LE_OQ>(self.0, o.0))) as u64
    }
    #[inline(always)]
    fn ge_bits(self, o: Self) -> u64 {
        simd!(_mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GE_OQ>(self.0, o.0))) as u64
    }
    #[inline(always)]
    fn not_le_bits(self, o: Self) -> u64 {
        simd!(_mm256_movemask_pd(_mm256_cmp_pd::<_CMP_NLE_UQ>(
            self.0, o.0
        ))) as u64
    }
    #[inline(always)]
    fn next(self, following: Self) -> Self {
        let (a, b) = (self.0, following.0);
        // [a1, a2, a3, b0]
        Self(simd!(_mm256_shuffle_pd::<0b0101>(
            a,
            _mm256_permute2f128_pd::<0x21>(a, b)
        )))
    }
    #[inline(always)]
    fn prev(self, preceding: Self) -> Self {
        let (p, a) = (preceding.0, self.0);
        // [p3, a0, a1, a2]
        Self(simd!(_mm256_shuffle_pd::<0b0101>(
            _mm256_permute2f128_pd::<0x21>(p, a),
            a
        )))
    }
}

#[inline(always)]
fn bits512(x: __m512d) -> __m512i {
    simd!(_mm512_castpd_si512(x))
}

#[inline(always)]
fn float512(x: __m512i) -> __m512d {
    simd!(_mm512_castsi512_pd(x))
}

binary_ops!(F64x8,
    Add add _mm512_add_pd;
    Sub sub _mm512_sub_pd;
    Mul mul _mm512_mul_pd;
    Div div _mm512_div_pd;
);

macro_rules! bit_ops_512 {
    ($($trait:ident $method:ident $f:ident;)*) => {
        $(impl $trait for F64x8 {
            type Output = Self;
            #[inline(always)]
            fn $method(self, o: Self) -> Self {
                Self($f(self.0, o.0))
            }
        })*
    };
}

bit_ops_512!(BitAnd bitand and512; BitOr bitor or512; BitXor bitxor xor512;);

#[inline(always)]
fn and512(a: __m512d, b: __m512d) -> __m512d {
    float512(simd!(_mm512_and_si512(bits512(a), bits512(b))))
}

#[inline(always)]
fn or512(a: __m512d, b: __m512d) -> __m512d {
    float512(simd!(_mm512_or_si512(bits512(a), bits512(b))))
}

#[inline(always)]
fn xor512(a: __m512d, b: __m512d) -> __m512d {
    float512(simd!(_mm512_xor_si512(bits512(a), bits512(b))))
}

impl Neg for F64x8 {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self ^ Self::splat(-0.0)
    }
}

impl Simd for F64x8 {
    const LANES: usize = 8;

    #[inline(always)]
    fn splat(x: f64) -> Self {
        Self(simd!(_mm512_set1_pd(x)))
    }
    #[inline(always)]
    unsafe fn load(p: *const f64) -> Self {
        Self(simd!(_mm512_loadu_pd(p)))
    }
    #[inline(always)]
    unsafe fn store(self, p: *mut f64) {
        simd!(_mm512_storeu_pd(p, self.0))
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Self(simd!(_mm512_sqrt_pd(self.0)))
    }
    #[inline(always)]
    fn select(self, other: Self, selector: Self) -> Self {
        let mask = simd!(_mm512_cmplt_epi64_mask(
            bits512(selector.0),
            _mm512_setzero_si512()
        ));
        Self(simd!(_mm512_mask_blend_pd(mask, self.0, other.0)))
    }
    #[inline(always)]
    fn shift_left(self, by: i32, add: i64) -> Self {
        let bits = simd!(_mm512_add_epi64(bits512(self.0), _mm512_set1_epi64(add)));
        Self(float512(simd!(_mm512_sll_epi64(
            bits,
            _mm_cvtsi32_si128(by)
        ))))
    }
    #[inline(always)]
    fn le_bits(self, o: Self) -> u64 {
        simd!(_mm512_cmp_pd_mask::<_CMP_LE_OQ>(self.0, o.0)) as u64
    }
    #[inline(always)]
    fn ge_bits(self, o: Self) -> u64 {
        simd!(_mm512_cmp_pd_mask::<_CMP_GE_OQ>(self.0, o.0)) as u64
    }
    #[inline(always)]
    fn not_le_bits(self, o: Self) -> u64 {
        simd!(_mm512_cmp_pd_mask::<_CMP_NLE_UQ>(self.0, o.0)) as u64
    }
    #[inline(always)]
    fn next(self, following: Self) -> Self {
        // [a1, …, a7, f0]
        Self(float512(simd!(_mm512_alignr_epi64::<1>(
            bits512(following.0),
            bits512(self.0)
        ))))
    }
    #[inline(always)]
    fn prev(self, preceding: Self) -> Self {
        // [p7, a0, …, a6]
        Self(float512(simd!(_mm512_alignr_epi64::<7>(
            bits512(self.0),
            bits512(preceding.0)
        ))))
    }
}

/// G vectors side by side as one of G · V::LANES lanes: G independent
/// instruction streams for the processor to overlap.
#[derive(Clone, Copy)]
pub struct Pack<V, const G: usize>(pub(crate) [V; G]);

macro_rules! pack_ops {
    ($($trait:ident $method:ident;)*) => {
        $(impl<V: Simd, const G: usize> $trait for Pack<V, G> {
            type Output = Self;
            #[inline(always)]
            fn $method(mut self, o: Self) -> Self {
                for g in 0..G {
                    self.0[g] = self.0[g].$method(o.0[g]);
                }
                self
            }
        })*
    };
}

pack_ops!(Add add; Sub sub; Mul mul; Div div; BitAnd bitand; BitOr bitor; BitXor bitxor;);

impl<V: Simd, const G: usize> Neg for Pack<V, G> {
    type Output = Self;
    #[inline(always)]
    fn neg(mut self) -> Self {
        for g in 0..G {
            self.0[g] = -self.0[g];
        }
        self
    }
}

/// A lane mask of a [`Pack`] from its vectors' masks.
macro_rules! pack_bits {
    ($a:expr, $b:expr, $method:ident) => {{
        let mut bits = 0;
        for g in 0..G {
            bits |= $a.0[g].$method($b.0[g]) << (g * V::LANES);
        }
        bits
    }};
}

impl<V: Simd, const G: usize> Simd for Pack<V, G> {
    const LANES: usize = G * V::LANES;

    #[inline(always)]
    fn splat(x: f64) -> Self {
        Self([V::splat(x); G])
    }
    #[inline(always)]
    unsafe fn load(p: *const f64) -> Self {
        let mut out = [V::splat(0.0); G];
        for g in 0..G {
            // SAFETY: the caller guarantees G · V::LANES readable values.
            out[g] = unsafe { V::load(p.add(g * V::LANES)) };
        }
        Self(out)
    }
    #[inline(always)]
    unsafe fn store(self, p: *mut f64) {
        for g in 0..G {
            // SAFETY: the caller guarantees G · V::LANES writable values.
            unsafe { self.0[g].store(p.add(g * V::LANES)) };
        }
    }
    #[inline(always)]
    fn sqrt(mut self) -> Self {
        for g in 0..G {
            self.0[g] = self.0[g].sqrt();
        }
        self
    }
    #[inline(always)]
    fn select(mut self, other: Self, selector: Self) -> Self {
        for g in 0..G {
            self.0[g] = self.0[g].select(other.0[g], selector.0[g]);
        }
        self
    }
    #[inline(always)]
    fn shift_left(mut self, by: i32, add: i64) -> Self {
        for g in 0..G {
            self.0[g] = self.0[g].shift_left(by, add);
        }
        self
    }
    #[inline(always)]
    fn le_bits(self, o: Self) -> u64 {
        pack_bits!(self, o, le_bits)
    }
    #[inline(always)]
    fn ge_bits(self, o: Self) -> u64 {
        pack_bits!(self, o, ge_bits)
    }
    #[inline(always)]
    fn not_le_bits(self, o: Self) -> u64 {
        pack_bits!(self, o, not_le_bits)
    }
    #[inline(always)]
    fn next(mut self, following: Self) -> Self {
        let a = self.0;
        for g in 0..G {
            let f = if g + 1 < G { a[g + 1] } else { following.0[0] };
            self.0[g] = a[g].next(f);
        }
        self
    }
    #[inline(always)]
    fn prev(mut self, preceding: Self) -> Self {
        let a = self.0;
        for g in 0..G {
            let p = if g > 0 { a[g - 1] } else { preceding.0[G - 1] };
            self.0[g] = a[g].prev(p);
        }
        self
    }
}

/// 1.5 · 2^52: x + this − this rounds x (|x| < 2^51) to an integer, ties
/// to even, exactly as `f64::round_ties_even`.
const ROUNDING: f64 = 6_755_399_441_055_744.0;

/// (c0 + z c1) + z² (c2 + z c3) + z⁴ (c4 + z c5): `trig::kernels`' Estrin form.
#[inline(always)]
fn estrin<S: Simd>(c: [f64; 6], z: S, z2: S, z4: S) -> S {
    let low = S::splat(c[0]) + z * S::splat(c[1]);
    let mid = S::splat(c[2]) + z * S::splat(c[3]);
    let high = S::splat(c[4]) + z * S::splat(c[5]);
    (low + z2 * mid) + z4 * high
}

/// r sin x and r cos x lane by lane with r = 1/2: r times
/// `trig::sin_cos_slice`, bit for bit (the factor, a power of two, is
/// applied to the reduced argument and to the constant term of the cosine).
/// The one vector sine and cosine of the fused, batch and chain kernels.
#[inline(always)]
pub fn half_sin_cos<S: Simd>(x: S) -> (S, S) {
    const _: () = assert!(R == 0.5);
    // k = round-half-even(x 2/π) by the 1.5 · 2^52 trick, which leaves
    // k mod 4 (the quadrant) in the low bits of `shifted`.
    let shifted = x * S::splat(FRAC_2_PI) + S::splat(ROUNDING);
    let k = shifted - S::splat(ROUNDING);
    let r = ((x - k * S::splat(PIO2_1)) - k * S::splat(PIO2_2)) - k * S::splat(PIO2_2T);
    let z = r * r;
    let z2 = z * z;
    let z4 = z2 * z2;
    let rr = r * S::splat(R);
    let ps = rr + (rr * z) * estrin([S1, S2, S3, S4, S5, S6], z, z2, z4);
    let pc = (S::splat(R) - z * S::splat(0.5 * R))
        + (z2 * S::splat(R)) * estrin([C1, C2, C3, C4, C5, C6], z, z2, z4);
    // Quadrant q = k mod 4: odd q swaps the kernels; q ∈ {2, 3} negates the
    // sine, q ∈ {1, 2} (bit 1 of q + 1) the cosine.
    let odd = shifted.shift_left(63, 0);
    let sign = S::splat(-0.0);
    let s = ps.select(pc, odd) ^ (shifted.shift_left(62, 0) & sign);
    let c = pc.select(ps, odd) ^ (shifted.shift_left(62, 1) & sign);
    // Arguments beyond the reduction (or NaN) go to the library.
    if x.abs().not_le_bits(S::splat(trig::REDUCE_LIMIT)) == 0 {
        (s, c)
    } else {
        library_half_sin_cos(x)
    }
}

#[cold]
#[inline(never)]
fn library_half_sin_cos<S: Simd>(x: S) -> (S, S) {
    let xs = x.to_array();
    let (mut s, mut c) = ([0.0; MAX_LANES], [0.0; MAX_LANES]);
    trig::sin_cos_slice(&xs[..S::LANES], &mut s, &mut c);
    (S::from_fn(|l| R * s[l]), S::from_fn(|l| R * c[l]))
}

/// θ and θ̇ of every block at one time, the blocks in C registers of
/// four lanes (the fused kernels' layout).
pub(crate) type Angles<const C: usize> = (f64, Pack<F64x4, C>, Pack<F64x4, C>);

/// The exact arrival test (`ArrivalDetector::try_record`) on the
/// candidate lanes of a step of the kernels that hold the ladder in
/// registers (`sim::fused`, `sim::terms_rk4`), in block order: the
/// blocks that arrived, as a bit mask.
#[cold]
#[inline(never)]
pub(crate) fn record_arrivals<const C: usize>(
    arrivals: &mut crate::sim::observables::ArrivalDetector,
    candidates: u64,
    before: Angles<C>,
    after: Angles<C>,
) -> u64 {
    let mut arrived = 0;
    for i in (0..4 * C).filter(|i| candidates >> i & 1 == 1) {
        let at = |(t, th, om): Angles<C>| (t, th.lane(i), om.lane(i));
        if arrivals.try_record(i, at(before), at(after)) {
            arrived |= 1 << i;
        }
    }
    arrived
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::sim::Isa;

    /// Angles to test sine and cosine at: a dense sweep, multiples of π/2
    /// and just past them, signed zeros, large, infinite and NaN.
    pub(crate) fn sin_cos_inputs() -> Vec<f64> {
        let quarter = std::f64::consts::FRAC_PI_2;
        let mut xs: Vec<f64> = (-4000..4000).map(|k| k as f64 * 0.0123 + 1e-3).collect();
        xs.extend((-8..8).flat_map(|k| [k as f64 * quarter, k as f64 * quarter + 1e-12]));
        xs.extend([
            0.0,
            -0.0,
            823_549.0,
            823_551.0,
            -3e7,
            1e300,
            f64::INFINITY,
            f64::NAN,
        ]);
        xs
    }

    /// The same f64, or both NaN.
    pub(crate) fn same(a: f64, b: f64) -> bool {
        a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
    }

    fn check<S: Simd>(xs: &[f64], f: impl Fn(&[f64]) -> (Vec<f64>, Vec<f64>)) {
        let mut xs = xs.to_vec();
        xs.resize(xs.len().div_ceil(S::LANES) * S::LANES, 0.5);
        for chunk in xs.chunks_exact(S::LANES) {
            let (s, c) = f(chunk);
            let (mut ws, mut wc) = (vec![0.0; chunk.len()], vec![0.0; chunk.len()]);
            trig::sin_cos_slice(chunk, &mut ws, &mut wc);
            for i in 0..chunk.len() {
                assert!(
                    same(s[i], R * ws[i]) && same(c[i], R * wc[i]),
                    "x = {}",
                    chunk[i]
                );
            }
        }
    }

    fn run<S: Simd>(x: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let (s, c) = half_sin_cos(S::from_fn(|l| x[l]));
        let lanes = |v: S| (0..S::LANES).map(|l| v.lane(l)).collect();
        (lanes(s), lanes(c))
    }

    #[target_feature(enable = "avx2")]
    fn run_avx2<S: Simd>(x: &[f64]) -> (Vec<f64>, Vec<f64>) {
        run::<S>(x)
    }

    #[target_feature(enable = "avx2,avx512f")]
    fn run_avx512(x: &[f64]) -> (Vec<f64>, Vec<f64>) {
        run::<F64x8>(x)
    }

    #[test]
    fn half_sin_cos_is_half_the_portable_sin_cos_bit_for_bit() {
        let xs = sin_cos_inputs();
        if Isa::Avx2.available() {
            // SAFETY: the CPU has AVX2, checked above. The batch and chain
            // kernels' packs (2), the fused kernel's ladders of N ≤ 12 (3)
            // and its largest, N ≤ 32 (8 registers, MAX_LANES).
            check::<Pack<F64x4, 2>>(&xs, |x| unsafe { run_avx2::<Pack<F64x4, 2>>(x) });
            check::<Pack<F64x4, 3>>(&xs, |x| unsafe { run_avx2::<Pack<F64x4, 3>>(x) });
            check::<Pack<F64x4, 8>>(&xs, |x| unsafe { run_avx2::<Pack<F64x4, 8>>(x) });
        }
        if Isa::Avx512.available() {
            // SAFETY: the CPU has AVX-512F, checked above.
            check::<F64x8>(&xs, |x| unsafe { run_avx512(x) });
        }
    }

    #[target_feature(enable = "avx2,avx512f")]
    fn shifts_avx512() -> (Vec<f64>, Vec<f64>) {
        let a = F64x8::from_fn(|l| l as f64);
        let b = F64x8::from_fn(|l| 10.0 + l as f64);
        let lanes = |v: F64x8| (0..8).map(|l| v.lane(l)).collect();
        (lanes(a.next(b)), lanes(b.prev(a)))
    }

    #[target_feature(enable = "avx2")]
    fn shifts_avx2() -> (Vec<f64>, Vec<f64>) {
        type P = Pack<F64x4, 2>;
        let a = P::from_fn(|l| l as f64);
        let b = P::from_fn(|l| 10.0 + l as f64);
        let lanes = |v: P| (0..8).map(|l| v.lane(l)).collect();
        (lanes(a.next(b)), lanes(b.prev(a)))
    }

    #[test]
    fn lane_shifts_bring_the_neighbours() {
        let next = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 10.0];
        let prev = [7.0, 10.0, 11.0, 12.0, 13.0, 14.0, 15.0, 16.0];
        if Isa::Avx2.available() {
            // SAFETY: the CPU has AVX2.
            let (n, p) = unsafe { shifts_avx2() };
            assert_eq!((n.as_slice(), p.as_slice()), (&next[..], &prev[..]));
        }
        if Isa::Avx512.available() {
            // SAFETY: the CPU has AVX-512F.
            let (n, p) = unsafe { shifts_avx512() };
            assert_eq!((n.as_slice(), p.as_slice()), (&next[..], &prev[..]));
        }
    }
}
