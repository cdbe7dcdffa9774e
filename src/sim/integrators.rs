//! Six time integrators behind one interface: explicit (forward) Euler,
//! symplectic (semi-implicit) Euler, velocity Verlet, classical RK4,
//! adaptive Dormand–Prince 5(4), and Moreau's time-stepping for
//! inextensible ribbons (`moreau`).
//!
//! Each `advance` call takes one step from `t` towards `t_stop` and lands
//! exactly on `t_stop` when the rest of the interval fits in one step; the
//! run loop puts every sample time and every drive corner into `t_stop`.

use super::budget::Quadrature;
use super::chain::{ChainEuler, ChainVerlet};
use super::fused::{Batch, FusedEuler, Stepping};
use super::observables::ArrivalDetector;
use super::rhs::{Rhs, State};
pub use super::stepping::ImplicitDamping;
pub(super) use super::stepping::Plan;
pub use super::tableau::{DOPRI5, RK4, Tableau};
use super::terms_rk4::TermsRk4;
use crate::error::{Error, Result};
use std::fmt;
use std::str::FromStr;

mod dopri5;
mod moreau;
pub use dopri5::{ATOL_SCALE, DOPRI5_MAX_STEP, Dopri5};

/// The integrators of README.md, by their command-line names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum IntegratorKind {
    ExplicitEuler,
    SymplecticEuler,
    Verlet,
    Rk4,
    Dopri5,
    /// Moreau's time-stepping, for inextensible ribbons only
    /// (`integrators::moreau`).
    Moreau,
}

impl IntegratorKind {
    pub const ALL: [Self; 6] = [
        Self::ExplicitEuler,
        Self::SymplecticEuler,
        Self::Verlet,
        Self::Rk4,
        Self::Dopri5,
        Self::Moreau,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Self::ExplicitEuler => "explicit-euler",
            Self::SymplecticEuler => "symplectic-euler",
            Self::Verlet => "verlet",
            Self::Rk4 => "rk4",
            Self::Dopri5 => "dopri5",
            Self::Moreau => "moreau",
        }
    }

    /// Order of convergence of the global error.
    pub fn order(self) -> u32 {
        match self {
            Self::ExplicitEuler | Self::SymplecticEuler | Self::Moreau => 1,
            Self::Verlet => 2,
            Self::Rk4 => 4,
            Self::Dopri5 => 5,
        }
    }

    /// Force evaluations per step (excluding dopri5's rejected steps).
    pub fn evals_per_step(self) -> u32 {
        match self {
            Self::ExplicitEuler | Self::SymplecticEuler | Self::Verlet | Self::Moreau => 1,
            Self::Rk4 => 4,
            Self::Dopri5 => 6,
        }
    }
}

impl fmt::Display for IntegratorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for IntegratorKind {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        Self::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| {
                let names: Vec<_> = Self::ALL.iter().map(|k| k.name()).collect();
                Error::bad_input(format!(
                    "unknown integrator '{s}'; choose one of {}",
                    names.join(", ")
                ))
            })
    }
}

/// The largest step of [`IntegratorConfig::auto`] (τ).
pub const AUTO_DT: f64 = 0.25;
/// The fraction of velocity Verlet's stability bound 2/ω_max that
/// [`IntegratorConfig::auto`] stays below.
pub const AUTO_STABILITY_FRACTION: f64 = 0.4;

/// Integration parameters, kept apart from the model's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IntegratorConfig {
    pub kind: IntegratorKind,
    /// Step for the fixed-step schemes; first trial step for dopri5.
    pub dt: f64,
    /// Relative (and absolute) tolerance of dopri5; `None` runs dopri5 with
    /// the fixed step `dt` and no error control (for convergence studies).
    pub rtol: Option<f64>,
}

impl IntegratorConfig {
    /// The paper's setting: symplectic Euler, dt = 0.01 (README.md default).
    pub fn paper() -> Self {
        Self {
            kind: IntegratorKind::SymplecticEuler,
            dt: 0.01,
            rtol: None,
        }
    }

