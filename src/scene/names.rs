//! The file name of a custom scene, made from what differs from the
//! scene it started from (docs/scenes.md): `a70-n20`, `4-a70`,
//! `kymograph-a-60`. Each parameter's mark is the parameter table's
//! (`model::table`, `tag`).

use super::{AUTO_T_END, Camera, Flip, OutputSpec, Scene};
use crate::model::Param;

/// A file name made from what differs between `scene` and `base`
/// (docs/scenes.md): "a70-n20" for α = 70° and N = 20 on the paper's scene,
/// "kymograph-a-60" for an antikink's kymograph. Two scenes that differ
/// get different names; "paper" when nothing differs. Letters, digits,
/// `-` and `.` only; a name over 80 characters keeps its start and ends
/// with a hash of the rest.
pub fn derived_name(scene: &Scene, base: &Scene) -> String {
    let mut parts = model_parts(scene, base);
    parts.extend(drive_parts(scene, base));
    parts.extend(run_parts(scene, base));
    parts.extend(output_parts(scene, base));
    if parts.is_empty() {
        return "paper".into();
    }
    shortened(parts.join("-"))
}

/// Each model parameter that differs (`a70`, `n20`), then the start.
fn model_parts(scene: &Scene, base: &Scene) -> Vec<String> {
    let (m, b) = (&scene.model, &base.model);
    let mut parts: Vec<String> = m
        .values()
        .zip(b.values())
        .filter(|((_, x), (_, y))| x != y)
        .map(|((p, x), _)| format!("{}{}", p.spec().tag, token(x)))
        .collect();
    if m.start != b.start {
        parts.push(m.start.to_string());
    }
    parts
}

/// The flips' starts where they differ (`flips0_1500`), and a drive time
/// where one differs from the base's (`td700`): a second flip at the
/// base's drive time asks for no `td`.
fn drive_parts(scene: &Scene, base: &Scene) -> Vec<String> {
    let mut parts = Vec::new();
    let (d, bd) = (&scene.drive.flips, &base.drive.flips);
    let starts = |f: &[Flip]| f.iter().map(|f| f.start).collect::<Vec<_>>();
    if starts(d) != starts(bd) {
        let s: Vec<String> = d.iter().map(|f| token(f.start)).collect();
        parts.push(format!("flips{}", s.join("_")));
    }
    let base_td = bd.first().map(|f| f.duration);
    if let Some(f) = d.iter().find(|f| Some(f.duration) != base_td) {
        parts.push(format!(
            "{}{}",
            Param::DriveTime.spec().tag,
            token(f.duration)
        ));
    }
    parts
}

/// The window, integrator, step and tolerances where they differ.
fn run_parts(scene: &Scene, base: &Scene) -> Vec<String> {
    let mut parts = Vec::new();
    let (r, br) = (&scene.run, &base.run);
    // The window the change of model gives by itself
    // (`Scene::window_following`) is no request of the user's: not named;
    // any other window is (the base's own number too, where the change
    // would have made it `auto`).
    let followed = {
        let mut s = scene.clone();
        s.run.t_end = br.t_end;
        s.window_following(base).run.t_end
    };
    if r.t_end != followed {
        let t = if r.t_end == AUTO_T_END {
            "auto".to_string()
        } else {
            token(r.t_end)
        };
        parts.push(format!("to{t}"));
    }
    if r.integrator != br.integrator {
        parts.push(r.integrator.to_string());
    }
    if r.dt != br.dt
        && let Some(dt) = r.dt
    {
        parts.push(format!("dt{}", token(dt)));
    }
    if r.rtol != br.rtol
        && let Some(x) = r.rtol
    {
        parts.push(format!("rtol{}", token(x)));
    }
    if r.tolerance != br.tolerance {
        parts.push(format!("tol{}", token(r.tolerance)));
    }
    parts
}

/// The view where it differs: `follow`, `filmstrip-t900_1100`,
/// `kymograph`, `arrivals`, `energy`.
fn output_parts(scene: &Scene, base: &Scene) -> Vec<String> {
    let mut parts = Vec::new();
    match (&scene.output, &base.output) {
        (a, b) if a == b => {}
        (OutputSpec::Movie { camera }, OutputSpec::Movie { .. }) => {
            parts.push(camera_word(*camera).into());
        }
        (OutputSpec::Filmstrip { times, .. }, _) => {
            if !matches!(base.output, OutputSpec::Filmstrip { .. }) {
                parts.push("filmstrip".into());
            }
            if !times.is_empty() {
                let t: Vec<String> = times.iter().map(|t| token(*t)).collect();
                parts.push(format!("t{}", t.join("_")));
            }
        }
        (OutputSpec::Kymograph, _) => parts.push("kymograph".into()),
        (OutputSpec::Arrivals { .. }, _) => parts.push("arrivals".into()),
        (OutputSpec::Energy, _) => parts.push("energy".into()),
        _ => {}
    }
    parts
}

/// The camera's word in a derived name.
fn camera_word(c: Camera) -> &'static str {
    match c {
        Camera::Auto => "auto",
        Camera::Fixed => "fixed",
        Camera::Follow => "follow",
    }
}

/// A number in a file name: 70, -60, 1.5, 0.0002 (as Rust prints it,
/// which reads back to the same number).
fn token(x: f64) -> String {
    format!("{x}")
}

/// `name`, cut to 80 characters with a hash (FNV-1a) of the whole so that
/// names that differ stay different.
fn shortened(name: String) -> String {
    const MAX: usize = 80;
    if name.len() <= MAX {
        return name;
    }
    let hash = name.bytes().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    });
    format!("{}-{hash:016x}", &name[..MAX - 17])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_second_flip_names_no_drive_time() {
        let base = Scene::default();
        let mut s = base.clone();
        s.drive.flips.push(Flip {
            start: 1500.0,
            duration: base.drive.flips[0].duration,
        });
        assert_eq!(derived_name(&s, &base), "flips0_1500");
        s.drive.flips[1].duration = 700.0;
        assert_eq!(derived_name(&s, &base), "flips0_1500-td700");
        let mut m = base.clone();
        m.model.alpha = 70.0;
        m.model.n = 20;
        m.model.gravity = 0.0;
        assert_eq!(derived_name(&m, &base), "a70-n20-grav0");
        assert_eq!(derived_name(&base, &base), "paper");
    }
}
