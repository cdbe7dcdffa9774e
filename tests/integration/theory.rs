//! Closed forms of the supplement against the model (docs/model.md). Test
//! names are cited by docs/paper-errata.md.

use jacobs_ladder::model::ladder::{itheta, iy, nodes};
use jacobs_ladder::model::params::S;
use jacobs_ladder::model::{Ladder, Params};
use jacobs_ladder::theory::bloch::*;
use jacobs_ladder::theory::compatibility::*;
use jacobs_ladder::theory::dispersion::*;
use jacobs_ladder::theory::edge::*;
use jacobs_ladder::theory::figures::*;
use jacobs_ladder::theory::gravity::*;
use jacobs_ladder::theory::{TheoryReport, linalg};
use std::f64::consts::PI;

fn params(n: usize, b: f64, alpha_deg: f64) -> Params {
    Params::paper(60.0).unwrap().with(n, b, alpha_deg).unwrap()
}

// ---------------------------------------------------------------- gravity

/// Dense minimisation of U(θ) = −2 m g (X_2 − X_1), the spacing solved from
/// the model's spring lengths by Newton (continuation over θ).
#[test]
fn u_theta_dense_minimisation_of_the_model_matches_eq_eq_alpha() {
    for (b, alpha_deg) in [(1.2, 75.0), (1.3, 60.0), (1.3, 30.0)] {
        let p = params(2, b, alpha_deg);
        let a = p.a();
        let mut guess = [b, -S * p.alpha.cos()];
        let mut best = (f64::INFINITY, 0.0);
        // θ from α down to −α and beyond, 1e-4 rad steps, keeping the root
        // that is continuous with the ground state.
        let steps = 30_000;
        for k in 0..=steps {
            let theta = p.alpha - 2.0 * p.alpha * k as f64 / steps as f64;
            let Some(sp) = model_pair_spacing(&p, theta, guess) else {
                break;
            };
            guess = sp;
            let u = -2.0 * sp[0] / S;
            let closed = potential(a, b, theta).unwrap();
            assert!(
                (u - closed).abs() < 1e-9,
                "b {b} alpha {alpha_deg} theta {theta}: {u} vs {closed}"
            );
            if u < best.0 {
                best = (u, theta);
            }
        }
        assert!((best.0 - u_min(b)).abs() < 1e-9, "{best:?}");
        assert!((best.1.abs() - p.alpha).abs() < 2e-4);
        let u0 = -2.0 * model_pair_spacing(&p, 0.0, [b, 0.0]).unwrap()[0];
        assert!((u0 - u_min(b) - barrier(b, p.alpha).unwrap()).abs() < 1e-9);
    }
}

/// A brute-force grid minimisation of the closed form agrees with α, U_min.
#[test]
fn u_theta_grid_minimum_is_at_plus_minus_alpha() {
    let (a, b) = (1.6, 1.2);
    let alpha = alpha_from_lengths(a, b).unwrap();
    let grid = (0..200_001).map(|k| -PI / 2.0 + PI * k as f64 / 200_000.0);
    let (mut lo_pos, mut lo_neg) = ((f64::INFINITY, 0.0), (f64::INFINITY, 0.0));
    for th in grid {
        if let Some(u) = potential(a, b, th) {
            let slot = if th > 0.0 { &mut lo_pos } else { &mut lo_neg };
            if u < slot.0 {
                *slot = (u, th);
            }
        }
    }
    for (u, th) in [lo_pos, lo_neg] {
        assert!(
            (u - u_min(b)).abs() < 1e-8 && (th.abs() - alpha).abs() < 2e-5,
            "{u} {th}"
        );
    }
}

