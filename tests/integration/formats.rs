//! Output formats (docs/formats.md): every figure as PNG, SVG and PDF that
//! look alike; PDFs that hold vector drawing and no page-sized raster; MP4s
//! that an independent reader parses and that decode back to the GIF's
//! frames; movie layouts that scale with the frame.
//!
//! `LADDER_FORMATS_DIR=DIR` also writes every file made here to DIR for
//! inspection (`pdftoppm`, a browser, a video player).

#[cfg(feature = "mp4")]
use crate::common;

use crate::common::golden::check;
use jacobs_ladder::catalog;
use jacobs_ladder::encode;
use jacobs_ladder::render::Picture;
use jacobs_ladder::scene;
use jacobs_ladder::scenes;
use std::sync::OnceLock;
use tiny_skia::Pixmap;

fn dump(name: &str, bytes: &[u8]) {
    if let Ok(dir) = std::env::var("LADDER_FORMATS_DIR") {
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(format!("{dir}/{name}"), bytes).unwrap();
    }
}

/// Every figure of the catalogue, drawn once (shared by the tests).
fn figures() -> &'static [(String, Picture)] {
    static ALL: OnceLock<Vec<(String, Picture)>> = OnceLock::new();
    ALL.get_or_init(|| {
        let entries = catalog::entries(scene::Kind::Figure).unwrap();
        // The sweep figures (charts of many runs) are checked by
        // `sweep_chart_in_every_format` below, on a small grid.
        let all: Vec<(String, Picture)> = entries
            .iter()
            .filter(|e| !matches!(e.scene.output, scene::OutputSpec::Sweep(_)))
            .map(|e| {
                let (p, _) = scenes::figure_picture(&crate::common::screen(), &e.scene)
                    .unwrap_or_else(|err| panic!("{}: {err}", e.id));
                (e.scene.stem(), p)
            })
            .collect();
        assert_eq!(all.len(), 19, "every figure of the catalogue");
        all
    })
}

/// Rasterises SVG bytes (text already outlines: no fonts given) onto white.
fn rasterize_svg_file(svg: &[u8], width: u32, height: u32) -> Pixmap {
    let tree = resvg::usvg::Tree::from_data(svg, &resvg::usvg::Options::default()).unwrap();
    let mut p = Pixmap::new(width, height).unwrap();
    p.fill(tiny_skia::Color::WHITE);
    let s = tree.size();
    let t = tiny_skia::Transform::from_scale(width as f32 / s.width(), height as f32 / s.height());
    resvg::render(&tree, t, &mut p.as_mut());
    p
}

/// Mean absolute difference per channel (0–255) and the fraction of pixels
/// where some channel differs by more than `big`.
fn difference(a: &Pixmap, b: &Pixmap, big: u8) -> (f64, f64) {
    assert_eq!((a.width(), a.height()), (b.width(), b.height()));
    let (mut sum, mut bad) = (0u64, 0usize);
    for (p, q) in a.data().chunks_exact(4).zip(b.data().chunks_exact(4)) {
        let d: Vec<u8> = (0..3).map(|k| p[k].abs_diff(q[k])).collect();
        sum += d.iter().map(|&v| v as u64).sum::<u64>();
        if d.iter().any(|&v| v > big) {
            bad += 1;
        }
    }
    let n = (a.width() * a.height()) as f64;
    (sum as f64 / (3.0 * n), bad as f64 / n)
}

#[test]
fn svg_of_every_figure_matches_its_png() {
    for (name, pic) in figures() {
        let png = pic.to_pixmap().unwrap();
        let tree = pic.to_tree(1.0).unwrap();
        let svg = encode::svg_bytes(&tree);
        assert!(
            !String::from_utf8_lossy(&svg).contains("<text"),
            "{name}: SVG text should be outlines"
        );
        dump(&format!("{name}.svg"), &svg);
        dump(&format!("{name}.png"), &encode::png_bytes(&png).unwrap());
        let back = rasterize_svg_file(&svg, png.width(), png.height());
        dump(
            &format!("{name}-from-svg.png"),
            &encode::png_bytes(&back).unwrap(),
        );
        let (mean, frac) = difference(&png, &back, 64);
        eprintln!(
            "{name}: mean {mean:.3}, {:.3} % of pixels off by > 64",
            100.0 * frac
        );
        assert!(
            mean < 1.0 && frac < 0.01,
            "{name}: mean {mean}, fraction {frac}"
        );
    }
}

