//! `collide contact --plot`: the work-precision diagram (error against run time, log-log, one
//! line per method; unstable runs left out and counted in the legend), and a run's history (the
//! force and the overlap of each contact against time, one colour per contact).

use super::svg::{Svg, short, ticks};
use crate::contact::work::Work;
use crate::contact::{ContactRun, Setup};

const WIDTH: f64 = 860.0;
const HEIGHT: f64 = 560.0;
const LEFT: f64 = 80.0;
const TOP: f64 = 70.0;
const W: f64 = 540.0;
const H: f64 = 400.0;
const COLOURS: [&str; 8] = [
    "#2563eb", "#dc2626", "#d97706", "#7c3aed", "#059669", "#db2777", "#0891b2", "#4b5563",
];

fn decades(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| *v > 0.0 && v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let (a, b) = (lo.log10().floor(), hi.log10().ceil());
    (a, if b > a { b } else { a + 1.0 })
}

/// The work-precision diagram.
pub fn svg(work: &Work) -> String {
    let stable: Vec<_> = work
        .rows
        .iter()
        .filter(|r| !r.unstable && r.error.is_some() && r.ns.is_some())
        .collect();
    let floor = 1e-16;
    let (t0, t1) = decades(stable.iter().filter_map(|r| r.ns));
    let (e0, e1) = decades(stable.iter().filter_map(|r| r.error.map(|e| e.max(floor))));
    let x = |ns: f64| LEFT + (ns.log10() - t0) / (t1 - t0) * W;
    let y = |e: f64| TOP + H - (e.max(floor).log10() - e0) / (e1 - e0) * H;
    let mut s = Svg::new(WIDTH, HEIGHT);
    s.heading(
        LEFT,
        "Error against run time",
        &format!(
            "collide contact --work-precision: final-velocity error ({} reference) against the \
             fastest time of each run; stiffness ratio {}",
            work.reference.kind,
            short(work.stiffness_ratio)
        ),
    );
    s.frame((LEFT, TOP, W, H));
    s.time_decades((t0, t1), x, (TOP, H));
    let step = (((e1 - e0) / 10.0).ceil() as usize).max(1);
    for d in ((e0 as i32)..=(e1 as i32)).step_by(step) {
        let py = y(10f64.powi(d));
        s.line(None, (LEFT, py), (LEFT + W, py), "stroke=\"#f3f4f6\"");
        s.text(
            (LEFT - 6.0, py + 4.0),
            &format!("1e{d}"),
            "text-anchor=\"end\" fill=\"#6b7280\" font-size=\"11\"",
        );
    }
    s.text(
        (LEFT + W / 2.0, TOP + H + 38.0),
        "run time (fastest of several)",
        "text-anchor=\"middle\" font-weight=\"600\"",
    );
    // The axis title above the axis, clear of its tick labels.
    s.text(
        (LEFT, TOP - 8.0),
        "error / initial relative speed",
        "font-weight=\"600\" font-size=\"12\"",
    );
    // Errors below the reference's own uncertainty cannot be told apart from it: a grey band,
    // and the points in it drawn hollow.
    let uncertain = work
        .reference
        .uncertainty
        .filter(|u| *u > 0.0 && u.is_finite());
    if let Some(u) = uncertain {
        let top = y(u).max(TOP);
        s.raw(&format!(
            "<rect id=\"reference-uncertainty\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" \
             fill=\"#e5e7eb\" fill-opacity=\"0.6\"/>",
            super::svg::f(LEFT),
            super::svg::f(top),
            super::svg::f(W),
            super::svg::f((TOP + H - top).max(0.0))
        ));
        s.text(
            (LEFT + 6.0, TOP + H - 6.0),
            &format!(
                "below the reference's own uncertainty ({}): not told apart from it",
                short(u)
            ),
            "fill=\"#4b5563\" font-size=\"11\"",
        );
    }
    let mut methods: Vec<&str> = Vec::new();
    for r in &work.rows {
        if !methods.contains(&r.method) {
            methods.push(r.method);
        }
    }
    let lx = LEFT + W + 24.0;
    for (i, m) in methods.iter().enumerate() {
        let colour = COLOURS[i % COLOURS.len()];
        let points: Vec<(f64, f64)> = stable
            .iter()
            .filter(|r| r.method == *m)
            .map(|r| (x(r.ns.unwrap_or(1.0)), y(r.error.unwrap_or(1.0))))
            .collect();
        let dash = if work
            .rows
            .iter()
            .any(|r| r.method == *m && r.kind == "implicit")
        {
            ""
        } else {
            " stroke-dasharray=\"6 3\""
        };
        s.polyline(
            Some(&format!("method-{m}")),
            &points,
            &format!("stroke=\"{colour}\" stroke-width=\"2\"{dash}"),
        );
        for (r, p) in stable.iter().filter(|r| r.method == *m).zip(&points) {
            let hollow = uncertain.is_some_and(|u| r.error.is_some_and(|e| e < u));
            let style = if hollow {
                format!("fill=\"white\" stroke=\"{colour}\" stroke-width=\"1.5\"")
            } else {
                format!("fill=\"{colour}\"")
            };
            s.circle(None, *p, 3.0, &style);
        }
        let unstable = work
            .rows
            .iter()
            .filter(|r| r.method == *m && r.unstable)
            .count();
        let ly = TOP + 10.0 + 22.0 * i as f64;
        s.line(
            None,
            (lx, ly),
            (lx + 22.0, ly),
            &format!("stroke=\"{colour}\" stroke-width=\"2\"{dash}"),
        );
        let label = if unstable > 0 {
            format!("{m} ({unstable} unstable)")
        } else {
            m.to_string()
        };
        s.text((lx + 28.0, ly + 4.0), &label, "font-size=\"12\"");
    }
    s.text(
        (lx, TOP + 10.0 + 22.0 * methods.len() as f64 + 10.0),
        "dashed: explicit",
        "fill=\"#6b7280\" font-size=\"11\"",
    );
    if uncertain.is_some() {
        for (k, line) in ["hollow: within the", "reference's uncertainty"]
            .iter()
            .enumerate()
        {
            s.text(
                (
                    lx,
                    TOP + 10.0 + 22.0 * methods.len() as f64 + 26.0 + 14.0 * k as f64,
                ),
                line,
                "fill=\"#6b7280\" font-size=\"11\"",
            );
        }
    }
    s.finish("Error against run time")
}

