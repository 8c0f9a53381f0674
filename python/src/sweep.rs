//! `collide.sweep`: `collide sweep`'s grid (`--vary` and the case, parsed and checked by the
//! command's own code, `commands::table::rail_sweep`), its rows (`SweepRows`) solved by the table
//! engine's row (`solve_row`) in parallel with the GIL released, into one float64 buffer per
//! column, handed to NumPy without a copy and to Polars or pandas as a DataFrame: no text
//! between the solver and the frame.

use numpy::PyArray1;
use pyo3::exceptions::PyImportError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;

use collide::table::engine::{SweepRows, solve_row};
use collide::table::pipeline::CHUNK_ROWS;
use collide::table::row::RowError;

use crate::cli::Command;
use crate::commands::table::{RailSweep, rail_sweep};
use crate::refused;

/// A sweep of collisions over a grid of parameters, on a rail or in the plane, as `collide
/// sweep` computes it, as a DataFrame: Polars (`to="polars"`, the default), pandas (`to="pandas"`), or a dict of NumPy
/// arrays (`to="numpy"`).
///
/// `vary` is `--vary` (one text or a list: `"e=0:1:11"`, `"m2=1e-3:1e3:7:log"`,
/// `"v1=1,2,3"`; the last varies fastest); `m`, `v`, `e` and the other keywords are `collide
/// sweep`'s flags (`columns=`, `inertia=`, `shard=`, `max_rows=`, `skip_bad=True`). Every value
/// is the binary64 `collide sweep` prints for the row. A bad row raises `CollideError` with the
/// command's message, unless `skip_bad=True`, which leaves it out as the command does.
///
/// >>> df = sweep(m=(4, 1), v=(60, 10), vary="e=0:1:3", columns=["e", "fin1", "fin2"], to="numpy")
/// >>> df["fin1"], df["fin2"]
/// (array([50., 45., 40.]), array([50., 70., 90.]))
#[pyfunction]
#[pyo3(signature = (m=None, v=None, e=None, *, vary, to="polars", **flags))]
pub fn sweep<'py>(
    py: Python<'py>,
    m: Option<&Bound<'py, PyAny>>,
    v: Option<&Bound<'py, PyAny>>,
    e: Option<&Bound<'py, PyAny>>,
    vary: &Bound<'py, PyAny>,
    to: &str,
    flags: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let frame = frame_module(py, to)?;
    let leading = [("m", m), ("v", v), ("e", e), ("vary", Some(vary))];
    let args = crate::functions::words_of(py, "sweep", &leading, flags)?;
    let Command::Sweep(args) = crate::command::parse(&args)?.command else {
        unreachable!("the words are a sweep's")
    };
    if args.case.spatial() {
        return runs_frame(py, Command::Sweep(args), frame);
    }
    let RailSweep {
        case,
        grid,
        columns,
    } = rail_sweep(&args).map_err(|e| refused(format!("{e:#}")))?;
    let rows = args.shard.rows(grid.total);
    let skip_bad = args.table.skip_bad;
    let (out, bad) = py.detach(|| {
        let of = SweepRows::new(&case, &grid);
        let starts: Vec<u64> = (rows.start..rows.end).step_by(CHUNK_ROWS).collect();
        let chunks: Vec<(Vec<Vec<f64>>, Vec<RowError>)> = starts
            .into_par_iter()
            .map(|s| {
                let end = (s + CHUNK_ROWS as u64).min(rows.end);
                let mut cols: Vec<Vec<f64>> = (0..columns.len())
                    .map(|_| Vec::with_capacity((end - s) as usize))
                    .collect();
                let mut values = vec![0.0; columns.len()];
                let mut bad = Vec::new();
                for r in s..end {
                    let case = of.row(r);
                    match solve_row(&case, of.shared.as_ref(), &columns, &mut values) {
                        Ok(()) => cols.iter_mut().zip(&values).for_each(|(c, x)| c.push(*x)),
                        Err(problem) => bad.push(RowError {
                            place: format!("row {}", r + 1),
                            problem,
                        }),
                    }
                }
                (cols, bad)
            })
            .collect();
        let mut out: Vec<Vec<f64>> = (0..columns.len())
            .map(|_| Vec::with_capacity((rows.end - rows.start) as usize))
            .collect();
        let mut bad = Vec::new();
        for (cols, errors) in chunks {
            out.iter_mut().zip(cols).for_each(|(o, c)| o.extend(c));
            bad.extend(errors);
        }
        (out, bad)
    });
    if let Some(e) = bad.iter().find(|e| !skip_bad || e.problem.ends_input()) {
        return Err(refused(format!(
            "{e} (skip_bad=True leaves bad rows out and goes on)"
        )));
    }
    let dict = PyDict::new(py);
    for (col, values) in columns.iter().zip(out) {
        dict.set_item(col.name, PyArray1::from_vec(py, values))?;
    }
    finish(dict, frame)
}

