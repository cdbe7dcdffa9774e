//! A decoded H.264 frame as the program's own `Yuv420` (tightly packed
//! planes), for tests that compare decoded MP4 frames with what was encoded.
#![cfg(feature = "mp4")]

use jacobs_ladder::encode::Yuv420;
use openh264::formats::YUVSource;

/// The planes of `yuv` without their row padding (strides).
pub fn packed(yuv: &impl YUVSource) -> Yuv420 {
    let (w, h) = yuv.dimensions();
    let (ys, us, vs) = yuv.strides();
    let rows = |plane: &[u8], stride: usize, width: usize, height: usize| -> Vec<u8> {
        (0..height)
            .flat_map(|r| plane[r * stride..r * stride + width].to_vec())
            .collect()
    };
    Yuv420 {
        width: w,
        height: h,
        y: rows(yuv.y(), ys, w, h),
        u: rows(yuv.u(), us, w / 2, h / 2),
        v: rows(yuv.v(), vs, w / 2, h / 2),
    }
}
