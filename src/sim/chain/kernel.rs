//! The chain step: symplectic Euler on one long ladder, consecutive blocks
//! across the lanes of a vector.
//!
//! Each quantity is one array, block after block, padded to whole vectors
//! plus one. A step walks down the ladder a vector at a time: it loads the
//! next vector's X, Y, θ, computes their sine and cosine, takes each
//! block's lower neighbour by a lane shift (`Simd::next`) from this vector
//! and the next, computes the springs below the vector's blocks, takes the
//! spring above each block by a shift (`Simd::prev`) from this vector's
//! springs and the previous ones, updates the blocks, stores them and
//! checks arrivals; the next vector's values and this vector's springs are
//! carried to the next iteration in registers. Nothing is allocated.
//!
//! Every lane's numbers are the portable path's (`Ladder::gradient_with`):
//! the missing spring above block 1 is (−0, −0, −0) and the missing spring
//! below block N is (+0, +0, −0) in (F_x, F_y, torque), which leave the
//! portable path's first and last blocks' sums unchanged bit for bit.

use super::super::lanes::{Blocks, StepConsts, pin};
use super::super::simd::{F64x4, F64x8, Pack, Simd, half_sin_cos};
use crate::sim::Isa;

mod verlet;
pub use verlet::{VerletParams, run as run_verlet};

/// Lanes of a vector for `isa`.
pub fn lanes(isa: Isa) -> usize {
    match isa {
        Isa::Avx2 => <Avx2Chain as Simd>::LANES,
        Isa::Avx512 => <Avx512Chain as Simd>::LANES,
    }
}

type Avx2Chain = Pack<F64x4, 2>;
type Avx512Chain = F64x8;

/// The chain in arrays of `len` = (N rounded up to whole vectors) + one
/// vector; entries past N are padding blocks at rest, far apart, whose
/// springs are masked.
#[derive(Debug, Clone)]
pub struct ChainState {
    pub n: usize,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub theta: Vec<f64>,
    pub vx: Vec<f64>,
    pub vy: Vec<f64>,
    pub vtheta: Vec<f64>,
    /// Arrival candidate windows; (−∞, +∞) where nothing is pending.
    pub window_lo: Vec<f64>,
    pub window_hi: Vec<f64>,
    /// Velocity Verlet's accelerations at the current positions, and the
    /// angles and rates a step started from (`verlet`).
    pub ax: Vec<f64>,
    pub ay: Vec<f64>,
    pub atheta: Vec<f64>,
    pub theta0: Vec<f64>,
    pub vtheta0: Vec<f64>,
}

impl ChainState {
    pub fn new(n: usize, lanes: usize) -> Self {
        let len = (n.div_ceil(lanes) + 1) * lanes;
        let zeros = vec![0.0; len];
        Self {
            n,
            x: (0..len).map(|i| 1e3 * i as f64).collect(),
            y: zeros.clone(),
            theta: zeros.clone(),
            vx: zeros.clone(),
            vy: zeros.clone(),
            vtheta: zeros.clone(),
            ax: zeros.clone(),
            ay: zeros.clone(),
            atheta: zeros.clone(),
            theta0: zeros.clone(),
            vtheta0: zeros,
            window_lo: vec![f64::NEG_INFINITY; len],
            window_hi: vec![f64::INFINITY; len],
        }
    }

    fn len(&self) -> usize {
        self.x.len()
    }
}

/// The scalars of a batch of steps.
#[derive(Debug, Clone, Copy)]
pub struct ChainParams {
    pub a_rest: f64,
    pub b_rest: f64,
    pub minus_g: f64,
    pub h: f64,
    /// Symplectic Euler's decay and kick for X and Y (the same) and θ.
    pub decay_xy: f64,
    pub kick_xy: f64,
    pub decay_theta: f64,
    pub kick_theta: f64,
    /// Block 1's clamped centre, if driven.
    pub clamp: Option<[f64; 2]>,
}

/// Where the steps are and what they do to block 1 and to the arrivals.
pub trait Stepper {
    /// The time after step `k` (0-based) from `t`, and block 1's angle and
    /// rate there (read only if driven).
    fn after(&mut self, k: u64, t: f64) -> (f64, f64, f64);
    /// The time t + h, and block 1's angle and rate there (velocity
    /// Verlet's forces are evaluated there, also on a step that lands).
    fn after_h(&mut self, t: f64) -> (f64, f64, f64);
    /// The exact arrival test of block `block`.
    fn try_record(&mut self, block: usize, before: (f64, f64, f64), after: (f64, f64, f64))
    -> bool;
}

