//! The table engine (`collide sweep`, `collide batch`, `[sweep]` scenes): rows are solved by the
//! same binary64 solver as `solve`, in parallel (rayon) in chunks, and written in order
//! ([`super::pipeline`]); a bad row stops the run after every row before it has been written
//! whole, or, with `skip_bad`, is reported on stderr and skipped.

use std::io::Write;

use nalgebra::Vector2;

use super::batch::Batch;
use super::columns::Column;
use super::pipeline::{CHUNK_ROWS, ChunkOut, RowsError, Summary, write_chunks};
use super::row::{Row, RowCase, RowError, RowProblem};
use super::sweep::{Grid, Param, Shard};
use super::writer::{FieldCache, RowWriter, Sealed, Sink};
use crate::line::case::Case;
use crate::line::collision::Collision;
use crate::line::inertia::InertiaTensor;
use crate::line::restitution::Restitution;
use crate::solver::binary64::Binary64;
use crate::values::number::Number;
use crate::values::output::Progress;

/// Solves a row's columns into `out`. `shared` is the tensor when every row has the same one.
pub fn solve_row(
    case: &RowCase,
    shared: Option<&InertiaTensor>,
    columns: &[&'static Column],
    out: &mut [f64],
) -> Result<(), RowProblem> {
    let n = Number::from_f64;
    let inertia = match shared {
        Some(t) => t.clone(),
        None => {
            InertiaTensor::general([[n(case.m11)?, n(case.m12)?], [n(case.m12)?, n(case.m22)?]])?
        }
    };
    let e = Restitution::new(n(case.e)?)?;
    let c = Collision::new(inertia, Vector2::new(case.v[0], case.v[1]), e);
    let mut row = Row::new(case, Binary64::lab(&c));
    for (slot, col) in out.iter_mut().zip(columns) {
        *slot = col.value(&mut row);
        if !slot.is_finite() {
            return Err(RowProblem::Unrepresentable(col.name));
        }
    }
    Ok(())
}

/// Solves and formats a chunk of rows: `(place, case)` or an input error.
pub fn chunk(
    items: impl Iterator<Item = Result<(u64, RowCase), RowError>>,
    place: &dyn Fn(u64) -> String,
    shared: Option<&InertiaTensor>,
    writer: &RowWriter,
    skip_bad: bool,
) -> ChunkOut {
    let mut buf = writer.buffer(CHUNK_ROWS);
    let mut fields = FieldCache::new(writer.columns().len());
    let mut values = vec![0.0; writer.columns().len()];
    let mut out = ChunkOut {
        body: Ok(Sealed::Bytes(Vec::new())),
        rows: 0,
        skipped: Vec::new(),
        stop: None,
    };
    for item in items {
        let result = item.and_then(|(at, case)| {
            solve_row(&case, shared, writer.columns(), &mut values).map_err(|problem| RowError {
                place: place(at),
                problem,
            })
        });
        match result {
            Ok(()) => {
                writer.row(&values, &mut buf, &mut fields);
                out.rows += 1;
            }
            Err(e) if skip_bad && !e.problem.ends_input() => out.skipped.push(e),
            Err(e) => {
                out.stop = Some(e);
                break;
            }
        }
    }
    out.body = writer.seal(buf);
    out
}

/// The rows of a sweep of `case` over `grid`: each row's case, and the tensor every row shares
/// when no mass varies. `collide sweep` writes them (`write_sweep`), the Python module's
/// `collide.sweep` solves them into columns; both with `solve_row`.
pub struct SweepRows<'a> {
    base: RowCase,
    grid: &'a Grid,
    /// The tensor of every row, when no mass varies (`solve_row`'s `shared`).
    pub shared: Option<InertiaTensor>,
}

