//! GIF bytes from pixels, with one fixed global palette made for the
//! caller's scenes (ramps from the white background to each drawing colour
//! the caller names: the renderer's palette), mapped by a
//! 32×32×32 lookup table, so no per-frame quantiser runs and the output is
//! deterministic. Each frame after the first encodes only the bounding box
//! of the pixels that changed, with unchanged pixels inside that box
//! transparent.

use super::{Rgb, WHITE};
use crate::error::{Error, Result};
use std::borrow::Cow;
use tiny_skia::Pixmap;

/// Ramp steps from white to each anchor (the anchor itself is the last
/// step): six anchors and two extras fill the 255 colours a GIF palette
/// holds besides its transparent index.
pub const GIF_RAMP_STEPS: usize = 42;

/// The palette index that marks "unchanged since the previous frame".
pub const TRANSPARENT_INDEX: u8 = 255;

/// A global GIF palette (at most 255 colours; index 255 is transparent) with
/// a 32×32×32 lookup table from RGB to the nearest entry.
pub struct Palette {
    colors: Vec<Rgb>,
    lut: Box<[u8; LUT_SIZE]>,
}

/// Entries of the 32×32×32 lookup table.
const LUT_SIZE: usize = 1 << 15;

impl Palette {
    /// Builds a palette of white, `steps` ramp colours from white to each
    /// anchor, and the extra colours. Every palette colour maps to itself
    /// exactly; other colours map to the nearest entry of their LUT cell.
    pub fn new(anchors: &[Rgb], steps: usize, extras: &[Rgb]) -> Result<Self> {
        let mut colors = vec![WHITE];
        for a in anchors {
            colors.extend((1..=steps).map(|j| ramp(*a, j, steps)));
        }
        colors.extend_from_slice(extras);
        if colors.len() > TRANSPARENT_INDEX as usize {
            return Err(Error::bad_input(format!(
                "a GIF palette holds at most 255 colours, this one has {}",
                colors.len()
            )));
        }
        let lut = build_lut(&colors, anchors, extras);
        Ok(Self { colors, lut })
    }

    /// The palette's colours in index order.
    pub fn colors(&self) -> &[Rgb] {
        &self.colors
    }

    /// Index of the palette entry for `c` (table lookup).
    #[inline(always)]
    pub fn index(&self, c: Rgb) -> u8 {
        self.lut[lut_key(c)]
    }

    /// Index of the palette entry for an RGBA pixel (alpha ignored).
    #[inline(always)]
    fn index_px(&self, px: &[u8]) -> u8 {
        self.lut[lut_key([px[0], px[1], px[2]])]
    }

    /// The colour of `index`.
    pub fn color(&self, index: u8) -> Rgb {
        self.colors.get(index as usize).copied().unwrap_or(WHITE)
    }

    /// The palette as `[r, g, b, ...]`, padded to 256 entries.
    fn gif_table(&self) -> Vec<u8> {
        let mut t: Vec<u8> = self.colors.iter().flatten().copied().collect();
        t.resize(256 * 3, 255);
        t
    }
}

/// Step `j` of `steps` from white to `a` (step `steps` is `a` itself).
fn ramp(a: Rgb, j: usize, steps: usize) -> Rgb {
    let f = j as f64 / steps as f64;
    a.map(|c| (255.0 + (c as f64 - 255.0) * f).round() as u8)
}

#[inline(always)]
fn lut_key(c: Rgb) -> usize {
    (((c[0] as usize >> 3) << 10) | ((c[1] as usize >> 3) << 5) | (c[2] as usize >> 3))
        & (LUT_SIZE - 1)
}

/// Nearest palette entry for the centre of every LUT cell, then the exact
/// palette colours (white, anchors and extras last, so they win) pinned to
/// their own cells.
fn build_lut(colors: &[Rgb], anchors: &[Rgb], extras: &[Rgb]) -> Box<[u8; LUT_SIZE]> {
    let mut lut = Box::new([0u8; LUT_SIZE]);
    for (key, slot) in lut.iter_mut().enumerate() {
        let centre = [(key >> 10) & 31, (key >> 5) & 31, key & 31].map(|v| (v << 3 | 4) as i32);
        *slot = nearest(colors, centre);
    }
    let pinned = colors.iter().chain(anchors).chain(extras).chain([&WHITE]);
    for c in pinned {
        if let Some(i) = colors.iter().position(|p| p == c) {
            lut[lut_key(*c)] = i as u8;
        }
    }
    lut
}

