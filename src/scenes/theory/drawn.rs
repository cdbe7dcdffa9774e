//! The numbers a theory figure draws, for its data file: the curves and
//! points of Fig. 2c (U(θ), eq:U_g), Fig. S5 (eq:dispersion), the winding
//! of det C(q) (eq:det-C), the surface zero mode (eq:2nd_sol) and the
//! barrier ΔU(α) (eq:delta_U). The charts are drawn from these same
//! functions (`plots`), so the data file holds exactly what is plotted.

use super::FigureInput;
use crate::error::Result;
use crate::scene::TheoryFigure;
use crate::theory::figures::{
    DetLoop, DispersionCurve, EdgeModeProfile, PotentialCurve, barrier_curve, det_loop,
    dispersion_curves, edge_mode_profile, potential_curves,
};
use crate::theory::gravity;
use serde::Serialize;

/// Samples of each U(θ) curve of Fig. 2c on θ ∈ (−90°, 90°).
pub const POTENTIAL_SAMPLES: usize = 1441;
/// Samples of the dispersion's lines and of its dots on qb ∈ [−π, π].
pub const LINE_SAMPLES: usize = 128;
pub const DOT_SAMPLES: usize = 24;
/// Samples of the det C(q) loop over the zone.
pub const LOOP_SAMPLES: usize = 720;
/// Samples of the closed-form barrier on α ∈ [0°, 90°].
pub const BARRIER_SAMPLES: usize = 180;
/// The model linkage's barrier is solved every this many degrees.
pub const BARRIER_DOT_STEP_DEG: f64 = 5.0;

/// What a theory figure plots, by figure (its data file's `drawn`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "figure", rename_all = "kebab-case")]
pub enum Drawn {
    /// Fig. 2c: U(θ) (mgs per pair, θ in degrees) for each a/b, and the
    /// minima (±α, −2mgb) marked on them.
    GravityPotential {
        curves: Vec<PotentialCurve>,
        minima: Vec<[f64; 2]>,
    },
    /// Fig. S5: ω±(qb) as printed, × √2, and the model's eigenvalues,
    /// at the lines' samples and at the dots' (ω in 1/τ).
    Dispersion {
        lines: Vec<DispersionCurve>,
        dots: Vec<DispersionCurve>,
    },
    /// det C(q) and det C/(e^{iqb} − 1) over the zone, α > 0 then α < 0.
    Winding { loops: Vec<DetLoop> },
    /// |δθ_n| of the surface zero mode, numerical and formula, for every
    /// α at the top edge (α > 0) and then at the bottom (α < 0).
    EdgeMode { profiles: Vec<EdgeModeProfile> },
    /// ΔU(α) (mgs per pair) in closed form (α in degrees), and the model
    /// linkage's U(0) − U(α) (dots).
    Barrier {
        curve: Vec<[f64; 2]>,
        model: Vec<[f64; 2]>,
    },
}

/// The numbers figure `figure` draws from `input`; `None` for the
/// drawings (2b, 2d, S3, S4), which plot no numbers.
pub fn drawn_numbers(figure: TheoryFigure, input: &FigureInput) -> Result<Option<Drawn>> {
    Ok(Some(match figure {
        TheoryFigure::GravityPotential => {
            let (curves, minima) = potential(input);
            Drawn::GravityPotential { curves, minima }
        }
        TheoryFigure::Dispersion => {
            let (lines, dots) = dispersion(input)?;
            Drawn::Dispersion { lines, dots }
        }
        TheoryFigure::Winding => Drawn::Winding {
            loops: [1.0, -1.0]
                .into_iter()
                .map(|sign| winding_loop(input, sign))
                .collect::<Result<_>>()?,
        },
        TheoryFigure::EdgeMode => Drawn::EdgeMode {
            profiles: [1.0, -1.0]
                .into_iter()
                .flat_map(|sign| input.alphas.iter().map(move |&a| sign * a.abs()))
                .map(|alpha| edge_profile(input, alpha))
                .collect::<Result<_>>()?,
        },
        TheoryFigure::Barrier => {
            let (curve, model) = barrier(input);
            Drawn::Barrier { curve, model }
        }
        _ => return Ok(None),
    }))
}

/// Fig. 2c's curves and the minima marked on them.
pub(super) fn potential(input: &FigureInput) -> (Vec<PotentialCurve>, Vec<[f64; 2]>) {
    let curves = potential_curves(input.model.b, &input.a_over_b, POTENTIAL_SAMPLES);
    let minima = curves
        .iter()
        .flat_map(|c| {
            let alpha = c.alpha_deg.unwrap_or(f64::NAN);
            let u = gravity::u_min(c.b);
            [[-alpha, u], [alpha, u]]
        })
        .collect();
    (curves, minima)
}

/// Fig. S5's lines and dots.
pub(super) fn dispersion(
    input: &FigureInput,
) -> Result<(Vec<DispersionCurve>, Vec<DispersionCurve>)> {
    let b = input.model.b;
    let base = input.params(input.model.n, b, input.model.alpha)?;
    Ok((
        dispersion_curves(&base, b, &input.alphas, LINE_SAMPLES)?,
        dispersion_curves(&base, b, &input.alphas, DOT_SAMPLES)?,
    ))
}

/// The det C(q) loop at α of sign `sign` (|α| the scene's).
pub(super) fn winding_loop(input: &FigureInput, sign: f64) -> Result<DetLoop> {
    let (n, b, alpha) = (input.model.n, input.model.b, input.model.alpha.abs());
    det_loop(&input.params(n, b, sign * alpha)?, LOOP_SAMPLES)
}

/// The surface zero mode's profile at α (degrees, signed).
pub(super) fn edge_profile(input: &FigureInput, alpha: f64) -> Result<EdgeModeProfile> {
    let (n, b) = (input.model.n, input.model.b);
    edge_mode_profile(&input.params(n, b, alpha)?)
}

/// The barrier in closed form, and the model linkage's where it solves.
pub(super) fn barrier(input: &FigureInput) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
    let curve = barrier_curve(input.model.b, BARRIER_SAMPLES);
    let steps = (90.0 / BARRIER_DOT_STEP_DEG).round() as usize;
    let model = (0..=steps)
        .map(|k| BARRIER_DOT_STEP_DEG * k as f64)
        .filter_map(|a| model_barrier(input, a).map(|du| [a, du]))
        .collect();
    (curve, model)
}

/// U(0) − U(α) from the model's two-block linkage (no closed form).
fn model_barrier(input: &FigureInput, alpha_deg: f64) -> Option<f64> {
    let b = input.model.b;
    let p = input.params(2, b, alpha_deg).ok()?;
    let guess = [b, -p.alpha.cos().powi(2)];
    let at_zero = gravity::model_pair_spacing(&p, 0.0, guess)?;
    let at_alpha = gravity::model_pair_spacing(&p, p.alpha, [b, -p.alpha.cos()])?;
    Some(2.0 * (at_alpha[0] - at_zero[0]))
}
