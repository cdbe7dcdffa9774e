//! The experiments' figures (SPEC section 12; docs/experiments.md) against
//! what their captions say: each level of model's kink speed and ratio in
//! the water tank, the "stiff" links' k-and-2k check, and the printed
//! linkage's antikink that stops where the kink runs.

use jacobs_ladder::scene::Scene;
use jacobs_ladder::scene::file::parse;
use jacobs_ladder::scenes::experiments::{self, MEASURED_KINK_CM_S, MEASURED_RATIO};

/// The scene file `assets/scenes/figure-NAME.toml` (not yet in the
/// built-in catalogue: `ladder render` it).
fn figure(name: &str, text: &str) -> Scene {
    parse(text, &format!("assets/scenes/figure-{name}.toml"), name).unwrap()
}

#[test]
fn each_level_of_model_lands_where_the_caption_says() {
    let scene = figure(
        "tank-levels",
        include_str!("../../assets/scenes/figure-tank-levels.toml"),
    );
    let caption = scene.caption.clone().unwrap_or_default();
    let (levels, data) = experiments::levels(&scene).unwrap();
    assert_eq!(data.len(), 3 * levels.len(), "every run is in the data");
    for r in &levels {
        println!(
            "{}: kink {:?}, antikink {:?}, ratio {:?}, 2k {:?} cm/s",
            r.name,
            r.kink_cm_s,
            r.antikink_cm_s,
            r.ratio(),
            r.kink_2k_cm_s
        );
    }
    // The three levels that run a wave: each kink faster than measured,
    // named in the caption with its speed and its factor; its ratio is
    // near 1, not 1.75; "stiff" links pass the k-and-2k check.
    for r in &levels[..3] {
        let c = r.kink_cm_s.unwrap_or_else(|| panic!("{}: no wave", r.name));
        assert!(c > 1.5 * MEASURED_KINK_CM_S, "{}: {c} cm/s", r.name);
        let (speed, times) = (
            format!("{c:.1} cm/s"),
            format!("{:.1} times", c / MEASURED_KINK_CM_S),
        );
        assert!(
            caption.contains(&speed) && caption.contains(&times),
            "{}: the caption lacks {speed} or {times}: {caption}",
            r.name
        );
        let q = r.ratio().unwrap();
        assert!(
            (q - 1.0).abs() < 0.15 && (q - MEASURED_RATIO).abs() > 0.5,
            "{q}"
        );
        assert!(caption.contains(&format!("{q:.2}")), "{}: {q:.2}", r.name);
        let d = r.stiff_difference().unwrap();
        assert!(d < experiments::STIFF_TOLERANCE, "{}: k vs 2k {d}", r.name);
    }
    // Each added term slows the kink.
    let c: Vec<f64> = levels[..3].iter().map(|r| r.kink_cm_s.unwrap()).collect();
    assert!(c[0] > c[1] && c[1] > c[2], "{c:?}");
    // The tape, alone or with every term: no wave, drawn and said so.
    for r in &levels[3..] {
        assert_eq!(r.kink_cm_s, None, "{}", r.name);
    }
    assert!(caption.contains("no wave"));
}

#[test]
fn the_linkage_antikink_stops_where_the_kink_runs() {
    let scene = figure(
        "linkage-friction",
        include_str!("../../assets/scenes/figure-linkage-friction.toml"),
    );
    let n = scene.model.n;
    let (rows, _) = experiments::fronts(&scene, &[0.0, 0.9]).unwrap();
    println!("(μ_p, kink, antikink): {rows:?}");
    // Without friction both run the whole chain (the spring model's
    // answer); at μ_p = 0.9 the kink still does and the antikink stops in
    // the upper half.
    assert_eq!(rows[0], (0.0, n, n));
    let (_, kink, antikink) = rows[1];
    assert_eq!(kink, n);
    assert!((1..=n / 2).contains(&antikink), "{antikink}");
}

#[test]
fn the_bulk_speed_needs_a_wave_running_down() {
    use experiments::bulk_speed;
    let down: Vec<Option<f64>> = (0..10).map(|k| Some(100.0 * k as f64)).collect();
    // Lower half, blocks 6..9: one block per 100 τ.
    assert!((bulk_speed(&down).unwrap() - 0.01).abs() < 1e-15);
    let mut up = down.clone();
    up[7] = Some(450.0);
    assert_eq!(bulk_speed(&up), None, "a block before the one above it");
    let mut short = down.clone();
    short[8] = None;
    assert_eq!(bulk_speed(&short), None, "a block that never flipped");
}
