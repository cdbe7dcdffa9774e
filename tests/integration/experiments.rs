//! The terms of docs/experiments.md against physics: buoyancy, terminal
//! velocity, periods with added mass, the Lagrangian velocity terms, the
//! energy budget of a water-tank run, slack tape, stiff links, the
//! kink–antikink symmetry at a = b, and bad apparatus values.

use jacobs_ladder::model::ladder::{itheta, ix, iy};
use jacobs_ladder::model::links::{Links, PinFriction};
use jacobs_ladder::model::media::{self, Terms};
use jacobs_ladder::model::{Ladder, Params};
use jacobs_ladder::scene::file::parse;
use jacobs_ladder::sim::speed::wave_speed;
use jacobs_ladder::sim::{
    self, Drive, IntegratorConfig, IntegratorKind, Protocol, Scenario, Start, State,
};

/// A water-tank scene file with `extra` apparatus keys.
fn tank(extra: &str, alpha: f64, motor: f64, duration: f64) -> String {
    format!(
        "[model]\nalpha = {alpha}\nn = 11\n[apparatus]\ns = 5.0\nb = 7.5\nthickness = 0.3\n\
         density = 1.2\nmedium = \"water\"\nmedium_density = 1.0\nmotor = {motor}\n\
         duration = {duration}\n{extra}\n[output]\nkind = \"data\"\n"
    )
}

fn rk4(dt: f64) -> IntegratorConfig {
    IntegratorConfig::fixed(IntegratorKind::Rk4, dt)
}

/// A ladder of `n` blocks at `alpha` (degrees, |α| ≤ 90 allowed) with
/// `terms`, block 1 held at angle `hold`, from `q0` at rest.
fn scenario(params: Params, terms: Terms, hold: f64, q0: Vec<f64>, t_end: f64) -> Scenario {
    Scenario {
        ladder: Ladder::new(params).with_terms(terms),
        protocol: Protocol::Driven(Drive::hold(hold)),
        initial: State::at_rest(q0),
        t_end,
    }
}

#[test]
fn buoyant_hanging_load_scales_with_one_minus_density_ratio() {
    // The hanging chain (`start = "relaxed"`, block 1 held) carries its
    // weight in the medium: the links pull block 1 down with
    // (N − 1) m g (1 − ρ_m/ρ), whatever the geometry. In dyn, from the
    // links' forces at the relaxed state and the apparatus' k and s.
    let load = |density: f64, medium: &str, rho_m: f64| {
        let text = format!(
            "[model]\nalpha = 60\nn = 10\nstart = \"relaxed\"\n[apparatus]\ns = 5.0\nb = 6.5\n\
             thickness = 0.3\ndensity = {density}\nmedium = \"{medium}\"\nmedium_density = {rho_m}\n\
             stiffness = 400.0\nbuoyancy = true\nduration = 1.0\n[output]\nkind = \"data\"\n"
        );
        let scene = parse(&text, "test", "test").unwrap();
        let conv = scene
            .apparatus
            .as_ref()
            .unwrap()
            .conversion
            .clone()
            .unwrap();
        let sc = scene.scenario().unwrap();
        let mut grad = vec![0.0; 3 * sc.ladder.n()];
        Links::default().gradient(&sc.ladder, &sc.initial.q, &mut grad);
        let pull = -(grad[ix(0)] + sc.ladder.params.gravity);
        let dyn_per_unit = conv.stiffness_n_per_m * 1e3 * 5.0;
        (pull * dyn_per_unit, conv.mass_g)
    };
    for (rho, medium, rho_m) in [
        (1.2, "water", 1.0),
        (2.0, "water", 1.0),
        (1.2, "air", 1.2e-3),
        (3.0, "water", 0.5),
    ] {
        let (pull, m) = load(rho, medium, rho_m);
        let expected = 9.0 * m * 981.0 * (1.0 - rho_m / rho);
        assert!(
            (pull / expected - 1.0).abs() < 1e-6,
            "rho = {rho}, rho_m = {rho_m}: pull {pull} dyn, (N - 1) m g (1 - rho_m/rho) = {expected}"
        );
    }
    let (water, _) = load(1.2, "water", 1.0);
    let (vacuum, _) = load(1.2, "air", 0.0);
    assert!(
        (water / vacuum - 1.0 / 6.0).abs() < 1e-7,
        "{}",
        water / vacuum
    );
}

