//! What one command may ask for: the ranges of the model's inputs and the
//! caps on the cost of a run, in one place (docs/limits.md explains them).
//!
//! Two kinds of bound live here. *Ranges* (the number of blocks, the
//! lengths) are where the computation can do what it is asked at all: past
//! them the linear algebra cannot converge or memory cannot hold the
//! model; they are fixed. *Caps* ([`Limits`]) bound the cost of a run,
//! computed before it starts (steps × N, samples × N, frames × pixels,
//! runs); they sit far above real work and may be raised on request. A
//! run past a cap is refused with [`LimitExceeded`] (exit 2), which says
//! what was asked and the cap; the command line words how to raise it (this
//! module knows no flag names).

use serde::{Deserialize, Serialize};
use std::fmt;

/// Largest number of blocks N of a simulation. Memory is about 0.4 kB per
/// block (state, forces, scratch), and `--integrator auto` finds ω_max from
/// the band Hessian in O(N), so N = 100,000 takes ~44 MB and about 4 s per
/// thousand steps.
pub const MAX_BLOCKS: usize = 100_000;

/// Largest N of the linear theory (`ladder theory`): its dense SVDs and
/// eigen-decompositions cost O(N³) time and O(N²) memory (N = 200 takes
/// about 0.5 s, N = 400 about 4 s and 40 MB).
pub const MAX_THEORY_BLOCKS: usize = 400;

/// Shortest rest length b of the B springs, in units of the block length s.
/// Below it the compatibility matrix mixes entries of order 1 and of order
/// b, and its numerical rank (relative tolerance 1e-9) and the winding
/// number stop being reliable: at b = 1e-4 the winding number is already
/// undefined, and at b = 1e-17 the ground state's B springs have zero
/// length (NaN entries).
pub const MIN_LENGTH: f64 = 1e-3;
/// Longest rest length b, in units of s (the mirror of [`MIN_LENGTH`]: at
/// b = 1e4 the winding number is undefined; at b = 1e308, b² overflows).
pub const MAX_LENGTH: f64 = 1e3;

/// Smallest moment of inertia I of a block, in units of m s² (paper 1/4).
/// ω_max grows as 1/sqrt(I); below this the stable step of an explicit
/// integrator falls under 1e-3 τ.
pub const MIN_INERTIA: f64 = 1e-6;
/// Largest moment of inertia I, in units of m s².
pub const MAX_INERTIA: f64 = 1e6;

/// Fewest steps per unit of the end time's rounding: a step `dt` must
/// satisfy `t_end / dt ≤ MAX_STEPS_PER_ULP_SPAN`, i.e. it must exceed the
/// spacing of floating-point numbers near `t_end` a thousandfold, so that
/// every step advances time (`t + dt > t`) by a well-defined amount. This
/// is a property of arithmetic, not a cost cap: it cannot be raised.
pub const MAX_STEPS_PER_ULP_SPAN: f64 = 1.0 / (1000.0 * f64::EPSILON);

/// Caps on the cost of one command. Every default sits far above the real
/// work of the catalogue and of the paper; each may be raised on request.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Limits {
    /// Steps × N of one simulation, in block-steps of the paper's model
    /// stepped by velocity Verlet: a run on another force path counts its
    /// steps × N times that path's weight (`sim::cost`, docs/limits.md).
    /// Default 1e10: about a minute and a half of the unit (8.6 ns per
    /// block-step, `sim::cost::REFERENCE_NS`).
    /// The paper's run is 4 × 10^6; N = 1000 for 2 × 10^5 steps is
    /// 2 × 10^8; N = 100,000 for 5000 steps is 5 × 10^8.
    pub block_steps: f64,
    /// Samples × N of one trajectory (block-samples): each keeps 6 numbers
    /// per block (48 bytes) in memory, about 12 bytes in a CSV. Default
    /// 5e7: 2.4 GB in memory. A 1000-frame movie of N = 10,000 is 10^7.
    pub block_samples: f64,
    /// Frames × width × height of one movie. Default 5e9: a 1920 × 1080
    /// movie of 1000 frames is 2.1 × 10^9 (about 30 s of drawing at
    /// ~14 ns per pixel).
    pub movie_pixels: f64,
    /// Runs of one sweep. Default 10^5: a 10,000-run sweep passes.
    pub sweep_runs: f64,
    /// Bytes of one data file (`<output>.json`), estimated before any
    /// work ([`Limits::check_data_bytes`]). Default 2e9: a 200-frame movie
    /// of N = 50,000 (about 1.5 GB).
    pub data_bytes: f64,
    /// Estimated operations of one theory figure (`theory::cost`, about a
    /// nanosecond each on the project's machine). Default 6e10: about a
    /// minute; Fig. 2d at N = 20,000 is 5.2 × 10^10, every figure of the
    /// catalogue under 10^9.
    pub theory_work: f64,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            block_steps: 1e10,
            block_samples: 5e7,
            movie_pixels: 5e9,
            sweep_runs: 1e5,
            data_bytes: 2e9,
            theory_work: 6e10,
        }
    }
}