    pub fn fixed(kind: IntegratorKind, dt: f64) -> Self {
        Self {
            kind,
            dt,
            rtol: None,
        }
    }

    /// `--integrator auto`: the measured best choice for these scenes
    /// (`ladder bench work-precision`, docs/performance.md). Velocity Verlet
    /// was the cheapest setting whose arrival times stay within 1 τ of the
    /// reference, at dt = 0.6 for the α = ±60° scenes (6801 force
    /// evaluations, 77 % of its stability bound 2/ω_max). `auto` keeps a
    /// margin: dt = min([`AUTO_DT`], [`AUTO_STABILITY_FRACTION`] · 2/ω_max),
    /// where `omega_max` is the highest normal mode of the clamped chain
    /// (`theory::dispersion::omega_max_clamped`); 0.25 τ for the paper's
    /// parameters, the step every simulated scene of the catalogue uses.
    pub fn auto(omega_max: f64) -> Self {
        let bound = AUTO_STABILITY_FRACTION * 2.0 / omega_max;
        let dt = if bound.is_finite() && bound > 0.0 {
            AUTO_DT.min(bound)
        } else {
            AUTO_DT
        };
        Self::fixed(IntegratorKind::Verlet, dt)
    }

    pub fn adaptive(rtol: f64) -> Self {
        Self {
            kind: IntegratorKind::Dopri5,
            dt: 0.1,
            rtol: Some(rtol),
        }
    }

    /// Rejects dt ≤ 0, NaN or infinite, and rtol outside (0, 1).
    pub fn validated(self) -> Result<Self> {
        if !(self.dt.is_finite() && self.dt > 0.0) {
            return Err(Error::bad_input(format!(
                "dt must be a finite number > 0, got {}",
                crate::error::num(self.dt)
            )));
        }
        if let Some(r) = self.rtol
            && !(r.is_finite() && r > 0.0 && r < 1.0)
        {
            return Err(Error::bad_input(format!(
                "rtol must be a number in (0, 1), got {}",
                crate::error::num(r)
            )));
        }
        Ok(self)
    }

    /// A stepper with scratch buffers for a system of `dof` coordinates;
    /// symplectic Euler's steps are taken as `stepping` says
    /// (`sim::fused`).
    pub fn build(&self, dof: usize, stepping: Stepping) -> Box<dyn Integrator> {
        match self.kind {
            IntegratorKind::Dopri5 => Box::new(Dopri5::new(dof, self.dt, self.rtol)),
            IntegratorKind::Moreau => Box::new(moreau::Moreau::new(dof, self.dt)),
            kind => {
                let mut stepper = FixedStep::new(kind, dof, self.dt);
                stepper.stepping = stepping;
                if kind == IntegratorKind::SymplecticEuler {
                    stepper.fused = FusedEuler::new(dof / 3, stepping);
                    stepper.chain = ChainEuler::new(dof / 3, stepping);
                }
                if kind == IntegratorKind::Verlet {
                    stepper.chain_verlet = ChainVerlet::new(dof / 3, stepping);
                }
                Box::new(stepper)
            }
        }
    }

    /// "dt = 0.01" or "rtol = 1e-6", for messages.
    pub fn describe_step(&self) -> String {
        match self.rtol {
            Some(r) if self.kind == IntegratorKind::Dopri5 => format!("rtol = {r:e}"),
            _ => format!("dt = {}", self.dt),
        }
    }
}

/// One step of a scheme. `st` satisfies the protocol's constraint at `t` on
/// entry and at the returned time on exit.
pub trait Integrator {
    fn kind(&self) -> IntegratorKind;
    /// Advances one step towards `t_stop` (> t); returns the new time.
    fn advance(&mut self, rhs: &mut Rhs, st: &mut State, t: f64, t_stop: f64) -> Result<f64>;

