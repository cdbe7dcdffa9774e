//! Small numerical helpers: rank and null space by SVD, Hessians by central
//! differences of an analytic gradient, mass-weighted eigenfrequencies.

use crate::error::{Error, Result};
use nalgebra::{DMatrix, DVector, Dyn, SVD, SymmetricEigen};

/// Relative tolerance of the numerical rank: a singular value σ counts as
/// zero when σ ≤ `RANK_RTOL` · σ_max. For b = 1.3, N ≤ 40 and |α| ≤ 89° the
/// smallest genuine singular value of the free chain's compatibility matrix
/// is above 8e-3 σ_max (it falls off like 1/N), while the exact zeros come
/// out below 1e-15 σ_max.
pub const RANK_RTOL: f64 = 1e-9;

/// Step of the central differences of the analytic gradient.
pub const HESSIAN_STEP: f64 = 1e-5;

/// Most QR sweeps of an SVD or a symmetric eigen-decomposition, per row or
/// column of the matrix (plus [`ITERATIONS_BASE`]). A well-posed problem
/// needs about two per singular value; a matrix whose entries span more
/// than the range of `f64` (lengths such as b = 1e-17 or 1e308) can sweep
/// forever without the cap.
pub const ITERATIONS_PER_DIMENSION: usize = 30;
/// Sweeps every decomposition may take, whatever its size.
pub const ITERATIONS_BASE: usize = 100;

/// The iteration cap of a decomposition of an `rows` × `cols` matrix.
fn iteration_cap(rows: usize, cols: usize) -> usize {
    ITERATIONS_BASE + ITERATIONS_PER_DIMENSION * rows.max(cols)
}

/// `Error::Failed` for a decomposition that did not converge (or was given
/// a matrix with NaN or infinite entries): one line, with a hint.
fn not_converged(what: &str, m: &DMatrix<f64>, cause: &str) -> Error {
    Error::failed(format!(
        "the {what} of a {}×{} matrix {cause}; hint: the lengths or angles are too \
         extreme for the linear theory, try values closer to the paper's (b = 1.3, alpha = 60)",
        m.nrows(),
        m.ncols()
    ))
}

/// Checks that every entry of `m` is finite.
fn finite(what: &str, m: &DMatrix<f64>) -> Result<()> {
    if m.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(not_converged(what, m, "has NaN or infinite entries"))
    }
}

/// SVD of `m` with the iteration cap; `Error::Failed` if it does not converge.
fn svd(m: &DMatrix<f64>, compute_v: bool) -> Result<SVD<f64, Dyn, Dyn>> {
    svd_capped(m, compute_v, iteration_cap(m.nrows(), m.ncols()))
}

/// SVD of `m` in at most `cap` sweeps.
fn svd_capped(m: &DMatrix<f64>, compute_v: bool, cap: usize) -> Result<SVD<f64, Dyn, Dyn>> {
    const WHAT: &str = "singular value decomposition";
    finite(WHAT, m)?;
    m.clone()
        .try_svd(false, compute_v, f64::EPSILON, cap)
        .ok_or_else(|| not_converged(WHAT, m, &format!("did not converge in {cap} sweeps")))
}

/// Numerical rank of `m` by SVD with the relative tolerance `RANK_RTOL`.
pub fn rank(m: &DMatrix<f64>) -> Result<usize> {
    if m.is_empty() {
        return Ok(0);
    }
    let sv = svd(m, false)?.singular_values;
    let tol = RANK_RTOL * sv.max();
    Ok(sv.iter().filter(|&&s| s > tol).count())
}

/// Singular values of `m`, descending.
pub fn singular_values(m: &DMatrix<f64>) -> Result<Vec<f64>> {
    if m.is_empty() {
        return Ok(Vec::new());
    }
    let mut sv: Vec<f64> = svd(m, false)?.singular_values.iter().copied().collect();
    sv.sort_by(|x, y| y.total_cmp(x));
    Ok(sv)
}

