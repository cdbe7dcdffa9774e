//! Every parameter of the table (`model::table`) appears in every front
//! end with the same default and range, each read from the program (its
//! `--help`, a default scene serialised, the sweep's axes, a data file),
//! never from a copy: the flags of each command that takes it, the
//! scene file's keys, the sweep's axes and columns, the data file's
//! fields. Python's keywords, `.pyi` and docstrings are checked against
//! the same table (`ParamInfo::all`) by the Python tests
//! (tests/python/), which extend [`front_ends`].

use crate::common::ladder_cli;
use jacobs_ladder::scene::params::{Param, ParamInfo, Place};
use jacobs_ladder::scene::{Model, Scene};

/// The front ends checked here; the Python tests add theirs (keywords,
/// `.pyi`, docstrings) against the same `ParamInfo::all()`.
fn front_ends() -> [&'static str; 4] {
    ["--help", "scene file", "sweep axes", "data file"]
}

fn help(command: &[&str]) -> String {
    let mut args = command.to_vec();
    args.push("--help");
    let out = ladder_cli(&args);
    assert_eq!(out.status.code(), Some(0), "{command:?}");
    String::from_utf8(out.stdout).unwrap()
}

/// The help of `flag`: its line and the lines that continue it (clap
/// puts a long help under its flag), up to the next flag or heading.
fn flag_help(text: &str, flag: &str, value_name: &str) -> Option<String> {
    let start = text.find(&format!("{flag} <{value_name}>"))?;
    let mut lines = text[start..].lines();
    let mut help = lines.next()?.to_string();
    for line in lines {
        let t = line.trim_start();
        if t.is_empty() || t.starts_with('-') || !line.starts_with(' ') {
            break;
        }
        help.push(' ');
        help.push_str(t);
    }
    Some(help)
}

#[test]
fn every_parameter_is_a_flag_with_the_tables_default_and_range() {
    assert_eq!(front_ends().len(), 4);
    for command in [&["simulate"][..], &["movie"], &["figure"]] {
        let text = help(command);
        for p in Param::ALL {
            let s = p.spec();
            let line = flag_help(&text, &p.flag(), s.value_name)
                .unwrap_or_else(|| panic!("{command:?}: no {} in\n{text}", p.flag()));
            let default = format!("[default: {}]", s.default_text());
            assert!(line.contains(&default), "{command:?} {}: {line}", p.flag());
            assert!(
                line.contains(&s.range_text(true)),
                "{command:?} {}: {line}",
                p.flag()
            );
            // The default parses back to the table's value.
            let typed: f64 = s.default_text().parse().unwrap();
            assert_eq!(typed, s.default, "{}", p.name());
        }
    }
    let sweep = help(&["sweep"]);
    for p in Param::ALL {
        assert!(
            flag_help(&sweep, &p.flag(), "RANGE").is_some(),
            "sweep: no axis flag {}",
            p.flag()
        );
    }
    let theory = help(&["theory"]);
    for p in [Param::Alpha, Param::N, Param::B] {
        let line = flag_help(&theory, &p.flag(), p.spec().value_name).unwrap();
        assert!(
            line.contains(&format!("[default: {}]", p.spec().default_text())),
            "theory {}: {line}",
            p.flag()
        );
    }
}

#[test]
fn every_parameter_is_a_scene_key_with_the_tables_default() {
    // The default scene, serialised as `ladder scene` writes a file.
    let text = toml::to_string(&Scene::default()).unwrap();
    let value: toml::Value = toml::from_str(&text).unwrap();
    let model = value["model"].as_table().unwrap();
    for p in Param::ALL {
        let s = p.spec();
        match s.place {
            Place::Model => {
                let v = &model[s.name];
                let x = v.as_float().or(v.as_integer().map(|i| i as f64)).unwrap();
                assert_eq!(x, s.default, "[model] {}", s.name);
            }
            Place::Drive => {
                let flips = value["drive"]["flips"].as_array().unwrap();
                assert_eq!(flips[0]["duration"].as_float(), Some(s.default));
            }
        }
    }
    // [model] holds the table's parameters and `start`, nothing else.
    assert_eq!(model.len(), Param::MODEL.len() + 1, "{model:?}");
    // Each bound of a model parameter's range is accepted, a value past
    // it refused naming the key (checks from the table's range).
    for p in Param::MODEL {
        let s = p.spec();
        let (lo, hi) = (s.range.min(), s.range.max());
        for (x, ok) in [(lo, true), (hi, true)] {
            if !x.is_finite() || (p == Param::Alpha && x.abs() == hi) {
                continue;
            }
            let mut scene = Scene::default();
            scene.model.set(p, x);
            assert_eq!(scene.check().is_ok(), ok, "{} = {x}", s.name);
        }
        let mut past = Scene::default();
        past.model
            .set(p, if lo.is_finite() { lo - 1.0 } else { f64::NAN });
        let (key, msg) = past.check().unwrap_err();
        assert_eq!(key, format!("model.{}", s.name), "{msg}");
    }
}

#[test]
fn every_parameter_is_a_sweep_axis_and_a_column() {
    use jacobs_ladder::scene::sweep::{Grid, SweepSpec, Values};
    let axes: Vec<&str> = Param::ALL.iter().map(|p| p.name()).collect();
    let info: Vec<&str> = ParamInfo::all().iter().map(|i| i.name).collect();
    assert_eq!(axes, info);
    for p in Param::ALL {
        let spec = SweepSpec {
            grid: Grid::new(vec![(p, Values::parse(&p.spec().default_text()).unwrap())]),
            ..SweepSpec::default()
        };
        let text = toml::to_string(&spec).unwrap();
        assert!(text.contains(p.name()), "{text}");
        let back: SweepSpec = toml::from_str(&text).unwrap();
        assert_eq!(back.grid.0[0].0, p);
        let at = spec.scene_at(&Scene::default(), &[p.default_value()]);
        assert_eq!(at.param(p), p.default_value());
    }
    // The message of a sweep given no axis lists every flag.
    let out = ladder_cli(&["sweep"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    for p in Param::ALL {
        assert!(err.contains(&p.flag()), "{err}");
    }
}

#[test]
fn every_parameter_is_a_data_field_with_the_value_run() {
    let out = ladder_cli(&["simulate", "--t-end", "10", "--json"]);
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let defaults = Model::default();
    for p in Param::ALL {
        let s = p.spec();
        let recorded = match s.place {
            Place::Model => v["model"][s.name].as_f64(),
            Place::Drive => v["drive"]["flips"][0]["duration"].as_f64(),
        };
        assert_eq!(recorded, Some(s.default), "{}", s.name);
        if s.place == Place::Model {
            assert_eq!(defaults.get(p), Some(s.default));
            assert_eq!(v["scene"]["model"][s.name].as_f64(), Some(s.default));
        }
    }
    // What the front ends read of the table: every field, as JSON.
    let table = serde_json::to_value(ParamInfo::all()).unwrap();
    assert_eq!(table.as_array().unwrap().len(), Param::ALL.len());
    assert_eq!(table[1]["kind"], "int");
    assert_eq!(table[0]["symbol"], "α");
}