/// Takes `count` steps from `t`; returns the time reached.
///
/// # Safety
/// The CPU must support `isa`; `state` must have been made by
/// [`ChainState::new`] for [`lanes`]`(isa)` lanes, with N > lanes.
pub unsafe fn run(
    isa: Isa,
    state: &mut ChainState,
    p: &ChainParams,
    t: f64,
    count: u64,
    stepper: &mut dyn Stepper,
) -> f64 {
    let w = lanes(isa);
    let len = state.len();
    assert!(state.n > w && len == (state.n.div_ceil(w) + 1) * w);
    assert!(
        [
            &state.y,
            &state.theta,
            &state.vx,
            &state.vy,
            &state.vtheta,
            &state.window_lo,
            &state.window_hi,
        ]
        .iter()
        .all(|v| v.len() == len)
    );
    // SAFETY: the caller guarantees the instruction set; sizes checked.
    unsafe {
        match isa {
            Isa::Avx2 => run_avx2(state, p, t, count, stepper),
            Isa::Avx512 => run_avx512(state, p, t, count, stepper),
        }
    }
}

#[target_feature(enable = "avx2")]
unsafe fn run_avx2(
    state: &mut ChainState,
    p: &ChainParams,
    t: f64,
    count: u64,
    stepper: &mut dyn Stepper,
) -> f64 {
    // SAFETY: as `run`.
    unsafe { body::<Avx2Chain>(state, p, t, count, stepper) }
}

#[target_feature(enable = "avx2,avx512f")]
unsafe fn run_avx512(
    state: &mut ChainState,
    p: &ChainParams,
    t: f64,
    count: u64,
    stepper: &mut dyn Stepper,
) -> f64 {
    // SAFETY: as `run`.
    unsafe { body::<Avx512Chain>(state, p, t, count, stepper) }
}

/// The vectors every step uses.
struct Consts<S> {
    step: StepConsts<S>,
    /// −0.0 in the lanes of even blocks ((−1)^n = −1), +0.0 in odd ones.
    parity: S,
    /// All ones in the lanes of the last vector whose spring exists.
    last_springs: S,
    /// −0.0 in lane 0 (block 1), +0.0 elsewhere.
    first: S,
}

#[inline(always)]
unsafe fn body<S: Simd>(
    state: &mut ChainState,
    p: &ChainParams,
    t0: f64,
    count: u64,
    stepper: &mut dyn Stepper,
) -> f64 {
    let n = state.n;
    let w = S::LANES;
    let vectors = n.div_ceil(w);
    // The last vector's first block; its springs exist for blocks < N − 1.
    let last = (vectors - 1) * w;
    let ones = f64::from_bits(u64::MAX);
    let c = Consts {
        step: StepConsts {
            a_rest: S::splat(p.a_rest),
            b_rest: S::splat(p.b_rest),
            minus_g: S::splat(p.minus_g),
            h: S::splat(p.h),
            decay_xy: S::splat(p.decay_xy),
            kick_xy: S::splat(p.kick_xy),
            decay_theta: S::splat(p.decay_theta),
            kick_theta: S::splat(p.kick_theta),
        },
        parity: S::from_fn(|l| if l % 2 == 0 { -0.0 } else { 0.0 }),
        last_springs: S::from_fn(|l| if last + l + 1 < n { ones } else { 0.0 }),
        first: S::from_fn(|l| if l == 0 { -0.0 } else { 0.0 }),
    };
    let mem = Blocks::new([
        &mut state.x,
        &mut state.y,
        &mut state.theta,
        &mut state.vx,
        &mut state.vy,
        &mut state.vtheta,
        &mut state.window_lo,
        &mut state.window_hi,
    ]);
    let mut t = t0;
    for k in 0..count {
        let (t_new, theta1, omega1) = stepper.after(k, t);
        let drive = p.clamp.map(|[cx, cy]| [cx, cy, theta1, omega1]);
        // SAFETY: `run` checked the sizes of the arrays behind `mem`.
        unsafe { step(&mem, vectors, &c, (t, t_new), drive, stepper) };
        t = t_new;
    }
    t
}

/// The angles of a vector of blocks: θ, r sin θ, r cos θ and both with
/// the parity's sign.
#[derive(Clone, Copy)]
struct Angles<S> {
    theta: S,
    rs: S,
    rc: S,
    rsp: S,
    rcp: S,
}

/// F_x, F_y and the torque on the lower block (tu) of the springs below a
/// vector of blocks.
#[derive(Clone, Copy)]
struct Springs<S> {
    fx: S,
    fy: S,
    tu: S,
}

#[inline(always)]
unsafe fn angles<S: Simd>(m: &Blocks, at: usize, parity: S) -> Angles<S> {
    // SAFETY: the caller keeps `at` within the arrays, less a vector.
    let theta = unsafe { S::load(m.theta.add(at)) };
    let (rs, rc) = half_sin_cos(theta);
    Angles {
        theta,
        rs,
        rc,
        rsp: rs ^ parity,
        rcp: rc ^ parity,
    }
}

