//! What every field of a shard file must be for the plan it names: its
//! program, version and fingerprint, its counts, and each record: values a
//! run can have, and agreeing with its own arrival times and the outcome
//! rule (docs/cluster.md, "Shard files are checked, not trusted").

use super::{MAX_SHARDS, Shard, ShardFile};
use crate::sim::waves::Fate;
use crate::sweep::outcome::{self, Outcome};
use crate::sweep::{Plan, Record, RunResult};

/// The program and version every shard file names (a file of another
/// version has another fingerprint too; this says which).
pub(super) const PROGRAM: &str = "ladder";
pub(super) const VERSION: &str = env!("CARGO_PKG_VERSION");

impl ShardFile {
    /// Checks this file against the sweep `plan` it claims to belong to:
    /// the program and version that wrote it, its fingerprint, its counts,
    /// and every record (index unique, in range and of this shard; every
    /// field as [`check_record`] checks it). `Err`: the field and why.
    pub fn validate(&self, plan: &Plan) -> std::result::Result<(), String> {
        if self.program != PROGRAM || self.version != VERSION {
            return Err(format!(
                "version: made by {} {}, not by this {PROGRAM} {VERSION}; rerun the shard with \
                 this version",
                self.program, self.version
            ));
        }
        if self.fingerprint != plan.fingerprint {
            return Err(format!(
                "made for another sweep (fingerprint {}, this sweep's is {})",
                self.fingerprint, plan.fingerprint
            ));
        }
        let Shard { k, n } = self.shard;
        if n == 0 || n > MAX_SHARDS || k == 0 || k > n {
            return Err(format!("names shard {k}/{n}, which does not exist"));
        }
        if self.runs_total != plan.len() {
            return Err(format!(
                "says the sweep has {} runs; its plan has {}",
                self.runs_total,
                plan.len()
            ));
        }
        let in_shard = self.shard.count(plan.len());
        if self.runs_in_shard != in_shard {
            return Err(format!(
                "says shard {k}/{n} has {} runs; the plan gives it {in_shard}",
                self.runs_in_shard
            ));
        }
        if self.records.len() > in_shard {
            return Err(format!(
                "holds {} records for a shard of {in_shard} runs",
                self.records.len()
            ));
        }
        let mut last: Option<usize> = None;
        for r in &self.records {
            if r.run >= plan.len() || r.run % n != k - 1 {
                return Err(format!(
                    "holds run {}, which is not a run of shard {k}/{n} of {} runs",
                    r.run,
                    plan.len()
                ));
            }
            if last.is_some_and(|l| l >= r.run) {
                return Err(format!("holds run {} twice (or out of order)", r.run));
            }
            last = Some(r.run);
            check_record(plan, r)?;
        }
        Ok(())
    }
}

/// Checks every field of record `r` of `plan`: values a run of its N can
/// have ([`sane`]), then each derived field against the record's own
/// arrival times, as the sweep derives them (`sweep::run`:
/// `outcome::blocks_flipped`, `front`, `block_n_turned_at`,
/// `wave_speed`), and its outcome and `t_decided` against the outcome rule
/// ([`check_outcome`]). `Err`: "run R: FIELD ..." naming what disagrees.
pub fn check_record(plan: &Plan, r: &Record) -> std::result::Result<(), String> {
    let scene = plan.scene_at(r.run);
    let res = &r.result;
    let at = |m: String| format!("run {}: {m}", r.run);
    sane(res, scene.model.n).map_err(at)?;
    let arr = &res.arrival_times;
    let shown = outcome::blocks_flipped(arr);
    if res.blocks_flipped != shown {
        return Err(at(format!(
            "blocks_flipped {}, but its arrival times show {shown}",
            res.blocks_flipped
        )));
    }
    let front = outcome::front(arr);
    if res.front != front {
        return Err(at(format!(
            "front {}, but its arrival times give {front}",
            res.front
        )));
    }
    if res.block_n_turned_at.map(f64::to_bits) != outcome::block_n_turned_at(arr).map(f64::to_bits)
    {
        return Err(at(
            "block_n_turned_at is not block N's arrival time".to_string()
        ));
    }
    let speed = outcome::wave_speed(arr);
    let same = match (res.speed, speed) {
        (None, None) => true,
        (Some(a), Some(b)) => (a - b).abs() <= 1e-12 * b.abs(),
        _ => false,
    };
    if !same {
        return Err(at(format!(
            "speed {}, but its arrival times give {}",
            opt(res.speed),
            opt(speed)
        )));
    }
    check_outcome(res, plan.spec.cap).map_err(at)
}

