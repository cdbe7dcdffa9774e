//! What the theory's computations and drawings cost, estimated before any
//! work starts (docs/limits.md, "Theory figures").
//!
//! The unit is an *operation*, calibrated so that one takes about a
//! nanosecond on the project's 2-core machine (release build, wall time
//! of `ladder render` on the figure alone). Each estimate is a formula in
//! N fitted to measurements at N = 1000 and 4000 (drawings) or 400 and 800
//! (the dense linear algebra), rounded up; the figure's own fixed cost (a
//! few tenths of a second: fonts, the page, the encoders) is left out.
//!
//! | computation | measured | estimate |
//! |---|---|---|
//! | a figure of full-ladder configurations (Fig. 2d, three panels) | 0.66 s at N = 1000, 3.5 s at 4000, about 15 min at 100,000 | 100 N² + 6 × 10⁵ N |
//! | zero-mode shapes (Fig. S4), per mode: the dense compatibility matrix of the free chain, 2(N − 1) × 3N, filled and applied | 0.27 s at 1000, 2.6 s at 4000 (770 MB) | 140 N² + 1.5 × 10⁵ N, and 48 N² bytes |
//! | the surface zero mode (edge-mode figure), per α and sign: an SVD of that matrix | 1.0 s at N = 400, 11 s at 800 | 22 N³ |
//!
//! Figures without N in their cost (the unit schematic, U(θ), ΔU(α), the
//! Bloch dispersion and winding of the infinite chain) cost [`FIXED`].

/// Estimated operations of a figure whose cost does not grow with N.
pub const FIXED: f64 = 1e8;

/// Most bytes of dense matrices one theory figure may hold (a range, not
/// a cap: past it the machine's memory, not the user's patience, is what
/// runs out). Fig. S4 reaches it at N ≈ 6,400.
pub const MAX_DENSE_BYTES: f64 = 2e9;

/// What one figure's computation costs.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Work {
    /// Estimated operations (about a nanosecond each).
    pub operations: f64,
    /// Largest memory held at once by dense matrices, bytes.
    pub dense_bytes: f64,
}

impl Work {
    /// A figure whose cost does not depend on N.
    pub fn fixed() -> Self {
        Self {
            operations: FIXED,
            dense_bytes: 0.0,
        }
    }

    /// Drawing `panels` snapshots of a ladder of `n` blocks, each with its
    /// orientation arrows or ghost (Fig. 2d, S3): quadratic in N (the
    /// three panels of Fig. 2d measured, per panel a third of it).
    pub fn configurations(n: usize, panels: usize) -> Self {
        let n = n as f64;
        Self {
            operations: FIXED + panels as f64 / 3.0 * (100.0 * n * n + 6e5 * n),
            dense_bytes: 0.0,
        }
    }

    /// `modes` zero-mode shapes of `n` blocks (Fig. S4): for each, the
    /// dense compatibility matrix (2(N − 1) rows, 3N columns) filled and
    /// applied to two vectors, and two snapshots drawn.
    pub fn zero_modes(n: usize, modes: usize) -> Self {
        let nf = n as f64;
        Self {
            operations: FIXED + modes as f64 * (140.0 * nf * nf + 1.5e5 * nf),
            dense_bytes: compatibility_bytes(n),
        }
    }

    /// The surface zero mode at `alphas` angles (each sign counted), `n` blocks: one SVD of
    /// the dense compatibility matrix each (O(N³), with U and V held).
    pub fn surface_modes(n: usize, alphas: usize) -> Self {
        let nf = n as f64;
        Self {
            operations: FIXED + alphas as f64 * 22.0 * nf * nf * nf,
            dense_bytes: compatibility_bytes(n) + 2.0 * 8.0 * (3.0 * nf) * (3.0 * nf),
        }
    }
}

/// Bytes of the dense 2(N − 1) × 3N compatibility matrix.
fn compatibility_bytes(n: usize) -> f64 {
    8.0 * 2.0 * (n as f64 - 1.0) * 3.0 * n as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The estimates reproduce the measurements of the module's table
    /// within a factor of two (seconds = operations × 1e-9).
    #[test]
    fn the_estimates_match_the_measurements() {
        let within = |est: f64, measured_s: f64| {
            let s = est * 1e-9;
            assert!(
                s > 0.5 * measured_s && s < 2.0 * measured_s,
                "{s} s against {measured_s} s"
            );
        };
        within(Work::configurations(1000, 3).operations, 0.66);
        within(Work::configurations(4000, 3).operations, 3.5);
        within(Work::configurations(100_000, 3).operations, 900.0);
        within(Work::zero_modes(4000, 2).operations, 5.1);
        within(Work::surface_modes(800, 4).operations, 43.0);
        // 770 MB measured at N = 4000 (peak resident memory, all of it).
        let bytes = Work::zero_modes(4000, 2).dense_bytes;
        assert!(bytes > 0.5 * 770e6 && bytes < 770e6, "{bytes}");
        // Quadratic: doubling N far out quadruples the cost.
        let (a, b) = (
            Work::configurations(50_000, 3).operations,
            Work::configurations(100_000, 3).operations,
        );
        assert!(b / a > 3.5 && b / a < 4.0, "{}", b / a);
    }
}
