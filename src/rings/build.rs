//! The chain at the start: ring k hangs at depth k·s below the held ring,
//! its plane vertical and turned k·β about the vertical. For the double
//! chain (ring k linked with k + 1 and k + 2, the default) s = R − r and
//! β = 45°: ring k rests on ring k − 2 of its own strand (their wires
//! touch) and passes loosely through ring k − 1 of the other; for a
//! single chain (k with k + 1) s = 2(R − r) and β = 90°; the tumbling
//! rings (k with k + 2, 2j with 2j + 1) are a guess the run lets settle
//! ([`tumbling_guess`]). The built chain
//! must realise the topology asked, pair by pair, or the scene is refused.
//! Tapes join two rings at their crossing (docs/rings.md).

use super::body::Body;
use super::chain::{G, RingChain, TapeKind};
use super::contact::{self, Law};
use super::guard;
use super::hand::Hand;
use super::math::{self, M3, Quat, V3};
use super::system::{Pin, System};
use crate::error::{Error, Result};

/// Typical impact speed for the Hunt–Crossley damping, m/s: a ring
/// dropping by its radius, √(2gR), at R = 12.5 mm.
pub const IMPACT_SPEED: f64 = 0.5;

/// Contact periods per step of the automatic time step.
pub const STEPS_PER_PERIOD: f64 = 20.0;

/// The fraction of friction's stability limit (an explicit damper of
/// rate c/m_eff is stable for dt < 2 m_eff/c) the automatic step takes.
pub const FRICTION_MARGIN: f64 = 0.75;

/// The chain's spacing s and turn β per ring, for its topology.
fn layout(chain: &RingChain) -> (f64, f64) {
    let single: Vec<[usize; 2]> = (0..chain.n - 1).map(|k| [k, k + 1]).collect();
    let s = chain.major_radius - chain.tube_radius;
    if chain.linked_pairs() == single {
        (2.0 * s, 90f64.to_radians())
    } else {
        (s, 45f64.to_radians())
    }
}

/// The contact law and the automatic step: Hertz stiffness such that the
/// weight of the whole chain W overlaps one contact by `overlap`·r; the
/// contact's frequency at that load, √(1.5 W/δ / m_eff) with m_eff = m/6
/// (two rings pushed at the rim, their turning included), over
/// [`STEPS_PER_PERIOD`]; and within [`FRICTION_MARGIN`] of the stability
/// limit of friction's regularised damping at that load, 2 m_eff v_ε/(μW).
pub fn law_and_step(chain: &RingChain) -> (Law, f64) {
    let m = chain.mass();
    let weight = chain.n as f64 * m * G;
    let delta = chain.overlap * chain.tube_radius;
    let k = weight / (delta * delta.sqrt());
    let law = Law {
        k,
        chi: 1.5 * (1.0 - chain.restitution) / IMPACT_SPEED,
        mu: chain.friction,
        slip: chain.slip_speed,
        reach: 2.0 * chain.tube_radius,
    };
    let m_eff = m / 6.0;
    let omega = (1.5 * weight / delta / m_eff).sqrt();
    let mut dt = std::f64::consts::TAU / omega / STEPS_PER_PERIOD;
    if chain.friction > 0.0 {
        dt = dt.min(FRICTION_MARGIN * 2.0 * m_eff * chain.slip_speed / (chain.friction * weight));
    }
    (law, if chain.dt > 0.0 { chain.dt } else { dt })
}

/// The system at t = 0: the chain built, checked against its topology,
/// tapes pinned, forces evaluated.
pub fn build(chain: &RingChain) -> Result<System> {
    chain.validated()?;
    assemble(chain, as_built(chain), true)
}

/// Each ring's pose in the chain as built (unmirrored, at rest): ring k
/// at depth k·s below the held ring, its plane vertical, turned k·β.
pub fn as_built(chain: &RingChain) -> Vec<Body> {
    if chain.is_tumbling() {
        return tumbling_guess(chain);
    }
    let (s, beta) = layout(chain);
    let tilt = Quat::axis_angle([0.0, 1.0, 0.0], std::f64::consts::FRAC_PI_2);
    (0..chain.n)
        .map(|k| Body {
            x: [0.0, 0.0, -s * (k as f64 - chain.held as f64)],
            v: [0.0; 3],
            q: Quat::axis_angle([0.0, 0.0, 1.0], beta * k as f64).mul(tilt),
            l: [0.0; 3],
        })
        .collect()
}

