//! `t_end = "auto"` (docs/sweeps.md): the window that shows every wave's
//! fate.
//!
//! The scenario is run to at most [`AUTO_CAP`] and stopped at the first
//! check (every 5 τ at most) after the drive has ended at which every wave
//! has a fate other than `undecided` (`waves::WaveTracker::all_decided`,
//! with the rest proof of `theory::stability` at its default tolerances
//! deciding `stopped`). The window is that time plus a margin, the larger
//! of [`AUTO_MARGIN_FRACTION`] of it and [`AUTO_MIN_MARGIN`], so that a
//! movie or figure shows the chain settle after the last fate. A run that
//! reaches the cap with a wave still undecided keeps the cap as its window
//! (the waves then say `undecided`).

use super::{IntegratorConfig, RunOptions, Scenario, StopView, run_streaming};
use crate::error::Result;
use crate::theory::stability::{RestTolerances, rest_proof};

/// Longest automatic window, τ: 25 times the paper's longest run (4000 τ);
/// the slow escape at the chain-length edge (about 24 000 τ at N = 185)
/// fits in it.
pub const AUTO_CAP: f64 = 100_000.0;
/// Margin after the last fate, as a fraction of its time.
pub const AUTO_MARGIN_FRACTION: f64 = 0.1;
/// Least margin after the last fate, τ.
pub const AUTO_MIN_MARGIN: f64 = 200.0;

/// The automatic window of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Window {
    /// The window's end, τ: the last fate plus the margin, or the cap.
    pub t_end: f64,
    /// When every wave had a fate, τ (`None`: not by the cap).
    pub decided_at: Option<f64>,
}

/// The window of `scenario` (whose `t_end` is ignored; see the module's
/// doc), run with `config` as `options` say (their stop rule is replaced
/// by the window's own).
pub fn auto_window(
    scenario: &Scenario,
    config: &IntegratorConfig,
    options: &RunOptions,
) -> Result<Window> {
    let mut capped = scenario.clone();
    capped.t_end = AUTO_CAP;
    let protocol = &capped.protocol;
    let drive_end = protocol.drive_end();
    let tolerances = RestTolerances::default();
    let stop = |v: &StopView| {
        v.t >= drive_end
            && v.waves
                .all_decided(v.q, rest_proof(v.ladder, v.q, v.v, &tolerances).proved)
    };
    let options = options.stop(&stop);
    let run = run_streaming(&capped, &[], config, &options, &mut |_| Ok(()))?;
    let decided = run.t_final < AUTO_CAP
        || run
            .waves
            .waves
            .iter()
            .all(|w| w.fate != super::waves::Fate::Undecided);
    Ok(if decided {
        let t = run.t_final;
        Window {
            t_end: (t + (AUTO_MARGIN_FRACTION * t).max(AUTO_MIN_MARGIN)).min(AUTO_CAP),
            decided_at: Some(t),
        }
    } else {
        Window {
            t_end: AUTO_CAP,
            decided_at: None,
        }
    })
}
