//! The batch step: symplectic Euler for a vector of runs of the same N,
//! one run per lane, all in lockstep.
//!
//! Memory holds every block's X, Y, θ, their velocities and the arrival
//! windows as [block][lane]; a step walks down the ladder once, block by
//! block: load block j + 1, its sine and cosine, spring j, block j's
//! gradient from springs j − 1 and j, its update, the store and the arrival
//! check, then move down one. The springs and the sine and cosine are
//! computed once per block, in registers, and every load and store is a
//! whole vector. Lanes never talk to each other, so a lane's numbers are
//! the portable path's for its run, operation for operation
//! (`Ladder::gradient_with` with r = s/2 folded into sine and cosine, as in
//! `sim::fused`; no fused multiply-adds).
//!
//! Each lane has its own step h, damping factors, drive piece and time; the
//! last step of a call may land a lane on its stop time (`lands`), as the
//! portable plan's last step of an interval does.

use super::super::lanes::{Blocks, StepConsts, pin};
use super::super::simd::{F64x4, F64x8, Pack, Simd, half_sin_cos};
use crate::sim::Isa;
use verlet::{VerletConsts, steps_verlet};

mod verlet;

/// The most lanes of any instruction set's batch.
pub const MAX_LANES: usize = 16;

/// The lanes of a batch for `isa`.
pub fn lanes(isa: Isa) -> usize {
    match isa {
        Isa::Avx2 => <Avx2Batch as Simd>::LANES,
        Isa::Avx512 => <Avx512Batch as Simd>::LANES,
    }
}

/// The vector of runs for each instruction set: two registers of four
/// lanes for AVX2 (two independent streams), one of eight for AVX-512.
type Avx2Batch = Pack<F64x4, 2>;
type Avx512Batch = F64x8;

/// A lane's scalars, one array entry per lane.
#[derive(Debug, Clone, Default)]
pub struct LaneParams {
    /// Rest lengths a and b, and −m G.
    pub a_rest: [f64; MAX_LANES],
    pub b_rest: [f64; MAX_LANES],
    pub minus_g: [f64; MAX_LANES],
    /// This call's step, and symplectic Euler's decay and kick for X and Y
    /// (the same) and for θ.
    pub h: [f64; MAX_LANES],
    pub decay_xy: [f64; MAX_LANES],
    pub kick_xy: [f64; MAX_LANES],
    pub decay_theta: [f64; MAX_LANES],
    pub kick_theta: [f64; MAX_LANES],
    /// The lane's time (read and written by the kernel).
    pub t: [f64; MAX_LANES],
    /// −0.0 where the call's last step lands on `t_stop`, else +0.0.
    pub lands: [f64; MAX_LANES],
    pub t_stop: [f64; MAX_LANES],
    /// Block 1's angle and rate where it lands (the drive's next piece).
    pub land_theta: [f64; MAX_LANES],
    pub land_omega: [f64; MAX_LANES],
    /// −0.0 where block 1 is driven, else +0.0; its clamped centre.
    pub driven: [f64; MAX_LANES],
    pub clamp_x: [f64; MAX_LANES],
    pub clamp_y: [f64; MAX_LANES],
    /// The drive's piece for the call's steps, and the one after it, in
    /// force from `until` on.
    pub piece: PieceLanes,
    pub next_piece: PieceLanes,
    pub until: [f64; MAX_LANES],
    /// Velocity Verlet's h/2, damping rates c, M⁻¹ and divisors 1 + c h/2,
    /// for X and Y (the same) and θ.
    pub half: [f64; MAX_LANES],
    pub rate_xy: [f64; MAX_LANES],
    pub rate_theta: [f64; MAX_LANES],
    pub inv_mass_xy: [f64; MAX_LANES],
    pub inv_mass_theta: [f64; MAX_LANES],
    pub div_xy: [f64; MAX_LANES],
    pub div_theta: [f64; MAX_LANES],
}

/// A drive piece per lane: −0.0 in `ramp` for a ramp
/// θ_s + (Δθ (t − t_0)) / T, +0.0 for a hold at `hold_theta`; rate ω.
#[derive(Debug, Clone, Default)]
pub struct PieceLanes {
    pub ramp: [f64; MAX_LANES],
    pub theta_start: [f64; MAX_LANES],
    pub theta_delta: [f64; MAX_LANES],
    pub t0: [f64; MAX_LANES],
    pub span: [f64; MAX_LANES],
    pub hold_theta: [f64; MAX_LANES],
    pub omega: [f64; MAX_LANES],
}

