//! Figures that show configurations of the model: Fig. 2d (the two
//! degenerate ground states), Fig. S3 (the gapless α = 0 configuration)
//! and Fig. S4 (zero-mode shapes, eq:zm_n and the model's true zero modes).

use super::{FigureInput, configuration, frame, grid, signed_deg};
use crate::error::Result;
use crate::model::Ladder;
use crate::render::charts::line_chart;
use crate::render::compose::Panel;
use crate::render::style::{self, DARK};
use crate::render::{Axis, ChartSpec, Legend, Marker, Picture, Series};
use crate::theory::figures::{gapless_configuration, zero_mode_shape};
use crate::theory::gravity;

/// Size of one full-ladder snapshot.
const LADDER_SIZE: (u32, u32) = (200, 560);

/// Fig. 2d: the ground states of both signs, and the two overlaid.
pub fn ground_states(input: &FigureInput) -> Result<Picture> {
    let (n, b, alpha) = (input.model.n, input.model.b, input.model.alpha.abs());
    let plus = Ladder::new(input.params(n, b, alpha)?);
    let minus = Ladder::new(input.params(n, b, -alpha)?);
    let (qp, qm) = (plus.ground_state(), minus.ground_state());
    let panels = vec![
        Panel::new(configuration(&plus, &qp, None, LADDER_SIZE)?)
            .label("(i)")
            .caption(format!("α = {}", signed_deg(alpha))),
        Panel::new(configuration(&minus, &qm, None, LADDER_SIZE)?)
            .label("(ii)")
            .caption(format!("α = {}", signed_deg(-alpha))),
        Panel::new(configuration(&plus, &qp, Some(&qm), LADDER_SIZE)?)
            .label("(iii)")
            .caption("(i) over (ii) in grey"),
    ];
    let body = grid(&panels, 3)?;
    let notes = format!(
        "N = {n}, b/s = {b}, a = {:.3} s. Each block is drawn from its red A end to its \
         blue B end, which marks its orientation: the blocks of (i) and (ii) tilt the opposite \
         way (sin θ = ±{:.2}), while the centres coincide (iii). Both states have the same \
         energy U_{{min}} = −2mgb per pair of blocks.",
        plus.a,
        alpha.to_radians().sin()
    );
    frame(&input.title, &body, &notes, 760)
}

/// Fig. S3: the α = 0 configuration (b/s = 1.3, N = 10) beside its
/// single-well U(θ) (eq:U_g with a² = b² + 4s²).
pub fn gapless(input: &FigureInput) -> Result<Picture> {
    let (n, b) = (input.model.n, input.model.b);
    let p = input.params(n, b, 0.0)?;
    let (a, q) = gapless_configuration(&p, n, b)?;
    let ladder = Ladder::new(p);
    let snap = configuration(&ladder, &q, None, LADDER_SIZE)?;
    let chart = gapless_potential(a, b)?;
    let panels = vec![
        Panel::new(snap)
            .label("(a)")
            .caption(format!("α = 0°, N = {n}")),
        Panel::new(chart)
            .label("(b)")
            .caption("a single minimum at θ = 0"),
    ];
    let body = grid(&panels, 2)?;
    let notes = format!(
        "b/s = {b}, a = √(b² + 4s²) = {a:.3} s: the A links are as long as the diagonal of a \
         pair of flat blocks, the blocks lie flat (θ = 0) and the double well of Fig. 2c \
         degenerates into one flat-bottomed minimum (U − U_{{min}} ∝ θ⁴): the bistability and \
         the gap ω₊(0) are lost."
    );
    frame(&input.title, &body, &notes, 760)
}

/// U(θ) for the gapless lengths with the minimum marked.
fn gapless_potential(a: f64, b: f64) -> Result<Picture> {
    let points: Vec<(f64, f64)> = (0..=720)
        .filter_map(|k| {
            let th = -89.75 + 179.5 * k as f64 / 720.0;
            gravity::potential(a, b, th.to_radians()).map(|u| (th, u))
        })
        .collect();
    let mut spec = ChartSpec::new(
        Axis::new("θ (degrees)").range(-90.0, 90.0),
        Axis::new("U(θ) / (m g s), per pair of blocks"),
    )
    .series(Series::line("U(θ), a² = b² + 4s²", points, style::RED))
    .series(Series::scatter(
        "U_{min} = −2mgb",
        vec![(0.0, gravity::u_min(b))],
        DARK,
        Marker::Circle,
    ));
    spec.legend = Legend::Auto;
    Ok(line_chart(&spec, 560, 440)?.into())
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
pub fn zero_modes(input: &FigureInput) -> Result<Picture> {
    let (n, b, alpha) = (input.model.n, input.model.b, input.model.alpha);
    let p = input.params(n, b, alpha)?;
    let ladder = Ladder::new(p);
    let size = (200, 500);
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
            Panel::new(configuration(&ladder, &z.model, Some(&z.ground), size)?)
                .label(format!("{label} model"))
                .caption(caption.clone()),
        );
        paper.push(
            Panel::new(configuration(&ladder, &z.paper, Some(&z.ground), size)?)
                .label(format!("{primed} as printed"))
                .caption(caption),
        );
        residuals.push((m, z.paper_residual, z.model_residual));
    }
    model.extend(paper);
    let body = grid(&model, 4)?;
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
    frame(&input.title, &body, &notes, 760)
}
