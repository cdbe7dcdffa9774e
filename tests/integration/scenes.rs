//! The paper's scenes: every catalogue entry renders, with its data file;
//! the movies show what the paper says (docs/model.md); a printed scene
//! renders back to the same bytes; golden images of figure 3 and a
//! kymograph; custom movies at N = 2, 40 and 200.

#![allow(clippy::field_reassign_with_default)]

use crate::common::golden::check;
use jacobs_ladder::catalog;
use jacobs_ladder::model::ladder::itheta;
use jacobs_ladder::scene::{self, Kind, Scene};
use jacobs_ladder::scenes::{self, MovieOptions, dynamic, run};
use std::sync::OnceLock;

const SMALL: MovieOptions = MovieOptions {
    frames: 3,
    width: 160,
    height: 120,
    fps: 10.0,
};

type Files = Vec<(String, Vec<u8>)>;

/// Every catalogue entry rendered at `SMALL`, in `catalog::catalogue()`'s
/// order: made once, by the first test that asks, for every test here.
/// The runs two entries share are made once and held while they render,
/// as `ladder all` holds them (`scenes::shared`: the water tank's levels
/// and movies, figure 4b's run taken from movie 12's), so that
/// [`a_printed_scene_renders_to_the_same_bytes`], which renders each
/// figure again on its own, also checks that a held run draws what a run
/// of its own draws.
fn rendered() -> &'static [Files] {
    use jacobs_ladder::scenes::shared;
    use jacobs_ladder::sim::tally::Tally;
    static ALL: OnceLock<Vec<Files>> = OnceLock::new();
    ALL.get_or_init(|| {
        let entries = catalog::catalogue().unwrap();
        let all: Vec<Scene> = entries.iter().map(|e| e.scene.clone()).collect();
        let tallies: Vec<std::sync::Arc<Tally>> = all.iter().map(|_| Default::default()).collect();
        let held = shared::prepare(&all, &SMALL, &tallies).unwrap();
        let rings: Vec<_> = shared::ring_groups(&all)
            .iter()
            .map(|g| {
                let group: Vec<&Scene> = g.iter().map(|&i| &all[i]).collect();
                shared::make_ring_runs(&group, &SMALL, &tallies[g[0]])
            })
            .collect();
        assert!(!held.is_empty(), "no run is shared");
        assert!(
            !rings.is_empty() && rings.iter().all(|r| r.len() > 1),
            "no ring chain's run is shared"
        );
        entries
            .iter()
            .map(|e| {
                scenes::render(&e.scene, &SMALL).unwrap_or_else(|err| panic!("{}: {err}", e.id))
            })
            .collect()
    })
}

