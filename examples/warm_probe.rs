use jacobs_ladder::rings::{RingChain, build, system::Search};
static mut PWORST: f64 = 0.0;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let t_end: f64 = args.get(1).map(|s| s.parse().unwrap()).unwrap_or(0.5);
    let compare = args.get(2).map(|s| s == "cmp").unwrap_or(true);
    let chain = if args.get(4).is_some_and(|s| s == "small") {
        RingChain { n: 12, t_end, turn: jacobs_ladder::rings::Turn { start: 0.1, ..Default::default() }, ..Default::default() }
    } else { RingChain {
        tapes: (1..28).step_by(2).map(|k| [k, k + 2]).collect(),
        t_end,
        ..Default::default()
    } };
    let mut sys = build::build(&chain).unwrap();
    sys.search = if args.get(3).is_some_and(|s| s == "full") { Search::Full } else { Search::Warm };
    let steps = (t_end / sys.dt).ceil() as u64;
    let r = chain.tube_radius;
    let (mut worst, mut missing, mut extra, mut nfull) = (0.0f64, 0u64, 0u64, 0u64);
    for k in 0..steps {
        sys.step().unwrap();
        if !compare { continue; }
        let rots: Vec<_> = sys.bodies.iter().map(|b| b.q.matrix()).collect();
        let full = sys.touches(&rots);
        let warm = sys.last_touches().to_vec();
        nfull += full.len() as u64;
        for &(i, j, t) in &full {
            let of = 2.0 * r - t.d;
            let ow = warm.iter().filter(|w| w.0 == i && w.1 == j && jacobs_ladder::rings::math::norm(jacobs_ladder::rings::math::sub(w.2.p, t.p)) < 1e-3)
                .map(|w| 2.0 * r - w.2.d).fold(0.0f64, f64::max);
            let diff = (of - ow).abs();
            if diff > 1e-9 * r { missing += 1; if missing < 10 { println!("step {k} t {:.5} pair {i} {j} d {} warm overlap {ow:e}", sys.t, t.d); } }
            worst = worst.max(diff);
            let pd = warm.iter().filter(|w| w.0 == i && w.1 == j && jacobs_ladder::rings::math::norm(jacobs_ladder::rings::math::sub(w.2.p, t.p)) < 1e-3).map(|w| jacobs_ladder::rings::math::norm(jacobs_ladder::rings::math::sub(w.2.p, t.p))).fold(0.0f64, f64::max);
            unsafe { PWORST = PWORST.max(pd); }
        }
        for &(i, j, w) in &warm {
            if !full.iter().any(|f| f.0 == i && f.1 == j && (f.2.d - w.d).abs() < 1e-9 * r) && 2.0 * r - w.d > 1e-9 * r { extra += 1; if extra < 10 { println!("extra: step {k} t {:.5} pair {i} {j} d {:e} overlap/r {:e}; full: {:?}", sys.t, w.d, (2.0*r - w.d)/r, full.iter().filter(|f| f.0 == i && f.1 == j).map(|f| (2.0*r-f.2.d)/r).collect::<Vec<_>>()); } }
        }
    }
    println!("largest |p_warm - p_full| {:e} m", unsafe { PWORST });
    println!("steps {} pairs {} full {} ({:.3}) touches {} worst |dd|/r {:e} missing {} extra {}",
        sys.stats.steps, sys.stats.pair_evaluations, sys.stats.full_searches,
        sys.stats.full_searches as f64 / sys.stats.pair_evaluations as f64, nfull, worst / r, missing, extra);
}
#[allow(dead_code)]
fn dummy() {}
