//! Captions against the data files: each figure is drawn by the `ladder`
//! binary as a user draws it (`ladder all`, the shared render of the
//! catalogue: `common::catalogue_render`), and every number its caption
//! gives is one of the numbers listed here, each made from the figure's
//! data file (or its scene); a number in a caption that no data accounts
//! for fails the test, and so does a listed number the caption lacks.
//! Captions name no marker shape (the legend does, and the palette decides
//! them).

use serde_json::Value;

/// The caption of the built-in scene `kind id`.
fn caption(kind: jacobs_ladder::scene::Kind, id: &str) -> String {
    jacobs_ladder::catalog::find(kind, id)
        .unwrap()
        .scene
        .caption
        .clone()
        .unwrap_or_default()
}

fn figure_caption(id: &str) -> String {
    caption(jacobs_ladder::scene::Kind::Figure, id)
}

/// Figure `id`'s data file as `ladder` writes it: read from the shared
/// render of the catalogue (`ladder all`, made once for every test that
/// reads it) instead of a `ladder figure ID` of its own, which simulated
/// the figure again (the chain-length sweep, the linkage's 18 runs, the
/// ribbon tank: about 9 s of the captions' 10). The two data files differ
/// only in what no caption reads: the command line, the files written
/// and the formats asked (`settings`); compared whole for figure 4b by
/// `timings::figure_4b_in_the_catalogue_is_figure_4b_alone`.
pub fn figure_data(id: &str) -> Value {
    let (dir, _) = crate::common::catalogue_render();
    let text = std::fs::read_to_string(dir.join(format!("figure-{id}.json"))).unwrap();
    serde_json::from_str(&text).unwrap()
}

/// Asserts that `caption` holds every one of `numbers` and no digit
/// besides theirs: each number of the caption is accounted for.
pub fn accounted(name: &str, caption: &str, numbers: &[String]) {
    // Names with a digit that are no number: the integrators'.
    let mut rest = caption.replace("RK4", " ").replace("dopri5", " ");
    let mut sorted: Vec<&String> = numbers.iter().collect();
    sorted.sort_by_key(|s| std::cmp::Reverse(s.chars().count()));
    for s in sorted {
        assert!(
            rest.contains(s.as_str()),
            "{name}: the caption lacks \"{s}\" (from the data): {caption}"
        );
        rest = rest.replace(s.as_str(), " ");
    }
    let digits = |c: char| c.is_ascii_digit() || "⁰¹²³⁴⁵⁶⁷⁸⁹₀₁₂₃₄₅₆₇₈₉".contains(c);
    let stray: Vec<&str> = rest
        .split(|c: char| c.is_whitespace())
        .filter(|w| w.chars().any(digits))
        .collect();
    assert!(
        stray.is_empty(),
        "{name}: numbers in the caption no data accounts for: {stray:?}"
    );
}

/// `x` to three significant figures, thousands set apart by a space
/// ("23 300", "4860", "278").
pub fn sig3(x: f64) -> String {
    let e = x.abs().log10().floor() as i32;
    let step = 10f64.powi(e - 2);
    let r = (x / step).round() * step;
    let digits = if e >= 2 { 0 } else { (2 - e) as usize };
    let s = format!("{r:.digits$}");
    if r.abs() >= 10_000.0 {
        let (int, frac) = s.split_once('.').unwrap_or((&s, ""));
        let mut out = String::new();
        for (k, c) in int.chars().enumerate() {
            if k > 0 && (int.len() - k) % 3 == 0 {
                out.push(' ');
            }
            out.push(c);
        }
        if frac.is_empty() {
            out
        } else {
            format!("{out}.{frac}")
        }
    } else {
        s
    }
}

/// A degree value as captions write it: "52.5°", "50°".
fn deg(x: f64) -> String {
    format!("{}°", num(x))
}

/// A number as short as it is exact to 0.1: "52.5", "50".
fn num(x: f64) -> String {
    if (x - x.round()).abs() < 1e-9 {
        format!("{x:.0}")
    } else {
        format!("{x:.1}")
    }
}

fn f(v: &Value) -> Option<f64> {
    v.as_f64()
}

fn runs(data: &Value) -> &Vec<Value> {
    data["runs"].as_array().unwrap()
}

