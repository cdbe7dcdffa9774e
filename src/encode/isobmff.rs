//! The MP4 container (ISO/IEC 14496-12 and -15) for one H.264 video track:
//! `ftyp`, then `moov` (the index) before `mdat` (the frames), so a player
//! can start before the whole file has arrived ("fast start"). Every frame
//! lasts the same time (one `stts` entry); all frames form one chunk.
//!
//! Pure Rust and independent of the encoder: it takes the encoder's SPS and
//! PPS and the frames as length-prefixed NAL units (AVCC form).

use crate::error::{Error, Result};

/// One H.264 video track and its frames.
#[derive(Clone, Debug, Default)]
pub struct Mp4Track {
    pub width: u32,
    pub height: u32,
    /// Frames per second, constant. Stored as a time scale of
    /// `round(1000 fps)` ticks per second and 1000 ticks per frame, so
    /// rates with up to three decimals (29.97) are exact.
    pub fps: f64,
    /// Sequence parameter set (one NAL unit, without start code).
    pub sps: Vec<u8>,
    /// Picture parameter set (one NAL unit, without start code).
    pub pps: Vec<u8>,
    /// Every frame's bytes, one after the other: NAL units each preceded by
    /// its length as a 4-byte big-endian number.
    pub data: Vec<u8>,
    /// Byte size of each frame in `data`.
    pub sizes: Vec<u32>,
    /// Frame numbers (0-based) of the key frames (IDR).
    pub key_frames: Vec<u32>,
}

impl Mp4Track {
    /// Appends one frame (AVCC bytes).
    pub fn push_sample(&mut self, avcc: &[u8], key: bool) {
        if key {
            self.key_frames.push(self.sizes.len() as u32);
        }
        self.data.extend_from_slice(avcc);
        self.sizes.push(avcc.len() as u32);
    }

    /// Ticks per second of the track's media clock.
    pub fn timescale(&self) -> u32 {
        (self.fps * 1000.0).round().clamp(1.0, u32::MAX as f64) as u32
    }
}

/// Ticks per frame in the media clock (see [`Mp4Track::fps`]).
const FRAME_TICKS: u32 = 1000;
/// Ticks per second of the movie header (milliseconds).
const MOVIE_TIMESCALE: u32 = 1000;

/// The bytes of an MP4 file holding `track`, the index first.
pub fn mp4_file(track: &Mp4Track) -> Result<Vec<u8>> {
    if track.sizes.is_empty() {
        return Err(Error::failed("an MP4 needs at least one frame"));
    }
    if track.sps.len() < 4 || track.pps.is_empty() {
        return Err(Error::failed(
            "the H.264 encoder gave no sequence or picture parameter set",
        ));
    }
    let ftyp = ftyp();
    // The chunk offset does not change the size of the index: write it
    // once to learn where the frames start, then again with that offset.
    let probe = moov(track, 0)?;
    let offset = ftyp.len() + probe.len() + 8;
    let moov = moov(track, offset)?;
    let mdat_size = u32::try_from(track.data.len() + 8)
        .map_err(|_| Error::failed("the MP4 would exceed 4 GiB"))?;
    let mut out = Vec::with_capacity(offset + track.data.len());
    out.extend_from_slice(&ftyp);
    out.extend_from_slice(&moov);
    out.extend_from_slice(&mdat_size.to_be_bytes());
    out.extend_from_slice(b"mdat");
    out.extend_from_slice(&track.data);
    Ok(out)
}

/// A box under construction: a 4-byte size (patched on `end`) and a type.
struct Boxes(Vec<u8>);

impl Boxes {
    fn begin(&mut self, kind: &[u8; 4]) -> usize {
        let at = self.0.len();
        self.0.extend_from_slice(&[0, 0, 0, 0]);
        self.0.extend_from_slice(kind);
        at
    }

    /// A "full box": version and 24 bits of flags after the type.
    fn begin_full(&mut self, kind: &[u8; 4], version: u8, flags: u32) -> usize {
        let at = self.begin(kind);
        self.u32(((version as u32) << 24) | (flags & 0x00ff_ffff));
        at
    }

    fn end(&mut self, at: usize) {
        let size = (self.0.len() - at) as u32;
        self.0[at..at + 4].copy_from_slice(&size.to_be_bytes());
    }

    fn u8(&mut self, v: u8) {
        self.0.push(v);
    }

    fn u16(&mut self, v: u16) {
        self.0.extend_from_slice(&v.to_be_bytes());
    }

    fn u32(&mut self, v: u32) {
        self.0.extend_from_slice(&v.to_be_bytes());
    }

    fn zeros(&mut self, n: usize) {
        self.0.resize(self.0.len() + n, 0);
    }

    fn bytes(&mut self, b: &[u8]) {
        self.0.extend_from_slice(b);
    }

