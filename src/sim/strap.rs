//! The strap hinge's run (docs/experiments.md, "The strap hinge: reduced
//! coordinates"): the chain of `model::strap` in its block angles, RK4
//! between events, block 1 driven.
//!
//! Events: a junction whose fold φ reaches a multiple of π (the blocks
//! face to face, on their ends or their faces) is an impact. The plastic
//! rule at the new pivot keeps the momentum of the motions the new pivots
//! allow (the impulse acts at the new pivot, which does no work on
//! them): M' θ̇⁺ = J'ᵀ M J θ̇⁻ over the free angles, J and J' the
//! kinematics under the old and the new pivot. Where that sends the
//! junction back (a block landing flat on its neighbour's face does: its
//! angular momentum about the landing corner turns the other way), the
//! block rebounds about the old pivot with the restitution e,
//! φ̇⁺ = −e φ̇⁻, the impulse along ∂φ/∂θ (every internal force of the
//! junction acts on the angles through its moment about the pivot); a
//! rebound slower than `LOCK_SPEED` leaves the junction locked face to
//! face (φ̈ = 0, a Lagrange multiplier) until its free acceleration
//! points into one of the two regions beside it. A drive corner (θ̇₁
//! jumps) is the same projection with the pivots unchanged.

use crate::error::{Error, Result};
use crate::model::params::M;
use crate::model::strap::{Region, StrapChain, fold, region_of, solve_spd};
use crate::sim::protocol::Drive;
use std::f64::consts::PI;

/// A rebound slower than this (per τ) locks the junction face to face.
pub const LOCK_SPEED: f64 = 1e-7;

/// What an impact did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// Rolled on about the new pivot.
    Switch,
    /// Rebounded about the old pivot.
    Rebound,
    /// Came to rest face to face.
    Lock,
}

/// One impact of the strap-hinge run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StrapImpact {
    pub t: f64,
    /// Junction index (blocks j + 1 and j + 2 in the paper's numbering).
    pub junction: usize,
    /// φ̇ just before.
    pub rate: f64,
    pub outcome: Outcome,
}

/// The run: samples of the maximal coordinates (x, y, θ per block), the
/// impacts, and the least ribbon tension met at any step (while taut it
/// stays > 0; where it does not, the strap hinge does not hold).
#[derive(Debug, Clone)]
pub struct StrapRun {
    pub times: Vec<f64>,
    pub states: Vec<Vec<f64>>,
    /// Kinetic energy of blocks 2..N plus the potential, at the samples.
    pub energies: Vec<f64>,
    pub impacts: Vec<StrapImpact>,
    pub least_tension: f64,
}

/// The state between events.
#[derive(Debug, Clone)]
struct Hinge {
    theta: Vec<f64>,
    omega: Vec<f64>,
    regions: Vec<Region>,
    locked: Vec<bool>,
}

impl Hinge {
    fn folds(&self) -> Vec<f64> {
        (0..self.regions.len())
            .map(|j| fold(&self.theta, j))
            .collect()
    }
}

/// θ̈ at the state (θ̈₁ = 0: the drive is piecewise linear), locked
/// junctions held by multipliers.
fn accelerations(c: &StrapChain, h: &Hinge, regions: &[Region], locked: &[bool]) -> Vec<f64> {
    let k = c.kinematics(&h.theta, &h.omega, regions);
    let (m, f) = c.equations(&k);
    let n = h.theta.len();
    let mf: Vec<Vec<f64>> = (1..n).map(|j| m[j][1..].to_vec()).collect();
    let base = solve_spd(&mf, &f[1..]);
    let locks: Vec<usize> = (0..n - 1).filter(|&j| locked[j]).collect();
    if locks.is_empty() {
        return std::iter::once(0.0).chain(base).collect();
    }
    // Γ_j θ̈ = −θ̈_j − θ̈_{j+1} = 0 for each lock (free angles 1..n).
    let gamma = |j: usize| -> Vec<f64> {
        (1..n)
            .map(|l| if l == j || l == j + 1 { -1.0 } else { 0.0 })
            .collect()
    };
    let cols: Vec<Vec<f64>> = locks.iter().map(|&j| solve_spd(&mf, &gamma(j))).collect();
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let s: Vec<Vec<f64>> = locks
        .iter()
        .map(|&a| cols.iter().map(|col| dot(&gamma(a), col)).collect())
        .collect();
    let rhs: Vec<f64> = locks.iter().map(|&a| -dot(&gamma(a), &base)).collect();
    let lambda = solve_spd(&s, &rhs);
    let mut acc = base;
    for (col, l) in cols.iter().zip(&lambda) {
        for (a, x) in acc.iter_mut().zip(col) {
            *a += l * x;
        }
    }
    std::iter::once(0.0).chain(acc).collect()
}

