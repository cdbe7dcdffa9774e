//! The chain step's velocity Verlet (`FixedStep::verlet` and the run
//! loop's constraint after it) on one long ladder: per step, a first pass
//! down the arrays takes every block's first half kick and drift
//! (v ← v + h/2 (a − c v), q ← q + h v; block 1 then set to the drive at
//! t + h), and a second pass computes the springs at the drifted
//! positions as the symplectic Euler pass does (`super::vector`), the
//! accelerations a = −∂E/∂q M⁻¹ and the second half kick
//! v ← (v + h/2 a) / (1 + c h/2), block 1 set to the drive at the step's
//! end, arrival checks. Every lane's numbers are the portable path's, in
//! its order, bit for bit.

use super::super::super::lanes::{Blocks, StepConsts, pin};
use super::super::super::simd::Simd;
use super::{Angles, Avx2Chain, Avx512Chain, ChainParams, ChainState, Springs, Stepper, angles};
use crate::sim::Isa;

/// Velocity Verlet's scalars besides the chain's: h/2, the damping rates
/// c, M⁻¹ and the divisors 1 + c h/2, for X and Y (the same) and θ.
#[derive(Debug, Clone, Copy)]
pub struct VerletParams {
    pub half: f64,
    pub rate_xy: f64,
    pub rate_theta: f64,
    pub inv_mass_xy: f64,
    pub inv_mass_theta: f64,
    pub div_xy: f64,
    pub div_theta: f64,
}

/// [`VerletParams`] as vectors, with the chain's constants.
struct Consts<S> {
    step: StepConsts<S>,
    parity: S,
    last_springs: S,
    first: S,
    half: S,
    rate_xy: S,
    rate_theta: S,
    inv_mass_xy: S,
    inv_mass_theta: S,
    div_xy: S,
    div_theta: S,
}

/// Takes `count` velocity Verlet steps from `t`; returns the time reached.
/// `state.ax`, `ay`, `atheta` hold the accelerations at the current
/// positions on entry and on return.
///
/// # Safety
/// As [`super::run`].
pub unsafe fn run(
    isa: Isa,
    state: &mut ChainState,
    p: &ChainParams,
    vp: &VerletParams,
    t: f64,
    count: u64,
    stepper: &mut dyn Stepper,
) -> f64 {
    let w = super::lanes(isa);
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
            &state.ax,
            &state.ay,
            &state.atheta,
            &state.theta0,
            &state.vtheta0,
        ]
        .iter()
        .all(|v| v.len() == len)
    );
    // SAFETY: the caller guarantees the instruction set; sizes checked.
    unsafe {
        match isa {
            Isa::Avx2 => run_avx2(state, p, vp, t, count, stepper),
            Isa::Avx512 => run_avx512(state, p, vp, t, count, stepper),
        }
    }
}

#[target_feature(enable = "avx2")]
unsafe fn run_avx2(
    state: &mut ChainState,
    p: &ChainParams,
    vp: &VerletParams,
    t: f64,
    count: u64,
    stepper: &mut dyn Stepper,
) -> f64 {
    // SAFETY: as `run`.
    unsafe { body::<Avx2Chain>(state, p, vp, t, count, stepper) }
}

#[target_feature(enable = "avx2,avx512f")]
unsafe fn run_avx512(
    state: &mut ChainState,
    p: &ChainParams,
    vp: &VerletParams,
    t: f64,
    count: u64,
    stepper: &mut dyn Stepper,
) -> f64 {
    // SAFETY: as `run`.
    unsafe { body::<Avx512Chain>(state, p, vp, t, count, stepper) }
}

/// Raw pointers to the accelerations and the angles and rates a step
/// started from.
struct Extra {
    ax: *mut f64,
    ay: *mut f64,
    atheta: *mut f64,
    theta0: *mut f64,
    vtheta0: *mut f64,
}

/// The constants of every Verlet step of `n` blocks, in registers (`last`:
/// the first block of the last vector).
#[inline(always)]
unsafe fn consts<S: Simd>(p: &ChainParams, vp: &VerletParams, n: usize, last: usize) -> Consts<S> {
    let ones = f64::from_bits(u64::MAX);
    Consts {
        step: StepConsts {
            a_rest: S::splat(p.a_rest),
            b_rest: S::splat(p.b_rest),
            minus_g: S::splat(p.minus_g),
            h: S::splat(p.h),
            decay_xy: S::splat(0.0),
            kick_xy: S::splat(0.0),
            decay_theta: S::splat(0.0),
            kick_theta: S::splat(0.0),
        },
        parity: S::from_fn(|l| if l % 2 == 0 { -0.0 } else { 0.0 }),
        last_springs: S::from_fn(|l| if last + l + 1 < n { ones } else { 0.0 }),
        first: S::from_fn(|l| if l == 0 { -0.0 } else { 0.0 }),
        half: S::splat(vp.half),
        rate_xy: S::splat(vp.rate_xy),
        rate_theta: S::splat(vp.rate_theta),
        inv_mass_xy: S::splat(vp.inv_mass_xy),
        inv_mass_theta: S::splat(vp.inv_mass_theta),
        div_xy: S::splat(vp.div_xy),
        div_theta: S::splat(vp.div_theta),
    }
}

