//! The leaning start (paper Fig. 4b: "by releasing the top ring, we
//! observed a helical solitary wave"): the chain is not posed by hand but
//! let settle under gravity from a leaning guess, with a damping that
//! takes out its motion, until it is at rest (decided from the state:
//! every ring's fastest point slower than [`REST_SPEED`]). The hand holds
//! the top ring still throughout; the tapes are pinned where the settled
//! rings cross. docs/rings.md, "The leaning start".

use super::body::Body;
use super::build;
use super::chain::RingChain;
use super::math::{self, M3, Quat};
use super::system::System;
use crate::error::{Error, Result};

/// Damping rate of the settle stage, 1/s: velocities and angular momenta
/// are scaled by exp(−rate·dt) each step (a numerical stage, not physics:
/// it only brings the chain to rest).
pub const RATE: f64 = 20.0;
/// A chain whose every ring's fastest point moves slower than this, m/s,
/// is at rest. Not smaller: the penalty contacts of the chain as built
/// keep its fastest point at about 5 mm/s under this damping (a 12-ring
/// chain, 4 s), so a tighter bound is never met (docs/rings.md).
pub const REST_SPEED: f64 = 1e-2;
/// The longest settle, s of chain time; a chain not at rest by then fails.
pub const MAX_TIME: f64 = 4.0;
/// The shortest settle, s of chain time: a guess starts at rest, and its
/// rings take about √(4R/g) = 0.07 s (R = 12.5 mm) to fall onto one
/// another; before that the rest test would end it at once (the 30-ring
/// tumbling chain's guess was "at rest" after 20 steps, 6 mm/s).
pub const MIN_TIME: f64 = 0.2;

/// How a settle ended (the data file's `rings.settled`).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Settled {
    /// Chain time it took, s.
    pub time: f64,
    /// Steps it took.
    pub steps: u64,
    /// The fastest point of any ring at the end, m/s.
    pub speed: f64,
}

/// The leaning guess: the chain as built with every ring tilted by
/// `lean` (degrees) about the horizontal diameter in its plane, all the
/// same way (n_z = sin lean > 0), and its spacing scaled by `squeeze`.
pub fn leaning_guess(chain: &RingChain, lean: f64, squeeze: f64) -> Vec<Body> {
    build::as_built(chain)
        .into_iter()
        .map(|b| {
            let rot = b.q.matrix();
            // The horizontal diameter in the ring's plane: the body x or y
            // axis, whichever is horizontal (the built ring's body x is
            // vertical).
            let h = [rot[0][1], rot[1][1], rot[2][1]];
            let q = Quat::axis_angle(h, -lean.to_radians()).mul(b.q);
            Body {
                x: [b.x[0], b.x[1], b.x[2] * squeeze],
                q: q.normalized(),
                ..b
            }
        })
        .collect()
}

/// The fastest point of ring k: |v| + R|ω|.
fn speed(sys: &System, k: usize, rot: &M3) -> f64 {
    let b = &sys.bodies[k];
    let w = b.omega(rot, &sys.inertia);
    math::norm(b.v) + sys.chain.major_radius * math::norm(w)
}

