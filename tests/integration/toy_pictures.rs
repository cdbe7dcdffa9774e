//! The toy as built in pictures (docs/experiments.md, "The toy as
//! built"): `movie toy`, `figure toy` and `movie water-tank-ribbons` draw
//! blocks with thickness and ribbons (`render::blocks`). Their captions
//! against their data files (every number accounted for, as
//! `captions.rs` checks the others'), every block's rectangle inside the
//! movie's ladder region, the ribbons drawn on the tangent points the
//! model gives, and a golden snapshot of the toy with an impact marked.

use crate::captions::accounted;
use crate::common::tempdir::TempDir;
use jacobs_ladder::catalog;
use jacobs_ladder::render::snapshot::{Region, Snapshot, pixel_of, render_snapshot};
use jacobs_ladder::render::{Palette, Role};
use jacobs_ladder::scene::Kind;
use serde_json::Value;

const TOY: &str = include_str!("../../assets/scenes/toy.toml");

/// `ladder KIND ID` drawn into a fresh folder (a movie at its default
/// frames, whose samples its numbers are read from, but small): its data
/// file.
fn data(kind: &str, id: &str) -> Value {
    let dir = TempDir::new(&format!("toy-pictures-{kind}-{id}"));
    let mut args = vec![kind, id, "--out", dir.to_str().unwrap()];
    if kind == "movie" {
        args.extend(["--size", "320x240"]);
    }
    let out = crate::common::ladder_cli(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(dir.join(format!("{kind}-{id}.json"))).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn caption(kind: Kind, id: &str) -> String {
    catalog::find(kind, id)
        .unwrap()
        .scene
        .caption
        .clone()
        .unwrap()
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn strings(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
}

/// Blocks (one-based) in the order their sin θ changed sign, with the
/// times in seconds.
fn flip_order(run: &Value) -> Vec<(usize, f64)> {
    let times = run["units"]["arrival_times_s"].as_array().unwrap();
    let mut order: Vec<(usize, f64)> = times
        .iter()
        .enumerate()
        .map(|(i, t)| (i + 1, f(t)))
        .collect();
    order.sort_by(|a, b| a.1.total_cmp(&b.1));
    order
}

#[test]
fn the_toy_movies_caption_is_its_run() {
    let d = data("movie", "toy");
    let run = &d["runs"][0];
    let units = &run["units"];
    let order = flip_order(run);
    let blocks: Vec<usize> = order.iter().map(|o| o.0).collect();
    let s2 = |t: f64| format!("{t:.2}");
    // The order the caption tells: 1 and 2 in turn, then the free end,
    // then 3, 4 and 5.
    assert_eq!(blocks, vec![1, 2, 6, 3, 4, 5], "{order:?}");
    let t: Vec<String> = order.iter().map(|o| s2(o.1)).collect();
    let said = format!(
        "Blocks 1 and 2 flip in turn (at {} and {} s), then block 6, the free end ({} s), before blocks 3, 4 and 5 ({}, {} and {} s)",
        t[0], t[1], t[2], t[3], t[4], t[5]
    );
    let c = caption(Kind::Movie, "toy");
    assert!(c.contains(&said), "the caption lacks \"{said}\": {c}");
    let impacts = run["impacts"].as_array().unwrap().len();
    let a = &d["scene"]["apparatus"];
    // The block numbers of the sentence above (6 is also N, below).
    let mut numbers = strings(&["1", "2", "3", "4", "5"]);
    numbers.extend(t);
    numbers.extend([
        format!("{}", run["model"]["n"]),
        format!("{}", f(&a["s"])),
        format!("{}", f(&a["thickness"])),
        format!("{:.2}", f(&units["drive_time_s"])),
        format!("{impacts}"),
        format!("{}", f(&units["t_end_s"])),
    ]);
    accounted("movie toy", &c, &numbers);
}

#[test]
fn the_ribbon_tanks_caption_is_its_run() {
    let d = data("movie", "water-tank-ribbons");
    let run = &d["runs"][0];
    let units = &run["units"];
    let n = run["model"]["n"].as_u64().unwrap() as usize;
    // Every plate (blocks 2..N) turns over, in turn.
    assert_eq!(run["blocks_flipped"].as_u64().unwrap() as usize, n - 1);
    let order = flip_order(run);
    assert_eq!(
        order.iter().map(|o| o.0).collect::<Vec<_>>(),
        (1..=n).collect::<Vec<_>>()
    );
    let speed = f(&units["speed_cm_s"]);
    // The tank's measured kink (the paper's supplement).
    let measured = 6.0;
    let a = &d["scene"]["apparatus"];
    let numbers = vec![
        format!("{}", n - 1),
        format!("{}", f(&a["s"])),
        format!("{}", f(&a["thickness"])),
        format!("{}", f(&a["b"])),
        format!("{}", f(&a["motor"])),
        // The last arrival to a tenth of a second: the free end's arrivals
        // move by tens of τ (0.1 s) with Moreau's step.
        format!("{:.1}", order[n - 1].1),
        format!("{speed:.1}"),
        // The speed's window, blocks 3 to N − 1 (`sim::speed`).
        "3".into(),
        format!("{:.1}", speed / measured),
        format!("{measured:.1}"),
    ];
    accounted(
        "movie water-tank-ribbons",
        &caption(Kind::Movie, "water-tank-ribbons"),
        &numbers,
    );
}

#[test]
fn the_toy_figure_starts_from_the_hanging_column_and_says_its_turn() {
    let d = data("figure", "toy");
    let run = &d["runs"][0];
    let units = &run["units"];
    // Its first snapshot is the column of Fig. 1a: every block hanging
    // (θ = 90°, sin θ = 1); by its last, block 1 is turned over.
    let frames = run["frames"].as_array().unwrap();
    let sin = |frame: &Value, i: usize| f(&frame["theta_deg"][i]).to_radians().sin();
    let first = &frames[0];
    for i in 0..6 {
        assert!((sin(first, i) - 1.0).abs() < 1e-9, "block {}", i + 1);
    }
    assert!((sin(frames.last().unwrap(), 0) + 1.0).abs() < 1e-6);
    let numbers = vec![
        "1".to_string(),
        format!("{:.2}", f(&units["drive_time_s"])),
        format!("{:.3}", 1e3 * f(&units["tau_s"])),
    ];
    accounted("figure toy", &caption(Kind::Figure, "toy"), &numbers);
}

/// The toy's ladder as built (blocks with thickness, ribbons, contact).
fn toy_ladder() -> jacobs_ladder::model::Ladder {
    let scene = jacobs_ladder::scene::file::parse(TOY, "toy", "toy").unwrap();
    scene.scenario().unwrap().ladder
}

/// A bent state of the toy: blocks zig-zagging down, ribbons wrapped.
fn bent(n: usize) -> Vec<f64> {
    let mut q = vec![0.0; 3 * n];
    for i in 0..n {
        let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
        q[3 * i] = 1.05 * i as f64;
        q[3 * i + 1] = 0.25 * sign;
        q[3 * i + 2] = std::f64::consts::FRAC_PI_2 + 0.5 * sign;
    }
    q
}

#[test]
fn every_block_of_the_toy_as_built_lies_inside_the_movie_frame() {
    let theme = crate::common::screen();
    let opts = jacobs_ladder::scenes::MovieOptions {
        frames: 40,
        ..Default::default()
    };
    for id in ["toy", "water-tank-ribbons"] {
        let scene = &catalog::find(Kind::Movie, id).unwrap().scene;
        let a = scene.apparatus.as_ref().unwrap();
        // Half the thickness, in s.
        let h = 0.5 * a.thickness / a.s;
        let (region, frames) =
            jacobs_ladder::scenes::movie::movie_block_pixels(&theme, scene, &opts).unwrap();
        assert_eq!(frames.len(), opts.frames);
        for (k, ends) in frames.iter().enumerate() {
            for (i, e) in ends.chunks(2).enumerate() {
                let (a, b) = (e[0], e[1]);
                // The pixels across the block, h s from its axis each way.
                let across = (-(b.1 - a.1) * h as f32, (b.0 - a.0) * h as f32);
                for p in [a, b] {
                    for s in [-1.0, 1.0] {
                        let (x, y) = (p.0 + s * across.0, p.1 + s * across.1);
                        assert!(
                            x >= region.x
                                && x <= region.x + region.w
                                && y >= region.y
                                && y <= region.y + region.h,
                            "{id}: frame {k}, block {}: corner ({x}, {y}) outside {region:?}",
                            i + 1
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn the_ribbons_are_drawn_on_the_tangent_points_the_model_gives() {
    let ladder = toy_ladder();
    let built = ladder.built.unwrap();
    let q = bent(ladder.n());
    let snap = Snapshot::new(&ladder, &q).unwrap();
    let (w, h) = (300, 600);
    let pixmap = render_snapshot(&crate::common::screen(), &snap, w, h).unwrap();
    let region = Region::full(w, h);
    let ink = Palette.color(Role::SpringA);
    let mut checked = 0;
    let mut r = 0;
    built
        .ribbons
        .for_each_span(ladder.n(), &q, |_, pu, pl, span| {
            let first = r % 2 == 0;
            r += 1;
            // Ribbon 1 is drawn solid: the middle of its free span, between
            // the tangent points D and E the model's force acts at, is its ink.
            if !first || span.free < 0.3 {
                return;
            }
            let (d, e) = (pu.point(span.d), pl.point(span.e));
            let mid = [0.5 * (d[0] + e[0]), 0.5 * (d[1] + e[1])];
            let (x, y) = pixel_of(region, &snap, mid);
            // The line is antialiased: its ink within a pixel of the point.
            let far = |dx: i32, dy: i32| {
                let px = pixmap
                    .pixel(
                        (x.round() as i32 + dx) as u32,
                        (y.round() as i32 + dy) as u32,
                    )
                    .unwrap();
                let got = [px.red(), px.green(), px.blue()];
                got.iter()
                    .zip(ink)
                    .map(|(a, b)| (*a as i32 - b as i32).abs())
                    .max()
                    .unwrap()
            };
            let nearest = (-1..=1)
                .flat_map(|dx| (-1..=1).map(move |dy| (dx, dy)))
                .map(|(dx, dy)| far(dx, dy))
                .min()
                .unwrap();
            assert!(
                nearest < 30,
                "ribbon 1 at ({x}, {y}): {nearest} from {ink:?}"
            );
            checked += 1;
        });
    assert!(checked >= 2, "{checked} free spans checked");
}

#[test]
fn golden_snapshot_of_the_toy_with_an_impact() {
    let ladder = toy_ladder();
    let q = bent(ladder.n());
    let mut snap = Snapshot::new(&ladder, &q)
        .unwrap()
        .with_title("toy as built")
        .with_time(480.0);
    snap.impacts = &[[1, 2]];
    crate::common::golden::check(
        "snapshot-toy-built",
        &render_snapshot(&crate::common::screen(), &snap, 220, 520).unwrap(),
    );
}
