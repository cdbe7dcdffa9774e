//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod fuzz;
pub mod golden;
pub mod lcg;
pub mod scenes;
pub mod tempdir;
