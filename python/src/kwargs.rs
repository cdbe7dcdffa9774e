//! Keyword arguments → a scene, through serde: the keywords arrive as one
//! JSON object (`convert::keywords`), are merged into the scene's JSON value and read back as a
//! `Scene`, so every scene key works from Python without new code.
//!
//! - The command line's long flags, with underscores: the parameter
//!   table's (`scene::params`: `alpha`, `n`, ... → `[model]`, and
//!   `drive_time` → `[drive]`), `t_end`, `integrator`, `dt`, `rtol`,
//!   `tolerance` (→ `[run]`), and `flips`, `second_flip` (→ `[drive]`, as
//!   the flags do it).
//! - Any top-level scene key (`name`, `title`, `model`, `drive`, `run`,
//!   `output`, ...), merged table by table into the scene's.
//! - A dotted key path (`"run.tolerance"`, `"output.camera"`).
//!
//! Errors are `ValueError`s naming the key path, as a scene file's do
//! (`model.alpha: must be degrees with 0 < |alpha| < 90, got 120`).
//!
//! Two keywords that set the same key (`t_end=100` and `run={"t_end":
//! 4000}`, or `run={...}` and `**{"run.t_end": ...}`) are refused, naming
//! both: which would win is not for alphabetical order to say. The others
//! are applied shortest path first, so that a dotted key changes the table
//! another keyword gave. A list where the scene has a table
//! (`model=[70, 20]`) is refused: a table's keys are named.

use jacobs_ladder::scene::params::{Param, Place};
use jacobs_ladder::scene::{Scene, Table};
use jacobs_ladder::{Error, Result};
use serde_json::{Map, Value};

/// The flags that set `[run]` keys.
const RUN: [&str; 5] = ["t_end", "integrator", "dt", "rtol", "tolerance"];
/// The drive's flags beside the table's drive time: where and how often
/// block 1 flips.
const DRIVE_FLIPS: [&str; 2] = ["flips", "second_flip"];

/// Whether `key` is a parameter of the table set in `place`.
fn in_table(key: &str, place: Place) -> bool {
    Param::from_name(key).is_some_and(|p| p.spec().place == place)
}

/// Whether `key` is a keyword that sets `[model]` (the table's model
/// parameters).
fn is_model(key: &str) -> bool {
    in_table(key, Place::Model)
}

/// Whether `key` is a keyword that reshapes the drive (the table's drive
/// time, the flips).
fn is_drive(key: &str) -> bool {
    in_table(key, Place::Drive) || DRIVE_FLIPS.contains(&key)
}

/// The table `key` sets (a keyword of a flag, or a key path under
/// `model`, `drive`, `run` or `apparatus`), if one of those.
fn table_of(key: &str) -> Option<Table> {
    let root = key.split('.').next().unwrap_or(key);
    if is_model(key) || root == "model" {
        Some(Table::Model)
    } else if is_drive(key) || root == "drive" {
        Some(Table::Drive)
    } else if RUN.contains(&key) || root == "run" {
        Some(Table::Run)
    } else if root == "apparatus" {
        Some(Table::Apparatus)
    } else {
        None
    }
}

/// Every keyword of a flag, for messages: the table's, then the run's and
/// the drive's.
fn keyword_names() -> Vec<&'static str> {
    let mut names: Vec<&str> = Param::ALL.iter().map(|p| p.name()).collect();
    names.extend(RUN);
    names.extend(DRIVE_FLIPS);
    names
}

