//! The warm-started contact search (docs/performance.md, "The ring chain:
//! where its time goes"). The full
//! search ([`contact::touches_from`]: 24 sampled distances along ring a,
//! each sampled minimum refined by four parabolas) stays the reference;
//! between two full searches of a pair, each local minimum of the
//! distance that the full search would start from is followed instead:
//! Newton's method on the closed-form squared distance, started from the
//! minimum's angle at the previous step (one or two steps when the rings
//! moved by a step's worth).
//!
//! **Why no contact is missed.** Let f_t(θ) be the distance from the
//! point at angle θ of ring a's centre circle to ring b's centre circle.
//! In b's frame that point is T + Q (R cos θ, R sin θ, 0), with T = R_bᵀ
//! (c_a − c_b) and Q = R_bᵀ R_a the pair's relative pose; the distance to
//! a fixed circle is 1-Lipschitz in the point, so for every θ
//!
//! |f_t(θ) − f_{t₀}(θ)| ≤ δ = |ΔT| + R √(|Δq₀|² + |Δq₁|²)
//!
//! (q₀, q₁ the first two columns of Q; |Δq₀ cos θ + Δq₁ sin θ| is at most
//! that root by Cauchy–Schwarz). At the full search (time t₀) the 24
//! sampled distances d_j bound f_{t₀} between samples j and j + 1 (a
//! point moves at most R times its angle, the samples are Δ = 2π/24
//! apart) by (d_j + d_{j+1} − RΔ)/2. Each sample the full search refines
//! from (a sampled minimum below 2r + RΔ/2) gets an arc of ±[`ARC`]
//! samples; the pair keeps the budget B, the least of
//!
//! - (lower bound − 2r) over every interval outside the arcs: while
//!   δ < B, f_t > 2r there, so a refinement that starts outside the arcs
//!   (it moves at most ⅔ of a spacing, so it stays outside) finds no
//!   contact;
//! - for each arc sample k ≥ 2 from its centre, max(d − (2r + RΔ/2),
//!   (d − d_inner)/2), d_inner its neighbour toward the centre: while
//!   δ < B it stays above the gate or above its inner neighbour, so the
//!   full search starts from no arc sample but the centre's three;
//! - for each arc, (the higher of the centre's neighbours − the
//!   centre)/2: the two neighbours are not both sampled minima.
//!
//! So while δ < B every contact the full search would find is the
//! refinement of a start in the middle three samples of an arc, which
//! ends within 1⅔ spacings of the arc's centre: the local minimum the
//! warm search follows there (Newton must converge, with F'' > 0, inside
//! the arc, or the pair is searched in full). The full search runs when
//! δ ≥ B, when Newton fails, and every [`REFRESH`] steps. Like the full
//! search, it resolves the distance at the samples' spacing: two minima
//! closer than a spacing are one to both.
//!
//! A followed minimum whose distance d_k, found at pose k, exceeds 2r by
//! more than the drift since pose k (the same bound) cannot have come
//! within reach, and is not refined at that step (most near pairs have
//! such near misses).
//!
//! Every operation commutes with the mirror x → −x bit for bit (the pose
//! in b's frame maps as the points do; Newton's step is odd in the angle;
//! the budget is a minimum over a mirror-symmetric set).

use super::contact::{self, Circle, MAX_CONTACTS, SAMPLES, Touch};
use super::math::{self, V3};

/// Most steps between two full searches of a pair.
pub const REFRESH: u32 = 256;
/// Half-width of a tracked minimum's arc, in sample spacings.
const ARC: usize = 2;
/// Tracked minima per pair at most (a pair with more is searched in full).
const TRACKED: usize = 4;
/// Newton steps per minimum at most, and the step (rad) below which it
/// has converged: the angle is then within ~C·10⁻¹⁴ rad of the minimum
/// (quadratic convergence), the distance within ~10⁻²⁰ m.
const NEWTON_STEPS: usize = 8;
const CONVERGED: f64 = 1e-4;
/// The largest Newton step taken (rad): a longer one leaves the warm
/// start's basin, and the pair is searched in full.
const LONGEST_STEP: f64 = 0.1;
/// A margin for rounding in the budget, m (computed distances are off
/// by ~10⁻¹⁸ m at these sizes).
const ROUNDING: f64 = 1e-9;

