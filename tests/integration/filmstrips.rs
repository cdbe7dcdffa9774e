//! Filmstrips of long ladders: folded into columns in each snapshot so that
//! no block is shorter than `scene::MIN_BLOCK_PIXELS`, every block inside
//! its snapshot and the image; the catalogue's filmstrips (N ≤ 20) drawn
//! as before, one ladder a snapshot.

use crate::common::golden::check;
use jacobs_ladder::catalog;
use jacobs_ladder::render::compose::StripGeometry;
use jacobs_ladder::render::{Item, Picture, style};
use jacobs_ladder::scene::{self, Kind, MIN_BLOCK_PIXELS, Scene};
use jacobs_ladder::scenes::dynamic;
use tiny_skia::Transform;

/// A filmstrip scene of `n` blocks from a scene file's text.
fn strip_scene(n: usize, extra: &str) -> Scene {
    let text = format!("[model]\nn = {n}\n{extra}\n[output]\nkind = \"filmstrip\"\n");
    scene::file::parse(&text, "test.toml", &format!("n{n}")).unwrap()
}

/// Every block end of every snapshot inside its snapshot and the image,
/// every block at least `MIN_BLOCK_PIXELS` long, every block drawn;
/// returns how many block ends the first snapshot draws.
fn check_geometry(what: &str, g: &StripGeometry, n: usize) -> usize {
    let (w, h) = (g.size.0 as f32, g.size.1 as f32);
    assert_eq!(g.snapshots.len(), g.blocks.len(), "{what}");
    for (k, (r, blocks)) in g.snapshots.iter().zip(&g.blocks).enumerate() {
        assert!(
            r.x >= 0.0 && r.y >= 0.0 && r.x + r.w <= w && r.y + r.h <= h,
            "{what}: snapshot {k} at {r:?} outside the {w}x{h} image"
        );
        assert!(
            blocks.len() >= n,
            "{what}: snapshot {k} draws {}",
            blocks.len()
        );
        for (i, [a, b]) in blocks.iter().enumerate() {
            for (x, y) in [a, b] {
                assert!(
                    *x >= r.x && *x <= r.x + r.w && *y >= r.y && *y <= r.y + r.h,
                    "{what}: snapshot {k}, block end {i} at ({x}, {y}) outside {r:?}"
                );
            }
            let len = (b.0 - a.0).hypot(b.1 - a.1);
            assert!(
                len >= MIN_BLOCK_PIXELS as f32 - 1e-3,
                "{what}: snapshot {k}, block {i} drawn {len} px long"
            );
        }
    }
    g.blocks[0].len()
}

#[test]
fn filmstrips_of_2_to_400_blocks_keep_every_block_inside_and_readable() {
    for n in [2, 20, 40, 200, 400] {
        // One Verlet run at `auto`'s coarse step, not `auto`'s pair of
        // runs (with the auto window's run, half the work at N = 400): the
        // layout of the strips depends on N and the frame, not on the
        // scheme.
        let s = strip_scene(n, "[run]\nintegrator = \"verlet\"\ndt = 0.25\n");
        let (picture, _) = dynamic::filmstrip_figure(&crate::common::screen(), &s, None).unwrap();
        let geometry = dynamic::filmstrip_geometry(&crate::common::screen(), &s, None).unwrap();
        assert_eq!(geometry.len(), 1);
        let g = &geometry[0];
        assert_eq!(g.size, picture.pixel_size(), "N = {n}");
        let drawn = check_geometry(&format!("N = {n}"), g, n);
        // Short ladders are one ladder a snapshot; long ones are folded
        // (the blocks where two columns meet are drawn twice).
        if n <= 20 {
            assert_eq!(drawn, n, "N = {n} is not folded");
        } else {
            assert!(drawn > n, "N = {n} is folded");
        }
        // Wide strips wrap into rows instead of running off to the side.
        assert!(g.size.0 <= 2000, "N = {n}: {} px wide", g.size.0);
    }
}

#[test]
fn folded_strips_of_several_panels_and_given_times_stay_inside() {
    let extra = "[drive]\nflips = [{ start = 0, duration = 1000 }, { start = 2500, duration = 1000 }]\n[run]\nt_end = 6000\n";
    let mut s = strip_scene(60, extra);
    let text = "\
[model]
n = 60
[run]
t_end = 3000
[output]
kind = \"filmstrip\"
times = [0, 1000, 2000, 3000]
[[output.panels]]
label = \"(a)\"
model = { alpha = 70 }
[[output.panels]]
label = \"(b)\"
model = { alpha = -70, n = 30 }
[[output.panels]]
label = \"(c)\"
model = { alpha = 50, n = 100 }
";
    let panels = scene::file::parse(text, "p.toml", "p").unwrap();
    for (what, scene) in [("two flips", &mut s), ("three panels", &mut panels.clone())] {
        let (picture, _) =
            dynamic::filmstrip_figure(&crate::common::screen(), scene, None).unwrap();
        let geometry = dynamic::filmstrip_geometry(&crate::common::screen(), scene, None).unwrap();
        for g in &geometry {
            assert_eq!(g.size, picture.pixel_size(), "{what}");
            check_geometry(what, g, 30);
        }
    }
}

