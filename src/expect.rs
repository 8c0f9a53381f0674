//! `[expect]` in a scene: numbers the report must reproduce, each addressed by its JSON path
//! (`fin`, `energy.crunch`, `ellipses.com.a`, `products.outer_in_fin`), each with a tolerance.
//! A scene with expectations is an autograder.

use std::fmt;

use num_traits::Signed;
use serde_json::Value as Json;

use crate::values::number::{Number, num, num_full};

/// Relative tolerance of a plain expected number.
pub const DEFAULT_REL: f64 = 1e-12;

/// An expected number or (nested) array of numbers.
#[derive(Clone, Debug, PartialEq)]
pub enum Expected {
    /// A number as written (a string keeps its decimal or fraction exactly).
    Number(Number),
    /// A word, compared exactly (`"stop.reason" = "zeno"`).
    Text(String),
    /// A yes-or-no answer (`collide_again = true`), compared exactly.
    Bool(bool),
    Array(Vec<Expected>),
}

/// `|actual - expected| <= abs + rel |expected|`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    pub abs: f64,
    pub rel: f64,
}

impl fmt::Display for Tolerance {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.abs > 0.0, self.rel > 0.0) {
            (true, true) => write!(f, "abs {} + rel {}", num(self.abs), num(self.rel)),
            (true, false) => write!(f, "abs {}", num(self.abs)),
            (false, true) => write!(f, "rel {}", num(self.rel)),
            (false, false) => write!(f, "exactly"),
        }
    }
}

/// One expectation of a scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Expectation {
    pub key: String,
    pub line: usize,
    pub expected: Expected,
    pub tolerance: Tolerance,
}

/// The outcome of checking one expectation.
#[derive(Clone, Debug, PartialEq)]
pub struct Check {
    pub key: String,
    pub line: usize,
    pub passed: bool,
    pub expected: String,
    pub actual: String,
    pub tolerance: Tolerance,
}

