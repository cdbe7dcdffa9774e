//! The charts of the speed-against-accuracy study: `work-precision.png`
//! (θ error against force evaluations and against wall time) and
//! `stability.png` (critical dt against α, observed and predicted).

use super::{INACCURATE_THETA, SceneReport, StabilityReport, Status, Sweep, WorkPrecisionReport};
use crate::encode::Rgb;
use crate::error::{Error, Result};
use crate::render::charts::{Axis, ChartSpec, Legend, Marker, Series, line_chart};
use crate::render::compose::{Layout, Panel, compose};
use crate::render::palette::{Palette, Role};
use crate::render::style::{self, HAlign, VAlign, size};
use crate::render::{Picture, Theme};
use crate::sim::IntegratorKind;
use tiny_skia::Pixmap;

/// Size of one panel of the work-precision chart, and of the stability chart.
const PANEL: (u32, u32) = (520, 440);
const STABILITY: (u32, u32) = (900, 520);

mod scene;
pub use scene::refusal_terms;
use scene::scene_stability_chart;

/// The colour of an integrator, the same in every chart.
pub fn integrator_color(kind: IntegratorKind) -> Rgb {
    match kind {
        IntegratorKind::ExplicitEuler => Palette.color(Role::Series(4)),
        IntegratorKind::SymplecticEuler => Palette.color(Role::Series(2)),
        IntegratorKind::Verlet => Palette.color(Role::Series(3)),
        IntegratorKind::Rk4 => Palette.color(Role::Series(6)),
        IntegratorKind::Dopri5 => Palette.color(Role::Series(1)),
        IntegratorKind::Moreau => Palette.color(Role::Series(5)),
    }
}

fn color_of(name: &str) -> Rgb {
    name.parse::<IntegratorKind>()
        .map_or(Palette.color(Role::Ink), integrator_color)
}

/// Legend name: "symplectic Euler", "dopri5 (adaptive)".
fn pretty(name: &str) -> &str {
    match name {
        "explicit-euler" => "explicit Euler",
        "symplectic-euler" => "symplectic Euler",
        "verlet" => "velocity Verlet",
        "rk4" => "RK4",
        "dopri5" => "dopri5 (adaptive)",
        "moreau" => "Moreau",
        other => other,
    }
}

/// What a diverged run would have cost had it reached the end: the fixed
/// step's force evaluations over `t_end`, and the wall time at the
/// integrator's measured seconds per evaluation.
fn nominal_cost(sweep: &Sweep, dt: f64, t_end: f64) -> (f64, f64) {
    let per_step = sweep
        .name
        .parse::<IntegratorKind>()
        .map_or(1, |k| k.evals_per_step()) as f64;
    let evals = (t_end / dt).ceil() * per_step;
    let mut rates: Vec<f64> = sweep
        .points
        .iter()
        .filter(|p| !p.diverged && p.force_evals > 0)
        .map(|p| p.wall_seconds / p.force_evals as f64)
        .collect();
    rates.sort_by(f64::total_cmp);
    let rate = rates.get(rates.len() / 2).copied().unwrap_or(f64::NAN);
    (evals, evals * rate)
}

/// Which cost goes on the x axis.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Cost {
    Evals,
    Wall,
}

/// Log range of positive values with a margin factor on each side.
fn log_range(vals: impl Iterator<Item = f64>, pad: f64) -> Option<(f64, f64)> {
    let (lo, hi) = vals
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    (lo <= hi).then(|| (lo / pad, hi * pad))
}

/// Decade-aligned log range covering `r`.
fn decades((lo, hi): (f64, f64)) -> (f64, f64) {
    (
        10f64.powf(lo.log10().floor()),
        10f64.powf(hi.log10().ceil()),
    )
}

/// The paper's setting: symplectic Euler at dt = 0.01 (the program's default).
const PAPER_KIND: &str = "symplectic-euler";
const PAPER_DT: f64 = 0.01;

