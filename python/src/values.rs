//! Python values as the command line's text, which the library's own parsers then read (so a
//! value is refused, or read, exactly as `collide solve` would): a `str` as typed (`"4 ton"`,
//! `"2/3"`, `"(4,1)"`, `"6 m/s @ 30deg"`), an `int` in decimal, a `float` as its shortest
//! round-trip text (read back as the same binary64), a `fractions.Fraction` (any
//! `numbers.Rational`) as `n/d`; a list of those comma-separated, a sequence inside it as the
//! vector `(x,y)`.

use pyo3::prelude::*;
use pyo3::types::{PyBool, PyFloat, PyInt, PyString};

use crate::refused;

/// A number (or text) as the command line's text; `what` names it in a refusal.
pub fn scalar(x: &Bound<'_, PyAny>, what: &str) -> PyResult<String> {
    if x.is_instance_of::<PyString>() {
        return x.extract::<String>();
    }
    if x.is_instance_of::<PyBool>() {
        return Err(refused(format!(
            "{what}: expected a number or text, got the bool {}",
            x.repr()?
        )));
    }
    if x.is_instance_of::<PyInt>() {
        return Ok(x.str()?.to_string());
    }
    if x.hasattr("numerator")? && x.hasattr("denominator")? && !x.is_instance_of::<PyFloat>() {
        let (n, d) = (x.getattr("numerator")?, x.getattr("denominator")?);
        return Ok(format!("{}/{}", n.str()?, d.str()?));
    }
    match x.extract::<f64>() {
        Ok(v) => float(v, what),
        Err(_) => Err(refused(format!(
            "{what}: expected a number or text, got {}",
            x.repr()?
        ))),
    }
}

/// A float as the shortest text that reads back as the same binary64 (`60.0`, `1e16`, `0.1`);
/// NaN and the infinities refused, as the command line refuses them.
fn float(v: f64, what: &str) -> PyResult<String> {
    if v.is_finite() {
        Ok(format!("{v:?}"))
    } else {
        Err(refused(format!(
            "{what}: {v} is not a number collide computes with (finite values only)"
        )))
    }
}

/// A list as the command line's text: the items comma-separated, an item that is itself a
/// sequence as the vector `(x,y)` (`v=((1, 0), "6 m/s @ 30deg")` is `(1,0),6 m/s @ 30deg`);
/// a single value as `scalar` reads it.
pub fn list(x: &Bound<'_, PyAny>, what: &str) -> PyResult<String> {
    match sequence(x) {
        Some(items) => items
            .iter()
            .enumerate()
            .map(|(i, item)| vector(item, &format!("{what}[{i}]")))
            .collect::<PyResult<Vec<_>>>()
            .map(|items| items.join(",")),
        None => scalar(x, what),
    }
}

/// One vector as the command line's text: a sequence as `(x,y)` (`(x,y,z)` in space), text
/// as typed (`"30deg"`, `"(1,1)"`).
pub fn vector(x: &Bound<'_, PyAny>, what: &str) -> PyResult<String> {
    match sequence(x) {
        Some(items) => items
            .iter()
            .enumerate()
            .map(|(i, c)| scalar(c, &format!("{what}[{i}]")))
            .collect::<PyResult<Vec<_>>>()
            .map(|c| format!("({})", c.join(","))),
        None => scalar(x, what),
    }
}

/// The items of a sequence that is not text (a tuple, a list, a NumPy array).
fn sequence<'py>(x: &Bound<'py, PyAny>) -> Option<Vec<Bound<'py, PyAny>>> {
    if x.is_instance_of::<PyString>() {
        return None;
    }
    let n = x.len().ok()?;
    (0..n).map(|i| x.get_item(i).ok()).collect()
}
