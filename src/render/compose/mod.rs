//! Composition: panels in a grid (`grid`) and filmstrips of snapshots
//! (`filmstrip`), which lay their snapshots out as grid panels, with
//! marks beside them (`marks`).

pub mod filmstrip;
pub mod grid;
mod marks;

pub use filmstrip::*;
pub use grid::*;
