//! The commercial Jacob's ladder in air as built (docs/experiments.md,
//! "The toy in air"): six pine blocks with ribbons and wooden contact.
//! Each claim is decided from the state of the run: no two blocks
//! overlapping by more than a tenth of their thickness (the run's own
//! check, `sim::divergence`), each block's polarisation sin θ_n.

use jacobs_ladder::model::ladder::itheta;
use jacobs_ladder::model::outline::Pose;
use jacobs_ladder::model::ribbons::Ribbons;
use jacobs_ladder::scene::file::parse;
use jacobs_ladder::sim::{self, Drive, IntegratorConfig, IntegratorKind, Protocol, State};
use jacobs_ladder::sim::{Scenario, Trajectory};

const TOY: &str = include_str!("../../assets/scenes/toy.toml");

/// The toy scene with its `[drive]` and `duration` replaced.
fn toy(drive: &str, duration: f64) -> String {
    let head = TOY.split("# The hand's turn").next().unwrap();
    let head = head.replace("duration = 2.0", &format!("duration = {duration}"));
    format!(
        "{head}[drive]\n{drive}\n[run]\nintegrator = \"rk4\"\ndt = 0.02\n[output]\nkind = \"data\"\n"
    )
}

fn run(text: &str, samples: &[f64]) -> jacobs_ladder::error::Result<Trajectory> {
    let sc = parse(text, "toy", "toy").unwrap().scenario().unwrap();
    sim::simulate(
        &sc,
        samples,
        &IntegratorConfig::fixed(IntegratorKind::Rk4, 0.02),
    )
}

fn polarisation(q: &[f64]) -> Vec<f64> {
    (0..q.len() / 3).map(|i| q[itheta(i)].sin()).collect()
}

#[test]
fn the_toy_runs_to_its_end_with_no_two_blocks_overlapping() {
    // The scene as built-in: the run checks every step's deepest overlap
    // against a tenth of t and stops with an error where it is passed.
    // Sampled every τ, the deepest overlap seen is reported and bounded.
    let scene = parse(TOY, "toy", "toy").unwrap();
    let sc = scene.scenario().unwrap();
    let built = sc.ladder.built.unwrap();
    let (o, c) = (built.ribbons.outline, built.contact.unwrap());
    let times: Vec<f64> = (0..=sc.t_end as usize).map(|k| k as f64).collect();
    let traj = run(TOY, &times).expect("the toy runs to its end");
    assert!((traj.t_final - sc.t_end).abs() < 1e-9);
    let mut deepest = 0.0f64;
    let mut touching = 0;
    for (q, v) in traj.states.iter().zip(&traj.velocities) {
        let t = c.touches(sc.ladder.blocks(), &o, q, v);
        touching += usize::from(!t.is_empty());
        deepest = t.iter().fold(deepest, |d, t| d.max(t.depth));
    }
    println!(
        "deepest sampled overlap {:.2e} t, samples touching {touching}",
        deepest / o.thickness()
    );
    assert!(
        touching > 10,
        "the blocks must touch for this to test contact"
    );
    assert!(deepest < 0.1 * o.thickness());
    // Its impacts, decided at every step: blocks clatter on one another
    // (the first between blocks 1 and 2, once the hand has turned block 1),
    // in time order, each between two blocks, at a speed ≥ 0.
    let impacts = traj
        .impacts
        .as_ref()
        .expect("a toy with contact has impacts");
    println!("{} impacts, first {:?}", impacts.len(), impacts.first());
    assert!(impacts.len() >= 6, "{impacts:?}");
    assert_eq!(impacts[0].blocks, [1, 2]);
    for w in impacts.windows(2) {
        assert!(w[1].t >= w[0].t, "in time order: {w:?}");
    }
    for i in impacts {
        let [a, b] = i.blocks;
        assert!(
            a < b && b <= 6 && i.t > 0.0 && i.t <= sc.t_end && i.speed >= 0.0,
            "{i:?}"
        );
    }
}