fn nearest(colors: &[Rgb], c: [i32; 3]) -> u8 {
    let dist = |p: &Rgb| -> i32 {
        let d = [0, 1, 2].map(|k| p[k] as i32 - c[k]);
        2 * d[0] * d[0] + 4 * d[1] * d[1] + 3 * d[2] * d[2]
    };
    let best = colors
        .iter()
        .enumerate()
        .min_by_key(|(_, p)| dist(p))
        .map_or(0, |(i, _)| i);
    best as u8
}

/// Streaming GIF encoder: push frames, then `finish` for the bytes.
///
/// Infinite loop, one global palette, per-frame delays from `fps` (rounded so
/// that the total duration never drifts), and only the changed rectangle of
/// each frame encoded.
pub struct GifWriter {
    /// The LZW stage: a thread that compresses and writes frames in order
    /// while the caller draws the next ones.
    lzw: LzwStage,
    palette: &'static Palette,
    width: u32,
    height: u32,
    fps: f64,
    frames: usize,
    previous: Option<Vec<u8>>,
    indices: Vec<u8>,
}

/// A thread owning the encoder: frames go in through a channel, in order,
/// and the GIF bytes come out when the channel closes. The output does not
/// depend on the timing of the two threads. Where no thread can be started
/// (a limit on processes), the caller's thread compresses each frame as it
/// comes, with the same bytes out.
enum LzwStage {
    Thread {
        frames: std::sync::mpsc::SyncSender<gif::Frame<'static>>,
        done: std::thread::JoinHandle<Result<Vec<u8>>>,
    },
    Inline(gif::Encoder<Vec<u8>>),
}

/// Frames that may wait for compression: bounds the memory held.
const LZW_QUEUE: usize = 16;

/// Compresses one frame and appends it.
fn write_frame(encoder: &mut gif::Encoder<Vec<u8>>, mut frame: gif::Frame<'static>) -> Result<()> {
    // The `gif` crate's own compression, code for code, only faster.
    frame.buffer = Cow::Owned(super::lzw::gif_lzw(&frame.buffer));
    encoder
        .write_lzw_pre_encoded_frame(&frame)
        .map_err(gif_error)
}

impl LzwStage {
    fn start(encoder: gif::Encoder<Vec<u8>>) -> Self {
        let (frames, inbox) = std::sync::mpsc::sync_channel::<gif::Frame<'static>>(LZW_QUEUE);
        // The encoder goes to the thread through a slot, so that it stays
        // here when the thread cannot be started.
        let slot = std::sync::Arc::new(std::sync::Mutex::new(Some(encoder)));
        let theirs = std::sync::Arc::clone(&slot);
        let spawned = std::thread::Builder::new()
            .name("gif-lzw".into())
            .spawn(move || {
                let taken = theirs.lock().unwrap_or_else(|p| p.into_inner()).take();
                let mut encoder =
                    taken.ok_or_else(|| Error::failed("the GIF encoder was not handed over"))?;
                for frame in inbox {
                    write_frame(&mut encoder, frame)?;
                }
                encoder.into_inner().map_err(gif_error)
            });
        match spawned {
            Ok(done) => Self::Thread { frames, done },
            Err(_) => {
                let encoder = slot.lock().unwrap_or_else(|p| p.into_inner()).take();
                Self::Inline(encoder.expect("the thread never started, so it took nothing"))
            }
        }
    }

    fn send(&mut self, frame: gif::Frame<'static>) -> Result<()> {
        match self {
            Self::Thread { frames, .. } => frames
                .send(frame)
                .map_err(|_| Error::failed("the GIF encoder stopped early")),
            Self::Inline(encoder) => write_frame(encoder, frame),
        }
    }

    fn finish(self) -> Result<Vec<u8>> {
        match self {
            Self::Thread { frames, done } => {
                drop(frames);
                done.join()
                    .map_err(|_| Error::failed("the GIF encoder thread panicked"))?
            }
            Self::Inline(encoder) => encoder.into_inner().map_err(gif_error),
        }
    }
}