/// The lanes' state, [block][lane]: `lanes` values per block.
#[derive(Debug, Clone)]
pub struct LaneState {
    pub n: usize,
    pub lanes: usize,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub theta: Vec<f64>,
    pub vx: Vec<f64>,
    pub vy: Vec<f64>,
    pub vtheta: Vec<f64>,
    /// Arrival candidate windows (`ArrivalDetector::window`); (−∞, +∞)
    /// where nothing is pending.
    pub window_lo: Vec<f64>,
    pub window_hi: Vec<f64>,
    /// Velocity Verlet's accelerations at the current positions.
    pub ax: Vec<f64>,
    pub ay: Vec<f64>,
    pub atheta: Vec<f64>,
    /// Velocity Verlet's steps, not symplectic Euler's.
    pub verlet: bool,
    pub params: LaneParams,
}

impl LaneState {
    pub fn new(n: usize, lanes: usize) -> Self {
        let zeros = vec![0.0; n * lanes];
        Self {
            n,
            lanes,
            x: zeros.clone(),
            y: zeros.clone(),
            theta: zeros.clone(),
            vx: zeros.clone(),
            vy: zeros.clone(),
            vtheta: zeros.clone(),
            window_lo: vec![f64::NEG_INFINITY; n * lanes],
            window_hi: vec![f64::INFINITY; n * lanes],
            ax: zeros.clone(),
            ay: zeros.clone(),
            atheta: zeros,
            verlet: false,
            params: LaneParams::default(),
        }
    }
}

/// The exact arrival test of a lane's run (`ArrivalDetector::try_record`).
pub trait Recorder {
    fn try_record(
        &mut self,
        lane: usize,
        block: usize,
        before: (f64, f64, f64),
        after: (f64, f64, f64),
    ) -> bool;
}

/// Takes `count` steps of every lane.
///
/// # Safety
/// The CPU must support `isa`; `state.lanes` must be [`lanes`]`(isa)` and
/// `state.n` ≥ 2.
pub unsafe fn run(isa: Isa, state: &mut LaneState, count: u64, rec: &mut dyn Recorder) {
    let len = state.n * state.lanes;
    assert!(state.n >= 2 && state.lanes == lanes(isa));
    assert!(
        [
            &state.x,
            &state.y,
            &state.theta,
            &state.vx,
            &state.vy,
            &state.vtheta,
            &state.window_lo,
            &state.window_hi,
            &state.ax,
            &state.ay,
            &state.atheta,
        ]
        .iter()
        .all(|v| v.len() == len)
    );
    // SAFETY: the caller guarantees the instruction set; the sizes are
    // checked above.
    unsafe {
        match isa {
            Isa::Avx2 => run_avx2(state, count, rec),
            Isa::Avx512 => run_avx512(state, count, rec),
        }
    }
}

#[target_feature(enable = "avx2")]
unsafe fn run_avx2(state: &mut LaneState, count: u64, rec: &mut dyn Recorder) {
    // SAFETY: as `run`.
    unsafe { body::<Avx2Batch>(state, count, rec) }
}

#[target_feature(enable = "avx2,avx512f")]
unsafe fn run_avx512(state: &mut LaneState, count: u64, rec: &mut dyn Recorder) {
    // SAFETY: as `run`.
    unsafe { body::<Avx512Batch>(state, count, rec) }
}

/// The lanes' constants of one call, in registers.
struct Consts<S> {
    step: StepConsts<S>,
    driven: S,
    clamp_x: S,
    clamp_y: S,
}

/// Raw pointers to the lanes' arrays.
struct Mem {
    blocks: Blocks,
    ax: *mut f64,
    ay: *mut f64,
    atheta: *mut f64,
}

/// Loads a parameter array into a vector.
macro_rules! param {
    ($p:expr, $($field:ident).+) => {
        // SAFETY: every parameter array holds MAX_LANES ≥ LANES values.
        unsafe { S::load($p.$($field).+.as_ptr()) }
    };
}

/// A drive piece in registers.
#[derive(Clone, Copy)]
struct PieceVecs<S> {
    ramp: S,
    theta_start: S,
    theta_delta: S,
    t0: S,
    span: S,
    hold_theta: S,
    omega: S,
}

impl<S: Simd> PieceVecs<S> {
    #[inline(always)]
    fn load(p: &PieceLanes) -> Self {
        Self {
            ramp: param!(p, ramp),
            theta_start: param!(p, theta_start),
            theta_delta: param!(p, theta_delta),
            t0: param!(p, t0),
            span: param!(p, span),
            hold_theta: param!(p, hold_theta),
            omega: param!(p, omega),
        }
    }

