//! Probe of the ring chain: runs a chain and prints flips, waves, energy.
use jacobs_ladder::rings::{self, RingChain};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let mut chain = RingChain::default();
    for a in &args[1..] {
        let (k, v) = a.split_once('=').expect("key=value");
        match k {
            "n" => chain.n = v.parse().unwrap(),
            "t" => chain.t_end = v.parse().unwrap(),
            "dt" => chain.dt = v.parse().unwrap(),
            "tapes" => {
                chain.tapes = (0..chain.n)
                    .filter(|k| k % 2 == 1 && k + 2 < chain.n)
                    .map(|k| [k, k + 2])
                    .collect()
            }
            "mirror" => chain.mirror = true,
            "turn" => chain.turn.duration = v.parse().unwrap(),
            "az" => chain.turn.azimuth = v.parse().unwrap(),
            _ => panic!("{k}"),
        }
    }
    let times = rings::run::even_times(chain.t_end, 31);
    let t0 = Instant::now();
    let run = rings::run(&chain, &times);
    let el = t0.elapsed().as_secs_f64();
    let run = match run {
        Ok(r) => r,
        Err(e) => {
            println!("error after {el:.1} s: {e}");
            return;
        }
    };
    println!(
        "dt {:.3e} s, steps {}, {:.1} us/step, pairs/step {:.1}, {:.2} us/pair, guard checks {}, max overlap {:.3} r",
        run.dt,
        run.stats.steps,
        el / run.stats.steps as f64 * 1e6,
        run.stats.pair_evaluations as f64 / run.stats.steps as f64,
        el / run.stats.pair_evaluations.max(1) as f64 * 1e6,
        run.stats.guard_checks,
        run.stats.max_overlap
    );
    for s in &run.samples {
        let nz: Vec<String> = (0..chain.n)
            .map(|k| {
                let q = s.quat(k).matrix();
                format!("{:+.1}", q[2][2])
            })
            .collect();
        println!(
            "t {:.2} E {:.6} bottom z {:.4} nz {}",
            s.t,
            s.energy,
            s.rings[chain.n - 1].x[2],
            nz.join(" ")
        );
    }
    for f in &run.flips {
        println!("flip ring {} t {:.3} phi {:.0}", f.ring, f.t, f.phi);
    }
    for w in &run.waves {
        println!(
            "wave strand {} rings {:?} step {:.1} speed {:.1} pitch {:.1}",
            w.strand, w.rings, w.step, w.speed, w.pitch
        );
    }
}