#[test]
fn every_catalogue_entry_renders_with_its_data() {
    for (entry, files) in catalog::catalogue().unwrap().iter().zip(rendered()) {
        assert_eq!(files.len(), scenes::file_names(&entry.scene).len());
        for (name, bytes) in files {
            assert!(bytes.len() > 100, "{name} is nearly empty");
            let magic: &[u8] = if name.ends_with(".gif") {
                b"GIF89a"
            } else if name.ends_with(".json") {
                b"{"
            } else if name.ends_with(".csv") {
                b"run,"
            } else {
                b"\x89PNG"
            };
            assert!(bytes.starts_with(magic), "{name}");
        }
        let (_, json) = files.last().unwrap();
        let v: serde_json::Value = serde_json::from_slice(json).unwrap();
        assert_eq!(v["version"], env!("CARGO_PKG_VERSION"));
        assert_eq!(v["scene"]["model"]["n"], entry.scene.model.n);
        if let scene::OutputSpec::Sweep(_) = entry.scene.output {
            // A sweep's data file: every run with its point and arrivals.
            let runs = v["runs"].as_array().unwrap();
            assert!(runs.len() > 5, "{}", entry.id);
            for r in runs {
                assert!(r["outcome"].is_string(), "{}", entry.id);
                assert!(r["arrival_times"].as_array().unwrap().len() >= 4);
            }
        } else if entry.scene.rings.is_some() {
            // A ring chain's data file: its run in `rings` (docs/rings.md),
            // every linked pair held by the guard, the energy sampled.
            let r = &v["rings"];
            assert!(r["steps"].as_u64().is_some_and(|s| s > 0), "{}", entry.id);
            assert!(r["guard_checks"].as_u64().is_some_and(|c| c > 0));
            assert!(!r["links"].as_array().unwrap().is_empty(), "{}", entry.id);
            assert!(r["energy"].as_array().unwrap().len() > 2, "{}", entry.id);
            assert!(r["flips"].is_array() && r["waves"].is_array());
        } else if entry.scene.fidelity() == scene::Fidelity::Simulation {
            let runs = v["runs"].as_array().unwrap();
            assert!(!runs.is_empty(), "{}", entry.id);
            for r in runs {
                // `auto` states the error it verified; a named scheme (the
                // experiment figures' RK4 at 0.125 τ) states none.
                let integrator = &r["integrator"];
                match integrator["requested"].as_str() {
                    Some("auto") => {
                        let err = integrator["arrival_error"].as_f64();
                        assert!(
                            err.is_some_and(|e| e <= entry.scene.run.tolerance),
                            "{}: auto's arrival error {err:?}",
                            entry.id
                        );
                    }
                    Some(_) => assert!(
                        integrator["name"].is_string() && integrator["dt"].is_number(),
                        "{}: a named scheme without its step: {integrator}",
                        entry.id
                    ),
                    None => panic!("{}: no integrator in the data: {r}", entry.id),
                }
                assert_eq!(
                    r["arrival_times"].as_array().unwrap().len(),
                    r["model"]["n"]
                );
            }
        }
    }
}

#[test]
fn a_printed_scene_renders_to_the_same_bytes() {
    // The entry's own files are `rendered()`'s; the printed scene's are made
    // here, from the text read back.
    for (entry, a) in catalog::catalogue().unwrap().iter().zip(rendered()) {
        let text = scene::file::to_toml(&entry.scene).unwrap();
        let back = scene::file::parse(&text, "printed", &entry.id).unwrap();
        assert_eq!(back, entry.scene, "{}", entry.id);
        // Every figure, and one movie, byte for byte.
        if matches!(
            (entry.scene.kind(), entry.id.as_str()),
            (Kind::Figure, _) | (Kind::Movie, "4")
        ) {
            let b = scenes::render(&back, &SMALL).unwrap();
            assert!(
                *a == b,
                "{}: the printed scene renders differently",
                entry.id
            );
        }
    }
}

fn movie_scene(id: &str) -> Scene {
    catalog::find(Kind::Movie, id).unwrap().scene.clone()
}

/// Signs of sin θ_n of every block at every frame of a movie.
fn frame_signs(id: &str, frames: usize) -> Vec<Vec<f64>> {
    let s = movie_scene(id);
    let r = run::simulate(&s, &dynamic::frame_times(s.run.t_end, frames)).unwrap();
    r.trajectory
        .states
        .iter()
        .map(|q| {
            (0..s.model.n)
                .map(|i| q[itheta(i)].sin().signum())
                .collect()
        })
        .collect()
}

#[test]
fn movie_7_shows_the_pinned_wall() {
    for signs in frame_signs("7", 200) {
        assert!(
            signs[2..].iter().all(|&s| s < 0.0),
            "a block below 2 flipped: {signs:?}"
        );
    }
}

#[test]
fn movie_11_ends_annihilated() {
    let frames = frame_signs("11", 200);
    let mid = &frames[100];
    assert!(mid.iter().any(|&s| s > 0.0), "the antikink exists half-way");
    let last = frames.last().unwrap();
    assert!(
        last.iter().all(|&s| s < 0.0),
        "a block is still flipped: {last:?}"
    );
}

#[test]
fn movie_10_shows_two_walls_at_once() {
    let walls = |signs: &Vec<f64>| signs.windows(2).filter(|w| w[0] != w[1]).count();
    let frames = frame_signs("10", 200);
    assert!(
        frames.iter().any(|s| walls(s) == 2),
        "no frame with kink and antikink"
    );
    assert!(
        frames.last().unwrap().iter().all(|&s| s > 0.0),
        "both walls leave at the bottom"
    );
}

