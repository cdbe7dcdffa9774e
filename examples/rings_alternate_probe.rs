//! Probe of the alternating hand (docs/rings.md, "Retrieving the top rings
//! alternately"): steps the chain with `alternate`, the linking guard on,
//! and prints each pass of the hand (and which ring's top point was then
//! highest of the strand), the energy every 0.05 s (the held ring's height
//! counted), the flips, and in each period between two passes the longest
//! run of a strand's rings flipping in order down it and the helical waves.
//! `cargo run --release --example rings_alternate_probe -- n=30 t=3 period=0.3 count=9 tapes`
use jacobs_ladder::rings::alternate::Alternate;
use jacobs_ladder::rings::body::Body;
use jacobs_ladder::rings::chain::G;
use jacobs_ladder::rings::observe::{self, Flip, FlipTracker};
use jacobs_ladder::rings::system::{Pass, System};
use jacobs_ladder::rings::{self, RingChain};

fn main() {
    let chain = parse();
    let cpu = std::time::Instant::now();
    let (mut sys, _) = rings::run::start(&chain).unwrap_or_else(|e| panic!("{e}"));
    let mut tracker = FlipTracker::new(sys.n());
    tracker.observe(sys.t, &rings::run::normals(&sys.bodies));
    let steps = (chain.t_end / sys.dt).ceil() as u64;
    let every = (0.05 / sys.dt).round() as u64;
    let mut hand_took = 0.0;
    for k in 1..=steps {
        let passes = sys.passes.len();
        let stepped = sys.step().and_then(|()| {
            if k % chain.guard_every as u64 == 0 || k == steps {
                sys.check_links()
            } else {
                Ok(())
            }
        });
        if let Err(e) = stepped {
            println!("failed: {e}");
            std::process::exit(1);
        }
        tracker.observe(sys.t, &rings::run::normals(&sys.bodies));
        if sys.passes.len() > passes {
            let p = sys.passes[passes];
            hand_took += p.kinetic;
            let top = highest_top(&chain, &sys.bodies, p.ring % 2);
            println!(
                "pass t {:.4} let go {} took {} at z {:.1} mm (kinetic {:.2e} J); highest top \
                 point of the strand: ring {top}",
                p.t,
                p.from,
                p.ring,
                sys.bodies[p.ring].x[2] * 1e3,
                p.kinetic
            );
        }
        if k % every == 0 || k == steps {
            print_state(&chain, &sys, hand_took);
        }
    }
    println!(
        "dt {:.3e} s, steps {}, guard pair checks {} (all passed), max overlap {:.3} r, \
         cpu {:.1} s",
        sys.dt,
        sys.stats.steps,
        sys.stats.guard_checks,
        sys.stats.max_overlap,
        cpu.elapsed().as_secs_f64()
    );
    for f in &tracker.flips {
        println!("flip ring {} t {:.3} phi {:.0}", f.ring, f.t, f.phi);
    }
    for (i, p) in sys.passes.iter().enumerate() {
        let end = sys.passes.get(i + 1).map_or(f64::INFINITY, |q| q.t);
        window(&chain, &tracker.flips, p, end);
    }
    let after = chain.alternate.map_or(0.0, |a| a.start);
    for w in observe::waves(&tracker.flips, sys.n(), chain.held, after) {
        println!(
            "wave (whole run) strand {} rings {:?} step {:.1} speed {:.1}",
            w.strand, w.rings, w.step, w.speed
        );
    }
}

fn parse() -> RingChain {
    let mut chain = RingChain::default();
    let mut a = Alternate::default();
    let mut tapes = false;
    for arg in std::env::args().skip(1) {
        let (k, v) = arg.split_once('=').unwrap_or((arg.as_str(), ""));
        let num = || v.parse::<f64>().unwrap_or_else(|e| panic!("{arg}: {e}"));
        match k {
            "n" => chain.n = num() as usize,
            "t" => chain.t_end = num(),
            "start" => a.start = num(),
            "period" => a.period = num(),
            "count" => a.count = num() as usize,
            "tapes" => tapes = true,
            "mirror" => chain.mirror = true,
            _ => panic!("unknown argument {arg}"),
        }
    }
    if tapes {
        chain.tapes = chain.odd_strand_tapes();
    }
    chain.alternate = Some(a);
    chain
}

