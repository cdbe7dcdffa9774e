//! The one conversion of Python values into the engine's: keywords into
//! the serde values a scene is read from, and the arguments that are not
//! scene keys (`samples`, `n`, `max_runs`, `frames`, `size`, ...) into
//! numbers. Every error names the key:
//!
//! - a value of the wrong kind among plain values (a string where a number
//!   goes, None where one is needed, NaN or infinity, a negative count, a
//!   number past its type, 10.7 blocks) is a `ValueError`;
//! - an object that is no plain value at all (a set of bytes, a function,
//!   a dict with keys that are not strings) is a `TypeError`.
//!
//! numpy scalars and arrays are read through `.tolist()`; a path through
//! `os.fspath`. Sizes are checked before anything is built from them (a
//! sequence's length is read first).

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use serde_json::{Map, Number, Value};

/// `key: message` as a ValueError.
pub fn bad(key: &str, message: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(format!("{key}: {message}"))
}

fn wrong_kind(key: &str, obj: &Bound<'_, PyAny>) -> PyErr {
    PyTypeError::new_err(format!(
        "{key}: a {} is not a value a scene takes (numbers, strings, lists and dicts of them)",
        type_name(obj)
    ))
}

fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type()
        .name()
        .map_or_else(|_| "object".into(), |n| n.to_string())
}

/// Longest list (or nesting) a keyword may hold: a scene's lists are
/// short (flips, times, a grid's values); the cap refuses a huge array
/// before it is copied.
const MAX_ITEMS: usize = 1_000_000;
/// Deepest nesting of lists and dicts.
const MAX_DEPTH: usize = 16;

/// The keywords (`dict`), None values left out (None keeps the scene's
/// value), as a JSON object.
pub fn keywords(dict: &Bound<'_, PyDict>) -> PyResult<Map<String, Value>> {
    let mut out = Map::new();
    for (k, v) in dict.iter() {
        let key: String = k
            .extract()
            .map_err(|_| PyTypeError::new_err("keywords must be named by strings"))?;
        if v.is_none() {
            continue;
        }
        out.insert(key.clone(), value(&v, &key, 0)?);
    }
    Ok(out)
}

/// A plain Python value as JSON; `key` names it in errors.
pub fn value(obj: &Bound<'_, PyAny>, key: &str, depth: usize) -> PyResult<Value> {
    if depth > MAX_DEPTH {
        return Err(bad(key, format!("nested deeper than {MAX_DEPTH} levels")));
    }
    if obj.is_none() {
        return Ok(Value::Null);
    }
    if obj.is_instance_of::<PyBool>() {
        return Ok(Value::Bool(obj.extract()?));
    }
    if obj.is_instance_of::<PyInt>() {
        if let Ok(i) = obj.extract::<i64>() {
            return Ok(Value::from(i));
        }
        if let Ok(u) = obj.extract::<u64>() {
            return Ok(Value::from(u));
        }
        return Err(bad(key, format!("{} is too large a number", repr(obj))));
    }
    if obj.is_instance_of::<PyFloat>() {
        let x: f64 = obj.extract()?;
        return Number::from_f64(x)
            .map(Value::Number)
            .ok_or_else(|| bad(key, format!("must be a finite number, got {x}")));
    }
    if obj.is_instance_of::<PyString>() {
        return Ok(Value::String(obj.extract()?));
    }
    if let Ok(d) = obj.cast::<PyDict>() {
        return table(d, key, depth);
    }
    if obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() {
        return list(obj, key, depth);
    }
    foreign(obj, key, depth)
}

/// A dict as a JSON object: string keys, each value at `key.name`.
fn table(d: &Bound<'_, PyDict>, key: &str, depth: usize) -> PyResult<Value> {
    let mut map = Map::new();
    for (k, v) in d.iter() {
        let name: String = k.extract().map_err(|_| {
            PyTypeError::new_err(format!(
                "{key}: a table's keys must be strings, got a {}",
                type_name(&k)
            ))
        })?;
        let path = format!("{key}.{name}");
        map.insert(name, value(&v, &path, depth + 1)?);
    }
    Ok(Value::Object(map))
}

/// A list or tuple as a JSON array of at most `MAX_ITEMS` values.
fn list(obj: &Bound<'_, PyAny>, key: &str, depth: usize) -> PyResult<Value> {
    let len = obj.len()?;
    if len > MAX_ITEMS {
        return Err(bad(
            key,
            format!("{len} values, past the {MAX_ITEMS} a list may hold"),
        ));
    }
    let mut items = Vec::with_capacity(len);
    for (i, item) in obj.try_iter()?.enumerate() {
        items.push(value(&item?, &format!("{key}.{i}"), depth + 1)?);
    }
    Ok(Value::Array(items))
}

