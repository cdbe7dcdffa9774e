//! Custom scenes of `ladder movie` and `ladder figure`: the paper's
//! scene or a built-in one with the flags applied, its view and times
//! set, refused where a built-in's panels set a flag themselves, and named
//! after what differs (`scene::names`).

use super::args::{CameraArg, DriveArgs, ModelArgs, RunArgs, ViewArg};
use super::convert::{checked, scene_from_flags};
use crate::error::{Error, Result};
use crate::scene::params::Param;
use crate::scene::{Camera, OutputSpec, Scene, describe};

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cli::args::ParamFlags;

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
