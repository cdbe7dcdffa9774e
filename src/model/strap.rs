//! The strap hinge (docs/experiments.md, "The strap hinge: reduced
//! coordinates"): the toy as built with its blocks end to end (pitch
//! b = s) and both crossed ribbons of every junction taut, in reduced
//! coordinates, one angle per block.
//!
//! Two taut crossed ribbons make the blocks of a junction roll on each
//! other: for rectangles, a pivot about a pair of corners that coincide.
//! With φ = π − θ_n − θ_{n+1} the junction's fold (0 in the hanging
//! column, ±π with the blocks face to face; the blocks' frames alternate,
//! so the same φ folds every junction the same way in its blocks' own
//! frames), the pivot is, in the frames of the upper and the lower block
//! (`outline`: c₀ = (−r, −h), c₁ = (r, −h), c₂ = (r, h), c₃ = (−r, h)):
//!
//! | φ | upper | lower |
//! |---|---|---|
//! | [−2π, −π] | c₀ | c₂ |
//! | [−π, 0] | c₁ | c₃ |
//! | [0, π] | c₂ | c₀ |
//! | [π, 2π] | c₃ | c₁ |
//!
//! In each, both ribbons (glued at the ends, `ribbon_anchors = [0, 1]`)
//! keep the length s + d they have in the column at b = s: one wraps the
//! upper block's end, the other the lower's. The pivot switches when the
//! two blocks lie face to face (φ a multiple of π).
//!
//! Block 1's centre is clamped at X₁ and its angle driven; every other
//! centre follows from the angles through the pivots,
//!
//! X_{n+1} = X_n + p_n(c_up) − p_{n+1}(c_low),  p_n(c) = u t_n + w ν_n,
//!
//! so Ẋ_k = Σ_j J_kj θ̇_j, J_kj = ∂X_k/∂θ_j (p' = u ν − w t, p'' = −p).
//! The Lagrangian L = Σ_k ½ m |Ẋ_k|² + ½ I θ̇_k² + m G Σ_k X_k,x gives
//!
//! Σ_l M_jl θ̈_l = Σ_k m J_kj · (G x̂ − a_k),
//! M_jl = Σ_k m J_kj · J_kl + I δ_jl,
//!
//! a_k = Ẍ_k − Σ_j J_kj θ̈_j, the part of Ẍ_k quadratic in the rates
//! (−p θ̇² of every pivot vector on the way down): the equations of the
//! rolling chain (docs/experiments.md derives them).

use super::outline::{Outline, Pose};
use super::params::M;

/// A junction's pivot: which quarter of φ ∈ [−2π, 2π] it rolls in,
/// −2, −1, 0 or 1 for [−2π, −π], [−π, 0], [0, π], [π, 2π].
pub type Region = i32;

/// The corners (upper, lower) that coincide at the pivot of `region`.
pub fn pivot_corners(region: Region) -> (usize, usize) {
    match region {
        -2 => (0, 2),
        -1 => (1, 3),
        0 => (2, 0),
        _ => (3, 1),
    }
}

/// The region of a fold φ, away from the boundaries (φ ∈ (−2π, 2π)).
pub fn region_of(phi: f64) -> Region {
    (phi / std::f64::consts::PI).floor().clamp(-2.0, 1.0) as Region
}

/// The fold φ_n = π − θ_n − θ_{n+1} of junction n (blocks i, i + 1).
pub fn fold(theta: &[f64], i: usize) -> f64 {
    std::f64::consts::PI - theta[i] - theta[i + 1]
}

/// The strap-hinge chain: the blocks' outline and inertia, gravity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StrapChain {
    pub outline: Outline,
    /// I of one block (m = 1).
    pub inertia: f64,
    /// G, along +x.
    pub gravity: f64,
    /// Block 1's clamped centre.
    pub top: [f64; 2],
}

/// The chain's kinematics at (θ, θ̇): maximal positions and velocities,
/// J = ∂X/∂θ per block and the rate-quadratic accelerations a_k.
#[derive(Debug, Clone)]
pub struct Kinematics {
    pub q: Vec<f64>,
    pub v: Vec<f64>,
    /// J[k][j]: ∂X_k/∂θ_j (2-vectors).
    pub jac: Vec<Vec<[f64; 2]>>,
    pub quad: Vec<[f64; 2]>,
}

