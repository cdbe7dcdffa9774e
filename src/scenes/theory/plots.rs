//! Chart figures of the linear theory: Fig. 2c (U(θ), eq:U_g), Fig. S5
//! (dispersion, eq:dispersion), the winding of det C(q) (eq:det-C,
//! eq:winding), the surface zero mode (eq:2nd_sol) and the barrier ΔU(α)
//! (eq:delta_U).

use super::drawn::{self, LOOP_SAMPLES};
use super::layout::{
    FIGURE_WIDTH, chart, chart_sized, chart_taller, columns, fit, grown, narrow, page_width, pairs,
    stack, titled_panel,
};
use super::pen;
use super::{FigureInput, configuration, frame, grid, signed_deg};
use crate::encode::Rgb;
use crate::error::{Error, Result};
use crate::model::Ladder;
use crate::render::charts::{line_chart, short_number};
use crate::render::compose::Panel;
use crate::render::palette::{Palette, Role};
use crate::render::style::{self, HAlign, VAlign, size};
use crate::render::{Axis, Canvas, ChartSpec, Legend, Marker, Picture, Series, Theme};
use crate::theory::figures::{DispersionCurve, det_loop};
use crate::theory::gravity;
use std::f64::consts::PI;

/// of two of the curves beside the chart.
pub fn gravity_potential(theme: &Theme, input: &FigureInput) -> Result<Picture> {
    let b = input.model.b;
    let (curves, minima) = drawn::potential(input);
    let mut spec = ChartSpec::new(
        Axis::new("θ (°)").range(-90.0, 90.0),
        Axis::new("U(θ) / mgs per pair"),
    );
    for (i, c) in curves.iter().enumerate() {
        let alpha = c.alpha_deg.unwrap_or(f64::NAN);
        let label = format!("a/b = {} (α = ±{alpha:.1}°)", c.a_over_b);
        spec = spec.series(Series::line(label, pairs(&c.points), curve_color(i)));
    }
    spec = spec.series(Series::scatter(
        "minima U(±α) = −2mgb",
        pairs(&minima),
        Palette.color(Role::Ink),
        Marker::Circle,
    ));
    let which: Vec<usize> = [1, 3]
        .into_iter()
        .filter(|&i| i < input.a_over_b.len())
        .collect();
    // The insets beside the chart keep their size while the chart scales
    // with the page: on a print page side by side, the chart gives up
    // what they take. They go under it where they are a row of four.
    // On a page too short for it (a slide at 20 pt) the chart is drawn
    // flatter until the figure keeps the page.
    let under = insets_in_a_row(theme);
    let body_at = |flat: f32| -> Result<Picture> {
        let insets = potential_insets(theme, input, &which, flat)?;
        let plot = if theme.is_print() && !under {
            let (w, h) = fit(theme, (620, 560));
            let room = page_width(theme, FIGURE_WIDTH)
                .saturating_sub(2 * (size::MARGIN + size::GAP) + insets.pixel_size().0 + 8);
            let h = ((h as f32 * flat) as u32).max(60);
            chart_sized(theme, &spec, (w.min(room).max(60), h))?
        } else {
            chart(theme, &spec, 620, 560)?
        };
        grid(
            theme,
            &[Panel::new(plot), Panel::new(insets)],
            if under { 1 } else { 2 },
        )
    };
    // (At `paper` the insets are one row of four under the chart.)
    let notes = format!(
        "Linkage limit, b/s = {b}: U(θ) = −mg√(2(a² + b²) − 4s²cos²θ − (a² − b²)²/(4s²cos²θ)), \
         a symmetric double well whose minima θ = ±α (cos α = √(a² − b²)/2s) all lie \
         at U_{{min}} = −2mgb. Right: the ladder (4 blocks) at θ = −α and θ = +α for two of the \
         curves; the two orientations are degenerate."
    );
    let framed = |flat: f32| -> Result<Picture> {
        let body = body_at(flat)?;
        frame(
            theme,
            &input.title,
            &body,
            &notes,
            page_width(theme, FIGURE_WIDTH),
        )
    };
    let first = framed(1.0)?;
    if !theme.is_print() || under || first.misfit(&theme.style).is_none() {
        return Ok(first);
    }
    for flat in [0.85, 0.7, 0.6, 0.5, 0.4] {
        let flatter = framed(flat)?;
        if flatter.misfit(&theme.style).is_none() {
            return Ok(flatter);
        }
    }
    Ok(first)
}

