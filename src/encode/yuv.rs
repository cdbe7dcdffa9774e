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

/// BT.709 luma and chroma weights for 8-bit limited range, scaled by 2¹⁶.
const KY: [i32; 3] = [11966, 40254, 4064];
const KCB: [i32; 3] = [-6596, -22188, 28784];
const KCR: [i32; 3] = [28784, -26145, -2639];

#[inline(always)]
fn dot(k: [i32; 3], r: i32, g: i32, b: i32) -> i32 {
    k[0] * r + k[1] * g + k[2] * b
}

/// Converts opaque RGBA pixels (`width × height`, both even) into `out`,
/// which is resized as needed. Chroma is taken from the mean of each 2 × 2
/// block.
pub fn rgba_to_yuv420(rgba: &[u8], width: usize, height: usize, out: &mut Yuv420) {
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
    let luma = out.y.chunks_exact_mut(2 * width);
    let chroma = out.u.chunks_exact_mut(cw).zip(out.v.chunks_exact_mut(cw));
    for ((pair, ys), (us, vs)) in rows.zip(luma).zip(chroma) {
        let (top, bottom) = pair.split_at(stride);
        let (y0, y1) = ys.split_at_mut(width);
        for i in 0..cw {
            let mut sum = [0i32; 3];
            for (row, ys) in [(top, &mut *y0), (bottom, &mut *y1)] {
                for x in 2 * i..2 * i + 2 {
                    let px = &row[4 * x..4 * x + 4];
                    let (r, g, b) = (px[0] as i32, px[1] as i32, px[2] as i32);
                    ys[x] = ((dot(KY, r, g, b) + (16 << 16) + (1 << 15)) >> 16) as u8;
                    sum[0] += r;
                    sum[1] += g;
                    sum[2] += b;
                }
            }
            // The sums are 4× the means: shift by 18 instead of 16.
            let chroma = |k| (dot(k, sum[0], sum[1], sum[2]) + (128 << 18) + (1 << 17)) >> 18;
            us[i] = chroma(KCB).clamp(0, 255) as u8;
            vs[i] = chroma(KCR).clamp(0, 255) as u8;
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
    }
}
