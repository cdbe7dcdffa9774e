//! The hand that holds the top ring (paper Fig. 4b, SI Movie 12: the wave
//! starts when the top ring is let go over): the held ring's centre stays
//! put while the hand turns it by `turn.angle` about a horizontal axis,
//! with the smooth profile a(t) = angle · ½(1 − cos πs), s = (t − start)/
//! duration in [0, 1]. The turn is computed in the chain's own frame and
//! mirrored after, so the mirrored chain's hand is the exact mirror image.
//! Once the hand has taken another ring (`release`, `alternate`) it holds
//! that ring's pose as gripped, or, with `alternate.lift`, carries it
//! along a straight line ([`Lift`]).

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
    /// The lift of the gripped ring (`alternate.lift`): its centre moves
    /// as this says, its orientation stays as gripped. None: it stays
    /// where it was gripped.
    pub lift: Option<Lift>,
}

/// The hand's lift of the ring it has taken: its centre carried along
/// the straight line from `from` (where it was taken) to `to` (where the
/// hand held the ring it let go), from `t0` over `duration`, with the
/// profile ½(1 − cos πs), s = (t − t0)/duration: zero speed at both
/// ends. Every coordinate is `from + f·(to − from)` with f the same for
/// all three, so the mirror image's lift is the exact mirror image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lift {
    /// Where the ring was taken (world frame), m.
    pub from: V3,
    /// Where it ends (world frame), m.
    pub to: V3,
    /// When the lift starts, s.
    pub t0: f64,
    /// How long it takes, s (more than 0).
    pub duration: f64,
}

impl Lift {
    /// The lifted ring's centre and velocity at `t`: `from` and rest
    /// before `t0`, `to` exactly and rest from `t0 + duration` on.
    pub fn at(&self, t: f64) -> (V3, V3) {
        let s = (t - self.t0) / self.duration;
        if s >= 1.0 {
            return (self.to, [0.0; 3]);
        }
        if s <= 0.0 {
            return (self.from, [0.0; 3]);
        }
        let pi = std::f64::consts::PI;
        let (c, sin) = math::cos_sin(pi * s);
        let d = math::sub(self.to, self.from);
        let x = math::axpy(self.from, 0.5 * (1.0 - c), d);
        (x, math::scale(d, 0.5 * pi * sin / self.duration))
    }
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
            return match self.lift {
                Some(lift) => {
                    let (x, v) = lift.at(t);
                    Body { x, v, ..b }
                }
                None => b,
            };
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