/// Operators of a PDF content stream, in order.
fn pdf_operators(doc: &lopdf::Document) -> Vec<String> {
    let mut ops = Vec::new();
    for (_, page) in doc.get_pages() {
        let content = doc.get_page_content(page);
        let parsed = lopdf::content::Content::decode(&content).expect("content parses");
        ops.extend(parsed.operations.into_iter().map(|o| o.operator));
    }
    ops
}

#[test]
fn pdf_of_every_figure_is_vector() {
    for (name, pic) in figures() {
        let tree = pic.to_tree(1.0).unwrap();
        let pdf = encode::pdf_bytes(
            &tree,
            encode::PdfOptions {
                real_text: false,
                ..Default::default()
            },
        )
        .unwrap();
        dump(&format!("{name}.pdf"), &pdf);
        assert!(pdf.starts_with(b"%PDF-1."), "{name}");
        let doc = lopdf::Document::load_mem(&pdf).unwrap();
        assert_eq!(doc.get_pages().len(), 1, "{name}");
        let ops = pdf_operators(&doc);
        let count = |op: &str| ops.iter().filter(|o| *o == op).count();
        // Paths (m, l, c), fills (f) and strokes (S): the drawing is vector.
        assert!(
            count("m") > 100 && count("l") > 100,
            "{name}: too few path operators"
        );
        assert!(count("c") > 100, "{name}: no curves (glyph outlines)");
        assert!(
            count("f") >= 10 && count("S") >= 10,
            "{name}: fills {} strokes {}",
            count("f"),
            count("S")
        );
        // Text is glyph outlines (the curves above), so no font is needed:
        // no text objects, no font resources.
        assert_eq!(count("BT") + count("Tj") + count("TJ"), 0, "{name}: text");
        for (_, obj) in doc.objects.iter() {
            if let Ok(d) = obj.as_dict() {
                assert!(d.get(b"Font").is_err(), "{name}: font resource");
            }
        }
        // No images at all: nothing is drawn as a raster (`Do` paints XObjects).
        assert_eq!(count("Do"), 0, "{name}: draws an XObject");
        assert_eq!(count("BI"), 0, "{name}: has an inline image");
        for (_, obj) in doc.objects.iter() {
            if let Ok(stream) = obj.as_stream() {
                let subtype = stream.dict.get(b"Subtype").and_then(|s| s.as_name()).ok();
                assert!(
                    subtype != Some(b"Image".as_slice()),
                    "{name}: image XObject"
                );
            }
        }
        // The page is the picture's size at 96 px per inch.
        let (_, page) = doc.get_pages().into_iter().next().unwrap();
        let media = doc
            .get_dictionary(page)
            .unwrap()
            .get(b"MediaBox")
            .unwrap()
            .as_array()
            .unwrap()
            .clone();
        let w = media[2].as_float().unwrap();
        assert!((w - 0.75 * pic.width()).abs() < 0.01, "{name}: width {w}");
    }
}

// ---------------------------------------------------------------- movies

fn movie_scene(id: &str) -> scene::Scene {
    catalog::find(scene::Kind::Movie, id).unwrap().scene.clone()
}

#[cfg(feature = "mp4")]
/// The top-level boxes of an MP4: (type, offset, size).
fn top_boxes(bytes: &[u8]) -> Vec<(String, usize, usize)> {
    let mut out = Vec::new();
    let mut at = 0;
    while at + 8 <= bytes.len() {
        let size = u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap()) as usize;
        let kind = String::from_utf8_lossy(&bytes[at + 4..at + 8]).into_owned();
        assert!(size >= 8 && at + size <= bytes.len(), "box {kind} at {at}");
        out.push((kind, at, size));
        at += size;
    }
    assert_eq!(at, bytes.len(), "boxes cover the file");
    out
}

