//! A run's numbers as numpy arrays, handed over without a copy: each
//! array is one `Vec<f64>` built once (a pass over the samples that
//! gathers one quantity in sample-major order) and given to numpy by
//! `PyArray::from_vec`, which takes ownership of the vector's buffer;
//! `reshape` to samples × N is a view of it.

use jacobs_ladder::output::data::MadeBy;
use jacobs_ladder::scene::Scene;
use jacobs_ladder::scenes::RunData;
use jacobs_ladder::scenes::experiments;
use jacobs_ladder::scenes::run::SceneRun;
use jacobs_ladder::{Error, Result};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Bytes of rows freed between two [`give_back`]s.
const RETURN_EVERY: usize = 32 << 20;

/// Gives the memory of the rows freed so far back to the system. glibc
/// keeps freed blocks below its mmap threshold in its arenas, and raises
/// that threshold (up to 32 MB) each time a larger mapped block is freed:
/// once `auto`'s two runs have freed their buffers, a run's rows come from
/// the arenas, and without this their memory stayed resident beside the
/// columns made from them (Python's peak was twice the CLI's).
/// `malloc_trim` returns the free pages of every arena (madvise); the
/// numbers are untouched.
fn give_back() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: malloc_trim only releases free memory of glibc's arenas.
    unsafe {
        libc::malloc_trim(0);
    }
}

/// The failed run of columns that cannot be allocated.
fn out_of_memory(samples: usize, n: usize) -> Error {
    Error::failed(format!(
        "not enough memory to hand the run to numpy: {samples} samples × N = {n}; hint: keep \
         fewer samples (a larger sample_every or fewer samples), fewer blocks, or give the \
         process more memory"
    ))
}

