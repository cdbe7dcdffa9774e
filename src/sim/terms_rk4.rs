//! Classical RK4 fused with the force loop of a ladder in a fluid
//! (docs/experiments.md: buoyancy, added mass, strip drag, the paper's
//! springs as stiff two-way links, block 1 turned by the motor): the
//! water tank's path.
//!
//! The portable path (`sim::rhs::Rhs::acceleration` under
//! `integrators::RungeKutta`) evaluates each stage through the integrator
//! interface: the springs' gradient into memory (block after block), the
//! frames (t, ν) of every block again with the C library's `sincos`, then
//! the drag and Lagrange's equations with added mass block by block, and
//! RK4's sums over whole vectors. Here the state is held as structure of
//! arrays (X, Y, θ and their rates, one array each, padded to whole
//! 256-bit registers), each stage's accelerations are one pass of
//! vectorised loops (sine and cosine, springs, generalised forces, drag in
//! closed form, the 2×2 mass matrix's closed-form inverse and the Munk
//! moment), and no step allocates.
//!
//! Pin friction (the printed linkage) is added to the generalised forces
//! as the portable path adds it (`PinFriction::add_forces`), link by link
//! and block by block in the same order, over whole arrays
//! (`terms_rk4::friction`).
//!
//! Every operation is the portable path's in the same order, with two
//! exceptions: the blocks' frames take the sine and cosine the springs
//! already computed (`model::trig`, fdlibm's kernels) instead of the C
//! library's (the two differ by at most 4 × 10⁻¹⁶, `model::trig`'s test);
//! and, in the runs without pin friction, the drag's and Lagrange's
//! divisions by 3, w, w² and I + I_a are products by 1/3, one reciprocal
//! of w and 1/(I + I_a) (`QUICK`, each within 1.5 ulp of its quotient;
//! docs/performance.md, "The tank's divisions"). So one force evaluation
//! differs from the portable one by a few ulps; with the library's frames
//! ([`TermsRk4::with_library_frames`]), which also take the portable
//! divisions, the trajectory is the portable path's bit for bit, with pin
//! friction too (`tests` below).

mod blocks;
mod friction;
mod regs;

use super::observables::ArrivalDetector;
use super::rhs::{Rhs, State};
use super::stepping::Plan;
use super::stepping::{Isa, Stepping};
use super::tableau::RK4;
use crate::model::params::{M, R};
use crate::sim::simd::{F64x4, Simd};
#[cfg(test)]
use blocks::drag_integrals;
use blocks::{PORTABLE, QUICK, block_acceleration, forces};

/// The state, stage values and stage rates of one run, one array per
/// coordinate: [X, Y, θ] then [Ẋ, Ẏ, θ̇].
type Soa = [Vec<f64>; 3];

/// The fused RK4 stepper of one ladder with the terms of a fluid.
pub struct TermsRk4 {
    c: Coeffs,
    /// (−1)ⁿ per block (padding included).
    parity: Vec<f64>,
    /// The state at the start of the step and the stage's (q, v).
    q0: Soa,
    v0: Soa,
    q: Soa,
    v: Soa,
    /// Stage rates: kq[i] = v, kv[i] = a(q, v) of stage i.
    kq: [Soa; 4],
    kv: [Soa; 4],
    s: Scratch,
    library_frames: bool,
    /// Whether the run takes the step in registers (`regs`: no pin
    /// friction, N ≤ 16).
    registers: bool,
    /// Pin friction's law, if the ladder has friction at its pins.
    friction: Option<friction::Law>,
    /// The instruction set of the step in registers.
    isa: Isa,
}

/// The run's coefficients, each computed as the portable path computes it.
#[derive(Debug, Clone, Copy)]
struct Coeffs {
    n: usize,
    /// Blocks and spring pairs rounded up to whole registers of four.
    np: usize,
    mp: usize,
    g: f64,
    a_rest: f64,
    b_rest: f64,
    gamma: f64,
    /// γ r², the θ coordinate's damping coefficient.
    gamma_theta: f64,
    ma: f64,
    /// I + I_a, and its reciprocal (the quick arithmetic: [`QUICK`]).
    j: f64,
    inv_j: f64,
    /// m_a / (m + m_a): Sherman–Morrison's factor.
    k_am: f64,
    drag: f64,
    driven: bool,
}

