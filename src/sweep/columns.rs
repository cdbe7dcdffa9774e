//! A sweep's results as typed columns at full precision (docs/python.md,
//! "Sweeps"): the CSV's columns ([`super::results::csv`]), in its order
//! and under its names, each with its type (whole numbers, numbers,
//! names) and every number as the run recorded it, not rounded as the
//! CSV prints it. A front end that hands the table over in memory (the
//! Python package's `Table`) takes its columns from here, so that no
//! front end decides which column holds whole numbers or how an empty
//! cell reads.

use super::results::{RESULT_COLUMNS, WAVE_COLUMNS};
use super::{Plan, Record};
use crate::scene::sweep::Param;
use crate::sim::waves::{Fate, Wave};

/// One column's values; an empty cell of the CSV is `-1` (a whole
/// number), NaN (a number) or `""` (a name).
#[derive(Debug, Clone, PartialEq)]
pub enum Values {
    Whole(Vec<i64>),
    Number(Vec<f64>),
    Name(Vec<String>),
}

/// A column: its CSV header and its values, one per run in grid order.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    pub name: String,
    pub values: Values,
}

/// Whether parameter `p` takes whole numbers only (N).
pub fn is_whole(p: Param) -> bool {
    matches!(p, Param::N)
}

/// What a column holds, as the CSV's cells are filled.
enum Cell {
    Whole(Option<i64>),
    Number(Option<f64>),
    Name(String),
}

/// The cells of one run, in the CSV's column order.
fn cells(plan: &Plan, r: &Record, per_wave: usize) -> Vec<Cell> {
    let scene = plan.scene_at(r.run);
    let res = &r.result;
    let mut row = vec![Cell::Whole(Some(r.run as i64))];
    for p in Param::ALL {
        let v = p.get(&scene);
        row.push(if is_whole(p) {
            Cell::Whole(Some(v as i64))
        } else {
            Cell::Number(Some(v))
        });
    }
    row.extend([
        Cell::Name(res.outcome.name().to_string()),
        Cell::Whole(Some(res.blocks_flipped as i64)),
        Cell::Whole(Some(res.front as i64)),
        Cell::Number(res.speed),
        Cell::Number(res.t_decided),
        Cell::Number(res.block_n_turned_at),
        Cell::Whole(Some(res.waves.waves.len() as i64)),
    ]);
    for k in 0..per_wave {
        row.extend(wave_cells(res.waves.waves.get(k)));
    }
    row
}

/// A wave's cells (`kind`, `launched_at`, `front`, `fate`, `fate_at`),
/// empty where the run had fewer waves.
fn wave_cells(w: Option<&Wave>) -> [Cell; 5] {
    let Some(w) = w else {
        return [
            Cell::Name(String::new()),
            Cell::Number(None),
            Cell::Whole(None),
            Cell::Name(String::new()),
            Cell::Number(None),
        ];
    };
    let (fate, at) = match w.fate {
        Fate::End => ("end", None),
        Fate::Stopped => ("stopped", None),
        Fate::Annihilated { at, .. } => ("annihilated", Some(at)),
        Fate::Undecided => ("undecided", None),
    };
    [
        Cell::Name(w.kind.name().to_string()),
        Cell::Number(Some(w.launched_at)),
        Cell::Whole(Some(w.front as i64)),
        Cell::Name(fate.to_string()),
        Cell::Number(at),
    ]
}

/// The column names, as the CSV's header: `run`, the parameters, the
/// outcome columns, `waves`, and the columns of each wave up to the most
/// any run had (where some run had more than one).
pub fn names(per_wave: usize) -> Vec<String> {
    let mut names = vec!["run".to_string()];
    names.extend(Param::ALL.iter().map(|p| p.name().to_string()));
    names.extend(RESULT_COLUMNS.iter().map(|c| c.to_string()));
    names.push("waves".into());
    for k in 1..=per_wave {
        names.extend(WAVE_COLUMNS.iter().map(|c| format!("wave{k}_{c}")));
    }
    names
}

