//! A grammar fuzz of the scene-file parser: 10 000 scene files
//! built from the keys of docs/scenes.md with hostile values (extreme,
//! non-finite, wrong-typed numbers; odd names; overlapping or huge flip
//! lists), with a fixed seed, in the normal suite. Where the mutation fuzz
//! of `tests/integration/scene_files.rs` mostly breaks the syntax, these files are
//! well-formed TOML, so they reach the checks of every value. Properties:
//!
//! - the parser never panics; a refusal is one line with exit status 2;
//! - a file it accepts can run: each of its simulations has a scenario
//!   and an integrator, and the cost check before a run (caps on steps × N
//!   and samples × N) answers "go" or a one-line refusal with exit 2,
//!   never a failure or a panic; `auto`'s ω_max is found.
//!
//! `LADDER_FUZZ_CASES=N` runs N cases instead, and `LADDER_FUZZ_SEED=K` (a
//! byte) another sequence (a run of 10 minutes is about 3 000 000
//! cases).

use crate::common::fuzz;
use jacobs_ladder::error::Error;
use jacobs_ladder::limits::Limits;
use jacobs_ladder::scene::{Fidelity, file};
use jacobs_ladder::sim;
use proptest::prelude::*;

/// Numbers a hostile user types, and a few things that are not numbers.
const NUMBERS: &[&str] = &[
    "0",
    "-0.0",
    "1",
    "2",
    "3",
    "10",
    "60",
    "-60",
    "45.5",
    "89.999",
    "90",
    "-90",
    "91",
    "0.01",
    "0.25",
    "1e-3",
    "1e3",
    "1e-17",
    "5e-324",
    "1e-320",
    "1e308",
    "-1e308",
    "nan",
    "inf",
    "-inf",
    "4000",
    "1e9",
    "1e12",
    "100000",
    "100001",
    "-1",
    "9223372036854775807",
    "18446744073709551616",
    "\"60\"",
    "true",
    "[1, 2]",
    "{ a = 1 }",
];

/// Plausible values, so that many files pass every check and reach the
/// run's cost check.
const PLAUSIBLE: &[&str] = &[
    "1", "2", "10", "60", "-60", "-45", "80", "0.25", "0.01", "0.1", "1.3", "0.02", "100", "1000",
    "4000",
];

const WORDS: &[&str] = &[
    "\"\"",
    "\"k70\"",
    "\"a-b_c.d\"",
    "\".hidden\"",
    "\"../escape\"",
    "\"with space\"",
    "\"ü\"",
    "\"x\\u0000y\"",
    "\"aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\"",
    "\"auto\"",
    "\"verlet\"",
    "\"dopri5\"",
    "\"symplectic-euler\"",
    "\"rk5\"",
    "\"movie\"",
    "\"filmstrip\"",
    "\"kymograph\"",
    "\"arrivals\"",
    "\"data\"",
    "\"theory\"",
    "\"dispersion\"",
    "\"zero-modes\"",
    "\"fixed\"",
    "\"follow\"",
    "1",
];

/// A picker over a pool, driven by the strategy's random indices.
struct Picks<'a>(std::slice::Iter<'a, usize>);

