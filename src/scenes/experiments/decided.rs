//! The rule that ends each of a figure's runs once it has decided what it
//! was run for (docs/experiments.md).

use crate::sim::StopView;
use std::sync::atomic::{AtomicU64, Ordering};

/// A pin turning slower than this many ω_ε is held: the smoothed law's
/// creep under a torque within 0.5 % of the Coulomb limit (atanh 0.995 =
/// 3.0, `model::links`).
pub const HELD_RATE: f64 = 3.0;
/// How long (s) every pin must stay held, after the motor has stopped,
/// for the front to have stopped.
pub const HELD_FOR_S: f64 = 0.5;

/// When a figure's run has decided what it was run for, and ends there
/// (its `[apparatus] duration` is the cap): once every block has flipped
/// (an arrival, once set, never changes); or, with pin friction, once the
/// motor has stopped and every pin has been held ([`HELD_RATE`]) for
/// [`HELD_FOR_S`]: the front has stopped, and what would still move it is
/// the smoothed law's creep, which vanishes as ω_ε → 0 (docs/experiments.md).
pub(super) struct Decided {
    /// The motor's end and the hold, in τ.
    drive_end: f64,
    hold: f64,
    /// The time the pins were first seen held in the current hold (f64
    /// bits; NaN: not held). The rule is asked in time order by one run.
    since: AtomicU64,
}

impl Decided {
    pub(super) fn new(drive_end: f64, tau_s: f64) -> Self {
        Self {
            drive_end,
            hold: HELD_FOR_S / tau_s,
            since: AtomicU64::new(f64::NAN.to_bits()),
        }
    }

    pub(super) fn decided(&self, view: &StopView) -> bool {
        if view.arrivals.iter().all(Option::is_some) {
            return true;
        }
        let Some(friction) = view.ladder.terms.friction else {
            return false;
        };
        let links = &view.ladder.terms.links;
        let held = view.t >= self.drive_end
            && friction.fastest_pin(view.ladder, links, view.q, view.v)
                < HELD_RATE * friction.omega_eps;
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