fn opt(x: Option<f64>) -> String {
    x.map_or("none".into(), crate::numfmt::plain)
}

/// The outcome and `t_decided` of a record against the rule
/// (`outcome::Rule::decide`, docs/sweeps.md "The outcome of a run"):
/// propagated is decided at the last of blocks 1..N − 1's arrivals;
/// pinned and stalled have their front ≤ 2 and past 2 (and short of
/// N − 1); undecided is decided at the cap; annihilated is a driven wave
/// annihilated, and no other outcome has one; diverged and failed runs
/// have a message and no `t_decided`; no time is past the cap or before
/// an arrival.
fn check_outcome(res: &RunResult, cap: f64) -> std::result::Result<(), String> {
    let n = res.arrival_times.len();
    let arrivals = res.arrival_times.iter().flatten().copied();
    let last = arrivals.clone().fold(0.0, f64::max);
    let broken = matches!(res.outcome, Outcome::Diverged | Outcome::Failed);
    let word = res.outcome.name();
    if broken {
        return match (res.t_decided, &res.message, res.blocks_flipped) {
            (None, Some(_), 0) => Ok(()),
            _ => Err(format!(
                "outcome {word} with a t_decided, a flipped block or no message"
            )),
        };
    }
    let Some(t) = res.t_decided else {
        return Err(format!("outcome {word} without a t_decided"));
    };
    if t > cap || t < last {
        return Err(format!(
            "t_decided {} outside its run: before an arrival ({}) or past the cap ({})",
            crate::numfmt::plain(t),
            crate::numfmt::plain(last),
            crate::numfmt::plain(cap)
        ));
    }
    let all_flipped = res.front + 1 >= n;
    let driven_annihilated = res
        .waves
        .waves
        .iter()
        .find(|w| w.origin == 1)
        .is_some_and(|w| matches!(w.fate, Fate::Annihilated { .. }));
    let fits = match res.outcome {
        Outcome::Propagated => all_flipped && t == last_above_n(res) && !driven_annihilated,
        Outcome::Pinned => res.front <= 2 && !all_flipped && !driven_annihilated,
        Outcome::Stalled => res.front > 2 && !all_flipped && !driven_annihilated,
        Outcome::Undecided => !all_flipped && t == cap && !driven_annihilated,
        Outcome::Annihilated => driven_annihilated,
        Outcome::Diverged | Outcome::Failed => true,
    };
    if fits {
        Ok(())
    } else {
        Err(format!(
            "outcome {word} does not fit its front {} of N = {n} (t_decided {}{})",
            res.front,
            crate::numfmt::plain(t),
            if driven_annihilated {
                ", its driven wave annihilated"
            } else {
                ""
            }
        ))
    }
}

/// The last arrival of blocks 1..N − 1: when a propagated run decided.
fn last_above_n(res: &RunResult) -> f64 {
    let n = res.arrival_times.len();
    res.arrival_times[..n.saturating_sub(1)]
        .iter()
        .flatten()
        .copied()
        .fold(f64::NEG_INFINITY, f64::max)
}

/// Whether a record's values can be a run of `blocks` blocks: counts
/// within the chain, times finite and not negative, a short integrator
/// name.
fn sane(r: &RunResult, blocks: usize) -> std::result::Result<(), String> {
    let time = |t: f64| t.is_finite() && t >= 0.0;
    if r.arrival_times.len() != blocks {
        return Err(format!(
            "{} arrival times for a chain of N = {blocks}",
            r.arrival_times.len()
        ));
    }
    if r.blocks_flipped > blocks || r.front > blocks {
        return Err(format!(
            "blocks_flipped {} or front {} past N = {blocks}",
            r.blocks_flipped, r.front
        ));
    }
    if r.arrival_times.iter().flatten().any(|&t| !time(t)) {
        return Err("an arrival time that is negative or not finite".into());
    }
    if r.t_decided.is_some_and(|t| !time(t))
        || r.arrival_error.is_some_and(|t| !time(t))
        || !time(r.dt)
    {
        return Err("a time (t_decided, dt, arrival_error) that is negative or not finite".into());
    }
    if r.speed.is_some_and(|v| !v.is_finite()) {
        return Err("a speed that is not finite".into());
    }
    let name_ok = !r.integrator.is_empty()
        && r.integrator.len() <= 64
        && r.integrator
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'-' || b == b'_' || b == b' ');
    if !name_ok {
        return Err("an integrator name that is not one".into());
    }
    if r.message.as_ref().is_some_and(|m| m.len() > 4096) {
        return Err("a message longer than 4096 bytes".into());
    }
    Ok(())
}
