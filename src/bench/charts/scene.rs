//! The charts of a scene's study (`bench work-precision|stability --scene
//! ID`): the refusals' wording and the stability chart of one scene.

use super::*;
use crate::bench::StabilityRow;
use crate::render::palette::{Palette, Role};

/// The terms a refusal names (`sim::check_terms`' message: "integrator X
/// cannot integrate TERMS: ..."), or the whole message,
/// with their parenthesised explanations left out.
pub fn refusal_terms(reason: &str) -> String {
    let terms = reason
        .split_once("cannot integrate ")
        .and_then(|(_, rest)| rest.split_once(':'))
        .map_or(reason, |(terms, _)| terms);
    let mut out = String::new();
    let mut depth = 0usize;
    for c in terms.chars() {
        match c {
            '(' => depth += 1,
            ')' => depth = depth.saturating_sub(1),
            _ if depth == 0 => out.push(c),
            _ => {}
        }
    }
    out.split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
        .replace(" ,", ",")
}

/// The stability chart of one scene (`bench stability --scene ID`): each
/// scheme's observed critical dt against its linear prediction, log–log,
/// with the line observed = predicted; a refused scheme is a legend line
/// with the terms it cannot take.
pub(super) fn scene_stability_chart(report: &StabilityReport) -> Result<Pixmap> {
    let rows = &report.integrators;
    let all = rows
        .iter()
        .filter(|r| r.refused.is_none() && r.failed.is_none())
        .flat_map(|r| [Some(r.critical_dt), linear_bound(r)])
        .flatten();
    let (lo, hi) = decades(log_range(all, 1.5).unwrap_or((1e-3, 1.0)));
    let name = report.scene.as_deref().unwrap_or("scene");
    let mut spec = ChartSpec::new(
        Axis::new("linear bound from ω_max (τ)").log().range(lo, hi),
        Axis::new("observed critical dt (τ)").log().range(lo, hi),
    )
    .title(format!(
        "Stability limits on {name}, α = {}°",
        report.alpha_deg
    ));
    spec.legend = Legend::Outside;
    spec = spec.series(
        Series::line(
            "observed = predicted",
            vec![(lo, lo), (hi, hi)],
            Palette.color(Role::Ground),
        )
        .dashed(),
    );
    for r in rows {
        spec = spec.series(row_series(r, lo));
    }
    let t = screen();
    let chart = line_chart(&t, &spec, 520 + legend_width(&spec), STABILITY.1)?.pixmap;
    let chart = compose(
        &[Panel::new(Picture::of_image(&t, chart))],
        &Layout::columns(&t, 1),
    )?;
    let caption = format!(
        "{name}{}: the largest fixed dt at which the scene stays bounded, by bisection to {:.0} %, \
         against the linear bound from ω_max = {:.3} /τ (the clamped chain without added mass; \
         added mass lowers the frequencies, so the bound errs small). Plus signs in the legend: \
         schemes that refuse the scene's terms (not run).",
        report
            .terms
            .as_ref()
            .map_or(String::new(), |t| format!(" ({t})")),
        100.0 * crate::bench::STABILITY_PRECISION,
        report.omega_max
    );
    with_caption(&chart, &caption)
}

/// A scheme's linear bound on dt, or `None` where it is 0 (explicit Euler
/// and dopri5 without linear damping, as in the tank): drawn at the left
/// edge.
fn linear_bound(r: &StabilityRow) -> Option<f64> {
    (r.predicted_dt > 1e-4).then_some(r.predicted_dt)
}

/// One scheme of the stability chart: its observed critical dt at its
/// bound (or at `lo`), or a legend line saying it was refused or failed.
fn row_series(r: &StabilityRow, lo: f64) -> Series {
    let color = color_of(&r.name);
    let label = match (&r.refused, &r.failed) {
        (Some(reason), _) => format!(
            "{} refused: {}",
            stability_label(&r.name),
            refusal_terms(reason)
        ),
        (None, Some(_)) => format!("{}: no stable step found", stability_label(&r.name)),
        (None, None) => match linear_bound(r) {
            Some(p) => format!(
                "{}: {:.3} τ ({:.2} × predicted)",
                stability_label(&r.name),
                r.critical_dt,
                r.critical_dt / p
            ),
            None => format!(
                "{}: {:.3} τ (linear bound 0 without damping; at the left edge)",
                stability_label(&r.name),
                r.critical_dt
            ),
        },
    };
    let (marker, pts) = if r.refused.is_some() {
        (Marker::Plus, Vec::new())
    } else if r.failed.is_some() {
        (Marker::Cross, Vec::new())
    } else {
        let x = linear_bound(r).unwrap_or(lo);
        (stability_marker(&r.name).0, vec![(x, r.critical_dt)])
    };
    Series::scatter(label, pts, color, marker).with_width(3.0)
}
