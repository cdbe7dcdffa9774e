//! RGB to Y′CbCr 4:2:0 (BT.709, limited range: black at luma 16, nominal
//! white at 235, chroma 16–240), the input of the H.264 encoder. The MP4
//! says so in its colour description (VUI). Luma codes above 235 are used
//! where they make a pixel decode nearer its colour (below).

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

    /// Back to RGB as a player that interpolates chroma does (bilinear,
    /// H.264's default chroma siting), `width × height × 3` bytes.
    pub fn to_rgb_bilinear(&self) -> Vec<u8> {
        let (w, cw, ch) = (self.width, self.width / 2, self.height / 2);
        let mut out = Vec::with_capacity(w * self.height * 3);
        for j in 0..self.height {
            for i in 0..w {
                let u = upsampled(&self.u, cw, ch, i, j);
                let v = upsampled(&self.v, cw, ch, i, j);
                let d = chroma_offsets(u, v);
                let y = luma_level(self.y[j * w + i]);
                out.extend(d.map(|c| (y + c).round().clamp(0.0, 255.0) as u8));
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
/// block; then each pixel's luma is the one that, with the chroma a player
/// gives it, decodes nearest its colour ([`fitted_luma`]). Where a region
/// is one colour that is its BT.709 luma; where a thin coloured line
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

/// What a chroma pair (code values, fractional where upsampled) adds to
/// R, G and B when decoded (BT.709, limited range; see
/// [`Yuv420::to_rgb`]), in full-range units.
#[inline(always)]
fn chroma_offsets(u: f32, v: f32) -> [f32; 3] {
    let cb = (u - 128.0) * (255.0 / 224.0);
    let cr = (v - 128.0) * (255.0 / 224.0);
    [1.5748 * cr, -0.187_324 * cb - 0.468_124 * cr, 1.8556 * cb]
}

/// `x` rounded to a whole level and clipped to 0–255, as a decoder makes
/// a channel (a cast, not `round`, which is a library call without SSE4.1).
#[inline(always)]
fn round_clip(x: f32) -> f32 {
    ((x + 0.5).clamp(0.0, 255.0) as u8) as f32
}

/// A luma code value in full-range units.
#[inline(always)]
fn luma_level(y: u8) -> f32 {
    (y as f32 - 16.0) * (255.0 / 219.0)
}

/// Squared error of the colour `t` decoded from luma code `y` with each of
/// the chroma offsets `d` (the decoder clips each channel to 0–255).
#[inline(always)]
fn decoded_error(y: u8, t: [f32; 3], d: &[[f32; 3]; 2]) -> f32 {
    let level = luma_level(y);
    let mut e = 0.0;
    for dr in d {
        for c in 0..3 {
            let x = round_clip(level + dr[c]) - t[c];
            e += x * x;
        }
    }
    e
}

/// The luma code (0–255) whose decoded colour is nearest `t` (least
/// squares over R, G and B) under both ways a player may spread a block's
/// chroma over its pixels: each pixel its own block's chroma (`d[0]`,
/// nearest: OpenH264's and libyuv's conversions) and chroma interpolated
/// between blocks (`d[1]`, bilinear: GPU players and browsers).
///
/// Without clipping the answer is the mean of `t − d` over the six
/// channels. A decoded channel is clipped to 0–255, so a channel pushed
/// past the end it should show (white's 255 under a red line's chroma)
/// costs nothing: those channels leave the mean, and the mean is taken
/// again until it settles, as libwebp's "sharp YUV" refines its luma.
/// The code nearest the result and its two neighbours are then compared
/// exactly. Codes above 235 (nominal white) are used: H.264 carries them
/// and decoders clip only the RGB they make.
#[inline(always)]
fn fitted_luma(t: [u8; 3], d: &[[f32; 3]; 2]) -> u8 {
    let t = t.map(|x| x as f32);
    let mut y = 0.0;
    for dr in d {
        for c in 0..3 {
            y += t[c] - dr[c];
        }
    }
    y *= 1.0 / 6.0;
    let inside = d.iter().flatten().all(|&dc| y + dc > 0.0 && y + dc < 255.0);
    if inside {
        // No channel clipped: least squares is exact (most drawn colours).
        return (y * (219.0 / 255.0) + 16.5).clamp(0.0, 255.0) as u8;
    }
    for _ in 0..4 {
        let (mut sum, mut n) = (0.0f32, 0.0f32);
        for dr in d {
            for c in 0..3 {
                let x = y + dr[c];
                // A channel clipped at the end its colour sits at is exact
                // wherever y goes further: it no longer pulls.
                let settled = (x >= 255.0 && t[c] >= 255.0) || (x <= 0.0 && t[c] <= 0.0);
                if !settled {
                    sum += t[c] - dr[c];
                    n += 1.0;
                }
            }
        }
        if n == 0.0 {
            break;
        }
        let next = sum / n;
        if (next - y).abs() < 0.25 {
            y = next;
            break;
        }
        y = next;
    }
    let code = (y * (219.0 / 255.0) + 16.5).clamp(0.0, 255.0) as u8;
    let mut best = (decoded_error(code, t, d), code);
    for c in [code.saturating_sub(1), code.saturating_add(1)] {
        let e = decoded_error(c, t, d);
        if e < best.0 {
            best = (e, c);
        }
    }
    best.1
}

/// Chroma at pixel (`i`, `j`) as a bilinear upsampler rebuilds it from a
/// `cw × ch` plane, with H.264's default chroma siting (type 0: each
/// sample level with the even columns, halfway between two rows).
#[inline(always)]
fn upsampled(plane: &[u8], cw: usize, ch: usize, i: usize, j: usize) -> f32 {
    let (x, m) = (i / 2, j / 2);
    let row = |r: usize| {
        let at = |x: usize| plane[r * cw + x.min(cw - 1)] as f32;
        if i.is_multiple_of(2) {
            at(x)
        } else {
            0.5 * (at(x) + at(x + 1))
        }
    };
    let other = if j.is_multiple_of(2) {
        m.saturating_sub(1)
    } else {
        (m + 1).min(ch - 1)
    };
    0.75 * row(m) + 0.25 * row(other)
}

/// The conversion, inlined into each instruction-set variant.
#[inline(always)]
fn convert(rgba: &[u8], width: usize, height: usize, out: &mut Yuv420) {
    debug_assert!(width.is_multiple_of(2) && height.is_multiple_of(2));
    debug_assert_eq!(rgba.len(), width * height * 4);
    let (cw, ch) = (width / 2, height / 2);
    out.width = width;
    out.height = height;
    out.y.resize(width * height, 0);
    out.u.resize(cw * ch, 0);
    out.v.resize(cw * ch, 0);
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
    let Yuv420 { y: ys, u, v, .. } = out;
    // Drawn frames are mostly runs of one colour under one chroma: the
    // previous answer is reused when nothing differs, and a block of one
    // colour whose chroma neighbours (all a bilinear upsampler reads) hold
    // its own chroma is fitted once for its four pixels.
    let mut last: Option<([u8; 3], [[f32; 3]; 2], u8)> = None;
    let mut fit = |t: [u8; 3], d: [[f32; 3]; 2]| match last {
        Some((lt, ld, ly)) if lt == t && ld == d => ly,
        _ => {
            let y = fitted_luma(t, &d);
            last = Some((t, d, y));
            y
        }
    };
    let colour = |i: usize, j: usize| {
        let p = &rgba[4 * (j * width + i)..][..3];
        [p[0], p[1], p[2]]
    };
    for m in 0..ch {
        for x in 0..cw {
            let k = m * cw + x;
            let t = colour(2 * x, 2 * m);
            let one_colour = [(1, 0), (0, 1), (1, 1)]
                .iter()
                .all(|&(a, b)| colour(2 * x + a, 2 * m + b) == t);
            if one_colour && flat_around(u, cw, ch, x, m) && flat_around(v, cw, ch, x, m) {
                let own = chroma_offsets(u[k] as f32, v[k] as f32);
                let y = fit(t, [own, own]);
                for (a, b) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                    ys[(2 * m + b) * width + 2 * x + a] = y;
                }
                continue;
            }
            for (a, b) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let (i, j) = (2 * x + a, 2 * m + b);
                let own = chroma_offsets(u[k] as f32, v[k] as f32);
                let spread = chroma_offsets(upsampled(u, cw, ch, i, j), upsampled(v, cw, ch, i, j));
                ys[j * width + i] = fit(colour(i, j), [own, spread]);
            }
        }
    }
}

/// Whether every chroma sample a bilinear upsampler reads for block
/// (`x`, `m`) (its own, the next column's, the rows above and below)
/// equals the block's own.
#[inline(always)]
fn flat_around(plane: &[u8], cw: usize, ch: usize, x: usize, m: usize) -> bool {
    let c = plane[m * cw + x];
    let cols = [x, (x + 1).min(cw - 1)];
    let rows = [m.saturating_sub(1), m, (m + 1).min(ch - 1)];
    rows.iter()
        .all(|&r| cols.iter().all(|&q| plane[r * cw + q] == c))
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

    /// Mean squared RGB error of `rgba` through 4:2:0 and back, summed over
    /// the two ways back (nearest and bilinear chroma).
    fn squared_error(rgba: &[u8], w: usize, h: usize, out: &Yuv420) -> f64 {
        [out.to_rgb(), out.to_rgb_bilinear()]
            .iter()
            .map(|back| {
                rgba.chunks_exact(4)
                    .zip(back.chunks_exact(3))
                    .flat_map(|(a, b)| (0..3).map(move |k| (a[k] as f64 - b[k] as f64).powi(2)))
                    .sum::<f64>()
            })
            .sum::<f64>()
            / (w * h) as f64
    }

    #[test]
    fn white_beside_a_red_line_stays_white() {
        // A one-pixel red line (the scene's red) down white, 4 × 4. The
        // line's chroma, shared by the white pixel of its block, would
        // leave that pixel at G = B ≈ 236 with luma held at nominal white
        // (235); a luma code above 235 pushes every channel to 255 or
        // beyond, which the decoder clips to white, under either chroma
        // upsampling.
        let (w, h) = (4, 4);
        let red = [214, 39, 40];
        let mut rgba = Vec::new();
        for _ in 0..h {
            for i in 0..w {
                let c = if i == 0 { red } else { [255; 3] };
                rgba.extend_from_slice(&[c[0], c[1], c[2], 255]);
            }
        }
        let mut out = Yuv420::new(w, h);
        rgba_to_yuv420(&rgba, w, h, &mut out);
        assert!(out.y[1] > 235, "luma {} of the white pixel", out.y[1]);
        for back in [out.to_rgb(), out.to_rgb_bilinear()] {
            for j in 0..h {
                for i in 1..w {
                    let px = &back[3 * (j * w + i)..][..3];
                    assert!(px.iter().all(|&c| c >= 254), "({i}, {j}): {px:?}");
                }
            }
        }
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
        // least-squares property (over both ways back to RGB).
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
        let (cw, ch) = (w / 2, h / 2);
        for (n, px) in rgba.chunks_exact(4).enumerate() {
            let (i, j) = (n % w, n / w);
            let k = (j / 2) * cw + i / 2;
            let own = chroma_offsets(out.u[k] as f32, out.v[k] as f32);
            let (u, v) = (&out.u, &out.v);
            let spread = chroma_offsets(upsampled(u, cw, ch, i, j), upsampled(v, cw, ch, i, j));
            let t = [px[0], px[1], px[2]];
            assert_eq!(out.y[n], fitted_luma(t, &[own, spread]), "{n}");
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
