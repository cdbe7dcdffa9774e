//! The paper's scheme fused with the force loop: symplectic Euler with
//! implicit damping ([`super::integrators::FixedStep`]) on the forces of
//! [`crate::model::Ladder::gradient_with`], with the whole state held in
//! 256-bit registers, four blocks to a register.
//!
//! The portable path evaluates the forces into memory, then updates the
//! velocities and positions from memory, one step at a time through the
//! integrator interface. Here the neighbours come from lane shifts inside
//! registers, the state is read and written once per batch of steps, and
//! block 1's drive and the arrival-time check are done in place. Each step
//! is one chain of dependent operations (θ → sin, cos → spring lengths →
//! forces → velocities → θ), so what counts is the length of that chain:
//! Estrin's form for the sine and cosine kernels, the factor r = s/2
//! folded into them, and the damping folded into one kick factor.
//!
//! Every floating-point result is the portable path's, bit for bit (no
//! fused multiply-adds; the folded factors are powers of two or ±1, which
//! scale exactly), so the two give the same trajectory (tests/sim.rs
//! checks it). The kernel is compiled twice: for AVX2 and, where the CPU
//! has it, for AVX-512VL, whose 32 vector registers spare the spills of
//! the 16 of AVX2 (same instructions on 256-bit vectors, same results).

#[cfg(doc)]
use super::integrators::ImplicitDamping;
use super::observables::ArrivalDetector;
use super::rhs::{Rhs, State};

#[cfg(target_arch = "x86_64")]
mod kernel;

/// Largest N the fused stepper takes (eight registers of four blocks);
/// longer ladders use the chain stepper (`sim::chain`).
pub const MAX_BLOCKS: usize = 32;

pub use super::stepping::{Batch, Isa, Stepping};

/// The fused stepper for one ladder length; exists only where the CPU has
/// AVX2 and N ≤ [`MAX_BLOCKS`].
#[derive(Debug, Clone, Copy)]
pub struct FusedEuler {
    chunks: usize,
    isa: Isa,
}

impl FusedEuler {
    /// The stepper `stepping` asks for, for `n` blocks, if this CPU and this
    /// N allow it.
    pub fn new(n: usize, stepping: Stepping) -> Option<Self> {
        let isa = stepping.isa()?;
        (2..=MAX_BLOCKS).contains(&n).then(|| Self {
            chunks: n.div_ceil(4),
            isa,
        })
    }

    pub fn isa(&self) -> Isa {
        self.isa
    }

    /// Takes the steps of `batch` with symplectic Euler's (decay, kick)
    /// `factors` for X, Y and θ (for step `batch.h`, the same for every
    /// free block: [`ImplicitDamping::uniform`]), constraining block 1 and
    /// recording arrivals after every step. Returns the time reached.
    pub fn run(
        &self,
        rhs: &mut Rhs,
        st: &mut State,
        batch: &Batch,
        factors: ([f64; 3], [f64; 3]),
        arrivals: &mut ArrivalDetector,
    ) -> f64 {
        rhs.count_evals(batch.count);
        #[cfg(target_arch = "x86_64")]
        {
            let job = kernel::Job {
                rhs,
                batch,
                factors,
            };
            // SAFETY: `new` checked that the CPU supports the instruction set.
            unsafe { kernel::run(self.isa, self.chunks, &job, st, arrivals) }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let _ = (rhs, st, batch, factors, arrivals);
            unreachable!("FusedEuler::new returns None off x86-64")
        }
    }
}
