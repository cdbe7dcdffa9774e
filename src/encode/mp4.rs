//! MP4 movies: H.264 (Cisco's OpenH264, built from source by the `openh264`
//! crate) in the container of [`super::isobmff`]. Behind the default cargo
//! feature `mp4`; see docs/formats.md for its build cost and the patent
//! situation of H.264.
//!
//! The encoder runs in a thread of its own: the caller converts each frame
//! to Y′CbCr 4:2:0 and hands it over, then draws the next frame while the
//! encoder works. Fixed quantiser (`Mp4Quality`), so a frame's quality
//! does not depend on its neighbours and the bytes are reproducible.

use super::format::Mp4Quality;
use super::gif::Palette;
use super::isobmff::{Mp4Track, annex_b_units, mp4_file};
use super::yuv::{Yuv420, rgba_to_yuv420};
use crate::error::{Error, Result};
use openh264::OpenH264API;
use openh264::encoder::{
    BitRate, Complexity, Encoder, EncoderConfig, FrameRate, FrameType, IntraFramePeriod, QpRange,
    RateControlMode, UsageType, VuiConfig,
};
use openh264::formats::YUVSlices;
use std::sync::mpsc::{Receiver, SyncSender, sync_channel};
use std::thread::JoinHandle;
use tiny_skia::Pixmap;

/// The bitrate given to OpenH264's rate controller, bits per second: far
/// above what any frame needs, so the fixed QP alone sets the quality.
const MAX_BITRATE: u32 = 50_000_000;
/// A key frame at least every this many seconds (for seeking).
pub const KEY_FRAME_SECONDS: f64 = 5.0;
/// Frames that may wait for the encoder: bounds the memory held.
const QUEUE: usize = 8;

/// OpenH264's `ENCODER_OPTION_TRACE_LEVEL` (`codec_app_def.h`; the
/// `openh264` crate uses it but does not export it).
const ENCODER_OPTION_TRACE_LEVEL: std::os::raw::c_int = 25;
/// OpenH264's `WELS_LOG_QUIET`: no log line at all.
const WELS_LOG_QUIET: u32 = 0;

/// Silences OpenH264's log before the encoder is initialised. The crate
/// sets the trace level (quiet) only after `InitializeExt`, which checks
/// the parameters and prints a warning on stderr at the default level
/// ("[OpenH264] this = 0x…, Warning: bEnableFrameSkip = 0, bitrate can't
/// be controlled …", true and harmless here: the quantiser is fixed).
/// OpenH264 takes this one option before initialisation
/// (`CWelsH264SVCEncoder::SetOption`); it sets what is logged, nothing of
/// what is encoded, so the bytes are the same.
fn quiet(encoder: &mut Encoder) {
    let mut level = WELS_LOG_QUIET;
    // SAFETY: the encoder is created (its pointer valid until it drops);
    // the option reads one `uint32_t` through the pointer, during the
    // call, from a local that outlives it. The trace level is no
    // parameter the encoder relies on (the crate sets it itself).
    unsafe {
        let _ = encoder
            .raw_api()
            .set_option(ENCODER_OPTION_TRACE_LEVEL, (&raw mut level).cast());
    }
}

/// Streaming MP4 encoder: push frames, then `finish` for the bytes.
pub struct Mp4Writer {
    width: u32,
    height: u32,
    frames: usize,
    /// The palette each frame is mapped to before conversion, if any.
    palette: Option<&'static Palette>,
    /// Scratch: the frame in the palette's colours.
    shown: Vec<u8>,
    stage: Stage,
}

/// Where frames are encoded: on a thread of its own while the caller draws
/// the next ones, or, where no thread can be started (a limit on
/// processes), on the caller's thread as each comes (the same bytes).
enum Stage {
    Thread {
        to_encoder: SyncSender<Yuv420>,
        /// Buffers the encoder has finished with, for reuse.
        spare: Receiver<Yuv420>,
        done: Option<JoinHandle<Result<Mp4Track>>>,
    },
    Inline {
        encoder: Box<Encoder>,
        track: Mp4Track,
        yuv: Option<Yuv420>,
        sample: Vec<u8>,
    },
}

impl Mp4Writer {
    /// A writer for `width × height` frames (even, at most 3840 × 2160)
    /// shown at `fps` frames per second, at the default quality.
    pub fn new(width: u32, height: u32, fps: f64) -> Result<Self> {
        Self::with_quality(width, height, fps, Mp4Quality::default())
    }