/// Force (top) and overlap (bottom) of each contact against time.
pub fn history(setup: &Setup, run: &ContactRun) -> String {
    let contacts = setup.contacts();
    let n = setup.bodies.len();
    let h = run.history.as_slice();
    let t_hi = h
        .iter()
        .map(|p| p.t)
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let t_lo = h.iter().map(|p| p.t).fold(t_hi, f64::min);
    let f_hi = h
        .iter()
        .map(|p| p.force)
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let d_hi = h
        .iter()
        .map(|p| p.overlap)
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let d_lo = h.iter().map(|p| p.overlap).fold(0.0, f64::min);
    let panel = (H - 40.0) / 2.0;
    let x = |t: f64| LEFT + (t - t_lo) / (t_hi - t_lo).max(f64::MIN_POSITIVE) * W;
    let yf = |v: f64| TOP + panel - v / f_hi * panel;
    let yd = |v: f64| TOP + panel + 40.0 + panel - (v - d_lo) / (d_hi - d_lo) * panel;
    let mut s = Svg::new(WIDTH, HEIGHT);
    s.heading(
        LEFT,
        "Contact forces and overlaps",
        &format!("collide contact, method {}: after every step", run.method),
    );
    let top2 = TOP + panel + 40.0;
    for top in [TOP, top2] {
        s.frame((LEFT, top, W, panel));
    }
    s.grid(
        (LEFT, top2, W, panel),
        ticks(t_lo, t_hi, 6).into_iter().map(|t| (x(t), t)),
        ticks(d_lo, d_hi, 4).into_iter().map(|d| (yd(d), d)),
    );
    for v in ticks(0.0, f_hi, 4) {
        s.text(
            (LEFT - 6.0, yf(v) + 4.0),
            &short(v),
            "text-anchor=\"end\" fill=\"#6b7280\" font-size=\"11\"",
        );
    }
    s.text(
        (LEFT, TOP - 6.0),
        "force",
        "font-weight=\"600\" font-size=\"12\"",
    );
    s.text(
        (LEFT, top2 - 6.0),
        "overlap",
        "font-weight=\"600\" font-size=\"12\"",
    );
    s.text(
        (LEFT + W / 2.0, TOP + H + 38.0),
        "time",
        "text-anchor=\"middle\" font-weight=\"600\"",
    );
    let lx = LEFT + W + 24.0;
    for (slot, who) in contacts.iter().enumerate() {
        let colour = COLOURS[slot % COLOURS.len()];
        let pts: Vec<_> = h.iter().filter(|p| p.slot == slot).collect();
        if pts.is_empty() {
            continue;
        }
        // A contact can open and close several times: one line per contact record.
        let runs: Vec<Vec<(f64, f64, f64)>> = run
            .contacts
            .iter()
            .filter(|c| c.slot == slot)
            .map(|c| {
                let end = c.duration.map_or(f64::INFINITY, |d| c.start + d);
                pts.iter()
                    .filter(|p| p.t >= c.start && p.t <= end)
                    .map(|p| (p.t, p.force, p.overlap))
                    .collect()
            })
            .collect();
        for r in &runs {
            let fpts: Vec<_> = r.iter().map(|(t, fv, _)| (x(*t), yf(*fv))).collect();
            let dpts: Vec<_> = r.iter().map(|(t, _, d)| (x(*t), yd(*d))).collect();
            let style = format!("stroke=\"{colour}\" stroke-width=\"1.5\"");
            s.polyline(None, &fpts, &style);
            s.polyline(None, &dpts, &style);
        }
        let ly = TOP + 10.0 + 22.0 * slot as f64;
        s.line(
            None,
            (lx, ly),
            (lx + 22.0, ly),
            &format!("stroke=\"{colour}\" stroke-width=\"2\""),
        );
        s.text((lx + 28.0, ly + 4.0), &who.describe(n), "font-size=\"12\"");
    }
    s.finish("Contact forces and overlaps")
}
