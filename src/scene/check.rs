//! Checks of a whole scene, field by field: each error names the key
//! path of the first bad field (`model.alpha`, `drive.flips.1.start`) for
//! the file loader to locate.

use super::params::Param;
use super::{AUTO_T_END, Fidelity, MAX_FLIPS, MAX_PANELS, MAX_TIMES, Method, Panel, TheoryFigure};
use super::{Model, OutputSpec, Scene, TheorySpec};
use crate::sim::IntegratorKind;

impl Scene {
    /// Checks every field; `Err((key path, message))` names the first bad
    /// one, for the file loader to locate (`model.alpha`,
    /// `drive.flips.1.start`, ...).
    pub fn check(&self) -> std::result::Result<(), (String, String)> {
        let bad = |key: &str, msg: String| Err((key.to_string(), msg));
        check_name(&self.name)?;
        for (key, text, lines) in [
            ("label", &self.label, false),
            ("title", &self.title, false),
            ("caption", &self.caption, true),
        ] {
            if let Some(t) = text {
                check_text(key, t, lines)?;
            }
        }
        // Ribbons hang the blocks in a column: the conversion sets α = ±90°
        // (docs/experiments.md), which the springs' model refuses.
        let hanging = self.apparatus.as_ref().is_some_and(|a| a.ribbons);
        check_model(
            "model",
            &self.model,
            self.fidelity() == Fidelity::Simulation,
            hanging,
        )?;
        // The run of ribbons starts from the column they hang in, at rest
        // (`Scenario::as_built`): another start would be ignored unsaid.
        if hanging && self.model.start == crate::sim::Start::Relaxed {
            return bad(
                "model.start",
                "the ribbons' run starts from the column they hang in, at rest; `relaxed` is \
                 the springs' hanging start (docs/experiments.md)"
                    .into(),
            );
        }
        if self.drive.flips.len() > MAX_FLIPS {
            return bad(
                "drive.flips",
                format!("at most {MAX_FLIPS} flips, got {}", self.drive.flips.len()),
            );
        }
        if let Some(a) = &self.apparatus {
            a.check().map_err(|(k, m)| (format!("apparatus.{k}"), m))?;
        }
        if let Some(chain) = &self.rings {
            self.check_rings(chain)?;
        }
        if let Err((k, msg)) = self.drive.check() {
            return Err((format!("drive.flips.{k}"), msg));
        }
        self.check_run()?;
        self.check_output()
    }

    /// The `run` table: the window, the step or tolerance, and which
    /// integrator they apply to.
    fn check_run(&self) -> std::result::Result<(), (String, String)> {
        let bad = |key: &str, msg: String| Err((key.to_string(), msg));
        let r = &self.run;
        if !((r.t_end.is_finite() || r.t_end == AUTO_T_END) && r.t_end > 0.0) {
            return bad(
                "run.t_end",
                format!("must be a finite time > 0 or \"auto\", got {}", r.t_end),
            );
        }
        // An apparatus' run has no automatic window (`with_auto_window`
        // leaves it): its `duration` (which replaces `t_end` when the
        // apparatus is converted) or a number of τ.
        if r.t_end == AUTO_T_END
            && self
                .apparatus
                .as_ref()
                .is_some_and(|a| a.duration.is_none())
        {
            return bad(
                "run.t_end",
                "\"auto\" is not a window for an apparatus: give [apparatus] duration (s) or a \
                 time in τ"
                    .into(),
            );
        }
        if let Some(dt) = r.dt
            && !(dt.is_finite() && dt > 0.0)
        {
            return bad("run.dt", format!("must be a finite number > 0, got {dt}"));
        }
        if let Some(rtol) = r.rtol
            && !(rtol.is_finite() && rtol > 0.0 && rtol < 1.0)
        {
            return bad(
                "run.rtol",
                format!("must be a number in (0, 1), got {rtol}"),
            );
        }
        if r.rtol.is_some() && r.integrator != Method::Fixed(IntegratorKind::Dopri5) {
            return bad("run.rtol", "applies only to integrator = \"dopri5\"".into());
        }
        if r.dt.is_some() && r.integrator == Method::Auto {
            return bad(
                "run.dt",
                "integrator \"auto\" picks its own step; name an integrator to set dt".into(),
            );
        }
        if !(r.tolerance.is_finite() && r.tolerance >= 1e-6 && r.tolerance <= 1e3) {
            return bad(
                "run.tolerance",
                format!("must be a time in [1e-6, 1000] τ, got {}", r.tolerance),
            );
        }
        Ok(())
    }

