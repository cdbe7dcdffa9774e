//! The tumbling rings (docs/rings.md, "The tumbling rings";
//! `topology = "tumbling"`): their links are the magicians' chain, their
//! guess realises them and settles with every pair linked, the released
//! top ring sends the even strand down past the odd one and the run is
//! mirrored bit for bit; bad input is refused. Each claim is decided
//! from the state of the simulation.

use crate::common::tempdir::TempDir;
use crate::rings::mirror_images;
use crate::rings_settle::refused_in_one_line;
use jacobs_ladder::rings::{self, RingChain, Topology, guard};

/// A 12-ring tumbling chain released at 0.1 s, friction 0.2 (the top two
/// even rings pass the odd ones: docs/rings.md).
fn small() -> RingChain {
    RingChain {
        topology: Some(Topology::Tumbling),
        friction: 0.2,
        release: true,
        t_end: 1.2,
        ..crate::rings::small()
    }
}

/// Ring k with k + 2 and ring 2j with 2j + 1: each strand a simple chain,
/// a rung every other ring; the top pair {1, 2} below ring 0 has one ring
/// (2) threading both rings of the pair below it {3, 4} and one (1)
/// threading only ring 3, as the magicians' chain has.
#[test]
fn the_links_are_the_tumbling_rings() {
    let links = RingChain::tumbling_links(8);
    assert_eq!(
        links,
        [
            [0, 1],
            [0, 2],
            [1, 3],
            [2, 3],
            [2, 4],
            [3, 5],
            [4, 5],
            [4, 6],
            [5, 7],
            [6, 7]
        ]
    );
    let chain = RingChain {
        n: 8,
        topology: Some(Topology::Tumbling),
        ..Default::default()
    };
    assert!(chain.is_tumbling());
    assert!(!RingChain::default().is_tumbling());
    let below = |k: usize| -> Vec<usize> {
        links
            .iter()
            .filter(|p| p[0] == k && (p[1] == 3 || p[1] == 4))
            .map(|p| p[1])
            .collect()
    };
    assert_eq!(below(2), [3, 4]);
    assert_eq!(below(1), [3]);
}

/// The guess realises the topology; settled, every pair is linked or
/// apart as the links say, and the rings hang in pairs: odd ring 2j + 1
/// beside even ring 2j + 2, within a sixth of the level spacing.
#[test]
fn the_tumbling_chain_settles_in_pairs() {
    let chain = RingChain {
        release: false,
        turn: rings::Turn {
            angle: 0.0,
            ..Default::default()
        },
        ..small()
    };
    let (sys, settled) = rings::run::start(&chain).unwrap();
    let settled = settled.expect("the tumbling chain settles");
    assert!(settled.time >= rings::settle::MIN_TIME, "{settled:?}");
    let rots: Vec<_> = sys.bodies.iter().map(|b| b.q.matrix()).collect();
    for i in 0..sys.n() {
        for j in i + 1..sys.n() {
            let linked = guard::linked(&sys.circle(i, &rots[i]), &sys.circle(j, &rots[j]));
            assert_eq!(linked, sys.is_linked(i, j), "rings {i} and {j}");
        }
    }
    let z = |k: usize| sys.bodies[k].x[2];
    let level = (z(0) - z(10)) / 5.0;
    assert!(level > 0.015, "a level of {level} m");
    for j in 0..5 {
        let gap = (z(2 * j + 1) - z(2 * j + 2)).abs();
        assert!(
            gap < level / 6.0,
            "rings {} and {}: {gap} m",
            2 * j + 1,
            2 * j + 2
        );
    }
}

/// Released, ring 0 falls past ring 1 (the hand's) to hang a level below
/// it; the even strand goes down, its top two rings by two levels (past
/// their rung partners), the rest by about one (the stall: ring 4 rests
/// on ring 2's top); the odd strand, held, stays within a fifth of a
/// level. No ring of the strand passes the flip criterion: the even
/// rings tip (ring 2 to |n_z| > 0.9) and come back.
#[test]
fn the_released_top_ring_sends_the_even_strand_down_and_it_stalls() {
    let chain = small();
    let times = rings::run::even_times(chain.t_end, 25);
    let run = rings::run(&chain, &times).unwrap();
    let (first, last) = (&run.samples[0], &run.samples[run.samples.len() - 1]);
    let z0 = |k: usize| first.rings[k].x[2];
    let z1 = |k: usize| last.rings[k].x[2];
    let level = (z0(1) - z0(11)) / 5.0;
    let drop = |k: usize| (z0(k) - z1(k)) / level;
    assert!((z1(1) - z1(0)) / level > 0.8, "ring 0 hangs below ring 1");
    for k in [0, 2] {
        assert!(drop(k) > 1.7, "ring {k} drops {} levels", drop(k));
    }
    for k in [4, 6, 8, 10] {
        assert!(
            (0.6..1.2).contains(&drop(k)),
            "ring {k} drops {} levels",
            drop(k)
        );
    }
    for k in (1..12).step_by(2) {
        assert!(drop(k).abs() < 0.2, "odd ring {k} moves {} levels", drop(k));
    }
    let tipped = run
        .samples
        .iter()
        .map(|s| s.quat(2).matrix()[2][2].abs())
        .fold(0.0, f64::max);
    assert!(tipped > 0.9, "ring 2 tips to |n_z| = {tipped}");
    assert!(
        !run.flips.iter().any(|f| f.ring == 0 || f.ring == 2),
        "a tumble is no flip by n_z's sign: {:?}",
        run.flips
    );
    assert!(run.stats.max_overlap < 0.5);
}

/// The mirrored tumbling chain, released, is the mirror image bit for bit.
#[test]
fn the_mirrored_tumbling_chain_is_the_mirror_image_bit_for_bit() {
    mirror_images(RingChain {
        n: 8,
        t_end: 0.5,
        ..small()
    });
}

/// A topology the program does not know, links beside a topology, the
/// tumbling rings with a leaning start or fewer than 4 rings: one line,
/// exit 2.
#[test]
fn bad_topologies_are_refused_in_one_line() {
    let dir = TempDir::new("rings-tumbling");
    for (what, keys, needle) in [
        (
            "unknown",
            "topology = \"triple\"",
            "must be \"double\" or \"tumbling\", got \"triple\"",
        ),
        (
            "a number",
            "topology = 5",
            "must be \"double\" or \"tumbling\", got another kind of value",
        ),
        (
            "both",
            "topology = \"tumbling\"\nlinks = [[0, 1], [0, 2], [1, 3], [2, 3]]",
            "give one",
        ),
        (
            "leaning",
            "topology = \"tumbling\"\nleaning = { angle = 30.0, squeeze = 0.7 }",
            "leave leaning out",
        ),
        ("few", "topology = \"tumbling\"\nn = 3", "at least 4 rings"),
    ] {
        let text = format!("name = \"t\"\n[rings]\n{keys}\n[output]\nkind = \"kymograph\"\n");
        refused_in_one_line(&dir, &text, what, needle);
    }
}
