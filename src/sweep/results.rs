//! A sweep's results as files (docs/sweeps.md): the CSV, one row per run
//! in grid order, and the JSON with every arrival time. Both are made from
//! the records alone (no wall times, no paths), so they are byte-identical
//! between runs, and between a sharded sweep and an unsharded one.

use super::outcome::Outcome;
use super::{Plan, Record};
use crate::scene::sweep::Param;
use crate::sim::waves::Fate;
use std::fmt::Write;

/// The CSV columns after the parameters.
pub const RESULT_COLUMNS: [&str; 6] = [
    "outcome",
    "blocks_flipped",
    "front",
    "speed",
    "t_decided",
    "block_n_turned_at",
];

/// The columns of each wave where a sweep launches more than one
/// (`wave2_kind`, ...; see [`csv`]).
pub const WAVE_COLUMNS: [&str; 5] = ["kind", "launched_at", "front", "fate", "fate_at"];

/// `run,alpha,n,b,gamma,gravity,inertia,drive_time,outcome,blocks_flipped,front,speed,t_decided,block_n_turned_at,waves`:
/// every parameter of every run (the varied ones and the base's), then
/// what the chain did from the top (the outcome columns: how far the flip
/// got down blocks 1..N − 1, `front` ≤ N − 1, and `blocks_flipped` of all
/// N), then when the free bottom block N first turned (empty if it had
/// not by t_decided; before block N − 1's arrival it fell over on its own
/// and sent a wall of its own up the chain), then how many waves the run
/// had. Speed in blocks/τ (empty when fewer than three blocks past block 2
/// flipped), t_decided in τ (empty for a diverged run). Where some run had more than
/// one wave, every wave k up to the most any run had follows in
/// `wavek_kind,wavek_launched_at,wavek_front,wavek_fate,wavek_fate_at`
/// (kink or antikink, τ, block, end/stopped/annihilated/undecided, the
/// annihilation's time; empty where the run had fewer waves).
pub fn csv(plan: &Plan, records: &[Record]) -> String {
    let mut out = String::from("run");
    for p in Param::ALL {
        out.push(',');
        out.push_str(p.name());
    }
    for c in RESULT_COLUMNS {
        out.push(',');
        out.push_str(c);
    }
    out.push_str(",waves");
    let most = records
        .iter()
        .map(|r| r.result.waves.waves.len())
        .max()
        .unwrap_or(0);
    let per_wave = if most > 1 { most } else { 0 };
    for k in 1..=per_wave {
        for c in WAVE_COLUMNS {
            let _ = write!(out, ",wave{k}_{c}");
        }
    }
    out.push('\n');
    for r in records {
        let scene = plan.scene_at(r.run);
        let _ = write!(out, "{}", r.run);
        for p in Param::ALL {
            let _ = write!(out, ",{}", p.get(&scene));
        }
        let res = &r.result;
        let _ = write!(
            out,
            ",{},{},{},{},{},{},{}",
            res.outcome,
            res.blocks_flipped,
            res.front,
            res.speed
                .map_or(String::new(), |v| format!("{}", sig(v, 6))),
            res.t_decided
                .map_or(String::new(), |t| format!("{}", sig(t, 9))),
            res.block_n_turned_at
                .map_or(String::new(), |t| format!("{}", sig(t, 9))),
            res.waves.waves.len()
        );
        for k in 0..per_wave {
            match res.waves.waves.get(k) {
                Some(w) => {
                    let kind = w.kind.name();
                    let (fate, at) = match w.fate {
                        Fate::End => ("end", None),
                        Fate::Stopped => ("stopped", None),
                        Fate::Annihilated { at, .. } => ("annihilated", Some(at)),
                        Fate::Undecided => ("undecided", None),
                    };
                    let _ = write!(
                        out,
                        ",{kind},{},{},{fate},{}",
                        sig(w.launched_at, 9),
                        w.front,
                        at.map_or(String::new(), |t| format!("{}", sig(t, 9)))
                    );
                }
                None => out.push_str(",,,,,"),
            }
        }
        out.push('\n');
    }
    out
}

/// `x` rounded to `digits` significant digits (printed shortest).
pub fn sig(x: f64, digits: usize) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    format!("{x:.*e}", digits.saturating_sub(1))
        .parse()
        .unwrap_or(x)
}

/// How many runs had each outcome.
pub fn counts(records: &[Record]) -> Vec<(Outcome, usize)> {
    Outcome::ALL
        .iter()
        .map(|o| {
            (
                *o,
                records.iter().filter(|r| r.result.outcome == *o).count(),
            )
        })
        .filter(|(_, c)| *c > 0)
        .collect()
}
