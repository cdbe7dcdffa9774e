//! The command line (SPEC section 5): `args` collects the arguments (clap),
//! `convert` turns them into scenes and options, and this module runs the
//! library and prints or writes what it returns. No physics and no drawing
//! here.

pub mod args;
pub mod convert;
pub mod sweep;

pub use args::*;

use crate::catalog::{self, Entry};
use crate::error::{Error, Result};
use crate::front;
use crate::limits::{Limits, Resource};
use crate::output;
use crate::scene::{self, Kind, Scene};
use crate::scenes::{self, MovieOptions, Outputs};
use crate::sim::{self, IntegratorKind};
use clap::Parser;
use serde::Serialize;
use std::ffi::OsString;
use std::time::Instant;

/// Runs the program on `args`; returns the process exit code.
pub fn main_with_args<I, T>(args: I) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    crate::output::temp::install_signal_cleanup();
    let args: Vec<OsString> = args.into_iter().map(Into::into).collect();
    // Recorded in every data file (issue 19): what reruns it.
    let command_line: Vec<String> = args
        .iter()
        .map(|a| a.to_string_lossy().into_owned())
        .collect();
    let result = match Cli::try_parse_from(args) {
        Ok(cli) => cli
            .command
            .limits()
            .install()
            .and_then(|()| run_with(cli, &command_line)),
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

    /// Installs the caps of the flags (the defaults where none is given)
    /// for this process.
    fn install(&self) -> Result<()> {
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
        limits.install();
        Ok(())
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
/// word) in the data files it writes.
pub fn run_with(cli: Cli, command_line: &[String]) -> Result<()> {
    let recorded = |outputs: Outputs| Outputs {
        command_line: command_line.to_vec(),
        ..outputs
    };
    match cli.command {
        Command::Simulate(args) => simulate(&args, command_line),
        Command::Bench(args) => bench(&args),
        Command::Theory(args) => theory(&args),
        Command::Sweep(args) => sweep::sweep(&args, command_line),
        Command::List => output::print(&catalog::listing()?),
        Command::Completions(args) => output::print(&completions(args.shell)?),
        Command::Man => output::print(&man_page()?),
        Command::Scene(args) => {
            let entry = scene_entry(&args.id)?;
            output::print(&scene::file::to_toml(&entry.scene)?)
        }
        Command::Figure(args) => {
            let outputs = recorded(args.figure_format.outputs()?);
            let scenes = figure_scenes(&args)?;
            let movie = MovieOptions::default();
            render_into(&scenes, &args.out, &movie, &outputs, Words::Flags, false)
        }
        Command::Movie(args) => {
            let opts = args.format.options()?;
            let outputs = recorded(Outputs {
                mp4_quality: args.format.mp4_quality(),
                ..front::options::movie_outputs(&args.formats, &opts, args.scale)?
            });
            let scenes = movie_scenes(&args)?;
            if let Some(line) = front::options::movie_formats_line(&args.formats, &outputs) {
                output::eprint(&format!("ladder: {line}\n"))?;
            }
            render_into(&scenes, &args.out, &opts, &outputs, Words::Flags, false)
        }
        Command::Render(args) => {
            let opts = args.format.options()?;
            let outputs = recorded(Outputs {
                mp4_quality: args.format.mp4_quality(),
                ..args.formats.outputs(&opts)?
            });
            let scenes = args
                .files
                .iter()
                .map(|f| scene::file::load(f))
                .collect::<Result<Vec<_>>>()?;
            args.formats.check_covers(&scenes)?;
            let sources: Vec<String> = args.files.iter().map(|f| f.display().to_string()).collect();
            front::render::check_distinct_outputs(&scenes, &sources, &args.out.out, &outputs)?;
            if args.check {
                // The checks rendering makes before its work, in one place.
                for (file, s) in args.files.iter().zip(&scenes) {
                    scenes::check(s, &opts, &outputs).map_err(|e| in_file(file, e))?;
                }
                for (file, s) in args.files.iter().zip(&scenes) {
                    output::print(&format!(
                        "{}: {} {} ({} run{}): {}\n",
                        file.display(),
                        s.kind().name(),
                        s.name,
                        s.runs().len(),
                        if s.runs().len() == 1 { "" } else { "s" },
                        scene::describe::parameters(s)
                    ))?;
                }
                return Ok(());
            }
            render_into(&scenes, &args.out, &opts, &outputs, Words::Keys, false)
        }
        Command::All(args) => {
            let opts = args.format.options()?;
            let outputs = recorded(Outputs {
                mp4_quality: args.format.mp4_quality(),
                ..args.formats.outputs(&opts)?
            });
            let scenes: Vec<Scene> = catalog::catalogue()?
                .iter()
                .map(|e| e.scene.clone())
                .collect();
            render_into(&scenes, &args.out, &opts, &outputs, Words::Flags, true)
        }
    }
}

/// `e` from the scene of `file`, the file named before its message (an
/// error of bad input; the others are the run's own).
fn in_file(file: &std::path::Path, e: Error) -> Error {
    match e {
        Error::BadInput(m) => Error::bad_input(format!("{}: {m}", file.display())),
        e => e,
    }
}

/// The catalogue entry `ladder scene` names: `ID` (a figure first, then a
/// movie), `KIND ID` or `KIND-ID` (KIND `figure` or `movie`).
fn scene_entry(words: &[String]) -> Result<&'static Entry> {
    let kind_of = |word: &str| match word.to_ascii_lowercase().as_str() {
        "figure" | "fig" => Some(Kind::Figure),
        "movie" => Some(Kind::Movie),
        _ => None,
    };
    match words {
        [kind, id] => match kind_of(kind) {
            Some(k) => catalog::find(k, id),
            None => Err(Error::bad_input(format!(
                "'{}' is not a kind of scene: say `figure {id}` or `movie {id}`",
                kind.escape_debug()
            ))),
        },
        [id] => match id
            .split_once('-')
            .and_then(|(k, rest)| Some((kind_of(k)?, rest)))
        {
            Some((k, rest)) => catalog::find(k, rest),
            None => catalog::find_any(id),
        },
        _ => Err(Error::bad_input(
            "ladder scene takes an ID, or a kind and an ID",
        )),
    }
}

/// The completion script of `shell` for every command and flag.
fn completions(shell: clap_complete::Shell) -> Result<String> {
    use clap::CommandFactory;
    let mut bytes = Vec::new();
    clap_complete::generate(shell, &mut Cli::command(), "ladder", &mut bytes);
    String::from_utf8(bytes).map_err(|_| Error::failed("the completion script is not UTF-8"))
}

/// The manual page, ladder(1), in roff: the commands' help, one section
/// each.
fn man_page() -> Result<String> {
    use clap::CommandFactory;
    let cmd = Cli::command();
    let mut bytes = Vec::new();
    let failed = |e: std::io::Error| Error::failed(format!("cannot write the man page: {e}"));
    let man = clap_mangen::Man::new(cmd.clone());
    man.render_title(&mut bytes).map_err(failed)?;
    man.render_name_section(&mut bytes).map_err(failed)?;
    man.render_synopsis_section(&mut bytes).map_err(failed)?;
    man.render_description_section(&mut bytes).map_err(failed)?;
    man.render_subcommands_section(&mut bytes).map_err(failed)?;
    for sub in cmd.get_subcommands().filter(|c| !c.is_hide_set()) {
        let name = sub.get_name().to_string();
        let sub = sub.clone().bin_name(format!("ladder {name}"));
        let man = clap_mangen::Man::new(sub);
        bytes.extend_from_slice(format!(".SH \"LADDER {}\"\n", name.to_uppercase()).as_bytes());
        man.render_synopsis_section(&mut bytes).map_err(failed)?;
        man.render_description_section(&mut bytes).map_err(failed)?;
        man.render_options_section(&mut bytes).map_err(failed)?;
    }
    man.render_version_section(&mut bytes).map_err(failed)?;
    String::from_utf8(bytes).map_err(|_| Error::failed("the man page is not UTF-8"))
}

/// The scenes of `ladder movie`: a built-in one, all of them, or a custom
/// one from the flags (on the paper's scene, or on the named one, whose
/// window and label it keeps). No ID and no flag: the catalogue and usage.
fn movie_scenes(args: &MovieArgs) -> Result<Vec<Scene>> {
    let flags = args.model.any() || args.drive.any() || args.run.any();
    let custom = flags || args.name.is_some() || args.camera.is_some();
    let make = |origin: convert::Origin<'_>| {
        convert::movie_scene(
            origin,
            args.name.as_deref(),
            args.camera,
            &args.model,
            &args.drive,
            &args.run,
        )
    };
    match args.id.as_deref() {
        Some("all") if custom => Err(Error::bad_input(
            "model, drive and run flags apply to one movie, not to all",
        )),
        Some("all") => Ok(builtin(Kind::Movie)?),
        Some(id) => {
            let entry = catalog::find(Kind::Movie, id)?;
            if !custom {
                return Ok(vec![entry.scene.clone()]);
            }
            Ok(vec![make(Some((&entry.id, &entry.scene)))?])
        }
        None if !custom => Err(what_to_make(Kind::Movie)?),
        None => Ok(vec![make(None)?]),
    }
}

