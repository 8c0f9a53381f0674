//! JSON: the report's fields as one object. Numbers are shortest-round-trip (serde_json uses
//! ryu); objects are indented one key a line, arrays of numbers stay on one line
//! (`"fin": [40.0, 90.0]`) so the output reads like the schema in the README.

use serde::Serialize;
use serde_json::Value;

/// Renders any serializable value in the layout above, with a final newline.
pub fn render<T: Serialize>(value: &T) -> String {
    let v = serde_json::to_value(value).expect("reports serialize");
    let mut out = String::new();
    write(&v, 0, &mut out);
    out.push('\n');
    out
}

fn inline(v: &Value) -> bool {
    match v {
        Value::Array(a) => a.iter().all(|x| !x.is_object() && inline(x)),
        Value::Object(_) => false,
        _ => true,
    }
}

fn write(v: &Value, depth: usize, out: &mut String) {
    let pad = |d: usize| "  ".repeat(d);
    match v {
        Value::Object(o) if !o.is_empty() => {
            out.push_str("{\n");
            for (i, (k, x)) in o.iter().enumerate() {
                out.push_str(&pad(depth + 1));
                out.push_str(&Value::String(k.clone()).to_string());
                out.push_str(": ");
                write(x, depth + 1, out);
                out.push_str(if i + 1 < o.len() { ",\n" } else { "\n" });
            }
            out.push_str(&pad(depth));
            out.push('}');
        }
        Value::Array(a) if !inline(v) => {
            out.push_str("[\n");
            for (i, x) in a.iter().enumerate() {
                out.push_str(&pad(depth + 1));
                write(x, depth + 1, out);
                out.push_str(if i + 1 < a.len() { ",\n" } else { "\n" });
            }
            out.push_str(&pad(depth));
            out.push(']');
        }
        Value::Array(a) => {
            out.push('[');
            for (i, x) in a.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                write(x, depth, out);
            }
            out.push(']');
        }
        other => out.push_str(&other.to_string()),
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn layout_round_trips() {
        let v = serde_json::json!({"fin": [40.0, 90.0], "m": [[4.0, 0.0], [0.0, 1.0]],
                                   "e": {"in": 7250.0}, "list": [{"a": 1}], "s": "x\"y"});
        let text = super::render(&v);
        assert!(text.contains("\"fin\": [40.0, 90.0]"), "{text}");
        assert!(text.contains("\"m\": [[4.0, 0.0], [0.0, 1.0]]"), "{text}");
        let back: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(back, v);
    }
}
