//! Probe of a settled start (docs/rings.md, "The leaning start" and "The
//! tumbling rings"): settles the chain from a leaning guess (the double
//! chain) or from the tumbling rings' guess (`tumbling`), then turns or
//! releases the top ring (or lifts the other strand's, `lift=`) and
//! prints each ring's n_z, azimuth and height, the flips and the waves.
//! `EVERY=0.02` prints every 0.02 s; `DBGEND=1` lists the touches at the
//! end; `KICK=5 SEED=1` spins every free ring at random (up to 5 rad/s a
//! component) after the settle; `TUMBLE=1.0,4,40` spins ring 4 at 1.0 s
//! about the horizontal axis in its plane at 40 rad/s.
//! `cargo run --release --example rings_wave_probe -- n=12 t=2 lean=30 squeeze=0.8 tapes release`
//! `cargo run --release --example rings_wave_probe -- tumbling n=30 t=3 start=0.1 release mu=0.2 [tapes]`
use jacobs_ladder::rings::observe::{self, FlipTracker};
use jacobs_ladder::rings::{self, RingChain, settle};

fn main() {
    let mut chain = RingChain::default();
    let (mut lean, mut squeeze, mut tapes) = (30.0, 0.8, false);
    for a in std::env::args().skip(1) {
        let (k, v) = a.split_once('=').unwrap_or((a.as_str(), ""));
        let num = || v.parse::<f64>().unwrap_or_else(|e| panic!("{a}: {e}"));
        match k {
            "n" => chain.n = num() as usize,
            "t" => chain.t_end = num(),
            "lean" => lean = num(),
            "squeeze" => squeeze = num(),
            "tumbling" => chain.topology = Some(rings::Topology::Tumbling),
            "tapes" => tapes = true,
            "release" => chain.release = true,
            "lift" => {
                chain.alternate = Some(rings::alternate::Alternate {
                    start: chain.turn.start,
                    period: 10.0,
                    count: 1,
                    lift: num(),
                })
            }
            "mirror" => chain.mirror = true,
            "angle" => chain.turn.angle = num(),
            "az" => chain.turn.azimuth = num(),
            "start" => chain.turn.start = num(),
            "turn" => chain.turn.duration = num(),
            "mu" => chain.friction = num(),
            "e" => chain.restitution = num(),
            "R" => chain.major_radius = num(),
            "r" => chain.tube_radius = num(),
            _ => panic!("unknown argument {a}"),
        }
    }
    if tapes {
        chain.tapes = chain.odd_strand_tapes();
    }
    let t0 = std::time::Instant::now();
    let started = if chain.is_tumbling() {
        rings::run::start(&chain).map(|(s, d)| (s, d.expect("the tumbling rings settle")))
    } else {
        settle::leaning(&chain, lean, squeeze)
    };
    let (mut sys, done) = match started {
        Ok(x) => x,
        Err(e) => {
            println!("settle failed: {e}");
            return;
        }
    };
    println!(
        "settled in {:.3} s ({} steps), speed {:.2e}, cpu {:.1} s",
        done.time,
        done.steps,
        done.speed,
        t0.elapsed().as_secs_f64()
    );
    let show = |sys: &rings::system::System, label: &str| {
        let n = rings::run::normals(&sys.bodies);
        let nz: Vec<String> = n.iter().map(|n| format!("{:+.2}", n[2])).collect();
        let az: Vec<String> = n
            .iter()
            .map(|n| format!("{:.0}", n[1].atan2(n[0]).to_degrees()))
            .collect();
        let z: Vec<String> = sys
            .bodies
            .iter()
            .map(|b| format!("{:.1}", b.x[2] * 1e3))
            .collect();
        println!(
            "{label} t {:.2} E {:.6}\n  nz {}\n  az {}\n  z(mm) {}",
            sys.t,
            sys.energy(),
            nz.join(" "),
            az.join(" "),
            z.join(" ")
        );
    };
    show(&sys, "rest");
    if let Ok(v) = std::env::var("KICK") {
        // KICK=w (SEED=s): a random spin of every free ring, each
        // component up to w rad/s (a seeded linear congruential generator).
        let w: f64 = v.parse().unwrap();
        let mut seed: u64 = std::env::var("SEED")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(1);
        let mut rnd = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        };
        let i_d = sys.inertia.i_d;
        for k in 0..sys.n() {
            if k != sys.held {
                sys.bodies[k].l = [w * rnd() * i_d, w * rnd() * i_d, w * rnd() * i_d];
            }
        }
    }
    if std::env::var("DBG").is_ok() {
        let rots: Vec<_> = sys.bodies.iter().map(|b| b.q.matrix()).collect();
        for p in &sys.pins {
            let (a, b) = sys.pin_points(p, &rots);
            println!("pin {} {} a {:?} b {:?}", p.i, p.j, a, b);
        }
        for (i, j, t) in sys.touches(&rots) {
            println!("touch {i} {j} d/r {:.3}", t.d / chain.tube_radius);
        }
    }
    let mut tracker = FlipTracker::new(sys.n());
    tracker.observe(sys.t, &rings::run::normals(&sys.bodies));
    let steps = (chain.t_end / sys.dt).ceil() as u64;
    let every = (std::env::var("EVERY")
        .ok()
        .and_then(|v| v.parse::<f64>().ok())
        .unwrap_or(0.25)
        / sys.dt)
        .round() as u64;
    // TUMBLE="t,ring,omega" spins one ring at time t about the horizontal
    // axis in its plane (a tumble started by hand).
    let tumble: Option<(f64, usize, f64)> = std::env::var("TUMBLE").ok().map(|v| {
        let p: Vec<f64> = v.split(',').map(|x| x.parse().unwrap()).collect();
        (p[0], p[1] as usize, p[2])
    });
    let mut tumbled = false;
    for k in 1..=steps {
        if let Some((t, ring, w)) = tumble
            && !tumbled
            && sys.t >= t
        {
            tumbled = true;
            println!("tumble ring {ring} at {:.3} s", sys.t);
            let n = rings::run::normals(&sys.bodies)[ring];
            let a = [n[1], -n[0], 0.0];
            let len = (a[0] * a[0] + a[1] * a[1]).sqrt();
            let i_d = sys.inertia.i_d;
            sys.bodies[ring].l = [w * i_d * a[0] / len, w * i_d * a[1] / len, 0.0];
        }
        if let Err(e) = sys.step() {
            println!("failed: {e}");
            break;
        }
        tracker.observe(sys.t, &rings::run::normals(&sys.bodies));
        if k.is_multiple_of(20)
            && let Err(e) = sys.check_links()
        {
            println!("failed: {e}");
            break;
        }
        if k % every == 0 {
            show(&sys, "at");
        }
    }
    if std::env::var("DBGEND").is_ok() {
        let rots: Vec<_> = sys.bodies.iter().map(|b| b.q.matrix()).collect();
        for (i, j, t) in sys.touches(&rots) {
            let c = |k: usize| sys.bodies[k].x;
            println!(
                "touch {i} {j} d/r {:.3} at z {:.1} mm (centres {:.1} {:.1}) point rel i ({:.1},{:.1},{:.1}) j ({:.1},{:.1},{:.1})",
                t.d / chain.tube_radius,
                t.p[2] * 1e3,
                c(i)[2] * 1e3,
                c(j)[2] * 1e3,
                (t.p[0] - c(i)[0]) * 1e3,
                (t.p[1] - c(i)[1]) * 1e3,
                (t.p[2] - c(i)[2]) * 1e3,
                (t.q[0] - c(j)[0]) * 1e3,
                (t.q[1] - c(j)[1]) * 1e3,
                (t.q[2] - c(j)[2]) * 1e3
            );
        }
        let n = rings::run::normals(&sys.bodies);
        for (k, b) in sys.bodies.iter().enumerate() {
            println!(
                "ring {k} x ({:.1},{:.1},{:.1}) n ({:+.2},{:+.2},{:+.2})",
                b.x[0] * 1e3,
                b.x[1] * 1e3,
                b.x[2] * 1e3,
                n[k][0],
                n[k][1],
                n[k][2]
            );
        }
    }
    for f in &tracker.flips {
        println!("flip ring {} t {:.3} phi {:.0}", f.ring, f.t, f.phi);
    }
    for w in observe::waves(&tracker.flips, sys.n(), chain.held, chain.turn.start) {
        println!(
            "wave strand {} rings {:?} step {:.1} speed {:.1} pitch {:.1}",
            w.strand, w.rings, w.step, w.speed, w.pitch
        );
    }
    println!(
        "max overlap {:.3} r, cpu {:.1} s",
        sys.stats.max_overlap,
        t0.elapsed().as_secs_f64()
    );
}