#[test]
fn no_caption_names_a_marker_shape() {
    // ("ring" is left out: figure 4b's key rings are rings.)
    const SHAPES: [&str; 12] = [
        "circle",
        "circles",
        "square",
        "squares",
        "triangle",
        "triangles",
        "cross",
        "crosses",
        "diamond",
        "diamonds",
        "star",
        "stars",
    ];
    for e in jacobs_ladder::catalog::catalogue().unwrap() {
        let c = e.scene.caption.clone().unwrap_or_default().to_lowercase();
        for w in c.split(|ch: char| !ch.is_alphabetic() && ch != '-') {
            assert!(
                !SHAPES.contains(&w),
                "{}: the caption names the marker shape \"{w}\" (the legend does): {c}",
                e.id
            );
        }
    }
}

/// Figure 3 (a2): the free bottom block's sin θ changes sign at the
/// time the caption gives, because the block turns over backwards
/// through 180° to the angle the caption gives (not the flipped +60°),
/// and stays there: run twice as long, it rests beyond 90° still.
#[test]
fn figure_3_caption_matches_its_data() {
    let data = figure_data("3");
    let run = |label: &str| {
        runs(&data)
            .iter()
            .find(|r| r["label"] == label)
            .unwrap_or_else(|| panic!("no run {label}"))
    };
    let a2 = run("(a2)");
    let n = a2["arrival_times"].as_array().unwrap().len();
    let t_n = f(&a2["arrival_times"][n - 1]).expect("block N's sin θ changes sign");
    let theta_n = f(&a2["final_theta_deg"][n - 1]).unwrap();
    assert!(theta_n > 90.0 && theta_n <= 180.0, "{theta_n}");
    for i in 1..n - 1 {
        let th = f(&a2["final_theta_deg"][i]).unwrap();
        assert!(th > 0.0, "block {}: {th}", i + 1);
    }
    let alpha = f(&a2["model"]["alpha"]).unwrap();
    let longer = crate::common::ladder_cli(&[
        "simulate",
        "--alpha",
        &num(alpha),
        "--integrator",
        "verlet",
        "--dt",
        "0.125",
        "--t-end",
        &format!("{}", 2.0 * f(&a2["t_end"]).unwrap()),
        "--json",
    ]);
    let longer: Value = serde_json::from_slice(&longer.stdout).unwrap();
    let rest = f(&longer["final_theta_deg"][n - 1]).unwrap();
    assert!(rest > 90.0, "block N at twice the window: {rest}");
    assert!(run("(b2)")["blocks_flipped"].as_u64().unwrap() <= 2);
    let numbers = vec![
        "(a1)".into(),
        "(a2)".into(),
        "(b1)".into(),
        "(b2)".into(),
        format!("{t_n:.0} τ"),
        format!("{theta_n:.0}°"),
        format!("+{}°", num(-alpha)),
        "180°".into(), // turning over backwards passes ±180°
    ];
    accounted("figure 3", &figure_caption("3"), &numbers);
}

/// The chain-length sweep: where the kink waits at block 2 and for how
/// long, from the sweep's own arrival times.
#[test]
fn chain_length_caption_matches_its_data() {
    let data = figure_data("chain-length");
    let mut runs: Vec<(f64, &Value)> = runs(&data)
        .iter()
        .map(|r| (f(&r["point"]["n"]).unwrap(), r))
        .collect();
    runs.sort_by(|a, b| a.0.total_cmp(&b.0));
    let wait = |r: &Value| Some(f(&r["arrival_times"][2])? - f(&r["arrival_times"][1])?);
    // Runs where block 3 flips more than 1000 τ after block 2 wait there.
    let waits: Vec<(f64, f64)> = runs
        .iter()
        .filter_map(|(n, r)| wait(r).filter(|w| *w > 1000.0).map(|w| (*n, w)))
        .collect();
    assert_eq!(waits.len(), 2, "{waits:?}");
    let quick: Vec<&(f64, &Value)> = runs
        .iter()
        .filter(|(_, r)| wait(r).is_some_and(|w| w <= 1000.0))
        .collect();
    let (n_quick, r_quick) = quick.last().unwrap();
    let quick_wait = (wait(r_quick).unwrap() / 10.0).ceil() * 10.0;
    let pinned: Vec<&(f64, &Value)> = runs
        .iter()
        .filter(|(_, r)| r["outcome"] == "pinned")
        .collect();
    let (n_pinned, r_pinned) = pinned[0];
    assert!(pinned.iter().all(|(_, r)| r["front"] == 2));
    let last_run = runs
        .iter()
        .filter(|(_, r)| r["outcome"] == "propagated")
        .map(|(n, _)| *n)
        .fold(0.0, f64::max);
    assert_eq!(last_run + 1.0, *n_pinned);
    let numbers = vec![
        "α = 60°".into(),
        "b/s = 1.3".into(),
        "γ = 0.02".into(),
        "G = 2 × 10⁻⁴".into(),
        "dt = 0.25 τ".into(),
        format!("N = {} to {}", num(runs[0].0), num(runs.last().unwrap().0)),
        format!("N = {}", num(*n_quick)),
        format!("within {quick_wait:.0} τ"),
        format!("{} τ at N = {}", sig3(waits[0].1), num(waits[0].0)),
        format!("{} τ at N = {}", sig3(waits[1].1), num(waits[1].0)),
        format!("From N = {}", num(*n_pinned)),
        format!(
            "(N = {}: after {} τ)",
            num(*n_pinned),
            sig3(f(&r_pinned["t_decided"]).unwrap())
        ),
        format!("past {} blocks", num(last_run)),
        "block 2".into(),
        "block 3".into(),
    ];
    accounted("chain-length", &figure_caption("chain-length"), &numbers);
}