/// Two pine blocks of the toy without ribbons (κ = 0): block 1 held at
/// rest at θ = 0 (lying across gravity, its face w = −h up at x = −h),
/// block 2 above it at (x, y, θ) with velocities `v`, free; run to
/// `t_end` by RK4 at the toy's step.
fn drop(q2: [f64; 3], v2: [f64; 3], t_end: f64) -> (Scenario, Trajectory) {
    let text = TOY.replace("n = 6", "n = 2");
    let mut sc = parse(&text, "toy", "toy").unwrap().scenario().unwrap();
    let mut built = sc.ladder.built.unwrap();
    built.ribbons = Ribbons::new(built.ribbons.outline, built.ribbons.ribbons, 0.0);
    sc.ladder.built = Some(built);
    sc.protocol = Protocol::Driven(Drive::hold(0.0));
    sc.initial = State {
        q: vec![0.0, 0.0, 0.0, q2[0], q2[1], q2[2]],
        v: vec![0.0, 0.0, 0.0, v2[0], v2[1], v2[2]],
    };
    sc.t_end = t_end;
    let traj = sim::simulate(
        &sc,
        &[],
        &IntegratorConfig::fixed(IntegratorKind::Rk4, 0.02),
    )
    .unwrap();
    (sc, traj)
}

#[test]
fn a_block_dropped_flat_hits_once_at_the_free_fall_time_and_speed() {
    // Block 2 flat (θ = 0), its face 0.05 s above block 1's, shifted
    // 0.2 s sideways: it falls freely, G t²/2 = 0.05, and lands at
    // t* = √(0.1/G) with speed G t*. The rebound (e = 0.5) flies for
    // about e · 2 t* ≈ t*: a window of 1.5 t* holds exactly one impact.
    let gap = 0.05;
    let (sc, _) = drop([0.0; 3], [0.0; 3], 0.0);
    let (g, h) = (
        sc.ladder.params.gravity,
        sc.ladder.built.unwrap().ribbons.outline.half_thickness,
    );
    let t_star = (2.0 * gap / g).sqrt();
    let (_, traj) = drop([-2.0 * h - gap, 0.2, 0.0], [0.0; 3], 1.5 * t_star);
    let impacts = traj.impacts.unwrap();
    println!("t* = {t_star}, v* = {}: {impacts:?}", g * t_star);
    assert_eq!(impacts.len(), 1, "{impacts:?}");
    let i = impacts[0];
    assert_eq!(i.blocks, [1, 2]);
    // Time to ½ G dt²/v (the look-back is linear), speed to G dt.
    assert!((i.t - t_star).abs() < 1e-4, "{} {t_star}", i.t);
    assert!(
        (i.speed - g * t_star).abs() < 1.01 * g * 0.02,
        "{}",
        i.speed
    );
}

