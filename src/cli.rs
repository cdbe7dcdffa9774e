//! Command-line definitions and dispatch (SPEC section 5). No physics and no
//! drawing here: each command calls the library and prints its result.

use crate::catalog::{self, Entry, Output};
use crate::error::{Error, Result};
use crate::model::Params;
use crate::scenes::{self, MovieOptions};
use crate::sim::{self, Drive, IntegratorConfig, IntegratorKind, Scenario};
use clap::{Args, Parser, Subcommand};
use serde::Serialize;
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::time::Instant;

#[derive(Parser, Debug)]
#[command(
    name = "ladder",
    version,
    about = "Simulate the Jacob's-ladder toy and render the figures and movies of \
             \"Topological antiqued mechanical toy\" (Wada, Mizobata, Ueno, Yoneda)",
    allow_negative_numbers = true
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Simulate a kink (alpha > 0) or antikink (alpha < 0) driven from the top block
    Simulate(SimulateArgs),
    /// Measure the integrators: speed against accuracy, or stability limits
    Bench(BenchArgs),
    /// Linear theory of the ladder: potential, zero modes, winding, dispersion
    Theory(TheoryArgs),
    /// Render every figure and movie, plus OUT/index.html
    All(AllArgs),
    /// Render one figure (figure-ID.png) or all of them
    Figure(FigureArgs),
    /// Render one movie (movie-ID.gif and movie-ID-kymograph.png) or all of them
    Movie(MovieArgs),
    /// List the catalogue of figures and movies, one line each
    List,
}

#[derive(Args, Debug)]
pub struct OutArgs {
    /// Output folder
    #[arg(long, default_value = "out", value_name = "DIR")]
    pub out: PathBuf,
}

#[derive(Args, Debug)]
pub struct MovieFormat {
    /// Frames per movie (2..=5000)
    #[arg(long, default_value_t = 200)]
    pub frames: usize,
    /// Frame size WxH in pixels
    #[arg(long, default_value = "640x480", value_name = "WxH", value_parser = parse_size)]
    pub size: (u32, u32),
    /// Frames per second
    #[arg(long, default_value_t = 25.0)]
    pub fps: f64,
}

impl MovieFormat {
    fn options(&self) -> Result<MovieOptions> {
        MovieOptions {
            frames: self.frames,
            width: self.size.0,
            height: self.size.1,
            fps: self.fps,
        }
        .validated()
    }
}

