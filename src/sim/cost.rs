//! What one block-step costs on each force path, relative to the paper's
//! model stepped by velocity Verlet: the one cost model every check made
//! before work reads (docs/limits.md, "What a block-step costs").
//!
//! The cap on steps × N (`Limits::block_steps`) counts block-steps *of the
//! paper's model* ("equivalent block-steps"): a run's steps × N times the
//! [`weight`] of its path. So a run of the water tank by RK4, about ten
//! times the paper's cost a block-step, is refused at a tenth of the
//! paper's steps × N, and the default cap (10¹⁰) is about the same time
//! whatever the path.
//!
//! The numbers are measured, not fitted to anything they are compared
//! with: `ladder bench cost` times each path (median of several rounds,
//! N = 1000 and each apparatus's own N) and prints this table's numbers
//! beside its own; re-measure there and copy them here when a kernel
//! changes speed. Each is in ns per block per step on the project's
//! 2-core machine; only their ratios are used.

use super::{IntegratorKind, Stepping};
use crate::model::Ladder;

/// ns per block-step of the paper's model on the portable path (`Rhs`
/// over `Ladder::gradient_with`), per integrator, measured by `ladder
/// bench cost` at N = 1000 (docs/limits.md): velocity Verlet is the unit
/// of the cap.
/// Moreau's step is one evaluation, as Verlet's, and is counted as it
/// (it runs only with the ribbons, whose term dominates).
const PAPER_NS: [(IntegratorKind, f64); 6] = [
    (IntegratorKind::ExplicitEuler, 52.0),
    (IntegratorKind::SymplecticEuler, 42.0),
    (IntegratorKind::Verlet, 54.0),
    (IntegratorKind::Rk4, 353.0),
    (IntegratorKind::Dopri5, 648.0),
    (IntegratorKind::Moreau, 54.0),
];

/// ns per block-step of symplectic Euler on the fused and chain kernels
/// (`sim::fused`, `sim::chain`), the paper's model only.
const PAPER_KERNEL_NS: f64 = 19.0;

/// ns per block and force evaluation each term of docs/experiments.md
/// adds to the portable path: `bench cost`'s path with the term less the
/// paper's by the same scheme (RK4), over its 4 evaluations a step.
const TERM_NS: Terms = Terms {
    // The tank: (1029 to 1143 − 353) / 4.
    water: 180.0,
    // The linkage in air (drag, "stiff" links, pin friction): (4172 to
    // 4302 − 353) / 4 − the drag's 180; its links and its friction are
    // measured together and counted once for either.
    linkage: 780.0,
    // The tank as built, ribbons and contact: (6185 at N = 11 − 353) / 4
    // − the water's 180 − the contact's 15.3 × 11.
    ribbons: 1110.0,
    // Contact tests every pair of blocks: (66550 at N = 1000 − 6185 at
    // N = 11) / 4 / 989, per block and per block of the chain.
    contact_per_block: 15.3,
};

/// The extra ns per block and force evaluation of each term.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Terms {
    /// Added mass and inertia, quadratic drag (a velocity-dependent mass
    /// matrix, solved per block).
    water: f64,
    /// Links of their own stiffness or tension-only, and Coulomb friction
    /// at the pins (smoothed by ω_ε).
    linkage: f64,
    /// The toy as built: ribbons wrapped round the blocks' outlines.
    ribbons: f64,
    /// Contact between blocks (as built), times N: each block is tested
    /// against every other.
    contact_per_block: f64,
}

/// The force path a run takes: which of the terms its ladder has, and
/// whether the paper's kernel steps it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Path {
    pub kind: IntegratorKind,
    /// Symplectic Euler on the fused or chain kernel (the paper's model,
    /// a CPU with the instruction set, `Stepping` not portable).
    pub kernel: bool,
    pub water: bool,
    pub links: bool,
    pub friction: bool,
    pub ribbons: bool,
    pub contact: bool,
    /// Blocks (contact's cost grows with N).
    pub n: usize,
}

impl Path {
    /// The path of `ladder` stepped by `kind` as `stepping` says.
    pub fn of(ladder: &Ladder, kind: IntegratorKind, stepping: Stepping) -> Self {
        let t = &ladder.terms;
        let paper = ladder.is_paper_model();
        Self {
            kind,
            kernel: paper && kind == IntegratorKind::SymplecticEuler && stepping.isa().is_some(),
            water: t.added_mass != 0.0 || t.added_inertia != 0.0 || t.drag != 0.0,
            links: t.links != crate::model::terms::Links::default(),
            friction: t.friction.is_some(),
            ribbons: ladder.built.is_some(),
            contact: ladder.built.is_some_and(|b| b.contact.is_some()),
            n: ladder.n(),
        }
    }