/// What a cap bounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Resource {
    /// Steps × N of a simulation.
    BlockSteps,
    /// Samples × N of a trajectory.
    BlockSamples,
    /// Frames × pixels of a movie.
    MoviePixels,
    /// Runs of a sweep.
    SweepRuns,
    /// Bytes of a data file.
    DataBytes,
    /// Estimated operations of a theory figure.
    TheoryWork,
}

impl Resource {
    pub const ALL: [Self; 6] = [
        Self::BlockSteps,
        Self::BlockSamples,
        Self::MoviePixels,
        Self::SweepRuns,
        Self::DataBytes,
        Self::TheoryWork,
    ];

    /// The unit of the count, for messages ("block-steps").
    pub fn unit(self) -> &'static str {
        match self {
            Self::BlockSteps => "block-steps",
            Self::BlockSamples => "block-samples",
            Self::MoviePixels => "pixels",
            Self::SweepRuns => "runs",
            Self::DataBytes => "bytes",
            Self::TheoryWork => "operations",
        }
    }

    /// What the count is ("steps × N").
    pub fn describe(self) -> &'static str {
        match self {
            Self::BlockSteps => "steps × N",
            Self::BlockSamples => "samples × N",
            Self::MoviePixels => "frames × width × height",
            Self::SweepRuns => "runs of a sweep",
            Self::DataBytes => "bytes of a data file",
            Self::TheoryWork => "estimated operations of a theory figure",
        }
    }
}

/// A request past a cap: what, how much, and the cap. Exit 2 (the user can
/// ask for less, or raise the cap).
#[derive(Debug, Clone, PartialEq)]
pub struct LimitExceeded {
    pub resource: Resource,
    /// What the request would cost, in the resource's unit (may be
    /// infinite).
    pub value: f64,
    pub cap: f64,
    /// How the value came about, e.g. "4e13 steps × N = 10".
    pub detail: String,
}

impl fmt::Display for LimitExceeded {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // As many digits as it takes for the two numbers to differ.
        let (value, cap) = (1..=17)
            .map(|digits| (count_to(self.value, digits), count_to(self.cap, digits)))
            .find(|(v, c)| v != c)
            .unwrap_or_else(|| (count(self.value), count(self.cap)));
        write!(
            f,
            "this needs {value} {} ({}), past the cap of {cap}",
            self.resource.unit(),
            self.detail,
        )
    }
}

impl std::error::Error for LimitExceeded {}

impl Limits {
    /// No caps at all (for tests and for callers with their own bounds).
    pub fn none() -> Self {
        Self {
            block_steps: f64::INFINITY,
            block_samples: f64::INFINITY,
            movie_pixels: f64::INFINITY,
            sweep_runs: f64::INFINITY,
            data_bytes: f64::INFINITY,
            theory_work: f64::INFINITY,
        }
    }

    /// The cap on `resource`.
    pub fn cap(&self, resource: Resource) -> f64 {
        match resource {
            Resource::BlockSteps => self.block_steps,
            Resource::BlockSamples => self.block_samples,
            Resource::MoviePixels => self.movie_pixels,
            Resource::SweepRuns => self.sweep_runs,
            Resource::DataBytes => self.data_bytes,
            Resource::TheoryWork => self.theory_work,
        }
    }

    /// Sets the cap on `resource`.
    pub fn set(&mut self, resource: Resource, cap: f64) {
        match resource {
            Resource::BlockSteps => self.block_steps = cap,
            Resource::BlockSamples => self.block_samples = cap,
            Resource::MoviePixels => self.movie_pixels = cap,
            Resource::SweepRuns => self.sweep_runs = cap,
            Resource::DataBytes => self.data_bytes = cap,
            Resource::TheoryWork => self.theory_work = cap,
        }
    }

    /// `Ok` if `value` (NaN counts as infinite) is within the cap on
    /// `resource`; otherwise [`LimitExceeded`] with `detail`.
    pub fn check(
        &self,
        resource: Resource,
        value: f64,
        detail: impl FnOnce() -> String,
    ) -> Result<(), LimitExceeded> {
        let cap = self.cap(resource);
        if value <= cap {
            Ok(())
        } else {
            Err(LimitExceeded {
                resource,
                value: if value.is_nan() { f64::INFINITY } else { value },
                cap,
                detail: detail(),
            })
        }
    }

