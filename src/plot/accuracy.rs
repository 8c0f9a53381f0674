//! The work-precision picture of `collide accuracy --plot`: each method on each family as a point,
//! median time per solve across (log), worst error in ulps up (log); results that were not finite
//! (or non-zero where the exact value is 0) sit on a marked top row.

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
    let e_top = rows
        .iter()
        .map(worst)
        .filter(|e| e.is_finite())
        .fold(1.0f64, f64::max)
        .log10()
        .ceil()
        .max(1.0);
    let (e0, e1) = (-1.0, e_top + 1.0);
    let x = |ns: f64| LEFT + (ns.max(1e-3).log10() - t0) / (t1 - t0).max(1.0) * W;
    let y = |err: f64| {
        let l = if err.is_finite() {
            err.max(0.1).log10()
        } else {
            e1
        };
        TOP + H - (l - e0) / (e1 - e0) * H
    };
    let mut s = Svg::new(WIDTH, HEIGHT);
    s.heading(
        LEFT,
        "Error against run time",
        &format!("collide accuracy, seed {seed}: worst error of FIN, crunch and lost in ulps, against median time per solve"),
    );
    s.frame((LEFT, TOP, W, H));
    s.time_decades((t0, t1), x, (TOP, H));
    // At most about 8 labelled decades (errors can span 300).
    let step = (((e1 - e0) / 8.0).ceil() as usize).max(1);
    for d in ((e0 as i32)..(e1 as i32)).step_by(step) {
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
    let top = y(f64::INFINITY);
    s.line(
        None,
        (LEFT, top),
        (LEFT + W, top),
        "stroke=\"#fca5a5\" stroke-dasharray=\"4 3\"",
    );
    s.text(
        (LEFT - 6.0, top + 4.0),
        "inf",
        "text-anchor=\"end\" fill=\"#dc2626\" font-size=\"11\"",
    );
    s.text(
        (LEFT + W / 2.0, TOP + H + 38.0),
        "median time per solve",
        "text-anchor=\"middle\" font-weight=\"600\"",
    );
    s.text(
        (20.0, TOP - 4.0),
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
