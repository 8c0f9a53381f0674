//! Sweeps of whole runs (`collide track --vary`, `collide contact --vary`): one row per run, the
//! run's summary in the columns, over the same grid of `--vary NAME=RANGE` as a two-body sweep
//! (`sweep::Grid`, shards, exact decimal steps) and through the same writer (`writer`: CSV, JSON
//! Lines, text, Parquet).
//!
//! Runs are spread over every core (rayon) a batch at a time and written in grid order, so the
//! output does not depend on the number of threads. A batch grows while runs are quick and
//! shrinks when they are slow (about half a second to a second a batch), so a progress bar
//! moves and a slow run holds up few others. No process is started and nothing is parsed per
//! run: a run is the base run with the grid's values put in.
//!
//! A run that fails (a contact run refused, a track that cannot be, an invariant broken) is a
//! row with its parameters and the message in the `error` column when that column is shown (it
//! is by default); with `--skip-bad` it is reported on stderr and left out; otherwise it stops
//! the table, after every row before it, as a bad row of `collide sweep` does. Never a silent
//! gap.
//!
//! - `contact`: the parameters and summary columns of `collide contact`;
//! - `track`: those of `collide track`.

pub mod columns;
pub mod contact;
pub mod plane;
pub mod track;

use std::io::Write;
use std::time::{Duration, Instant};

use rayon::prelude::*;

use super::pipeline::{CHUNK_ROWS, RowsError, Summary};
use super::row::{RowError, RowProblem, ValueProblem};
use super::sweep::{Grid, Named, RANGE_FORMS, Shard, Vary, VaryError, parse_vary};
use super::writer::{FieldCache, RowWriter, Sink};
use crate::values::number::Number;
use crate::values::output::Progress;

/// A parameter of a run: a body's mass, position, velocity or size (0-based), or a named one
/// (`stiffness`, `gravity`, ...).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Knob {
    Mass(usize),
    Position(usize),
    Velocity(usize),
    Size(usize),
    Named(&'static str),
}

impl Named for Knob {
    fn name(&self) -> String {
        match self {
            Knob::Mass(i) => format!("m{}", i + 1),
            Knob::Position(i) => format!("x{}", i + 1),
            Knob::Velocity(i) => format!("v{}", i + 1),
            Knob::Size(i) => format!("s{}", i + 1),
            Knob::Named(n) => n.to_string(),
        }
    }
}

/// A kind of run that can be swept: its parameters, its run, its summary columns.
pub trait Kind: Sync {
    /// What a run gives.
    type Out: Send;
    /// A summary column.
    type Col: Copy + Send + Sync;

    /// The named parameters (`stiffness`, ...), as typed with `_` for `-`.
    fn scalars(&self) -> &'static [&'static str];
    /// Bodies on the track (for `m1` ... `mN`).
    fn bodies(&self) -> usize;
    /// Refuses a value a parameter cannot take (checked before anything runs).
    fn check(&self, knob: Knob, value: &Number) -> Result<(), ValueProblem>;
    /// The run with the parameters of `point`; `Err` says why it failed.
    fn run(&self, point: &[(Knob, f64)]) -> Result<Self::Out, String>;
    /// The column `name` is, if one.
    fn column(&self, name: &str) -> Option<Self::Col>;
    /// The default summary columns.
    fn defaults(&self) -> Vec<String>;
    /// The names of the summary columns, for messages.
    fn column_forms(&self) -> String;
    /// A column's value for a run: `None` where it has none (a contact that did not happen).
    fn value(&self, col: Self::Col, out: &Self::Out) -> Option<f64>;
    /// Whether a column counts (collisions, steps): written as an integer in every format.
    fn counts(&self, _col: Self::Col) -> bool {
        false
    }
    /// Runs of microseconds (an impact, not an integration): solved and formatted in chunks
    /// in parallel, as `collide sweep` on a line, rather than in batches sized to a second.
    fn cheap(&self) -> bool {
        false
    }
}

/// The row's cells into `values`: parameters from `point`, columns from `out`; `Err` for a
/// result that is not a number.
#[inline(always)]
fn fill<K: Kind>(
    kind: &K,
    cells: &[Cell<K::Col>],
    point: &[(Knob, f64)],
    out: &K::Out,
    values: &mut [f64],
) -> Result<(), String> {
    for (slot, cell) in values.iter_mut().zip(cells) {
        *slot = match cell {
            Cell::Param(p) => point[*p].1,
            Cell::Of(c) => match kind.value(*c, out) {
                Some(v) if !v.is_finite() => {
                    return Err(format!(
                        "a result is beyond binary64 (it became {v}): rescale the units"
                    ));
                }
                Some(v) => v,
                None => f64::NAN,
            },
            Cell::Error => f64::NAN,
        };
    }
    Ok(())
}

