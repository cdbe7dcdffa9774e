//! The batch step's velocity Verlet (`FixedStep::verlet` and the run
//! loop's constraint after it), lane for lane the portable path's
//! operations, as the symplectic Euler step of the parent module.

use super::super::super::lanes::pin;
use super::super::super::simd::{Simd, half_sin_cos};
use super::{Block, Consts, Landing, Mem, PieceVecs, Recorder, blend_lanes, spring};

/// `count` velocity Verlet steps of every lane from `t`; the lanes' time
/// after them. Block 1's drive at t + h comes from `piece`, or from
/// `next` in the lanes past `until`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(super) unsafe fn steps_verlet<S: Simd>(
    mem: &Mem,
    n: usize,
    c: &Consts<S>,
    v: &VerletConsts<S>,
    land: &Landing<S>,
    (piece, next, until): (&PieceVecs<S>, &PieceVecs<S>, S),
    mut t: S,
    count: u64,
    rec: &mut dyn Recorder,
) -> S {
    for k in 0..count {
        // Block 1 where the forces are evaluated (t + h) and where the
        // step ends (t_new, which differs only on landing).
        let t_h = t + c.step.h;
        let past = t_h.ge_bits(until);
        let drive_h = if past == 0 {
            piece.at(t_h)
        } else {
            blend_lanes(past, piece.at(t_h), next.at(t_h))
        };
        let (mut t_new, mut drive_new) = (t_h, drive_h);
        if k + 1 == count {
            t_new = t_h.select(land.t_stop, land.lands);
            drive_new = (
                drive_h.0.select(land.theta, land.lands),
                drive_h.1.select(land.omega, land.lands),
            );
        }
        // SAFETY: `run` checked the sizes of the arrays behind `mem`.
        unsafe { step_verlet(mem, n, c, v, (t, t_new), (drive_h, drive_new), rec) };
        t = t_new;
    }
    t
}

/// Velocity Verlet's per-lane constants.
pub(super) struct VerletConsts<S> {
    pub(super) half: S,
    pub(super) rate_xy: S,
    pub(super) rate_theta: S,
    pub(super) inv_mass_xy: S,
    pub(super) inv_mass_theta: S,
    pub(super) div_xy: S,
    pub(super) div_theta: S,
}

/// A block after Verlet's first half kick and drift: new position and
/// half-step velocity, with the angle and rate it started the step with.
#[derive(Clone, Copy)]
struct Drifted<S> {
    block: Block<S>,
    vx: S,
    vy: S,
    vt: S,
    theta0: S,
    vt0: S,
}

/// Block j's first half kick and drift (`FixedStep::verlet`'s first loop:
/// v += h/2 (a − c v), q += h v); block 1 (`FIRST`) then set to the drive
/// at t + h where driven.
#[inline(always)]
unsafe fn drift<S: Simd, const FIRST: bool>(
    m: &Mem,
    j: usize,
    parity: S,
    c: &Consts<S>,
    v: &VerletConsts<S>,
    (theta_h, omega_h): (S, S),
) -> Drifted<S> {
    let at = j * S::LANES;
    // SAFETY: the caller keeps j < n.
    let (x, y, theta0, vx0, vy0, vt0, ax, ay, at_) = unsafe {
        (
            S::load(m.blocks.x.add(at)),
            S::load(m.blocks.y.add(at)),
            S::load(m.blocks.theta.add(at)),
            S::load(m.blocks.vx.add(at)),
            S::load(m.blocks.vy.add(at)),
            S::load(m.blocks.vtheta.add(at)),
            S::load(m.ax.add(at)),
            S::load(m.ay.add(at)),
            S::load(m.atheta.add(at)),
        )
    };
    let vx = vx0 + v.half * (ax - v.rate_xy * vx0);
    let vy = vy0 + v.half * (ay - v.rate_xy * vy0);
    let vt = vt0 + v.half * (at_ - v.rate_theta * vt0);
    let x = x + c.step.h * vx;
    let y = y + c.step.h * vy;
    let theta = theta0 + c.step.h * vt;
    let mut qv = ([x, y, theta], [vx, vy, vt]);
    if FIRST {
        let zero = S::splat(0.0);
        let drive = ([c.clamp_x, c.clamp_y, theta_h], [zero, zero, omega_h]);
        qv = pin(qv, drive, c.driven);
    }
    let ([x, y, theta], [vx, vy, vt]) = qv;
    let (rs, rc) = half_sin_cos(theta);
    Drifted {
        block: Block {
            x,
            y,
            theta,
            rs,
            rc,
            parity,
        },
        vx,
        vy,
        vt,
        theta0,
        vt0,
    }
}