impl GifWriter {
    /// A writer for `width × height` frames shown at `fps` frames per
    /// second, in the colours of `palette` (the renderer's:
    /// `render::Palette::gif`).
    pub fn new(width: u32, height: u32, fps: f64, palette: &'static Palette) -> Result<Self> {
        check_gif_size(width, height)?;
        check_gif_fps(fps)?;
        let table = palette.gif_table();
        let mut encoder = gif::Encoder::new(Vec::new(), width as u16, height as u16, &table)
            .map_err(gif_error)?;
        encoder
            .set_repeat(gif::Repeat::Infinite)
            .map_err(gif_error)?;
        Ok(Self {
            lzw: LzwStage::start(encoder),
            palette,
            width,
            height,
            fps,
            frames: 0,
            previous: None,
            indices: Vec::new(),
        })
    }

    /// Number of frames pushed so far.
    pub fn frames(&self) -> usize {
        self.frames
    }

    /// Appends one frame; it must have the writer's size.
    pub fn push_frame(&mut self, pixmap: &Pixmap) -> Result<()> {
        if (pixmap.width(), pixmap.height()) != (self.width, self.height) {
            return Err(Error::bad_input(format!(
                "GIF frame is {}x{}, the movie is {}x{}",
                pixmap.width(),
                pixmap.height(),
                self.width,
                self.height
            )));
        }
        let data = pixmap.data();
        let rect = match &self.previous {
            None => Some(Rect {
                x0: 0,
                y0: 0,
                x1: self.width,
                y1: self.height,
            }),
            Some(prev) => changed_rect(prev, data, self.width as usize),
        };
        let rect = rect.unwrap_or(Rect {
            x0: 0,
            y0: 0,
            x1: 1,
            y1: 1,
        });
        self.fill_indices(data, rect);
        let frame = gif::Frame {
            delay: self.delay(self.frames),
            dispose: gif::DisposalMethod::Keep,
            transparent: Some(TRANSPARENT_INDEX),
            left: rect.x0 as u16,
            top: rect.y0 as u16,
            width: (rect.x1 - rect.x0) as u16,
            height: (rect.y1 - rect.y0) as u16,
            buffer: Cow::Owned(self.indices.clone()),
            ..gif::Frame::default()
        };
        self.lzw.send(frame)?;
        match &mut self.previous {
            // Outside the changed rectangle the frames are equal already.
            Some(prev) => {
                let stride = 4 * self.width as usize;
                let rows = rect.y0 as usize * stride..rect.y1 as usize * stride;
                prev[rows.clone()].copy_from_slice(&data[rows]);
            }
            None => self.previous = Some(data.to_vec()),
        }
        self.frames += 1;
        Ok(())
    }

    /// Finishes the stream and returns the GIF bytes.
    pub fn finish(self) -> Result<Vec<u8>> {
        let bytes = self.lzw.finish()?;
        if self.frames == 0 {
            return Err(Error::failed("a GIF needs at least one frame"));
        }
        Ok(bytes)
    }

    /// Delay of frame `k` in 1/100 s: differences of rounded cumulative times.
    fn delay(&self, k: usize) -> u16 {
        let t = |k: usize| (k as f64 * 100.0 / self.fps).round() as i64;
        (t(k + 1) - t(k)).clamp(1, u16::MAX as i64) as u16
    }

    /// Palette indices of `rect`; pixels equal to the previous frame become
    /// transparent (the decoder keeps what it showed).
    fn fill_indices(&mut self, data: &[u8], rect: Rect) {
        let w = self.width as usize;
        let pal = self.palette;
        self.indices.clear();
        for y in rect.y0 as usize..rect.y1 as usize {
            let row = (y * w + rect.x0 as usize) * 4..(y * w + rect.x1 as usize) * 4;
            let cur = &data[row.clone()];
            match self.previous.as_deref() {
                Some(p) => map_changed(pal, cur, &p[row], &mut self.indices),
                None => self
                    .indices
                    .extend(cur.chunks_exact(4).map(|c| pal.index_px(c))),
            }
        }
    }
}

