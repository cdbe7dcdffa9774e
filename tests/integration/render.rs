//! Determinism, GIF round trip, degenerate input, and atomic output.

use crate::common;

use crate::common::golden::rgba;
use crate::common::scenes::{domain_wall, kink_state, ladder, ladder_with};
use jacobs_ladder::encode::{GifWriter, TRANSPARENT_INDEX, png_bytes};

/// The colour table every movie of the program is encoded with.
fn gif_palette() -> &'static jacobs_ladder::encode::Palette {
    jacobs_ladder::render::Palette.gif()
}
use jacobs_ladder::output::{check_writable, write_atomic, write_atomic_with};
use jacobs_ladder::render::charts::{self, line_chart};
use jacobs_ladder::render::compose::filmstrip;
use jacobs_ladder::render::snapshot::{render_snapshot, render_snapshot_into};
use jacobs_ladder::render::style;
use jacobs_ladder::render::{Palette, Role};

const RED: [u8; 3] = Palette.color(Role::Series(1));
const BLUE: [u8; 3] = Palette.color(Role::Series(2));
use jacobs_ladder::render::{
    Axis, ChartSpec, FilmstripOptions, Frame, Kymograph, Series, Snapshot, View,
};
use jacobs_ladder::{Error, model::Ladder};
use tiny_skia::Pixmap;

/// Frames of a kink sweeping through the ladder, fixed window, time label.
fn sweep(l: &Ladder, frames: usize, w: u32, h: u32) -> Vec<Pixmap> {
    let view = View::fit(&[&l.ground_state()]);
    (0..frames)
        .map(|k| {
            let wall = 11.0 * k as f64 / (frames - 1).max(1) as f64;
            let q = kink_state(l, wall);
            let snap = Snapshot::new(l, &q)
                .unwrap()
                .with_view(view)
                .with_time(10.0 * k as f64);
            render_snapshot(&crate::common::screen(), &snap, w, h).unwrap()
        })
        .collect()
}

fn gif_of(frames: &[Pixmap], fps: f64) -> Vec<u8> {
    let mut g = GifWriter::new(frames[0].width(), frames[0].height(), fps, gif_palette()).unwrap();
    for f in frames {
        g.push_frame(f).unwrap();
    }
    g.finish().unwrap()
}

#[test]
fn same_input_gives_identical_bytes() {
    let l = ladder(60.0);
    let (a, b) = (sweep(&l, 5, 160, 240), sweep(&l, 5, 160, 240));
    assert_eq!(png_bytes(&a[2]).unwrap(), png_bytes(&b[2]).unwrap());
    assert_eq!(gif_of(&a, 12.0), gif_of(&b, 12.0));
    let (t, v) = domain_wall(10, 50, 100.0);
    let k = Kymograph::new(&t, &v, 10);
    let (k1, k2) = (
        charts::kymograph(&crate::common::screen(), &k, 300, 240).unwrap(),
        charts::kymograph(&crate::common::screen(), &k, 300, 240).unwrap(),
    );
    assert_eq!(k1.svg, k2.svg);
    assert_eq!(
        png_bytes(&k1.pixmap).unwrap(),
        png_bytes(&k2.pixmap).unwrap()
    );
}

#[test]
fn gif_round_trip() {
    let l = ladder(60.0);
    let frames = sweep(&l, 12, 200, 300);
    let bytes = gif_of(&frames, 30.0);
    let common::gif::GifFrames {
        width: w,
        height: h,
        frames: decoded,
        delays,
    } = common::gif::decode(&bytes);
    assert_eq!((w, h), (200, 300));
    assert_eq!(decoded.len(), 12);
    assert_eq!(delays.iter().map(|&d| d as u32).sum::<u32>(), 40); // 12 frames at 30 fps = 0.4 s
    assert!(delays.iter().all(|&d| d == 3 || d == 4));
    for (orig, got) in frames.iter().zip(&decoded) {
        let o = rgba(orig);
        let errs: Vec<u8> = o
            .chunks_exact(4)
            .zip(got.chunks_exact(3))
            .map(|(a, b)| (0..3).map(|k| a[k].abs_diff(b[k])).max().unwrap())
            .collect();
        let mean = errs.iter().map(|&e| e as f64).sum::<f64>() / errs.len() as f64;
        let big = errs.iter().filter(|&&e| e > 24).count();
        assert!(mean < 1.0, "mean colour error {mean}");
        assert!(big * 200 < errs.len(), "{big} pixels off by more than 24");
    }
}

#[test]
fn scene_colours_are_exact_in_the_gif_palette() {
    let p = gif_palette();
    let roles = [
        Role::Paper,
        Role::Ink,
        Role::SpringA,
        Role::SpringB,
        Role::Series(3),
        Role::Ground,
        Role::Negative,
        Role::Positive,
    ];
    for c in roles.map(|r| Palette.color(r)) {
        assert_eq!(p.color(p.index(c)), c, "{c:?}");
        assert_ne!(p.index(c), TRANSPARENT_INDEX);
    }
    // Kymograph colours and anti-aliased edges on white lie on ramps.
    for v in [-0.8, -0.3, 0.2, 0.9] {
        let c = style::diverging(v);
        let got = p.color(p.index(c));
        assert!(
            (0..3).all(|k| got[k].abs_diff(c[k]) <= 10),
            "{c:?} -> {got:?}"
        );
    }
}

