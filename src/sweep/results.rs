//! A sweep's results as files (SPEC section 7): the CSV, one row per run
//! in grid order, and the JSON with every arrival time. Both are made from
//! the records alone (no wall times, no paths), so they are byte-identical
//! between runs, and between a sharded sweep and an unsharded one.

use super::outcome::Outcome;
use super::{Plan, Record};
use crate::error::{Error, Result};
use crate::scene::describe;
use crate::scene::sweep::Param;
use serde::Serialize;
use std::fmt::Write;

/// The CSV columns after the parameters.
pub const RESULT_COLUMNS: [&str; 5] = ["outcome", "blocks_flipped", "front", "speed", "t_decided"];

/// `run,alpha,n,b,gamma,gravity,inertia,drive_time,outcome,blocks_flipped,front,speed,t_decided`:
/// every parameter of every run (the varied ones and the base's), then
/// what the wave did. Speed in blocks/τ (empty when fewer than three
/// blocks past block 2 flipped), t_decided in τ (empty for a diverged run).
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
    out.push('\n');
    for r in records {
        let scene = plan.scene_at(r.run);
        let _ = write!(out, "{}", r.run);
        for p in Param::ALL {
            let _ = write!(out, ",{}", p.get(&scene));
        }
        let res = &r.result;
        let _ = writeln!(
            out,
            ",{},{},{},{},{}",
            res.outcome,
            res.blocks_flipped,
            res.front,
            res.speed
                .map_or(String::new(), |v| format!("{}", sig(v, 6))),
            res.t_decided
                .map_or(String::new(), |t| format!("{}", sig(t, 9)))
        );
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

#[derive(Serialize)]
struct Axis<'a> {
    param: &'static str,
    values: &'a [f64],
}

#[derive(Serialize)]
struct RunEntry<'a> {
    #[serde(flatten)]
    record: &'a Record,
    /// The varied parameters' values.
    point: serde_json::Map<String, serde_json::Value>,
}

#[derive(Serialize)]
struct Rule {
    t_end: f64,
    cap: f64,
    kinetic_tolerance: f64,
    force_tolerance: f64,
    stability_margin: f64,
    description: &'static str,
}

#[derive(Serialize)]
struct SweepData<'a> {
    /// The program, its build and the command line (issue 19).
    #[serde(flatten)]
    made_by: crate::scenes::data::MadeBy<'a>,
    title: String,
    parameters: String,
    files: &'a [String],
    fingerprint: &'a str,
    scene: &'a crate::scene::Scene,
    axes: Vec<Axis<'a>>,
    rule: Rule,
    outcomes: serde_json::Map<String, serde_json::Value>,
    /// The linear theory at each α of the grid (when α varies).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    theory: Vec<super::chart::TheoryPoint>,
    runs: Vec<RunEntry<'a>>,
}

/// The JSON beside the CSV: the sweep (scene, axes, rule, fingerprint),
/// the count of each outcome, the linear theory along α, and every run
/// with its arrival times.
pub fn json(
    plan: &Plan,
    records: &[Record],
    files: &[String],
    command_line: &[String],
) -> Result<Vec<u8>> {
    let outcomes = counts(records)
        .into_iter()
        .map(|(o, c)| (o.name().to_string(), c.into()))
        .collect();
    let runs = records
        .iter()
        .map(|r| RunEntry {
            record: r,
            point: plan
                .axes
                .iter()
                .zip(&plan.points[r.run])
                .map(|((p, _), v)| (p.name().to_string(), json_number(*v)))
                .collect(),
        })
        .collect();
    let tol = crate::theory::stability::RestTolerances::default();
    let data = SweepData {
        made_by: crate::scenes::data::MadeBy::new(command_line),
        title: describe::title(&plan.scene),
        parameters: describe::parameters(&plan.scene),
        files,
        fingerprint: &plan.fingerprint,
        scene: &plan.scene,
        axes: plan
            .axes
            .iter()
            .map(|(p, v)| Axis {
                param: p.name(),
                values: v,
            })
            .collect(),
        rule: Rule {
            t_end: plan.scene.run.t_end,
            cap: plan.spec.cap,
            kinetic_tolerance: tol.kinetic,
            force_tolerance: tol.force,
            stability_margin: tol.margin,
            description: "propagated: block N-1 flipped; otherwise, after the drive, pinned \
                          (front <= 2) or stalled once the state is proved at rest (kinetic \
                          energy and largest residual force under the tolerances) at a linearly \
                          stable equilibrium (smallest mass-weighted eigenvalue of the clamped \
                          Hessian above the margin); undecided at the cap (docs/sweeps.md). The \
                          outcome columns describe the first wave's blocks; `waves` has every wave",
        },
        outcomes,
        theory: super::chart::theory_points(plan),
        runs,
    };
    serde_json::to_vec_pretty(&data)
        .map_err(|e| Error::failed(format!("cannot encode the sweep's data file: {e}")))
}

fn json_number(v: f64) -> serde_json::Value {
    serde_json::Number::from_f64(v).map_or(serde_json::Value::Null, serde_json::Value::Number)
}
