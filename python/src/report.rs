//! `collide.solve` and its `Report`: the JSON of `collide solve --format json` for the case, as
//! the command line prints it (the library's `view` entry points compute it, byte for byte), read
//! by Python's `json` (so `to_dict()` equals `json.loads` of the command's output), with its
//! sections as attributes; with `exact=True` the numbers, which the JSON holds as fractions in
//! text (`"4/3"`), are `fractions.Fraction`s.

use pyo3::exceptions::{PyAttributeError, PyKeyError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString};

use collide::view::input::{CaseInput, PlaneInput};

use crate::refused;
use crate::values::{Velocity, pair, scalar, velocity};

/// A part of a report (a JSON object): its keys as attributes (`r.energy.crunch`) and items
/// (`r["energy"]["crunch"]`; a key that is a Python keyword, `in`, also as `in_`).
#[pyclass(module = "collide", frozen, subclass)]
pub struct Section {
    data: Py<PyDict>,
    exact: bool,
}

/// The report of one case (`collide.solve`): a `Section` over the whole JSON, with the JSON
/// text itself.
#[pyclass(module = "collide", frozen, extends = Section)]
pub struct Report {
    json: String,
}

/// Whether `s` is a number as the exact JSON writes it: an integer or a fraction `n/d`.
fn rational(s: &str) -> bool {
    let digits = |t: &str| !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit());
    let s = s.strip_prefix('-').unwrap_or(s);
    match s.split_once('/') {
        Some((n, d)) => digits(n) && digits(d),
        None => digits(s),
    }
}

impl Section {
    /// A JSON value as an attribute: an object as a `Section`, a list item by item, an exact
    /// number as a `Fraction`, anything else as it is.
    fn wrap(&self, py: Python<'_>, value: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        if let Ok(d) = value.cast::<PyDict>() {
            let section = Section {
                data: d.clone().unbind(),
                exact: self.exact,
            };
            return Ok(Py::new(py, section)?.into_any());
        }
        if let Ok(list) = value.cast::<PyList>() {
            let items = list
                .iter()
                .map(|x| self.wrap(py, &x))
                .collect::<PyResult<Vec<_>>>()?;
            return Ok(PyList::new(py, items)?.into_any().unbind());
        }
        if self.exact && value.is_instance_of::<PyString>() && rational(&value.extract::<String>()?)
        {
            let fraction = py.import("fractions")?.getattr("Fraction")?;
            return Ok(fraction.call1((value,))?.unbind());
        }
        Ok(value.clone().unbind())
    }

    /// The value at `key`, or at `key` without a trailing `_` (`in_` for `in`).
    fn item<'py>(&self, py: Python<'py>, key: &str) -> Option<Bound<'py, PyAny>> {
        let data = self.data.bind(py);
        let found = data.get_item(key).ok().flatten();
        found.or_else(|| {
            let bare = key.strip_suffix('_')?;
            data.get_item(bare).ok().flatten()
        })
    }
}

#[pymethods]
impl Section {
    fn __getattr__(&self, py: Python<'_>, name: &str) -> PyResult<Py<PyAny>> {
        match self.item(py, name) {
            Some(v) => self.wrap(py, &v),
            None => Err(PyAttributeError::new_err(format!(
                "no '{name}' here: the keys are {}",
                self.keys(py)?.join(", ")
            ))),
        }
    }

    fn __getitem__(&self, py: Python<'_>, key: &str) -> PyResult<Py<PyAny>> {
        match self.item(py, key) {
            Some(v) => self.wrap(py, &v),
            None => Err(PyKeyError::new_err(key.to_owned())),
        }
    }

    fn __contains__(&self, py: Python<'_>, key: &str) -> bool {
        self.item(py, key).is_some()
    }

    fn __dir__(&self, py: Python<'_>) -> PyResult<Vec<String>> {
        self.keys(py)
    }

    /// The keys, in the JSON's order.
    fn keys(&self, py: Python<'_>) -> PyResult<Vec<String>> {
        self.data
            .bind(py)
            .keys()
            .iter()
            .map(|k| k.extract::<String>())
            .collect()
    }

    /// This part of the JSON as plain Python values (a copy: `json.loads` of the command's
    /// output; with `exact=True` the numbers are its fraction strings).
    fn to_dict(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        Ok(py
            .import("copy")?
            .call_method1("deepcopy", (self.data.bind(py),))?
            .unbind())
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        Ok(format!("Section({})", self.keys(py)?.join(", ")))
    }

    /// An HTML table of this part (Jupyter's rich display).
    fn _repr_html_(&self, py: Python<'_>) -> PyResult<String> {
        crate::report::html(self.data.bind(py).as_any())
    }
}

#[pymethods]
impl Report {
    /// The JSON text, as `collide solve --format json` prints it.
    fn to_json(&self) -> &str {
        &self.json
    }

    fn __repr__(slf: PyRef<'_, Self>, py: Python<'_>) -> PyResult<String> {
        Ok(format!("Report({})", slf.as_super().keys(py)?.join(", ")))
    }
}