    /// ns per block-step of this path on the project's machine (the
    /// table above).
    pub fn ns_per_block_step(&self) -> f64 {
        if self.kernel {
            return PAPER_KERNEL_NS;
        }
        let base = PAPER_NS
            .iter()
            .find(|(k, _)| *k == self.kind)
            .map_or(PAPER_NS[2].1, |(_, ns)| *ns);
        let t = TERM_NS;
        let extra = [
            (self.water, t.water),
            (self.links || self.friction, t.linkage),
            (self.ribbons, t.ribbons),
            (self.contact, t.contact_per_block * self.n as f64),
        ]
        .iter()
        .filter(|(on, _)| *on)
        .map(|(_, ns)| ns)
        .sum::<f64>();
        base + extra * f64::from(self.kind.evals_per_step())
    }

    /// Block-steps of the paper's model (Verlet) one block-step of this
    /// path costs: its ns over [`REFERENCE_NS`], and never less than 1, so
    /// that no path passes more steps × N than the cap says.
    pub fn weight(&self) -> f64 {
        (self.ns_per_block_step() / REFERENCE_NS).max(1.0)
    }

    /// "rk4 with water terms, pin friction" — for messages.
    pub fn describe(&self) -> String {
        let terms: Vec<&str> = [
            (self.water, "added mass and drag"),
            (self.links, "links of their own stiffness"),
            (self.friction, "pin friction"),
            (self.ribbons, "ribbons"),
            (self.contact, "contact"),
        ]
        .iter()
        .filter(|(on, _)| *on)
        .map(|(_, w)| *w)
        .collect();
        match (terms.is_empty(), self.kernel) {
            (true, true) => format!("{} on the paper's kernel", self.kind),
            (true, false) => format!("{} on the paper's model", self.kind),
            (false, _) => format!("{} with {}", self.kind, terms.join(", ")),
        }
    }
}

/// ns per block-step of the unit of the cap: the paper's model stepped
/// by velocity Verlet (`auto`'s scheme).
pub const REFERENCE_NS: f64 = PAPER_NS[2].1;

/// The weight of a block-step of `ladder` stepped by `kind` as `stepping`
/// says ([`Path::weight`]).
pub fn weight(ladder: &Ladder, kind: IntegratorKind, stepping: Stepping) -> f64 {
    Path::of(ladder, kind, stepping).weight()
}

/// The estimated seconds of computing (one core) of `equivalent`
/// block-steps of the paper's model.
pub fn seconds(equivalent: f64) -> f64 {
    equivalent * REFERENCE_NS * 1e-9
}

/// "about 5 min", "about 3.2 h": an estimated time for messages.
pub fn about(equivalent: f64) -> String {
    let s = seconds(equivalent);
    if !s.is_finite() {
        "forever".into()
    } else if s < 1.0 {
        "under a second".into()
    } else if s < 120.0 {
        format!("about {s:.0} s")
    } else if s < 7200.0 {
        format!("about {:.0} min", s / 60.0)
    } else if s < 48.0 * 3600.0 {
        format!("about {:.1} h", s / 3600.0)
    } else {
        format!("about {:.0} days", s / 86400.0)
    }
}

/// The words a message adds to a count of steps × N on `path`: its weight
/// where it is above 1, and the estimated time of `equivalent`.
pub fn weighed(path: &Path, equivalent: f64) -> String {
    let w = path.weight();
    if w > 1.0 {
        format!(
            ", × {w:.1} for {} (the cap counts block-steps of the paper's model by Verlet), \
             {} of computing",
            path.describe(),
            about(equivalent)
        )
    } else {
        format!(", {} of computing", about(equivalent))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Params;

    #[test]
    fn the_paper_by_verlet_is_the_unit_and_terms_cost_more() {
        let paper = Ladder::new(Params::paper(60.0).unwrap());
        let w = |l: &Ladder, k| weight(l, k, Stepping::Portable);
        assert_eq!(w(&paper, IntegratorKind::Verlet), 1.0);
        assert!(w(&paper, IntegratorKind::Rk4) > 3.0);
        let mut terms = crate::model::terms::Terms {
            drag: 0.1,
            ..Default::default()
        };
        let tank = paper.with_terms(terms);
        assert!(w(&tank, IntegratorKind::Rk4) > w(&paper, IntegratorKind::Rk4));
        terms.friction = Some(crate::model::terms::PinFriction {
            mu_rp: 0.1,
            omega_eps: 3.0,
        });
        let linkage = paper.with_terms(terms);
        assert!(w(&linkage, IntegratorKind::Rk4) > w(&tank, IntegratorKind::Rk4));
        assert!(
            Path::of(&linkage, IntegratorKind::Rk4, Stepping::Portable)
                .describe()
                .contains("pin friction")
        );
        assert_eq!(
            about(1e10),
            format!("about {:.0} min", 1e10 * REFERENCE_NS * 1e-9 / 60.0)
        );
    }
}