/// A table of runs (`collide sweep` in the plane, `collide track --vary`, `collide contact
/// --vary`: `command`), run by the command's own code (`commands::table::columns_of`) with the
/// GIL released, as a DataFrame of `frame`'s module or a dict of NumPy arrays. Counts
/// (collisions, steps) are int64 where every run has one, as the command writes them as
/// integers; the `error` column holds the failed runs' messages (None for the others).
pub fn runs_frame<'py>(
    py: Python<'py>,
    command: Command,
    frame: Option<Bound<'py, PyModule>>,
) -> PyResult<Bound<'py, PyAny>> {
    let table = py
        .detach(|| crate::commands::table::columns_of(command))
        .map_err(|e| refused(format!("{e:#}")))?
        .ok_or_else(|| {
            refused("vary= names no parameter: give at least one, as NAME=RANGE (\"e=0:1:11\")")
        })?;
    let dict = PyDict::new(py);
    let mut values = table.values.into_iter();
    let mut errors = table.errors;
    for (name, integer) in table.names.iter().zip(table.integers) {
        let column = values.next().unwrap_or_default();
        if name == collide::table::runs::ERROR {
            dict.set_item(name, errors.take().unwrap_or_default())?;
        } else if integer && column.iter().all(|x| x.is_finite()) {
            let counts: Vec<i64> = column.iter().map(|&x| x as i64).collect();
            dict.set_item(name, PyArray1::from_vec(py, counts))?;
        } else {
            dict.set_item(name, PyArray1::from_vec(py, column))?;
        }
    }
    finish(dict, frame)
}

/// `to=`'s module: Polars or pandas (imported), or `None` for a dict of NumPy arrays.
pub fn frame_module<'py>(py: Python<'py>, to: &str) -> PyResult<Option<Bound<'py, PyModule>>> {
    match to {
        "polars" | "pandas" => Ok(Some(import(py, to)?)),
        "numpy" => Ok(None),
        _ => Err(refused(format!(
            "to='{to}': a table is a 'polars' or a 'pandas' DataFrame, or 'numpy' (a dict of \
             arrays)"
        ))),
    }
}

/// The columns as `frame`'s DataFrame, or the dict itself.
fn finish<'py>(
    dict: Bound<'py, PyDict>,
    frame: Option<Bound<'py, PyModule>>,
) -> PyResult<Bound<'py, PyAny>> {
    match frame {
        Some(module) => module.call_method1("DataFrame", (dict,)),
        None => Ok(dict.into_any()),
    }
}

/// Polars or pandas, imported when a sweep asks for its DataFrame.
fn import<'py>(py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyModule>> {
    py.import(name).map_err(|e| {
        PyImportError::new_err(format!(
            "collide.sweep(to='{name}') needs {name} ({e}): pip install {name}, or pass \
             to='numpy' for a dict of NumPy arrays"
        ))
    })
}
