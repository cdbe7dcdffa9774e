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
        for y in 0..f.height as usize {
            for x in 0..f.width as usize {
                let i = f.buffer[y * f.width as usize + x];
                if Some(i) == f.transparent {
                    continue;
                }
                let at = 3 * ((f.top as usize + y) * w + f.left as usize + x);
                screen[at..at + 3].copy_from_slice(&pal[3 * i as usize..3 * i as usize + 3]);
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
    let mse = a
        .iter()
        .zip(b)
        .map(|(&x, &y)| (x as f64 - y as f64).powi(2))
        .sum::<f64>()
        / a.len() as f64;
    10.0 * (255.0f64 * 255.0 / mse.max(1e-12)).log10()
}
