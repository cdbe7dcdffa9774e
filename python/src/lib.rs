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
mod sweep;
mod work;

use errors::IntoPy;
use jacobs_ladder::Error;
use jacobs_ladder::catalog;
use jacobs_ladder::scene::{OutputSpec, Scene};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// `simulate(**keywords)`: the paper's scene with the keywords applied (a
/// data run), simulated; samples every `sample_every` τ or at `samples`.
#[pyfunction]
#[pyo3(signature = (kwargs, sample_every=None, samples=None, dissipation=false, progress=None))]
fn simulate<'py>(
    py: Python<'py>,
    kwargs: &Bound<'py, PyDict>,
    sample_every: Option<&Bound<'py, PyAny>>,
    samples: Option<&Bound<'py, PyAny>>,
    dissipation: bool,
    progress: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let base = Scene {
        output: OutputSpec::Data,
        ..Scene::default()
    };
    let scene = kwargs::apply(&base, convert::keywords(kwargs)?).py_err()?;
    let how = scene::Sampling {
        every: sample_every,
        at: samples,
        dissipation,
        progress,
    };
    scene::simulate_scene(py, scene, how)
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
        let params = jacobs_ladder::model::Params::new(n, b, alpha, m.gamma, m.gravity, m.inertia)?;
        let report = jacobs_ladder::theory::TheoryReport::compute(&params)?;
        serde_json::to_string(&report).map_err(|e| Error::failed(format!("cannot encode: {e}")))
    })
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
    m.add_function(wrap_pyfunction!(sweep::sweep_chunk, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::table_columns, m)?)?;
    m.add_class::<sweep::PySweep>()?;
    m.add("SWEEP_PARAMETERS", sweep::parameters())?;
    m.add(
        "OUTCOMES",
        jacobs_ladder::sweep::outcome::Outcome::ALL
            .iter()
            .map(|o| o.name())
            .collect::<Vec<_>>(),
    )?;
    m.add_function(wrap_pyfunction!(catalogue, m)?)?;
    m.add_class::<scene::PyScene>()?;
    m.add("RunError", m.py().get_type::<errors::RunError>())?;
    m.add("InternalError", m.py().get_type::<errors::InternalError>())?;
    m.add("VERSION", jacobs_ladder::version::LONG)?;
    Ok(())
}