/// Pixels compared at once where two frames are compared: 8 RGBA pixels,
/// 32 bytes, one AVX2 register. Most of a frame's changed rectangle is
/// unchanged pixels, so whole blocks of them are passed over at once.
const BLOCK_PIXELS: usize = 8;
/// The bytes of [`BLOCK_PIXELS`] pixels.
const BLOCK_BYTES: usize = 4 * BLOCK_PIXELS;

/// Whether two blocks of [`BLOCK_BYTES`] bytes are equal (a fixed-size
/// compare, inlined, not a call to `memcmp`).
#[inline(always)]
fn same_block(a: &[u8], b: &[u8]) -> bool {
    let a: &[u8; BLOCK_BYTES] = a.try_into().expect("a whole block");
    let b: &[u8; BLOCK_BYTES] = b.try_into().expect("a whole block");
    a == b
}

/// Appends the palette index of each pixel of `cur`, or the transparent
/// index where it equals `prev`: a block of [`BLOCK_PIXELS`] unchanged
/// pixels at once, the others pixel by pixel ([`map_pixels`]); the same
/// indices as [`map_pixels`] over the whole row.
#[inline]
fn map_changed(pal: &Palette, cur: &[u8], prev: &[u8], out: &mut Vec<u8>) {
    let mut cur_blocks = cur.chunks_exact(BLOCK_BYTES);
    let mut prev_blocks = prev.chunks_exact(BLOCK_BYTES);
    for (c, p) in (&mut cur_blocks).zip(&mut prev_blocks) {
        if same_block(c, p) {
            out.extend_from_slice(&[TRANSPARENT_INDEX; BLOCK_PIXELS]);
        } else {
            map_pixels(pal, c, p, out);
        }
    }
    map_pixels(pal, cur_blocks.remainder(), prev_blocks.remainder(), out);
}

/// Appends the palette index of each pixel of `cur`, or the transparent
/// index where it equals `prev`, pixel by pixel.
#[inline]
fn map_pixels(pal: &Palette, cur: &[u8], prev: &[u8], out: &mut Vec<u8>) {
    let word = |c: &[u8]| u32::from_ne_bytes([c[0], c[1], c[2], c[3]]);
    out.extend(cur.chunks_exact(4).zip(prev.chunks_exact(4)).map(|(c, o)| {
        if word(c) == word(o) {
            TRANSPARENT_INDEX
        } else {
            pal.index_px(c)
        }
    }));
}

/// A pixel rectangle [x0, x1) × [y0, y1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Rect {
    x0: u32,
    y0: u32,
    x1: u32,
    y1: u32,
}

/// Bounding box of the pixels that differ between two RGBA buffers of row
/// width `w`; `None` when they are identical.
fn changed_rect(prev: &[u8], cur: &[u8], w: usize) -> Option<Rect> {
    let stride = w * 4;
    let rows = prev.chunks_exact(stride).zip(cur.chunks_exact(stride));
    let (mut x0, mut x1, mut y0, mut y1) = (w, 0, usize::MAX, 0);
    for (y, (p, c)) in rows.enumerate() {
        if p == c {
            continue;
        }
        let first = first_changed(p, c).unwrap_or(0);
        let last = last_changed(p, c).unwrap_or(first);
        x0 = x0.min(first);
        x1 = x1.max(last + 1);
        y0 = y0.min(y);
        y1 = y + 1;
    }
    (y0 != usize::MAX).then_some(Rect {
        x0: x0 as u32,
        y0: y0 as u32,
        x1: x1 as u32,
        y1: y1 as u32,
    })
}

/// The first pixel at which two RGBA rows differ: blocks of
/// [`BLOCK_PIXELS`] passed over while equal, then pixel by pixel.
fn first_changed(p: &[u8], c: &[u8]) -> Option<usize> {
    let blocks = p.chunks_exact(BLOCK_BYTES).zip(c.chunks_exact(BLOCK_BYTES));
    for (k, (a, b)) in blocks.enumerate() {
        if !same_block(a, b) {
            return first_pixel(a, b).map(|i| k * BLOCK_PIXELS + i);
        }
    }
    let whole = p.len() / BLOCK_BYTES * BLOCK_BYTES;
    first_pixel(&p[whole..], &c[whole..]).map(|i| whole / 4 + i)
}

