//! The ring chain's normal modes at rest (docs/rings.md, "What the
//! simulation shows"; `src/rings/modes.rs`): relaxes the chain to a
//! minimum of its potential with the top ring(s) held, takes the Hessian
//! by differences of the program's forces and prints the lowest modes:
//! ω, where along the chain each lives, which strand, whether it twists,
//! and whether its rotation axes advance helically down a strand.
//! `cargo run --release --example rings_modes -- n=30 [tapes] [mirror]
//! [lean=30 squeeze=0.7] [hold=2] [show=40] [settle=6 rate=4] [most=200]`
//! (the chain as built is first damped for `settle` s at `rate` 1/s, then
//! relaxed by at most `most` Newton steps).
use jacobs_ladder::rings::chain::G;
use jacobs_ladder::rings::{RingChain, build, modes, settle};

fn main() {
    let mut chain = RingChain::default();
    let (mut tapes, mut lean, mut squeeze, mut hold, mut show) = (false, None, 0.7, 1, 40);
    let (mut settle_time, mut most, mut rate) = (6.0, 200, 4.0);
    for a in std::env::args().skip(1) {
        let (k, v) = a.split_once('=').unwrap_or((a.as_str(), ""));
        let num = || v.parse::<f64>().unwrap_or_else(|e| panic!("{a}: {e}"));
        match k {
            "n" => chain.n = num() as usize,
            "tapes" => tapes = true,
            "mirror" => chain.mirror = true,
            "lean" => lean = Some(num()),
            "squeeze" => squeeze = num(),
            "hold" => hold = num() as usize,
            "show" => show = num() as usize,
            "settle" => settle_time = num(),
            "most" => most = num() as usize,
            "rate" => rate = num(),
            _ => panic!("unknown argument {a}"),
        }
    }
    if tapes {
        chain.tapes = chain.odd_strand_tapes();
    }
    let t0 = std::time::Instant::now();
    let mut sys = match lean {
        None => {
            let mut sys = build::build(&chain).expect("the chain builds");
            modes::damp(&mut sys, settle_time, rate).expect("the chain settles");
            sys
        }
        Some(l) => {
            settle::leaning(&chain, l, squeeze)
                .expect("the chain settles")
                .0
        }
    };
    let fixed: Vec<usize> = (0..hold).collect();
    let before = sys.bodies.clone();
    let relaxed = modes::relax(&mut sys, &fixed, 1e-9, most);
    let moved: Vec<String> = (0..sys.n())
        .map(|k| {
            let d = jacobs_ladder::rings::math::sub(sys.bodies[k].x, before[k].x);
            format!(
                "{k}:({:.2},{:.2},{:.2})",
                d[0] * 1e3,
                d[1] * 1e3,
                d[2] * 1e3
            )
        })
        .collect();
    println!("moved by the relaxation (mm): {}", moved.join(" "));
    let c = modes::coords(&sys, &fixed);
    let k = modes::stiffness(&sys, &c);
    let m = modes::mass(&sys, &c);
    let found = modes::modes(&k, &m);
    let h = modes::step_for(&sys);
    let coarse = modes::modes(&modes::stiffness_at(&sys, &c, 4.0 * h), &m);
    let compat = modes::compatibility(&sys, &c);
    let rank = modes::rank(&compat);
    let (law, dt) = build::law_and_step(&chain);
    let w_g = (G / chain.major_radius).sqrt();
    let w_c = std::f64::consts::TAU / (dt * build::STEPS_PER_PERIOD);
    println!(
        "{} rings{}{}{}, held {:?}: relaxed in {} Newton steps (force left {:.1e} of a ring's \
         weight); {} coordinates, {} constraints (touches and tape pins), rank {}, mechanisms \
         {}; K asymmetry {:.1e}, error scale in omega^2 {:.2e} s^-2 (omega {:.3} rad/s); k = {:.3e}; scales: sqrt(g/R) = {:.1} rad/s, contact {:.0} \
         rad/s; cpu {:.1} s",
        chain.n,
        if tapes { ", odd strand taped" } else { "" },
        if chain.mirror { ", mirrored" } else { "" },
        lean.map(|l| format!(", leaning start {l}° settled"))
            .unwrap_or_default(),
        fixed,
        relaxed.steps,
        relaxed.residual,
        c.len(),
        compat.nrows(),
        rank,
        c.len() - rank,
        modes::asymmetry(&k),
        modes::noise(&k, &m),
        modes::noise(&k, &m).sqrt(),
        law.k,
        w_g,
        w_c,
        t0.elapsed().as_secs_f64()
    );
    let nz: Vec<String> = jacobs_ladder::rings::run::normals(&sys.bodies)
        .iter()
        .map(|n| format!("{:+.2}", n[2]))
        .collect();
    println!("n_z at rest: {}", nz.join(" "));
    let rots: Vec<_> = sys.bodies.iter().map(|b| b.q.matrix()).collect();
    let mut light: Vec<(f64, usize, usize)> = modes::exact_touches(&sys, &rots)
        .iter()
        .map(|(i, j, t)| ((law.reach - t.d) / chain.tube_radius, *i, *j))
        .collect();
    light.sort_by(|a, b| a.0.total_cmp(&b.0));
    let light: Vec<String> = light
        .iter()
        .take(6)
        .map(|(d, i, j)| format!("{i}-{j}: {d:.2e}"))
        .collect();
    println!("difference step h = {h:.2e} m");
    println!("lightest touches (overlap / r): {}", light.join(", "));
    println!(
        "mode | omega rad/s | with step 4h | omega/sqrt(g/R) | rings | centre | odd share | twist share | axis step | helical | run | largest shares"
    );
    for (i, (w2, v)) in found.iter().take(show).enumerate() {
        let s = modes::shape(&sys, &c, *w2, v);
        let mut top: Vec<(usize, f64)> = s.share.iter().cloned().enumerate().collect();
        top.sort_by(|a, b| b.1.total_cmp(&a.1));
        let top: Vec<String> = top
            .iter()
            .take(4)
            .map(|(k, f)| format!("{k}:{:.2}", f))
            .collect();
        println!(
            "{i} | {:.3} | {:.3} | {:.4} | {:.1} | {:.1} | {:.2} | {:.2} | {} | {} | {:?} | {}",
            s.omega,
            modes::omega(coarse[i].0),
            s.omega / w_g,
            s.rings,
            s.centre,
            s.odd,
            s.twist,
            s.step.map(|x| format!("{x:.0}°")).unwrap_or("-".into()),
            if s.helical { "yes" } else { "no" },
            s.run,
            top.join(" ")
        );
    }
}