/// One step: every vector of blocks in turn, block 1 set to `drive`
/// ([X, Y, θ, θ̇]) if driven. The first and the last vector (where the
/// springs end) are peeled off the loop.
#[inline(always)]
unsafe fn step<S: Simd>(
    m: &Blocks,
    vectors: usize,
    c: &Consts<S>,
    times: (f64, f64),
    drive: Option<[f64; 4]>,
    stepper: &mut dyn Stepper,
) {
    let w = S::LANES;
    let minus_zero = S::splat(-0.0);
    let above = Springs {
        fx: minus_zero,
        fy: minus_zero,
        tu: minus_zero,
    };
    // SAFETY (every access below): vector i + 1 ≤ `vectors` lies within
    // the arrays (one padding vector past the last); `vectors` ≥ 2.
    let mut cur = unsafe { angles(m, 0, c.parity) };
    let mut next = unsafe { angles(m, w, c.parity) };
    let mut above = match drive {
        Some(d) => unsafe {
            vector::<S, true, false>(m, 0, &cur, &next, above, c, times, stepper, d)
        },
        None => unsafe {
            vector::<S, false, false>(m, 0, &cur, &next, above, c, times, stepper, [0.0; 4])
        },
    };
    for i in 1..vectors - 1 {
        cur = next;
        next = unsafe { angles(m, (i + 1) * w, c.parity) };
        above = unsafe {
            vector::<S, false, false>(m, i * w, &cur, &next, above, c, times, stepper, [0.0; 4])
        };
    }
    let at = (vectors - 1) * w;
    cur = next;
    next = unsafe { angles(m, at + w, c.parity) };
    unsafe { vector::<S, false, true>(m, at, &cur, &next, above, c, times, stepper, [0.0; 4]) };
}

/// The springs below the blocks at `at` (angles `b`, the next vector's
/// `next`), the blocks' update, store and arrival check; returns the
/// springs. `FIRST`: block 1 is set to `drive`; `LAST`: the springs past
/// block N are masked.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
unsafe fn vector<S: Simd, const FIRST: bool, const LAST: bool>(
    m: &Blocks,
    at: usize,
    b: &Angles<S>,
    next: &Angles<S>,
    above: Springs<S>,
    c: &Consts<S>,
    (t, t_new): (f64, f64),
    stepper: &mut dyn Stepper,
    [cx, cy, th1, om1]: [f64; 4],
) -> Springs<S> {
    // SAFETY: the caller keeps `at` within the arrays, less a vector; the
    // blocks below (at + 1 …) are not yet stored this step.
    let (x, y, lx, ly) = unsafe {
        (
            S::load(m.x.add(at)),
            S::load(m.y.add(at)),
            S::load(m.x.add(at + 1)),
            S::load(m.y.add(at + 1)),
        )
    };
    // Each block's lower neighbour.
    let (lrs, lrc) = (b.rs.next(next.rs), b.rc.next(next.rc));
    let (lrsp, lrcp) = (b.rsp.next(next.rsp), b.rcp.next(next.rcp));
    let e = (lx - x, ly - y);
    let arms = (lrs - b.rs, lrcp - b.rcp);
    let ((mut fx, mut fy), (dfx, dfy)) = c.step.spring_pair(e, arms);
    let mut tu = dfx * lrc - dfy * lrsp;
    let mut tl = -(dfx * b.rc - dfy * b.rsp);
    if LAST {
        // Below block N: (+0, +0, −0); none on the padding blocks.
        fx = fx & c.last_springs;
        fy = fy & c.last_springs;
        tu = tu & c.last_springs;
        tl = S::splat(-0.0).select(tl, c.last_springs);
    }
    // Each block's spring above.
    let (afx, afy, atu) = (fx.prev(above.fx), fy.prev(above.fy), tu.prev(above.tu));
    let (gx, gy, gt) = ((c.step.minus_g + afx) - fx, afy - fy, atu + tl);
    // SAFETY: as above.
    let v0 = unsafe { m.rates(at) };
    let mut qv = c.step.kick_drift([x, y, b.theta], v0, [gx, gy, gt]);
    if FIRST {
        let zero = S::splat(0.0);
        let drive = (
            [S::splat(cx), S::splat(cy), S::splat(th1)],
            [zero, zero, S::splat(om1)],
        );
        qv = pin(qv, drive, c.first);
    }
    let (q, v) = qv;
    // SAFETY: as above.
    let (lo, hi) = unsafe { m.store(at, q, v) };
    let candidates = q[2].le_bits(lo) | q[2].ge_bits(hi);
    if candidates != 0 {
        let before = [S::splat(t), b.theta, v0[2]];
        let after = [S::splat(t_new), q[2], v[2]];
        // SAFETY: as above.
        unsafe {
            m.record(at, candidates, before, after, |lane, before, after| {
                stepper.try_record(at + lane, before, after)
            })
        };
    }
    Springs { fx, fy, tu }
}