    /// Block-samples of `samples` samples of `n` blocks.
    pub fn check_samples(&self, samples: f64, n: usize) -> Result<(), LimitExceeded> {
        self.check(Resource::BlockSamples, samples * n as f64, || {
            format!("{} samples, times N = {n}", count(samples))
        })
    }

    /// Pixels of a movie of `frames` frames of `width` × `height`.
    pub fn check_movie(&self, frames: usize, width: u32, height: u32) -> Result<(), LimitExceeded> {
        let pixels = frames as f64 * width as f64 * height as f64;
        self.check(Resource::MoviePixels, pixels, || {
            format!("{frames} frames of {width}×{height}")
        })
    }

    /// A sweep of `runs` runs.
    pub fn check_sweep(&self, runs: f64) -> Result<(), LimitExceeded> {
        self.check(Resource::SweepRuns, runs, || {
            format!("{} runs", count(runs))
        })
    }
}

impl Limits {
    /// A data file estimated at `bytes` (`detail` says of what).
    pub fn check_data_bytes(
        &self,
        bytes: f64,
        detail: impl FnOnce() -> String,
    ) -> Result<(), LimitExceeded> {
        self.check(Resource::DataBytes, bytes, detail)
    }
}

/// A count for messages: integers up to 10^6 in full, larger ones as
/// 4.0e13, infinity as "infinitely many".
pub fn count(x: f64) -> String {
    count_to(x, 1)
}

/// [`count`] with `digits` decimals (of the mantissa, past 10^6).
fn count_to(x: f64, digits: usize) -> String {
    if !x.is_finite() {
        "infinitely many".into()
    } else if x.abs() < 1e6 && x.fract() == 0.0 {
        format!("{x}")
    } else if x.abs() < 1e6 {
        format!("{x:.digits$}")
    } else {
        format!("{x:.digits$e}")
    }
}

/// Most runs of one sweep, whatever `--max-runs` says: its points and
/// records are held in memory (0.4 kB a run, plus 16 bytes per block for
/// the run's arrival times and each wave's: 0.7 kB at N = 10 with one
/// wave, measured in tests/memory_caps.rs), so 10^7 runs take about 7 GB.
/// A range, not a cap.
pub const MAX_SWEEP_RUNS: usize = 10_000_000;

/// Parses a cap on a count of runs the way the other caps are written:
/// a whole number, in any float notation (`1e7`), or `inf` (no cap).
pub fn parse_runs_cap(text: &str) -> Result<usize, String> {
    let x: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("'{text}' is not a number (e.g. 200000, 1e6 or inf)"))?;
    if x == f64::INFINITY {
        return Ok(usize::MAX);
    }
    if x.is_nan() || x < 1.0 || x.fract() != 0.0 {
        return Err(format!(
            "'{text}' is not a whole number of runs, 1 or more (or inf)"
        ));
    }
    // `as` saturates past usize::MAX.
    Ok(x as usize)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_defaults_pass_real_work() {
        let l = Limits::default();
        // The paper's run, N = 1000 for 2e5 steps, N = 100,000 for 5000 steps.
        for (steps, n) in [(4e5, 10.0), (2e5, 1000.0), (5e3, 1e5)] {
            assert!(
                l.check(Resource::BlockSteps, steps * n, String::new)
                    .is_ok()
            );
        }
        assert!(l.check_movie(1000, 1920, 1080).is_ok());
        assert!(l.check_sweep(10_000.0).is_ok());
        assert!(l.check_samples(1000.0, 10_000).is_ok());
    }

    #[test]
    fn past_the_cap_says_what_and_how_much() {
        let l = Limits::default();
        let e = l.check_samples(f64::INFINITY, 10).unwrap_err();
        assert_eq!(e.resource, Resource::BlockSamples);
        assert_eq!(e.value, f64::INFINITY);
        let text = e.to_string();
        assert!(
            text.contains("block-samples") && text.contains("5.0e7"),
            "{text}"
        );
        assert!(!text.contains("--"), "the library names no flag: {text}");
        // A value just past the cap is printed with the digits that show it.
        let e = l
            .check(Resource::MoviePixels, 5_000_000_001.0, String::new)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("5.000000001e9") && e.contains("cap of 5.000000000e9"),
            "{e}"
        );
        assert_eq!(parse_runs_cap("1e7"), Ok(10_000_000));
        assert_eq!(parse_runs_cap("inf"), Ok(usize::MAX));
        assert!(parse_runs_cap("0").is_err() && parse_runs_cap("2.5").is_err());
        let nan = l.check(Resource::BlockSteps, f64::NAN, String::new);
        assert!(nan.is_err());
        let mut raised = l;
        raised.set(Resource::MoviePixels, 1e12);
        assert!(raised.check_movie(5000, 4096, 4096).is_ok());
        assert!(l.check_movie(5000, 4096, 4096).is_err());
    }
}