/// The last pixel at which two RGBA rows differ: the part past the last
/// whole block pixel by pixel, then blocks from the end.
fn last_changed(p: &[u8], c: &[u8]) -> Option<usize> {
    let whole = p.len() / BLOCK_BYTES * BLOCK_BYTES;
    if let Some(i) = last_pixel(&p[whole..], &c[whole..]) {
        return Some(whole / 4 + i);
    }
    let blocks = p[..whole]
        .chunks_exact(BLOCK_BYTES)
        .zip(c[..whole].chunks_exact(BLOCK_BYTES));
    for (k, (a, b)) in blocks.enumerate().rev() {
        if !same_block(a, b) {
            return last_pixel(a, b).map(|i| k * BLOCK_PIXELS + i);
        }
    }
    None
}

/// The first pixel at which two RGBA runs differ, pixel by pixel.
fn first_pixel(p: &[u8], c: &[u8]) -> Option<usize> {
    p.chunks_exact(4)
        .zip(c.chunks_exact(4))
        .position(|(a, b)| a != b)
}

/// The last pixel at which two RGBA runs differ, pixel by pixel.
fn last_pixel(p: &[u8], c: &[u8]) -> Option<usize> {
    p.chunks_exact(4)
        .zip(c.chunks_exact(4))
        .rposition(|(a, b)| a != b)
}

/// Highest frame rate a GIF plays at its real speed: delays are whole
/// hundredths of a second, and browsers show delays of 10 ms or less at
/// 100 ms, so 2/100 s (50 frames per second) is the shortest delay that
/// plays as written. Faster movies are refused, not slowed down or thinned.
pub const GIF_MAX_FPS: f64 = 50.0;

/// Lowest frame rate a GIF plays at its real speed: a frame's delay is a
/// 16-bit count of hundredths of a second, at most 655.35 s, so one frame
/// per 655 s (0.0016 frames per second, rounded up so every delay fits).
/// Slower movies are refused, not played faster.
pub const GIF_MIN_FPS: f64 = 0.0016;

/// Refuses frame rates a GIF cannot play at their real speed.
pub(crate) fn check_gif_fps(fps: f64) -> Result<()> {
    if !(fps.is_finite() && fps > 0.0) {
        return Err(Error::bad_input(format!(
            "the frame rate must be a number above 0, got {fps}"
        )));
    }
    if fps < GIF_MIN_FPS {
        return Err(Error::bad_input(format!(
            "a GIF plays at least {GIF_MIN_FPS} frames per second (a frame shows at most \
             655.35 s: delays are 16-bit counts of 1/100 s), got {fps}; ask for \
             {GIF_MIN_FPS} to {GIF_MAX_FPS}, or for MP4"
        )));
    }
    if fps > GIF_MAX_FPS {
        return Err(Error::bad_input(format!(
            "a GIF plays at most {GIF_MAX_FPS} frames per second (browsers slow shorter frame \
             delays down to 10 per second), got {fps}; ask for {GIF_MAX_FPS} or fewer, or for MP4"
        )));
    }
    Ok(())
}

pub(crate) fn check_gif_size(width: u32, height: u32) -> Result<()> {
    let ok = |v: u32| (1..=u16::MAX as u32).contains(&v);
    if ok(width) && ok(height) {
        Ok(())
    } else {
        Err(Error::bad_input(format!(
            "GIF size must be between 1x1 and 65535x65535 pixels, got {width}x{height}"
        )))
    }
}

