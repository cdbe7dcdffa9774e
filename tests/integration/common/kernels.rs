//! The ways of taking symplectic Euler's steps that this CPU offers, for
//! tests that run the physics through every one of them (docs/testing.md).

use super::require::{self, cpu_lacks};
use jacobs_ladder::sim::{Isa, Stepping};

/// The portable path and the fused kernel of every instruction set this
/// CPU has, each with its name. Says (uncaptured, see `require::note`)
/// which ran for `test`; a missing AVX2 fails under CI (`require`), a
/// missing AVX-512 is reported as a skip (no install can add it).
pub fn every(test: &str) -> Vec<(Stepping, &'static str)> {
    let mut out = vec![(Stepping::Portable, "portable")];
    out.extend(fused(test));
    let names: Vec<&str> = out.iter().map(|k| k.1).collect();
    require::note(&format!("{test}: kernels run: {}", names.join(", ")));
    out
}

/// Only the fused kernels this CPU has (for tests that compare them with
/// the portable path), reported as [`every`] does.
pub fn fused(test: &str) -> Vec<(Stepping, &'static str)> {
    let mut out = Vec::new();
    let avx2 = Isa::Avx2.available();
    if require::require(
        test,
        avx2,
        "this CPU lacks AVX2: no fused kernel ran",
        "run on an x86-64 CPU with AVX2",
    ) {
        out.push((Stepping::Fused(Isa::Avx2), "avx2"));
    }
    if Isa::Avx512.available() {
        out.push((Stepping::Fused(Isa::Avx512), "avx512"));
    } else if avx2 {
        cpu_lacks(
            test,
            "avx512",
            "this CPU lacks AVX-512F/VL: the AVX-512 kernel did not run",
        );
    }
    out
}

/// `sim::run` with the steps taken as `stepping` says and the other
/// options at their defaults.
pub fn run_stepped(
    scenario: &jacobs_ladder::sim::Scenario,
    samples: &[f64],
    config: &jacobs_ladder::sim::IntegratorConfig,
    stepping: Stepping,
) -> jacobs_ladder::Result<jacobs_ladder::sim::Trajectory> {
    let options = jacobs_ladder::sim::RunOptions::default().stepping(stepping);
    jacobs_ladder::sim::run(scenario, samples, config, &options)
}
