//! The experiments' figures (docs/experiments.md; docs/experiments.md): what
//! each level of model predicts for the paper's water tank and printed
//! linkage, in the apparatus' units (s, cm, cm/s), beside the measurements.
//!
//! Every run is the scene's `[apparatus]` with some of its terms switched,
//! integrated by RK4 at [`STEP`] τ (the scheme that takes every term: a
//! velocity-dependent mass matrix, drag, pin friction), or, with ribbons
//! and contact, by dopri5 at [`RIBBON_RTOL`]; each run's integrator is in
//! the data file. No coefficient is fitted: the levels
//! switch terms of the apparatus on, nothing else.
//!
//! Files: `runs` makes and runs a figure's variants, `decided` is the rule
//! that ends each run, and one file per figure: `positions` (tank
//! positions), `levels` (tank levels), `linkage` (linkage friction).

mod decided;
mod levels;
mod linkage;
mod positions;
mod runs;

pub(crate) use runs::decided_run;

pub use decided::{
    DECIDABLE_FRACTION_OF_BLOCK_RATE, HELD_FOR_S, HELD_FRACTION_OF_BLOCK_RATE, HELD_RATE,
    block_rate, decidable,
};
pub use levels::{LevelResult, STIFF_TOLERANCE, level_names, levels};
pub use linkage::{Front, fronts, most_pin_frictions, refined_fronts, steps};
pub use positions::motor_marker;

use super::data::{ApparatusNumbers, BulkFit, RunData};
use crate::error::Result;
use crate::render::charts::{self, ChartSpec};
use crate::render::{Picture, Theme};
use crate::scene::apparatus::{
    Apparatus, Damping, ExperimentFigure, Material, PaperWord, StiffWord, Stiffness,
};
use crate::scene::{Scene, describe};

/// The tank's measured kink speed (cm/s; main text and supplement).
pub const MEASURED_KINK_CM_S: f64 = 6.0;
/// The tank's measured c_antikink / c_kink.
pub const MEASURED_RATIO: f64 = 1.75;
/// The motor speeds of the tank's runs (Hz).
pub const MOTORS_HZ: [f64; 3] = [0.1, 0.2, 0.4];
/// The motor speed of the levels' figure (Hz), the middle one.
pub const LEVELS_MOTOR_HZ: f64 = 0.2;
/// The pin friction coefficients μ_p the linkage's figure starts from:
/// its range, coarse; [`refined_fronts`] adds the points between.
pub const PIN_FRICTION: [f64; 4] = [0.0, 0.5, 1.0, 1.5];
/// The linkage's figure halves every interval of μ_p at whose ends a
/// front differs, down to this width.
pub const PIN_FRICTION_RESOLUTION: f64 = 0.125;
/// The RK4 step of every run, in τ (docs/experiments.md: halving it moves
/// the speeds of a running wave by < 10⁻⁶).
pub const STEP: f64 = 0.125;
/// The tolerance of dopri5 for a level with ribbons and contact, whose
/// contact refuses RK4 at [`STEP`] (docs/experiments.md, "The water tank
/// with ribbons": at 10⁻⁶ every arrival of the scene's tank at 0.1, 0.2
/// and 0.4 Hz is within 0.008 s of RK4 at τ/128, nearer than RK4 at the
/// contact's stable step, for a quarter of its force evaluations).
pub const RIBBON_RTOL: f64 = 1e-6;
/// The step of Moreau's time-stepping for the inextensible ribbons' level,
/// in τ; its check runs at half of it (docs/experiments.md,
/// "Inextensible ribbons").
pub const INEXTENSIBLE_STEP: f64 = 0.05;

/// The levels of model of the tank (docs/experiments.md): name and what it switches on
/// over the bare apparatus (two-way stiff links, gravity g).
pub const LEVELS: [(&str, Level); 7] = [
    (
        "1 paper: linear damping γ",
        Level {
            damping: true,
            buoyancy_and_drag: false,
            added_mass: false,
            tape: false,
            ribbons: false,
            inextensible: false,
        },
    ),
    (
        "2 buoyancy + quadratic drag",
        Level {
            damping: false,
            buoyancy_and_drag: true,
            added_mass: false,
            tape: false,
            ribbons: false,
            inextensible: false,
        },
    ),
    (
        "3 + added mass",
        Level {
            damping: false,
            buoyancy_and_drag: true,
            added_mass: true,
            tape: false,
            ribbons: false,
            inextensible: false,
        },
    ),
    (
        "4 + tension-only tape",
        Level {
            damping: false,
            buoyancy_and_drag: true,
            added_mass: true,
            tape: true,
            ribbons: false,
            inextensible: false,
        },
    ),
    (
        "5 all terms (+ γ)",
        Level {
            damping: true,
            buoyancy_and_drag: true,
            added_mass: true,
            tape: true,
            ribbons: false,
            inextensible: false,
        },
    ),
    (
        "6 ribbons + contact",
        Level {
            damping: false,
            buoyancy_and_drag: true,
            added_mass: true,
            tape: false,
            ribbons: true,
            inextensible: false,
        },
    ),
    (
        "7 inextensible ribbons",
        Level {
            damping: false,
            buoyancy_and_drag: true,
            added_mass: true,
            tape: false,
            ribbons: true,
            inextensible: true,
        },
    ),
];