/// One panel: θ error of every integrator of `scene` against `cost`, with
/// the common y range `yr` and x range `xr`.
fn wp_panel(
    scene: &SceneReport,
    cheapest: Option<(&str, f64)>,
    cost: Cost,
    xr: (f64, f64),
    yr: (f64, f64),
) -> Result<ChartSpec> {
    let x_label = match cost {
        Cost::Evals => "force evaluations",
        Cost::Wall => "wall time (s, median of repeats)",
    };
    let title = match cost {
        Cost::Evals => "θ error against force evaluations",
        Cost::Wall => "θ error against wall time",
    };
    let mut spec = ChartSpec::new(
        Axis::new(x_label).log().range(xr.0, xr.1),
        Axis::new("max |θ − θ_ref| (rad)").log().range(yr.0, yr.1),
    )
    .title(title);
    spec.legend = Legend::Outside;
    let mut marks = Marks::default();
    for sweep in &scene.integrators {
        spec = spec.series(integrator_series(sweep, cost));
        if sweep.refused.is_none() {
            marks.collect(sweep, scene.t_end, cheapest, cost, yr.1 / 2.0);
        }
    }
    for series in marks.into_series(cheapest) {
        spec = spec.series(series);
    }
    Ok(spec)
}

/// A run's position on the x axis of `cost`.
fn at(cost: Cost, evals: f64, wall: f64) -> f64 {
    match cost {
        Cost::Evals => evals,
        Cost::Wall => wall,
    }
}

/// A refused integrator's legend line: its name, what it refused, and
/// nothing to plot.
fn refused_entry(name: &str, reason: &str) -> Series {
    Series::scatter(
        format!("{} refused: {}", pretty(name), refusal_terms(reason)),
        Vec::new(),
        color_of(name),
        Marker::Plus,
    )
    .with_width(3.0)
}

/// The series of one integrator: its error line against `cost`, or, for a
/// refused integrator, a legend line with the reason and nothing to plot.
fn integrator_series(sweep: &Sweep, cost: Cost) -> Series {
    let color = color_of(&sweep.name);
    if let Some(reason) = &sweep.refused {
        return refused_entry(&sweep.name, reason);
    }
    let pts: Vec<(f64, f64)> = sweep
        .points
        .iter()
        .filter(|p| !p.diverged)
        .filter_map(|p| {
            let e = p.theta_error?;
            Some((at(cost, p.force_evals as f64, p.wall_seconds), e))
        })
        .collect();
    let order = sweep
        .measured_order
        .map_or(String::new(), |o| format!(", slope {o:.1}"));
    Series::line(format!("{}{order}", pretty(&sweep.name)), pts, color).with_marker(Marker::Circle)
}

/// The runs a panel marks over the integrators' lines: the paper's
/// setting, the cheapest accurate run, the inaccurate runs and the diverged
/// ones (drawn at `diverged_y`, at the cost they would have had).
#[derive(Default)]
struct Marks {
    paper: Vec<(f64, f64)>,
    best: Vec<(f64, f64)>,
    inaccurate: Vec<(f64, f64)>,
    diverged: Vec<(f64, f64, Rgb, String)>,
}

impl Marks {
    /// Adds the marks of `sweep`'s runs.
    fn collect(
        &mut self,
        sweep: &Sweep,
        t_end: f64,
        cheapest: Option<(&str, f64)>,
        cost: Cost,
        diverged_y: f64,
    ) {
        let color = color_of(&sweep.name);
        for p in &sweep.points {
            let step = p.dt.or(p.rtol).unwrap_or(f64::NAN);
            if p.diverged {
                if let Some(dt) = p.dt {
                    let (e, w) = nominal_cost(sweep, dt, t_end);
                    let what = format!("{}, dt = {dt}", pretty(&sweep.name));
                    self.diverged
                        .push((at(cost, e, w), diverged_y, color, what));
                }
                continue;
            }
            let Some(err) = p.theta_error else { continue };
            let x = at(cost, p.force_evals as f64, p.wall_seconds);
            if p.status == Status::Inaccurate {
                self.inaccurate.push((x, err));
            }
            if sweep.name == PAPER_KIND && p.dt == Some(PAPER_DT) {
                self.paper.push((x, err));
            }
            if cheapest == Some((sweep.name.as_str(), step)) {
                self.best.push((x, err));
            }
        }
    }

