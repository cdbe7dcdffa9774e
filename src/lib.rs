//! `jacobs-ladder`: simulate the Jacob's-ladder toy and render the figures and
//! movies of "Topological antiqued mechanical toy" (Wada, Mizobata, Ueno,
//! Yoneda). See `SPEC.md` for the conventions.
//!
//! Floors, from the ground up: `model` (parameters, energy, forces);
//! `sim` (integrators, drives, observables), `theory` (linear analysis) and
//! `render` (pixels of a ladder state, charts) on the model; `encode` and
//! `output` know nothing of it; `catalog` and `bench` bring them together;
//! `cli` on top.

// Numerical loops index several arrays with one index, as the formulas do.
#![allow(clippy::needless_range_loop)]

pub mod encode;
pub mod error;
pub mod limits;
pub mod model;
pub mod render;
pub mod sim;
pub mod theory;

pub mod bench;
pub mod catalog;
pub mod cli;
pub mod output;
pub mod scene;
pub mod sweep;

pub use error::{Error, Result};
pub mod gallery;
pub mod scenes;
