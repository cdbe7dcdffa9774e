//! The paper's scenes: every catalogue entry renders; the movies show what
//! the paper says (SPEC section 2); golden images of figure 3 and a kymograph.

mod common;

use common::golden::check;
use jacobs_ladder::catalog::{self, CATALOGUE, Content, Output, SimSpec};
use jacobs_ladder::model::ladder::itheta;
use jacobs_ladder::scenes::{self, MovieOptions, dynamic};

const SMALL: MovieOptions = MovieOptions {
    frames: 3,
    width: 160,
    height: 120,
    fps: 10.0,
};

#[test]
fn every_catalogue_entry_renders() {
    for entry in CATALOGUE {
        let files = scenes::render(entry, &SMALL)
            .unwrap_or_else(|e| panic!("{} {}: {e}", entry.id, entry.title));
        assert_eq!(files.len(), entry.files().len(), "{}", entry.id);
        for (name, bytes) in &files {
            assert!(bytes.len() > 100, "{name} is nearly empty");
            let magic: &[u8] = if name.ends_with(".gif") {
                b"GIF89a"
            } else {
                b"\x89PNG"
            };
            assert!(bytes.starts_with(magic), "{name}");
        }
    }
}

fn movie_sim(id: &str) -> SimSpec {
    match catalog::find(Output::Movie, id).unwrap().content {
        Content::Movie { sim, .. } => sim,
        _ => unreachable!("movies hold a simulation"),
    }
}

/// Signs of θ_n of every block at every frame of a movie.
fn frame_signs(id: &str, frames: usize) -> Vec<Vec<f64>> {
    let sim = movie_sim(id);
    let traj = dynamic::run(&sim, &dynamic::frame_times(sim.t_end, frames)).unwrap();
    traj.states
        .iter()
        .map(|q| (0..sim.n).map(|i| q[itheta(i)].signum()).collect())
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
    assert!((dynamic::fitted_speed(&arrivals).unwrap() - 4.0).abs() < 1e-9);
    assert!(dynamic::fitted_speed(&[Some(1.0), Some(2.0), None, None]).is_none());
}

#[test]
fn golden_figure_3() {
    let entry = catalog::find(Output::Figure, "3").unwrap();
    let Content::Strips(strips) = entry.content else {
        unreachable!("figure 3 is strips")
    };
    let image = dynamic::strips_figure("Fig. 3", strips, (86, 200)).unwrap();
    check("figure-3-small", &image);
}

#[test]
fn golden_kymograph_movie_7() {
    let sim = movie_sim("7");
    let traj = dynamic::run(&sim, &dynamic::frame_times(sim.t_end, 60)).unwrap();
    let image = dynamic::kymograph_image("Movie 7", &traj, sim.n, 320, 240).unwrap();
    check("kymograph-movie-7", &image);
}