/// Spacing of the samples, rad.
const SPACING: f64 = std::f64::consts::TAU / SAMPLES as f64;

/// Ring a's pose in ring b's frame: T = R_bᵀ(c_a − c_b) and the first two
/// columns of Q = R_bᵀ R_a, with both radii.
#[derive(Clone, Copy, Debug)]
pub struct Relative {
    t: V3,
    q0: V3,
    q1: V3,
    ra: f64,
    rb: f64,
}

impl Relative {
    pub fn of(a: &Circle, b: &Circle) -> Relative {
        let col = |k: usize| [a.rot[0][k], a.rot[1][k], a.rot[2][k]];
        Relative {
            t: math::mul_mtv(&b.rot, math::sub(a.c, b.c)),
            q0: math::mul_mtv(&b.rot, col(0)),
            q1: math::mul_mtv(&b.rot, col(1)),
            ra: a.radius,
            rb: b.radius,
        }
    }

    /// δ: the most the distance at any angle can differ between this pose
    /// and `o` (the module's bound).
    pub fn drift(&self, o: &Relative) -> f64 {
        let (d0, d1) = (math::sub(self.q0, o.q0), math::sub(self.q1, o.q1));
        math::norm(math::sub(self.t, o.t))
            + self.ra * (math::dot(d0, d0) + math::dot(d1, d1)).sqrt()
    }

    /// Newton's step on F(θ) = f(θ)² at `cs` = (cos θ, sin θ): −F'/F'',
    /// or `None` where F'' ≤ 0 or on b's axis. In b's frame, with P the
    /// point, u = P − T, P' its tangent, N the nearest point of b and
    /// e_φ the azimuth: F' = 2 (P − N)·P', F'' = 2 (|P'|² − (R_b/ρ)
    /// (e_φ·P')² − (P − N)·u).
    fn newton_step(&self, cs: (f64, f64)) -> Option<f64> {
        let (c, s) = cs;
        let (q0, q1, r) = (self.q0, self.q1, self.ra);
        let u = [
            r * (c * q0[0] + s * q1[0]),
            r * (c * q0[1] + s * q1[1]),
            r * (c * q0[2] + s * q1[2]),
        ];
        let dp = [
            r * (-s * q0[0] + c * q1[0]),
            r * (-s * q0[1] + c * q1[1]),
            r * (-s * q0[2] + c * q1[2]),
        ];
        let p = math::add(self.t, u);
        let rho = (p[0] * p[0] + p[1] * p[1]).sqrt();
        if rho <= 0.0 {
            return None;
        }
        let inv = 1.0 / rho;
        let ratio = self.rb * inv;
        let k = 1.0 - ratio;
        let n = [k * p[0], k * p[1], p[2]];
        let azimuthal = (p[0] * dp[1] - p[1] * dp[0]) * inv;
        let curv = math::dot(dp, dp) - ratio * (azimuthal * azimuthal) - math::dot(n, u);
        if curv.is_nan() || curv <= 0.0 {
            return None;
        }
        Some(-math::dot(n, dp) / curv)
    }

    /// The local minimum of the distance reached by Newton's method from
    /// `cs`, as (cos θ, sin θ); `None` if a step is too long, F'' ≤ 0 on
    /// the way, or it has not converged in [`NEWTON_STEPS`].
    pub fn minimum(&self, mut cs: (f64, f64)) -> Option<(f64, f64)> {
        for _ in 0..NEWTON_STEPS {
            let h = self.newton_step(cs)?;
            if h.abs() > LONGEST_STEP {
                return None;
            }
            cs = turned(cs, h);
            if h.abs() <= CONVERGED {
                let n = 1.0 / (cs.0 * cs.0 + cs.1 * cs.1).sqrt();
                return Some((cs.0 * n, cs.1 * n));
            }
        }
        None
    }
}