    /// The marks as series, in the legend's order.
    fn into_series(self, cheapest: Option<(&str, f64)>) -> Vec<Series> {
        let ink = Palette.color(Role::Ink);
        let mut out = Vec::new();
        if !self.paper.is_empty() {
            let label = "paper's setting: symplectic Euler, dt = 0.01";
            out.push(Series::scatter(label, self.paper, ink, Marker::Square).with_width(3.0));
        }
        if !self.best.is_empty() {
            let (name, step) = cheapest.unwrap_or_default();
            let label = format!("cheapest within 1 τ: {}, dt = {step}", pretty(name));
            out.push(Series::scatter(label, self.best, ink, Marker::Triangle).with_width(3.0));
        }
        if !self.inaccurate.is_empty() {
            let label = format!("inaccurate (θ error > {INACCURATE_THETA} rad or a flip differs)");
            let marks = Series::scatter(label, self.inaccurate, ink, Marker::Ring);
            out.push(marks.with_width(2.0));
        }
        for (x, y, color, what) in self.diverged {
            let label = format!("diverged: {what}");
            out.push(Series::scatter(label, vec![(x, y)], color, Marker::Cross).with_width(3.0));
        }
        out
    }
}

/// The bench report's charts are drawn at the screen style.
fn screen() -> Theme {
    Theme::of(&crate::render::Style::default())
}

/// Width of the legend column of `spec` drawn outside the plot, in pixels
/// (as the chart module lays it out).
fn legend_width(spec: &ChartSpec) -> u32 {
    let text = spec
        .series
        .iter()
        .filter_map(|s| s.label.as_deref())
        .map(|l| style::text_width(screen().font(), l, screen().tick))
        .fold(0.0, f32::max);
    (text + 28.0 + 34.0 + 8.0).ceil() as u32
}

/// `work-precision.png`: for each scene of the report (the α = 60° kink,
/// the α = −60° antikink) θ error against force evaluations and against
/// wall time, log–log, one line per integrator; the paper's setting, the
/// cheapest setting within 1 τ on arrival times, and diverged runs marked.
pub fn work_precision_chart(report: &WorkPrecisionReport) -> Result<Pixmap> {
    if report.scenes.is_empty() {
        return Err(Error::bad_input("the work-precision report has no scenes"));
    }
    // Common ranges across the scenes, so the rows compare directly.
    let mut evals = Vec::new();
    let mut walls = Vec::new();
    let mut errors = Vec::new();
    for scene in &report.scenes {
        for sweep in &scene.integrators {
            for p in &sweep.points {
                if p.diverged {
                    if let Some(dt) = p.dt {
                        let (e, w) = nominal_cost(sweep, dt, scene.t_end);
                        evals.push(e);
                        walls.push(w);
                    }
                } else {
                    evals.push(p.force_evals as f64);
                    walls.push(p.wall_seconds);
                    errors.extend(p.theta_error);
                }
            }
        }
    }
    let xr_e = decades(log_range(evals.into_iter(), 1.2).unwrap_or((1.0, 10.0)));
    let xr_w = decades(log_range(walls.into_iter(), 1.2).unwrap_or((1e-3, 1.0)));
    let (ylo, yhi) = decades(log_range(errors.into_iter(), 1.5).unwrap_or((1e-6, 1.0)));
    // Room above the largest error for the row of diverged crosses.
    let yr = (ylo, yhi.max(10.0));
    let mut panels = Vec::new();
    for scene in &report.scenes {
        let cheapest = report
            .cheapest_within_1tau
            .iter()
            .find(|c| c.scene == scene.scene)
            .map(|c| (c.integrator.as_str(), c.step));
        let mut work = wp_panel(scene, cheapest, Cost::Evals, xr_e, yr)?;
        let time = wp_panel(scene, cheapest, Cost::Wall, xr_w, yr)?;
        // One legend per row, right of the wall-time panel; both plots
        // get the same size.
        work.legend = Legend::Hidden;
        let extra = legend_width(&time);
        let label = match &scene.terms {
            Some(terms) => format!("{} ({terms})", scene.scene),
            None => scene.scene.replace('-', "−"),
        };
        let t = screen();
        let work = line_chart(&t, &work, PANEL.0, PANEL.1)?.pixmap;
        let time = line_chart(&t, &time, PANEL.0 + extra, PANEL.1)?.pixmap;
        // A label with the scene's terms runs on over the second panel.
        let second = match &scene.terms {
            Some(_) => String::new(),
            None => label.clone(),
        };
        panels.push(Panel::new(Picture::of_image(&t, work)).label(label));
        panels.push(Panel::new(Picture::of_image(&t, time)).label(second));
    }
    let first = &report.scenes[0];
    let title = format!(
        "Work–precision of the integrators (N = {}, {} τ; reference: {})",
        first.n,
        if first.t_end >= 100.0 {
            format!("{:.0}", first.t_end)
        } else {
            crate::numfmt::plain(first.t_end)
        },
        report.reference
    );
    compose(&panels, &Layout::columns(&screen(), 2).title(title))
}

