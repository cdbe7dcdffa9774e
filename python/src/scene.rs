//! The scene class: a `jacobs_ladder::scene::Scene`, read from the
//! catalogue or TOML, changed by keywords, simulated, rendered and saved
//! as the command line does.

use crate::arrays;
use crate::convert;
use crate::errors::IntoPy;
use crate::kwargs;
use crate::work;
use jacobs_ladder::front::{self, options::RenderOptions};
use jacobs_ladder::scene::{Kind, Scene};
use jacobs_ladder::{Error, Result, catalog, scene, scenes};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

/// A scene (native half of `jacobs_ladder.Scene`).
#[pyclass(name = "_Scene", module = "jacobs_ladder._native", frozen)]
pub struct PyScene {
    pub scene: Scene,
}

/// The render options (`format`, `frames`, `size`, `fps`, `scale`): each
/// left out (None) keeps the library's default
/// ([`front::options::RenderOptions`]), and each is checked by the
/// library's own code, as the command line's flags are.
pub struct RenderArgs {
    formats: Option<String>,
    frames: Option<usize>,
    size: Option<(u32, u32)>,
    fps: Option<f64>,
    scale: Option<f32>,
}

impl<'py> FromPyObject<'_, 'py> for RenderArgs {
    type Error = PyErr;

    fn extract(obj: Borrowed<'_, 'py, PyAny>) -> PyResult<Self> {
        let d = obj.cast::<PyDict>()?;
        let item = |k: &str| d.get_item(k).ok().flatten();
        let formats = match item("format") {
            None => None,
            Some(f) if f.is_none() => None,
            Some(f) => Some(formats(&f)?),
        };
        let size = match item("size") {
            None => None,
            Some(v) if v.is_none() => None,
            Some(v) => Some(size(&v)?),
        };
        Ok(Self {
            formats,
            frames: convert::whole_or_none(item("frames").as_ref(), "frames")?,
            size,
            fps: convert::number_or_none(item("fps").as_ref(), "fps")?,
            scale: convert::number_or_none(item("scale").as_ref(), "scale")?.map(|x| x as f32),
        })
    }
}

/// `format`: `"png,svg"` or `["png", "svg"]`; no empty name.
fn formats(obj: &Bound<'_, PyAny>) -> PyResult<String> {
    let names: Vec<String> = match convert::value(obj, "format", 0)? {
        serde_json::Value::String(s) => s.split(',').map(|n| n.trim().to_string()).collect(),
        serde_json::Value::Array(items) => items
            .into_iter()
            .enumerate()
            .map(|(i, v)| match v {
                serde_json::Value::String(s) => Ok(s),
                other => Err(convert::bad(
                    "format",
                    format!("must name formats (strings), got {other} at index {i}"),
                )),
            })
            .collect::<PyResult<_>>()?,
        other => {
            return Err(convert::bad(
                "format",
                format!("must be a format or a list of them (\"png,svg\"), got {other}"),
            ));
        }
    };
    if names.is_empty() || names.iter().any(String::is_empty) {
        return Err(convert::bad(
            "format",
            format!(
                "an empty format name in {:?}; give names such as \"png,svg\"",
                names.join(",")
            ),
        ));
    }
    Ok(names.join(","))
}

/// `size`: `"640x480"` or `(640, 480)`, pixels; a number past a frame's
/// refused here, before anything is allocated (the library checks the
/// frame's pixels against its cap).
fn size(obj: &Bound<'_, PyAny>) -> PyResult<(u32, u32)> {
    match convert::value(obj, "size", 0)? {
        serde_json::Value::String(text) => {
            front::options::parse_size(&text).map_err(|e| convert::bad("size", e))
        }
        serde_json::Value::Array(items) if items.len() == 2 => {
            let side = |v: &serde_json::Value| {
                v.as_u64()
                    .filter(|&x| (1..=u64::from(u32::MAX)).contains(&x))
                    .map(|x| x as u32)
                    .ok_or_else(|| {
                        convert::bad(
                            "size",
                            format!("must be (width, height) in whole pixels >= 1, got {v}"),
                        )
                    })
            };
            Ok((side(&items[0])?, side(&items[1])?))
        }
        other => Err(convert::bad(
            "size",
            format!("must be (width, height) or \"WxH\" in pixels, got {other}"),
        )),
    }
}

impl RenderArgs {
    fn outputs(&self, scene: &Scene) -> Result<(scenes::MovieOptions, scenes::Outputs)> {
        let defaults = RenderOptions::default();
        let size = self.size.unwrap_or(defaults.size);
        // No style flags: a scene's own `[style]` table (the `style`
        // keyword of `render`) sets its look.
        let options = RenderOptions {
            formats: self.formats.clone().unwrap_or(defaults.formats),
            frames: self.frames.unwrap_or(defaults.frames),
            size,
            fps: self.fps.unwrap_or(defaults.fps),
            scale: self.scale.unwrap_or(defaults.scale),
            ..defaults
        };
        let movie = options.movie()?;
        let outputs = options.outputs(&movie)?;
        if self.formats.is_some() {
            front::options::check_covers(&options.formats, std::slice::from_ref(scene))?;
        }
        Ok((movie, outputs))
    }
}