impl Picks<'_> {
    fn next(&mut self) -> usize {
        self.0.next().copied().unwrap_or(0)
    }

    /// Whether to write an optional key (about half the time).
    fn some(&mut self) -> bool {
        self.next().is_multiple_of(2)
    }

    fn number(&mut self) -> &'static str {
        NUMBERS[self.next() % NUMBERS.len()]
    }

    fn word(&mut self) -> &'static str {
        WORDS[self.next() % WORDS.len()]
    }

    /// A plausible value of `key` (most of the time), else [`Picks::value`].
    fn value_for(&mut self, key: &str) -> &'static str {
        let plausible: &[&'static str] = match key {
            "alpha" => &["60", "-60", "45", "80", "-75", "30"],
            "n" => &["2", "10", "30", "100", "1000"],
            "b" => &["1.3", "1.1", "2"],
            "gamma" | "gravity" => &["0.02", "0", "2e-4"],
            "inertia" => &["0.25", "1"],
            "t_end" | "start" | "duration" => &["0", "500", "1000", "4000"],
            "dt" => &["0.01", "0.1"],
            "rtol" => &["1e-6", "1e-9"],
            "tolerance" => &["0.1", "1"],
            "name" | "label" | "title" | "caption" => &["\"k70\"", "\"a-b_c.d\""],
            "integrator" => &["\"auto\"", "\"verlet\"", "\"dopri5\"", "\"rk4\""],
            "kind" => &[
                "\"movie\"",
                "\"filmstrip\"",
                "\"kymograph\"",
                "\"arrivals\"",
                "\"data\"",
            ],
            _ => &[],
        };
        if !plausible.is_empty() && !self.next().is_multiple_of(4) {
            plausible[self.next() % plausible.len()]
        } else if key == "integrator" || key == "kind" || key == "name" {
            self.word()
        } else {
            self.value()
        }
    }

    /// A plausible number (most of the time), a hostile one, or now and
    /// then a word.
    fn value(&mut self) -> &'static str {
        match self.next() % 16 {
            0 => self.word(),
            1..=5 => self.number(),
            _ => PLAUSIBLE[self.next() % PLAUSIBLE.len()],
        }
    }

    fn list(&mut self, max: usize) -> String {
        let n = self.next() % (max + 1);
        let items: Vec<&str> = (0..n).map(|_| self.value()).collect();
        format!("[{}]", items.join(", "))
    }

    /// An inline table of model keys.
    fn model_table(&mut self) -> String {
        let keys = ["alpha", "n", "b", "gamma", "gravity", "inertia", "alpah"];
        let mut parts = Vec::new();
        for k in keys {
            let wanted = (k != "alpah" || self.next().is_multiple_of(16)) && self.some();
            if wanted {
                parts.push(format!("{k} = {}", self.value_for(k)));
            }
        }
        format!("{{ {} }}", parts.join(", "))
    }
}

/// A scene file from the pool indices `p`.
fn scene_text(p: &[usize]) -> String {
    let mut p = Picks(p.iter());
    let mut t = String::new();
    for key in ["name", "label", "title", "caption"] {
        if p.next() % 3 == 0 {
            t += &format!("{key} = {}\n", p.value_for(key));
        }
    }
    t += "[model]\n";
    for key in ["alpha", "n", "b", "gamma", "gravity", "inertia"] {
        if p.some() {
            t += &format!("{key} = {}\n", p.value_for(key));
        }
    }
    if p.some() {
        t += "[drive]\n";
        let flips = p.next() % 5;
        let list: Vec<String> = (0..flips)
            .map(|_| {
                let start = p.value_for("start");
                format!(
                    "{{ start = {start}, duration = {} }}",
                    p.value_for("duration")
                )
            })
            .collect();
        t += &format!("flips = [{}]\n", list.join(", "));
    }
    if p.some() {
        t += "[run]\n";
        if p.some() {
            t += &format!("t_end = {}\n", p.value_for("t_end"));
        }
        if p.some() {
            t += &format!("integrator = {}\n", p.value_for("integrator"));
        }
        for key in ["dt", "rtol", "tolerance"] {
            if p.next() % 3 == 0 {
                t += &format!("{key} = {}\n", p.value_for(key));
            }
        }
    }
    if p.some() {
        t += "[output]\n";
        t += &format!("kind = {}\n", p.value_for("kind"));
        match p.next() % 6 {
            0 => t += &format!("times = {}\n", p.list(8)),
            1 => t += &format!("camera = {}\n", p.word()),
            2 => t += &format!("figure = {}\nalphas = {}\n", p.word(), p.list(4)),
            3 => {
                let n = p.next() % 3;
                let curves: Vec<String> = (0..n)
                    .map(|_| format!("{{ model = {} }}", p.model_table()))
                    .collect();
                t += &format!("curves = [{}]\n", curves.join(", "));
            }
            4 => {
                for _ in 0..p.next() % 3 {
                    t += "[[output.panels]]\n";
                    t += &format!("label = {}\nmodel = {}\n", p.word(), p.model_table());
                    if p.some() {
                        t += &format!("t_end = {}\n", p.value());
                    }
                    if p.some() {
                        t += &format!("times = {}\n", p.list(8));
                    }
                }
            }
            _ => {}
        }
    }
    t
}

