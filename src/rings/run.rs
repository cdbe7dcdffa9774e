//! A run of the ring chain: steps to `t_end`, the linking guard every
//! `guard_every` steps, flips observed every step, the state and the
//! energy sampled at given times.

use super::body::Body;
use super::build;
use super::chain::RingChain;
use super::math::{Quat, V3};
use super::observe::{self, Flip, FlipTracker, Wave};
use super::settle::{self, Settled};
use super::system::{Stats, System};
use crate::error::Result;
use serde::Serialize;

/// One ring's pose at a sample.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Pose {
    pub x: V3,
    pub q: [f64; 4],
}

/// The chain at one time.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Sample {
    pub t: f64,
    /// Total energy, J (docs/rings.md: kinetic, gravity, contact, tapes).
    pub energy: f64,
    pub rings: Vec<Pose>,
}

impl Sample {
    /// Ring k's orientation.
    pub fn quat(&self, k: usize) -> Quat {
        let [w, x, y, z] = self.rings[k].q;
        Quat { w, x, y, z }
    }
}

/// What a run gives.
#[derive(Clone, Debug)]
pub struct RingRun {
    pub samples: Vec<Sample>,
    pub flips: Vec<Flip>,
    pub waves: Vec<Wave>,
    pub stats: Stats,
    /// The step used, s.
    pub dt: f64,
    /// The system at the end (its constants: law, tapes, links).
    pub system: System,
    /// How the leaning start settled (`leaning`), or none: the chain as
    /// built.
    pub settled: Option<Settled>,
}

/// The system at t = 0: the chain as built, or settled from its leaning
/// start (docs/rings.md, "The leaning start").
pub fn start(chain: &RingChain) -> Result<(System, Option<Settled>)> {
    match &chain.leaning {
        None => Ok((build::build(chain)?, None)),
        Some(l) => {
            let (sys, done) = settle::leaning(chain, l.angle, l.squeeze)?;
            Ok((sys, Some(done)))
        }
    }
}

/// Checks that `chain` can start, without settling it: it builds, and a
/// leaning start's guess realises its topology.
pub fn check(chain: &RingChain) -> Result<()> {
    match &chain.leaning {
        None => build::build(chain).map(drop),
        Some(l) => settle::guess(chain, l.angle, l.squeeze).map(drop),
    }
}

/// Runs `chain` to its `t_end`, sampling at `times` (sorted, s).
pub fn run(chain: &RingChain, times: &[f64]) -> Result<RingRun> {
    let (mut sys, settled) = start(chain)?;
    let mut tracker = FlipTracker::new(sys.n());
    let mut samples = Vec::with_capacity(times.len());
    let mut next = 0;
    let steps = (chain.t_end / sys.dt).ceil() as u64;
    let take = |sys: &System, samples: &mut Vec<Sample>, next: &mut usize| {
        while *next < times.len() && times[*next] <= sys.t + 0.5 * sys.dt {
            samples.push(sample(sys));
            *next += 1;
        }
    };
    take(&sys, &mut samples, &mut next);
    tracker.observe(sys.t, &normals(&sys.bodies));
    sys.check_links()?;
    for k in 1..=steps {
        sys.step()?;
        tracker.observe(sys.t, &normals(&sys.bodies));
        if k % chain.guard_every as u64 == 0 || k == steps {
            sys.check_links()?;
        }
        take(&sys, &mut samples, &mut next);
    }
    let waves = observe::waves(&tracker.flips, sys.n(), chain.held, chain.turn.start);
    // One run of `steps` steps of every ring (`ladder all --timings`).
    crate::sim::tally::record(steps, sys.n());
    Ok(RingRun {
        samples,
        flips: tracker.flips,
        waves,
        stats: sys.stats,
        dt: sys.dt,
        system: sys,
        settled,
    })
}

fn sample(sys: &System) -> Sample {
    Sample {
        t: sys.t,
        energy: sys.energy(),
        rings: sys
            .bodies
            .iter()
            .map(|b| Pose {
                x: b.x,
                q: b.q.as_array(),
            })
            .collect(),
    }
}

/// Each ring's normal (the body z axis), from its quaternion.
pub fn normals(bodies: &[Body]) -> Vec<V3> {
    bodies
        .iter()
        .map(|b| {
            let Quat { w, x, y, z } = b.q;
            [
                2.0 * (x * z + w * y),
                2.0 * (y * z - w * x),
                1.0 - 2.0 * (x * x + y * y),
            ]
        })
        .collect()
}

/// `count` times evenly over [0, t_end].
pub fn even_times(t_end: f64, count: usize) -> Vec<f64> {
    let last = (count.max(2) - 1) as f64;
    (0..count.max(2)).map(|k| t_end * k as f64 / last).collect()
}
