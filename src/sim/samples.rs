//! The times a run hands out and the times it lands on: the sample times,
//! checked and sorted, the stops (samples, the drive's corners, t_end) and
//! the hand-over of the state at every sample a step has reached.

use super::{Protocol, Sample, State};
use crate::error::{Error, Result};

/// Hands `sink` the state for every sample time not after `t` not yet
/// handed over.
pub(super) fn emit_due(
    samples: &[f64],
    next: &mut usize,
    t: f64,
    st: &State,
    dissipated: Option<f64>,
    sink: &mut dyn FnMut(&Sample) -> Result<()>,
) -> Result<()> {
    while *next < samples.len() && samples[*next] <= t {
        sink(&Sample {
            t: samples[*next],
            q: &st.q,
            v: &st.v,
            dissipated,
        })?;
        *next += 1;
    }
    Ok(())
}

/// Sample times sorted and deduplicated; each must lie in [0, t_end].
pub(super) fn sorted_samples(sample_times: &[f64], t_end: f64) -> Result<Vec<f64>> {
    if let Some(bad) = sample_times
        .iter()
        .find(|t| !(t.is_finite() && **t >= 0.0 && **t <= t_end))
    {
        return Err(Error::bad_input(format!(
            "sample time {bad} lies outside [0, t_end = {t_end}]"
        )));
    }
    let mut s = sample_times.to_vec();
    s.sort_by(f64::total_cmp);
    s.dedup();
    Ok(s)
}

/// Every time the integrator must land on: samples, drive corners, t_end.
pub(super) fn stop_times(samples: &[f64], protocol: &Protocol, t_end: f64) -> Vec<f64> {
    let mut stops: Vec<f64> = samples.to_vec();
    if let Some(d) = protocol.drive() {
        stops.extend(d.corners().filter(|&c| c > 0.0 && c < t_end));
    }
    stops.push(t_end);
    stops.retain(|&t| t > 0.0);
    stops.sort_by(f64::total_cmp);
    stops.dedup();
    stops
}
