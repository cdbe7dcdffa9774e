//! The alternating hand of the double ring chain (paper Fig. 4b, SI Movie
//! 12: "by retrieving a top ring of one of two strands alternately";
//! docs/rings.md, "Retrieving the top rings alternately").

use crate::common::tempdir::TempDir;
use crate::rings::fingerprint;
use jacobs_ladder::rings::alternate::Alternate;
use jacobs_ladder::rings::math;
use jacobs_ladder::rings::{self, RingChain, build};
use std::process::Command;

/// The chain's state after `t_end`, stepped by hand.
fn stepped(chain: &RingChain) -> Vec<rings::body::Body> {
    let mut sys = build::build(chain).unwrap();
    let steps = (chain.t_end / sys.dt).ceil() as u64;
    for _ in 0..steps {
        sys.step().unwrap();
    }
    sys.bodies
}

/// The hand that releases the top ring (`release`) keeps its trajectory
/// bit for bit (recorded before the alternating hand was written).
#[test]
fn the_release_keeps_its_trajectory_bit_for_bit() {
    let chain = RingChain {
        n: 10,
        t_end: 0.3,
        release: true,
        turn: rings::Turn {
            start: 0.05,
            ..Default::default()
        },
        ..Default::default()
    };
    let end = fingerprint(&stepped(&chain));
    assert_eq!(end, 0x5d96_5195_59b7_451d, "{end:#x}");
}

/// A 12-ring chain whose hand passes between the strands from 0.1 s,
/// every `period`, `count` times.
fn alternating(period: f64, count: usize) -> RingChain {
    RingChain {
        n: 12,
        t_end: 0.1 + count as f64 * period,
        alternate: Some(Alternate {
            start: 0.1,
            period,
            count,
            lift: 0.0,
        }),
        ..Default::default()
    }
}

/// The mirrored chain with the alternating hand is the mirror image bit
/// for bit (every sample, flip and wave; the hand takes the same rings
/// at the same steps), and the linking guard ran over the whole run.
#[test]
fn the_alternating_mirror_chain_is_the_mirror_image_bit_for_bit() {
    let chain = alternating(0.15, 4);
    let (a, b) = crate::rings::mirror_images(chain.clone());
    assert_eq!(a.system.passes, b.system.passes);
    assert_eq!(a.system.passes.len(), 4, "{:?}", a.system.passes);
    let pairs = chain.linked_pairs().len() as u64;
    let checks = pairs * (a.stats.steps / chain.guard_every as u64);
    assert!(
        a.stats.guard_checks >= checks,
        "the guard checked {} pairs, {checks} at least",
        a.stats.guard_checks
    );
}

/// Each pass lets go the ring held and takes the ring of the other strand
/// whose centre is highest at that step (the rule of docs/rings.md,
/// decided here from the state after the step, where every centre is as
/// the pass saw it), at the first step at or after its time; the hand
/// then holds it still until the next pass.
#[test]
fn the_ring_taken_is_the_top_ring_of_the_other_strand() {
    let chain = alternating(0.3, 4);
    let a = chain.alternate.unwrap();
    let mut sys = build::build(&chain).unwrap();
    let mut held = (chain.held, sys.bodies[chain.held].x);
    while sys.t < chain.t_end {
        let before = sys.passes.len();
        sys.step().unwrap();
        if sys.passes.len() == before {
            assert_eq!((sys.held, sys.bodies[sys.held].x), held, "t = {}", sys.t);
            continue;
        }
        let p = *sys.passes.last().unwrap();
        assert_eq!((p.from, p.ring, p.t), (held.0, sys.held, sys.t));
        assert!(
            p.t >= a.time(before) && p.t - sys.dt < a.time(before),
            "{p:?}"
        );
        assert_ne!(p.ring % 2, p.from % 2, "the other strand: {p:?}");
        let z = sys.bodies[p.ring].x[2];
        for k in (p.ring % 2..chain.n).step_by(2) {
            let zk = sys.bodies[k].x[2];
            assert!(
                zk < z || (zk == z && k >= p.ring),
                "t = {}: ring {k} at z = {zk} is above ring {} at {z}",
                sys.t,
                p.ring
            );
        }
        held = (p.ring, sys.bodies[p.ring].x);
    }
    assert_eq!(sys.passes.len(), a.count, "{:?}", sys.passes);
}

