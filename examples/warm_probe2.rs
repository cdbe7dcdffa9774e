use jacobs_ladder::rings::{RingChain, Turn, build, math, system::Search};
fn run(f: f64, search: Search, full_every: bool) -> Vec<Vec<[f64; 3]>> {
    let kick = full_every;
    let chain0 = RingChain { n: 12, t_end: 0.3, turn: Turn { start: 0.1, ..Default::default() }, ..Default::default() };
    let base_dt = build::build(&chain0).unwrap().dt;
    let chain = RingChain { dt: if f == 1.0 { 0.0 } else { f * base_dt }, ..chain0 };
    let mut sys = build::build(&chain).unwrap();
    sys.search = search;
    if kick { sys.bodies[5].x[0] += 1e-12; }
    let mut out = Vec::new();
    let times = [0.1, 0.3];
    let mut next = 0;
    let steps = (chain.t_end / sys.dt).ceil() as u64;
    for _ in 0..steps {
        sys.step().unwrap();
        while next < 2 && times[next] <= sys.t + 0.5 * sys.dt {
            out.push(sys.bodies.iter().map(|b| b.x).collect());
            next += 1;
        }
    }
    out
}
fn diff(a: &[Vec<[f64; 3]>], b: &[Vec<[f64; 3]>], k: usize) -> f64 {
    a[k].iter().zip(&b[k]).map(|(x, y)| math::norm(math::sub(*x, *y))).fold(0.0, f64::max)
}
fn main() {
    for s in [Search::Full, Search::Warm] {
        let r: Vec<_> = [1.0, 0.5, 0.25, 0.125].iter().map(|&f| run(f, s, false)).collect();
        for k in 0..2 {
            println!("{s:?} t={}: {:e} {:e} {:e}", [0.1, 0.3][k], diff(&r[0], &r[1], k), diff(&r[1], &r[2], k), diff(&r[2], &r[3], k));
        }
    }
}