/// A run's numbers, made without the GIL.
pub struct RunArrays {
    /// Blocks N.
    n: usize,
    /// (name, values, per block): per-block arrays are samples × N.
    columns: Vec<(&'static str, Vec<f64>, bool)>,
    /// The run's record as JSON: what a data file says of the run
    /// (`RunData` without its frames): the integrator report, arrival
    /// times, speed, and whatever else the library records.
    record: String,
}

/// The arrays of `run` of `scene`.
pub fn arrays(scene: &Scene, mut run: SceneRun) -> Result<RunArrays> {
    // The energies at each sample (`Trajectory::energies`), before the
    // states are handed over; `dissipated` is NaN where the run did not
    // record it (`RunOptions::dissipation`).
    let ladder = scene.scenario()?.ladder;
    let energies = run.trajectory.energies(&ladder);
    let samples = run.trajectory.times.len();
    // Only a run that recorded it has `dissipated` (Python's `Run` runs
    // the scene again with it when it is asked for).
    let dissipated = (energies.dissipated.len() == samples).then_some(energies.dissipated);
    // The experiment figures' fit over the chain's lower half, and the
    // apparatus' units (τ in s, a block per τ in cm/s), where it has one.
    let bulk = experiments::bulk_speed(&run.trajectory.arrival_times);
    let units = scene
        .apparatus
        .as_ref()
        .and_then(|a| Some((a.conversion.as_ref()?, a.b)))
        .map(|(c, pitch_cm)| (c.tau_s, c.cm_per_s, pitch_cm));
    let traj = &mut run.trajectory;
    let n = traj.final_state.q.len() / 3;
    let times = std::mem::take(&mut traj.times);
    let states = std::mem::take(&mut traj.states);
    let velocities = std::mem::take(&mut traj.velocities);
    let kink = std::mem::take(&mut traj.kink_position);
    // Layout of q and v: [X, Y, θ] per block (`model::ladder`). Each
    // sample's row is freed as soon as it is split, so the peak is the
    // trajectory's size once, not twice: the columns are
    // reserved (address space, no page touched) and fill as the rows go.
    let split = |rows: Vec<Vec<f64>>| -> Result<[Vec<f64>; 3]> {
        let mut out: [Vec<f64>; 3] = Default::default();
        for column in &mut out {
            column
                .try_reserve_exact(rows.len().saturating_mul(n))
                .map_err(|_| out_of_memory(rows.len(), n))?;
        }
        let mut freed = 0usize;
        for row in rows {
            for (k, column) in out.iter_mut().enumerate() {
                column.extend((0..n).map(|i| row[3 * i + k]));
            }
            freed += std::mem::size_of_val(row.as_slice());
            drop(row);
            if freed >= RETURN_EVERY {
                give_back();
                freed = 0;
            }
        }
        // (A small run's rows are not worth the walk over the arenas.)
        if freed >= 1 << 20 {
            give_back();
        }
        Ok(out)
    };
    let [x, y, theta] = split(states)?;
    let [vx, vy, omega] = split(velocities)?;
    let arrival: Vec<f64> = traj
        .arrival_times
        .iter()
        .map(|t| t.unwrap_or(f64::NAN))
        .collect();
    let mut columns = vec![
        ("t", times, false),
        ("x", x, true),
        ("y", y, true),
        ("theta", theta, true),
        ("vx", vx, true),
        ("vy", vy, true),
        ("omega", omega, true),
        ("kink_position", kink, false),
        ("arrival_times", arrival, false),
        ("final_theta_deg", traj.final_theta_deg(), false),
        ("kinetic", energies.kinetic, false),
        ("elastic", energies.elastic, false),
        ("gravitational", energies.gravitational, false),
    ];
    if let Some(d) = dissipated {
        columns.push(("dissipated", d, false));
    }
    if let Some((tau_s, _, _)) = units {
        let seconds = |name: &str| -> Vec<f64> {
            let (_, v, _) = columns.iter().find(|c| c.0 == name).expect("made above");
            v.iter().map(|t| t * tau_s).collect()
        };
        let (t_s, arrivals_s) = (seconds("t"), seconds("arrival_times"));
        columns.push(("t_s", t_s, false));
        columns.push(("arrival_times_s", arrivals_s, false));
    }
    let mut data = RunData::from_run(scene, &run);
    if let Some((tau_s, _, pitch_cm)) = units {
        // The experiment figures' numbers: arrivals in s, the bulk fit in
        // cm/s with its line (the data file's `apparatus`).
        let arrivals_s: Vec<Option<f64>> = data
            .arrival_times
            .iter()
            .map(|t| t.map(|t| t * tau_s))
            .collect();
        data.apparatus = Some(experiments::apparatus_numbers(&arrivals_s, tau_s, pitch_cm));
    }
    let mut record = serde_json::to_value(data)
        .map_err(|e| Error::failed(format!("cannot encode the run: {e}")))?;
    let encode = |e: serde_json::Error| Error::failed(format!("cannot encode the run: {e}"));
    // Provenance, as every data file carries it: the program, its version
    // and commit, and the scene run (no command line: Python has none).
    let made_by = serde_json::to_value(MadeBy::new(&[])).map_err(encode)?;
    let scene_json = serde_json::to_value(scene).map_err(encode)?;
    if let Some(m) = record.as_object_mut() {
        m.remove("frames");
        for (k, v) in made_by.as_object().into_iter().flatten() {
            if k != "command_line" {
                m.entry(k.clone()).or_insert_with(|| v.clone());
            }
        }
        m.entry("scene").or_insert(scene_json);
        // The wave block 1's first flip launches: the library's rule
        // (`WaveKind::launched`), for the repr.
        let launched = jacobs_ladder::sim::waves::WaveKind::launched(scene.model.alpha);
        m.entry("launched").or_insert(launched.name().into());
        let speed = m.get("speed").and_then(serde_json::Value::as_f64);
        m.insert("bulk_speed".into(), bulk.into());
        if let Some((tau_s, cm_per_s, _)) = units {
            m.insert("tau_s".into(), tau_s.into());
            m.insert("cm_per_s".into(), cm_per_s.into());
            m.insert("speed_cm_s".into(), speed.map(|v| v * cm_per_s).into());
        }
    }
    Ok(RunArrays {
        n,
        columns,
        record: record.to_string(),
    })
}

impl RunArrays {
    /// A dict of numpy arrays, and `record` (JSON text).
    pub fn into_dict(self, py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
        let d = PyDict::new(py);
        for (name, values, per_block) in self.columns {
            let rows = values.len() / self.n.max(1);
            let a = PyArray1::from_vec(py, values);
            if per_block {
                d.set_item(name, a.reshape([rows, self.n])?)?;
            } else {
                d.set_item(name, a)?;
            }
        }
        d.set_item("record", self.record)?;
        Ok(d)
    }
}
