//! The work-precision picture of `collide accuracy --plot`: each method on each family as a point,
//! median time per solve across (log), worst error in ulps up (log, over the errors below 1e16
//! ulps); results with no correct digit, and results that were not finite (or non-zero where
//! the exact value is 0), sit in marked bands above the axis.

use super::svg::{Svg, f};
use crate::accuracy::Row;

const WIDTH: f64 = 820.0;
const HEIGHT: f64 = 560.0;
const LEFT: f64 = 80.0;
const TOP: f64 = 70.0;
const W: f64 = 520.0;
const H: f64 = 400.0;
const COLOURS: [(&str, &str); 5] = [
    ("impulse", "#2563eb"),
    ("textbook", "#dc2626"),
    ("quadratic", "#d97706"),
    ("tensor", "#7c3aed"),
    ("exact", "#059669"),
];

/// The scatter: one point per (method, family), the worst of FIN, crunch and lost errors.
pub fn svg(rows: &[Row], seed: u64) -> String {
    let worst = |r: &Row| {
        r.fin_ulps
            .worst
            .max(r.crunch_ulps.worst)
            .max(r.lost_ulps.worst)
    };
    // Decades shown: time from the fastest to the slowest; error from 0.1 ulp (exact answers are
    // drawn there) up to the largest finite error.
    let ns: Vec<f64> = rows.iter().map(|r| r.ns_median.max(1e-3)).collect();
    let (t0, t1) = (
        ns.iter()
            .fold(f64::INFINITY, |a, b| a.min(*b))
            .log10()
            .floor(),
        ns.iter()
            .fold(0.0f64, |a, b| a.max(*b))
            .log10()
            .ceil()
            .max(1.0),
    );
    // Errors up: a log axis from the exact row (0.1) to the largest error below 1e16 ulps (an
    // error of 2^53 ulps or more leaves no correct digit), then two separate bands: results
    // with no correct digit, and results that were not finite (or non-zero where the exact
    // value is 0). Each band only when some point is in it.
    const NO_DIGIT: f64 = 1e16;
    let finite = rows.iter().map(worst).filter(|e| e.is_finite());
    let e_top = finite
        .clone()
        .filter(|e| *e < NO_DIGIT)
        .fold(1.0f64, f64::max)
        .log10()
        .ceil()
        .max(1.0);
    let garbage = finite.clone().any(|e| e >= NO_DIGIT);
    let infinite = rows.iter().map(worst).any(|e| !e.is_finite());
    let (e0, e1) = (-1.0, e_top);
    let x = |ns: f64| LEFT + (ns.max(1e-3).log10() - t0) / (t1 - t0).max(1.0) * W;
    let band = 34.0;
    let axis_top = TOP + band * (f64::from(u8::from(garbage)) + f64::from(u8::from(infinite)));
    let axis_h = TOP + H - axis_top;
    let garbage_y = TOP + band * f64::from(u8::from(infinite)) + band / 2.0;
    let infinite_y = TOP + band / 2.0;
    let y = |err: f64| {
        if !err.is_finite() {
            infinite_y
        } else if err >= NO_DIGIT {
            garbage_y
        } else {
            let l = err.max(0.1).log10();
            axis_top + axis_h - (l - e0) / (e1 - e0) * (axis_h - 10.0)
        }
    };
    let mut s = Svg::new(WIDTH, HEIGHT);
    s.heading(
        LEFT,
        "Error against run time",
        &format!(
            "collide accuracy, seed {seed}: worst error of FIN, crunch and lost in ulps, \
             against median time per solve"
        ),
    );
    s.frame((LEFT, TOP, W, H));
    s.time_decades((t0, t1), x, (TOP, H));
    // Every decade labelled, or every other one past 10.
    let step = if e1 - e0 > 10.0 { 2 } else { 1 };
    for d in ((e0 as i32)..=(e1 as i32)).step_by(step) {
        let py = y(10f64.powi(d));
        s.line(None, (LEFT, py), (LEFT + W, py), "stroke=\"#f3f4f6\"");
        let label = if d == -1 {
            "0 (exact)".to_string()
        } else {
            format!("1e{d}")
        };
        s.text(
            (LEFT - 6.0, py + 4.0),
            &label,
            "text-anchor=\"end\" fill=\"#6b7280\" font-size=\"11\"",
        );
    }
    // The bands above the axis, each with its own label and a rule under it.
    let bands = [
        (
            infinite,
            infinite_y,
            "not finite",
            "inf or NaN, or non-zero where 0 is exact",
        ),
        (garbage, garbage_y, "> 1e16", "no correct digit"),
    ];
    for (shown, by, label, note) in bands {
        if !shown {
            continue;
        }
        s.line(
            None,
            (LEFT, by + band / 2.0),
            (LEFT + W, by + band / 2.0),
            "stroke=\"#fca5a5\" stroke-dasharray=\"4 3\"",
        );
        s.text(
            (LEFT - 6.0, by + 4.0),
            label,
            "text-anchor=\"end\" fill=\"#dc2626\" font-size=\"11\"",
        );
        s.text(
            (LEFT + W - 6.0, by - 6.0),
            note,
            "text-anchor=\"end\" fill=\"#dc2626\" font-size=\"10\"",
        );
    }
    s.text(
        (LEFT + W / 2.0, TOP + H + 38.0),
        "median time per solve",
        "text-anchor=\"middle\" font-weight=\"600\"",
    );
    // The axis title above the axis, clear of its tick labels.
    s.text(
        (LEFT, TOP - 8.0),
        "worst error (ulps)",
        "font-weight=\"600\" font-size=\"12\"",
    );
    for r in rows {
        let colour = COLOURS
            .iter()
            .find(|c| c.0 == r.method.name())
            .map_or("#111827", |c| c.1);
        let (px, py) = (x(r.ns_median), y(worst(r)));
        s.circle(
            Some(&format!("point-{}-{}", r.method.name(), r.family)),
            (px, py),
            4.5,
            &format!("fill=\"{colour}\" fill-opacity=\"0.8\""),
        );
        s.raw(&format!(
            "<title>{}, {}: worst {:.3e} ulps, {} ns</title>",
            r.method.name(),
            r.family,
            worst(r),
            f(r.ns_median)
        ));
    }
    let lx = LEFT + W + 30.0;
    for (i, (name, colour)) in COLOURS.iter().enumerate() {
        let ly = TOP + 10.0 + 22.0 * i as f64;
        s.circle(None, (lx, ly), 4.5, &format!("fill=\"{colour}\""));
        s.text((lx + 12.0, ly + 4.0), name, "font-size=\"12\"");
    }
    s.text(
        (lx - 4.0, TOP + 140.0),
        "one point per case family",
        "fill=\"#6b7280\" font-size=\"11\"",
    );
    s.finish("Error against run time")
}
