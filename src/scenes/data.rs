//! The data file beside every output (`<output>.json`, docs/scenes.md):
//! what made it and the numbers its picture shows, one [`RunData`] per
//! simulation drawn.

use super::Outputs;
use super::options::MovieOptions;
use super::run::{IntegratorReport, SceneRun};
use crate::encode::Format;
use crate::encode::npz::{ArrayWriter, NpzWriter};
use crate::model::Ladder;
use crate::render::StyleSpec;
use crate::scene::{DriveSpec, Model, OutputSpec, Scene};
use crate::sim;
use serde::ser::SerializeStruct;
use serde::{Serialize, Serializer};
use std::io::{self, Seek, Write};
use std::sync::Arc;

pub use crate::output::data::{BYTES_PER_VALUE, MadeBy, write_json};

/// `<output>.json`: the scene with every parameter, the program that made
/// the output, and the numbers the picture shows (docs/scenes.md); with
/// `settings` and the scene, what reruns it.
#[derive(Debug, Clone, Serialize)]
pub struct DataFile<'a> {
    #[serde(flatten)]
    pub made_by: MadeBy<'a>,
    /// How the files were drawn beyond the scene.
    pub settings: Settings,
    pub title: String,
    pub parameters: String,
    pub fidelity: &'static str,
    pub files: Vec<String>,
    pub scene: &'a Scene,
    /// One entry per simulation drawn (empty for the theory figures).
    pub runs: Vec<RunData>,
    /// The numbers a theory figure plots (its curves and points,
    /// `scenes::theory::Drawn`); absent for every other output.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub drawn: Option<serde_json::Value>,
}

/// What an output was drawn with besides its scene: the scene rendered
/// again with these settings gives the same numbers and files.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Settings {
    /// A movie's frames, size, rate, formats and MP4 quality.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub movie: Option<MovieSettings>,
    /// A figure's formats and PNG scale.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub figure: Option<FigureSettings>,
    /// The style in force: the command's style flags over the scene's
    /// `[style]` (empty: the screen style).
    pub style: StyleSpec,
}

/// The settings of a movie (`--frames`, `--size`, `--fps`, `--format`,
/// `--quality`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MovieSettings {
    pub frames: usize,
    pub width: u32,
    pub height: u32,
    pub fps: f64,
    pub formats: Vec<Format>,
    pub mp4_quality: &'static str,
}

/// The settings of a figure (`--format`, `--scale`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FigureSettings {
    pub formats: Vec<Format>,
    pub scale: f32,
}

impl Settings {
    /// The settings `scene` is drawn with under `movie` and `outputs`.
    pub fn new(scene: &Scene, movie: &MovieOptions, outputs: &Outputs) -> Self {
        let is_movie = matches!(scene.output, OutputSpec::Movie { .. });
        let is_figure = !is_movie && !matches!(scene.output, OutputSpec::Data);
        Self {
            movie: is_movie.then(|| MovieSettings {
                frames: movie.frames,
                width: movie.width,
                height: movie.height,
                fps: movie.fps,
                formats: outputs.movies.as_slice().to_vec(),
                mp4_quality: outputs.mp4_quality.name(),
            }),
            figure: is_figure.then(|| FigureSettings {
                formats: outputs.figures.as_slice().to_vec(),
                scale: outputs.scale,
            }),
            style: outputs.style.over(scene.style),
        }
    }
}