#[test]
fn unchanged_frames_still_count() {
    let l = ladder(60.0);
    let f = sweep(&l, 1, 100, 120).remove(0);
    let bytes = gif_of(&[f.clone(), f.clone(), f], 10.0);
    let common::gif::GifFrames { frames, delays, .. } = common::gif::decode(&bytes);
    assert_eq!(frames.len(), 3);
    assert_eq!(delays, vec![10, 10, 10]);
    assert_eq!(frames[0], frames[2]);
}

#[test]
fn gif_rejects_bad_sizes_and_fps() {
    assert!(matches!(
        GifWriter::new(0, 10, 10.0, gif_palette()),
        Err(Error::BadInput(_))
    ));
    assert!(matches!(
        GifWriter::new(10, 10, f64::NAN, gif_palette()),
        Err(Error::BadInput(_))
    ));
    let mut g = GifWriter::new(10, 10, 10.0, gif_palette()).unwrap();
    let wrong = Pixmap::new(5, 5).unwrap();
    assert!(matches!(g.push_frame(&wrong), Err(Error::BadInput(_))));
    assert!(g.finish().is_err());
}

#[test]
fn degenerate_legal_input_renders() {
    for (n, alpha) in [
        (2, 60.0),
        (10, 0.5),
        (10, -0.5),
        (10, 89.9),
        (10, -89.9),
        (10, 0.0),
        (10, 90.0),
        (2, 90.0),
    ] {
        let l = ladder_with(n, 1.3, alpha);
        let g = l.ground_state();
        let q = kink_state(&l, 1.5);
        let snap = Snapshot::new(&l, &q)
            .unwrap()
            .with_ghost(&l, &g)
            .unwrap()
            .with_time(0.25)
            .with_title("t");
        let p = render_snapshot(&crate::common::screen(), &snap, 64, 64).unwrap();
        assert!(
            p.pixels().iter().any(|c| c.red() < 128),
            "N={n} α={alpha}: nothing drawn"
        );
        let frames = [Frame { time: 0.0, q: &g }, Frame { time: 1.0, q: &q }];
        filmstrip(
            &crate::common::screen(),
            &l,
            &frames,
            &FilmstripOptions::default(),
        )
        .unwrap();
    }
    // Tiny frames, NaN states, degenerate windows: no panic.
    let l = ladder(60.0);
    let mut q = l.ground_state();
    q[5] = f64::NAN;
    let snap = Snapshot::new(&l, &q)
        .unwrap()
        .with_view(View::window((1.0, 1.0), (0.0, 0.0)));
    render_snapshot(&crate::common::screen(), &snap, 1, 1).unwrap();
    let mut p = Pixmap::new(3, 3).unwrap();
    render_snapshot_into(
        &crate::common::screen(),
        &mut p,
        &Snapshot::new(&l, &q).unwrap(),
    );
    assert!(render_snapshot(&crate::common::screen(), &snap, 0, 10).is_err());
    assert!(Snapshot::new(&l, &q[..6]).is_err());
}

#[test]
fn degenerate_charts_render() {
    let one = ChartSpec::new(Axis::new("x"), Axis::new("y")).series(Series::line(
        "p",
        vec![(1.0, 1.0)],
        RED,
    ));
    line_chart(&crate::common::screen(), &one, 200, 150).unwrap();
    let empty = ChartSpec::new(Axis::new("x").log(), Axis::new("y").log());
    line_chart(&crate::common::screen(), &empty, 200, 150).unwrap();
    let bad = ChartSpec::new(Axis::new("x"), Axis::new("y").log()).series(Series::line(
        "z",
        vec![(0.0, 0.0), (1.0, f64::NAN), (2.0, -1.0), (3.0, 1e-3)],
        BLUE,
    ));
    line_chart(&crate::common::screen(), &bad, 200, 150).unwrap();
    let flat = ChartSpec::new(Axis::new("x"), Axis::new("y")).series(Series::line(
        "c",
        vec![(0.0, 2.0), (0.0, 2.0)],
        RED,
    ));
    let mut flat = flat;
    flat.equal_aspect = true;
    line_chart(&crate::common::screen(), &flat, 200, 150).unwrap();
    let fixed = ChartSpec::new(Axis::new("x").range(1.0, 0.0), Axis::new("y"));
    assert!(matches!(
        line_chart(&crate::common::screen(), &fixed, 200, 150),
        Err(Error::BadInput(_))
    ));
    let (t, v) = (vec![5.0], vec![0.3, f64::NAN]);
    charts::kymograph(
        &crate::common::screen(),
        &Kymograph::new(&t, &v, 2),
        200,
        150,
    )
    .unwrap();
    assert!(
        charts::kymograph(
            &crate::common::screen(),
            &Kymograph::new(&t, &v, 3),
            200,
            150
        )
        .is_err()
    );
}

