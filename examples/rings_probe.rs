//! Probe of the ring chain: runs a chain and prints flips, waves, energy.
//! `cargo run --release --example rings_probe -- n=30 t=2 tapes release`;
//! its output may be cut short (`| head`): a closed pipe ends it quietly.
use jacobs_ladder::rings::{self, RingChain};
use std::io::Write;
use std::time::Instant;

fn main() {
    let chain = match parse(std::env::args().skip(1)) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("rings_probe: {e}");
            std::process::exit(2);
        }
    };
    let times = rings::run::even_times(chain.t_end, 31);
    let t0 = Instant::now();
    let run = rings::run(&chain, &times);
    let el = t0.elapsed().as_secs_f64();
    let mut out = std::io::stdout().lock();
    let written = match run {
        Ok(r) => report(&mut out, &chain, &r, el),
        Err(e) => writeln!(out, "error after {el:.1} s: {e}"),
    };
    // A reader that stopped early (a broken pipe) is no failure of the probe.
    match written.and_then(|()| out.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
            eprintln!("rings_probe: {e}");
            std::process::exit(1);
        }
        _ => {}
    }
}

fn parse(args: impl Iterator<Item = String>) -> Result<RingChain, String> {
    let mut chain = RingChain::default();
    let mut tapes = false;
    for a in args {
        let (k, v) = a.split_once('=').unwrap_or((a.as_str(), ""));
        let num = |v: &str| v.parse::<f64>().map_err(|e| format!("{k}={v}: {e}"));
        match k {
            "n" => chain.n = num(v)? as usize,
            "t" => chain.t_end = num(v)?,
            "dt" => chain.dt = num(v)?,
            "tapes" => tapes = true,
            "mirror" => chain.mirror = true,
            "release" => chain.release = true,
            "start" => chain.turn.start = num(v)?,
            "turn" => chain.turn.duration = num(v)?,
            "az" => chain.turn.azimuth = num(v)?,
            "slip" => chain.slip_speed = num(v)?,
            "mu" => chain.friction = num(v)?,
            "e" => chain.restitution = num(v)?,
            "overlap" => chain.overlap = num(v)?,
            _ => return Err(format!("unknown argument {a}")),
        }
    }
    if tapes {
        chain.tapes = (0..chain.n)
            .filter(|k| k % 2 == 1 && k + 2 < chain.n)
            .map(|k| [k, k + 2])
            .collect();
    }
    Ok(chain)
}

fn report(
    out: &mut impl Write,
    chain: &RingChain,
    run: &rings::RingRun,
    el: f64,
) -> std::io::Result<()> {
    writeln!(
        out,
        "dt {:.3e} s, steps {}, {:.1} us/step, pairs/step {:.1}, {:.2} us/pair, guard checks {}, \
         max overlap {:.3} r",
        run.dt,
        run.stats.steps,
        el / run.stats.steps as f64 * 1e6,
        run.stats.pair_evaluations as f64 / run.stats.steps as f64,
        el / run.stats.pair_evaluations.max(1) as f64 * 1e6,
        run.stats.guard_checks,
        run.stats.max_overlap
    )?;
    for s in &run.samples {
        let nz: Vec<String> = (0..chain.n)
            .map(|k| format!("{:+.1}", s.quat(k).matrix()[2][2]))
            .collect();
        writeln!(
            out,
            "t {:.2} E {:.6} bottom z {:.4} nz {}",
            s.t,
            s.energy,
            s.rings[chain.n - 1].x[2],
            nz.join(" ")
        )?;
    }
    for f in &run.flips {
        writeln!(out, "flip ring {} t {:.3} phi {:.0}", f.ring, f.t, f.phi)?;
    }
    for w in &run.waves {
        writeln!(
            out,
            "wave strand {} rings {:?} step {:.1} speed {:.1} pitch {:.1}",
            w.strand, w.rings, w.step, w.speed, w.pitch
        )?;
    }
    Ok(())
}