#[cfg(feature = "mp4")]
#[test]
fn mp4_is_index_first_h264_and_shows_the_gif_frames() {
    use jacobs_ladder::encode::Format;
    use openh264::formats::YUVSource;
    let scene = movie_scene("4");
    let opts = scenes::MovieOptions {
        frames: 24,
        width: 320,
        height: 240,
        fps: 12.0,
    };
    let (movies, _, _) = scenes::dynamic::movie(
        &crate::common::screen(),
        &scene,
        &opts,
        &[Format::Gif, Format::Mp4],
        &|| {},
    )
    .unwrap();
    let (gif, mp4) = (&movies[0].1, &movies[1].1);
    assert_eq!((movies[0].0, movies[1].0), (Format::Gif, Format::Mp4));
    dump("movie-4.mp4", mp4);
    dump("movie-4.gif", gif);

    // Container, read by an independent parser.
    let kinds: Vec<String> = top_boxes(mp4).into_iter().map(|b| b.0).collect();
    assert_eq!(
        kinds,
        ["ftyp", "moov", "mdat"],
        "the index comes before the frames"
    );
    let mut reader =
        mp4::Mp4Reader::read_header(std::io::Cursor::new(mp4.as_slice()), mp4.len() as u64)
            .unwrap();
    assert_eq!(reader.tracks().len(), 1);
    let track = reader.tracks().values().next().unwrap();
    let id = track.track_id();
    assert_eq!(track.media_type().unwrap(), mp4::MediaType::H264);
    assert_eq!((track.width(), track.height()), (320, 240));
    assert_eq!(track.sample_count(), 24);
    assert!(
        (track.frame_rate() - 12.0).abs() < 1e-6,
        "{}",
        track.frame_rate()
    );
    assert!((reader.duration().as_secs_f64() - 2.0).abs() < 0.01);
    let sps = track.sequence_parameter_set().unwrap().to_vec();
    let pps = track.picture_parameter_set().unwrap().to_vec();

    // Decoded back with OpenH264's decoder: frame k is the GIF's frame k.
    let common::gif::GifFrames {
        width: gw,
        height: gh,
        frames: gif_rgb,
        ..
    } = common::gif::decode(gif);
    assert_eq!((gw, gh, gif_rgb.len()), (320, 240, 24));
    let mut decoder = openh264::decoder::Decoder::new().unwrap();
    let start = |v: &mut Vec<u8>, nal: &[u8]| {
        v.extend_from_slice(&[0, 0, 0, 1]);
        v.extend_from_slice(nal);
    };
    let mut head = Vec::new();
    start(&mut head, &sps);
    start(&mut head, &pps);
    let _ = decoder.decode(&head);
    let mut total = 0usize;
    for k in 0..24u32 {
        let sample = reader.read_sample(id, k + 1).unwrap().unwrap();
        assert_eq!(
            sample.is_sync,
            k == 0,
            "key frames: the first only (5 s period)"
        );
        assert_eq!(sample.duration, 1000, "constant frame duration");
        total += sample.bytes.len();
        let mut annex_b = Vec::new();
        let mut rest = &sample.bytes[..];
        while rest.len() >= 4 {
            let n = u32::from_be_bytes(rest[..4].try_into().unwrap()) as usize;
            start(&mut annex_b, &rest[4..4 + n]);
            rest = &rest[4 + n..];
        }
        assert!(rest.is_empty(), "sample {k} is whole NAL units");
        let yuv = decoder
            .decode(&annex_b)
            .unwrap()
            .unwrap_or_else(|| panic!("frame {k} decodes"));
        let (w, h) = yuv.dimensions();
        assert_eq!((w, h), (320, 240));
        let ours = common::h264::packed(&yuv);
        let rgb = ours.to_rgb();
        if k == 16 {
            let rgba: Vec<u8> = rgb
                .chunks_exact(3)
                .flat_map(|c| [c[0], c[1], c[2], 255])
                .collect();
            let png = common::pngio::encode_rgba8(w as u32, h as u32, &rgba);
            dump("movie-4-mp4-frame-16.png", &png);
        }
        let p = common::gif::psnr(&rgb, &gif_rgb[k as usize]);
        assert!(p >= 30.0, "frame {k}: PSNR {p:.1} dB");
        if k % 8 == 0 {
            eprintln!("frame {k}: PSNR {p:.1} dB against the GIF");
        }
    }
    let mdat = top_boxes(mp4).into_iter().find(|b| b.0 == "mdat").unwrap();
    assert_eq!(total, mdat.2 - 8, "the samples fill mdat");
}

