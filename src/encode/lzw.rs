//! GIF's LZW compression of one frame's palette indices (GIF89a,
//! appendix F: variable-length codes from one bit more than the minimum
//! code size up to 12 bits, least significant bit first, a clear code
//! when the table is full), written out code for code as the `gif`
//! crate's own encoder (`Frame::make_lzw_pre_encoded`, which runs the
//! `weezl` 0.1 encoder) writes it, so that every GIF stays the same byte
//! for byte; only faster: one hash table of 16 384 slots looks up a
//! code's successors instead of `weezl`'s tree of short lists and
//! 256-entry tables (`tests::same_bytes_as_the_gif_crate`).
//!
//! One quirk of that encoder is kept on purpose, since the codes depend
//! on it: a code gets up to [`SHORT`] successors into its table; when a
//! seventeenth is added it receives its code number but is not
//! recorded (the encoder turns its short list into a full table and
//! leaves the new entry out), so the next time that string is met it is
//! added again under a new number.

/// The largest code size (GIF's limit).
const MAX_CODESIZE: u32 = 12;
/// Codes in a full table: a clear code follows once the table passes it.
const MAX_ENTRIES: u32 = 1 << MAX_CODESIZE;
/// Successors a code holds before its list turns into a table (the
/// `weezl` 0.1 encoder's `SHORT`; the entry that overflows it is dropped).
const SHORT: u8 = 16;
/// A code whose successor list has turned into a full table.
const FULL: u8 = SHORT + 1;
/// Slots of the hash table: at most 4096 entries, so at most a quarter full.
const SLOT_BITS: u32 = 14;
/// An empty slot (no entry packs to it: a successor's code is always
/// larger than its prefix's, and this would need both to be 4095).
const EMPTY: u32 = u32::MAX;

/// The string table: (prefix code, next byte) → code, in open addressing;
/// a slot holds `(prefix << 8 | byte) << 12 | code`.
struct Table {
    slots: Vec<u32>,
    /// Successors recorded per prefix code (up to [`SHORT`]), or [`FULL`].
    kids: Vec<u8>,
    /// Per prefix code, the successor last found or recorded, as
    /// `byte << 16 | code` (or [`EMPTY`]): one load instead of a hash
    /// probe along a run of one colour.
    last: Vec<u32>,
}

impl Table {
    fn new() -> Self {
        Self {
            slots: vec![EMPTY; 1 << SLOT_BITS],
            kids: vec![0; MAX_ENTRIES as usize + 1],
            last: vec![EMPTY; MAX_ENTRIES as usize + 1],
        }
    }

    fn reset(&mut self) {
        self.slots.fill(EMPTY);
        self.kids.fill(0);
        self.last.fill(EMPTY);
    }

    /// The code of the string `prefix` + `byte`, if recorded: from
    /// `last` when it is the prefix's last successor, else from the hash
    /// table (and then remembered in `last`).
    #[inline(always)]
    fn lookup(&mut self, prefix: u32, byte: u32) -> Option<u32> {
        let last = self.last[prefix as usize];
        if last >> 16 == byte {
            return Some(last & 0xffff);
        }
        let code = self.find(prefix << 8 | byte)?;
        self.last[prefix as usize] = byte << 16 | code;
        Some(code)
    }

    #[inline(always)]
    fn slot(key: u32) -> usize {
        (key.wrapping_mul(0x9E37_79B1) >> (32 - SLOT_BITS)) as usize
    }

    /// The code of the string `prefix` + `byte`, if recorded.
    #[inline(always)]
    fn find(&self, key: u32) -> Option<u32> {
        let mask = (1 << SLOT_BITS) - 1;
        let mut i = Self::slot(key);
        loop {
            let s = self.slots[i];
            if s == EMPTY {
                return None;
            }
            if s >> 12 == key {
                return Some(s & 0xfff);
            }
            i = (i + 1) & mask;
        }
    }

    /// Gives the string `prefix` + `byte` (`key`) the code `code`, as the
    /// `weezl` 0.1 encoder does (the overflowing successor left out).
    fn append(&mut self, prefix: u32, key: u32, code: u32) -> bool {
        let kids = &mut self.kids[prefix as usize];
        if *kids == SHORT {
            *kids = FULL;
            return false;
        }
        if *kids != FULL {
            *kids += 1;
        }
        // Code 4096 is given out just before the table is cleared and is
        // never looked up: it is not recorded (it would not fit the slot).
        if code >= MAX_ENTRIES {
            return false;
        }
        let mask = (1 << SLOT_BITS) - 1;
        let mut i = Self::slot(key);
        while self.slots[i] != EMPTY {
            i = (i + 1) & mask;
        }
        self.slots[i] = key << 12 | code;
        self.last[prefix as usize] = (key & 0xff) << 16 | code;
        true
    }
}

