//! Compatibility matrices of the finite and the periodic chain and their
//! Calladine–Maxwell index count (supplement, "floppy modes and index
//! count"; main text around eq:C-q).
//!
//! The compatibility matrix C maps displacements δq = (δX_n, δY_n, δθ_n) to
//! spring extensions e = (e_{A,1}, e_{B,1}, ...): it is the Jacobian of the
//! spring lengths, taken from the model. Zero modes are its null vectors
//! (N_0 = columns − rank), states of self-stress the null vectors of Cᵀ
//! (N_s = rows − rank), and ν = 3N − N_b = N_0 − N_s.

use super::linalg::{self, HESSIAN_STEP};
use crate::error::{Error, Result};
use crate::model::ladder::{itheta, ix, iy};
use crate::model::{Ladder, Params};
use nalgebra::DMatrix;
use serde::Serialize;

/// Boundary condition of the chain.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Boundary {
    /// Open chain of N blocks and N − 1 pairs of springs, nothing fixed: the
    /// counts include the 3 rigid-body motions of the plane.
    Free,
    /// Open chain with block 1 clamped (its 3 columns dropped).
    Clamped,
    /// Ring of N blocks (N even) and N pairs of springs; block N is joined to
    /// block 1 shifted by N b along x.
    Periodic,
}

/// Zero modes, states of self-stress and the Maxwell index of one chain.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct IndexCount {
    pub boundary: Boundary,
    /// Number of blocks N.
    pub blocks: usize,
    /// Degrees of freedom (columns of C).
    pub dof: usize,
    /// Number of springs N_b (rows of C).
    pub springs: usize,
    /// Numerical rank of C (SVD, relative tolerance `RANK_RTOL`).
    pub rank: usize,
    /// N_0 = dof − rank.
    pub zero_modes: usize,
    /// N_s = springs − rank.
    pub self_stress: usize,
    /// ν = dof − N_b, which equals N_0 − N_s by rank–nullity.
    pub maxwell_index: i64,
}

impl IndexCount {
    fn of(boundary: Boundary, blocks: usize, c: &DMatrix<f64>) -> Result<Self> {
        let rank = linalg::rank(c)?;
        Ok(Self {
            boundary,
            blocks,
            dof: c.ncols(),
            springs: c.nrows(),
            rank,
            zero_modes: c.ncols() - rank,
            self_stress: c.nrows() - rank,
            maxwell_index: c.ncols() as i64 - c.nrows() as i64,
        })
    }
}

/// Parameters with gravity switched off: the linear theory uses the springs
/// only (supplement: "we ignore any further effects of gravity").
pub fn springs_only(params: &Params) -> Params {
    Params {
        gravity: 0.0,
        ..*params
    }
}

/// Compatibility matrix of the N-block chain at its ground state, from the
/// model's spring-length Jacobian. Free: 2(N − 1) × 3N; clamped: block 1's
/// columns dropped; periodic: the ring's 2N × 3N matrix.
pub fn compatibility_matrix(params: &Params, boundary: Boundary) -> Result<DMatrix<f64>> {
    let ladder = Ladder::new(*params);
    let c = match boundary {
        Boundary::Free => ladder.spring_length_jacobian(&ladder.ground_state()),
        Boundary::Clamped => {
            clamp_block_one_cols(&ladder.spring_length_jacobian(&ladder.ground_state()))
        }
        Boundary::Periodic => {
            let ring = Ring::new(params)?;
            ring.jacobian(&ring.ground_state())
        }
    };
    Ok(c)
}

/// Zero modes and states of self-stress of the N-block chain (eq:C-q text;
/// "Calladine–Maxwell" count).
pub fn index_count(params: &Params, boundary: Boundary) -> Result<IndexCount> {
    let c = compatibility_matrix(params, boundary)?;
    IndexCount::of(boundary, params.n, &c)
}