fn parse_size(s: &str) -> std::result::Result<(u32, u32), String> {
    let bad = || format!("expected WxH such as 640x480, got '{s}'");
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    Ok((
        w.trim().parse().map_err(|_| bad())?,
        h.trim().parse().map_err(|_| bad())?,
    ))
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct AllArgs {
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub format: MovieFormat,
}

#[derive(Args, Debug)]
pub struct FigureArgs {
    /// Figure ID (see `ladder list`) or all
    pub id: String,
    #[command(flatten)]
    pub out: OutArgs,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct MovieArgs {
    /// Movie ID (see `ladder list`) or all
    pub id: String,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub format: MovieFormat,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct TheoryArgs {
    /// Equilibrium angle alpha in degrees, 0 <= |alpha| <= 90
    #[arg(long, default_value_t = 60.0, value_name = "DEG")]
    pub alpha: f64,
    /// Rest length b of the B springs, in units of s
    #[arg(long, default_value_t = 1.3)]
    pub b: f64,
    /// Number of blocks N of the finite chain (2..=400)
    #[arg(long, default_value_t = 10)]
    pub n: usize,
    /// Print one JSON object instead of a table
    #[arg(long)]
    pub json: bool,
}

#[derive(Args, Debug)]
pub struct BenchArgs {
    /// work-precision (error against cost), stability (critical time
    /// steps), or kernels (the paper's run timed with each `simulate
    /// --kernel`; prints only, writes no file)
    #[arg(value_name = "STUDY")]
    pub study: String,
    /// Output folder for the chart and its CSV
    #[arg(long, default_value = "out", value_name = "DIR")]
    pub out: PathBuf,
    /// Print one JSON object instead of a table
    #[arg(long)]
    pub json: bool,
    /// Repeats per work-precision point, or rounds of bench kernels (the
    /// median wall time is kept)
    #[arg(long, default_value_t = 3)]
    pub repeats: usize,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct SimulateArgs {
    /// Equilibrium angle alpha in degrees, 0 < |alpha| < 90; its sign picks the ground state
    #[arg(long, default_value_t = 60.0, value_name = "DEG")]
    pub alpha: f64,
    /// Number of blocks N (>= 2)
    #[arg(long, default_value_t = 10)]
    pub n: usize,
    /// Rest length b of the B springs, in units of the block length s
    #[arg(long, default_value_t = 1.3)]
    pub b: f64,
    /// End time, in units of tau = sqrt(m/k)
    #[arg(long, default_value_t = 4000.0, value_name = "T")]
    pub t_end: f64,
    /// Time T_d over which block 1 turns from alpha to -alpha
    #[arg(long, default_value_t = sim::PAPER_DRIVE_TIME, value_name = "TD")]
    pub drive_time: f64,
    /// Turn block 1 back (−alpha → alpha) over [T, T + drive time] as well (movies 10, 11)
    #[arg(long, value_name = "T")]
    pub second_flip: Option<f64>,
    /// explicit-euler, symplectic-euler, verlet, rk4, dopri5, or auto: the
    /// measured best (docs/performance.md), velocity Verlet at
    /// dt = min(0.25, 0.4 * 2/omega_max), 0.25 for the paper's ladder; auto ignores --dt
    #[arg(long, default_value = "symplectic-euler", value_name = "NAME")]
    pub integrator: String,
    /// Time step (first trial step for dopri5)
    #[arg(long, default_value_t = 0.01)]
    pub dt: f64,
    /// Error tolerance of dopri5 (relative and absolute) [default: 1e-6]
    #[arg(long, value_name = "R")]
    pub rtol: Option<f64>,
    /// Damping gamma (force -gamma*dX/dt, torque -gamma*r^2*dtheta/dt)
    #[arg(long, default_value_t = 0.02, value_name = "G")]
    pub gamma: f64,
    /// Gravity G = mg/(ks)
    #[arg(long, default_value_t = 2e-4, value_name = "G")]
    pub gravity: f64,
    /// Print one JSON object instead of a table
    #[arg(long)]
    pub json: bool,
    /// Write theta_n(t) in degrees at the sample times to this CSV file
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// Interval between CSV samples, in tau
    #[arg(long, default_value_t = 10.0, value_name = "T")]
    pub sample_every: f64,
    /// Code that takes symplectic Euler's steps (N <= 32; otherwise, and for
    /// the other integrators, the portable loop): the fused kernel for the
    /// best instruction set of this CPU, the one for a given set, or the
    /// portable loop. All give the same numbers, bit for bit; only the time
    /// differs
    #[arg(long, value_enum, default_value_t = KernelArg::Fastest, value_name = "KERNEL")]
    pub kernel: KernelArg,
}

/// `simulate --kernel`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum KernelArg {
    Fastest,
    Avx2,
    Avx512,
    Portable,
}

impl KernelArg {
    /// The stepping asked for, if this CPU can run it.
    fn stepping(self) -> Result<sim::Stepping> {
        let fused = |isa: sim::Isa| {
            if isa.available() {
                Ok(sim::Stepping::Fused(isa))
            } else {
                Err(Error::bad_input(format!(
                    "--kernel {}: this CPU lacks the instruction set; use fastest or portable",
                    isa.name()
                )))
            }
        };
        match self {
            Self::Fastest => Ok(sim::Stepping::Fastest),
            Self::Avx2 => fused(sim::Isa::Avx2),
            Self::Avx512 => fused(sim::Isa::Avx512),
            Self::Portable => Ok(sim::Stepping::Portable),
        }
    }
}

/// Runs the program on `args`; returns the process exit code.
pub fn main_with_args<I, T>(args: I) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) => return clap_exit(e),
    };
    match run(cli) {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("ladder: {e}");
            e.exit_code()
        }
    }
}

