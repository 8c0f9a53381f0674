//! `collide.solve_many`: NumPy arrays of masses, velocities and restitutions, broadcast as NumPy
//! broadcasts them, solved row by row by the table engine's own row
//! (`collide::table::engine::solve_row`, which `collide sweep` and `collide batch` print), in
//! parallel (rayon, chunks of the engine's `CHUNK_ROWS`) with the GIL released.

use numpy::ndarray::{ArrayViewD, IxDyn};
use numpy::{AllowTypeChange, PyArray1, PyArrayLikeDyn, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;

use collide::table::columns::{Column, by_names};
use collide::table::engine::solve_row;
use collide::table::pipeline::CHUNK_ROWS;
use collide::table::row::RowCase;

use crate::refused;

/// The shape NumPy broadcasts `shapes` to, or why they do not broadcast.
fn broadcast(shapes: &[(&str, Vec<usize>)]) -> Result<Vec<usize>, String> {
    let ndim = shapes.iter().map(|(_, s)| s.len()).max().unwrap_or(0);
    let mut out = vec![1; ndim];
    for (name, shape) in shapes {
        for (k, &n) in shape.iter().rev().enumerate() {
            let slot = &mut out[ndim - 1 - k];
            if *slot == 1 {
                *slot = n;
            } else if n != 1 && n != *slot {
                let all: Vec<String> = shapes.iter().map(|(n, s)| format!("{n} {s:?}")).collect();
                return Err(format!(
                    "{name}: the shapes do not broadcast together ({})",
                    all.join(", ")
                ));
            }
        }
    }
    Ok(out)
}

/// An input over the broadcast rows: one value for all, or one per row (in C order).
enum Input<'a> {
    One(f64),
    Each(std::borrow::Cow<'a, [f64]>),
}

impl Input<'_> {
    fn of<'a>(a: &'a ArrayViewD<'a, f64>, shape: &[usize]) -> Input<'a> {
        if a.len() == 1 {
            return Input::One(a.iter().next().copied().unwrap_or(f64::NAN));
        }
        if a.shape() == shape
            && let Some(s) = a.as_slice()
        {
            return Input::Each(s.into());
        }
        let b = a
            .broadcast(IxDyn(shape))
            .expect("the shapes were checked to broadcast");
        Input::Each(b.iter().copied().collect::<Vec<_>>().into())
    }

    fn at(&self, i: usize) -> f64 {
        match self {
            Input::One(x) => *x,
            Input::Each(xs) => xs[i],
        }
    }
}

/// Many collisions on a rail at once, as `collide batch` and `collide sweep` compute them.
///
/// `m1`, `m2`, `v1`, `v2`, `e` are numbers or arrays (read as float64) that broadcast together
/// as NumPy broadcasts them. Returns a dict of float64 arrays of the broadcast shape, one per
/// column (`columns`, by default the sweep's: m1 m2 v1 v2 e fin1 fin2 v_com ke_in ke_fin
/// crunch lost; any of `collide.COLUMNS`), bit for bit the numbers `collide batch` prints for
/// the same rows, and `error`: an object array, `None` for a good row and the command line's
/// message for a bad one (whose columns are NaN), as `--skip-bad` reports it.
///
/// >>> import numpy as np
/// >>> out = solve_many(4.0, 1.0, np.array([60.0, 30.0]), 10.0, 1.0)
/// >>> out["fin1"], out["fin2"]
/// (array([40., 22.]), array([90., 42.]))
#[pyfunction]
#[pyo3(signature = (m1, m2, v1, v2, e=None, *, columns=None))]
pub fn solve_many<'py>(
    py: Python<'py>,
    m1: PyArrayLikeDyn<'py, f64, AllowTypeChange>,
    m2: PyArrayLikeDyn<'py, f64, AllowTypeChange>,
    v1: PyArrayLikeDyn<'py, f64, AllowTypeChange>,
    v2: PyArrayLikeDyn<'py, f64, AllowTypeChange>,
    e: Option<PyArrayLikeDyn<'py, f64, AllowTypeChange>>,
    columns: Option<Vec<String>>,
) -> PyResult<Bound<'py, PyDict>> {
    let columns: Vec<&'static Column> = match &columns {
        Some(names) => {
            by_names(&names.iter().map(String::as_str).collect::<Vec<_>>()).map_err(refused)?
        }
        None => Column::defaults(false),
    };
    let e = e.as_ref().map(|e| e.as_array());
    let mut inputs = vec![
        ("m1", m1.as_array()),
        ("m2", m2.as_array()),
        ("v1", v1.as_array()),
        ("v2", v2.as_array()),
    ];
    inputs.extend(e.map(|e| ("e", e)));
    let shapes: Vec<(&str, Vec<usize>)> = inputs
        .iter()
        .map(|(n, a)| (*n, a.shape().to_vec()))
        .collect();
    let shape = broadcast(&shapes).map_err(refused)?;
    let rows: usize = shape.iter().product();
    let k = columns.len();
    let (out, errors) = py.detach(|| {
        let mut inputs: Vec<Input<'_>> = inputs.iter().map(|(_, a)| Input::of(a, &shape)).collect();
        // No e: elastic, as `collide sweep` without -e.
        if inputs.len() == 4 {
            inputs.push(Input::One(1.0));
        }
        let mut out = vec![vec![0.0; rows]; k];
        let mut chunks: Vec<Vec<&mut [f64]>> = (0..rows.div_ceil(CHUNK_ROWS))
            .map(|_| Vec::with_capacity(k))
            .collect();
        for col in out.iter_mut() {
            for (c, part) in chunks.iter_mut().zip(col.chunks_mut(CHUNK_ROWS)) {
                c.push(part);
            }
        }
        let errors: Vec<(usize, String)> = chunks
            .into_par_iter()
            .enumerate()
            .flat_map_iter(|(n, mut parts)| {
                solve_chunk(n * CHUNK_ROWS, &inputs, &columns, &mut parts)
            })
            .collect();
        (out, errors)
    });
    let dict = PyDict::new(py);
    for (col, values) in columns.iter().zip(out) {
        let array = PyArray1::from_vec(py, values).reshape(shape.clone())?;
        dict.set_item(col.name, array)?;
    }
    let kwargs = PyDict::new(py);
    kwargs.set_item("dtype", "object")?;
    let error = py
        .import("numpy")?
        .call_method("full", (rows, py.None()), Some(&kwargs))?;
    for (i, message) in errors {
        error.set_item(i, message)?;
    }
    dict.set_item("error", error.call_method1("reshape", (shape,))?)?;
    Ok(dict)
}

/// Solves the rows from `start` into `parts` (one slice a column); the bad rows' columns are
/// NaN, and their messages returned with their places.
fn solve_chunk(
    start: usize,
    inputs: &[Input<'_>],
    columns: &[&'static Column],
    parts: &mut [&mut [f64]],
) -> Vec<(usize, String)> {
    let mut values = vec![0.0; columns.len()];
    let mut errors = Vec::new();
    let len = parts.first().map_or(0, |p| p.len());
    for j in 0..len {
        let i = start + j;
        let [m1, m2, v1, v2, e] = std::array::from_fn(|k| inputs[k].at(i));
        let solved = RowCase::masses(m1, m2, [v1, v2], e)
            .and_then(|case| solve_row(&case, None, columns, &mut values));
        if let Err(problem) = solved {
            values.fill(f64::NAN);
            errors.push((i, problem.to_string()));
        }
        for (part, x) in parts.iter_mut().zip(&values) {
            part[j] = *x;
        }
    }
    errors
}