/// Projection (δu_n, δθ_n) ↦ (δu_n, (−1)^n (s/2) sin α δθ_n, δθ_n) of the
/// constraint eq:constraint_Y, 3N × 2N.
pub fn transverse_constraint(params: &Params) -> DMatrix<f64> {
    let n = params.n;
    let w = 0.5 * crate::model::params::S * params.alpha.sin();
    let mut p = DMatrix::zeros(3 * n, 2 * n);
    for i in 0..n {
        p[(ix(i), 2 * i)] = 1.0;
        p[(iy(i), 2 * i + 1)] = crate::model::ladder::parity(i) * w;
        p[(itheta(i), 2 * i + 1)] = 1.0;
    }
    p
}

/// Index count of the free chain under δv_n = (−1)^n (s/2) sin α δθ_n
/// (main text before eq:C_red): 2N columns (δu_n, δθ_n), 2(N − 1) springs.
/// The paper expects ν = 2 and N_0 = 2: translation along x and the surface
/// zero mode.
pub fn constrained_index_count(params: &Params) -> Result<IndexCount> {
    let ladder = Ladder::new(*params);
    let c = ladder.spring_length_jacobian(&ladder.ground_state()) * transverse_constraint(params);
    IndexCount::of(Boundary::Free, params.n, &c)
}

/// Drop the three columns of block 1.
pub fn clamp_block_one_cols(c: &DMatrix<f64>) -> DMatrix<f64> {
    linalg::remove_rows_cols(c, &[], &[ix(0), iy(0), itheta(0)])
}

/// Drop the three rows and columns of block 1 of a 3N × 3N matrix.
pub fn clamp_block_one(h: &DMatrix<f64>) -> DMatrix<f64> {
    let b1 = [ix(0), iy(0), itheta(0)];
    linalg::remove_rows_cols(h, &b1, &b1)
}

/// Hessian of the spring energy at a stress-free state, H = Cᵀ C: in general
/// H = k Cᵀ C + Σ_s t_s ∇²L_s, and every tension t_s = k(L_s − ℓ_s) vanishes
/// in the ground state with G = 0 (every spring at its rest length).
/// `chain_hessian_by_differences` checks it against the analytic gradient.
pub fn stress_free_hessian(c: &DMatrix<f64>) -> DMatrix<f64> {
    c.transpose() * c
}

/// Hessian of the spring energy (G = 0) of the open N-block chain at its
/// ground state (stress free, so Cᵀ C exactly).
pub fn chain_hessian(params: &Params) -> DMatrix<f64> {
    let ladder = Ladder::new(*params);
    stress_free_hessian(&ladder.spring_length_jacobian(&ladder.ground_state()))
}

/// The same Hessian by central differences of the model's analytic gradient
/// (step `HESSIAN_STEP`, symmetrised): an independent check of `chain_hessian`.
pub fn chain_hessian_by_differences(params: &Params) -> DMatrix<f64> {
    let ladder = Ladder::new(springs_only(params));
    let grad = |q: &[f64], g: &mut [f64]| ladder.gradient(q, g);
    linalg::hessian_by_differences(grad, &ladder.ground_state(), HESSIAN_STEP)
}

/// Diagonal mass matrix (m, m, I per block) of `blocks` blocks.
pub fn block_masses(params: &Params, blocks: usize) -> Vec<f64> {
    use crate::model::params::M;
    (0..blocks).flat_map(|_| [M, M, params.inertia]).collect()
}

/// Periodic ladder: N blocks on a ring (N even), N A and N B springs. Block
/// N + 1 is the image of block 1 shifted by N b along x; for even N it has
/// block 1's parity, so the ring is the open (N + 1)-block model chain with
/// its last block tied to the first.
#[derive(Debug, Clone, Copy)]
pub struct Ring {
    /// The open chain of N + 1 blocks that the ring is folded from (G = 0).
    pub open: Ladder,
    /// Number of blocks N on the ring.
    pub n: usize,
}

