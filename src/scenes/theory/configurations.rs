//! Figures that show configurations of the model: Fig. 2d (the two
//! degenerate ground states), Fig. S3 (the gapless α = 0 configuration)
//! and Fig. S4 (zero-mode shapes, eq:zm_n and the model's true zero modes).

use super::{FigureInput, configuration, frame, grid, pen, signed_deg};
use crate::error::Result;
use crate::model::Ladder;
use crate::model::ladder::nodes;
use crate::render::charts::{line_chart, line_chart_growing};
use crate::render::compose::Panel;
use crate::render::palette::{Palette, Role};
use crate::render::snapshot::{Region, Snapshot, pixel_of};
use crate::render::style::size;
use crate::render::{Axis, ChartSpec, Legend, Marker, Picture, Series, Theme};
use crate::theory::figures::{gapless_configuration, zero_mode_shape};
use crate::theory::gravity;

/// Size of one full-ladder snapshot.
const LADDER_SIZE: (u32, u32) = (200, 560);

/// Fig. 2d: the ground states of both signs, and the two overlaid.
pub fn ground_states(theme: &Theme, input: &FigureInput) -> Result<Picture> {
    let (n, b, alpha) = (input.model.n, input.model.b, input.model.alpha.abs());
    let plus = Ladder::new(input.params(n, b, alpha)?);
    let minus = Ladder::new(input.params(n, b, -alpha)?);
    let (qp, qm) = (plus.ground_state(), minus.ground_state());
    let size = super::cells(theme, LADDER_SIZE, 3);
    let with_arrows = |ladder: &Ladder, q: &[f64]| -> Result<Picture> {
        let mut p = configuration(theme, ladder, q, None, size)?;
        orientation_arrows(&mut p, ladder, q)?;
        Ok(p)
    };
    let panels = vec![
        Panel::new(with_arrows(&plus, &qp)?)
            .label("(i)")
            .caption(format!("α = {}", signed_deg(alpha))),
        Panel::new(with_arrows(&minus, &qm)?)
            .label("(ii)")
            .caption(format!("α = {}", signed_deg(-alpha))),
        Panel::new(configuration(theme, &plus, &qp, Some(&qm), size)?)
            .label("(iii)")
            .caption("(i) over (ii) in grey"),
    ];
    let body = grid(theme, &panels, 3)?;
    let notes = format!(
        "N = {n}, b/s = {b}, a = {:.3} s. Each block is drawn from its red A end to its \
         blue B end; the arrow at its height points from B to A: its orientation, up in every \
         block of (i) and down in every block of (ii). The blocks of (i) and (ii) tilt the \
         opposite way (sin θ = ±{:.2}), while the centres coincide (iii). Both states have the \
         same energy U_{{min}} = −2mgb per pair of blocks.",
        plus.a,
        alpha.to_radians().sin()
    );
    frame(theme, &input.title, &body, &notes, 760)
}

/// An arrow beside each block of a [`configuration`] picture, in a column
/// to the right of the ladder at the height of the block's centre, parallel
/// to the block and pointing from its B end to its A end (the paper's
/// Fig. 2d: "Arrow indicates orientation of each block").
fn orientation_arrows(p: &mut Picture, ladder: &Ladder, q: &[f64]) -> Result<()> {
    let mut snap = Snapshot::new(ladder, q)?;
    snap.clamp = false;
    let (w, h) = p.pixel_size();
    let region = Region::full(w, h);
    let ends: Vec<((f32, f32), (f32, f32))> = (0..ladder.n())
        .map(|i| {
            let (a, b) = nodes(q, i);
            (pixel_of(region, &snap, a), pixel_of(region, &snap, b))
        })
        .collect();
    let right = ends
        .iter()
        .flat_map(|(a, b)| [a.0, b.0])
        .fold(f32::MIN, f32::max);
    let column = right + 16.0;
    for (pa, pb) in ends {
        let (dx, dy) = (pa.0 - pb.0, pa.1 - pb.1);
        let len = (dx * dx + dy * dy).sqrt().max(1e-3);
        let (ux, uy) = (dx / len, dy / len);
        let half = 0.4 * len;
        let mid = (column, 0.5 * (pa.1 + pb.1));
        pen::arrow(
            p,
            (mid.0 - half * ux, mid.1 - half * uy),
            (mid.0 + half * ux, mid.1 + half * uy),
            1.6,
            Palette.color(Role::Ink),
        );
    }
    Ok(())
}

