//! Symplectic Euler for long ladders (N > [`fused::MAX_BLOCKS`], up to the
//! model's 100 000 blocks): consecutive blocks across the lanes of a
//! vector, neighbours by lane shifts, one pass down the ladder per step
//! (`chain/kernel.rs`). Memory is a few arrays of N, allocated once per
//! run; nothing is allocated while stepping. Every floating-point result is
//! the portable path's, bit for bit (tests/sim.rs checks N up to 1000).
//!
//! [`fused::MAX_BLOCKS`]: super::fused::MAX_BLOCKS

#[cfg(target_arch = "x86_64")]
mod kernel;

use super::fused::MAX_BLOCKS;
use super::observables::ArrivalDetector;
use super::protocol::{Drive, Piece};
use super::rhs::{Rhs, State};
use super::stepping::{Batch, Isa, Stepping};
use crate::model::params::M;

/// The chain stepper of one run: its instruction set and its arrays.
#[derive(Debug, Clone)]
pub struct ChainEuler {
    isa: Isa,
    #[cfg(target_arch = "x86_64")]
    state: kernel::ChainState,
}

impl ChainEuler {
    /// The stepper `stepping` asks for, for `n` blocks, if this CPU allows
    /// it and N is beyond the fused kernel's registers.
    pub fn new(n: usize, stepping: Stepping) -> Option<Self> {
        let isa = stepping.isa()?;
        if n <= MAX_BLOCKS {
            return None;
        }
        #[cfg(target_arch = "x86_64")]
        {
            Some(Self {
                isa,
                state: kernel::ChainState::new(n, kernel::lanes(isa)),
            })
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let _ = isa;
            None
        }
    }

    pub fn isa(&self) -> Isa {
        self.isa
    }

    /// As [`super::fused::FusedEuler::run`]: the steps of `batch` with
    /// symplectic Euler's (decay, kick) `factors`, block 1 constrained,
    /// arrivals recorded after every step. Returns the time reached.
    pub fn run(
        &mut self,
        rhs: &mut Rhs,
        st: &mut State,
        batch: &Batch,
        factors: ([f64; 3], [f64; 3]),
        arrivals: &mut ArrivalDetector,
    ) -> f64 {
        rhs.count_evals(batch.count);
        #[cfg(target_arch = "x86_64")]
        {
            let ladder = rhs.ladder;
            let ([decay_xy, _, decay_theta], [kick_xy, _, kick_theta]) = factors;
            let drive = rhs.drive();
            let params = kernel::ChainParams {
                a_rest: ladder.a,
                b_rest: ladder.params.b,
                minus_g: -(M * ladder.params.gravity),
                h: batch.h,
                decay_xy,
                kick_xy,
                decay_theta,
                kick_theta,
                clamp: drive.map(|(_, c)| c),
            };
            self.load(st, arrivals);
            let mut stepper = Steps {
                batch,
                drive: drive.map(|(d, _)| (d, d.piece(batch.t))),
                arrivals,
            };
            // SAFETY: `new` checked the instruction set; the state was made
            // for its lanes; N > MAX_BLOCKS ≥ 2.
            let t = unsafe {
                kernel::run(
                    self.isa,
                    &mut self.state,
                    &params,
                    batch.t,
                    batch.count,
                    &mut stepper,
                )
            };
            self.store(st);
            arrivals.restart(t, &st.q, &st.v);
            t
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let _ = (st, batch, factors, arrivals);
            unreachable!("ChainEuler::new returns None off x86-64")
        }
    }

    /// The state and the pending blocks' windows into the arrays; padding
    /// blocks back at rest, far apart.
    #[cfg(target_arch = "x86_64")]
    fn load(&mut self, st: &State, arrivals: &ArrivalDetector) {
        let s = &mut self.state;
        let n = s.n;
        for (i, (q, v)) in st.q.chunks_exact(3).zip(st.v.chunks_exact(3)).enumerate() {
            (s.x[i], s.y[i], s.theta[i]) = (q[0], q[1], q[2]);
            (s.vx[i], s.vy[i], s.vtheta[i]) = (v[0], v[1], v[2]);
            [s.window_lo[i], s.window_hi[i]] = if arrivals.arrival[i].is_none() {
                arrivals.window(i)
            } else {
                [f64::NEG_INFINITY, f64::INFINITY]
            };
        }
        for i in n..s.x.len() {
            (s.x[i], s.y[i], s.theta[i]) = (1e3 * i as f64, 0.0, 0.0);
            (s.vx[i], s.vy[i], s.vtheta[i]) = (0.0, 0.0, 0.0);
        }
    }

    #[cfg(target_arch = "x86_64")]
    fn store(&self, st: &mut State) {
        let s = &self.state;
        for (i, (q, v)) in
            st.q.chunks_exact_mut(3)
                .zip(st.v.chunks_exact_mut(3))
                .enumerate()
        {
            (q[0], q[1], q[2]) = (s.x[i], s.y[i], s.theta[i]);
            (v[0], v[1], v[2]) = (s.vx[i], s.vy[i], s.vtheta[i]);
        }
    }
}

/// Velocity Verlet's steps on a long ladder (`FixedStep::verlet`), in the
/// chain's arrays: the same numbers as the portable path, bit for bit.
#[derive(Debug, Clone)]
pub struct ChainVerlet {
    chain: ChainEuler,
}

impl ChainVerlet {
    /// As [`ChainEuler::new`].
    pub fn new(n: usize, stepping: Stepping) -> Option<Self> {
        ChainEuler::new(n, stepping).map(|chain| Self { chain })
    }