/// eq:U_g's middle member, −2mg(s sin α + Δ_x(θ)), is not the potential:
/// the spacing of the centres is s sin θ + Δ_x(θ).
#[test]
fn eq_u_g_middle_member_needs_sin_theta() {
    let p = params(2, 1.3, 60.0);
    let (a, b, theta) = (p.a(), p.b, 0.6);
    let delta_x = centre_spacing(a, b, theta).unwrap() - S * theta.sin();
    let sp = model_pair_spacing(&p, theta, [b, -0.5]).unwrap();
    assert!((-2.0 * (S * theta.sin() + delta_x) + 2.0 * sp[0]).abs() < 1e-9);
    assert!((-2.0 * (S * p.alpha.sin() + delta_x) + 2.0 * sp[0]).abs() > 0.1);
}

/// eq:eq_values2's (−1)^{n+1} s cos α makes every A spring b long and every
/// B spring a long; the model's (−1)^n gives A = a, B = b.
#[test]
fn eq_eq_values2_sign_swaps_the_springs() {
    let p = params(6, 1.3, 60.0);
    let ladder = Ladder::new(p);
    let mut q = ladder.ground_state();
    for i in 0..p.n {
        q[iy(i)] = -q[iy(i)];
    }
    let (mut la, mut lb) = (vec![0.0; 5], vec![0.0; 5]);
    ladder.spring_lengths(&q, &mut la, &mut lb);
    assert!(la.iter().all(|l| (l - p.b).abs() < 1e-12));
    assert!(lb.iter().all(|l| (l - p.a()).abs() < 1e-12));
}

// ------------------------------------------------------------ index counts

#[test]
fn index_counts_a_greater_than_b() {
    for alpha in [60.0, -60.0, 30.0, 1.0, 0.0] {
        for n in 2..=40 {
            let p = params(n, 1.3, alpha);
            let free = index_count(&p, Boundary::Free).unwrap();
            assert_eq!(
                (free.zero_modes, free.self_stress),
                (n + 2, 0),
                "alpha {alpha} N {n}"
            );
            assert_eq!(
                free.maxwell_index,
                free.zero_modes as i64 - free.self_stress as i64
            );
            let cl = index_count(&p, Boundary::Clamped).unwrap();
            assert_eq!((cl.zero_modes, cl.self_stress), (n - 1, 0));
            if n % 2 == 0 && n >= 4 {
                let ring = index_count(&p, Boundary::Periodic).unwrap();
                assert_eq!((ring.zero_modes, ring.self_stress), (n + 1, 1));
            }
        }
    }
}

/// a = b (α = 90°): both springs of a pair lie on one line.
#[test]
fn index_counts_symmetric_toy() {
    for n in 2..=40 {
        let p = params(n, 1.3, 90.0);
        let free = index_count(&p, Boundary::Free).unwrap();
        assert_eq!(
            (free.zero_modes, free.self_stress),
            (2 * n + 1, n - 1),
            "N {n}"
        );
        let cl = index_count(&p, Boundary::Clamped).unwrap();
        // The paper's M = 2N − 2 mechanisms.
        assert_eq!((cl.zero_modes, cl.self_stress), (2 * n - 2, n - 1));
        if n % 2 == 0 && n >= 4 {
            let ring = index_count(&p, Boundary::Periodic).unwrap();
            assert_eq!((ring.zero_modes, ring.self_stress), (2 * n + 1, n + 1));
        }
    }
}

/// Under δv_n = (−1)^n (s/2) sin α δθ_n the free chain has ν = 2 and
/// N_0 = 2 (translation along x and the surface mode), as the paper says.
#[test]
fn constrained_free_chain_has_two_zero_modes() {
    for alpha in [60.0, -60.0, 30.0] {
        for n in [2, 5, 10, 21] {
            let c = constrained_index_count(&params(n, 1.3, alpha)).unwrap();
            assert_eq!((c.maxwell_index, c.zero_modes, c.self_stress), (2, 2, 0));
        }
    }
}

