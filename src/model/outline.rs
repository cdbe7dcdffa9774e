//! A block with thickness (docs/experiments.md, "The toy as built"): the
//! rectangle s × d in the plane of the chain, in the block's own frame.
//!
//! A point of block n at (u, w) in its frame (u along t_n, w along the
//! normal ν_n = ∂t_n/∂θ_n, docs/model.md) is at X_n + u t_n + w ν_n; it
//! moves with ∂/∂θ = u ν_n − w t_n. The corners, counter-clockwise in
//! (u, w), are c₀ = (−r, −h), c₁ = (r, −h), c₂ = (r, h), c₃ = (−r, h)
//! (h = d/2); edge k runs from c_k to c_{k+1}: edges 0 and 2 are the
//! faces (w = ∓h), edges 1 and 3 the ends (u = ±r, the B and A ends).
//! The frame (t, ν) turns clockwise for odd n and counter-clockwise for
//! even n (t × ν = −(−1)ⁿ), so the same corner of every block alternates
//! side in the lab, as the ladder's zig-zag does.

use super::params::R;

// The ladder's layout and frame (docs/model.md), as `model::ladder` has
// them: this file sits below the ladder, which carries the toy as built.
const fn ix(i: usize) -> usize {
    3 * i
}
const fn iy(i: usize) -> usize {
    3 * i + 1
}
const fn itheta(i: usize) -> usize {
    3 * i + 2
}

/// t_n = (sin θ, (−1)ⁿ cos θ) and ν_n = ∂t_n/∂θ of block `i` (n = i + 1).
#[inline]
fn frame(i: usize, theta: f64) -> ([f64; 2], [f64; 2]) {
    let (s, c) = theta.sin_cos();
    let p = if i.is_multiple_of(2) { -1.0 } else { 1.0 };
    ([s, p * c], [c, -p * s])
}

/// The block's outline: half length r = s/2 and half thickness h = d/2.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outline {
    /// Half thickness h = d/2, in s.
    pub half_thickness: f64,
}

impl Outline {
    /// A block of thickness `d` (in s).
    pub fn new(d: f64) -> Self {
        Self {
            half_thickness: 0.5 * d,
        }
    }

    /// Thickness d, in s.
    pub fn thickness(&self) -> f64 {
        2.0 * self.half_thickness
    }

    /// Corner k (mod 4) in the block's frame (u, w).
    #[inline]
    pub fn corner(&self, k: usize) -> [f64; 2] {
        let h = self.half_thickness;
        match k % 4 {
            0 => [-R, -h],
            1 => [R, -h],
            2 => [R, h],
            _ => [-R, h],
        }
    }

    /// Length of edge k (mod 4): s for the faces, d for the ends.
    #[inline]
    pub fn edge_length(&self, k: usize) -> f64 {
        if k.is_multiple_of(2) {
            2.0 * R
        } else {
            2.0 * self.half_thickness
        }
    }

    /// The point at fraction `f` ∈ [0, 1) along edge k, in the frame.
    #[inline]
    pub fn on_edge(&self, k: usize, f: f64) -> [f64; 2] {
        let (a, b) = (self.corner(k), self.corner(k + 1));
        [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])]
    }

    /// Outward normal of edge k in the frame: faces ∓w, ends ±u.
    #[inline]
    pub fn normal(&self, k: usize) -> [f64; 2] {
        match k % 4 {
            0 => [0.0, -1.0],
            1 => [1.0, 0.0],
            2 => [0.0, 1.0],
            _ => [-1.0, 0.0],
        }
    }

    /// Circumradius √(r² + h²): two blocks whose centres are farther
    /// apart than twice it cannot touch.
    pub fn radius(&self) -> f64 {
        (R * R + self.half_thickness * self.half_thickness).sqrt()
    }
}

/// Block `i`'s pose at `q`: centre, t and ν.
#[derive(Debug, Clone, Copy)]
pub struct Pose {
    pub centre: [f64; 2],
    pub t: [f64; 2],
    pub nu: [f64; 2],
}

impl Pose {
    #[inline]
    pub fn of(q: &[f64], i: usize) -> Self {
        let (t, nu) = frame(i, q[itheta(i)]);
        Self {
            centre: [q[ix(i)], q[iy(i)]],
            t,
            nu,
        }
    }

    /// The lab point of the frame point (u, w).
    #[inline]
    pub fn point(&self, p: [f64; 2]) -> [f64; 2] {
        [
            self.centre[0] + p[0] * self.t[0] + p[1] * self.nu[0],
            self.centre[1] + p[0] * self.t[1] + p[1] * self.nu[1],
        ]
    }

    /// A frame vector in the lab.
    #[inline]
    pub fn vector(&self, p: [f64; 2]) -> [f64; 2] {
        [
            p[0] * self.t[0] + p[1] * self.nu[0],
            p[0] * self.t[1] + p[1] * self.nu[1],
        ]
    }

    /// The frame coordinates (u, w) of a lab point.
    #[inline]
    pub fn local(&self, x: [f64; 2]) -> [f64; 2] {
        let d = [x[0] - self.centre[0], x[1] - self.centre[1]];
        [
            d[0] * self.t[0] + d[1] * self.t[1],
            d[0] * self.nu[0] + d[1] * self.nu[1],
        ]
    }

    /// ∂x/∂θ of the frame point (u, w): u ν − w t.
    #[inline]
    pub fn turning(&self, p: [f64; 2]) -> [f64; 2] {
        [
            p[0] * self.nu[0] - p[1] * self.t[0],
            p[0] * self.nu[1] - p[1] * self.t[1],
        ]
    }
}

/// Adds the generalised force of a lab force `f` at the frame point `p` of
/// block `i` to `out`: f on (X, Y) and f · ∂x/∂θ on θ.
#[inline]
pub fn add_point_force(out: &mut [f64], pose: &Pose, i: usize, p: [f64; 2], f: [f64; 2]) {
    let d = pose.turning(p);
    out[ix(i)] += f[0];
    out[iy(i)] += f[1];
    out[itheta(i)] += f[0] * d[0] + f[1] * d[1];
}

/// Lab velocity of the frame point `p` of block `i` at velocities `v`.
#[inline]
pub fn point_velocity(pose: &Pose, i: usize, p: [f64; 2], v: &[f64]) -> [f64; 2] {
    let d = pose.turning(p);
    let w = v[itheta(i)];
    [v[ix(i)] + w * d[0], v[iy(i)] + w * d[1]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn corners_run_round_and_turning_is_the_derivative() {
        let o = Outline::new(0.06);
        let q = [0.3, -0.2, 0.7, 1.5, 0.1, -0.4];
        for i in 0..2 {
            let pose = Pose::of(&q, i);
            for k in 0..4 {
                let c = o.corner(k);
                let x = pose.point(c);
                let back = pose.local(x);
                assert!((back[0] - c[0]).abs() < 1e-15 && (back[1] - c[1]).abs() < 1e-15);
                let h = 1e-7;
                let (mut qp, mut qm) = (q, q);
                qp[itheta(i)] += h;
                qm[itheta(i)] -= h;
                let (xp, xm) = (Pose::of(&qp, i).point(c), Pose::of(&qm, i).point(c));
                let d = pose.turning(c);
                for a in 0..2 {
                    assert!(((xp[a] - xm[a]) / (2.0 * h) - d[a]).abs() < 1e-8);
                }
                // The outward normal points away from the centre.
                let n = o.normal(k);
                let mid = o.on_edge(k, 0.5);
                assert!(n[0] * mid[0] + n[1] * mid[1] > 0.0);
            }
        }
    }
}