/// One RK4 step of `dt` from `t` (block 1 from the drive).
fn rk4(c: &StrapChain, drive: &Drive, h: &Hinge, t: f64, dt: f64) -> Hinge {
    let n = h.theta.len();
    let at = |th: &[f64], om: &[f64], tt: f64| {
        let mut s = h.clone();
        s.theta.copy_from_slice(th);
        s.omega.copy_from_slice(om);
        s.theta[0] = drive.theta(tt);
        s.omega[0] = h.omega[0];
        s
    };
    let f = |s: &Hinge| (s.omega.clone(), accelerations(c, s, &h.regions, &h.locked));
    let (k1x, k1v) = f(h);
    let step = |kx: &[f64], kv: &[f64], a: f64| {
        let th: Vec<f64> = (0..n).map(|i| h.theta[i] + a * kx[i]).collect();
        let om: Vec<f64> = (0..n).map(|i| h.omega[i] + a * kv[i]).collect();
        (th, om)
    };
    let (t2, o2) = step(&k1x, &k1v, 0.5 * dt);
    let (k2x, k2v) = f(&at(&t2, &o2, t + 0.5 * dt));
    let (t3, o3) = step(&k2x, &k2v, 0.5 * dt);
    let (k3x, k3v) = f(&at(&t3, &o3, t + 0.5 * dt));
    let (t4, o4) = step(&k3x, &k3v, dt);
    let (k4x, k4v) = f(&at(&t4, &o4, t + dt));
    let comb = |a: &[f64], b: &[f64], c2: &[f64], d: &[f64], i: usize| {
        (a[i] + 2.0 * b[i] + 2.0 * c2[i] + d[i]) * dt / 6.0
    };
    let th: Vec<f64> = (0..n)
        .map(|i| h.theta[i] + comb(&k1x, &k2x, &k3x, &k4x, i))
        .collect();
    let om: Vec<f64> = (0..n)
        .map(|i| h.omega[i] + comb(&k1v, &k2v, &k3v, &k4v, i))
        .collect();
    at(&th, &om, t + dt)
}

/// The first unlocked junction whose fold left its region, if any.
fn crossed(h: &Hinge) -> Option<usize> {
    h.folds().iter().enumerate().position(|(j, &phi)| {
        let r = h.regions[j] as f64;
        !h.locked[j] && (phi < r * PI || phi > (r + 1.0) * PI)
    })
}

