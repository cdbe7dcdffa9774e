//! Bloch-space compatibility matrix C(q) (eq:C-q), its reduced 2 × 2 form
//! (eq:C_red), det C(q) (eq:det-C), the zero modes (eq:zm_q) and the winding
//! number n_C (eq:n, eq:winding); both the paper's closed forms and the
//! numerical Bloch transform of the model's periodic chain.
//!
//! Staggering. In the model the A spring n runs along (b, 2(−1)^n s cos α),
//! so its extension contains 4γ(−1)^n (δv_{n+1} − δv_n): the chain is
//! periodic with one block per cell only in the staggered transverse
//! variable ṽ_n = (−1)^n δv_n. All Bloch matrices here act on (û, ṽ̂, θ̂)
//! with δu_n = Σ_q û e^{iqnb} etc. (eq:FT). The supplement's constraint
//! δv_n = (−1)^n (s/2) sin α δθ_n (eq:constraint_Y) is ṽ = (s/2) sin α θ.

use super::compatibility::Ring;
use crate::error::Result;
use crate::model::Params;
use crate::model::ladder::parity;
use crate::model::params::S;
use nalgebra::{Complex, Matrix2, Matrix2x3, Matrix3, Vector3};
use std::f64::consts::PI;

/// Complex numbers of the Bloch matrices.
pub type C64 = Complex<f64>;

/// The paper's coefficients (eq:c_12, eq:C_red) for rest length b and angle α.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coefficients {
    /// Rest length a = sqrt(b² + 4 s² cos²α) of the A springs.
    pub a: f64,
    pub b: f64,
    pub alpha: f64,
    /// γ = (s/2a) cos α (not the damping).
    pub gamma: f64,
    /// c_1 = γ (b + 2 s sin α).
    pub c1: f64,
    /// c_2 = γ (b − 2 s sin α).
    pub c2: f64,
    /// v_1 = c_1 + 2γ s sin α.
    pub v1: f64,
    /// v_2 = c_2 − 2γ s sin α.
    pub v2: f64,
}

impl Coefficients {
    pub fn new(b: f64, alpha: f64) -> Self {
        let a = super::gravity::a_from_alpha(b, alpha);
        let gamma = S / (2.0 * a) * alpha.cos();
        let ss = S * alpha.sin();
        let (c1, c2) = (gamma * (b + 2.0 * ss), gamma * (b - 2.0 * ss));
        Self {
            a,
            b,
            alpha,
            gamma,
            c1,
            c2,
            v1: c1 + 2.0 * gamma * ss,
            v2: c2 - 2.0 * gamma * ss,
        }
    }

    pub fn of(params: &Params) -> Self {
        Self::new(params.b, params.alpha)
    }

    /// z = e^{iqb}.
    pub fn z(&self, q: f64) -> C64 {
        Complex::from_polar(1.0, q * self.b)
    }

    /// Coefficient (s/2) sin α of the constraint ṽ = (s/2) sin α θ
    /// (eq:constraint_Y, eq:u-v-theta).
    pub fn constraint(&self) -> f64 {
        0.5 * S * self.alpha.sin()
    }
}

/// C(q) exactly as printed in eq:C-q (columns û, v̂, θ̂).
pub fn paper_compatibility_matrix(k: &Coefficients, q: f64) -> Matrix2x3<C64> {
    let (z, one) = (k.z(q), C64::from(1.0));
    let (g, r) = (C64::from(k.gamma), C64::from(k.b / k.a));
    Matrix2x3::new(
        r * (z - one),
        -g * 4.0 * (z - one),
        -z * k.c1 + k.c2,
        z - one,
        C64::from(0.0),
        g * k.a * (z - one),
    )
}

/// C(q) of the model in the staggered variables (û, ṽ̂, θ̂): eq:C-q with the
/// transverse entry −4γ(e^{iqb} + 1) instead of −4γ(e^{iqb} − 1).
pub fn corrected_compatibility_matrix(k: &Coefficients, q: f64) -> Matrix2x3<C64> {
    let mut c = paper_compatibility_matrix(k, q);
    c[(0, 1)] = -(k.z(q) + 1.0) * 4.0 * k.gamma;
    c
}

/// The reduced 2 × 2 C(q) as printed in eq:C_red (columns û, θ̂).
pub fn paper_reduced_compatibility_matrix(k: &Coefficients, q: f64) -> Matrix2<C64> {
    let (z, one) = (k.z(q), C64::from(1.0));
    Matrix2::new(
        (z - one) * (k.b / k.a),
        -z * k.v1 + k.v2,
        z - one,
        (z - one) * (k.gamma * k.a),
    )
}

