//! What the batch and chain kernels (`sim::batch::kernel`,
//! `sim::chain::kernel`) share: a block's symplectic Euler update and
//! spring pair in [`Simd`] lanes, block 1's constraint, the block arrays
//! behind raw pointers, and the hand-over of arrival candidates.
//!
//! Each function applies the portable path's operations in the portable
//! path's order (`Ladder::gradient_with`, `FixedStep`), so a kernel built
//! from them keeps every lane's numbers bit for bit; all are
//! `#[inline(always)]` (see `sim::simd`) except the cold arrival path.

#![cfg(target_arch = "x86_64")]

use super::simd::{MAX_LANES, Simd};

/// The scalars every symplectic Euler step uses, one vector each.
#[derive(Clone, Copy)]
pub struct StepConsts<S> {
    /// Rest lengths a and b of the springs, and −m G.
    pub a_rest: S,
    pub b_rest: S,
    pub minus_g: S,
    /// The step h.
    pub h: S,
    /// Symplectic Euler's decay and kick for X and Y (the same) and θ.
    pub decay_xy: S,
    pub kick_xy: S,
    pub decay_theta: S,
    pub kick_theta: S,
}

impl<S: Simd> StepConsts<S> {
    /// A spring pair (`Ladder::gradient_with`'s loop body) from the offset
    /// `(ex, ey)` of the lower block's centre from the upper's and the
    /// offset `(ux, uy)` of their arms: the net force (F_a + F_b) and the
    /// difference F_b − F_a that makes the torques.
    #[inline(always)]
    pub fn spring_pair(&self, (ex, ey): (S, S), (ux, uy): (S, S)) -> ((S, S), (S, S)) {
        let one = S::splat(1.0);
        let (ax, ay, bx, by) = (ex - ux, ey - uy, ex + ux, ey + uy);
        let ka = one - self.a_rest / (ax * ax + ay * ay).sqrt();
        let kb = one - self.b_rest / (bx * bx + by * by).sqrt();
        let (fax, fay, fbx, fby) = (ka * ax, ka * ay, kb * bx, kb * by);
        ((fax + fbx, fay + fby), (fbx - fax, fby - fay))
    }

    /// Symplectic Euler for one block from its gradient `g`:
    /// v ← v d − g k, then q ← q + v h; returns (q, v) as (X, Y, θ).
    #[inline(always)]
    pub fn kick_drift(&self, q: [S; 3], v: [S; 3], [gx, gy, gt]: [S; 3]) -> ([S; 3], [S; 3]) {
        let vx = v[0] * self.decay_xy - gx * self.kick_xy;
        let vy = v[1] * self.decay_xy - gy * self.kick_xy;
        let vt = v[2] * self.decay_theta - gt * self.kick_theta;
        let x = q[0] + vx * self.h;
        let y = q[1] + vy * self.h;
        let theta = q[2] + vt * self.h;
        ([x, y, theta], [vx, vy, vt])
    }
}

/// Block 1 held by the drive: `q` and `v` replaced by `to_q` and `to_v`
/// in the lanes where `mask`'s sign bit is set.
#[inline(always)]
pub fn pin<S: Simd>(
    (q, v): ([S; 3], [S; 3]),
    (to_q, to_v): ([S; 3], [S; 3]),
    mask: S,
) -> ([S; 3], [S; 3]) {
    (
        std::array::from_fn(|i| q[i].select(to_q[i], mask)),
        std::array::from_fn(|i| v[i].select(to_v[i], mask)),
    )
}

/// Raw pointers to the block arrays a kernel steps: X, Y, θ, their rates
/// and the arrival windows.
pub struct Blocks {
    pub x: *mut f64,
    pub y: *mut f64,
    pub theta: *mut f64,
    pub vx: *mut f64,
    pub vy: *mut f64,
    pub vtheta: *mut f64,
    pub window_lo: *mut f64,
    pub window_hi: *mut f64,
}

impl Blocks {
    /// Pointers into `[x, y, θ, vx, vy, vθ, window_lo, window_hi]`.
    pub fn new(arrays: [&mut Vec<f64>; 8]) -> Self {
        let [x, y, theta, vx, vy, vtheta, window_lo, window_hi] = arrays.map(|a| a.as_mut_ptr());
        Self {
            x,
            y,
            theta,
            vx,
            vy,
            vtheta,
            window_lo,
            window_hi,
        }
    }

    /// Loads the rates at `at`.
    ///
    /// # Safety
    /// `at + LANES` must lie within the arrays.
    #[inline(always)]
    pub unsafe fn rates<S: Simd>(&self, at: usize) -> [S; 3] {
        // SAFETY: as the caller guarantees.
        unsafe {
            [
                S::load(self.vx.add(at)),
                S::load(self.vy.add(at)),
                S::load(self.vtheta.add(at)),
            ]
        }
    }

    /// Stores a vector of blocks' `q` and `v` at `at`; returns their
    /// arrival windows (lo, hi).
    ///
    /// # Safety
    /// As [`Blocks::rates`].
    #[inline(always)]
    pub unsafe fn store<S: Simd>(&self, at: usize, q: [S; 3], v: [S; 3]) -> (S, S) {
        // SAFETY: as the caller guarantees.
        unsafe {
            q[0].store(self.x.add(at));
            q[1].store(self.y.add(at));
            q[2].store(self.theta.add(at));
            v[0].store(self.vx.add(at));
            v[1].store(self.vy.add(at));
            v[2].store(self.vtheta.add(at));
            (
                S::load(self.window_lo.add(at)),
                S::load(self.window_hi.add(at)),
            )
        }
    }

    /// Hands the `candidates` lanes (bit l for lane l) of the vector at
    /// `at` to `try_record(lane, before, after)` with their (t, θ, θ̇)
    /// before and after the step, and closes the windows of those that
    /// arrived.
    ///
    /// # Safety
    /// As [`Blocks::rates`].
    #[inline(always)]
    pub unsafe fn record<S: Simd>(
        &self,
        at: usize,
        candidates: u64,
        before: [S; 3],
        after: [S; 3],
        try_record: impl FnMut(usize, (f64, f64, f64), (f64, f64, f64)) -> bool,
    ) {
        // SAFETY: as the caller guarantees.
        let windows = unsafe {
            (
                std::slice::from_raw_parts_mut(self.window_lo.add(at), S::LANES),
                std::slice::from_raw_parts_mut(self.window_hi.add(at), S::LANES),
            )
        };
        record(
            candidates,
            before.map(S::to_array),
            after.map(S::to_array),
            windows,
            try_record,
        );
    }
}

/// The exact arrival test on the candidate lanes; closes the windows of
/// the lanes that arrived.
#[cold]
#[inline(never)]
fn record(
    candidates: u64,
    before: [[f64; MAX_LANES]; 3],
    after: [[f64; MAX_LANES]; 3],
    (lo, hi): (&mut [f64], &mut [f64]),
    mut try_record: impl FnMut(usize, (f64, f64, f64), (f64, f64, f64)) -> bool,
) {
    for lane in (0..lo.len()).filter(|l| candidates >> l & 1 == 1) {
        let at = |v: &[[f64; MAX_LANES]; 3]| (v[0][lane], v[1][lane], v[2][lane]);
        if try_record(lane, at(&before), at(&after)) {
            (lo[lane], hi[lane]) = (f64::NEG_INFINITY, f64::INFINITY);
        }
    }
}