/// The scenes of `ladder figure`, as [`movie_scenes`] for figures.
fn figure_scenes(args: &FigureArgs) -> Result<Vec<Scene>> {
    let flags = args.model.any() || args.drive.any() || args.run.any();
    let custom = flags || args.name.is_some() || args.view.is_some() || args.times.is_some();
    let make = |origin: convert::Origin<'_>| {
        convert::figure_scene(
            origin,
            args.name.as_deref(),
            args.view,
            args.times.as_deref(),
            (&args.model, &args.drive, &args.run),
        )
    };
    match args.id.as_deref() {
        Some("all") if custom => Err(Error::bad_input(
            "model, drive and run flags apply to one figure, not to all",
        )),
        Some("all") => builtin(Kind::Figure),
        Some(id) => {
            let entry = catalog::find(Kind::Figure, id)?;
            if !custom {
                return Ok(vec![entry.scene.clone()]);
            }
            Ok(vec![make(Some((&entry.id, &entry.scene)))?])
        }
        None if !custom => Err(what_to_make(Kind::Figure)?),
        None => Ok(vec![make(None)?]),
    }
}

/// `ladder figure` or `ladder movie` with neither an ID nor a flag: the
/// entries of that kind and the ways to call it (exit 2).
fn what_to_make(kind: Kind) -> Result<Error> {
    let name = kind.name();
    let mut text = format!(
        "{name} needs an ID, all, or model flags for your own {name}. The built-in {name}s:\n"
    );
    for e in catalog::entries(kind)? {
        text.push_str(&format!(
            "  {:<14} {}\n",
            e.id,
            scene::describe::title(&e.scene)
        ));
    }
    let own = match kind {
        Kind::Movie => "ladder movie --alpha 70 --n 20      your own movie (see --help)",
        _ => "ladder figure --alpha 70 --times 0,900,1100   your own filmstrip (see --help)",
    };
    text.push_str(&format!(
        "Usage:\n  ladder {name} ID       one of the above\n  ladder {name} all      every one\n  {own}"
    ));
    Ok(Error::bad_input(text))
}

