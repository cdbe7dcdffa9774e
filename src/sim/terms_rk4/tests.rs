//! The fused RK4 of a ladder in a fluid against the portable path.

use super::*;
use crate::model::Ladder;
use crate::model::Params;
use crate::model::terms::Terms;
use crate::sim::protocol::{Drive, Protocol};
use crate::sim::{IntegratorConfig, IntegratorKind};

/// The water tank's ladder (N = 11, α = 86°, b = 1.5, added mass, added
/// inertia, drag: `ladder scene water-tank`), with linear damping `gamma`
/// and drag `drag`.
fn tank(gamma: f64, drag: f64) -> Ladder {
    tank_of(11, gamma, drag)
}

/// The tank's ladder with `n` blocks.
fn tank_of(n: usize, gamma: f64, drag: f64) -> Ladder {
    let mut p = Params::paper(86.0).unwrap();
    p.n = n;
    p.b = 1.5;
    p.gamma = gamma;
    p.gravity = 2e-4;
    p.inertia = 0.083_633_333_333_333_34;
    let terms = Terms {
        added_mass: 6.315_910_230_654_479,
        added_inertia: 0.197_372_194_707_952_5,
        drag,
        ..Terms::default()
    };
    Ladder::new(p).with_terms(terms)
}

/// The tank's ladder with Coulomb pin friction μ_p r_p = `mu_rp` (the
/// printed linkage's term: `figure linkage-friction`).
fn with_friction(gamma: f64, drag: f64, mu_rp: f64) -> Ladder {
    let l = tank(gamma, drag);
    let terms = Terms {
        friction: Some(crate::model::links::PinFriction {
            mu_rp,
            omega_eps: 0.01,
        }),
        ..l.terms
    };
    l.with_terms(terms)
}

/// Block 1 turned from α to −α over 400 τ (the motor), or free.
fn protocol(ladder: &Ladder, driven: bool) -> Protocol {
    let a = ladder.params.alpha;
    if driven {
        Protocol::Driven(Drive::new(vec![(0.0, a), (400.0, -a)]).unwrap())
    } else {
        Protocol::Free
    }
}

/// A state away from equilibrium: every block displaced and moving.
fn start(ladder: &Ladder) -> State {
    let mut q = ladder.ground_state();
    for (k, x) in q.iter_mut().enumerate() {
        *x += 0.02 * ((k as f64) * 1.7).sin();
    }
    let v = (0..q.len())
        .map(|k| 0.01 * ((k as f64) * 1.3).sin())
        .collect();
    State { q, v }
}

/// `steps` RK4 steps of dt = 0.125 by the portable path and by the fused
/// stepper (`library`: with the C library's frames), in batches of 37
/// steps; both final states and arrival times.
fn both(ladder: &Ladder, driven: bool, steps: u64, library: bool) -> [(State, Vec<String>); 2] {
    [
        one(ladder, driven, steps, None),
        one(ladder, driven, steps, Some(library)),
    ]
}

/// One run of `steps` RK4 steps of 0.125 τ: the portable path (`None`) or
/// the fused one with the library's frames (`Some(true)`) or the
/// springs' (`Some(false)`); its final state and arrivals.
fn one(ladder: &Ladder, driven: bool, steps: u64, fused: Option<bool>) -> (State, Vec<String>) {
    one_with(ladder, driven, steps, fused, StepPath::AsChosen)
}

/// Which step the fused stepper takes in [`one_with`].
#[derive(Clone, Copy)]
enum StepPath {
    /// The one it chooses (registers where it takes them, on the best
    /// instruction set this CPU has).
    AsChosen,
    /// Always over arrays.
    Arrays,
    /// In registers, compiled for this instruction set.
    Registers(Isa),
}