    /// [`Mp4Writer::new`] at `quality`: every frame at its fixed quantiser.
    pub fn with_quality(width: u32, height: u32, fps: f64, quality: Mp4Quality) -> Result<Self> {
        let qp = quality.qp();
        super::check_movie_frame(super::Format::Mp4, width, height, fps)?;
        let config = EncoderConfig::new()
            .usage_type(UsageType::CameraVideoRealTime)
            // With rate control off OpenH264 takes the layer's own QP
            // (26, which the crate does not expose) and ignores the range;
            // in quality mode every QP is clipped to the range, so a range
            // of one value fixes it, and a bitrate far above what any
            // frame needs keeps the controller from skipping frames.
            .rate_control_mode(RateControlMode::Quality)
            .bitrate(BitRate::from_bps(MAX_BITRATE))
            .qp(QpRange::new(qp, qp))
            .skip_frames(false)
            .max_frame_rate(FrameRate::from_hz(fps as f32))
            .complexity(Complexity::Low)
            // Each of these costs time and saves no bytes at a fixed
            // quantiser on drawn frames (measured: background detection
            // alone is 30 % of the encoder's time at 1280 × 720).
            .background_detection(false)
            .scene_change_detect(false)
            .adaptive_quantization(false)
            .num_threads(1)
            .intra_frame_period(IntraFramePeriod::from_num_frames(
                (KEY_FRAME_SECONDS * fps).round().max(1.0) as u32,
            ))
            .vui(VuiConfig::bt709());
        let mut encoder = Encoder::with_api_config(OpenH264API::from_source(), config)
            .map_err(|e| Error::failed(format!("the H.264 encoder did not start: {e}")))?;
        quiet(&mut encoder);
        let track = Mp4Track {
            width,
            height,
            fps,
            ..Mp4Track::default()
        };
        Ok(Self {
            width,
            height,
            frames: 0,
            palette: None,
            shown: Vec::new(),
            stage: Stage::start(encoder, track),
        })
    }

    /// Encodes every frame in `palette`'s colours (each pixel its nearest
    /// entry), as the GIF of the same frames shows them: what a viewer
    /// compares the MP4 with. The movies' palette is made for their
    /// drawings (drawn frame against the GIF: 46–51 dB), so this costs the
    /// drawing little and gains the MP4 about 0.8 dB against the GIF.
    pub fn showing(mut self, palette: &'static Palette) -> Self {
        self.palette = Some(palette);
        self
    }

    /// Number of frames pushed so far.
    pub fn frames(&self) -> usize {
        self.frames
    }

    /// Appends one opaque frame; it must have the writer's size.
    pub fn push_frame(&mut self, pixmap: &Pixmap) -> Result<()> {
        if (pixmap.width(), pixmap.height()) != (self.width, self.height) {
            return Err(Error::bad_input(format!(
                "MP4 frame is {}x{}, the movie is {}x{}",
                pixmap.width(),
                pixmap.height(),
                self.width,
                self.height
            )));
        }
        let (w, h) = (self.width as usize, self.height as usize);
        let data = match self.palette {
            Some(pal) => {
                self.shown.resize(pixmap.data().len(), 255);
                let pairs = self
                    .shown
                    .chunks_exact_mut(4)
                    .zip(pixmap.data().chunks_exact(4));
                for (to, p) in pairs {
                    to[..3].copy_from_slice(&pal.color(pal.index([p[0], p[1], p[2]])));
                }
                &self.shown[..]
            }
            None => pixmap.data(),
        };
        match &mut self.stage {
            Stage::Thread {
                to_encoder,
                spare,
                done,
            } => {
                let mut yuv = spare.try_recv().unwrap_or_else(|_| Yuv420::new(w, h));
                rgba_to_yuv420(data, w, h, &mut yuv);
                if to_encoder.send(yuv).is_err() {
                    // The encoder thread ended: report why.
                    return Err(match done.take().map(JoinHandle::join) {
                        Some(Ok(Err(e))) => e,
                        _ => Error::failed("the H.264 encoder stopped early"),
                    });
                }
            }
            Stage::Inline {
                encoder,
                track,
                yuv,
                sample,
            } => {
                let yuv = yuv.get_or_insert_with(|| Yuv420::new(w, h));
                rgba_to_yuv420(data, w, h, yuv);
                encode_one(encoder, track, yuv, sample)?;
            }
        }
        self.frames += 1;
        Ok(())
    }