#[test]
fn a_spinning_block_hits_where_and_as_fast_as_its_free_flight_says() {
    // Block 2 tilted by 0.1 rad and turning at ω = 2e-3 per τ as it
    // falls: a corner lands first. Its free flight, X = X₀ + G t²/2,
    // θ = θ₀ + ω t, puts each corner at x_k(t) (`Pose`); the first time
    // one reaches block 1's face x = −h (by bisection of the flight, not
    // of the run) and its speed there, Ẋ + ω ∂x_k/∂θ, are the impact's.
    let (q0, om) = ([-0.35, -0.2, 0.1], 2e-3);
    let (sc, _) = drop([0.0; 3], [0.0; 3], 0.0);
    let g = sc.ladder.params.gravity;
    let o = sc.ladder.built.unwrap().ribbons.outline;
    let h = o.half_thickness;
    let flight = |t: f64| {
        [
            0.0,
            0.0,
            0.0,
            q0[0] + 0.5 * g * t * t,
            q0[1],
            q0[2] + om * t,
        ]
    };
    // The lowest corner's distance above block 1's face (> 0 before).
    let lowest = |t: f64| -> (f64, usize) {
        let p = Pose::of(&flight(t), 1);
        (0..4)
            .map(|k| (-h - p.point(o.corner(k))[0], k))
            .fold((f64::INFINITY, 0), |m, d| if d.0 < m.0 { d } else { m })
    };
    let (mut lo, mut hi) = (0.0, 0.0);
    while lowest(hi).0 > 0.0 {
        (lo, hi) = (hi, hi + 0.5);
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if lowest(mid).0 > 0.0 {
            lo = mid
        } else {
            hi = mid
        }
    }
    let (t_star, k) = (hi, lowest(hi).1);
    let p = Pose::of(&flight(t_star), 1);
    let (c, turning) = (o.corner(k), p.turning(o.corner(k)));
    let y_hit = p.point(c)[1];
    assert!(
        y_hit.abs() < 0.45,
        "the corner lands on block 1's face: {y_hit}"
    );
    let v_star = g * t_star + om * turning[0];
    let (_, traj) = drop(q0, [0.0, 0.0, om], t_star + 2.0);
    let impacts = traj.impacts.unwrap();
    println!("t* = {t_star}, v* = {v_star}, corner {k}: {impacts:?}");
    assert_eq!(impacts.len(), 1, "{impacts:?}");
    assert_eq!(impacts[0].blocks, [1, 2]);
    assert!((impacts[0].t - t_star).abs() < 1e-4, "{}", impacts[0].t);
    assert!(
        (impacts[0].speed - v_star).abs() < 2e-3 * v_star,
        "{}",
        impacts[0].speed
    );
}

#[test]
fn a_step_longer_than_the_contacts_stable_step_is_refused() {
    // k_c = 1e5 k/s rings at ω_c = √(k_c · 2 (1/m + ρ²/I)) = 894 per τ:
    // RK4's bound 2√2/ω_c = 0.0032 τ; at 0.01 τ (ω_c dt = 8.9) the run is
    // refused before it starts, naming the bound.
    let text = TOY.replace(
        "contact = \"wood\"",
        "contact = \"wood\"\ncontact_stiffness = 1e5",
    );
    let sc = parse(&text, "toy", "toy").unwrap().scenario().unwrap();
    let built = sc.ladder.built.unwrap();
    let c = built.contact.unwrap();
    let w = c.frequency(sc.ladder.blocks(), &built.ribbons.outline);
    assert!((w - 894.4).abs() < 0.1, "{w}");
    let e = sim::simulate(
        &sc,
        &[],
        &IntegratorConfig::fixed(IntegratorKind::Rk4, 0.01),
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("stable step") && e.contains("0.0032"), "{e}");
    // Inside the bound it runs and the overlap check holds.
    let short = text.replace("duration = 2.0", "duration = 0.3");
    let sc = parse(&short, "toy", "toy").unwrap().scenario().unwrap();
    sim::simulate(
        &sc,
        &[],
        &IntegratorConfig::fixed(IntegratorKind::Rk4, 0.003),
    )
    .unwrap();
}

#[test]
fn turned_over_and_back_the_toy_ends_inverted_then_restored() {
    // The paper's introduction: block 1 turned over (0.25 s = 232 τ)
    // turns every block over; turned back the other way at 1855 τ (2 s)
    // every block returns to its first orientation. Decided from sin θ_n
    // of the state just before the second turn and at the end.
    let drive = "flips = [{ start = 0.0, duration = 232.0 }, { start = 1855.0, duration = 232.0 }]";
    let traj = run(&toy(drive, 4.0), &[0.0, 1854.0]).unwrap();
    let first = polarisation(&traj.states[0]);
    let turned = polarisation(&traj.states[1]);
    let last = polarisation(&traj.final_state.q);
    println!("sin θ: start {first:.2?}\nturned {turned:.2?}\nback {last:.2?}");
    assert!(first.iter().all(|p| *p > 0.99));
    assert!(
        turned.iter().all(|p| *p < 0.0),
        "every block inverted: {turned:?}"
    );
    assert!(
        last.iter().all(|p| *p > 0.0),
        "every block restored: {last:?}"
    );
}