    /// The unity matrix of `mvhd` and `tkhd` (16.16 and 2.30 fixed point).
    fn matrix(&mut self) {
        for v in [0x0001_0000, 0, 0, 0, 0x0001_0000, 0, 0, 0, 0x4000_0000] {
            self.u32(v);
        }
    }
}

fn ftyp() -> Vec<u8> {
    let mut b = Boxes(Vec::new());
    let at = b.begin(b"ftyp");
    b.bytes(b"isom");
    b.u32(0x200);
    for brand in [b"isom", b"iso2", b"avc1", b"mp41"] {
        b.bytes(brand);
    }
    b.end(at);
    b.0
}

/// The movie's index: `moov` with one video track, its sample tables
/// pointing at the frames stored from `chunk_offset`.
fn moov(t: &Mp4Track, chunk_offset: usize) -> Result<Vec<u8>> {
    let frames = t.sizes.len() as u64;
    let media_duration = u32::try_from(frames * FRAME_TICKS as u64)
        .map_err(|_| Error::failed("the MP4 is too long for its clock"))?;
    let movie_duration = (frames as f64 * MOVIE_TIMESCALE as f64 / t.fps).round() as u32;
    let offset =
        u32::try_from(chunk_offset).map_err(|_| Error::failed("the MP4 index is too large"))?;
    let (w, h) = (
        u16::try_from(t.width).map_err(|_| Error::failed("MP4 width too large"))?,
        u16::try_from(t.height).map_err(|_| Error::failed("MP4 height too large"))?,
    );
    let mut b = Boxes(Vec::new());
    let moov = b.begin(b"moov");
    mvhd(&mut b, movie_duration);
    let trak = b.begin(b"trak");
    tkhd(&mut b, t, movie_duration);
    let mdia = b.begin(b"mdia");
    mdhd_hdlr(&mut b, t.timescale(), media_duration);
    let minf = b.begin(b"minf");
    vmhd_dinf(&mut b);
    let stbl = b.begin(b"stbl");
    stsd(&mut b, t, w, h);
    sample_tables(&mut b, t, offset);
    b.end(stbl);
    b.end(minf);
    b.end(mdia);
    b.end(trak);
    b.end(moov);
    Ok(b.0)
}

/// The movie header: timescale, duration, unity matrix, next track ID.
fn mvhd(b: &mut Boxes, movie_duration: u32) {
    let mvhd = b.begin_full(b"mvhd", 0, 0);
    b.u32(0); // creation time: none, so the bytes are reproducible
    b.u32(0); // modification time
    b.u32(MOVIE_TIMESCALE);
    b.u32(movie_duration);
    b.u32(0x0001_0000); // rate 1.0
    b.u16(0x0100); // volume 1.0
    b.zeros(10);
    b.matrix();
    b.zeros(24); // pre_defined
    b.u32(2); // next track ID
    b.end(mvhd);
}

/// The track header: track 1, enabled, its duration and size.
fn tkhd(b: &mut Boxes, t: &Mp4Track, movie_duration: u32) {
    let tkhd = b.begin_full(b"tkhd", 0, 0x3); // enabled, in movie
    b.u32(0);
    b.u32(0);
    b.u32(1); // track ID
    b.u32(0);
    b.u32(movie_duration);
    b.zeros(8);
    b.u16(0); // layer
    b.u16(0); // alternate group
    b.u16(0); // volume (video)
    b.u16(0);
    b.matrix();
    b.u32(t.width << 16);
    b.u32(t.height << 16);
    b.end(tkhd);
}

/// The media header (timescale, duration, language) and the video handler.
fn mdhd_hdlr(b: &mut Boxes, timescale: u32, media_duration: u32) {
    let mdhd = b.begin_full(b"mdhd", 0, 0);
    b.u32(0);
    b.u32(0);
    b.u32(timescale);
    b.u32(media_duration);
    b.u16(0x55c4); // language "und"
    b.u16(0);
    b.end(mdhd);
    let hdlr = b.begin_full(b"hdlr", 0, 0);
    b.u32(0);
    b.bytes(b"vide");
    b.zeros(12);
    b.bytes(b"VideoHandler\0");
    b.end(hdlr);
}

/// The video media header and a data reference to this file.
fn vmhd_dinf(b: &mut Boxes) {
    let vmhd = b.begin_full(b"vmhd", 0, 1);
    b.zeros(8); // graphics mode, opcolor
    b.end(vmhd);
    let dinf = b.begin(b"dinf");
    let dref = b.begin_full(b"dref", 0, 0);
    b.u32(1);
    let url = b.begin_full(b"url ", 0, 1); // data in this file
    b.end(url);
    b.end(dref);
    b.end(dinf);
}