/// numpy arrays and scalars (their plain values) and paths; anything else
/// is refused with its kind.
fn foreign(obj: &Bound<'_, PyAny>, key: &str, depth: usize) -> PyResult<Value> {
    let py = obj.py();
    let numpy = py.import("sys")?.getattr("modules")?.get_item("numpy").ok();
    if let Some(np) = numpy {
        let is_array = obj.is_instance(&np.getattr("ndarray")?)?;
        let is_scalar = obj.is_instance(&np.getattr("generic")?)?;
        if is_array {
            let size: usize = obj.getattr("size")?.extract()?;
            if size > MAX_ITEMS {
                return Err(bad(
                    key,
                    format!("{size} values, past the {MAX_ITEMS} a list may hold"),
                ));
            }
        }
        if is_array || is_scalar {
            return value(&obj.call_method0("tolist")?, key, depth + 1);
        }
    }
    let os = py.import("os")?;
    if obj.is_instance(&os.getattr("PathLike")?)? {
        return value(&os.call_method1("fspath", (obj,))?, key, depth + 1);
    }
    Err(wrong_kind(key, obj))
}

fn repr(obj: &Bound<'_, PyAny>) -> String {
    obj.repr()
        .map_or_else(|_| "the value".into(), |r| r.to_string())
}

/// A whole number ≥ 0 (`n`, `max_runs`, `index`, `frames`): refuses None,
/// a fraction, a negative number, one past `usize`, and anything not a
/// number, naming `key`.
pub fn whole(obj: &Bound<'_, PyAny>, key: &str) -> PyResult<usize> {
    let v = value(obj, key, 0)?;
    let what = "must be a whole number >= 0";
    match &v {
        Value::Number(n) => {
            if let Some(u) = n.as_u64() {
                return usize::try_from(u).map_err(|_| bad(key, format!("{what}, got {u}")));
            }
            if let Some(x) = n.as_f64()
                && x.fract() == 0.0
                && (0.0..=9.007_199_254_740_992e15).contains(&x)
            {
                return Ok(x as usize);
            }
            Err(bad(key, format!("{what}, got {n}")))
        }
        other => Err(bad(key, format!("{what}, got {}", shown(other)))),
    }
}

/// A whole number ≥ 0, or None for the default.
pub fn whole_or_none(obj: Option<&Bound<'_, PyAny>>, key: &str) -> PyResult<Option<usize>> {
    match obj {
        None => Ok(None),
        Some(o) if o.is_none() => Ok(None),
        Some(o) => whole(o, key).map(Some),
    }
}

/// A finite number, or None for the default.
pub fn number_or_none(obj: Option<&Bound<'_, PyAny>>, key: &str) -> PyResult<Option<f64>> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(None);
    };
    match value(obj, key, 0)? {
        Value::Number(n) => Ok(n.as_f64()),
        other => Err(bad(
            key,
            format!("must be a finite number, got {}", shown(&other)),
        )),
    }
}

/// Times, τ (`samples`): a flat sequence of finite numbers in increasing
/// order, each once; its length given to `check` (the cap on samples)
/// before any value is copied.
pub fn times(
    obj: &Bound<'_, PyAny>,
    key: &str,
    check: &dyn Fn(usize) -> PyResult<()>,
) -> PyResult<Vec<f64>> {
    let len = obj.len().map_err(|_| {
        bad(
            key,
            format!("must be a list of times, got a {}", type_name(obj)),
        )
    })?;
    check(len)?;
    let Value::Array(items) = value(obj, key, 0)? else {
        return Err(bad(
            key,
            format!("must be a list of times, got {}", repr(obj)),
        ));
    };
    let mut out = Vec::with_capacity(items.len());
    for (i, item) in items.iter().enumerate() {
        let Some(t) = item.as_f64() else {
            return Err(bad(
                key,
                format!(
                    "must be a flat list of times, got {} at index {i}",
                    shown(item)
                ),
            ));
        };
        if let Some(&last) = out.last()
            && t <= last
        {
            return Err(bad(
                key,
                format!(
                    "must be increasing times, each once: {t} at index {i} after {last}; \
                     sort them (numpy.unique sorts and drops repeats)"
                ),
            ));
        }
        out.push(t);
    }
    Ok(out)
}

/// A value as a message shows it: strings quoted, lists and tables by kind.
fn shown(v: &Value) -> String {
    match v {
        Value::Null => "None".into(),
        Value::Array(_) => "a list".into(),
        Value::Object(_) => "a dict".into(),
        other => other.to_string(),
    }
}
