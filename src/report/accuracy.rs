//! `collide accuracy`'s report: each method's error against exact arithmetic beside its run time,
//! per family of cases.

use serde::Serialize;

use super::text::{Block, paragraph};
use crate::accuracy::{Family, Row, Spread};

/// The JSON document: the seed, the families and the rows. An infinite error (a non-zero result
/// where the exact value is 0, or an overflow: `inf` in the text) has no JSON number and is not
/// `null` (which reads as a missing result): its key is left out and `"<key>_infinite": true`
/// says why (`"worst_infinite": true`).
pub fn json(seed: u64, families: &[Family], rows: &[Row]) -> serde_json::Value {
    let mut rows = serde_json::to_value(rows).expect("rows serialize");
    for spread in rows
        .as_array_mut()
        .into_iter()
        .flatten()
        .filter_map(serde_json::Value::as_object_mut)
        .flat_map(|row| row.values_mut())
        .filter_map(serde_json::Value::as_object_mut)
    {
        for key in ["median", "worst"] {
            if spread.get(key).is_some_and(serde_json::Value::is_null) {
                spread.remove(key);
                spread.insert(format!("{key}_infinite"), true.into());
            }
        }
    }
    #[derive(Serialize)]
    struct FamilyJson<'a> {
        name: &'a str,
        about: &'a str,
        cases: usize,
    }
    serde_json::json!({
        "seed": seed,
        "families": families
            .iter()
            .map(|f| FamilyJson { name: f.name, about: f.about, cases: f.cases.len() })
            .collect::<Vec<_>>(),
        "rows": rows,
    })
}

/// The table for people, one group of rows per family, each under a line saying what the
/// family is.
pub fn text(seed: u64, families: &[Family], rows: &[Row]) -> String {
    let mut out = paragraph(&format!(
        "Error against run time, seed {seed}: errors in ulps of each quantity's natural scale \
         (FIN: max(|V1|, |V2|, |FIN1|, |FIN2|); crunch and lost: themselves), median / worst, \
         inf when there is no finite result (overflow) or a non-zero one where the exact value \
         is 0; time per solve in ns, median (lower-upper quartile of the timed passes)."
    ));
    out.push('\n');
    let u = |s: &Spread| format!("{} / {}", ulp_text(s.median), ulp_text(s.worst));
    let mut table = Block::table(&[1, 2, 3, 4]);
    table.cells([
        "method".to_string(),
        "FIN ulps".into(),
        "crunch ulps".into(),
        "lost ulps".into(),
        "ns/solve".into(),
    ]);
    let mut family = None;
    for r in rows {
        // A blank line and the family's line before its rows.
        if family != Some(r.family) {
            table.gap();
            let about = families
                .iter()
                .find(|f| f.name == r.family)
                .map(|f| f.about);
            table.line(format!(
                "{}, {} cases: {}",
                r.family,
                r.cases,
                about.unwrap_or("")
            ));
        }
        family = Some(r.family);
        table.cells([
            r.method.name().to_string(),
            u(&r.fin_ulps),
            u(&r.crunch_ulps),
            u(&r.lost_ulps),
            format!(
                "{} ({}-{})",
                ns_text(r.ns_median),
                ns_text(r.ns_q1),
                ns_text(r.ns_q3)
            ),
        ]);
    }
    table.render(&mut out);
    out
}

/// A time in ns to 3 or 4 significant digits: `9.5`, `110`, `2558`.
fn ns_text(ns: f64) -> String {
    if ns < 100.0 {
        format!("{ns:.1}")
    } else {
        format!("{ns:.0}")
    }
}

/// An error in ulps for the table: `0`, `0.5`, `3`, `2.1e12`, or `inf`.
fn ulp_text(x: f64) -> String {
    if !x.is_finite() {
        "inf".into()
    } else if x == 0.0 {
        "0".into()
    } else if x < 100.0 {
        format!("{x:.2}")
            .trim_end_matches('0')
            .trim_end_matches('.')
            .to_string()
    } else {
        format!("{x:.1e}")
    }
}
