//! Words for a scene, generated from its fields (never retyped): the
//! title drawn on a picture, the parameter line of the gallery and of
//! `ladder list`, the sentence that says which level of the model made a
//! picture, and the text that describes a picture to a reader who cannot
//! see it.

use super::{Camera, DriveSpec, Fidelity, Method, Model, OutputSpec, Scene, TheoryFigure};

pub use super::names::derived_name;
pub use crate::numfmt::typeset as num;

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
    let default = Model::default();
    let mut extra = String::new();
    if m.n != default.n {
        extra.push_str(&format!(", N = {}", m.n));
    }
    if m.b != default.b {
        extra.push_str(&format!(", b/s = {}", num(m.b)));
    }
    let flips = scene.drive.flips.len();
    let mut t = format!("{}{extra}", wave(m));
    if flips > 1 {
        // Each flip of block 1 launches a wall of the other kind than the
        // flip before: the title names every wave.
        let first = crate::sim::waves::WaveKind::launched(m.alpha);
        let (first, second) = (first.name(), first.other().name());
        t = format!(
            "{first} and {second}, {flips} flips of block 1, α = {}°{extra}",
            num(m.alpha)
        );
    }
    // Arrival times of curves of both signs, or of several flips, show
    // kinks and antikinks: the title says so rather than name one.
    if let OutputSpec::Arrivals { .. } = &scene.output {
        let alphas: Vec<f64> = scene.runs().iter().map(|(s, _)| s.model.alpha).collect();
        let both = alphas.iter().any(|a| *a > 0.0) && alphas.iter().any(|a| *a < 0.0);
        if both || flips > 1 {
            let flips = if flips > 1 {
                format!(", {flips} flips of block 1")
            } else {
                String::new()
            };
            return format!("arrival times of kinks and antikinks{flips}{extra}");
        }
    }
    match &scene.output {
        OutputSpec::Movie {
            camera: Camera::Follow,
        } => format!("{t}, camera following the kink"),
        OutputSpec::Arrivals { .. } => format!("arrival times, {t}"),
        OutputSpec::Kymograph => format!("{t}: sin θₙ"),
        OutputSpec::Energy => format!("energies, {t}"),
        OutputSpec::Sweep(sw) => sw.title(m),
        _ => t,
    }
}