/// The cells of a failed run: its parameters, the rest empty.
fn fill_failed<C>(cells: &[Cell<C>], point: &[(Knob, f64)], values: &mut [f64]) {
    for (slot, cell) in values.iter_mut().zip(cells) {
        *slot = match cell {
            Cell::Param(p) => point[*p].1,
            _ => f64::NAN,
        };
    }
}

/// `write_runs` for a cheap kind: chunks of rows run and formatted in parallel, written in
/// order (`pipeline::write_chunks`, as a sweep on a line).
#[allow(clippy::too_many_arguments)]
fn write_cheap<K: Kind>(
    kind: &K,
    grid: &Grid<Knob>,
    rows: std::ops::Range<u64>,
    cells: &[Cell<K::Col>],
    writer: &RowWriter,
    skip_bad: bool,
    sink: &mut Sink,
    progress: &mut Progress,
) -> Result<Summary, RowsError> {
    use super::pipeline::{ChunkOut, write_chunks};
    use std::sync::atomic::{AtomicU64, Ordering};
    let errors = AtomicU64::new(0);
    let solve = |start: u64| -> ChunkOut {
        let end = (start + CHUNK_ROWS as u64).min(rows.end);
        let mut rows = start..end;
        let mut point = vec![(Knob::Named(""), 0.0); grid.vary.len()];
        let next = |point: &mut Vec<(Knob, f64)>| {
            let r = rows.next()?;
            grid.row(r, point);
            Some(Ok(r))
        };
        let place = |r: u64, point: &[(Knob, f64)]| format!("run {} ({})", r + 1, describe(point));
        let table = Chunks::new(kind, cells, writer, skip_bad, &errors);
        chunk(&table, &mut point, next, place)
    };
    let starts = (rows.start..rows.end).step_by(CHUNK_ROWS);
    let mut summary = write_chunks(starts, solve, sink, progress)?;
    summary.errors = errors.load(Ordering::Relaxed);
    Ok(summary)
}

/// What every chunk of a table of cheap runs shares: the kind, the columns and their writer,
/// whether a failed run is skipped, and the count of failed runs written as rows.
struct Chunks<'a, K: Kind> {
    kind: &'a K,
    cells: &'a [Cell<K::Col>],
    writer: &'a RowWriter,
    skip_bad: bool,
    errors: &'a std::sync::atomic::AtomicU64,
}

impl<'a, K: Kind> Chunks<'a, K> {
    fn new(
        kind: &'a K,
        cells: &'a [Cell<K::Col>],
        writer: &'a RowWriter,
        skip_bad: bool,
        errors: &'a std::sync::atomic::AtomicU64,
    ) -> Self {
        Chunks {
            kind,
            cells,
            writer,
            skip_bad,
            errors,
        }
    }
}

/// `cheap_chunk` compiled for the processor: for x86-64-v3 (AVX2 and FMA: the double-double
/// arithmetic's `mul_add` one instruction instead of a call, three-operand forms) where it has
/// them, else for the x86-64 baseline the binary is built for. The same bytes either way: IEEE
/// operations round alike in both, the compiler fuses no `a * b + c` that the source does not
/// ask for, and `mul_add` is the correctly rounded fused product either way
/// (`v3_writes_the_bytes_of_the_baseline` compares them). A planar row takes 19% fewer
/// instructions and 5-19% less time (docs/benchmarks.md).
fn chunk<K: Kind>(
    table: &Chunks<K>,
    point: &mut Vec<(Knob, f64)>,
    next: impl FnMut(&mut Vec<(Knob, f64)>) -> Option<Result<u64, RowError>>,
    place: impl Fn(u64, &[(Knob, f64)]) -> String,
) -> super::pipeline::ChunkOut {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma") {
        // SAFETY: the processor has every feature `cheap_chunk_v3` is compiled for.
        return unsafe { cheap_chunk_v3(table, point, next, place) };
    }
    cheap_chunk(table, point, next, place)
}

