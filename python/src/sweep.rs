//! Sweeps from Python (`jacobs_ladder.sweep`): the sweep scene made from
//! the keywords (the grid keywords picked out and ordered by the library's
//! parameters, `Param::ALL`), planned and checked once (`_Sweep`), run
//! here or cut into chunks for an executor's workers (`sweep_chunk`), the
//! chunks checked as they come back and merged (`front::executor`), and
//! the results handed over as the CSV, the JSON and typed columns at full
//! precision (`sweep::columns`).

use crate::convert;
use crate::errors::IntoPy;
use crate::kwargs;
use crate::scene::PyScene;
use crate::work::{self, Report};
use jacobs_ladder::front::{self, executor};
use jacobs_ladder::scene::sweep::{DEFAULT_MAX_RUNS, Param};
use jacobs_ladder::scene::{OutputSpec, Scene};
use jacobs_ladder::sweep::columns::{self, Values};
use jacobs_ladder::sweep::shard::Shard;
use jacobs_ladder::sweep::{Plan, Record};
use jacobs_ladder::{Error, Result};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};
use serde_json::{Map, Value};

/// The sweep scene: `base` with the keywords applied, the grid keywords
/// (the sweep's parameters, `Param::ALL`) taken out as its axes in that
/// order (the first varies slowest, as `ladder sweep`'s flags), `cap` its
/// cap; checked whole.
fn sweep_scene(
    base: Option<&PyScene>,
    mut keys: Map<String, Value>,
    cap: Option<f64>,
) -> Result<Scene> {
    let grid: Vec<(Param, Value)> = Param::ALL
        .into_iter()
        .filter_map(|p| keys.remove(p.name()).map(|v| (p, v)))
        .collect();
    let Some(((first, first_values), rest)) = grid.split_first() else {
        return Err(Error::bad_input(format!(
            "sweep needs at least one grid keyword: {}",
            Param::names()
        )));
    };
    // The first axis goes with the scene (a sweep needs one to be read and
    // checked); the others follow in order (a JSON object would sort them).
    let mut output = Map::new();
    output.insert("kind".into(), "sweep".into());
    let first_axis = Map::from_iter([(first.name().to_string(), first_values.clone())]);
    output.insert("grid".into(), Value::Object(first_axis));
    if let Some(cap) = cap {
        output.insert("cap".into(), cap.into());
    }
    keys.insert("output".into(), Value::Object(output));
    let base = base.map_or_else(Scene::default, |s| s.scene.clone());
    let mut scene = kwargs::apply(&base, keys)?;
    if let OutputSpec::Sweep(spec) = &mut scene.output {
        for (param, values) in rest {
            let values = serde_json::from_value(values.clone())
                .map_err(|e| Error::bad_input(format!("{}: {e}", param.name())))?;
            spec.grid.0.push((*param, values));
        }
    }
    kwargs::checked(scene)
}

/// A sweep planned and checked (native half of `jacobs_ladder.sweep`).
#[pyclass(name = "_Sweep", module = "jacobs_ladder._native", frozen)]
pub struct PySweep {
    plan: Plan,
    max_runs: usize,
    /// The chunks an executor's sweep is cut into.
    chunks: usize,
}

/// The plan of `scene` within `max_runs` runs, its files' estimated bytes
/// checked before any run (docs/limits.md).
fn planned(scene: &Scene, max_runs: usize) -> Result<Plan> {
    let plan = executor::plan(scene, max_runs)?;
    jacobs_ladder::sweep::json::check_estimate(&plan)?;
    Ok(plan)
}

#[pymethods]
impl PySweep {
    /// The sweep of `base` (None: the paper's scene) changed by `kwargs`,
    /// grid keywords among them; `chunks` only with an executor.
    #[new]
    #[pyo3(signature = (base, kwargs, cap=None, max_runs=None, executor=false, chunks=None))]
    fn new(
        base: Option<PyRef<'_, PyScene>>,
        kwargs: &Bound<'_, PyDict>,
        cap: Option<&Bound<'_, PyAny>>,
        max_runs: Option<&Bound<'_, PyAny>>,
        executor: bool,
        chunks: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let max_runs = convert::whole_or_none(max_runs, "max_runs")?.unwrap_or(DEFAULT_MAX_RUNS);
        let chunks = convert::whole_or_none(chunks, "chunks")?;
        if chunks.is_some() && !executor {
            return Err(convert::bad(
                "chunks",
                "cuts the grid for an executor; give executor= too",
            ));
        }
        let cap = convert::number_or_none(cap, "cap")?;
        let keys = convert::keywords(kwargs)?;
        let scene = sweep_scene(base.as_deref(), keys, cap).py_err()?;
        let plan = planned(&scene, max_runs).py_err()?;
        let chunks = match chunks {
            None => executor::default_chunks(plan.len()),
            Some(c) => {
                executor::check_chunks(c, plan.len()).py_err()?;
                c
            }
        };
        Ok(Self {
            plan,
            max_runs,
            chunks,
        })
    }

