//! The `--max-*` flags: the caps on a command's cost (`crate::limits`,
//! docs/limits.md), their defaults read from `Limits::default`.

use super::{Command, SweepArgs, SweepCommand, with_default};
use clap::Args;

/// The caps' defaults (`Limits::default`), for help texts.
fn limits() -> crate::limits::Limits {
    crate::limits::Limits::default()
}

/// Caps on the cost of one command (`crate::limits`, docs/limits.md), as
/// given by the flags of the command that has them (the defaults where
/// none is given).
#[derive(Debug, Clone, Default)]
pub struct LimitArgs {
    pub max_block_steps: Option<f64>,
    pub max_block_samples: Option<f64>,
    pub max_pixels: Option<f64>,
    pub max_data_bytes: Option<f64>,
    pub max_theory_work: Option<f64>,
}

/// The caps on a simulation's cost, on the commands that simulate. A
/// request past a cap is refused before any work, with the flag that
/// raises it.
#[derive(Args, Debug, Clone, Default)]
#[command(next_help_heading = "Limits (docs/limits.md)")]
pub struct SimLimitArgs {
    // Most steps × N of one simulation.
    #[arg(long, value_name = "X", help = with_default(
        &format!(
            "Most steps × N of one simulation, counted as the paper's model by Verlet (about {:.0} ns each); other force paths count theirs times their weight (docs/limits.md)",
            crate::sim::cost::REFERENCE_NS,
        ),
        limits().block_steps,
    ))]
    pub max_block_steps: Option<f64>,
    // Most samples × N kept of one simulation.
    #[arg(long, value_name = "X", help = with_default(
        "Most samples × N kept of one simulation (48 bytes each in memory)",
        limits().block_samples,
    ))]
    pub max_block_samples: Option<f64>,
    // Most bytes of one data file.
    #[arg(long, value_name = "X", help = with_default(
        "Most bytes of one data file (<output>.json), estimated before any work",
        limits().data_bytes,
    ))]
    pub max_data_bytes: Option<f64>,
}

/// The cap on a data file's bytes alone, on `sweep gather` (which runs
/// nothing, and writes the sweep's CSV and JSON).
#[derive(Args, Debug, Clone, Default)]
#[command(next_help_heading = "Limits (docs/limits.md)")]
pub struct DataLimitArgs {
    // Most bytes of one data file.
    #[arg(long, value_name = "X", help = with_default(
        "Most bytes of one data file (the sweep's .json or .csv)",
        limits().data_bytes,
    ))]
    pub max_data_bytes: Option<f64>,
}

/// The cap on a movie's size, on the commands that write movies.
#[derive(Args, Debug, Clone, Default)]
#[command(next_help_heading = "Limits (docs/limits.md)")]
pub struct PixelLimitArgs {
    // Most frames × pixels of one movie.
    #[arg(long, value_name = "X", help = with_default(
        "Most frames × width × height of one movie",
        limits().movie_pixels,
    ))]
    pub max_pixels: Option<f64>,
}

/// The cap on a theory figure's cost, on the commands that draw them.
#[derive(Args, Debug, Clone, Default)]
#[command(next_help_heading = "Limits (docs/limits.md)")]
pub struct TheoryLimitArgs {
    // Most operations of one theory figure.
    #[arg(long, value_name = "X", help = with_default(
        "Most estimated operations of one theory figure (about 1 ns each; Fig. 2d at N = 20000 is 5.2e10)",
        limits().theory_work,
    ))]
    pub max_theory_work: Option<f64>,
}

impl Command {
    /// The caps the command's flags set (the defaults for a command that
    /// has none).
    pub fn limits(&self) -> LimitArgs {
        let (sim, pixels) = match self {
            Self::Simulate(a) => (Some(&a.limits), None),
            Self::Movie(a) => (Some(&a.limits), Some(&a.pixel_limits)),
            Self::Figure(a) => (Some(&a.limits), None),
            Self::Render(a) => (Some(&a.limits), Some(&a.pixel_limits)),
            Self::All(a) => (Some(&a.limits), Some(&a.pixel_limits)),
            Self::Sweep(a) => (Some(&a.limits), None),
            Self::Bench(a) => (Some(&a.limits), None),
            _ => (None, None),
        };
        LimitArgs {
            max_block_steps: sim.and_then(|l| l.max_block_steps),
            max_block_samples: sim.and_then(|l| l.max_block_samples),
            max_pixels: pixels.and_then(|l| l.max_pixels),
            max_data_bytes: match self {
                Self::Sweep(SweepArgs {
                    command: Some(SweepCommand::Gather { limits, .. }),
                    ..
                }) => limits.max_data_bytes,
                _ => sim.and_then(|l| l.max_data_bytes),
            },
            max_theory_work: match self {
                Self::Figure(a) => a.theory_limits.max_theory_work,
                Self::Render(a) => a.theory_limits.max_theory_work,
                Self::All(a) => a.theory_limits.max_theory_work,
                _ => None,
            },
        }
    }
}
