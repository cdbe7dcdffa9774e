//! Axis ranges: from the data with a pad, checked when given, equalised
//! for equal aspect; which points an axis can draw.

use super::{Axis, ChartSpec, Scale, Series};
use crate::error::{Error, Result};
use std::ops::Range;

/// Pixel ranges (horizontal, vertical) of the plotting area.
pub(super) type Range2 = (Range<i32>, Range<i32>);

/// Grows one range so that both axes have the same units per pixel.
pub(super) fn equalize(
    xr: Range<f64>,
    yr: Range<f64>,
    pw: f64,
    ph: f64,
) -> (Range<f64>, Range<f64>) {
    let (sx, sy) = ((xr.end - xr.start) / pw, (yr.end - yr.start) / ph);
    let grow = |r: Range<f64>, s: f64, p: f64| {
        let (mid, half) = (0.5 * (r.start + r.end), 0.5 * s * p);
        mid - half..mid + half
    };
    if sx > sy {
        (xr, grow(yr, sx, ph))
    } else {
        (grow(xr, sy, pw), yr)
    }
}

pub(super) fn axis_ok(scale: Scale, v: f64) -> bool {
    v.is_finite() && (scale == Scale::Linear || v > 0.0)
}

/// The axis range: the given one, or the data's with a 5 % pad (a factor on
/// log axes). Degenerate data get a unit-wide range.
pub(super) fn data_range(spec: &ChartSpec, is_x: bool) -> Result<Range<f64>> {
    let axis = if is_x { &spec.x } else { &spec.y };
    if let Some((lo, hi)) = axis.range {
        return check_range(axis, lo, hi);
    }
    let vals = spec
        .series
        .iter()
        .flat_map(|s| s.points.iter())
        .filter(|p| axis_ok(spec.x.scale, p.0) && axis_ok(spec.y.scale, p.1))
        .map(|p| if is_x { p.0 } else { p.1 });
    let (lo, hi) = vals.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    Ok(padded(axis.scale, lo, hi))
}

fn check_range(axis: &Axis, lo: f64, hi: f64) -> Result<Range<f64>> {
    let ok =
        lo.is_finite() && hi.is_finite() && lo < hi && (axis.scale == Scale::Linear || lo > 0.0);
    if ok {
        Ok(lo..hi)
    } else {
        Err(Error::bad_input(format!(
            "axis \"{}\" needs a finite range lo < hi (lo > 0 on a log axis), got {lo}..{hi}",
            axis.label
        )))
    }
}

fn padded(scale: Scale, lo: f64, hi: f64) -> Range<f64> {
    match scale {
        _ if !lo.is_finite() => match scale {
            Scale::Linear => 0.0..1.0,
            Scale::Log => 1.0..10.0,
        },
        Scale::Linear => {
            let pad = if hi > lo {
                0.05 * (hi - lo)
            } else {
                0.5 * lo.abs().max(1.0)
            };
            lo - pad..hi + pad
        }
        Scale::Log => {
            let f = if hi > lo { (hi / lo).powf(0.05) } else { 3.0 };
            lo / f..hi * f
        }
    }
}

/// Runs of consecutive drawable points (a gap wherever a point is not).
pub(super) fn runs(s: &Series, spec: &ChartSpec) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for &p in &s.points {
        if axis_ok(spec.x.scale, p.0) && axis_ok(spec.y.scale, p.1) {
            if let Some(last) = out.last_mut() {
                last.push(p);
            }
        } else if out.last().is_some_and(|r| !r.is_empty()) {
            out.push(Vec::new());
        }
    }
    out.retain(|r| !r.is_empty());
    out
}