/// What the program says of one run, in a data file (one per simulation
/// drawn), in `ladder simulate --json` and in Python's `Run.record`: the
/// model, drive and window the run used (an apparatus's converted values,
/// `Scene::with_conversion`), the integrator and accuracy, the arrival
/// times, the final angles, the same in seconds and cm/s where an
/// apparatus gives units, and, at each drawn time, θ_n (degrees, wrapped
/// to (−180°, 180°]) and the centres.
#[derive(Debug, Clone, Serialize)]
pub struct RunData {
    pub label: String,
    /// The model run.
    pub model: Model,
    /// The drive of block 1 run (a motor's flip where the apparatus has
    /// one).
    pub drive: DriveSpec,
    /// The window run, τ.
    pub t_end: f64,
    pub integrator: IntegratorReport,
    pub arrival_times: Vec<Option<f64>>,
    /// The wave speed c in blocks per τ (`sim::speed::wave_speed`:
    /// least squares over blocks 3..N−1, the one definition the program
    /// reports); `None` when too few flipped in order.
    pub speed: Option<f64>,
    /// Of blocks 1..N − 1, how many flipped by the end of the run
    /// (`sweep::outcome::blocks_flipped`: block N, free, is left out, as
    /// in a sweep's CSV).
    pub blocks_flipped: usize,
    pub final_theta_deg: Vec<f64>,
    /// Every wave of the run and block N's fate (docs/sweeps.md).
    pub waves: sim::waves::Waves,
    /// Every impact between two blocks, in time order (`sim::impacts`,
    /// docs/formats.md "Impacts"): for blocks that may touch (the toy as
    /// built with contact); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub impacts: Option<Vec<sim::impacts::Impact>>,
    /// The run's energy budget (`sim::budget`, docs/formats.md "The
    /// energy budget"): the work W done through block 1, the energy D
    /// dissipated, the change ΔE and the residual ΔE − (W − D), in k s²,
    /// accumulated inside the integrator; for the toy as built, absent
    /// otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub budget: Option<sim::budget::Budget>,
    /// Times in seconds and speeds in cm/s, where an apparatus gives the
    /// units (docs/experiments.md); absent in the model's units alone.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub units: Option<Units>,
    /// The state at each drawn time, one [`FrameData`] each.
    pub frames: Frames,
    /// The kymograph drawn from this run (a movie's, a kymograph
    /// figure's), as numbers; absent where none is drawn.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub kymograph: Option<Kymograph>,
    /// The energies at the run's samples (the energy view's numbers,
    /// `scenes::energy`); absent where none is drawn.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energies: Option<EnergyData>,
    /// An apparatus run's numbers in the apparatus' units, as the
    /// experiment figures draw them (docs/experiments.md); absent for a
    /// run in the model's units only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub apparatus: Option<ApparatusNumbers>,
}

/// An apparatus run in seconds and centimetres: what the experiment
/// figures plot (docs/experiments.md, "Built-in scenes and figures").
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ApparatusNumbers {
    /// The unit of time τ (s) and the block pitch b (cm).
    pub tau_s: f64,
    pub pitch_cm: f64,
    /// Each block's arrival time t_n (s), and t_n − t_1: the time since
    /// block 1 flipped, the positions figure's time axis.
    pub arrival_times_s: Vec<Option<f64>>,
    pub since_block_1_s: Vec<Option<f64>>,
    /// The bulk speed (cm/s) and its fitted line, where the lower half
    /// of the chain flipped down it one block after another.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bulk: Option<BulkFit>,
}

/// The least-squares line through the lower half of the chain's
/// arrivals: position (n − 1) b = centroid_cm + speed_cm_s (t − t_1 −
/// centroid_s), fitted over blocks `blocks` (one-based, inclusive).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BulkFit {
    pub speed_cm_s: f64,
    pub blocks: [usize; 2],
    pub centroid_s: f64,
    pub centroid_cm: f64,
}

/// The state drawn at one time.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrameData {
    pub t: f64,
    pub theta_deg: Vec<f64>,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
}

/// The sampled states of a run (3 numbers a block: X, Y, θ), shared by
/// its frames and its kymograph and turned into numbers only as the data
/// file is written: the data file keeps no second copy of them
/// (docs/limits.md).
#[derive(Debug, Default)]
struct SampleRows {
    times: Vec<f64>,
    states: Vec<Vec<f64>>,
}

/// The frames of a run's data: serialized as a list of [`FrameData`],
/// made one number at a time.
#[derive(Debug, Clone, Default)]
pub struct Frames(Arc<SampleRows>);

impl Frames {
    /// How many frames.
    pub fn len(&self) -> usize {
        self.0.times.len()
    }

    pub fn is_empty(&self) -> bool {
        self.0.times.is_empty()
    }

    /// Each sample's time and state (3 numbers a block), as simulated.
    pub fn rows(&self) -> impl Iterator<Item = (f64, &[f64])> + '_ {
        let rows = &self.0;
        rows.times
            .iter()
            .copied()
            .zip(rows.states.iter().map(Vec::as_slice))
    }

    /// Frame `k`, as the data file writes it.
    pub fn get(&self, k: usize) -> Option<FrameData> {
        let q = self.0.states.get(k)?;
        Some(FrameData {
            t: self.0.times[k],
            theta_deg: sim::observables::angles_deg(q),
            x: Column::new(q, 0).values().collect(),
            y: Column::new(q, 1).values().collect(),
        })
    }
}

/// One coordinate of every block of a state (0: X, 1: Y, 2: θ in degrees
/// wrapped as [`sim::observables::angles_deg`], 3: sin θ), serialized as
/// a list without being collected.
struct Column<'a> {
    q: &'a [f64],
    k: usize,
}

