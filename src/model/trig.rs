//! Fast, inlinable transcendental functions for the force loop: a sin/cos
//! pair, and tanh for the pins' smoothed Coulomb friction ([`tanh`]).
//!
//! `f64::sin_cos` calls the C library's sin and cos separately, each with its
//! own range reduction; the force evaluation needs both for every block at
//! every step. This shares one Cody–Waite reduction by π/2 and evaluates the
//! fdlibm kernel polynomials (Sun Microsystems' minimax coefficients on
//! [−π/4, π/4]), accurate to about one ulp for |x| < 2^19 π/2; larger
//! arguments fall back to the library. The constants are quoted to fdlibm's
//! printed precision so that they can be checked against its source.
#![allow(clippy::excessive_precision)]

/// The reduction and kernel constants, shared with the vectorised copy in
/// `sim::fused`.
pub(crate) mod consts {
    pub const FRAC_2_PI: f64 = std::f64::consts::FRAC_2_PI;
    // π/2 split into three parts of 33, 33 and 53 bits (fdlibm pio2_1, pio2_2, pio2_2t).
    pub const PIO2_1: f64 = 1.570_796_326_734_125_614_17e0;
    pub const PIO2_2: f64 = 6.077_100_506_303_965_976_60e-11;
    pub const PIO2_2T: f64 = 2.022_266_248_795_950_631_54e-21;

    pub const S1: f64 = -1.666_666_666_666_663_243_48e-1;
    pub const S2: f64 = 8.333_333_333_322_489_461_24e-3;
    pub const S3: f64 = -1.984_126_982_985_794_931_34e-4;
    pub const S4: f64 = 2.755_731_370_707_006_767_89e-6;
    pub const S5: f64 = -2.505_076_025_340_686_341_95e-8;
    pub const S6: f64 = 1.589_690_995_211_550_102_21e-10;

    pub const C1: f64 = 4.166_666_666_666_660_190_37e-2;
    pub const C2: f64 = -1.388_888_888_887_410_957_49e-3;
    pub const C3: f64 = 2.480_158_728_947_672_941_78e-5;
    pub const C4: f64 = -2.755_731_435_139_066_330_35e-7;
    pub const C5: f64 = 2.087_572_321_298_174_827_90e-9;
    pub const C6: f64 = -1.135_964_755_778_819_482_65e-11;
}
use consts::*;

/// Largest |x| reduced here; beyond it the library is used.
pub(crate) const REDUCE_LIMIT: f64 = 823_550.0; // ≈ 2^19 · π/2

/// fdlibm's sine and cosine kernels on the reduced argument |r| ≤ π/4:
/// r + r z S(z) and 1 − z/2 + z² C(z) with z = r², the degree-5
/// polynomials S and C evaluated in Estrin's form
/// (a + z b) + z² (c + z d) + z⁴ (e + z f), which halves the chain of
/// dependent operations of Horner's rule at the same accuracy.
#[inline(always)]
pub fn kernels(r: f64) -> (f64, f64) {
    let z = r * r;
    let z2 = z * z;
    let z4 = z2 * z2;
    let estrin =
        |k: [f64; 6]| ((k[0] + z * k[1]) + z2 * (k[2] + z * k[3])) + z4 * (k[4] + z * k[5]);
    let ps = r + r * z * estrin([S1, S2, S3, S4, S5, S6]);
    let pc = (1.0 - 0.5 * z) + z2 * estrin([C1, C2, C3, C4, C5, C6]);
    (ps, pc)
}

