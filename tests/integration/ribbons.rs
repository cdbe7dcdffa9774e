//! The toy as built (docs/experiments.md, "The toy as built"): blocks
//! with thickness held by ribbons that wrap round their ends, in the water
//! tank. Each test checks physics: the wave runs and every plate ends
//! turned over; the stiff ribbons are shown stiff (k and 2k); the energy
//! budget closes; a mirrored apparatus moves as the mirror image; the
//! arrangement that breaks the kink–antikink symmetry is named.

use jacobs_ladder::model::ladder::itheta;
use jacobs_ladder::scene::file::parse;
use jacobs_ladder::sim::budget::Budget;
use jacobs_ladder::sim::speed::wave_speed;
use jacobs_ladder::sim::{self, Drive, IntegratorConfig, IntegratorKind, Protocol};

/// The tank of docs/experiments.md with ribbons and `extra` keys.
fn tank(extra: &str, alpha: f64, motor: f64, duration: f64, n: usize) -> String {
    format!(
        "[model]\nalpha = {alpha}\nn = {n}\n[apparatus]\ns = 5.0\nb = 7.5\nthickness = 0.3\n\
         density = 1.2\nmedium = \"water\"\nmedium_density = 1.0\nbuoyancy = true\n\
         ribbons = true\nmotor = {motor}\nduration = {duration}\n{extra}\n[output]\nkind = \"data\"\n"
    )
}

fn rk4(dt: f64) -> IntegratorConfig {
    IntegratorConfig::fixed(IntegratorKind::Rk4, dt)
}

/// Arrival times (s) and the whole-chain speed (cm/s) of a tank run.
fn run(text: &str, dt: f64) -> (Vec<Option<f64>>, Option<f64>, Vec<f64>) {
    let scene = parse(text, "t", "t").unwrap();
    let c = scene
        .apparatus
        .as_ref()
        .unwrap()
        .conversion
        .clone()
        .unwrap();
    let sc = scene.scenario().unwrap();
    let traj = sim::simulate(&sc, &[], &rk4(dt)).unwrap();
    let speed = wave_speed(&traj.arrival_times).map(|v| v * c.cm_per_s);
    let seconds = traj
        .arrival_times
        .iter()
        .map(|t| t.map(|t| t * c.tau_s))
        .collect();
    let n = sc.ladder.n();
    let last = traj.final_state.q.clone();
    let angles = (0..n).map(|i| last[itheta(i)].to_degrees()).collect();
    (seconds, speed, angles)
}

#[test]
fn the_tank_with_ribbons_turns_every_plate_over_in_turn() {
    // Kink at 0.2 Hz: every plate flips, one after the other down the
    // chain, and ends turned over (θ near −90°: the column upside down).
    let text = tank("added_mass = true\ndrag = true\n", 86.0, 0.2, 20.0, 11);
    let (t, c, angles) = run(&text, 0.125);
    println!("arrivals (s) {t:?}\nspeed {c:?} cm/s\nfinal θ {angles:?}");
    let t: Vec<f64> = t.iter().map(|t| t.expect("every plate flips")).collect();
    for w in t[..10].windows(2) {
        assert!(w[1] > w[0], "in turn: {t:?}");
    }
    for a in &angles[..10] {
        assert!((a + 90.0).abs() < 10.0, "{angles:?}");
    }
    let c = c.unwrap();
    assert!(c > 3.0 && c < 15.0, "{c}");
}

#[test]
fn stiff_ribbons_k_and_2k_agree() {
    // "Stiff" ribbons (κ = k, G = 2e-4): doubling k moves the whole-chain
    // speed by less than 3 %.
    let keys = "added_mass = true\ndrag = true\n";
    let (_, c1, _) = run(&tank(keys, 86.0, 0.4, 14.0, 11), 0.125);
    let (_, c2, _) = run(
        &tank(
            &format!("{keys}stiff_gravity = 1e-4\n"),
            86.0,
            0.4,
            14.0,
            11,
        ),
        0.125,
    );
    let (c1, c2) = (c1.unwrap(), c2.unwrap());
    println!("k: {c1} cm/s, 2k: {c2} cm/s");
    assert!((c1 / c2 - 1.0).abs() < 3e-2, "{c1} {c2}");
}