#[test]
#[ignore = "open, a result of the model: at the scene's gap and turn block 6 (the free end) flips \
            third (442 τ, blocks 1–3 at 116, 354, 479 τ); over 16 turns within 10 % of the \
            scene's, all six in turn at 2 and 3 of 16 (the two steps), about what a random order \
            of the last three gives, 2.7 (docs/experiments.md, \"The odds of the order\")"]
fn block_1_turned_over_once_flips_every_block_in_turn() {
    let traj = run(TOY, &[]).unwrap();
    let t: Vec<f64> = traj
        .arrival_times
        .iter()
        .map(|t| t.expect("every block flips"))
        .collect();
    println!("arrivals (τ) {t:?}");
    for w in t.windows(2) {
        assert!(w[1] > w[0], "in turn: {t:?}");
    }
}

#[test]
#[ignore = "open, a result of the model: a toy of ten blocks (the scene's otherwise) turned over \
            once flips blocks 1 and 2 (116, 320 τ) and the free end (465 τ); blocks 3 to 9 never \
            flip in 10.8 s, at every gap and turn tried the cascade stops after 2 to 4 blocks \
            (docs/experiments.md, \"A longer toy\")"]
fn block_1_turned_over_once_flips_every_block_of_a_ten_block_toy_in_turn() {
    assert!(TOY.contains("n = 6"), "the scene's N");
    let text = toy("flips = [{ start = 0.0, duration = 232.0 }]", 10.8).replace("n = 6", "n = 10");
    let traj = run(&text, &[]).unwrap();
    println!("arrivals (τ) {:?}", traj.arrival_times);
    let t: Vec<f64> = traj
        .arrival_times
        .iter()
        .map(|t| t.expect("every block flips"))
        .collect();
    for w in t.windows(2) {
        assert!(w[1] > w[0], "in turn: {t:?}");
    }
}

/// The toy with its ends `gap_mm` apart, block 1 turned over once in
/// each of `k` turn times spread evenly over ±10 % of `turn` (τ), run to
/// `duration` (s): each run's blocks in the order of their first flips
/// (0-based; a block that never flips is left out).
fn orders(gap_mm: f64, turn: f64, k: usize, duration: f64) -> Vec<Vec<usize>> {
    orders_with(gap_mm, turn, k, duration, "")
}

/// [`orders`] with `extra` lines added to the scene's `[apparatus]`.
fn orders_with(gap_mm: f64, turn: f64, k: usize, duration: f64, extra: &str) -> Vec<Vec<usize>> {
    // The gap is set by replacing the scene's b (0.5 mm), the extra keys
    // after its contact; a scene that says them otherwise would leave
    // every run as the scene is.
    assert!(TOY.contains("b = 5.75"), "the scene's b = s + 0.5 mm");
    assert!(TOY.contains("contact = \"wood\"\n"), "the scene's contact");
    (0..k)
        .map(|i| {
            let td = turn * (0.9 + 0.2 * i as f64 / (k - 1) as f64);
            let drive = format!("flips = [{{ start = 0.0, duration = {td} }}]");
            let text = toy(&drive, duration)
                .replace("b = 5.75", &format!("b = {}", 5.7 + gap_mm / 10.0))
                .replace(
                    "contact = \"wood\"\n",
                    &format!("contact = \"wood\"\n{extra}"),
                );
            let a = run(&text, &[]).unwrap().arrival_times;
            let mut flipped: Vec<(f64, usize)> =
                (0..a.len()).filter_map(|n| a[n].map(|t| (t, n))).collect();
            flipped.sort_by(|x, y| x.0.total_cmp(&y.0));
            flipped.into_iter().map(|(_, n)| n).collect()
        })
        .collect()
}

