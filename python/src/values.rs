//! Python values as the command line's text, which the library's own parsers then read (so a
//! value is refused, or read, exactly as `collide solve` would): a `str` as typed (`"4 ton"`,
//! `"2/3"`, `"(4,1)"`, `"6 m/s @ 30deg"`), an `int` in decimal, a `float` as its shortest
//! round-trip text (read back as the same binary64), a `fractions.Fraction` (any
//! `numbers.Rational`) as `n/d`, a pair of those as the vector `(x,y)`.

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

/// A pair of values (`m=(4, 1)`, `v=("60 mph", "10 mph")`), each as `item` reads it.
pub fn pair<T>(
    x: &Bound<'_, PyAny>,
    what: &str,
    item: impl Fn(&Bound<'_, PyAny>, &str) -> PyResult<T>,
) -> PyResult<[T; 2]> {
    let items = sequence(x).ok_or_else(|| {
        refused(format!(
            "{what}: expected a pair such as (4, 1), got {}",
            x.repr().map(|r| r.to_string()).unwrap_or_default()
        ))
    })?;
    match items.as_slice() {
        [a, b] => Ok([
            item(a, &format!("{what}[0]"))?,
            item(b, &format!("{what}[1]"))?,
        ]),
        _ => Err(refused(format!(
            "{what}: expected two values (body 1, body 2), got {}",
            items.len()
        ))),
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

/// A velocity: a scalar on the rail, or a vector in the plane (a pair of numbers, or text).
#[derive(Clone, Debug, PartialEq)]
pub struct Velocity {
    pub text: String,
    /// Given as a pair, or as text that only the plane reads (`(4,1)`, `6 m/s @ 30deg`).
    pub planar: bool,
}

/// A velocity as the command line's text.
pub fn velocity(x: &Bound<'_, PyAny>, what: &str) -> PyResult<Velocity> {
    if let Some(items) = sequence(x) {
        if items.len() != 2 {
            return Err(refused(format!(
                "{what}: a vector in the plane has two components, got {}",
                items.len()
            )));
        }
        let [a, b] = pair(x, what, scalar)?;
        return Ok(Velocity {
            text: format!("({a},{b})"),
            planar: true,
        });
    }
    let text = scalar(x, what)?;
    let planar = text.contains('(') || text.contains('@');
    Ok(Velocity { text, planar })
}