/// θ in the maximal layout with zero centres (for the poses).
fn angles_only(theta: &[f64]) -> Vec<f64> {
    theta.iter().flat_map(|&t| [0.0, 0.0, t]).collect()
}

impl StrapChain {
    /// The kinematics at angles `theta`, rates `omega`, pivots `regions`
    /// (one per junction).
    pub fn kinematics(&self, theta: &[f64], omega: &[f64], regions: &[Region]) -> Kinematics {
        let n = theta.len();
        let ang = angles_only(theta);
        let poses: Vec<Pose> = (0..n).map(|i| Pose::of(&ang, i)).collect();
        let mut q = vec![0.0; 3 * n];
        let mut v = vec![0.0; 3 * n];
        let mut jac = vec![vec![[0.0; 2]; n]; n];
        let mut quad = vec![[0.0; 2]; n];
        let (mut x, mut xd, mut acc) = (self.top, [0.0; 2], [0.0; 2]);
        for k in 0..n {
            if k > 0 {
                let (cu, cl) = pivot_corners(regions[k - 1]);
                let (pu, pl) = (&poses[k - 1], &poses[k]);
                let (cu, cl) = (self.outline.corner(cu), self.outline.corner(cl));
                let (au, al) = (pu.vector(cu), pl.vector(cl));
                let (du, dl) = (pu.turning(cu), pl.turning(cl));
                let (wu, wl) = (omega[k - 1], omega[k]);
                // X_k = X_{k−1} + p_{k−1}(c_up) − p_k(c_low).
                jac[k] = jac[k - 1].clone();
                for a in 0..2 {
                    x[a] += au[a] - al[a];
                    xd[a] += du[a] * wu - dl[a] * wl;
                    acc[a] += -au[a] * wu * wu + al[a] * wl * wl;
                    // Block k − 1's centre-to-pivot and block k's.
                    jac[k][k - 1][a] += du[a];
                    jac[k][k][a] -= dl[a];
                }
            }
            q[3 * k] = x[0];
            q[3 * k + 1] = x[1];
            q[3 * k + 2] = theta[k];
            v[3 * k] = xd[0];
            v[3 * k + 1] = xd[1];
            v[3 * k + 2] = omega[k];
            quad[k] = acc;
        }
        Kinematics { q, v, jac, quad }
    }

    /// The reduced mass matrix M_jl and the generalised force
    /// Σ_k m J_kj · (G x̂ − a_k) of the Lagrangian (module doc).
    pub fn equations(&self, k: &Kinematics) -> (Vec<Vec<f64>>, Vec<f64>) {
        let n = k.jac.len();
        let mut mass = vec![vec![0.0; n]; n];
        let mut force = vec![0.0; n];
        for b in 0..n {
            let g = [self.gravity - k.quad[b][0], -k.quad[b][1]];
            for j in 0..n {
                let jj = k.jac[b][j];
                force[j] += M * (jj[0] * g[0] + jj[1] * g[1]);
                for l in 0..n {
                    let jl = k.jac[b][l];
                    mass[j][l] += M * (jj[0] * jl[0] + jj[1] * jl[1]);
                }
            }
        }
        for (j, row) in mass.iter_mut().enumerate() {
            row[j] += self.inertia;
        }
        (mass, force)
    }

    /// Kinetic energy of blocks 2..N (block 1's centre is clamped and its
    /// turn is the hand's) and the potential −m G Σ X_k of all.
    pub fn energy(&self, theta: &[f64], omega: &[f64], regions: &[Region]) -> (f64, f64) {
        let k = self.kinematics(theta, omega, regions);
        let n = theta.len();
        let kin: f64 = (1..n)
            .map(|b| {
                let (vx, vy, w) = (k.v[3 * b], k.v[3 * b + 1], k.v[3 * b + 2]);
                0.5 * M * (vx * vx + vy * vy) + 0.5 * self.inertia * w * w
            })
            .sum();
        let pot: f64 = -(0..n).map(|b| M * self.gravity * k.q[3 * b]).sum::<f64>();
        (kin, pot)
    }
}