/// The free angles' velocities after an impulse that keeps the momentum
/// of the motions `after` allows, from the motion under `before`
/// (block 1's rate set to `omega1`).
fn project(
    c: &StrapChain,
    h: &Hinge,
    before: &[Region],
    after: &[Region],
    omega1: f64,
) -> Vec<f64> {
    let n = h.theta.len();
    let k0 = c.kinematics(&h.theta, &h.omega, before);
    let mut om = h.omega.clone();
    om[0] = omega1;
    let k1 = c.kinematics(&h.theta, &om, after);
    let (m, _) = c.equations(&k1);
    // J'ᵀ M ẋ⁻ over the free angles, less the part block 1's new rate
    // carries (M' θ̇⁺ = J'ᵀ M ẋ⁻ with θ̇⁺₁ = omega1).
    let rhs: Vec<f64> = (1..n)
        .map(|j| {
            let p: f64 = (0..n)
                .map(|b| {
                    let jj = k1.jac[b][j];
                    M * (jj[0] * k0.v[3 * b] + jj[1] * k0.v[3 * b + 1])
                })
                .sum::<f64>()
                + c.inertia * h.omega[j];
            p - m[j][0] * omega1
        })
        .collect();
    let mf: Vec<Vec<f64>> = (1..n).map(|j| m[j][1..].to_vec()).collect();
    std::iter::once(omega1)
        .chain(solve_spd(&mf, &rhs))
        .collect()
}

/// φ̇ of junction j.
fn fold_rate(omega: &[f64], j: usize) -> f64 {
    -omega[j] - omega[j + 1]
}

/// Junction `j` at the boundary between `from` and the region beyond:
/// roll on about the new pivot, rebound, or lock (module doc).
fn impact(
    c: &StrapChain,
    h: &mut Hinge,
    j: usize,
    restitution: f64,
    t: f64,
) -> Result<StrapImpact> {
    let rate = fold_rate(&h.omega, j);
    let from = h.regions[j];
    let to = if rate > 0.0 { from + 1 } else { from - 1 };
    if !(-2..=1).contains(&to) {
        return Err(Error::Failed(format!(
            "junction {} folded past 2π at t = {t}: outside the strap hinge",
            j + 1
        )));
    }
    let mut after = h.regions.clone();
    after[j] = to;
    let switched = project(c, h, &h.regions, &after, h.omega[0]);
    let onward = fold_rate(&switched, j) * f64::from(to - from);
    if onward > 0.0 {
        h.regions = after;
        h.omega = switched;
        return Ok(StrapImpact {
            t,
            junction: j,
            rate,
            outcome: Outcome::Switch,
        });
    }
    // Rebound about the old pivot: an impulse along ∂φ/∂θ.
    let n = h.theta.len();
    let k = c.kinematics(&h.theta, &h.omega, &h.regions);
    let (m, _) = c.equations(&k);
    let mf: Vec<Vec<f64>> = (1..n).map(|l| m[l][1..].to_vec()).collect();
    let gamma: Vec<f64> = (1..n)
        .map(|l| if l == j || l == j + 1 { -1.0 } else { 0.0 })
        .collect();
    let col = solve_spd(&mf, &gamma);
    let g: f64 = gamma.iter().zip(&col).map(|(a, b)| a * b).sum();
    let mut e = restitution;
    let outcome = if restitution * rate.abs() < LOCK_SPEED {
        e = 0.0;
        h.locked[j] = true;
        Outcome::Lock
    } else {
        Outcome::Rebound
    };
    let lambda = -(1.0 + e) * rate / g;
    for (l, x) in col.iter().enumerate() {
        h.omega[l + 1] += lambda * x;
    }
    Ok(StrapImpact {
        t,
        junction: j,
        rate,
        outcome,
    })
}

/// Unlocks a locked junction whose free acceleration points into one of
/// the regions beside its boundary (that region's pivot).
fn unlock(c: &StrapChain, h: &mut Hinge) {
    for j in 0..h.locked.len() {
        if !h.locked[j] {
            continue;
        }
        let boundary = (fold(&h.theta, j) / PI).round() as Region;
        for (r, sign) in [(boundary, 1.0), (boundary - 1, -1.0)] {
            if !(-2..=1).contains(&r) {
                continue;
            }
            let mut regions = h.regions.clone();
            regions[j] = r;
            let mut locked = h.locked.clone();
            locked[j] = false;
            let a = accelerations(c, h, &regions, &locked);
            if sign * (-a[j] - a[j + 1]) > 0.0 {
                h.regions = regions;
                h.locked = locked;
                break;
            }
        }
    }
}

