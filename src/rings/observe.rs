//! What the chain did, decided from its state (paper Fig. 4b, SI Movie
//! 12): ring i flips when its normal's vertical component n_z changes
//! sign, counted with a hysteresis band |n_z| < [`BAND`] (a flip is a
//! tilt reversed past ±15°, not a wobble about the vertical). Its flip
//! axis is n(before) × n(after), the normals at the band's two edges, and
//! φ_i that axis's azimuth. A helical wave is a run of consecutive rings
//! of one strand whose first flips come in order down the strand with φ
//! advancing by a constant step that is neither 0 nor π; its clarity is
//! the run's length, its speed rings per second, its pitch rings per
//! turn of φ.

use super::math::{self, V3};
use serde::Serialize;

/// Half-width of the hysteresis band of n_z: sin 15°.
pub const BAND: f64 = 0.258_819_045_102_520_8;
/// How far a step of φ may stray from the run's median step, degrees.
pub const STEP_TOLERANCE: f64 = 30.0;
/// A step of φ within this of 0 or ±180° is no helix, degrees.
pub const STEP_MARGIN: f64 = 15.0;

/// One flip of one ring.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Flip {
    pub ring: usize,
    /// When n_z crossed 0, s (between steps, linearly).
    pub t: f64,
    /// n(before) × n(after), normalised.
    pub axis: V3,
    /// Azimuth of the axis, degrees in (−180, 180].
    pub phi: f64,
}

/// Tracks each ring's n_z and records flips.
#[derive(Clone, Debug)]
pub struct FlipTracker {
    /// Side of the band each ring was last on (+1, −1, or 0 at first).
    side: Vec<i8>,
    /// Normal at the last exit from a side of the band.
    left_at: Vec<V3>,
    /// Last zero crossing of n_z, s.
    crossed: Vec<f64>,
    last: Vec<(f64, f64)>,
    pub flips: Vec<Flip>,
}

impl FlipTracker {
    pub fn new(n: usize) -> FlipTracker {
        FlipTracker {
            side: vec![0; n],
            left_at: vec![[0.0; 3]; n],
            crossed: vec![f64::NAN; n],
            last: vec![(f64::NAN, f64::NAN); n],
            flips: Vec::new(),
        }
    }

    /// Records the normals at time `t`.
    pub fn observe(&mut self, t: f64, normals: &[V3]) {
        for (i, n) in normals.iter().enumerate() {
            let nz = n[2];
            let (t0, z0) = self.last[i];
            if z0.is_finite() && (z0 < 0.0) != (nz < 0.0) {
                self.crossed[i] = t0 + (t - t0) * z0 / (z0 - nz);
            }
            self.last[i] = (t, nz);
            let now: i8 = if nz > BAND {
                1
            } else if nz < -BAND {
                -1
            } else {
                // Inside the band: remember the normal while still on a side.
                continue;
            };
            if now == -self.side[i] && self.crossed[i].is_finite() {
                let a = math::cross(self.left_at[i], *n);
                let size = math::norm(a);
                if size > 0.0 {
                    let axis = math::scale(a, 1.0 / size);
                    let phi = axis[1].atan2(axis[0]).to_degrees();
                    self.flips.push(Flip {
                        ring: i,
                        t: self.crossed[i],
                        axis,
                        phi,
                    });
                }
            }
            self.side[i] = now;
            self.left_at[i] = *n;
        }
    }
}

/// A helical wave down one strand.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Wave {
    /// 0 for the even rings, 1 for the odd.
    pub strand: usize,
    /// The rings of the run, top first.
    pub rings: Vec<usize>,
    /// Their first flip times, s.
    pub times: Vec<f64>,
    /// Their flip azimuths, degrees.
    pub phis: Vec<f64>,
    /// Median step of φ from one ring of the strand to the next, degrees:
    /// its sign is the helicity.
    pub step: f64,
    /// Rings of the strand per second (least squares over the run).
    pub speed: f64,
    /// Rings of the strand per full turn of φ: 360°/|step|.
    pub pitch: f64,
}

/// φ_b − φ_a wrapped to (−180°, 180°].
pub fn angle_step(a: f64, b: f64) -> f64 {
    let d = (b - a).rem_euclid(360.0);
    if d > 180.0 { d - 360.0 } else { d }
}