fn builtin(kind: Kind) -> Result<Vec<Scene>> {
    Ok(catalog::entries(kind)?
        .into_iter()
        .map(|e: &Entry| e.scene.clone())
        .collect())
}

/// `simulate --json` (SPEC section 5), with what reruns it (issue 19):
/// the program, its build, the command line and the scene.
#[derive(Serialize, Debug)]
pub struct SimulateReport<'a> {
    #[serde(flatten)]
    pub made_by: scenes::data::MadeBy<'a>,
    /// The scene run, every value (a data scene: `ladder scene` writes it
    /// as TOML, `ladder render` reruns it).
    pub scene: &'a Scene,
    pub alpha_deg: f64,
    pub n: usize,
    pub b: f64,
    pub a: f64,
    pub gamma: f64,
    pub gravity: f64,
    pub inertia: f64,
    /// The scheme that made the numbers below.
    pub integrator: String,
    /// `auto` when the program chose it.
    pub requested_integrator: String,
    pub dt: f64,
    pub rtol: Option<f64>,
    /// `auto` only: estimated largest error of the arrival times, in τ.
    pub arrival_error: Option<f64>,
    pub t_end: f64,
    pub drive_time: f64,
    pub flips: Vec<f64>,
    pub steps: u64,
    pub force_evals: u64,
    pub wall_seconds: f64,
    /// The first wave's arrival times (per block, the first sign change).
    pub arrival_times: Vec<Option<f64>>,
    pub final_theta_deg: Vec<f64>,
    /// Every wave of the run and block N's fate (SPEC section 9).
    pub waves: crate::sim::waves::Waves,
}