/// The force loop's scratch: sines and cosines, the springs' pair forces
/// and torques, the gradient, the frames.
struct Scratch {
    sin: Vec<f64>,
    cos: Vec<f64>,
    fsin: Vec<f64>,
    fcos: Vec<f64>,
    fx: Vec<f64>,
    fy: Vec<f64>,
    tl: Vec<f64>,
    tu: Vec<f64>,
    grad: Soa,
    /// Pin friction's buffers: each sign's links, and the generalised
    /// forces with the friction.
    links: [friction::LinkForces; 2],
    forces: Soa,
}

const fn padded(n: usize) -> usize {
    n.div_ceil(4) * 4
}

impl TermsRk4 {
    /// The stepper for `rhs`'s ladder, if this path takes it: the paper's
    /// springs (stiff two-way links), velocity-dependent terms of a fluid
    /// (added mass, drag), pin friction or none, not the toy as built, N ≥ 2,
    /// and a CPU with AVX2 that `stepping` lets a kernel use.
    pub fn new(rhs: &Rhs, stepping: Stepping) -> Option<Self> {
        let ladder = rhs.ladder;
        let t = rhs.terms();
        let eligible = ladder.built.is_none()
            && t.links.is_paper()
            && ladder.velocity_dependent()
            && ladder.n() >= 2;
        let isa = stepping.isa()?;
        eligible.then(|| Self::build(rhs, isa))
    }

    /// As [`TermsRk4::new`], the frames from the C library's sine and
    /// cosine: the portable path's arithmetic throughout (for tests).
    /// Such a run takes the step over arrays: the step in registers is
    /// compiled for the springs' frames only.
    pub fn with_library_frames(rhs: &Rhs, stepping: Stepping) -> Option<Self> {
        Self::new(rhs, stepping).map(|s| Self {
            library_frames: true,
            registers: false,
            ..s
        })
    }

    fn build(rhs: &Rhs, isa: Isa) -> Self {
        let ladder = rhs.ladder;
        let p = &ladder.params;
        let t = rhs.terms();
        let n = p.n;
        let (np, mp) = (padded(n), padded(n - 1));
        let len = np + 4;
        let z = || vec![0.0; len];
        let soa = || [z(), z(), z()];
        // Padding blocks sit far apart at θ = 0 (as `ForceScratch`).
        let mut q0 = soa();
        for (i, x) in q0[0].iter_mut().enumerate() {
            *x = 10.0 * i as f64;
        }
        let c = Coeffs {
            n,
            np,
            mp,
            g: M * p.gravity,
            a_rest: ladder.a,
            b_rest: p.b,
            gamma: p.gamma,
            gamma_theta: p.gamma * R * R,
            ma: t.added_mass,
            j: p.inertia + t.added_inertia,
            inv_j: 1.0 / (p.inertia + t.added_inertia),
            k_am: t.added_mass / (M + t.added_mass),
            drag: t.drag,
            driven: rhs.drive().is_some(),
        };
        Self {
            c,
            parity: (0..len).map(crate::model::ladder::parity).collect(),
            q: q0.clone(),
            q0,
            v0: soa(),
            v: soa(),
            kq: [soa(), soa(), soa(), soa()],
            kv: [soa(), soa(), soa(), soa()],
            s: Scratch {
                sin: z(),
                cos: z(),
                fsin: z(),
                fcos: z(),
                fx: z(),
                fy: z(),
                tl: z(),
                tu: z(),
                grad: soa(),
                links: [
                    friction::LinkForces::new(len),
                    friction::LinkForces::new(len),
                ],
                forces: soa(),
            },
            library_frames: false,
            // The step in registers is compiled once per register count
            // and instruction set, for runs with drag and the springs'
            // frames (every catalogue run with drag that takes this path):
            // each variant is a large unrolled function, and with the
            // runs without drag and the library's frames (tests only)
            // too, the 32 variants took the library's release build from
            // 55 s to 154 s. The other runs take the step over arrays,
            // the same numbers bit for bit.
            registers: t.friction.is_none() && np <= 4 * regs::MAX_REGS && t.drag != 0.0,
            isa,
            friction: t.friction.map(|friction| friction::Law {
                links: t.links,
                friction,
                rest: [ladder.a, p.b],
            }),
        }
    }

