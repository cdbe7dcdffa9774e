//! Moreau's time-stepping (J. J. Moreau, "Unilateral contact and dry
//! friction in finite freedom dynamics", CISM Courses 302, 1988) for the
//! toy's inextensible ribbons (`sim::taut`), in its midpoint form:
//!
//! q_m = q + ½ h v,  v⁺ = v + h a(q_m, v) − B Gᵀ P,  q⁺ = q_m + ½ h v⁺,
//!
//! one evaluation of the smooth forces a step (gravity, drag, added mass:
//! everything but the ribbons, which act only through the impulses P),
//! the prescribed block put on its path at the midpoint and at the end.
//! Between impulses it is the leapfrog; a ribbon jerked taut within a
//! step makes it first order, as any time-stepping of impacts is.
//!
//! The energy budget (`sim::budget`). With v̄ = (v + v⁺)/2 and the
//! potential's change by the midpoint rule, a step changes the energy by
//! h F_nc · v̄ − Pᵀ G v̄ over the free blocks (F_nc the non-conservative
//! forces): the smooth forces' powers at the midpoint stage times h, and
//! the impulses' part, whose loss is Pᵀ G v̄ over every block and whose
//! part on the driven block 1 is the drive's work (`Taut::energy`). Their
//! sum closes at the scheme's first order; a ribbon held taut step after
//! step loses nothing (G v = G v⁺ = 0), as an inextensible one should.
//!
//! Contact between blocks is not integrated (as a penalty force it would
//! hold the step to the contact's own time, 2√2/ω_c): the run checks
//! after every step that no two blocks touch, and stops if they do, so a
//! run that ends is one in which contact never acted.

use super::{Integrator, IntegratorKind, subdivide};
use crate::error::{Error, Result};
use crate::sim::budget::Quadrature;
use crate::sim::rhs::{Rhs, State};

pub struct Moreau {
    h: f64,
    qm: Vec<f64>,
    /// The velocities the smooth forces are evaluated at: the step's
    /// start, block 1's at the midpoint.
    vm: Vec<f64>,
    scratch: Vec<f64>,
    acc: Vec<f64>,
    budget: Option<Quadrature>,
}

impl Moreau {
    pub fn new(dof: usize, h: f64) -> Self {
        Self {
            h,
            qm: vec![0.0; dof],
            vm: vec![0.0; dof],
            scratch: vec![0.0; dof],
            acc: vec![0.0; dof],
            budget: None,
        }
    }
}

impl Integrator for Moreau {
    fn kind(&self) -> IntegratorKind {
        IntegratorKind::Moreau
    }

    fn budget(&self) -> Option<Quadrature> {
        self.budget
    }

    fn advance(&mut self, rhs: &mut Rhs, st: &mut State, t: f64, t_stop: f64) -> Result<f64> {
        let (h, last) = subdivide(t, t_stop, self.h);
        let t_new = if last { t_stop } else { t + h };
        let n = st.q.len();
        for k in 0..n {
            self.qm[k] = st.q[k] + 0.5 * h * st.v[k];
        }
        self.vm.copy_from_slice(&st.v);
        rhs.constrain(t + 0.5 * h, &mut self.qm, &mut self.vm);
        rhs.acceleration(&self.qm, &self.vm, &mut self.acc);
        if let Some(p) = rhs.powers() {
            Quadrature::step(&mut self.budget, h, &[1.0], &[p]);
        }
        for k in 0..n {
            st.v[k] += h * self.acc[k];
        }
        // The prescribed block's velocity at the step's end.
        self.scratch.copy_from_slice(&self.qm);
        rhs.constrain(t_new, &mut self.scratch, &mut st.v);
        self.impulses(rhs, st, h, t)?;
        for k in 0..n {
            st.q[k] = self.qm[k] + 0.5 * h * st.v[k];
        }
        rhs.constrain(t_new, &mut st.q, &mut st.v);
        if let Some((a, b)) = rhs.first_touch(&st.q, &st.v) {
            return Err(Error::failed(format!(
                "blocks {} and {} touch at t = {t_new:.3} τ: moreau does not integrate \
                 contact between blocks; give the ribbons a stiffness and run dopri5",
                a + 1,
                b + 1
            )));
        }
        Ok(t_new)
    }
}

impl Moreau {
    /// The step's impulses into `st.v` (`Rhs::taut_impulses`), and their
    /// loss and the drive's part into the budget where it is kept.
    fn impulses(&mut self, rhs: &mut Rhs, st: &mut State, h: f64, t: f64) -> Result<()> {
        if let Err(why) = rhs.taut_impulses(h, &mut st.v) {
            return Err(Error::failed(format!(
                "moreau: the ribbons' impulses have no solution at t = {t:.3} τ ({why})"
            )));
        }
        if rhs.powers().is_some() {
            let (work, lost) = rhs.taut_energy(&self.vm, &st.v);
            let b = self.budget.get_or_insert_with(Quadrature::default);
            b.work += work;
            b.dissipated += lost;
        }
        Ok(())
    }
}