/// The columns of the sweep `plan`'s `records` (in grid order).
pub fn columns(plan: &Plan, records: &[Record]) -> Vec<Column> {
    let most = records
        .iter()
        .map(|r| r.result.waves.waves.len())
        .max()
        .unwrap_or(0);
    let per_wave = if most > 1 { most } else { 0 };
    let rows: Vec<Vec<Cell>> = records.iter().map(|r| cells(plan, r, per_wave)).collect();
    // The first row's kinds (every row has the same); with no row, the
    // kinds of an empty run's cells.
    names(per_wave)
        .into_iter()
        .enumerate()
        .map(|(j, name)| {
            let kind = rows.first().map(|row| &row[j]);
            let values = match kind {
                Some(Cell::Whole(_)) => Values::Whole(
                    rows.iter()
                        .map(|row| match row[j] {
                            Cell::Whole(v) => v.unwrap_or(-1),
                            _ => -1,
                        })
                        .collect(),
                ),
                Some(Cell::Name(_)) => Values::Name(
                    rows.iter()
                        .map(|row| match &row[j] {
                            Cell::Name(s) => s.clone(),
                            _ => String::new(),
                        })
                        .collect(),
                ),
                Some(Cell::Number(_)) | None => Values::Number(
                    rows.iter()
                        .map(|row| match row[j] {
                            Cell::Number(v) => v.unwrap_or(f64::NAN),
                            _ => f64::NAN,
                        })
                        .collect(),
                ),
            };
            Column { name, values }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::sweep::{Piece, Values as Grid};
    use crate::scene::{OutputSpec, Scene};

    fn small_sweep() -> (Plan, Vec<Record>) {
        let mut scene = Scene::default();
        scene.model.n = 6;
        let mut spec = crate::scene::sweep::SweepSpec::default();
        spec.grid.0.push((
            Param::Alpha,
            Grid([55.0, 65.0, -60.0].map(Piece::Value).to_vec()),
        ));
        scene.output = OutputSpec::Sweep(spec);
        let plan = Plan::new(&scene, 100).unwrap().unwrap();
        let all: Vec<usize> = (0..plan.len()).collect();
        let records = plan.run(&all, &|| {}).unwrap();
        (plan, records)
    }

    /// The columns are the CSV's: the same header, and every cell the
    /// CSV's once rounded as the CSV rounds it (whole numbers and names
    /// equal, numbers to the CSV's digits, empty cells -1, NaN or "").
    #[test]
    fn the_columns_are_the_csvs_at_full_precision() {
        let (plan, records) = small_sweep();
        let csv = super::super::results::csv(&plan, &records);
        let mut lines = csv.lines();
        let header: Vec<&str> = lines.next().unwrap().split(',').collect();
        let cols = columns(&plan, &records);
        assert_eq!(
            cols.iter().map(|c| c.name.as_str()).collect::<Vec<_>>(),
            header
        );
        for (i, line) in lines.enumerate() {
            for (cell, col) in line.split(',').zip(&cols) {
                match &col.values {
                    Values::Whole(v) => {
                        let want = if cell.is_empty() {
                            -1
                        } else {
                            cell.parse().unwrap()
                        };
                        assert_eq!(v[i], want, "{} row {i}", col.name);
                    }
                    Values::Name(v) => assert_eq!(v[i], cell, "{} row {i}", col.name),
                    Values::Number(v) if cell.is_empty() => assert!(v[i].is_nan()),
                    Values::Number(v) => {
                        let printed: f64 = cell.parse().unwrap();
                        let rel = ((v[i] - printed) / printed).abs();
                        assert!(rel < 1e-5, "{} row {i}: {} against {cell}", col.name, v[i]);
                    }
                }
            }
        }
        // The speed at full precision: the record's own number.
        let speed = cols.iter().find(|c| c.name == "speed").unwrap();
        let Values::Number(v) = &speed.values else {
            panic!("speed is a number column")
        };
        assert_eq!(v[0], records[0].result.speed.unwrap());
        assert!(
            matches!(cols[2].values, Values::Whole(_)),
            "n holds whole numbers"
        );
    }
}