/// The same rule where its answer is no ring next to the held one: the
/// 8-ring chain held by ring 1, ring 6 lifted 1 m above the chain (out
/// of every contact) before the first pass at t = 0: the hand lets ring
/// 1 go and takes ring 6, where it is, stopped; had ring 4 been lifted
/// higher still, ring 4. (Which ring a chain in motion offers is chaotic:
/// a change of 1e-12 m in a grip turned the 12-ring chain's passes from
/// rings 1, 0, 1, 2 to 1, 0, 1, 0.)
#[test]
fn the_ring_taken_is_the_highest_even_where_it_is_far_down_the_strand() {
    for lifted in [vec![6], vec![6, 4]] {
        let chain = RingChain {
            n: 8,
            held: 1,
            t_end: 0.01,
            alternate: Some(Alternate {
                start: 0.0,
                period: 1.0,
                count: 1,
                lift: 0.0,
            }),
            ..Default::default()
        };
        let mut sys = build::build(&chain).unwrap();
        for (i, &k) in lifted.iter().enumerate() {
            sys.bodies[k].x[2] += (i + 1) as f64;
            sys.bodies[k].v = [0.1, 0.0, 0.0];
        }
        let want = *lifted.last().unwrap();
        let x = sys.bodies[want].x;
        sys.step().unwrap();
        let p = sys.passes[0];
        assert_eq!((p.from, p.ring, sys.held), (1, want, want), "{p:?}");
        assert!(p.kinetic > 0.0, "its motion taken by the hand: {p:?}");
        let b = sys.bodies[want];
        assert_eq!(b.v, [0.0; 3], "stopped");
        let moved = math::norm(math::sub(b.x, x));
        assert!(moved < 1e-4, "taken where it was (one step on): {moved} m");
        sys.step().unwrap();
        assert_eq!(sys.bodies[want], b, "and held still");
    }
}

const BIN: &str = env!("CARGO_BIN_EXE_ladder");

/// `ladder render FILE` of a ring scene with `[rings]` `body` added.
fn render(dir: &TempDir, body: &str) -> std::process::Output {
    let text = format!(
        "name = \"alternate\"\n[rings]\nn = 8\nt_end = 0.35\n{body}\n[output]\nkind = \
         \"kymograph\"\n"
    );
    let path = dir.file("alternate.toml", &text);
    Command::new(BIN)
        .args(["render", &path, "--format", "png", "--out"])
        .arg(dir.path())
        .output()
        .unwrap()
}

/// [`render`] of `body` into a fresh folder named `name`, which must
/// succeed: its data file.
fn rendered_data(name: &str, body: &str) -> serde_json::Value {
    let dir = TempDir::new(name);
    let out = render(&dir, body);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    let json = std::fs::read(dir.join("figure-alternate.json")).unwrap();
    serde_json::from_slice(&json).unwrap()
}

