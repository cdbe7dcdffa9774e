//! The ring chain in motion: bodies, forces (gravity, contact, tapes) and
//! the step. The step is velocity Verlet (kick, drift, kick) with the
//! exact rotation of a symmetric top in the drift ([`Body::drift`]); the
//! forces are evaluated once per step, at the new positions and the
//! half-step velocities. The held ring follows the hand ([`super::hand`]).
//! Contacts come from the warm-started search ([`super::warm`], the
//! default), which falls back on the full one ([`super::contact`])
//! wherever it cannot guarantee to find what the full search would, or,
//! when [`System::search`] asks for it, from the full search alone.
//! Pairs are visited in index order and forces summed in that order, so
//! a run is deterministic and the mirrored chain its exact mirror image.

use super::alternate;
use super::body::{Body, Inertia};
use super::chain::{G, RingChain};
use super::contact::{self, Circle, Law, SAMPLES, Touch};
use super::guard;
use super::hand::{Hand, Lift};
use super::math::{self, M3, V3};
use super::warm;
use crate::error::{Error, Result};

/// A tape's joint: material points `a` on ring i and `b` on ring j (body
/// frames) held together by a stiff spring with critical damping.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pin {
    pub i: usize,
    pub j: usize,
    pub a: V3,
    pub b: V3,
}

/// One pass of the hand from the ring it held to another (a ring
/// scene's data file lists them as `rings.passes`).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Pass {
    /// When, s (the first step at or after the time asked).
    pub t: f64,
    /// The ring let go.
    pub from: usize,
    /// The ring taken.
    pub ring: usize,
    /// The kinetic energy of the ring taken, which the hand takes away
    /// by stopping it, J.
    pub kinetic: f64,
}

/// Counters of a run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stats {
    /// Pairs of rings checked by the linking guard (pair checks).
    pub guard_checks: u64,
    /// Largest overlap of two tubes, as a fraction of r.
    pub max_overlap: f64,
    /// Pairs of rings tested for contact (near enough to touch), over all
    /// steps.
    pub pair_evaluations: u64,
    /// Steps taken.
    pub steps: u64,
    /// Of the pairs tested, those searched in full (the rest warm,
    /// [`super::warm`]).
    pub full_searches: u64,
}

/// Which contact search the step uses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Search {
    /// The warm-started search, falling back on the full one where
    /// needed ([`super::warm`]): the default. Its contact points are
    /// Newton's (to rounding), the full search's four parabolas' (within
    /// 3·10⁻⁸ m); the trajectories differ by far less than the step's own
    /// error (docs/performance.md, "The warm-started contact search").
    #[default]
    Warm,
    /// The full search of every near pair at every step
    /// ([`contact::touches_at`]: the reference the warm search is checked
    /// against).
    Full,
}

/// The chain and its state.
#[derive(Clone, Debug)]
pub struct System {
    pub chain: RingChain,
    pub inertia: Inertia,
    pub law: Law,
    /// Linked pairs (i < j), sorted.
    pub links: Vec<[usize; 2]>,
    linked: Vec<bool>,
    pub pins: Vec<Pin>,
    /// Spring constant (N/m) and damping (N s/m) of a pin.
    pub pin_k: f64,
    pub pin_c: f64,
    pub bodies: Vec<Body>,
    pub hand: Hand,
    /// The ring the hand holds now (`chain.held`, then held + 1 once a
    /// `release` has passed the chain, or the ring the last pass of
    /// `alternate` took).
    pub held: usize,
    /// The hand's passes so far (`release`, `alternate`), in order.
    pub passes: Vec<Pass>,
    pub t: f64,
    pub dt: f64,
    /// The contact search.
    pub search: Search,
    table: [(f64, f64); SAMPLES],
    force: Vec<V3>,
    torque: Vec<V3>,
    /// Buffers the step reuses (no allocation per step): each ring's
    /// rotation, angular velocity and sample points, and the touches.
    scratch: Scratch,
    pub stats: Stats,
}