#[test]
fn lone_plate_falls_broadside_at_its_terminal_velocity() {
    // Block 2 on slack tape (long rest lengths) falls freely, broadside
    // (θ = 0: its normal is the x axis, along gravity), against quadratic
    // drag: (m + m_a) dv/dt = m g* − c s v², so v(t) = v_t tanh(t/t_v) with
    // v_t = √(m g*/(c s)) = √(2 m g*/(ρ_m C_D A)) and
    // t_v = (m + m_a)/√(m g* c s).
    for added in [0.0, 6.3] {
        let g = 2e-4;
        let c = 8.1;
        let params = Params::paper(10.0)
            .unwrap()
            .with_n(2)
            .with_b(30.0)
            .with_gamma(0.0)
            .with_gravity(g)
            .with_inertia(0.0837)
            .validated()
            .unwrap();
        let terms = Terms {
            added_mass: added,
            added_inertia: 0.1 * added,
            drag: c,
            links: Links {
                stiffness: 1.0,
                tension_only: true,
            },
            friction: None,
        };
        let mut q0 = vec![0.0; 6];
        q0[itheta(0)] = 0.0;
        q0[ix(1)] = 0.0;
        q0[iy(1)] = 3.0;
        q0[itheta(1)] = 0.0;
        let vt = (g / c).sqrt();
        let tv = (1.0 + added) / (g * c).sqrt();
        let t_end = 8.0 * tv;
        let sc = scenario(params, terms, 0.0, q0, t_end);
        let times: Vec<f64> = (1..=8).map(|k| k as f64 * tv).collect();
        let traj = sim::simulate(&sc, &times, &rk4(0.05)).unwrap();
        for (t, v) in traj.times.iter().zip(&traj.velocities) {
            let exact = vt * (t / tv).tanh();
            assert!(
                (v[ix(1)] - exact).abs() < 1e-7 * vt,
                "m_a = {added}, t = {t}: v = {}, exact {exact}",
                v[ix(1)]
            );
            assert!(v[iy(1)].abs() < 1e-15 && v[itheta(1)].abs() < 1e-15);
        }
        // And the terminal speed from the apparatus' own numbers, in cm/s.
        let scene = parse(
            &tank("buoyancy = true\ndrag = true\n", 86.0, 0.2, 1.0),
            "t",
            "t",
        )
        .unwrap();
        let conv = scene.apparatus.unwrap().conversion.unwrap();
        let model_vt = (conv.gravity / conv.drag).sqrt() * 5.0 / conv.tau_s;
        let (m, gstar, rho, cd, area): (f64, f64, f64, f64, f64) =
            (9.0, 981.0 / 6.0, 1.0, 1.17, 25.0);
        let physical = (2.0 * m * gstar / (rho * cd * area)).sqrt();
        assert!(
            (model_vt / physical - 1.0).abs() < 1e-12,
            "{model_vt} {physical}"
        );
    }
}

/// Period of a block of added mass `ma` on an isotropic spring of
/// stiffness `k` at its centre, released from rest at `x0` (normal or
/// along the plate), by RK4 on `media::block_acceleration`.
fn block_period(ma: f64, k: f64, x0: [f64; 2]) -> f64 {
    let (i, theta) = (1, 0.0); // t = (0, −1), ν = (1, 0)
    let j = 0.25;
    let acc = |x: [f64; 2], v: [f64; 2]| {
        let a = media::block_acceleration(
            ma,
            j,
            i,
            theta,
            [v[0], v[1], 0.0],
            [-k * x[0], -k * x[1], 0.0],
        );
        [a[0], a[1]]
    };
    let (mut x, mut v) = (x0, [0.0, 0.0]);
    let h = 1e-3;
    let mut t = 0.0;
    let mut crossings = Vec::new();
    let along = if x0[0] != 0.0 { 0 } else { 1 };
    while crossings.len() < 3 {
        let k1 = (v, acc(x, v));
        let x2 = [x[0] + 0.5 * h * k1.0[0], x[1] + 0.5 * h * k1.0[1]];
        let v2 = [v[0] + 0.5 * h * k1.1[0], v[1] + 0.5 * h * k1.1[1]];
        let k2 = (v2, acc(x2, v2));
        let x3 = [x[0] + 0.5 * h * k2.0[0], x[1] + 0.5 * h * k2.0[1]];
        let v3 = [v[0] + 0.5 * h * k2.1[0], v[1] + 0.5 * h * k2.1[1]];
        let k3 = (v3, acc(x3, v3));
        let x4 = [x[0] + h * k3.0[0], x[1] + h * k3.0[1]];
        let v4 = [v[0] + h * k3.1[0], v[1] + h * k3.1[1]];
        let k4 = (v4, acc(x4, v4));
        let old = x[along];
        for d in 0..2 {
            x[d] += h / 6.0 * (k1.0[d] + 2.0 * k2.0[d] + 2.0 * k3.0[d] + k4.0[d]);
            v[d] += h / 6.0 * (k1.1[d] + 2.0 * k2.1[d] + 2.0 * k3.1[d] + k4.1[d]);
        }
        if old > 0.0 && x[along] <= 0.0 {
            // Upward-to-downward zero crossing, interpolated.
            crossings.push(t + h * old / (old - x[along]));
        }
        t += h;
    }
    crossings[2] - crossings[1]
}

#[test]
fn periods_with_and_without_added_mass_normal_and_along_the_plate() {
    use std::f64::consts::TAU;
    let (k, ma) = (1.0, 6.3);
    let normal = block_period(ma, k, [0.01, 0.0]);
    let along = block_period(ma, k, [0.0, 0.01]);
    let bare = block_period(0.0, k, [0.01, 0.0]);
    assert!(
        (normal / (TAU * ((1.0 + ma) / k).sqrt()) - 1.0).abs() < 1e-6,
        "{normal}"
    );
    assert!(
        (along / (TAU * (1.0 / k).sqrt()) - 1.0).abs() < 1e-6,
        "{along}"
    );
    assert!(
        (bare / (TAU * (1.0 / k).sqrt()) - 1.0).abs() < 1e-6,
        "{bare}"
    );

    // Along the plate through the whole ladder: at α = 90° (a = b) block 2
    // hangs below block 1 on two parallel links; its motion along its
    // length (x) stretches both, 2π√(m/2k), whatever the added mass.
    let params = Params::paper(90.0)
        .unwrap()
        .with_n(2)
        .with_b(1.5)
        .with_gamma(0.0)
        .with_gravity(0.0)
        .with_inertia(0.0837)
        .validated()
        .unwrap();
    let terms = Terms {
        added_mass: ma,
        added_inertia: 0.3,
        ..Terms::default()
    };
    let mut q0 = Ladder::new(params).ground_state();
    let x_rest = q0[ix(1)];
    q0[ix(1)] += 0.01;
    let period = TAU * (1.0f64 / 2.0).sqrt();
    let times: Vec<f64> = (0..=400).map(|k| k as f64 * period / 100.0).collect();
    let sc = scenario(params, terms, params.alpha, q0, 4.0 * period);
    let traj = sim::simulate(&sc, &times, &rk4(0.005)).unwrap();
    for (t, q) in traj.times.iter().zip(&traj.states) {
        let exact = 0.01 * (TAU * t / period).cos();
        assert!((q[ix(1)] - x_rest - exact).abs() < 1e-9, "t = {t}");
    }
}