/// The longest helical wave of each strand (none where no two rings
/// flip in order), from each ring's first flip after `after`.
pub fn waves(flips: &[Flip], n: usize, held: usize, after: f64) -> Vec<Wave> {
    let mut first: Vec<Option<Flip>> = vec![None; n];
    for f in flips.iter().filter(|f| f.t >= after && f.ring != held) {
        first[f.ring].get_or_insert(*f);
    }
    (0..2)
        .filter_map(|s| strand_wave(&first, s, held))
        .collect()
}

fn strand_wave(first: &[Option<Flip>], strand: usize, held: usize) -> Option<Wave> {
    let rings: Vec<usize> = (0..first.len())
        .filter(|&k| k % 2 == strand && k != held)
        .collect();
    let mut best: Option<Wave> = None;
    for start in 0..rings.len() {
        let mut run: Vec<Flip> = Vec::new();
        for &k in &rings[start..] {
            let Some(f) = first[k] else { break };
            if let Some(prev) = run.last() {
                if f.t <= prev.t {
                    break;
                }
                let mut steps: Vec<f64> = run
                    .windows(2)
                    .map(|w| angle_step(w[0].phi, w[1].phi))
                    .collect();
                steps.push(angle_step(prev.phi, f.phi));
                if !constant_helix(&steps) {
                    break;
                }
            }
            run.push(f);
        }
        if run.len() >= 3 && best.as_ref().is_none_or(|b| run.len() > b.rings.len()) {
            best = Some(wave_of(&run, strand));
        }
    }
    best
}

/// Whether the steps are within [`STEP_TOLERANCE`] of their median and
/// the median is a helix (not near 0 or 180°).
fn constant_helix(steps: &[f64]) -> bool {
    let m = median(steps);
    m.abs() >= STEP_MARGIN
        && m.abs() <= 180.0 - STEP_MARGIN
        && steps.iter().all(|s| (s - m).abs() <= STEP_TOLERANCE)
}

fn median(v: &[f64]) -> f64 {
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    let k = s.len() / 2;
    if s.len() % 2 == 1 {
        s[k]
    } else {
        0.5 * (s[k - 1] + s[k])
    }
}