impl<'a> SweepRows<'a> {
    pub fn new(case: &Case, grid: &'a Grid) -> SweepRows<'a> {
        let m = case.inertia().matrix();
        let shared =
            (!grid.varies(Param::M1) && !grid.varies(Param::M2)).then(|| case.inertia().untyped());
        let c = &case.collision;
        let base = RowCase {
            m11: m[(0, 0)],
            m12: m[(0, 1)],
            m22: m[(1, 1)],
            v: [c.v_in.x, c.v_in.y],
            e: c.restitution.value(),
        };
        SweepRows { base, grid, shared }
    }

    /// Row `r`'s case (from 0, in the grid's order: the last parameter varies fastest).
    pub fn row(&self, r: u64) -> RowCase {
        let mut varied = [(Param::E, 0.0); 5];
        let varied = &mut varied[..self.grid.vary.len()];
        self.grid.row(r, varied);
        let mut row = self.base;
        for &(p, x) in varied.iter() {
            match p {
                Param::M1 => row.m11 = x,
                Param::M2 => row.m22 = x,
                Param::V1 => row.v[0] = x,
                Param::V2 => row.v[1] = x,
                Param::E => row.e = x,
            }
        }
        row
    }
}

/// Solves the rows of `shard` of a sweep of `case` over `grid` and writes them (with the header
/// when the writer puts one in this shard: by default, the first) to `out`. A Parquet table is
/// complete (footer written) only when this returns `Ok`.
pub fn write_sweep(
    case: &Case,
    grid: &Grid,
    shard: Shard,
    writer: &RowWriter,
    skip_bad: bool,
    out: &mut dyn Write,
    progress: &mut Progress,
) -> Result<Summary, RowsError> {
    let rows_of = SweepRows::new(case, grid);
    let rows = shard.rows(grid.total);
    let mut sink = Sink::open(writer, shard.k, out)?;
    let chunk_ranges = (rows.start..rows.end)
        .step_by(CHUNK_ROWS)
        .map(move |s| s..(s + CHUNK_ROWS as u64).min(rows.end));
    let solve = |range: std::ops::Range<u64>| {
        let items = range.map(|r| Ok((r + 1, rows_of.row(r))));
        chunk(
            items,
            &|r| format!("row {r}"),
            rows_of.shared.as_ref(),
            writer,
            skip_bad,
        )
    };
    let summary = write_chunks(chunk_ranges, solve, &mut sink, progress)?;
    sink.finish()?;
    Ok(summary)
}

/// Solves every case of `input` and writes its rows, with the header (unless `Header::Never`),
/// to `out`. The input is read a batch of chunks at a time: memory stays bounded whatever its
/// size.
pub fn write_batch(
    input: Batch,
    writer: &RowWriter,
    skip_bad: bool,
    out: &mut dyn Write,
    progress: &mut Progress,
) -> Result<Summary, RowsError> {
    let mut sink = Sink::open(writer, 1, out)?;
    let mut input = input.on_a_line().peekable();
    let chunks = std::iter::from_fn(move || {
        input.peek()?;
        Some(input.by_ref().take(CHUNK_ROWS).collect::<Vec<_>>())
    });
    let solve = |items: Vec<Result<(u64, RowCase), RowError>>| {
        chunk(
            items.into_iter(),
            &|l| format!("line {l}"),
            None,
            writer,
            skip_bad,
        )
    };
    let summary = write_chunks(chunks, solve, &mut sink, progress)?;
    sink.finish()?;
    Ok(summary)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::columns::by_names;
    use crate::table::writer::RowFormat;

    fn case(m1: f64, m2: f64, v: [f64; 2], e: f64) -> RowCase {
        RowCase {
            m11: m1,
            m12: 0.0,
            m22: m2,
            v,
            e,
        }
    }

    #[test]
    fn a_row_is_the_lecture_case() {
        let cols = Column::defaults(false);
        let mut out = vec![0.0; cols.len()];
        solve_row(&case(4.0, 1.0, [60.0, 10.0], 1.0), None, &cols, &mut out).unwrap();
        // m1 m2 v1 v2 e fin1 fin2 v_com ke_in ke_fin crunch lost
        assert_eq!(
            out,
            [
                4.0, 1.0, 60.0, 10.0, 1.0, 40.0, 90.0, 50.0, 7250.0, 7250.0, 1000.0, 0.0
            ]
        );
    }

    #[test]
    fn bad_rows_stop_or_are_skipped() {
        let w = RowWriter::new(by_names(&["fin1"]).unwrap(), RowFormat::Csv);
        let items = || {
            vec![
                Ok((1, case(4.0, 1.0, [60.0, 10.0], 1.0))),
                Ok((2, case(1.0, 1.0, [1e200, -1e200], 1.0))),
                Ok((3, case(4.0, 1.0, [60.0, 10.0], 0.0))),
            ]
            .into_iter()
        };
        let place = |r: u64| format!("row {r}");
        // FIN of row 2 is representable (-1e200, 1e200): only what is asked is computed.
        let bytes = |c: ChunkOut| match c.body {
            Ok(Sealed::Bytes(b)) => b,
            _ => panic!("CSV is bytes"),
        };
        let all = chunk(items(), &place, None, &w, false);
        assert_eq!(bytes(all), b"40.0\n-1e200\n50.0\n");
        // Its KE (1e400) is not.
        let w = RowWriter::new(by_names(&["ke_in"]).unwrap(), RowFormat::Csv);
        let mut stopped = chunk(items(), &place, None, &w, false);
        assert_eq!(stopped.stop.take().unwrap().place, "row 2");
        assert_eq!(bytes(stopped), b"7250.0\n");
        let skipping = chunk(items(), &place, None, &w, true);
        assert_eq!(skipping.skipped.len(), 1);
        assert!(
            skipping.skipped[0]
                .to_string()
                .contains("ke_in is not representable")
        );
        assert_eq!(bytes(skipping), b"7250.0\n7250.0\n");
    }
}