#[test]
fn a_free_plate_keeps_its_impulse_and_energy() {
    // No force: Lagrange's velocity terms must conserve the kinetic energy
    // and the linear impulse M V = m V + m_a (V·ν) ν, while the Munk
    // moment turns a plate moving obliquely (here with tension-only links
    // slack all along, no gravity, no damping).
    let params = Params::paper(10.0)
        .unwrap()
        .with_n(2)
        .with_b(50.0)
        .with_gamma(0.0)
        .with_gravity(0.0)
        .with_inertia(0.0837)
        .validated()
        .unwrap();
    let terms = Terms {
        added_mass: 6.3,
        added_inertia: 0.4,
        links: Links {
            stiffness: 1.0,
            tension_only: true,
        },
        ..Terms::default()
    };
    let mut q0 = vec![0.0; 6];
    q0[iy(1)] = 5.0;
    q0[itheta(1)] = 0.3;
    let mut sc = scenario(params, terms, 0.0, q0, 40.0);
    sc.initial.v[ix(1)] = 0.03;
    sc.initial.v[iy(1)] = 0.02;
    sc.initial.v[itheta(1)] = 0.01;
    let ladder = sc.ladder;
    let impulse = |q: &[f64], v: &[f64]| {
        let (_, nu) = media::frame(1, q[itheta(1)]);
        let vn = v[ix(1)] * nu[0] + v[iy(1)] * nu[1];
        [v[ix(1)] + 6.3 * vn * nu[0], v[iy(1)] + 6.3 * vn * nu[1]]
    };
    let times: Vec<f64> = (0..=40).map(f64::from).collect();
    let traj = sim::simulate(&sc, &times, &rk4(0.01)).unwrap();
    let (p0, e0) = (
        impulse(&sc.initial.q, &sc.initial.v),
        media::kinetic_energy(&ladder, &terms, &sc.initial.q, &sc.initial.v, true),
    );
    for (q, v) in traj.states.iter().zip(&traj.velocities) {
        let p = impulse(q, v);
        let e = media::kinetic_energy(&ladder, &terms, q, v, true);
        assert!((p[0] - p0[0]).abs() < 1e-12 && (p[1] - p0[1]).abs() < 1e-12);
        assert!((e / e0 - 1.0).abs() < 1e-10, "{e} {e0}");
    }
    // The plate did turn (the Munk moment), by more than its spin alone.
    let last = traj.states.last().unwrap();
    let spin_only = 0.3 + 0.01 * 40.0;
    assert!((last[itheta(1)] - spin_only).abs() > 1e-2);
}

/// Composite Simpson's rule on equally spaced samples (an even number of
/// intervals).
fn simpson(y: &[f64], h: f64) -> f64 {
    assert!(y.len() % 2 == 1);
    let n = y.len() - 1;
    let inner: f64 = (1..n)
        .map(|k| if k % 2 == 1 { 4.0 * y[k] } else { 2.0 * y[k] })
        .sum();
    (y[0] + y[n] + inner) * h / 3.0
}

#[test]
fn water_tank_energy_budget_closes() {
    // Whole run: the energy of the free blocks (kinetic with added mass,
    // links and gravity) changes by the motor's work less the work of
    // linear damping and of quadratic drag. The motor's power is
    // θ̇_1 ∂U/∂θ_1 (block 1's centre is held); the velocity terms of the
    // added mass do no work.
    let text = tank(
        "buoyancy = true\ndrag = true\nadded_mass = true\ntension_only = true\ndamping = \"paper\"\n",
        86.0,
        0.4,
        14.0,
    );
    let scene = parse(&text, "t", "t").unwrap();
    let sc = scene.scenario().unwrap();
    let t_d = sc.protocol.drive().unwrap().end();
    let steps_drive = 2 * (t_d / 0.5).ceil() as usize;
    let h1 = t_d / steps_drive as f64;
    let rest = sc.t_end - t_d;
    let steps_rest = 2 * (rest / 0.5).ceil() as usize;
    let h2 = rest / steps_rest as f64;
    let mut times: Vec<f64> = (0..=steps_drive).map(|k| k as f64 * h1).collect();
    times.extend((1..=steps_rest).map(|k| t_d + k as f64 * h2));
    let traj = sim::simulate(&sc, &times, &rk4(h1.min(h2) / 2.0)).unwrap();
    let ladder = sc.ladder;
    let terms = ladder.terms;
    let energy = |q: &[f64], v: &[f64]| {
        media::kinetic_energy(&ladder, &terms, q, v, true)
            + media::potential_energy(&ladder, &terms, q)
    };
    let mut grad = vec![0.0; q_len(&ladder)];
    let mut drive = Vec::new();
    let (mut linear, mut drag) = (Vec::new(), Vec::new());
    for (q, v) in traj.states.iter().zip(&traj.velocities) {
        terms.links.gradient(&ladder, q, &mut grad);
        drive.push(v[itheta(0)] * grad[itheta(0)]);
        let (l, d, f) = media::dissipation(&ladder, &terms, q, v, 1);
        assert_eq!(f, 0.0);
        linear.push(l);
        drag.push(d);
    }
    // The drive's power jumps at T_d: integrate each piece on its own.
    let split = steps_drive;
    let work = |y: &[f64]| simpson(&y[..=split], h1) + simpson(&y[split..], h2);
    let (w_drive, w_linear, w_drag) = (work(&drive), work(&linear), work(&drag));
    let e0 = energy(&traj.states[0], &traj.velocities[0]);
    let e1 = energy(traj.states.last().unwrap(), traj.velocities.last().unwrap());
    let residual = (e1 - e0) - (w_drive - w_linear - w_drag);
    println!(
        "ΔE = {:.6e}, drive {w_drive:.6e}, linear {w_linear:.6e}, drag {w_drag:.6e}, residual {residual:.3e}",
        e1 - e0
    );
    assert!(w_drag > 0.1 * w_drive && w_linear > 0.0);
    assert!(
        residual.abs() < 1e-4 * w_drive,
        "residual {residual:e} of {w_drive:e}"
    );
}