/// The tumbling rings' guess (not at rest: the run settles it): each
/// strand a simple chain on its own vertical axis, its rings 1.6 R apart
/// and turned 90° from one to the next; the even strand on the held
/// ring's axis (ring 0 facing x, as the double chain's), the odd strand on
/// an axis (R/2, R/2) beside it and half a spacing lower, each odd ring
/// 2j + 1 turned 90° from ring 2j so that it passes through it (the rung)
/// and lies parallel to ring 2j + 2 (no link).
pub fn tumbling_guess(chain: &RingChain) -> Vec<Body> {
    let r = chain.major_radius;
    let p = 1.6 * r;
    let tilt = Quat::axis_angle([0.0, 1.0, 0.0], std::f64::consts::FRAC_PI_2);
    let z0 = if chain.held.is_multiple_of(2) {
        -p * (chain.held / 2) as f64
    } else {
        -p * (chain.held / 2) as f64 - 0.5 * p
    };
    (0..chain.n)
        .map(|k| {
            let j = k / 2;
            let (x, z, quarter) = if k.is_multiple_of(2) {
                ([0.0, 0.0], -p * j as f64, j)
            } else {
                ([0.5 * r, 0.5 * r], -p * j as f64 - 0.5 * p, j + 1)
            };
            let azimuth = std::f64::consts::FRAC_PI_2 * (quarter % 2) as f64;
            Body {
                x: [x[0], x[1], z - z0],
                v: [0.0; 3],
                q: Quat::axis_angle([0.0, 0.0, 1.0], azimuth).mul(tilt),
                l: [0.0; 3],
            }
        })
        .collect()
}

/// The system from the rings' poses (unmirrored): the hand holds the
/// held ring as posed, the chain is mirrored if asked, checked against
/// its topology, its tapes pinned (if `tapes`) where their rings cross,
/// forces evaluated; refused if two tubes overlap past `overlap`.
pub fn assemble(chain: &RingChain, bodies: Vec<Body>, tapes: bool) -> Result<System> {
    let held = bodies[chain.held];
    let mut turn = chain.turn;
    if chain.release || chain.alternate.is_some() {
        turn.angle = 0.0;
    }
    let hand = Hand {
        x: held.x,
        q0: held.q,
        turn,
        mirror: chain.mirror,
        grip: None,
        lift: None,
    };
    let bodies = if chain.mirror {
        bodies.iter().map(Body::mirrored).collect()
    } else {
        bodies
    };
    let (law, dt) = law_and_step(chain);
    let mut sys = System::new(chain.clone(), bodies, hand, law, dt);
    check_topology(&sys)?;
    if tapes {
        pin_tapes(&mut sys)?;
    }
    sys.start();
    if sys.stats.max_overlap > chain.overlap {
        return Err(Error::bad_input(format!(
            "rings: the chain as built has tubes overlapping by {:.0} % of r: R = {} m is too \
             small for r = {} m",
            100.0 * sys.stats.max_overlap,
            chain.major_radius,
            chain.tube_radius
        )));
    }
    sys.stats = Default::default();
    Ok(sys)
}

fn rotations(sys: &System) -> Vec<M3> {
    sys.bodies.iter().map(|b| b.q.matrix()).collect()
}

/// Refuses a topology the built chain does not realise.
fn check_topology(sys: &System) -> Result<()> {
    let rots = rotations(sys);
    for i in 0..sys.n() {
        for j in i + 1..sys.n() {
            let built = guard::linked(&sys.circle(i, &rots[i]), &sys.circle(j, &rots[j]));
            if built != sys.is_linked(i, j) {
                return Err(Error::bad_input(format!(
                    "rings: the links {} rings {i} and {j}, but the chain as built ({}) {} them; \
                     the program builds the double chain (ring k linked with k + 1 and k + 2), \
                     the tumbling rings (k with k + 2, 2j with 2j + 1) and the single chain \
                     (k with k + 1)",
                    if built { "leave apart" } else { "interlock" },
                    "each ring hanging through the ones above it",
                    if built { "links" } else { "does not link" },
                )));
            }
        }
    }
    Ok(())
}

/// Pins each tape at the crossing of its two rings (and, for a weld, at
/// two more points half a radius away along ring i's normal and radius).
pub fn pin_tapes(sys: &mut System) -> Result<()> {
    let rots = rotations(sys);
    let chain = sys.chain.clone();
    let table = contact::sample_table();
    for &[i, j] in &chain.tapes {
        let (a, b) = (sys.circle(i, &rots[i]), sys.circle(j, &rots[j]));
        let reach = 4.0 * chain.tube_radius;
        let Some(touch) = contact::touches(&a, &b, reach, &table).first().copied() else {
            return Err(Error::bad_input(format!(
                "rings: a tape between rings {i} and {j}, which do not touch in the chain as \
                 built (a tape joins two rings where their wires cross)"
            )));
        };
        let c = math::scale(math::add(touch.p, touch.q), 0.5);
        let mut points: Vec<V3> = vec![c];
        if chain.tape == TapeKind::Weld {
            let half = 0.5 * chain.major_radius;
            let radial = math::sub(c, a.c);
            let radial = math::scale(radial, half / math::norm(radial));
            points.push(math::axpy(c, half, Body::normal(&rots[i])));
            points.push(math::add(c, radial));
        }
        for p in points {
            let body = |k: usize| math::mul_mtv(&rots[k], math::sub(p, sys.bodies[k].x));
            sys.pins.push(Pin {
                i,
                j,
                a: body(i),
                b: body(j),
            });
        }
    }
    // As stiff as a contact at the chain's weight, critically damped.
    let m_eff = sys.inertia.m / 6.0;
    let weight = chain.n as f64 * sys.inertia.m * G;
    sys.pin_k = 1.5 * weight / (chain.overlap * chain.tube_radius);
    sys.pin_c = 2.0 * (sys.pin_k * m_eff).sqrt();
    Ok(())
}
