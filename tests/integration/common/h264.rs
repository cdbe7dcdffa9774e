//! A decoded H.264 frame as the program's own `Yuv420` (tightly packed
//! planes), for tests that compare decoded MP4 frames with what was encoded.
#![cfg(feature = "mp4")]

use jacobs_ladder::encode::Yuv420;
use openh264::formats::YUVSource;

/// The planes of `yuv` without their row padding (strides).
pub fn packed(yuv: &impl YUVSource) -> Yuv420 {
    let (w, h) = yuv.dimensions();
    let (ys, us, vs) = yuv.strides();
    // A row at a time (a copy each; byte by byte cost seconds a movie at
    // the integration tests' opt-level 0).
    let rows = |plane: &[u8], stride: usize, width: usize, height: usize| -> Vec<u8> {
        let mut packed = Vec::with_capacity(width * height);
        for r in 0..height {
            packed.extend_from_slice(&plane[r * stride..r * stride + width]);
        }
        packed
    };
    Yuv420 {
        width: w,
        height: h,
        y: rows(yuv.y(), ys, w, h),
        u: rows(yuv.u(), us, w / 2, h / 2),
        v: rows(yuv.v(), vs, w / 2, h / 2),
    }
}