/// As [`one`], the fused stepper taking the step `path` says.
fn one_with(
    ladder: &Ladder,
    driven: bool,
    steps: u64,
    fused: Option<bool>,
    path: StepPath,
) -> (State, Vec<String>) {
    let protocol = protocol(ladder, driven);
    let s0 = start(ladder);
    let (dt, t_end) = (0.125, 0.125 * steps as f64);
    let run = |fast: Option<bool>| {
        let mut rhs = Rhs::new(ladder, &protocol, &s0.q);
        let mut st = s0.clone();
        rhs.constrain(0.0, &mut st.q, &mut st.v);
        let mut arrivals = ArrivalDetector::new(0.0, &st.q, &st.v);
        let mut t = 0.0;
        if let Some(library) = fast {
            let make = if library {
                TermsRk4::with_library_frames
            } else {
                TermsRk4::new
            };
            let mut k = make(&rhs, Stepping::Fastest).expect("the tank takes the fused path");
            assert_eq!(
                k.registers,
                ladder.terms.friction.is_none()
                    && ladder.n() <= 16
                    && ladder.terms.drag != 0.0
                    && !library
            );
            match path {
                StepPath::AsChosen => {}
                StepPath::Arrays => k.registers = false,
                StepPath::Registers(isa) => k.isa = isa,
            }
            let mut plan = Plan::default();
            while t < t_end {
                let (t1, _) = k.advance_many(
                    &mut rhs,
                    &mut st,
                    (&mut plan, dt),
                    (t, t_end),
                    37,
                    &mut arrivals,
                );
                t = t1;
            }
        } else {
            let cfg = IntegratorConfig::fixed(IntegratorKind::Rk4, dt);
            let mut integ = cfg.build(s0.q.len(), Stepping::Portable);
            while t < t_end {
                t = integ
                    .advance_many(&mut rhs, &mut st, (t, t_end), 37, &mut arrivals)
                    .unwrap()
                    .0;
            }
        }
        assert_eq!(rhs.force_evals, 4 * steps);
        (st, vec![format!("{:?}", arrivals.arrival)])
    };
    run(fused)
}

/// Two runs' final states equal bit for bit, and their arrivals.
fn assert_same_bits(
    (a, arr_a): &(State, Vec<String>),
    (b, arr_b): &(State, Vec<String>),
    what: &str,
) {
    for (k, (x, y)) in a.q.iter().zip(&b.q).chain(a.v.iter().zip(&b.v)).enumerate() {
        assert_eq!(x.to_bits(), y.to_bits(), "{what}: coordinate {k}: {x} {y}");
    }
    assert_eq!(arr_a, arr_b, "{what}");
}

fn has_avx2() -> bool {
    Stepping::Fastest.isa().is_some()
}

/// With the library's frames the fused stepper is the portable path bit
/// for bit: every term (springs, buoyancy's gravity, linear damping,
/// drag in both of its closed forms, added mass, the Munk moment, the
/// drive) computed by the same operations in the same order.
#[test]
fn library_frames_give_the_portable_trajectory_bit_for_bit() {
    if !has_avx2() {
        return;
    }
    for (gamma, drag, driven) in [(0.0, 8.125, true), (0.003, 8.125, false), (0.01, 0.0, true)] {
        let ladder = tank(gamma, drag);
        let [a, b] = both(&ladder, driven, 4000, true);
        assert_same_bits(&a, &b, &format!("γ {gamma}, drag {drag}"));
    }
}

/// Pin friction in the fused path (`terms_rk4::friction`): with the
/// library's frames the portable trajectory bit for bit (the friction's
/// torques and the links' balancing forces added in the portable order;
/// pins both held (|ω/ω_ε| < 22) and sliding), with the springs' frames
/// within 1e-9 of it over 250 τ, and not the trajectory without
/// friction.
#[test]
fn pin_friction_gives_the_portable_trajectory() {
    if !has_avx2() {
        return;
    }
    for (gamma, drag, driven, mu_rp) in [
        (0.0, 8.125, true, 0.05),
        (0.003, 8.125, false, 0.2),
        (0.01, 0.0, true, 0.02),
    ] {
        let ladder = with_friction(gamma, drag, mu_rp);
        // The portable run once, against both fused ones.
        let portable = one(&ladder, driven, 2000, None);
        let fused = one(&ladder, driven, 2000, Some(true));
        assert_same_bits(
            &fused,
            &portable,
            &format!("μ r {mu_rp}, γ {gamma}, drag {drag}"),
        );
        let a = &fused.0;
        let (p, f) = (&portable.0, one(&ladder, driven, 2000, Some(false)).0);
        let worst =
            p.q.iter()
                .zip(&f.q)
                .chain(p.v.iter().zip(&f.v))
                .map(|(x, y)| (x - y).abs())
                .fold(0.0, f64::max);
        eprintln!("μ r {mu_rp}: the springs' frames move the run by {worst:e}");
        assert!(
            worst < 1e-9,
            "μ r {mu_rp}, γ {gamma}, drag {drag}: {worst:e}"
        );
        let (none, _) = one(&tank(gamma, drag), driven, 2000, None);
        let moved = none.q.iter().zip(&a.q).any(|(x, y)| (x - y).abs() > 1e-6);
        assert!(moved, "μ r {mu_rp}: the friction must change the run");
    }
}