/// `scene` with the keywords `kwargs` applied, checked.
pub fn apply(scene: &Scene, kwargs: Map<String, Value>) -> Result<Scene> {
    let before = scene.clone();
    // A keyword that would set nothing run (a ring chain's ladder, a
    // drawing's drive or run) is refused, naming it (`Scene::sets_nothing`).
    for key in kwargs.keys() {
        if let Some(why) = table_of(key).and_then(|t| before.sets_nothing(t)) {
            return Err(Error::bad_input(format!("{key}: {why}")));
        }
    }
    let mut scene = scene.clone();
    let (drive_time, flips, second_flip) = drive_args(&kwargs)?;
    if drive_time.is_some() || flips.is_some() || second_flip.is_some() {
        scene.drive = scene
            .drive
            .reshaped(drive_time, flips.as_deref(), second_flip);
    }
    let mut value = serde_json::to_value(&scene)
        .map_err(|e| Error::failed(format!("cannot encode the scene: {e}")))?;
    // Each keyword's path in the scene, then every key it sets.
    let mut given: Vec<(Vec<String>, String, Value)> = Vec::new();
    for (key, v) in kwargs {
        if is_drive(&key) {
            given.push((vec!["drive".into()], key, Value::Null));
            continue;
        }
        // A print style by its name (`style="paper"`), as `--style paper`.
        let v = match (key.as_str(), v) {
            ("style", Value::String(name)) => {
                Value::Object(Map::from_iter([("name".to_string(), Value::String(name))]))
            }
            (_, v) => v,
        };
        let path: Vec<String> = if is_model(&key) {
            vec!["model".into(), key.clone()]
        } else if RUN.contains(&key.as_str()) {
            vec!["run".into(), key.clone()]
        } else {
            key.split('.').map(str::to_string).collect()
        };
        if path.iter().any(String::is_empty) {
            return Err(Error::bad_input(format!(
                "{key}: not a key path (an empty part between dots)"
            )));
        }
        given.push((path, key, v));
    }
    check_conflicts(&given)?;
    given.sort_by_key(|(path, _, _)| path.len());
    for (path, key, v) in given {
        if is_drive(&key) {
            continue;
        }
        let path: Vec<&str> = path.iter().map(String::as_str).collect();
        set(&mut value, &path, v, &key)?;
    }
    let scene: Scene = serde_path_to_error::deserialize(value).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner().to_string();
        if inner.starts_with("unknown field") && !path.contains('.') {
            Error::bad_input(format!(
                "{inner}; or one of the keywords {}",
                keyword_names().join(", ")
            ))
        } else {
            Error::bad_input(format!("{path}: {inner}"))
        }
    })?;
    // A model value the apparatus would replace is refused, naming it.
    if let Some(a) = &scene.apparatus {
        for p in Param::ALL {
            let changed = scene.param(p).to_bits() != before.param(p).to_bits();
            if let Some(why) = a.replaces(p).filter(|_| changed) {
                return Err(Error::bad_input(format!("{}: {why}", p.name())));
            }
        }
    }
    // A window given (`t_end=`, `run={"t_end": ...}`) replaces an
    // apparatus' `duration`, and a drive given its `motor`, as the
    // flags do (`Scene::with_t_end`, `Scene::with_drive`).
    let mut scene = scene;
    if scene.run.t_end.to_bits() != before.run.t_end.to_bits() {
        let t = scene.run.t_end;
        scene = scene.with_t_end(t);
    }
    if scene.drive != before.drive {
        let d = scene.drive.clone();
        scene = scene.with_drive(d);
    }
    checked(scene)
}

/// `Scene::check`, its error as `key.path: message`; then the
/// apparatus' conversion made afresh (`Scene::with_conversion`), as a
/// scene file's: a keyword that changes α or the apparatus leaves no
/// stale `apparatus.conversion` in `Run.record`.
pub fn checked(scene: Scene) -> Result<Scene> {
    scene
        .check()
        .map_err(|(key, msg)| Error::bad_input(format!("{key}: {msg}")))?;
    Ok(scene.with_conversion())
}

/// The drive keywords (`drive_time`, `flips`, `second_flip`), typed as
/// the flags are.
type DriveKeywords = (Option<f64>, Option<Vec<f64>>, Option<f64>);