/// The U(θ) curves' colours, with their names for the inset labels: none
/// is red, green or blue, the colours of the A springs, the B springs and
/// the block ends drawn in the insets.
const CURVE_COLORS: [(Rgb, &str); 5] = [
    (Palette.color(Role::Ink), "black"),
    (Palette.color(Role::Series(6)), "purple"),
    (Palette.color(Role::Series(5)), "sky blue"),
    (Palette.color(Role::Series(4)), "orange"),
    (Palette.color(Role::Series(3)), "green"),
];

fn curve_color(i: usize) -> Rgb {
    CURVE_COLORS[i % CURVE_COLORS.len()].0
}

/// The name of `curve_color(i)`, for the inset labels.
fn color_name(i: usize) -> &'static str {
    CURVE_COLORS.get(i).map_or("", |c| c.1)
}

/// Ground states of 4 blocks at θ = ∓α for the curves `which`, one row per
/// curve.
/// Whether Fig. 2c's insets are one row of four under the chart (a page
/// whose body is under 600 design pixels wide), not two columns beside it.
fn insets_in_a_row(theme: &Theme) -> bool {
    super::body_room(theme).is_some_and(|r| r < 600.0)
}

/// Fig. 2c's insets; beside the chart, their cells `flat` times their
/// size (a short page).
fn potential_insets(
    theme: &Theme,
    input: &FigureInput,
    which: &[usize],
    flat: f32,
) -> Result<Picture> {
    let b = input.model.b;
    let mut panels = Vec::new();
    // On a narrow page one row of four small ladders under the chart.
    let (cell, columns, short) = match super::body_room(theme).filter(|_| insets_in_a_row(theme)) {
        Some(room) => {
            let w = ((room - 3.0 * size::GAP as f32) / 4.0).floor() as u32;
            ((w, w * 3 / 2), 4, true)
        }
        None => {
            let f = |v: f32| (v * flat).round() as u32;
            ((f(120.0), f(230.0)), 2, false)
        }
    };
    for &i in which {
        let r = input.a_over_b[i];
        let alpha = gravity::alpha_from_lengths(r * b, b)
            .ok_or_else(|| Error::failed(format!("a/b = {r} has no equilibrium")))?
            .to_degrees();
        for sign in [-1.0, 1.0] {
            let l = Ladder::new(input.params(4, b, sign * alpha)?);
            let q = l.ground_state();
            let mut panel = Panel::new(configuration(theme, &l, &q, None, cell)?)
                .caption(signed_deg((sign * alpha * 10.0).round() / 10.0));
            if sign < 0.0 && short {
                panel = panel.label(format!("a/b = {r}"));
            } else if sign < 0.0 {
                panel = panel.label(format!("a/b = {r} ({})", color_name(i)));
            }
            panels.push(panel);
        }
    }
    grid(theme, &panels, columns)
}

