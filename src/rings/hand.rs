//! The hand that holds the top ring (paper Fig. 4b, SI Movie 12: the wave
//! starts when the top ring is let go over): the held ring's centre stays
//! put while the hand turns it by `turn.angle` about a horizontal axis,
//! with the smooth profile a(t) = angle · ½(1 − cos πs), s = (t − start)/
//! duration in [0, 1]. The turn is computed in the chain's own frame and
//! mirrored after, so the mirrored chain's hand is the exact mirror image.

use super::body::Body;
use super::chain::Turn;
use super::math::{self, Quat, V3};

/// The held ring's motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hand {
    /// Centre of the held ring (unmirrored).
    pub x: V3,
    /// Its orientation before the turn (unmirrored).
    pub q0: Quat,
    pub turn: Turn,
    pub mirror: bool,
    /// The pose the hand holds once it has taken the other strand's top
    /// ring (`release`), in the world frame as it was gripped.
    pub grip: Option<Body>,
}

impl Hand {
    fn axis(&self) -> V3 {
        let (c, s) = math::cos_sin(self.turn.azimuth.to_radians());
        [c, s, 0.0]
    }

    /// The turned angle and its rate at `t`.
    fn angle(&self, t: f64) -> (f64, f64) {
        let total = self.turn.angle.to_radians();
        if self.turn.duration <= 0.0 {
            return (if t >= self.turn.start { total } else { 0.0 }, 0.0);
        }
        let s = ((t - self.turn.start) / self.turn.duration).clamp(0.0, 1.0);
        let pi = std::f64::consts::PI;
        let rate = if s > 0.0 && s < 1.0 {
            total * 0.5 * pi * (pi * s).sin() / self.turn.duration
        } else {
            0.0
        };
        (total * 0.5 * (1.0 - (pi * s).cos()), rate)
    }

    /// The held ring's state at `t`.
    pub fn body(&self, t: f64) -> Body {
        if let Some(b) = self.grip {
            return b;
        }
        let q = Quat::axis_angle(self.axis(), self.angle(t).0).mul(self.q0);
        let b = Body {
            x: self.x,
            v: [0.0; 3],
            q: q.normalized(),
            l: [0.0; 3],
        };
        if self.mirror { b.mirrored() } else { b }
    }

    /// The held ring's angular velocity at `t`.
    pub fn omega(&self, t: f64) -> V3 {
        if self.grip.is_some() {
            return [0.0; 3];
        }
        let w = math::scale(self.axis(), self.angle(t).1);
        if self.mirror {
            math::mirror_axial(w)
        } else {
            w
        }
    }
}