/// Help and version go to stdout with exit 0; a usage error is one line on
/// stderr with exit 2.
fn clap_exit(e: clap::Error) -> i32 {
    use clap::error::ErrorKind;
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            print!("{e}");
            0
        }
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            eprint!("{e}");
            2
        }
        _ => {
            let text = e.to_string();
            let line = text.lines().next().unwrap_or("invalid arguments");
            eprintln!("ladder: {}", line.trim_start_matches("error: "));
            2
        }
    }
}

pub fn run(cli: Cli) -> Result<()> {
    match cli.command {
        Command::Simulate(args) => simulate(&args),
        Command::Bench(args) => bench(&args),
        Command::Theory(args) => theory(&args),
        Command::List => {
            print!("{}", catalog::listing());
            Ok(())
        }
        Command::Figure(args) => {
            let entries = pick(Output::Figure, &args.id)?;
            render_into(&entries, &args.out.out, &MovieOptions::default(), false)
        }
        Command::Movie(args) => {
            let opts = args.format.options()?;
            let entries = pick(Output::Movie, &args.id)?;
            render_into(&entries, &args.out.out, &opts, false)
        }
        Command::All(args) => {
            let opts = args.format.options()?;
            let entries: Vec<&'static Entry> = catalog::CATALOGUE.iter().collect();
            render_into(&entries, &args.out.out, &opts, true)
        }
    }
}

/// `simulate --json` (SPEC section 5).
#[derive(Serialize, Debug)]
pub struct SimulateReport {
    pub alpha_deg: f64,
    pub n: usize,
    pub b: f64,
    pub a: f64,
    pub integrator: String,
    pub dt: f64,
    pub rtol: Option<f64>,
    pub t_end: f64,
    pub drive_time: f64,
    pub steps: u64,
    pub force_evals: u64,
    pub wall_seconds: f64,
    pub arrival_times: Vec<Option<f64>>,
    pub final_theta_deg: Vec<f64>,
}

fn simulate(args: &SimulateArgs) -> Result<()> {
    let base = Params::paper(60.0)?;
    let params = Params {
        gamma: args.gamma,
        gravity: args.gravity,
        ..base.with(args.n, args.b, args.alpha)?
    }
    .validated()?;
    let auto = args.integrator == "auto";
    let kind: IntegratorKind = if auto {
        IntegratorKind::Verlet
    } else {
        args.integrator
            .parse()
            .map_err(|e: Error| Error::bad_input(format!("{e}, or auto")))?
    };
    let rtol = match (kind, args.rtol) {
        (IntegratorKind::Dopri5, r) => Some(r.unwrap_or(1e-6)),
        (_, Some(_)) => {
            return Err(Error::bad_input(
                "--rtol applies only to --integrator dopri5",
            ));
        }
        (_, None) => None,
    };
    let config = if auto {
        IntegratorConfig::auto(crate::theory::dispersion::omega_max_clamped(&params)?)
    } else {
        IntegratorConfig {
            kind,
            dt: args.dt,
            rtol,
        }
    }
    .validated()?;
    let scenario = match args.second_flip {
        None => Scenario::single_flip(params, args.drive_time, args.t_end)?,
        Some(t2) => {
            sim::check_simulable(&params)?;
            let drive = Drive::two_flips(params.alpha, args.drive_time, t2)?;
            Scenario::with_drive(params, drive, args.t_end)?
        }
    };
    let samples = csv_samples(args)?;
    let stepping = args.kernel.stepping()?;
    if let Some(path) = &args.csv {
        crate::output::check_writable(path)?;
    }
    let start = Instant::now();
    let traj = sim::simulate_with(&scenario, &samples, &config, stepping)?;
    let wall_seconds = start.elapsed().as_secs_f64();
    if let Some(path) = &args.csv {
        crate::output::write_atomic(path, csv_text(&traj).as_bytes())?;
    }
    let report = SimulateReport {
        alpha_deg: args.alpha,
        n: params.n,
        b: params.b,
        a: params.a(),
        integrator: kind.name().to_string(),
        dt: config.dt,
        rtol,
        t_end: args.t_end,
        drive_time: args.drive_time,
        steps: traj.steps,
        force_evals: traj.force_evals,
        wall_seconds,
        arrival_times: traj.arrival_times.clone(),
        final_theta_deg: traj.final_theta_deg(),
    };
    if args.json {
        let text = serde_json::to_string(&report).map_err(|e| Error::failed(e.to_string()))?;
        println!("{text}");
    } else {
        print!("{}", simulate_table(&report));
    }
    Ok(())
}