#[pymethods]
impl PyScene {
    /// The built-in scene `id` (`ladder list`); `kind` "figure" or "movie"
    /// where both have the ID.
    #[staticmethod]
    #[pyo3(signature = (id, kind=None))]
    fn builtin(id: &str, kind: Option<&str>) -> PyResult<Self> {
        let entry = match kind {
            None => catalog::find_any(id),
            Some("figure") => catalog::find(Kind::Figure, id),
            Some("movie") => catalog::find(Kind::Movie, id),
            Some(other) => Err(Error::bad_input(format!(
                "kind must be \"figure\" or \"movie\", got \"{other}\""
            ))),
        }
        .py_err()?;
        Ok(Self {
            scene: entry.scene.clone(),
        })
    }

    /// A scene from TOML text; `origin` names it in messages.
    #[staticmethod]
    fn parse(text: &str, origin: &str, name: &str) -> PyResult<Self> {
        Ok(Self {
            scene: scene::file::parse(text, origin, name).py_err()?,
        })
    }

    /// The scene file at `path` (named after the file).
    #[staticmethod]
    fn load(path: PathBuf) -> PyResult<Self> {
        Ok(Self {
            scene: scene::file::load(&path).py_err()?,
        })
    }

    /// A scene from its JSON value (`to_json`), checked.
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Self> {
        let value: Scene = serde_json::from_str(text)
            .map_err(|e| Error::bad_input(format!("not a scene: {e}")))
            .py_err()?;
        Ok(Self {
            scene: kwargs::checked(value).py_err()?,
        })
    }

    fn to_toml(&self) -> PyResult<String> {
        scene::file::to_toml(&self.scene).py_err()
    }

    fn to_json(&self) -> PyResult<String> {
        serde_json::to_string(&self.scene)
            .map_err(|e| Error::failed(format!("cannot encode the scene: {e}")))
            .py_err()
    }

    /// A changed copy (the keywords `kwargs`); a window fitted to the old
    /// chain follows a new N (`Scene::window_following`).
    fn replace(&self, kwargs: &Bound<'_, PyDict>) -> PyResult<Self> {
        let changed = kwargs::apply(&self.scene, convert::keywords(kwargs)?).py_err()?;
        Ok(Self {
            scene: changed.window_following(&self.scene),
        })
    }

    #[getter]
    fn name(&self) -> String {
        self.scene.name.clone()
    }

    #[getter]
    fn kind(&self) -> &'static str {
        self.scene.kind().name()
    }

    #[getter]
    fn title(&self) -> String {
        scene::describe::title(&self.scene)
    }

    #[getter]
    fn parameters(&self) -> String {
        scene::describe::parameters(&self.scene)
    }

    /// Number of simulations the scene runs.
    #[getter]
    fn runs(&self) -> usize {
        self.scene.runs().len()
    }

    fn __eq__(&self, other: &Self) -> bool {
        self.scene == other.scene
    }

    /// Simulates run `index` of the scene (its only one for most scenes).
    #[pyo3(signature = (sample_every=None, samples=None, index=None, dissipation=false, progress=None))]
    fn simulate<'py>(
        &self,
        py: Python<'py>,
        sample_every: Option<&Bound<'py, PyAny>>,
        samples: Option<&Bound<'py, PyAny>>,
        index: Option<&Bound<'py, PyAny>>,
        dissipation: bool,
        progress: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let index = convert::whole_or_none(index, "index")?.unwrap_or(0);
        let runs = self.scene.runs();
        let Some((single, _)) = runs.into_iter().nth(index) else {
            let count = self.scene.runs().len();
            return Err(Error::bad_input(format!(
                "{} {} has {count} simulation{}; index must be below that",
                self.scene.kind().name(),
                self.scene.name,
                if count == 1 { "" } else { "s" }
            )))
            .py_err();
        };
        let how = Sampling {
            every: sample_every,
            at: samples,
            dissipation,
            progress,
        };
        simulate_scene(py, single, how)
    }

    /// The files the command line writes for this scene, as (name, bytes).
    fn render(&self, py: Python<'_>, args: RenderArgs) -> PyResult<Vec<(String, Vec<u8>)>> {
        let scene = self.scene.clone();
        work::run(py, move |_| {
            let (opts, outputs) = args.outputs(&scene)?;
            scenes::render_with(&scene, &opts, &outputs, &|| {})
        })
    }

    /// Writes the files into `dir` as `ladder render --out DIR` does
    /// (atomically; every target checked first); returns their paths.
    /// `progress(done, total)`: a movie's frames, else the scene's files.
    #[pyo3(signature = (dir, args, progress=None))]
    fn save(
        &self,
        py: Python<'_>,
        dir: PathBuf,
        args: RenderArgs,
        progress: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Vec<PathBuf>> {
        if dir.as_os_str().is_empty() {
            // As `--out ""`: an empty name is no folder (not the current one).
            return Err(convert::bad("dir", "must name a folder, got \"\""));
        }
        let scene = self.scene.clone();
        // As the command line's bar: a movie's frames, else the files.
        let movie = scene.kind() == Kind::Movie;
        let total = if movie {
            args.outputs(&scene).py_err()?.0.frames as f64
        } else {
            f64::NAN
        };
        let report = work::Report::new(progress, total.is_finite().then_some(total), true);
        work::run_reporting(py, report, move |stop| {
            let (opts, outputs) = args.outputs(&scene)?;
            // Ctrl-C stops the drawing as it stops a sweep (`work::Stop`):
            // the work unwinds at the next frame of a movie, or before a
            // figure's next file (or its file's rename), each file's
            // temporary removed as it unwinds, so nothing is written after
            // it.
            let frame = || if movie { stop.add(1.0) } else { stop.check() };
            let file = || if movie { stop.check() } else { stop.add(1.0) };
            let progress = front::render::Progress {
                frame: &frame,
                file: &file,
                ..front::render::Progress::quiet()
            };
            let files = front::render::into_folder(
                std::slice::from_ref(&scene),
                &dir,
                &opts,
                &outputs,
                false,
                &progress,
            )?;
            Ok(files.iter().map(|name| dir.join(name)).collect())
        })
    }
}