/// `cheap_chunk` for x86-64-v3: what it inlines (the kind's run and columns, marked
/// `#[inline(always)]` for this, the impact, the row's text) is compiled with these features.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx,avx2,fma,bmi1,bmi2,lzcnt,popcnt")]
fn cheap_chunk_v3<K: Kind>(
    table: &Chunks<K>,
    point: &mut Vec<(Knob, f64)>,
    next: impl FnMut(&mut Vec<(Knob, f64)>) -> Option<Result<u64, RowError>>,
    place: impl Fn(u64, &[(Knob, f64)]) -> String,
) -> super::pipeline::ChunkOut {
    cheap_chunk(table, point, next, place)
}

/// The rows of a chunk of cheap runs (`kind.cheap()`): `next` puts each point's parameters in
/// `point` and gives its number (or an input row that could not be read, which stops the chunk
/// or is skipped); `place` names a point in a message (only a failed one: formatting costs).
// Always inlined: into `cheap_chunk_v3` too, which is what gives it the features.
#[inline(always)]
fn cheap_chunk<K: Kind>(
    table: &Chunks<K>,
    point: &mut Vec<(Knob, f64)>,
    mut next: impl FnMut(&mut Vec<(Knob, f64)>) -> Option<Result<u64, RowError>>,
    place: impl Fn(u64, &[(Knob, f64)]) -> String,
) -> super::pipeline::ChunkOut {
    use super::pipeline::ChunkOut;
    use super::writer::Sealed;
    use std::sync::atomic::Ordering;
    let (kind, cells, writer, skip_bad, errors) = (
        table.kind,
        table.cells,
        table.writer,
        table.skip_bad,
        table.errors,
    );
    let with_error = error_at(cells).is_some();
    let mut buf = writer.buffer(CHUNK_ROWS);
    let mut fields = FieldCache::new(cells.len());
    let mut values = vec![0.0; cells.len()];
    let mut out = ChunkOut {
        body: Ok(Sealed::Bytes(Vec::new())),
        rows: 0,
        skipped: Vec::new(),
        stop: None,
    };
    while let Some(item) = next(point) {
        let failed = match item {
            Err(e) => Some(e),
            Ok(r) => {
                // A match, not `and_then`'s closure: a closure is compiled apart, without
                // `cheap_chunk_v3`'s instructions.
                let result = match kind.run(point) {
                    Ok(o) => fill(kind, cells, point, &o, &mut values),
                    Err(e) => Err(e),
                };
                match result {
                    Ok(()) => {
                        writer.row_of_run(&values, None, &mut buf, &mut fields);
                        None
                    }
                    Err(why) if with_error => {
                        fill_failed(cells, point, &mut values);
                        writer.row_of_run(&values, Some(&why), &mut buf, &mut fields);
                        errors.fetch_add(1, Ordering::Relaxed);
                        None
                    }
                    Err(why) => Some(RowError {
                        place: place(r, point),
                        problem: RowProblem::Run(why),
                    }),
                }
            }
        };
        if let Some(e) = failed {
            // A run refused, or a row of the input that is not one: skipped, or the end.
            if skip_bad && !e.problem.ends_input() {
                out.skipped.push(e);
                continue;
            }
            out.stop = Some(e);
            break;
        }
        out.rows += 1;
    }
    out.body = writer.seal(buf);
    out
}

/// Runs every point of `input` (a batch's rows: line numbers and parameters, in the order of
/// the parameters `cells` names) and writes their rows to `out`, in input order: `collide
/// batch` in the plane. The input is read a batch of chunks at a time, so memory stays bounded
/// whatever its size. A row that cannot be read stops the table (after every row before it) or,
/// with `skip_bad`, is reported and left out; a run that fails is a row with its error when
/// that column is shown.
pub fn write_points<K: Kind>(
    kind: &K,
    input: impl Iterator<Item = Point>,
    cells: &[Cell<K::Col>],
    writer: &RowWriter,
    skip_bad: bool,
    out: &mut dyn Write,
    progress: &mut Progress,
) -> Result<Summary, RowsError> {
    use super::pipeline::write_chunks;
    use std::sync::atomic::{AtomicU64, Ordering};
    let mut sink = Sink::open(writer, 1, out)?;
    let errors = AtomicU64::new(0);
    let mut input = input.peekable();
    let chunks = std::iter::from_fn(move || {
        input.peek()?;
        Some(input.by_ref().take(CHUNK_ROWS).collect::<Vec<_>>())
    });
    let solve = |items: Vec<Point>| {
        let mut items = items.into_iter();
        let next = |point: &mut Vec<(Knob, f64)>| {
            Some(items.next()?.map(|(line, p)| {
                *point = p;
                line
            }))
        };
        let table = Chunks::new(kind, cells, writer, skip_bad, &errors);
        chunk(&table, &mut Vec::new(), next, |line, _| {
            format!("line {line}")
        })
    };
    let mut summary = write_chunks(chunks, solve, &mut sink, progress)?;
    summary.errors = errors.load(Ordering::Relaxed);
    sink.finish()?;
    Ok(summary)
}

