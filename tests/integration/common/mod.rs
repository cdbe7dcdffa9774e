//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod fuzz;
pub mod gif;
pub mod golden;
pub mod h264;
pub mod kernels;
pub mod lcg;
pub mod require;
pub mod scenes;
pub mod tempdir;
