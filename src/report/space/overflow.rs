//! Values beyond binary64 in a report of the plane, space or rigid bodies: marked where the
//! JSON would hold them, so the error names the quantity by its path (docs/accuracy.md), as the
//! rail's reports name theirs.

use serde_json::Value;

/// A result beyond binary64, where the report would print inf (or 0 for a nonzero energy),
/// named by its place in the JSON report (`energy.in`, `fin[0][0]`), as the rail's reports
/// name theirs ([`Style::checked_json`](super::Style::checked_json)).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "{} beyond binary64 (|x| above 1.8e308, or an energy below 4.9e-324 and not zero): rescale \
     the units, or use --exact",
    match quantity { Some(q) => format!("{q} is"), None => "a result is".to_string() }
)]
pub struct Overflow {
    /// The JSON path of the first value beyond binary64, when a JSON report holds it.
    pub quantity: Option<String>,
}

/// What [`Style::json`](super::Style::json) writes before the decimal text of a value beyond
/// binary64 (`≈3.4e308`), in place of the number: found to name the quantity
/// ([`Style::checked_json`](super::Style::checked_json)), and taken away where a report prints
/// such a value as text ([`unmarked`]).
pub(super) const BEYOND: char = '\u{1}';

/// The path (`energy.in`, `fin[0][1]`) of the first value marked [`BEYOND`] in `v`.
pub(super) fn beyond_at(v: &Value) -> Option<String> {
    crate::report::first_path(
        v,
        &|x| matches!(x, Value::String(s) if s.starts_with(BEYOND)),
    )
}

/// `v` with the values beyond binary64 as their decimal text (`"≈3.4e308"`), as a report that
/// prints them (given values that contradict each other, exit 1) shows them: never 0 or inf.
pub fn unmarked(v: Value) -> Value {
    match v {
        Value::String(s) => Value::String(s.trim_start_matches(BEYOND).to_string()),
        Value::Array(a) => Value::Array(a.into_iter().map(unmarked).collect()),
        Value::Object(o) => Value::Object(o.into_iter().map(|(k, x)| (k, unmarked(x))).collect()),
        other => other,
    }
}

/// Renders `text` only once `json`, the same quantities under their names, is within binary64:
/// an overflow then names the quantity, whichever format was asked for.
pub fn named<T>(
    json: impl FnOnce() -> Result<Value, Overflow>,
    text: impl FnOnce() -> Result<T, Overflow>,
) -> Result<T, Overflow> {
    json()?;
    text()
}
