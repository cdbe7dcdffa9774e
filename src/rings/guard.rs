//! The linking guard: whether ring a's centre circle passes through ring
//! b's disc exactly once (the two rings interlock). The circle's height
//! over b's plane is A cos θ + B sin θ + C, so its crossings of the plane
//! are closed form; the rings are linked when exactly one crossing lies
//! inside b's circle. A wave through a ring that tunnelled is no result:
//! the run checks every pair every few steps and fails on any change
//! (paper Fig. 4b: the chain's topology is what makes the wave).

use super::contact::Circle;
use super::math;

/// Whether circle `a` passes through the disc of circle `b` exactly once.
pub fn linked(a: &Circle, b: &Circle) -> bool {
    let ex = [a.rot[0][0], a.rot[1][0], a.rot[2][0]];
    let ey = [a.rot[0][1], a.rot[1][1], a.rot[2][1]];
    // In b's frame: p(θ) = c + R (cos θ ex + sin θ ey).
    let c = math::mul_mtv(&b.rot, math::sub(a.c, b.c));
    let u = math::scale(math::mul_mtv(&b.rot, ex), a.radius);
    let w = math::scale(math::mul_mtv(&b.rot, ey), a.radius);
    let amp = (u[2] * u[2] + w[2] * w[2]).sqrt();
    if amp <= c[2].abs() {
        return false;
    }
    let mid = w[2].atan2(u[2]);
    let half = (-c[2] / amp).acos();
    let inside = |t: f64| {
        let (ct, st) = (t.cos(), t.sin());
        let x = c[0] + ct * u[0] + st * w[0];
        let y = c[1] + ct * u[1] + st * w[1];
        x * x + y * y < b.radius * b.radius
    };
    inside(mid + half) != inside(mid - half)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rings::math::Quat;

    fn ring(c: [f64; 3], q: Quat) -> Circle {
        Circle {
            c,
            rot: q.matrix(),
            radius: 1.0,
        }
    }

    #[test]
    fn hopf_link_and_apart() {
        let flat = ring([0.0; 3], Quat::IDENTITY);
        let upright = Quat::axis_angle([1.0, 0.0, 0.0], std::f64::consts::FRAC_PI_2);
        // Through the hole: centre at distance 1 along x, in the xz plane.
        assert!(linked(&ring([1.0, 0.0, 0.0], upright), &flat));
        assert!(linked(&flat, &ring([1.0, 0.0, 0.0], upright)));
        // Beside it, and crossing the plane twice inside the disc.
        assert!(!linked(&ring([2.5, 0.0, 0.0], upright), &flat));
        let small = Circle {
            c: [0.0; 3],
            rot: upright.matrix(),
            radius: 0.5,
        };
        assert!(!linked(&small, &flat));
        // Parallel planes never link.
        assert!(!linked(&ring([0.3, 0.0, 0.2], Quat::IDENTITY), &flat));
    }
}