fn simulate(args: &SimulateArgs, command_line: &[String]) -> Result<()> {
    let run = RunArgs {
        t_end: Some(args.t_end),
        integrator: Some(args.integrator.clone()),
        dt: args.dt,
        tol: args.tol.clone(),
    };
    let base = Scene {
        output: scene::OutputSpec::Data,
        ..Scene::default()
    };
    let method = convert::parse_method(&args.integrator)?;
    if args.dt.is_some() && method == scene::Method::Auto {
        return Err(Error::bad_input(
            "--dt: the auto integrator picks its own step; name an integrator to set --dt",
        ));
    }
    let scene = convert::scene_from_flags(base, &args.model, &args.drive, &run)?;
    let samples = csv_samples(args, scene.model.n)?;
    let stepping = args.kernel.stepping()?;
    for path in [&args.csv, &args.npz].into_iter().flatten() {
        output::check_writable(path)?;
    }
    let start = Instant::now();
    let bar = time_bar(scene.run.t_end);
    let result = scenes::run::simulate_with(&scene, &samples, stepping, &|t| {
        bar.set_position(bar.position().max(t as u64));
    });
    bar.finish_and_clear();
    let result = result.map_err(|e| with_divergence_hint(e, &scene, Words::Flags))?;
    let wall_seconds = start.elapsed().as_secs_f64();
    let traj = &result.trajectory;
    if let Some(path) = &args.csv {
        output::write_atomic_with(path, |f| write_csv(traj, &mut std::io::BufWriter::new(f)))?;
    }
    let params = scene.model.params()?;
    if let Some(path) = &args.npz {
        let ladder = crate::model::Ladder::new(params);
        output::write_atomic_with(path, |f| {
            scenes::data::write_npz(traj, &ladder, std::io::BufWriter::new(f)).map(drop)
        })?;
    }
    let report = SimulateReport {
        made_by: scenes::data::MadeBy::new(command_line),
        scene: &scene,
        alpha_deg: scene.model.alpha,
        n: params.n,
        b: params.b,
        a: params.a(),
        gamma: params.gamma,
        gravity: params.gravity,
        inertia: params.inertia,
        integrator: result.integrator.name.clone(),
        requested_integrator: result.integrator.requested.clone(),
        dt: result.integrator.dt,
        rtol: result.integrator.rtol,
        arrival_error: result.integrator.arrival_error,
        t_end: scene.run.t_end,
        drive_time: scene.drive.flips.first().map_or(0.0, |f| f.duration),
        flips: scene.drive.flips.iter().map(|f| f.start).collect(),
        steps: traj.steps,
        force_evals: traj.force_evals,
        wall_seconds,
        arrival_times: traj.arrival_times.clone(),
        final_theta_deg: traj.final_theta_deg(),
        waves: traj.waves.clone(),
    };
    if args.json {
        output::print(&format!("{}\n", to_json(&report)?))
    } else {
        output::print(&simulate_table(&report))
    }
}

/// How a hint names the settings: as command-line flags, or as the keys
/// of a scene file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Words {
    Flags,
    Keys,
}

impl Words {
    fn dt(self) -> &'static str {
        match self {
            Self::Flags => "--dt",
            Self::Keys => "[run] dt",
        }
    }

    fn rtol(self) -> &'static str {
        match self {
            Self::Flags => "--rtol",
            Self::Keys => "[run] rtol",
        }
    }

    fn auto(self) -> &'static str {
        match self {
            Self::Flags => "--integrator auto",
            Self::Keys => "[run] integrator = \"auto\"",
        }
    }
}