/// The partner of a pivot corner along the edge the ribbons leave by:
/// the end's other corner while the blocks roll on their ends (φ in
/// [−π, π]), the face's other corner once they have rolled over a face.
fn partner(corner: usize, region: Region) -> usize {
    if region == 0 || region == -1 {
        3 - corner
    } else {
        corner ^ 1
    }
}

impl StrapChain {
    /// The two ribbons' tensions (T₁ pulls the lower block towards the
    /// pivot along its own edge, T₂ towards the upper block's partner
    /// corner along the upper's edge: both lines pass through the pivot)
    /// that carry the pivot's reaction on the blocks below junction `j`,
    /// R = Σ_{k>j} m (Ẍ_k − G x̂), at accelerations `alpha`. A negative
    /// tension means that ribbon would have to push: the strap hinge no
    /// longer holds and the maximal model must take over.
    pub fn tensions(
        &self,
        k: &Kinematics,
        alpha: &[f64],
        regions: &[Region],
        j: usize,
    ) -> [f64; 2] {
        let n = alpha.len();
        let mut r = [0.0; 2];
        for b in j + 1..n {
            for a in 0..2 {
                let acc: f64 =
                    (0..n).map(|l| k.jac[b][l][a] * alpha[l]).sum::<f64>() + k.quad[b][a];
                let g = if a == 0 { self.gravity } else { 0.0 };
                r[a] += M * (acc - g);
            }
        }
        let (cu, cl) = pivot_corners(regions[j]);
        let (pu, pl) = (Pose::of(&k.q, j), Pose::of(&k.q, j + 1));
        let p = pu.point(self.outline.corner(cu));
        let unit = |a: [f64; 2], b: [f64; 2]| {
            let d = [b[0] - a[0], b[1] - a[1]];
            let l = (d[0] * d[0] + d[1] * d[1]).sqrt();
            [d[0] / l, d[1] / l]
        };
        let u1 = unit(pl.point(self.outline.corner(partner(cl, regions[j]))), p);
        let u2 = unit(p, pu.point(self.outline.corner(partner(cu, regions[j]))));
        // R = T₁ u₁ + T₂ u₂ (Cramer).
        let det = u1[0] * u2[1] - u1[1] * u2[0];
        [
            (r[0] * u2[1] - r[1] * u2[0]) / det,
            (u1[0] * r[1] - u1[1] * r[0]) / det,
        ]
    }
}

