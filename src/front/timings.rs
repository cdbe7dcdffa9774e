//! Where the time of a render goes (`ladder all --timings`): each output's
//! wall time and the runs and block-steps it simulated, and the process's
//! wall and CPU time over the whole render.
//!
//! What is measured, exactly:
//! - an output's wall time runs from the start of its rendering to its
//!   files being in place. Outputs render in parallel (rayon), so these
//!   overlap and do not add up to the render's wall time; while an output
//!   waits for its own parallel runs, its thread may pick up another
//!   output's work, which is then in both wall times;
//! - an output's runs and block-steps (steps × blocks, summed over its
//!   runs) are counted by the simulation as each run finishes
//!   (`sim::tally`), whichever thread ran it; a run two outputs make
//!   alike is made once, before the outputs start (a ring chain's at the
//!   start of the output whose end is the latest), and counted in the
//!   first's (`scenes::shared`): the others count it as **reused**;
//! - an output's CPU time is the time threads spent on its tasks: its
//!   own rendering and the runs it spread over the cores, each thread's
//!   clock charged to the output whose tally was set on it
//!   (`sim::tally`); an encoder's or rasteriser's own parallel loops are
//!   in no output's CPU time, only in the process's;
//! - the process's CPU time (user + system, every thread) over the whole
//!   render is read from `/proc/self/stat`.

use crate::scene::Kind;
use crate::sim::tally;
use std::time::Instant;

/// One output's cost.
#[derive(Debug, Clone)]
pub struct Timing {
    pub kind: Kind,
    pub name: String,
    /// Seconds from its start to its files in place.
    pub wall_s: f64,
    /// CPU seconds its tasks took on every thread (module doc).
    pub cpu_s: f64,
    pub runs: u64,
    pub block_steps: u64,
    /// Runs another output made for it (`scenes::shared`), not counted
    /// in `runs`.
    pub reused: u64,
}

/// A whole render's costs.
#[derive(Debug, Clone)]
pub struct Timings {
    /// Every output's, in the order rendered.
    pub outputs: Vec<Timing>,
    /// The render's wall time (s).
    pub wall_s: f64,
    /// The process's CPU time over the render (s), where the system says.
    pub cpu_s: Option<f64>,
    /// Every run of the render, whether an output's or not.
    pub runs: u64,
    pub block_steps: u64,
}

/// The clock, CPU time and run count at the start of a render.
pub struct Start {
    at: Instant,
    cpu_s: Option<f64>,
    runs: u64,
    block_steps: u64,
}

impl Start {
    pub fn now() -> Self {
        let total = tally::total();
        Self {
            at: Instant::now(),
            cpu_s: process_cpu_s(),
            runs: total.runs(),
            block_steps: total.block_steps(),
        }
    }

    /// The render's costs from this start to now, with its outputs'.
    pub fn finish(self, outputs: Vec<Timing>) -> Timings {
        let total = tally::total();
        Timings {
            outputs,
            wall_s: self.at.elapsed().as_secs_f64(),
            cpu_s: process_cpu_s().zip(self.cpu_s).map(|(b, a)| b - a),
            runs: total.runs() - self.runs,
            block_steps: total.block_steps() - self.block_steps,
        }
    }
}

/// The process's user + system time (s), every thread, from
/// `/proc/self/stat`; `None` where there is no such file.
pub fn process_cpu_s() -> Option<f64> {
    cpu_s_of_stat(&std::fs::read_to_string("/proc/self/stat").ok()?)
}

/// utime + stime (fields 14 and 15 of `proc(5)`'s stat line, in clock
/// ticks of 1/100 s: Linux's USER_HZ) in seconds.
fn cpu_s_of_stat(stat: &str) -> Option<f64> {
    // The command name (field 2) is in parentheses and may hold spaces
    // and parentheses: the fields after it start after the last ')'.
    let rest = &stat[stat.rfind(')')? + 1..];
    let fields: Vec<&str> = rest.split_whitespace().collect();
    let ticks = |k: usize| fields.get(k - 3)?.parse::<u64>().ok();
    Some((ticks(14)? + ticks(15)?) as f64 / 100.0)
}