fn q_len(ladder: &Ladder) -> usize {
    3 * ladder.n()
}

#[test]
fn a_slack_tape_pushes_nothing() {
    // Blocks pushed together: every link shorter than its rest length.
    let params = Params::paper(60.0).unwrap();
    let ladder = Ladder::new(params);
    let mut q = ladder.ground_state();
    for i in 0..ladder.n() {
        q[ix(i)] *= 0.5;
    }
    let tape = Links {
        stiffness: 1.0,
        tension_only: true,
    };
    let mut grad = vec![0.0; q.len()];
    tape.gradient(&ladder, &q, &mut grad);
    for (k, g) in grad.iter().enumerate() {
        let gravity = if k % 3 == 0 { -params.gravity } else { 0.0 };
        assert_eq!(*g, gravity, "coordinate {k}");
    }
    assert_eq!(tape.elastic_energy(&ladder, &q), 0.0);
    // The paper's two-way springs push at the same state.
    Links::default().gradient(&ladder, &q, &mut grad);
    assert!(grad.iter().skip(3).any(|g| g.abs() > 1e-3));
}

#[test]
fn integrators_that_cannot_take_a_term_are_refused() {
    let scene = parse(&tank("drag = true\n", 86.0, 0.2, 1.0), "t", "t").unwrap();
    let sc = scene.scenario().unwrap();
    for kind in [IntegratorKind::SymplecticEuler, IntegratorKind::Verlet] {
        let e = sim::simulate(&sc, &[], &IntegratorConfig::fixed(kind, 0.1)).unwrap_err();
        assert!(e.to_string().contains("quadratic drag"), "{e}");
    }
    // Tension-only tape alone is a force of the positions: Verlet takes it.
    let scene = parse(&tank("tension_only = true\n", 86.0, 0.2, 0.05), "t", "t").unwrap();
    let sc = scene.scenario().unwrap();
    sim::simulate(
        &sc,
        &[],
        &IntegratorConfig::fixed(IntegratorKind::Verlet, 0.25),
    )
    .unwrap();
}

/// Speed (blocks per τ) over the lower half of the chain, blocks
/// N/2 + 1 .. N − 1 (one-based): the steady wave, after what happens next
/// to the driven block (least squares of t_n against n, as `wave_speed`).
fn bulk_speed(arrivals: &[Option<f64>]) -> Option<f64> {
    let n = arrivals.len();
    let pts: Vec<(f64, f64)> = (n / 2..n - 1)
        .filter_map(|i| arrivals[i].map(|t| (i as f64, t)))
        .collect();
    (pts.len() >= 3).then(|| {
        let m = pts.len() as f64;
        let (mx, my) = pts
            .iter()
            .fold((0.0, 0.0), |(a, b), p| (a + p.0 / m, b + p.1 / m));
        let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
        let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
        sxx / sxy
    })
}

/// A tank run with `extra` keys: (whole-chain speed, bulk speed) in cm/s
/// (`None` where fewer than three blocks flipped), and the arrival times in s.
fn tank_run(
    extra: &str,
    alpha: f64,
    motor: f64,
    duration: f64,
) -> (Option<f64>, Option<f64>, Vec<Option<f64>>) {
    let scene = parse(&tank(extra, alpha, motor, duration), "t", "t").unwrap();
    let conv = scene
        .apparatus
        .as_ref()
        .unwrap()
        .conversion
        .clone()
        .unwrap();
    let sc = scene.scenario().unwrap();
    let traj = sim::simulate(&sc, &[], &rk4(0.125)).unwrap();
    let cm = |c: Option<f64>| c.map(|c| c * conv.cm_per_s);
    let seconds = traj
        .arrival_times
        .iter()
        .map(|a| a.map(|t| t * conv.tau_s))
        .collect();
    (
        cm(wave_speed(&traj.arrival_times)),
        cm(bulk_speed(&traj.arrival_times)),
        seconds,
    )
}

#[test]
fn stiff_links_k_and_2k_agree() {
    // "Stiff" links: k = m g*/(s G) at G = 2e-4; doubling k (G = 1e-4)
    // changes the wave's speed in the bulk by less than 1 % with buoyancy
    // and drag, 3 % with added mass too (where the blocks next to the
    // driven one turn together, an event that moves with k).
    for (level, tolerance) in [
        ("buoyancy = true\ndrag = true\n", 1e-2),
        ("buoyancy = true\ndrag = true\nadded_mass = true\n", 3e-2),
    ] {
        let (_, c1, _) = tank_run(level, 86.0, 0.4, 14.0);
        let (_, c2, _) = tank_run(&format!("{level}stiff_gravity = 1e-4\n"), 86.0, 0.4, 14.0);
        let (c1, c2) = (c1.unwrap(), c2.unwrap());
        println!("k: {c1} cm/s, 2k: {c2} cm/s");
        assert!((c1 / c2 - 1.0).abs() < tolerance, "{c1} {c2}");
    }
}

