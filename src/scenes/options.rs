//! A movie's frame count, size and rate, and their bounds.

use crate::error::{Error, Result};

/// Movie frame count, size and rate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MovieOptions {
    pub frames: usize,
    pub width: u32,
    pub height: u32,
    pub fps: f64,
}

impl Default for MovieOptions {
    fn default() -> Self {
        Self {
            frames: 200,
            width: 640,
            height: 480,
            fps: 25.0,
        }
    }
}

/// Largest frame count and side accepted: bounded memory and time.
pub const MAX_FRAMES: usize = 5000;

pub const MIN_SIDE: u32 = 64;

pub const MAX_SIDE: u32 = 4096;

impl MovieOptions {
    pub fn validated(self) -> Result<Self> {
        if !(2..=MAX_FRAMES).contains(&self.frames) {
            return Err(Error::bad_input(format!(
                "a movie needs between 2 and {MAX_FRAMES} frames, got {}",
                self.frames
            )));
        }
        for side in [self.width, self.height] {
            if !(MIN_SIDE..=MAX_SIDE).contains(&side) {
                return Err(Error::bad_input(format!(
                    "the frame size must be WxH with each side between {MIN_SIDE} and {MAX_SIDE} pixels, got {}x{}",
                    self.width, self.height
                )));
            }
        }
        if !(self.fps.is_finite() && self.fps > 0.0 && self.fps <= 100.0) {
            return Err(Error::bad_input(format!(
                "the frame rate must be a number of frames per second in (0, 100], got {}",
                self.fps
            )));
        }
        Ok(self)
    }
}
