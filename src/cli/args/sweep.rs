//! The arguments of `ladder sweep` and `ladder sweep gather`.

use super::{DataLimitArgs, FigureFormat, OutArgs, RunArgs, SimLimitArgs};
use clap::{Args, Subcommand};
use std::path::PathBuf;

/// `ladder sweep`: a grid from flags or a sweep file (docs/sweeps.md).
#[derive(Args, Debug)]
#[command(
    args_conflicts_with_subcommands = true,
    allow_negative_numbers = true,
    after_help = "Ranges are START:STOP:STEP, inclusive (--alpha=-45:-60:-0.5), or comma lists \
                  of numbers and ranges (--gamma 0.01,0.02,0.04). Writes OUT/sweep-NAME.csv, \
                  OUT/sweep-NAME.json and OUT/sweep-NAME.png (or --format svg,pdf), and keeps the runs done in \
                  OUT/shards/ so that a rerun resumes. With --shard K/N only shard K is run; \
                  `ladder sweep gather OUT` merges the shards (docs/cluster.md)."
)]
pub struct SweepArgs {
    #[command(subcommand)]
    pub command: Option<SweepCommand>,
    /// A sweep file: a scene (TOML) with [output] kind = "sweep" and its
    /// grid in [output.grid]; grid flags add or replace axes
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,
    #[command(flatten)]
    pub grid: GridArgs,
    #[command(flatten)]
    pub run: RunArgs,
    // How every run starts.
    #[arg(long, value_name = "START", help_heading = "Run", help = super::with_default(
        "How every run starts: ground (at rest, springs at rest length) or relaxed (at rest \
         hanging under gravity, block 1 clamped)",
        format!("the file's, or {}", crate::sim::Start::default()),
    ))]
    pub start: Option<super::StartArg>,
    // The latest time of an undecided run.
    #[arg(long, value_name = "T", help_heading = "Outcome", help = super::with_default(
        "Latest time a run may reach while its outcome is undecided, in tau",
        crate::scene::sweep::SweepSpec::default().cap,
    ))]
    pub cap: Option<f64>,
    /// Removed (an error if given): outcomes are proved by the state
    #[arg(long, value_name = "K", help_heading = "Outcome", hide = true)]
    pub quiet: Option<f64>,
    /// Name of the output files, sweep-NAME.* [default: the file's name, or custom]
    #[arg(long, value_name = "NAME")]
    pub name: Option<String>,
    #[command(flatten)]
    pub out: OutArgs,
    /// Run only shard K of N (1 <= K <= N): runs K, K + N, K + 2N, ... of the
    /// grid, kept in OUT/shards/; then `ladder sweep gather OUT`
    #[arg(long, value_name = "K/N")]
    pub shard: Option<String>,
    #[command(flatten)]
    pub figure_format: FigureFormat,
    /// Largest number of runs accepted (e.g. 1e6; inf: no cap)
    #[arg(
        long,
        value_name = "N",
        default_value_t = crate::scene::sweep::DEFAULT_MAX_RUNS,
        value_parser = crate::limits::parse_runs_cap,
        help_heading = "Limits (docs/limits.md)"
    )]
    pub max_runs: usize,
    #[command(flatten)]
    pub limits: SimLimitArgs,
}

#[derive(Subcommand, Debug)]
pub enum SweepCommand {
    /// Merge the shards in DIR/shards/ into DIR/sweep-NAME.csv, .json and .png
    Gather {
        /// The folder the shards were written to (their --out)
        #[arg(value_name = "DIR")]
        dir: PathBuf,
        #[command(flatten)]
        figure_format: FigureFormat,
        #[command(flatten)]
        limits: DataLimitArgs,
    },
}

/// The grid: one flag per parameter of the table (`model::table`), each
/// a range START:STOP:STEP or a comma list.
#[derive(Args, Debug, Clone, Default)]
#[command(next_help_heading = "Grid (each a value, START:STOP:STEP inclusive, or a comma list)")]
pub struct GridArgs {
    #[command(flatten)]
    pub axes: super::GridFlags,
}