/// Kink and antikink speeds (blocks per τ) of an 8-block ladder at `alpha`
/// (±) with `terms` and linear damping `gamma`, block 1 flipped over 400 τ.
/// The arrival times of the kink (α) and the antikink (−α) of a ladder
/// of 8 blocks with `terms`.
fn kink_and_antikink_arrivals(
    alpha: f64,
    gamma: f64,
    terms: Terms,
) -> (Vec<Option<f64>>, Vec<Option<f64>>) {
    let arrivals = |alpha: f64| {
        let p = Params::paper(alpha)
            .unwrap()
            .with_n(8)
            .with_b(1.5)
            .with_gamma(gamma)
            .with_gravity(2e-4)
            .with_inertia(0.0837)
            .validated()
            .unwrap();
        let ladder = Ladder::new(p).with_terms(terms);
        let sc = Scenario {
            ladder,
            protocol: Protocol::Driven(Drive::single_flip(p.alpha, 400.0).unwrap()),
            initial: State::at_rest(ladder.ground_state()),
            t_end: 6000.0,
        };
        sim::simulate(&sc, &[], &rk4(0.25)).unwrap().arrival_times
    };
    (arrivals(alpha), arrivals(-alpha))
}

fn kink_and_antikink(alpha: f64, gamma: f64, terms: Terms) -> (Option<f64>, Option<f64>) {
    let (k, a) = kink_and_antikink_arrivals(alpha, gamma, terms);
    (wave_speed(&k), wave_speed(&a))
}

#[test]
fn symmetric_terms_give_equal_kink_and_antikink_speeds_at_a_equal_b() {
    // At a = b (α = ±90°) turning every block over and mirroring y maps the
    // kink onto the antikink; each term of docs/experiments.md respects it, so with
    // each term on (over quadratic drag, which damps the wave) the two
    // runs' arrival times, and so their speeds, agree to 1e-6. The test
    // names the term that breaks it. (At a = b exactly several of these
    // sets turn whole groups of blocks at once rather than run a steady
    // wave, where `wave_speed` gives none: the arrivals are compared, which
    // the mirror maps onto each other whatever the motion.)
    let drag = Terms {
        drag: 8.1,
        ..Terms::default()
    };
    let tape = Links {
        stiffness: 1.0,
        tension_only: true,
    };
    let friction = Some(PinFriction {
        mu_rp: 0.01,
        omega_eps: 0.01,
    });
    let cases: [(&str, f64, Terms); 7] = [
        (
            "linear damping γ (the paper's model)",
            0.02,
            Terms::default(),
        ),
        ("quadratic drag", 0.0, drag),
        (
            "added mass and inertia",
            0.0,
            Terms {
                added_mass: 6.3,
                added_inertia: 0.05,
                ..drag
            },
        ),
        (
            "tension-only tape",
            0.0,
            Terms {
                links: tape,
                ..drag
            },
        ),
        ("pin friction", 0.0, Terms { friction, ..drag }),
        (
            "stiffer links (k doubled)",
            0.0,
            Terms {
                links: Links {
                    stiffness: 2.0,
                    tension_only: false,
                },
                ..drag
            },
        ),
        (
            "every term",
            0.02,
            Terms {
                added_mass: 6.3,
                added_inertia: 0.05,
                drag: 8.1,
                links: tape,
                friction,
            },
        ),
    ];
    let mut broken = Vec::new();
    for (name, gamma, terms) in cases {
        // The mirror maps every arrival of the kink's run onto the
        // antikink's: the same blocks flip, at the same times to 1e-6.
        let (k, a) = kink_and_antikink_arrivals(90.0, gamma, terms);
        let flipped = k.iter().filter(|t| t.is_some()).count();
        assert!(flipped >= 3, "{name}: the kink flipped {flipped} blocks");
        let apart = k
            .iter()
            .zip(&a)
            .map(|(k, a)| match (k, a) {
                (Some(k), Some(a)) => (k - a).abs() / k.abs().max(1.0),
                (None, None) => 0.0,
                _ => f64::INFINITY,
            })
            .fold(0.0, f64::max);
        println!("a = b, {name}: {flipped} blocks, arrivals apart by {apart:.2e} (relative)");
        if apart >= 1e-6 {
            broken.push(format!("{name} (arrivals apart by {apart:.2e})"));
        }
    }
    assert!(
        broken.is_empty(),
        "terms that break the kink–antikink symmetry at a = b: {}",
        broken.join(", ")
    );
    // What does break it: a ≠ b. At α = 86° (the tank's scenes) the two
    // speeds differ by more than 1e-3, so the comparison above can fail.
    let (k, a) = kink_and_antikink(86.0, 0.0, drag);
    let (k, a) = (k.unwrap(), a.unwrap());
    println!("α = 86° (a ≠ b): c_antikink/c_kink = {}", a / k);
    assert!((a / k - 1.0).abs() > 1e-3, "a ≠ b: {k} {a}");
}

#[test]
fn linkage_speeds_converge_in_the_friction_rate() {
    // The printed linkage at μ_p = 0.3: the smoothed Coulomb law's rate
    // ω_ε (apparatus.friction_rate, rad/s) halved moves the kink's and the
    // antikink's speeds by less than 1 % (docs/experiments.md: 0.2 %),
    // while the friction itself slows them by more than 10 % (μ_p = 0).
    let run = |alpha: f64, mu: f64, rate: f64| {
        let text = format!(
            "[model]\nalpha = {alpha}\nn = 8\nstart = \"relaxed\"\n[apparatus]\ns = 5.0\nb = 6.0\n\
             a = 7.0\nthickness = 0.5\ndensity = 1.24\nmedium = \"air\"\ndrag = true\n\
             pin_friction = {mu}\npin_radius = 0.15\nfriction_rate = {rate}\nmotor = 0.2\n\
             duration = 5.0\n[output]\nkind = \"data\"\n"
        );
        let sc = parse(&text, "linkage", "linkage")
            .unwrap()
            .scenario()
            .unwrap();
        let traj = sim::simulate(&sc, &[], &rk4(0.125)).unwrap();
        wave_speed(&traj.arrival_times)
            .unwrap_or_else(|| panic!("α = {alpha}, μ_p = {mu}: no wave"))
    };
    for alpha in [69.0, -69.0] {
        let (c, half, free) = (
            run(alpha, 0.3, 0.05),
            run(alpha, 0.3, 0.025),
            run(alpha, 0.0, 0.05),
        );
        println!("α = {alpha}: ω_ε = 0.05: {c}, 0.025: {half}, no friction: {free} blocks/τ");
        assert!((c / half - 1.0).abs() < 1e-2, "α = {alpha}: {c} {half}");
        assert!(
            free > 1.1 * c,
            "α = {alpha}: friction does not slow the wave: {free} {c}"
        );
    }
}

