//! The hanging start (docs/sweeps.md): the static equilibrium of the chain
//! under gravity with block 1 clamped, as the toy hangs before its top
//! block is turned.
//!
//! The equilibrium solves ∂E/∂q = 0 for the free coordinates (blocks
//! 2..N), E = Σ ½k[(L_A,n − a)² + (L_B,n − b)²] − m G Σ X_n
//! (docs/model.md; the supplement's equations of motion, "Details of numerical
//! simulation", at rest). Block 1 keeps its ground-state centre and the
//! drive's angle at t = 0 (θ_1 = α).
//!
//! Plain Newton from the ground state fails: there the springs sit at
//! their rest lengths, nothing stiffens the chain's softest mode, and the
//! clamped Hessian's smallest ω² is about 6e-13, so the first step along
//! that mode is of order G / 6e-13. The solver is Newton damped by a
//! Levenberg–Marquardt shift: each step solves (H + μ M) Δq = −∂E/∂q with
//! the band Hessian H of `theory::stability` (O(N) per step) and the mass
//! matrix M, and is kept only where it lowers the energy (or, once the
//! energy no longer changes beyond its rounding, the residual force). The
//! shift grows tenfold on a refused step and shrinks tenfold on a kept one,
//! down to zero: far from the solution the steps follow the gradient (as
//! damped dynamics would, without its slow modes' wait), near it they are
//! Newton's, and the residual falls quadratically to the stated 1e-12.

use super::{Scenario, State};
use crate::error::{Error, Result, num};
use crate::model::Ladder;
use crate::theory::stability::{clamped_hessian, free_masses, solve_shifted};
use serde::{Deserialize, Serialize};
use std::fmt;

/// How a run starts (`[model] start`, `--start`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Start {
    /// At rest in the ground state of sign α, every spring at its rest
    /// length (gravity not yet felt; the paper's start).
    #[default]
    Ground,
    /// At rest in the static equilibrium under gravity with block 1
    /// clamped ([`hanging`]).
    Relaxed,
}

impl Start {
    pub fn name(&self) -> &'static str {
        match self {
            Self::Ground => "ground",
            Self::Relaxed => "relaxed",
        }
    }
}

impl fmt::Display for Start {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for Start {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "ground" => Ok(Self::Ground),
            "relaxed" => Ok(Self::Relaxed),
            _ => Err(Error::bad_input(format!(
                "start must be \"relaxed\" or \"ground\", got \"{s}\""
            ))),
        }
    }
}

/// Settings of the hanging-start solver. Defaults are stated with each
/// field.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RelaxConfig {
    /// Largest residual generalised force |∂E/∂q| on a free coordinate
    /// at the solution, k s or k s² (default 1e-12). On chains so long
    /// that the rounding of their positions exceeds it (beyond about a
    /// 850 blocks), the rounding floor [`rounding_floor`] instead.
    pub force: f64,
    /// Most Newton steps, refused ones included (default 400).
    pub max_steps: usize,
    /// First Levenberg–Marquardt shift μ, 1/τ² (default 1e-4: ten times
    /// the gravity G = 2e-4 would need no shift at all; the soft mode's
    /// 6e-13 would).
    pub initial_shift: f64,
    /// Largest shift before the solver gives up, 1/τ² (default 1e6).
    pub max_shift: f64,
}

impl Default for RelaxConfig {
    fn default() -> Self {
        Self {
            force: 1e-12,
            max_steps: 400,
            initial_shift: 1e-4,
            max_shift: 1e6,
        }
    }
}

/// The hanging equilibrium and how it was found.
#[derive(Debug, Clone, PartialEq)]
pub struct Hanging {
    /// Positions [X, Y, θ per block]; block 1 as given.
    pub q: Vec<f64>,
    /// Largest |∂E/∂q| on a free coordinate at `q`.
    pub residual: f64,
    /// Newton steps taken (kept and refused).
    pub steps: usize,
}

/// The residual force the gradient's own rounding allows at `q`:
/// 4 ε (1 + max |q|) k, the rounding of a spring's length computed from
/// centres that far from block 1 (2.3e-12 at N = 2000; below 1e-12 up to
/// N ≈ 850, where the stated 1e-12 holds).
pub fn rounding_floor(q: &[f64]) -> f64 {
    let size = q.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    4.0 * f64::EPSILON * (1.0 + size)
}