/// The energy, the held ring's weight counted (it is at rest in the
/// hand), with the kinetic energy the hand has taken away so far, the
/// held ring's height and the bottom ring's, and each ring's n_z.
fn print_state(chain: &RingChain, sys: &System, hand_took: f64) {
    let z = sys.bodies[sys.held].x[2];
    let e = sys.energy() + chain.mass() * G * z;
    let nz: Vec<String> = rings::run::normals(&sys.bodies)
        .iter()
        .map(|n| format!("{:+.1}", n[2]))
        .collect();
    println!(
        "t {:.2} E {:.5} J (hand took {:.2e} J) held {} z {:.1} mm, bottom z {:.1} mm\n  nz {}",
        sys.t,
        e,
        hand_took,
        sys.held,
        z * 1e3,
        sys.bodies[chain.n - 1].x[2] * 1e3,
        nz.join(" ")
    );
}

/// Of `strand`, the ring whose top point (centre + R·√(1 − n_z²)) is
/// highest: the other rule a hand reaching from above might follow.
fn highest_top(chain: &RingChain, bodies: &[Body], strand: usize) -> usize {
    let normals = rings::run::normals(bodies);
    let top = |k: usize| {
        let nz = normals[k][2];
        bodies[k].x[2] + chain.major_radius * (1.0 - nz * nz).max(0.0).sqrt()
    };
    let mut best = strand;
    for k in (strand..chain.n).step_by(2) {
        if top(k) > top(best) {
            best = k;
        }
    }
    best
}

/// The period after pass `p`, to `end`: per strand, the longest run of
/// consecutive rings whose first flips come in order down the strand,
/// and the helical waves by the rule (docs/rings.md).
fn window(chain: &RingChain, flips: &[Flip], p: &Pass, end: f64) {
    let inside: Vec<Flip> = flips
        .iter()
        .filter(|f| f.t >= p.t && f.t < end)
        .copied()
        .collect();
    let mut first: Vec<Option<f64>> = vec![None; chain.n];
    for f in &inside {
        first[f.ring].get_or_insert(f.t);
    }
    let mut runs = [0usize; 2];
    for (strand, best) in runs.iter_mut().enumerate() {
        let mut len = 0;
        let mut last = f64::NEG_INFINITY;
        for k in (strand..chain.n).step_by(2) {
            match first[k] {
                Some(t) if t > last && len > 0 => len += 1,
                Some(_) => len = 1,
                None => len = 0,
            }
            last = first[k].unwrap_or(f64::NEG_INFINITY);
            *best = (*best).max(len);
        }
    }
    let waves = observe::waves(&inside, chain.n, p.ring, p.t);
    let mut order: Vec<(f64, usize)> = first
        .iter()
        .enumerate()
        .filter_map(|(k, t)| t.map(|t| (t, k)))
        .collect();
    order.sort_by(|a, b| a.0.total_cmp(&b.0));
    let order: Vec<usize> = order.iter().map(|(_, k)| *k).collect();
    println!(
        "period from {:.3} s (held {}): {} flips (first flips in order: rings {order:?}), \
         longest ordered run even {} odd {}, waves {}",
        p.t,
        p.ring,
        inside.len(),
        runs[0],
        runs[1],
        waves
            .iter()
            .map(|w| format!(
                "strand {} rings {:?} step {:.0} speed {:.1}",
                w.strand, w.rings, w.step, w.speed
            ))
            .collect::<Vec<_>>()
            .join("; ")
    );
}