#[test]
fn a_slow_turn_starts_the_cascade_in_turn_whatever_its_exact_time() {
    // The claim docs/experiments.md ("The odds of the order") makes of a
    // turn of half a second: whatever its exact time, blocks 1, 2, 3 are
    // the first three to flip, in that order, at the scene's gap. One
    // run says little (the clatter is chaotic); eight turns over ±10 %
    // of 464 τ (0.5 s) each say it. Run to 1.2 s (1113 τ): block 3
    // flips by about 710 τ.
    for order in orders(0.5, 464.0, 8, 1.2) {
        assert!(
            order.len() >= 3 && order[..3] == [0, 1, 2],
            "blocks 1, 2, 3 first, in turn: {order:?}"
        );
    }
}

#[test]
fn a_quick_turn_throws_the_free_end_over_before_block_3() {
    // The claim docs/experiments.md ("The odds of the order") makes of a
    // quick turn (0.25 s = 232 τ) at gaps of 1 mm and more: the hand's
    // turn whips the column and block 6, the free end, flips before
    // block 3, at every turn within ±10 % of it. Run to 0.6 s (557 τ):
    // block 3 flips by about 480 τ.
    for order in orders(1.0, 232.0, 8, 0.6) {
        let at = |n: usize| order.iter().position(|m| *m == n);
        assert!(
            matches!((at(5), at(2)), (Some(six), Some(three)) if six < three),
            "block 6 before block 3: {order:?}"
        );
    }
}

#[test]
fn turned_the_other_way_round_block_1_flips_block_2_and_mostly_no_more() {
    // The claim docs/experiments.md ("Which way round the hand turns")
    // makes: the ribbons' faces fix a sense; block 1 turned the other way
    // round (the mirrored ribbons turned the scene's way: the mirror image
    // of that turn) flips block 2 and leaves it hanging short of
    // inverted. Over eight turns within ±10 % of a slow 1 s (928 τ), to
    // 3000 τ: no run starts 1, 2, 3, and in 7 of the 8 blocks 1 and 2
    // are the only ones to flip (the longest turn flips 1, 3, 2, 4). The
    // scene's own sense flips block 3, third, in 6 of the same 8 turns.
    let mirrored = orders_with(0.5, 928.0, 8, 3.234, "ribbon_mirror = true\n");
    assert!(
        mirrored.iter().all(|o| !o.starts_with(&[0, 1, 2])),
        "no run in turn: {mirrored:?}"
    );
    let stopped = mirrored.iter().filter(|o| o[..] == [0, 1]).count();
    assert!(stopped >= 6, "blocks 1 and 2 alone in most: {mirrored:?}");
    let scene = orders(0.5, 928.0, 8, 3.234);
    let on = scene.iter().filter(|o| o.starts_with(&[0, 1, 2])).count();
    assert!(
        on >= 6,
        "the scene's sense starts in turn in most: {scene:?}"
    );
}

/// The arrival times (τ) of `text` run at a fixed RK4 step `dt`, sampled
/// at `samples`.
fn arrivals_at(text: &str, dt: f64, samples: &[f64]) -> Vec<Option<f64>> {
    let sc = parse(text, "toy", "toy").unwrap().scenario().unwrap();
    let cfg = IntegratorConfig::fixed(IntegratorKind::Rk4, dt);
    sim::simulate(&sc, samples, &cfg).unwrap().arrival_times
}

#[test]
fn the_first_three_flips_hold_in_the_step_and_the_sampling() {
    // The claim `movie toy`'s caption and docs/experiments.md make of the
    // cascade's start: blocks 1, 2, 3 flip at about 116, 355, 480 τ. It
    // must not be an artefact of the step (0.02 τ against 0.01 τ, both
    // inside the contact's stable step) nor of the frame times the fixed
    // step lands on (none, 200 frames, 50 frames over 1113 τ). The later
    // blocks' order is not claimed: the clatter is chaotic.
    let text = toy("flips = [{ start = 0.0, duration = 232.0 }]", 0.6);
    let frames = |k: usize| -> Vec<f64> {
        (0..k)
            .map(|i| 1113.0 * i as f64 / (k - 1) as f64)
            .filter(|t| *t < 550.0)
            .collect()
    };
    let reference = arrivals_at(&text, 0.01, &[]);
    for (dt, samples) in [(0.02, vec![]), (0.02, frames(200)), (0.02, frames(50))] {
        let a = arrivals_at(&text, dt, &samples);
        for n in 0..3 {
            let (x, y) = (a[n].expect("flips"), reference[n].expect("flips"));
            println!(
                "block {}: {x:.2} τ against {y:.2} τ (dt {dt}, {} samples)",
                n + 1,
                samples.len()
            );
            assert!((x - y).abs() < 5.0, "block {}: {x} against {y}", n + 1);
        }
    }
}