/// (sin x, cos x).
#[inline(always)]
pub fn sin_cos(x: f64) -> (f64, f64) {
    if x.abs() > REDUCE_LIMIT || !x.is_finite() {
        return x.sin_cos();
    }
    let k = (x * FRAC_2_PI).round();
    let r = ((x - k * PIO2_1) - k * PIO2_2) - k * PIO2_2T;
    let (s, c) = kernels(r);
    match (k as i64) & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// sin and cos of every `x[i]` into `s[i]`, `c[i]`, branch-free so that
/// the compiler vectorises the loop; arguments beyond the reduction range
/// (or not finite) are redone with the library.
#[inline(always)]
pub fn sin_cos_slice(x: &[f64], s: &mut [f64], c: &mut [f64]) {
    let n = x.len().min(s.len()).min(c.len());
    let (x, s, c) = (&x[..n], &mut s[..n], &mut c[..n]);
    for i in 0..n {
        let k = (x[i] * FRAC_2_PI).round_ties_even();
        let r = ((x[i] - k * PIO2_1) - k * PIO2_2) - k * PIO2_2T;
        let (ps, pc) = kernels(r);
        // Quadrant k mod 4 as a float in {0, 1, 2, 3}.
        let quadrant = k - 4.0 * (k * 0.25).floor();
        let odd = quadrant == 1.0 || quadrant == 3.0;
        let sin_sign = if quadrant >= 2.0 { -1.0 } else { 1.0 };
        let cos_sign = if quadrant == 1.0 || quadrant == 2.0 {
            -1.0
        } else {
            1.0
        };
        s[i] = sin_sign * if odd { pc } else { ps };
        c[i] = cos_sign * if odd { ps } else { pc };
    }
    for i in 0..n {
        if x[i].is_nan() || x[i].abs() > REDUCE_LIMIT {
            (s[i], c[i]) = x[i].sin_cos();
        }
    }
}

/// ln 2 split as fdlibm's expm1 splits it (ln2_hi has 32 significant
/// bits, so k ln2_hi is exact for the |k| ≤ 64 used here), and 1/ln 2.
pub(crate) const LN2_HI: f64 = 6.931_471_803_691_238_164_90e-1;
pub(crate) const LN2_LO: f64 = 1.908_214_929_270_587_700_02e-10;
pub(crate) const INV_LN2: f64 = std::f64::consts::LOG2_E;
/// 1.5 × 2⁵²: x + ROUND − ROUND is x rounded to an integer for |x| < 2⁵¹.
pub(crate) const ROUND: f64 = 6_755_399_441_055_744.0;
/// 1/n! for n = 2…14: expm1's Taylor series on |r| ≤ ln2/2, whose first
/// term left out, r¹⁵/15!, is below 2 × 10⁻¹⁹ |r|.
pub(crate) const INV_FACTORIAL: [f64; 13] = [
    1.0 / 2.0,
    1.0 / 6.0,
    1.0 / 24.0,
    1.0 / 120.0,
    1.0 / 720.0,
    1.0 / 5_040.0,
    1.0 / 40_320.0,
    1.0 / 362_880.0,
    1.0 / 3_628_800.0,
    1.0 / 39_916_800.0,
    1.0 / 479_001_600.0,
    1.0 / 6_227_020_800.0,
    1.0 / 87_178_291_200.0,
];

/// e^y − 1 for −44 ≤ y ≤ 0, branch-free: y = k ln 2 + r with |r| ≤ ln2/2
/// (Cody and Waite's two-part ln 2), expm1(r) from its Taylor series, then
/// expm1(y) = 2ᵏ expm1(r) + (2ᵏ − 1), both terms of one sign or the
/// second exact and dominant. (`sim::terms_rk4::friction` has a copy over
/// vectors, the same operations in the same order.)
#[inline(always)]
fn expm1_negative(y: f64) -> f64 {
    // k = y / ln 2 rounded to the nearest integer (ties to even) by adding
    // and taking away 1.5 × 2⁵², which the baseline x86-64 (no SSE4.1
    // round) does in two additions, not a library call.
    let k = (y * INV_LN2 + ROUND) - ROUND;
    let r = (y - k * LN2_HI) - k * LN2_LO;
    let mut p = INV_FACTORIAL[12];
    for c in INV_FACTORIAL[..12].iter().rev() {
        p = c + r * p;
    }
    let em = r + r * r * p;
    // 2ᵏ from the integer k + 1023 in the exponent's bits: k + 1023 + 2⁵²
    // holds k + 1023 in its low mantissa bits.
    let biased = (k + 1023.0 + 4_503_599_627_370_496.0).to_bits();
    let two_k = f64::from_bits(biased << 52);
    two_k * em + (two_k - 1.0)
}

/// tanh x for |x| ≤ 22 (beyond, tanh rounds to ±1 and callers take that):
/// tanh |x| = −e / (2 + e) with e = expm1(−2|x|), the formula of fdlibm's
/// and the C library's tanh for |x| < 1, here for every |x|, with an
/// expm1 of our own ([`expm1_negative`]) and no branch, so that loops over
/// pins stay in registers. Within 3 ulp of the C library's `tanh` on
/// [−22, 22] (the test below; 3 at x = 0.1107, where the two formulas'
/// roundings add); about a third of the library call's cost,
/// which was 30 % of a pin-friction run. Not finite in, NaN out.
#[inline(always)]
pub fn tanh(x: f64) -> f64 {
    let e = expm1_negative(-2.0 * x.abs());
    (-e / (2.0 + e)).copysign(x)
}

#[cfg(test)]
mod tests {
    #[test]
    fn agrees_with_the_library() {
        let mut worst: f64 = 0.0;
        for k in -200_000..=200_000 {
            let x = k as f64 * 1.234_567e-4 + 0.5e-9 * (k as f64).sin();
            let (s, c) = super::sin_cos(x);
            worst = worst.max((s - x.sin()).abs()).max((c - x.cos()).abs());
        }
        for x in [1e3, -7e4, 8e5, 1e7, 0.0, -0.0] {
            let (s, c) = super::sin_cos(x);
            worst = worst.max((s - x.sin()).abs()).max((c - x.cos()).abs());
        }
        assert!(worst < 4e-16, "largest deviation {worst:e}");
        assert!(super::sin_cos(f64::NAN).0.is_nan());
    }

    #[test]
    fn slice_version_matches_scalar() {
        let x: Vec<f64> = (-3000..3000)
            .map(|k| k as f64 * 0.0173)
            .chain([1e7, -2e6])
            .collect();
        let (mut s, mut c) = (vec![0.0; x.len()], vec![0.0; x.len()]);
        super::sin_cos_slice(&x, &mut s, &mut c);
        for i in 0..x.len() {
            let (ws, wc) = super::sin_cos(x[i]);
            assert!(
                (s[i] - ws).abs() < 1e-16 && (c[i] - wc).abs() < 1e-16,
                "x = {}",
                x[i]
            );
        }
    }
    /// Units in the last place between `a` and `b` (same sign).
    fn ulps(a: f64, b: f64) -> u64 {
        (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs()
    }

    #[test]
    fn tanh_is_within_three_ulp_of_the_library() {
        let mut worst = (0, 0.0);
        let mut x = 1e-300f64;
        while x <= 22.0 {
            for y in [x, -x, x * (1.0 + 1e-9 * x.fract())] {
                let d = ulps(super::tanh(y), y.tanh());
                if d > worst.0 {
                    worst = (d, y);
                }
            }
            x *= if x < 1e-3 { 1.1 } else { 1.000_01 };
        }
        for k in 0..=220_000 {
            let y = k as f64 * 1e-4;
            let d = ulps(super::tanh(y), y.tanh());
            if d > worst.0 {
                worst = (d, y);
            }
        }
        assert!(worst.0 <= 3, "{} ulp at x = {:e}", worst.0, worst.1);
        assert_eq!(super::tanh(0.0).to_bits(), 0.0f64.to_bits());
        assert_eq!(super::tanh(-0.0).to_bits(), (-0.0f64).to_bits());
        assert_eq!(super::tanh(22.0), 1.0);
        assert!(super::tanh(f64::NAN).is_nan());
    }
}