    /// Up to `max_steps` steps towards `t_stop`, feeding `arrivals` after
    /// each; returns the new time and the number of steps taken.
    fn advance_many(
        &mut self,
        rhs: &mut Rhs,
        st: &mut State,
        (t, t_stop): (f64, f64),
        max_steps: u64,
        arrivals: &mut ArrivalDetector,
    ) -> Result<(f64, u64)> {
        default_advance_many(self, rhs, st, (t, t_stop), max_steps, arrivals)
    }

    /// W and D so far (`sim::budget`, `Rhs::keep_powers`): explicit
    /// Euler, RK4 on the portable path and dopri5 keep them.
    fn budget(&self) -> Option<Quadrature> {
        None
    }
}

/// Step size that divides [t, t_stop] into whole steps of at most `dt`.
fn subdivide(t: f64, t_stop: f64, dt: f64) -> (f64, bool) {
    let span = t_stop - t;
    let n = (span / dt - 1e-6).ceil().max(1.0);
    (span / n, n <= 1.0)
}

/// Explicit Euler, symplectic Euler and velocity Verlet (one force evaluation
/// per step each), and classical RK4 (four).
pub struct FixedStep {
    kind: IntegratorKind,
    dt: f64,
    acc: Vec<f64>,
    /// Verlet: conservative acceleration at the current (q, t), if known.
    cached_at: Option<f64>,
    rk: Option<RungeKutta>,
    /// Symplectic Euler's factors for the last step size.
    damping: ImplicitDamping,
    plan: Plan,
    /// Symplectic Euler's fused stepper (N ≤ 32) or chain stepper
    /// (longer ladders), where available.
    fused: Option<FusedEuler>,
    chain: Option<ChainEuler>,
    /// Velocity Verlet's chain stepper (longer ladders), where available.
    chain_verlet: Option<ChainVerlet>,
    /// RK4 fused with a fluid's terms (`sim::terms_rk4`): `None` until
    /// the first `advance_many` looks at the ladder, then whether it applies.
    terms_rk4: Option<Option<Box<TermsRk4>>>,
    stepping: Stepping,
    /// Explicit Euler's W and D (`sim::budget`), once kept.
    budget: Option<Quadrature>,
}

impl FixedStep {
    pub fn new(kind: IntegratorKind, dof: usize, dt: f64) -> Self {
        let rk = (kind == IntegratorKind::Rk4).then(|| RungeKutta::new(&RK4, dof));
        Self {
            kind,
            dt,
            acc: vec![0.0; dof],
            cached_at: None,
            rk,
            damping: ImplicitDamping::default(),
            plan: Plan::default(),
            fused: None,
            chain: None,
            chain_verlet: None,
            terms_rk4: None,
            stepping: Stepping::Portable,
            budget: None,
        }
    }

    /// Forward Euler: q' = q + h v, v' = v + h a(q, v).
    fn explicit_euler(&mut self, rhs: &mut Rhs, st: &mut State, h: f64) {
        rhs.acceleration(&st.q, &st.v, &mut self.acc);
        if let Some(p) = rhs.powers() {
            Quadrature::step(&mut self.budget, h, &[1.0], &[p]);
        }
        for k in 0..st.q.len() {
            st.q[k] += h * st.v[k];
            st.v[k] += h * self.acc[k];
        }
    }

    /// Semi-implicit Euler, damping taken implicitly (unconditionally stable
    /// for the damping term, still first order):
    /// v' = (v + h F(q)/m) / (1 + h γ/m), q' = q + h v', computed as
    /// v' = v d − ∂E/∂q · (h M⁻¹ d) with d = 1/(1 + h c) and both factors
    /// precomputed per step size.
    fn symplectic_euler(&mut self, rhs: &mut Rhs, st: &mut State, h: f64) {
        self.implicit_damping(rhs, h);
        let (grad, _) = rhs.gradient(&st.q);
        let coords = st.q.iter_mut().zip(st.v.iter_mut());
        let factors = grad.iter().zip(&self.damping.kick).zip(&self.damping.decay);
        for ((q, v), ((g, kick), decay)) in coords.zip(factors) {
            *v = *v * decay - g * kick;
            *q += h * *v;
        }
    }