/// The frames from the springs' sine and cosine (`model::trig`, within
/// 4e-16 of the library's) and the quick arithmetic (`QUICK`: products
/// by 1/3, 1/w and 1/(I + I_a) for the drag's and Lagrange's divisions)
/// move one force evaluation by a few ulps, and the tank's trajectory
/// over 500 τ (the motor's drive and the kink's start) by less than 1e-9
/// s and 1e-9 rad (measured: 1.9e-10 and 6.1e-11 /τ, the frames alone
/// 6.0e-11 and 1.8e-11; the kink amplifies the first differences).
#[test]
fn shared_frames_stay_within_the_stated_bound() {
    if !has_avx2() {
        return;
    }
    let ladder = tank(0.0, 8.125);
    let [(a, _), (b, _)] = both(&ladder, true, 4000, false);
    let worst =
        a.q.iter()
            .zip(&b.q)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max);
    let worst_v =
        a.v.iter()
            .zip(&b.v)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max);
    eprintln!("largest difference: q {worst:e}, v {worst_v:e}");
    assert!(
        worst > 0.0 || worst_v > 0.0,
        "the shared frames should differ in the last bits somewhere"
    );
    assert!(worst < 1e-9 && worst_v < 1e-9, "q {worst:e}, v {worst_v:e}");
}

/// One force evaluation with the shared frames against the portable
/// path's: every acceleration within 64 ulps of the largest (the frames'
/// sine and cosine differ by at most 4e-16 from the library's).
#[test]
fn one_evaluation_within_ulps_of_the_portable_one() {
    if !has_avx2() {
        return;
    }
    for driven in [true, false] {
        let ladder = tank(0.003, 8.125);
        let protocol = protocol(&ladder, driven);
        let st = start(&ladder);
        let mut rhs = Rhs::new(&ladder, &protocol, &st.q);
        let mut want = vec![0.0; st.q.len()];
        rhs.acceleration(&st.q, &st.v, &mut want);
        let mut k = TermsRk4::new(&rhs, Stepping::Fastest).unwrap();
        k.load(&st);
        let [ax, ay, aw] = &mut k.kv[0];
        acceleration(
            (&k.c, k.friction.as_ref()),
            &k.parity,
            (&k.q0, &k.v0),
            [ax, ay, aw],
            &mut k.s,
            false,
        );
        let scale = want.iter().fold(0.0f64, |m, a| m.max(a.abs()));
        let mut worst = 0.0f64;
        for (i, w) in want.chunks_exact(3).enumerate() {
            for (c, w) in w.iter().enumerate() {
                let got = k.kv[0][c][i];
                worst = worst.max((got - w).abs());
            }
        }
        eprintln!("driven {driven}: largest difference {worst:e} of {scale:e}");
        assert!(
            worst <= 64.0 * f64::EPSILON * scale,
            "{worst:e} of {scale:e}"
        );
    }
}

