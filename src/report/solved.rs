//! What a homework problem's unknowns came out as (`Solved: v1 = 60, e = 1`), the laws checked
//! rather than used, and the units: the lines and JSON keys `solve` and scenes add to a report.

use crate::values::rational::Q;
use serde_json::{Map, Value};

use super::text::paragraph;
use crate::line::unknowns::{Solved, Var};
use crate::values::number::num;
use crate::values::quantity::{Exact, Scalar, fraction, to_f64};
use crate::values::units::Units;

/// `Solved: ...` and `Check: ...` lines, then a blank line.
pub fn text(s: &Solved, exact: bool, units: &Units) -> String {
    lines(s, exact, units) + "\n"
}

/// `Solved: v1 = 60 mph, e = 1` (each value in its unit, when the case has units) and `Check:
/// ...` lines.
pub fn lines(s: &Solved, exact: bool, units: &Units) -> String {
    let show = |q: &Q| {
        match crate::values::rational::to_f64(q) {
            _ if exact => Exact::Rational(q.clone()).show(),
            Some(x) => num(x),
            // Beyond binary64 (a residual of 2e308): its value to 20 digits, never inf or NaN.
            None => Exact::Approx(q.clone()).show(),
        }
    };
    let unit = |v: Var| {
        let unit = match v {
            Var::M1 | Var::M2 => units.mass,
            Var::E => None,
            _ => units.velocity,
        };
        unit.map(|u| format!(" {u}")).unwrap_or_default()
    };
    let mut out = String::new();
    if !s.unknowns.is_empty() {
        let mut parts: Vec<String> = s
            .unknowns
            .iter()
            .filter(|v| s.has(**v))
            .map(|v| format!("{v} = {}{}", show(s.get(*v)), unit(*v)))
            .collect();
        if s.separation {
            parts.push("e undefined (the bodies start together)".into());
        }
        out.push_str(&paragraph(&format!("Solved: {}", parts.join(", "))));
    }
    for (law, residual) in &s.checks {
        if residual.is_zero() {
            out.push_str(&paragraph(&format!("Check: {law} holds exactly")));
        } else {
            out.push_str(&paragraph(&format!(
                "Check: {law} does NOT hold: it misses by {}",
                show(residual)
            )));
        }
    }
    out
}

/// Adds `units` (when given), `solved` and `check` (when unknowns were solved) to a report's
/// JSON object.
pub fn annotate(json: &mut Value, units: &Units, solved: Option<&Solved>, exact: bool) {
    let Some(o) = json.as_object_mut() else {
        return;
    };
    if *units != Units::default() {
        let u = units;
        // Only the units given ("as given" values have none).
        let mut units = Map::new();
        if let Some(m) = u.mass {
            units.insert("mass".into(), m.into());
        }
        if let Some(v) = u.velocity {
            units.insert("velocity".into(), v.into());
        }
        units.insert("energy".into(), u.energy().into());
        o.insert("units".into(), Value::Object(units));
    }
    let Some(s) = solved else {
        return;
    };
    let value = |q: &Q| {
        if exact {
            Value::String(fraction(q))
        } else {
            serde_json::json!(to_f64(q))
        }
    };
    let solved: Map<String, Value> = s
        .unknowns
        .iter()
        .filter(|v| s.has(**v))
        .map(|v| (v.name().to_string(), value(s.get(*v))))
        .collect();
    o.insert("solved".into(), Value::Object(solved));
    let checks: Map<String, Value> = s
        .checks
        .iter()
        .map(|(law, r)| (law.to_string(), value(r)))
        .collect();
    if !checks.is_empty() {
        o.insert("check".into(), Value::Object(checks));
    }
}

/// What `solve` and scenes print, after the checks, for given values that contradict a law.
pub fn contradiction() -> String {
    paragraph(
        "The given values contradict each other, so no collision is printed: check them, or mark \
         one '?' to solve for it.",
    )
}
