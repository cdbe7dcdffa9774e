//! The parameter table (`scene::params`) as Python reads it: one dict per
//! parameter (`jacobs_ladder.PARAMETERS`), from which the package takes
//! its keywords' docs, defaults and ranges (docs/python.md). Nothing here
//! is typed twice: every field is the table's (`ParamInfo`).

use jacobs_ladder::scene::params::ParamInfo;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

/// Every parameter's declaration, in the table's order (`Param::ALL`):
/// name, flag, symbol, unit, label, doc, default, min, max (±inf where
/// unbounded), range (in words), kind ("int" or "float"), place ("model"
/// or "drive").
pub fn parameters(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let list = PyList::empty(py);
    for info in ParamInfo::all() {
        let d = PyDict::new(py);
        let value = serde_json::to_value(&info).map_err(|e| {
            pyo3::exceptions::PyRuntimeError::new_err(format!("cannot encode the table: {e}"))
        })?;
        for (k, v) in value.as_object().into_iter().flatten() {
            match v {
                serde_json::Value::String(s) => d.set_item(k, s)?,
                serde_json::Value::Number(n) => d.set_item(k, n.as_f64())?,
                _ => d.set_item(k, py.None())?,
            }
        }
        // Numbers as the table holds them (JSON has no infinity); a whole
        // number's default as an int.
        d.set_item("min", info.min)?;
        d.set_item("max", info.max)?;
        if info.kind == "int" {
            d.set_item("default", info.default as i64)?;
        }
        list.append(d)?;
    }
    Ok(list)
}

/// The defaults the package's docstrings show, each read from the type
/// that owns it: the run's (`RunSpec`, `DEFAULT_DT`, `DEFAULT_RTOL`), the
/// samples' interval, the render options' (`RenderOptions`), the sweep's
/// (`SweepSpec`, its cap on runs, an executor's chunks) and the theory's
/// largest chain.
pub fn defaults(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    use jacobs_ladder::front::{executor, options::RenderOptions};
    use jacobs_ladder::scene::{self, sweep};
    let d = PyDict::new(py);
    let run = scene::Scene::default().run;
    d.set_item("t_end", run.t_end)?;
    d.set_item("integrator", run.integrator.to_string())?;
    d.set_item("tolerance", run.tolerance)?;
    d.set_item("dt", scene::run::DEFAULT_DT)?;
    d.set_item("rtol", scene::run::DEFAULT_RTOL)?;
    d.set_item("sample_every", crate::scene::DEFAULT_SAMPLE_EVERY)?;
    let render = RenderOptions::default();
    d.set_item("formats", render.formats)?;
    d.set_item("frames", render.frames)?;
    d.set_item("size", render.size)?;
    d.set_item("fps", render.fps)?;
    d.set_item("scale", render.scale)?;
    d.set_item("cap", sweep::SweepSpec::default().cap)?;
    d.set_item("max_runs", sweep::DEFAULT_MAX_RUNS)?;
    d.set_item("chunk_runs", executor::CHUNK_RUNS)?;
    d.set_item("min_chunks", executor::MIN_CHUNKS)?;
    d.set_item("theory_max_n", jacobs_ladder::limits::MAX_THEORY_BLOCKS)?;
    Ok(d)
}
