//! Adaptive Dormand–Prince 5(4).

use super::{Integrator, IntegratorKind, RungeKutta, subdivide};
use crate::error::{Error, Result};
use crate::sim::budget::Quadrature;
use crate::sim::rhs::{Rhs, State};
use crate::sim::tableau::DOPRI5;

/// Adaptive Dormand–Prince 5(4) with the standard step-size controller
/// (Hairer I, II.4): err = RMS of e_k / (rtol (ATOL_SCALE + max(|y_k|, |y'_k|)))
/// over all coordinates; accept when err ≤ 1; h ← h · clamp(0.9 err^(−1/5), 0.2, 5).
pub struct Dopri5 {
    rk: RungeKutta,
    h: f64,
    rtol: Option<f64>,
    pub rejected: u64,
}

/// Largest step dopri5 takes, in τ (keeps the arrival times' interpolation accurate).
pub const DOPRI5_MAX_STEP: f64 = 5.0;

/// Absolute part of dopri5's error scale, relative to rtol: velocities are of
/// order 1e-3 s/τ, which an absolute tolerance equal to rtol would not control.
pub const ATOL_SCALE: f64 = 1e-3;

impl Dopri5 {
    pub fn new(dof: usize, h0: f64, rtol: Option<f64>) -> Self {
        Self {
            rk: RungeKutta::new(&DOPRI5, dof),
            h: h0,
            rtol,
            rejected: 0,
        }
    }

    fn error_norm(&self, st: &State, rtol: f64) -> f64 {
        let rk = &self.rk;
        let mut sum = 0.0;
        let n = st.q.len();
        for k in 0..n {
            let sq = rtol * (ATOL_SCALE + st.q[k].abs().max(rk.q[k].abs()));
            let sv = rtol * (ATOL_SCALE + st.v[k].abs().max(rk.v[k].abs()));
            sum += (rk.err_q[k] / sq).powi(2) + (rk.err_v[k] / sv).powi(2);
        }
        (sum / (2 * n) as f64).sqrt()
    }
}

impl Integrator for Dopri5 {
    fn kind(&self) -> IntegratorKind {
        IntegratorKind::Dopri5
    }

    fn budget(&self) -> Option<Quadrature> {
        self.rk.budget
    }
    fn advance(&mut self, rhs: &mut Rhs, st: &mut State, t: f64, t_stop: f64) -> Result<f64> {
        let Some(rtol) = self.rtol else {
            let (h, last) = subdivide(t, t_stop, self.h);
            let t_new = if last { t_stop } else { t + h };
            self.rk.step(rhs, st, t, h, t_new, true);
            rhs.constrain(t_new, &mut st.q, &mut st.v);
            return Ok(t_new);
        };
        loop {
            let span = t_stop - t;
            let h = self.h.min(DOPRI5_MAX_STEP).min(span);
            self.rk.trial(rhs, st, t, h, true);
            let err = self.error_norm(st, rtol);
            let factor = if err.is_finite() {
                (0.9 * err.powf(-0.2)).clamp(0.2, 5.0)
            } else {
                0.2
            };
            if err <= 1.0 {
                let t_new = if h >= span { t_stop } else { t + h };
                self.rk.accept(st, t_new, true);
                rhs.constrain(t_new, &mut st.q, &mut st.v);
                self.h = h * factor;
                return Ok(t_new);
            }
            self.rejected += 1;
            self.rk.fsal_at = Some(t);
            self.h = h * factor.min(1.0);
            if self.h < 1e-10 * t.abs().max(1.0) {
                return Err(Error::failed(format!(
                    "dopri5 step size underflow at t = {t:.3} τ (rtol = {rtol:e})"
                )));
            }
        }
    }
}