/// What happened to one file.
#[derive(Default)]
struct Tally {
    refused: u32,
    accepted: u32,
    runs: u32,
    over_cap: u32,
    keys: std::collections::BTreeMap<String, u32>,
}

fn check_one(text: &str, tally: &mut Tally) -> Result<(), TestCaseError> {
    let scene = match file::parse(text, "fuzz.toml", "fuzz") {
        Ok(s) => s,
        Err(e) => {
            prop_assert_eq!(e.exit_code(), 2, "{}\n{}", e, text);
            prop_assert_eq!(e.to_string().lines().count(), 1, "{}\n{}", e, text);
            tally.refused += 1;
            if std::env::var("LADDER_FUZZ_DEBUG").is_ok() {
                let msg = e.to_string();
                let key = msg.split(": ").nth(1).unwrap_or("").to_string();
                *tally.keys.entry(key).or_insert(0) += 1;
            }
            return Ok(());
        }
    };
    tally.accepted += 1;
    if scene.fidelity() != Fidelity::Simulation {
        return Ok(());
    }
    for (mut run, times) in scene.runs() {
        tally.runs += 1;
        // `t_end = "auto"` is costed as its window's own run, to the cap
        // (`scenes::run::check_cost`).
        if run.run.t_end == jacobs_ladder::scene::AUTO_T_END {
            run.run.t_end = jacobs_ladder::sim::window::AUTO_CAP;
        }
        let scenario = run.scenario();
        prop_assert!(scenario.is_ok(), "{:?}\n{}", scenario.err(), text);
        let scenario = scenario.unwrap();
        let config = run.run.fixed_config();
        prop_assert!(config.is_ok(), "{:?}\n{}", config.err(), text);
        let cost = match config.unwrap() {
            Some(config) => sim::check_cost(&scenario, times.len(), &config, &Limits::default()),
            None => {
                // auto: ω_max by the band Hessian (O(N); kept to N ≤ 2000
                // here for speed), then auto's first step.
                if run.model.n <= 2000 {
                    let params = run.model.params().unwrap();
                    let w = jacobs_ladder::theory::dispersion::omega_max_clamped(&params);
                    prop_assert!(
                        w.as_ref().is_ok_and(|w| w.is_finite() && *w > 0.0),
                        "{:?}\n{}",
                        w,
                        text
                    );
                    let config = sim::IntegratorConfig::auto(w.unwrap());
                    sim::check_cost(&scenario, times.len(), &config, &Limits::default())
                } else {
                    continue;
                }
            }
        };
        match cost {
            Ok(_) => {}
            Err(e @ (Error::Limit(_) | Error::BadInput(_))) => {
                prop_assert_eq!(e.to_string().lines().count(), 1, "{}", e);
                tally.over_cap += 1;
            }
            Err(e) => prop_assert!(false, "cost check failed: {}\n{}", e, text),
        }
    }
    Ok(())
}

#[test]
fn ten_thousand_generated_scene_files_parse_or_are_refused_in_one_line() {
    // LADDER_FUZZ_SEED=K (a byte) for a long run over other files.
    let seed = std::env::var("LADDER_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(15u8);
    let mut runner = fuzz::runner(fuzz::cases(10_000), seed);
    let tally = std::cell::RefCell::new(Tally::default());
    let strategy = prop::collection::vec(any::<usize>(), 120);
    runner
        .run(&strategy, |picks| {
            let text = scene_text(&picks);
            check_one(&text, &mut tally.borrow_mut())
        })
        .unwrap();
    let t = tally.into_inner();
    eprintln!(
        "{} files refused, {} accepted ({} simulations: {} past a cap or refused before running)",
        t.refused, t.accepted, t.runs, t.over_cap
    );
    if !t.keys.is_empty() {
        eprintln!("{:?}", t.keys);
    }
    // The generator reaches past the syntax: both outcomes, and runs.
    assert!(t.accepted > 100 && t.refused > 100 && t.runs > 100);
}