/// What [`System::evaluate`] fills anew at every step, kept between steps
/// so that a step allocates nothing, and what the warm search keeps of
/// each pair (`memos[i]`: (j, memo) for the pairs (i, j) ever near).
#[derive(Clone, Debug, Default)]
struct Scratch {
    rots: Vec<M3>,
    omega: Vec<V3>,
    points: Vec<[V3; SAMPLES]>,
    /// Whether `points[i]` is ring i's at this step.
    ready: Vec<bool>,
    touches: Vec<(usize, usize, Touch)>,
    memos: Vec<Vec<(usize, warm::Memo)>>,
}

/// The fraction of r past which an overlap fails the run.
pub const MAX_OVERLAP: f64 = 0.5;

impl System {
    /// A system from its parts (see [`super::build`]).
    pub fn new(chain: RingChain, bodies: Vec<Body>, hand: Hand, law: Law, dt: f64) -> System {
        let n = chain.n;
        let chain_held = chain.held;
        let links = chain.linked_pairs();
        let mut linked = vec![false; n * n];
        for &[a, b] in &links {
            linked[a * n + b] = true;
        }
        let (i_d, i_a) = chain.inertia();
        let inertia = Inertia {
            m: chain.mass(),
            i_d,
            i_a,
        };
        System {
            chain,
            inertia,
            law,
            links,
            linked,
            pins: Vec::new(),
            pin_k: 0.0,
            pin_c: 0.0,
            bodies,
            hand,
            held: chain_held,
            passes: Vec::new(),
            t: 0.0,
            dt,
            search: Search::default(),
            table: contact::sample_table(),
            force: vec![[0.0; 3]; n],
            torque: vec![[0.0; 3]; n],
            scratch: Scratch::default(),
            stats: Stats::default(),
        }
    }

    pub fn n(&self) -> usize {
        self.bodies.len()
    }

    /// Whether the topology links rings a < b.
    pub fn is_linked(&self, a: usize, b: usize) -> bool {
        self.linked[a.min(b) * self.n() + a.max(b)]
    }

    /// Ring k's centre circle.
    pub fn circle(&self, k: usize, rot: &M3) -> Circle {
        Circle {
            c: self.bodies[k].x,
            rot: *rot,
            radius: self.chain.major_radius,
        }
    }

    /// Whether rings i and j are near enough to touch.
    fn near(&self, i: usize, j: usize) -> bool {
        let reach = 2.0 * (self.chain.major_radius + self.chain.tube_radius);
        let d = math::sub(self.bodies[i].x, self.bodies[j].x);
        math::dot(d, d) < reach * reach
    }

    /// Angular velocity of each ring (the held one's from the hand).
    pub fn omegas(&self, rots: &[M3]) -> Vec<V3> {
        let mut out = Vec::new();
        self.omegas_into(rots, &mut out);
        out
    }

    /// [`System::omegas`] into `out`.
    fn omegas_into(&self, rots: &[M3], out: &mut Vec<V3>) {
        out.clear();
        out.extend((0..self.n()).map(|k| {
            if k == self.held {
                self.hand.omega(self.t)
            } else {
                self.bodies[k].omega(&rots[k], &self.inertia)
            }
        }));
    }

    /// Every touch of every near pair, in pair order.
    pub fn touches(&self, rots: &[M3]) -> Vec<(usize, usize, Touch)> {
        let (mut out, mut points) = (Vec::new(), Vec::new());
        self.touches_into(rots, &mut points, &mut out);
        out
    }