/// The paper's "n_s(q) = 0, N_s = 0" fails at q = 0: C(0) has a zero B row,
/// so the ring has one state of self-stress (uniform tension of the
/// collinear B springs) and one extra zero mode.
#[test]
fn periodic_chain_has_a_self_stress_at_q0() {
    let chain = BlochChain::new(&params(8, 1.3, 60.0)).unwrap();
    let c0 = chain.compatibility_matrix(0.0);
    assert!(c0.row(1).iter().all(|x| x.norm() < 1e-14));
    // n_0(0) = 2: translation along x and the uniform tilt ṽ = −(s/2) sin α θ.
    let w = chain.coefficients.constraint();
    for mode in [[1.0, 0.0, 0.0], [0.0, -w, 1.0]] {
        let v = nalgebra::Vector3::from(mode).map(C64::from);
        assert!((c0 * v).norm() < 1e-14);
    }
    let ring = Ring::new(&params(8, 1.3, 60.0)).unwrap();
    let c = ring.jacobian(&ring.ground_state());
    let t = nalgebra::DVector::from_fn(16, |r, _| if r % 2 == 1 { 1.0 } else { 0.0 });
    assert!((c.transpose() * t).norm() < 1e-13);
}

#[test]
fn hessian_zero_modes_match_the_rank_count_and_omega_max() {
    for alpha in [60.0, -60.0, 90.0] {
        let p = params(10, 1.3, alpha);
        let omega = normal_mode_frequencies(&p, Boundary::Clamped).unwrap();
        let zeros = omega.iter().filter(|w| **w < 1e-6).count();
        assert_eq!(
            zeros,
            index_count(&p, Boundary::Clamped).unwrap().zero_modes,
            "{alpha}"
        );
        assert_eq!(*omega.last().unwrap(), omega_max_clamped(&p).unwrap());
    }
    // The finite-difference Hessian of the analytic gradient gives the same ω_max.
    let p = params(10, 1.3, 60.0);
    let h = clamp_block_one(&chain_hessian_by_differences(&p));
    let ev = linalg::mass_weighted_eigenvalues(&h, &block_masses(&p, 9)).unwrap();
    assert!((ev.last().unwrap().sqrt() - omega_max_clamped(&p).unwrap()).abs() < 1e-8);
}

// ----------------------------------------------------- Bloch C(q), winding

/// The model's C(q) (staggered ṽ_n = (−1)^n δv_n) equals eq:C-q except
/// the transverse entry: −4γ(e^{iqb} + 1), printed −4γ(e^{iqb} − 1).
#[test]
fn model_bloch_c_differs_from_eq_c_q_only_in_the_v_entry() {
    for alpha in [60.0, -60.0, 20.0, 75.0] {
        let chain = BlochChain::new(&params(8, 1.3, alpha)).unwrap();
        let k = chain.coefficients;
        for qb in [0.0, 0.5, 1.3, 2.2, PI] {
            let q = qb / k.b;
            let model = chain.compatibility_matrix(q);
            let paper = paper_compatibility_matrix(&k, q);
            for (r, c) in [(0, 0), (0, 2), (1, 0), (1, 1), (1, 2)] {
                assert!(
                    (model[(r, c)] - paper[(r, c)]).norm() < 1e-12,
                    "alpha {alpha} ({r},{c})"
                );
            }
            let z = k.z(q);
            assert!((model[(0, 1)] + (z + 1.0) * 4.0 * k.gamma).norm() < 1e-12);
            assert!((model - corrected_compatibility_matrix(&k, q)).camax() < 1e-12);
            if qb != 0.0 {
                assert!((model[(0, 1)] - paper[(0, 1)]).norm() > 0.1);
            }
            // eq:C_red follows from the corrected entry, not from the printed one.
            let from_paper = reduce(&paper, &k);
            assert!(
                (reduce(&model, &k) - paper_reduced_compatibility_matrix(&k, q)).camax() < 1e-12
            );
            assert!(
                (from_paper[(0, 1)] - paper_reduced_compatibility_matrix(&k, q)[(0, 1)]).norm()
                    > 1e-3
            );
        }
    }
}