    /// A ring chain that builds (docs/rings.md) and an output it makes.
    fn check_rings(
        &self,
        chain: &crate::rings::RingChain,
    ) -> std::result::Result<(), (String, String)> {
        if !matches!(
            self.output,
            OutputSpec::Movie { .. } | OutputSpec::Filmstrip { .. } | OutputSpec::Kymograph
        ) {
            return Err((
                "output.kind".into(),
                "a ring chain makes a \"movie\", a \"filmstrip\" or a \"kymograph\"".into(),
            ));
        }
        crate::rings::run::check(chain).map_err(|e| {
            let msg = e.to_string();
            let msg = msg.strip_prefix("rings: ").unwrap_or(&msg).to_string();
            ("rings".to_string(), msg)
        })
    }

    fn check_output(&self) -> std::result::Result<(), (String, String)> {
        let simulated = self.fidelity() == Fidelity::Simulation;
        let hanging = self.apparatus.as_ref().is_some_and(|a| a.ribbons);
        let check_panels =
            |key: &str, panels: &[Panel]| -> std::result::Result<(), (String, String)> {
                if panels.len() > MAX_PANELS {
                    return Err((
                        key.into(),
                        format!("at most {MAX_PANELS} entries, got {}", panels.len()),
                    ));
                }
                for (k, p) in panels.iter().enumerate() {
                    check_text(&format!("{key}.{k}.label"), &p.label, false)?;
                    let m = p.model.apply(&self.model);
                    check_model(&format!("{key}.{k}.model"), &m, simulated, hanging)?;
                    // A value the apparatus sets would be replaced unsaid.
                    if let Some(a) = &self.apparatus {
                        for q in Param::ALL {
                            if let Some(why) = a.replaces(q).filter(|_| p.model.get(q).is_some()) {
                                return Err((format!("{key}.{k}.model.{}", q.name()), why));
                            }
                        }
                    }
                    if let Some(t) = p.t_end
                        && !(t.is_finite() && t > 0.0)
                    {
                        return Err((
                            format!("{key}.{k}.t_end"),
                            format!("must be a finite time > 0, got {t}"),
                        ));
                    }
                    let t_end = p.t_end.unwrap_or(self.run.t_end);
                    check_times(&format!("{key}.{k}.times"), &p.times, t_end)?;
                }
                Ok(())
            };
        match &self.output {
            OutputSpec::Filmstrip { times, panels } => {
                if panels.is_empty() || panels.iter().any(|p| p.times.is_empty()) {
                    let t_end = if panels.is_empty() {
                        self.run.t_end
                    } else {
                        panels
                            .iter()
                            .filter(|p| p.times.is_empty())
                            .map(|p| p.t_end.unwrap_or(self.run.t_end))
                            .fold(f64::INFINITY, f64::min)
                    };
                    check_times("output.times", times, t_end)?;
                }
                check_panels("output.panels", panels)
            }
            OutputSpec::Arrivals { curves } => check_panels("output.curves", curves),
            OutputSpec::Theory(t) => check_theory(t, self.model.b),
            OutputSpec::Sweep(spec) => spec.check(Scene::check, self),
            _ => Ok(()),
        }
    }
}

/// Longest label or title, in characters: a title is drawn on one or two
/// lines of a picture (the longest built-in one has 72).
pub const MAX_TITLE_CHARS: usize = 300;

/// Longest caption, in characters: a paragraph of the gallery and the
/// data file (the longest built-in one has about 1800).
pub const MAX_CAPTION_CHARS: usize = 10_000;

