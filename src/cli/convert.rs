//! The one conversion from low-level arguments to domain objects: model,
//! drive and run flags onto a base scene, validated by `Scene::check`, whose
//! key paths are worded here as the flags the user typed; a sweep's grid
//! flags onto its scene. Custom movies and figures are `cli::custom`'s,
//! the format flags `cli::formats`'.

use super::args::{DriveArgs, GridArgs, MediumArg, ModelArgs, RunArgs, StartArg, SweepArgs};
use crate::error::{Error, Result};
use crate::scene::sweep::{Param, SweepSpec, Values};
use crate::scene::{Method, OutputSpec, Scene, Table};
use crate::sim;

impl ModelArgs {
    /// Whether any model flag was given.
    pub fn any(&self) -> bool {
        self.params.any()
            || self.start.is_some()
            || self.apparatus.is_some()
            || self.medium.is_some()
    }

    /// `--apparatus FILE` and `--medium` onto `scene`: the file's
    /// `[apparatus]` read as a scene file's (an error says FILE:line:col
    /// and the key), the medium set on the apparatus the scene then has;
    /// the conversion made afresh (`Scene::with_conversion`).
    fn apply_apparatus(&self, scene: &mut Scene) -> Result<()> {
        if let Some(path) = &self.apparatus {
            let from = crate::scene::file::load(path)?;
            let Some(a) = from.apparatus else {
                return Err(Error::bad_input(format!(
                    "--apparatus: {} has no [apparatus] table (its keys: docs/experiments.md)",
                    path.display()
                )));
            };
            scene.apparatus = Some(a);
        }
        if let Some(medium) = self.medium {
            let Some(a) = scene.apparatus.as_mut() else {
                return Err(Error::bad_input(
                    "--medium: the scene has no apparatus; give --apparatus FILE (or a built-in \
                     scene with one: water-tank, linkage-69)",
                ));
            };
            a.medium = match medium {
                MediumArg::Air => crate::scene::apparatus::Medium::Air,
                MediumArg::Water => crate::scene::apparatus::Medium::Water,
            };
            // The medium's own density, not the one the file gave for
            // the other medium.
            a.medium_density = None;
        }
        if self.apparatus.is_some() || self.medium.is_some() {
            *scene = std::mem::take(scene).with_conversion();
        }
        Ok(())
    }

    fn apply(&self, scene: &mut Scene) {
        for (p, x) in self.params.given() {
            scene.set_param(p, x);
        }
        let m = &mut scene.model;
        m.start = self.start.map_or(m.start, |s| match s {
            StartArg::Ground => sim::Start::Ground,
            StartArg::Relaxed => sim::Start::Relaxed,
        });
    }
}

impl DriveArgs {
    pub fn any(&self) -> bool {
        self.drive_time.is_some() || self.flips.is_some() || self.second_flip.is_some()
    }

    /// The drive flags onto `scene`'s drive ([`DriveSpec::reshaped`]).
    pub fn apply(&self, scene: &mut Scene) {
        if self.any() {
            scene.drive =
                scene
                    .drive
                    .reshaped(self.drive_time, self.flips.as_deref(), self.second_flip);
        }
    }
}

impl RunArgs {
    pub fn any(&self) -> bool {
        self.t_end.is_some()
            || self.integrator.is_some()
            || self.dt.is_some()
            || self.tol.rtol.is_some()
            || self.tol.tolerance.is_some()
    }

    fn apply(&self, scene: &mut Scene) -> Result<()> {
        let r = &mut scene.run;
        if let Some(name) = &self.integrator {
            r.integrator = parse_method(name)?;
        }
        r.t_end = self.t_end.unwrap_or(r.t_end);
        r.dt = self.dt.or(r.dt);
        r.rtol = self.tol.rtol.or(r.rtol);
        r.tolerance = self.tol.tolerance.unwrap_or(r.tolerance);
        Ok(())
    }
}

/// `--integrator NAME`.
pub fn parse_method(name: &str) -> Result<Method> {
    name.parse()
        .map_err(|e: Error| Error::bad_input(format!("--integrator: {e}")))
}

/// The flags applied to `base`, then validated; an error names the flag.
pub fn scene_from_flags(
    mut base: Scene,
    model: &ModelArgs,
    drive: &DriveArgs,
    run: &RunArgs,
) -> Result<Scene> {
    for (flag, table) in given_flags(model, drive, run) {
        if let Some(why) = base.sets_nothing(table) {
            let hint = match base.rings {
                Some(_) => ": `ladder scene ID > rings.toml`, edit, `ladder render rings.toml`",
                None => "",
            };
            return Err(Error::bad_input(format!("{flag}: {why}{hint}")));
        }
    }
    let before = base.clone();
    model.apply(&mut base);
    drive.apply(&mut base);
    let drive_given = drive.any().then(|| base.drive.clone());
    run.apply(&mut base)?;
    model.apply_apparatus(&mut base)?;
    // The flags are the window and the drive, whatever `duration` and
    // `motor` the apparatus gives.
    if let Some(t) = run.t_end {
        base = base.with_t_end(t);
    }
    if let Some(d) = drive_given {
        base = base.with_drive(d);
    }
    if let Some(a) = &base.apparatus {
        for (p, _) in model.params.given() {
            if let Some(why) = a.replaces(p) {
                return Err(Error::bad_input(format!(
                    "--{}: {why}",
                    p.name().replace('_', "-")
                )));
            }
        }
    }
    // A window fitted to the built-in's chain follows a changed model
    // unless --t-end sets it (`Scene::window_following`).
    if run.t_end.is_none() {
        base = base.window_following(&before);
    }
    checked(base)
}

