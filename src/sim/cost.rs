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
/// bench cost` at N = 1000 (docs/limits.md; median of 5 rounds, the
/// machine otherwise idle): velocity Verlet is the unit of the cap.
/// Moreau's step is one evaluation plus its impulses and projection: its
/// number is the tank as built's at N = 11 (331.5 to 341.3) less the
/// terms' one evaluation (water, ribbons, contact at N = 11; below).
const PAPER_NS: [(IntegratorKind, f64); 6] = [
    (IntegratorKind::ExplicitEuler, 7.8),
    (IntegratorKind::SymplecticEuler, 6.8),
    (IntegratorKind::Verlet, 8.6),
    (IntegratorKind::Rk4, 41.8),
    (IntegratorKind::Dopri5, 82.8),
    (IntegratorKind::Moreau, 215.0),
];

/// ns per block-step of symplectic Euler on the fused and chain kernels
/// (`sim::fused`, `sim::chain`), the paper's model only.
const PAPER_KERNEL_NS: f64 = 2.8;

/// ns per block and force evaluation each term of docs/experiments.md
/// adds to the portable path: `bench cost`'s path with the term less the
/// paper's by the same scheme (RK4), over its 4 evaluations a step.
const TERM_NS: Terms = Terms {
    // The tank: (149.6 at N = 11 − 41.8) / 4 (19 at N = 1000).
    water: 27.0,
    // The linkage in air (drag, "stiff" links, pin friction): (448.1 at
    // N = 8 − 41.8) / 4 − the drag's 27; its links and its friction are
    // measured together and counted once for either.
    linkage: 75.0,
    // The tank as built, ribbons and contact: (459.8 at N = 11 − 41.8) / 4
    // − the water's 27 − the contact's 0.49 × 11.
    ribbons: 72.0,
    // Contact tests every pair of blocks: (828.7 at N = 200 − 459.8 at
    // N = 11) / 4 / 189, per block and per block of the chain (at N =
    // 1000, 2134.7 measured: 0.42).
    contact_per_block: 0.49,
};

/// Moreau's step tests the pairs of blocks more than once (its smooth
/// forces, and after the step that no two touch): its contact counts as
/// this many evaluations (measured 3.5: (2046.8 at N = 1000 − 331.5 at
/// N = 11) / 989 / 0.49).
const MOREAU_CONTACT_PASSES: f64 = 4.0;

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
        let passes = if self.kind == IntegratorKind::Moreau {
            MOREAU_CONTACT_PASSES
        } else {
            1.0
        };
        let extra = [
            (self.water, t.water),
            (self.links || self.friction, t.linkage),
            (self.ribbons, t.ribbons),
            (self.contact, passes * t.contact_per_block * self.n as f64),
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
        let per_second = 1.0 / seconds(1.0);
        assert_eq!(about(60.0 * per_second), "about 60 s");
        assert_eq!(about(300.0 * per_second), "about 5 min");
        assert_eq!(about(3.0 * 3600.0 * per_second), "about 3.0 h");
        assert_eq!(about(0.5 * per_second), "under a second");
    }
}