#[test]
fn the_ribbon_tank_converges_in_its_step() {
    // RK4 at 0.125 τ against 0.0625 τ: every arrival within 0.02 s.
    let text = tank("added_mass = true\ndrag = true\n", 86.0, 0.4, 14.0, 11);
    let (a, _, _) = run(&text, 0.125);
    let (b, _, _) = run(&text, 0.0625);
    for (x, y) in a.iter().zip(&b) {
        let (x, y) = (x.unwrap(), y.unwrap());
        assert!((x - y).abs() < 0.02, "{a:?} {b:?}");
    }
}

/// The energy budget of the ribbon tank without drag (N = 6, acrylic
/// contact, 8 s) run by RK4 at `dt`, as the run keeps it (`sim::budget`:
/// W and D accumulated inside the integrator from every stage's powers).
fn ribbon_tank_budget(dt: f64) -> Budget {
    let text = tank(
        "added_mass = true\ncontact = \"acrylic\"\n",
        86.0,
        0.4,
        8.0,
        6,
    );
    let sc = parse(&text, "t", "t").unwrap().scenario().unwrap();
    let traj = sim::simulate(&sc, &[], &rk4(dt)).unwrap();
    traj.budget.expect("the toy as built keeps its budget")
}

/// Prints a budget and returns its residual as a fraction of the work.
fn relative_residual(what: &str, b: &Budget) -> f64 {
    let r = b.residual / b.work;
    println!(
        "{what}: ΔE {:.6e}, W {:.6e}, D {:.6e}, residual {:.3e} = {r:.2e} of W",
        b.energy_change, b.work, b.dissipated, b.residual
    );
    r
}

#[test]
fn the_energy_budget_of_the_ribbon_tank_closes() {
    // Without drag: the energy of the free blocks (kinetic with added
    // mass, ribbons, contact overlaps, gravity) changes by the work done
    // through block 1 less what the ribbons' dashpots and the contacts
    // dissipated, W and D accumulated by RK4 from the same stages as the
    // state (docs/experiments.md, "The energy budget of the toy as
    // built"). The plates clatter from 1300 τ on, and a contact's force
    // jumps where a corner touches (its dashpot, c δ̇), so the residual
    // shrinks as the step at first order, not RK4's fourth: measured
    // 5.6e-3, 2.8e-3, 1.4e-3, 4.2e-4 of W at 1/64, 1/128, 1/256, 1/512 τ.
    // Two steps a factor 4 apart show the order (first: 4, none: 1) at
    // a third of the cost of three halvings down to 1/512 τ.
    let steps = [1.0 / 64.0, 1.0 / 256.0];
    let r: Vec<f64> = steps
        .iter()
        .map(|&dt| {
            let b = ribbon_tank_budget(dt);
            assert!(b.dissipated > 0.5 * b.work, "{b:?}");
            relative_residual(&format!("dt = {dt} τ"), &b)
        })
        .collect();
    assert!(
        r[0].abs() > 2.5 * r[1].abs(),
        "a quarter of the step, at first order a quarter of the residual: {r:?}"
    );
    assert!(r[1].abs() < 2e-3, "{r:?}");
}

#[test]
fn the_energy_budget_of_the_toy_in_air_closes() {
    // The toy in air (assets/scenes/toy.toml): the hand turns block 1
    // over and the blocks clatter down (about 50 impacts in 1855 τ).
    // The residual at 0.0025 τ is within 1e-3 of W and well below the
    // one at 0.01 τ (measured 2.0e-3 and 4.4e-5 of W: the clatter is
    // chaotic, so each step's run has impacts of its own).
    let sc = toy_in_air();
    let r: Vec<f64> = [0.01, 0.0025]
        .iter()
        .map(|&dt| {
            let traj = sim::simulate(&sc, &[], &rk4(dt)).unwrap();
            assert!(traj.impacts.as_ref().is_some_and(|i| i.len() > 20));
            let b = traj.budget.expect("the toy as built keeps its budget");
            assert!(b.dissipated > 0.5 * b.work, "{b:?}");
            relative_residual(&format!("dt = {dt} τ"), &b)
        })
        .collect();
    assert!(r[0].abs() > 2.0 * r[1].abs(), "{r:?}");
    assert!(r[1].abs() < 1e-3, "{r:?}");
}