#[test]
fn movie_layout_scales_with_the_frame() {
    let scene = movie_scene("4");
    let frame = |w: u32, h: u32| {
        let opts = scenes::MovieOptions {
            frames: 10,
            width: w,
            height: h,
            fps: 10.0,
        };
        scenes::dynamic::movie_frame(&crate::common::screen(), &scene, &opts, 6).unwrap()
    };
    let small = frame(640, 360);
    let big = frame(1920, 1080);
    dump("frame-640x360.png", &encode::png_bytes(&small).unwrap());
    dump("frame-1920x1080.png", &encode::png_bytes(&big).unwrap());
    // 3 × 3 box average of the big frame.
    let mut down = Pixmap::new(640, 360).unwrap();
    {
        let (src, dst) = (big.data(), down.data_mut());
        for y in 0..360 {
            for x in 0..640 {
                for c in 0..4 {
                    let mut s = 0u32;
                    for dy in 0..3 {
                        for dx in 0..3 {
                            s += src[4 * ((3 * y + dy) * 1920 + 3 * x + dx) + c] as u32;
                        }
                    }
                    dst[4 * (y * 640 + x) + c] = ((s + 4) / 9) as u8;
                }
            }
        }
    }
    dump(
        "frame-1920x1080-down.png",
        &encode::png_bytes(&down).unwrap(),
    );
    let (mean, frac) = difference(&small, &down, 96);
    eprintln!(
        "1920x1080 scaled down vs 640x360: mean {mean:.2}, {:.2} % off by > 96",
        100.0 * frac
    );
    assert!(mean < 3.0 && frac < 0.02, "mean {mean}, fraction {frac}");
}

#[test]
fn nothing_is_cut_from_320x240_to_3840x2160() {
    // Movie 4 (fixed camera), 3 (following camera, lab scale), 11 (two
    // flips).
    for (id, (w, h)) in ["4", "3", "11"]
        .into_iter()
        .flat_map(|id| MOVIE_SIZES[..7].iter().map(move |&s| (id, s)))
    {
        let scene = movie_scene(id);
        let opts = scenes::MovieOptions {
            frames: 4,
            width: w,
            height: h,
            fps: 10.0,
        };
        let f = scenes::dynamic::movie_frame(&crate::common::screen(), &scene, &opts, 3).unwrap();
        let (w, h) = (f.width(), f.height());
        // The outermost rows and columns stay white: no text or ladder runs
        // off the frame.
        let px = |x: u32, y: u32| {
            let i = 4 * (y * w + x) as usize;
            [f.data()[i], f.data()[i + 1], f.data()[i + 2]]
        };
        let edge = (w as f32 / 320.0).ceil() as u32;
        for x in 0..w {
            for y in (0..edge).chain(h - edge..h) {
                assert_eq!(px(x, y), [255; 3], "{w}x{h}: ink at ({x}, {y})");
            }
        }
        for y in 0..h {
            for x in (0..edge).chain(w - edge..w) {
                assert_eq!(px(x, y), [255; 3], "{w}x{h}: ink at ({x}, {y})");
            }
        }
        if w == 320 || w == 480 || w == 3840 {
            dump(
                &format!("movie-{id}-frame-{w}x{h}.png"),
                &encode::png_bytes(&f).unwrap(),
            );
        }
    }
}

/// Frame sizes from the smallest a talk might use to 4K, and the extremes
/// `--size` takes (64 to 4096 each way).
const MOVIE_SIZES: [(u32, u32); 9] = [
    (320, 240),
    (640, 360),
    (640, 480),
    (1280, 720),
    (1920, 1080),
    (3840, 2160),
    (480, 1080),
    (64, 64),
    (4096, 64),
];

