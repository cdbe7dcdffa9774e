//! The rule that ends each of a figure's runs once it has decided what it
//! was run for (docs/experiments.md).
//!
//! A pin of the smoothed Coulomb law (`model::links`) is held when it turns
//! slowly against both of the scene's own rates: the smoothing's ω_ε (a
//! held pin creeps at ω_ε atanh(τ/τ_max)) and the block's own rate
//! ω_b = √(G/(I + I_a)), the rate at which gravity turns a free block
//! (`block_rate`). Where ω_ε is not small against ω_b the smoothed law is a
//! viscous one, its creep turns blocks over as fast as the wave does, and
//! no rate tells a stopped front from a slow one: the rule says so
//! ([`Decided::verdict`]) and the runs go to their end.

use crate::sim::StopView;
use std::sync::atomic::{AtomicU64, Ordering};

/// A pin turning slower than this many ω_ε is held: the smoothed law's
/// creep under a torque within 0.5 % of the Coulomb limit (atanh 0.995 =
/// 3.0, `model::links`).
pub const HELD_RATE: f64 = 3.0;
/// A held pin also turns slower than this fraction of the block's own rate
/// ω_b: held for [`HELD_FOR_S`], it turns by less than 1 % of what a free
/// block turns in that time.
pub const HELD_FRACTION_OF_BLOCK_RATE: f64 = 0.01;
/// The rule decides only where [`HELD_RATE`] ω_ε is at most this fraction
/// of the block's own rate ω_b: the smoothing's creep at least ten times
/// slower than a block turning under gravity.
pub const DECIDABLE_FRACTION_OF_BLOCK_RATE: f64 = 0.1;
/// How long (s) every pin must stay held, after the motor has stopped,
/// for the front to have stopped.
pub const HELD_FOR_S: f64 = 0.5;

/// The block's own rate ω_b = √(G/(I + I_a)) in 1/τ: gravity's torque
/// scale m g s over the block's moment of inertia with the medium's added
/// inertia (model units: G = m g/(k s), I in m s²). `None` without gravity.
pub fn block_rate(gravity: f64, inertia: f64, added_inertia: f64) -> Option<f64> {
    let w = (gravity / (inertia + added_inertia)).sqrt();
    (w.is_finite() && w > 0.0).then_some(w)
}

/// Whether the held-front rule can decide at ω_ε against ω_b (both in
/// 1/τ): `Err` with the reason, in rad/s (`tau_s` the unit of time),
/// where it cannot.
pub fn decidable(omega_eps: f64, block_rate: Option<f64>, tau_s: f64) -> Result<(), String> {
    let held = HELD_RATE * omega_eps;
    match block_rate {
        Some(wb) if held <= DECIDABLE_FRACTION_OF_BLOCK_RATE * wb => Ok(()),
        Some(wb) => Err(format!(
            "the stop rule cannot decide where the front stopped: a held pin's creep, \
             {HELD_RATE} ω_ε = {} rad/s, is not under {} of the block's own rate \
             √(G/I) = {} rad/s; run to its duration",
            short(held / tau_s),
            DECIDABLE_FRACTION_OF_BLOCK_RATE,
            short(wb / tau_s)
        )),
        None => Err(
            "the stop rule cannot decide where the front stopped: without gravity a block \
             has no rate of its own to hold a pin against; run to its duration"
                .to_string(),
        ),
    }
}

/// Three significant digits (0.15, 9, 48.2).
fn short(x: f64) -> String {
    crate::numfmt::plain(format!("{x:.2e}").parse().unwrap_or(x))
}

/// When a figure's run has decided what it was run for, and ends there
/// (its `[apparatus] duration` is the cap): once every block has flipped
/// (an arrival, once set, never changes); or, with pin friction, once the
/// motor has stopped and every pin has been held (slower than [`HELD_RATE`]
/// ω_ε and than [`HELD_FRACTION_OF_BLOCK_RATE`] ω_b) for [`HELD_FOR_S`]:
/// the front has stopped, and what would still move it is the smoothed
/// law's creep, which vanishes as ω_ε → 0 (docs/experiments.md). Where the
/// held rule cannot decide ([`decidable`]) only the first rule ends a run.
pub(super) struct Decided {
    /// The motor's end and the hold, in τ.
    drive_end: f64,
    hold: f64,
    /// The fastest a held pin turns (1/τ); `None`: the held rule cannot
    /// decide, with its reason in `verdict`.
    held_below: Option<f64>,
    verdict: Result<(), String>,
    /// The time the pins were first seen held in the current hold (f64
    /// bits; NaN: not held). The rule is asked in time order by one run.
    since: AtomicU64,
}