fn gif_error(e: gif::EncodingError) -> Error {
    Error::failed(format!("GIF encoding failed: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A palette of six ramps and two extras (as the renderer's).
    fn six() -> &'static Palette {
        static P: std::sync::OnceLock<Palette> = std::sync::OnceLock::new();
        P.get_or_init(|| Palette::new(&ANCHORS, GIF_RAMP_STEPS, &EXTRAS).unwrap())
    }
    const ANCHORS: [Rgb; 6] = [
        [34, 34, 34],
        [213, 94, 0],
        [0, 114, 178],
        [0, 158, 115],
        [33, 102, 172],
        [178, 24, 43],
    ];
    const EXTRAS: [Rgb; 2] = [[150, 150, 150], [0, 0, 0]];

    #[test]
    fn palette_colours_map_to_themselves() {
        let p = six();
        for c in ANCHORS.iter().chain(&EXTRAS).chain([&WHITE]) {
            assert_eq!(p.color(p.index(*c)), *c);
        }
        assert!(p.colors().len() <= 255);
    }

    #[test]
    fn delays_do_not_drift() {
        let w = GifWriter::new(4, 4, 30.0, six()).unwrap();
        let total: u32 = (0..30).map(|k| w.delay(k) as u32).sum();
        assert_eq!(total, 100);
        // At the slowest rate allowed every delay fits its 16 bits
        // (100 / 0.0016 = 62,500 hundredths, under 65,535); below it the
        // delay would be cut to 655.35 s and the movie play faster.
        let slow = GifWriter::new(4, 4, GIF_MIN_FPS, six()).unwrap();
        assert!((0..3).all(|k| f64::from(slow.delay(k)) == (100.0 / GIF_MIN_FPS).round()));
        assert!(check_gif_fps(100.0 / 65_536.0).is_err());
    }

    #[test]
    fn changed_rect_finds_box() {
        let a = vec![0u8; 4 * 5 * 3];
        let mut b = a.clone();
        b[4 * (5 + 2)] = 9;
        b[4 * (2 * 5 + 3) + 1] = 9;
        let r = changed_rect(&a, &b, 5).unwrap();
        assert_eq!(
            r,
            Rect {
                x0: 2,
                y0: 1,
                x1: 4,
                y1: 3
            }
        );
        assert!(changed_rect(&a, &a, 5).is_none());
    }

    /// The bounding box pixel by pixel, as [`changed_rect`] gives it.
    fn changed_rect_pixelwise(prev: &[u8], cur: &[u8], w: usize) -> Option<Rect> {
        let (mut x0, mut x1, mut y0, mut y1) = (w, 0, usize::MAX, 0);
        for y in 0..prev.len() / (4 * w) {
            let px = |i: usize| {
                let k = 4 * (y * w + i);
                prev[k..k + 4] != cur[k..k + 4]
            };
            if let Some(first) = (0..w).find(|&i| px(i)) {
                let last = (0..w).rev().find(|&i| px(i)).unwrap_or(first);
                (x0, x1, y0, y1) = (x0.min(first), x1.max(last + 1), y0.min(y), y + 1);
            }
        }
        (y0 != usize::MAX).then_some(Rect {
            x0: x0 as u32,
            y0: y0 as u32,
            x1: x1 as u32,
            y1: y1 as u32,
        })
    }

    /// Two frames of width `w` and 3 rows, the second with `changes`
    /// (pixel, channel) changed.
    fn frames(w: usize, changes: &[(usize, usize)]) -> (Vec<u8>, Vec<u8>) {
        let prev: Vec<u8> = (0..4 * w * 3).map(|i| (i * 37 % 251) as u8).collect();
        let mut cur = prev.clone();
        for &(px, ch) in changes {
            cur[4 * px + ch] ^= 0x40;
        }
        (prev, cur)
    }

    #[test]
    fn blockwise_compares_match_pixelwise() {
        // Every width around the 8-pixel blocks, one or two changed pixels
        // at every place (first and last pixel of a block, the part past
        // the last whole block), each channel.
        for w in 1..=41 {
            for a in 0..3 * w {
                for b in [a, a + 1, a + 7, a + 8, 3 * w - 1] {
                    let b = b.min(3 * w - 1);
                    let (prev, cur) = frames(w, &[(a, a % 4), (b, (b + 1) % 4)]);
                    let want = changed_rect_pixelwise(&prev, &cur, w);
                    assert_eq!(changed_rect(&prev, &cur, w), want, "w {w}, {a} {b}");
                    let (mut fast, mut slow) = (Vec::new(), Vec::new());
                    map_changed(six(), &cur, &prev, &mut fast);
                    map_pixels(six(), &cur, &prev, &mut slow);
                    assert_eq!(fast, slow, "w {w}, {a} {b}");
                }
            }
            let (prev, _) = frames(w, &[]);
            assert_eq!(changed_rect(&prev, &prev, w), None);
        }
    }
}