/// A diverged run's message with a hint in the user's terms: the largest
/// step at which this scene stays bounded with the integrator that failed
/// (measured by bisection, or the linear prediction where measuring would
/// take long), or the auto integrator. Other errors pass unchanged.
fn with_divergence_hint(e: Error, scene: &Scene, words: Words) -> Error {
    let Error::Diverged(d) = &e else {
        return e;
    };
    let scene::Method::Fixed(kind) = scene.run.integrator else {
        return e;
    };
    let auto = words.auto();
    let hint = if kind == IntegratorKind::Dopri5 && scene.run.rtol.is_some() {
        format!("use a smaller {}, or {auto}", words.rtol())
    } else {
        let dt = words.dt();
        match scenes::run::critical_step(scene, kind) {
            Ok(scenes::run::CriticalStep {
                measured: Some(c),
                predicted,
            }) => format!(
                "on this scene {kind} stays bounded up to dt ≈ {} τ (measured; the linear theory \
                 predicts {}): use {dt} below that, or {auto}, which picks a step and checks it",
                short(c),
                short(predicted)
            ),
            Ok(scenes::run::CriticalStep { predicted, .. }) if predicted.is_finite() => format!(
                "the linear theory puts the stable step of {kind} on this scene near dt ≈ {} τ: \
                 use {dt} well below that, or {auto}, which picks a step and checks it",
                short(predicted)
            ),
            _ => format!("use a smaller {dt}, or {auto}, which picks a step and checks it"),
        }
    };
    Error::failed(format!("{}; hint: {hint}", d.facts()))
}

/// `x` to two significant digits, as a reader writes it.
fn short(x: f64) -> String {
    if !(x.is_finite() && x > 0.0) {
        return format!("{x}");
    }
    let scale = 10f64.powf(x.log10().floor() - 1.0);
    crate::numfmt::typeset((x / scale).floor() * scale)
}

/// The CSV's and npz's sample times, 0, every, 2 every, ... up to
/// --t-end, within the cap on samples × N (checked before any is made).
fn csv_samples(args: &SimulateArgs, n: usize) -> Result<Vec<f64>> {
    if args.csv.is_none() && args.npz.is_none() {
        return Ok(Vec::new());
    }
    let every = args.sample_every;
    if !(every.is_finite() && every > 0.0) {
        return Err(Error::bad_input(format!(
            "--sample-every must be a finite number > 0, got {}",
            crate::numfmt::plain(every)
        )));
    }
    let count = (args.t_end / every).floor() + 1.0;
    Limits::active().check_samples(count, n)?;
    let mut times = Vec::new();
    times
        .try_reserve_exact(count as usize)
        .map_err(|_| Error::failed("not enough memory for the CSV's sample times"))?;
    times.extend((0..count as usize).map(|k| k as f64 * every));
    Ok(times)
}

fn simulate_table(r: &SimulateReport) -> String {
    let step = r
        .rtol
        .map_or(format!("dt = {}", r.dt), |x| format!("rtol = {x:e}"));
    let chosen = match (r.requested_integrator.as_str(), r.arrival_error) {
        ("auto", Some(e)) => format!(" (chosen by auto; arrival times within about {e:.2e} τ)"),
        _ => String::new(),
    };
    let mut s = format!(
        "alpha = {}°, N = {}, b = {}, a = {:.6}; {} with {step}{chosen}; {} steps, {} force evaluations, {:.3} s\n",
        r.alpha_deg, r.n, r.b, r.a, r.integrator, r.steps, r.force_evals, r.wall_seconds
    );
    s.push_str("block  arrival t/τ   final θ (deg)\n");
    for (i, (t, th)) in r.arrival_times.iter().zip(&r.final_theta_deg).enumerate() {
        let t = t.map_or("never".to_string(), |t| format!("{t:.2}"));
        s.push_str(&format!("{:>5}  {:>11}   {:>13.3}\n", i + 1, t, th));
    }
    s
}

