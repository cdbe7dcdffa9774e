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

/// `simulate --json` (README.md): what reruns it (the program, its
/// build, the command line and the scene), then the run in the one shape
/// every run is reported in ([`scenes::data::RunData`]: a data file's
/// runs and Python's `Run.record` alike), then the wall time.
#[derive(Serialize, Debug)]
pub struct SimulateReport<'a> {
    #[serde(flatten)]
    pub made_by: scenes::data::MadeBy<'a>,
    /// The scene run, every value (a data scene: `ladder scene` writes it
    /// as TOML, `ladder render` reruns it).
    pub scene: &'a Scene,
    /// The run: the model, drive and window it used, the integrator, the
    /// arrival times, speed, final angles and waves (and in seconds and
    /// cm/s where an apparatus gives units).
    #[serde(flatten)]
    pub run: scenes::data::RunData,
    pub wall_seconds: f64,
    /// A scene with "stiff" links: how far the wave moves with 2k
    /// (`scenes::stiff`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stiff_links: Option<scenes::stiff::StiffCheck>,
}

pub(crate) fn simulate(args: &SimulateArgs, call: &Call<'_>) -> Result<()> {
    let command_line = call.command_line;
    let scene = call.capped_one(simulate_scene(args)?);
    let samples = csv_samples(args, &scene)?;
    // The run with its "stiff" links' second run, one cost, before the
    // first (`scenes::cost`).
    scenes::cost::check_with_stiff(&scene, samples.len())?;
    let stepping = args.kernel.stepping()?;
    let sidecar = check_targets(args)?;
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
        run: scenes::data::RunData::summary(&scene, &result),
        wall_seconds,
        stiff_links,
    };
    if let Some(path) = &sidecar {
        write_sidecar(path, &report)?;
    }
    if args.json {
        output::print(&format!("{}\n", to_json(&report)?))
    } else {
        output::print(&simulate_table(&report, &params))
    }
}

/// The files `simulate` writes (--csv, its JSON sidecar, --npz), checked
/// distinct and writable before the run; the sidecar's path.
fn check_targets(args: &SimulateArgs) -> Result<Option<std::path::PathBuf>> {
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
    Ok(sidecar)
}

/// The CSV's provenance (docs/formats.md): the report without its wall
/// time, so that the file is the same on every run.
fn write_sidecar(path: &std::path::Path, report: &SimulateReport<'_>) -> Result<()> {
    let mut value = serde_json::to_value(report)
        .map_err(|e| Error::failed(format!("cannot encode the CSV's sidecar: {e}")))?;
    if let Some(m) = value.as_object_mut() {
        m.remove("wall_seconds");
    }
    output::write_atomic_with(path, |f| {
        scenes::data::write_json(&mut std::io::BufWriter::new(f), &value)
    })
}

/// The scene of `ladder simulate`: a data scene with `simulate`'s run
/// ([`simulate_run`]: the paper's window and integrator) under the flags;
/// the window stays a number (a data scene's window follows no changed
/// N, `Scene::window_following`), and is an apparatus' `duration` unless
/// `--t-end` gives it.
fn simulate_scene(args: &SimulateArgs) -> Result<Scene> {
    let defaults = simulate_run();
    let base = Scene {
        output: scene::OutputSpec::Data,
        run: defaults,
        ..Scene::default()
    };
    let run = args.run.clone();
    if run.t_end == Some(scene::AUTO_T_END) {
        return Err(Error::bad_input(
            "--t-end: simulate runs to a time given in tau; auto (until every wave has a fate) \
             is for movie and figure",
        ));
    }
    let method = match &run.integrator {
        Some(name) => convert::parse_method(name)?,
        None => defaults.integrator,
    };
    if run.dt.is_some() && method == scene::Method::Auto {
        return Err(Error::bad_input(
            "--dt: the auto integrator picks its own step; name an integrator to set --dt",
        ));
    }
    convert::scene_from_flags(base, &args.model, &args.drive, &run)
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
    let count = (scene.run.t_end / every).floor() + 1.0;
    scene.limits.check_samples(count, scene.model.n)?;
    let mut times = Vec::new();
    times
        .try_reserve_exact(count as usize)
        .map_err(|_| Error::failed("not enough memory for the CSV's sample times"))?;
    times.extend((0..count as usize).map(|k| k as f64 * every));
    Ok(times)
}

/// The table of `simulate`: the parameters run (`params`, the model's
/// derived a) and the integrator, then each block's arrival time and
/// final angle (and the arrival in seconds, and the speed in cm/s, where
/// an apparatus gives units).
pub(crate) fn simulate_table(r: &SimulateReport, params: &crate::model::Params) -> String {
    let run = &r.run;
    let i = &run.integrator;
    let step = i
        .rtol
        .map_or(format!("dt = {}", i.dt), |x| format!("rtol = {x:e}"));
    let chosen = match (i.requested.as_str(), i.arrival_error) {
        ("auto", Some(e)) => format!(" (chosen by auto; arrival times within about {e:.2e} τ)"),
        _ => String::new(),
    };
    let mut s = format!(
        "alpha = {}°, N = {}, b = {}, a = {:.6}; {} with {step}{chosen}; {} steps, {} force evaluations, {:.3} s\n",
        run.model.alpha,
        run.model.n,
        run.model.b,
        params.a(),
        i.name,
        i.steps,
        i.force_evals,
        r.wall_seconds
    );
    match &run.units {
        None => {
            s.push_str("block  arrival t/τ   final θ (deg)\n");
            for (k, (t, th)) in run
                .arrival_times
                .iter()
                .zip(&run.final_theta_deg)
                .enumerate()
            {
                let t = t.map_or("never".to_string(), |t| format!("{t:.2}"));
                s.push_str(&format!("{:>5}  {:>11}   {:>13.3}\n", k + 1, t, th));
            }
        }
        Some(u) => s.push_str(&units_table(run, u)),
    }
    s
}

/// The table of a run with an apparatus: τ and the speed in its units,
/// and each block's arrival in τ and in seconds.
fn units_table(run: &scenes::data::RunData, u: &scenes::data::Units) -> String {
    let speed = match (run.speed, u.speed_cm_s) {
        (Some(c), Some(cm)) => format!("{c:.4} blocks/τ = {cm:.2} cm/s"),
        _ => "none (too few blocks flipped in order)".into(),
    };
    let mut s = format!(
        "τ = {:.4} s; run to {} τ = {:.2} s; wave speed {speed}\n",
        u.tau_s, run.t_end, u.t_end_s
    );
    s.push_str("block  arrival t/τ   arrival t (s)   final θ (deg)\n");
    for (k, ((t, ts), th)) in run
        .arrival_times
        .iter()
        .zip(&u.arrival_times_s)
        .zip(&run.final_theta_deg)
        .enumerate()
    {
        let t = t.map_or("never".to_string(), |t| format!("{t:.2}"));
        let ts = ts.map_or("never".to_string(), |t| format!("{t:.3}"));
        s.push_str(&format!(
            "{:>5}  {:>11}   {:>13}   {:>13.3}\n",
            k + 1,
            t,
            ts,
            th
        ));
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