/// (cos, sin) of θ + h from those of θ, h small: Taylor polynomials of
/// cos h and sin h (exactly even and odd in h; within 10⁻¹² of the
/// library's for |h| ≤ 0.1, and Newton's last steps are short). The
/// result is off the unit circle by rounding only; [`Relative::minimum`]
/// scales its answer back.
fn turned((c, s): (f64, f64), h: f64) -> (f64, f64) {
    let h2 = h * h;
    let cos = 1.0 - h2 * 0.5 * (1.0 - h2 * (1.0 / 12.0) * (1.0 - h2 * (1.0 / 30.0)));
    let sin = h * (1.0 - h2 * (1.0 / 6.0) * (1.0 - h2 * (1.0 / 20.0) * (1.0 - h2 * (1.0 / 42.0))));
    (c * cos - s * sin, s * cos + c * sin)
}

/// A followed minimum: its angle on ring a, the sample it started from,
/// the distance there and the pair's pose when it was last found.
#[derive(Clone, Copy, Debug)]
struct Minimum {
    cs: (f64, f64),
    home: usize,
    d: f64,
    at: Relative,
}

/// What a pair keeps from its last full search.
#[derive(Clone, Debug)]
pub struct Memo {
    pose: Relative,
    /// B, m: the warm search holds while δ < B.
    budget: f64,
    /// Warm steps since the full search.
    age: u32,
    count: usize,
    minima: [Minimum; TRACKED],
}

/// The full search of a pair (the reference, bit for bit: the touches it
/// sends to `out` are [`contact::touches_at`]'s), and what the pair
/// keeps for the warm searches that follow.
pub fn full(
    a: &Circle,
    points: &[V3; SAMPLES],
    b: &Circle,
    reach: f64,
    table: &[(f64, f64); SAMPLES],
    out: &mut impl FnMut(Touch),
) -> Memo {
    let d2 = b.distances2(points);
    contact::touches_from(a, points, &d2, b, reach, table, out);
    memo_of(a, b, &d2, reach, table)
}

/// The budget and the followed minima of a pair from its sampled squared
/// distances (the module's bound).
fn memo_of(
    a: &Circle,
    b: &Circle,
    d2: &[f64; SAMPLES],
    reach: f64,
    table: &[(f64, f64); SAMPLES],
) -> Memo {
    let pose = Relative::of(a, b);
    let start = Minimum {
        cs: table[0],
        home: 0,
        d: f64::INFINITY,
        at: pose,
    };
    let mut memo = Memo {
        pose,
        budget: f64::NEG_INFINITY,
        age: 0,
        count: 0,
        minima: [start; TRACKED],
    };
    let d = d2.map(f64::sqrt);
    let at = |j: usize, k: isize| d[(j as isize + k).rem_euclid(SAMPLES as isize) as usize];
    let slack = a.radius * std::f64::consts::PI / SAMPLES as f64;
    let (gate, gate2) = (reach + slack, (reach + slack) * (reach + slack));
    let mut covered = [false; SAMPLES];
    let mut budget = f64::INFINITY;
    for j in 0..SAMPLES {
        let (prev, next) = (d2[(j + SAMPLES - 1) % SAMPLES], d2[(j + 1) % SAMPLES]);
        if d2[j] > prev || d2[j] > next || d2[j] >= gate2 {
            continue;
        }
        if memo.count == TRACKED {
            return memo;
        }
        // The parabola through the three samples around j, then Newton.
        let (dm, dp) = (at(j, -1), at(j, 1));
        let curv = (dm + dp) - 2.0 * d[j];
        let offset = if curv > 0.0 {
            (0.5 * SPACING * (dm - dp) / curv).clamp(-0.5 * SPACING, 0.5 * SPACING)
        } else {
            0.0
        };
        let cs = match pose.minimum(turned(table[j], offset)) {
            Some(cs) if inside_arc(cs, table[j]) => cs,
            _ => return memo,
        };
        let Some((_, dmin)) = b.nearest(a.point(cs)) else {
            return memo;
        };
        memo.minima[memo.count] = Minimum {
            cs,
            home: j,
            d: dmin,
            at: pose,
        };
        memo.count += 1;
        for k in 0..2 * ARC {
            covered[(j + SAMPLES - ARC + k) % SAMPLES] = true;
        }
        budget = budget.min(0.5 * (at(j, -1).max(at(j, 1)) - d[j]));
        for k in 2..=ARC as isize {
            for (s, inner) in [(-k, 1 - k), (k, k - 1)] {
                let (ds, di) = (at(j, s), at(j, inner));
                budget = budget.min((ds - gate).max(0.5 * (ds - di)));
            }
        }
    }
    for j in (0..SAMPLES).filter(|&j| !covered[j]) {
        let low = 0.5 * (d[j] + at(j, 1) - a.radius * SPACING);
        budget = budget.min(low - reach);
    }
    memo.budget = budget - ROUNDING;
    memo
}

