//! Composition: panels in a grid (`grid`) and filmstrips of snapshots
//! (`filmstrip`), which lay their snapshots out as grid panels.

pub mod filmstrip;
pub mod grid;

pub use filmstrip::*;
pub use grid::*;
