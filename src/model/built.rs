//! The toy as built (docs/experiments.md, "The toy as built"): blocks with
//! thickness (`outline`), held by ribbons that wrap round them
//! (`ribbons`) in place of the paper's springs, and touching one another
//! (`contact`). A ladder carries it in [`Ladder::built`]; the paper's
//! model has none, and nothing of the paper's force loop reads it.
//!
//! [`Ladder::built`]: super::Ladder::built
//!
//! It sits below the ladder: its functions take the number of blocks and
//! their inertia ([`Blocks`]), not the ladder.

use super::contact::{Blocks, Contact};
use super::ribbons::Ribbons;

/// Ribbons and, where the blocks may touch, contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AsBuilt {
    pub ribbons: Ribbons,
    pub contact: Option<Contact>,
}

impl AsBuilt {
    /// Elastic energy of the ribbons and of the contacts' overlaps.
    pub fn elastic_energy(&self, blocks: Blocks, q: &[f64]) -> f64 {
        let o = &self.ribbons.outline;
        self.ribbons.elastic_energy(blocks.n, q)
            + self.contact.map_or(0.0, |c| c.elastic_energy(blocks, o, q))
    }

    /// Power dissipated by the ribbons' dashpots and the contacts at (q, v).
    pub fn dissipation(&self, blocks: Blocks, q: &[f64], v: &[f64]) -> f64 {
        self.ribbons.dissipation(blocks.n, q, v)
            + self
                .contact
                .map_or(0.0, |c| c.dissipation(blocks, &self.ribbons.outline, q, v))
    }

    /// Whether its forces depend on the velocities (a dashpot, contact,
    /// inextensible ribbons' tensions).
    pub fn velocity_dependent(&self) -> bool {
        self.ribbons.damping != 0.0 || self.contact.is_some() || self.ribbons.inextensible
    }
}
