//! Probe of the alternating hand (docs/rings.md, "Retrieving the top rings
//! alternately" and "Retrieving with a lifting hand"): steps the chain
//! with `alternate` (and its `lift`), the linking guard on, and prints
//! each pass of the hand (where the ring taken was, the chain's heights,
//! the energy and the hand's work, and which ring's top point was then
//! highest of the strand), the energy every 0.05 s (the ring in the hand
//! counted; `quiet` leaves it out), the flips, in each period between two
//! passes the longest run of a strand's rings flipping in order down it
//! and the helical waves, and a summary line.
//! `cargo run --release --example rings_alternate_probe -- n=30 t=3 period=0.3 count=9 lift=0.1 tapes`
use jacobs_ladder::rings::alternate::Alternate;
use jacobs_ladder::rings::body::Body;
use jacobs_ladder::rings::math;
use jacobs_ladder::rings::observe::{self, Flip, FlipTracker};
use jacobs_ladder::rings::system::{Pass, System};
use jacobs_ladder::rings::{self, RingChain};

fn main() {
    let (chain, quiet) = parse();
    let cpu = std::time::Instant::now();
    let (mut sys, _) = rings::run::start(&chain).unwrap_or_else(|e| panic!("{e}"));
    let mut tracker = FlipTracker::new(sys.n());
    tracker.observe(sys.t, &rings::run::normals(&sys.bodies));
    let steps = (chain.t_end / sys.dt).ceil() as u64;
    let every = (0.05 / sys.dt).round() as u64;
    let mut work = HandWork::new(&sys);
    let mut at_passes = Vec::new();
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
        let pass = (sys.passes.len() > passes).then(|| sys.passes[passes]);
        work.step(&sys, pass);
        if let Some(p) = pass {
            at_passes.push((sys.energy(), work.total));
            print_pass(&chain, &sys, &p, &work);
        }
        if !quiet && (k % every == 0 || k == steps) {
            print_state(&chain, &sys, &work);
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
    let mut longest = 0;
    let mut waves = 0;
    for (i, p) in sys.passes.iter().enumerate() {
        let end = sys.passes.get(i + 1).map_or(f64::INFINITY, |q| q.t);
        let (run, w) = window(&chain, &tracker.flips, p, end);
        longest = longest.max(run);
        waves += w;
    }
    let after = chain.alternate.map_or(0.0, |a| a.start);
    for w in observe::waves(&tracker.flips, sys.n(), chain.held, after) {
        println!(
            "wave (whole run) strand {} rings {:?} step {:.1} speed {:.1}",
            w.strand, w.rings, w.step, w.speed
        );
    }
    summary(&sys, &tracker.flips, &at_passes, &work, (longest, waves));
}

/// The work the hand has done on the chain, J: on the ring it holds,
/// whose motion it prescribes, its power is (m a − F)·v with F the ring's
/// weight, contacts and tapes, so its work over a step is the change of
/// the ring's kinetic energy less F·v dt (trapezoid over the step's two
/// ends); at a pass it takes away the kinetic energy of the ring it stops.
/// With the ring in the hand counted in `System::energy`, the energy of
/// the whole changes by this work less what the contacts dissipate.
struct HandWork {
    total: f64,
    /// The kinetic energy the hand took by stopping rings, J.
    took: f64,
    power: f64,
    kinetic: f64,
}

impl HandWork {
    fn new(sys: &System) -> HandWork {
        let (power, kinetic) = HandWork::held(sys);
        HandWork {
            total: 0.0,
            took: 0.0,
            power,
            kinetic,
        }
    }

    /// F·v and ½ m v² of the ring in the hand now.
    fn held(sys: &System) -> (f64, f64) {
        let v = sys.bodies[sys.held].v;
        let power = math::dot(sys.held_force(), v);
        (power, 0.5 * sys.inertia.m * math::dot(v, v))
    }

    /// After a step (with the pass it made, if any).
    fn step(&mut self, sys: &System, pass: Option<Pass>) {
        let (power, kinetic) = HandWork::held(sys);
        self.total += kinetic - self.kinetic - 0.5 * sys.dt * (power + self.power);
        if let Some(p) = pass {
            self.total -= p.kinetic;
            self.took += p.kinetic;
        }
        (self.power, self.kinetic) = (power, kinetic);
    }
}

/// One line at a pass: the rings let go and taken, where the ring taken
/// was (the grip's centre; with a lift, it is then carried to the hand),
/// the bottom ring's height and the rings' mean height, the energy and
/// the hand's work so far, and which ring's top point was highest.
fn print_pass(chain: &RingChain, sys: &System, p: &Pass, work: &HandWork) {
    let top = highest_top(chain, &sys.bodies, p.ring % 2);
    let mean = sys.bodies.iter().map(|b| b.x[2]).sum::<f64>() / sys.n() as f64;
    println!(
        "pass t {:.4} let go {} took {} at z {:.1} mm (kinetic {:.2e} J), bottom z {:.1} mm, \
         mean z {:.1} mm, E {:.5} J, hand work {:.5} J; highest top point of the strand: ring \
         {top}",
        p.t,
        p.from,
        p.ring,
        sys.bodies[p.ring].x[2] * 1e3,
        p.kinetic,
        sys.bodies[chain.n - 1].x[2] * 1e3,
        mean * 1e3,
        sys.energy(),
        work.total,
    );
}

/// The run in one line: passes, flips and the rings that flipped, the
/// longest run in order down a strand within a period, the helical waves
/// (within periods), the grip heights' trend, the energy and the hand's
/// work per pass from the first pass to the end, and the energy the
/// contacts dissipated per pass (the work less the energy's change).
fn summary(
    sys: &System,
    flips: &[Flip],
    at_passes: &[(f64, f64)],
    work: &HandWork,
    (longest, waves): (usize, usize),
) {
    let mut rings: Vec<usize> = flips.iter().map(|f| f.ring).collect();
    rings.sort_unstable();
    rings.dedup();
    let taken: Vec<String> = sys.passes.iter().map(|p| format!("{}", p.ring)).collect();
    let n = sys.passes.len().max(1) as f64;
    let (e0, w0) = at_passes.first().copied().unwrap_or((sys.energy(), 0.0));
    let de = (sys.energy() - e0) / n;
    let dw = (work.total - w0) / n;
    println!(
        "summary: passes {} (rings taken {}), flips {} (rings {rings:?}), longest run in order \
         down {longest}, waves in periods {waves}, bottom z {:.1} mm, E {:.5} -> {:.5} J, per \
         pass: energy {:+.2} mJ, hand work {:+.2} mJ, dissipated {:.2} mJ (hand took {:.2} mJ \
         by stopping rings)",
        sys.passes.len(),
        taken.join(","),
        flips.len(),
        sys.bodies[sys.n() - 1].x[2] * 1e3,
        e0,
        sys.energy(),
        de * 1e3,
        dw * 1e3,
        (dw - de) * 1e3,
        work.took * 1e3
    );
}

/// The chain asked for, and whether to leave out the state every 0.05 s.
fn parse() -> (RingChain, bool) {
    let mut chain = RingChain::default();
    let mut a = Alternate::default();
    let (mut tapes, mut quiet) = (false, false);
    for arg in std::env::args().skip(1) {
        let (k, v) = arg.split_once('=').unwrap_or((arg.as_str(), ""));
        let num = || v.parse::<f64>().unwrap_or_else(|e| panic!("{arg}: {e}"));
        match k {
            "n" => chain.n = num() as usize,
            "t" => chain.t_end = num(),
            "start" => a.start = num(),
            "period" => a.period = num(),
            "count" => a.count = num() as usize,
            "lift" => a.lift = num(),
            "quiet" => quiet = true,
            "tapes" => tapes = true,
            "mirror" => chain.mirror = true,
            _ => panic!("unknown argument {arg}"),
        }
    }
    if tapes {
        chain.tapes = chain.odd_strand_tapes();
    }
    chain.alternate = Some(a);
    chain.validated().unwrap_or_else(|e| panic!("{e}"));
    (chain, quiet)
}

/// The energy (the ring in the hand counted), with the hand's work so
/// far and the kinetic energy it took by stopping rings, the held ring's
/// height and the bottom ring's, and each ring's n_z.
fn print_state(chain: &RingChain, sys: &System, work: &HandWork) {
    let nz: Vec<String> = rings::run::normals(&sys.bodies)
        .iter()
        .map(|n| format!("{:+.1}", n[2]))
        .collect();
    println!(
        "t {:.2} E {:.5} J (hand work {:.5} J, took {:.2e} J) held {} z {:.1} mm, bottom z \
         {:.1} mm\n  nz {}",
        sys.t,
        sys.energy(),
        work.total,
        work.took,
        sys.held,
        sys.bodies[sys.held].x[2] * 1e3,
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
/// and the helical waves by the rule (docs/rings.md); returns the longer
/// run and the number of waves.
fn window(chain: &RingChain, flips: &[Flip], p: &Pass, end: f64) -> (usize, usize) {
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
    (runs[0].max(runs[1]), waves.len())
}
