//! RGB to Y′CbCr 4:2:0 (BT.709, limited range 16–235 / 16–240), the input
//! of the H.264 encoder. The MP4 says so in its colour description (VUI).

/// A planar 4:2:0 picture: full-size luma, chroma at half width and height.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Yuv420 {
    pub width: usize,
    pub height: usize,
    /// Luma, `width × height`, row-major.
    pub y: Vec<u8>,
    /// Cb, `width/2 × height/2`.
    pub u: Vec<u8>,
    /// Cr, `width/2 × height/2`.
    pub v: Vec<u8>,
}

impl Yuv420 {
    /// A black picture of an even size.
    pub fn new(width: usize, height: usize) -> Yuv420 {
        let c = (width / 2) * (height / 2);
        Yuv420 {
            width,
            height,
            y: vec![16; width * height],
            u: vec![128; c],
            v: vec![128; c],
        }
    }

    /// Back to RGB (BT.709, limited range; chroma of each 2 × 2 block
    /// shared), `width × height × 3` bytes: for tests and checks.
    pub fn to_rgb(&self) -> Vec<u8> {
        let (w, cw) = (self.width, self.width / 2);
        let mut out = Vec::with_capacity(w * self.height * 3);
        for j in 0..self.height {
            for i in 0..w {
                let y = (self.y[j * w + i] as f32 - 16.0) * (255.0 / 219.0);
                let k = (j / 2) * cw + i / 2;
                let cb = (self.u[k] as f32 - 128.0) * (255.0 / 224.0);
                let cr = (self.v[k] as f32 - 128.0) * (255.0 / 224.0);
                let r = y + 1.5748 * cr;
                let g = y - 0.187_324 * cb - 0.468_124 * cr;
                let b = y + 1.8556 * cb;
                out.extend([r, g, b].map(|c| c.round().clamp(0.0, 255.0) as u8));
            }
        }
        out
    }
}

/// BT.709 weights for 8-bit limited range, scaled by 2⁸ (16-bit integer
/// arithmetic, which the compiler turns into vector instructions on every
/// x86-64 and ARM CPU; at most one level from the exact values).
#[cfg(test)]
const KY: [i16; 3] = [47, 157, 16];
const KCB: [i16; 3] = [-26, -86, 112];
const KCR: [i16; 3] = [112, -102, -10];

/// One luma value, BT.709's (the tests' reference).
#[cfg(test)]
fn luma(r: u16, g: u16, b: u16) -> u8 {
    // At most 220 · 255 + 128 < 2¹⁶: no overflow in u16.
    (((KY[0] as u16 * r + KY[1] as u16 * g + KY[2] as u16 * b + 128) >> 8) + 16) as u8
}

/// One chroma value from a mean colour.
#[inline(always)]
fn chroma(k: [i16; 3], r: i16, g: i16, b: i16) -> u8 {
    // |k · rgb| ≤ 112 · 255 < 2¹⁵: no overflow in i16.
    (((k[0] * r + k[1] * g + k[2] * b + 128) >> 8) + 128) as u8
}

/// Converts opaque RGBA pixels (`width × height`, both even) into `out`,
/// which is resized as needed. Chroma is taken from the mean of each 2 × 2
/// block; then each pixel's luma is the one that, with its block's chroma,
/// decodes nearest its colour (least squares over R, G and B). Where a
/// block is one colour that is its BT.709 luma; where a thin coloured line
/// crosses white, the shared chroma would otherwise tint the white and
/// pale the line (a fringe, and 2–3 dB of PSNR on drawn frames). The same
/// code is compiled for AVX2 as well and picked at run time when the CPU
/// has it (the bytes are identical).
pub fn rgba_to_yuv420(rgba: &[u8], width: usize, height: usize, out: &mut Yuv420) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU supports AVX2, checked just above.
        unsafe { convert_avx2(rgba, width, height, out) };
        return;
    }
    convert(rgba, width, height, out);
}