impl<'a> Column<'a> {
    fn new(q: &'a [f64], k: usize) -> Self {
        Self { q, k }
    }

    fn values(&self) -> impl Iterator<Item = f64> + '_ {
        self.q.chunks_exact(3).map(|b| match self.k {
            2 => sim::observables::wrap_deg(b[2].to_degrees()),
            3 => b[2].sin(),
            k => b[k],
        })
    }
}

impl Serialize for Column<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.values())
    }
}

impl Serialize for Frames {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        struct Frame<'a>(f64, &'a [f64]);
        impl Serialize for Frame<'_> {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                let mut f = s.serialize_struct("FrameData", 4)?;
                f.serialize_field("t", &self.0)?;
                f.serialize_field("theta_deg", &Column::new(self.1, 2))?;
                f.serialize_field("x", &Column::new(self.1, 0))?;
                f.serialize_field("y", &Column::new(self.1, 1))?;
                f.end()
            }
        }
        let rows = &self.0;
        s.collect_seq(
            rows.times
                .iter()
                .zip(&rows.states)
                .map(|(&t, q)| Frame(t, q)),
        )
    }
}

/// A kymograph's matrix, written as `{"times": [...],
/// "sin_theta": [[...], ...]}`: `sin_theta[k][i]` is sin θ of block i + 1
/// at `times[k]`, the colour of the kymograph's row k and column i + 1
/// (the polarisation, docs/model.md).
#[derive(Debug, Clone, Default)]
pub struct Kymograph(Arc<SampleRows>);

impl Kymograph {
    /// Row `k`: sin θ of every block at the kymograph's `k`-th time.
    pub fn row(&self, k: usize) -> Option<Vec<f64>> {
        let q = self.0.states.get(k)?;
        Some(Column::new(q, 3).values().collect())
    }
}

impl Serialize for Kymograph {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let rows = &self.0;
        let mut k = s.serialize_struct("Kymograph", 2)?;
        k.serialize_field("times", &rows.times)?;
        let matrix: Vec<Column<'_>> = rows.states.iter().map(|q| Column::new(q, 3)).collect();
        k.serialize_field("sin_theta", &matrix)?;
        k.end()
    }
}

impl RunData {
    pub fn from_run(scene: &Scene, run: &SceneRun) -> Self {
        Self::new("", scene, run)
    }

    /// The data of `run` (its samples copied: the run is drawn after).
    pub(super) fn new(label: &str, scene: &Scene, run: &SceneRun) -> Self {
        let traj = &run.trajectory;
        let rows = SampleRows {
            times: traj.times.clone(),
            states: traj.states.clone(),
        };
        Self::with_rows(label, scene, run, rows)
    }

    /// The data of a run drawn as a kymograph, which it consumes: its
    /// samples move into the data file's frames and matrix, uncopied.
    pub(super) fn with_kymograph(scene: &Scene, mut run: SceneRun) -> Self {
        let mut data = Self::taking_samples("", scene, &mut run);
        data.kymograph = Some(Kymograph(data.frames.0.clone()));
        data
    }

    /// The data of `run`, its samples moved (uncopied) into the data's
    /// frames, from which the run is then drawn ([`Frames::rows`]: a
    /// filmstrip's snapshots); its velocities, which the data file does
    /// not write, are freed.
    pub(super) fn taking_samples(label: &str, scene: &Scene, run: &mut SceneRun) -> Self {
        let traj = &mut run.trajectory;
        let rows = SampleRows {
            times: std::mem::take(&mut traj.times),
            states: std::mem::take(&mut traj.states),
        };
        traj.velocities = Vec::new();
        Self::with_rows(label, scene, run, rows)
    }

    /// The run ended at `t` (before its window, where a stop rule ended
    /// it): its `t_end`, in τ and in seconds.
    pub fn ended_at(&mut self, t: f64) {
        if let Some(u) = &mut self.units {
            u.t_end_s = t * u.tau_s;
        }
        self.t_end = t;
    }

    /// The record of `run` without its samples (`ladder simulate`,
    /// Python's `Run.record`): `frames` is empty.
    pub fn summary(scene: &Scene, run: &SceneRun) -> Self {
        Self::with_rows("", scene, run, SampleRows::default())
    }

