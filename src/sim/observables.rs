//! Observables of a run: arrival times of the flip at each block
//! (docs/model.md), the kink position, and the topological polarisation sin
//! θ_n.

use crate::model::ladder::itheta;

/// Records, for every block, the first time its polarisation sin θ_n
/// changes sign from the one it started with (docs/model.md): θ_n leaves
/// the interval (kπ, (k + 1)π) it started in, through the horizontal
/// (θ = kπ, the usual flip) or by turning the other way round (through
/// ±180°, as whole groups of blocks do near α = ±90°). The time is
/// interpolated inside the step by a cubic Hermite polynomial through θ and
/// θ̇ at both ends of the step, as the root of θ(t) − kπ for the multiple
/// of π crossed.
///
/// The test after each step is in two stages, so that a vectorised stepper
/// can do the first for many blocks at once: a cheap *candidate* test (θ_n
/// outside a window strictly inside the starting interval, [`Self::window`]),
/// then, for candidates only, the exact test sin θ_n · s_n < 0 in
/// [`Self::try_record`]. Every block whose polarisation changed sign is a
/// candidate, so the outcome is that of the exact test alone; a stepper
/// that flags candidates its own way gets the same arrivals bit for bit as
/// long as it flags a superset and calls `try_record` in block order.
#[derive(Debug, Clone)]
pub struct ArrivalDetector {
    /// s_n: +1 or −1, the sign of sin θ_n at the start (+1 when it is 0).
    initial_sign: Vec<f64>,
    /// The multiple of π below and above the starting interval, kπ and
    /// (k + 1)π, with (−1)^k = s_n.
    bounds: Vec<[f64; 2]>,
    /// The candidate window (kπ + m, (k + 1)π − m): inside it the
    /// polarisation has the starting sign, whatever the rounding.
    window: Vec<[f64; 2]>,
    prev_theta: Vec<f64>,
    prev_omega: Vec<f64>,
    prev_t: f64,
    pub arrival: Vec<Option<f64>>,
}

/// sin θ as the force loop computes it.
#[inline]
fn sin_of(theta: f64) -> f64 {
    crate::model::trig::sin_cos(theta).0
}

/// The starting interval of a block at `theta0` with polarisation sign
/// `sign`: ([kπ, (k + 1)π], candidate window).
fn start_interval(theta0: f64, sign: f64) -> ([f64; 2], [f64; 2]) {
    use std::f64::consts::PI;
    if !theta0.is_finite() {
        // Never a candidate: the run's divergence check reports it.
        return (
            [f64::NEG_INFINITY, f64::INFINITY],
            [f64::NEG_INFINITY, f64::INFINITY],
        );
    }
    let mut k = (theta0 / PI).floor();
    // (−1)^k must be the sign of sin θ0 (they can disagree only within
    // rounding of a multiple of π).
    let parity = if (k * 0.5).floor() * 2.0 == k {
        1.0
    } else {
        -1.0
    };
    if parity != sign {
        k += if theta0 - k * PI < 0.5 * PI {
            -1.0
        } else {
            1.0
        };
    }
    let (lo, hi) = (k * PI, (k + 1.0) * PI);
    let margin = 1e-6 * (1.0 + k.abs());
    ([lo, hi], [lo + margin, hi - margin])
}

impl ArrivalDetector {
    pub fn new(t0: f64, q: &[f64], v: &[f64]) -> Self {
        let n = q.len() / 3;
        let theta: Vec<f64> = (0..n).map(|i| q[itheta(i)]).collect();
        let initial_sign: Vec<f64> = theta
            .iter()
            .map(|&th| if sin_of(th) >= 0.0 { 1.0 } else { -1.0 })
            .collect();
        let (bounds, window) = theta
            .iter()
            .zip(&initial_sign)
            .map(|(&th, &s)| start_interval(th, s))
            .unzip();
        Self {
            initial_sign,
            bounds,
            window,
            prev_omega: (0..n).map(|i| v[itheta(i)]).collect(),
            prev_theta: theta,
            prev_t: t0,
            arrival: vec![None; n],
        }
    }

    /// Feeds the state at the end of a step.
    #[inline]
    pub fn observe(&mut self, t: f64, q: &[f64], v: &[f64]) {
        let t0 = self.prev_t;
        for (i, (qb, vb)) in q.chunks_exact(3).zip(v.chunks_exact(3)).enumerate() {
            let (th, om) = (qb[2], vb[2]);
            if self.is_candidate(i, th) {
                let (th0, om0) = (self.prev_theta[i], self.prev_omega[i]);
                self.try_record(i, (t0, th0, om0), (t, th, om));
            }
            (self.prev_theta[i], self.prev_omega[i]) = (th, om);
        }
        self.prev_t = t;
    }