/// Text items of a picture with their boxes (left, top, right, bottom) in
/// the picture's pixels.
fn text_boxes(items: &[Item], t: Transform, out: &mut Vec<(String, [f32; 4])>) {
    for item in items {
        match item {
            Item::Group { transform, items } => text_boxes(items, t.pre_concat(*transform), out),
            Item::Text {
                text,
                at,
                size,
                align,
                ..
            } => {
                let mut p = [tiny_skia::Point::from_xy(at.0, at.1)];
                t.map_points(&mut p);
                let size = size * t.sx;
                let font = crate::common::screen().font();
                let width = style::text_width(font, text, size);
                let (left, base) = style::text_origin(font, (p[0].x, p[0].y), width, size, *align);
                let top = base - style::ascent(font, size);
                out.push((text.clone(), [left, top, left + width, base + 0.25 * size]));
            }
            _ => {}
        }
    }
}

fn texts(p: &Picture) -> Vec<(String, [f32; 4])> {
    let mut out = Vec::new();
    text_boxes(p.items(), Transform::identity(), &mut out);
    out
}

/// Two flips on a 40-block ladder: the kink and the antikink are marked in
/// the column that shows them, the marks beside the chain inside the
/// snapshot, never over another column's blocks.
#[test]
fn wall_marks_of_a_folded_ladder_stay_in_their_snapshot() {
    let extra = "alpha = 70\n[drive]\nflips = [{ start = 0, duration = 1000 }, { start = 2500, duration = 1000 }]\n[run]\nt_end = 9000\n";
    let mut s = strip_scene(40, extra);
    if let scene::OutputSpec::Filmstrip { times, .. } = &mut s.output {
        *times = vec![3000.0, 4500.0, 6000.0, 7500.0, 9000.0];
    }
    let (picture, _) = dynamic::filmstrip_figure(&crate::common::screen(), &s, None).unwrap();
    let g = &dynamic::filmstrip_geometry(&crate::common::screen(), &s, None).unwrap()[0];
    check_geometry("two flips, N = 40", g, 40);
    let marks: Vec<_> = texts(&picture)
        .into_iter()
        .filter(|(t, _)| ["kink", "antikink", "collision"].contains(&t.as_str()))
        .collect();
    // The kink of the first flip and, after the second, both walls: one at
    // block 23, in the second column.
    assert!(marks.len() >= 6, "{marks:?}");
    for (text, [l, t, r, b]) in &marks {
        let k = g
            .snapshots
            .iter()
            .position(|s| *l >= s.x && *r <= s.x + s.w && *t >= s.y && *b <= s.y + s.h)
            .unwrap_or_else(|| panic!("{text} at {:?} is in no snapshot", [l, t, r, b]));
        for (x, y) in g.blocks[k].iter().flatten() {
            assert!(
                !(*x > *l && *x < *r && *y > *t && *y < *b),
                "{text} at {:?} covers a block end at ({x}, {y})",
                [l, t, r, b]
            );
        }
    }
}

/// The catalogue's filmstrips are short enough for one ladder a snapshot:
/// none is folded, and figures 1c and 4a (its wall marks) look as before.
#[test]
fn catalogue_filmstrips_are_not_folded() {
    for id in ["1c", "3", "4a"] {
        let s = &catalog::find(Kind::Figure, id).unwrap().scene;
        let (picture, _) = dynamic::filmstrip_figure(&crate::common::screen(), s, None).unwrap();
        for (k, g) in dynamic::filmstrip_geometry(&crate::common::screen(), s, None)
            .unwrap()
            .iter()
            .enumerate()
        {
            assert_eq!(g.size, picture.pixel_size());
            let n = s.model.n;
            assert_eq!(check_geometry(&format!("figure {id}"), g, n), n);
            assert!(
                g.blocks.iter().all(|b| b.len() == n),
                "figure {id}, strip {k}"
            );
        }
        if id != "3" {
            check(&format!("figure-{id}"), &picture.to_pixmap().unwrap());
        }
    }
}

/// The most snapshots a strip may have, of a long ladder: the rows widen
/// rather than the strip grow taller than a picture may be.
#[test]
fn many_snapshots_of_a_long_ladder_fit_one_picture() {
    let mut s = strip_scene(300, "[run]\nt_end = 2000\n");
    if let scene::OutputSpec::Filmstrip { times, .. } = &mut s.output {
        *times = scene::even_times(2000.0, scene::MAX_TIMES);
    }
    let (picture, _) = dynamic::filmstrip_figure(&crate::common::screen(), &s, None).unwrap();
    let g = &dynamic::filmstrip_geometry(&crate::common::screen(), &s, None).unwrap()[0];
    assert_eq!(g.snapshots.len(), scene::MAX_TIMES);
    assert_eq!(g.size, picture.pixel_size());
    check_geometry("64 snapshots, N = 300", g, 300);
}