    fn with_rows(label: &str, scene: &Scene, run: &SceneRun, rows: SampleRows) -> Self {
        let traj = &run.trajectory;
        let speed = crate::sim::speed::wave_speed(&traj.arrival_times);
        Self {
            label: label.to_string(),
            model: scene.model,
            drive: scene.drive.clone(),
            t_end: scene.run.t_end,
            integrator: run.integrator.clone(),
            arrival_times: traj.arrival_times.clone(),
            speed,
            blocks_flipped: crate::sweep::outcome::blocks_flipped(&traj.arrival_times),
            final_theta_deg: traj.final_theta_deg(),
            waves: traj.waves.clone(),
            impacts: traj.impacts.clone(),
            budget: traj.budget,
            units: Units::of(scene, &traj.arrival_times, speed)
                .map(|u| u.with_impacts(scene, traj.impacts.as_deref())),
            frames: Frames(Arc::new(rows)),
            kymograph: None,
            energies: None,
            apparatus: None,
        }
    }
}

/// A run's times in seconds and its speed in cm/s, beside the model's τ
/// and blocks per τ, where the scene's apparatus gives the units
/// (docs/experiments.md: τ = √(m/k) in s; one block per τ is b/τ in
/// cm/s).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Units {
    /// τ in seconds.
    pub tau_s: f64,
    /// One block per τ in cm/s.
    pub cm_per_s: f64,
    /// The window, s.
    pub t_end_s: f64,
    /// The first flip's drive time T_d, s; absent without a flip.
    pub drive_time_s: Option<f64>,
    /// The first wave's arrival times, s.
    pub arrival_times_s: Vec<Option<f64>>,
    /// The wave speed c, cm/s.
    pub speed_cm_s: Option<f64>,
    /// Each impact's time (s) and normal speed (cm/s), in the order of
    /// the run's `impacts`; absent where the blocks cannot touch.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub impact_times_s: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub impact_speeds_cm_s: Option<Vec<f64>>,
}

impl Units {
    /// The units of `scene`'s converted apparatus, if it has one.
    pub fn of(scene: &Scene, arrival_times: &[Option<f64>], speed: Option<f64>) -> Option<Self> {
        let c = scene.apparatus.as_ref()?.conversion.as_ref()?;
        Some(Self {
            tau_s: c.tau_s,
            cm_per_s: c.cm_per_s,
            t_end_s: scene.run.t_end * c.tau_s,
            drive_time_s: scene.drive.flips.first().map(|f| f.duration * c.tau_s),
            arrival_times_s: arrival_times
                .iter()
                .map(|t| t.map(|t| t * c.tau_s))
                .collect(),
            speed_cm_s: speed.map(|v| v * c.cm_per_s),
            impact_times_s: None,
            impact_speeds_cm_s: None,
        })
    }

    /// These units with the run's `impacts` in seconds and cm/s (a speed
    /// of one s per τ is s/τ = `cm_per_s` / b in cm/s).
    fn with_impacts(self, scene: &Scene, impacts: Option<&[sim::impacts::Impact]>) -> Self {
        let (Some(imp), Some(c)) = (
            impacts,
            scene.apparatus.as_ref().and_then(|a| a.conversion.as_ref()),
        ) else {
            return self;
        };
        Self {
            impact_times_s: Some(imp.iter().map(|i| i.t * c.tau_s).collect()),
            impact_speeds_cm_s: Some(imp.iter().map(|i| i.speed * c.cm_per_s / c.b).collect()),
            ..self
        }
    }
}

/// Samples of the energy view (`scenes::energy`) over its window.
pub const ENERGY_SAMPLES: usize = 801;

/// The energies of a run at its samples (the data file's `energies`),
/// in units of k s², each its value (not its change).
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct EnergyData {
    pub times: Vec<f64>,
    pub kinetic: Vec<f64>,
    pub elastic: Vec<f64>,
    pub gravitational: Vec<f64>,
    /// Dissipated from t = 0 to each sample.
    pub dissipated: Vec<f64>,
    /// Kinetic + elastic + gravitational.
    pub total: Vec<f64>,
}

impl EnergyData {
    /// Total plus dissipated at each sample: flat once the drive has
    /// ended.
    pub fn total_with_dissipated(&self) -> Vec<f64> {
        self.total
            .iter()
            .zip(&self.dissipated)
            .map(|(a, b)| a + b)
            .collect()
    }

    /// The values per sample the data file writes (six lists of numbers).
    pub const VALUES_PER_SAMPLE: f64 = 6.0;
}

