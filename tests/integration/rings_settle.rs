//! The leaning start of the ring chain (docs/rings.md, "The leaning
//! start"; `src/rings/settle.rs`): the chain let settle from a leaning
//! guess ends at rest, the lean −θ settles to the image of +θ, the
//! linking guard holds through it, and a bad lean is refused. Each claim
//! is decided from the state of the simulation.

use crate::common::tempdir::TempDir;
use jacobs_ladder::rings::math::{self, M3};
use jacobs_ladder::rings::settle::{self, REST_SPEED};
use jacobs_ladder::rings::start::Leaning;
use jacobs_ladder::rings::system::System;
use jacobs_ladder::rings::{self, RingChain, guard};
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_ladder");

/// An 8-ring chain whose hand holds the top ring still: cheap (about
/// 14 000 steps of settle), and every claim in it.
fn small() -> RingChain {
    RingChain {
        n: 8,
        t_end: 0.1,
        turn: rings::Turn {
            angle: 0.0,
            ..Default::default()
        },
        ..Default::default()
    }
}

/// The fastest point of any ring but the held one, |v| + R|ω|, m/s.
fn fastest(sys: &System) -> f64 {
    (0..sys.n())
        .filter(|&k| k != sys.held)
        .map(|k| {
            let b = &sys.bodies[k];
            let w = b.omega(&b.q.matrix(), &sys.inertia);
            math::norm(b.v) + sys.chain.major_radius * math::norm(w)
        })
        .fold(0.0, f64::max)
}

/// The settle ends at rest: the speed it reports is below
/// [`REST_SPEED`], and the settled state, let go without the settle's
/// damping for 0.1 s (the hand still), stays at rest: no ring's fastest
/// point passes `AFTER` and none moves 1 mm (measured, 8-ring chain:
/// 18 mm/s at most, the penalty contacts' chatter, and 0.2 mm).
#[test]
fn the_settle_ends_at_rest() {
    const AFTER: f64 = 3.0 * REST_SPEED;
    let chain = small();
    let (mut sys, done) = settle::leaning(&chain, 30.0, 0.7).unwrap();
    assert!(done.speed < REST_SPEED, "{done:?}");
    assert!(done.time > 0.1 && done.steps > 0, "{done:?}");
    assert_eq!(fastest(&sys), 0.0, "the settled chain starts still");
    let start: Vec<_> = sys.bodies.iter().map(|b| b.x).collect();
    let mut worst: f64 = 0.0;
    while sys.t < 0.1 {
        sys.step().unwrap();
        worst = worst.max(fastest(&sys));
    }
    let moved = sys
        .bodies
        .iter()
        .zip(&start)
        .map(|(b, x)| math::norm(math::sub(b.x, *x)))
        .fold(0.0, f64::max);
    assert!(
        worst < AFTER,
        "a ring moved at {worst} m/s after the settle"
    );
    assert!(moved < 1e-3, "a ring moved by {moved} m after the settle");
}

/// Every pair is linked in the settled chain as the topology says,
/// decided pair by pair from the rings' centre circles, and the run from
/// it passes the linking guard.
#[test]
fn the_linking_guard_holds_through_the_settle() {
    let chain = RingChain {
        leaning: Some(Leaning::default()),
        ..small()
    };
    let run = rings::run(&chain, &[0.0]).unwrap();
    let sys = &run.system;
    let rots: Vec<M3> = sys.bodies.iter().map(|b| b.q.matrix()).collect();
    let links = chain.linked_pairs();
    for i in 0..sys.n() {
        for j in i + 1..sys.n() {
            let linked = guard::linked(&sys.circle(i, &rots[i]), &sys.circle(j, &rots[j]));
            assert_eq!(linked, links.contains(&[i, j]), "rings {i} and {j}");
        }
    }
    assert!(run.settled.is_some());
    assert!(run.stats.guard_checks > 0);
}

/// Rotation by half a turn about the vertical through the held ring:
/// (x, y, z) → (−x, −y, z).
fn half_turn(a: math::V3) -> math::V3 {
    [-a[0], -a[1], a[2]]
}

/// The lean −θ is the lean +θ turned half a turn about the vertical (the
/// rings' centres lie on it; each torus is its own image under a half
/// turn about a diameter, which flips its normal): so −θ settles to +θ's
/// state turned, centres (x, y, z) → (−x, −y, z) and normals
/// (n_x, n_y, n_z) → (n_x, n_y, −n_z). Not bit for bit (the half turn
/// is two mirrors, and the code is symmetric under x → −x alone): to
/// 1e-9 m and 1e-7 (measured 2.6e-12 m and 9.7e-10, 8-ring chain), and
/// at the same step.
#[test]
fn the_lean_minus_theta_settles_to_the_image_of_plus_theta() {
    let chain = small();
    let (a, da) = settle::leaning(&chain, 30.0, 0.7).unwrap();
    let (b, db) = settle::leaning(&chain, -30.0, 0.7).unwrap();
    assert_eq!(da.steps, db.steps);
    let na = rings::run::normals(&a.bodies);
    let nb = rings::run::normals(&b.bodies);
    for k in 0..a.n() {
        let dx = math::norm(math::sub(half_turn(a.bodies[k].x), b.bodies[k].x));
        let dn = math::norm(math::sub([na[k][0], na[k][1], -na[k][2]], nb[k]));
        assert!(dx < 1e-9 && dn < 1e-7, "ring {k}: {dx} m, {dn}");
    }
    let lean = na.iter().skip(1).map(|n| n[2].abs()).fold(0.0, f64::max);
    assert!(
        lean > 0.1,
        "a ring below the held one still leans: a test of a lean"
    );
}

/// A lean out of its range, or a guess that is not the topology, is one
/// line and exit 2.
#[test]
fn a_bad_lean_is_refused() {
    let dir = TempDir::new("rings-settle-bad");
    for (what, lean, needle) in [
        (
            "angle",
            "angle = 60.0",
            "leaning.angle must be degrees from -45 to 45",
        ),
        (
            "squeeze",
            "squeeze = 0.2",
            "leaning.squeeze must be a fraction",
        ),
        (
            "topology",
            "angle = 30.0, squeeze = 1.0",
            "is not the chain's topology",
        ),
        ("unknown key", "lean = 30.0", "lean"),
    ] {
        let text = format!(
            "name = \"lean\"\n[rings]\nn = 8\nleaning = {{ {lean} }}\n[output]\nkind = \"kymograph\"\n"
        );
        refused_in_one_line(&dir, &text, what, needle);
    }
}

/// `ladder render --check` on the scene `text` exits 2 with one line on
/// stderr that contains `needle`.
pub fn refused_in_one_line(dir: &TempDir, text: &str, what: &str, needle: &str) {
    let path = dir.file("bad.toml", text);
    let out = Command::new(BIN)
        .args(["render", &path, "--check", "--out"])
        .arg(dir.path())
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{what}: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{what}: {err}");
    assert!(err.contains(needle), "{what}: {err}");
    assert!(!err.contains("  "), "{what}: a run of spaces in \"{err}\"");
}
