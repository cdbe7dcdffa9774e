//! Linear theory of the ladder (supplement sections "Equilibrium
//! configuration under gravity" through "phonon dispersion"), every closed
//! form beside its numerical counterpart derived from the model of
//! `crate::model` (Jacobian of the spring lengths, Hessian of the energy).
//! Where the two disagree the model is right; docs/paper-errata.md lists
//! the differences.

pub mod bloch;
pub mod compatibility;
pub mod cost;
pub mod dispersion;
pub mod edge;
pub mod figures;
pub mod formulas;
pub mod gravity;
pub mod linalg;
pub mod report;
pub mod stability;

pub use report::TheoryReport;