/// Everything a run of the toy decides, as bits: arrivals, impacts, the
/// final state and the step count.
fn run_bits(traj: &Trajectory) -> Vec<u64> {
    let mut bits: Vec<u64> = traj
        .arrival_times
        .iter()
        .map(|t| t.map_or(u64::MAX, f64::to_bits))
        .collect();
    for i in traj.impacts.iter().flatten() {
        bits.extend([i.t.to_bits(), i.speed.to_bits(), i.blocks[0] as u64]);
    }
    let end = &traj.final_state;
    bits.extend(end.q.iter().chain(&end.v).map(|x| x.to_bits()));
    bits.push(traj.steps);
    bits
}

#[test]
fn the_toys_run_is_the_same_at_any_number_of_frames() {
    // The clatter is chaotic: a step landing on each frame's time made
    // `movie toy` flip its last blocks in another order at 50 and at 200
    // frames. Stepped on a grid of its own, frames taken between steps,
    // the run is one, bit for bit, whatever it is sampled at.
    let text = toy("flips = [{ start = 0.0, duration = 232.0 }]", 0.6);
    let sc = parse(&text, "toy", "toy").unwrap().scenario().unwrap();
    let frames = |k: usize| -> Vec<f64> {
        (0..k)
            .map(|i| sc.t_end * i as f64 / (k - 1) as f64)
            .collect()
    };
    let reference = run_bits(&run(&text, &[]).unwrap());
    for k in [50, 200, 1000] {
        let traj = run(&text, &frames(k)).unwrap();
        assert_eq!(traj.times.len(), k);
        assert!(run_bits(&traj) == reference, "{k} frames moved the run");
    }
}

/// The toy turned over once, run for each of `durations` (s) by `cfg`,
/// each sampled at `frames` frames spread over the first duration: the
/// runs, and the first one's t_end (τ).
fn runs_to(durations: [f64; 2], cfg: &IntegratorConfig, frames: usize) -> ([Trajectory; 2], f64) {
    let scenario = |d: f64| {
        let text = toy("flips = [{ start = 0.0, duration = 232.0 }]", d);
        parse(&text, "toy", "toy").unwrap().scenario().unwrap()
    };
    let t_end = scenario(durations[0]).t_end;
    let samples: Vec<f64> = (0..frames)
        .map(|i| t_end * i as f64 / (frames - 1) as f64)
        .collect();
    let runs = durations.map(|d| sim::simulate(&scenario(d), &samples, cfg).unwrap());
    (runs, t_end)
}

/// Asserts that two runs agree, bit for bit, at every sample, arrival
/// and impact before `before` (τ), and that all but the last two samples
/// are before it.
fn same_before(runs: &[Trajectory; 2], before: f64) {
    let [a, b] = runs;
    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    let common = a.times.iter().take_while(|&&t| t < before).count();
    for k in 0..common {
        let t = a.times[k];
        assert_eq!(t, b.times[k]);
        assert!(bits(&a.states[k]) == bits(&b.states[k]), "q at {t} τ");
        assert!(
            bits(&a.velocities[k]) == bits(&b.velocities[k]),
            "v at {t} τ"
        );
    }
    assert!(common + 2 >= a.times.len(), "{common} of {}", a.times.len());
    let early = |t: &Option<f64>| t.filter(|&t| t < before).map(f64::to_bits);
    let arrivals = |r: &Trajectory| r.arrival_times.iter().map(early).collect::<Vec<_>>();
    assert_eq!(arrivals(a), arrivals(b));
    let impacts = |r: &Trajectory| -> Vec<(u64, u64, [usize; 2])> {
        let early = r.impacts.iter().flatten().filter(|i| i.t < before);
        early
            .map(|i| (i.t.to_bits(), i.speed.to_bits(), i.blocks))
            .collect()
    };
    assert!(!impacts(a).is_empty(), "the toy clatters");
    assert_eq!(impacts(a), impacts(b));
}

