//! Vectors and unit quaternions for the ring chain, written so that every
//! operation commutes with the mirror x → −x bit for bit: each formula is
//! a fixed sum of products, IEEE rounding is symmetric under a change of
//! sign, and angles enter through [`cos_sin`], which is exactly even and
//! odd. The mirror maps a point (polar vector) by [`mirror`], an angular
//! velocity or momentum (axial vector) by [`mirror_axial`] and an
//! orientation by [`Quat::mirrored`] (conjugation by the reflection), so
//! a mirrored chain runs as the exact mirror image of its original
//! (paper Fig. 4b: the chain's helicity).

/// A vector in 3D (metres, m/s, N, ...).
pub type V3 = [f64; 3];

pub fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// `a + s b`.
pub fn axpy(a: V3, s: f64, b: V3) -> V3 {
    [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]]
}

pub fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

/// The mirror image of a point or force (x → −x).
pub fn mirror(a: V3) -> V3 {
    [-a[0], a[1], a[2]]
}

/// The mirror image of an axial vector (angular velocity, momentum,
/// torque): det(P) P a.
pub fn mirror_axial(a: V3) -> V3 {
    [a[0], -a[1], -a[2]]
}

/// (cos a, sin a), exactly even and odd in `a` (whatever the libm does
/// with negative arguments).
pub fn cos_sin(a: f64) -> (f64, f64) {
    let (s, c) = a.abs().sin_cos();
    (c, if a < 0.0 { -s } else { s })
}

/// A 3 × 3 matrix, rows first.
pub type M3 = [[f64; 3]; 3];

/// `m v`.
pub fn mul_mv(m: &M3, v: V3) -> V3 {
    [dot(m[0], v), dot(m[1], v), dot(m[2], v)]
}

/// `mᵀ v`.
pub fn mul_mtv(m: &M3, v: V3) -> V3 {
    [
        m[0][0] * v[0] + m[1][0] * v[1] + m[2][0] * v[2],
        m[0][1] * v[0] + m[1][1] * v[1] + m[2][1] * v[2],
        m[0][2] * v[0] + m[1][2] * v[1] + m[2][2] * v[2],
    ]
}

/// A unit quaternion w + x i + y j + z k: an orientation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quat {
    pub w: f64,
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

impl Quat {
    pub const IDENTITY: Quat = Quat {
        w: 1.0,
        x: 0.0,
        y: 0.0,
        z: 0.0,
    };

    /// The rotation by `angle` (radians, right-handed) about the unit
    /// vector `axis`.
    pub fn axis_angle(axis: V3, angle: f64) -> Quat {
        let (c, s) = cos_sin(0.5 * angle);
        Quat {
            w: c,
            x: s * axis[0],
            y: s * axis[1],
            z: s * axis[2],
        }
    }

    /// `self ⊗ o`: first `o`, then `self`.
    #[allow(clippy::should_implement_trait)] // a product of rotations, spelled as the formula
    pub fn mul(self, o: Quat) -> Quat {
        Quat {
            w: self.w * o.w - self.x * o.x - self.y * o.y - self.z * o.z,
            x: self.w * o.x + self.x * o.w + self.y * o.z - self.z * o.y,
            y: self.w * o.y - self.x * o.z + self.y * o.w + self.z * o.x,
            z: self.w * o.z + self.x * o.y - self.y * o.x + self.z * o.w,
        }
    }

    pub fn conj(self) -> Quat {
        Quat {
            w: self.w,
            x: -self.x,
            y: -self.y,
            z: -self.z,
        }
    }

    pub fn normalized(self) -> Quat {
        let n = (self.w * self.w + self.x * self.x + self.y * self.y + self.z * self.z).sqrt();
        Quat {
            w: self.w / n,
            x: self.x / n,
            y: self.y / n,
            z: self.z / n,
        }
    }

    /// The rotation matrix (body → world).
    pub fn matrix(self) -> M3 {
        let Quat { w, x, y, z } = self;
        [
            [
                1.0 - 2.0 * (y * y + z * z),
                2.0 * (x * y - w * z),
                2.0 * (x * z + w * y),
            ],
            [
                2.0 * (x * y + w * z),
                1.0 - 2.0 * (x * x + z * z),
                2.0 * (y * z - w * x),
            ],
            [
                2.0 * (x * z - w * y),
                2.0 * (y * z + w * x),
                1.0 - 2.0 * (x * x + y * y),
            ],
        ]
    }

    /// The mirror image of the orientation: P R P with P = diag(−1, 1, 1).
    pub fn mirrored(self) -> Quat {
        Quat {
            w: self.w,
            x: self.x,
            y: -self.y,
            z: -self.z,
        }
    }

    pub fn as_array(self) -> [f64; 4] {
        [self.w, self.x, self.y, self.z]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matrix_rotates_like_the_quaternion() {
        let q = Quat::axis_angle([0.0, 0.6, 0.8], 0.7);
        let v = [0.3, -1.2, 0.5];
        let p = Quat {
            w: 0.0,
            x: v[0],
            y: v[1],
            z: v[2],
        };
        let r = q.mul(p).mul(q.conj());
        let m = mul_mv(&q.matrix(), v);
        for k in 0..3 {
            assert!((m[k] - [r.x, r.y, r.z][k]).abs() < 1e-14);
        }
        let back = mul_mtv(&q.matrix(), m);
        for k in 0..3 {
            assert!((back[k] - v[k]).abs() < 1e-14);
        }
    }

    #[test]
    fn the_mirror_commutes_with_rotation_bit_for_bit() {
        let q =
            Quat::axis_angle([0.48, 0.6, 0.64], 1.3).mul(Quat::axis_angle([0.0, 0.0, 1.0], -0.4));
        let v = [0.31, -1.27, 0.53];
        let a = mirror(mul_mv(&q.matrix(), v));
        let b = mul_mv(&q.mirrored().matrix(), mirror(v));
        assert_eq!(a, b);
        let w = [0.2, 0.7, -0.1];
        assert_eq!(mirror_axial(cross(w, v)), cross(mirror(w), mirror(v)));
        assert_eq!(cross(mirror_axial(w), mirror(v)), mirror(cross(w, v)));
        assert_eq!(cos_sin(-0.3).1, -cos_sin(0.3).1);
    }
}
