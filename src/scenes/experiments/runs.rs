//! A figure's runs: each a variant of the scene's apparatus (its terms,
//! motor, μ_p, wave), run by RK4 at [`STEP`] τ (with ribbons, dopri5 at
//! [`RIBBON_RTOL`]; inextensible ribbons, Moreau's time-stepping at
//! [`INEXTENSIBLE_STEP`]) until it has decided
//! ([`Decided`]), two at a time or more.

use super::decided::{Decided, block_rate};
use super::{INEXTENSIBLE_STEP, RIBBON_RTOL, STEP};
use super::{apparatus_numbers, bulk_speed};
use crate::error::{Error, Result};
use crate::scene::apparatus::{Apparatus, StiffWord, Stiffness};
use crate::scene::{Method, OutputSpec, Scene};
use crate::scenes::data::RunData;
use crate::scenes::reuse;
use crate::scenes::run::{self, SceneRun};
use crate::sim::IntegratorKind;
use crate::sim::{RunOptions, StopView};
use rayon::prelude::*;

/// One run of the figure: its label, and `scene` as a data scene with its
/// apparatus changed by `change`, its α of sign `sign`, RK4 at [`STEP`]
/// (with ribbons, dopri5 at [`RIBBON_RTOL`]; inextensible ribbons, Moreau
/// at [`INEXTENSIBLE_STEP`]).
pub(super) struct Variant {
    pub(super) label: String,
    pub(super) scene: Scene,
}

pub(super) fn variant(
    scene: &Scene,
    label: String,
    sign: f64,
    change: impl FnOnce(&mut Apparatus),
) -> Result<Variant> {
    let mut s = scene.clone();
    let mut a = scene.apparatus.clone().ok_or_else(|| {
        Error::bad_input(format!(
            "{} {}: an experiment figure needs an [apparatus]",
            scene.kind().name(),
            scene.name
        ))
    })?;
    change(&mut a);
    let ribbons = a.ribbons;
    let inextensible = a.stiffness == Stiffness::Word(StiffWord::Inextensible);
    s.model.alpha = sign * scene.model.alpha.abs();
    s.apparatus = Some(a);
    // The model, drive and window the changed apparatus gives (the run
    // builds its own from the apparatus; the data file records these).
    let mut s = s.with_conversion();
    s.output = OutputSpec::Data;
    s.run.dt = Some(STEP);
    if inextensible {
        s.run.integrator = Method::Fixed(IntegratorKind::Moreau);
        s.run.dt = Some(INEXTENSIBLE_STEP);
    } else if ribbons {
        // Its contact refuses RK4 at STEP; dopri5 shortens its step only
        // where the plates touch.
        s.run.integrator = Method::Fixed(IntegratorKind::Dopri5);
        s.run.rtol = Some(RIBBON_RTOL);
    } else {
        s.run.integrator = Method::Fixed(IntegratorKind::Rk4);
    }
    Ok(Variant { label, scene: s })
}

/// A finished run: its arrival times (s), bulk speed (cm/s), the block
/// pitch b (cm), and its data.
pub(super) struct Done {
    pub(super) arrivals_s: Vec<Option<f64>>,
    pub(super) bulk_cm_s: Option<f64>,
    pub(super) pitch_cm: f64,
    pub(super) data: RunData,
}

/// Runs every variant, two at a time or more (rayon), in order, each
/// until it has decided ([`Decided`]); each run's data says where it
/// ended (`t_end`).
pub(super) fn run_all(variants: &[Variant]) -> Result<Vec<Done>> {
    let tally = crate::sim::tally::current();
    variants
        .par_iter()
        .map(|v| crate::sim::tally::within(tally.clone(), || run_one(v)))
        .collect()
}

/// The rule that ends a variant's run ([`Decided`]), from its converted
/// apparatus.
fn decided_of(scene: &Scene) -> Result<Decided> {
    let unconverted = || {
        Error::failed(format!(
            "{}: the run has no converted [apparatus]",
            scene.name
        ))
    };
    let a = scene.apparatus.as_ref().ok_or_else(unconverted)?;
    let c = a.conversion.as_ref().ok_or_else(unconverted)?;
    let drive_end = scene.scenario()?.protocol.drive_end();
    let block_rate = block_rate(c.gravity, c.inertia, c.added_inertia);
    Ok(Decided::new(
        drive_end,
        c.tau_s,
        c.friction_rate,
        block_rate,
    ))
}

/// A variant's scene run until it has decided ([`Decided`]), made here
/// (`scenes::shared` makes a run two figures plan with it).
pub(crate) fn decided_run(scene: &Scene) -> Result<SceneRun> {
    decided_run_with(scene, &decided_of(scene)?)
}

/// [`decided_run`] with its rule already made.
fn decided_run_with(scene: &Scene, decided: &Decided) -> Result<SceneRun> {
    let stop = |view: &StopView| decided.decided(view);
    let options = RunOptions::default().limits(scene.limits).stop(&stop);
    run::simulate_with(scene, &[], &options)
}

/// One variant run until it has decided ([`Decided`]), or the same run
/// made for another figure of the render (`scenes::shared`).
fn run_one(v: &Variant) -> Result<Done> {
    let a = v.scene.apparatus.as_ref().ok_or_else(|| unconverted(v))?;
    let c = a.conversion.as_ref().ok_or_else(|| unconverted(v))?;
    // The rule's verdict is fixed when it is made, not by the run.
    let decided = decided_of(&v.scene)?;
    let r = reuse::or_run(&v.scene, &[], reuse::Stop::Decided, || {
        decided_run_with(&v.scene, &decided)
    })?;
    let arrivals = &r.trajectory.arrival_times;
    // A run with pin friction whose held rule cannot decide says so
    // in its data (its label), having run to its duration.
    let label = match decided.verdict() {
        Err(why) if a.pin_friction > 0.0 => format!("{} ({why})", v.label),
        _ => v.label.clone(),
    };
    let mut data = RunData::new(&label, &v.scene, &r);
    data.ended_at(r.trajectory.t_final);
    let arrivals_s: Vec<Option<f64>> = arrivals.iter().map(|t| t.map(|t| t * c.tau_s)).collect();
    let numbers = apparatus_numbers(&arrivals_s, c.tau_s, a.b);
    let bulk_cm_s = numbers.bulk.map(|f| f.speed_cm_s);
    debug_assert_eq!(
        bulk_cm_s.is_some(),
        bulk_speed(arrivals).is_some(),
        "the bulk fit in s and cm is the bulk speed's"
    );
    data.apparatus = Some(numbers);
    Ok(Done {
        arrivals_s,
        bulk_cm_s,
        pitch_cm: a.b,
        data,
    })
}

/// The error of a variant without its converted apparatus (never made by
/// [`variant`]).
fn unconverted(v: &Variant) -> Error {
    Error::failed(format!("{}: the run has no converted [apparatus]", v.label))
}