    /// Up to `max_steps` RK4 steps towards `t_stop` (the steps of `plan`
    /// at `dt`, as `FixedStep::advance` takes them), block 1 constrained
    /// at every stage and after every step, `arrivals` fed after each
    /// step. Returns the time reached and the steps taken.
    pub(super) fn advance_many(
        &mut self,
        rhs: &mut Rhs,
        st: &mut State,
        (plan, dt): (&mut Plan, f64),
        (t, t_stop): (f64, f64),
        max_steps: u64,
        arrivals: &mut ArrivalDetector,
    ) -> (f64, u64) {
        if self.registers {
            let job = regs::Job {
                c: self.c,
                rhs,
                st,
                plan: (plan, dt),
                span: (t, t_stop),
                max_steps,
                arrivals,
            };
            // SAFETY: `new` checked that the CPU supports `self.isa`.
            let (t, taken) = unsafe { self.advance_regs(job) };
            rhs.count_evals(4 * taken);
            return (t, taken);
        }
        self.load(st);
        let (mut t, mut taken) = (t, 0);
        while taken < max_steps && t < t_stop {
            let (h, last) = plan.next(t, t_stop, dt);
            let t_new = if last { t_stop } else { t + h };
            // SAFETY: `new` checked that the CPU supports AVX2.
            unsafe { self.step_avx2(rhs, t, h, t_new) };
            t = t_new;
            for i in 0..self.c.n {
                st.q[3 * i + 2] = self.q0[2][i];
                st.v[3 * i + 2] = self.v0[2][i];
            }
            arrivals.observe(t, &st.q, &st.v);
            taken += 1;
        }
        rhs.count_evals(4 * taken);
        self.store(st);
        (t, taken)
    }

    /// [`regs::advance_avx2`] (or its copy with AVX-512's 32 registers) for
    /// this run's registers per quantity, with drag, the springs' frames
    /// and the quick arithmetic (the only runs that take it).
    ///
    /// # Safety
    /// The CPU must have `self.isa`.
    unsafe fn advance_regs(&self, job: regs::Job) -> (f64, u64) {
        macro_rules! dispatch {
            ($entry:ident, $($c:literal)*) => {
                match self.c.np / 4 {
                    $(
                        // SAFETY: the caller guarantees the instruction set.
                        $c => unsafe { regs::$entry::<$c, true, QUICK>(job) },
                    )*
                    _ => unreachable!("N ≤ 16 checked by the caller"),
                }
            };
        }
        match self.isa {
            Isa::Avx2 => dispatch!(advance_avx2, 1 2 3 4),
            Isa::Avx512 => dispatch!(advance_avx512, 1 2 3 4),
        }
    }

    /// The state of `st` into the arrays.
    fn load(&mut self, st: &State) {
        for i in 0..self.c.n {
            for k in 0..3 {
                self.q0[k][i] = st.q[3 * i + k];
                self.v0[k][i] = st.v[3 * i + k];
            }
        }
    }

    /// The arrays' state into `st`.
    fn store(&self, st: &mut State) {
        for i in 0..self.c.n {
            for k in 0..3 {
                st.q[3 * i + k] = self.q0[k][i];
                st.v[3 * i + k] = self.v0[k][i];
            }
        }
    }

    #[cfg_attr(target_arch = "x86_64", target_feature(enable = "avx2"))]
    unsafe fn step_avx2(&mut self, rhs: &Rhs, t: f64, h: f64, t_new: f64) {
        self.step(rhs, t, h, t_new);
    }

