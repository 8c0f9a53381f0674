//! `collide` for Python: the library behind a native module (PyO3, the stable ABI), with no
//! physics of its own. One case goes through the page's entry points
//! (`collide::view::two_body::CaseInput`, `collide::view::plane::PlaneInput`), whose JSON is
//! `collide solve --format json`'s byte for byte; many cases go through the table engine's row
//! (`collide::table::engine::solve_row`), the one `collide sweep` and `collide batch` print.
//!
//! The modules: `values` (Python values as the command line's text), `command` (the command
//! line run in the module), `functions` (one per command), `report` (the `Report` class over the
//! JSON), `picture` (its SVG), `many` (`solve_many`: NumPy arrays in and out), `sweep` (`collide.sweep`:
//! a DataFrame).

use pyo3::prelude::*;

mod command;
mod functions;
mod many;
mod picture;
mod report;
mod sweep;
mod values;

/// The command line's own flags and commands, from the library (`collide::cli`,
/// `collide::commands`, `collide::usage`; the binary runs the same build of them): one parser and
/// one renderer for both, so a report is the command's JSON by construction.
use collide::{cli, commands, usage};

pyo3::create_exception!(
    collide,
    CollideError,
    pyo3::exceptions::PyValueError,
    "A value collide refuses, with the command line's message (`collide solve` exits 2 with it)."
);

/// A `CollideError` with `message`.
pub(crate) fn refused(message: impl std::fmt::Display) -> PyErr {
    CollideError::new_err(message.to_string())
}

/// collide: two-body collisions on a rail and in the plane, exact or in binary64, with the same
/// numbers as the command line.
///
/// >>> import collide
/// >>> r = collide.solve(m=(4, 1), v=(60, 10), e=1)
/// >>> r.fin
/// [40.0, 90.0]
#[pymodule(name = "collide")]
fn collide_module(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("CollideError", m.py().get_type::<CollideError>())?;
    m.add(
        "COLUMNS",
        collide::table::columns::COLUMNS
            .iter()
            .map(|c| c.name)
            .collect::<Vec<_>>(),
    )?;
    m.add_class::<report::Section>()?;
    m.add_class::<report::Report>()?;
    for f in [
        wrap_pyfunction!(functions::solve, m)?,
        wrap_pyfunction!(functions::frames, m)?,
        wrap_pyfunction!(functions::plot, m)?,
        wrap_pyfunction!(functions::track, m)?,
        wrap_pyfunction!(functions::contact, m)?,
        wrap_pyfunction!(functions::pi, m)?,
        wrap_pyfunction!(functions::scene, m)?,
        wrap_pyfunction!(sweep::sweep, m)?,
    ] {
        m.add_function(f)?;
    }
    m.add_function(wrap_pyfunction!(many::solve_many, m)?)?;
    Ok(())
}