/// Fig. S5: ω±(q)/ω₀ against qb for each α of the scene, at its b/s,
/// one panel per α: eq:dispersion as printed (dashed), ×√2 (solid, errata
/// item 9) and the model's eigenvalues (dots).
pub fn dispersion(theme: &Theme, input: &FigureInput) -> Result<Picture> {
    let (lines, dots) = drawn::dispersion(input)?;
    let top = lines
        .iter()
        .flat_map(|c| c.samples.iter())
        .map(|s| s.closed_form_rescaled[1].max(s.numerical[1]))
        .fold(0.0, f64::max);
    let y_max = (top * 1.08 * 2.0).ceil() / 2.0;
    // On a narrow page two panels a row, each half the page (six panels
    // one a row would print taller than a page).
    let (cols, size) = if narrow(theme) {
        let half =
            (page_width(theme, FIGURE_WIDTH) as f32 - 2.0 * size::MARGIN as f32 - size::GAP as f32)
                / 2.0;
        (
            2,
            (half.floor() as u32, (half * 225.0 / 300.0).round() as u32),
        )
    } else {
        (3, fit(theme, (300, 250)))
    };
    let count = lines.len();
    let notes = "ω₀ = √(k/m) = 1/τ, I = m s²/4, constraint δv_{n} = (−1)ⁿ(s/2) sin α δθ_{n}. The printed closed form is √2 too small for this ω₀ \
                 (docs/paper-errata.md item 9): it is exact if ω₀ is read as √(2k/m). The \
                 eigenvalues of the model's constrained periodic chain (kinetic metric diag(m, I), \
                 as in the paper) lie on the corrected curves. ω₊(0) = 4ω₀(s/a)|sin 2α| > 0 is the gap \
                 of the rotational branch; ω₋ is acoustic.";
    let draw_at = |h: u32| -> Result<Picture> {
        let w = size.0;
        let mut panels = Vec::new();
        for (k, (l, d)) in lines.iter().zip(&dots).enumerate() {
            let title = format!("α = {}°", short_number(l.alpha_deg));
            // At a journal style the x axis is labelled once, under the
            // bottom row: the rows above share it (their plots keep their
            // height, the panels lose the label's band).
            let shared = !theme.titles && k + cols < count;
            let size = if shared {
                (
                    w,
                    h.saturating_sub(theme.x_label_area - theme.shared_x_area)
                        .max(60),
                )
            } else {
                (w, h)
            };
            let chart = dispersion_panel(theme, l, d, y_max, size, &title, shared)?;
            panels.push(titled_panel(theme, k, &title, chart));
        }
        let body = grid(theme, &panels, cols)?;
        let body = stack(&body, &dispersion_key(theme, body.pixel_size().0)?);
        frame(
            theme,
            &input.title,
            &body,
            notes,
            page_width(theme, FIGURE_WIDTH),
        )
    };
    // Plots no taller than wide.
    let drawn = grown(
        theme,
        count.div_ceil(cols) as u32,
        size.0.saturating_sub(size.1),
        |extra| draw_at(size.1 + extra),
    )?;
    // A page too short for two rows of them (a slide at 20 pt): plots
    // flatter, each row shorter, until the figure keeps the page.
    if drawn.misfit(&theme.style).is_none() {
        return Ok(drawn);
    }
    for f in [0.85, 0.7, 0.6, 0.5] {
        let flatter = draw_at(((size.1 as f32 * f) as u32).max(60))?;
        if flatter.misfit(&theme.style).is_none() {
            return Ok(flatter);
        }
    }
    Ok(drawn)
}

fn dispersion_panel(
    theme: &Theme,
    lines: &DispersionCurve,
    dots: &DispersionCurve,
    y_max: f64,
    (w, h): (u32, u32),
    title: &str,
    shared_x: bool,
) -> Result<Picture> {
    let x = Axis::new("qb").range(-PI, PI);
    let mut spec = ChartSpec::new(
        if shared_x { x.shared() } else { x },
        Axis::new("ω/ω₀").range(0.0, y_max),
    )
    .title(title);
    for (branch, color) in [
        (1, Palette.color(Role::Series(1))),
        (0, Palette.color(Role::Series(2))),
    ] {
        let pick = |f: fn(&crate::theory::figures::DispersionSample) -> [f64; 2]| {
            lines
                .samples
                .iter()
                .map(|s| (s.qb, f(s)[branch]))
                .collect::<Vec<_>>()
        };
        spec = spec
            .series(Series::line("", pick(|s| s.closed_form), color).dashed())
            .series(Series::line("", pick(|s| s.closed_form_rescaled), color));
        let pts = dots
            .samples
            .iter()
            .map(|s| (s.qb, s.numerical[branch]))
            .collect();
        spec = spec.series(Series::scatter("", pts, color, Marker::Circle).with_width(1.0));
    }
    spec.legend = Legend::Hidden;
    Ok(line_chart(theme, &spec, w, h)?.into())
}

