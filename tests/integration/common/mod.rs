//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod fuzz;
pub mod gif;
pub mod golden;
pub mod h264;
pub mod kernels;
pub mod lcg;
pub mod pdf;
pub mod require;
pub mod scenes;
pub mod tempdir;

/// The theme of the screen style (the catalogue's default), for tests
/// that draw at it.
pub fn screen() -> jacobs_ladder::render::Theme {
    jacobs_ladder::render::Theme::of(&jacobs_ladder::render::Style::default())
}

/// Runs the `ladder` binary with `args` and waits for it.
pub fn ladder_cli(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .output()
        .expect("the ladder binary runs")
}