impl Decided {
    /// The rule of a run whose unit of time is `tau_s`, with the smoothing
    /// rate `omega_eps` and the block's own rate `block_rate` (1/τ).
    pub(super) fn new(drive_end: f64, tau_s: f64, omega_eps: f64, block_rate: Option<f64>) -> Self {
        let verdict = decidable(omega_eps, block_rate, tau_s);
        let held_below = match (&verdict, block_rate) {
            (Ok(()), Some(wb)) => {
                Some((HELD_RATE * omega_eps).min(HELD_FRACTION_OF_BLOCK_RATE * wb))
            }
            _ => None,
        };
        Self {
            drive_end,
            hold: HELD_FOR_S / tau_s,
            held_below,
            verdict,
            since: AtomicU64::new(f64::NAN.to_bits()),
        }
    }

    /// Whether the held-front rule can decide this run (`Err`: why not).
    pub(super) fn verdict(&self) -> &Result<(), String> {
        &self.verdict
    }

    pub(super) fn decided(&self, view: &StopView) -> bool {
        if view.arrivals.iter().all(Option::is_some) {
            return true;
        }
        let (Some(friction), Some(held_below)) = (view.ladder.terms.friction, self.held_below)
        else {
            return false;
        };
        let links = &view.ladder.terms.links;
        let held = view.t >= self.drive_end
            && friction.fastest_pin(view.ladder, links, view.q, view.v) < held_below;
        if !held {
            self.since.store(f64::NAN.to_bits(), Ordering::Relaxed);
            return false;
        }
        let since = f64::from_bits(self.since.load(Ordering::Relaxed));
        if since.is_nan() {
            self.since.store(view.t.to_bits(), Ordering::Relaxed);
            return false;
        }
        view.t - since >= self.hold
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The printed linkage (docs/experiments.md): τ = 1.01 ms, G = 2e-4,
    /// I = 0.0842: ω_b = 48 rad/s.
    const TAU_S: f64 = 1.0106e-3;

    fn linkage_rate() -> Option<f64> {
        block_rate(2e-4, (1.0 + 0.01) / 12.0, 0.0)
    }

    #[test]
    fn the_block_rate_is_gravitys_over_the_inertia() {
        let wb = linkage_rate().unwrap() / TAU_S;
        assert!((wb - 48.2).abs() < 0.5, "{wb}");
        assert_eq!(block_rate(0.0, 0.1, 0.0), None);
    }

    #[test]
    fn the_rule_decides_at_the_scenes_smoothing_and_not_at_3_or_100_rad_s() {
        let wb = linkage_rate();
        assert!(decidable(0.05 * TAU_S, wb, TAU_S).is_ok());
        for rate in [3.0, 100.0] {
            let e = decidable(rate * TAU_S, wb, TAU_S).unwrap_err();
            assert!(e.contains("cannot decide") && e.contains("rad/s"), "{e}");
        }
        assert!(decidable(0.05 * TAU_S, None, TAU_S).is_err());
    }

    #[test]
    fn a_held_pin_is_slow_against_both_rates() {
        let wb = linkage_rate().unwrap();
        // At the scene's ω_ε the smoothing's rate is the smaller: the
        // figure's runs end where they did.
        let d = Decided::new(0.0, TAU_S, 0.05 * TAU_S, Some(wb));
        assert_eq!(d.held_below, Some(HELD_RATE * 0.05 * TAU_S));
        // Near the edge of what decides, the block's rate bounds it.
        let eps = DECIDABLE_FRACTION_OF_BLOCK_RATE * wb / HELD_RATE;
        let d = Decided::new(0.0, TAU_S, eps, Some(wb));
        assert_eq!(d.held_below, Some(HELD_FRACTION_OF_BLOCK_RATE * wb));
        let d = Decided::new(0.0, TAU_S, 3.0 * TAU_S, Some(wb));
        assert_eq!(d.held_below, None);
        assert!(d.verdict().is_err());
    }
}