/// The drag's closed forms in the quick arithmetic against the portable
/// one, over speeds and rates of either sign and both closed forms: the
/// force within 4 ulps of the larger of g(u0 ± wR)/|w|, the torque within
/// 4 ulps of (the larger h(u0 ± wR) + |u0| g(u0 ± wR))/w² (the terms the
/// closed form subtracts; each product is within 1.5 ulp of the quotient
/// it replaces, and 1/3 is rounded once).
#[test]
fn the_quick_drag_is_within_ulps_of_the_portable_one() {
    if !has_avx2() {
        return;
    }
    #[target_feature(enable = "avx2")]
    unsafe fn both(u0: f64, w: f64) -> [(f64, f64); 2] {
        let (u, w) = (F64x4::splat(u0), F64x4::splat(w));
        let lane = |(f, t): (F64x4, F64x4)| (f.lane(0), t.lane(0));
        [
            lane(drag_integrals::<F64x4, PORTABLE>(u, w)),
            lane(drag_integrals::<F64x4, QUICK>(u, w)),
        ]
    }
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let mut differed = 0;
    for _ in 0..20_000 {
        let (u0, w) = (
            next() * 10f64.powf(3.0 * next()),
            next() * 10f64.powf(3.0 * next()),
        );
        // SAFETY: the CPU has AVX2 (checked above).
        let [(f, t), (fq, tq)] = unsafe { both(u0, w) };
        let g = |u: f64| u * u * u.abs() / 3.0;
        let h = |u: f64| u * u * u * u.abs() / 4.0;
        let (up, um) = (u0 + w * R, u0 - w * R);
        let gm = g(up).max(g(um));
        let f_scale = gm / w.abs();
        let t_scale = (h(up).abs().max(h(um).abs()) + u0.abs() * gm) / (w * w);
        let ulp = 4.0 * f64::EPSILON;
        assert!(
            (f - fq).abs() <= ulp * f_scale.max(f.abs()),
            "u0 {u0}, w {w}: {f} {fq}"
        );
        assert!(
            (t - tq).abs() <= ulp * t_scale.max(t.abs()),
            "u0 {u0}, w {w}: {t} {tq}"
        );
        differed += usize::from(f != fq || t != tq);
    }
    assert!(differed > 0, "the quick arithmetic should differ somewhere");
}

/// The step with the ladder in registers (`terms_rk4::regs`) is the step
/// over arrays bit for bit, for the runs that take it (drag, the springs'
/// frames and the quick divisions; the others take the arrays), for one
/// to four registers of blocks (N = 2, 5, 11, 16: the padding, the pairs
/// masked at the chain's end), driven and free, with and without linear
/// damping; positions, velocities and arrival times, after 600 steps
/// (75 τ: the unit tests run at opt-level 0, where 2000 steps took 11 s).
#[test]
fn registers_give_the_array_trajectory_bit_for_bit() {
    if !has_avx2() {
        return;
    }
    // Both compilations of the step in registers that this CPU can run:
    // AVX2's 16 registers (every CPU with AVX2) and AVX-512's 32.
    let isas: Vec<Isa> = [Isa::Avx2, Isa::Avx512]
        .into_iter()
        .filter(|isa| isa.available())
        .collect();
    for n in [2, 5, 11, 16] {
        for (gamma, drag, driven) in [(0.0, 8.125, true), (0.003, 8.125, false), (0.01, 2.0, true)]
        {
            let ladder = tank_of(n, gamma, drag);
            let arrays = one_with(&ladder, driven, 600, Some(false), StepPath::Arrays);
            for &isa in &isas {
                let regs = one_with(&ladder, driven, 600, Some(false), StepPath::Registers(isa));
                let what = format!("N {n}, γ {gamma}, drag {drag}, {isa:?}");
                assert_same_bits(&regs, &arrays, &what);
            }
        }
    }
}

/// The registers' sine and cosine are `trig::sin_cos_slice`'s bit for bit
/// (every lane, the quadrants, signed zeros, the library's arguments).
#[test]
fn register_sin_cos_is_the_slice_one_bit_for_bit() {
    if !has_avx2() {
        return;
    }
    #[target_feature(enable = "avx2")]
    unsafe fn lanes(x: &[f64; 4]) -> ([f64; 4], [f64; 4]) {
        // SAFETY: `x` holds four values.
        let (s, c) = regs::sin_cos(unsafe { F64x4::load(x.as_ptr()) });
        let (s, c) = (s.to_array(), c.to_array());
        (std::array::from_fn(|l| s[l]), std::array::from_fn(|l| c[l]))
    }
    let xs = crate::sim::simd::tests::sin_cos_inputs();
    let (mut s, mut c) = (vec![0.0; xs.len()], vec![0.0; xs.len()]);
    crate::model::trig::sin_cos_slice(&xs, &mut s, &mut c);
    for (k, x) in xs.chunks_exact(4).enumerate() {
        // SAFETY: the CPU has AVX2 (checked above).
        let (sv, cv) = unsafe { lanes(x.try_into().unwrap()) };
        for l in 0..4 {
            let i = 4 * k + l;
            let same = |a: f64, b: f64| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
            assert!(
                same(sv[l], s[i]) && same(cv[l], c[i]),
                "x {}: {} {}",
                xs[i],
                sv[l],
                cv[l]
            );
        }
    }
}