#[inline(always)]
unsafe fn body<S: Simd>(
    state: &mut ChainState,
    p: &ChainParams,
    vp: &VerletParams,
    t0: f64,
    count: u64,
    stepper: &mut dyn Stepper,
) -> f64 {
    let n = state.n;
    let w = S::LANES;
    let vectors = n.div_ceil(w);
    let last = (vectors - 1) * w;
    // SAFETY: as the caller's.
    let c = unsafe { consts::<S>(p, vp, n, last) };
    let extra = Extra {
        ax: state.ax.as_mut_ptr(),
        ay: state.ay.as_mut_ptr(),
        atheta: state.atheta.as_mut_ptr(),
        theta0: state.theta0.as_mut_ptr(),
        vtheta0: state.vtheta0.as_mut_ptr(),
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
        let (t_h, theta_h, omega_h) = stepper.after_h(t);
        let (t_new, theta1, omega1) = stepper.after(k, t);
        debug_assert!(t_h == t + p.h);
        let clamp = p.clamp;
        // SAFETY: `run` checked the sizes of the arrays.
        unsafe {
            drift(
                &mem,
                &extra,
                vectors,
                &c,
                clamp.map(|[x, y]| [x, y, theta_h, omega_h]),
            );
            kick_pass(
                &mem,
                &extra,
                vectors,
                &c,
                (t, t_new),
                clamp.map(|[x, y]| [x, y, theta1, omega1]),
                stepper,
            );
        }
        t = t_new;
    }
    t
}

/// The first pass: every block's first half kick and drift, the angle
/// and rate it started from kept; block 1 set to `drive` ([X, Y, θ, θ̇]
/// at t + h) if driven.
#[inline(always)]
unsafe fn drift<S: Simd>(
    m: &Blocks,
    e: &Extra,
    vectors: usize,
    c: &Consts<S>,
    drive: Option<[f64; 4]>,
) {
    let h = c.step.h;
    for i in 0..vectors {
        let at = i * S::LANES;
        // SAFETY: vector i < `vectors` lies within the arrays.
        unsafe {
            let [vx0, vy0, vt0] = m.rates::<S>(at);
            let (x, y, theta0) = (
                S::load(m.x.add(at)),
                S::load(m.y.add(at)),
                S::load(m.theta.add(at)),
            );
            let (ax, ay, at_) = (
                S::load(e.ax.add(at)),
                S::load(e.ay.add(at)),
                S::load(e.atheta.add(at)),
            );
            let vx = vx0 + c.half * (ax - c.rate_xy * vx0);
            let vy = vy0 + c.half * (ay - c.rate_xy * vy0);
            let vt = vt0 + c.half * (at_ - c.rate_theta * vt0);
            let mut qv = ([x + h * vx, y + h * vy, theta0 + h * vt], [vx, vy, vt]);
            if let (0, Some([cx, cy, th, om])) = (i, drive) {
                let zero = S::splat(0.0);
                let to = (
                    [S::splat(cx), S::splat(cy), S::splat(th)],
                    [zero, zero, S::splat(om)],
                );
                qv = pin(qv, to, c.first);
            }
            theta0.store(e.theta0.add(at));
            vt0.store(e.vtheta0.add(at));
            m.store(at, qv.0, qv.1);
        }
    }
}

/// The second pass: the springs at the drifted positions, vector by
/// vector as the symplectic Euler pass walks them; the first and the last
/// vector peeled off.
#[inline(always)]
unsafe fn kick_pass<S: Simd>(
    m: &Blocks,
    e: &Extra,
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
    let d = drive.unwrap_or([0.0; 4]);
    let mut above = match drive {
        Some(_) => unsafe {
            vector::<S, true, false>(m, e, 0, &cur, &next, above, c, times, stepper, d)
        },
        None => unsafe {
            vector::<S, false, false>(m, e, 0, &cur, &next, above, c, times, stepper, d)
        },
    };
    for i in 1..vectors - 1 {
        cur = next;
        next = unsafe { angles(m, (i + 1) * w, c.parity) };
        above = unsafe {
            vector::<S, false, false>(m, e, i * w, &cur, &next, above, c, times, stepper, d)
        };
    }
    let at = (vectors - 1) * w;
    cur = next;
    next = unsafe { angles(m, at + w, c.parity) };
    unsafe { vector::<S, false, true>(m, e, at, &cur, &next, above, c, times, stepper, d) };
}