#[test]
fn bad_apparatus_values_name_file_line_and_key() {
    let text = tank("drag_coefficient = -1.0\n", 86.0, 0.2, 1.0);
    let e = parse(&text, "tank.toml", "t").unwrap_err().to_string();
    assert!(e.starts_with("tank.toml:13:"), "{e}");
    assert!(e.contains("apparatus.drag_coefficient"), "{e}");
    let text = tank("", 86.0, 0.2, 1.0).replace("density = 1.2", "density = 0.5\nbuoyancy = true");
    let e = parse(&text, "tank.toml", "t").unwrap_err().to_string();
    assert!(
        e.contains("apparatus.buoyancy") && e.contains("float"),
        "{e}"
    );
    let text = tank("a = 7.5\n", 86.0, 0.2, 1.0);
    let e = parse(&text, "tank.toml", "t").unwrap_err().to_string();
    assert!(e.contains("apparatus.a") && e.contains("alpha = 90"), "{e}");
    let text = tank("stiffness = \"soft\"\n", 86.0, 0.2, 1.0);
    assert!(parse(&text, "tank.toml", "t").is_err());
    let _ = Start::Ground;
}

/// Block 2 hanging from block 1 by its B tape alone (the A tape slack),
/// turned by `delta` about its pin, released from rest; returns how far
/// θ_2 moved by `t_end`. Holding needs a torque m g r sin δ at each pin
/// (the massless tape passes the block's torque to the top pin), against
/// the limit μ_p r_p T with T = m g: it holds for sin δ < μ_p r_p / r.
fn pin_turn(delta_deg: f64, mu_rp: f64, omega_eps: f64, t_end: f64) -> f64 {
    let g = 2e-4;
    let params = Params::paper(10.0)
        .unwrap()
        .with_n(2)
        .with_b(0.5)
        .with_gamma(0.0)
        .with_gravity(g)
        .with_inertia(0.0837)
        .validated()
        .unwrap();
    let terms = Terms {
        links: Links {
            stiffness: 1.0,
            tension_only: true,
        },
        friction: Some(PinFriction { mu_rp, omega_eps }),
        ..Terms::default()
    };
    let delta = delta_deg.to_radians();
    let mut q0 = vec![0.0; 6];
    // Block 1 at θ = 0: its B node at (0, −r). Block 2's B node right
    // below it, the tape stretched by T/k = m g; θ_2 = −π/2 − δ puts its
    // centre r below that node, turned by δ.
    let node = [0.5 + g, -0.5];
    q0[itheta(1)] = -std::f64::consts::FRAC_PI_2 - delta;
    let (t, _) = media::frame(1, q0[itheta(1)]);
    q0[ix(1)] = node[0] - 0.5 * t[0];
    q0[iy(1)] = node[1] - 0.5 * t[1];
    let sc = scenario(params, terms, 0.0, q0.clone(), t_end);
    // The A tape is slack all along (checked at the start).
    let a_len = {
        let (t1, _) = media::frame(0, 0.0);
        let a0 = [-0.5 * t1[0], -0.5 * t1[1]];
        let a1 = [q0[ix(1)] - 0.5 * t[0], q0[iy(1)] - 0.5 * t[1]];
        ((a1[0] - a0[0]).powi(2) + (a1[1] - a0[1]).powi(2)).sqrt()
    };
    assert!(a_len < sc.ladder.a - 0.1);
    let traj = sim::simulate(&sc, &[0.25 * t_end], &rk4(0.02)).unwrap();
    // The turn after the first quarter of the run (the tape's settling
    // is over by then).
    (traj.final_state.q[itheta(1)] - traj.states[0][itheta(1)]).to_degrees()
}

#[test]
fn pin_friction_holds_below_its_threshold_and_slips_above() {
    // μ_p r_p = 0.05 s: sin δ* = 0.05/0.5, δ* = 5.74°.
    let (mu_rp, t_end) = (0.05, 300.0);
    let eps = 2e-6;
    let held = pin_turn(4.0, mu_rp, eps, t_end);
    let slipped = pin_turn(8.0, mu_rp, eps, t_end);
    let free = pin_turn(4.0, 0.0, eps, t_end);
    println!("held {held}°, slipped {slipped}°, frictionless {free}°");
    assert!(held.abs() < 0.1, "held: {held}°");
    assert!(slipped.abs() > 1.0, "slipped: {slipped}°");
    assert!(free.abs() > 1.0, "frictionless: {free}°");
    // Convergence in ω_ε: the creep of the held block is ∝ ω_ε.
    let half = pin_turn(4.0, mu_rp, 0.5 * eps, t_end);
    println!("creep at ω_ε: {held}°, at ω_ε/2: {half}°");
    // The held block's creep shrinks with ω_ε (tanh → sign as ω_ε → 0).
    assert!(half.abs() < 0.9 * held.abs(), "{held} {half}");
    // Just below and just above the threshold.
    let below = pin_turn(5.2, mu_rp, eps, t_end);
    let above = pin_turn(6.5, mu_rp, eps, t_end);
    println!("5.2°: {below}°, 6.5°: {above}°");
    assert!(below.abs() < 0.1 && above.abs() > 0.5, "{below} {above}");
}