/// The shared key of the dispersion panels: entries left to right, a new
/// row where the next would pass the width.
fn dispersion_key(theme: &Theme, width: u32) -> Result<Picture> {
    let entries: [(&str, Rgb, u8); 6] = [
        ("ω₊ closed form × √2", Palette.color(Role::Series(1)), 0),
        ("ω₊ as printed", Palette.color(Role::Series(1)), 1),
        ("ω₊ model", Palette.color(Role::Series(1)), 2),
        ("ω₋ closed form × √2", Palette.color(Role::Series(2)), 0),
        ("ω₋ as printed", Palette.color(Role::Series(2)), 1),
        ("ω₋ model", Palette.color(Role::Series(2)), 2),
    ];
    let widths: Vec<f32> = entries
        .iter()
        .map(|e| 34.0 + style::text_width(theme.font(), e.0, theme.tick) + 22.0)
        .collect();
    let room = width as f32 - 2.0 * size::MARGIN as f32;
    let mut rows: Vec<Vec<usize>> = vec![vec![]];
    let mut used = 0.0;
    for (k, w) in widths.iter().enumerate() {
        if used + w > room && rows.last().is_some_and(|r| !r.is_empty()) {
            rows.push(vec![]);
            used = 0.0;
        }
        used += w;
        if let Some(r) = rows.last_mut() {
            r.push(k);
        }
    }
    const ROW: f32 = 26.0;
    let mut p = Picture::new(theme, width as f32, 8.0 + ROW * rows.len() as f32);
    for (j, row) in rows.iter().enumerate() {
        let total: f32 = row.iter().map(|&k| widths[k]).sum();
        let mut x = 0.5 * (width as f32 - total);
        let y = 17.0 + ROW * j as f32;
        for &k in row {
            let e = entries[k];
            match e.2 {
                0 => pen::line(&mut p, (x, y), (x + 26.0, y), 2.0, e.1),
                1 => pen::polyline(&mut p, &[(x, y), (x + 26.0, y)], 2.0, e.1, true),
                _ => pen::dot(&mut p, (x + 13.0, y), 3.5, e.1),
            }
            p.text(
                e.0,
                (x + 34.0, y),
                theme.tick,
                Palette.color(Role::Ink),
                (HAlign::Left, VAlign::Middle),
            );
            x += widths[k];
        }
    }
    Ok(p)
}

/// The winding figure: det C_red(q)/(e^(iqb) − 1) (a circle of radius 2|c₁|
/// about −2c₂, errata item 8) and det C_red(q) itself (eq:det-C) over the
/// Brillouin zone for α = ±60°, b/s = 1.3.
pub fn winding(theme: &Theme, input: &FigureInput) -> Result<Picture> {
    let (n, b, alpha) = (input.model.n, input.model.b, input.model.alpha.abs());
    let mut panels = Vec::new();
    for (k, sign) in [1.0, -1.0].into_iter().enumerate() {
        let p = input.params(n, b, sign * alpha)?;
        let (chart, title) = winding_panel(theme, &p)?;
        panels.push(titled_panel(theme, k, &title, chart));
    }
    let body = grid(theme, &panels, columns(theme, 2))?;
    let notes = format!(
        "b/s = {b}. Solid: det C(q)/(e^{{iqb}} − 1) = 2(c₁e^{{iqb}} − c₂), the circle of \
                 radius 2|c₁| about −2c₂ whose winding about the origin (+) is the winding number \
                 n; dashed: det C(q) of the model's reduced chain (the paper's det C), which passes \
                 through 0 at q = 0 (translation along x). For α > 0, |c₂| < c₁ and the loop \
                 encloses the origin (n = 1, surface zero mode at the top); for α < 0 it does not \
                 (n = 0)."
    );
    frame(
        theme,
        &input.title,
        &body,
        &notes,
        page_width(theme, FIGURE_WIDTH),
    )
}