/// Whether `cs` lies within [`ARC`] spacings of the sample at `home`.
fn inside_arc(cs: (f64, f64), home: (f64, f64)) -> bool {
    static COS_ARC: std::sync::OnceLock<f64> = std::sync::OnceLock::new();
    let limit = *COS_ARC.get_or_init(|| (ARC as f64 * SPACING).cos());
    cs.0 * home.0 + cs.1 * home.1 > limit
}

/// The warm search of a pair from its `memo`: the touches (the deepest
/// first, at most [`MAX_CONTACTS`]) sent to `out` and `true`, or nothing
/// sent and `false` when the pair needs the full search (δ ≥ B, Newton
/// failed or left its arc, or [`REFRESH`] steps since the last).
pub fn warm(
    memo: &mut Memo,
    a: &Circle,
    b: &Circle,
    reach: f64,
    table: &[(f64, f64); SAMPLES],
    out: &mut impl FnMut(Touch),
) -> bool {
    if memo.age >= REFRESH || memo.budget.is_nan() || memo.budget <= 0.0 {
        return false;
    }
    let pose = Relative::of(a, b);
    if pose.drift(&memo.pose) >= memo.budget {
        return false;
    }
    let slack = a.radius * std::f64::consts::PI / SAMPLES as f64;
    let mut found = [None::<Touch>; TRACKED];
    for m in memo.minima.iter_mut().take(memo.count) {
        // Its distance can have fallen by the drift since it was found at
        // most: still out of reach, it is not followed this step.
        if m.d - pose.drift(&m.at) - ROUNDING >= reach {
            continue;
        }
        let Some(cs) = pose.minimum(m.cs) else {
            return false;
        };
        if !inside_arc(cs, table[m.home]) {
            return false;
        }
        let p = a.point(cs);
        let Some((q, d)) = b.nearest(p) else {
            return false;
        };
        (m.cs, m.d, m.at) = (cs, d, pose);
        if d < reach {
            contact::insert_by_depth(&mut found, Touch { p, q, d }, slack);
        }
    }
    memo.age += 1;
    for t in found.iter().take(MAX_CONTACTS).flatten() {
        out(*t);
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rings::math::Quat;

    fn uniform(seed: &mut u64) -> f64 {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        (*seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }

    fn random_ring(seed: &mut u64, spread: f64) -> Circle {
        let mut axis = [uniform(seed), uniform(seed), uniform(seed)];
        axis = math::scale(axis, 1.0 / math::norm(axis).max(1e-9));
        Circle {
            c: [0.0; 3].map(|_| spread * uniform(seed)),
            rot: Quat::axis_angle(axis, 3.2 * uniform(seed)).matrix(),
            radius: 0.0125,
        }
    }

    /// Moves a ring by up to `by` m and turns it by up to `by`/R rad.
    fn nudged(seed: &mut u64, c: &Circle, by: f64) -> Circle {
        let mut axis = [uniform(seed), uniform(seed), uniform(seed)];
        axis = math::scale(axis, 1.0 / math::norm(axis).max(1e-9));
        let turn = Quat::axis_angle(axis, by / c.radius * uniform(seed)).matrix();
        let mut rot = [[0.0; 3]; 3];
        for (i, row) in rot.iter_mut().enumerate() {
            for (k, v) in row.iter_mut().enumerate() {
                *v = (0..3).map(|m| turn[i][m] * c.rot[m][k]).sum();
            }
        }
        Circle {
            c: math::add(c.c, [0.0; 3].map(|_| by * uniform(seed))),
            rot,
            radius: c.radius,
        }
    }

    fn distance(a: &Circle, b: &Circle, theta: f64) -> f64 {
        b.nearest(a.point((theta.cos(), theta.sin())))
            .map_or(0.0, |(_, d)| d)
    }

    /// The module's bound: between two poses of a pair, the distance at
    /// every angle (a scan of 2000) changes by at most δ, and δ is not
    /// loose by orders of magnitude (the largest change is within a
    /// factor 5 of it somewhere).
    #[test]
    fn the_drift_bounds_the_change_of_the_distance() {
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut tight = 0;
        for trial in 0..400 {
            let (a, b) = (random_ring(&mut seed, 0.0), random_ring(&mut seed, 0.015));
            let by = [1e-6, 1e-4, 1e-3][trial % 3];
            let (a2, b2) = (nudged(&mut seed, &a, by), nudged(&mut seed, &b, by));
            let delta = Relative::of(&a2, &b2).drift(&Relative::of(&a, &b));
            let mut most: f64 = 0.0;
            for k in 0..2000 {
                let theta = k as f64 / 2000.0 * std::f64::consts::TAU;
                most = most.max((distance(&a2, &b2, theta) - distance(&a, &b, theta)).abs());
            }
            assert!(
                most <= delta * (1.0 + 1e-9) + 1e-15,
                "trial {trial}: {most} > δ = {delta}"
            );
            tight += usize::from(most > 0.2 * delta);
        }
        assert!(tight > 100, "δ is loose: {tight} of 400 within a factor 5");
    }

    /// Newton's minimum against a scan of the angles within 0.01 rad of
    /// it at 10⁻⁷ rad, from starts up to 0.05 rad away, for random pairs
    /// whose minimum is near contact.
    #[test]
    fn newton_finds_the_minimum_of_a_fine_scan() {
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut checked = 0;
        while checked < 200 {
            let (a, b) = (random_ring(&mut seed, 0.0), random_ring(&mut seed, 0.015));
            let theta = std::f64::consts::PI * uniform(&mut seed);
            let pose = Relative::of(&a, &b);
            let Some(cs) = pose.minimum(math::cos_sin(theta)) else {
                continue;
            };
            let found = cs.1.atan2(cs.0);
            let d = distance(&a, &b, found);
            if d > 0.004 {
                continue;
            }
            let start = found + 0.05 * uniform(&mut seed);
            let again = pose.minimum(math::cos_sin(start)).unwrap();
            let best = scanned_minimum(&a, &b, found);
            for cs in [cs, again] {
                let d = distance(&a, &b, cs.1.atan2(cs.0));
                assert!(d - best < 1e-15 && best - d < 1e-12, "{d} vs {best}");
            }
            checked += 1;
        }
    }

    /// The least distance over the angles within 0.01 rad of `centre`, at
    /// 10⁻⁷ rad: scanned at 10⁻⁵ rad, then at 10⁻⁷ rad within two coarse
    /// steps of the coarse scan's least (the distance is smooth at that
    /// scale, its curvature set by millimetres: one minimum within 10⁻⁵
    /// rad). 2 400 evaluations where a scan of the whole window at 10⁻⁷
    /// rad takes 200 000.
    fn scanned_minimum(a: &Circle, b: &Circle, centre: f64) -> f64 {
        let scan = |around: f64, step: f64, half: i64| {
            (-half..=half)
                .map(|k| around + k as f64 * step)
                .map(|t| (distance(a, b, t), t))
                .fold(
                    (f64::INFINITY, around),
                    |m, x| if x.0 < m.0 { x } else { m },
                )
        };
        let (_, coarse) = scan(centre, 1e-5, 1000);
        scan(coarse, 1e-7, 200).0
    }
}