/// eq:zm_q is a null vector of the printed C(q) but not of the model's;
/// the corrected mode is. In real space (eq:zm_n, N = 10, b = 1.2, α = 75°)
/// the printed shapes stretch the springs, the corrected ones do not.
#[test]
fn eq_zm_q_is_not_a_zero_mode_of_the_model() {
    let chain = BlochChain::new(&params(8, 1.2, 75.0)).unwrap();
    let k = chain.coefficients;
    for qb in [0.4, 1.0, 2.0, 3.0] {
        let q = qb / k.b;
        let paper_mode = paper_zero_mode(&k, q);
        assert!((paper_compatibility_matrix(&k, q) * paper_mode).norm() < 1e-12);
        assert!((chain.compatibility_matrix(q) * paper_mode).norm() > 0.1);
        assert!((chain.compatibility_matrix(q) * corrected_zero_mode(&k, q)).norm() < 1e-12);
    }
    let p = params(10, 1.2, 75.0);
    for m in 1..10 {
        let shape = zero_mode_shape(&p, m, 0.1);
        assert!(shape.model_residual < 1e-12, "m {m}");
        assert!(
            shape.paper_residual > 0.1,
            "m {m}: {}",
            shape.paper_residual
        );
    }
    // m = N/2: the model's zero mode is a rigid translation along y.
    let shape = zero_mode_shape(&p, 5, 0.05);
    let dy: Vec<f64> = (0..10)
        .map(|i| shape.model[iy(i)] - shape.ground[iy(i)])
        .collect();
    assert!(
        dy.iter()
            .all(|d| (d - dy[0]).abs() < 1e-12 && d.abs() > 0.1)
    );
}

#[test]
fn winding_number_from_the_phase_of_det_c() {
    for alpha in [5.0, 30.0, 60.0, 75.0, 86.0, 89.0] {
        for b in [1.2, 1.3, 1.5] {
            let plus = BlochChain::new(&params(8, b, alpha)).unwrap();
            let minus = BlochChain::new(&params(8, b, -alpha)).unwrap();
            assert_eq!(plus.winding_number(), Some(1), "alpha {alpha} b {b}");
            assert_eq!(minus.winding_number(), Some(0), "alpha -{alpha} b {b}");
        }
    }
    for alpha in [0.0, 90.0, -90.0] {
        assert_eq!(
            BlochChain::new(&params(8, 1.3, alpha))
                .unwrap()
                .winding_number(),
            None
        );
    }
}

/// det C_red(q)/(e^{iqb} − 1) = 2(c_1 e^{iqb} − c_2): a circle of radius
/// 2|c_1| about −2c_2 (the paper: radius c_1 about −c_2).
#[test]
fn det_c_circle_has_radius_2c1() {
    let chain = BlochChain::new(&params(8, 1.3, 60.0)).unwrap();
    let k = chain.coefficients;
    for qb in [0.3, 1.0, 2.5, 4.0] {
        let r = chain.det(qb / k.b) / (k.z(qb / k.b) - 1.0);
        assert!(((r + 2.0 * k.c2).norm() - 2.0 * k.c1.abs()).abs() < 1e-12);
    }
}

/// The full ring's normal modes are the union of the Bloch branches at
/// q = 2πj/(N b).
#[test]
fn ring_spectrum_is_the_union_of_bloch_spectra() {
    let p = params(8, 1.3, 60.0);
    let mut ring = normal_mode_frequencies(&p, Boundary::Periodic).unwrap();
    let chain = BlochChain::new(&p).unwrap();
    let mut bloch: Vec<f64> = (0..8)
        .flat_map(|j| chain.unconstrained_dispersion(2.0 * PI * j as f64 / (8.0 * p.b)))
        .collect();
    ring.sort_by(f64::total_cmp);
    bloch.sort_by(f64::total_cmp);
    for (x, y) in ring.iter().zip(&bloch) {
        assert!((x - y).abs() < 1e-6, "{x} vs {y}");
    }
}