/// Bytes per block of each run beyond its frames: the final angles, the
/// arrival times and every wave's per-block arrival times (a few waves).
pub const BYTES_PER_BLOCK_RUN: f64 = 400.0;

/// Bytes of a data file beyond its runs: the scene, the settings, the
/// command line, titles.
pub const BYTES_FIXED: f64 = 64e3;

/// Bytes of one impact in the data file: the event (`{t, blocks, speed}`
/// pretty-printed, 130–150 bytes) and its time and speed in s and cm/s
/// (`units`, two numbers of at most 40 bytes).
pub const BYTES_PER_IMPACT: f64 = 240.0;

/// Impacts allowed for per block and 100 τ of a run whose blocks may
/// touch (ribbons with contact): the toy in air clatters at 0.52 (58
/// impacts of 6 blocks in 1855 τ, docs/experiments.md, "The toy in air"),
/// the tank's plates at 0; four times the toy's. Not a bound: how many
/// impacts a run has is not known before it runs.
pub const IMPACTS_PER_BLOCK_100_TAU: f64 = 2.0;

/// The bytes allowed for the impacts a run of `s` records (0 where its
/// blocks cannot touch).
pub fn impact_bytes(s: &Scene) -> f64 {
    let touch = s
        .apparatus
        .as_ref()
        .is_some_and(|a| a.ribbons && a.contact.is_some());
    if !touch {
        return 0.0;
    }
    let n = s.model.n as f64;
    n * s.run.t_end / 100.0 * IMPACTS_PER_BLOCK_100_TAU * BYTES_PER_IMPACT
}

/// Bytes of a run's `budget` (`sim::budget::Budget`: four numbers and
/// their keys, pretty-printed, about 150).
pub const BYTES_PER_BUDGET: f64 = 200.0;

/// The bytes allowed for the budget a run of `s` records: a run of the
/// toy as built (ribbons) keeps one (`sim::budget::kept`), others none.
pub fn budget_bytes(s: &Scene) -> f64 {
    let built = s.apparatus.as_ref().is_some_and(|a| a.ribbons);
    if built { BYTES_PER_BUDGET } else { 0.0 }
}

/// Numbers of the data file per block and sample of `output`: θ, X and
/// Y of each frame, and sin θ where a kymograph is drawn.
fn values_per_block_sample(output: &OutputSpec) -> f64 {
    match output {
        OutputSpec::Movie { .. } | OutputSpec::Kymograph => 4.0,
        OutputSpec::Filmstrip { .. } => 3.0,
        _ => 0.0,
    }
}

/// An upper estimate of the bytes of `scene`'s data file drawn with
/// `movie` (a kymograph figure with `kymograph_rows` rows), made before
/// any work (docs/limits.md): per run, samples × N × the numbers of each
/// block × [`BYTES_PER_VALUE`], plus N × [`BYTES_PER_BLOCK_RUN`], the
/// impacts' allowance ([`impact_bytes`]) and the budget's
/// ([`budget_bytes`]); plus [`BYTES_FIXED`].
/// Returns the bytes and the largest samples × N.
pub fn estimated_bytes(scene: &Scene, movie: &MovieOptions, kymograph_rows: usize) -> (f64, f64) {
    let per = values_per_block_sample(&scene.output);
    let mut bytes = BYTES_FIXED;
    let mut block_samples: f64 = 0.0;
    for (s, times) in scene.runs() {
        let samples = match scene.output {
            OutputSpec::Movie { .. } => movie.frames,
            OutputSpec::Kymograph => kymograph_rows,
            _ => times.len(),
        } as f64;
        let n = s.model.n as f64;
        bytes += samples * n * per * BYTES_PER_VALUE
            + n * BYTES_PER_BLOCK_RUN
            + impact_bytes(&s)
            + budget_bytes(&s);
        if matches!(scene.output, OutputSpec::Energy) {
            // Six numbers a sample, whatever N.
            bytes += ENERGY_SAMPLES as f64 * EnergyData::VALUES_PER_SAMPLE * BYTES_PER_VALUE;
        }
        block_samples += samples * n;
    }
    (bytes, block_samples)
}

/// Names of the `.npz` arrays of [`write_npz`], in the order written.
pub const NPZ_ARRAYS: [&str; 12] = [
    "t",
    "theta",
    "x",
    "y",
    "vx",
    "vy",
    "omega",
    "kinetic_energy",
    "elastic_energy",
    "gravitational_energy",
    "energy",
    "dissipated_energy",
];

/// Name of the `.npz` array holding the file's provenance (JSON text,
/// [`NpzMetadata`]).
pub const NPZ_METADATA: &str = "metadata";