/// Fig. S3: the α = 0 configuration (b/s = 1.3, N = 10) beside its
/// single-well U(θ) (eq:U_g with a² = b² + 4s²).
pub fn gapless(theme: &Theme, input: &FigureInput) -> Result<Picture> {
    let (n, b) = (input.model.n, input.model.b);
    let p = input.params(n, b, 0.0)?;
    let (a, q) = gapless_configuration(&p, n, b)?;
    let ladder = Ladder::new(p);
    // On a narrow page the ladder stays beside the chart, slimmer, and the
    // chart takes the rest of the row.
    let narrow = super::body_room(theme).is_some_and(|r| r < 600.0);
    let (size, chart_size) = if narrow {
        let room = super::body_room(theme).unwrap_or(560.0).floor() as u32;
        let h = room * 3 / 5;
        let ladder_w = h / 3;
        ((ladder_w, h), (room - ladder_w - size::GAP, h))
    } else {
        (
            super::cells(theme, LADDER_SIZE, 3),
            super::cells(theme, (560, 440), 1),
        )
    };
    let snap = configuration(theme, &ladder, &q, None, size)?;
    // A legend that goes under a narrow chart (on two lines on a narrower
    // page) makes the chart taller by its band, so that the plot keeps
    // the height it was given.
    let most = narrow.then(|| theme.style.fit_box().map_or(u32::MAX, |(_, h)| h as u32));
    let chart = gapless_potential(theme, a, b, chart_size, most)?;
    let panels = vec![
        Panel::new(snap)
            .label("(a)")
            .caption(format!("α = 0°, N = {n}")),
        Panel::new(chart)
            .label("(b)")
            .caption("a single minimum at θ = 0"),
    ];
    let body = grid(theme, &panels, 2)?;
    let notes = format!(
        "b/s = {b}, a = √(b² + 4s²) = {a:.3} s: the A links are as long as the diagonal of a \
         pair of flat blocks, the blocks lie flat (θ = 0) and the double well of Fig. 2c \
         degenerates into one flat-bottomed minimum (U − U_{{min}} grows as θ⁴): the bistability and \
         the gap ω₊(0) are lost."
    );
    frame(theme, &input.title, &body, &notes, 760)
}

/// U(θ) for the gapless lengths with the minimum marked, `w` × `h`
/// pixels, or taller by the legend's band (up to `most`) when given.
fn gapless_potential(
    theme: &Theme,
    a: f64,
    b: f64,
    (w, h): (u32, u32),
    most: Option<u32>,
) -> Result<Picture> {
    let points: Vec<(f64, f64)> = (0..=720)
        .filter_map(|k| {
            let th = -89.75 + 179.5 * k as f64 / 720.0;
            gravity::potential(a, b, th.to_radians()).map(|u| (th, u))
        })
        .collect();
    let mut spec = ChartSpec::new(
        Axis::new("θ (°)").range(-90.0, 90.0),
        Axis::new("U(θ) / mgs per pair"),
    )
    .series(Series::line(
        "U(θ), a² = b² + 4s²",
        points,
        Palette.color(Role::Series(1)),
    ))
    .series(Series::scatter(
        "U_{min} = −2mgb",
        vec![(0.0, gravity::u_min(b))],
        Palette.color(Role::Ink),
        Marker::Circle,
    ));
    spec.legend = Legend::Auto;
    Ok(match most {
        Some(most) => line_chart_growing(theme, &spec, w, h, most)?,
        None => line_chart(theme, &spec, w, h)?,
    }
    .into())
}

/// A residual that is zero to rounding as "< 10⁻¹²", otherwise 2 decimals.
fn tiny(x: f64) -> String {
    if x < 1e-12 {
        "< 10⁻¹²".into()
    } else {
        format!("{x:.2}")
    }
}