/// Ratio range observed/predicted of one integrator over the α sweep.
fn ratio_range(report: &StabilityReport, name: &str) -> Option<(f64, f64)> {
    let ratios = report.sweep.iter().flat_map(|p| {
        p.integrators
            .iter()
            .filter(|r| r.name == name && r.predicted_dt > 0.0)
            .map(|r| r.critical_dt / r.predicted_dt)
    });
    let (lo, hi) = ratios.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    (lo <= hi).then_some((lo, hi))
}

fn ratio_text(r: Option<(f64, f64)>) -> String {
    match r {
        Some((lo, hi)) if (hi - lo) < 0.005 => format!("{lo:.2}"),
        Some((lo, hi)) => format!("{lo:.2}–{hi:.2}"),
        None => "n/a".into(),
    }
}

/// Ratio observed/predicted of one integrator at the report's own α (60°).
fn ratio_at(report: &StabilityReport, name: &str) -> String {
    report
        .integrators
        .iter()
        .find(|r| r.name == name && r.predicted_dt > 0.0)
        .map_or("n/a".into(), |r| {
            format!("{:.2}", r.critical_dt / r.predicted_dt)
        })
}

/// ln of the growth over the kink scene's 4000 τ of the stiffest mode,
/// λ = −c/2 + iω_max, for `kind` at its observed limit at the report's α:
/// (T/h) ln|R(hλ)| with R the scheme's stability function.
fn growth_at_limit(report: &StabilityReport, kind: IntegratorKind) -> Option<f64> {
    let h = report
        .integrators
        .iter()
        .find(|r| r.name == kind.name())?
        .critical_dt;
    let lambda = nalgebra::Complex::new(-report.damping_rate / 2.0, report.omega_max);
    let per_step = super::stability_function(kind, lambda * h).norm().ln();
    Some(4000.0 / h * per_step).filter(|g| g.is_finite())
}

/// The caption of `stability.png`: what is plotted, and why each method's
/// observed bound agrees with its prediction or not (with the measured
/// ratios observed/predicted at α = 60° and over the α sweep). One
/// paragraph per line.
pub fn stability_caption(report: &StabilityReport) -> String {
    let r = |name| {
        format!(
            "ratio {} at {}°, {} over α",
            ratio_at(report, name),
            report.alpha_deg,
            ratio_text(ratio_range(report, name))
        )
    };
    let c = report.damping_rate;
    format!(
        "Dots and solid lines: the largest fixed dt at which the kink scene (N = 10, b/s = 1.3, \
         4000 τ) stays bounded, by bisection to {prec:.0} %. Dashed: the linear prediction from \
         ω_max, the highest normal mode of the clamped chain in its ground state (2.4–2.8 /τ). \
         Lower panel: observed over predicted (1: the linear theory is exact).\n\
         Symplectic Euler and velocity Verlet ({se}; {vv}): stable for ω h < 2; past it the \
         growth per step jumps at once, so the bound 2/ω_max is sharp.\n\
         RK4 ({rk}): its region meets the imaginary axis at ω h = 2√2. Near α = 60° the bound is \
         sharp; at small and large α runs just past it stay bounded because the unstable mode \
         saturates nonlinearly, but they are wrong (α = 5°, dt = 1.1: blocks turn by hundreds \
         of degrees).\n\
         Explicit Euler ({ee}): unstable for every undamped mode; with damping c = {c} /τ the \
         linear bound is h = c/ω_max². Just above it a mode grows by only |R| − 1 ≈ (h²ω² − hc)/2 \
         per step, e^(T(hω² − c)/2) over the run, and the runaway is not reached within 4000 τ \
         until about twice the linear bound. Those runs stay bounded but are wrong: at dt = 0.005 \
         the kink's arrival times are off by hundreds of τ.\n\
         dopri5 at fixed step ({dp}): the Dormand–Prince region leaves the imaginary axis near \
         ω h ≈ 1 and the growth beyond is slow, so damping sets the linear bound |R(hλ)| = 1, \
         λ = −c/2 + iω_max; as for explicit Euler the run survives a finite growth (about \
         e^{growth:.0} at the observed limit for α = {alpha}°) beyond it.",
        growth = growth_at_limit(report, IntegratorKind::Dopri5).unwrap_or(f64::NAN),
        alpha = report.alpha_deg,
        prec = 100.0 * super::STABILITY_PRECISION,
        se = r("symplectic-euler"),
        vv = r("verlet"),
        rk = r("rk4"),
        ee = r("explicit-euler"),
        dp = r("dopri5"),
    )
}

