//! A ring as a rigid body: centre x, velocity v, orientation q (body → world;
//! the ring's centre circle lies in the body's xy plane, its normal is the
//! body's z axis) and angular momentum L in the world frame. The torus is
//! a symmetric top (I_axis about its normal, I_diameter about any
//! diameter), so the free rotation over a step is exact: a precession
//! about the fixed L at |L|/I_diameter and a spin about the normal at
//! (L·n)(1/I_axis − 1/I_diameter) (the gyroscopic term, exactly).

use super::math::{self, M3, Quat, V3};

/// The state of one ring.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    /// Centre, m.
    pub x: V3,
    /// Velocity of the centre, m/s.
    pub v: V3,
    /// Orientation.
    pub q: Quat,
    /// Angular momentum about the centre, world frame, kg m²/s.
    pub l: V3,
}

/// Mass and inertia of a ring.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Inertia {
    pub m: f64,
    /// About a diameter.
    pub i_d: f64,
    /// About the axis (the normal).
    pub i_a: f64,
}

impl Body {
    /// The ring's normal (the body z axis in the world), from its matrix.
    pub fn normal(rot: &M3) -> V3 {
        [rot[0][2], rot[1][2], rot[2][2]]
    }

    /// Angular velocity, world frame: L/I_d + (1/I_a − 1/I_d)(L·n) n.
    pub fn omega(&self, rot: &M3, inertia: &Inertia) -> V3 {
        let n = Body::normal(rot);
        let c = (1.0 / inertia.i_a - 1.0 / inertia.i_d) * math::dot(self.l, n);
        math::axpy(math::scale(self.l, 1.0 / inertia.i_d), c, n)
    }

    /// Velocity of the material point at world position `p`.
    pub fn velocity_at(&self, omega: V3, p: V3) -> V3 {
        math::add(self.v, math::cross(omega, math::sub(p, self.x)))
    }

    /// Kinetic energy, J.
    pub fn kinetic(&self, rot: &M3, inertia: &Inertia) -> f64 {
        0.5 * inertia.m * math::dot(self.v, self.v)
            + 0.5 * math::dot(self.omega(rot, inertia), self.l)
    }

    /// The free motion over `dt`: straight line and the exact rotation of
    /// a symmetric top.
    pub fn drift(&mut self, dt: f64, inertia: &Inertia) {
        self.x = math::axpy(self.x, dt, self.v);
        let n = Body::normal(&self.q.matrix());
        let spin = dt * (1.0 / inertia.i_a - 1.0 / inertia.i_d) * math::dot(self.l, n);
        let q_spin = Quat::axis_angle([0.0, 0.0, 1.0], spin);
        let size = math::norm(self.l);
        let q = if size > 0.0 {
            let q_prec = Quat::axis_angle(math::scale(self.l, 1.0 / size), dt * size / inertia.i_d);
            q_prec.mul(self.q).mul(q_spin)
        } else {
            self.q.mul(q_spin)
        };
        self.q = q.normalized();
    }

    /// The mirror image (x → −x) of this state.
    pub fn mirrored(&self) -> Body {
        Body {
            x: math::mirror(self.x),
            v: math::mirror(self.v),
            q: self.q.mirrored(),
            l: math::mirror_axial(self.l),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn top() -> Inertia {
        Inertia {
            m: 2e-3,
            i_d: 1.6e-7,
            i_a: 3.1e-7,
        }
    }

    /// The exact drift against many tiny explicit Euler steps of
    /// dq/dt = ½ ω q with ω from the current L and q.
    #[test]
    fn drift_is_the_free_symmetric_top() {
        let inertia = top();
        let start = Body {
            x: [0.0; 3],
            v: [0.0; 3],
            q: Quat::axis_angle([0.6, 0.0, 0.8], 0.9),
            l: [2e-6, -1e-6, 3e-6],
        };
        let mut exact = start;
        exact.drift(0.05, &inertia);
        let mut q = start.q;
        let steps = 200_000;
        let h = 0.05 / steps as f64;
        for _ in 0..steps {
            let w = start.omega(&q.matrix(), &inertia);
            let dq = Quat {
                w: 0.0,
                x: w[0],
                y: w[1],
                z: w[2],
            }
            .mul(q);
            q = Quat {
                w: q.w + 0.5 * h * dq.w,
                x: q.x + 0.5 * h * dq.x,
                y: q.y + 0.5 * h * dq.y,
                z: q.z + 0.5 * h * dq.z,
            }
            .normalized();
        }
        let (a, b) = (exact.q.as_array(), q.as_array());
        for k in 0..4 {
            assert!((a[k] - b[k]).abs() < 1e-4, "{a:?} vs {b:?}");
        }
        // Energy of the free top is kept exactly (up to rounding).
        let e0 = start.kinetic(&start.q.matrix(), &inertia);
        let e1 = exact.kinetic(&exact.q.matrix(), &inertia);
        assert!((e0 - e1).abs() < 1e-12 * e0.max(1e-30) + 1e-25);
    }

    #[test]
    fn drift_commutes_with_the_mirror() {
        let inertia = top();
        let b = Body {
            x: [0.01, -0.02, 0.3],
            v: [0.1, 0.2, -0.3],
            q: Quat::axis_angle([0.6, 0.0, 0.8], 0.9),
            l: [2e-6, -1e-6, 3e-6],
        };
        let mut a = b;
        a.drift(1e-3, &inertia);
        let mut m = b.mirrored();
        m.drift(1e-3, &inertia);
        assert_eq!(a.mirrored(), m);
    }
}