/// The pinning sweep: every threshold of α the caption gives, the 88°
/// kink's speed and why it is no one wave's, and the theory's numbers.
#[test]
fn pinning_caption_matches_its_data() {
    let data = figure_data("pinning");
    let at = |a: f64| {
        runs(&data)
            .iter()
            .find(|r| f(&r["point"]["alpha"]) == Some(a))
            .unwrap_or_else(|| panic!("no run at {a}"))
    };
    let alphas: Vec<f64> = runs(&data)
        .iter()
        .map(|r| f(&r["point"]["alpha"]).unwrap())
        .collect();
    let of = |sign: f64, outcome: &str| -> Vec<f64> {
        alphas
            .iter()
            .copied()
            .filter(|a| a * sign > 0.0 && at(*a)["outcome"] == outcome)
            .map(f64::abs)
            .collect()
    };
    let kink_runs = of(1.0, "propagated");
    let (k_lo, k_hi) = (kink_runs[0], *kink_runs.last().unwrap());
    assert!(
        kink_runs.windows(2).all(|w| w[1] - w[0] == 1.0),
        "{kink_runs:?}"
    );
    // Below: block N turned first; above: a bulk block flipped first.
    let annihilated = of(1.0, "annihilated");
    let below: Vec<f64> = annihilated.iter().copied().filter(|a| *a < k_lo).collect();
    let above: Vec<f64> = annihilated.iter().copied().filter(|a| *a > k_hi).collect();
    for a in &below {
        assert!(f(&at(*a)["block_n_turned_at"]).is_some(), "{a}");
    }
    assert_eq!(above.len(), 2, "{above:?}");
    let bulk_origin = |a: f64| at(a)["waves"]["waves"][1]["origin"].as_u64().unwrap();
    let r88 = at(above[0]);
    let waves88 = r88["waves"]["waves"].as_array().unwrap();
    assert_eq!(
        waves88.len(),
        3,
        "the driven kink, the wall, the kink sent down"
    );
    let met_at = waves88[0]["block"].as_u64().unwrap();
    let speed88 = f(&r88["speed"]).unwrap();
    let neighbour = f(&at(k_hi)["speed"]).unwrap();
    assert!(speed88 > 1.3 * neighbour, "{speed88} against {neighbour}");
    let pinned = of(-1.0, "pinned");
    let stalled = of(-1.0, "stalled");
    let anti = of(-1.0, "propagated");
    let p_hi = pinned.iter().copied().fold(0.0, f64::max);
    let s_lo = stalled.iter().copied().fold(90.0, f64::min);
    let s_hi = stalled.iter().copied().fold(0.0, f64::max);
    let a_lo = anti.iter().copied().fold(90.0, f64::min);
    assert!(p_hi < s_lo && s_hi < a_lo, "{p_hi} {s_lo} {s_hi} {a_lo}");
    let theory = |a: f64, key: &str| {
        data["theory"]
            .as_array()
            .unwrap()
            .iter()
            .find(|t| f(&t["alpha"]) == Some(a))
            .and_then(|t| f(&t[key]))
            .unwrap()
    };
    let (g50, g60) = (
        theory(-50.0, "gap_omega_plus_q0"),
        theory(-60.0, "gap_omega_plus_q0"),
    );
    let (u50, u60) = (theory(-50.0, "barrier"), theory(-60.0, "barrier"));
    let mantissa = speed88 / 10f64.powi(speed88.log10().floor() as i32);
    let numbers = vec![
        "N = 10".into(),
        "b/s = 1.3".into(),
        "dt = 0.25 τ".into(),
        "blocks 1 to N − 1".into(),
        format!("from {} to {}", deg(k_lo), deg(k_hi)),
        format!(
            "At {} and below",
            deg(below.iter().copied().fold(0.0, f64::max))
        ),
        format!("at {} and {}", deg(above[0]), deg(above[1])),
        format!(
            "(block {}, block {})",
            bulk_origin(above[0]),
            bulk_origin(above[1])
        ),
        format!("block 2 up to {}", deg(p_hi)),
        format!("stalls at {} to {}", deg(s_lo), deg(s_hi)),
        format!("propagates from {}", deg(a_lo)),
        format!(
            "at {} the kink's {mantissa:.1} × 10⁻³ blocks/τ",
            deg(above[0])
        ),
        format!("at block {met_at}"),
        format!("from block {}", bulk_origin(above[0])),
        "ω₊(0)".into(), // the gap at q = 0
        format!("{g50:.2} and {g60:.2}/τ"),
        format!("{u50:.2} and {u60:.2} mgs at 50° and 60°"),
    ];
    accounted("pinning", &figure_caption("pinning"), &numbers);
}