fn csv_samples(args: &SimulateArgs) -> Result<Vec<f64>> {
    if args.csv.is_none() {
        return Ok(Vec::new());
    }
    let every = args.sample_every;
    if !(every.is_finite() && every > 0.0) {
        return Err(Error::bad_input(format!(
            "--sample-every must be a finite number > 0, got {every}"
        )));
    }
    let count = (args.t_end / every).floor() as usize;
    if count > 10_000_000 {
        return Err(Error::bad_input(
            "--sample-every is too small for this --t-end",
        ));
    }
    Ok((0..=count).map(|k| k as f64 * every).collect())
}

fn csv_text(traj: &sim::Trajectory) -> String {
    let n = traj.final_state.q.len() / 3;
    let mut out = String::from("t");
    for i in 1..=n {
        out.push_str(&format!(",theta_{i}_deg"));
    }
    out.push('\n');
    for (t, q) in traj.times.iter().zip(&traj.states) {
        out.push_str(&format!("{t}"));
        for th in sim::observables::angles_deg(q) {
            out.push_str(&format!(",{th:.6}"));
        }
        out.push('\n');
    }
    out
}

fn simulate_table(r: &SimulateReport) -> String {
    let mut s = format!(
        "alpha = {}°, N = {}, b = {}, a = {:.6}; {} with {}; {} steps, {} force evaluations, {:.3} s\n",
        r.alpha_deg,
        r.n,
        r.b,
        r.a,
        r.integrator,
        r.rtol
            .map_or(format!("dt = {}", r.dt), |x| format!("rtol = {x:e}")),
        r.steps,
        r.force_evals,
        r.wall_seconds
    );
    s.push_str("block  arrival t/τ   final θ (deg)\n");
    for (i, (t, th)) in r.arrival_times.iter().zip(&r.final_theta_deg).enumerate() {
        let t = t.map_or("never".to_string(), |t| format!("{t:.2}"));
        s.push_str(&format!("{:>5}  {:>11}   {:>13.3}\n", i + 1, t, th));
    }
    s
}

fn bench(args: &BenchArgs) -> Result<()> {
    if !(1..=100).contains(&args.repeats) {
        return Err(Error::bad_input(format!(
            "--repeats must be between 1 and 100, got {}",
            args.repeats
        )));
    }
    match args.study.as_str() {
        "work-precision" | "stability" => crate::output::ensure_dir(&args.out)?,
        "kernels" => return bench_kernels(args),
        other => {
            return Err(Error::bad_input(format!(
                "unknown study '{other}'; choose work-precision, stability or kernels"
            )));
        }
    }
    match args.study.as_str() {
        "work-precision" => bench_work_precision(args),
        _ => bench_stability(args),
    }
}

fn bench_kernels(args: &BenchArgs) -> Result<()> {
    let runs = args.repeats * crate::bench::kernels::kernel_count();
    let bar = progress_bar(runs as u64, "kernels");
    let report = crate::bench::kernels(args.repeats, &ticker(&bar))?;
    bar.finish_and_clear();
    if args.json {
        println!("{}", to_json(&report)?);
    } else {
        print!("{}", crate::bench::kernels_table(&report));
    }
    Ok(())
}

fn bench_work_precision(args: &BenchArgs) -> Result<()> {
    use crate::bench::{self, BenchScene};
    let scenes = [BenchScene::paper(60.0)?, BenchScene::paper(-60.0)?];
    let total: usize = scenes.len()
        * IntegratorKind::ALL
            .iter()
            .map(|k| bench::default_steps(*k).len())
            .sum::<usize>();
    let bar = progress_bar(total as u64, "work-precision");
    let report = bench::work_precision(&scenes, args.repeats, &ticker(&bar))?;
    bar.finish_and_clear();
    let chart = bench::work_precision_chart(&report)?;
    let csv = bench::work_precision_csv(&report);
    let table = bench::work_precision_table(&report);
    write_study(args, "work-precision", &csv, &chart, &report, &table)
}