    /// Every touch of every near pair, in pair order, into `out` (cleared
    /// first), with each ring's sample points in `points`; returns the
    /// number of near pairs tested.
    fn touches_into(
        &self,
        rots: &[M3],
        points: &mut Vec<[V3; SAMPLES]>,
        out: &mut Vec<(usize, usize, Touch)>,
    ) -> u64 {
        out.clear();
        let mut pairs = 0;
        // Each ring's sample points once (the same arithmetic as per pair).
        points.resize(self.n(), [[0.0; 3]; SAMPLES]);
        for (i, p) in points.iter_mut().enumerate() {
            contact::sample_points_into(&self.circle(i, &rots[i]), &self.table, p);
        }
        let reach = self.law.reach;
        for i in 0..self.n() {
            let a = self.circle(i, &rots[i]);
            for j in i + 1..self.n() {
                if !self.near(i, j) {
                    continue;
                }
                pairs += 1;
                let b = self.circle(j, &rots[j]);
                contact::touches_at(&a, &points[i], &b, reach, &self.table, &mut |t| {
                    out.push((i, j, t))
                });
            }
        }
        pairs
    }

    /// Every touch of every near pair, in pair order, into
    /// `s.touches`: each pair's warm search from its memo, or its full
    /// search (and a new memo) where the warm one cannot answer. Returns
    /// the number of near pairs tested; counts the full searches.
    fn touches_warm(&mut self, s: &mut Scratch) -> u64 {
        let Scratch {
            rots,
            points,
            ready,
            touches,
            memos,
            ..
        } = s;
        touches.clear();
        let n = self.n();
        points.resize(n, [[0.0; 3]; SAMPLES]);
        ready.clear();
        ready.resize(n, false);
        memos.resize_with(n, Vec::new);
        let (reach, table) = (self.law.reach, &self.table);
        let (mut pairs, mut full) = (0, 0);
        for i in 0..n {
            let a = self.circle(i, &rots[i]);
            for j in i + 1..n {
                if !self.near(i, j) {
                    continue;
                }
                pairs += 1;
                let b = self.circle(j, &rots[j]);
                let mut push = |t| touches.push((i, j, t));
                let slot = memos[i].iter().position(|(k, _)| *k == j);
                if let Some(k) = slot
                    && warm::warm(&mut memos[i][k].1, &a, &b, reach, table, &mut push)
                {
                    continue;
                }
                if !ready[i] {
                    contact::sample_points_into(&a, table, &mut points[i]);
                    ready[i] = true;
                }
                full += 1;
                let memo = warm::full(&a, &points[i], &b, reach, table, &mut push);
                match slot {
                    Some(k) => memos[i][k].1 = memo,
                    None => memos[i].push((j, memo)),
                }
            }
        }
        self.stats.full_searches += full;
        pairs
    }

    /// Forces and torques at the current state, into `self.force`/`torque`.
    fn evaluate(&mut self) {
        let mut scratch = std::mem::take(&mut self.scratch);
        scratch.rots.clear();
        scratch
            .rots
            .extend(self.bodies.iter().map(|b| b.q.matrix()));
        self.omegas_into(&scratch.rots, &mut scratch.omega);
        let pairs = match self.search {
            Search::Full => {
                let pairs =
                    self.touches_into(&scratch.rots, &mut scratch.points, &mut scratch.touches);
                self.stats.full_searches += pairs;
                pairs
            }
            Search::Warm => self.touches_warm(&mut scratch),
        };
        self.stats.pair_evaluations += pairs;
        let (rots, omega) = (&scratch.rots, &scratch.omega);
        let weight = [0.0, 0.0, -self.inertia.m * G];
        self.force.iter_mut().for_each(|f| *f = weight);
        self.torque.iter_mut().for_each(|t| *t = [0.0; 3]);
        for &(i, j, touch) in &scratch.touches {
            let c = math::scale(math::add(touch.p, touch.q), 0.5);
            let v_rel = math::sub(
                self.bodies[i].velocity_at(omega[i], c),
                self.bodies[j].velocity_at(omega[j], c),
            );
            let f = self.law.force(&touch, v_rel);
            self.apply(i, c, f);
            self.apply(j, c, math::scale(f, -1.0));
            let overlap = (self.law.reach - touch.d) / self.chain.tube_radius;
            self.stats.max_overlap = self.stats.max_overlap.max(overlap);
        }
        for k in 0..self.pins.len() {
            let pin = self.pins[k];
            let (pa, pb) = self.pin_points(&pin, rots);
            let dv = math::sub(
                self.bodies[pin.i].velocity_at(omega[pin.i], pa),
                self.bodies[pin.j].velocity_at(omega[pin.j], pb),
            );
            let stretch = math::sub(pa, pb);
            let f = math::axpy(math::scale(stretch, -self.pin_k), -self.pin_c, dv);
            self.apply(pin.i, pa, f);
            self.apply(pin.j, pb, math::scale(f, -1.0));
        }
        self.scratch = scratch;
    }

