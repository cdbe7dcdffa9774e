//! Seeded proptest runners for the fuzz tests: reproducible by default,
//! `LADDER_FUZZ_CASES=K` for a longer (or shorter) run.

use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

/// `LADDER_FUZZ_CASES` if set to a number, else `default`.
pub fn cases(default: u32) -> u32 {
    std::env::var("LADDER_FUZZ_CASES")
        .ok()
        .and_then(|c| c.parse().ok())
        .unwrap_or(default)
}

/// A runner of `cases` cases from the ChaCha seed `[seed; 32]`, without
/// failure persistence (nothing written into the source tree).
pub fn runner(cases: u32, seed: u8) -> TestRunner {
    let config = Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    };
    TestRunner::new_with_rng(
        config,
        TestRng::from_seed(RngAlgorithm::ChaCha, &[seed; 32]),
    )
}