#[test]
fn the_toys_run_is_the_same_at_any_duration_up_to_its_last_step() {
    // The clatter is chaotic: the stretch from the drive's corner to
    // t_end cut into equal steps, the run to 1.2 s (`movie toy`) and the
    // run to 1.37 times that parted from the corner on. Stepped on the
    // grid k·dt, cut at the drive's corners and clipped at t_end, the two
    // are one, bit for bit, at every frame, flip and impact before the
    // shorter run's last grid point.
    let dt = 0.02;
    let cfg = IntegratorConfig::fixed(IntegratorKind::Rk4, dt);
    let (runs, t_end) = runs_to([1.2, 1.2 * 1.37], &cfg, 400);
    let last_grid_point = (t_end / dt).floor() * dt;
    same_before(&runs, last_grid_point - 1e-6);
    assert!(runs[0].arrival_times.iter().all(Option::is_some));
}

#[test]
fn adaptive_dopri5_runs_the_toy_the_same_at_any_duration_up_to_its_last_step() {
    // Adaptive dopri5 takes the steps its error control chooses and
    // clips only the one that would cross a stop: runs to two durations
    // are one, bit for bit, up to the shorter run's last step (every
    // frame more than dopri5's longest step before its end).
    let cfg = IntegratorConfig::adaptive(1e-6);
    let (runs, t_end) = runs_to([0.3, 0.3 * 1.37], &cfg, 100);
    same_before(&runs, t_end - sim::integrators::DOPRI5_MAX_STEP);
}

#[test]
fn a_frame_between_steps_is_the_state_a_step_landing_on_it_gives() {
    // On a run that is not chaotic (the paper's ladder, its flip under
    // way), frames taken between the steps by cubic Hermite interpolation
    // are the states of a run that lands a step on each, to the
    // interpolation's error (fourth order in the step) and the steps'
    // (the two runs step on different grids).
    let params = jacobs_ladder::model::Params::paper(60.0).unwrap();
    let sc = Scenario::single_flip(params, 1000.0, 300.0).unwrap();
    let samples: Vec<f64> = (0..=29).map(|i| 10.0 * i as f64 + 0.0371).collect();
    let cfg = IntegratorConfig::fixed(IntegratorKind::Rk4, 0.1);
    let runs = [true, false].map(|between| {
        let options = sim::RunOptions::default().samples_between_steps(between);
        sim::run(&sc, &samples, &cfg, &options).unwrap()
    });
    let largest = |a: &[Vec<f64>], b: &[Vec<f64>]| {
        a.iter().zip(b).fold(0.0f64, |d, (a, b)| {
            a.iter().zip(b).fold(d, |d, (x, y)| d.max((x - y).abs()))
        })
    };
    let dq = largest(&runs[0].states, &runs[1].states);
    let dv = largest(&runs[0].velocities, &runs[1].velocities);
    println!("largest difference: q {dq:.2e} s, v {dv:.2e} s/τ");
    assert_eq!(runs[0].times, runs[1].times);
    assert!(dq < 1e-9 && dv < 1e-8, "q {dq:e}, v {dv:e}");
    assert!(dq > 0.0, "the two runs took the same steps");
}

