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
/// start (docs/rings.md, "The leaning start") or, for the tumbling rings,
/// from their guess ("The tumbling rings").
pub fn start(chain: &RingChain) -> Result<(System, Option<Settled>)> {
    match &chain.leaning {
        None if chain.is_tumbling() => {
            let (sys, done) = settle::settled_from(chain, settle::tumbling_assembled(chain)?)?;
            Ok((sys, Some(done)))
        }
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
        None if chain.is_tumbling() => settle::tumbling_assembled(chain).map(drop),
        None => build::build(chain).map(drop),
        Some(l) => settle::guess(chain, l.angle, l.squeeze).map(drop),
    }
}

/// Runs `chain` to its `t_end`, sampling at `times` (sorted, s).
pub fn run(chain: &RingChain, times: &[f64]) -> Result<RingRun> {
    let asked = [Asked {
        t_end: chain.t_end,
        times,
    }];
    let mut made = runs(chain, &asked)?;
    Ok(made.pop().expect("one run asked, one made"))
}

/// What one output asks of a run of the chain: its end (s) and its
/// sample times (sorted, s).
#[derive(Clone, Copy, Debug)]
pub struct Asked<'a> {
    pub t_end: f64,
    pub times: &'a [f64],
}

/// One run of `chain` to the latest of the `asked` ends (the chain's own
/// `t_end` is not read) that gives, for each of them, what [`run`] of the
/// chain with that end and those times gives, bit for bit: the step does
/// not depend on the end, so a run to an earlier end is the first steps
/// of a run to a later one; a sample only reads the state; and at an
/// earlier end the linking guard checks the chain as a run ending there
/// would, that check counted in that run's `guard_checks` only (it reads
/// the state and changes nothing else). Figure 4b is movie 12's first
/// 2 s (docs/rings.md, docs/performance.md "Runs two outputs make alike").
/// Counted as one run of the latest end's steps (`sim::tally`).
pub fn runs(chain: &RingChain, asked: &[Asked<'_>]) -> Result<Vec<RingRun>> {
    let (mut sys, settled) = start(chain)?;
    let mut tracker = FlipTracker::new(sys.n());
    let ends: Vec<u64> = asked
        .iter()
        .map(|a| (a.t_end / sys.dt).ceil() as u64)
        .collect();
    let steps = ends.iter().copied().max().unwrap_or(0);
    let mut taken: Vec<Taken> = asked.iter().map(|a| Taken::new(a.times)).collect();
    let mut made: Vec<Option<RingRun>> = vec![None; asked.len()];
    for t in &mut taken {
        t.take(&sys);
    }
    tracker.observe(sys.t, &normals(&sys.bodies));
    sys.check_links()?;
    for k in 0..=steps {
        if k > 0 {
            sys.step()?;
            tracker.observe(sys.t, &normals(&sys.bodies));
            if k % chain.guard_every as u64 == 0 || k == steps {
                sys.check_links()?;
            }
        }
        for (i, t) in taken.iter_mut().enumerate() {
            if k == 0 || k > ends[i] {
                continue;
            }
            t.take(&sys);
            if k == ends[i] && k < steps {
                let end = (k, asked[i].t_end);
                made[i] = Some(ended_early(&mut sys, chain, &tracker, t, end, settled)?);
            }
        }
    }
    // One run of `steps` steps of every ring (`ladder all --timings`).
    crate::sim::tally::record(steps, sys.n());
    let last = asked.iter().zip(&ends).rposition(|(_, &e)| e == steps);
    for (i, slot) in made.iter_mut().enumerate() {
        if slot.is_none() && Some(i) != last {
            let mut system = sys.clone();
            system.chain.t_end = asked[i].t_end;
            *slot = Some(finish(system, chain, &tracker, &mut taken[i], settled));
        }
    }
    if let Some(i) = last {
        sys.chain.t_end = asked[i].t_end;
        made[i] = Some(finish(sys, chain, &tracker, &mut taken[i], settled));
    }
    Ok(made
        .into_iter()
        .map(|m| m.expect("every end reached"))
        .collect())
}

/// The samples one asked run has taken.
struct Taken<'a> {
    times: &'a [f64],
    next: usize,
    samples: Vec<Sample>,
}

impl<'a> Taken<'a> {
    fn new(times: &'a [f64]) -> Self {
        Taken {
            times,
            next: 0,
            samples: Vec::with_capacity(times.len()),
        }
    }

    /// The state at every time not yet taken that this step has reached.
    fn take(&mut self, sys: &System) {
        while self.next < self.times.len() && self.times[self.next] <= sys.t + 0.5 * sys.dt {
            self.samples.push(sample(sys));
            self.next += 1;
        }
    }
}

/// The run asked to end at this step, `end` = (step, t_end), before the
/// latest end: the linking guard's check at its end (where the guard's
/// every `guard_every` steps did not check) counted in its run only.
fn ended_early(
    sys: &mut System,
    chain: &RingChain,
    tracker: &FlipTracker,
    taken: &mut Taken<'_>,
    (step, t_end): (u64, f64),
    settled: Option<Settled>,
) -> Result<RingRun> {
    let before = sys.stats.guard_checks;
    if step % chain.guard_every as u64 != 0 {
        sys.check_links()?;
    }
    let mut system = sys.clone();
    system.chain.t_end = t_end;
    sys.stats.guard_checks = before;
    Ok(finish(system, chain, tracker, taken, settled))
}

/// A run as it ended: its samples, the flips so far and their waves.
fn finish(
    system: System,
    chain: &RingChain,
    tracker: &FlipTracker,
    taken: &mut Taken<'_>,
    settled: Option<Settled>,
) -> RingRun {
    let flips = tracker.flips.clone();
    let after = chain.alternate.map_or(chain.turn.start, |a| a.start);
    let waves = observe::waves(&flips, system.n(), chain.held, after);
    RingRun {
        samples: std::mem::take(&mut taken.samples),
        flips,
        waves,
        stats: system.stats,
        dt: system.dt,
        system,
        settled,
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    /// One run to the latest of several ends gives each end what a run of
    /// its own gives, bit for bit: the samples (also where the times
    /// asked go past the end), the flips, the counts (the guard's check
    /// at an end off its grid in that run only), the step and the state.
    #[test]
    fn one_run_to_several_ends_is_each_ends_own_run() {
        let chain = |t_end: f64| RingChain {
            t_end,
            ..RingChain::default()
        };
        let early = [0.0, 0.004, 0.011, 0.019, 0.03];
        let late = even_times(0.05, 6);
        let asked = [
            Asked {
                t_end: 0.05,
                times: &late,
            },
            Asked {
                t_end: 0.019,
                times: &early,
            },
            Asked {
                t_end: 0.05,
                times: &early,
            },
        ];
        let made = runs(&chain(0.05), &asked).unwrap();
        assert_eq!(made[1].samples.len(), 4, "the time past its end not taken");
        for (a, m) in asked.iter().zip(&made) {
            let own = run(&chain(a.t_end), a.times).unwrap();
            assert_eq!(m.samples, own.samples);
            assert_eq!((&m.flips, &m.waves), (&own.flips, &own.waves));
            assert_eq!((m.stats, m.dt), (own.stats, own.dt));
            assert_eq!(m.system.chain, own.system.chain);
            assert_eq!(format!("{:?}", m.system), format!("{:?}", own.system));
        }
        assert_ne!(
            made[1].stats.steps % 20,
            0,
            "the early end is off the guard's grid"
        );
    }
}