/// How a run is sampled and reported: every `every` τ or at the times
/// `at`, the energy dissipated recorded or not, `progress(t, t_end)`.
pub struct Sampling<'a, 'py> {
    pub every: Option<&'a Bound<'py, PyAny>>,
    pub at: Option<&'a Bound<'py, PyAny>>,
    pub dissipation: bool,
    pub progress: Option<&'a Bound<'py, PyAny>>,
}

/// Simulates a single-run scene without the GIL; the arrays as a dict.
pub fn simulate_scene<'py>(
    py: Python<'py>,
    scene: Scene,
    how: Sampling<'_, 'py>,
) -> PyResult<Bound<'py, PyDict>> {
    let Sampling {
        every: sample_every,
        at: samples,
        dissipation,
        progress,
    } = how;
    let limits = scene.limits;
    let n = scene.model.n;
    // Counted against the cap on samples × N before any is copied.
    let check = |count: usize| {
        limits
            .check_samples(count as f64, n)
            .map_err(|e| convert::bad("samples", Error::from(e)))
    };
    let samples = match samples.filter(|s| !s.is_none()) {
        Some(s) => Some(convert::times(s, "samples", &check)?),
        None => None,
    };
    let sample_every = convert::number_or_none(sample_every, "sample_every")?;
    // t_end "auto" is resolved in the work: its end is not known here.
    let t_end = scene.run.t_end;
    let report = work::Report::new(progress, t_end.is_finite().then_some(t_end), false);
    let out = work::run_reporting(py, report, move |stop| {
        // `t_end = "auto"` resolved first: the samples reach its end.
        let scene = scene.with_auto_window()?;
        let times = match samples {
            Some(t) => t,
            None => sample_times(&scene, sample_every.unwrap_or(DEFAULT_SAMPLE_EVERY))?,
        };
        // Python holds a run twice over for a moment (the run's rows, and
        // the numpy columns made from them; the rows' address space is not
        // given back): both asked for before the run, after its caps, so
        // that an address-space limit fails the call before the work.
        scenes::run::check_cost(&scene, times.len())?;
        jacobs_ladder::sim::ensure_memory(times.len().saturating_mul(2), scene.model.n)?;
        let progress = |t: f64| stop.at(t);
        let options = jacobs_ladder::sim::RunOptions::default()
            .limits(scene.limits)
            .progress(&progress)
            .dissipation(dissipation);
        let run = scenes::run::simulate_with(&scene, &times, &options)?;
        arrays::arrays(&scene, run)
    })?;
    out.into_dict(py)
}

/// Interval of the samples kept, τ: the CSV's of `ladder simulate`.
const DEFAULT_SAMPLE_EVERY: f64 = 10.0;

/// 0, every, 2 every, ... up to t_end (as `simulate --csv`), within the
/// cap on samples × N.
fn sample_times(scene: &Scene, every: f64) -> Result<Vec<f64>> {
    if !(every.is_finite() && every > 0.0) {
        return Err(Error::bad_input(format!(
            "sample_every: must be a finite time > 0, got {every}"
        )));
    }
    let count = (scene.run.t_end / every).floor() + 1.0;
    scene
        .limits
        .check_samples(count, scene.model.n)
        .map_err(|e| {
            Error::bad_input(format!(
                "sample_every: every {every} τ up to t_end = {} τ: {}; give a larger \
                 sample_every, a shorter t_end or samples=[...]",
                scene.run.t_end,
                Error::from(e)
            ))
        })?;
    Ok((0..count as usize).map(|k| k as f64 * every).collect())
}