/// The top of the winding panels' imaginary axis: room above the loops
/// for the legend.
const WINDING_TOP: f64 = 3.4;

/// A winding panel and its title.
fn winding_panel(theme: &Theme, p: &crate::model::Params) -> Result<(Picture, String)> {
    let l = det_loop(p, LOOP_SAMPLES)?;
    let n = l
        .winding_number
        .map_or_else(|| "undefined".to_string(), |n| n.to_string());
    let color = if l.alpha_deg > 0.0 {
        Palette.color(Role::Series(1))
    } else {
        Palette.color(Role::Series(2))
    };
    let closed = |v: &[[f64; 2]]| {
        let mut v = pairs(v);
        if let Some(&first) = v.first() {
            v.push(first);
        }
        v
    };
    let title = format!("α = {}: n = {n}", signed_deg(l.alpha_deg));
    let mut spec = ChartSpec::new(Axis::new("Re det C"), Axis::new("Im det C"))
        .title(title.clone())
        .series(Series::line(
            "det C / (e^{iqb} − 1)",
            closed(&l.reduced),
            color,
        ))
        .series(Series::line("det C", closed(&l.det), Palette.color(Role::Ground)).dashed())
        .series(Series::scatter(
            "origin",
            vec![(0.0, 0.0)],
            Palette.color(Role::Ink),
            Marker::Cross,
        ));
    // Room above the loops (|det C| ≤ 1.6 here) for the legend, placed
    // where it covers no data (it sat on the det C circle).
    spec.x = spec.x.range(-2.6, 2.6);
    spec.y = spec.y.range(-2.2, WINDING_TOP);
    spec.equal_aspect = true;
    spec.zero_lines = true;
    spec.legend = Legend::Auto;
    Ok((chart(theme, &spec, 440, 440)?, title))
}

/// The edge-mode figure: |δθ_n| of the reduced chain's null vector (dots)
/// and |c₂/c₁|^{n−1} ∝ e^{−κ(n−1)b} (eq:2nd_sol, lines), log scale; α > 0
/// left (top edge), α < 0 right (bottom edge).
pub fn edge_mode(theme: &Theme, input: &FigureInput) -> Result<Picture> {
    let (n, b) = (input.model.n, input.model.b);
    let notes = format!(
        "N = {n}, b/s = {b}; surface zero mode of the chain with the B nodes pinned \
                 (the paper's edge mode), found as the null vector of the model's compatibility \
                 matrix and normalised to max |δθ_{{n}}| = 1 (dots), against {} (lines). κ = b⁻¹ ln|(b + 2s sin α)/(b − 2s sin α)| changes sign \
                 with α: the mode decays from the top for α > 0 (κ > 0) and from the bottom for \
                 α < 0 (κ < 0). \
                 Beyond |α| ≈ {:.1}° (b < 2s|sin α|) c₂/c₁ < 0 and δθ_{{n}} alternates in sign.",
        crate::theory::formulas::EDGE_DECAY,
        (0.5 * b).min(1.0).asin().to_degrees()
    );
    let cols = columns(theme, 2);
    let draw = |extra: u32| -> Result<Picture> {
        let mut panels = Vec::new();
        for (k, sign) in [1.0, -1.0].into_iter().enumerate() {
            let title = if sign > 0.0 {
                "α > 0: localised at the top"
            } else {
                "α < 0: localised at the bottom"
            };
            let chart = edge_panel(theme, input, sign, title, extra)?;
            panels.push(titled_panel(theme, k, title, chart));
        }
        let body = grid(theme, &panels, cols)?;
        frame(
            theme,
            &input.title,
            &body,
            &notes,
            page_width(theme, FIGURE_WIDTH),
        )
    };
    grown(theme, (2 / cols) as u32, u32::MAX, draw)
}