    /// Block 1's angle and rate at `t` (`Piece::theta`, operation for
    /// operation, and `Piece::omega`).
    #[inline(always)]
    fn at(&self, t: S) -> (S, S) {
        let ramp_theta = self.theta_start + (self.theta_delta * (t - self.t0)) / self.span;
        (self.hold_theta.select(ramp_theta, self.ramp), self.omega)
    }
}

#[inline(always)]
unsafe fn body<S: Simd>(state: &mut LaneState, count: u64, rec: &mut dyn Recorder) {
    let n = state.n;
    let p = &state.params;
    let c = Consts::<S> {
        step: StepConsts {
            a_rest: param!(p, a_rest),
            b_rest: param!(p, b_rest),
            minus_g: param!(p, minus_g),
            h: param!(p, h),
            decay_xy: param!(p, decay_xy),
            kick_xy: param!(p, kick_xy),
            decay_theta: param!(p, decay_theta),
            kick_theta: param!(p, kick_theta),
        },
        driven: param!(p, driven),
        clamp_x: param!(p, clamp_x),
        clamp_y: param!(p, clamp_y),
    };
    let land = Landing {
        lands: param!(p, lands),
        t_stop: param!(p, t_stop),
        theta: param!(p, land_theta),
        omega: param!(p, land_omega),
    };
    let piece = PieceVecs::<S>::load(&p.piece);
    let mem = Mem {
        blocks: Blocks::new([
            &mut state.x,
            &mut state.y,
            &mut state.theta,
            &mut state.vx,
            &mut state.vy,
            &mut state.vtheta,
            &mut state.window_lo,
            &mut state.window_hi,
        ]),
        ax: state.ax.as_mut_ptr(),
        ay: state.ay.as_mut_ptr(),
        atheta: state.atheta.as_mut_ptr(),
    };
    let t = param!(p, t);
    let t = if state.verlet {
        let v = VerletConsts {
            half: param!(p, half),
            rate_xy: param!(p, rate_xy),
            rate_theta: param!(p, rate_theta),
            inv_mass_xy: param!(p, inv_mass_xy),
            inv_mass_theta: param!(p, inv_mass_theta),
            div_xy: param!(p, div_xy),
            div_theta: param!(p, div_theta),
        };
        let next = PieceVecs::<S>::load(&p.next_piece);
        let until = param!(p, until);
        // SAFETY: as `run`.
        unsafe {
            steps_verlet(
                &mem,
                n,
                &c,
                &v,
                &land,
                (&piece, &next, until),
                t,
                count,
                rec,
            )
        }
    } else {
        // SAFETY: as `run`.
        unsafe { steps_euler(&mem, n, &c, &land, &piece, t, count, rec) }
    };
    // SAFETY: as `param!`.
    unsafe { t.store(state.params.t.as_mut_ptr()) };
}

/// Where a call's last step lands: `lands` (−0.0 where it lands on
/// `t_stop`) and block 1's angle and rate there.
struct Landing<S> {
    lands: S,
    t_stop: S,
    theta: S,
    omega: S,
}

/// `count` symplectic Euler steps of every lane from `t`; the lanes'
/// time after them.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
unsafe fn steps_euler<S: Simd>(
    mem: &Mem,
    n: usize,
    c: &Consts<S>,
    land: &Landing<S>,
    piece: &PieceVecs<S>,
    mut t: S,
    count: u64,
    rec: &mut dyn Recorder,
) -> S {
    for k in 0..count {
        let mut t_new = t + c.step.h;
        // Block 1's drive at t_new.
        let (mut theta1, mut omega1) = piece.at(t_new);
        if k + 1 == count {
            t_new = t_new.select(land.t_stop, land.lands);
            theta1 = theta1.select(land.theta, land.lands);
            omega1 = omega1.select(land.omega, land.lands);
        }
        // SAFETY: `run` checked the sizes of the arrays behind `mem`.
        unsafe { step(mem, n, c, (t, t_new), (theta1, omega1), rec) };
        t = t_new;
    }
    t
}

/// One block's centre and angle, and r sin θ, r cos θ and the parity sign.
#[derive(Clone, Copy)]
struct Block<S> {
    x: S,
    y: S,
    theta: S,
    rs: S,
    rc: S,
    /// −0.0 where (−1)^n = −1, else +0.0.
    parity: S,
}

/// The forces of the spring pair below a block: net force on the lower
/// block, torques on the lower (tu) and upper (tl) block.
#[derive(Clone, Copy)]
struct Spring<S> {
    fx: S,
    fy: S,
    tu: S,
    tl: S,
}

