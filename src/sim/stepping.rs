//! What the three symplectic-Euler steppers (the fused kernel for
//! N ≤ 32, the chain kernel for longer ladders, and the batch kernel of
//! sweeps) share: a batch of equal steps, the implicit damping factors,
//! the instruction set a kernel is compiled for, and which code takes the
//! steps; and the grid a run stepped between its samples keeps.

use super::rhs::Rhs;

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

/// Symplectic Euler's factors for step `h`, per coordinate: the decay
/// d = 1/(1 + h c) of the implicit damping and the kick h M⁻¹ d (zero for
/// a prescribed coordinate).
#[derive(Debug, Clone, Default)]
pub struct ImplicitDamping {
    pub h: f64,
    pub decay: Vec<f64>,
    pub kick: Vec<f64>,
    /// (decay, kick) for X, Y and θ if every free block has the same ones
    /// (as the ladder's uniform blocks do) and a prescribed block 1 has no
    /// kick: what the fused stepper needs.
    pub uniform: Option<([f64; 3], [f64; 3])>,
}

impl ImplicitDamping {
    /// Recomputes the factors for step `h` in place (allocating only the
    /// first time).
    pub(crate) fn set(&mut self, rhs: &Rhs, h: f64) {
        let dof = rhs.damping_rate.len();
        self.decay.resize(dof, 0.0);
        self.kick.resize(dof, 0.0);
        let rates = rhs.damping_rate.iter().zip(rhs.inv_mass());
        for ((d, kick), (rate, im)) in self.decay.iter_mut().zip(&mut self.kick).zip(rates) {
            *d = 1.0 / (1.0 + h * rate);
            *kick = h * im * *d;
        }
        self.h = h;
        self.uniform = self.find_uniform();
    }

    fn find_uniform(&self) -> Option<([f64; 3], [f64; 3])> {
        let block = |i: usize| {
            let at = |v: &[f64]| -> Option<[f64; 3]> { v.get(3 * i..3 * i + 3)?.try_into().ok() };
            Some((at(&self.decay)?, at(&self.kick)?))
        };
        let free = block(1)?;
        let n = self.decay.len() / 3;
        let first = block(0)?;
        let first_ok = first == free || first.1 == [0.0; 3];
        ((2..n).all(|i| block(i) == Some(free)) && first_ok).then_some(free)
    }
}

/// The subdivision of the current interval [t, t_stop]: equal steps `h`,
/// `left` of them still to take. Computed once per interval.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Plan {
    t_stop: f64,
    h: f64,
    left: u64,
}

impl Plan {
    /// Next step towards `t_stop` from `t`: (h, is the last step).
    pub(crate) fn next(&mut self, t: f64, t_stop: f64, dt: f64) -> (f64, bool) {
        let (h, _, last) = self.take(t, t_stop, dt, 1);
        (h, last)
    }

    /// Steps left in the current interval (0 before the first).
    pub(crate) fn left(&self) -> u64 {
        self.left
    }

    /// Returns `count` steps taken by [`Plan::take`] but not made.
    pub(crate) fn give_back(&mut self, count: u64) {
        self.left += count;
    }

    /// Up to `max` (≥ 1) steps towards `t_stop` from `t`: (h, how many,
    /// whether the last of them ends the interval).
    pub(crate) fn take(&mut self, t: f64, t_stop: f64, dt: f64, max: u64) -> (f64, u64, bool) {
        if self.left == 0 || self.t_stop != t_stop {
            let span = t_stop - t;
            let n = (span / dt - 1e-6).ceil().max(1.0);
            *self = Self {
                t_stop,
                h: span / n,
                left: n as u64,
            };
        }
        let count = self.left.min(max);
        self.left -= count;
        (self.h, count, self.left == 0)
    }
}

/// The grid of a fixed-step run that takes its samples between steps
/// (docs/model.md, "Samples and steps"): the points k·dt from t = 0, cut
/// where a stop (a drive corner, t_end) falls between two of them. A step
/// that would cross a stop ends on it, and the next goes on to the next
/// grid point. A stop within [`Grid::SLIVER`]·dt of a grid point takes
/// that point's place, so no step is a sliver. Where the steps end then
/// depends on the stops before them only, never on t_end until the last
/// grid point before it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Grid {
    dt: f64,
    /// The next grid point is k·dt.
    k: u64,
}

impl Grid {
    /// How close, in steps, a stop may come to a grid point and be taken
    /// as that point.
    pub(crate) const SLIVER: f64 = 1e-9;

    /// The grid of steps `dt` for a run from t = 0.
    pub(crate) fn new(dt: f64) -> Self {
        Self { dt, k: 1 }
    }

    /// Where the step from `t` (a grid point or a stop) ends, given the
    /// next stop `t_stop`: the next grid point, or `t_stop` if that comes
    /// first or within a sliver after it.
    pub(crate) fn target(&mut self, t: f64, t_stop: f64) -> f64 {
        let sliver = Self::SLIVER * self.dt;
        while self.k as f64 * self.dt <= t + sliver {
            self.k += 1;
        }
        let next = self.k as f64 * self.dt;
        if next >= t_stop - sliver {
            t_stop
        } else {
            next
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ends of the steps from 0 to the last of `stops`.
    fn ends(dt: f64, stops: &[f64]) -> Vec<f64> {
        let (mut grid, mut t, mut out) = (Grid::new(dt), 0.0, Vec::new());
        for &stop in stops {
            while t < stop {
                t = grid.target(t, stop);
                out.push(t);
            }
        }
        out
    }

    #[test]
    fn the_grid_is_k_dt_cut_at_a_corner_and_clipped_at_t_end() {
        // A corner at 0.25 cuts the step from 0.2 to 0.3; the next step
        // goes on to 0.3; t_end = 0.47 clips the last.
        let k = |k: u32| k as f64 * 0.1;
        let want = [k(1), k(2), 0.25, k(3), k(4), 0.47];
        assert_eq!(ends(0.1, &[0.25, 0.47]), want);
    }

    #[test]
    fn a_longer_run_takes_the_same_steps_up_to_the_shorter_ones_last_grid_point() {
        let short = ends(0.02, &[4.64, 37.13]);
        let long = ends(0.02, &[4.64, 37.13 * 1.37]);
        let last = short.iter().rposition(|&t| t < 37.13).unwrap();
        assert_eq!(short[..=last], long[..=last]);
        assert_ne!(short.last(), long.get(last + 1));
    }

    #[test]
    fn a_stop_a_sliver_from_a_grid_point_takes_its_place() {
        // Just after 0.2 (a corner) and just before 0.4 (t_end): no step
        // shorter than the sliver, and the grid goes on from the corner.
        let (after, before) = (0.2 + 1e-12, 0.4 - 1e-12);
        let got = ends(0.1, &[after, before]);
        assert_eq!(got, [0.1, after, 0.30000000000000004, before]);
        // A stop on a grid point, computed otherwise, is that point.
        assert_eq!(ends(0.1, &[0.3]), [0.1, 0.2, 0.3]);
    }
}