/// "α = 60°, N = 10, b/s = 1.3, γ = 0.02, G = 2e−4, I = 0.25 m s²": every
/// parameter of the model's table, its symbol, value and unit.
pub fn model(m: &Model) -> String {
    let parts: Vec<String> = m.values().map(|(p, x)| p.spec().equation(x, num)).collect();
    parts.join(", ")
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
    if let Some(chain) = &scene.rings {
        return chain.parameters();
    }
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

/// Which level of the model made the scene's picture, in a sentence
/// (the gallery's line under each caption).
pub fn model_level(scene: &Scene) -> String {
    if scene.rings.is_some() {
        return crate::rings::RingChain::model_level().into();
    }
    match scene.fidelity() {
        Fidelity::Drawing => "Drawn from the ladder's geometry alone: no forces or motion are \
                              computed."
            .into(),
        Fidelity::Formula => "Plotted from closed-form expressions of the model; nothing is \
                              simulated."
            .into(),
        Fidelity::LinearTheory => "Computed from the linear theory of the model: small \
                                   deformations about the ground state, from its compatibility \
                                   matrix and stiffness."
            .into(),
        Fidelity::Simulation => {
            let how = match scene.run.integrator {
                Method::Auto => format!(
                    "with a step chosen by the program and checked so that every arrival \
                     time is within {} τ",
                    num(scene.run.tolerance)
                ),
                Method::Fixed(kind) => match (scene.run.rtol, scene.run.dt) {
                    (Some(r), _) => format!("with {} at tolerance {}", kind.name(), num(r)),
                    (None, dt) => format!(
                        "with {} at dt = {} τ",
                        kind.name(),
                        num(dt.unwrap_or(super::DEFAULT_DT))
                    ),
                },
            };
            format!(
                "Simulated: the full nonlinear equations of motion of the blocks, integrated \
                 in time {how}; the data file gives the integrator used and its accuracy."
            )
        }
    }
}

/// What the picture shows, for a reader who cannot see it (the gallery's
/// alt text, after the title).
pub fn picture(scene: &Scene) -> String {
    if let Some(chain) = &scene.rings {
        return match &scene.output {
            OutputSpec::Movie { .. } => format!(
                "Animation of the {} rings from 0 to {} s, seen from the side, with the \
                 kymograph of their azimuths beside it",
                chain.n,
                num(chain.t_end)
            ),
            OutputSpec::Filmstrip { .. } => format!(
                "Snapshots of the {} rings seen from the side, at the times written under them",
                chain.n
            ),
            _ => crate::rings::RingChain::kymograph_words().into(),
        };
    }
    let n = scene.model.n;
    match &scene.output {
        OutputSpec::Movie { camera } => {
            let follow = match camera {
                Camera::Follow => ", the camera moving with the kink",
                Camera::Fixed | Camera::Auto => "",
            };
            format!(
                "Animation of the {n} blocks from 0 to {} τ{follow}, with the kymograph of \
                 sin θₙ growing beside it",
                num(scene.run.t_end)
            )
        }
        OutputSpec::Filmstrip { times, panels } => {
            if panels.len() > 1 {
                let labels: Vec<&str> = panels.iter().map(|p| p.label.as_str()).collect();
                format!(
                    "{} rows of snapshots of the {n} blocks, one row per run ({}), time \
                     running from left to right",
                    panels.len(),
                    labels.join(", ")
                )
            } else if times.is_empty() {
                format!("Snapshots of the {n} blocks, time running from left to right")
            } else {
                let list: Vec<String> = times.iter().map(|t| num(*t)).collect();
                format!(
                    "Snapshots of the {n} blocks at t/τ = {}, from left to right",
                    list.join(", ")
                )
            }
        }
        OutputSpec::Kymograph => kymograph(),
        OutputSpec::Energy => "Chart of the energies against time t/τ: kinetic, elastic, \
                               gravitational and the energy dissipated so far, each from its \
                               value at t = 0, and the total with and without the dissipated \
                               energy, which stays flat once the drive has ended"
            .into(),
        OutputSpec::Arrivals { curves } => format!(
            "Chart of the arrival time tₙ against block n, {} with its fitted speed",
            match curves.len() {
                0 | 1 => "one line".to_string(),
                k => format!("{k} lines, each"),
            }
        ),
        OutputSpec::Data => "No picture: the run's numbers only".into(),
        OutputSpec::Experiment(e) => e.figure.describe().into(),
        OutputSpec::Sweep(sw) => format!(
            "Charts of a sweep of the {n}-block ladder over {}: how far the wave got and \
             how fast, coloured by its outcome, against the parameters swept",
            sw.describe_grid()
        ),
        OutputSpec::Theory(t) => theory_picture(t.figure, n),
    }
}

/// What a figure of the linear theory shows, for a reader who cannot see
/// it.
fn theory_picture(figure: TheoryFigure, n: usize) -> String {
    match figure {
        TheoryFigure::UnitSchematic => "Drawing of two blocks of length s joined by an A \
                                            link (a) and a B link (b), with θ, Δx and Δy marked"
            .into(),
        TheoryFigure::GravityPotential => "Chart of the potential U against θ, one curve \
                                               per ratio a/b, with the ladder at its minimum as \
                                               an inset"
            .into(),
        TheoryFigure::GroundStates => format!(
            "Two drawings of the {n}-block ladder at rest, with its blocks tilted at +α and \
                 at −α, an arrow on each block for its orientation"
        ),
        TheoryFigure::Gapless => {
            format!("Drawing of the {n}-block ladder at rest with horizontal blocks")
        }
        TheoryFigure::ZeroModes => {
            "Drawings of the ladder deformed along its zero modes, over the ground state in \
                 grey"
                .into()
        }
        TheoryFigure::Dispersion => {
            "Chart of the phonon frequencies ω₊ and ω₋ against qb, one pair of curves per α".into()
        }
        TheoryFigure::Winding => {
            "Closed curves of det C(q) in the complex plane, one for α > 0 and one for α < 0".into()
        }
        TheoryFigure::EdgeMode => "Chart of the zero mode's amplitude |δθₙ| against block \
                                       n on a logarithmic scale, dots against a line"
            .into(),
        TheoryFigure::Barrier => "Chart of the energy barrier ΔU against α".into(),
    }
}

/// The words for a kymograph picture.
pub fn kymograph() -> String {
    "Kymograph: sin θₙ of each block n (across) against time (down), red for +1 and blue \
     for −1"
        .into()
}

/// The fields of `m` that differ from `base`, e.g. "α = −60°, to 3700 τ".
fn differences(base: &Model, m: &Model, t0: f64, t: f64) -> String {
    let mut d: Vec<String> = m
        .values()
        .zip(base.values())
        .filter(|((_, x), (_, y))| x != y)
        .map(|((p, x), _)| p.spec().equation(x, num))
        .collect();
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
    fn a_second_flip_names_no_drive_time_and_every_wave() {
        let base = Scene::default();
        let mut s = base.clone();
        s.drive.flips.push(crate::scene::Flip {
            start: 1500.0,
            duration: base.drive.flips[0].duration,
        });
        assert_eq!(derived_name(&s, &base), "flips0_1500");
        s.drive.flips[1].duration = 700.0;
        assert!(
            derived_name(&s, &base).contains("td"),
            "{}",
            derived_name(&s, &base)
        );
        s.drive.flips[1].duration = base.drive.flips[0].duration;
        assert_eq!(title(&s), "kink and antikink, 2 flips of block 1, α = 60°");
        s.model.alpha = -60.0;
        assert_eq!(title(&s), "antikink and kink, 2 flips of block 1, α = −60°");
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