impl Timings {
    /// The table `--timings` prints: the outputs slowest first, then the
    /// render's totals, and what each column measures.
    pub fn table(&self) -> String {
        let mut rows = self.outputs.clone();
        rows.sort_by(|a, b| b.wall_s.total_cmp(&a.wall_s));
        let width = rows
            .iter()
            .map(|t| t.kind.name().len() + 1 + t.name.len())
            .chain([24])
            .max()
            .unwrap_or(24);
        let mut s = format!(
            "{:<width$}  {:>8}  {:>7}  {:>5}  {:>12}  {:>6}\n",
            "output", "wall (s)", "CPU (s)", "runs", "block-steps", "reused"
        );
        for t in &rows {
            let name = format!("{} {}", t.kind.name(), t.name);
            s += &format!(
                "{name:<width$}  {:>8.2}  {:>7.2}  {:>5}  {:>12}  {:>6}\n",
                t.wall_s, t.cpu_s, t.runs, t.block_steps, t.reused
            );
        }
        let runs: u64 = rows.iter().map(|t| t.runs).sum();
        let reused: u64 = rows.iter().map(|t| t.reused).sum();
        let outputs_cpu: f64 = rows.iter().map(|t| t.cpu_s).sum();
        let cpu = self.cpu_s.map_or("-".into(), |c| format!("{c:.2}"));
        s += &format!(
            "{:<width$}  {:>8.2}  {:>7}  {:>5}  {:>12}  {:>6}\n",
            "whole render", self.wall_s, cpu, self.runs, self.block_steps, reused
        );
        let outside = self.cpu_s.map_or("not measured".into(), |c| {
            format!("{:.2} s", c - outputs_cpu)
        });
        s += &format!(
            "CPU of the whole render: user + system, every thread, the whole process; CPU \
             outside the outputs' own tasks (encoders' parallel loops, start-up): {outside}; \
             runs outside any output: {}\nwall: an output's start to its files in place \
             (outputs overlap, rendered in parallel); CPU: its tasks' time on every thread; \
             block-steps: steps x blocks of its runs; reused: runs another output made for \
             it, made once for both (before the outputs started; a ring chain's, in the \
             first output's time), not in its runs, wall or CPU\n",
            self.runs.saturating_sub(runs),
        );
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cpu_time_is_utime_plus_stime_after_the_command_name() {
        // pid (comm) state ppid pgrp session tty tpgid flags minflt
        // cminflt majflt cmajflt utime stime cutime cstime ...
        let stat = "4242 (a (b) c) R 1 2 3 4 5 6 7 8 9 10 1234 567 11 12 20 0 3";
        assert_eq!(cpu_s_of_stat(stat), Some(18.01));
        assert_eq!(cpu_s_of_stat("4242 (x) R 1 2"), None, "too few fields");
        assert!(process_cpu_s().is_some(), "Linux has /proc/self/stat");
    }

    #[test]
    fn the_table_lists_the_slowest_first_and_the_totals() {
        let t = |name: &str, wall_s, runs| Timing {
            kind: Kind::Figure,
            name: name.into(),
            wall_s,
            cpu_s: 2.0 * wall_s,
            runs,
            block_steps: 100 * runs,
            reused: 0,
        };
        let timings = Timings {
            outputs: vec![t("3", 0.5, 2), t("tank-levels", 4.0, 15)],
            wall_s: 4.2,
            cpu_s: Some(9.9),
            runs: 18,
            block_steps: 1800,
        };
        let table = timings.table();
        let lines: Vec<&str> = table.lines().collect();
        assert!(lines[1].starts_with("figure tank-levels"), "{table}");
        assert!(lines[2].starts_with("figure 3"), "{table}");
        assert!(lines[3].starts_with("whole render"), "{table}");
        assert!(lines[3].contains(" 9.90 "), "{table}");
        assert!(
            table.contains("start-up): 0.90 s; runs outside any output: 1"),
            "{table}"
        );
    }
}