/// One velocity Verlet step of every lane (`FixedStep::verlet` and the
/// run loop's constraint after it): drift every block, forces at the new
/// positions with block 1 at the drive's t + h, the second half kick
/// v ← (v + h/2 a) / (1 + c h/2), block 1 set to the drive at t_new where
/// driven, arrival checks.
#[inline(always)]
unsafe fn step_verlet<S: Simd>(
    m: &Mem,
    n: usize,
    c: &Consts<S>,
    v: &VerletConsts<S>,
    times: (S, S),
    (drive_h, drive_new): ((S, S), (S, S)),
    rec: &mut dyn Recorder,
) {
    let flip = S::splat(-0.0);
    // SAFETY (every block access below): j < n, n ≥ 2.
    let mut upper = unsafe { drift::<S, true>(m, 0, flip, c, v, drive_h) };
    let mut lower = unsafe { drift::<S, false>(m, 1, S::splat(0.0), c, v, drive_h) };
    let mut s = spring(&upper.block, &lower.block, c);
    let g = (c.step.minus_g - s.fx, -s.fy, s.tl);
    unsafe { kick::<S, true>(m, 0, &upper, g, c, v, times, drive_new, rec) };
    for j in 1..n - 1 {
        let above = s;
        upper = lower;
        lower = unsafe { drift::<S, false>(m, j + 1, upper.block.parity ^ flip, c, v, drive_h) };
        s = spring(&upper.block, &lower.block, c);
        let g = (
            (c.step.minus_g + above.fx) - s.fx,
            above.fy - s.fy,
            above.tu + s.tl,
        );
        unsafe { kick::<S, false>(m, j, &upper, g, c, v, times, drive_new, rec) };
    }
    let g = (c.step.minus_g + s.fx, s.fy, s.tu);
    unsafe { kick::<S, false>(m, n - 1, &lower, g, c, v, times, drive_new, rec) };
}

/// Block j's acceleration a = −∂E/∂q M⁻¹ from its gradient `g`, second
/// half kick, block 1 (`FIRST`) set to the drive at t_new where driven,
/// store and arrival check.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
unsafe fn kick<S: Simd, const FIRST: bool>(
    m: &Mem,
    j: usize,
    d: &Drifted<S>,
    (gx, gy, gtheta): (S, S, S),
    c: &Consts<S>,
    v: &VerletConsts<S>,
    (t, t_new): (S, S),
    (theta1, omega1): (S, S),
    rec: &mut dyn Recorder,
) {
    let at = j * S::LANES;
    let (ax, ay, at_) = (
        (-gx) * v.inv_mass_xy,
        (-gy) * v.inv_mass_xy,
        (-gtheta) * v.inv_mass_theta,
    );
    let vx = (d.vx + v.half * ax) / v.div_xy;
    let vy = (d.vy + v.half * ay) / v.div_xy;
    let vt = (d.vt + v.half * at_) / v.div_theta;
    let mut qv = ([d.block.x, d.block.y, d.block.theta], [vx, vy, vt]);
    if FIRST {
        let zero = S::splat(0.0);
        let drive = ([c.clamp_x, c.clamp_y, theta1], [zero, zero, omega1]);
        qv = pin(qv, drive, c.driven);
    }
    let (q, v_new) = qv;
    // SAFETY: the caller keeps j < n.
    let (lo, hi) = unsafe {
        ax.store(m.ax.add(at));
        ay.store(m.ay.add(at));
        at_.store(m.atheta.add(at));
        m.blocks.store(at, q, v_new)
    };
    let candidates = q[2].le_bits(lo) | q[2].ge_bits(hi);
    if candidates != 0 {
        let (before, after) = ([t, d.theta0, d.vt0], [t_new, q[2], v_new[2]]);
        // SAFETY: as above.
        unsafe {
            m.blocks
                .record(at, candidates, before, after, |lane, before, after| {
                    rec.try_record(lane, j, before, after)
                })
        };
    }
}
