//! The one conversion from low-level arguments to domain objects: model,
//! drive and run flags onto a base scene, validated by `Scene::check`, whose
//! key paths are worded here as the flags the user typed.

use super::args::{
    CameraArg, DriveArgs, FigureFormat, GridArgs, KernelArg, MediumArg, MixedFormat, ModelArgs,
    MovieFormat, QualityArg, RunArgs, StartArg, StyleArgs, SweepArgs, ViewArg,
};
use crate::encode;
use crate::error::{Error, Result};
use crate::front;
use crate::render::page_style::parse_length;
use crate::render::{FontChoice, Length, StyleName, StyleSpec, TextMode};
use crate::scene::sweep::{Param, SweepSpec, Values};
use crate::scene::{Camera, Method, OutputSpec, Scene, describe};
use crate::scenes::{MovieOptions, Outputs};
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
    let before = base.clone();
    model.apply(&mut base);
    drive.apply(&mut base);
    run.apply(&mut base)?;
    model.apply_apparatus(&mut base)?;
    // A window fitted to the built-in's chain follows a changed model
    // unless --t-end sets it (`Scene::window_following`).
    if run.t_end.is_none() {
        base = base.window_following(&before);
    }
    checked(base)
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

/// A built-in entry a custom scene starts from: its ID and scene.
pub type Origin<'a> = Option<(&'a str, &'a Scene)>;

/// A custom movie: the paper's scene (or the built-in `origin`) with the
/// flags applied, named by `name` or after what differs (`a70-n20`,
/// `4-a70`).
pub fn movie_scene(
    origin: Origin<'_>,
    name: Option<&str>,
    camera: Option<CameraArg>,
    model: &ModelArgs,
    drive: &DriveArgs,
    run: &RunArgs,
) -> Result<Scene> {
    let mut scene = custom_base(origin);
    if let Some(c) = camera {
        scene.output = OutputSpec::Movie {
            camera: match c {
                CameraArg::Auto => Camera::Auto,
                CameraArg::Fixed => Camera::Fixed,
                CameraArg::Follow => Camera::Follow,
            },
        };
    }
    let scene = scene_from_flags(scene, model, drive, run)?;
    // Checked again with its name: a name that climbs out of --out (`../x`),
    // makes folders (`a/b`) or is empty is refused as a scene file's is.
    checked(named(scene, origin, name))
}

/// A custom figure: a filmstrip at `times` (or a kymograph or arrival
/// chart) of the paper's scene (or of the built-in `origin`, its panels,
/// window and label kept) with the flags applied, named by `name` or after
/// what differs (`t0_900_1100-a70`, `3-n20`).
pub fn figure_scene(
    origin: Origin<'_>,
    name: Option<&str>,
    view: Option<ViewArg>,
    times: Option<&[f64]>,
    flags: (&ModelArgs, &DriveArgs, &RunArgs),
) -> Result<Scene> {
    let (model, drive, run) = flags;
    if let Some((id, base)) = origin {
        check_fits_entry(id, base, view, times, model, run)?;
    }
    let mut scene = custom_base(origin);
    let view = match (view, &scene.output) {
        (None, OutputSpec::Kymograph) => ViewArg::Kymograph,
        (None, OutputSpec::Arrivals { .. }) => ViewArg::Arrivals,
        (None, OutputSpec::Energy) => ViewArg::Energy,
        (None, OutputSpec::Theory(_)) => return finish_theory(scene, origin, name, flags),
        (v, _) => v.unwrap_or(ViewArg::Filmstrip),
    };
    if times.is_some() && view != ViewArg::Filmstrip {
        return Err(Error::bad_input("--times applies only to --view filmstrip"));
    }
    match view {
        ViewArg::Filmstrip => {
            let keep = times.is_none() && matches!(scene.output, OutputSpec::Filmstrip { .. });
            if !keep {
                scene.output = OutputSpec::Filmstrip {
                    times: times.map(<[f64]>::to_vec).unwrap_or_default(),
                    panels: Vec::new(),
                };
            }
        }
        ViewArg::Kymograph => scene.output = OutputSpec::Kymograph,
        ViewArg::Energy => scene.output = OutputSpec::Energy,
        ViewArg::Arrivals => {
            if !matches!(scene.output, OutputSpec::Arrivals { .. }) {
                scene.output = OutputSpec::Arrivals { curves: Vec::new() }
            }
        }
    }
    let scene = scene_from_flags(scene, model, drive, run)?;
    // Checked again with its name: a name that climbs out of --out (`../x`),
    // makes folders (`a/b`) or is empty is refused as a scene file's is.
    checked(named(scene, origin, name))
}

