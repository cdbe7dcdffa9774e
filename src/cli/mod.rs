//! The command line (README.md): `args` collects the arguments (clap),
//! `convert` turns them into scenes and options, and this module runs the
//! library and prints or writes what it returns. No physics and no drawing
//! here.

pub mod args;
pub mod commands;
pub mod convert;
pub mod custom;
pub mod formats;
pub mod hints;
pub mod progress;

pub use args::*;

use crate::catalog::{self};
use crate::error::{Error, Result};
use crate::limits::{Limits, Resource};
use crate::output;
use crate::scene::{self};
use clap::Parser;
use serde::Serialize;
use std::ffi::OsString;

/// Runs the program on `args`; returns the process exit code.
pub fn main_with_args<I, T>(args: I) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    crate::output::temp::install_signal_cleanup();
    let args: Vec<OsString> = args.into_iter().map(Into::into).collect();
    // Recorded in every data file: what reruns it.
    let command_line: Vec<String> = args
        .iter()
        .map(|a| a.to_string_lossy().into_owned())
        .collect();
    let result = match Cli::try_parse_from(args) {
        Ok(cli) => run_with(cli, &command_line),
        Err(e) => return clap_exit(e),
    };
    match result {
        Ok(()) | Err(Error::Closed) => 0,
        Err(e) => report_error(&e),
    }
}

/// Writes the error's one line (a cap's with the flag that raises it) to
/// standard error; returns its exit code, or 1 if standard error cannot
/// be written (but not when its reader is gone).
fn report_error(e: &Error) -> i32 {
    let line = match e {
        Error::Limit(limit) => format!("ladder: {limit}; {}\n", limit_hint(limit)),
        _ => format!("ladder: {e}\n"),
    };
    exit_after(output::eprint(&line), e.exit_code())
}

/// How to get past a cap: ask for less, or raise it with its flag.
fn limit_hint(limit: &crate::limits::LimitExceeded) -> String {
    let flag = LimitArgs::flag(limit.resource);
    if limit.value.is_finite() {
        let ask = format!("{:.1e}", limit.value * 1.05);
        format!("ask for less, or raise the cap with {flag} {ask}")
    } else {
        "ask for less (no cap can allow it)".to_string()
    }
}

impl LimitArgs {
    /// The flag that sets the cap on `resource`.
    pub fn flag(resource: Resource) -> &'static str {
        match resource {
            Resource::BlockSteps => "--max-block-steps",
            Resource::BlockSamples => "--max-block-samples",
            Resource::MoviePixels => "--max-pixels",
            Resource::SweepRuns => "--max-runs",
            Resource::DataBytes => "--max-data-bytes",
            Resource::TheoryWork => "--max-theory-work",
        }
    }

    /// The caps of the flags (the defaults where none is given), which
    /// every scene of the command then carries (`Scene::limits`).
    pub fn caps(&self) -> Result<Limits> {
        let mut limits = Limits::default();
        for (resource, value) in [
            (Resource::BlockSteps, self.max_block_steps),
            (Resource::BlockSamples, self.max_block_samples),
            (Resource::MoviePixels, self.max_pixels),
            (Resource::DataBytes, self.max_data_bytes),
            (Resource::TheoryWork, self.max_theory_work),
        ] {
            if let Some(v) = value {
                if v.is_nan() || v <= 0.0 {
                    return Err(Error::bad_input(format!(
                        "{} must be a number > 0 (inf for no cap), got {}",
                        Self::flag(resource),
                        crate::numfmt::plain(v)
                    )));
                }
                limits.set(resource, v);
            }
        }
        Ok(limits)
    }
}

/// Help and version go to stdout with exit 0. A missing argument gets
/// clap's whole message (what is missing, the usage line, the pointer to
/// --help); any other usage error one line, with clap's tip (the closest
/// subcommand or flag) after it. Exit 2.
fn clap_exit(e: clap::Error) -> i32 {
    use clap::error::ErrorKind;
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            exit_after(output::print(&e.to_string()), 0)
        }
        ErrorKind::MissingRequiredArgument
        | ErrorKind::MissingSubcommand
        | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let text = e.to_string().replacen("error: ", "ladder: ", 1);
            exit_after(output::eprint(&text), 2)
        }
        _ => exit_after(
            output::eprint(&format!("ladder: {}\n", one_line(&e.to_string()))),
            2,
        ),
    }
}

/// `code`, or 1 if the message could not be written (a closed pipe is
/// not a failure).
fn exit_after(written: Result<()>, code: i32) -> i32 {
    match written {
        Ok(()) | Err(Error::Closed) => code,
        Err(_) => 1,
    }
}

/// clap's first line, with its tip ("a similar subcommand exists: ...")
/// after it.
fn one_line(text: &str) -> String {
    let mut lines = text.lines().map(str::trim).filter(|l| !l.is_empty());
    let first = lines
        .next()
        .unwrap_or("invalid arguments")
        .trim_start_matches("error: ")
        .to_string();
    match lines.find_map(|l| l.strip_prefix("tip: ")) {
        Some(tip) => format!("{first} ({tip})"),
        None => first,
    }
}

pub fn run(cli: Cli) -> Result<()> {
    run_with(cli, &[])
}

/// [`run`], recording `command_line` (the program's arguments, word by
/// word) in the data files it writes. The caps of the `--max-*` flags
/// reach every scene the command makes (`Scene::limits`).
pub fn run_with(cli: Cli, command_line: &[String]) -> Result<()> {
    use commands::render;
    let limits = cli.command.limits().caps()?;
    let call = commands::Call {
        command_line,
        limits,
    };
    match cli.command {
        Command::Simulate(args) => commands::simulate::simulate(&args, &call),
        Command::Bench(args) => commands::bench::bench(&args),
        Command::Theory(args) => commands::theory::theory(&args),
        Command::Sweep(args) => commands::sweep::sweep(&args, &call),
        Command::List => output::print(&catalog::listing()?),
        Command::Completions(args) => output::print(&commands::docs::completions(args.shell)?),
        Command::Man => output::print(&commands::docs::man_page()?),
        Command::Scene(args) => {
            let entry = render::scene_entry(&args.id)?;
            output::print(&scene::file::to_toml(&entry.scene)?)
        }
        Command::Figure(args) => render::figure(&args, &call),
        Command::Movie(args) => render::movie(&args, &call),
        Command::Render(args) => render::render(&args, &call),
        Command::All(args) => render::all(&args, &call),
    }
}

pub(crate) fn to_json<T: Serialize>(value: &T) -> Result<String> {
    serde_json::to_string(value).map_err(|e| Error::failed(format!("cannot encode JSON: {e}")))
}
