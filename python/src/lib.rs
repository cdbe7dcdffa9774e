//! `jacobs_ladder._native`: the Python extension of `jacobs-ladder`, a thin
//! layer over the library (no physics and no drawing here). Scenes cross
//! as serde values (`kwargs`), arrays as numpy arrays made from the
//! library's vectors (`arrays`), errors become exceptions in one place
//! (`errors`), and every call into the engine runs without the GIL and
//! stops on Ctrl-C (`work`). The package `jacobs_ladder` (python/) wraps
//! these functions with keyword signatures, docstrings and Jupyter display.

mod arrays;
mod convert;
mod errors;
mod kwargs;
mod scene;
mod work;

use errors::IntoPy;
use jacobs_ladder::catalog;
use jacobs_ladder::scene::{OutputSpec, Scene};
use jacobs_ladder::{Error, Result};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

/// `simulate(**keywords)`: the paper's scene with the keywords applied (a
/// data run), simulated; samples every `sample_every` τ or at `samples`.
#[pyfunction]
#[pyo3(signature = (kwargs, sample_every=None, samples=None, dissipation=false))]
fn simulate<'py>(
    py: Python<'py>,
    kwargs: &Bound<'py, PyDict>,
    sample_every: Option<&Bound<'py, PyAny>>,
    samples: Option<&Bound<'py, PyAny>>,
    dissipation: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let base = Scene {
        output: OutputSpec::Data,
        ..Scene::default()
    };
    let scene = kwargs::apply(&base, convert::keywords(kwargs)?).py_err()?;
    scene::simulate_scene(py, scene, sample_every, samples, dissipation)
}

/// `theory(alpha, n, b)`: the numbers of `ladder theory --json`, as JSON;
/// a value left out (None) is the model's default (`Model::default`).
#[pyfunction]
fn theory(
    py: Python<'_>,
    alpha: &Bound<'_, PyAny>,
    n: &Bound<'_, PyAny>,
    b: &Bound<'_, PyAny>,
) -> PyResult<String> {
    let m = jacobs_ladder::scene::Model::default();
    let (alpha, n, b) = (
        convert::number_or_none(Some(alpha), "alpha")?.unwrap_or(m.alpha),
        convert::whole_or_none(Some(n), "n")?.unwrap_or(m.n),
        convert::number_or_none(Some(b), "b")?.unwrap_or(m.b),
    );
    work::run(py, move |_| {
        let params = jacobs_ladder::scene::Model { alpha, n, b, ..m }.params()?;
        let report = jacobs_ladder::theory::TheoryReport::compute(&params)?;
        serde_json::to_string(&report).map_err(|e| Error::failed(format!("cannot encode: {e}")))
    })
}