/// The springs below the blocks at `at` (as `super::vector`), their
/// accelerations, second half kick, store and arrival check; returns the
/// springs. `FIRST`: block 1 is set to `drive`; `LAST`: the springs past
/// block N are masked.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
unsafe fn vector<S: Simd, const FIRST: bool, const LAST: bool>(
    m: &Blocks,
    e: &Extra,
    at: usize,
    b: &Angles<S>,
    next: &Angles<S>,
    above: Springs<S>,
    c: &Consts<S>,
    (t, t_new): (f64, f64),
    stepper: &mut dyn Stepper,
    [cx, cy, th1, om1]: [f64; 4],
) -> Springs<S> {
    // SAFETY: the caller keeps `at` within the arrays, less a vector;
    // every block's drifted position is stored.
    let (x, y, lx, ly) = unsafe {
        (
            S::load(m.x.add(at)),
            S::load(m.y.add(at)),
            S::load(m.x.add(at + 1)),
            S::load(m.y.add(at + 1)),
        )
    };
    let (lrs, lrc) = (b.rs.next(next.rs), b.rc.next(next.rc));
    let lrsp = b.rsp.next(next.rsp);
    let lrcp = b.rcp.next(next.rcp);
    let ((mut fx, mut fy), (dfx, dfy)) = c
        .step
        .spring_pair((lx - x, ly - y), (lrs - b.rs, lrcp - b.rcp));
    let mut tu = dfx * lrc - dfy * lrsp;
    let mut tl = -(dfx * b.rc - dfy * b.rsp);
    if LAST {
        fx = fx & c.last_springs;
        fy = fy & c.last_springs;
        tu = tu & c.last_springs;
        tl = S::splat(-0.0).select(tl, c.last_springs);
    }
    let (afx, afy, atu) = (fx.prev(above.fx), fy.prev(above.fy), tu.prev(above.tu));
    let (gx, gy, gt) = ((c.step.minus_g + afx) - fx, afy - fy, atu + tl);
    let (ax, ay, at_) = (
        (-gx) * c.inv_mass_xy,
        (-gy) * c.inv_mass_xy,
        (-gt) * c.inv_mass_theta,
    );
    // SAFETY: as above.
    let [vx, vy, vt] = unsafe { m.rates::<S>(at) };
    let v = [
        (vx + c.half * ax) / c.div_xy,
        (vy + c.half * ay) / c.div_xy,
        (vt + c.half * at_) / c.div_theta,
    ];
    let mut qv = ([x, y, b.theta], v);
    if FIRST {
        let zero = S::splat(0.0);
        let to = (
            [S::splat(cx), S::splat(cy), S::splat(th1)],
            [zero, zero, S::splat(om1)],
        );
        qv = pin(qv, to, c.first);
    }
    let (q, v) = qv;
    // SAFETY: as above.
    let (lo, hi) = unsafe {
        ax.store(e.ax.add(at));
        ay.store(e.ay.add(at));
        at_.store(e.atheta.add(at));
        m.store(at, q, v)
    };
    let candidates = q[2].le_bits(lo) | q[2].ge_bits(hi);
    if candidates != 0 {
        // SAFETY: as above.
        unsafe { record(m, e, at, candidates, (t, t_new), (q[2], v[2]), stepper) };
    }
    Springs { fx, fy, tu }
}

/// The arrivals among the blocks at `at` whose angle left its window
/// (`candidates`' lanes) between `t` and `t_new`, from the angle and rate
/// each started the step with and its new `theta` and `omega`.
#[inline(always)]
unsafe fn record<S: Simd>(
    m: &Blocks,
    e: &Extra,
    at: usize,
    candidates: u64,
    (t, t_new): (f64, f64),
    (theta, omega): (S, S),
    stepper: &mut dyn Stepper,
) {
    // SAFETY: the caller keeps `at` within the arrays, less a vector.
    let (theta0, vt0) = unsafe { (S::load(e.theta0.add(at)), S::load(e.vtheta0.add(at))) };
    let before = [S::splat(t), theta0, vt0];
    let after = [S::splat(t_new), theta, omega];
    unsafe {
        m.record(at, candidates, before, after, |lane, before, after| {
            stepper.try_record(at + lane, before, after)
        })
    };
}
