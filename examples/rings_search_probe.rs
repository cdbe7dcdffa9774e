//! Probe of the two contact searches (docs/performance.md, "The
//! warm-started contact search"). `lockstep`: the 12-ring chain of the
//! step-halving test to 0.3 s; at every step of the warm run, one step
//! from the same state with each search, their touches and states
//! compared. `halving [levels]`: both searches at dt, dt/2, ...,
//! against the full search at the finest step.
//! `cargo run --release --example rings_search_probe -- lockstep`.
use jacobs_ladder::rings::math;
use jacobs_ladder::rings::system::{Search, System};
use jacobs_ladder::rings::{self, RingChain, build};

fn small(t_end: f64, dt: f64) -> RingChain {
    RingChain {
        n: 12,
        t_end,
        dt,
        turn: rings::Turn {
            start: 0.1,
            ..Default::default()
        },
        ..Default::default()
    }
}

fn lockstep() {
    let chain = small(0.3, 0.0);
    let mut w = build::build(&chain).unwrap();
    w.search = Search::Warm;
    let steps = (chain.t_end / w.dt).ceil() as u64;
    let mut first = None;
    let (mut worst_p, mut worst_d, mut worst_state) = (0.0f64, 0.0f64, 0.0f64);
    for k in 1..=steps {
        let mut f = w.clone();
        f.search = Search::Full;
        w.step().unwrap();
        f.step().unwrap();
        let (tw, tf) = (w.last_touches(), f.last_touches());
        let mut dp: f64 = 0.0;
        let mut dd: f64 = 0.0;
        let mut which = (0, 0);
        let same_set =
            tw.len() == tf.len() && tw.iter().zip(tf).all(|(a, b)| (a.0, a.1) == (b.0, b.1));
        if same_set {
            for (a, b) in tw.iter().zip(tf) {
                let e = math::norm(math::sub(a.2.p, b.2.p));
                if e > dp {
                    dp = e;
                    which = (a.0, a.1);
                }
                dd = dd.max((a.2.d - b.2.d).abs());
            }
        }
        let ds = w
            .bodies
            .iter()
            .zip(&f.bodies)
            .map(|(a, b)| math::norm(math::sub(a.x, b.x)))
            .fold(0.0, f64::max);
        if first.is_none() && (dp > 0.0 || !same_set) {
            first = Some(k);
            println!(
                "first differing step {k} (t = {:.6}): same pairs {same_set}, {} touches, largest |dp| {dp:e} m at pair {which:?}, |dd| {dd:e} m, state after one step {ds:e} m",
                w.t,
                tw.len()
            );
        }
        if !same_set {
            println!(
                "step {k}: touch sets differ: warm {} full {}",
                tw.len(),
                tf.len()
            );
        }
        worst_p = worst_p.max(dp);
        worst_d = worst_d.max(dd);
        worst_state = worst_state.max(ds);
    }
    println!(
        "over {steps} steps, one step each from the same state: largest |dp| {worst_p:e} m, |dd| {worst_d:e} m, state {worst_state:e} m; full searches {} of {}",
        w.stats.full_searches, w.stats.pair_evaluations
    );
}

fn run_to(chain: &RingChain, search: Search, times: &[f64]) -> Vec<Vec<[f64; 3]>> {
    let mut sys: System = build::build(chain).unwrap();
    sys.search = search;
    let steps = (chain.t_end / sys.dt).ceil() as u64;
    let mut out = Vec::new();
    let mut next = 0;
    for _ in 0..steps {
        sys.step().unwrap();
        while next < times.len() && times[next] <= sys.t + 0.5 * sys.dt {
            out.push(sys.bodies.iter().map(|b| b.x).collect());
            next += 1;
        }
    }
    out
}

fn halving(levels: usize) {
    let times = [0.1, 0.2, 0.3];
    let dt0 = build::build(&small(0.3, 0.0)).unwrap().dt;
    let diff = |a: &Vec<[f64; 3]>, b: &Vec<[f64; 3]>| {
        a.iter()
            .zip(b)
            .map(|(x, y)| math::norm(math::sub(*x, *y)))
            .fold(0.0, f64::max)
    };
    let mut runs = Vec::new();
    for search in [Search::Full, Search::Warm] {
        let mut v = Vec::new();
        for l in 0..levels {
            let f = 0.5f64.powi(l as i32);
            v.push(run_to(&small(0.3, f * dt0), search, &times));
        }
        runs.push(v);
    }
    // Reference: the finest full run.
    let reference = &runs[0][levels - 1];
    for (s, name) in ["full", "warm"].iter().enumerate() {
        for l in 0..levels {
            let line: Vec<String> = (0..times.len())
                .map(|k| format!("t={} {:.3e}", times[k], diff(&runs[s][l][k], &reference[k])))
                .collect();
            let succ: Vec<String> = if l + 1 < levels {
                (0..times.len())
                    .map(|k| format!("{:.3e}", diff(&runs[s][l][k], &runs[s][l + 1][k])))
                    .collect()
            } else {
                vec![]
            };
            println!(
                "{name} dt/{}: vs full dt/{}: {line:?}; vs own next half: {succ:?}",
                1 << l,
                1 << (levels - 1)
            );
        }
    }
    for (l, (full, warm)) in runs[0].iter().zip(&runs[1]).enumerate() {
        let line: Vec<String> = (0..times.len())
            .map(|k| format!("{:.3e}", diff(&full[k], &warm[k])))
            .collect();
        println!("full vs warm at dt/{}: {line:?}", 1 << l);
    }
}

fn main() {
    let mode = std::env::args().nth(1).unwrap_or_default();
    match mode.as_str() {
        "lockstep" => lockstep(),
        "halving" => halving(std::env::args().nth(2).map_or(4, |s| s.parse().unwrap())),
        _ => eprintln!("lockstep | halving [levels]"),
    }
}
