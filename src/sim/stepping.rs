//! What the three symplectic-Euler steppers (the fused kernel for
//! N ≤ 32, the chain kernel for longer ladders, and the batch kernel of
//! sweeps) share: a batch of equal steps, the instruction set a kernel is
//! compiled for, and which code takes the steps.

/// A batch of equal steps: `count` steps of size `h` from `t`; if `lands`,
/// the last one ends exactly on `t_stop` (as in the portable path).
#[derive(Debug, Clone, Copy)]
pub struct Batch {
    pub t: f64,
    pub h: f64,
    pub count: u64,
    pub t_stop: f64,
    pub lands: bool,
}

impl Batch {
    /// Time at the end of step `k` (0-based), given the time before it.
    #[inline(always)]
    pub(crate) fn after(&self, k: u64, t: f64) -> f64 {
        if self.lands && k + 1 == self.count {
            self.t_stop
        } else {
            t + self.h
        }
    }
}

/// The instruction sets the kernel is compiled for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Isa {
    Avx2,
    Avx512,
}

impl Isa {
    /// Whether this CPU can run the kernel built for `self`.
    #[cfg(target_arch = "x86_64")]
    pub fn available(self) -> bool {
        use std::arch::is_x86_feature_detected as has;
        match self {
            Self::Avx2 => has!("avx2"),
            Self::Avx512 => has!("avx2") && has!("avx512f") && has!("avx512vl"),
        }
    }

    /// Whether this CPU can run the kernel built for `self`.
    #[cfg(not(target_arch = "x86_64"))]
    pub fn available(self) -> bool {
        false
    }

    /// The best this CPU supports, if any.
    pub fn detect() -> Option<Self> {
        [Self::Avx512, Self::Avx2]
            .into_iter()
            .find(|isa| isa.available())
    }

    pub fn name(self) -> &'static str {
        match self {
            Self::Avx2 => "avx2",
            Self::Avx512 => "avx512",
        }
    }
}

/// Which code takes symplectic Euler's steps. Every choice gives the same
/// trajectory, bit for bit; they differ in speed only.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Stepping {
    /// The fused kernel for the best instruction set this CPU has, where N
    /// allows it; the portable path otherwise.
    #[default]
    Fastest,
    /// The fused kernel for this instruction set, if the CPU has it and N
    /// allows it; the portable path otherwise.
    Fused(Isa),
    /// The integrator interface over `Ladder::gradient_with`.
    Portable,
}

impl Stepping {
    /// The instruction set a kernel would use: the best this CPU has for
    /// `Fastest`, the one asked for if this CPU has it, else `None`.
    pub fn isa(self) -> Option<Isa> {
        match self {
            Stepping::Fastest => Isa::detect(),
            Stepping::Fused(isa) => isa.available().then_some(isa),
            Stepping::Portable => None,
        }
    }
}