/// [`convert`] compiled with AVX2 enabled.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn convert_avx2(rgba: &[u8], width: usize, height: usize, out: &mut Yuv420) {
    convert(rgba, width, height, out);
}

/// What a block's chroma adds to R + G + B when decoded (BT.709, limited
/// range; see [`Yuv420::to_rgb`]): (1.5748 − 0.468124) Cr + (1.8556 −
/// 0.187324) Cb, with Cb and Cr in full-range units.
#[inline(always)]
fn chroma_sum(u: u8, v: u8) -> f32 {
    let cb = (u as f32 - 128.0) * (255.0 / 224.0);
    let cr = (v as f32 - 128.0) * (255.0 / 224.0);
    1.106_676 * cr + 1.668_276 * cb
}

/// The luma that decodes nearest (r, g, b) with chroma adding `sum` to
/// R + G + B: the mean of the three channels less a third of `sum`, in
/// limited range.
#[inline(always)]
fn fitted_luma(r: u8, g: u8, b: u8, sum: f32) -> u8 {
    let y = (r as f32 + g as f32 + b as f32 - sum) * (1.0 / 3.0);
    (y * (219.0 / 255.0) + 16.5).clamp(16.0, 235.0) as u8
}

/// The conversion, inlined into each instruction-set variant; plain loops
/// that the compiler vectorises.
#[inline(always)]
fn convert(rgba: &[u8], width: usize, height: usize, out: &mut Yuv420) {
    debug_assert!(width.is_multiple_of(2) && height.is_multiple_of(2));
    debug_assert_eq!(rgba.len(), width * height * 4);
    let cw = width / 2;
    out.width = width;
    out.height = height;
    out.y.resize(width * height, 0);
    out.u.resize(cw * (height / 2), 0);
    out.v.resize(cw * (height / 2), 0);
    let stride = width * 4;
    let rows = rgba.chunks_exact(2 * stride);
    let planes = out.u.chunks_exact_mut(cw).zip(out.v.chunks_exact_mut(cw));
    for (pair, (us, vs)) in rows.zip(planes) {
        let (top, bottom) = pair.split_at(stride);
        let blocks = top.chunks_exact(8).zip(bottom.chunks_exact(8));
        for ((a, b), (u, v)) in blocks.zip(us.iter_mut().zip(vs.iter_mut())) {
            let mean = |k: usize| {
                let sum = a[k] as u16 + a[k + 4] as u16 + b[k] as u16 + b[k + 4] as u16;
                ((sum + 2) >> 2) as i16
            };
            let (r, g, bl) = (mean(0), mean(1), mean(2));
            *u = chroma(KCB, r, g, bl);
            *v = chroma(KCR, r, g, bl);
        }
    }
    let (y_rows, (u, v)) = (out.y.chunks_exact_mut(width), (&out.u, &out.v));
    for (j, (ys, px)) in y_rows.zip(rgba.chunks_exact(stride)).enumerate() {
        let (us, vs) = (&u[(j / 2) * cw..][..cw], &v[(j / 2) * cw..][..cw]);
        for (i, (y, p)) in ys.iter_mut().zip(px.chunks_exact(4)).enumerate() {
            let sum = chroma_sum(us[i / 2], vs[i / 2]);
            *y = fitted_luma(p[0], p[1], p[2], sum);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn white_black_and_red() {
        let mut px = Vec::new();
        for c in [[255, 255, 255], [0, 0, 0], [214, 39, 40], [31, 119, 180]] {
            px.clear();
            for _ in 0..4 {
                px.extend_from_slice(&[c[0], c[1], c[2], 255]);
            }
            let mut out = Yuv420::new(2, 2);
            rgba_to_yuv420(&px, 2, 2, &mut out);
            let back = out.to_rgb();
            for k in 0..3 {
                assert!(back[k].abs_diff(c[k]) <= 2, "{c:?} -> {back:?}");
            }
        }
        let mut out = Yuv420::new(2, 2);
        rgba_to_yuv420(&[255; 16], 2, 2, &mut out);
        assert_eq!((out.y[0], out.u[0], out.v[0]), (235, 128, 128));
        rgba_to_yuv420(&[0, 0, 0, 255].repeat(4), 2, 2, &mut out);
        assert_eq!((out.y[0], out.u[0], out.v[0]), (16, 128, 128));
    }

    /// Sum of squared RGB errors of `rgba` through 4:2:0 and back.
    fn squared_error(rgba: &[u8], w: usize, h: usize, out: &Yuv420) -> f64 {
        let back = out.to_rgb();
        rgba.chunks_exact(4)
            .zip(back.chunks_exact(3))
            .flat_map(|(a, b)| (0..3).map(move |k| (a[k] as f64 - b[k] as f64).powi(2)))
            .sum::<f64>()
            / (w * h) as f64
    }

    #[test]
    fn a_thin_coloured_line_on_white_keeps_its_colour() {
        // A one-pixel reddish line down a light grey 4 × 4 picture: each
        // block holds one line and one grey column (colours chosen so that
        // no decoded channel leaves 0–255, where least squares is exact).
        let (w, h) = (4, 4);
        let mut rgba = Vec::new();
        for _ in 0..h {
            for i in 0..w {
                let c = if i % 2 == 0 {
                    [180, 60, 60]
                } else {
                    [200, 200, 200]
                };
                rgba.extend_from_slice(&[c[0], c[1], c[2], 255]);
            }
        }
        let mut out = Yuv420::new(w, h);
        rgba_to_yuv420(&rgba, w, h, &mut out);
        let fitted = squared_error(&rgba, w, h, &out);
        // The same chroma with each pixel's own BT.709 luma (the usual
        // conversion): the fitted luma must do better, by the formula's
        // least-squares property. (Near white or black the decoder's
        // clamping can reverse this for one pixel; on movie 4's frames the
        // fitted luma gains 0.2 dB, tests/mp4_quality.rs.)
        let mut plain = out.clone();
        for (i, px) in rgba.chunks_exact(4).enumerate() {
            plain.y[i] = luma(px[0] as u16, px[1] as u16, px[2] as u16);
        }
        let usual = squared_error(&rgba, w, h, &plain);
        assert!(
            fitted < usual,
            "fitted luma {fitted:.1}, BT.709 luma {usual:.1}"
        );
    }

    #[test]
    fn vector_and_scalar_paths_agree() {
        // 40 × 4: two 16-pixel steps and a remainder of 8 per row.
        let (w, h) = (40, 4);
        let rgba: Vec<u8> = (0..w * h * 4)
            .map(|i| {
                if i % 4 == 3 {
                    255
                } else {
                    (i * 37 % 256) as u8
                }
            })
            .collect();
        let mut out = Yuv420::new(w, h);
        rgba_to_yuv420(&rgba, w, h, &mut out);
        let mut portable = Yuv420::new(w, h);
        convert(&rgba, w, h, &mut portable);
        assert_eq!(out, portable, "the AVX2 build gives the same bytes");
        for (i, px) in rgba.chunks_exact(4).enumerate() {
            let k = (i / w / 2) * (w / 2) + (i % w) / 2;
            let sum = chroma_sum(out.u[k], out.v[k]);
            assert_eq!(out.y[i], fitted_luma(px[0], px[1], px[2], sum), "{i}");
        }
        for j in 0..h / 2 {
            for i in 0..w / 2 {
                let at = |x: usize, y: usize, k: usize| rgba[4 * (y * w + x) + k] as u16;
                let mean = |k| {
                    let s = at(2 * i, 2 * j, k)
                        + at(2 * i + 1, 2 * j, k)
                        + at(2 * i, 2 * j + 1, k)
                        + at(2 * i + 1, 2 * j + 1, k);
                    ((s + 2) >> 2) as i16
                };
                let (r, g, b) = (mean(0), mean(1), mean(2));
                assert_eq!(out.u[j * w / 2 + i], chroma(KCB, r, g, b));
                assert_eq!(out.v[j * w / 2 + i], chroma(KCR, r, g, b));
            }
        }
    }
}