    /// Symplectic Euler's per-coordinate factors for the step `h`.
    fn implicit_damping(&mut self, rhs: &Rhs, h: f64) {
        if h != self.damping.h {
            self.damping.set(rhs, h);
        }
    }

    /// Velocity Verlet, damping explicit in the first half kick, implicit in the second (order 2).
    fn verlet(&mut self, rhs: &mut Rhs, st: &mut State, t: f64, h: f64) {
        if self.cached_at != Some(t) {
            rhs.conservative(&st.q, &mut self.acc);
        }
        let half = 0.5 * h;
        // Slice iterators, not indices: the loops vectorise.
        let coords = st.q.iter_mut().zip(st.v.iter_mut());
        for ((q, v), (a, c)) in coords.zip(self.acc.iter().zip(&rhs.damping_rate)) {
            *v += half * (a - c * *v);
            *q += h * *v;
        }
        rhs.constrain(t + h, &mut st.q, &mut st.v);
        rhs.conservative(&st.q, &mut self.acc);
        let kicks = self.acc.iter().zip(&rhs.damping_rate);
        for (v, (a, c)) in st.v.iter_mut().zip(kicks) {
            *v = (*v + half * a) / (1.0 + half * c);
        }
        self.cached_at = Some(t + h);
    }

    /// Up to `max_steps` of velocity Verlet's steps in the chain stepper
    /// (`chain_verlet` is set), the same numbers as [`FixedStep::verlet`]
    /// step by step; the portable steps where its factors do not apply.
    fn verlet_chain(
        &mut self,
        rhs: &mut Rhs,
        st: &mut State,
        (t, t_stop): (f64, f64),
        max_steps: u64,
        arrivals: &mut ArrivalDetector,
    ) -> Result<(f64, u64)> {
        if max_steps == 0 || t >= t_stop {
            return Ok((t, 0));
        }
        let (h, count, lands) = self.plan.take(t, t_stop, self.dt, max_steps);
        let (Some(chain), Some(factors)) =
            (self.chain_verlet.as_mut(), ChainVerlet::factors(rhs, h))
        else {
            self.plan.give_back(count);
            self.chain_verlet = None;
            return default_advance_many(self, rhs, st, (t, t_stop), max_steps, arrivals);
        };
        if self.cached_at != Some(t) {
            rhs.conservative(&st.q, &mut self.acc);
        }
        let batch = Batch {
            t,
            h,
            count,
            t_stop,
            lands,
        };
        let t_new = chain.run(rhs, st, &mut self.acc, &batch, factors, arrivals);
        self.cached_at = Some(t_new);
        Ok((t_new, count))
    }
}

impl Integrator for FixedStep {
    fn kind(&self) -> IntegratorKind {
        self.kind
    }

    fn advance(&mut self, rhs: &mut Rhs, st: &mut State, t: f64, t_stop: f64) -> Result<f64> {
        let (h, last) = self.plan.next(t, t_stop, self.dt);
        match self.kind {
            IntegratorKind::ExplicitEuler => self.explicit_euler(rhs, st, h),
            IntegratorKind::SymplecticEuler => self.symplectic_euler(rhs, st, h),
            IntegratorKind::Verlet => self.verlet(rhs, st, t, h),
            _ => {
                if let Some(rk) = self.rk.as_mut() {
                    rk.step(rhs, st, t, h, t + h, false);
                }
            }
        }
        let t_new = if last { t_stop } else { t + h };
        if self.kind == IntegratorKind::Verlet && last {
            self.cached_at = Some(t_stop);
        }
        rhs.constrain(t_new, &mut st.q, &mut st.v);
        Ok(t_new)
    }

