//! The toy's order of flips with the hand's turn smooth against the
//! scene's linear turn (docs/experiments.md, "The order of the flips: the
//! gap and the turn"): for each gap (mm) and turn time (s) of
//! `scripts/toy-order`, block 1 turned over once and run 3000 τ at RK4
//! 0.02 and 0.01 τ, the turn linear (the scene's: constant angular
//! speed) and smooth (θ₁ along a half cosine, as 32 linear pieces:
//! starting and stopping at rest). Prints each run's order of first flips
//! ("-" for a block that never flips) and whether both smooth runs flip
//! every block in turn.
//!
//! `cargo run --release --example toy_smooth_probe`
use jacobs_ladder::scene::file::parse;
use jacobs_ladder::sim::{self, Drive, IntegratorConfig, IntegratorKind, Protocol};

const TOY: &str = include_str!("../assets/scenes/toy.toml");

fn main() {
    for gap in [0.2, 0.5, 1.0, 2.0, 5.0] {
        for turn in [116.0, 232.0, 464.0, 928.0] {
            let mut row = format!("{gap} {:.3}", turn * 0.0010779979);
            let mut in_turn = true;
            for profile in ["linear", "smooth"] {
                for dt in [0.02, 0.01] {
                    let b = 5.7 + gap / 10.0;
                    let text = TOY
                        .replace("b = 5.75", &format!("b = {b}"))
                        .replace("duration = 2.0", "duration = 3.234")
                        .replace("duration = 232.0", &format!("duration = {turn}"));
                    let mut sc = parse(&text, "toy", "toy").unwrap().scenario().unwrap();
                    if profile == "smooth" {
                        let d = sc.protocol.drive().unwrap().clone();
                        let (a, z) = (d.theta(0.0), d.theta(turn));
                        let k = 32;
                        let knots = (0..=k)
                            .map(|i| {
                                let s = i as f64 / k as f64;
                                (
                                    turn * s,
                                    a + (z - a) * (1.0 - (std::f64::consts::PI * s).cos()) / 2.0,
                                )
                            })
                            .collect();
                        sc.protocol = Protocol::Driven(Drive::new(knots).unwrap());
                    }
                    let tr =
                        sim::simulate(&sc, &[], &IntegratorConfig::fixed(IntegratorKind::Rk4, dt))
                            .unwrap();
                    let a = &tr.arrival_times;
                    let key = |i: usize| a[i].unwrap_or(f64::INFINITY);
                    let mut idx: Vec<usize> = (0..a.len()).collect();
                    idx.sort_by(|&x, &y| key(x).total_cmp(&key(y)));
                    let order: String = idx
                        .iter()
                        .map(|&i| {
                            if a[i].is_some() {
                                format!("{}", i + 1)
                            } else {
                                "-".into()
                            }
                        })
                        .collect();
                    let ok = order == "123456";
                    if profile == "smooth" {
                        in_turn &= ok;
                    }
                    row += &format!(" {profile}:{dt}:{order}");
                }
            }
            println!(
                "{row} smooth-in-turn={}",
                if in_turn { "yes" } else { "no" }
            );
        }
    }
}