/// One panel of the edge-mode figure, `extra` pixels taller than its
/// default.
fn edge_panel(
    theme: &Theme,
    input: &FigureInput,
    sign: f64,
    title: &str,
    extra: u32,
) -> Result<Picture> {
    let (n, b) = (input.model.n, input.model.b);
    let mut spec = ChartSpec::new(
        Axis::new("block n").range(0.5, n as f64 + 0.5),
        Axis::new("|δθ_{n}| / max").log(),
    )
    .title(title);
    for (k, &alpha) in input.alphas.iter().enumerate() {
        let e = drawn::edge_profile(input, sign * alpha.abs())?;
        let color = [
            Palette.color(Role::Series(1)),
            Palette.color(Role::Series(2)),
        ]
        .get(k)
        .copied()
        .unwrap_or_else(|| style::series_color(k + 1));
        let kb = e.kappa.map_or(f64::NAN, |x| x * b);
        let line = e.n.iter().map(|&n| n as f64).zip(e.formula.iter().copied());
        let dots =
            e.n.iter()
                .map(|&n| n as f64)
                .zip(e.numerical.iter().copied());
        // One legend entry per α (the notes say which is the formula and
        // which the numerical mode), so that the legend fits inside the
        // plot at every style.
        let mut formula = Series::line("", line.collect(), color);
        formula.label = None;
        spec = spec.series(formula).series(Series::scatter(
            format!(
                "α = {}: κb = {}",
                signed_deg(sign * alpha),
                format!("{kb:.2}").replace('-', "−")
            ),
            dots.collect(),
            color,
            Marker::Circle,
        ));
    }
    spec.y = spec.y.range(1e-9, 3.0);
    chart_taller(theme, &spec, (440, 420), extra)
}