    /// One RK4 step from (q0, v0) at `t`: `RungeKutta::step` of the
    /// portable path, its sums in the same order.
    #[inline(always)]
    fn step(&mut self, rhs: &Rhs, t: f64, h: f64, t_new: f64) {
        // Stage 0 at the state itself (constrained at `t` already: the
        // same values again).
        constrain(rhs, t, &mut self.q0, &mut self.v0);
        let np = self.c.np;
        for k in 0..3 {
            copy(&mut self.kq[0][k], &self.v0[k], np);
        }
        self.evaluate(0, true);
        for i in 1..4 {
            self.combine(h, RK4.a[i]);
            self.stage(rhs, i, t + RK4.c[i] * h);
        }
        self.combine(h, RK4.b);
        std::mem::swap(&mut self.q0, &mut self.q);
        std::mem::swap(&mut self.v0, &mut self.v);
        constrain(rhs, t_new, &mut self.q0, &mut self.v0);
    }

    /// (q, v) = (q0, v0) + h Σ w_j k_j, the sum from 0.0 in order of j.
    #[inline(always)]
    fn combine(&mut self, h: f64, w: &[f64]) {
        let np = self.c.np;
        for k in 0..3 {
            for (y, y0, ks) in [
                (&mut self.q[k], &self.q0[k], &self.kq),
                (&mut self.v[k], &self.v0[k], &self.kv),
            ] {
                let (y, y0) = (&mut y[..np], &y0[..np]);
                let k0 = &ks[0][k][..np];
                match *w {
                    [w0] => {
                        for l in 0..np {
                            y[l] = y0[l] + h * (0.0 + w0 * k0[l]);
                        }
                    }
                    [w0, w1] => {
                        let k1 = &ks[1][k][..np];
                        for l in 0..np {
                            y[l] = y0[l] + h * ((0.0 + w0 * k0[l]) + w1 * k1[l]);
                        }
                    }
                    [w0, w1, w2] => {
                        let (k1, k2) = (&ks[1][k][..np], &ks[2][k][..np]);
                        for l in 0..np {
                            let d = ((0.0 + w0 * k0[l]) + w1 * k1[l]) + w2 * k2[l];
                            y[l] = y0[l] + h * d;
                        }
                    }
                    _ => {
                        let (k1, k2, k3) = (&ks[1][k][..np], &ks[2][k][..np], &ks[3][k][..np]);
                        for l in 0..np {
                            let d = (((0.0 + w[0] * k0[l]) + w[1] * k1[l]) + w[2] * k2[l])
                                + w[3] * k3[l];
                            y[l] = y0[l] + h * d;
                        }
                    }
                }
            }
        }
    }

    /// Stage `i` at (q, v), block 1 constrained at `ts`.
    #[inline(always)]
    fn stage(&mut self, rhs: &Rhs, i: usize, ts: f64) {
        constrain(rhs, ts, &mut self.q, &mut self.v);
        // kq[i] = v: the stage's v moves into kq[i] (the next combine
        // writes every lane of v again).
        std::mem::swap(&mut self.kq[i], &mut self.v);
        self.evaluate(i, false);
    }

    /// kv[i] = a(q, v) of stage `i`: (q0, kq[0]) for stage 0 (`start`),
    /// (q, kq[i]) for the others.
    #[inline(always)]
    fn evaluate(&mut self, i: usize, start: bool) {
        let q = if start { &self.q0 } else { &self.q };
        let [ax, ay, aw] = &mut self.kv[i];
        acceleration(
            (&self.c, self.friction.as_ref()),
            &self.parity,
            (q, &self.kq[i]),
            [ax, ay, aw],
            &mut self.s,
            self.library_frames,
        );
    }
}

/// `dst[..np] = src[..np]` by a loop the compiler keeps in registers.
#[inline(always)]
fn copy(dst: &mut [f64], src: &[f64], np: usize) {
    for (d, s) in dst[..np].chunks_exact_mut(4).zip(src[..np].chunks_exact(4)) {
        d.copy_from_slice(s);
    }
}

/// Block 1's prescribed position and velocity at `ts`, if driven.
#[inline(always)]
fn constrain(rhs: &Rhs, ts: f64, q: &mut Soa, v: &mut Soa) {
    if let Some((qp, vp)) = rhs.prescribed(ts) {
        for k in 0..3 {
            q[k][0] = qp[k];
            v[k][0] = vp[k];
        }
    }
}