    /// Finishes the stream and returns the MP4 bytes.
    pub fn finish(self) -> Result<Vec<u8>> {
        let track = match self.stage {
            Stage::Thread {
                to_encoder, done, ..
            } => {
                drop(to_encoder);
                let done = done.ok_or_else(|| Error::failed("the H.264 encoder stopped early"))?;
                done.join()
                    .map_err(|_| Error::failed("the H.264 encoder thread panicked"))??
            }
            Stage::Inline { track, .. } => track,
        };
        if track.sizes.len() != self.frames {
            return Err(Error::failed(format!(
                "the H.264 encoder returned {} of {} frames",
                track.sizes.len(),
                self.frames
            )));
        }
        mp4_file(&track)
    }
}

impl Stage {
    /// The encoder on a thread of its own, or inline where none can start.
    fn start(encoder: Encoder, track: Mp4Track) -> Self {
        let (to_encoder, inbox) = sync_channel::<Yuv420>(QUEUE);
        let (give_back, spare) = sync_channel::<Yuv420>(QUEUE + 2);
        // The encoder and track go to the thread through a slot, so that
        // they stay here when the thread cannot be started.
        let slot = std::sync::Arc::new(std::sync::Mutex::new(Some((encoder, track))));
        let theirs = std::sync::Arc::clone(&slot);
        let spawned = std::thread::Builder::new()
            .name("h264".into())
            .spawn(move || {
                let taken = theirs.lock().unwrap_or_else(|p| p.into_inner()).take();
                let (encoder, track) =
                    taken.ok_or_else(|| Error::failed("the H.264 encoder was not handed over"))?;
                encode_all(encoder, track, inbox, give_back)
            });
        match spawned {
            Ok(done) => Self::Thread {
                to_encoder,
                spare,
                done: Some(done),
            },
            Err(_) => {
                let taken = slot.lock().unwrap_or_else(|p| p.into_inner()).take();
                let (encoder, track) = taken.expect("the thread never started, so it took nothing");
                Self::Inline {
                    encoder: Box::new(encoder),
                    track,
                    yuv: None,
                    sample: Vec::new(),
                }
            }
        }
    }
}

/// The encoder thread: every frame in, one sample out per frame.
fn encode_all(
    mut encoder: Encoder,
    mut track: Mp4Track,
    inbox: Receiver<Yuv420>,
    give_back: SyncSender<Yuv420>,
) -> Result<Mp4Track> {
    let mut sample = Vec::new();
    for yuv in inbox {
        encode_one(&mut encoder, &mut track, &yuv, &mut sample)?;
        // The caller may have stopped taking buffers back; that is fine.
        let _ = give_back.try_send(yuv);
    }
    Ok(track)
}

/// Encodes one frame and appends it to `track` as one sample (`sample`
/// is scratch).
fn encode_one(
    encoder: &mut Encoder,
    track: &mut Mp4Track,
    yuv: &Yuv420,
    sample: &mut Vec<u8>,
) -> Result<()> {
    let (w, h) = (yuv.width, yuv.height);
    let src = YUVSlices::new((&yuv.y, &yuv.u, &yuv.v), (w, h), (w, w / 2, w / 2));
    let stream = encoder
        .encode(&src)
        .map_err(|e| Error::failed(format!("H.264 encoding failed: {e}")))?;
    if stream.frame_type() == FrameType::Skip {
        return Err(Error::failed("the H.264 encoder skipped a frame"));
    }
    let key = stream.frame_type() == FrameType::IDR;
    sample.clear();
    for l in 0..stream.num_layers() {
        let Some(layer) = stream.layer(l) else {
            continue;
        };
        for n in 0..layer.nal_count() {
            let Some(bytes) = layer.nal_unit(n) else {
                continue;
            };
            for unit in annex_b_units(bytes) {
                match unit[0] & 0x1f {
                    7 => track.sps = unit.to_vec(),
                    8 => track.pps = unit.to_vec(),
                    _ => {
                        sample.extend_from_slice(&(unit.len() as u32).to_be_bytes());
                        sample.extend_from_slice(unit);
                    }
                }
            }
        }
    }
    if sample.is_empty() {
        return Err(Error::failed("the H.264 encoder returned an empty frame"));
    }
    track.push_sample(sample, key);
    Ok(())
}