/// S6: where an antikink's point at block N is its free bottom block
/// turning over backwards (its sin θ changed sign but it ends beyond
/// 90°, not near the flipped +|α|), the caption says so for that α, and
/// for no other.
#[test]
fn s6_caption_says_which_antikink_s_last_point_is_no_flip() {
    let data = figure_data("S6");
    let c = figure_caption("S6");
    let mut backwards = 0;
    for r in runs(&data) {
        let alpha = f(&r["model"]["alpha"]).unwrap();
        let a = r["arrival_times"].as_array().unwrap();
        let n = a.len();
        let th = f(&r["final_theta_deg"][n - 1]).unwrap();
        let named = format!("At α = {}°", num(alpha).replace('-', "−"));
        let said = c.contains(&format!("{named} the antikink's last point"));
        let turned_over = alpha < 0.0 && f(&a[n - 1]).is_some() && th.abs() > 90.0;
        assert_eq!(said, turned_over, "α = {alpha}: block N ends at {th}: {c}");
        backwards += usize::from(turned_over);
    }
    assert!(backwards > 0);
    assert!(c.contains("over backwards"), "{c}");
}

/// The linkage's window of friction is the same in the figure's caption,
/// the movie's caption and docs/experiments.md, and is the one the
/// figure's data gives: the antikink stops and the kink runs at every
/// point inside it, and not at the points next to it.
#[test]
fn the_linkage_window_is_the_data_s_everywhere() {
    let data = figure_data("linkage-friction");
    let mut rows: Vec<(f64, usize, usize)> = Vec::new();
    for pair in runs(&data).chunks(2) {
        let flipped = |r: &Value| {
            r["arrival_times"]
                .as_array()
                .unwrap()
                .iter()
                .filter(|t| !t.is_null())
                .count()
        };
        let label = pair[0]["label"].as_str().unwrap();
        let mu: f64 = label.rsplit("= ").next().unwrap().parse().unwrap();
        rows.push((mu, flipped(&pair[0]), flipped(&pair[1])));
    }
    let n = 8;
    let inside: Vec<&(f64, usize, usize)> =
        rows.iter().filter(|(_, k, a)| *k == n && *a < n).collect();
    let (lo, hi) = (inside[0].0, inside.last().unwrap().0);
    let stopped: Vec<usize> = inside.iter().map(|r| r.2).collect();
    let window = format!("{lo:?} ≤ μₚ ≤ {hi:?}");
    let first_kink_stop = rows.iter().find(|(_, k, _)| *k < n).unwrap().0;
    let fig = figure_caption("linkage-friction");
    let numbers = vec![
        "a = 7, b = 6, s = 5 cm, 8 blocks".into(),
        "1.5 mm".into(),
        "0.2 Hz".into(),
        "0.5 s".into(),
        "0.125 apart".into(),
        window.clone(),
        format!(
            "after {} or {} of the 8 blocks",
            stopped.iter().min().unwrap(),
            stopped.iter().max().unwrap()
        ),
        format!("from μₚ = {first_kink_stop}"),
        "0.125 τ".into(),
    ];
    accounted("linkage-friction", &fig, &numbers);
    let movie = caption(jacobs_ladder::scene::Kind::Movie, "linkage-69");
    assert!(movie.contains(&window), "{movie}");
    let docs = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/experiments.md"))
        .unwrap();
    assert!(docs.contains(&format!("{lo:?} ≤ μ_p ≤ {hi:?}")), "docs");
}