/// The tank's levels of model (docs/experiments.md).
const LEVELS: [(&str, &str); 5] = [
    (
        "paper: two-way springs, linear damping, g",
        "damping = \"paper\"\n",
    ),
    (
        "+ buoyancy + quadratic drag (no γ)",
        "buoyancy = true\ndrag = true\n",
    ),
    (
        "+ added mass",
        "buoyancy = true\ndrag = true\nadded_mass = true\n",
    ),
    (
        "+ tension-only tape",
        "buoyancy = true\ndrag = true\nadded_mass = true\ntension_only = true\n",
    ),
    (
        "all terms (+ the paper's γ)",
        "buoyancy = true\ndrag = true\nadded_mass = true\ntension_only = true\ndamping = \"paper\"\n",
    ),
];

/// The table of docs/experiments.md: `cargo test --release --test
/// integration -- --ignored --nocapture experiments::numbers`.
#[test]
#[ignore]
fn numbers() {
    let f = |c: Option<f64>| c.map_or("—".to_string(), |c| format!("{c:.2}"));
    let r = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) => format!("{:.3}", a / b),
        _ => "—".into(),
    };
    println!(
        "| level | motor (Hz) | c_kink (cm/s), whole / bulk | c_antikink (cm/s), whole / bulk | ratio whole / bulk |"
    );
    println!("|---|---|---|---|---|");
    for (name, extra) in LEVELS {
        for motor in [0.1, 0.2, 0.4] {
            let (kw, kb, ka) = tank_run(extra, 86.0, motor, 30.0);
            let (aw, ab, aa) = tank_run(extra, -86.0, motor, 30.0);
            println!(
                "| {name} | {motor} | {} / {} | {} / {} | {} / {} |",
                f(kw),
                f(kb),
                f(aw),
                f(ab),
                r(aw, kw),
                r(ab, kb)
            );
            if motor == 0.2 {
                let s = |v: &[Option<f64>]| {
                    v.iter()
                        .map(|a| a.map_or("—".into(), |t| format!("{t:.2}")))
                        .collect::<Vec<_>>()
                        .join(" ")
                };
                eprintln!("{name}: kink arrivals (s) {}; antikink {}", s(&ka), s(&aa));
            }
        }
    }
    println!();
    println!(
        "| μ_p | ω_ε (rad/s) | kink: blocks flipped, c (cm/s) | antikink: blocks flipped, c (cm/s), front |"
    );
    println!("|---|---|---|---|");
    for mu in [0.0, 0.3, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.5] {
        for rate in [0.05, 0.025] {
            let mut row = format!("| {mu} | {rate} |");
            for alpha in [69.0, -69.0] {
                let text = format!(
                    "[model]\nalpha = {alpha}\nn = 8\nstart = \"relaxed\"\n[apparatus]\ns = 5.0\nb = 6.0\n\
                     a = 7.0\nthickness = 0.5\ndensity = 1.24\nmedium = \"air\"\ndrag = true\n\
                     pin_friction = {mu}\npin_radius = 0.15\nfriction_rate = {rate}\nmotor = 0.2\n\
                     duration = 20.0\n[output]\nkind = \"data\"\n"
                );
                let scene = parse(&text, "linkage", "linkage").unwrap();
                let conv = scene
                    .apparatus
                    .as_ref()
                    .unwrap()
                    .conversion
                    .clone()
                    .unwrap();
                let sc = scene.scenario().unwrap();
                let traj = sim::simulate(&sc, &[], &rk4(0.125)).unwrap();
                let flipped = traj.arrival_times.iter().filter(|a| a.is_some()).count();
                let front = traj.waves.waves.first().map(|w| w.front + 1);
                row += &format!(
                    " {flipped}/8, {}, front {} |",
                    f(wave_speed(&traj.arrival_times).map(|c| c * conv.cm_per_s)),
                    front.map_or("—".into(), |b| b.to_string())
                );
            }
            println!("{row}");
        }
    }
}

