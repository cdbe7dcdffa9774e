//! The theory figures' data files hold the numbers they draw
//! (`drawn`): checked against the figure's own scene and against closed
//! forms computed here, not by the program.

use crate::captions::figure_data;
use serde_json::Value;

fn drawn(id: &str) -> Value {
    let d = figure_data(id);
    assert!(d["runs"].as_array().unwrap().is_empty(), "{id}: no run");
    d["drawn"].clone()
}

fn scene(id: &str) -> jacobs_ladder::scene::Scene {
    jacobs_ladder::catalog::find(jacobs_ladder::scene::Kind::Figure, id)
        .unwrap()
        .scene
        .clone()
}

/// The barrier's curve is ΔU(α) = 2b(1 − √(1 − sin⁴α / b²)) (mgs per
/// pair, s = 1; the paper's eq:delta_U) at every drawn α, and the model's
/// dots agree with it.
#[test]
fn the_barrier_data_is_the_closed_form_drawn() {
    let d = drawn("barrier");
    assert_eq!(d["figure"], "barrier");
    let b = scene("barrier").model.b;
    let du = |a: f64| 2.0 * b * (1.0 - (1.0 - a.to_radians().sin().powi(4) / (b * b)).sqrt());
    let curve = d["curve"].as_array().unwrap();
    assert!(curve.len() > 100);
    for p in curve {
        let (a, u) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
        assert!((u - du(a)).abs() < 1e-9, "α = {a}: {u} against {}", du(a));
    }
    let model = d["model"].as_array().unwrap();
    assert!(model.len() >= 10);
    for p in model {
        let (a, u) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
        assert!((u - du(a)).abs() < 1e-3, "model at α = {a}: {u}");
    }
}

/// Winding: the loop for α > 0 winds once about the origin, for α < 0
/// not at all (the figure's panel titles n = 1, n = 0), counted here from
/// the drawn points of det C/(e^{iqb} − 1).
#[test]
fn the_winding_data_winds_as_drawn() {
    let d = drawn("winding");
    let loops = d["loops"].as_array().unwrap();
    assert_eq!(loops.len(), 2);
    for (l, expected) in loops.iter().zip([1, 0]) {
        let pts: Vec<(f64, f64)> = l["reduced"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
            .collect();
        let mut turn = 0.0;
        for k in 0..pts.len() {
            let (a, b) = (pts[k], pts[(k + 1) % pts.len()]);
            let mut d = b.1.atan2(b.0) - a.1.atan2(a.0);
            if d > std::f64::consts::PI {
                d -= 2.0 * std::f64::consts::PI;
            } else if d < -std::f64::consts::PI {
                d += 2.0 * std::f64::consts::PI;
            }
            turn += d;
        }
        let n = (turn / (2.0 * std::f64::consts::PI)).round().abs() as i64;
        assert_eq!(n, expected, "α = {}", l["alpha_deg"]);
        assert_eq!(l["winding_number"].as_i64(), Some(expected));
    }
}

/// Fig. 2c, S5 and the edge mode: one drawn curve per value of the
/// scene's list, and the shapes the captions describe (U's minima at
/// −2mgb, the edge mode largest at the top for α > 0 and at the bottom for
/// α < 0); the drawings hold no numbers.
#[test]
fn the_other_theory_data_files_hold_one_curve_per_value() {
    let spec = |id: &str| match scene(id).output {
        jacobs_ladder::scene::OutputSpec::Theory(s) => s,
        _ => panic!("{id} is a theory figure"),
    };
    let d = drawn("2c");
    let curves = d["curves"].as_array().unwrap();
    assert_eq!(curves.len(), spec("2c").a_over_b.len());
    for (c, m) in curves.iter().zip(d["minima"].as_array().unwrap().chunks(2)) {
        let b = c["b"].as_f64().unwrap();
        let lowest = c["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p[1].as_f64().unwrap())
            .fold(f64::MAX, f64::min);
        assert!((m[0][1].as_f64().unwrap() + 2.0 * b).abs() < 1e-12);
        assert!(
            lowest >= -2.0 * b - 1e-9 && lowest < -2.0 * b + 1e-3,
            "{lowest}"
        );
    }
    let d = drawn("S5");
    let n = spec("S5").alphas.len();
    assert_eq!(d["lines"].as_array().unwrap().len(), n);
    assert_eq!(d["dots"].as_array().unwrap().len(), n);
    let d = drawn("edge-mode");
    let profiles = d["profiles"].as_array().unwrap();
    assert_eq!(profiles.len(), 2 * spec("edge-mode").alphas.len());
    for p in profiles {
        let v: Vec<f64> = p["numerical"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        let top = p["alpha_deg"].as_f64().unwrap() > 0.0;
        let edge = if top { v[0] } else { *v.last().unwrap() };
        assert!((edge - 1.0).abs() < 1e-9, "{}: {v:?}", p["alpha_deg"]);
    }
    for id in ["2b", "2d", "S3", "S4"] {
        assert!(
            figure_data(id).get("drawn").is_none(),
            "{id} draws no numbers"
        );
    }
}