/// Why an expectation is not one.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ExpectError {
    #[error("expected a number, a word, true or false, or an array of them, got {0}")]
    Type(&'static str),
    #[error("`{name}` must be a number >= 0, got {got}")]
    Tolerance { name: &'static str, got: String },
    #[error("a table needs `value` (and `abs` and/or `rel`)")]
    NoValue,
    #[error("unknown key `{0}`: expected `value`, `abs` or `rel`")]
    Key(String),
    #[error("the report has no quantity '{0}'")]
    Missing(String),
    #[error("unknown quantity '{top}': expected one of {expected}")]
    UnknownQuantity { top: String, expected: String },
}

fn expected_of(v: toml::Value) -> Result<Expected, ExpectError> {
    match v {
        toml::Value::Integer(i) => Ok(Expected::Number(
            i.to_string()
                .parse()
                .map_err(|_| ExpectError::Type("integer"))?,
        )),
        toml::Value::Float(f) if f.is_finite() => Ok(Expected::Number(
            Number::from_f64(f).map_err(|_| ExpectError::Type("float"))?,
        )),
        // A string is a number ("4/3") if it reads as one, else a word compared exactly.
        toml::Value::String(s) => Ok(match s.parse::<Number>() {
            Ok(n) => Expected::Number(n),
            Err(_) => Expected::Text(s),
        }),
        toml::Value::Boolean(b) => Ok(Expected::Bool(b)),
        toml::Value::Array(a) => a
            .into_iter()
            .map(expected_of)
            .collect::<Result<_, _>>()
            .map(Expected::Array),
        other => Err(ExpectError::Type(other.type_str())),
    }
}

fn tolerance_of(v: Option<toml::Value>, name: &'static str) -> Result<f64, ExpectError> {
    match v {
        None => Ok(0.0),
        Some(toml::Value::Integer(i)) if i >= 0 => Ok(i as f64),
        Some(toml::Value::Float(f)) if f.is_finite() && f >= 0.0 => Ok(f),
        Some(other) => Err(ExpectError::Tolerance {
            name,
            got: other.to_string(),
        }),
    }
}

impl Expectation {
    /// From a TOML value: a number, a string number ("4/3"), an array, or a table
    /// `{ value = ..., abs = ..., rel = ... }`.
    pub fn from_toml(key: &str, v: toml::Value) -> Result<Expectation, ExpectError> {
        let (expected, tolerance) = match v {
            toml::Value::Table(mut t) => {
                let value = t.remove("value").ok_or(ExpectError::NoValue)?;
                let abs = tolerance_of(t.remove("abs"), "abs")?;
                let rel = tolerance_of(t.remove("rel"), "rel")?;
                if let Some(k) = t.keys().next() {
                    return Err(ExpectError::Key(k.clone()));
                }
                (expected_of(value)?, Tolerance { abs, rel })
            }
            v => (
                expected_of(v)?,
                Tolerance {
                    abs: 0.0,
                    rel: DEFAULT_REL,
                },
            ),
        };
        Ok(Expectation {
            key: key.to_string(),
            line: 0,
            expected,
            tolerance,
        })
    }

    pub fn at_line(mut self, line: usize) -> Expectation {
        self.line = line;
        self
    }

    /// Checks against the report as JSON. `Err` when the key names nothing in the report; an
    /// entry past the end of a list (`next.0.bodies` when `next` is empty) is a wrong answer, a
    /// failed check: the list is the report's, its length the answer.
    pub fn check(&self, report: &Json) -> Result<Check, ExpectError> {
        let mut node = report;
        let mut path: Vec<&str> = Vec::new();
        for seg in self.key.split('.') {
            node = match node {
                Json::Object(o) => o.get(seg),
                Json::Array(a) => match seg.parse::<usize>() {
                    Ok(i) if i >= a.len() => {
                        return Ok(Check {
                            key: self.key.clone(),
                            line: self.line,
                            passed: false,
                            expected: show_expected(&self.expected),
                            actual: format!("nothing: {} has {} entries", path.join("."), a.len()),
                            tolerance: self.tolerance,
                        });
                    }
                    Ok(i) => a.get(i),
                    Err(_) => None,
                },
                _ => None,
            }
            .ok_or_else(|| ExpectError::Missing(self.key.clone()))?;
            path.push(seg);
        }
        Ok(Check {
            key: self.key.clone(),
            line: self.line,
            passed: matches(&self.expected, node, self.tolerance),
            expected: show_expected(&self.expected),
            actual: show_json(node),
            tolerance: self.tolerance,
        })
    }
}

fn matches(e: &Expected, a: &Json, tol: Tolerance) -> bool {
    match (e, a) {
        (Expected::Number(x), Json::Number(y)) => {
            let (x, y) = (x.value(), y.as_f64().unwrap_or(f64::NAN));
            (y - x).abs() <= tol.abs + tol.rel * x.abs()
        }
        // Exact mode: "35/3", or 20 significant digits of an irrational value, compared as
        // the rationals they are (a decimal expectation is the decimal it is).
        (Expected::Number(x), Json::String(y)) => y.parse::<Number>().is_ok_and(|y| {
            let x = x.exact();
            let bound = |t: f64| crate::values::rational::from_f64(t);
            (y.exact() - &x).abs() <= bound(tol.abs) + bound(tol.rel) * x.abs()
        }),
        (Expected::Text(x), Json::String(y)) => x == y,
        (Expected::Bool(x), Json::Bool(y)) => x == y,
        (Expected::Array(xs), Json::Array(ys)) => {
            xs.len() == ys.len() && xs.iter().zip(ys).all(|(x, y)| matches(x, y, tol))
        }
        _ => false,
    }
}

fn show_expected(e: &Expected) -> String {
    match e {
        Expected::Number(x) => match x.text() {
            std::borrow::Cow::Borrowed(typed) => typed.to_string(),
            std::borrow::Cow::Owned(_) => num_full(x.value()),
        },
        Expected::Text(t) => t.clone(),
        Expected::Bool(b) => b.to_string(),
        Expected::Array(a) => {
            format!(
                "[{}]",
                a.iter().map(show_expected).collect::<Vec<_>>().join(", ")
            )
        }
    }
}

fn show_json(v: &Json) -> String {
    match v {
        Json::Number(n) => n.as_f64().map(num_full).unwrap_or_else(|| n.to_string()),
        Json::String(s) => s.clone(),
        Json::Array(a) => format!(
            "[{}]",
            a.iter().map(show_json).collect::<Vec<_>>().join(", ")
        ),
        other => other.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exp(key: &str, toml_value: &str) -> Result<Expectation, String> {
        let v: toml::Table = toml::from_str(&format!("x = {toml_value}")).unwrap();
        Expectation::from_toml(key, v["x"].clone()).map_err(|e| e.to_string())
    }

    #[test]
    fn numbers_arrays_and_tolerances() {
        let report = serde_json::json!({"fin": [40.0, 90.0], "energy": {"crunch": 1000.0},
                                        "ellipses": {"com": {"a": 55.90169943749474}}});
        let check = |k: &str, v: &str| exp(k, v).unwrap().check(&report).unwrap().passed;
        assert!(check("fin", "[40, 90]"));
        assert!(!check("fin", "[40, 91]"));
        assert!(!check("fin", "[40]"));
        assert!(check("fin.1", "90"));
        assert!(check("energy.crunch", "1000"));
        assert!(!check("energy.crunch", "1000.000001"));
        assert!(check("energy.crunch", "\"3000/3\""));
        assert!(check("ellipses.com.a", "{ value = 55.90, abs = 0.005 }"));
        assert!(!check("ellipses.com.a", "{ value = 55.90, abs = 0.001 }"));
        assert!(check("ellipses.com.a", "{ value = 55.9, rel = 1e-3 }"));
    }

    #[test]
    fn wrong_keys_are_errors() {
        // Words are compared exactly.
        let report = serde_json::json!({"stop": {"reason": "zeno"}});
        assert!(
            exp("stop.reason", "\"zeno\"")
                .unwrap()
                .check(&report)
                .unwrap()
                .passed
        );
        assert!(
            !exp("stop.reason", "\"done\"")
                .unwrap()
                .check(&report)
                .unwrap()
                .passed
        );
        assert!(
            exp("fin", "{ value = 1, tol = 2 }")
                .unwrap_err()
                .contains("`tol`")
        );
        assert!(exp("fin", "{ abs = 2 }").unwrap_err().contains("`value`"));
        assert!(exp("fin", "1979-05-27").unwrap_err().contains("datetime"));
        // Yes-or-no answers compare exactly, and only with a yes-or-no answer.
        let report = serde_json::json!({"collide_again": true, "fin": [1.0, 2.0]});
        let check = |k: &str, v: &str| exp(k, v).unwrap().check(&report).unwrap().passed;
        assert!(check("collide_again", "true"));
        assert!(!check("collide_again", "false"));
        assert!(!check("fin", "true"));
        let report = serde_json::json!({"energy": {"crunch": 1.0}});
        let e = exp("energy.crunsh", "1")
            .unwrap()
            .check(&report)
            .unwrap_err()
            .to_string();
        assert!(e.contains("energy.crunsh"), "{e}");
    }
}
