//! The ring chain's normal modes at rest (docs/rings.md, "What the
//! simulation shows"; `src/rings/modes.rs`): the Hessian of the
//! program's potential, by differences of its own forces, against the
//! closed form of one ring hanging from the held ring, symmetric at rest,
//! and the mirrored chain's spectrum the same as the chain's.

use jacobs_ladder::rings::chain::G;
use jacobs_ladder::rings::system::System;
use jacobs_ladder::rings::{RingChain, build, modes};

/// ω of every mode (rad/s, lowest first), the error scale in ω² and K's
/// asymmetry, the chain relaxed with ring 0 held.
fn spectrum(sys: &mut System) -> (Vec<f64>, f64, f64) {
    let relaxed = modes::relax(sys, &[0], 1e-9, 100);
    assert!(relaxed.residual < 1e-9, "{relaxed:?}");
    let c = modes::coords(sys, &[0]);
    let k = modes::stiffness(sys, &c);
    let m = modes::mass(sys, &c);
    let w: Vec<f64> = modes::modes(&k, &m)
        .iter()
        .map(|(w2, _)| modes::omega(*w2))
        .collect();
    (w, modes::noise(&k, &m), modes::asymmetry(&k))
}

/// Ring 1 hangs from the held ring 0 (the single chain: their planes
/// crossed at 90°), ring 1's top wire on ring 0's bottom wire: its centre
/// line's top point P lies ℓ = R − 2r + δ from ring 0's centre, δ the
/// overlap under its weight, (mg/k)^{2/3}. Its five modes (the turn about
/// its own normal left out): the twist about the vertical through P,
/// free (0); the swing in its own plane, a point pendulum of length ℓ
/// with its spin free (ω² = g/ℓ); the two swings across it, P sliding on
/// a circle of radius ℓ about ring 0's centre and the ring turning about
/// P (a double pendulum, ω⁴ ℓ i − ω² g (R² + i + Rℓ) + g² R = 0, i =
/// I_diameter/m); and the bounce on the contact, ω² = 1.5 g/δ (Hertz's
/// stiffness 1.5 k δ^{1/2} at load mg).
#[test]
fn one_ring_hanging_from_the_held_ring_has_the_closed_form_modes() {
    let chain = RingChain {
        n: 2,
        ..Default::default()
    };
    let mut sys = build::build(&chain).unwrap();
    let (w, noise, _) = spectrum(&mut sys);
    let (r_c, r_t) = (chain.major_radius, chain.tube_radius);
    let m = chain.mass();
    let delta = (m * G / sys.law.k).powf(2.0 / 3.0);
    let ell = r_c - 2.0 * r_t + delta;
    let i = chain.inertia().0 / m;
    let (a, b, c) = (ell * i, G * (r_c * r_c + i + r_c * ell), G * G * r_c);
    let root = (b * b - 4.0 * a * c).sqrt();
    let expected = [
        0.0,
        ((b - root) / (2.0 * a)).sqrt(),
        (G / ell).sqrt(),
        ((b + root) / (2.0 * a)).sqrt(),
        (1.5 * G / delta).sqrt(),
    ];
    assert_eq!(w.len(), 5, "{w:?}");
    assert!(
        w[0].abs() < noise.sqrt().max(0.1),
        "twist {} (noise {noise:e})",
        w[0]
    );
    for k in 1..5 {
        let rel = (w[k] - expected[k]).abs() / expected[k];
        assert!(
            rel < 2e-3,
            "mode {k}: {} rad/s against {} ({w:?})",
            w[k],
            expected[k]
        );
    }
    // One touch, four mechanisms: every motion but the bounce keeps it.
    let coords = modes::coords(&sys, &[0]);
    assert_eq!(modes::rank(&modes::compatibility(&sys, &coords)), 1);
}

/// The 4-ring double chain as built, relaxed (it rests at a saddle: the
/// built chain is symmetric, and two of its modes have ω² < 0): K is
/// symmetric at rest to the differences' accuracy, and the mirrored chain
/// (x → −x) has the same spectrum, mode by mode.
#[test]
fn the_hessian_is_symmetric_and_the_mirror_chain_has_the_same_modes() {
    let hang = |mirror: bool| {
        let chain = RingChain {
            n: 4,
            mirror,
            ..Default::default()
        };
        spectrum(&mut build::build(&chain).unwrap())
    };
    let (w, noise, asym) = hang(false);
    let (w_m, _, asym_m) = hang(true);
    assert!(
        asym < 1e-8 && asym_m < 1e-8,
        "asymmetry {asym:e}, mirrored {asym_m:e}"
    );
    assert_eq!(w.len(), 15);
    assert_eq!(w.len(), w_m.len());
    for (a, b) in w.iter().zip(&w_m) {
        assert!(
            (a - b).abs() < 1e-6 * a.abs() + noise.sqrt(),
            "{w:?}\n{w_m:?}"
        );
    }
}