    /// The force on the ring in the hand at the last evaluation (its
    /// weight, its contacts and tapes), N: what the hand must balance,
    /// so that the hand's power on it is (m a − this)·v.
    pub fn held_force(&self) -> V3 {
        self.force[self.held]
    }

    /// The touches of the last evaluation of the forces (those the step
    /// used), in pair order.
    pub fn last_touches(&self) -> &[(usize, usize, Touch)] {
        &self.scratch.touches
    }

    /// World positions of a pin's two material points.
    pub fn pin_points(&self, pin: &Pin, rots: &[M3]) -> (V3, V3) {
        let pa = math::add(self.bodies[pin.i].x, math::mul_mv(&rots[pin.i], pin.a));
        let pb = math::add(self.bodies[pin.j].x, math::mul_mv(&rots[pin.j], pin.b));
        (pa, pb)
    }

    fn apply(&mut self, k: usize, at: V3, f: V3) {
        self.force[k] = math::add(self.force[k], f);
        let arm = math::sub(at, self.bodies[k].x);
        self.torque[k] = math::add(self.torque[k], math::cross(arm, f));
    }

    /// Half a kick: v += h F/m, L += h τ (the held ring excepted).
    fn kick(&mut self, h: f64) {
        let m = self.inertia.m;
        for k in 0..self.n() {
            if k == self.held {
                continue;
            }
            let b = &mut self.bodies[k];
            b.v = math::axpy(b.v, h / m, self.force[k]);
            b.l = math::axpy(b.l, h, self.torque[k]);
        }
    }

    /// Prepares the first step (forces at the start).
    pub fn start(&mut self) {
        self.place_held();
        self.evaluate();
    }

    /// With `release`, at `turn.start` the hand takes ring held + 1 where
    /// it is (stopped) and lets the held ring go. With `alternate`, at
    /// each of its times the hand lets the held ring go and takes the top
    /// ring of the other strand where it is (stopped).
    fn pass_hand(&mut self) {
        if self.chain.release && self.held == self.chain.held && self.t >= self.chain.turn.start {
            self.take(self.held + 1);
        } else if let Some(a) = self.chain.alternate
            && self.passes.len() < a.count
            && self.t >= a.time(self.passes.len())
        {
            let other = 1 - RingChain::strand(self.held);
            self.take(alternate::top_ring(&self.bodies, other));
        }
    }

    /// The hand lets the held ring go (as the hand holds it at this
    /// step: at rest, unless a lift as long as the period has not quite
    /// ended) and holds ring k where it is, stopped: its pose frozen, its
    /// motion taken away by the hand. With `alternate.lift` the hand then
    /// carries ring k to where it held the ring let go (the end of the
    /// last lift, or the held ring's centre at the first pass).
    fn take(&mut self, k: usize) {
        self.place_held();
        let place = self
            .hand
            .lift
            .map_or(self.bodies[self.held].x, |lift| lift.to);
        let b = self.bodies[k];
        let kinetic = b.kinetic(&b.q.matrix(), &self.inertia);
        self.hand.grip = Some(Body {
            v: [0.0; 3],
            l: [0.0; 3],
            ..b
        });
        self.passes.push(Pass {
            t: self.t,
            from: self.held,
            ring: k,
            kinetic,
        });
        self.held = k;
        let duration = self.chain.alternate.map_or(0.0, |a| a.lift);
        self.hand.lift = (duration > 0.0).then_some(Lift {
            from: b.x,
            to: place,
            t0: self.t,
            duration,
        });
    }

