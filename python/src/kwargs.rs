//! Keyword arguments → a scene, through serde: the keywords arrive as one
//! JSON object, are merged into the scene's JSON value and read back as a
//! `Scene`, so every scene key works from Python without new code.
//!
//! - The command line's long flags, with underscores: `alpha`, `n`, `b`,
//!   `gamma`, `gravity`, `inertia` (→ `[model]`), `t_end`, `integrator`,
//!   `dt`, `rtol`, `tolerance` (→ `[run]`), and `drive_time`, `flips`,
//!   `second_flip` (→ `[drive]`, as the flags do it).
//! - Any top-level scene key (`name`, `title`, `model`, `drive`, `run`,
//!   `output`, ...), merged table by table into the scene's.
//! - A dotted key path (`"run.tolerance"`, `"output.camera"`).
//!
//! Errors are `ValueError`s naming the key path, as a scene file's do
//! (`model.alpha: must be degrees with 0 < |alpha| < 90, got 120`).

use jacobs_ladder::scene::Scene;
use jacobs_ladder::{Error, Result};
use serde_json::{Map, Value};

/// The flags that set `[model]` keys.
const MODEL: [&str; 6] = ["alpha", "n", "b", "gamma", "gravity", "inertia"];
/// The flags that set `[run]` keys.
const RUN: [&str; 5] = ["t_end", "integrator", "dt", "rtol", "tolerance"];
/// The flags that set the drive.
const DRIVE: [&str; 3] = ["drive_time", "flips", "second_flip"];

/// `scene` with the keywords of the JSON object `kwargs` applied, checked.
pub fn apply(scene: &Scene, kwargs: &str) -> Result<Scene> {
    let kwargs: Map<String, Value> = serde_json::from_str(kwargs)
        .map_err(|e| Error::bad_input(format!("keywords must be plain values: {e}")))?;
    let mut scene = scene.clone();
    let (drive_time, flips, second_flip) = drive_args(&kwargs)?;
    if drive_time.is_some() || flips.is_some() || second_flip.is_some() {
        scene.drive = scene
            .drive
            .reshaped(drive_time, flips.as_deref(), second_flip);
    }
    let mut value = serde_json::to_value(&scene)
        .map_err(|e| Error::failed(format!("cannot encode the scene: {e}")))?;
    for (key, v) in kwargs {
        if DRIVE.contains(&key.as_str()) {
            continue;
        }
        let path: Vec<&str> = if MODEL.contains(&key.as_str()) {
            vec!["model", &key]
        } else if RUN.contains(&key.as_str()) {
            vec!["run", &key]
        } else {
            key.split('.').collect()
        };
        set(&mut value, &path, v);
    }
    let scene: Scene = serde_path_to_error::deserialize(value).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner().to_string();
        if inner.starts_with("unknown field") && !path.contains('.') {
            Error::bad_input(format!(
                "{inner}; or one of the keywords {}",
                [&MODEL[..], &RUN[..], &DRIVE[..]].concat().join(", ")
            ))
        } else {
            Error::bad_input(format!("{path}: {inner}"))
        }
    })?;
    checked(scene)
}

/// `Scene::check`, its error as `key.path: message`.
pub fn checked(scene: Scene) -> Result<Scene> {
    scene
        .check()
        .map_err(|(key, msg)| Error::bad_input(format!("{key}: {msg}")))?;
    Ok(scene)
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
    if args.1.is_some() && args.2.is_some() {
        return Err(Error::bad_input(
            "flips and second_flip: give one (second_flip=T is flips=[0, T])",
        ));
    }
    Ok(args)
}

/// Sets the value at `path`, merging tables into tables.
fn set(value: &mut Value, path: &[&str], new: Value) {
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
    merge(here, new);
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