/// The toy in air of assets/scenes/toy.toml.
fn toy_in_air() -> sim::Scenario {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/assets/scenes/toy.toml"
    ))
    .unwrap();
    parse(&text, "toy", "toy").unwrap().scenario().unwrap()
}

#[test]
fn keeping_the_budget_leaves_the_run_bit_for_bit() {
    // The tank with drag and contact (its scene's step) and the toy in
    // air through its clatter: the same states, every τ, with the budget
    // kept and without.
    let text = tank(
        "added_mass = true\ndrag = true\ncontact = \"acrylic\"\n",
        86.0,
        0.4,
        8.0,
        6,
    );
    let tank = parse(&text, "t", "t").unwrap().scenario().unwrap();
    for (sc, dt) in [(tank, 1.0 / 32.0), (toy_in_air(), 0.02)] {
        let samples: Vec<f64> = (0..sc.t_end as usize).map(|k| k as f64).collect();
        let bits = |keep: bool| {
            let options = sim::RunOptions::default().budget(keep);
            let traj = sim::run(&sc, &samples, &rk4(dt), &options).unwrap();
            assert_eq!(traj.budget.is_some(), keep);
            let bits: Vec<u64> = traj
                .states
                .iter()
                .chain(&traj.velocities)
                .flatten()
                .chain(&traj.final_state.q)
                .chain(&traj.final_state.v)
                .map(|x| x.to_bits())
                .collect();
            (bits, traj.arrival_times, traj.impacts.map(|i| i.len()))
        };
        let (with, without) = (bits(true), bits(false));
        println!("{:?} impacts", with.2);
        assert!(with == without, "keeping the budget moved the run");
    }
}

#[test]
fn a_mirrored_apparatus_moves_as_the_mirror_image() {
    // y → −y maps a block at θ to π − θ (t keeps its x part, ν turns
    // over) and each ribbon to the other face (`ribbon_mirror`); block 1
    // then turns the other way round, π/2 → 3π/2. Every arrival agrees.
    let text = tank("added_mass = true\ndrag = true\n", 86.0, 0.4, 10.0, 6);
    let scene = parse(&text, "t", "t").unwrap();
    let sc = scene.scenario().unwrap();
    let mirrored = parse(
        &tank(
            "added_mass = true\ndrag = true\nribbon_mirror = true\n",
            86.0,
            0.4,
            10.0,
            6,
        ),
        "t",
        "t",
    )
    .unwrap()
    .scenario()
    .unwrap();
    let mut sm = sc.clone();
    sm.ladder = mirrored.ladder;
    let t_d = sc.protocol.drive().unwrap().end();
    let half_pi = std::f64::consts::FRAC_PI_2;
    sm.protocol = Protocol::Driven(Drive::new(vec![(0.0, half_pi), (t_d, 3.0 * half_pi)]).unwrap());
    let a = sim::simulate(&sc, &[], &rk4(0.125)).unwrap();
    let b = sim::simulate(&sm, &[], &rk4(0.125)).unwrap();
    println!("{:?}\n{:?}", a.arrival_times, b.arrival_times);
    for (x, y) in a.arrival_times.iter().zip(&b.arrival_times) {
        let (x, y) = (x.unwrap(), y.unwrap());
        assert!((x - y).abs() < 1e-6 * x, "{x} {y}");
    }
    let (qa, qb) = (&a.final_state.q, &b.final_state.q);
    for i in 0..sc.ladder.n() {
        assert!((qa[3 * i] - qb[3 * i]).abs() < 1e-6);
        assert!((qa[3 * i + 1] + qb[3 * i + 1]).abs() < 1e-6);
    }
}

#[test]
fn the_ribbons_that_break_the_kink_antikink_symmetry_are_named() {
    // The map between kink and antikink (every block turned over, y
    // mirrored) takes a ribbon glued at x on a face to 1 − x on the same
    // face: glued at the ends (0 on one face, 1 on the other) both
    // ribbons break it; glued at mid-face none does.
    let names = |extra: &str| {
        let scene = parse(&tank(extra, 86.0, 0.2, 1.0, 4), "t", "t").unwrap();
        scene.apparatus.unwrap().symmetry_breakers()
    };
    let ends = names("");
    println!("{ends:?}");
    assert_eq!(ends.len(), 2, "{ends:?}");
    assert!(ends[0].contains("ribbon 1") && ends[1].contains("ribbon 2"));
    assert!(names("ribbon_anchors = [0.5, 0.5]\n").is_empty());
    assert_eq!(names("ribbon_anchors = [0.5, 0.0]\n").len(), 1);
}

