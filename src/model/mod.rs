//! The ladder model: parameters, geometry, energy and analytic forces.
//! Knows nothing else of the project.

pub mod built;
pub mod contact;
pub mod ladder;
pub mod links;
pub mod media;
pub mod outline;
pub mod params;
pub mod ribbons;
pub mod strap;
pub mod table;
pub mod tangent;
pub mod taut;
pub mod terms;
pub mod trig;

pub use ladder::Ladder;
pub use params::{ParamError, Params};
pub use table::{Kind, Param, Place, Range, Spec};