/// The knob `name` names (`m2`, `x1`, `wall-stiffness`), if `kind` has it.
pub fn knob<K: Kind>(kind: &K, name: &str) -> Option<Knob> {
    let name = name.trim().replace('-', "_");
    let body = |prefix: &str| -> Option<usize> {
        let i: usize = name.strip_prefix(prefix)?.parse().ok()?;
        (1..=kind.bodies()).contains(&i).then(|| i - 1)
    };
    if let Some(i) = body("m") {
        return Some(Knob::Mass(i));
    }
    if let Some(i) = body("x") {
        return Some(Knob::Position(i));
    }
    if let Some(i) = body("v") {
        return Some(Knob::Velocity(i));
    }
    if let Some(i) = body("s") {
        return Some(Knob::Size(i));
    }
    kind.scalars()
        .iter()
        .find(|s| **s == name)
        .map(|s| Knob::Named(s))
}

/// Parses a `--vary NAME=RANGE` of a run of `kind`.
pub fn vary<K: Kind>(kind: &K, text: &str) -> Result<Vary<Knob>, VaryError> {
    let n = kind.bodies();
    let form = format!(
        "{RANGE_FORMS} with NAME one of m1..m{n}, x1..x{n}, v1..v{n}, s1..s{n} (sizes), {}",
        kind.scalars().join(", ")
    );
    parse_vary(text, &form, |s| knob(kind, s), |k, v| kind.check(k, v))
}

/// A column of a table of runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Cell<C> {
    /// The value of the grid's i-th parameter.
    Param(usize),
    /// A summary column.
    Of(C),
    /// Why the run failed (text).
    Error,
}

/// The name of the column of failures.
pub const ERROR: &str = "error";

/// A table's columns and their names.
pub type Cells<C> = (Vec<Cell<C>>, Vec<String>);

/// A row of a batch: its line and its parameters, or why it could not be read.
pub type Point = Result<(u64, Vec<(Knob, f64)>), RowError>;

/// A run done: its row, its parameters, what it gave.
type Done<O> = (u64, Vec<(Knob, f64)>, Result<O, String>);

/// The columns: `chosen`, or the parameters (those a grid varies, or a batch's inputs), the
/// kind's defaults and `error`.
pub fn cells<K: Kind>(
    kind: &K,
    params: &[Knob],
    chosen: &[String],
) -> Result<Cells<K::Col>, String> {
    let names: Vec<String> = if chosen.is_empty() {
        let mut n: Vec<String> = params.iter().map(Named::name).collect();
        n.extend(kind.defaults());
        n.push(ERROR.into());
        n
    } else {
        chosen.iter().map(|c| c.trim().replace('-', "_")).collect()
    };
    let mut cells = Vec::with_capacity(names.len());
    for (i, name) in names.iter().enumerate() {
        if names[..i].contains(name) {
            return Err(format!(
                "column '{name}' is given twice: give each column once"
            ));
        }
        let cell = if name == ERROR {
            Cell::Error
        } else if let Some(p) = params.iter().position(|k| k.name() == *name) {
            Cell::Param(p)
        } else if let Some(c) = kind.column(name) {
            Cell::Of(c)
        } else {
            let params: Vec<String> = params.iter().map(Named::name).collect();
            // The summary columns that are not also parameters (nx, ny of a batch).
            let forms = kind.column_forms();
            let forms: Vec<&str> = forms
                .split(", ")
                .filter(|c| !params.iter().any(|p| p == c))
                .collect();
            return Err(format!(
                "'{name}' is not a column: expected a parameter ({}), {}, or {ERROR}",
                params.join(", "),
                forms.join(", ")
            ));
        };
        cells.push(cell);
    }
    Ok((cells, names))
}

/// Which columns count (collisions, steps; `Kind::counts`), for
/// [`RowWriter::with_integers`].
pub fn counts<K: Kind>(kind: &K, cells: &[Cell<K::Col>]) -> Vec<bool> {
    cells
        .iter()
        .map(|c| matches!(c, Cell::Of(col) if kind.counts(*col)))
        .collect()
}

