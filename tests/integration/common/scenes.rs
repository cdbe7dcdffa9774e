//! Synthetic scenes for render tests: ground states, a kink sweep, a
//! domain wall for kymographs.

use jacobs_ladder::model::ladder::itheta;
use jacobs_ladder::model::{Ladder, Params};

/// The paper's ladder (N = 10, b = 1.3) at `alpha_deg`.
pub fn ladder(alpha_deg: f64) -> Ladder {
    Ladder::new(Params::paper(alpha_deg).unwrap())
}

/// A ladder with N blocks and b at `alpha_deg`.
pub fn ladder_with(n: usize, b: f64, alpha_deg: f64) -> Ladder {
    let p = Params::paper(60.0).unwrap().with(n, b, alpha_deg).unwrap();
    Ladder::new(p)
}

/// The ground state with a smooth kink: block n has angle α·tanh((n − w)/1),
/// with the wall at fractional position `wall` (blocks above it flipped).
pub fn kink_state(ladder: &Ladder, wall: f64) -> Vec<f64> {
    let mut q = ladder.ground_state();
    let alpha = ladder.params.alpha;
    for i in 0..ladder.n() {
        let n = i as f64 + 1.0;
        q[itheta(i)] = alpha * ((n - wall) / 0.8).tanh();
    }
    q
}

/// Kymograph data of a tanh domain wall moving through `n` blocks:
/// (times, row-major sin θ_n values).
pub fn domain_wall(n: usize, rows: usize, t_end: f64) -> (Vec<f64>, Vec<f64>) {
    let alpha = 60f64.to_radians();
    let times: Vec<f64> = (0..rows)
        .map(|k| t_end * k as f64 / (rows - 1) as f64)
        .collect();
    let mut values = Vec::with_capacity(rows * n);
    for &t in &times {
        let wall = 0.5 + (n as f64 + 1.0) * t / t_end;
        for i in 0..n {
            let x = i as f64 + 1.0;
            values.push((alpha * ((x - wall) / 0.8).tanh()).sin());
        }
    }
    (times, values)
}
