//! "Stiff" links shown to be stiff, as `auto` shows its step
//! (docs/experiments.md, "Units and the apparatus"): a scene whose
//! `[apparatus]`
//! gives its links as `stiffness = "stiff"` gets a stiffness k from
//! `stiff_gravity` (`scene::apparatus`), a modelling choice, not a
//! measured value. The same run with the links twice as stiff (2k: half
//! the `stiff_gravity`) must give the same wave in physical units, within
//! [`STIFF_TOLERANCE`]; how far it moves is said beside the run.

use crate::error::{Error, Result};
use crate::scene::Scene;
use crate::scene::apparatus::{StiffWord, Stiffness};
use crate::scenes::run::{self, SceneRun};
use crate::sim::RunOptions;
use serde::Serialize;

/// The largest relative change of the wave's speed between k and 2k for
/// which "stiff" links are stiff (docs/experiments.md). 3 %: the
/// apparatus's own speeds are measured to a few per cent.
pub const STIFF_TOLERANCE: f64 = 0.03;

/// How much the run moves when its "stiff" links are made twice as stiff.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StiffCheck {
    /// The wave's speed (blocks 3..N−1, `sim::speed::wave_speed`) at k and
    /// at 2k, in blocks per second; None where no wave crossed them.
    pub speed_k: Option<f64>,
    pub speed_2k: Option<f64>,
    /// |c(2k)/c(k) − 1|, where both ran.
    pub change: Option<f64>,
    /// The change allowed, [`STIFF_TOLERANCE`].
    pub tolerance: f64,
}

impl StiffCheck {
    /// Whether the links are stiff enough: the change within the
    /// tolerance (no wave in either run: nothing to compare, and then it
    /// is not claimed).
    pub fn holds(&self) -> bool {
        self.change.is_some_and(|c| c <= self.tolerance)
    }

    /// One line for the run's summary.
    pub fn describe(&self) -> String {
        match self.change {
            Some(c) => format!(
                "\"stiff\" links: with 2k the wave's speed moves by {:.2} % ({} {} %){}",
                100.0 * c,
                if c <= self.tolerance {
                    "within"
                } else {
                    "more than"
                },
                100.0 * self.tolerance,
                if c <= self.tolerance {
                    ""
                } else {
                    "; hint: give the links' stiffness in N/m, or a smaller stiff_gravity"
                }
            ),
            None => "\"stiff\" links: no wave crossed the chain at k or 2k, so k and 2k \
                     cannot be compared"
                .to_string(),
        }
    }
}

/// `scene` with its "stiff" links twice as stiff, over the same window
/// in seconds; None where the scene has no apparatus or its links have
/// a stiffness of their own.
pub fn doubled(scene: &Scene) -> Option<Scene> {
    let a = scene.apparatus.as_ref()?;
    if a.stiffness != Stiffness::Word(StiffWord::Stiff) {
        return None;
    }
    let tau_k = a.conversion.as_ref()?.tau_s;
    let mut s = scene.clone();
    let b = s.apparatus.as_mut()?;
    b.stiff_gravity *= 0.5;
    b.conversion = None;
    let s = s.with_conversion();
    let tau_2k = s.apparatus.as_ref()?.conversion.as_ref()?.tau_s;
    let mut s = s;
    // A window given in τ (not in the apparatus's seconds) is kept in
    // seconds: τ is √2 shorter at 2k.
    if scene
        .apparatus
        .as_ref()?
        .conversion
        .as_ref()?
        .t_end
        .is_none()
    {
        s.run.t_end = scene.run.t_end * tau_k / tau_2k;
    }
    Some(s)
}

/// What the "stiff" links' check of `scene` costs, before the first run
/// (its second run, at 2k: τ is √2 shorter, so √2 more steps over the
/// same seconds), in block-steps of the paper's model (`sim::cost`);
/// None where the scene has no "stiff" links. Not checked against the cap
/// here: `scenes::cost` checks it with the first run, as one cost, so
/// that the check is made before any run and never names the second
/// run's window in τ, which the user never gave.
pub fn cost(scene: &Scene, samples: usize) -> Result<Option<f64>> {
    let Some(mut stiffer) = doubled(scene) else {
        return Ok(None);
    };
    stiffer.limits = crate::limits::Limits::none();
    run::check_cost(&stiffer, samples)
        .map(Some)
        .map_err(|e| match e {
            Error::BadInput(m) => Error::bad_input(format!(
                "the \"stiff\" links' check, a second run with the links twice as stiff (2k) \
                 over the same seconds: {m}; or give the links' stiffness in N/m, which makes \
                 no second run"
            )),
            other => other,
        })
}

/// Runs `scene` again with 2k (with `options`) and compares the wave's
/// speed in blocks per second with `at_k`'s, `scene`'s own run; None
/// where the scene has no "stiff" links.
pub fn check(scene: &Scene, at_k: &SceneRun, options: &RunOptions) -> Result<Option<StiffCheck>> {
    let Some(stiffer) = doubled(scene) else {
        return Ok(None);
    };
    let tau = |s: &Scene| {
        s.apparatus
            .as_ref()
            .and_then(|a| a.conversion.as_ref())
            .map_or(f64::NAN, |c| c.tau_s)
    };
    let at_2k = run::simulate_with(&stiffer, &[], options)?;
    let speed = |r: &SceneRun, tau_s: f64| {
        crate::sim::speed::wave_speed(&r.trajectory.arrival_times).map(|c| c / tau_s)
    };
    let speed_k = speed(at_k, tau(scene));
    let speed_2k = speed(&at_2k, tau(&stiffer));
    let change = speed_k.zip(speed_2k).map(|(k, k2)| (k2 / k - 1.0).abs());
    Ok(Some(StiffCheck {
        speed_k,
        speed_2k,
        change,
        tolerance: STIFF_TOLERANCE,
    }))
}
