//! `jacobs-ladder`: simulate the Jacob's-ladder toy and render the figures and
//! movies of "Topological antiqued mechanical toy" (Wada, Mizobata, Ueno,
//! Yoneda). The binary `ladder` is a thin layer over this library; the
//! model's conventions are in `docs/model.md`.
//!
//! # As a library
//!
//! A scene (the model, the drive of block 1, the run and the picture) is
//! plain data; running it gives the trajectory, rendering it the bytes of
//! its files:
//!
//! ```
//! use jacobs_ladder::scene::{Kind, Scene};
//! use jacobs_ladder::{catalog, scenes};
//!
//! // The paper's kink: N = 10, b/s = 1.3, α = 60°, block 1 turned over 1000 τ.
//! let mut scene = Scene::default();
//! scene.run.t_end = 2200.0;
//! let run = scenes::run::simulate(&scene, &[])?;
//! let arrivals = &run.trajectory.arrival_times;
//! assert!(arrivals.iter().all(Option::is_some), "every block flips");
//! assert!(arrivals.windows(2).all(|w| w[0] < w[1]), "top first");
//!
//! // A built-in figure, as (file name, bytes): its PNG and its data file.
//! let figure = catalog::find(Kind::Figure, "2d")?;
//! let files = scenes::render(&figure.scene, &scenes::MovieOptions::default())?;
//! assert_eq!(files[0].0, "figure-2d.png");
//! # Ok::<(), jacobs_ladder::Error>(())
//! ```
//!
//! Floors, from the ground up: a module uses its own floor's and lower
//! floors' modules, never a higher floor's (`scripts/check-layers` checks
//! it, from the same list):
//!
//! 1. `numfmt`, `version`, `limits`: numbers as text, the build, the caps;
//! 2. `model`: parameters, energy, forces;
//! 3. `error`: the error type and its exit codes;
//! 4. `encode`, `output`: bytes from pictures, files written; they know
//!    nothing of the model;
//! 5. `sim`, `theory`, `render`, `rings`: integrators, drives and
//!    observables; the linear analysis; pictures of a ladder state and
//!    charts; the double ring chain of Fig. 4b;
//! 6. `scene`: what one output needs, as data;
//! 7. `scenes`, `catalog`, `sweep`, `bench`, `gallery`: scenes run and
//!    rendered, the paper's catalogue, sweeps, speed against accuracy, the
//!    gallery page;
//! 8. `front`: what the command line and the Python package both do;
//! 9. `cli`: the command line, and the binary on top.

// Numerical loops index several arrays with one index, as the formulas do.
#![allow(clippy::needless_range_loop)]

pub mod encode;
pub mod error;
pub mod limits;
pub mod model;
pub mod numfmt;
pub mod render;
pub mod rings;
pub mod sim;
pub mod theory;
pub mod version;

pub mod bench;
pub mod catalog;
pub mod cli;
pub mod output;
pub mod scene;
pub mod sweep;

pub use error::{Error, Result};
pub mod front;
pub mod gallery;
pub mod scenes;