#[inline(always)]
unsafe fn load_block<S: Simd>(m: &Mem, j: usize, parity: S) -> Block<S> {
    let at = j * S::LANES;
    // SAFETY: the caller keeps j < n.
    let (x, y, theta) = unsafe {
        (
            S::load(m.blocks.x.add(at)),
            S::load(m.blocks.y.add(at)),
            S::load(m.blocks.theta.add(at)),
        )
    };
    let (rs, rc) = half_sin_cos(theta);
    Block {
        x,
        y,
        theta,
        rs,
        rc,
        parity,
    }
}

/// Spring pair j between blocks `u` (j) and `l` (j + 1):
/// `Ladder::gradient_with`'s loop body.
#[inline(always)]
fn spring<S: Simd>(u: &Block<S>, l: &Block<S>, c: &Consts<S>) -> Spring<S> {
    let e = (l.x - u.x, l.y - u.y);
    let arms = (l.rs - u.rs, (l.rc ^ l.parity) - (u.rc ^ u.parity));
    let ((fx, fy), (dfx, dfy)) = c.step.spring_pair(e, arms);
    Spring {
        fx,
        fy,
        tu: dfx * l.rc - (dfy ^ l.parity) * l.rs,
        tl: -(dfx * u.rc - (dfy ^ u.parity) * u.rs),
    }
}

/// One step of every lane: symplectic Euler on every block, block 1
/// constrained where driven, arrival checks.
#[inline(always)]
unsafe fn step<S: Simd>(
    m: &Mem,
    n: usize,
    c: &Consts<S>,
    times: (S, S),
    drive: (S, S),
    rec: &mut dyn Recorder,
) {
    let flip = S::splat(-0.0);
    // SAFETY (every block access below): j < n, n ≥ 2.
    let mut upper = unsafe { load_block(m, 0, flip) };
    let mut lower = unsafe { load_block(m, 1, S::splat(0.0)) };
    let mut s = spring(&upper, &lower, c);
    let g = (c.step.minus_g - s.fx, -s.fy, s.tl);
    unsafe { update::<S, true>(m, 0, &upper, g, c, times, drive, rec) };
    for j in 1..n - 1 {
        let above = s;
        upper = lower;
        lower = unsafe { load_block(m, j + 1, upper.parity ^ flip) };
        s = spring(&upper, &lower, c);
        let g = (
            (c.step.minus_g + above.fx) - s.fx,
            above.fy - s.fy,
            above.tu + s.tl,
        );
        unsafe { update::<S, false>(m, j, &upper, g, c, times, drive, rec) };
    }
    let g = (c.step.minus_g + s.fx, s.fy, s.tu);
    unsafe { update::<S, false>(m, n - 1, &lower, g, c, times, drive, rec) };
}

/// Block j's update from its gradient `g`: v ← v d − g k, q ← q + h v;
/// block 1 (`FIRST`) set to the drive where driven; then the arrival check.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
unsafe fn update<S: Simd, const FIRST: bool>(
    m: &Mem,
    j: usize,
    b: &Block<S>,
    (gx, gy, gtheta): (S, S, S),
    c: &Consts<S>,
    (t, t_new): (S, S),
    (theta1, omega1): (S, S),
    rec: &mut dyn Recorder,
) {
    let at = j * S::LANES;
    // SAFETY: the caller keeps j < n.
    let v0 = unsafe { m.blocks.rates(at) };
    let mut qv = c.step.kick_drift([b.x, b.y, b.theta], v0, [gx, gy, gtheta]);
    if FIRST {
        let zero = S::splat(0.0);
        let drive = ([c.clamp_x, c.clamp_y, theta1], [zero, zero, omega1]);
        qv = pin(qv, drive, c.driven);
    }
    let (q, v) = qv;
    // SAFETY: as above.
    let (lo, hi) = unsafe { m.blocks.store(at, q, v) };
    let candidates = q[2].le_bits(lo) | q[2].ge_bits(hi);
    if candidates != 0 {
        let (before, after) = ([t, b.theta, v0[2]], [t_new, q[2], v[2]]);
        // SAFETY: as above.
        unsafe {
            m.blocks
                .record(at, candidates, before, after, |lane, before, after| {
                    rec.try_record(lane, j, before, after)
                })
        };
    }
}

/// Lanes of `b` where `mask` has a bit, else of `a` (rare: a drive corner
/// crossed inside a step).
#[cold]
#[inline(never)]
fn blend_lanes<S: Simd>(mask: u64, a: (S, S), b: (S, S)) -> (S, S) {
    let pick = |x: S, y: S| {
        let (x, y) = (x.to_array(), y.to_array());
        S::from_fn(|l| if mask >> l & 1 == 1 { y[l] } else { x[l] })
    };
    (pick(a.0, b.0), pick(a.1, b.1))
}
