//! Words for a scene, generated from its fields (never retyped): the
//! title drawn on a picture and the parameter line of the gallery and of
//! `ladder list`.

use super::{Camera, DriveSpec, Model, OutputSpec, Scene};

/// A number as a reader writes it: 60, 1.3, 0.0002 → 2e-4, with a
/// typographic minus sign.
pub fn num(x: f64) -> String {
    let s = if x != 0.0 && (x.abs() < 1e-3 || x.abs() >= 1e6) {
        let e = format!("{x:e}");
        e.replace("e-", "e−")
    } else {
        let r = (x * 1e9).round() / 1e9;
        format!("{r}")
    };
    s.replace('-', "−")
}

/// "kink, α = 60°" or "antikink, α = −60°".
pub fn wave(model: &Model) -> String {
    format!("{}, α = {}°", model.wave(), num(model.alpha))
}

/// The scene's title: its label, then its own title or one made from its
/// fields ("Movie 4: kink, α = 60°").
pub fn title(scene: &Scene) -> String {
    let body = scene
        .title
        .clone()
        .unwrap_or_else(|| generated_title(scene));
    match &scene.label {
        Some(l) => format!("{l}: {body}"),
        None => body,
    }
}

/// A title made from the fields.
pub fn generated_title(scene: &Scene) -> String {
    let m = &scene.model;
    let mut t = wave(m);
    let default = Model::default();
    if m.n != default.n {
        t.push_str(&format!(", N = {}", m.n));
    }
    if m.b != default.b {
        t.push_str(&format!(", b/s = {}", num(m.b)));
    }
    if scene.drive.flips.len() > 1 {
        t = format!("{} flips of block 1, {t}", scene.drive.flips.len());
    }
    match &scene.output {
        OutputSpec::Movie {
            camera: Camera::Follow,
        } => format!("{t}, camera following the kink"),
        OutputSpec::Arrivals { .. } => format!("arrival times, {t}"),
        OutputSpec::Kymograph => format!("{t}: sin θₙ"),
        OutputSpec::Sweep(sw) => sw.title(m),
        _ => t,
    }
}

/// "α = 60°, N = 10, b/s = 1.3, γ = 0.02, G = 2e−4, I = 0.25 ms²".
pub fn model(m: &Model) -> String {
    format!(
        "α = {}°, N = {}, b/s = {}, γ = {}, G = {}, I = {} ms²",
        num(m.alpha),
        m.n,
        num(m.b),
        num(m.gamma),
        num(m.gravity),
        num(m.inertia)
    )
}

/// "block 1 turned α → −α over 0–1000 τ, and back over 1500–2500 τ".
pub fn drive(d: &DriveSpec) -> String {
    if d.flips.is_empty() {
        return "block 1 held at α".into();
    }
    let parts: Vec<String> = d
        .flips
        .iter()
        .enumerate()
        .map(|(k, f)| {
            let turn = if k % 2 == 0 {
                "α → −α"
            } else {
                "−α → α"
            };
            format!("{turn} over {}–{} τ", num(f.start), num(f.end()))
        })
        .collect();
    format!("block 1 turned {}", parts.join(", then "))
}

/// Everything a reader needs to rerun the scene, in one line.
pub fn parameters(scene: &Scene) -> String {
    match &scene.output {
        OutputSpec::Theory(t) => {
            let m = &scene.model;
            let mut s = format!("N = {}, b/s = {}", m.n, num(m.b));
            if t.alphas.is_empty() {
                s.push_str(&format!(", α = {}°", num(m.alpha)));
            } else {
                let list: Vec<String> = t.alphas.iter().map(|a| num(*a)).collect();
                s.push_str(&format!(", α = {}°", list.join("°, ")));
            }
            if !t.a_over_b.is_empty() {
                let list: Vec<String> = t.a_over_b.iter().map(|a| num(*a)).collect();
                s.push_str(&format!(", a/b = {}", list.join(", ")));
            }
            for z in &t.modes {
                s.push_str(&format!(", mode m = {} (ε₀ = {})", z.m, num(z.epsilon)));
            }
            s
        }
        OutputSpec::Sweep(sw) => format!(
            "{}; {}; window {} τ, continued until decided (at most {} τ); grid: {}",
            model(&scene.model),
            drive(&scene.drive),
            num(scene.run.t_end),
            num(sw.cap),
            sw.describe_grid()
        ),
        _ => {
            let runs = scene.runs();
            let base = format!(
                "{}; {}; simulated to {} τ",
                model(&scene.model),
                drive(&scene.drive),
                num(scene.run.t_end)
            );
            if runs.len() <= 1 {
                return base;
            }
            let variants: Vec<String> = runs
                .iter()
                .map(|(v, _)| differences(&scene.model, &v.model, scene.run.t_end, v.run.t_end))
                .collect();
            format!("{base}; variants: {}", variants.join(" | "))
        }
    }
}

/// The fields of `m` that differ from `base`, e.g. "α = −60°, to 3700 τ".
fn differences(base: &Model, m: &Model, t0: f64, t: f64) -> String {
    let mut d = Vec::new();
    if m.alpha != base.alpha {
        d.push(format!("α = {}°", num(m.alpha)));
    }
    if m.n != base.n {
        d.push(format!("N = {}", m.n));
    }
    if m.b != base.b {
        d.push(format!("b/s = {}", num(m.b)));
    }
    if m.gamma != base.gamma {
        d.push(format!("γ = {}", num(m.gamma)));
    }
    if m.gravity != base.gravity {
        d.push(format!("G = {}", num(m.gravity)));
    }
    if m.inertia != base.inertia {
        d.push(format!("I = {}", num(m.inertia)));
    }
    if t != t0 {
        d.push(format!("to {} τ", num(t)));
    }
    if d.is_empty() {
        "as above".into()
    } else {
        d.join(", ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_read_as_typed() {
        assert_eq!(num(60.0), "60");
        assert_eq!(num(-60.0), "−60");
        assert_eq!(num(1.3), "1.3");
        assert_eq!(num(2e-4), "2e−4");
        assert_eq!(num(0.02), "0.02");
    }

    #[test]
    fn titles_come_from_the_fields() {
        let mut s = Scene::default();
        assert_eq!(title(&s), "kink, α = 60°");
        s.model.alpha = -70.0;
        s.model.n = 20;
        assert_eq!(title(&s), "antikink, α = −70°, N = 20");
        s.label = Some("Movie 5".into());
        assert_eq!(title(&s), "Movie 5: antikink, α = −70°, N = 20");
        s.title = Some("a wave".into());
        assert_eq!(title(&s), "Movie 5: a wave");
    }
}
