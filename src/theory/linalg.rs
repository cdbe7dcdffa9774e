//! Small numerical helpers: rank and null space by SVD, Hessians by central
//! differences of an analytic gradient, mass-weighted eigenfrequencies.

use nalgebra::{DMatrix, DVector, SymmetricEigen};

/// Relative tolerance of the numerical rank: a singular value σ counts as
/// zero when σ ≤ `RANK_RTOL` · σ_max. For b = 1.3, N ≤ 40 and |α| ≤ 89° the
/// smallest genuine singular value of the free chain's compatibility matrix
/// is above 8e-3 σ_max (it falls off like 1/N), while the exact zeros come
/// out below 1e-15 σ_max.
pub const RANK_RTOL: f64 = 1e-9;

/// Step of the central differences of the analytic gradient.
pub const HESSIAN_STEP: f64 = 1e-5;

/// Numerical rank of `m` by SVD with the relative tolerance `RANK_RTOL`.
pub fn rank(m: &DMatrix<f64>) -> usize {
    if m.is_empty() {
        return 0;
    }
    let sv = m.clone().svd(false, false).singular_values;
    let tol = RANK_RTOL * sv.max();
    sv.iter().filter(|&&s| s > tol).count()
}

/// Singular values of `m`, descending.
pub fn singular_values(m: &DMatrix<f64>) -> Vec<f64> {
    let mut sv: Vec<f64> = m
        .clone()
        .svd(false, false)
        .singular_values
        .iter()
        .copied()
        .collect();
    sv.sort_by(|x, y| y.total_cmp(x));
    sv
}

/// The right singular vector of the smallest singular value of `m`
/// (`m` with at least as many rows as columns): its best null vector.
pub fn null_vector(m: &DMatrix<f64>) -> DVector<f64> {
    let svd = m.clone().svd(false, true);
    let v_t = svd.v_t.expect("v_t was requested");
    let k = svd.singular_values.imin();
    v_t.row(k).transpose()
}

/// Hessian of a function from its gradient by central differences with step
/// `h`, symmetrised: H = ½(H̃ + H̃ᵀ).
pub fn hessian_by_differences(
    grad: impl Fn(&[f64], &mut [f64]),
    q: &[f64],
    h: f64,
) -> DMatrix<f64> {
    let n = q.len();
    let mut hess = DMatrix::zeros(n, n);
    let (mut gp, mut gm) = (vec![0.0; n], vec![0.0; n]);
    let mut x = q.to_vec();
    for j in 0..n {
        x[j] = q[j] + h;
        grad(&x, &mut gp);
        x[j] = q[j] - h;
        grad(&x, &mut gm);
        x[j] = q[j];
        for i in 0..n {
            hess[(i, j)] = (gp[i] - gm[i]) / (2.0 * h);
        }
    }
    0.5 * (&hess + hess.transpose())
}

/// Squared normal-mode frequencies ω² of the stiffness `k` with the diagonal
/// mass matrix `masses`: eigenvalues of M^{-1/2} K M^{-1/2}, ascending.
pub fn mass_weighted_eigenvalues(k: &DMatrix<f64>, masses: &[f64]) -> Vec<f64> {
    let w: Vec<f64> = masses.iter().map(|m| 1.0 / m.sqrt()).collect();
    let weighted = DMatrix::from_fn(k.nrows(), k.ncols(), |i, j| w[i] * k[(i, j)] * w[j]);
    let mut ev: Vec<f64> = SymmetricEigen::new(weighted)
        .eigenvalues
        .iter()
        .copied()
        .collect();
    ev.sort_by(f64::total_cmp);
    ev
}

/// ω = sqrt(max(ω², 0)): round-off can make a zero mode slightly negative.
pub fn frequency(omega_sq: f64) -> f64 {
    omega_sq.max(0.0).sqrt()
}

/// `m` without the listed `rows` and `cols` (in any order).
pub fn remove_rows_cols(m: &DMatrix<f64>, rows: &[usize], cols: &[usize]) -> DMatrix<f64> {
    let keep_r: Vec<usize> = (0..m.nrows()).filter(|i| !rows.contains(i)).collect();
    let keep_c: Vec<usize> = (0..m.ncols()).filter(|j| !cols.contains(j)).collect();
    DMatrix::from_fn(keep_r.len(), keep_c.len(), |i, j| m[(keep_r[i], keep_c[j])])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rank_of_a_rank_two_matrix() {
        let m = DMatrix::from_row_slice(3, 3, &[1.0, 2.0, 3.0, 2.0, 4.0, 6.0, 0.0, 1.0, 1.0]);
        assert_eq!(rank(&m), 2);
        let v = null_vector(&m);
        assert!((&m * v).norm() < 1e-12);
    }

    #[test]
    fn hessian_of_a_quadratic() {
        let grad = |q: &[f64], g: &mut [f64]| {
            g[0] = 2.0 * q[0] + q[1];
            g[1] = q[0] + 6.0 * q[1];
        };
        let h = hessian_by_differences(grad, &[0.3, -0.2], HESSIAN_STEP);
        assert!((h[(0, 0)] - 2.0).abs() < 1e-9 && (h[(0, 1)] - 1.0).abs() < 1e-9);
        let ev = mass_weighted_eigenvalues(&DMatrix::from_diagonal_element(2, 2, 4.0), &[1.0, 4.0]);
        assert!((ev[0] - 1.0).abs() < 1e-12 && (ev[1] - 4.0).abs() < 1e-12);
    }
}