/// The least ribbon tension over every junction at the state.
fn least_tension(c: &StrapChain, h: &Hinge) -> f64 {
    let k = c.kinematics(&h.theta, &h.omega, &h.regions);
    let a = accelerations(c, h, &h.regions, &h.locked);
    (0..h.regions.len())
        .filter(|&j| !h.locked[j])
        .flat_map(|j| c.tensions(&k, &a, &h.regions, j))
        .fold(f64::INFINITY, f64::min)
}

/// Runs the strap-hinge chain from angles `theta` and rates `omega`
/// (block 1's from the drive) to `t_end` by RK4 steps of at most `dt`,
/// sampling the maximal coordinates at `samples`; face impacts rebound
/// with `restitution`.
pub fn simulate_strap(
    c: &StrapChain,
    drive: &Drive,
    (theta, omega): (&[f64], &[f64]),
    t_end: f64,
    dt: f64,
    samples: &[f64],
    restitution: f64,
) -> Result<StrapRun> {
    let n = theta.len();
    let mut h = Hinge {
        theta: theta.to_vec(),
        omega: omega.to_vec(),
        regions: (0..n - 1).map(|j| region_of(fold(theta, j))).collect(),
        locked: vec![false; n - 1],
    };
    h.theta[0] = drive.theta(0.0);
    let mut stops: Vec<f64> = samples.iter().copied().filter(|&s| s <= t_end).collect();
    stops.extend(drive.corners().filter(|&s| s > 0.0 && s < t_end));
    stops.push(t_end);
    stops.sort_by(f64::total_cmp);
    stops.dedup();
    let mut run = StrapRun {
        times: Vec::new(),
        states: Vec::new(),
        energies: Vec::new(),
        impacts: Vec::new(),
        least_tension: f64::INFINITY,
    };
    let mut t = 0.0;
    h.omega = project(c, &h, &h.regions, &h.regions, drive.omega(0.0));
    for stop in stops {
        while t < stop {
            let step = dt.min(stop - t);
            advance(c, drive, &mut h, &mut t, step, restitution, &mut run)?;
            if (stop - t).abs() < 1e-9 * dt {
                t = stop;
            }
        }
        if drive.corners().any(|k| k == stop) {
            h.omega = project(c, &h, &h.regions, &h.regions, drive.omega(stop));
        }
        if samples.contains(&stop) {
            run.times.push(stop);
            let k = c.kinematics(&h.theta, &h.omega, &h.regions);
            run.states.push(k.q);
            let (kin, pot) = c.energy(&h.theta, &h.omega, &h.regions);
            run.energies.push(kin + pot);
        }
    }
    Ok(run)
}

/// One step of `step` from `t`, or up to the first impact in it.
fn advance(
    c: &StrapChain,
    drive: &Drive,
    h: &mut Hinge,
    t: &mut f64,
    step: f64,
    restitution: f64,
    run: &mut StrapRun,
) -> Result<()> {
    unlock(c, h);
    let next = rk4(c, drive, h, *t, step);
    let Some(_) = crossed(&next) else {
        *h = next;
        *t += step;
        run.least_tension = run.least_tension.min(least_tension(c, h));
        return Ok(());
    };
    // Bisect for the first crossing inside the step.
    let (mut lo, mut hi) = (0.0, step);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if crossed(&rk4(c, drive, h, *t, mid)).is_some() {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let j = crossed(&rk4(c, drive, h, *t, hi)).unwrap_or(0);
    *h = rk4(c, drive, h, *t, lo);
    *t += lo;
    // Exactly on the boundary the region reached.
    let boundary = if fold_rate(&h.omega, j) > 0.0 {
        (h.regions[j] + 1) as f64 * PI
    } else {
        h.regions[j] as f64 * PI
    };
    h.theta[j + 1] = PI - boundary - h.theta[j];
    let i = impact(c, h, j, restitution, *t)?;
    run.impacts.push(i);
    Ok(())
}