/// Refuses a text longer than its cap (drawing a title costs time that
/// grows faster than its length), or a control character in a text drawn on a picture (a title, a
/// label): most cannot be written in SVG at all, and none draws. A
/// caption (`lines`) may hold line breaks and tabs.
pub fn check_text(key: &str, text: &str, lines: bool) -> std::result::Result<(), (String, String)> {
    let cap = if lines {
        MAX_CAPTION_CHARS
    } else {
        MAX_TITLE_CHARS
    };
    let chars = text.chars().count();
    if chars > cap {
        return Err((
            key.into(),
            format!("must be at most {cap} characters, got {chars}"),
        ));
    }
    match text
        .chars()
        .find(|c| c.is_control() && !(lines && matches!(c, '\n' | '\t')))
    {
        Some(c) => Err((
            key.into(),
            format!(
                "must not contain control characters, got U+{:04X} in \"{}\"",
                u32::from(c),
                text.escape_debug()
            ),
        )),
        None => Ok(()),
    }
}

/// `hanging`: ribbons hang the blocks, and |α| = 90° (the column) is the
/// conversion's own value.
fn check_model(
    key: &str,
    m: &Model,
    simulated: bool,
    hanging: bool,
) -> std::result::Result<(), (String, String)> {
    let at = |field: &str, msg: String| Err((format!("{key}.{field}"), msg));
    let max = if simulated && !hanging {
        90.0
    } else {
        90.0 + 1e-9
    };
    if !(m.alpha.is_finite() && m.alpha.abs() < max) || (simulated && m.alpha == 0.0) {
        let range = if simulated {
            "0 < |alpha| < 90"
        } else {
            "|alpha| <= 90"
        };
        return at(
            "alpha",
            format!("must be degrees with {range}, got {}", m.alpha),
        );
    }
    if m.n < 2 || m.n > crate::model::params::MAX_BLOCKS {
        return at(
            "n",
            format!(
                "must be a number of blocks from 2 to {}, got {}",
                crate::model::params::MAX_BLOCKS,
                m.n
            ),
        );
    }
    use crate::limits::{MAX_INERTIA, MAX_LENGTH, MIN_INERTIA, MIN_LENGTH};
    if !(m.b.is_finite() && (MIN_LENGTH..=MAX_LENGTH).contains(&m.b)) {
        return at(
            "b",
            format!(
                "must be a length from {MIN_LENGTH:e} to {MAX_LENGTH:e}, got {}",
                crate::numfmt::plain(m.b)
            ),
        );
    }
    if !(m.gamma.is_finite() && m.gamma >= 0.0) {
        return at(
            "gamma",
            format!("must be a finite number >= 0, got {}", m.gamma),
        );
    }
    if !(m.gravity.is_finite() && m.gravity >= 0.0) {
        return at(
            "gravity",
            format!("must be a finite number >= 0, got {}", m.gravity),
        );
    }
    if !(m.inertia.is_finite() && (MIN_INERTIA..=MAX_INERTIA).contains(&m.inertia)) {
        return at(
            "inertia",
            format!(
                "must be a number from {MIN_INERTIA:e} to {MAX_INERTIA:e}, got {}",
                crate::numfmt::plain(m.inertia)
            ),
        );
    }
    match m.params() {
        Err(e) => return at("alpha", e.to_string()),
        // What a run will ask (e.g. |alpha| >= 1e-9°), asked here.
        Ok(p) if simulated && !hanging => {
            if let Err(e) = crate::sim::check_simulable(&p) {
                return at("alpha", e.to_string());
            }
        }
        Ok(_) => {}
    }
    Ok(())
}

fn check_times(key: &str, times: &[f64], t_end: f64) -> std::result::Result<(), (String, String)> {
    if times.len() > MAX_TIMES {
        return Err((
            key.into(),
            format!("at most {MAX_TIMES} times, got {}", times.len()),
        ));
    }
    if let Some(t) = times
        .iter()
        .find(|t| !(t.is_finite() && **t >= 0.0 && **t <= t_end))
    {
        return Err((
            key.into(),
            format!("time {t} lies outside the window [0, t_end = {t_end}]"),
        ));
    }
    Ok(())
}

