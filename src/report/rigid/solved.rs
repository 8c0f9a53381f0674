//! What a rigid problem's unknown came out as (`rigid::unknowns`), and each given final value
//! checked against the impact solved with it: the `Solved:` and `Check:` lines before the
//! report, and JSON `solved: {NAME: value}` (`mu_at_least` where the contact sticks) and
//! `check: {NAME: residual}`, as the rail prints them.

use num_traits::Signed;
use serde_json::{Map, Value};

use crate::rigid::unknowns::{Solution, Unknown};
use crate::values::quantity::significant;

use super::super::space::Style;
use super::super::text::paragraph;

/// The unit of a solved value (` m/s`), or nothing.
fn unit(u: Unknown, si: bool) -> String {
    match (u.measure(), si) {
        (Some(m), true) => format!(" {}", m.si_name()),
        _ => String::new(),
    }
}

/// ` rad/s` after a spin, or nothing.
fn spin_unit(name: &str, si: bool) -> &'static str {
    if si && name.starts_with("omega") {
        " rad/s"
    } else if si && name.starts_with('v') {
        " m/s"
    } else if si {
        " N s"
    } else {
        ""
    }
}

/// `Solved: v1 = 1285.9 m/s` (`mu >= 2/7` where the contact sticks) and `Check: omega2' =
/// -10 rad/s holds exactly` lines, then a blank line.
pub fn text(s: &Solution, style: &Style, si: bool) -> String {
    let mut out = String::new();
    if let Some(v) = &s.value {
        let value = style.show(&v.value, v.approx);
        let line = if v.at_least {
            format!(
                "Solved: mu >= {value} (the contact sticks: every mu from {value} on gives this \
                 FIN, shown at {value})"
            )
        } else {
            format!(
                "Solved: {} = {value}{}",
                v.unknown.name(),
                unit(v.unknown, si)
            )
        };
        out.push_str(&paragraph(&line));
    }
    for c in &s.checks {
        let u = spin_unit(&c.name, si);
        let given = match &c.typed {
            Some(t) => format!("'{t}'"),
            None => format!("{}{u}", style.show(&c.given, false)),
        };
        let line = if c.residual.is_zero() {
            format!("Check: {} = {given} holds exactly", c.name)
        } else if c.approx {
            format!(
                "Check: {} = {given} holds to {}{u} (rounded values)",
                c.name,
                significant(&c.residual.clone().abs(), 2)
            )
        } else {
            format!(
                "Check: {} = {given} does NOT hold: it misses by {}{u}",
                c.name,
                style.show(&c.residual, false)
            )
        };
        out.push_str(&paragraph(&line));
    }
    out + "\n"
}

/// Adds `solved` and `check` to a report's JSON object.
pub fn annotate(json: &mut Value, s: &Solution, style: &Style) {
    let Some(o) = json.as_object_mut() else {
        return;
    };
    if let Some(v) = &s.value {
        let key = if v.at_least {
            "mu_at_least".to_string()
        } else {
            v.unknown.name()
        };
        let mut solved = Map::new();
        solved.insert(key, style.json(&v.value, v.approx));
        o.insert("solved".into(), Value::Object(solved));
    }
    if !s.checks.is_empty() {
        let checks: Map<String, Value> = s
            .checks
            .iter()
            .map(|c| (c.name.clone(), style.json(&c.residual, c.approx)))
            .collect();
        o.insert("check".into(), Value::Object(checks));
    }
}
