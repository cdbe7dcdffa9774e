//! The experiments' movies (docs/experiments.md): the printed linkage at
//! the friction where its antikink stops, ending once the front has
//! decided; the water tank until every block has flipped, in seconds,
//! played in real time.

use jacobs_ladder::catalog;
use jacobs_ladder::scene::{Kind, Scene};
use jacobs_ladder::scenes::MovieOptions;
use jacobs_ladder::scenes::experiments;
use jacobs_ladder::scenes::movie::SecondsClock;
use serde_json::Value;

use crate::common::tempdir::TempDir;

fn scene(kind: Kind, id: &str) -> Scene {
    catalog::find(kind, id).unwrap().scene.clone()
}

/// τ of a scene's apparatus (s).
fn tau_s(s: &Scene) -> f64 {
    s.apparatus
        .as_ref()
        .unwrap()
        .conversion
        .as_ref()
        .unwrap()
        .tau_s
}

/// `ladder movie ID` with two frames (the run is the movie's whatever the
/// frames): its data file.
fn movie_data(id: &str) -> Value {
    let dir = TempDir::new(&format!("movie-{id}"));
    let out =
        crate::common::ladder_cli(&["movie", id, "--frames", "2", "--out", dir.to_str().unwrap()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(dir.join(format!("movie-{id}.json"))).unwrap();
    serde_json::from_str(&text).unwrap()
}

/// The linkage movie runs at a μ_p where the figure's kink runs all the
/// way and its antikink stops (the supplement's observation), and it ends
/// at most 1 s after that antikink's front has decided, never before.
#[test]
fn the_linkage_movie_shows_its_antikink_stopping_and_ends_when_decided() {
    let movie = scene(Kind::Movie, "linkage-69");
    let mu = movie.apparatus.as_ref().unwrap().pin_friction;
    let figure = scene(Kind::Figure, "linkage-friction");
    let n = figure.model.n;
    let (rows, data) = experiments::fronts(&figure, &[mu]).unwrap();
    let (_, kink, antikink) = rows[0];
    assert_eq!(kink, n, "the kink runs at μ_p = {mu}");
    assert!(antikink < n, "the antikink stops at μ_p = {mu}: {antikink}");
    assert!(movie.model.alpha < 0.0, "the movie shows the antikink");
    let decided = data[1].t_end;
    let end = movie.run.t_end;
    let tau = tau_s(&movie);
    assert!(
        end >= decided && end <= decided + 1.0 / tau,
        "the movie ends at {} s, the front decided at {} s",
        end * tau,
        decided * tau
    );
    let caption = movie.caption.clone().unwrap_or_default();
    assert!(
        caption.contains(&format!("after {antikink} of the {n} blocks")),
        "{caption}"
    );
    assert!(caption.contains(&format!("μₚ = {mu}")), "{caption}");
    // The movie's own run flips as many blocks as the figure's.
    let d = movie_data("linkage-69");
    let flipped = d["runs"][0]["arrival_times"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|t| !t.is_null())
        .count();
    assert_eq!(flipped, antikink);
}

/// The tank movie: every block has flipped, the frames after the last
/// flip are at most a fifth of the movie, and at the default 200 frames
/// at 25 frames/s it plays in real time, its clock in seconds.
#[test]
fn the_water_tank_movie_is_in_seconds_in_real_time_without_a_still_tail() {
    let movie = scene(Kind::Movie, "water-tank");
    let d = movie_data("water-tank");
    let run = &d["runs"][0];
    let arrivals: Vec<f64> = run["arrival_times"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| t.as_f64().expect("every block flips"))
        .collect();
    let last = arrivals.iter().copied().fold(0.0, f64::max);
    let end = run["t_end"].as_f64().unwrap();
    assert!(
        end - last <= 0.2 * end,
        "still for {:.0} % of the movie",
        100.0 * (end - last) / end
    );
    let clock = SecondsClock::of(&movie, &MovieOptions::default()).unwrap();
    assert!((clock.speed_up - 1.0).abs() < 0.02, "{clock:?}");
    let tau = tau_s(&movie);
    assert_eq!(clock.label(1.0 / tau), "t = 1.00 s (real time)");
}

/// The clock of an apparatus movie says how it plays: slowed, sped up or
/// in real time; a scene without an apparatus has none.
#[test]
fn an_apparatus_clock_says_how_the_movie_plays() {
    let mut movie = scene(Kind::Movie, "water-tank");
    let opts = MovieOptions::default();
    let tau = tau_s(&movie);
    movie.run.t_end = 2.0 * opts.frames as f64 / opts.fps / tau;
    assert_eq!(
        SecondsClock::of(&movie, &opts).unwrap().rate(),
        "played 2.0× faster"
    );
    movie.run.t_end /= 8.0;
    assert_eq!(
        SecondsClock::of(&movie, &opts).unwrap().rate(),
        "played 4.0× slower"
    );
    assert!(SecondsClock::of(&scene(Kind::Movie, "4"), &opts).is_none());
}

/// A movie's last frame is at its window's end exactly, whatever the
/// window (the tank's 8 s in τ: t_end · 199 / 199 rounds above t_end).
#[test]
fn the_last_frame_time_is_the_window_end() {
    let t_end = scene(Kind::Movie, "water-tank").run.t_end;
    for frames in [2, 199, 200, 201, 5000] {
        let t = jacobs_ladder::scene::even_times(t_end, frames);
        assert_eq!(t.len(), frames);
        assert_eq!(*t.last().unwrap(), t_end, "{frames} frames");
        assert!(t.windows(2).all(|w| w[0] < w[1]));
    }
}
