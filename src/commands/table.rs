//! `collide sweep` and `collide batch`: tables of collisions for scripts; also a `[sweep]` scene.

use anyhow::Result;
use clap::ValueEnum;
use collide::line::case::Case;
use collide::table::batch;
use collide::table::columns::Column;
use collide::table::engine::{write_batch, write_sweep};
use collide::table::pipeline::{RowsError, Summary};
use collide::table::sweep::{Grid, Param, Shard};
use collide::table::writer::{Header, RowFormat, RowWriter};
use collide::values::output::{Output, Progress};

use collide::table::runs::{self, Kind};

use super::Outcome;
use crate::cli::{BatchArgs, Command, RunFormat, RunTableArgs, SweepArgs, TableArgs};

pub fn sweep(args: SweepArgs) -> Result<Outcome> {
    if args.case.spatial() {
        return plane_sweep(args);
    }
    let RailSweep {
        case,
        grid,
        columns,
    } = rail_sweep(&args)?;
    let writer = RowWriter::new(columns, format_of(&args.table)?);
    write_rows(&case, &grid, args.shard, &args.table, writer)
}

/// A sweep on a rail, checked: the case, its grid and its columns.
pub struct RailSweep {
    pub case: Case,
    pub grid: Grid,
    pub columns: Vec<&'static Column>,
}