/// Steps `sys` with its hand still and the damping of [`RATE`] until it
/// is at rest; then zeroes its motion, its clock and its counters.
pub fn settle(sys: &mut System) -> Result<Settled> {
    let (turn, release) = (sys.hand.turn, sys.chain.release);
    let alternate = sys.chain.alternate.take();
    sys.hand.turn.angle = 0.0;
    sys.chain.release = false;
    let keep = (-RATE * sys.dt).exp();
    let every = sys.chain.guard_every as u64;
    let mut steps = 0u64;
    let fastest = loop {
        sys.step()?;
        steps += 1;
        let held = sys.held;
        for (k, b) in sys.bodies.iter_mut().enumerate() {
            if k != held {
                b.v = math::scale(b.v, keep);
                b.l = math::scale(b.l, keep);
            }
        }
        if !steps.is_multiple_of(every) {
            continue;
        }
        sys.check_links()?;
        let fastest = (0..sys.n())
            .filter(|&k| k != held)
            .map(|k| speed(sys, k, &sys.bodies[k].q.matrix()))
            .fold(0.0, f64::max);
        if fastest < REST_SPEED && sys.t >= MIN_TIME {
            break fastest;
        }
        if sys.t > MAX_TIME {
            let (start, hint) = if sys.chain.is_tumbling() {
                (
                    "the tumbling rings' guess",
                    "at the defaults 30 tumbling rings settle in about 1 s of chain time \
                     (docs/rings.md, \"The tumbling rings\"): compare your keys with them",
                )
            } else {
                ("its leaning start", "a smaller lean")
            };
            return Err(Error::failed(format!(
                "the ring chain did not come to rest from {start} within {MAX_TIME} s (a ring \
                 still moves at {fastest:.3} m/s); hint: {hint}"
            )));
        }
    };
    let done = Settled {
        time: sys.t,
        steps,
        speed: fastest,
    };
    for b in &mut sys.bodies {
        b.v = [0.0; 3];
        b.l = [0.0; 3];
    }
    sys.hand.turn = turn;
    sys.chain.release = release;
    sys.chain.alternate = alternate;
    sys.t = 0.0;
    Ok(done)
}

/// The most pins on one ring. Each pin is damped critically for one
/// contact's mass (m/6); the settled chain's welded rings also touch
/// their neighbours, and the sum of the dampers on one ring must stay
/// within the explicit step's limit (dt < 2 m_eff/c): so the pin damping
/// is shared among a ring's pins (with the chain as built, each pin's own
/// critical damping is stable; here 6 pins on a ring of the taped strand
/// failed within 5 ms, docs/rings.md).
fn most_pins(sys: &System) -> usize {
    let mut count = vec![0usize; sys.n()];
    for p in &sys.pins {
        count[p.i] += 1;
        count[p.j] += 1;
    }
    count.into_iter().max().unwrap_or(0).max(1)
}

/// The leaning guess assembled (no tapes, not settled): refuses, with
/// one line, a guess that does not realise the chain's topology.
pub fn guess(chain: &RingChain, lean: f64, squeeze: f64) -> Result<System> {
    chain.validated()?;
    build::assemble(chain, leaning_guess(chain, lean, squeeze), false).map_err(|e| match e {
        Error::BadInput(m) => Error::bad_input(format!(
            "rings: the leaning start (angle {lean}°, squeeze {squeeze}) is not the chain's \
             topology: {}; hint: a smaller angle with a squeeze near 1 − angle/100 (30° and \
             0.7 settle, docs/rings.md)",
            m.strip_prefix("rings: ").unwrap_or(&m)
        )),
        e => e,
    })
}

/// The tumbling rings' guess ([`build::tumbling_guess`]) assembled (no
/// tapes, not settled): the tapes are pinned where the settled rings
/// cross.
pub fn tumbling_assembled(chain: &RingChain) -> Result<System> {
    chain.validated()?;
    build::assemble(chain, build::as_built(chain), false)
}

/// The chain settled from the leaning guess, its tapes pinned where the
/// settled rings cross, ready to run from t = 0.
pub fn leaning(chain: &RingChain, lean: f64, squeeze: f64) -> Result<(System, Settled)> {
    settled_from(chain, guess(chain, lean, squeeze)?)
}

/// The chain settled from the guess `sys` (assembled without tapes), its
/// tapes pinned where the settled rings cross, ready to run from t = 0.
pub fn settled_from(chain: &RingChain, mut sys: System) -> Result<(System, Settled)> {
    let done = settle(&mut sys)?;
    let mut bodies = sys.bodies.clone();
    if chain.mirror {
        bodies = bodies.iter().map(Body::mirrored).collect();
    }
    let mut sys = build::assemble(chain, bodies, true)?;
    sys.pin_c /= most_pins(&sys) as f64;
    sys.stats = Default::default();
    Ok((sys, done))
}