/// Impose ṽ = (s/2) sin α θ on a 2 × 3 C(q): columns (û, θ̂ + (s/2) sin α ṽ̂).
pub fn reduce(c: &Matrix2x3<C64>, k: &Coefficients) -> Matrix2<C64> {
    let w = k.constraint();
    Matrix2::new(
        c[(0, 0)],
        c[(0, 2)] + c[(0, 1)] * w,
        c[(1, 0)],
        c[(1, 2)] + c[(1, 1)] * w,
    )
}

/// det C(q) = 2(e^{iqb} − 1)(c_1 e^{iqb} − c_2) (eq:det-C).
pub fn paper_det(k: &Coefficients, q: f64) -> C64 {
    let z = k.z(q);
    (z - 1.0) * (z * k.c1 - k.c2) * 2.0
}

/// Determinant of a 2 × 2 complex matrix.
pub fn det2(m: &Matrix2<C64>) -> C64 {
    m[(0, 0)] * m[(1, 1)] - m[(0, 1)] * m[(1, 0)]
}

/// Zero mode of eq:zm_q as printed, (û, v̂, θ̂) with ε(q) = 1.
pub fn paper_zero_mode(k: &Coefficients, q: f64) -> Vector3<C64> {
    let z = k.z(q);
    let ss = S * k.alpha.sin();
    Vector3::new(
        (z - 1.0) * (-2.0 * k.gamma * k.a),
        -z * (k.b + ss) + (k.b - ss),
        (z - 1.0) * 2.0,
    )
}

/// Zero mode of the model's C(q) in the staggered variables (û, ṽ̂, θ̂):
/// eq:zm_q multiplied by (e^{iqb} + 1), with v̂ replaced by
/// ṽ̂ = (e^{iqb} − 1)[(b − s sin α) − (b + s sin α) e^{iqb}].
pub fn corrected_zero_mode(k: &Coefficients, q: f64) -> Vector3<C64> {
    let z = k.z(q);
    let p = paper_zero_mode(k, q);
    Vector3::new(p[0] * (z + 1.0), p[1] * (z - 1.0), p[2] * (z + 1.0))
}

/// Real-space blocks of the model's periodic chain in staggered variables:
/// C(q) = C₀ + C₊ e^{iqb} and D(q) = D₋ e^{−iqb} + D₀ + D₊ e^{iqb}, where D is
/// the Hessian of the spring energy at the ground state (G = 0).
#[derive(Debug, Clone)]
pub struct BlochChain {
    pub coefficients: Coefficients,
    /// C₀, C₊: rows (A_n, B_n), columns of blocks n and n + 1.
    pub c_blocks: [Matrix2x3<f64>; 2],
    /// D₋, D₀, D₊: rows of block n, columns of blocks n − 1, n, n + 1.
    pub d_blocks: [Matrix3<f64>; 3],
    /// Moment of inertia I of a block (from the parameters).
    pub inertia: f64,
}

/// Number of blocks of the ring that the Bloch blocks are read from.
pub const RING_BLOCKS: usize = 8;

impl BlochChain {
    /// Blocks read from cell 1 of an 8-block ring of the model.
    pub fn new(params: &Params) -> Result<Self> {
        Self::at_cell(params, 0)
    }

    /// Blocks read from the cell with zero-based index `cell` (any cell gives
    /// the same blocks: the staggered chain is translation invariant).
    pub fn at_cell(params: &Params, cell: usize) -> Result<Self> {
        let ring = Ring::new(&params.with(RING_BLOCKS, params.b, params.alpha_deg())?)?;
        let c = ring.jacobian(&ring.ground_state());
        let h = ring.hessian();
        let block = |j: isize| (cell as isize + j).rem_euclid(RING_BLOCKS as isize) as usize;
        let stag = |i: usize| Matrix3::from_diagonal(&Vector3::new(1.0, parity(i), 1.0));
        let c_block = |j: isize| {
            let (r, col) = (2 * cell, 3 * block(j));
            c.fixed_view::<2, 3>(r, col).into_owned() * stag(block(j))
        };
        let d_block = |j: isize| {
            let (r, col) = (3 * cell, 3 * block(j));
            stag(cell) * h.fixed_view::<3, 3>(r, col).into_owned() * stag(block(j))
        };
        Ok(Self {
            coefficients: Coefficients::of(params),
            c_blocks: [c_block(0), c_block(1)],
            d_blocks: [d_block(-1), d_block(0), d_block(1)],
            inertia: params.inertia,
        })
    }

    /// The model's C(q) (staggered columns û, ṽ̂, θ̂).
    pub fn compatibility_matrix(&self, q: f64) -> Matrix2x3<C64> {
        let z = self.coefficients.z(q);
        self.c_blocks[0].map(C64::from) + self.c_blocks[1].map(|x| z * x)
    }

