//! A table of runs as columns: the rows [`write_runs`](super::write_runs) writes, as one binary64
//! vector per column and the `error` column as texts, with no text between the run and the value
//! (the Python module's DataFrames: `collide.sweep` in the plane, `collide.track(vary=...)`,
//! `collide.contact(vary=...)`). A cell is the value the writer formats: the same `fill` and
//! `fill_failed`, so every number equals the command line's row bit for bit.

use rayon::prelude::*;

use super::{Cell, Kind, Knob, counts, describe, error_at, fill, fill_failed};
use crate::table::row::{RowError, RowProblem};
use crate::table::sweep::{Grid, Shard};

/// A table of runs, column by column.
#[derive(Debug, Clone, PartialEq)]
pub struct RunColumns {
    /// The columns' names, in order (the `error` column's among them when it is shown).
    pub names: Vec<String>,
    /// One vector per column, a value per row (NaN where a run has none: a failed run's
    /// summary, a contact that did not happen); the `error` column's vector is empty.
    pub values: Vec<Vec<f64>>,
    /// The `error` column (where it is shown): `None` for a run that succeeded.
    pub errors: Option<Vec<Option<String>>>,
    /// Which columns count (collisions, steps): integers, as every format writes them.
    pub integers: Vec<bool>,
    /// Runs that failed and were left out (`skip_bad`, with no `error` column shown).
    pub skipped: Vec<RowError>,
}

/// Runs the rows of `shard` of `grid` into columns `cells` (named `names`), in grid order. A
/// failed run is a row with its message where the `error` column is shown; otherwise it is left
/// out with `skip_bad` (listed in `skipped`) or stops the table: `Err` with the first failure in
/// grid order, as `write_runs` stops at it.
pub fn run_columns<K: Kind>(
    kind: &K,
    grid: &Grid<Knob>,
    shard: Shard,
    cells: &[Cell<K::Col>],
    names: Vec<String>,
    skip_bad: bool,
) -> Result<RunColumns, RowError> {
    let rows = shard.rows(grid.total);
    let error_column = error_at(cells);
    let done: Vec<(Vec<f64>, Result<(), RowError>)> = (rows.start..rows.end)
        .into_par_iter()
        .map(|r| {
            let mut point = vec![(Knob::Named(""), 0.0); grid.vary.len()];
            grid.row(r, &mut point);
            let mut values = vec![0.0; cells.len()];
            let result = kind
                .run(&point)
                .and_then(|o| fill(kind, cells, &point, &o, &mut values));
            let result = result.map_err(|why| {
                fill_failed(cells, &point, &mut values);
                RowError {
                    place: format!("run {} ({})", r + 1, describe(&point)),
                    problem: RowProblem::Run(why),
                }
            });
            (values, result)
        })
        .collect();
    let mut values: Vec<Vec<f64>> = cells
        .iter()
        .map(|c| match c {
            Cell::Error => Vec::new(),
            _ => Vec::with_capacity(done.len()),
        })
        .collect();
    let mut errors = error_column.map(|_| Vec::with_capacity(done.len()));
    let mut skipped = Vec::new();
    for (row, result) in done {
        let why = match result {
            Ok(()) => None,
            Err(e) => match (&mut errors, skip_bad) {
                (Some(_), _) => Some(e),
                (None, true) => {
                    skipped.push(e);
                    continue;
                }
                (None, false) => return Err(e),
            },
        };
        if let Some(errors) = &mut errors {
            errors.push(why.map(|e| match e.problem {
                RowProblem::Run(why) => why,
                other => other.to_string(),
            }));
        }
        for ((column, cell), x) in values.iter_mut().zip(cells).zip(row) {
            if !matches!(cell, Cell::Error) {
                column.push(x);
            }
        }
    }
    Ok(RunColumns {
        names,
        values,
        errors,
        integers: counts(kind, cells),
        skipped,
    })
}