/// `--apparatus FILE` and `--medium` bring the apparatus to a run from the
/// command line: the file's `[apparatus]` converted as a scene file's (the
/// run in the file's seconds), a bad value named with FILE:line:col and
/// its key, `--medium` without an apparatus refused naming the flag; each
/// refusal one line on stderr and exit 2.
#[test]
fn the_apparatus_reaches_a_run_from_the_command_line() {
    use crate::common::ladder_cli;
    let dir = std::env::temp_dir().join(format!("ladder-apparatus-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let good = dir.join("tank.toml");
    std::fs::write(
        &good,
        "[apparatus]\ns = 5.0\nb = 7.5\nthickness = 0.3\ndensity = 1.2\nmedium = \"water\"\n\
         medium_density = 1.0\nbuoyancy = true\ndrag = true\nmotor = 0.4\nduration = 2.0\n",
    )
    .unwrap();
    let bad = dir.join("bad.toml");
    std::fs::write(
        &bad,
        "[apparatus]\ns = 5.0\nb = 7.5\nthickness = 0.3\ndensity = 1.2\nmedium = \"water\"\n\
         drag_coefficient = -1.0\n",
    )
    .unwrap();
    let path = |p: &std::path::Path| p.to_str().unwrap().to_string();
    let run = |extra: &[&str]| {
        let mut args = vec![
            "simulate",
            "--alpha",
            "86",
            "--n",
            "6",
            "--integrator",
            "rk4",
        ];
        args.extend_from_slice(extra);
        ladder_cli(&args)
    };
    // The run is the file's 2 s: τ = 2.47 ms for the buoyant plates, so
    // t_end = 2 s / τ ≈ 809 τ (the --json summary's t_end).
    let out = run(&["--dt", "0.125", "--apparatus", &path(&good), "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let t_end = v["t_end"].as_f64().unwrap();
    let tau = (5.0f64 * 2e-4 / ((1.0 - 1.0 / 1.2) * 981.0)).sqrt();
    assert!((t_end - 2.0 / tau).abs() < 1e-6 * t_end, "t_end {t_end} τ");
    // In air the same plates have no buoyancy worth naming: g* ≈ g, so τ
    // is shorter and the same 2 s is more τ.
    let out = run(&[
        "--dt",
        "0.125",
        "--apparatus",
        &path(&good),
        "--medium",
        "air",
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(v["t_end"].as_f64().unwrap() > 2.0 * t_end, "{}", v["t_end"]);
    // A bad value: FILE:line:col: apparatus.KEY, exit 2, one line.
    let out = run(&["--apparatus", &path(&bad)]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("bad.toml:7:") && err.contains("apparatus.drag_coefficient"),
        "{err}"
    );
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    // --medium needs an apparatus; a missing file is named.
    let out = run(&["--medium", "water"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--medium") && err.contains("--apparatus"),
        "{err}"
    );
    let out = run(&["--apparatus", &path(&dir.join("none.toml"))]);
    assert_eq!(out.status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&dir);
}

/// `ladder simulate` with "stiff" links shows they are stiff, as `auto`
/// shows its step: the same run with 2k (over the same seconds) moves the
/// wave's speed by less than the 3 % allowed, said on stderr and in the
/// JSON; links given in N/m get no such line. The JSON's b is the
/// apparatus's (7.5 cm / 5 cm = 1.5), not `[model]`'s 1.3.
#[test]
fn stiff_links_are_shown_stiff_beside_the_run() {
    use crate::common::ladder_cli;
    let dir = std::env::temp_dir().join(format!("ladder-stiff-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let tank = "[apparatus]\ns = 5.0\nb = 7.5\nthickness = 0.3\ndensity = 1.2\n\
                medium = \"water\"\nmedium_density = 1.0\nbuoyancy = true\nadded_mass = true\n\
                drag = true\nmotor = 0.2\nduration = 20.0\n";
    let stiff = dir.join("stiff.toml");
    std::fs::write(&stiff, format!("{tank}stiffness = \"stiff\"\n")).unwrap();
    let given = dir.join("given.toml");
    std::fs::write(&given, format!("{tank}stiffness = 500.0\n")).unwrap();
    let run = |file: &std::path::Path| {
        ladder_cli(&[
            "simulate",
            "--alpha",
            "86",
            "--n",
            "11",
            "--integrator",
            "rk4",
            "--dt",
            "0.125",
            "--apparatus",
            file.to_str().unwrap(),
            "--json",
        ])
    };
    let out = run(&stiff);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let b = &v["model"]["b"];
    assert!((b.as_f64().unwrap() - 1.5).abs() < 1e-12, "{b}");
    let check = &v["stiff_links"];
    let (k, k2) = (
        check["speed_k"].as_f64().expect("a wave at k"),
        check["speed_2k"].as_f64().expect("a wave at 2k"),
    );
    let change = check["change"].as_f64().unwrap();
    assert!((change - (k2 / k - 1.0).abs()).abs() < 1e-12);
    assert!(change < 0.03, "k and 2k differ by {change}");
    assert!(
        err.contains("\"stiff\" links: with 2k the wave's speed moves by")
            && err.contains("within 3 %"),
        "{err}"
    );
    // The speed at k, in blocks per second, is the run's own (blocks per
    // τ over τ in seconds).
    let tau = v["scene"]["apparatus"]["conversion"]["tau_s"]
        .as_f64()
        .unwrap();
    let own = v["speed"].as_f64().unwrap() / tau;
    assert!((own - k).abs() < 1e-9 * k, "{own} against {k}");
    let out = run(&given);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(v.get("stiff_links").is_none(), "{v}");
    assert!(!err.contains("stiff"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Ribbons from the command line: `--apparatus` with `ribbons = true`
/// hangs the plates in a column (α = ±90°, the conversion's value), which
/// the run takes and reports; the check of `--alpha`'s range (0 < |α| <
/// 90) applies to what the user typed, not to the column's 90°.
#[test]
fn ribbons_from_the_command_line_hang_the_column() {
    use crate::common::ladder_cli;
    let dir = std::env::temp_dir().join(format!("ladder-ribbons-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("ribbons.toml");
    std::fs::write(
        &file,
        "[apparatus]\ns = 5.0\nb = 7.5\nthickness = 0.3\ndensity = 1.2\nmedium = \"water\"\n\
         medium_density = 1.0\nbuoyancy = true\nribbons = true\nribbon_anchors = [0.0, 1.0]\n\
         contact = \"acrylic\"\nmotor = 0.2\nduration = 0.05\n",
    )
    .unwrap();
    for (alpha, column) in [("86", 90.0), ("-86", -90.0)] {
        let out = ladder_cli(&[
            "simulate",
            "--alpha",
            alpha,
            "--n",
            "4",
            "--integrator",
            "rk4",
            "--dt",
            "0.03125",
            "--apparatus",
            file.to_str().unwrap(),
            "--json",
        ]);
        assert!(
            out.status.success(),
            "--alpha {alpha}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(
            v["model"]["alpha"].as_f64(),
            Some(column),
            "--alpha {alpha}"
        );
    }
    // The user's own α is still checked.
    let out = ladder_cli(&[
        "simulate",
        "--alpha",
        "90",
        "--apparatus",
        file.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&dir);
}