/// The sweep scene: the base scene with `kwargs` applied (its `output`
/// the sweep with its first axis), the axes `grid` added in their order
/// (a list of (name, values): a JSON object would lose the order),
/// checked whole.
fn sweep_scene(
    base: Option<&scene::PyScene>,
    kwargs: &Bound<'_, PyDict>,
    grid: &Bound<'_, PyList>,
) -> PyResult<Scene> {
    use jacobs_ladder::scene::sweep::{Param, Values};
    let base = base.map_or_else(Scene::default, |s| s.scene.clone());
    let mut scene = kwargs::apply(&base, convert::keywords(kwargs)?).py_err()?;
    if let OutputSpec::Sweep(spec) = &mut scene.output {
        for item in grid.iter() {
            let (name, values): (String, Bound<'_, PyAny>) = item.extract()?;
            let param = Param::from_name(&name)
                .ok_or_else(|| Error::bad_input(format!("{name}: not a sweep parameter")))
                .py_err()?;
            let values: Values = serde_json::from_value(convert::value(&values, &name, 0)?)
                .map_err(|e| Error::bad_input(format!("{name}: {e}")))
                .py_err()?;
            spec.grid.0.push((param, values));
        }
    }
    kwargs::checked(scene).py_err()
}

/// `sweep`: the sweep scene ([`sweep_scene`]) run whole; returns (CSV,
/// JSON) as `ladder sweep` writes them.
#[pyfunction]
#[pyo3(signature = (base, kwargs, grid, max_runs))]
fn sweep(
    py: Python<'_>,
    base: Option<&scene::PyScene>,
    kwargs: &Bound<'_, PyDict>,
    grid: &Bound<'_, PyList>,
    max_runs: &Bound<'_, PyAny>,
) -> PyResult<(String, String)> {
    let max_runs = convert::whole_or_none(Some(max_runs), "max_runs")?
        .unwrap_or(jacobs_ladder::scene::sweep::DEFAULT_MAX_RUNS);
    let scene = sweep_scene(base, kwargs, grid)?;
    work::run(py, move |stop| sweep_tables(&scene, max_runs, stop))
}

/// `sweep(..., executor=EX)`, first step: the sweep scene as JSON (what a
/// chunk is sent) and its number of chunks (`chunks`, checked, or the
/// default for its size), every check of the whole sweep made (runs, the files' estimated bytes).
#[pyfunction]
#[pyo3(signature = (base, kwargs, grid, max_runs, chunks))]
fn sweep_prepare(
    base: Option<&scene::PyScene>,
    kwargs: &Bound<'_, PyDict>,
    grid: &Bound<'_, PyList>,
    max_runs: &Bound<'_, PyAny>,
    chunks: Option<&Bound<'_, PyAny>>,
) -> PyResult<(String, usize, usize)> {
    use jacobs_ladder::front;
    let max_runs = convert::whole_or_none(Some(max_runs), "max_runs")?
        .unwrap_or(jacobs_ladder::scene::sweep::DEFAULT_MAX_RUNS);
    let chunks = convert::whole_or_none(chunks, "chunks")?;
    let scene = sweep_scene(base, kwargs, grid)?;
    let plan = front::sweep::plan(&scene, max_runs, &|runs| format!("max_runs={runs}")).py_err()?;
    jacobs_ladder::sweep::json::check_estimate(&plan)
        .map_err(Error::from)
        .py_err()?;
    let json = serde_json::to_string(&scene)
        .map_err(|e| Error::failed(format!("cannot encode the scene: {e}")))
        .py_err()?;
    let chunks = match chunks {
        None => front::executor::default_chunks(plan.len()),
        Some(c) => {
            front::executor::check_chunks(c, plan.len()).py_err()?;
            c
        }
    };
    Ok((json, max_runs, chunks))
}

/// Runs chunk `k` of `chunks` of the sweep scene `scene` (JSON, from
/// [`sweep_prepare`]), in a worker; returns its shard file's bytes.
#[pyfunction]
fn sweep_chunk<'py>(
    py: Python<'py>,
    scene: &str,
    max_runs: usize,
    k: usize,
    chunks: usize,
) -> PyResult<Bound<'py, pyo3::types::PyBytes>> {
    let scene: Scene = serde_json::from_str(scene)
        .map_err(|e| Error::bad_input(format!("not a sweep scene: {e}")))
        .py_err()?;
    let scene = kwargs::checked(scene).py_err()?;
    let bytes = work::run(py, move |stop| {
        let tick = || stop.check(0.0);
        let between = || stop.check(0.0);
        jacobs_ladder::front::executor::run_chunk(&scene, max_runs, k, chunks, &tick, &between)
    })?;
    Ok(pyo3::types::PyBytes::new(py, &bytes))
}

/// Merges the chunks' shard files (through a fresh folder `dir`) by the
/// code that gathers shards; returns (CSV, JSON) as [`sweep`] does.
#[pyfunction]
fn sweep_gather(
    py: Python<'_>,
    dir: std::path::PathBuf,
    chunks: Vec<Bound<'_, pyo3::types::PyBytes>>,
    max_runs: usize,
) -> PyResult<(String, String)> {
    use pyo3::types::PyBytesMethods;
    let chunks: Vec<Vec<u8>> = chunks.iter().map(|b| b.as_bytes().to_vec()).collect();
    work::run(py, move |_| {
        jacobs_ladder::front::executor::gather(&dir, &chunks, max_runs)
    })
}

fn sweep_tables(scene: &Scene, max_runs: usize, stop: &work::Stop) -> Result<(String, String)> {
    use jacobs_ladder::front;
    let plan = front::sweep::plan(scene, max_runs, &|runs| format!("max_runs={runs}"))?;
    // The files' bytes, estimated before any run (docs/limits.md).
    jacobs_ladder::sweep::json::check_estimate(&plan)?;
    let all: Vec<usize> = (0..plan.len()).collect();
    let mut records = Vec::new();
    // Ctrl-C is noticed after each run (the runs unwind) and between chunks.
    let tick = || stop.check(0.0);
    front::sweep::run_in_chunks(&plan, &all, &mut records, &tick, &mut |_| {
        stop.check(0.0);
        Ok(())
    })?;
    // Python takes the JSON as one string: here it is held whole.
    front::sweep::tables(&plan, &records)
}

/// The built-in scenes: (ID, kind, title) in catalogue order.
#[pyfunction]
fn catalogue() -> PyResult<Vec<(String, String, String)>> {
    Ok(catalog::catalogue()
        .py_err()?
        .iter()
        .map(|e| {
            (
                e.id.clone(),
                e.kind().name().to_string(),
                jacobs_ladder::scene::describe::title(&e.scene),
            )
        })
        .collect())
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(theory, m)?)?;
    m.add_function(wrap_pyfunction!(sweep, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_prepare, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_chunk, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_gather, m)?)?;
    m.add_function(wrap_pyfunction!(catalogue, m)?)?;
    m.add_class::<scene::PyScene>()?;
    m.add("RunError", m.py().get_type::<errors::RunError>())?;
    m.add("InternalError", m.py().get_type::<errors::InternalError>())?;
    m.add("VERSION", jacobs_ladder::version::LONG)?;
    Ok(())
}