fn check_theory(t: &TheorySpec, b: f64) -> std::result::Result<(), (String, String)> {
    if t.alphas.len() > MAX_PANELS || t.a_over_b.len() > MAX_PANELS || t.modes.len() > MAX_PANELS {
        return Err((
            "output".into(),
            format!("at most {MAX_PANELS} alphas, a_over_b or modes"),
        ));
    }
    // The list each figure draws one curve or panel of: never empty.
    let needs = match t.figure {
        TheoryFigure::Dispersion | TheoryFigure::EdgeMode => {
            Some(("alphas", t.alphas.is_empty(), "alphas = [25, 60]"))
        }
        TheoryFigure::GravityPotential => {
            Some(("a_over_b", t.a_over_b.is_empty(), "a_over_b = [1.2, 1.6]"))
        }
        TheoryFigure::ZeroModes => Some((
            "modes",
            t.modes.is_empty(),
            "modes = [{ m = 1, epsilon = 0.1 }]",
        )),
        _ => None,
    };
    if let Some((key, true, example)) = needs {
        return Err((
            format!("output.{key}"),
            format!(
                "this figure draws one curve or panel per entry and needs at least one, e.g. {example}"
            ),
        ));
    }
    check_theory_values(t, b)
}

/// The values of a theory figure's lists: angles, length ratios (each
/// with a ground state at `b`) and modes.
fn check_theory_values(t: &TheorySpec, b: f64) -> std::result::Result<(), (String, String)> {
    if let Some(a) = t
        .alphas
        .iter()
        .find(|a| !(a.is_finite() && a.abs() <= 90.0))
    {
        return Err((
            "output.alphas".into(),
            format!("angles must satisfy |alpha| <= 90, got {a}"),
        ));
    }
    if let Some(r) = t
        .a_over_b
        .iter()
        .find(|r| !(r.is_finite() && **r > 1.0 && **r < 10.0))
    {
        return Err((
            "output.a_over_b".into(),
            format!("ratios must lie in (1, 10), got {r}"),
        ));
    }
    // The gravitational potential draws each ratio's ground states: a/b
    // must have an equilibrium angle at the scene's b, cos α =
    // √((a/b)² − 1)·b/(2s) ≤ 1 (eq:eq_alpha), else it cannot render.
    if t.figure == TheoryFigure::GravityPotential
        && let Some(r) = t
            .a_over_b
            .iter()
            .find(|r| crate::theory::gravity::alpha_from_lengths(**r * b, b).is_none())
    {
        let most = (1.0 + (2.0 / b).powi(2)).sqrt();
        return Err((
            "output.a_over_b".into(),
            format!(
                "a/b = {r} has no equilibrium angle at b/s = {b}: the ratios must be at most \
                 {most:.4} (cos α = √((a/b)² − 1)·b/(2s) ≤ 1)"
            ),
        ));
    }
    if let Some(m) = t
        .modes
        .iter()
        .find(|m| m.m == 0 || m.m > 1000 || !(m.epsilon.is_finite() && m.epsilon.abs() <= 1.0))
    {
        return Err((
            "output.modes".into(),
            format!(
                "modes need m in 1..=1000 and |epsilon| <= 1, got m = {}, epsilon = {}",
                m.m, m.epsilon
            ),
        ));
    }
    Ok(())
}

/// A scene's name: 1 to 64 letters, digits, '-', '_' or '.', not first.
fn check_name(name: &str) -> std::result::Result<(), (String, String)> {
    let allowed = name
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c));
    if name.is_empty() || name.len() > 64 || !allowed || name.starts_with('.') {
        return Err((
            "name".to_string(),
            format!(
                "must be 1 to 64 letters, digits, '-', '_' or '.' (not first), got '{}'",
                name.escape_debug()
            ),
        ));
    }
    Ok(())
}