/// The model, drive and run flags given, by name (`--alpha`,
/// `--drive-time`, `--t-end`), each with the table it sets.
fn given_flags(model: &ModelArgs, drive: &DriveArgs, run: &RunArgs) -> Vec<(String, Table)> {
    let params = model
        .params
        .given()
        .map(|(p, _)| (format!("--{}", p.name().replace('_', "-")), Table::Model));
    let named = [
        (model.start.is_some(), "--start", Table::Model),
        (model.apparatus.is_some(), "--apparatus", Table::Apparatus),
        (model.medium.is_some(), "--medium", Table::Apparatus),
        (drive.drive_time.is_some(), "--drive-time", Table::Drive),
        (drive.flips.is_some(), "--flips", Table::Drive),
        (drive.second_flip.is_some(), "--second-flip", Table::Drive),
        (run.t_end.is_some(), "--t-end", Table::Run),
        (run.integrator.is_some(), "--integrator", Table::Run),
        (run.dt.is_some(), "--dt", Table::Run),
        (run.tol.rtol.is_some(), "--rtol", Table::Run),
        (run.tol.tolerance.is_some(), "--tolerance", Table::Run),
    ];
    let named = named
        .into_iter()
        .filter(|(given, _, _)| *given)
        .map(|(_, flag, table)| (flag.to_string(), table));
    params.chain(named).collect()
}

/// `Scene::check`, its key path worded as the flag that sets it.
pub fn checked(scene: Scene) -> Result<Scene> {
    scene
        .check()
        .map_err(|(key, msg)| Error::bad_input(format!("{}: {msg}", flag_of(&key))))?;
    Ok(scene)
}

/// The command-line flag that sets a scene key.
fn flag_of(key: &str) -> String {
    let last = key.rsplit('.').next().unwrap_or(key);
    if key.starts_with("apparatus.") {
        // The apparatus came from --apparatus FILE (checked with its
        // lines there) or the scene, with --medium set on it.
        return format!("--apparatus/--medium ({key})");
    }
    let flag = if key.starts_with("drive.flips") {
        if matches!(last, "duration") {
            "--drive-time"
        } else {
            "--flips"
        }
    } else if key.starts_with("output.times") || key.ends_with(".times") {
        "--times"
    } else {
        match last {
            "t_end" => "--t-end",
            other => return format!("--{}", other.replace('_', "-")),
        }
    };
    flag.to_string()
}

impl GridArgs {
    /// The grid flags given, in the order of [`Param::ALL`].
    pub fn given(&self) -> Vec<(Param, &str)> {
        self.axes.given()
    }
}

/// The sweep scene of `ladder sweep`: the sweep file (or the paper's
/// scene), its grid extended or replaced by the grid flags, the run and
/// outcome flags applied, validated; an error names the flag.
pub fn sweep_scene(args: &SweepArgs) -> Result<Scene> {
    // `--out` names the folder of the sweep's files, as for every command.
    crate::front::render::check_out_dir(&args.out.out)?;
    let grid = args.grid.given();
    let mut scene = match &args.file {
        Some(path) => {
            let s = crate::scene::file::load(path)?;
            if !matches!(s.output, OutputSpec::Sweep(_)) {
                return Err(Error::bad_input(format!(
                    "{}: not a sweep file: its [output] kind must be \"sweep\" with the grid in [output.grid] (docs/sweeps.md)",
                    path.display()
                )));
            }
            s
        }
        None if grid.is_empty() => {
            return Err(Error::bad_input(format!(
                "ladder sweep needs a sweep file or at least one grid flag: --{} (e.g. --alpha=-45:-60:-0.5)",
                Param::ALL.map(Param::flag).join(", ")
            )));
        }
        None => Scene {
            output: OutputSpec::Sweep(SweepSpec::default()),
            ..Scene::default()
        },
    };
    if let Some(name) = &args.name {
        scene.name = name.clone();
    }
    let OutputSpec::Sweep(spec) = &mut scene.output else {
        unreachable!("checked above")
    };
    for (param, text) in grid {
        let flag = param.flag();
        let values = Values::parse(text).map_err(|m| Error::bad_input(format!("{flag}: {m}")))?;
        values
            .expand(param)
            .map_err(|m| Error::bad_input(format!("{flag}: {m}")))?;
        match spec.grid.0.iter_mut().find(|(p, _)| *p == param) {
            Some(axis) => axis.1 = values,
            None => spec.grid.0.push((param, values)),
        }
    }
    if let Some(cap) = args.cap {
        spec.cap = cap;
    }
    if args.quiet.is_some() {
        return Err(Error::bad_input(format!(
            "--quiet: {}",
            crate::scene::sweep::QUIET_REMOVED
        )));
    }
    args.run.apply(&mut scene)?;
    if let Some(start) = args.start {
        scene.model.start = match start {
            StartArg::Ground => sim::Start::Ground,
            StartArg::Relaxed => sim::Start::Relaxed,
        };
    }
    if args.run.t_end.is_some()
        && args.cap.is_none()
        && let OutputSpec::Sweep(spec) = &mut scene.output
    {
        spec.cap = spec.cap.max(scene.run.t_end);
    }
    checked(scene)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sweep_keys_are_worded_as_flags() {
        assert_eq!(flag_of("output.grid.alpha"), "--alpha");
        assert_eq!(flag_of("output.grid.drive_time"), "--drive-time");
        assert_eq!(flag_of("output.cap"), "--cap");
    }

    #[test]
    fn keys_are_worded_as_flags() {
        assert_eq!(flag_of("model.alpha"), "--alpha");
        assert_eq!(flag_of("run.t_end"), "--t-end");
        assert_eq!(flag_of("drive.flips.1"), "--flips");
        assert_eq!(flag_of("drive.flips.0.duration"), "--drive-time");
        assert_eq!(flag_of("output.times"), "--times");
    }
}