    /// Whether block `i` at angle `theta` may have arrived: θ outside its
    /// candidate window. The cheap first stage of the test.
    #[inline]
    pub fn is_candidate(&self, i: usize, theta: f64) -> bool {
        let [lo, hi] = self.window[i];
        theta <= lo || theta >= hi
    }

    /// Block `i`'s candidate window (lo, hi): θ ≤ lo or θ ≥ hi flags a
    /// candidate, for steppers that test many blocks at once.
    pub fn window(&self, i: usize) -> [f64; 2] {
        self.window[i]
    }

    /// Whether block `i`, at angle `theta`, has just changed the sign of
    /// its polarisation for the first time.
    #[inline]
    pub fn crossed(&self, i: usize, theta: f64) -> bool {
        self.arrival[i].is_none() && sin_of(theta) * self.initial_sign[i] < 0.0
    }

    /// Blocks still to arrive, as a bit mask (bit i for block i; the first
    /// 64 blocks).
    pub fn pending_mask(&self) -> u64 {
        self.arrival
            .iter()
            .take(64)
            .enumerate()
            .filter(|(_, a)| a.is_none())
            .fold(0, |m, (i, _)| m | 1 << i)
    }

    /// (−1 or +1) sign of block `i`'s initial polarisation sin θ_n.
    pub fn initial_sign(&self, i: usize) -> f64 {
        self.initial_sign[i]
    }

    /// The exact test for a candidate: if block `i` has just arrived in the
    /// step from (t0, θ0, θ̇0) to (t1, θ1, θ̇1), records the time and
    /// returns true.
    #[inline]
    pub fn try_record(&mut self, i: usize, start: (f64, f64, f64), end: (f64, f64, f64)) -> bool {
        if !self.crossed(i, end.1) {
            return false;
        }
        self.record(i, start, end);
        true
    }

    /// Records block `i`'s arrival inside the step from (t0, θ0, θ̇0) to
    /// (t1, θ1, θ̇1), where θ crossed the bound of its starting interval on
    /// the side it moved to.
    pub fn record(&mut self, i: usize, start: (f64, f64, f64), end: (f64, f64, f64)) {
        let ((t0, th0, om0), (t1, th1, om1)) = (start, end);
        let [lo, hi] = self.bounds[i];
        let c = if th1 < th0 { lo } else { hi };
        let h = t1 - t0;
        let s = hermite_root(th0 - c, h * om0, th1 - c, h * om1);
        self.arrival[i] = Some(t0 + s * h);
    }

    /// Takes (t, q, v) as the end of the last step, for callers that step
    /// several times between observations and record crossings themselves.
    pub fn restart(&mut self, t: f64, q: &[f64], v: &[f64]) {
        for (i, (qb, vb)) in q.chunks_exact(3).zip(v.chunks_exact(3)).enumerate() {
            (self.prev_theta[i], self.prev_omega[i]) = (qb[2], vb[2]);
        }
        self.prev_t = t;
    }
}