#[test]
fn movie_texts_and_panels_lie_inside_the_frame_at_every_size() {
    use jacobs_ladder::render::snapshot::time_label;
    use jacobs_ladder::render::{MovieLayout, Region};
    const EPS: f32 = 1e-3;
    let inside = |a: Region, b: Region| {
        a.x >= b.x - EPS
            && a.y >= b.y - EPS
            && a.x + a.w <= b.x + b.w + EPS
            && a.y + a.h <= b.y + b.h + EPS
    };
    let apart = |a: Region, b: Region| {
        a.x + a.w <= b.x + EPS
            || b.x + b.w <= a.x + EPS
            || a.y + a.h <= b.y + EPS
            || b.y + b.h <= a.y + EPS
    };
    let movies = catalog::entries(scene::Kind::Movie).unwrap();
    assert_eq!(movies.len(), 14);
    // A title longer than any frame is shrunk to fit, not cut.
    let long = "A title much longer than any movie frame could show at the size of \
                the catalogue's titles, written by a user of `ladder render`";
    for (w, h) in MOVIE_SIZES {
        for e in &movies {
            for title in [scene::describe::title(&e.scene), long.to_string()] {
                let n = e.scene.model.n;
                let t_end = e.scene.run.t_end;
                let l = MovieLayout::new(&crate::common::screen(), w, h, n);
                let what = format!("movie {} at {w}x{h}", e.id);
                let frame = Region {
                    x: 0.0,
                    y: 0.0,
                    w: l.design.0,
                    h: l.design.1,
                };
                // The design frame is the pixel frame, scaled.
                assert!((l.design.0 * l.scale - w as f32).abs() < 0.01, "{what}");
                assert!((l.design.1 * l.scale - h as f32).abs() < 0.01, "{what}");
                assert!(inside(l.ladder, frame), "{what}: ladder {:?}", l.ladder);
                assert!(inside(l.heat, frame), "{what}: kymograph {:?}", l.heat);
                assert!(apart(l.ladder, l.heat), "{what}: ladder over kymograph");
                let (x, y, hw, hh) = l.heat_pixels();
                assert!(x + hw <= w && y + hh <= h, "{what}: kymograph pixels");
                // The snapshot's time label fits the ladder's width.
                let time = jacobs_ladder::render::style::text_width(
                    crate::common::screen().font(),
                    &time_label(t_end),
                    jacobs_ladder::render::style::size::LABEL,
                );
                assert!(time < 0.9 * l.ladder.w, "{what}: time label {time}");
                let labels = l.labels(&title, t_end, n);
                assert_eq!(labels.len(), 6, "{what}");
                for (i, a) in labels.iter().enumerate() {
                    let b = a.bounds();
                    assert!(b.w > 0.0 && b.h >= a.size * 0.99, "{what}: {:?}", a.text);
                    assert!(inside(b, frame), "{what}: {:?} at {b:?} is cut", a.text);
                    assert!(apart(b, l.heat), "{what}: {:?} over the kymograph", a.text);
                    assert!(apart(b, l.ladder), "{what}: {:?} over the ladder", a.text);
                    for c in &labels[i + 1..] {
                        assert!(
                            apart(b, c.bounds()),
                            "{what}: {:?} and {:?} overlap",
                            a.text,
                            c.text
                        );
                    }
                }
                // The catalogue's titles keep their full size.
                if title != long {
                    assert_eq!(labels[0].size, 18.0, "{what}: {title}");
                } else if l.design.0 < 1000.0 {
                    assert!(labels[0].size < 18.0, "{what}");
                }
            }
        }
    }
}

/// A golden image of a vector output: the SVG file of the edge-mode figure
/// (superscripts and subscripts in chart legends, axis labels and notes)
/// rasterised by resvg.
#[test]
fn golden_rasterised_svg() {
    let (_, pic) = figures()
        .iter()
        .find(|(n, _)| n == "figure-edge-mode")
        .unwrap();
    let svg = encode::svg_bytes(&pic.to_tree(1.0).unwrap());
    let (w, h) = pic.pixel_size();
    check("svg-figure-edge-mode", &rasterize_svg_file(&svg, w, h));
}

// ---------------------------------------------------------------- labels