/// Fig. S4: the model's zero modes (top row, exact) and the paper's
/// eq:zm_n shapes (bottom row) for m = 1, ε₀ = 0.1 and m = 5, ε₀ = 0.05.
pub fn zero_modes(theme: &Theme, input: &FigureInput) -> Result<Picture> {
    let (n, b, alpha) = (input.model.n, input.model.b, input.model.alpha);
    let p = input.params(n, b, alpha)?;
    let ladder = Ladder::new(p);
    let size = super::cells(theme, (200, 500), 4);
    let mut model = Vec::new();
    let mut paper = Vec::new();
    let mut residuals = Vec::new();
    for (k, mode) in input.modes.iter().enumerate() {
        let (m, eps) = (mode.m, mode.epsilon);
        let z = zero_mode_shape(&p, m, eps);
        let letter = char::from(b'a' + (k % 26) as u8);
        let (label, primed) = (format!("({letter})"), format!("({letter}′)"));
        let caption = format!("m = {m}, ε₀ = {eps}");
        model.push(
            Panel::new(configuration(
                theme,
                &ladder,
                &z.model,
                Some(&z.ground),
                size,
            )?)
            .label(format!("{label} model"))
            .caption(caption.clone()),
        );
        paper.push(
            Panel::new(configuration(
                theme,
                &ladder,
                &z.paper,
                Some(&z.ground),
                size,
            )?)
            .label(format!("{primed} as printed"))
            .caption(caption),
        );
        residuals.push((m, z.paper_residual, z.model_residual));
    }
    model.extend(paper);
    let body = grid(theme, &model, 4)?;
    let res: Vec<String> = residuals
        .iter()
        .map(|(m, p, q)| format!("m = {m}: {p:.2} as printed, {} for the model", tiny(*q)))
        .collect();
    let notes = format!(
        "N = {n}, b/s = {b}, α = {alpha}°; deformed configuration in colour, ground state in \
         grey. (a), (b): the model's true zero modes (null vectors of its compatibility \
         matrix, δv staggered, docs/paper-errata.md item 5); for m = 5 (k = π/b) the zero \
         mode is a rigid shift along y. (a′), (b′): the paper's zero-mode formula as printed (Fig. S4), \
         which stretches the springs. Relative spring stretch |C δq|/|δq|: {}.",
        res.join("; ")
    );
    frame(theme, &input.title, &body, &notes, 760)
}

#[cfg(test)]
mod tests {
    use super::*;

    use tiny_skia::Pixmap;

    /// Widest run of dark pixels in the `rows` rows from the top of the
    /// first (topmost) arrow.
    fn head_width_at_top(p: &Pixmap, rows: u32) -> u32 {
        let dark = |x: u32, y: u32| p.pixel(x, y).is_some_and(|c| c.red() < 128);
        let top = (0..p.height())
            .find(|&y| (0..p.width()).any(|x| dark(x, y)))
            .expect("an arrow was drawn");
        (top..top + rows)
            .map(|y| (0..p.width()).filter(|&x| dark(x, y)).count() as u32)
            .max()
            .unwrap_or(0)
    }

    #[test]
    fn arrows_point_up_in_one_ground_state_and_down_in_the_other() {
        let input = FigureInput {
            title: String::new(),
            model: crate::scene::Model::default(),
            alphas: vec![],
            a_over_b: vec![],
            modes: vec![],
            limits: Default::default(),
        };
        let mut widths = Vec::new();
        for alpha in [75.0, -75.0] {
            let ladder = Ladder::new(input.params(10, 1.2, alpha).unwrap());
            let q = ladder.ground_state();
            let theme = Theme::of(&Default::default());
            let mut p = Picture::new(&theme, LADDER_SIZE.0 as f32, LADDER_SIZE.1 as f32);
            orientation_arrows(&mut p, &ladder, &q).unwrap();
            widths.push(head_width_at_top(&p.to_pixmap().unwrap(), 6));
        }
        // An arrowhead at the top is wide; a shaft at the top is thin.
        assert!(widths[0] >= 6 && widths[1] <= 3, "{widths:?}");
    }
}