    /// The sweep again from what a chunk is sent (`scene`, JSON), to
    /// resume an executor's sweep.
    #[staticmethod]
    fn from_json(scene: &str, max_runs: usize, chunks: usize) -> PyResult<Self> {
        let scene = scene_from_json(scene).py_err()?;
        let plan = planned(&scene, max_runs).py_err()?;
        executor::check_chunks(chunks, plan.len()).py_err()?;
        Ok(Self {
            plan,
            max_runs,
            chunks,
        })
    }

    /// The sweep scene as JSON: what each chunk is sent.
    #[getter]
    fn scene(&self) -> PyResult<String> {
        serde_json::to_string(&self.plan.scene)
            .map_err(|e| Error::failed(format!("cannot encode the scene: {e}")))
            .py_err()
    }

    #[getter]
    fn max_runs(&self) -> usize {
        self.max_runs
    }

    #[getter]
    fn chunks(&self) -> usize {
        self.chunks
    }

    #[getter]
    fn runs(&self) -> usize {
        self.plan.len()
    }

    #[getter]
    fn fingerprint(&self) -> String {
        self.plan.fingerprint.clone()
    }

    /// Runs the whole sweep here, on every core; `progress(runs done,
    /// runs)` while it runs. Returns (CSV, JSON, columns).
    #[pyo3(signature = (progress=None))]
    fn run<'py>(
        &self,
        py: Python<'py>,
        progress: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Tables<'py>> {
        let plan = self.plan.clone();
        let report = Report::new(progress, Some(plan.len() as f64), true);
        let (csv, json, cols) = work::run_reporting(py, report, move |stop| {
            let all: Vec<usize> = (0..plan.len()).collect();
            let mut records = Vec::new();
            // Ctrl-C is noticed after each run (the runs unwind) and between chunks.
            let tick = || stop.add(1.0);
            front::sweep::run_in_chunks(&plan, &all, &mut records, &tick, &mut |_| {
                stop.check();
                Ok(())
            })?;
            tables(&plan, &records)
        })?;
        into_py(py, csv, json, cols)
    }

    /// The number of runs of chunk `k`.
    fn chunk_runs(&self, k: usize) -> PyResult<usize> {
        Ok(self.shard(k)?.count(self.plan.len()))
    }

    /// The grid points of chunk `k`: (run, {parameter: value}) per run.
    fn chunk_points<'py>(&self, py: Python<'py>, k: usize) -> PyResult<Bound<'py, PyList>> {
        let list = PyList::empty(py);
        for (run, at) in executor::chunk_points(&self.plan, self.shard(k)?) {
            let point = PyDict::new(py);
            for (p, v) in at {
                point.set_item(p.name(), v)?;
            }
            list.append((run, point))?;
        }
        Ok(list)
    }

    /// Checks what a worker returned for chunk `k` (it must be the bytes
    /// of that chunk of this sweep); a RunError naming the chunk if not.
    fn check_chunk(&self, py: Python<'_>, k: usize, returned: &Bound<'_, PyAny>) -> PyResult<()> {
        let shard = self.shard(k)?;
        let bytes = chunk_bytes(shard, returned)?;
        let plan = self.plan.clone();
        work::run(py, move |_| {
            executor::check_chunk(&plan, shard, &bytes).map(|_| ())
        })
    }

    /// Merges the chunks (a list of (k, bytes), every chunk once), each
    /// checked; returns (CSV, JSON, columns) as [`PySweep::run`] does.
    fn gather<'py>(&self, py: Python<'py>, chunks: &Bound<'py, PyList>) -> PyResult<Tables<'py>> {
        let mut given: Vec<(usize, Vec<u8>)> = Vec::with_capacity(chunks.len());
        for item in chunks.iter() {
            let (k, returned): (usize, Bound<'_, PyAny>) = item.extract()?;
            given.push((k, chunk_bytes(self.shard(k)?, &returned)?));
        }
        let plan = self.plan.clone();
        let n = self.chunks;
        let (csv, json, cols) = work::run(py, move |_| {
            let records = executor::gather_chunks(&plan, &given, n)?;
            tables(&plan, &records)
        })?;
        into_py(py, csv, json, cols)
    }
}