#[test]
fn the_warm_tangent_search_runs_the_toy_as_the_cold_one_bit_for_bit() {
    // The toy as built-in (the hand's turn, the clatter: corners pressed
    // into faces where the ribbons leave them), each common tangent
    // started from the last evaluation's against searched from the
    // anchors every time: the same states, bit for bit, every 5 τ.
    let sc = parse(TOY, "toy", "toy").unwrap().scenario().unwrap();
    let samples: Vec<f64> = (0..(sc.t_end / 5.0) as usize)
        .map(|k| 5.0 * k as f64)
        .collect();
    let cfg = IntegratorConfig::fixed(IntegratorKind::Rk4, 0.02);
    let (warm, arrivals) = crate::ribbons::run_bits(&sc, &samples, &cfg, true);
    let (cold, cold_arrivals) = crate::ribbons::run_bits(&sc, &samples, &cfg, false);
    assert_eq!(arrivals, cold_arrivals);
    assert!(warm == cold, "the warm search moved the run");
}

#[test]
fn the_pruned_way_search_runs_the_toy_as_the_full_one_bit_for_bit() {
    // The toy as built-in through its clatter, a pair of ways round that
    // has an earlier pair's tangent points at its anchor taken unsearched
    // against every pair searched (both warm): the same states, every 5 τ.
    use crate::ribbons::run_bits_searched;
    let sc = parse(TOY, "toy", "toy").unwrap().scenario().unwrap();
    let samples: Vec<f64> = (0..(sc.t_end / 5.0) as usize)
        .map(|k| 5.0 * k as f64)
        .collect();
    let cfg = IntegratorConfig::fixed(IntegratorKind::Rk4, 0.02);
    let (pruned, arrivals) = run_bits_searched(&sc, &samples, &cfg, (true, true));
    let (full, full_arrivals) = run_bits_searched(&sc, &samples, &cfg, (true, false));
    assert_eq!(arrivals, full_arrivals);
    assert!(pruned == full, "the pruned search moved the run");
}

#[test]
fn the_toy_data_file_is_within_its_estimate_its_impacts_counted() {
    // `ladder figure toy` written, against the estimate made before any
    // work (`scenes::data::estimated_bytes`): the file within it, and the
    // bytes its impacts take (the events and their times and speeds in
    // s and cm/s) within the impacts' allowance (which it counts).
    use jacobs_ladder::catalog;
    use jacobs_ladder::scene::Kind;
    use jacobs_ladder::scenes::data::{estimated_bytes, impact_bytes};
    use jacobs_ladder::scenes::options::MovieOptions;
    let dir = crate::common::tempdir::TempDir::new("toy-estimate");
    let out = crate::common::ladder_cli(&["figure", "toy", "--out", dir.to_str().unwrap()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(dir.join("figure-toy.json")).unwrap();
    let scene = &catalog::find(Kind::Figure, "toy").unwrap().scene;
    let (estimate, _) = estimated_bytes(scene, &MovieOptions::default(), 400);
    let allowance: f64 = scene.runs().iter().map(|(s, _)| impact_bytes(s)).sum();
    // The impacts' bytes: the file pretty-printed again with and without them.
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let whole = serde_json::to_string_pretty(&v).unwrap().len();
    let mut impacts = 0;
    for run in v["runs"].as_array_mut().unwrap() {
        let run = run.as_object_mut().unwrap();
        impacts += run["impacts"].as_array().map_or(0, Vec::len);
        run.remove("impacts");
        if let Some(u) = run.get_mut("units").and_then(|u| u.as_object_mut()) {
            u.remove("impact_times_s");
            u.remove("impact_speeds_cm_s");
        }
    }
    let taken = whole - serde_json::to_string_pretty(&v).unwrap().len();
    println!(
        "file {} bytes, estimate {estimate:.0}; {impacts} impacts take {taken} bytes, allowed {allowance:.0}",
        text.len()
    );
    assert!(impacts > 0, "the toy clatters");
    assert!(
        (text.len() as f64) <= estimate,
        "{} > {estimate}",
        text.len()
    );
    assert!((taken as f64) <= allowance, "{taken} > {allowance}");
}