/// `stability.png`: critical dt against α (log y), one colour per
/// integrator, observed as dots and solid line, predicted dashed, with the
/// caption of [`stability_caption`] drawn underneath.
pub fn stability_chart(report: &StabilityReport) -> Result<Pixmap> {
    if report.sweep.is_empty() {
        return Err(Error::bad_input("the stability report has no α values"));
    }
    if report.scene.is_some() {
        return scene_stability_chart(report);
    }
    // A scheme refused by the scene's terms has no limit to plot: the
    // legend names it and why (`refused_entry`).
    let names: Vec<&str> = report.sweep[0]
        .integrators
        .iter()
        .filter(|r| r.refused.is_none())
        .map(|r| r.name.as_str())
        .collect();
    let mut specs = [stability_spec(report, &names), ratio_spec(report, &names)];
    for r in report.sweep[0].integrators.iter() {
        if let Some(reason) = &r.refused {
            for spec in specs.iter_mut() {
                *spec = std::mem::take(spec).series(refused_entry(&r.name, reason));
            }
        }
    }
    // Equal plot widths: each chart is narrower by what its legend needs
    // less than the widest legend.
    let widest = specs.iter().map(legend_width).max().unwrap_or(0);
    let mut panels = Vec::new();
    for (k, spec) in specs.iter().enumerate() {
        let w = STABILITY.0 - (widest - legend_width(spec));
        let h = if k == 0 {
            STABILITY.1
        } else {
            STABILITY.1 * 3 / 4
        };
        let t = screen();
        let chart = line_chart(&t, spec, w, h)?.pixmap;
        panels.push(Panel::new(Picture::of_image(&t, chart)));
    }
    let chart = compose(&panels, &Layout::columns(&screen(), 1))?;
    with_caption(&chart, &stability_caption(report))
}

/// Legend name of an integrator in the stability chart.
fn stability_label(name: &str) -> &str {
    match name {
        "dopri5" => "dopri5 (fixed step)",
        other => pretty(other),
    }
}

/// Marker and width: symplectic Euler and Verlet coincide, so a larger
/// square shows behind Verlet's dots.
fn stability_marker(name: &str) -> (Marker, f64) {
    match name {
        "symplectic-euler" => (Marker::Square, 3.0),
        "rk4" => (Marker::Triangle, 2.0),
        _ => (Marker::Circle, 2.0),
    }
}

/// `f` of integrator `name` at every α of the sweep.
fn stability_series(
    report: &StabilityReport,
    name: &str,
    f: impl Fn(&super::StabilityRow) -> f64,
) -> Vec<(f64, f64)> {
    report
        .sweep
        .iter()
        .filter_map(|p| {
            let r = p.integrators.iter().find(|r| r.name == name)?;
            Some((p.alpha_deg, f(r)))
        })
        .collect()
}