    fn place_held(&mut self) {
        let k = self.held;
        self.bodies[k] = self.hand.body(self.t);
    }

    /// One step of dt; fails on an overlap past [`MAX_OVERLAP`] or a
    /// non-finite state.
    pub fn step(&mut self) -> Result<()> {
        let dt = self.dt;
        self.kick(0.5 * dt);
        for k in 0..self.n() {
            if k != self.held {
                let inertia = self.inertia;
                self.bodies[k].drift(dt, &inertia);
            }
        }
        self.t += dt;
        self.pass_hand();
        self.place_held();
        self.evaluate();
        self.kick(0.5 * dt);
        self.stats.steps += 1;
        if self.stats.max_overlap > MAX_OVERLAP {
            return Err(Error::failed(format!(
                "the ring chain failed at t = {:.4} s: two tubes overlapped by {:.0} % of r (the \
                 contact no longer resembles steel); hint: a smaller `overlap` (stiffer contact) \
                 or a smaller dt",
                self.t,
                100.0 * self.stats.max_overlap
            )));
        }
        if !self
            .bodies
            .iter()
            .all(|b| b.x.iter().chain(&b.v).all(|c| c.is_finite()))
        {
            return Err(Error::failed(format!(
                "the ring chain diverged at t = {:.4} s (dt = {:.3e} s); hint: a smaller dt",
                self.t, self.dt
            )));
        }
        Ok(())
    }

    /// The linking guard: every linked pair still linked, every other
    /// near pair still apart; the first change fails the run.
    pub fn check_links(&mut self) -> Result<()> {
        let rots: Vec<M3> = self.bodies.iter().map(|b| b.q.matrix()).collect();
        for i in 0..self.n() {
            for j in i + 1..self.n() {
                let listed = self.is_linked(i, j);
                if !listed && !self.near(i, j) {
                    continue;
                }
                self.stats.guard_checks += 1;
                let now = guard::linked(&self.circle(i, &rots[i]), &self.circle(j, &rots[j]));
                if now != listed {
                    return Err(Error::failed(format!(
                        "the linking guard failed at t = {:.4} s: rings {i} and {j} {} (a ring \
                         passed through another's tube, so the chain is no longer the one \
                         asked); hint: a smaller dt or a stiffer contact (smaller `overlap`)",
                        self.t,
                        if listed {
                            "came apart"
                        } else {
                            "became linked"
                        }
                    )));
                }
            }
        }
        Ok(())
    }

    /// Total energy, J: kinetic and potential of every ring, the one in
    /// the hand included (its weight's potential, and its kinetic energy
    /// as the hand moves it: the lift's; the hand's turn is not counted,
    /// its held ring's angular momentum being kept 0), so that a pass of
    /// the hand from one ring to another moves no energy but the kinetic
    /// energy of the ring it stops; and the elastic energy of contacts
    /// and tapes.
    pub fn energy(&self) -> f64 {
        let rots: Vec<M3> = self.bodies.iter().map(|b| b.q.matrix()).collect();
        let mut e = 0.0;
        for (k, b) in self.bodies.iter().enumerate() {
            e += b.kinetic(&rots[k], &self.inertia) + self.inertia.m * G * b.x[2];
        }
        for (_, _, touch) in self.touches(&rots) {
            e += self.law.energy(&touch);
        }
        for pin in &self.pins {
            let (pa, pb) = self.pin_points(pin, &rots);
            let s = math::sub(pa, pb);
            e += 0.5 * self.pin_k * math::dot(s, s);
        }
        e
    }
}