/// Largest |∂E/∂q| over the free coordinates, with the gradient in `g`.
fn residual(ladder: &Ladder, q: &[f64], g: &mut [f64]) -> f64 {
    ladder.gradient(q, g);
    g[3..].iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// The static equilibrium under gravity nearest `q0` downhill, block 1
/// held where `q0` has it (see the module's doc). `Error::Failed` when the
/// residual does not reach `config.force` within its steps.
pub fn hanging(ladder: &Ladder, q0: &[f64], config: &RelaxConfig) -> Result<Hanging> {
    let mass = free_masses(ladder);
    let mut q = q0.to_vec();
    let mut g = vec![0.0; q.len()];
    let mut trial_g = g.clone();
    let mut e = ladder.energy(&q);
    let mut r = residual(ladder, &q, &mut g);
    let mut mu = config.initial_shift;
    let mut h = clamped_hessian(ladder, &q);
    let wanted = config.force.max(rounding_floor(q0));
    for step in 0..config.max_steps {
        if r <= wanted {
            return Ok(Hanging {
                q,
                residual: r,
                steps: step,
            });
        }
        let rhs: Vec<f64> = g[3..].iter().map(|x| -x).collect();
        let kept = solve_shifted(&h, mu, &mass, &rhs).and_then(|dq| {
            let mut trial = q.clone();
            for (x, d) in trial[3..].iter_mut().zip(&dq) {
                *x += d;
            }
            let e_t = ladder.energy(&trial);
            let r_t = residual(ladder, &trial, &mut trial_g);
            // Energy down, or (at the energy's rounding) the force down.
            let rounding = 1e-13 * (1.0 + e.abs());
            let better = e_t < e - rounding || (e_t <= e + rounding && r_t < r);
            (better && r_t.is_finite()).then_some((trial, e_t, r_t))
        });
        match kept {
            Some((trial, e_t, r_t)) => {
                (q, e, r) = (trial, e_t, r_t);
                g.copy_from_slice(&trial_g);
                mu = if mu < 1e-12 { 0.0 } else { mu / 10.0 };
                h = clamped_hessian(ladder, &q);
            }
            None => {
                mu = (mu * 10.0).max(1e-12);
                if mu > config.max_shift {
                    break;
                }
            }
        }
    }
    Err(Error::failed(format!(
        "the hanging start did not converge: residual force {} after {} steps \
         (wanted {}); hint: start = \"ground\" starts from the ground state",
        num(r),
        config.max_steps,
        num(wanted)
    )))
}

impl Scenario {
    /// This scenario started as `start` says: the ground state as built,
    /// or the hanging equilibrium with block 1 where the drive holds it at
    /// t = 0 ([`hanging`], default settings). A chain whose block 1 is not
    /// driven has no clamp to hang from: it keeps its ground state.
    pub fn started(mut self, start: Start) -> Result<Self> {
        if start == Start::Relaxed
            && let Some(d) = self.protocol.drive()
        {
            let mut q0 = self.initial.q.clone();
            q0[2] = d.theta(0.0);
            let hung = hanging(&self.ladder, &q0, &RelaxConfig::default())?;
            self.initial = State::at_rest(hung.q);
        }
        Ok(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Params;

    #[test]
    fn the_paper_chain_hangs_at_rest() {
        for alpha in [60.0, -50.0, 86.0] {
            let ladder = Ladder::new(Params::paper(alpha).unwrap());
            let h = hanging(&ladder, &ladder.ground_state(), &RelaxConfig::default()).unwrap();
            assert!(h.residual <= 1e-12, "α = {alpha}: {}", h.residual);
            // Block 1 stays where it was put.
            assert_eq!(&h.q[..3], &ladder.ground_state()[..3]);
            // Gravity stretches the chain: the bottom block hangs lower.
            let n = ladder.n();
            assert!(h.q[3 * (n - 1)] > ladder.ground_state()[3 * (n - 1)]);
        }
    }

    #[test]
    fn keywords_read_back() {
        for s in [Start::Ground, Start::Relaxed] {
            assert_eq!(s.name().parse::<Start>().unwrap(), s);
        }
        assert!("hanging".parse::<Start>().is_err());
    }
}