/// The lower panel: observed over predicted critical dt against α.
fn ratio_spec(report: &StabilityReport, names: &[&str]) -> ChartSpec {
    let ratio = |r: &super::StabilityRow| r.critical_dt / r.predicted_dt;
    let all: Vec<f64> = names
        .iter()
        .flat_map(|n| stability_series(report, n, ratio))
        .map(|p| p.1)
        .filter(|v| v.is_finite())
        .collect();
    let hi = all.iter().copied().fold(1.0, f64::max);
    let lo = all.iter().copied().fold(1.0, f64::min);
    let pad = 0.08 * (hi - lo).max(0.1);
    let mut spec = ChartSpec::new(
        Axis::new("equilibrium angle α (°)").range(0.0, 90.0),
        Axis::new("observed / predicted").range(lo - pad, hi + pad),
    );
    spec.legend = Legend::Outside;
    spec = spec.series(
        Series::line(
            "",
            vec![(0.0, 1.0), (90.0, 1.0)],
            Palette.color(Role::Ground),
        )
        .dashed(),
    );
    for &name in names {
        let (marker, width) = stability_marker(name);
        spec = spec.series(
            Series::line(
                stability_label(name),
                stability_series(report, name, ratio),
                color_of(name),
            )
            .with_marker(marker)
            .with_width(width),
        );
    }
    spec
}

/// The upper panel: critical and predicted dt of every integrator, log y.
fn stability_spec(report: &StabilityReport, names: &[&str]) -> ChartSpec {
    let all = report.sweep.iter().flat_map(|p| {
        p.integrators
            .iter()
            .flat_map(|r| [r.critical_dt, r.predicted_dt])
    });
    let yr = log_range(all, 1.4).unwrap_or((1e-3, 1.0));
    let mut spec = ChartSpec::new(
        Axis::new("equilibrium angle α (°)").range(0.0, 90.0),
        Axis::new("critical dt (τ)").log().range(yr.0, yr.1),
    )
    .title("Stability limits of the fixed-step integrators, kink scene");
    spec.legend = Legend::Outside;
    for &name in names {
        let color = color_of(name);
        let (marker, width) = stability_marker(name);
        spec = spec.series(
            Series::line(
                stability_label(name),
                stability_series(report, name, |r| r.critical_dt),
                color,
            )
            .with_marker(marker)
            .with_width(width),
        );
        spec = spec.series(
            Series::line(
                "",
                stability_series(report, name, |r| r.predicted_dt),
                color,
            )
            .dashed(),
        );
    }
    spec.series(
        Series::line(
            "observed (bisection)",
            Vec::new(),
            Palette.color(Role::Ground),
        )
        .with_marker(Marker::Circle),
    )
    .series(
        Series::line(
            "predicted (linear, ω_max)",
            Vec::new(),
            Palette.color(Role::Ground),
        )
        .dashed(),
    )
}

/// `image` with `text` wrapped underneath it.
fn with_caption(image: &Pixmap, text: &str) -> Result<Pixmap> {
    let margin = size::MARGIN as f32 * 2.0;
    let theme = screen();
    let font_size = theme.tick;
    let lines = style::wrap_text(
        theme.font(),
        text,
        image.width() as f32 - 2.0 * margin,
        font_size,
    );
    let line_h = font_size * 1.45;
    let caption_h = (lines.len() as f32 * line_h + margin).ceil() as u32;
    let (w, h) = (image.width(), image.height() + caption_h);
    let mut out = style::white_pixmap(w, h)
        .ok_or_else(|| Error::failed(format!("cannot allocate a {w}x{h} image")))?;
    crate::render::compose::blit(&mut out, image, 0, 0);
    for (k, line) in lines.iter().enumerate() {
        let y = image.height() as f32 + k as f32 * line_h;
        style::draw_text(
            &mut out,
            theme.font(),
            line,
            (margin, y),
            font_size,
            Palette.color(Role::Ink),
            (HAlign::Left, VAlign::Top),
        );
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_keeps_words_and_paragraphs() {
        let lines = style::wrap_text(screen().font(), "one two three\nfour", 10_000.0, 13.0);
        assert_eq!(lines, vec!["one two three", "four"]);
        let narrow = style::wrap_text(screen().font(), "alpha beta gamma", 1.0, 13.0);
        assert_eq!(narrow, vec!["alpha", "beta", "gamma"]);
    }
}