/// The accelerations at (q, v): `Rhs::acceleration_with_terms` over
/// whole arrays (`model::media`: Lagrange's equations with added mass,
/// M⁻¹ in closed form, the Munk moment, strip drag in closed form; pin
/// friction as `PinFriction::add_forces` adds it).
#[inline(always)]
fn acceleration(
    (c, law): (&Coeffs, Option<&friction::Law>),
    parity: &[f64],
    (q, v): (&Soa, &Soa),
    out: [&mut Vec<f64>; 3],
    s: &mut Scratch,
    library_frames: bool,
) {
    springs(c, parity, q, s);
    let np = c.np;
    if library_frames {
        for i in 0..np {
            (s.fsin[i], s.fcos[i]) = q[2][i].sin_cos();
        }
    }
    // Whole arrays (the links' pass reads block j + 1 beside block j).
    let (fsin, fcos) = if library_frames {
        (&s.fsin[..], &s.fcos[..])
    } else {
        (&s.sin[..], &s.cos[..])
    };
    let [ax, ay, aw] = out;
    let frames = (&fsin[..np], &fcos[..np], &parity[..np]);
    let a = [&mut ax[..np], &mut ay[..np], &mut aw[..np]];
    let vs = [&v[0][..np], &v[1][..np], &v[2][..np]];
    if let Some(law) = law {
        let all = (fsin, fcos, parity);
        friction::forces((c, law), all, (q, v), &s.grad, &mut s.links, &mut s.forces);
        let [fx, fy, ft] = &s.forces;
        let forces = [&fx[..np], &fy[..np], &ft[..np]];
        with_drag_or_not::<true, PORTABLE>(c, forces, frames, vs, a);
    } else {
        let [gx, gy, gt] = &s.grad;
        let g = [&gx[..np], &gy[..np], &gt[..np]];
        if library_frames {
            with_drag_or_not::<false, PORTABLE>(c, g, frames, vs, a);
        } else {
            with_drag_or_not::<false, QUICK>(c, g, frames, vs, a);
        }
    }
    let first = usize::from(c.driven);
    for a in [ax, ay, aw] {
        a[..first].fill(0.0);
        a[c.n..np].fill(0.0);
    }
}

/// [`block_accelerations`] with drag where the run has it: the choice
/// made once per evaluation, each variant compiled without the branch.
#[inline(always)]
fn with_drag_or_not<const FORCES: bool, const EXACT: bool>(
    c: &Coeffs,
    g: [&[f64]; 3],
    frames: (&[f64], &[f64], &[f64]),
    v: [&[f64]; 3],
    a: [&mut [f64]; 3],
) {
    // SAFETY: a `TermsRk4` is made only where the CPU has AVX2
    // (`TermsRk4::new`), and only it calls this.
    if c.drag != 0.0 {
        unsafe { block_accelerations::<true, FORCES, EXACT>(c, g, frames, v, a) };
    } else {
        unsafe { block_accelerations::<false, FORCES, EXACT>(c, g, frames, v, a) };
    }
}