/// The sweep on a rail of `args` (a case in the plane is `plane_sweep`'s), checked: what `collide
/// sweep` writes and the Python module's `collide.sweep` solves into columns.
pub fn rail_sweep(args: &SweepArgs) -> Result<RailSweep> {
    let vary = args
        .vary
        .iter()
        .map(|v| {
            v.parse::<collide::table::sweep::Vary>().map_err(|e| {
                let plane = e.to_string();
                anyhow::anyhow!("--vary '{v}': {plane} (b, normal_deg, v1x, ... are for the plane)")
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let case = args.case.clone().into_case(false)?;
    let grid = Grid::new(vary, args.max_rows)?;
    let columns = checked(&case, &grid, &args.table)?;
    Ok(RailSweep {
        case,
        grid,
        columns,
    })
}

/// `collide sweep` in the plane: two bodies with 2-vectors and a line of impact
/// (`table::runs::plane`), one row per point of the grid.
fn plane_sweep(args: SweepArgs) -> Result<Outcome> {
    let (kind, runs, format) = plane_runs(args)?;
    run_table(&kind, &runs, format)
}

/// The runs of a sweep in the plane: its kind, its table's arguments and its format.
fn plane_runs(
    args: SweepArgs,
) -> Result<(
    collide::table::runs::plane::PlaneSweep,
    RunTableArgs,
    Option<RunFormat>,
)> {
    use collide::table::runs::plane::{Line, PlaneSweep};
    let posed = args.case.space_input(None, false)?.pose()?;
    let st = &posed.statement;
    if st.dim != 2 || st.masses.len() != 2 {
        anyhow::bail!(
            "a sweep of a collision away from a line is of two bodies in the plane (this case \
             has {} bodies in {} dimensions)",
            st.masses.len(),
            st.dim
        );
    }
    let f =
        |q: &collide::values::rational::Q| collide::values::rational::to_f64(q).unwrap_or(f64::NAN);
    let m: Vec<f64> = st
        .masses
        .iter()
        .map(|g| g.known().map(f))
        .collect::<Option<_>>()
        .ok_or_else(|| anyhow::anyhow!("a sweep takes known masses, not '?'"))?;
    let v: Vec<[f64; 2]> = st
        .v_in
        .iter()
        .map(|w| w.value().map(|w| [f(&w[0]), f(&w[1])]))
        .collect::<Option<_>>()
        .ok_or_else(|| anyhow::anyhow!("a sweep takes known velocities, not '?'"))?;
    let e = match &st.e {
        None => 1.0,
        Some(g) => g
            .known()
            .map(f)
            .ok_or_else(|| anyhow::anyhow!("a sweep takes a known e, not '?'"))?,
    };
    let line = match (args.case.geometry()?, &st.normal) {
        (Some((r, b)), _) => Line::Geometry {
            r: [r[0].value(), r[1].value()],
            b: b.value(),
        },
        (_, Some(n)) => Line::Normal([f(&n[0]), f(&n[1])]),
        _ => anyhow::bail!(
            "a sweep in the plane needs the line of impact: --normal, or --radii with \
             --impact-parameter"
        ),
    };
    let kind = PlaneSweep {
        m: [m[0], m[1]],
        v: [v[0], v[1]],
        line,
        e,
    };
    let format = match args.table.format {
        None => None,
        Some(RowFormat::Text) => Some(RunFormat::Text),
        Some(RowFormat::Csv) => Some(RunFormat::Csv),
        Some(RowFormat::Jsonl) => Some(RunFormat::Jsonl),
        Some(RowFormat::Parquet) => Some(RunFormat::Parquet),
    };
    let runs = RunTableArgs {
        vary: args.vary,
        shard: Some(args.shard),
        max_rows: args.max_rows,
        columns: args.table.columns,
        output: args.table.output,
        skip_bad: args.table.skip_bad,
        header: args.table.header,
    };
    Ok((kind, runs, format))
}

/// The table of runs `command` asks for, as columns (`run_columns`): a sweep in the plane,
/// `track --vary` or `contact --vary`; `None` for any other command (a sweep on a rail is the
/// table engine's, `SweepRows`).
pub fn columns_of(command: Command) -> Result<Option<runs::columns::RunColumns>> {
    Ok(Some(match command {
        Command::Sweep(args) if args.case.spatial() => {
            let (kind, runs, _) = plane_runs(args)?;
            run_columns(&kind, &runs)?
        }
        Command::Track(args) if !args.table.vary.is_empty() => {
            run_columns(&super::track::sweep_kind(&args)?, &args.table)?
        }
        Command::Contact(args) if !args.table.vary.is_empty() => {
            run_columns(&super::contact::sweep_kind(&args)?, &args.table)?
        }
        _ => return Ok(None),
    }))
}

/// Writes the table of a sweep of `case` over `grid` (the rows of `shard`).
pub fn run_sweep(case: &Case, grid: &Grid, shard: Shard, table: &TableArgs) -> Result<Outcome> {
    let writer = RowWriter::new(checked(case, grid, table)?, format_of(table)?);
    write_rows(case, grid, shard, table, writer)
}

/// The columns of a sweep of `case` over `grid`, once the sweep is one a table can hold.
fn checked(case: &Case, grid: &Grid, table: &TableArgs) -> Result<Vec<&'static Column>> {
    if let Some(unit) = case.units.energy_as {
        // A table's columns carry no unit: its energies are the case's own.
        anyhow::bail!(
            "--energy-unit {} (energy_unit in a scene): a table's energies are in the case's own \
             unit, {}, and its columns carry no unit label; drop it, or convert the columns",
            unit.name,
            collide::values::units::Units {
                energy_as: None,
                ..case.units.clone()
            }
            .energy()
        );
    }
    let general = !case.inertia().is_diagonal();
    if general && (grid.varies(Param::M1) || grid.varies(Param::M2)) {
        anyhow::bail!("--vary m1 or m2 needs --masses; with --inertia, vary v1, v2 or e");
    }
    columns(&table.columns, general)
}

/// Writes the rows of `shard` of a sweep with `writer`.
fn write_rows(
    case: &Case,
    grid: &Grid,
    shard: Shard,
    table: &TableArgs,
    writer: RowWriter,
) -> Result<Outcome> {
    let (mut out, writer) = open(table, writer)?;
    let rows = shard.rows(grid.total);
    let mut progress = Progress::new(Some(rows.end - rows.start));
    let result = write_sweep(
        case,
        grid,
        shard,
        &writer,
        table.skip_bad,
        &mut out,
        &mut progress,
    );
    finish(result, out, &progress, table)
}

pub fn batch(args: BatchArgs) -> Result<Outcome> {
    let mut input = batch::open(
        args.input.as_deref(),
        args.input_format,
        args.restitution.value(),
    )?;
    if let Some((kind, params)) = input.plane.take() {
        return plane_batch(input, &kind, &params, &args.table);
    }
    let writer = RowWriter::new(
        columns(&args.table.columns, input.general)?,
        format_of(&args.table)?,
    );
    let (mut out, writer) = open(&args.table, writer)?;
    let mut progress = Progress::new(None);
    let result = write_batch(input, &writer, args.table.skip_bad, &mut out, &mut progress);
    finish(result, out, &progress, &args.table)
}

/// `collide batch` in the plane: each row gives the parameters of a sweep in the plane
/// (`table::runs::plane`); the columns are those of `collide sweep` in the plane, after the
/// inputs.
fn plane_batch(
    input: batch::Batch,
    kind: &collide::table::runs::plane::PlaneSweep,
    params: &[runs::Knob],
    table: &TableArgs,
) -> Result<Outcome> {
    let (cells, names) =
        runs::cells(kind, params, &table.columns).map_err(|e| anyhow::anyhow!("--columns: {e}"))?;
    let writer = RowWriter::runs(names, runs::error_at(&cells), format_of(table)?);
    let (mut out, writer) = open(table, writer)?;
    let mut progress = Progress::new(None);
    let result = runs::write_points(
        kind,
        input.in_the_plane(),
        &cells,
        &writer,
        table.skip_bad,
        &mut out,
        &mut progress,
    );
    finish(result, out, &progress, table)
}

fn columns(chosen: &[String], general: bool) -> Result<Vec<&'static Column>> {
    if chosen.is_empty() {
        Ok(Column::defaults(general))
    } else {
        chosen
            .iter()
            .map(|c| {
                c.parse::<&'static Column>().map_err(|e| {
                    anyhow::anyhow!("--columns: {e} ({c} is a column of a sweep in the plane)")
                })
            })
            .collect()
    }
}