/// The strings of one byte repeated ("b", "bb", "bbb", ...) that the
/// table holds, so that a run of that byte is passed over in one step
/// instead of a lookup a byte: a movie frame's indices are mostly long
/// runs of the transparent index. The lookups would find exactly these
/// codes: b^(j+1) is recorded only as the successor of b^j by b, and a
/// recorded string is never recorded again (a lookup finds it first).
struct Runs {
    /// Per byte, the codes of b, bb, bbb, ... up to the longest recorded.
    chains: Vec<Vec<u16>>,
    /// Per code, `byte << 16 | j` if it is the string of `byte` j times,
    /// else 0.
    of: Vec<u32>,
}

impl Runs {
    fn new(clear: u32) -> Self {
        let mut of = vec![0; MAX_ENTRIES as usize + 1];
        for b in 0..clear {
            of[b as usize] = b << 16 | 1;
        }
        Self {
            chains: (0..256u16).map(|b| vec![b]).collect(),
            of,
        }
    }

    /// After a clear code: the single bytes only.
    fn reset(&mut self, clear: u32) {
        for chain in &mut self.chains {
            chain.truncate(1);
        }
        self.of[clear as usize..].fill(0);
    }

    /// `code`, just recorded as `prefix` + `byte`: a longer run of
    /// `byte` if `prefix` is the longest one recorded.
    #[inline(always)]
    fn recorded(&mut self, prefix: u32, byte: u32, code: u32) {
        let chain = &mut self.chains[byte as usize];
        if self.of[prefix as usize] == byte << 16 | chain.len() as u32 {
            chain.push(code as u16);
            self.of[code as usize] = byte << 16 | chain.len() as u32;
        }
    }

    /// Where `cur` is the string of `byte` j times and `data` starts with
    /// `byte`: the code of the longest recorded run that `cur` and the
    /// bytes of `data` that follow make, and how many of those bytes it
    /// takes (none if `cur` is already the longest).
    #[inline(always)]
    fn skip(&self, cur: u32, byte: u8, data: &[u8]) -> Option<(u32, usize)> {
        let of = self.of[cur as usize];
        if of >> 16 != u32::from(byte) || of == 0 {
            return None;
        }
        let chain = &self.chains[usize::from(byte)];
        let j = (of & 0xffff) as usize;
        let room = (chain.len() - j).min(data.len());
        if room == 0 {
            return None;
        }
        let ahead = data[..room].iter().position(|&x| x != byte).unwrap_or(room);
        Some((u32::from(chain[j + ahead - 1]), ahead))
    }
}

/// Codes packed least significant bit first.
struct Bits {
    out: Vec<u8>,
    acc: u64,
    n: u32,
}

impl Bits {
    #[inline(always)]
    fn put(&mut self, code: u32, size: u32) {
        self.acc |= u64::from(code) << self.n;
        self.n += size;
        if self.n >= 32 {
            self.out.extend_from_slice(&(self.acc as u32).to_le_bytes());
            self.acc >>= 32;
            self.n -= 32;
        }
    }

    /// The last code's bits, padded with zeros to a whole byte.
    fn finish(mut self) -> Vec<u8> {
        while self.n > 0 {
            self.out.push(self.acc as u8);
            self.acc >>= 8;
            self.n = self.n.saturating_sub(8);
        }
        self.out
    }
}

/// The minimum code size byte, then the LZW codes of `data` (palette
/// indices), exactly as `gif::Frame::make_lzw_pre_encoded` leaves a frame's
/// buffer (the image data before its split into sub-blocks).
pub(crate) fn gif_lzw(data: &[u8]) -> Vec<u8> {
    let min = min_code_size(data);
    let mut bits = Bits {
        out: Vec::with_capacity(data.len() / 4 + 16),
        acc: 0,
        n: 0,
    };
    bits.out.push(min as u8);
    let clear = 1u32 << min;
    let mut size = min + 1;
    bits.put(clear, size);
    let Some((&first, rest)) = data.split_first() else {
        bits.put(clear + 1, size);
        return bits.finish();
    };
    let mut table = Table::new();
    let mut runs = Runs::new(clear);
    let mut next = clear + 2;
    let mut cur = u32::from(first);
    let mut i = 0;
    while let Some(&byte) = rest.get(i) {
        if let Some((code, taken)) = runs.skip(cur, byte, &rest[i..]) {
            cur = code;
            i += taken;
            continue;
        }
        i += 1;
        if let Some(code) = table.lookup(cur, u32::from(byte)) {
            cur = code;
            continue;
        }
        if table.append(cur, cur << 8 | u32::from(byte), next) {
            runs.recorded(cur, u32::from(byte), next);
        }
        next += 1;
        bits.put(cur, size);
        if next > 1 << size && size < MAX_CODESIZE {
            size += 1;
        }
        if next > MAX_ENTRIES {
            bits.put(clear, size);
            table.reset();
            runs.reset(clear);
            next = clear + 2;
            size = min + 1;
        }
        cur = u32::from(byte);
    }
    bits.put(cur, size);
    // The decoder adds an entry on reading this code before the end code,
    // and may widen its codes for it.
    if next >= 1 << size && size < MAX_CODESIZE {
        size += 1;
    }
    bits.put(clear + 1, size);
    bits.finish()
}

