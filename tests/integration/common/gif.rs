//! A GIF decoded as a viewer shows it, and the PSNR of two frames: for the
//! tests that compare GIF frames with what was drawn or with the MP4's.

/// A GIF's frames, each composited over the ones before it (disposal
/// "keep"; a transparent index leaves the pixel as it was), as RGB.
pub struct GifFrames {
    pub width: usize,
    pub height: usize,
    pub frames: Vec<Vec<u8>>,
    /// Each frame's delay, in hundredths of a second.
    pub delays: Vec<u16>,
}

/// Decodes `bytes`, each frame in its own palette or the global one, over
/// a white screen.
pub fn decode(bytes: &[u8]) -> GifFrames {
    let mut opts = gif::DecodeOptions::new();
    opts.set_color_output(gif::ColorOutput::Indexed);
    let mut d = opts.read_info(bytes).unwrap();
    let (w, h) = (d.width() as usize, d.height() as usize);
    let global = d.global_palette().map(<[u8]>::to_vec);
    let mut screen = vec![255u8; w * h * 3];
    let (mut frames, mut delays) = (Vec::new(), Vec::new());
    while let Some(f) = d.read_next_frame().unwrap() {
        let pal = f
            .palette
            .clone()
            .or_else(|| global.clone())
            .expect("a GIF frame has a palette");
        // Row by row, each pixel's three bytes stored one by one: the
        // integration tests compile at opt-level 0, where a slice copy per
        // pixel cost about a second for a 200-frame movie.
        let fw = f.width as usize;
        let transparent = f.transparent.map_or(-1, i32::from);
        for (y, row) in f.buffer.chunks_exact(fw.max(1)).enumerate() {
            let line = &mut screen[3 * ((f.top as usize + y) * w + f.left as usize)..][..3 * fw];
            let mut at = 0;
            for &i in row {
                if i32::from(i) != transparent {
                    let c = 3 * i as usize;
                    line[at] = pal[c];
                    line[at + 1] = pal[c + 1];
                    line[at + 2] = pal[c + 2];
                }
                at += 3;
            }
        }
        frames.push(screen.clone());
        delays.push(f.delay);
    }
    GifFrames {
        width: w,
        height: h,
        frames,
        delays,
    }
}

/// Peak signal-to-noise ratio of two RGB buffers, in dB (10 log10 of
/// 255² over the mean squared difference).
pub fn psnr(a: &[u8], b: &[u8]) -> f64 {
    assert_eq!(a.len(), b.len());
    // Summed in integers: every square and every partial sum is an
    // integer under 2⁵³, so this is the sum of the squares in f64 exactly,
    // and at the integration tests' opt-level 0 several times faster than
    // an iterator chain over f64 (a 200-frame movie: 184 million terms).
    let mut sum: u64 = 0;
    for (&x, &y) in a.iter().zip(b) {
        let d = u64::from(x.abs_diff(y));
        sum += d * d;
    }
    assert!(sum < 1 << 53, "the sum of squares is exact in f64");
    let mse = sum as f64 / a.len() as f64;
    10.0 * (255.0f64 * 255.0 / mse.max(1e-12)).log10()
}