    /// Velocity Verlet's (h/2, c, M⁻¹, 1 + c h/2) for X and Y and for θ
    /// if every free block has the same ones (block 1, where driven, is set
    /// by the drive) and the ladder is the paper's: what the kernel needs.
    pub fn factors(rhs: &Rhs, h: f64) -> Option<[f64; 7]> {
        let (rate, inv_mass) = (&rhs.damping_rate, rhs.inv_mass());
        let block = |i: usize| -> Option<([f64; 3], [f64; 3])> {
            let r = rate.get(3 * i..3 * i + 3)?.try_into().ok()?;
            let m = inv_mass.get(3 * i..3 * i + 3)?.try_into().ok()?;
            Some((r, m))
        };
        let free = block(1)?;
        let n = rate.len() / 3;
        let first_ok = rhs.drive().is_some() || block(0) == Some(free);
        let uniform = (2..n).all(|i| block(i) == Some(free)) && first_ok;
        let ([rx, ry, rt], [mx, my, mt]) = free;
        let paper = rhs.ladder.is_paper_model();
        if !(uniform && paper && rx == ry && mx == my) {
            return None;
        }
        let half = 0.5 * h;
        Some([half, rx, rt, mx, mt, 1.0 + half * rx, 1.0 + half * rt])
    }

    /// The steps of `batch` from `st`, whose accelerations at its
    /// positions are `acc` (updated to the end's), with velocity Verlet's
    /// `factors` ([`ChainVerlet::factors`] for `batch.h`), block 1
    /// constrained, arrivals recorded after every step. Returns the time
    /// reached.
    pub fn run(
        &mut self,
        rhs: &mut Rhs,
        st: &mut State,
        acc: &mut [f64],
        batch: &Batch,
        factors: [f64; 7],
        arrivals: &mut ArrivalDetector,
    ) -> f64 {
        rhs.count_evals(batch.count);
        #[cfg(target_arch = "x86_64")]
        {
            let ladder = rhs.ladder;
            let drive = rhs.drive();
            let params = kernel::ChainParams {
                a_rest: ladder.a,
                b_rest: ladder.params.b,
                minus_g: -(M * ladder.params.gravity),
                h: batch.h,
                decay_xy: 0.0,
                kick_xy: 0.0,
                decay_theta: 0.0,
                kick_theta: 0.0,
                clamp: drive.map(|(_, c)| c),
            };
            let [
                half,
                rate_xy,
                rate_theta,
                inv_mass_xy,
                inv_mass_theta,
                div_xy,
                div_theta,
            ] = factors;
            let vp = kernel::VerletParams {
                half,
                rate_xy,
                rate_theta,
                inv_mass_xy,
                inv_mass_theta,
                div_xy,
                div_theta,
            };
            self.chain.load(st, arrivals);
            self.load_acc(acc);
            let mut stepper = Steps {
                batch,
                drive: drive.map(|(d, _)| (d, d.piece(batch.t))),
                arrivals,
            };
            let isa = self.chain.isa;
            // SAFETY: `new` checked the instruction set; the state was made
            // for its lanes; N > MAX_BLOCKS ≥ 2.
            let t = unsafe {
                kernel::run_verlet(
                    isa,
                    &mut self.chain.state,
                    &params,
                    &vp,
                    batch.t,
                    batch.count,
                    &mut stepper,
                )
            };
            self.chain.store(st);
            let s = &self.chain.state;
            for (i, a) in acc.chunks_exact_mut(3).enumerate() {
                (a[0], a[1], a[2]) = (s.ax[i], s.ay[i], s.atheta[i]);
            }
            arrivals.restart(t, &st.q, &st.v);
            t
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let _ = (st, acc, batch, factors, arrivals);
            unreachable!("ChainEuler::new returns None off x86-64")
        }
    }

    /// The accelerations into the arrays; the padding blocks' zero.
    #[cfg(target_arch = "x86_64")]
    fn load_acc(&mut self, acc: &[f64]) {
        let s = &mut self.chain.state;
        for (i, a) in acc.chunks_exact(3).enumerate() {
            (s.ax[i], s.ay[i], s.atheta[i]) = (a[0], a[1], a[2]);
        }
        for i in s.n..s.x.len() {
            (s.ax[i], s.ay[i], s.atheta[i]) = (0.0, 0.0, 0.0);
        }
    }
}

/// The batch's times, block 1's drive and the arrival detector, for the
/// kernel.
#[cfg(target_arch = "x86_64")]
struct Steps<'b, 'd, 'a> {
    batch: &'b Batch,
    /// The drive and the piece last used.
    drive: Option<(&'d Drive, Piece)>,
    arrivals: &'a mut ArrivalDetector,
}

#[cfg(target_arch = "x86_64")]
impl kernel::Stepper for Steps<'_, '_, '_> {
    #[inline(always)]
    fn after(&mut self, k: u64, t: f64) -> (f64, f64, f64) {
        let t_new = self.batch.after(k, t);
        match self.drive.as_mut() {
            Some((drive, piece)) => {
                if !piece.contains(t_new) {
                    *piece = drive.piece(t_new);
                }
                (t_new, piece.theta(t_new), piece.omega())
            }
            None => (t_new, 0.0, 0.0),
        }
    }

    #[inline(always)]
    fn after_h(&mut self, t: f64) -> (f64, f64, f64) {
        let t_h = t + self.batch.h;
        match self.drive.as_mut() {
            Some((drive, piece)) => {
                if !piece.contains(t_h) {
                    *piece = drive.piece(t_h);
                }
                (t_h, piece.theta(t_h), piece.omega())
            }
            None => (t_h, 0.0, 0.0),
        }
    }

    fn try_record(
        &mut self,
        block: usize,
        before: (f64, f64, f64),
        after: (f64, f64, f64),
    ) -> bool {
        self.arrivals.try_record(block, before, after)
    }
}
