//! `ladder all --timings`: the table lists every built-in figure and movie
//! once, and the runs and block-steps it gives an output are the runs that
//! output made, decided from the output's own data file (never from a
//! clock: the times are not checked).

use jacobs_ladder::catalog;
use jacobs_ladder::scene::Fidelity;
use std::collections::BTreeMap;

/// One row of the table: runs and block-steps.
type Row = (u64, u64);
/// An output's row, its CPU seconds and the runs it reused.
type Output = (Row, f64, u64);

/// The rows of the table (output, wall, CPU, runs, block-steps, reused),
/// by "kind name", with their CPU seconds and reused runs; and the whole
/// render's row and CPU.
fn parse(table: &str) -> (BTreeMap<String, Output>, (Row, f64)) {
    let mut rows = BTreeMap::new();
    let mut whole = None;
    for line in table.lines().skip(1) {
        let words: Vec<&str> = line.split_whitespace().collect();
        let n = words.len();
        if n < 7 || words[n - 5].parse::<f64>().is_err() {
            continue;
        }
        let row = (words[n - 3].parse().unwrap(), words[n - 2].parse().unwrap());
        let cpu: f64 = words[n - 4].parse().unwrap();
        let reused: u64 = words[n - 1].parse().unwrap();
        let name = words[..n - 5].join(" ");
        if name == "whole render" {
            whole = Some((row, cpu));
        } else {
            assert!(
                rows.insert(name, (row, cpu, reused)).is_none(),
                "a row twice:\n{table}"
            );
        }
    }
    (rows, whole.expect("the whole render's row"))
}

/// What an automatic-step (velocity Verlet) run of `data` simulated: the
/// kept run's `steps` at the step dt, and before it the coarser runs at
/// 2 dt, 4 dt, ... that the step was halved from (docs/model.md). Verlet
/// evaluates the forces once a step and once at the start, so the data's
/// `total_force_evals` = Σ (steps + 1) over the runs decides how many
/// there were. Returns (runs, block-steps).
fn verified_runs(run: &serde_json::Value, n: u64) -> Row {
    let integrator = &run["integrator"];
    assert_eq!(integrator["name"], "verlet", "{integrator}");
    let steps = integrator["steps"].as_u64().unwrap();
    let total = integrator["total_force_evals"].as_u64().unwrap();
    let (mut runs, mut evals, mut block_steps) = (0, 0, 0);
    while evals < total {
        let s = steps >> runs;
        assert!(s > 0 && steps.is_multiple_of(1 << runs), "{integrator}");
        evals += s + 1;
        block_steps += s * n;
        runs += 1;
    }
    assert_eq!(
        evals, total,
        "the halvings account for every force evaluation"
    );
    (runs, block_steps)
}

#[test]
fn the_table_lists_every_output_and_the_runs_each_made() {
    let (dir, table) = crate::common::catalogue_render();
    let (rows, whole) = parse(table);

    // Every entry of the catalogue once, nothing else; a simulated one
    // made runs or took another's (`scenes::shared`), a drawing, formula
    // or linear theory none.
    let entries = catalog::catalogue().unwrap();
    assert_eq!(rows.len(), entries.len(), "{table}");
    for e in entries {
        let name = format!("{} {}", e.kind().name(), e.scene.name);
        let ((runs, block_steps), _, reused) = rows[&name];
        let simulated = e.scene.fidelity() == Fidelity::Simulation;
        assert_eq!(runs + reused > 0, simulated, "{name}:\n{table}");
        assert_eq!(block_steps > 0 || reused > 0, simulated, "{name}:\n{table}");
    }
    // Movies 3 and 4 are one run (one scene, two cameras): made for
    // movie 3, taken by movie 4; and the tank's positions at 0.2 Hz, with
    // links and with ribbons, are its level 3 and its ribbons' level, made
    // for the positions, taken by the levels.
    assert_eq!(rows["movie 4"].0, (0, 0), "{table}");
    assert_eq!(rows["movie 4"].2, rows["movie 3"].0.0, "{table}");
    assert_eq!(rows["figure tank-levels"].2, 4, "{table}");
    // Figure 4b's chain is movie 12's first 2 s: one run, made for the
    // movie, taken by the figure.
    assert_eq!(rows["movie 12"].0.0, 1, "{table}");
    assert_eq!(
        (rows["figure 4b"].0, rows["figure 4b"].2),
        ((0, 0), 1),
        "{table}"
    );
    // Every run of the render is some output's, counted once: also those
    // spread over the cores in rayon's tasks.
    let runs: u64 = rows.values().map(|r| r.0.0).sum();
    let block_steps: u64 = rows.values().map(|r| r.0.1).sum();
    assert_eq!(whole.0, (runs, block_steps), "{table}");
    assert!(table.contains("runs outside any output: 0"), "{table}");
    // The outputs' CPU times are parts of the process's (each thread's
    // time charged to one output at a time): they add up to no more than
    // it, within the process clock's tick of 10 ms a thread.
    let cpu: f64 = rows.values().map(|r| r.1).sum();
    assert!(cpu <= whole.1 + 0.05, "outputs' CPU {cpu} s:\n{table}");
    let simulated = |name: &str| rows[name].1 > 0.0;
    assert!(simulated("movie 3") && simulated("figure phase"), "{table}");

    // Fig. 1c is one automatic-step run of N blocks: its row is that run's
    // halvings, read from its data file.
    let data: serde_json::Value =
        serde_json::from_slice(&std::fs::read(dir.join("figure-1c.json")).unwrap()).unwrap();
    let [run] = data["runs"].as_array().unwrap().as_slice() else {
        panic!("Fig. 1c has one run")
    };
    let n = run["model"]["n"].as_u64().unwrap();
    let expected = verified_runs(run, n);
    assert!(expected.0 >= 2, "a verified run is at least a pair");
    assert_eq!(rows["figure 1c"].0, expected, "{table}");
}

/// Figure 4b in `ladder all` takes its run from movie 12's (the chain's
/// first 2 s: docs/performance.md, "Runs two outputs make alike") and its
/// files are those of `ladder figure 4b` alone, byte for byte: its
/// pictures, and its data file but for the command line and the list of
/// files (the render adds a PNG preview).
#[test]
fn figure_4b_in_the_catalogue_is_figure_4b_alone() {
    let (dir, table) = crate::common::catalogue_render();
    let (rows, _) = parse(table);
    assert_eq!(rows["figure 4b"].2, 1, "reused:\n{table}");
    let alone = crate::common::tempdir::TempDir::new("figure-4b-alone");
    let out = alone.path().to_str().unwrap();
    let cli = crate::common::ladder_cli(&["figure", "4b", "--format", "svg,pdf", "--out", out]);
    assert_eq!(
        cli.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&cli.stderr)
    );
    for ext in ["svg", "pdf"] {
        let name = format!("figure-4b.{ext}");
        let (a, b) = (
            std::fs::read(alone.join(&name)),
            std::fs::read(dir.join(&name)),
        );
        assert!(
            a.unwrap() == b.unwrap(),
            "{name} differs from its render alone"
        );
    }
    let data = |d: &std::path::Path| {
        let text = std::fs::read(d.join("figure-4b.json")).unwrap();
        let mut v: serde_json::Value = serde_json::from_slice(&text).unwrap();
        let map = v.as_object_mut().unwrap();
        assert!(map.remove("command_line").is_some() && map.remove("files").is_some());
        v
    };
    assert_eq!(data(alone.path()), data(dir));
}