    fn advance_many(
        &mut self,
        rhs: &mut Rhs,
        st: &mut State,
        (t, t_stop): (f64, f64),
        max_steps: u64,
        arrivals: &mut ArrivalDetector,
    ) -> Result<(f64, u64)> {
        if self.kind == IntegratorKind::Rk4 {
            let stepping = self.stepping;
            let fast = self
                .terms_rk4
                .get_or_insert_with(|| TermsRk4::new(rhs, stepping).map(Box::new));
            if let Some(fast) = fast {
                let plan = (&mut self.plan, self.dt);
                return Ok(fast.advance_many(rhs, st, plan, (t, t_stop), max_steps, arrivals));
            }
        }
        if self.chain_verlet.is_some() {
            return self.verlet_chain(rhs, st, (t, t_stop), max_steps, arrivals);
        }
        if self.fused.is_none() && self.chain.is_none() {
            return default_advance_many(self, rhs, st, (t, t_stop), max_steps, arrivals);
        }
        if max_steps == 0 || t >= t_stop {
            return Ok((t, 0));
        }
        let (h, count, lands) = self.plan.take(t, t_stop, self.dt, max_steps);
        self.implicit_damping(rhs, h);
        let Some(factors) = self.damping.uniform else {
            self.plan.give_back(count);
            (self.fused, self.chain) = (None, None);
            return default_advance_many(self, rhs, st, (t, t_stop), max_steps, arrivals);
        };
        let batch = Batch {
            t,
            h,
            count,
            t_stop,
            lands,
        };
        let t_new = match (self.fused, self.chain.as_mut()) {
            (Some(fused), _) => fused.run(rhs, st, &batch, factors, arrivals),
            (None, Some(chain)) => chain.run(rhs, st, &batch, factors, arrivals),
            (None, None) => unreachable!("checked above"),
        };
        Ok((t_new, count))
    }

    fn budget(&self) -> Option<Quadrature> {
        match self.kind {
            IntegratorKind::ExplicitEuler => self.budget,
            // Not the fused RK4 of a fluid's terms.
            IntegratorKind::Rk4 if !matches!(self.terms_rk4, Some(Some(_))) => {
                self.rk.as_ref()?.budget
            }
            _ => None,
        }
    }
}

/// The trait's default `advance_many`, for an override that falls back to it.
fn default_advance_many<I: Integrator + ?Sized>(
    stepper: &mut I,
    rhs: &mut Rhs,
    st: &mut State,
    (t, t_stop): (f64, f64),
    max_steps: u64,
    arrivals: &mut ArrivalDetector,
) -> Result<(f64, u64)> {
    let (mut t, mut taken) = (t, 0);
    while taken < max_steps && t < t_stop {
        t = stepper.advance(rhs, st, t, t_stop)?;
        arrivals.observe(t, &st.q, &st.v);
        taken += 1;
    }
    Ok((t, taken))
}

/// Explicit Runge–Kutta on y = (q, v), y' = (v, a(q, v)); block 1 constrained at each stage.
struct RungeKutta {
    tableau: &'static Tableau,
    /// Stage derivatives: kq[i] = q-rate, kv[i] = v-rate.
    kq: Vec<Vec<f64>>,
    kv: Vec<Vec<f64>>,
    q: Vec<f64>,
    v: Vec<f64>,
    /// Error estimate of the last step (q then v), when the tableau has one.
    err_q: Vec<f64>,
    err_v: Vec<f64>,
    /// Σ w_j k_j of [`RungeKutta::combine`] (scratch): q then v.
    dq: Vec<f64>,
    dv: Vec<f64>,
    /// Time at which stage 0 equals the derivative of the current state (FSAL).
    fsal_at: Option<f64>,
    /// Ẇ and Ḋ at each stage (`kept`: the right-hand side gives them),
    /// the last trial's step, and W and D: y's two more components
    /// summed with the weights b (`sim::budget`).
    powers: Vec<Quadrature>,
    kept: bool,
    h: f64,
    budget: Option<Quadrature>,
}