/// The terms one level of model switches on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Level {
    /// The paper's linear damping ("paper": γ/√G kept).
    pub damping: bool,
    pub buoyancy_and_drag: bool,
    pub added_mass: bool,
    pub tape: bool,
    /// The toy as built (docs/experiments.md, "The toy as built"): the
    /// plates as thick as the apparatus says, held by tapes glued at their
    /// ends and wrapped round them in place of the links (`ribbon_anchors`
    /// at its default, the paper's nodes), with contact between acrylic
    /// plates.
    pub ribbons: bool,
    /// The ribbons inextensible (`stiffness = "inextensible"`), run by
    /// Moreau's time-stepping at [`INEXTENSIBLE_STEP`].
    pub inextensible: bool,
}

impl Level {
    pub(super) fn apply(self, a: &mut Apparatus) {
        a.damping = self.damping.then_some(Damping::Word(PaperWord::Paper));
        a.buoyancy = self.buoyancy_and_drag;
        a.drag = self.buoyancy_and_drag;
        a.added_mass = self.added_mass;
        a.tension_only = self.tape;
        a.ribbons = self.ribbons;
        a.contact = self.ribbons.then_some(Material::Acrylic);
        if self.inextensible {
            a.stiffness = Stiffness::Word(StiffWord::Inextensible);
        }
    }
}

/// The figure `which` of `scene` (whose `[apparatus]` is the tank's or the
/// linkage's), with every run's data.
pub fn experiment_figure(
    theme: &Theme,
    scene: &Scene,
    which: ExperimentFigure,
) -> Result<(Picture, Vec<RunData>)> {
    let (picture, data) = match which {
        ExperimentFigure::TankPositions => positions::tank_positions(theme, scene)?,
        ExperimentFigure::TankLevels => levels::tank_levels(theme, scene)?,
        ExperimentFigure::LinkageFriction => linkage::linkage_friction(theme, scene)?,
    };
    Ok((picture.titled(describe::title(scene)), data))
}

/// Every run the figure `which` of `scene` may make, as data scenes, for
/// the check of its runs together before the first (`scenes::cost`): the
/// linkage's figure at the most μ_p its refinement can reach
/// ([`most_pin_frictions`]); each runs at most to its window (a run that
/// has decided ends sooner).
pub fn planned_runs(scene: &Scene, which: ExperimentFigure) -> Result<Vec<Scene>> {
    let variants = match which {
        ExperimentFigure::TankPositions => positions::variants(scene)?,
        ExperimentFigure::TankLevels => levels::variants(scene)?,
        ExperimentFigure::LinkageFriction => linkage::variants(scene, &most_pin_frictions())?,
    };
    Ok(variants.into_iter().map(|v| v.scene).collect())
}

/// The runs the figure `which` of `scene` makes whatever they give, as
/// data scenes (`scenes::shared` makes those two figures share before
/// either starts): every variant, but of the linkage's figure only those
/// at [`PIN_FRICTION`] (its refinement's runs depend on their fronts).
pub fn certain_runs(scene: &Scene, which: ExperimentFigure) -> Result<Vec<Scene>> {
    let variants = match which {
        ExperimentFigure::LinkageFriction => linkage::variants(scene, &PIN_FRICTION)?,
        _ => return planned_runs(scene, which),
    };
    Ok(variants.into_iter().map(|v| v.scene).collect())
}

/// The steady wave's speed (blocks per τ) in the lower half of the chain,
/// blocks N/2 + 1 .. N − 1 (one-based), away from the driven block: the
/// least-squares slope of n against t_n by the rule of the program's one
/// wave speed (`sim::speed::fit`: blocks that flip in groups, less than
/// `COLLECTIVE_FLIP_GAP` apart, have no speed). `None` unless every one of
/// those blocks flipped, each after the one above it (a wave running
/// down): a chain that turns all at once, or from the bottom up, has no
/// speed.
pub fn bulk_speed(arrivals: &[Option<f64>]) -> Option<f64> {
    crate::sim::speed::fit(&lower_half(arrivals)?).map(|f| f.speed)
}

/// The points (k, t_n) of blocks N/2 + 1 .. N − 1 (k counting them from
/// 0), when every one of them flipped, each after the one above it.
fn lower_half(arrivals: &[Option<f64>]) -> Option<Vec<(f64, f64)>> {
    let n = arrivals.len();
    let times: Vec<f64> = arrivals
        .get(n / 2..n.checked_sub(1)?)?
        .iter()
        .copied()
        .collect::<Option<Vec<f64>>>()?;
    if times.windows(2).any(|w| w[1] <= w[0]) {
        return None;
    }
    Some(
        times
            .iter()
            .enumerate()
            .map(|(i, t)| (i as f64, *t))
            .collect(),
    )
}