/// A scene file asks for the alternating hand (and its data file records
/// the key in the scene and each pass: at its time, from the ring held to
/// a ring of the other strand); a value out of its key's range, the key with
/// `release`, an unknown key of it, or links that are not the double
/// chain, are one line on stderr and exit 2.
#[test]
fn the_alternating_hand_is_a_key_and_a_bad_value_is_refused() {
    let json = rendered_data(
        "rings-alternate-good",
        "alternate = { start = 0.1, period = 0.1, count = 2 }",
    );
    let asked = &json["scene"]["rings"]["alternate"];
    assert_eq!(asked["count"], 2, "{asked}");
    let passes = json["rings"]["passes"].as_array().unwrap();
    assert_eq!(passes.len(), 2, "{passes:?}");
    let dt = json["rings"]["dt"].as_f64().unwrap();
    let mut held = 0;
    for (i, p) in passes.iter().enumerate() {
        let t = p["t"].as_f64().unwrap();
        let want = 0.1 + 0.1 * i as f64;
        assert!(
            t >= want - 1e-9 && t < want + dt + 1e-9,
            "pass {i} at {t} s"
        );
        let (from, ring) = (p["from"].as_u64().unwrap(), p["ring"].as_u64().unwrap());
        assert_eq!(from, held, "pass {i} lets go of the ring held");
        assert_ne!(from % 2, ring % 2, "pass {i} takes the other strand's ring");
        assert!(p["kinetic"].as_f64().unwrap() >= 0.0);
        held = ring;
    }
    let dir = TempDir::new("rings-alternate-bad");
    for (what, body, needle) in [
        (
            "period",
            "alternate = { period = 0.0 }",
            "rings: alternate.period must be seconds from 0.01 to 60, got 0",
        ),
        (
            "count",
            "alternate = { count = 0 }",
            "alternate.count must be a whole number from 1 to 1000, got 0",
        ),
        (
            "start",
            "alternate = { start = -1.0 }",
            "alternate.start must be seconds from 0 to 600, got -1",
        ),
        (
            "two hands",
            "release = true\nalternate = {}",
            "alternate and release = true are two hands",
        ),
        ("unknown key", "alternate = { every = 0.3 }", "every"),
        (
            "single chain",
            "links = [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 6], [6, 7]]\nalternate = {}",
            "the two strands of the double chain",
        ),
    ] {
        let out = render(&dir, body);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{what}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{what}: {err}");
        assert!(err.contains(needle), "{what}: {err}");
    }
}

/// The alternating hand keeps its trajectory bit for bit (recorded when
/// it was written, docs/rings.md), so that a change of it is one made on
/// purpose.
#[test]
fn the_alternating_hand_keeps_its_trajectory_bit_for_bit() {
    let end = fingerprint(&stepped(&alternating(0.15, 3)));
    assert_eq!(end, 0x5b12_8f88_c25b_86f5, "{end:#x}");
}

/// A 12-ring chain whose hand passes between the strands from 0.1 s,
/// every `period`, `count` times, lifting each ring it takes over `lift`
/// to where it held the ring it let go (docs/rings.md, "Retrieving with
/// a lifting hand").
fn lifting(period: f64, count: usize, lift: f64) -> RingChain {
    let mut chain = alternating(period, count);
    chain.alternate.as_mut().unwrap().lift = lift;
    chain
}

/// The lifting hand carries each ring it takes from where it took it
/// (stopped) along the straight line to where it held the ring it let go,
/// which is where it held ring 0 at the start: it ends there exactly,
/// at rest, its orientation as taken, at the end of the lift, and stays
/// there still until the next pass; on the way its centre stays on the
/// line and moves along it, fastest (π/2 times the mean speed) at half
/// the lift.
#[test]
fn the_lifted_ring_ends_at_the_previous_grip_at_rest() {
    let lift = 0.05;
    let chain = lifting(0.15, 3, lift);
    let mut sys = build::build(&chain).unwrap();
    let place = sys.bodies[chain.held].x;
    let mut taken = None;
    let mut peak: f64 = 0.0;
    while sys.t < chain.t_end {
        let before = sys.passes.len();
        sys.step().unwrap();
        if sys.passes.len() > before {
            let b = sys.bodies[sys.held];
            assert_eq!(b.v, [0.0; 3], "taken stopped");
            taken = Some((sys.t, b));
            peak = 0.0;
            continue;
        }
        let Some((t0, from)) = taken else { continue };
        let b = sys.bodies[sys.held];
        assert_eq!((b.q, b.l), (from.q, [0.0; 3]), "orientation as taken");
        let d = math::sub(place, from.x);
        let (gone, speed) = (math::sub(b.x, from.x), math::norm(b.v));
        if sys.t >= t0 + lift {
            assert_eq!((b.x, b.v), (place, [0.0; 3]), "t = {}", sys.t);
            let mean = math::norm(d) / lift;
            let want = 0.5 * std::f64::consts::PI * mean;
            assert!((peak - want).abs() < 1e-3 * want, "peak {peak}, {want}");
            continue;
        }
        let along = math::dot(gone, d) / math::dot(d, d);
        let off = math::norm(math::sub(gone, math::scale(d, along)));
        assert!((0.0..=1.0).contains(&along) && off < 1e-12, "t = {}", sys.t);
        assert!(math::norm(math::cross(b.v, d)) < 1e-9 * math::norm(d));
        peak = peak.max(speed);
    }
    assert_eq!(sys.passes.len(), 3);
    let far = math::norm(math::sub(place, taken.unwrap().1.x));
    assert!(far > 5e-3, "each ring carried some way: {far} m");
}