/// The barrier figure: ΔU(α) = U(0) − U(α) (eq:delta_U) for b/s = 1.3, and
/// the same from the model's two-block linkage solved at θ = 0 (dots).
pub fn barrier(theme: &Theme, input: &FigureInput) -> Result<Picture> {
    let b = input.model.b;
    let (curve, dots) = drawn::barrier(input);
    let (curve, dots) = (pairs(&curve), pairs(&dots));
    let mut spec = ChartSpec::new(
        Axis::new("equilibrium angle α (°)").range(-2.0, 92.0),
        Axis::new("ΔU / mgs per pair"),
    )
    .series(Series::line(
        "ΔU(α), closed form",
        curve,
        Palette.color(Role::Series(1)),
    ))
    .series(Series::scatter(
        "model linkage, U(0) − U(α)",
        dots,
        Palette.color(Role::Ink),
        Marker::Circle,
    ));
    spec.legend = Legend::UpperLeft;
    let plot = chart(theme, &spec, 800, 500)?;
    let notes = format!(
        "b/s = {b}. ΔU(α) = 2mgb(1 − √(1 − (s²/b²)sin⁴α)): the height of the criss-cross \
                 configuration θ = 0 above the two minima θ = ±α of U(θ). Dots: centre spacing \
                 of the model's two-block chain with both springs at rest length, solved by \
                 Newton's method at θ = 0 and θ = α. The barrier vanishes as α → 0 (the gapless \
                 configuration of Fig. S3) and is largest for the symmetric toy α → 90°."
    );
    frame(theme, &input.title, &plot, &notes, page_width(theme, 840))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn u_curves_avoid_the_spring_and_block_end_colours() {
        for (c, name) in CURVE_COLORS {
            for taken in [Palette.color(Role::SpringA), Palette.color(Role::SpringB)] {
                let d = crate::render::theme::delta_e(c, taken);
                assert!(d > 20.0, "{name} is {d:.1} ΔE from {taken:?}");
            }
        }
    }

    /// The value of attribute `name` in the SVG element `e`.
    fn attr<'a>(e: &'a str, name: &str) -> Option<&'a str> {
        let i = e.find(&format!(" {name}=\""))? + name.len() + 3;
        e[i..].split('"').next()
    }

    /// The winding panels' legends cover no data: no point of a drawn loop
    /// (det C and det C/(e^{iqb} − 1)) within the legend's frame (panel
    /// (a)'s legend, fixed at the upper left, lay on the det C circle).
    #[test]
    fn winding_legends_cover_no_data() {
        use crate::render::{Item, Style, StyleName};
        for style in [Style::default(), Style::named(StyleName::Paper)] {
            let theme = Theme::of(&style);
            for alpha in [60.0, -60.0] {
                let p = crate::model::Params::defaults()
                    .with_n(10)
                    .with_b(1.3)
                    .with_alpha_deg(alpha)
                    .with_gamma(0.02)
                    .with_gravity(2e-4)
                    .with_inertia(0.25)
                    .validated()
                    .unwrap();
                let (picture, _) = winding_panel(&theme, &p).unwrap();
                let Some(Item::Chart { chart, .. }) = picture
                    .items()
                    .iter()
                    .find(|i| matches!(i, Item::Chart { .. }))
                else {
                    panic!("no chart");
                };
                let svg = &chart.svg;
                // The legend's frame: the rect drawn in the legend's
                // translucent white; without one the legend is outside
                // the plot, its entries beside or under it.
                let frame = svg
                    .split("<rect")
                    .skip(1)
                    .find(|e| e.contains("opacity=\"0.9"))
                    .map(|e| {
                        let v = |n| attr(e, n).and_then(|v| v.parse::<f32>().ok()).unwrap();
                        (v("x"), v("y"), v("x") + v("width"), v("y") + v("height"))
                    });
                let Some(frame) = frame else {
                    let (px, py) = (chart.plot_x.unwrap(), chart.plot_y.unwrap());
                    for e in svg.split("<text").skip(1) {
                        let body = e.split('>').nth(1).unwrap_or("");
                        if body.starts_with("origin") || body.starts_with("det C") {
                            let v = |n| attr(e, n).and_then(|v| v.parse::<f32>().ok()).unwrap();
                            let inside = v("x") > px.0 as f32
                                && v("x") < px.1 as f32
                                && v("y") > py.0 as f32
                                && v("y") < py.1 as f32;
                            assert!(!inside, "{alpha}° at {style:?}: a legend entry in the plot");
                        }
                    }
                    continue;
                };
                let loops = [
                    Palette.color(Role::Series(1)),
                    Palette.color(Role::Series(2)),
                    Palette.color(Role::Ground),
                ]
                .map(|c| crate::render::style::hex(c).to_uppercase());
                let mut points = 0;
                for e in svg.split("<polyline").skip(1) {
                    let stroke = attr(e, "stroke").unwrap_or("").to_uppercase();
                    if !loops.contains(&stroke) {
                        continue;
                    }
                    for xy in attr(e, "points").unwrap_or("").split_whitespace() {
                        let mut it = xy.split(',').map(|v| v.parse::<f32>().unwrap());
                        let (x, y) = (it.next().unwrap(), it.next().unwrap());
                        points += 1;
                        assert!(
                            !(x >= frame.0 && x <= frame.2 && y >= frame.1 && y <= frame.3),
                            "{alpha}° at {style:?}: a loop point ({x}, {y}) under the legend {frame:?}"
                        );
                    }
                }
                assert!(points > 100, "{points} loop points read");
            }
        }
    }
}