/// The fitted line of [`bulk_speed`] in seconds and centimetres:
/// position (n − 1) b against t_n − t_1, over the same blocks and under
/// the same rule (`None` where [`bulk_speed`] is: the rule's gap between
/// blocks that flip together is in τ, so the arrivals are put back in τ
/// for it, with τ = `tau_s`).
pub fn bulk_fit(arrivals_s: &[Option<f64>], tau_s: f64, pitch_cm: f64) -> Option<BulkFit> {
    let arrivals: Vec<Option<f64>> = arrivals_s.iter().map(|t| t.map(|t| t / tau_s)).collect();
    bulk_speed(&arrivals)?;
    let per_s = 1.0 / crate::sim::observables::least_squares_slope(&lower_half(arrivals_s)?);
    let n = arrivals_s.len();
    let t1 = arrivals_s.first().copied().flatten()?;
    let pts: Vec<(f64, f64)> = (n / 2..n - 1)
        .filter_map(|i| arrivals_s[i].map(|t| (t - t1, i as f64 * pitch_cm)))
        .collect();
    let k = pts.len() as f64;
    let (centroid_s, centroid_cm) = pts
        .iter()
        .fold((0.0, 0.0), |(a, b), p| (a + p.0 / k, b + p.1 / k));
    Some(BulkFit {
        speed_cm_s: per_s * pitch_cm,
        blocks: [n / 2 + 1, n - 1],
        centroid_s,
        centroid_cm,
    })
}

/// A run's numbers in seconds and centimetres (its data file's
/// `apparatus`).
pub fn apparatus_numbers(
    arrivals_s: &[Option<f64>],
    tau_s: f64,
    pitch_cm: f64,
) -> ApparatusNumbers {
    let t1 = arrivals_s.first().copied().flatten();
    ApparatusNumbers {
        tau_s,
        pitch_cm,
        arrival_times_s: arrivals_s.to_vec(),
        since_block_1_s: arrivals_s
            .iter()
            .map(|t| t.zip(t1).map(|(t, t1)| t - t1))
            .collect(),
        bulk: bulk_fit(arrivals_s, tau_s, pitch_cm),
    }
}

/// "12.8 cm/s" or "no wave".
pub(super) fn speed_text(c: Option<f64>) -> String {
    c.map_or("no wave".into(), |c| format!("{c:.1} cm/s"))
}

/// A chart at the style's frame of `natural` design pixels.
pub(super) fn chart_picture(
    theme: &Theme,
    spec: &ChartSpec,
    natural: (u32, u32),
) -> Result<Picture> {
    let (w, h) = theme.style.frame(natural);
    Ok(Picture::from(charts::line_chart(theme, spec, w, h)?))
}

#[cfg(test)]
mod tests {
    use super::bulk_speed;

    /// Blocks 6..10 of 11 flipping 0.4 τ apart turn together: no wave, as
    /// the program's one wave speed says (`sim::speed::wave_speed`), not
    /// the 2.5 blocks/τ (7750 cm/s in a tank) a slope through them gives.
    #[test]
    fn blocks_that_flip_together_have_no_bulk_speed() {
        let mut arrivals: Vec<Option<f64>> = (0..11).map(|i| Some(100.0 * i as f64)).collect();
        for (k, t) in arrivals[5..10].iter_mut().enumerate() {
            *t = Some(600.0 + 0.4 * k as f64);
        }
        assert_eq!(crate::sim::speed::wave_speed(&arrivals), None);
        assert_eq!(bulk_speed(&arrivals), None);
        // A steady wave, 100 τ a block: 0.01 blocks/τ in the bulk too.
        let steady: Vec<Option<f64>> = (0..11).map(|i| Some(100.0 * i as f64)).collect();
        let c = bulk_speed(&steady).unwrap();
        assert!((c - 0.01).abs() < 1e-15, "{c}");
        // In seconds (τ = 2.5 ms: 0.25 s a block) and cm (b = 7.5): the
        // same fit, 30 cm/s; and none for the blocks that flip together.
        let tau_s = 2.5e-3;
        let seconds = |a: &[Option<f64>]| -> Vec<Option<f64>> {
            a.iter().map(|t| t.map(|t| t * tau_s)).collect()
        };
        let fit = super::bulk_fit(&seconds(&steady), tau_s, 7.5).unwrap();
        assert!((fit.speed_cm_s - 30.0).abs() < 1e-9, "{}", fit.speed_cm_s);
        assert!(super::bulk_fit(&seconds(&arrivals), tau_s, 7.5).is_none());
    }
}