/// Every state of the run of `sc` sampled at `samples`, the final state
/// and the arrivals, as bits, the common tangents searched warm (started
/// from the last evaluation's, as the program runs) or cold (from the
/// anchors, every time).
pub fn run_bits(
    sc: &sim::Scenario,
    samples: &[f64],
    cfg: &IntegratorConfig,
    warm: bool,
) -> (Vec<u64>, Vec<Option<f64>>) {
    run_bits_searched(sc, samples, cfg, (warm, true))
}

/// [`run_bits`] with the search's two short cuts set: `(warm, prune)`,
/// started from the last evaluation's tangent points, and a pair of ways
/// round that shares an earlier pair's not searched again (`prune`
/// counts only searching warm).
pub fn run_bits_searched(
    sc: &sim::Scenario,
    samples: &[f64],
    cfg: &IntegratorConfig,
    (warm, prune): (bool, bool),
) -> (Vec<u64>, Vec<Option<f64>>) {
    let mut sc = sc.clone();
    let mut built = sc.ladder.built.unwrap();
    built.ribbons.warm = warm;
    built.ribbons.prune = prune;
    sc.ladder.built = Some(built);
    let traj = sim::simulate(&sc, samples, cfg).unwrap();
    let bits = traj
        .states
        .iter()
        .flatten()
        .chain(&traj.final_state.q)
        .chain(&traj.final_state.v)
        .map(|x| x.to_bits())
        .collect();
    (bits, traj.arrival_times)
}

#[test]
fn the_warm_tangent_search_runs_the_tank_as_the_cold_one_bit_for_bit() {
    // The tank at 0.2 Hz through every plate's flip (20 s), each common
    // tangent started from the last evaluation's against searched from
    // the anchors every time: the same states, bit for bit, every τ.
    let text = tank("added_mass = true\ndrag = true\n", 86.0, 0.2, 20.0, 11);
    let sc = parse(&text, "t", "t").unwrap().scenario().unwrap();
    let samples: Vec<f64> = (0..sc.t_end as usize).map(|k| k as f64).collect();
    let (warm, arrivals) = run_bits(&sc, &samples, &rk4(0.125), true);
    let (cold, cold_arrivals) = run_bits(&sc, &samples, &rk4(0.125), false);
    assert!(arrivals.iter().all(|t| t.is_some()), "{arrivals:?}");
    assert_eq!(arrivals, cold_arrivals);
    assert!(warm == cold, "the warm search moved the run");
}

#[test]
fn the_pruned_way_search_runs_the_tank_as_the_full_one_bit_for_bit() {
    // The scene's ribbon tank (drag, acrylic contact, its step 1/32 τ,
    // 20 s through every flip) and the tank without drag whose plates
    // clatter (N = 6, 8 s): each pair of ways round searched (warm)
    // against a pair that has an earlier pair's tangent points at its
    // anchor taking them unsearched: the same states, every τ.
    let scene = tank(
        "added_mass = true\ndrag = true\ncontact = \"acrylic\"\n",
        86.0,
        0.2,
        20.0,
        11,
    );
    let clatter = tank(
        "added_mass = true\ncontact = \"acrylic\"\n",
        86.0,
        0.4,
        8.0,
        6,
    );
    for text in [scene, clatter] {
        let sc = parse(&text, "t", "t").unwrap().scenario().unwrap();
        let samples: Vec<f64> = (0..sc.t_end as usize).map(|k| k as f64).collect();
        let cfg = rk4(1.0 / 32.0);
        let (pruned, arrivals) = run_bits_searched(&sc, &samples, &cfg, (true, true));
        let (full, full_arrivals) = run_bits_searched(&sc, &samples, &cfg, (true, false));
        assert!(arrivals.iter().any(|t| t.is_some()), "{arrivals:?}");
        assert_eq!(arrivals, full_arrivals);
        assert!(pruned == full, "the pruned search moved the run");
    }
}