/// What an `.npz` says of itself (docs/python.md: every file carries
/// its provenance): the program that wrote it and the scene it ran.
#[derive(Debug, Clone, Serialize)]
pub struct NpzMetadata<'a> {
    #[serde(flatten)]
    pub made_by: MadeBy<'a>,
    pub scene: &'a Scene,
}

/// θ wrapped to (−π, π], as the CSV's degrees are to (−180°, 180°].
fn wrap_rad(theta: f64) -> f64 {
    let w = theta.rem_euclid(std::f64::consts::TAU);
    if w > std::f64::consts::PI {
        w - std::f64::consts::TAU
    } else {
        w
    }
}

/// Coordinate `k` (0: X, 1: Y, 2: θ) of every block of every sample of
/// `rows` (the state's layout, 3 numbers a block), through `f`.
fn column<W: Write>(
    a: &mut ArrayWriter<'_, W>,
    rows: &[Vec<f64>],
    k: usize,
    f: fn(f64) -> f64,
) -> io::Result<()> {
    rows.iter()
        .try_for_each(|r| r.chunks_exact(3).try_for_each(|b| a.push(f(b[k]))))
}

/// The whole state of `traj` at its sample times as NumPy's `.npz`
/// (docs/sweeps.md), streamed into `w`: `t` (S), and S × N arrays `theta`
/// (radians, wrapped to (−π, π]), `x`, `y` (centres, units of s), `vx`,
/// `vy`, `omega` (θ̇), then per sample the energies (units of k s²):
/// `kinetic_energy` ½m(Ẋ²+Ẏ²)+½Iθ̇², `elastic_energy`
/// Σ½k[(L_A−a)²+(L_B−b)²], `gravitational_energy` −mGΣX_n and their sum
/// `energy` (docs/model.md). Nothing is held beyond one buffer.
///
/// Last, `metadata`: the file's provenance as JSON text in a 0-d unicode
/// array ([`NPZ_METADATA`]; `json.loads(str(npz["metadata"]))`): the
/// program, version, commit, build, command line and the scene run
/// ([`NpzMetadata`], docs/formats.md).
pub fn write_npz<W: Write + Seek>(
    traj: &sim::Trajectory,
    ladder: &Ladder,
    metadata: &NpzMetadata<'_>,
    w: W,
) -> io::Result<W> {
    let samples = traj.times.len();
    let n = ladder.n();
    let mut npz = NpzWriter::new(w);
    npz.array("t", &[samples], |a| {
        traj.times.iter().try_for_each(|&t| a.push(t))
    })?;
    let shape = [samples, n];
    let same = |v: f64| v;
    npz.array("theta", &shape, |a| column(a, &traj.states, 2, wrap_rad))?;
    npz.array("x", &shape, |a| column(a, &traj.states, 0, same))?;
    npz.array("y", &shape, |a| column(a, &traj.states, 1, same))?;
    npz.array("vx", &shape, |a| column(a, &traj.velocities, 0, same))?;
    npz.array("vy", &shape, |a| column(a, &traj.velocities, 1, same))?;
    npz.array("omega", &shape, |a| column(a, &traj.velocities, 2, same))?;
    let kinetic = |k: usize| ladder.kinetic_energy(&traj.velocities[k]);
    let elastic = |k: usize| ladder.elastic_energy(&traj.states[k]);
    let gravity = |k: usize| ladder.energy(&traj.states[k]) - elastic(k);
    let energies: [(&str, &dyn Fn(usize) -> f64); 4] = [
        ("kinetic_energy", &kinetic),
        ("elastic_energy", &elastic),
        ("gravitational_energy", &gravity),
        ("energy", &|k| kinetic(k) + ladder.energy(&traj.states[k])),
    ];
    for (name, e) in energies {
        npz.array(name, &[samples], |a| {
            (0..samples).try_for_each(|k| a.push(e(k)))
        })?;
    }
    // The energy dissipated from t = 0 to each sample (recorded in the run
    // loop, `sim::RunOptions::dissipation`): `energy` + this is flat once
    // the drive has ended. NaN where the run did not record it.
    npz.array("dissipated_energy", &[samples], |a| {
        (0..samples).try_for_each(|k| a.push(traj.dissipated.get(k).copied().unwrap_or(f64::NAN)))
    })?;
    let text = serde_json::to_string(metadata).map_err(io::Error::other)?;
    npz.text(NPZ_METADATA, &text)?;
    npz.finish()
}