/// The CSV of θ_n(t) in degrees, streamed row by row into `w`.
fn write_csv(traj: &sim::Trajectory, w: &mut impl std::io::Write) -> std::io::Result<()> {
    let n = traj.final_state.q.len() / 3;
    write!(w, "t")?;
    for i in 1..=n {
        write!(w, ",theta_{i}_deg")?;
    }
    writeln!(w)?;
    for (t, q) in traj.times.iter().zip(&traj.states) {
        write!(w, "{t}")?;
        for th in sim::observables::angles_deg(q) {
            write!(w, ",{th:.6}")?;
        }
        writeln!(w)?;
    }
    w.flush()
}

fn bench(args: &BenchArgs) -> Result<()> {
    if !(1..=100).contains(&args.repeats) {
        return Err(Error::bad_input(format!(
            "--repeats must be between 1 and 100, got {}",
            args.repeats
        )));
    }
    match args.study.as_str() {
        "work-precision" | "stability" => output::check_targets(&[
            args.out.join(format!("{}.csv", args.study)),
            args.out.join(format!("{}.png", args.study)),
        ])?,
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
        output::print(&format!("{}\n", to_json(&report)?))
    } else {
        output::print(&crate::bench::kernels_table(&report))
    }
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
        output::print(&format!("{}\n", to_json(report)?))
    } else {
        output::print(&format!(
            "{table}wrote {} and {}\n",
            csv.display(),
            png.display()
        ))
    }
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

/// A progress bar over simulated time, shown only for a run long enough
/// to wait for (over 10^5 τ of simulated time) and only on a terminal.
fn time_bar(t_end: f64) -> indicatif::ProgressBar {
    if t_end < 1e5 {
        return indicatif::ProgressBar::hidden();
    }
    let bar = indicatif::ProgressBar::new(t_end as u64);
    let style = indicatif::ProgressStyle::with_template(
        "simulating [{bar:30}] t/τ = {pos}/{len} {elapsed} (eta {eta})",
    )
    .map(|s| s.progress_chars("=> "));
    if let Ok(style) = style {
        bar.set_style(style);
    }
    bar
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
    let m = scene::Model::default();
    let params =
        crate::model::Params::new(args.n, args.b, args.alpha, m.gamma, m.gravity, m.inertia)?;
    let report = crate::theory::TheoryReport::compute(&params)?;
    if args.json {
        output::print(&format!("{}\n", to_json(&report)?))
    } else {
        output::print(&report.to_table())
    }
}

/// Renders `scenes` into `out` ([`front::render::into_folder`]) with a
/// progress bar, then says what it wrote.
fn render_into(
    scenes: &[Scene],
    out: &OutArgs,
    movie: &MovieOptions,
    outputs: &Outputs,
    words: Words,
    index: bool,
) -> Result<()> {
    let (out, verbose) = (out.out.as_path(), out.verbose);
    let start = Instant::now();
    // One movie: a bar over its frames; several scenes: over the scenes.
    let one_movie = scenes.len() == 1 && scenes[0].kind() == Kind::Movie;
    let bar = if one_movie {
        progress_bar(movie.frames as u64, &format!("movie {}", scenes[0].name))
    } else {
        progress_bar(scenes.len() as u64, "rendering")
    };
    let progress = front::render::Progress {
        frame: &|| {
            if one_movie {
                bar.inc(1);
            }
        },
        scene: &|s| {
            if !one_movie {
                bar.set_message(format!("{} {}", s.kind().name(), s.name));
                bar.inc(1);
            }
        },
        hint: &|e, s| with_divergence_hint(e, s, words),
    };
    let files = front::render::into_folder(scenes, out, movie, outputs, index, &progress);
    bar.finish_and_clear();
    let files = files?;
    if verbose {
        let list: String = files
            .iter()
            .map(|f| format!("{}\n", out.join(f).display()))
            .collect();
        output::eprint(&list)?;
    }
    output::eprint(&format!(
        "ladder: {} into {} in {:.2} s\n",
        front::render::summary(scenes, &files, index),
        out.display(),
        start.elapsed().as_secs_f64()
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_numbers_round_down_to_two_digits() {
        assert_eq!(short(0.7512), "0.75");
        assert_eq!(short(0.0056789), "0.0056");
        assert_eq!(short(12.9), "12");
    }
}