/// Root in [0, 1] of the cubic Hermite interpolant with values y0, y1 and
/// scaled slopes m0, m1 at 0 and 1, where y1 ≠ 0 and y0 is zero or of the
/// opposite sign (a zero y0 is the root). Bisection to machine precision.
pub fn hermite_root(y0: f64, m0: f64, y1: f64, m1: f64) -> f64 {
    let p = |s: f64| {
        let (s2, s3) = (s * s, s * s * s);
        (2.0 * s3 - 3.0 * s2 + 1.0) * y0
            + (s3 - 2.0 * s2 + s) * m0
            + (-2.0 * s3 + 3.0 * s2) * y1
            + (s3 - s2) * m1
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    let sign_lo = -y1.signum();
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if p(mid) * sign_lo > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Kink position in blocks: Σ_n (1 − sin θ_n / sin α)/2, the number of
/// blocks turned from the ground state of sign α to that of sign −α
/// (0 before the drive, N when every block has flipped).
pub fn kink_position(q: &[f64], alpha: f64) -> f64 {
    let sa = alpha.sin();
    (0..q.len() / 3)
        .map(|i| 0.5 * (1.0 - q[itheta(i)].sin() / sa))
        .sum()
}

/// Least-squares slope of y against x.
pub fn least_squares_slope(pts: &[(f64, f64)]) -> f64 {
    let n = pts.len() as f64;
    let (mx, my) = pts
        .iter()
        .fold((0.0, 0.0), |(a, b), p| (a + p.0 / n, b + p.1 / n));
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    sxy / sxx
}

/// Topological polarisation of each block, sin θ_n (docs/model.md).
pub fn polarisation(q: &[f64]) -> Vec<f64> {
    (0..q.len() / 3).map(|i| q[itheta(i)].sin()).collect()
}

/// Block angles θ_n in degrees, wrapped to (−180°, 180°] as they are
/// reported to the user (docs/model.md).
pub fn angles_deg(q: &[f64]) -> Vec<f64> {
    angles_deg_unwrapped(q).into_iter().map(wrap_deg).collect()
}

/// Block angles θ_n in degrees as integrated, not wrapped (a block that
/// turned once round reads 360° more).
pub fn angles_deg_unwrapped(q: &[f64]) -> Vec<f64> {
    (0..q.len() / 3)
        .map(|i| q[itheta(i)].to_degrees())
        .collect()
}

/// An angle in degrees wrapped to (−180°, 180°]; angles already there are
/// returned unchanged, bit for bit.
pub fn wrap_deg(deg: f64) -> f64 {
    if deg > -180.0 && deg <= 180.0 {
        return deg;
    }
    let w = deg.rem_euclid(360.0);
    if w > 180.0 { w - 360.0 } else { w }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hermite_root_of_a_line_and_a_cubic() {
        assert!((hermite_root(-1.0, 2.0, 1.0, 2.0) - 0.5).abs() < 1e-12);
        // y = s^3 - 0.125 on [0, 1]: root 0.5; slopes 0 and 3.
        assert!((hermite_root(-0.125, 0.0, 0.875, 3.0) - 0.5).abs() < 1e-12);
        // A step that starts exactly on the root.
        assert!(hermite_root(0.0, 1.0, 1.0, 1.0) < 1e-12);
        assert!(hermite_root(-0.0, -1.0, -1.0, -1.0) < 1e-12);
    }

    #[test]
    fn arrival_is_interpolated_between_steps() {
        // Block angle θ(t) = 1 − t crosses zero at t = 1.
        let q0 = [0.0, 0.0, 1.0];
        let v = [0.0, 0.0, -1.0];
        let mut det = ArrivalDetector::new(0.0, &q0, &v);
        det.observe(0.7, &[0.0, 0.0, 0.3], &v);
        det.observe(1.4, &[0.0, 0.0, -0.4], &v);
        assert!((det.arrival[0].unwrap() - 1.0).abs() < 1e-12);
    }

    /// θ(t) = θ0 + ω t observed every `dt` up to `t_end`.
    fn ramp(theta0: f64, omega: f64, dt: f64, t_end: f64) -> ArrivalDetector {
        let v = [0.0, 0.0, omega];
        let mut det = ArrivalDetector::new(0.0, &[0.0, 0.0, theta0], &v);
        let steps = (t_end / dt).round() as usize;
        for k in 1..=steps {
            let t = k as f64 * dt;
            det.observe(t, &[0.0, 0.0, theta0 + omega * t], &v);
        }
        det
    }

    #[test]
    fn a_block_turning_through_180_degrees_arrives() {
        use std::f64::consts::PI;
        // From 88° up through 180° (the polarisation sin θ turns negative
        // there; θ itself never changes sign).
        let (theta0, omega) = (88f64.to_radians(), 0.01);
        let det = ramp(theta0, omega, 0.3, 250.0);
        let want = (PI - theta0) / omega;
        let got = det.arrival[0].expect("the block turned through 180°");
        assert!((got - want).abs() < 1e-9, "arrival {got}, want {want}");
        // From −88° down through −180°.
        let det = ramp(-theta0, -omega, 0.3, 250.0);
        assert!((det.arrival[0].unwrap() - want).abs() < 1e-9);
        // From −88° up through 0, as before.
        let det = ramp(-theta0, omega, 0.3, 250.0);
        assert!((det.arrival[0].unwrap() - theta0 / omega).abs() < 1e-9);
        // Turning towards 180° but stopping short: no arrival.
        assert!(ramp(theta0, omega, 0.3, 150.0).arrival[0].is_none());
    }

    #[test]
    fn a_block_that_starts_beyond_a_turn_uses_its_own_interval() {
        use std::f64::consts::PI;
        // θ0 = 2π + 1 (sin > 0): arrives at 3π going up, at 2π going down.
        let theta0 = 2.0 * PI + 1.0;
        let up = ramp(theta0, 0.01, 0.3, 300.0).arrival[0].unwrap();
        assert!((up - (PI - 1.0) / 0.01).abs() < 1e-9, "{up}");
        let down = ramp(theta0, -0.01, 0.3, 300.0).arrival[0].unwrap();
        assert!((down - 1.0 / 0.01).abs() < 1e-9, "{down}");
    }

    #[test]
    fn reported_angles_are_wrapped() {
        assert_eq!(wrap_deg(-60.0), -60.0);
        assert_eq!(wrap_deg(180.0), 180.0);
        assert_eq!(wrap_deg(-180.0), 180.0);
        assert_eq!(wrap_deg(272.0), -88.0);
        assert_eq!(wrap_deg(-448.0), -88.0);
        assert_eq!(wrap_deg(0.1), 0.1);
        let q = [0.0, 0.0, 272f64.to_radians()];
        assert!((angles_deg(&q)[0] + 88.0).abs() < 1e-12);
        assert!((angles_deg_unwrapped(&q)[0] - 272.0).abs() < 1e-12);
    }
}