// ------------------------------------------------------------ surface mode

#[test]
fn surface_zero_mode_ratio_is_c2_over_c1() {
    for alpha in [
        20.0, 45.0, 60.0, 75.0, 86.0, -20.0, -45.0, -60.0, -75.0, -86.0,
    ] {
        let p = params(10, 1.3, alpha);
        let mode = surface_zero_mode(&p).unwrap();
        assert_eq!(mode.zero_modes, 1);
        let c = Coefficients::of(&p);
        for r in &mode.ratios {
            assert!(
                (r - c.c2 / c.c1).abs() < 1e-6 * (c.c2 / c.c1).abs().max(1.0),
                "alpha {alpha}"
            );
        }
        let expected = if alpha > 0.0 { Edge::Top } else { Edge::Bottom };
        assert_eq!(mode.edge, Some(expected), "alpha {alpha}");
        assert!(formula_mode_residual(&p).unwrap() < 1e-12);
    }
}

#[test]
fn surface_mode_decays_as_exp_minus_kappa_n_b() {
    let p = params(12, 1.3, 25.0);
    let profile = edge_mode_profile(&p).unwrap();
    let kappa = profile.kappa.unwrap();
    for (n, (num, formula)) in profile.numerical.iter().zip(&profile.formula).enumerate() {
        let expected = (-kappa * n as f64 * p.b).exp();
        assert!((num - expected).abs() < 1e-9 && (formula - expected).abs() < 1e-12);
    }
}

/// Pinning the B nodes gives eq:u-v-theta; eq:R_B's y component must read
/// +(−1)^n (s/2) cos(α + δθ_n) (printed: −(−1)^n (s/2) sin(α + δθ_n)).
#[test]
fn pinned_b_nodes_give_eq_u_v_theta() {
    let p = params(6, 1.3, 60.0);
    let ladder = Ladder::new(p);
    let q0 = ladder.ground_state();
    let proj = pinned_b_projection(&ladder, &q0);
    let h = 1e-6;
    for i in 0..p.n {
        let mut q = q0.clone();
        for (j, x) in q.iter_mut().enumerate() {
            *x += h * proj[(j, i)];
        }
        let (b0, b1) = (nodes(&q0, i).1, nodes(&q, i).1);
        assert!((b1[0] - b0[0]).abs() < 1e-11 && (b1[1] - b0[1]).abs() < 1e-11);
        let sign = if (i + 1) % 2 == 0 { 1.0 } else { -1.0 };
        assert!((proj[(iy(i), i)] - sign * 0.5 * S * p.alpha.sin()).abs() < 1e-15);
        assert!((proj[(3 * i, i)] + 0.5 * S * p.alpha.cos()).abs() < 1e-15);
        // The model's B node: y = Y + (−1)^n (s/2) cos θ.
        let y = q0[iy(i)] + sign * 0.5 * S * q0[itheta(i)].cos();
        assert!((nodes(&q0, i).1[1] - y).abs() < 1e-15);
    }
}

// -------------------------------------------------------------- dispersion

/// The model's constrained spectrum with the paper's metric diag(m, I) is
/// √2 times eq:dispersion evaluated with ω_0 = sqrt(k/m) = 1/τ, for every q
/// and α: the printed d_ij are half the mass-weighted D_ij (eq:d_s).
#[test]
fn numerical_dispersion_is_sqrt2_times_eq_dispersion() {
    for alpha in [15.0, 30.0, 45.0, 60.0, 75.0, 86.0]
        .iter()
        .chain(&[-60.0, -30.0])
    {
        let chain = BlochChain::new(&params(8, 1.3, *alpha)).unwrap();
        for j in 0..=32 {
            let q = (-PI + 2.0 * PI * j as f64 / 32.0) / chain.coefficients.b;
            let num = chain.constrained_dispersion(q, KineticMetric::Paper);
            let closed = omega_closed_form(&chain.coefficients, q);
            for (x, y) in num.iter().zip(closed) {
                assert!(
                    (x - 2f64.sqrt() * y).abs() < 1e-9,
                    "alpha {alpha} q {q}: {x} vs {y}"
                );
            }
        }
    }
}