/// An HTML rendering of a JSON value read by Python: objects as tables of their keys, lists of
/// numbers as `(x, y)`, other lists item by item.
pub fn html(value: &Bound<'_, PyAny>) -> PyResult<String> {
    if let Ok(d) = value.cast::<PyDict>() {
        let mut out = String::from("<table class=\"collide\">");
        for (k, v) in d.iter() {
            out.push_str(&format!(
                "<tr><th style=\"text-align:left\">{}</th><td style=\"text-align:left\">{}</td></tr>",
                escape(&k.str()?.to_string()),
                html(&v)?
            ));
        }
        out.push_str("</table>");
        return Ok(out);
    }
    if let Ok(list) = value.cast::<PyList>() {
        let items = list
            .iter()
            .map(|x| html(&x))
            .collect::<PyResult<Vec<_>>>()?;
        let nested = list.iter().any(|x| x.is_instance_of::<PyDict>());
        return Ok(if nested {
            items.join("")
        } else {
            format!("({})", items.join(", "))
        });
    }
    if value.is_none() {
        return Ok("null".into());
    }
    Ok(escape(&value.str()?.to_string()))
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The text of an optional value, empty when absent.
fn text(x: Option<&Bound<'_, PyAny>>, what: &str) -> PyResult<String> {
    x.map_or(Ok(String::new()), |x| scalar(x, what))
}

/// One collision, as `collide solve ... --format json` solves it.
///
/// Values are numbers (`int`, `float`, `fractions.Fraction`) or the command line's text
/// (`"4 ton"`, `"60 mph"`, `"2/3"`, `"elastic"`). Velocities that are vectors (`(4, 1)`,
/// `"(4,1)"`, `"6 m/s @ 30deg"`), or a line of impact (`normal=`, or `radii=` with `b=`),
/// make it a case in the plane.
///
/// >>> r = solve(m=(4, 1), v=(60, 10), e=1)
/// >>> r.fin, r.energy.crunch
/// ([40.0, 90.0], 1000.0)
/// >>> solve(m=(6, 1), v=(3, -4), e="2/3", exact=True).fin
/// [Fraction(4, 3), Fraction(6, 1)]
/// >>> solve(m=(1, 1), v=((1, 0), (0, 0)), radii=(1, 1), b=1).angle_between_deg
/// 90.0
///
/// Raises `CollideError` (a `ValueError`) with the command line's message for a value
/// `collide solve` refuses.
#[pyfunction]
#[pyo3(signature = (m=None, v=None, e=None, *, inertia=None, normal=None, radii=None, b=None,
    frame="lab", reverse=false, exact=false))]
#[allow(clippy::too_many_arguments)]
pub fn solve(
    py: Python<'_>,
    m: Option<&Bound<'_, PyAny>>,
    v: Option<&Bound<'_, PyAny>>,
    e: Option<&Bound<'_, PyAny>>,
    inertia: Option<&Bound<'_, PyAny>>,
    normal: Option<&Bound<'_, PyAny>>,
    radii: Option<&Bound<'_, PyAny>>,
    b: Option<&Bound<'_, PyAny>>,
    frame: &str,
    reverse: bool,
    exact: bool,
) -> PyResult<Py<Report>> {
    let v = v.ok_or_else(|| refused("v: the velocities (V1, V2) are missing"))?;
    let [v1, v2] = pair(v, "v", velocity)?;
    let e = match e {
        Some(e) => scalar(e, "e")?,
        None => "elastic".into(),
    };
    let [m1, m2] = match (m, inertia) {
        (Some(_), Some(_)) => return Err(refused("give the masses m or the inertia, not both")),
        (Some(m), None) => pair(m, "m", scalar)?,
        (None, Some(_)) => [String::new(), String::new()],
        (None, None) => return Err(refused("m: the masses (M1, M2) are missing")),
    };
    let normal = match normal {
        Some(n) => velocity(n, "normal")?.text,
        None => String::new(),
    };
    let [r1, r2] = match radii {
        Some(r) => pair(r, "radii", scalar)?,
        None => [String::new(), String::new()],
    };
    let b = text(b, "b")?;
    let planar = v1.planar || v2.planar || [&normal, &r1, &r2, &b].iter().any(|s| !s.is_empty());
    let state = if planar {
        if inertia.is_some() {
            return Err(refused(
                "inertia: a general tensor is for two bodies on a rail, not the plane",
            ));
        }
        let input = PlaneInput {
            m1,
            m2,
            v1: v1.text,
            v2: v2.text,
            e,
            normal,
            r1,
            r2,
            b,
            frame: frame.into(),
            reverse,
            exact,
            line: String::new(),
        };
        py.detach(|| input.solve_typed().map(|s| s.state))
    } else {
        let Velocity { text: v1, .. } = v1;
        let input = CaseInput {
            m1,
            m2,
            inertia: inertia.map(|t| scalar(t, "inertia")).transpose()?,
            v1,
            v2: v2.text,
            e,
            frame: frame.into(),
            reverse,
            exact,
        };
        py.detach(|| input.solve_typed().map(|s| s.state))
    }
    .map_err(|e| refused(e.error))?;
    let data = py
        .import("json")?
        .call_method1("loads", (&state,))?
        .cast_into::<PyDict>()?
        .unbind();
    let init =
        PyClassInitializer::from(Section { data, exact }).add_subclass(Report { json: state });
    Py::new(py, init)
}
