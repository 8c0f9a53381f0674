//! `collide.solve` and its `Report`: the JSON of `collide solve --format json` for the case, as
//! the command line prints it (the library's `view` entry points compute it, byte for byte), read
//! by Python's `json` (so `to_dict()` equals `json.loads` of the command's output), with its
//! sections as attributes; with `exact=True` the numbers, which the JSON holds as fractions in
//! text (`"4/3"`), are `fractions.Fraction`s.

use pyo3::exceptions::{PyAttributeError, PyKeyError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString};

use crate::command::Printed;

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
    /// The command's words that made it (`solve --masses 4,1 ...`, without `--format json`).
    args: Vec<String>,
    status: u8,
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

    /// The command line that prints this report (`collide solve --masses 4,1 ...`), quoted
    /// for a POSIX shell.
    #[getter]
    fn command(&self) -> String {
        let words: Vec<String> = self
            .args
            .iter()
            .chain(["--format".to_string(), "json".to_string()].iter())
            .map(|w| collide::view::shell::word(w))
            .collect();
        format!("collide {}", words.join(" "))
    }

    /// The command's exit status: 0, or 1 when a scene's check failed or given values
    /// contradict each other (the report then says what was checked).
    #[getter]
    fn status(&self) -> u8 {
        self.status
    }

    fn __repr__(slf: PyRef<'_, Self>, py: Python<'_>) -> PyResult<String> {
        Ok(format!("Report({})", slf.as_super().keys(py)?.join(", ")))
    }

    /// The velocity plane as SVG (Jupyter's rich display): what `collide plot` draws for a case
    /// of `collide.solve` or `collide.frames` with the same values; `None` for a report that
    /// `collide plot` does not draw (a track, a scene, a case with unknowns or knowns).
    fn _repr_svg_(&self, py: Python<'_>) -> Option<String> {
        let args = crate::picture::plot_args(&self.args)?;
        crate::command::run(py, &args).ok().map(|p| p.stdout)
    }
}

impl Report {
    /// The report of what `args` printed (`--format json`), with Fractions when `exact`.
    pub fn new(py: Python<'_>, args: Vec<String>, printed: Printed) -> PyResult<Py<Report>> {
        let exact = args.iter().any(|a| a == "--exact");
        let data = py
            .import("json")?
            .call_method1("loads", (&printed.stdout,))?
            .cast_into::<PyDict>()?
            .unbind();
        let report = Report {
            json: printed.stdout,
            args,
            status: printed.status,
        };
        Py::new(
            py,
            PyClassInitializer::from(Section { data, exact }).add_subclass(report),
        )
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