/// Each block's generalised forces, drag (`DRAG`) and accelerations
/// (`Rhs::acceleration_with_terms`, `media::block_acceleration_framed`),
/// from the gradient `g` (or, `FORCES`, the generalised forces before
/// drag), the frames (sine, cosine, parity) and `v`, four blocks at a
/// time (a lane's arithmetic is the scalar IEEE operation, in the
/// portable path's order); in the portable path's arithmetic (`EXACT`)
/// or the quick one ([`QUICK`]). Its own function compiled for AVX2 (the
/// compiler left the loop scalar, with a branch for the drag's closed
/// forms).
///
/// # Safety
/// The CPU must have AVX2 (a `TermsRk4` is made only where it has).
#[cfg_attr(target_arch = "x86_64", target_feature(enable = "avx2"))]
#[inline(never)]
unsafe fn block_accelerations<const DRAG: bool, const FORCES: bool, const EXACT: bool>(
    c: &Coeffs,
    g: [&[f64]; 3],
    (fsin, fcos, parity): (&[f64], &[f64], &[f64]),
    v: [&[f64]; 3],
    a: [&mut [f64]; 3],
) {
    // Four lanes from `x[i..i + 4]` (i + 4 ≤ np ≤ x's length).
    let ld = |x: &[f64], i: usize| {
        let x = &x[i..i + 4];
        // SAFETY: `x` holds four values.
        unsafe { F64x4::load(x.as_ptr()) }
    };
    let [ax, ay, aw] = a;
    for i in (0..c.np).step_by(4) {
        let (vx, vy, w) = (ld(v[0], i), ld(v[1], i), ld(v[2], i));
        let f = if FORCES {
            [ld(g[0], i), ld(g[1], i), ld(g[2], i)]
        } else {
            forces(c, [ld(g[0], i), ld(g[1], i), ld(g[2], i)], [vx, vy, w])
        };
        let frames = (ld(fsin, i), ld(fcos, i), ld(parity, i));
        let values = block_acceleration::<F64x4, DRAG, EXACT>(c, f, frames, [vx, vy, w]);
        for (out, value) in [&mut *ax, &mut *ay, &mut *aw].into_iter().zip(values) {
            let out = &mut out[i..i + 4];
            // SAFETY: `out` has room for four values.
            unsafe { value.store(out.as_mut_ptr()) };
        }
    }
}

/// The paper's springs' gradient into `s.grad`: `Ladder::gradient_with`'s
/// loop (`model::ladder`), the same operations in the same order, on
/// arrays instead of the interleaved layout.
#[inline(always)]
fn springs(c: &Coeffs, parity: &[f64], q: &Soa, s: &mut Scratch) {
    let (np, mp, n) = (c.np, c.mp, c.n);
    let m = n - 1;
    crate::model::trig::sin_cos_slice(&q[2][..np], &mut s.sin[..np], &mut s.cos[..np]);
    let (x, y, sn, cs, p) = (
        &q[0][..=mp],
        &q[1][..=mp],
        &s.sin[..=mp],
        &s.cos[..=mp],
        &parity[..=mp],
    );
    let (fx, fy) = (&mut s.fx[..mp], &mut s.fy[..mp]);
    let (tl, tu) = (&mut s.tl[..mp], &mut s.tu[..mp]);
    for j in 0..mp {
        let (tx0, ty0, tx1, ty1) = (sn[j], p[j] * cs[j], sn[j + 1], p[j + 1] * cs[j + 1]);
        let (ex, ey) = (x[j + 1] - x[j], y[j + 1] - y[j]);
        let (ux, uy) = (R * (tx1 - tx0), R * (ty1 - ty0));
        let (ax, ay, bx, by) = (ex - ux, ey - uy, ex + ux, ey + uy);
        let ka = 1.0 - c.a_rest / (ax * ax + ay * ay).sqrt();
        let kb = 1.0 - c.b_rest / (bx * bx + by * by).sqrt();
        let (fax, fay, fbx, fby) = (ka * ax, ka * ay, kb * bx, kb * by);
        fx[j] = fax + fbx;
        fy[j] = fay + fby;
        let (dx, dy) = (R * (fbx - fax), R * (fby - fay));
        tu[j] = dx * cs[j + 1] - dy * p[j + 1] * sn[j + 1];
        tl[j] = -(dx * cs[j] - dy * p[j] * sn[j]);
    }
    let g = c.g;
    let [gx, gy, gt] = &mut s.grad;
    // Block i + 1 feels pair i from above and pair i + 1 from below.
    for i in 0..m - 1 {
        gx[i + 1] = -g + fx[i] - fx[i + 1];
        gy[i + 1] = fy[i] - fy[i + 1];
        gt[i + 1] = tu[i] + tl[i + 1];
    }
    (gx[0], gy[0], gt[0]) = (-g - fx[0], -fy[0], tl[0]);
    (gx[m], gy[m], gt[m]) = (-g + fx[m - 1], fy[m - 1], tu[m - 1]);
}

#[cfg(test)]
mod tests;