/// Opens where the rows go, once `writer` (its format from [`format_of`]) is known to be
/// writable: nothing is opened, so no file is truncated in place, for a run that is refused.
/// The header goes in every shard written to a file (each reads on its own), only in the first
/// on stdout or a device (the shards concatenated are the whole table), unless `--header` says
/// otherwise.
fn open(table: &TableArgs, writer: RowWriter) -> Result<(Output, RowWriter)> {
    writer.check().map_err(anyhow::Error::msg)?;
    let out = Output::open(table.output.as_deref()).map_err(|e| output_error(table, e))?;
    let header = header(table, &out);
    Ok((out, writer.with_header(header)))
}

/// The header's pieces: `--header`, else every shard of a file, the first on stdout.
fn header(table: &TableArgs, out: &Output) -> Header {
    table.header.unwrap_or(if out.is_file() {
        Header::Always
    } else {
        Header::First
    })
}

/// How the rows are written: `--format`, else the format `-o`'s extension names (`.csv`,
/// `.jsonl`, `.ndjson`, `.parquet`; `.txt`: text), else CSV; a format the name contradicts is
/// refused (`-o x.jsonl` wrote CSV), and so is a name of a format collide does not write.
/// Parquet is written to a file only (`-o`), and always has its schema.
fn format_of(table: &TableArgs) -> Result<RowFormat> {
    let extension = table
        .output
        .as_deref()
        .and_then(|p| p.extension())
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let named = match extension.as_deref() {
        Some("csv") => Some(RowFormat::Csv),
        Some("jsonl" | "ndjson") => Some(RowFormat::Jsonl),
        Some("parquet" | "pq") => Some(RowFormat::Parquet),
        _ => None,
    };
    // Names of formats collide does not write: CSV in them would pass for what they name.
    if table.format.is_none()
        && let Some(e) = extension.as_deref()
        && let Some(instead) = match e {
            "json" => Some(
                "a table is JSON Lines, one object a line, not one JSON document: name \
                 it .jsonl",
            ),
            "tsv" | "tab" => Some("collide writes comma-separated tables: name it .csv"),
            "xlsx" | "xls" | "ods" => Some(
                "collide writes no spreadsheets: name it .csv, which \
                 they open",
            ),
            _ => None,
        }
    {
        anyhow::bail!(
            "-o {} names a .{e} file, which collide does not write: {instead}, or give --format \
             csv|jsonl|text|parquet",
            target(table)
        );
    }
    let format = match (table.format, named) {
        (Some(f), Some(n)) if f != n => anyhow::bail!(
            "-o {} names a {} file, but --format is {}: name the file for its format, or leave \
             out --format",
            target(table),
            n.name(),
            f.name()
        ),
        (Some(f), _) | (None, Some(f)) => f,
        // A `.txt` file is for people (text), unless --format says otherwise.
        (None, None) if extension.as_deref() == Some("txt") => RowFormat::Text,
        (None, None) => RowFormat::Csv,
    };
    if format == RowFormat::Parquet {
        if Output::is_stdout(table.output.as_deref()) {
            anyhow::bail!(
                "--format parquet writes a file: give -o FILE.parquet (a Parquet file ends with \
                 its footer, so it is not streamed to stdout)"
            );
        }
        if let Some(h) = table.header {
            anyhow::bail!(
                "--header {} is for csv and text: a Parquet file always carries its schema",
                h.to_possible_value()
                    .map_or("?".into(), |v| v.get_name().to_string())
            );
        }
    }
    Ok(format)
}

fn output_error(table: &TableArgs, e: std::io::Error) -> anyhow::Error {
    anyhow::Error::new(e).context(format!("cannot write {}", target(table)))
}

/// `-o`'s path, or stdout.
fn target(table: &TableArgs) -> String {
    table
        .output
        .as_ref()
        .map_or("stdout".into(), |p| p.display().to_string())
}