/// The right singular vector of the smallest singular value of `m`
/// (`m` non-empty, with at least as many rows as columns): its best null
/// vector.
pub fn null_vector(m: &DMatrix<f64>) -> Result<DVector<f64>> {
    if m.is_empty() {
        return Err(Error::failed("null vector of an empty matrix"));
    }
    let svd = svd(m, true)?;
    let k = svd.singular_values.imin();
    match svd.v_t {
        Some(v_t) => Ok(v_t.row(k).transpose()),
        None => Err(Error::failed("the SVD returned no singular vectors")),
    }
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
/// `Error::Failed` if the decomposition does not converge within its
/// iteration cap.
pub fn mass_weighted_eigenvalues(k: &DMatrix<f64>, masses: &[f64]) -> Result<Vec<f64>> {
    const WHAT: &str = "symmetric eigen-decomposition";
    let w: Vec<f64> = masses.iter().map(|m| 1.0 / m.sqrt()).collect();
    let weighted = DMatrix::from_fn(k.nrows(), k.ncols(), |i, j| w[i] * k[(i, j)] * w[j]);
    if weighted.is_empty() {
        return Ok(Vec::new());
    }
    finite(WHAT, &weighted)?;
    let cap = iteration_cap(weighted.nrows(), weighted.ncols());
    let eigen = SymmetricEigen::try_new(weighted.clone(), f64::EPSILON, cap).ok_or_else(|| {
        not_converged(
            WHAT,
            &weighted,
            &format!("did not converge in {cap} sweeps"),
        )
    })?;
    let mut ev: Vec<f64> = eigen.eigenvalues.iter().copied().collect();
    ev.sort_by(f64::total_cmp);
    Ok(ev)
}

/// A symmetric band matrix, stored by rows of its upper band:
/// `upper[i (width + 1) + k]` = A[i][i + k] for k ≤ `width` (zero past the
/// last row). O(n · width) memory, where the dense matrix
/// takes O(n²).
#[derive(Debug, Clone, PartialEq)]
pub struct BandSymmetric {
    /// Half-bandwidth: A[i][j] = 0 for |i − j| > width.
    pub width: usize,
    upper: Vec<f64>,
}

impl BandSymmetric {
    /// The n × n zero matrix of half-bandwidth `width`.
    pub fn zeros(n: usize, width: usize) -> Self {
        Self {
            width,
            upper: vec![0.0; n * (width + 1)],
        }
    }

    pub fn dim(&self) -> usize {
        self.upper.len() / (self.width + 1)
    }

    /// Row `i` of the upper band: A[i][i..=i + width].
    fn row(&self, i: usize) -> &[f64] {
        let w = self.width + 1;
        &self.upper[i * w..(i + 1) * w]
    }

    /// Adds `x` to A[i][j] (and so to A[j][i]); |i − j| ≤ `width`.
    pub fn add(&mut self, i: usize, j: usize, x: f64) {
        let (i, j) = if i <= j { (i, j) } else { (j, i) };
        assert!(j - i <= self.width, "entry ({i}, {j}) outside the band");
        self.upper[i * (self.width + 1) + j - i] += x;
    }

    /// A[i][j] (zero outside the band).
    pub fn get(&self, i: usize, j: usize) -> f64 {
        let (i, j) = if i <= j { (i, j) } else { (j, i) };
        self.row(i).get(j - i).copied().unwrap_or(0.0)
    }

    /// The dense matrix (for tests and small n).
    pub fn to_dense(&self) -> DMatrix<f64> {
        let n = self.dim();
        DMatrix::from_fn(n, n, |i, j| self.get(i, j))
    }

    /// Whether σ I − A is positive definite: its band Cholesky
    /// factorisation (O(n · width²), backward stable for a positive
    /// definite matrix) finds only positive pivots.
    fn shifted_is_positive_definite(&self, sigma: f64, u: &mut [f64]) -> bool {
        let (n, p) = (self.dim(), self.width);
        let w = p + 1;
        for i in 0..n {
            // u[k w + d] = U[k][k + d] of σI − A = UᵀU.
            let a = self.row(i);
            let mut diag = sigma - a[0];
            for k in i.saturating_sub(p)..i {
                diag -= u[k * w + i - k] * u[k * w + i - k];
            }
            // NaN counts as not positive.
            if diag.is_nan() || diag <= 0.0 {
                return false;
            }
            let pivot = diag.sqrt();
            u[i * w] = pivot;
            for j in i + 1..(i + w).min(n) {
                let mut x = -a[j - i];
                for k in j.saturating_sub(p)..i {
                    x -= u[k * w + i - k] * u[k * w + j - k];
                }
                u[i * w + j - i] = x / pivot;
            }
        }
        true
    }

    /// The largest eigenvalue, to a few ulps, by bisection on σ between a
    /// lower bound (the largest diagonal entry) and Gershgorin's upper
    /// bound, testing σ I − A for positive definiteness by Cholesky.
    /// Returns the upper end of the final bracket (never below the true
    /// value by more than rounding). O(n · width²) per step, about 60
    /// steps: O(n) in all. `Error::Failed` for NaN or infinite entries.
    pub fn largest_eigenvalue(&self) -> Result<f64> {
        let n = self.dim();
        if n == 0 {
            return Ok(0.0);
        }
        if !self.upper.iter().all(|x| x.is_finite()) {
            return Err(Error::failed(format!(
                "the {n}×{n} band matrix has NaN or infinite entries; hint: the lengths or \
                 angles are too extreme, try values closer to the paper's (b = 1.3, alpha = 60)"
            )));
        }
        let mut lo = (0..n)
            .map(|i| self.row(i)[0])
            .fold(f64::NEG_INFINITY, f64::max);
        let mut hi = (0..n)
            .map(|i| {
                let lower = i.saturating_sub(self.width)..=(i + self.width).min(n - 1);
                let off: f64 = lower
                    .filter(|&j| j != i)
                    .map(|j| self.get(i, j).abs())
                    .sum();
                self.row(i)[0] + off
            })
            .fold(f64::NEG_INFINITY, f64::max);
        let mut u = vec![0.0; self.upper.len()];
        // Make sure hi is strictly above (Gershgorin can be attained).
        let bump = f64::EPSILON * hi.abs().max(f64::MIN_POSITIVE) * 16.0;
        hi += bump;
        while !self.shifted_is_positive_definite(hi, &mut u) {
            lo = hi;
            hi += (hi.abs() * 1e-12).max(bump);
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if !(mid > lo && mid < hi) || hi - lo <= 4.0 * f64::EPSILON * hi.abs() {
                break;
            }
            if self.shifted_is_positive_definite(mid, &mut u) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        Ok(hi)
    }
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
        assert_eq!(rank(&m).unwrap(), 2);
        let v = null_vector(&m).unwrap();
        assert!((&m * v).norm() < 1e-12);
    }

    #[test]
    fn the_iteration_cap_ends_a_decomposition_with_failed() {
        let m = DMatrix::from_fn(30, 30, |i, j| ((i * 31 + j * 17) as f64 * 0.37).sin());
        assert!(svd_capped(&m, false, 1).is_err());
        assert!(svd_capped(&m, false, iteration_cap(30, 30)).is_ok());
        let nan = DMatrix::from_element(3, 3, f64::NAN);
        assert!(matches!(rank(&nan), Err(Error::Failed(_))));
        let inf = DMatrix::from_element(3, 3, f64::INFINITY);
        assert!(matches!(
            mass_weighted_eigenvalues(&inf, &[1.0; 3]),
            Err(Error::Failed(_))
        ));
    }

    #[test]
    fn band_largest_eigenvalue_is_the_dense_one() {
        for (n, width) in [(1, 0), (2, 1), (7, 2), (40, 5), (41, 3)] {
            let mut a = BandSymmetric::zeros(n, width);
            for i in 0..n {
                for j in i..(i + width + 1).min(n) {
                    a.add(
                        i,
                        j,
                        ((i * 7 + j * 3) as f64 * 0.91).cos() + if i == j { 0.5 } else { 0.0 },
                    );
                }
            }
            let dense = SymmetricEigen::new(a.to_dense()).eigenvalues.max();
            let band = a.largest_eigenvalue().unwrap();
            assert!(
                (band - dense).abs() <= 1e-12 * dense.abs().max(1.0),
                "n {n} width {width}: band {band}, dense {dense}"
            );
        }
    }

    #[test]
    fn hessian_of_a_quadratic() {
        let grad = |q: &[f64], g: &mut [f64]| {
            g[0] = 2.0 * q[0] + q[1];
            g[1] = q[0] + 6.0 * q[1];
        };
        let h = hessian_by_differences(grad, &[0.3, -0.2], HESSIAN_STEP);
        assert!((h[(0, 0)] - 2.0).abs() < 1e-9 && (h[(0, 1)] - 1.0).abs() < 1e-9);
        let ev = mass_weighted_eigenvalues(&DMatrix::from_diagonal_element(2, 2, 4.0), &[1.0, 4.0])
            .unwrap();
        assert!((ev[0] - 1.0).abs() < 1e-12 && (ev[1] - 4.0).abs() < 1e-12);
    }
}