/// A theory figure (`ladder figure 2c --b 1.5`): the model flags applied.
fn finish_theory(
    scene: Scene,
    origin: Origin<'_>,
    name: Option<&str>,
    (model, drive, run): (&ModelArgs, &DriveArgs, &RunArgs),
) -> Result<Scene> {
    let scene = scene_from_flags(scene, model, drive, run)?;
    // Checked again with its name: a name that climbs out of --out (`../x`),
    // makes folders (`a/b`) or is empty is refused as a scene file's is.
    checked(named(scene, origin, name))
}

/// Refuses a flag that a built-in figure's panels (or curves) set each for
/// themselves, and a view or times on a figure of several runs or of the
/// linear theory: the flag would be silently overridden or the figure's
/// panels lost.
fn check_fits_entry(
    id: &str,
    base: &Scene,
    view: Option<ViewArg>,
    times: Option<&[f64]>,
    model: &ModelArgs,
    run: &RunArgs,
) -> Result<()> {
    let edit = format!(
        "print it with `ladder scene {id} > f.toml`, edit the file and `ladder render f.toml`"
    );
    let panels: &[crate::scene::Panel] = match &base.output {
        OutputSpec::Filmstrip { panels, .. } => panels,
        OutputSpec::Arrivals { curves } => curves,
        OutputSpec::Theory(_) if view.is_some() || times.is_some() => {
            return Err(Error::bad_input(format!(
                "figure {id} is drawn from the linear theory: --view and --times apply to \
                 simulated figures (leave out the ID for your own filmstrip)"
            )));
        }
        _ => &[],
    };
    if panels.len() < 2 {
        return Ok(());
    }
    if view.is_some() || times.is_some() {
        return Err(Error::bad_input(format!(
            "figure {id} has {} panels with times of their own: --view and --times would \
             replace them; to change them, {edit}",
            panels.len()
        )));
    }
    // Each model flag given that a panel sets too, then the window.
    let mut given: Vec<(String, bool, bool)> = Param::MODEL
        .into_iter()
        .map(|p| {
            let set = panels.iter().any(|panel| panel.model.get(p).is_some());
            (p.flag(), model.params.get(p).is_some(), set)
        })
        .collect();
    given.push((
        "--t-end".into(),
        run.t_end.is_some(),
        panels.iter().any(|p| p.t_end.is_some()),
    ));
    if let Some((flag, ..)) = given.iter().find(|(_, g, set)| *g && *set) {
        return Err(Error::bad_input(format!(
            "figure {id}: each of its {} panels sets {} itself, so {flag} cannot change it; \
             to change them, {edit}",
            panels.len(),
            flag.trim_start_matches("--").replace('-', "_")
        )));
    }
    Ok(())
}

/// The base of a custom scene: the paper's, or a built-in scene with its
/// window, panels, label and title kept (the title made again from the
/// fields where it had none) and its caption dropped (it describes the
/// original).
fn custom_base(origin: Origin<'_>) -> Scene {
    let mut scene = origin
        .map(|(_, s)| s.clone())
        .unwrap_or_else(auto_window_base);
    scene.caption = None;
    scene
}

/// The paper's scene with `t_end = "auto"`: a movie or figure given no
/// `--t-end` shows every wave's fate (`Scene::with_auto_window`).
fn auto_window_base() -> Scene {
    let mut s = Scene::default();
    s.run.t_end = crate::scene::AUTO_T_END;
    s
}

/// `scene` under `name`, or under a name made from what differs from its
/// origin: `a70-n20` from the paper's scene, `4-a70` from movie 4.
fn named(mut scene: Scene, origin: Origin<'_>, name: Option<&str>) -> Scene {
    scene.name = match (name, origin) {
        (Some(n), _) => n.to_string(),
        (None, Some((id, base))) => match describe::derived_name(&scene, base).as_str() {
            "paper" => id.to_string(),
            d => format!("{id}-{d}"),
        },
        (None, None) => {
            let paper = Scene {
                output: paper_output(&scene.output),
                ..auto_window_base()
            };
            describe::derived_name(&scene, &paper)
        }
    };
    scene
}

/// The output a custom scene of this kind has when no flag changes it:
/// a movie with the auto camera, or a filmstrip at the default times.
fn paper_output(output: &OutputSpec) -> OutputSpec {
    match output {
        OutputSpec::Movie { .. } => OutputSpec::default(),
        _ => OutputSpec::Filmstrip {
            times: Vec::new(),
            panels: Vec::new(),
        },
    }
}

impl MovieFormat {
    /// The movie options, validated ([`front::options::movie_options`]).
    pub fn options(&self) -> Result<MovieOptions> {
        front::options::movie_options(self.frames, self.size, self.fps)
    }