fn drive_args(kwargs: &Map<String, Value>) -> Result<DriveKeywords> {
    fn get<T: serde::de::DeserializeOwned>(
        kwargs: &Map<String, Value>,
        key: &str,
        what: &str,
    ) -> Result<Option<T>> {
        match kwargs.get(key) {
            None | Some(Value::Null) => Ok(None),
            Some(v) => serde_json::from_value(v.clone())
                .map(Some)
                .map_err(|_| Error::bad_input(format!("{key}: must be {what}, got {v}"))),
        }
    }
    let args: DriveKeywords = (
        get(kwargs, "drive_time", "a time in τ")?,
        get(kwargs, "flips", "a list of start times in τ")?,
        get(kwargs, "second_flip", "a time in τ")?,
    );
    // Checked here, in the keywords' words (the scene would name the
    // flips they reshape): the drive time by the table's range.
    if let Some(t) = args.0 {
        let p = Param::DriveTime;
        p.spec()
            .check(t, true)
            .map_err(|m| Error::bad_input(format!("{}: {m}", p.name())))?;
    }
    if let Some(t) = args.2
        && !(t.is_finite() && t >= 0.0)
    {
        return Err(Error::bad_input(format!(
            "second_flip: must be a finite time >= 0, got {t}"
        )));
    }
    if args.1.is_some() && args.2.is_some() {
        return Err(Error::bad_input(
            "flips and second_flip: give one (second_flip=T is flips=[0, T])",
        ));
    }
    Ok(args)
}

/// The keys a keyword sets: its path, and below it every leaf of the
/// tables it gives (a drive flag sets all of `drive`).
fn leaves(path: &[String], v: &Value, out: &mut Vec<Vec<String>>) {
    match v {
        Value::Object(m) if !m.is_empty() && !m.contains_key("kind") => {
            for (k, v) in m {
                let mut p = path.to_vec();
                p.push(k.clone());
                leaves(&p, v, out);
            }
        }
        _ => out.push(path.to_vec()),
    }
}

/// Refuses two keywords that set one key (or a key and a table that holds
/// it), naming both.
fn check_conflicts(given: &[(Vec<String>, String, Value)]) -> Result<()> {
    let sets: Vec<Vec<Vec<String>>> = given
        .iter()
        .map(|(path, _, v)| {
            let mut out = Vec::new();
            leaves(path, v, &mut out);
            out
        })
        .collect();
    let flag = |i: usize| is_drive(&given[i].1);
    for i in 0..given.len() {
        for j in i + 1..given.len() {
            // The drive flags reshape one drive together (`drive_args`).
            if flag(i) && flag(j) {
                continue;
            }
            for a in &sets[i] {
                for b in &sets[j] {
                    if a.starts_with(b) || b.starts_with(a) {
                        let key = if a.len() >= b.len() { a } else { b };
                        return Err(Error::bad_input(format!(
                            "{}: given twice, by the keywords {} and {}; give it once",
                            key.join("."),
                            given[i].1,
                            given[j].1
                        )));
                    }
                }
            }
        }
    }
    Ok(())
}

/// Sets the value at `path`, merging tables into tables; `key` is the
/// keyword, for errors.
fn set(value: &mut Value, path: &[&str], new: Value, key: &str) -> Result<()> {
    let mut here = value;
    for p in path {
        if !here.is_object() {
            *here = Value::Object(Map::new());
        }
        here = here
            .as_object_mut()
            .expect("made a table above")
            .entry(p.to_string())
            .or_insert(Value::Null);
    }
    if here.is_object() && !new.is_object() && !new.is_null() {
        return Err(Error::bad_input(format!(
            "{}: is a table of named keys; give a dict ({key}={{...}}) or a dotted key, got {}",
            path.join("."),
            match &new {
                Value::Array(_) => "a list".to_string(),
                other => other.to_string(),
            }
        )));
    }
    merge(here, new);
    Ok(())
}

/// `new` into `slot`: a table key by key into a table, anything else in
/// its place. A table that names its `kind` (an `[output]`) replaces the
/// old one whole: the keys of one kind are not those of another.
fn merge(slot: &mut Value, new: Value) {
    match (slot, new) {
        (Value::Object(old), Value::Object(new)) if !new.contains_key("kind") => {
            for (k, v) in new {
                merge(old.entry(k).or_insert(Value::Null), v);
            }
        }
        (slot, new) => *slot = new,
    }
}