fn wave_of(run: &[Flip], strand: usize) -> Wave {
    let steps: Vec<f64> = run
        .windows(2)
        .map(|w| angle_step(w[0].phi, w[1].phi))
        .collect();
    let step = median(&steps);
    let times: Vec<f64> = run.iter().map(|f| f.t).collect();
    // Least squares of position along the strand against time.
    let m = times.len() as f64;
    let (mt, mk) = (times.iter().sum::<f64>() / m, 0.5 * (m - 1.0));
    let (mut stk, mut stt) = (0.0, 0.0);
    for (k, t) in times.iter().enumerate() {
        stk += (t - mt) * (k as f64 - mk);
        stt += (t - mt) * (t - mt);
    }
    Wave {
        strand,
        rings: run.iter().map(|f| f.ring).collect(),
        times,
        phis: run.iter().map(|f| f.phi).collect(),
        step,
        speed: stk / stt,
        pitch: 360.0 / step.abs(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flip(ring: usize, t: f64, phi: f64) -> Flip {
        Flip {
            ring,
            t,
            axis: [0.0; 3],
            phi,
        }
    }

    #[test]
    fn a_run_of_constant_steps_is_a_wave() {
        let flips: Vec<Flip> = (0..8)
            .map(|k| flip(2 * k + 1, 0.1 * k as f64, -170.0 + 40.0 * k as f64))
            .collect();
        let w = waves(&flips, 17, 0, 0.0);
        assert_eq!(w.len(), 1);
        assert_eq!(w[0].rings.len(), 8);
        assert!((w[0].step - 40.0).abs() < 1e-9 && (w[0].speed - 10.0).abs() < 1e-9);
        assert!((w[0].pitch - 9.0).abs() < 1e-9);
        // Steps of 180° are a zig-zag, no helix; times out of order no wave.
        let zig: Vec<Flip> = (0..8)
            .map(|k| flip(2 * k + 1, 0.1 * k as f64, 180.0 * k as f64))
            .collect();
        assert!(waves(&zig, 17, 0, 0.0).is_empty());
        let up: Vec<Flip> = (0..8)
            .map(|k| flip(2 * k + 1, -0.1 * k as f64 + 1.0, 40.0 * k as f64))
            .collect();
        assert!(waves(&up, 17, 0, 0.0).is_empty());
    }

    #[test]
    fn flips_are_the_sign_changes_of_n_z_with_their_axis() {
        let mut tr = FlipTracker::new(1);
        // Tilting about +y: n goes from +x-ish up to down.
        for k in 0..=100 {
            let a = -0.8 + 1.6 * k as f64 / 100.0;
            tr.observe(k as f64, &[[a.cos(), 0.0, -a.sin()]]);
        }
        assert_eq!(tr.flips.len(), 1);
        let f = tr.flips[0];
        assert!((f.t - 50.0).abs() < 1e-9);
        assert!((f.phi - 90.0).abs() < 1e-9, "{f:?}");
    }

    /// Ring k of the odd strand tipped over about the horizontal axis at
    /// azimuth `phi0 + k·step`, its flip centred at 0.1 (k + 1) s; the
    /// even rings stand still; mirrored (x → −x) if asked.
    fn helix(phi0: f64, step: f64, mirror: bool) -> Vec<Flip> {
        let n = 12;
        let mut tr = FlipTracker::new(n);
        for s in 0..=1200 {
            let t = s as f64 * 1e-3;
            let normals: Vec<V3> = (0..n)
                .map(|ring| {
                    if ring % 2 == 0 {
                        return [1.0, 0.0, 0.0];
                    }
                    let k = (ring / 2) as f64;
                    let phi = (phi0 + k * step - 90.0).to_radians();
                    // Tilt from +0.8 to −0.8 rad around 0.1 (k + 1) s.
                    let a = (8.0 * (t - 0.1 * (k + 1.0)) / 0.05).clamp(-0.8, 0.8);
                    let m = [a.cos() * phi.cos(), a.cos() * phi.sin(), -a.sin()];
                    if mirror { [-m[0], m[1], m[2]] } else { m }
                })
                .collect();
            tr.observe(t, &normals);
        }
        tr.flips
    }

    /// The tracker and the wave finder end to end: a helix of flips with a
    /// 40° step is found with its step, speed and pitch, and its mirror
    /// image has the opposite step (the opposite helicity); a wobble
    /// inside the band is no flip.
    #[test]
    fn a_helix_of_flips_and_its_mirror_have_opposite_steps() {
        let flips = helix(30.0, 40.0, false);
        assert_eq!(flips.len(), 6, "{flips:?}");
        for (k, f) in flips.iter().enumerate() {
            assert!((f.t - 0.1 * (k + 1) as f64).abs() < 1e-3, "{f:?}");
            assert!(
                angle_step(30.0 + 40.0 * k as f64, f.phi).abs() < 1e-6,
                "{f:?}"
            );
        }
        let w = waves(&flips, 12, 0, 0.0);
        assert_eq!(w.len(), 1);
        assert_eq!(w[0].rings, vec![1, 3, 5, 7, 9, 11]);
        assert!((w[0].step - 40.0).abs() < 1e-6 && (w[0].speed - 10.0).abs() < 0.05);
        assert!((w[0].pitch - 9.0).abs() < 1e-6);
        let m = waves(&helix(30.0, 40.0, true), 12, 0, 0.0);
        assert_eq!(m.len(), 1);
        assert!((m[0].step + 40.0).abs() < 1e-6, "{:?}", m[0]);
        for (a, b) in w[0].phis.iter().zip(&m[0].phis) {
            assert!(angle_step(-a, *b).abs() < 1e-9, "{a} vs {b}");
        }
        // A wobble of n_z within ±0.2 (inside the ±sin 15° band) is no flip.
        let mut tr = FlipTracker::new(1);
        for s in 0..1000 {
            let z = 0.2 * (s as f64 * 0.05).sin();
            tr.observe(s as f64, &[[(1.0 - z * z).sqrt(), 0.0, z]]);
        }
        assert!(tr.flips.is_empty());
    }
}