    /// `--quality`, as the encoder's level.
    pub fn mp4_quality(&self) -> encode::Mp4Quality {
        match self.quality {
            QualityArg::Draft => encode::Mp4Quality::Draft,
            QualityArg::Standard => encode::Mp4Quality::Standard,
            QualityArg::High => encode::Mp4Quality::High,
            QualityArg::Best => encode::Mp4Quality::Best,
        }
    }
}

impl FigureFormat {
    /// The figure formats and scale of `ladder figure`.
    pub fn outputs(&self) -> Result<Outputs> {
        if let Some(size) = &self.size {
            return Err(Error::bad_input(format!(
                "--size {size}: a figure keeps its layout and takes no frame size; \
                 use --scale S for S times the PNG's pixels (e.g. --scale 2), \
                 or --format svg,pdf for vector files"
            )));
        }
        front::options::figure_outputs(&self.formats, self.scale, self.style.spec()?)
    }
}

impl MixedFormat {
    /// `ladder render`: every scene has a format of its kind in the list.
    pub fn check_covers(&self, scenes: &[Scene]) -> Result<()> {
        front::options::check_covers(&self.formats, scenes)
    }

    /// The figure and movie formats of `ladder all` and `ladder render`.
    pub fn outputs(&self, movie: &MovieOptions) -> Result<Outputs> {
        front::options::mixed_outputs(&self.formats, self.scale, self.style.spec()?, movie)
    }
}

impl StyleArgs {
    /// The style flags as a [`StyleSpec`], each checked: one line naming
    /// the flag and what it takes.
    pub fn spec(&self) -> Result<StyleSpec> {
        fn named<T>(
            flag: &str,
            v: &Option<String>,
            parse: fn(&str) -> Option<T>,
            names: &[&str],
        ) -> Result<Option<T>> {
            v.as_deref()
                .map(|s| {
                    parse(s).ok_or_else(|| {
                        Error::bad_input(format!("--{flag} {s}: unknown; use {}", names.join(", ")))
                    })
                })
                .transpose()
        }
        let length = |flag: &str, v: &Option<String>| -> Result<Option<Length>> {
            v.as_deref()
                .map(|s| {
                    parse_length(s)
                        .map(Length)
                        .map_err(|e| Error::bad_input(format!("--{flag}: {e}")))
                })
                .transpose()
        };
        let spec = StyleSpec {
            name: named("style", &self.style, StyleName::parse, &StyleName::NAMES)?,
            width: length("width", &self.width)?,
            height: length("height", &self.height)?,
            font_size: self.font_size,
            font: named("font", &self.font, FontChoice::parse, &FontChoice::NAMES)?,
            dpi: self.dpi,
            text: named("text", &self.text, TextMode::parse, &TextMode::NAMES)?,
        };
        // The numbers' ranges, worded as flags (the scene file's table is
        // checked when the scene is drawn).
        spec.resolve()
            .map_err(|e| Error::bad_input(format!("--{e}")))?;
        Ok(spec)
    }
}

impl KernelArg {
    /// The stepping asked for, if this CPU can run it.
    pub fn stepping(self) -> Result<sim::Stepping> {
        let fused = |isa: sim::Isa| {
            if isa.available() {
                Ok(sim::Stepping::Fused(isa))
            } else {
                Err(Error::bad_input(format!(
                    "--kernel {}: this CPU lacks the instruction set; use fastest or portable",
                    isa.name()
                )))
            }
        };
        match self {
            Self::Fastest => Ok(sim::Stepping::Fastest),
            Self::Avx2 => fused(sim::Isa::Avx2),
            Self::Avx512 => fused(sim::Isa::Avx512),
            Self::Portable => Ok(sim::Stepping::Portable),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cli::args::ParamFlags;

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

    #[test]
    fn flags_land_on_the_scene() {
        let model = ModelArgs {
            params: ParamFlags::of(&[(Param::Alpha, 70.0), (Param::N, 20.0)]),
            ..Default::default()
        };
        let drive = DriveArgs {
            second_flip: Some(1500.0),
            ..Default::default()
        };
        let s = movie_scene(None, Some("k70"), None, &model, &drive, &RunArgs::default()).unwrap();
        assert_eq!(
            (s.model.alpha, s.model.n, s.name.as_str()),
            (70.0, 20, "k70")
        );
        assert_eq!(s.drive.flips.len(), 2);
        assert_eq!(s.drive.flips[1].start, 1500.0);
        let bad = ModelArgs {
            params: ParamFlags::of(&[(Param::Alpha, 120.0)]),
            ..Default::default()
        };
        let e = movie_scene(None, None, None, &bad, &drive, &RunArgs::default()).unwrap_err();
        assert!(e.to_string().starts_with("--alpha: "), "{e}");
        assert!(e.to_string().contains("got 120"), "{e}");
    }
}