/// The mirrored chain with the lifting hand is the mirror image bit for
/// bit (every sample; the same rings taken at the same steps).
#[test]
fn the_lifting_mirror_chain_is_the_mirror_image_bit_for_bit() {
    let chain = lifting(0.15, 4, 0.05);
    let (a, b) = crate::rings::mirror_images(chain);
    assert_eq!(a.system.passes, b.system.passes);
    assert_eq!(a.system.passes.len(), 4, "{:?}", a.system.passes);
}

/// The energy counts the ring in the hand (its weight, and its motion in
/// a lift), so a pass moves none of it but the kinetic energy of the
/// ring the hand stops: across the step of each pass, the energy changes
/// by no more than in the 100 steps before it (the penalty contacts'
/// energy moves by up to 2·10⁻⁶ J a step there at the first pass, 5·10⁻⁵
/// J at a later one), where leaving the ring in the hand out made it jump
/// by m g Δz, Δz the height between the ring let go and the ring taken
/// (3.6·10⁻⁴ J at the first pass, Δz = 19 mm).
#[test]
fn the_energy_does_not_jump_at_a_pass() {
    for lift in [0.0, 0.05] {
        let chain = lifting(0.15, 3, lift);
        let mut sys = build::build(&chain).unwrap();
        let mut e = sys.energy();
        let mut steps = std::collections::VecDeque::new();
        while sys.t < chain.t_end {
            let before = sys.passes.len();
            let z_from = sys.bodies[sys.held].x[2];
            sys.step().unwrap();
            let now = sys.energy();
            if sys.passes.len() == before {
                steps.push_back((now - e).abs());
                if steps.len() > 100 {
                    steps.pop_front();
                }
                e = now;
                continue;
            }
            let quiet = steps.iter().copied().fold(0.0, f64::max);
            let p = sys.passes[before];
            let at_pass = (now - e + p.kinetic).abs();
            let dz = z_from - sys.bodies[p.ring].x[2];
            let jump = sys.inertia.m * jacobs_ladder::rings::chain::G * dz.abs();
            assert!(
                at_pass <= quiet,
                "lift {lift}, {p:?}: at the pass {at_pass} J, the steps before up to {quiet} J"
            );
            if before == 0 {
                assert!(10.0 * quiet < jump, "m g dz {jump} J seen: {quiet} J");
            }
            e = now;
        }
        assert_eq!(sys.passes.len(), 3);
    }
}

/// A scene file asks for the lifting hand (its data file records the
/// key); a negative or NaN lift, a lift longer than the period, or a lift
/// without the alternating hand (a key of `[rings]` it is not) are one
/// line on stderr and exit 2.
#[test]
fn the_lift_is_a_key_and_a_bad_value_is_refused() {
    let json = rendered_data(
        "rings-lift-good",
        "alternate = { start = 0.1, period = 0.1, count = 2, lift = 0.05 }",
    );
    assert_eq!(json["scene"]["rings"]["alternate"]["lift"], 0.05);
    let dir = TempDir::new("rings-lift-bad");
    for (what, body, needle) in [
        (
            "negative",
            "alternate = { lift = -0.1 }",
            "rings: alternate.lift must be seconds from 0 to 60, got -0.1",
        ),
        (
            "nan",
            "alternate = { lift = nan }",
            "rings: alternate.lift must be seconds from 0 to 60, got NaN",
        ),
        (
            "longer than the period",
            "alternate = { period = 0.3, lift = 0.31 }",
            "rings: alternate.lift must be at most alternate.period (0.3 s), got 0.31",
        ),
        ("without alternate", "lift = 0.1", "lift"),
    ] {
        let out = render(&dir, body);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{what}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{what}: {err}");
        assert!(err.contains(needle), "{what}: {err}");
    }
}
