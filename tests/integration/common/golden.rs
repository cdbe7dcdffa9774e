//! Golden-image comparison.
//!
//! `check(name, &pixmap)` compares with `tests/golden/NAME.png`: every
//! channel may differ by at most `TOLERANCE`, except for a fraction
//! `OUTLIER_FRACTION` of the pixels. `LADDER_BLESS=1` (re)writes the
//! reference instead, and says (uncaptured) which image it wrote and that
//! it must be looked at; under CI blessing is refused (the test fails).
//! On a mismatch, expected | difference | actual is written side by side
//! to `target/golden-diffs/NAME.png` and the panic message names it.

use jacobs_ladder::encode::png_bytes;
use std::path::PathBuf;
use tiny_skia::Pixmap;

/// Largest per-channel difference, in 1/255 steps.
pub const TOLERANCE: u8 = 2;
/// Fraction of pixels allowed to differ by more.
pub const OUTLIER_FRACTION: f64 = 0.001;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Path of the reference image `NAME.png`.
pub fn golden_path(name: &str) -> PathBuf {
    root()
        .join("tests")
        .join("golden")
        .join(format!("{name}.png"))
}

fn blessing() -> bool {
    std::env::var("LADDER_BLESS").is_ok_and(|v| v == "1")
}

/// Straight RGBA bytes of a pixmap (demultiplied).
pub fn rgba(p: &Pixmap) -> Vec<u8> {
    p.pixels()
        .iter()
        .flat_map(|c| {
            let c = c.demultiply();
            [c.red(), c.green(), c.blue(), c.alpha()]
        })
        .collect()
}

/// Compares `actual` with the reference `name`, or blesses it.
pub fn check(name: &str, actual: &Pixmap) {
    let path = golden_path(name);
    if blessing() {
        assert!(
            !super::require::strict(),
            "golden {name}: LADDER_BLESS=1 is refused under CI: a reference image is \
             written by a person who looked at it, never by CI"
        );
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, png_bytes(actual).unwrap()).unwrap();
        super::require::note(&format!(
            "BLESSED golden {name}: wrote {}; LOOK AT IT (open the PNG) before committing it",
            path.display()
        ));
        return;
    }
    let (ew, eh, exp) = match super::pngio::read_rgba8(&path) {
        Ok(img) => img,
        Err(e) => panic!(
            "golden image {} missing or unreadable ({e}); run with LADDER_BLESS=1 to create it",
            path.display()
        ),
    };
    let (w, h) = (actual.width(), actual.height());
    let act = rgba(actual);
    if (ew, eh) != (w, h) {
        write_diff(name, &exp, (ew, eh), &act, (w, h));
        panic!(
            "golden {name}: size {w}x{h} differs from the reference {ew}x{eh}; \
             expected | difference | actual side by side: {}",
            diff_path(name).display()
        );
    }
    let bad = exp
        .chunks_exact(4)
        .zip(act.chunks_exact(4))
        .filter(|(e, a)| {
            e.iter()
                .zip(a.iter())
                .any(|(x, y)| x.abs_diff(*y) > TOLERANCE)
        })
        .count();
    let allowed = (OUTLIER_FRACTION * (w * h) as f64).floor() as usize;
    if bad > allowed {
        let diff = write_diff(name, &exp, (w, h), &act, (w, h));
        panic!(
            "golden {name}: {bad} pixels differ by more than {TOLERANCE}/255 (allowed {allowed}); \
             expected | difference (red: beyond tolerance) | actual side by side: {}",
            diff.display()
        );
    }
}

/// Writes expected | difference | actual to target/golden-diffs/NAME.png.
fn write_diff(
    name: &str,
    exp: &[u8],
    (ew, eh): (u32, u32),
    act: &[u8],
    (aw, ah): (u32, u32),
) -> PathBuf {
    let (cw, ch) = (ew.max(aw), eh.max(ah));
    let ow = 3 * cw + 8;
    let mut out: Vec<u8> = [255, 0, 255, 255].repeat((ow * ch) as usize);
    let mut put = |x: u32, y: u32, c: [u8; 4]| {
        let i = 4 * (y * ow + x) as usize;
        out[i..i + 4].copy_from_slice(&c);
    };
    let px = |buf: &[u8], w: u32, x: u32, y: u32| {
        let i = 4 * (y * w + x) as usize;
        [buf[i], buf[i + 1], buf[i + 2], buf[i + 3]]
    };
    for y in 0..ch {
        for x in 0..cw {
            let e = (x < ew && y < eh).then(|| px(exp, ew, x, y));
            let a = (x < aw && y < ah).then(|| px(act, aw, x, y));
            if let Some(e) = e {
                put(x, y, e);
            }
            if let Some(a) = a {
                put(2 * cw + 8 + x, y, a);
            }
            let d = match (e, a) {
                (Some(e), Some(a)) => {
                    let m = (0..3).map(|k| e[k].abs_diff(a[k])).max().unwrap_or(0);
                    if m > TOLERANCE {
                        [255, 255 - m.saturating_mul(4), 0, 255]
                    } else {
                        [m * 20, m * 20, m * 20, 255]
                    }
                }
                _ => [255, 0, 255, 255],
            };
            put(cw + 4 + x, y, d);
        }
    }
    let path = diff_path(name);
    let _ = std::fs::create_dir_all(path.parent().unwrap());
    let _ = std::fs::write(&path, super::pngio::encode_rgba8(ow, ch, &out));
    path
}

/// Where expected | difference | actual of `name` is written on a mismatch.
pub fn diff_path(name: &str) -> PathBuf {
    root()
        .join("target")
        .join("golden-diffs")
        .join(format!("{name}.png"))
}
