//! `jacobs-ladder`: simulate the Jacob's-ladder toy and render the figures and
//! movies of "Topological antiqued mechanical toy" (Wada, Mizobata, Ueno,
//! Yoneda). See `SPEC.md` for the conventions.

pub mod encode;
pub mod error;
pub mod model;
pub mod output;
pub mod render;

pub use error::{Error, Result};