impl RungeKutta {
    fn new(tableau: &'static Tableau, dof: usize) -> Self {
        let stages = tableau.b.len();
        Self {
            tableau,
            kq: vec![vec![0.0; dof]; stages],
            kv: vec![vec![0.0; dof]; stages],
            q: vec![0.0; dof],
            v: vec![0.0; dof],
            err_q: vec![0.0; dof],
            err_v: vec![0.0; dof],
            dq: vec![0.0; dof],
            dv: vec![0.0; dof],
            fsal_at: None,
            powers: vec![Quadrature::default(); stages],
            kept: false,
            h: 0.0,
            budget: None,
        }
    }

    /// Evaluates stage `i` at (self.q, self.v), constrained at time `ts`.
    fn stage(&mut self, rhs: &mut Rhs, i: usize, ts: f64) {
        rhs.constrain(ts, &mut self.q, &mut self.v);
        self.kq[i].copy_from_slice(&self.v);
        rhs.acceleration(&self.q, &self.v, &mut self.kv[i]);
        if let Some(p) = rhs.powers() {
            (self.powers[i], self.kept) = (p, true);
        }
    }

    /// Computes all stages for a step of size `h` from (st, t) and leaves the
    /// new state in (self.q, self.v) and the error estimate in err_q/err_v.
    fn trial(&mut self, rhs: &mut Rhs, st: &State, t: f64, h: f64, fsal: bool) {
        let tab = self.tableau;
        self.h = h;
        if !(fsal && self.fsal_at == Some(t)) {
            self.q.copy_from_slice(&st.q);
            self.v.copy_from_slice(&st.v);
            self.stage(rhs, 0, t);
        }
        for i in 1..tab.b.len() {
            self.combine(st, h, tab.a[i]);
            self.stage(rhs, i, t + tab.c[i] * h);
        }
        // With FSAL the last stage is evaluated at the new solution; without
        // it, form the solution from the weights b.
        if !fsal {
            self.combine(st, h, tab.b);
        }
        if let Some(b_hat) = tab.b_hat {
            let dof = self.q.len();
            for k in 0..dof {
                let (mut eq, mut ev) = (0.0, 0.0);
                for (i, (bi, bh)) in tab.b.iter().zip(b_hat).enumerate() {
                    eq += (bi - bh) * self.kq[i][k];
                    ev += (bi - bh) * self.kv[i][k];
                }
                self.err_q[k] = h * eq;
                self.err_v[k] = h * ev;
            }
        }
    }

    /// (self.q, self.v) = st + h Σ w_j k_j, summed in order of j (vectorised).
    fn combine(&mut self, st: &State, h: f64, w: &[f64]) {
        self.dq.fill(0.0);
        self.dv.fill(0.0);
        for (j, &wj) in w.iter().enumerate() {
            for (d, k) in self.dq.iter_mut().zip(&self.kq[j]) {
                *d += wj * k;
            }
            for (d, k) in self.dv.iter_mut().zip(&self.kv[j]) {
                *d += wj * k;
            }
        }
        let q = self.q.iter_mut().zip(&st.q).zip(&self.dq);
        for ((y, y0), d) in q {
            *y = y0 + h * d;
        }
        let v = self.v.iter_mut().zip(&st.v).zip(&self.dv);
        for ((y, y0), d) in v {
            *y = y0 + h * d;
        }
    }

    /// Accepts the trial: copies it into `st` and, with FSAL, moves the last
    /// stage into stage 0 for the next step.
    fn accept(&mut self, st: &mut State, t_new: f64, fsal: bool) {
        st.q.copy_from_slice(&self.q);
        st.v.copy_from_slice(&self.v);
        if self.kept {
            Quadrature::step(&mut self.budget, self.h, self.tableau.b, &self.powers);
        }
        if fsal {
            let last = self.kq.len() - 1;
            self.kq.swap(0, last);
            self.kv.swap(0, last);
            self.powers.swap(0, last);
            self.fsal_at = Some(t_new);
        }
    }

    /// One step without error control, ending at `t_new` (= t + h up to rounding).
    fn step(&mut self, rhs: &mut Rhs, st: &mut State, t: f64, h: f64, t_new: f64, fsal: bool) {
        self.trial(rhs, st, t, h, fsal);
        self.accept(st, t_new, fsal);
    }
}