    /// The model's reduced C(q) under ṽ = (s/2) sin α θ (compare eq:C_red).
    pub fn reduced_compatibility_matrix(&self, q: f64) -> Matrix2<C64> {
        reduce(&self.compatibility_matrix(q), &self.coefficients)
    }

    /// det of the model's reduced C(q) (compare eq:det-C).
    pub fn det(&self, q: f64) -> C64 {
        det2(&self.reduced_compatibility_matrix(q))
    }

    /// The model's Bloch dynamical matrix D(q) (3 × 3 Hermitian, staggered).
    pub fn dynamical_matrix(&self, q: f64) -> Matrix3<C64> {
        let z = self.coefficients.z(q);
        self.d_blocks[0].map(|x| z.conj() * x)
            + self.d_blocks[1].map(C64::from)
            + self.d_blocks[2].map(|x| z * x)
    }
}

/// Samples of qb on the Brillouin zone avoiding qb = 0: (k + ½) 2π / M.
pub fn zone_samples(m: usize) -> impl Iterator<Item = f64> {
    (0..m).map(move |k| (k as f64 + 0.5) * 2.0 * PI / m as f64)
}

/// Number of samples of the loop in `winding_number`.
pub const WINDING_SAMPLES: usize = 4096;

/// Winding number of the closed curve qb ↦ f(qb), qb ∈ [0, 2π), about 0, by
/// unwrapping its phase over `WINDING_SAMPLES` points (eq:n). `None` when the
/// curve is degenerate (|f| < 1e-10 s everywhere) or passes so close to 0
/// that a single step turns the phase by more than π/2 (the winding is then
/// not defined at this resolution).
pub fn winding_number(f: impl Fn(f64) -> C64) -> Option<i32> {
    let values: Vec<C64> = zone_samples(WINDING_SAMPLES).map(f).collect();
    if values.iter().all(|v| v.norm() < 1e-10 * S) {
        return None;
    }
    let mut total = 0.0;
    for k in 0..values.len() {
        let step = (values[(k + 1) % values.len()] / values[k]).arg();
        if !step.is_finite() || step.abs() > PI / 2.0 {
            return None;
        }
        total += step;
    }
    Some((total / (2.0 * PI)).round() as i32)
}

impl BlochChain {
    /// n_C of the model: the winding of det C_red(q) / (e^{iqb} − 1) around 0.
    /// The factor (e^{iqb} − 1) is the trivial rigid translation along x,
    /// which the paper excludes (text after eq:n-2); it vanishes on the
    /// contour itself, so it is divided out before the phase is followed.
    pub fn winding_number(&self) -> Option<i32> {
        let b = self.coefficients.b;
        winding_number(|qb| {
            let q = qb / b;
            self.det(q) / (self.coefficients.z(q) - 1.0)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn chain(alpha: f64) -> BlochChain {
        BlochChain::new(&Params::paper(alpha).unwrap()).unwrap()
    }

    #[test]
    fn blocks_do_not_depend_on_the_cell() {
        let p = Params::paper(60.0).unwrap();
        let c0 = BlochChain::at_cell(&p, 0).unwrap();
        for cell in 1..RING_BLOCKS {
            let c = BlochChain::at_cell(&p, cell).unwrap();
            for j in 0..2 {
                assert!((c.c_blocks[j] - c0.c_blocks[j]).amax() < 1e-14);
            }
            for j in 0..3 {
                assert!((c.d_blocks[j] - c0.d_blocks[j]).amax() < 1e-8);
            }
        }
    }

    #[test]
    fn dynamical_matrix_is_c_dagger_c() {
        let ch = chain(60.0);
        for q in [0.0, 0.7, 2.0, -2.9] {
            let c = ch.compatibility_matrix(q);
            let d = c.adjoint() * c;
            assert!((ch.dynamical_matrix(q) - d).camax() < 1e-8);
        }
    }

    #[test]
    fn reduced_matrix_of_the_model_is_eq_c_red() {
        for alpha in [60.0, -60.0, 20.0, -75.0] {
            let ch = chain(alpha);
            for q in [0.3, 1.1, 2.4] {
                let diff = ch.reduced_compatibility_matrix(q)
                    - paper_reduced_compatibility_matrix(&ch.coefficients, q);
                assert!(diff.camax() < 1e-12, "alpha {alpha} q {q}");
                assert!((ch.det(q) - paper_det(&ch.coefficients, q)).norm() < 1e-12);
            }
        }
    }

    #[test]
    fn winding_number_detects_degenerate_curves() {
        assert_eq!(
            winding_number(|qb| Complex::from_polar(1.0, qb) * 0.5 + 0.1),
            Some(1)
        );
        assert_eq!(
            winding_number(|qb| Complex::from_polar(0.1, qb) + 0.5),
            Some(0)
        );
        assert_eq!(winding_number(|_| C64::from(1e-13)), None);
    }
}
