//! Fuzzing of shard files: a genuine shard file of a small
//! sweep, mutated at random (run indices, counts, values, duplicated and
//! dropped records, the fingerprint), is gathered and resumed through the
//! library. Either the mutation left the file valid and the result is the
//! genuine one, or the answer is bad input naming the file; never a
//! panic, never other records.

use crate::common::tempdir::TempDir;
use jacobs_ladder::error::Error;
use jacobs_ladder::sweep::shard::{self, Earlier, Shard};
use proptest::prelude::*;
use serde_json::Value;
use std::sync::OnceLock;

const FILE: &str = "sweep-fz.1-of-1.json";

/// The genuine shard file (one shard of four runs), made once.
fn genuine() -> &'static Value {
    static G: OnceLock<Value> = OnceLock::new();
    G.get_or_init(|| {
        let dir = TempDir::new("fuzz-genuine");
        let d = dir.path().to_str().unwrap();
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
            .args([
                "sweep",
                "--alpha=-50,-56",
                "--gamma",
                "0.02,0.04",
                "--name",
                "fz",
                "--out",
                d,
                "--shard",
                "1/1",
            ])
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice(&std::fs::read(dir.join("shards").join(FILE)).unwrap()).unwrap()
    })
}

/// One mutation of a shard file's JSON.
#[derive(Debug, Clone)]
enum Mutation {
    Run(usize, u64),
    Field(usize, &'static str, f64),
    Count(&'static str, u64),
    Duplicate(usize),
    Drop(usize),
    Arrivals(usize, usize),
    Fingerprint,
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let field = prop::sample::select(vec![
        "blocks_flipped",
        "front",
        "speed",
        "t_decided",
        "dt",
        "force_evals",
    ]);
    let value = prop_oneof![
        Just(-1.0),
        Just(0.0),
        Just(1e300),
        Just(-1e300),
        (0.0..1e4f64),
        Just(4.0e9)
    ];
    prop_oneof![
        (0..4usize, prop_oneof![0..8u64, Just(u64::MAX)]).prop_map(|(i, r)| Mutation::Run(i, r)),
        (0..4usize, field, value).prop_map(|(i, f, v)| Mutation::Field(i, f, v)),
        (
            prop::sample::select(vec!["runs_total", "runs_in_shard"]),
            prop_oneof![0..8u64, Just(u64::MAX)]
        )
            .prop_map(|(f, v)| Mutation::Count(f, v)),
        (0..4usize).prop_map(Mutation::Duplicate),
        (0..4usize).prop_map(Mutation::Drop),
        (0..4usize, 0..40usize).prop_map(|(i, n)| Mutation::Arrivals(i, n)),
        Just(Mutation::Fingerprint),
    ]
}

fn apply(v: &mut Value, m: &Mutation) {
    let recs = v["records"].as_array_mut().unwrap();
    let n = recs.len();
    match m {
        Mutation::Run(i, r) => recs[i % n]["run"] = (*r).into(),
        Mutation::Field(i, f, x) => {
            let x = if matches!(*f, "blocks_flipped" | "front" | "force_evals") {
                if *x < 0.0 {
                    Value::from(-1)
                } else {
                    Value::from(*x as u64)
                }
            } else {
                Value::from(*x)
            };
            recs[i % n][*f] = x;
        }
        Mutation::Count(f, x) => v[*f] = (*x).into(),
        Mutation::Duplicate(i) => {
            let r = recs[i % n].clone();
            recs.push(r);
        }
        Mutation::Drop(i) => {
            recs.remove(i % n);
        }
        Mutation::Arrivals(i, len) => {
            recs[i % n]["arrival_times"] = Value::Array(vec![Value::from(1.0); *len]);
        }
        Mutation::Fingerprint => v["fingerprint"] = "0000000000000000".into(),
    }
}

proptest! {
    // A fixed seed: CI runs the same 96 cases every time (a failure reproduces).
    #![proptest_config(ProptestConfig { cases: 96, failure_persistence: None, rng_seed: proptest::test_runner::RngSeed::Fixed(0x001a_dde5), .. ProptestConfig::default() })]

    #[test]
    fn a_mutated_shard_is_either_valid_or_refused_by_name(ms in prop::collection::vec(mutation(), 1..4)) {
        let good = genuine();
        let mut v = good.clone();
        for m in &ms {
            apply(&mut v, m);
        }
        let dir = TempDir::new("fuzz");
        std::fs::create_dir_all(dir.join("shards")).unwrap();
        std::fs::write(dir.join("shards").join(FILE), serde_json::to_vec(&v).unwrap()).unwrap();
        let truth: Vec<Value> = good["records"].as_array().unwrap().clone();
        match shard::gather(dir.path(), 1000) {
            Ok((plan, records)) => {
                // Every run once, in grid order; a record differs from the
                // genuine one only where a value was changed to a sane one
                // (which no check can tell from a real result).
                let runs: Vec<usize> = records.iter().map(|r| r.run).collect();
                prop_assert_eq!(runs, (0..plan.len()).collect::<Vec<_>>());
                prop_assert_eq!(plan.len(), truth.len());
                // Only the values no rule derives (the step, the count of
                // force evaluations, and a stopped run's t_decided, any
                // check time after its last arrival and within the cap)
                // can change and still be taken: every other field is
                // checked against the run's own arrival times and the
                // outcome rule.
                let values_changed = ms.iter().any(|m| {
                    matches!(m, Mutation::Field(_, "dt" | "force_evals" | "t_decided", _))
                });
                for (r, t) in records.iter().zip(&truth) {
                    let got = serde_json::to_value(r).unwrap();
                    prop_assert!(values_changed || &got == t, "gather accepted other records after {:?}", ms);
                }
                // And resume takes the same file.
                match shard::earlier(&plan, Shard { k: 1, n: 1 }, dir.path()) {
                    Ok(Earlier::Resumed(r)) => prop_assert_eq!(r.len(), truth.len()),
                    Ok(_) => prop_assert!(false, "resume did not take a valid file"),
                    Err(e) => prop_assert!(false, "resume refused a valid file: {}", e),
                }
            }
            Err(Error::BadInput(m)) => {
                prop_assert!(m.contains("shard"), "{} names no shard", m);
                prop_assert_eq!(m.lines().count(), 1);
            }
            Err(e) => prop_assert!(false, "not bad input: {}", e),
        }
    }
}

/// The genuine file of `genuine()` with `edit` applied, gathered from the
/// command line: exit 2, one line naming the file and `field`.
fn refused_by_gather(edit: impl FnOnce(&mut Value), field: &str) {
    let mut v = genuine().clone();
    edit(&mut v);
    let dir = TempDir::new("edited");
    std::fs::create_dir_all(dir.join("shards")).unwrap();
    std::fs::write(
        dir.join("shards").join(FILE),
        serde_json::to_vec(&v).unwrap(),
    )
    .unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(["sweep", "gather", dir.path().to_str().unwrap()])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{field}: {err}");
    assert_eq!(err.trim().lines().count(), 1, "{field}: {err}");
    assert!(err.contains(FILE) && err.contains(field), "{field}: {err}");
    assert!(!dir.join("sweep-fz.csv").exists(), "{field}: wrote a CSV");
}

/// Shards edited to say what their own arrival times do not (before,
/// `sweep gather` exited 0 on each, and wrote a t_decided of 1e300 into
/// the CSV as a 301-digit number); and a shard of another version.
#[test]
fn every_field_of_a_shard_is_checked_against_its_own_arrivals() {
    // Find a run whose chain flipped (a propagated kink or stalled wave)
    // and one pinned.
    let recs = genuine()["records"].as_array().unwrap();
    let flipped = recs
        .iter()
        .position(|r| r["blocks_flipped"].as_u64().unwrap() > 2)
        .expect("a run that flipped more than 2 blocks");
    let i = flipped;
    refused_by_gather(
        |v| v["records"][i]["outcome"] = "pinned".into(),
        "outcome pinned",
    );
    refused_by_gather(
        |v| v["records"][i]["blocks_flipped"] = 2.into(),
        "blocks_flipped 2",
    );
    refused_by_gather(|v| v["records"][i]["speed"] = 99.0.into(), "speed 99");
    refused_by_gather(
        |v| v["records"][i]["t_decided"] = 1e300.into(),
        "t_decided 1e300",
    );
    refused_by_gather(|v| v["version"] = "0.0.1".into(), "version");
    refused_by_gather(|v| v["program"] = "other".into(), "version");
}
