//! `ladder simulate`: one run from the flags, its table or JSON, and its
//! CSV and NPZ.

use crate::cli::commands::Call;
use crate::cli::convert;
use crate::cli::hints::{Words, with_divergence_hint};
use crate::cli::progress::time_bar;
use crate::cli::*;
use crate::error::{Error, Result};
use crate::output;
use crate::scene::{self, Scene};
use crate::scenes;
use crate::sim;
use serde::Serialize;
use std::time::Instant;

/// `simulate --json` (README.md), with what reruns it:
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
    /// The wave speed c, blocks per τ (`sim::speed::wave_speed`: the
    /// one definition, also a run's, figure S6's and a sweep's); `null`
    /// when too few blocks flipped in order.
    pub speed: Option<f64>,
    /// Of blocks 1..N − 1, how many flipped (block N, free, apart: as a
    /// sweep counts).
    pub blocks_flipped: usize,
    pub final_theta_deg: Vec<f64>,
    /// Every wave of the run and block N's fate (docs/sweeps.md).
    pub waves: crate::sim::waves::Waves,
    /// A scene with "stiff" links: how far the wave moves with 2k
    /// (`scenes::stiff`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stiff_links: Option<scenes::stiff::StiffCheck>,
}

pub(crate) fn simulate(args: &SimulateArgs, call: &Call<'_>) -> Result<()> {
    let command_line = call.command_line;
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
    let scene = call.capped_one(convert::scene_from_flags(
        base,
        &args.model,
        &args.drive,
        &run,
    )?);
    let samples = csv_samples(args, &scene)?;
    let stepping = args.kernel.stepping()?;
    let sidecar = args.csv.as_deref().map(csv_sidecar);
    let targets: Vec<(std::path::PathBuf, String)> = [
        (&args.csv, "--csv"),
        (&sidecar, "--csv's JSON sidecar"),
        (&args.npz, "--npz"),
    ]
    .into_iter()
    .filter_map(|(p, flag)| Some((p.clone()?, flag.to_string())))
    .collect();
    output::check_distinct(&targets, "give each its own file")?;
    for (path, _) in &targets {
        output::check_writable(path)?;
    }
    let start = Instant::now();
    let bar = time_bar(scene.run.t_end);
    let progress = |t: f64| bar.set_position(bar.position().max(t as u64));
    let options = crate::sim::RunOptions::default()
        .stepping(stepping)
        .limits(scene.limits)
        .progress(&progress)
        // The npz's `dissipated_energy` (the trajectory is the same bits).
        .dissipation(args.npz.is_some());
    let result = scenes::run::simulate_with(&scene, &samples, &options);
    bar.finish_and_clear();
    let result = result.map_err(|e| with_divergence_hint(e, &scene, Words::Flags))?;
    let wall_seconds = start.elapsed().as_secs_f64();
    let traj = &result.trajectory;
    if let Some(path) = &args.csv {
        output::write_atomic_with(path, |f| write_csv(traj, &mut std::io::BufWriter::new(f)))?;
    }
    // The parameters run: the apparatus's, converted, where it has one.
    let params = scene.scenario()?.ladder.params;
    // "Stiff" links shown to be stiff, as `auto` shows its step.
    let stiff_options = crate::sim::RunOptions::default()
        .stepping(stepping)
        .limits(scene.limits);
    let stiff_links = scenes::stiff::check(&scene, &result, &stiff_options)?;
    if let Some(check) = &stiff_links {
        output::eprint(&format!("ladder: {}\n", check.describe()))?;
    }
    if let Some(path) = &args.npz {
        let ladder = crate::model::Ladder::new(params);
        let metadata = scenes::data::NpzMetadata {
            made_by: scenes::data::MadeBy::new(command_line),
            scene: &scene,
        };
        output::write_atomic_with(path, |f| {
            scenes::data::write_npz(traj, &ladder, &metadata, std::io::BufWriter::new(f)).map(drop)
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
        speed: crate::sim::speed::wave_speed(&traj.arrival_times),
        blocks_flipped: crate::sweep::outcome::blocks_flipped(&traj.arrival_times),
        final_theta_deg: traj.final_theta_deg(),
        waves: traj.waves.clone(),
        stiff_links,
    };
    if let Some(path) = &sidecar {
        // The CSV's provenance (docs/formats.md): the report without its
        // wall time, so that the file is the same on every run.
        let mut value = serde_json::to_value(&report)
            .map_err(|e| Error::failed(format!("cannot encode the CSV's sidecar: {e}")))?;
        if let Some(m) = value.as_object_mut() {
            m.remove("wall_seconds");
        }
        output::write_atomic_with(path, |f| {
            scenes::data::write_json(&mut std::io::BufWriter::new(f), &value)
        })?;
    }
    if args.json {
        output::print(&format!("{}\n", to_json(&report)?))
    } else {
        output::print(&simulate_table(&report))
    }
}

/// The JSON sidecar of `simulate --csv FILE`: `FILE.json` (`run.csv` →
/// `run.csv.json`), the CSV's provenance (the scene, the program, its
/// version and commit, and what the run did), so that the CSV itself
/// stays plain (docs/formats.md).
pub fn csv_sidecar(csv: &std::path::Path) -> std::path::PathBuf {
    let mut name = csv.as_os_str().to_owned();
    name.push(".json");
    std::path::PathBuf::from(name)
}

/// The CSV's and npz's sample times, 0, every, 2 every, ... up to
/// --t-end, within the cap on samples × N (checked before any is made).
pub(crate) fn csv_samples(args: &SimulateArgs, scene: &Scene) -> Result<Vec<f64>> {
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
    scene.limits.check_samples(count, scene.model.n)?;
    let mut times = Vec::new();
    times
        .try_reserve_exact(count as usize)
        .map_err(|_| Error::failed("not enough memory for the CSV's sample times"))?;
    times.extend((0..count as usize).map(|k| k as f64 * every));
    Ok(times)
}

pub(crate) fn simulate_table(r: &SimulateReport) -> String {
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
pub(crate) fn write_csv(
    traj: &sim::Trajectory,
    w: &mut impl std::io::Write,
) -> std::io::Result<()> {
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