/// Solves A x = b (A symmetric positive definite, small) by Cholesky.
pub fn solve_spd(a: &[Vec<f64>], b: &[f64]) -> Vec<f64> {
    let n = b.len();
    let mut l = vec![vec![0.0; n]; n];
    for i in 0..n {
        for j in 0..=i {
            let s: f64 = (0..j).map(|k| l[i][k] * l[j][k]).sum();
            if i == j {
                l[i][i] = (a[i][i] - s).max(f64::MIN_POSITIVE).sqrt();
            } else {
                l[i][j] = (a[i][j] - s) / l[j][j];
            }
        }
    }
    let mut y = vec![0.0; n];
    for i in 0..n {
        let s: f64 = (0..i).map(|k| l[i][k] * y[k]).sum();
        y[i] = (b[i] - s) / l[i][i];
    }
    let mut x = vec![0.0; n];
    for i in (0..n).rev() {
        let s: f64 = (i + 1..n).map(|k| l[k][i] * x[k]).sum();
        x[i] = (y[i] - s) / l[i][i];
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    fn chain() -> StrapChain {
        let d = 0.635 / 5.7;
        StrapChain {
            outline: Outline::new(d),
            inertia: (1.0 + d * d) / 12.0,
            gravity: 2e-4,
            top: [0.3, -0.1],
        }
    }

    fn state() -> (Vec<f64>, Vec<f64>, Vec<Region>) {
        let theta = vec![1.3, 0.4, 2.9, -0.8, 1.1];
        let omega = vec![0.02, -0.03, 0.01, 0.05, -0.015];
        let regions = (0..4).map(|i| region_of(fold(&theta, i))).collect();
        (theta, omega, regions)
    }

    #[test]
    fn the_pivot_corners_coincide() {
        let c = chain();
        let (theta, omega, regions) = state();
        let k = c.kinematics(&theta, &omega, &regions);
        for (i, &r) in regions.iter().enumerate() {
            let (cu, cl) = pivot_corners(r);
            let pu = Pose::of(&k.q, i).point(c.outline.corner(cu));
            let pl = Pose::of(&k.q, i + 1).point(c.outline.corner(cl));
            assert!((pu[0] - pl[0]).abs() < 1e-15 && (pu[1] - pl[1]).abs() < 1e-15);
        }
    }

    #[test]
    fn jacobian_and_rate_terms_are_the_derivatives_of_the_positions() {
        // J against finite differences of X(θ), and a_k against the second
        // derivative of X along θ + ω t.
        let c = chain();
        let (theta, omega, regions) = state();
        let k = c.kinematics(&theta, &omega, &regions);
        let h = 1e-6;
        let at = |s: f64, j: Option<usize>| {
            let th: Vec<f64> = match j {
                Some(j) => theta
                    .iter()
                    .enumerate()
                    .map(|(l, t)| t + if l == j { s } else { 0.0 })
                    .collect(),
                None => theta.iter().zip(&omega).map(|(t, w)| t + s * w).collect(),
            };
            c.kinematics(&th, &omega, &regions).q
        };
        for j in 0..theta.len() {
            let (p, m) = (at(h, Some(j)), at(-h, Some(j)));
            for b in 0..theta.len() {
                for a in 0..2 {
                    let fd = (p[3 * b + a] - m[3 * b + a]) / (2.0 * h);
                    assert!((fd - k.jac[b][j][a]).abs() < 1e-8, "{b} {j} {a}");
                }
            }
        }
        let h = 1e-3;
        let (p, z, m) = (at(h, None), at(0.0, None), at(-h, None));
        for b in 0..theta.len() {
            for a in 0..2 {
                let fd = (p[3 * b + a] - 2.0 * z[3 * b + a] + m[3 * b + a]) / (h * h);
                assert!((fd - k.quad[b][a]).abs() < 1e-9, "{b} {a}: {fd}");
                let vd = (p[3 * b + a] - m[3 * b + a]) / (2.0 * h);
                assert!((vd - k.v[3 * b + a]).abs() < 1e-9);
            }
        }
    }

    #[test]
    fn generalised_gravity_is_minus_the_potential_gradient() {
        // At rest (a_k = 0) the force is −∂V/∂θ, V = −m G Σ X_k.
        let c = chain();
        let (theta, _, regions) = state();
        let zero = vec![0.0; theta.len()];
        let (_, f) = c.equations(&c.kinematics(&theta, &zero, &regions));
        let h = 1e-6;
        for j in 0..theta.len() {
            let mut tp = theta.clone();
            let mut tm = theta.clone();
            tp[j] += h;
            tm[j] -= h;
            let v = |t: &[f64]| c.energy(t, &zero, &regions).1;
            let fd = (v(&tp) - v(&tm)) / (2.0 * h);
            assert!((fd + f[j]).abs() < 1e-10, "{j}: {fd} {}", f[j]);
        }
    }

    #[test]
    fn the_mass_matrix_is_the_kinetic_energy_hessian() {
        let c = chain();
        let (theta, omega, regions) = state();
        let k = c.kinematics(&theta, &omega, &regions);
        let (m, _) = c.equations(&k);
        // ½ ω·Mω over blocks 1..N equals Σ ½ m |Ẋ|² + ½ I θ̇² of all.
        let quad: f64 = (0..theta.len())
            .flat_map(|j| (0..theta.len()).map(move |l| (j, l)))
            .map(|(j, l)| 0.5 * omega[j] * m[j][l] * omega[l])
            .sum();
        let direct: f64 = (0..theta.len())
            .map(|b| {
                let (vx, vy) = (k.v[3 * b], k.v[3 * b + 1]);
                0.5 * (vx * vx + vy * vy) + 0.5 * c.inertia * omega[b] * omega[b]
            })
            .sum();
        assert!((quad - direct).abs() < 1e-15, "{quad} {direct}");
        let x = solve_spd(&m, &omega);
        for j in 0..theta.len() {
            let r: f64 = (0..theta.len()).map(|l| m[j][l] * x[l]).sum();
            assert!((r - omega[j]).abs() < 1e-12);
        }
    }
}