#[test]
fn fitted_speed_of_evenly_spaced_arrivals() {
    let arrivals: Vec<Option<f64>> = (0..10).map(|i| Some(100.0 + 250.0 * i as f64)).collect();
    assert!((scenes::arrivals::fitted_speed(&arrivals).unwrap() - 4.0).abs() < 1e-9);
    assert!(scenes::arrivals::fitted_speed(&[Some(1.0), Some(2.0), None, None]).is_none());
}

#[test]
fn golden_figure_3() {
    let scene = &catalog::find(Kind::Figure, "3").unwrap().scene;
    let (image, _) =
        dynamic::filmstrip_figure(&crate::common::screen(), scene, Some((86, 200))).unwrap();
    check("figure-3-small", &image.to_pixmap().unwrap());
}

#[test]
fn golden_kymograph_movie_7() {
    let s = movie_scene("7");
    let r = run::simulate(&s, &dynamic::frame_times(s.run.t_end, 60)).unwrap();
    let image = scenes::kymograph::kymograph_image(
        &crate::common::screen(),
        "Movie 7",
        &r.trajectory,
        s.model.n,
        320,
        240,
    )
    .unwrap();
    check("kymograph-movie-7", &image);
}

/// A custom movie at N blocks: both ends of every block stay inside the
/// ladder's part of the frame at every frame, as the movie draws them.
#[test]
fn custom_movies_at_2_40_and_200_blocks_keep_every_block_in_the_frame() {
    for (n, t_end) in [(2, 1500.0), (40, 2500.0), (200, 1500.0)] {
        let mut s = Scene::default();
        s.name = format!("n{n}");
        s.model.n = n;
        s.run.t_end = t_end;
        let opts = MovieOptions {
            frames: 20,
            width: 320,
            height: 240,
            fps: 10.0,
        };
        let files = scenes::render(&s, &opts).unwrap_or_else(|e| panic!("N = {n}: {e}"));
        assert_eq!(files[0].0, format!("movie-n{n}.gif"));
        let v: serde_json::Value = serde_json::from_slice(&files[2].1).unwrap();
        assert_eq!(v["runs"][0]["frames"].as_array().unwrap().len(), 20);
        let (region, frames) =
            dynamic::movie_block_pixels(&crate::common::screen(), &s, &opts).unwrap();
        assert_eq!(frames.len(), 20);
        for px in frames {
            // A folded ladder draws the block shared by two columns twice.
            assert!(px.len() >= 2 * n, "N = {n}: {} block ends drawn", px.len());
            for (x, y) in px {
                assert!(
                    x >= region.x
                        && x <= region.x + region.w
                        && y >= region.y
                        && y <= region.y + region.h,
                    "N = {n}: a block end drawn at ({x}, {y}) outside {region:?}"
                );
            }
        }
    }
}

/// Movie 3's camera follows the kink but stays on the ladder: at the last
/// frame the bottom block sits at the bottom of the window, whole, with no
/// empty band below it.
#[test]
fn movie_3_keeps_the_ladder_filling_the_window_to_the_end() {
    let entry = jacobs_ladder::catalog::find(jacobs_ladder::scene::Kind::Movie, "3").unwrap();
    let opts = MovieOptions {
        frames: 12,
        width: 320,
        height: 240,
        fps: 10.0,
    };
    let (region, frames) =
        dynamic::movie_block_pixels(&crate::common::screen(), &entry.scene, &opts).unwrap();
    // The window's bottom: above the snapshot's time band and margin.
    let margin = (0.03 * region.w.min(region.h)).clamp(2.0, 12.0);
    let bottom = region.y + region.h - margin - 1.5 * jacobs_ladder::render::style::size::LABEL;
    let last = frames.last().unwrap();
    let lowest = last.iter().map(|p| p.1).fold(f32::MIN, f32::max);
    assert!(
        lowest <= bottom && lowest >= bottom - 0.08 * region.h,
        "lowest block end at {lowest}, window bottom {bottom}, {region:?}"
    );
}