/// Writes a study's chart and CSV (`DIR/NAME.png`, `DIR/NAME.csv`; the PNG
/// is encoded before anything is written) and prints its JSON or table.
fn write_study<T: Serialize>(
    args: &BenchArgs,
    name: &str,
    csv_text: &str,
    chart: &tiny_skia::Pixmap,
    report: &T,
    table: &str,
) -> Result<()> {
    let png_bytes = crate::encode::png_bytes(chart)?;
    let (csv, png) = (
        args.out.join(format!("{name}.csv")),
        args.out.join(format!("{name}.png")),
    );
    crate::output::write_atomic(&csv, csv_text.as_bytes())?;
    crate::output::write_atomic(&png, &png_bytes)?;
    if args.json {
        println!("{}", to_json(report)?);
    } else {
        print!("{table}");
        println!("wrote {} and {}", csv.display(), png.display());
    }
    Ok(())
}

fn bench_stability(args: &BenchArgs) -> Result<()> {
    use crate::bench;
    let alphas = bench::STABILITY_ALPHAS;
    let bar = progress_bar(alphas.len() as u64, "stability");
    let report = bench::stability(&alphas, &ticker(&bar))?;
    bar.finish_and_clear();
    let chart = bench::stability_chart(&report)?;
    let csv = bench::stability_csv(&report);
    let table = bench::stability_table(&report);
    write_study(args, "stability", &csv, &chart, &report, &table)
}

fn to_json<T: Serialize>(value: &T) -> Result<String> {
    serde_json::to_string(value).map_err(|e| Error::failed(format!("cannot encode JSON: {e}")))
}

/// A progress bar on stderr (hidden when stderr is not a terminal).
/// A progress callback for a study: shows `msg` and counts one item.
fn ticker(bar: &indicatif::ProgressBar) -> impl Fn(&str) + Sync + '_ {
    move |msg| {
        bar.set_message(msg.to_string());
        bar.inc(1);
    }
}

fn progress_bar(len: u64, what: &str) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(len);
    let style =
        indicatif::ProgressStyle::with_template("{prefix} [{bar:30}] {pos}/{len} {elapsed} {msg}")
            .map(|s| s.progress_chars("=> "));
    if let Ok(style) = style {
        bar.set_style(style);
    }
    bar.set_prefix(what.to_string());
    bar
}

fn theory(args: &TheoryArgs) -> Result<()> {
    let params = Params::paper(60.0)?.with(args.n, args.b, args.alpha)?;
    let report = crate::theory::TheoryReport::compute(&params)?;
    if args.json {
        println!("{}", to_json(&report)?);
    } else {
        print!("{}", report.to_table());
    }
    Ok(())
}

/// The entries named by `id` (or all of that kind).
fn pick(output: Output, id: &str) -> Result<Vec<&'static Entry>> {
    if id == "all" {
        Ok(catalog::entries(output).collect())
    } else {
        Ok(vec![catalog::find(output, id)?])
    }
}

/// Renders `entries` into `out` in parallel (rayon), each file written
/// atomically as soon as it is ready, with a progress bar and a summary.
fn render_into(
    entries: &[&'static Entry],
    out: &Path,
    movie: &MovieOptions,
    index: bool,
) -> Result<()> {
    use rayon::prelude::*;
    crate::output::check_writable(&out.join("index.html"))?;
    let start = Instant::now();
    let bar = progress_bar(entries.len() as u64, "rendering");
    let written: Vec<usize> = entries
        .par_iter()
        .map(|e| {
            let files = scenes::render(e, movie)?;
            for (name, bytes) in &files {
                crate::output::write_atomic(&out.join(name), bytes)?;
            }
            bar.set_message(e.id.to_string());
            bar.inc(1);
            Ok(files.len())
        })
        .collect::<Result<_>>()?;
    bar.finish_and_clear();
    let mut files: usize = written.iter().sum();
    if index {
        let page = crate::gallery::index_html(entries);
        crate::output::write_atomic(&out.join("index.html"), page.as_bytes())?;
        files += 1;
    }
    eprintln!(
        "ladder: wrote {files} files ({} scenes) into {} in {:.2} s",
        entries.len(),
        out.display(),
        start.elapsed().as_secs_f64()
    );
    Ok(())
}