/// ω_+(0) = 4 ω_0 (s/a)|sin 2α| (printed: 2√2 ω_0 (s/a) sin 2α).
#[test]
fn gap_is_4_s_over_a_abs_sin_2alpha() {
    for alpha in [15.0, 45.0, 60.0, 86.0, -60.0] {
        let chain = BlochChain::new(&params(8, 1.3, alpha)).unwrap();
        let k = chain.coefficients;
        let expected = 4.0 * S / k.a * (2.0 * k.alpha).sin().abs();
        assert!((chain.gap(KineticMetric::Paper) - expected).abs() < 1e-9);
        assert!(
            (chain.gap(KineticMetric::Paper) - 2f64.sqrt() * gap_closed_form(&k).abs()).abs()
                < 1e-9
        );
        assert_eq!(
            chain.constrained_dispersion(0.0, KineticMetric::Paper)[0],
            0.0
        );
    }
}

/// With the consistent kinetic metric (θ inertia I + m (s/2)² sin²α) the
/// gap is 4 (s/a)|sin 2α| sqrt(I/(I + m (s/2)² sin²α)); the unconstrained
/// chain's top branch at q = 0 is 8γ sqrt(1/m + s² sin²α/(4I)).
#[test]
fn consistent_metric_and_unconstrained_gaps() {
    let p = params(8, 1.3, 60.0);
    let chain = BlochChain::new(&p).unwrap();
    let k = chain.coefficients;
    let i_c = p.inertia + 0.25 * (S * k.alpha.sin()).powi(2);
    let expected = chain.gap(KineticMetric::Paper) * (p.inertia / i_c).sqrt();
    assert!((chain.gap(KineticMetric::Constrained) - expected).abs() < 1e-9);
    let top = 8.0 * k.gamma * (1.0 + (S * k.alpha.sin()).powi(2) / (4.0 * p.inertia)).sqrt();
    assert!((chain.unconstrained_dispersion(0.0)[2] - top).abs() < 1e-9);
}

// ------------------------------------------------------------------ report

#[test]
fn report_numbers_for_the_paper_parameters() {
    let r = TheoryReport::compute(&params(10, 1.3, 60.0)).unwrap();
    assert!((r.a - (1.69f64 + 1.0).sqrt()).abs() < 1e-12);
    assert_eq!((r.u_min, r.winding_number), (-2.6, Some(1)));
    assert_eq!(
        (r.zero_modes_free, r.self_stress_free, r.zero_modes_clamped),
        (12, 0, 9)
    );
    assert!((r.kappa.unwrap() - (3.0321f64 / 0.4321).ln() / 1.3).abs() < 1e-3);
    assert!(r.omega_max > 2.0 && r.omega_max < 3.0);
    let sym = TheoryReport::compute(&params(10, 1.3, 90.0)).unwrap();
    assert_eq!((sym.kappa, sym.winding_number), (None, None));
    assert_eq!(
        (
            sym.zero_modes_free,
            sym.self_stress_free,
            sym.zero_modes_clamped
        ),
        (21, 9, 18)
    );
    let flat = TheoryReport::compute(&params(10, 1.3, 0.0)).unwrap();
    assert_eq!(
        (flat.kappa, flat.winding_number, flat.barrier),
        (Some(0.0), None, Some(0.0))
    );
    assert!(flat.gap_omega_plus_q0 < 1e-6);
}
