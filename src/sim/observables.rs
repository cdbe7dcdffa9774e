//! Observables of a run: arrival times of the flip at each block (SPEC
//! section 1), the kink position, and the topological polarisation sin θ_n.

use crate::model::ladder::itheta;

/// Records, for every block, the first time θ_n changes sign (the block is
/// horizontal), interpolated inside the step by a cubic Hermite polynomial
/// through θ and θ̇ at both ends of the step.
#[derive(Debug, Clone)]
pub struct ArrivalDetector {
    initial_sign: Vec<f64>,
    prev_theta: Vec<f64>,
    prev_omega: Vec<f64>,
    prev_t: f64,
    pub arrival: Vec<Option<f64>>,
}

impl ArrivalDetector {
    pub fn new(t0: f64, q: &[f64], v: &[f64]) -> Self {
        let n = q.len() / 3;
        let theta: Vec<f64> = (0..n).map(|i| q[itheta(i)]).collect();
        Self {
            initial_sign: theta.iter().map(|th| th.signum()).collect(),
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
            if self.crossed(i, th) {
                let (th0, om0) = (self.prev_theta[i], self.prev_omega[i]);
                self.record(i, (t0, th0, om0), (t, th, om));
            }
            (self.prev_theta[i], self.prev_omega[i]) = (th, om);
        }
        self.prev_t = t;
    }

    /// Whether block `i`, at angle `theta`, has just turned past horizontal
    /// for the first time.
    #[inline]
    pub fn crossed(&self, i: usize, theta: f64) -> bool {
        theta * self.initial_sign[i] < 0.0 && self.arrival[i].is_none()
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

    /// (−1 or +1) sign of block `i`'s initial angle.
    pub fn initial_sign(&self, i: usize) -> f64 {
        self.initial_sign[i]
    }

    /// Records block `i`'s arrival inside the step from (t0, θ0, θ̇0) to
    /// (t1, θ1, θ̇1), where θ changed sign.
    pub fn record(&mut self, i: usize, start: (f64, f64, f64), end: (f64, f64, f64)) {
        let ((t0, th0, om0), (t1, th1, om1)) = (start, end);
        let h = t1 - t0;
        let s = hermite_root(th0, h * om0, th1, h * om1);
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

/// Speed of the wave in blocks per τ: the inverse slope of the arrival
/// time t_n against n over blocks 2..N−1 (the driven top and the free
/// bottom left out); `None` if fewer than three of them flipped.
pub fn wave_speed(arrivals: &[Option<f64>]) -> Option<f64> {
    let last = arrivals.len().saturating_sub(1);
    let pts: Vec<(f64, f64)> = (1..last)
        .filter_map(|i| arrivals[i].map(|t| (i as f64 + 1.0, t)))
        .collect();
    (pts.len() >= 3).then(|| 1.0 / least_squares_slope(&pts))
}

/// Topological polarisation of each block, sin θ_n (SPEC section 1).
pub fn polarisation(q: &[f64]) -> Vec<f64> {
    (0..q.len() / 3).map(|i| q[itheta(i)].sin()).collect()
}

/// Block angles θ_n in degrees.
pub fn angles_deg(q: &[f64]) -> Vec<f64> {
    (0..q.len() / 3)
        .map(|i| q[itheta(i)].to_degrees())
        .collect()
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
}