impl PySweep {
    fn shard(&self, k: usize) -> PyResult<Shard> {
        if k == 0 || k > self.chunks {
            return Err(convert::bad(
                "chunk",
                format!("chunks are numbered from 1 to {}, got {k}", self.chunks),
            ));
        }
        Ok(Shard { k, n: self.chunks })
    }
}

/// The bytes a worker returned for `chunk`: refuses anything else (None,
/// a string) naming the chunk, not the argument it was passed as.
fn chunk_bytes(chunk: Shard, returned: &Bound<'_, PyAny>) -> PyResult<Vec<u8>> {
    match returned.cast::<PyBytes>() {
        Ok(b) => Ok(b.as_bytes().to_vec()),
        Err(_) => {
            let kind = returned
                .get_type()
                .name()
                .map_or_else(|_| "object".to_string(), |n| n.to_string());
            let shown = if returned.is_none() {
                "None".to_string()
            } else {
                format!("a {kind}")
            };
            Err(crate::errors::RunError::new_err(format!(
                "chunk {} of {}: the executor's worker returned {shown}, not the chunk's results \
                 (bytes); does the executor's submit(fn, *args) return a future of fn(*args)?",
                chunk.k, chunk.n
            )))
        }
    }
}

/// A sweep scene from its JSON, checked.
fn scene_from_json(text: &str) -> Result<Scene> {
    let scene: Scene = serde_json::from_str(text)
        .map_err(|e| Error::bad_input(format!("not a sweep scene: {e}")))?;
    kwargs::checked(scene)
}

/// The CSV, the JSON and the columns of a sweep's records.
fn tables(plan: &Plan, records: &[Record]) -> Result<(String, String, Vec<columns::Column>)> {
    let (csv, json) = front::sweep::tables(plan, records)?;
    Ok((csv, json, columns::columns(plan, records)))
}

/// (CSV, JSON, [(name, values)]): whole numbers and numbers as numpy
/// arrays, names as lists of strings.
type Tables<'py> = (String, String, Bound<'py, PyList>);

fn into_py(
    py: Python<'_>,
    csv: String,
    json: String,
    cols: Vec<columns::Column>,
) -> PyResult<Tables<'_>> {
    Ok((csv, json, columns_py(py, cols)?))
}

fn columns_py(py: Python<'_>, cols: Vec<columns::Column>) -> PyResult<Bound<'_, PyList>> {
    let list = PyList::empty(py);
    for c in cols {
        let values: Bound<'_, PyAny> = match c.values {
            Values::Whole(v) => PyArray1::from_vec(py, v).into_any(),
            Values::Number(v) => PyArray1::from_vec(py, v).into_any(),
            Values::Name(v) => PyList::new(py, v)?.into_any(),
        };
        list.append((c.name, values))?;
    }
    Ok(list)
}

/// Runs chunk `k` of `chunks` of the sweep scene `scene` (JSON, from
/// `_Sweep.scene`), in a worker; returns its shard file's bytes.
#[pyfunction]
pub fn sweep_chunk<'py>(
    py: Python<'py>,
    scene: &str,
    max_runs: usize,
    k: usize,
    chunks: usize,
) -> PyResult<Bound<'py, PyBytes>> {
    let scene = scene_from_json(scene).py_err()?;
    let bytes = work::run(py, move |stop| {
        let tick = || stop.check();
        let between = || stop.check();
        executor::run_chunk(&scene, max_runs, k, chunks, &tick, &between)
    })?;
    Ok(PyBytes::new(py, &bytes))
}

/// The columns of a sweep's JSON text (its scene and runs), as
/// `_Sweep.run` gives them: a `Table` made again from its text (read and
/// made without the GIL: a large sweep's JSON is hundreds of megabytes).
#[pyfunction]
pub fn table_columns<'py>(py: Python<'py>, json: String) -> PyResult<Bound<'py, PyList>> {
    #[derive(serde::Deserialize)]
    struct Text {
        scene: Scene,
        runs: Vec<Record>,
    }
    let cols = work::run(py, move |_| {
        let text: Text = serde_json::from_str(&json)
            .map_err(|e| Error::bad_input(format!("json: not a sweep's JSON ({e})")))?;
        let scene = kwargs::checked(text.scene)?;
        let plan = Plan::new(&scene, usize::MAX)?.map_err(|e| Error::bad_input(e.to_string()))?;
        Ok(columns::columns(&plan, &text.runs))
    })?;
    columns_py(py, cols)
}

/// The sweep's parameters (`Param::ALL`), in the order the axes vary.
pub fn parameters() -> Vec<&'static str> {
    Param::ALL.iter().map(|p| p.name()).collect()
}
