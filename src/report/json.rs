//! JSON: the report's fields as one object, numbers shortest-round-trip (serde_json uses ryu).

use super::Report;

pub fn render(report: &Report) -> String {
    let mut s = serde_json::to_string_pretty(report).expect("a report serializes");
    s.push('\n');
    s
}
