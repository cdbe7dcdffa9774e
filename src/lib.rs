//! `jacobs-ladder`: simulate the Jacob's-ladder toy and render the figures and
//! movies of "Topological antiqued mechanical toy" (Wada, Mizobata, Ueno,
//! Yoneda). See `SPEC.md` for the conventions.

// Numerical loops index several arrays with one index, as the formulas do.
#![allow(clippy::needless_range_loop)]

pub mod error;
pub mod model;

pub use error::{Error, Result};
pub mod bench;
pub mod cli;
pub mod output;
pub mod sim;
pub mod catalog;