/// The sample tables: one duration for every frame, the key frames, one
/// chunk holding every sample, each sample's size, the chunk's offset.
fn sample_tables(b: &mut Boxes, t: &Mp4Track, offset: u32) {
    let frames = t.sizes.len() as u32;
    let stts = b.begin_full(b"stts", 0, 0);
    b.u32(1);
    b.u32(frames);
    b.u32(FRAME_TICKS);
    b.end(stts);
    let stss = b.begin_full(b"stss", 0, 0);
    b.u32(t.key_frames.len() as u32);
    for k in &t.key_frames {
        b.u32(k + 1);
    }
    b.end(stss);
    let stsc = b.begin_full(b"stsc", 0, 0);
    b.u32(1);
    b.u32(1); // first chunk
    b.u32(frames); // samples per chunk: all
    b.u32(1); // sample description
    b.end(stsc);
    let stsz = b.begin_full(b"stsz", 0, 0);
    b.u32(0); // sizes differ
    b.u32(frames);
    for s in &t.sizes {
        b.u32(*s);
    }
    b.end(stsz);
    let stco = b.begin_full(b"stco", 0, 0);
    b.u32(1);
    b.u32(offset);
    b.end(stco);
}

/// The sample description: an `avc1` entry with its `avcC` configuration.
fn stsd(b: &mut Boxes, t: &Mp4Track, w: u16, h: u16) {
    let stsd = b.begin_full(b"stsd", 0, 0);
    b.u32(1);
    let avc1 = b.begin(b"avc1");
    b.zeros(6);
    b.u16(1); // data reference index
    b.zeros(16); // pre_defined, reserved
    b.u16(w);
    b.u16(h);
    b.u32(0x0048_0000); // 72 dpi
    b.u32(0x0048_0000);
    b.u32(0);
    b.u16(1); // frames per sample
    let mut name = [0u8; 32];
    let label = b"H.264";
    name[0] = label.len() as u8;
    name[1..=label.len()].copy_from_slice(label);
    b.bytes(&name);
    b.u16(0x0018); // depth: colour, no alpha
    b.u16(0xffff);
    let avcc = b.begin(b"avcC");
    b.u8(1);
    b.u8(t.sps[1]); // profile
    b.u8(t.sps[2]); // constraint flags
    b.u8(t.sps[3]); // level
    b.u8(0xff); // 4-byte NAL lengths
    b.u8(0xe1); // one SPS
    b.u16(t.sps.len() as u16);
    b.bytes(&t.sps);
    b.u8(1); // one PPS
    b.u16(t.pps.len() as u16);
    b.bytes(&t.pps);
    b.end(avcc);
    b.end(avc1);
    b.end(stsd);
}

/// Splits an Annex B byte stream (NAL units after 00 00 01 or 00 00 00 01
/// start codes) into its NAL units (the form H.264 encoders hand out).
pub fn annex_b_units(stream: &[u8]) -> Vec<&[u8]> {
    let mut starts = Vec::new();
    let mut i = 0;
    while i + 3 <= stream.len() {
        if stream[i] == 0 && stream[i + 1] == 0 && stream[i + 2] == 1 {
            starts.push(i + 3);
            i += 3;
        } else {
            i += 1;
        }
    }
    let mut units = Vec::with_capacity(starts.len());
    for (k, &s) in starts.iter().enumerate() {
        let mut end = starts.get(k + 1).map_or(stream.len(), |&n| n - 3);
        // A 4-byte start code leaves a zero at the end of the unit before.
        while end > s && stream[end - 1] == 0 {
            end -= 1;
        }
        if end > s {
            units.push(&stream[s..end]);
        }
    }
    units
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splits_annex_b() {
        let s = [
            0, 0, 0, 1, 0x67, 1, 2, 0, 0, 1, 0x68, 3, 0, 0, 0, 1, 0x65, 4, 5,
        ];
        let u = annex_b_units(&s);
        assert_eq!(u, vec![&[0x67, 1, 2][..], &[0x68, 3], &[0x65, 4, 5]]);
    }

    #[test]
    fn index_comes_first_and_points_at_the_frames() {
        let mut t = Mp4Track {
            width: 64,
            height: 48,
            fps: 25.0,
            sps: vec![0x67, 0x42, 0xc0, 0x1e],
            pps: vec![0x68, 0xce],
            ..Default::default()
        };
        t.push_sample(&[0, 0, 0, 2, 0x65, 1], true);
        t.push_sample(&[0, 0, 0, 1, 0x41], false);
        let f = mp4_file(&t).unwrap();
        let moov = f.windows(4).position(|w| w == b"moov").unwrap();
        let mdat = f.windows(4).position(|w| w == b"mdat").unwrap();
        assert!(moov < mdat);
        let stco = f.windows(4).position(|w| w == b"stco").unwrap();
        let off = u32::from_be_bytes(f[stco + 12..stco + 16].try_into().unwrap()) as usize;
        assert_eq!(&f[off..off + 6], &[0, 0, 0, 2, 0x65, 1]);
        assert_eq!(f.len(), off + 11);
    }
}