/// Where the `error` column is.
pub fn error_at<C>(cells: &[Cell<C>]) -> Option<usize> {
    cells.iter().position(|c| matches!(c, Cell::Error))
}

/// `m2=3, zeta=0.2`: a run's parameters, for messages.
fn describe(point: &[(Knob, f64)]) -> String {
    point
        .iter()
        .map(|(k, v)| format!("{}={}", k.name(), ryu::Buffer::new().format(*v)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Most runs a batch may hold.
const MAX_BATCH: u64 = 1 << 14;

/// Runs the rows of `shard` of the grid and writes them to `out`, in grid order.
#[allow(clippy::too_many_arguments)]
pub fn write_runs<K: Kind>(
    kind: &K,
    grid: &Grid<Knob>,
    shard: Shard,
    cells: &[Cell<K::Col>],
    writer: &RowWriter,
    skip_bad: bool,
    out: &mut dyn Write,
    progress: &mut Progress,
) -> Result<Summary, RowsError> {
    let rows = shard.rows(grid.total);
    let mut sink = Sink::open(writer, shard.k, out)?;
    if kind.cheap() {
        let summary = write_cheap(
            kind, grid, rows, cells, writer, skip_bad, &mut sink, progress,
        )?;
        sink.finish()?;
        return Ok(summary);
    }
    let mut summary = Summary::default();
    let mut buf = writer.buffer(CHUNK_ROWS);
    let mut in_buf = 0usize;
    let mut fields = FieldCache::new(cells.len());
    let mut values = vec![0.0; cells.len()];
    let threads = rayon::current_num_threads().max(1) as u64;
    let mut batch = threads;
    let mut next = rows.start;
    while next < rows.end {
        let end = (next + batch).min(rows.end);
        let started = Instant::now();
        let done: Vec<Done<K::Out>> = (next..end)
            .into_par_iter()
            .map(|r| {
                let mut point = vec![(Knob::Named(""), 0.0); grid.vary.len()];
                grid.row(r, &mut point);
                let out = kind.run(&point);
                (r, point, out)
            })
            .collect();
        for (r, point, result) in done {
            let result = result.and_then(|o| fill(kind, cells, &point, &o, &mut values));
            match result {
                Ok(()) => writer.row_of_run(&values, None, &mut buf, &mut fields),
                Err(why) if error_at(cells).is_some() => {
                    fill_failed(cells, &point, &mut values);
                    writer.row_of_run(&values, Some(&why), &mut buf, &mut fields);
                    summary.errors += 1;
                }
                Err(why) => {
                    let e = RowError {
                        place: format!("run {} ({})", r + 1, describe(&point)),
                        problem: RowProblem::Run(why),
                    };
                    if !skip_bad {
                        sink.put(writer.seal(buf)?)?;
                        sink.flush()?;
                        return Err(e.into());
                    }
                    crate::values::output::diagnostic(format_args!("skipped {e}"));
                    summary.skipped += 1;
                    continue;
                }
            }
            summary.rows += 1;
            in_buf += 1;
            if in_buf == CHUNK_ROWS {
                let full = std::mem::replace(&mut buf, writer.buffer(CHUNK_ROWS));
                sink.put(writer.seal(full)?)?;
                in_buf = 0;
            }
        }
        progress.advance(end - next);
        next = end;
        // About half a second to a second a batch.
        let took = started.elapsed();
        if took < Duration::from_millis(250) {
            batch = (batch * 2).min(MAX_BATCH);
        } else if took > Duration::from_secs(1) {
            batch = (batch / 2).max(threads);
        }
    }
    if in_buf > 0 {
        sink.put(writer.seal(buf)?)?;
    }
    sink.finish()?;
    Ok(summary)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A kind whose run is `y = 2 x1`, failing for x1 < 0: the engine alone.
    struct Double;

    impl Kind for Double {
        type Out = f64;
        type Col = ();
        fn scalars(&self) -> &'static [&'static str] {
            &["k"]
        }
        fn bodies(&self) -> usize {
            1
        }
        fn check(&self, _: Knob, _: &Number) -> Result<(), ValueProblem> {
            Ok(())
        }
        fn run(&self, point: &[(Knob, f64)]) -> Result<f64, String> {
            let x = point[0].1;
            if x < 0.0 {
                Err(format!("x1 = {x} < 0"))
            } else {
                Ok(2.0 * x)
            }
        }
        fn column(&self, name: &str) -> Option<()> {
            (name == "y").then_some(())
        }
        fn defaults(&self) -> Vec<String> {
            vec!["y".into()]
        }
        fn column_forms(&self) -> String {
            "y".into()
        }
        fn value(&self, _: (), out: &f64) -> Option<f64> {
            Some(*out)
        }
    }

    fn table(vary: &str, chosen: &[&str], skip_bad: bool) -> (Result<Summary, String>, String) {
        let grid = Grid::new(vec![super::vary(&Double, vary).unwrap()], 100).unwrap();
        let chosen: Vec<String> = chosen.iter().map(|s| s.to_string()).collect();
        let params: Vec<Knob> = grid.vary.iter().map(|v| v.param).collect();
        let (cells, names) = cells(&Double, &params, &chosen).unwrap();
        let w = RowWriter::runs(
            names,
            error_at(&cells),
            super::super::writer::RowFormat::Csv,
        );
        let mut out = Vec::new();
        let r = write_runs(
            &Double,
            &grid,
            Shard::WHOLE,
            &cells,
            &w,
            skip_bad,
            &mut out,
            &mut Progress::new(None),
        );
        (
            r.map_err(|e| e.to_string()),
            String::from_utf8(out).unwrap(),
        )
    }

    #[test]
    fn rows_in_grid_order_with_failures_as_error_rows() {
        let (r, out) = table("x1=-1:2:4", &[], false);
        assert_eq!(
            out,
            "x1,y,error\n-1.0,,x1 = -1 < 0\n0.0,0.0,\n1.0,2.0,\n2.0,4.0,\n"
        );
        assert_eq!(
            r.unwrap(),
            Summary {
                rows: 4,
                skipped: 0,
                errors: 1
            }
        );
    }

    #[test]
    fn without_an_error_column_a_failure_stops_or_is_skipped() {
        let (r, out) = table("x1=1,-1,2", &["x1", "y"], false);
        assert_eq!(out, "x1,y\n1.0,2.0\n");
        assert_eq!(r.unwrap_err(), "run 2 (x1=-1.0): x1 = -1 < 0");
        let (r, out) = table("x1=1,-1,2", &["x1", "y"], true);
        assert_eq!(out, "x1,y\n1.0,2.0\n2.0,4.0\n");
        assert_eq!(r.unwrap().skipped, 1);
    }

    /// `columns::run_columns` gives the rows `write_runs` writes: the same values, the same
    /// failures (an error row, a stop, a skip).
    #[test]
    fn columns_are_the_written_rows() {
        let run = |vary: &str, chosen: &[&str], skip_bad: bool| {
            let grid = Grid::new(vec![super::vary(&Double, vary).unwrap()], 100).unwrap();
            let chosen: Vec<String> = chosen.iter().map(|s| s.to_string()).collect();
            let params: Vec<Knob> = grid.vary.iter().map(|v| v.param).collect();
            let (cells, names) = cells(&Double, &params, &chosen).unwrap();
            columns::run_columns(&Double, &grid, Shard::WHOLE, &cells, names, skip_bad)
        };
        let t = run("x1=-1:2:4", &[], false).unwrap();
        assert_eq!(t.names, ["x1", "y", "error"]);
        assert_eq!(t.values[0], [-1.0, 0.0, 1.0, 2.0]);
        assert!(t.values[1][0].is_nan());
        assert_eq!(t.values[1][1..], [0.0, 2.0, 4.0]);
        assert!(t.values[2].is_empty());
        let errors = t.errors.unwrap();
        assert_eq!(errors, [Some("x1 = -1 < 0".to_string()), None, None, None]);
        let e = run("x1=1,-1,2", &["x1", "y"], false).unwrap_err();
        assert_eq!(e.to_string(), "run 2 (x1=-1.0): x1 = -1 < 0");
        let t = run("x1=1,-1,2", &["x1", "y"], true).unwrap();
        assert_eq!(
            (t.values[0].clone(), t.values[1].clone()),
            (vec![1.0, 2.0], vec![2.0, 4.0])
        );
        assert_eq!(t.skipped.len(), 1);
        assert!(t.errors.is_none());
    }

    #[test]
    fn knobs_by_name() {
        assert_eq!(knob(&Double, "m1"), Some(Knob::Mass(0)));
        assert_eq!(knob(&Double, "m2"), None, "one body");
        assert_eq!(knob(&Double, "k"), Some(Knob::Named("k")));
        let e = super::vary(&Double, "q=1,2").unwrap_err().to_string();
        assert!(e.contains("with NAME one of m1..m1, x1..x1"), "{e}");
    }
}