impl Ring {
    /// Ring of `params.n` blocks; N must be even and at least 4.
    pub fn new(params: &Params) -> Result<Self> {
        let n = params.n;
        if n < 4 || n % 2 == 1 {
            return Err(Error::bad_input(format!(
                "the periodic chain needs an even number of blocks N >= 4, got {n}"
            )));
        }
        let open = springs_only(params).with(n + 1, params.b, params.alpha_deg())?;
        Ok(Self {
            open: Ladder::new(open),
            n,
        })
    }

    /// Ground state of the ring: the first N blocks of the model's ground state.
    pub fn ground_state(&self) -> Vec<f64> {
        let mut q = self.open.ground_state();
        q.truncate(3 * self.n);
        q
    }

    /// Coordinates of the open (N + 1)-block chain: q plus the image of block 1.
    pub fn unfold(&self, q: &[f64]) -> Vec<f64> {
        let mut full = q.to_vec();
        full.extend([
            q[ix(0)] + self.n as f64 * self.open.params.b,
            q[iy(0)],
            q[itheta(0)],
        ]);
        full
    }

    /// Add the image block's entries (the last three) onto block 1's.
    fn fold(&self, v: &mut [f64]) {
        for k in 0..3 {
            v[k] += v[3 * self.n + k];
        }
    }

    /// Compatibility matrix of the ring, 2N × 3N, rows [A_1, B_1, ..., A_N, B_N].
    pub fn jacobian(&self, q: &[f64]) -> DMatrix<f64> {
        let open = self.open.spring_length_jacobian(&self.unfold(q));
        let n3 = 3 * self.n;
        DMatrix::from_fn(open.nrows(), n3, |r, c| {
            open[(r, c)] + if c < 3 { open[(r, n3 + c)] } else { 0.0 }
        })
    }

    /// Gradient of the ring's spring energy (the model's analytic gradient, folded).
    pub fn gradient(&self, q: &[f64], grad: &mut [f64]) {
        let mut full = vec![0.0; 3 * (self.n + 1)];
        self.open.gradient(&self.unfold(q), &mut full);
        self.fold(&mut full);
        grad.copy_from_slice(&full[..3 * self.n]);
    }

    /// Hessian of the ring's spring energy at its (stress-free) ground state,
    /// Cᵀ C.
    pub fn hessian(&self) -> DMatrix<f64> {
        stress_free_hessian(&self.jacobian(&self.ground_state()))
    }

    /// The same Hessian by central differences of the model's analytic
    /// gradient, folded onto the ring (step `HESSIAN_STEP`, symmetrised).
    pub fn hessian_by_differences(&self) -> DMatrix<f64> {
        let grad = |q: &[f64], g: &mut [f64]| self.gradient(q, g);
        linalg::hessian_by_differences(grad, &self.ground_state(), HESSIAN_STEP)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn params(n: usize, alpha: f64) -> Params {
        Params::paper(60.0).unwrap().with(n, 1.3, alpha).unwrap()
    }

    #[test]
    fn ring_contains_the_open_chain() {
        let p = params(8, 60.0);
        let ring = Ring::new(&p).unwrap();
        let cr = ring.jacobian(&ring.ground_state());
        let co = compatibility_matrix(&p, Boundary::Free).unwrap();
        assert_eq!(cr.nrows(), 16);
        for r in 0..co.nrows() {
            for c in 0..co.ncols() {
                assert_eq!(cr[(r, c)], co[(r, c)]);
            }
        }
    }

    #[test]
    fn hessian_is_ct_c_at_the_stress_free_ground_state() {
        let p = params(8, 60.0);
        let ring = Ring::new(&p).unwrap();
        let diff = ring.hessian_by_differences() - ring.hessian();
        assert!(diff.amax() < 1e-8, "{}", diff.amax());
        let diff = chain_hessian_by_differences(&p) - chain_hessian(&p);
        assert!(diff.amax() < 1e-8, "{}", diff.amax());
    }

    #[test]
    fn odd_ring_is_rejected() {
        assert!(Ring::new(&params(7, 60.0)).is_err());
    }
}