/// What a reader of `text` sees that is source code rather than typeset
/// text: equation tags, markup left unconverted, TeX, identifiers with
/// underscores, Greek letters spelled out.
fn code_names(text: &str) -> Vec<String> {
    let mut found = Vec::new();
    for bad in ["eq:", "^{", "_{", "\\", "sqrt(", "$"] {
        if text.contains(bad) {
            found.push(bad.to_string());
        }
    }
    let words = text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'));
    for word in words {
        let lower = word.to_ascii_lowercase();
        let greek = [
            "alpha", "beta", "gamma", "delta", "theta", "kappa", "omega", "tau", "sigma", "phi",
            "pi", "epsilon", "eq",
        ];
        if word.contains('_') || greek.contains(&lower.as_str()) {
            found.push(word.to_string());
        }
    }
    found
}

/// The text content of every `<text>` element of an SVG document.
fn svg_texts(svg: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(start) = rest.find("<text") {
        let body = &rest[start..];
        let end = body.find("</text>").expect("closed <text>");
        out.push(strip_tags(&body[..end]));
        rest = &body[end..];
    }
    out
}

/// `html` without its tags (and without `<style>` and `<script>` bodies).
fn strip_tags(html: &str) -> String {
    let mut out = String::new();
    let mut rest = html;
    while let Some(open) = rest.find('<') {
        out.push_str(&rest[..open]);
        let tag = &rest[open..];
        let skip_to = ["<style", "<script"]
            .iter()
            .find(|t| tag.starts_with(*t))
            .map(|t| format!("</{}", &t[1..]));
        let close = match skip_to {
            Some(end) => tag.find(&end).unwrap_or(tag.len()),
            None => 0,
        };
        let gt = tag[close..].find('>').map_or(tag.len(), |i| close + i + 1);
        out.push(' ');
        rest = &tag[gt..];
    }
    out.push_str(rest);
    out
}

#[test]
fn code_names_finds_what_it_should() {
    assert!(code_names("as printed (eq:zm_n)").len() >= 2);
    assert_eq!(code_names("e^{−κ} omega_plus"), ["^{", "omega_plus"]);
    assert_eq!(code_names("kappa b"), ["kappa"]);
    assert!(code_names("ω₊ and e−κ(n−1)b, |δθₙ|, t/τ = 2200").is_empty());
    assert_eq!(
        svg_texts("<svg><text x=\"1\">a<tspan dy=\"2\">b</tspan></text></svg>")
            .iter()
            .map(|t| t.split_whitespace().collect::<String>())
            .collect::<Vec<_>>(),
        ["ab"]
    );
    assert_eq!(
        strip_tags("<style>p { x: 1 }</style><p>n<sub>C</sub></p>").trim(),
        "n C"
    );
}

/// What readers see is typeset: no equation tags or code names in any
/// figure's text (legends, axes, notes; charts included), in any movie
/// frame's text, or in the gallery's captions and alt texts; and the
/// figures' super- and subscripts are real ones in the SVG.
#[test]
fn labels_are_typeset_nowhere_a_code_name() {
    let mut scripts = 0;
    for (name, pic) in figures() {
        let svg = pic.to_svg(1.0).unwrap();
        scripts += svg.matches("baseline-shift").count();
        let texts = svg_texts(&svg);
        assert!(!texts.is_empty(), "{name}: no text");
        for t in texts {
            let bad = code_names(&t);
            assert!(bad.is_empty(), "{name}: {bad:?} in {t:?}");
        }
    }
    assert!(
        scripts >= 10,
        "super- and subscripts drawn as such: {scripts}"
    );
    for e in catalog::entries(scene::Kind::Movie).unwrap() {
        let layout = jacobs_ladder::render::MovieLayout::new(
            &crate::common::screen(),
            640,
            480,
            e.scene.model.n,
        );
        let title = scene::describe::title(&e.scene);
        for l in layout.labels(&title, e.scene.run.t_end, e.scene.model.n) {
            let bad = code_names(&l.text.replace("_{n}", "ₙ"));
            assert!(bad.is_empty(), "movie {}: {bad:?} in {:?}", e.id, l.text);
        }
    }
    // The gallery of everything the catalogue makes.
    let scenes: Vec<_> = [scene::Kind::Figure, scene::Kind::Movie]
        .into_iter()
        .flat_map(|k| catalog::entries(k).unwrap())
        .collect();
    let items: Vec<jacobs_ladder::gallery::Item> = scenes
        .iter()
        .map(|e| jacobs_ladder::gallery::Item {
            scene: &e.scene,
            files: vec![format!("{}.png", e.scene.stem())],
        })
        .collect();
    let html = jacobs_ladder::gallery::index_html(&items).unwrap();
    dump("index.html", html.as_bytes());
    let seen = strip_tags(&html);
    let bad = code_names(&seen);
    assert!(bad.is_empty(), "gallery text: {bad:?}");
    let alts: Vec<&str> = html
        .split("alt=\"")
        .skip(1)
        .map(|a| &a[..a.find('"').unwrap()])
        .collect();
    assert!(alts.len() >= 20, "alt texts: {}", alts.len());
    for a in alts {
        let bad = code_names(a);
        assert!(bad.is_empty(), "alt text {a:?}: {bad:?}");
    }
    // Formulas of the captions are typeset as HTML, as in the images.
    assert!(html.contains("e<sup>−κ(n−1)b</sup>"), "edge-mode caption");
}

