//! The wave speed c: the one definition the program reports (a run's
//! `speed`, the arrivals figure S6, a sweep's `speed` column,
//! `simulate --json`, Python's `Run.speed`), decided from the arrival
//! times the run loop records.

/// Shortest time between the arrivals of successive blocks that is still
/// a wave passing from one to the next, τ. The model's waves take hundreds
/// of τ per block (the paper's kink: about 220 τ; the slowest antikinks of
/// the pinning sweep several thousand); blocks that flip less than 1 τ
/// apart flip together, faster than a block can respond to its neighbour
/// (the shortest period of the linear chain, 2π/ω_max, is 2.3 τ at
/// |α| = 89°, N = 10, b/s = 1.3: `ladder theory --alpha 89`).
pub const COLLECTIVE_FLIP_GAP: f64 = 1.0;

/// The first block (one-based) whose arrival enters the wave speed
/// [`wave_speed`]: block 1 is driven and block 2 is pushed by it, so
/// their arrival times follow the drive, not the wave.
pub const FIRST_SPEED_BLOCK: usize = 3;

/// The least-squares fit behind [`wave_speed`]: the speed c (blocks per
/// τ) and the centroid (n̄, t̄) of the points fitted, so that the line is
/// t = t̄ + (n − n̄)/c.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedFit {
    pub speed: f64,
    pub centroid: (f64, f64),
}

/// **The wave speed c**, in blocks per τ: the one definition the program
/// reports (a run's `speed`, the arrivals figure S6's legend and line,
/// a sweep's `speed` column, `simulate --json`).
///
/// The paper measures the kink's and antikink's speeds c_kink and
/// c_antikink from t_n, the time the wave reaches block n, against n
/// (Supplement, "Experiment", Fig. S-experiment (d)), and finds them
/// insensitive to the initial excitation (main text, p. 2). So c is the
/// inverse least-squares slope of t_n against n over the blocks past the
/// drive's reach and before the free bottom block, n = 3..N−1
/// ([`FIRST_SPEED_BLOCK`]; block 1 is driven, block 2 pushed by it, and
/// block N turns its own way), that flipped. Measured at α = 60°, N = 10:
/// with drive times T_d = 250, 500, 1000 and 2000 τ this c is 0.007727,
/// 0.007729, 0.007729 and 0.007728 blocks/τ, where a fit over blocks
/// 2..N−1 gives 0.007630 to 0.007374 (it follows the drive);
/// docs/sweeps.md, "The wave speed". Every speed the program reports is this one (`sweep::outcome` re-exports it).
///
/// `None` with fewer than three such blocks, no positive slope (blocks
/// that do not flip in order down the ladder: walls from both ends), or
/// blocks that flip in groups rather than one after another: when at
/// least half the gaps between successive arrivals are shorter than
/// [`COLLECTIVE_FLIP_GAP`] (near |α| = 90°: at 89° the antikink's blocks
/// 2–9 flip within 0.8 τ, the kink's in two groups), a slope through
/// them is no speed.
pub fn wave_speed(arrivals: &[Option<f64>]) -> Option<f64> {
    wave_speed_fit(arrivals).map(|f| f.speed)
}

/// [`wave_speed`] with the fitted line's centroid.
pub fn wave_speed_fit(arrivals: &[Option<f64>]) -> Option<SpeedFit> {
    let n = arrivals.len();
    let pts: Vec<(f64, f64)> = (FIRST_SPEED_BLOCK - 1..n.saturating_sub(1))
        .filter_map(|i| arrivals[i].map(|t| (i as f64 + 1.0, t)))
        .collect();
    fit(&pts)
}

/// The speed through the points (block n, arrival time t_n) of a wave:
/// the inverse least-squares slope of t_n against n, and the centroid.
/// `None` with fewer than three points, no positive slope, or blocks that
/// flip in groups (at least half the gaps between successive arrivals
/// shorter than [`COLLECTIVE_FLIP_GAP`]): the rule of [`wave_speed`], for
/// any stretch of the chain (the experiment figures' lower half too).
pub fn fit(pts: &[(f64, f64)]) -> Option<SpeedFit> {
    if pts.len() < 3 {
        return None;
    }
    let together = pts
        .windows(2)
        .filter(|w| (w[1].1 - w[0].1).abs() < COLLECTIVE_FLIP_GAP)
        .count();
    if 2 * together >= pts.len() - 1 {
        return None;
    }
    let slope = super::observables::least_squares_slope(pts);
    let k = pts.len() as f64;
    let centroid = pts
        .iter()
        .fold((0.0, 0.0), |(a, b), p| (a + p.0 / k, b + p.1 / k));
    (slope.is_finite() && slope > 0.0).then(|| SpeedFit {
        speed: 1.0 / slope,
        centroid,
    })
}