fn one_line(e: &Error) -> String {
    let msg = e.to_string();
    assert!(!msg.contains('\n'), "not one line: {msg:?}");
    msg
}

#[test]
fn unwritable_folder_is_bad_input() {
    let e = write_atomic(std::path::Path::new("/proc/ladder-test/out.png"), b"x").unwrap_err();
    assert!(matches!(e, Error::BadInput(_)));
    assert!(one_line(&e).contains("/proc/ladder-test"), "{e}");

    let dir = tempdir("parent-file");
    let file = dir.join("plain");
    std::fs::write(&file, b"x").unwrap();
    let e = write_atomic(&file.join("sub").join("a.gif"), b"x").unwrap_err();
    assert!(matches!(e, Error::BadInput(_)));
    let msg = one_line(&e);
    assert!(
        msg.starts_with("cannot write to ") && msg.contains("plain"),
        "{msg}"
    );
    let e = check_writable(&file.join("x.png")).unwrap_err();
    assert!(matches!(e, Error::BadInput(_)));
    one_line(&e);
    check_writable(&dir.join("new").join("x.png")).unwrap();
}

#[test]
fn failure_half_way_leaves_no_file() {
    let dir = tempdir("half-way");
    let path = dir.join("movie.gif");
    let e = write_atomic_with(&path, |f| {
        use std::io::Write;
        f.write_all(b"GIF89a partial")?;
        Err(std::io::Error::other("encoder stopped"))
    })
    .unwrap_err();
    // Not the user's mistake: a failed run (exit 1).
    assert!(matches!(e, Error::Failed(_)), "{e:?}");
    one_line(&e);
    assert!(!path.exists());
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        0,
        "temporary file left behind"
    );
    // A good write replaces atomically and creates missing folders.
    let nested = dir.join("a").join("b").join("x.png");
    write_atomic(&nested, b"ok").unwrap();
    assert_eq!(std::fs::read(&nested).unwrap(), b"ok");
}

/// A folder for one test, removed when the test ends.
fn tempdir(name: &str) -> common::tempdir::TempDir {
    common::tempdir::TempDir::new(&format!("render-{name}"))
}

/// The `<text>` elements of a chart's SVG: left and right ends in pixels
/// (from `x`, `text-anchor` and `font-size`) and the content.
fn svg_text_extents(svg: &str) -> Vec<(f32, f32, String)> {
    let attr = |tag: &str, name: &str| {
        let key = format!(" {name}=\"");
        let start = tag.find(&key)? + key.len();
        Some(tag[start..start + tag[start..].find('"')?].to_string())
    };
    let mut out = Vec::new();
    for piece in svg.split("<text").skip(1) {
        let (tag, rest) = piece.split_once('>').unwrap();
        let content = rest.split("</text>").next().unwrap().trim().to_string();
        let x: f32 = attr(tag, "x").unwrap().parse().unwrap();
        let size: f32 = attr(tag, "font-size").unwrap().parse().unwrap();
        let w = style::text_width(crate::common::screen().font(), &content, size);
        let left = match attr(tag, "text-anchor").as_deref() {
            Some("middle") => x - w / 2.0,
            Some("end") => x - w,
            _ => x,
        };
        out.push((left, left + w, content));
    }
    out
}

/// Movie 3's long title fits the kymograph's width (it was clipped at
/// 480 px, the kymograph's smallest movie size), also when narrow.
#[test]
fn kymograph_title_fits_the_width() {
    use jacobs_ladder::catalog;
    use jacobs_ladder::scene::{Kind, describe};
    let scene = &catalog::find(Kind::Movie, "3").unwrap().scene;
    let title = format!("{}: sin θₙ", describe::title(scene));
    let (t, v) = (vec![0.0, 1.0], vec![0.5; 20]);
    let mut k = Kymograph::new(&t, &v, 10);
    k.title = Some(&title);
    for (w, h) in [(480, 360), (320, 240), (200, 150), (60, 60)] {
        let chart = charts::kymograph(&crate::common::screen(), &k, w, h).unwrap();
        // The title's lines are drawn first, above everything else.
        let texts = svg_text_extents(&chart.svg);
        let lines = (1..=3)
            .map(|n| &texts[..n])
            .find(|l| l.iter().map(|t| t.2.as_str()).collect::<Vec<_>>().join(" ") == title)
            .unwrap_or_else(|| panic!("{w}x{h}: the title's lines come first: {texts:?}"));
        for (left, right, content) in lines {
            assert!(
                *left >= 0.0 && *right <= w as f32,
                "{w}x{h}: title line {content:?} spans {left:.1}..{right:.1}"
            );
        }
    }
}