/// The `gif` crate's minimum code size for `data`: the bits of its largest
/// index (at least 2), reading no further once an index above 127 shows.
fn min_code_size(data: &[u8]) -> u32 {
    let mut max = 0u8;
    for &b in data {
        if b > max {
            max = b;
            if b > 127 {
                break;
            }
        }
    }
    (u32::from(max) + 1)
        .max(4)
        .next_power_of_two()
        .trailing_zeros()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::borrow::Cow;

    fn theirs(data: &[u8]) -> Vec<u8> {
        let mut frame = gif::Frame {
            buffer: Cow::Owned(data.to_vec()),
            ..gif::Frame::default()
        };
        frame.make_lzw_pre_encoded();
        frame.buffer.into_owned()
    }

    /// A deterministic stream of bytes (xorshift).
    fn noise(n: usize, seed: u64, modulo: u32) -> Vec<u8> {
        let mut s = seed;
        (0..n)
            .map(|_| {
                s ^= s << 13;
                s ^= s >> 7;
                s ^= s << 17;
                ((s >> 11) % u64::from(modulo)) as u8
            })
            .collect()
    }

    #[test]
    fn same_bytes_as_the_gif_crate() {
        let mut cases: Vec<Vec<u8>> = vec![
            vec![],
            vec![0],
            vec![7],
            vec![255],
            vec![3; 100_000],
            vec![255; 300_000],
        ];
        // Every palette width from 2 to 256 colours, and noise wide enough
        // to overflow the short successor lists and fill the table often.
        for (k, m) in [2u32, 3, 4, 5, 8, 16, 17, 64, 128, 129, 200, 256]
            .into_iter()
            .enumerate()
        {
            cases.push(noise(50_000, k as u64 + 1, m));
        }
        // Runs and a few colours, as a movie frame's indices are: long
        // stretches of the transparent index broken by short strokes.
        let mut frame = vec![255u8; 640 * 480];
        for (i, px) in frame.iter_mut().enumerate() {
            if (i % 640) % 97 < 5 || (i / 640) % 61 < 2 {
                *px = ((i / 7) % 43) as u8;
            }
        }
        cases.push(frame);
        for data in &cases {
            assert_eq!(gif_lzw(data), theirs(data), "{} bytes", data.len());
        }
    }

    #[test]
    fn the_overflowing_successor_is_left_out() {
        // Byte 0 followed by 17 different bytes: the seventeenth string
        // "0 x" gets a code but is not found again, so the same pair is
        // added twice; a table that kept it would write other codes.
        let mut data = Vec::new();
        for _ in 0..3 {
            for b in 1..=20u8 {
                data.extend_from_slice(&[0, b]);
            }
        }
        assert_eq!(gif_lzw(&data), theirs(&data));
    }

    /// Runs of random lengths (1 to `longest`) of bytes below `modulo`.
    fn runs_of(n: usize, seed: u64, modulo: u32, longest: u64) -> Vec<u8> {
        let mut s = seed;
        let mut rand = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s >> 11
        };
        let mut out = Vec::with_capacity(n);
        while out.len() < n {
            let byte = (rand() % u64::from(modulo)) as u8;
            let len = 1 + (rand() % longest) as usize;
            out.extend(std::iter::repeat_n(byte, len.min(n - out.len())));
        }
        out
    }

    #[test]
    fn runs_passed_over_give_the_same_codes() {
        let mut cases: Vec<Vec<u8>> = Vec::new();
        for (k, (m, longest)) in [
            (2, 3000),
            (3, 40),
            (5, 700),
            (17, 9),
            (200, 5000),
            (256, 64),
        ]
        .into_iter()
        .enumerate()
        {
            cases.push(runs_of(200_000, k as u64 + 11, m, longest));
        }
        // A run's strings with many successors: "0"^j followed by each of
        // 1..=20, so that the seventeenth successor of a run string is
        // left out and the run's chain must not take it.
        let mut many = Vec::new();
        for j in 1..60 {
            for b in 1..=20u8 {
                many.extend(std::iter::repeat_n(0u8, j));
                many.push(b);
            }
        }
        cases.push(many);
        // The transparent index broken by single strokes, every width.
        for gap in [1usize, 2, 3, 7, 64, 639, 640, 641, 5000] {
            let mut frame = vec![255u8; 307_200];
            for (i, px) in frame.iter_mut().enumerate() {
                if i % gap == 0 {
                    *px = (i % 13) as u8;
                }
            }
            cases.push(frame);
        }
        for data in &cases {
            assert_eq!(gif_lzw(data), theirs(data), "{} bytes", data.len());
        }
    }
}