/// "a, b and c".
pub fn list(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    }
}

/// The tank's positions figures, with links and with ribbons: each data
/// file has each run's arrival times in seconds from block 1's flip and
/// its bulk line (speed in cm/s); the caption's speeds, ratios, factor
/// and τ are those, and its integrator the runs'.
#[test]
fn tank_positions_caption_matches_its_data() {
    for id in ["tank-positions", "tank-positions-ribbons"] {
        let data = figure_data(id);
        accounted(id, &figure_caption(id), &tank_positions_numbers(&data));
    }
}

/// The numbers the caption of a tank positions figure (`data`) may say.
fn tank_positions_numbers(data: &Value) -> Vec<String> {
    let mut kink = Vec::new();
    let mut anti = Vec::new();
    let mut motors = Vec::new();
    let mut tau_s = 0.0;
    let mut integrators = Vec::new();
    for r in runs(data) {
        let label = r["label"].as_str().unwrap();
        let a = &r["apparatus"];
        assert_eq!(f(&a["since_block_1_s"][0]), Some(0.0), "{label}");
        tau_s = f(&a["tau_s"]).unwrap();
        let c = f(&a["bulk"]["speed_cm_s"]).unwrap_or_else(|| panic!("{label}: no bulk fit"));
        let motor = label.rsplit(", ").next().unwrap().trim_end_matches(" Hz");
        // The run's own drive is recorded: the motor's flip of 2|α|.
        let flip_s = f(&r["drive"]["flips"][0]["duration"]).unwrap() * tau_s;
        let alpha = f(&r["model"]["alpha"]).unwrap().abs();
        let hz: f64 = motor.parse().unwrap();
        assert!(
            (flip_s - 2.0 * alpha / 360.0 / hz).abs() < 1e-9,
            "{label}: a flip of {flip_s} s recorded"
        );
        if label.starts_with("kink") {
            kink.push(c);
            motors.push(motor.to_string());
        } else {
            anti.push(c);
        }
        integrators.push(r["integrator"]["name"].as_str().unwrap().to_string());
    }
    let measured = jacobs_ladder::scenes::experiments::MEASURED_KINK_CM_S;
    let spread =
        kink.iter().copied().fold(0.0, f64::max) / kink.iter().copied().fold(f64::MAX, f64::min);
    assert!(spread < 1.025, "the kink depends on the motor: {kink:?}");
    let times: Vec<f64> = kink.iter().map(|c| c / measured).collect();
    let (t_lo, t_hi) = (
        format!("{:.1}", times.iter().copied().fold(f64::MAX, f64::min)),
        format!("{:.1}", times.iter().copied().fold(0.0, f64::max)),
    );
    let factor = if t_lo == t_hi {
        t_lo
    } else {
        format!("{t_lo} to {t_hi}")
    };
    let one =
        |v: &[f64], d: usize| -> Vec<String> { v.iter().map(|x| format!("{x:.d$}")).collect() };
    let ratios: Vec<f64> = anti.iter().zip(&kink).map(|(a, k)| a / k).collect();
    let mut numbers = vec![
        format!("{} Hz", list(&motors)),
        format!("{} cm/s", list(&one(&kink, 1))),
        format!("{factor} times faster"),
        format!(
            "{} cm/s give ratios {}",
            list(&one(&anti, 1)),
            list(&one(&ratios, 2))
        ),
        format!(
            "measured {}",
            jacobs_ladder::scenes::experiments::MEASURED_RATIO
        ),
        format!("measured kink's {measured:.1} cm/s"),
        "block 1".into(),
        format!("τ = {:.2} ms", 1000.0 * tau_s),
    ];
    let apparatus = &data["scene"]["apparatus"];
    if apparatus["ribbons"].as_bool() == Some(true) {
        // Every run by dopri5 at the tolerance the caption says.
        assert!(integrators.iter().all(|i| i == "dopri5"), "{integrators:?}");
        let rtol = jacobs_ladder::scenes::experiments::RIBBON_RTOL;
        assert_eq!(rtol, 1e-6, "the caption says 10⁻⁶");
        numbers.extend([
            format!("{} cm thick", f(&apparatus["thickness"]).unwrap()),
            "tolerance of 10⁻⁶".into(),
        ]);
    } else {
        assert!(integrators.iter().all(|i| i == "rk4"), "{integrators:?}");
        numbers.push("0.125 τ".into());
    }
    numbers
}
