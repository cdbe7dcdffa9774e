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