// ------------------------------------------------------------ command line

fn ladder(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .output()
        .unwrap()
}

fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("ladder-formats-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

#[test]
fn bad_formats_sizes_and_outs_are_one_line_exit_2() {
    let out = scratch("bad");
    let o = out.to_str().unwrap();
    let cases: [(&[&str], &str); 14] = [
        (
            &["figure", "3", "--format", "jpg", "--out", o],
            "--format: unknown format 'jpg'",
        ),
        (
            &["movie", "4", "--format", "pdf", "--out", o],
            "--format pdf: no movie format; a movie is gif or mp4",
        ),
        (
            &["all", "--format", "png,webm", "--out", o],
            "--format: unknown format 'webm'",
        ),
        (
            &["movie", "4", "--format", "gif", "--fps", "60", "--out", o],
            "--fps: a GIF plays at most 50",
        ),
        (
            &[
                "movie", "4", "--format", "mp4", "--size", "641x480", "--out", o,
            ],
            if cfg!(feature = "mp4") {
                "try 640x480"
            } else {
                "without the cargo feature 'mp4'"
            },
        ),
        (
            &["movie", "4", "--size", "9000x480", "--out", o],
            "between 64 and 4096",
        ),
        (&["figure", "2b", "--scale", "100", "--out", o], "--scale:"),
        (
            &["figure", "3", "--size", "1280x960", "--out", o],
            "use --scale S",
        ),
        (
            &[
                "movie", "4", "--format", "mp4", "--size", "1280x721", "--out", o,
            ],
            if cfg!(feature = "mp4") {
                "try 1280x720"
            } else {
                "without the cargo feature 'mp4'"
            },
        ),
        (&["figure", "3", "--out", "x.svg"], "--out is a folder"),
        (&["figure", "3", "--out", "Cargo.toml"], "--out is a folder"),
        (
            &["sweep", "--alpha", "50,60", "--out", "x.pdf"],
            "--out is a folder",
        ),
        (&["movie", "4", "--out", "x.mp4"], "--out is a folder"),
        (&["all", "--out", "x.html"], "--out is a folder"),
    ];
    for (args, expected) in cases {
        let r = ladder(args);
        let err = String::from_utf8_lossy(&r.stderr);
        assert_eq!(r.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(expected), "{args:?}: {err}");
    }
    assert!(!out.exists(), "nothing written on bad input");
    for f in ["x.svg", "x.pdf", "x.mp4", "x.html"] {
        assert!(!std::path::Path::new(f).exists(), "{f} made");
    }
}

#[test]
fn figure_in_every_format_and_scale() {
    let out = scratch("figure");
    let o = out.to_str().unwrap();
    let r = ladder(&[
        "figure",
        "2d",
        "--format",
        "pdf,svg,png",
        "--scale",
        "2",
        "--out",
        o,
    ]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let png = std::fs::read(out.join("figure-2d.png")).unwrap();
    let svg = std::fs::read(out.join("figure-2d.svg")).unwrap();
    let pdf = std::fs::read(out.join("figure-2d.pdf")).unwrap();
    assert!(pdf.starts_with(b"%PDF-") && svg.starts_with(b"<svg"));
    let (w, h) = crate::common::pngio::dimensions(&out.join("figure-2d.png")).unwrap();
    let pic = &figures().iter().find(|(n, _)| n == "figure-2d").unwrap().1;
    assert_eq!(
        (w, h),
        pic.scaled_size(2.0).unwrap(),
        "--scale 2 doubles the pixels"
    );
    assert!(png.len() > 1000);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn sweep_chart_in_every_format() {
    let out = scratch("sweep");
    let o = out.to_str().unwrap();
    let r = ladder(&[
        "sweep",
        "--alpha",
        "50,60",
        "--t-end",
        "3000",
        "--name",
        "tiny",
        "--format",
        "svg,pdf,png",
        "--out",
        o,
    ]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    for ext in ["svg", "pdf", "png", "csv", "json"] {
        let f = out.join(format!("sweep-tiny.{ext}"));
        assert!(f.exists(), "{} missing", f.display());
    }
    let pdf = std::fs::read(out.join("sweep-tiny.pdf")).unwrap();
    let doc = lopdf::Document::load_mem(&pdf).unwrap();
    let ops = pdf_operators(&doc);
    let count = |op: &str| ops.iter().filter(|o| *o == op).count();
    // Vector paths (axes, grid, marks) and real text (docs/formats.md: a
    // PDF carries its labels as text in the embedded font).
    assert!(
        count("m") > 20 && count("l") + count("c") > 20,
        "vector chart: m {}, l {}, c {}",
        count("m"),
        count("l"),
        count("c")
    );
    assert!(
        count("BT") > 0 && count("Tj") + count("TJ") > 0,
        "real text in the chart"
    );
    let json = std::fs::read_to_string(out.join("sweep-tiny.json")).unwrap();
    assert!(
        json.contains("sweep-tiny.pdf"),
        "the data file lists the chart files"
    );
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn movie_and_render_write_every_format_asked_for() {
    let movies = if cfg!(feature = "mp4") {
        "gif,mp4"
    } else {
        "gif"
    };
    let out = scratch("movie");
    let o = out.to_str().unwrap();
    let small = ["--frames", "6", "--size", "320x240", "--out", o];
    let r = ladder(&[&["movie", "4", "--format", movies][..], &small].concat());
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let gif = std::fs::read(out.join("movie-4.gif")).unwrap();
    assert!(gif.starts_with(b"GIF89a"));
    if cfg!(feature = "mp4") {
        let mp4 = std::fs::read(out.join("movie-4.mp4")).unwrap();
        assert_eq!(&mp4[4..8], b"ftyp");
    }
    // `render` takes figure and movie formats in one list; a scene file of
    // each kind gets the formats of its kind. (movie-4.toml renders to
    // movie-4.*: clear the `movie` command's files first.)
    for ext in ["gif", "mp4", "json"] {
        let _ = std::fs::remove_file(out.join(format!("movie-4.{ext}")));
    }
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let (fig, mov) = (dir.join("figure-2d.toml"), dir.join("movie-4.toml"));
    let list = format!("svg,pdf,{movies}");
    let r = ladder(
        &[
            &["render", fig.to_str().unwrap(), mov.to_str().unwrap()][..],
            &["--format", &list],
            &small,
        ]
        .concat(),
    );
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let names: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    let has = |ext: &str, kind: &str| {
        names
            .iter()
            .any(|n| n.starts_with(kind) && n.ends_with(&format!(".{ext}")))
    };
    assert!(has("svg", "figure") && has("pdf", "figure"), "{names:?}");
    assert!(
        !has("png", "figure"),
        "only the formats asked for: {names:?}"
    );
    assert!(has("gif", "movie"), "{names:?}");
    if cfg!(feature = "mp4") {
        assert!(names.iter().any(|n| n == "movie-4.mp4"), "{names:?}");
    }
    let _ = std::fs::remove_dir_all(&out);
}