/// Ends a table run: commits the output when complete (a bad row leaves no file behind), and
/// reports skipped rows.
fn finish(
    result: Result<Summary, RowsError>,
    out: Output,
    progress: &Progress,
    table: &TableArgs,
) -> Result<Outcome> {
    progress.finish();
    let summary = match result {
        Ok(s) => s,
        // `out` is dropped unfinished: a temporary file is removed, stdout keeps whole rows.
        Err(RowsError::Row(e)) => {
            let hint = if table.skip_bad {
                ""
            } else {
                " (--skip-bad reports bad rows and goes on)"
            };
            return Err(anyhow::anyhow!("{e}{hint}"));
        }
        // Named by path; the io::Error stays in the chain (a closed stdout is no error).
        Err(RowsError::Io(e)) => {
            return Err(output_error(table, e));
        }
    };
    out.commit().map_err(|e| output_error(table, e))?;
    if summary.skipped > 0 {
        collide::values::output::diagnostic(format_args!(
            "{} rows written, {} bad rows skipped",
            summary.rows, summary.skipped
        ));
    }
    if summary.errors > 0 {
        collide::values::output::diagnostic(format_args!(
            "{} of {} runs failed: their rows give why in the error column",
            summary.errors, summary.rows
        ));
    }
    Ok(Outcome::print(String::new()))
}

/// A table of runs checked against its kind: the grid of `--vary`, the columns and their names.
pub struct RunGrid<C> {
    pub grid: Grid<runs::Knob>,
    pub cells: Vec<runs::Cell<C>>,
    pub names: Vec<String>,
}

/// The grid and columns of a table of runs of `kind` (`--vary`, `--columns`, `--max-rows`),
/// checked before anything runs.
pub fn run_grid<K: Kind>(kind: &K, args: &RunTableArgs) -> Result<RunGrid<K::Col>> {
    let vary = args
        .vary
        .iter()
        .map(|v| runs::vary(kind, v))
        .collect::<Result<Vec<_>, _>>()?;
    for group in [
        ["damping", "zeta", "e"],
        ["wall_damping", "wall_zeta", "wall_restitution"],
    ] {
        let named: Vec<&str> = vary
            .iter()
            .filter_map(|v| match v.param {
                runs::Knob::Named(n) if group.contains(&n) => Some(n),
                _ => None,
            })
            .collect();
        if named.len() > 1 {
            anyhow::bail!(
                "{} are one damping given two ways: vary one of them",
                named.join(" and ")
            );
        }
    }
    let grid = Grid::new(vary, args.max_rows)?;
    let params: Vec<runs::Knob> = grid.vary.iter().map(|v| v.param).collect();
    let (cells, names) = runs::cells(kind, &params, &args.columns).map_err(anyhow::Error::msg)?;
    Ok(RunGrid { grid, cells, names })
}

/// The table of runs of `kind` over `args`' grid as columns (`table::runs::columns`): what
/// `run_table` writes, every value the same binary64, for the Python module's DataFrames.
pub fn run_columns<K: Kind>(kind: &K, args: &RunTableArgs) -> Result<runs::columns::RunColumns> {
    let RunGrid { grid, cells, names } = run_grid(kind, args)?;
    let shard = args.shard.unwrap_or(Shard::WHOLE);
    runs::columns::run_columns(kind, &grid, shard, &cells, names, args.skip_bad).map_err(|e| {
        let hint = if args.skip_bad {
            ""
        } else {
            " (--skip-bad reports bad rows and goes on)"
        };
        anyhow::anyhow!("{e}{hint}")
    })
}

/// `collide track --vary`, `collide contact --vary`: the table of runs of `kind` over the grid
/// of `args.vary`.
pub fn run_table<K: Kind>(
    kind: &K,
    args: &RunTableArgs,
    format: Option<RunFormat>,
) -> Result<Outcome> {
    let RunGrid { grid, cells, names } = run_grid(kind, args)?;
    let table = TableArgs {
        columns: Vec::new(),
        format: match format {
            None => None,
            Some(RunFormat::Json) => anyhow::bail!(
                "--format json is one run's report: a table of runs is csv, jsonl (one JSON \
                 object a line), text or parquet"
            ),
            Some(RunFormat::Text) => Some(RowFormat::Text),
            Some(RunFormat::Csv) => Some(RowFormat::Csv),
            Some(RunFormat::Jsonl) => Some(RowFormat::Jsonl),
            Some(RunFormat::Parquet) => Some(RowFormat::Parquet),
        },
        output: args.output.clone(),
        skip_bad: args.skip_bad,
        header: args.header,
    };
    let writer = RowWriter::runs(names, runs::error_at(&cells), format_of(&table)?)
        .with_integers(runs::counts(kind, &cells));
    let (mut out, writer) = open(&table, writer)?;
    let shard = args.shard.unwrap_or(Shard::WHOLE);
    let rows = shard.rows(grid.total);
    let mut progress = Progress::new(Some(rows.end - rows.start));
    let result = runs::write_runs(
        kind,
        &grid,
        shard,
        &cells,
        &writer,
        table.skip_bad,
        &mut out,
        &mut progress,
    );
    finish(result, out, &progress, &table)
}
