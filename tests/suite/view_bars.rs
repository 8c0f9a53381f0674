//! `collide view`'s PhET controls of issue 43 (section 2, and the live region of section 4): the
//! momentum and kinetic-energy bars beside the rail and the plane, the rail's cars dragged to
//! where they start, and the live region that says the result once a drag has ended. One run of
//! `view_bars.py` in headless Chromium at 1280x800 reports what the page did; each test checks a
//! part against values derived by hand in its comments.

use std::sync::OnceLock;

use serde_json::Value;

use super::view::{cli_json, run_shown};
use super::view_layout::drive;

/// What the browser did, once for all these tests.
fn run() -> &'static Value {
    static RUN: OnceLock<Value> = OnceLock::new();
    RUN.get_or_init(|| {
        let v = drive("bars", "view_bars.py");
        assert_eq!(
            v["console"],
            serde_json::json!([]),
            "console: {}",
            v["console"]
        );
        v
    })
}

/// The rows of an energy group: each body and the sum, before and after.
const KE_ROWS: [&str; 6] = [
    "KE₁ IN",
    "KE₂ IN",
    "sum IN",
    "KE₁ FIN",
    "KE₂ FIN",
    "sum FIN",
];

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// `got` within `ulps` units in the last place of `want`.
fn close(got: f64, want: f64, ulps: f64, what: &str) {
    let tol = ulps * f64::EPSILON * want.abs().max(f64::MIN_POSITIVE);
    assert!((got - want).abs() <= tol, "{what}: {got} against {want}");
}

/// A group's bars as (name, value), and each bar's drawn length checked against its value: a
/// bar is `|value| / max |value|` of the group's reach long (the page rounds coordinates to
/// 0.01 of a viewBox unit), from the zero line, on the side of its sign.
fn group(groups: &Value, id: &str) -> Vec<(String, f64)> {
    let g = groups
        .as_array()
        .unwrap()
        .iter()
        .find(|g| g["id"] == id)
        .unwrap_or_else(|| panic!("no group {id} in {groups}"));
    let rows = g["rows"].as_array().unwrap();
    let big = rows
        .iter()
        .map(|r| f(&r["value"]).abs())
        .fold(0.0, f64::max);
    let (zero, reach) = (f(&g["zero"]), f(&g["reach"]));
    for r in rows {
        let v = f(&r["value"]);
        let want = v.abs() / big * reach;
        assert!((f(&r["width"]) - want).abs() <= 0.011, "{id}: {r} ({want})");
        let start = if v < 0.0 { zero - want } else { zero };
        assert!((f(&r["x"]) - start).abs() <= 0.011, "{id}: {r}");
    }
    rows.iter()
        .map(|r| (r["name"].as_str().unwrap().to_string(), f(&r["value"])))
        .collect()
}

fn names_values(rows: &[(String, f64)]) -> (Vec<String>, Vec<f64>) {
    (
        rows.iter().map(|r| r.0.clone()).collect(),
        rows.iter().map(|r| r.1).collect(),
    )
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_rail_bars_of_fig_1_3_are_the_lecture_momenta_and_energies() {
    // Fig. 1.3: M = (4, 1), IN = (60, 10), e = 1, FIN = (40, 90) (physics.md). Momenta M_i V_i:
    // IN (240, 10), FIN (160, 90), the sum 250 both times. Energies 1/2 M_i V_i^2: IN
    // (1/2 4 3600, 1/2 100) = (7200, 50), sum 7250; FIN (1/2 4 1600, 1/2 8100) = (3200, 4050),
    // sum 7250. All exact in binary64.
    let bars = &run()["bars"]["fig13"]["rail"];
    let (names, p) = names_values(&group(bars, "bars-momentum"));
    assert_eq!(names, KE_ROWS.map(|n| n.replace("KE", "P")));
    assert_eq!(p, [240.0, 10.0, 250.0, 160.0, 90.0, 250.0]);
    let (names, ke) = names_values(&group(bars, "bars-energy"));
    assert_eq!(names, KE_ROWS);
    assert_eq!(ke, [7200.0, 50.0, 7250.0, 3200.0, 4050.0, 7250.0]);
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_rail_bars_at_e_two_thirds_keep_momentum_and_lose_energy() {
    // e = 2/3: COM = 50, FIN = (1 + e) COM - e IN = (250/3 - 40, 250/3 - 20/3) = (130/3, 230/3).
    // Momenta FIN (520/3, 230/3), sum 750/3 = 250. Energies FIN: 1/2 4 (130/3)^2 = 33800/9,
    // 1/2 (230/3)^2 = 26450/9, sum 60250/9 = 7250 - (1 - 4/9) 1000 (the crunch KE_IN - KE_COM =
    // 7250 - 6250 = 1000). Each value rounded from the exact one within a few ulps; the sum FIN
    // is `collide solve`'s energy.fin itself.
    let bars = &run()["bars"]["two_thirds"]["rail"];
    let (_, p) = names_values(&group(bars, "bars-momentum"));
    for (got, want) in p
        .iter()
        .zip([240.0, 10.0, 250.0, 520.0 / 3.0, 230.0 / 3.0, 250.0])
    {
        close(*got, want, 4.0, "momentum");
    }
    let (_, ke) = names_values(&group(bars, "bars-energy"));
    for (got, want) in ke.iter().zip([
        7200.0,
        50.0,
        7250.0,
        33800.0 / 9.0,
        26450.0 / 9.0,
        60250.0 / 9.0,
    ]) {
        close(*got, want, 4.0, "energy");
    }
    let cli: Value = serde_json::from_str(&cli_json(
        &[
            "solve", "-m", "4,1", "-v", "60,10", "-e", "2/3", "--format", "json",
        ]
        .map(String::from),
    ))
    .unwrap();
    assert_eq!(ke[5], f(&cli["energy"]["fin"]));
    assert_eq!(ke[2], f(&cli["energy"]["in"]));
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_plane_bars_split_the_pucks_energy() {
    // The page's first plane case: equal disks m = (1, 1), v1 = (1, 0), v2 = 0, b = R: the line
    // of impact at 30 degrees, v1' = (1/4, -sqrt3/4), v2' = (3/4, sqrt3/4) (the 90-degree rule).
    // KE IN (1/2, 0); FIN 1/2 (1/16 + 3/16) = 1/8 and 1/2 (9/16 + 3/16) = 3/8 (exact rationals,
    // so exact in binary64), sums 1/2 = `collide solve`'s energy.
    let (names, ke) = names_values(&group(
        &run()["bars"]["fig13"]["plane"],
        "plane-bars-energy",
    ));
    assert_eq!(names, KE_ROWS);
    assert_eq!(ke, [0.5, 0.0, 0.5, 0.125, 0.375, 0.5]);
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_a_car_dragged_on_the_rail_starts_where_it_was_let_go() {
    // At t = -1 car 1 (on the left) has its front at x = -V1. The rail is 960 units wide at
    // 1280x800: X(u) = 30 + 84 + (u / reach + 1) 732 / 2, reach = 1.1 max(60, 10, 40, 90) = 99,
    // so a screen pixel is 1/k units (k px per unit, read) and a unit is 2 reach / 732 of
    // velocity. 120 px to the left moves the front by -(120/k) (198/732) and V1 by as much the
    // other way, snapped to the velocity plane's step (1): V1 = round(60 + (120/k) 198/732) =
    // 86 at k = 1.2396. V2 stays as typed.
    let r = &run()["rail"];
    let k = f(&r["grabbed"]["k"]);
    let v1 = (60.0 + 120.0 / k * 198.0 / 732.0).round();
    assert_eq!(v1, 86.0, "k = {k}");
    assert_eq!(r["typed"], serde_json::json!([format!("{v1}"), "10"]));
    // The page's state is `collide solve`'s, and the command it shows reproduces it.
    let state = r["state"].as_str().unwrap();
    let cli = cli_json(
        &[
            "solve", "-m", "4,1", "-v", "86,10", "-e", "elastic", "--format", "json",
        ]
        .map(String::from),
    );
    assert_eq!(state, cli);
    assert_eq!(run_shown(r["command"].as_str().unwrap()), cli);
    // The bars follow: P1 IN = 4 86 = 344, KE1 IN = 1/2 4 86^2 = 14792.
    let (_, p) = names_values(&group(&r["bars"], "bars-momentum"));
    assert_eq!(p[0], 344.0);
    let (_, ke) = names_values(&group(&r["bars"], "bars-energy"));
    assert_eq!(ke[0], 14792.0);
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_live_region_says_one_sentence_when_the_drag_ends() {
    // 30 moves of IN: no live region may change during them (a screen reader would read each),
    // and the velocity plane's says one short sentence once the button is up: IN and FIN of the
    // state on screen, and the energies. No live region holds a table of the two panels.
    let s = &run()["said"];
    let log = s["log"].as_array().unwrap();
    assert_eq!(log.len(), 1, "{log:?}");
    assert_eq!(log[0][0], "case-said");
    assert_eq!(log[0][1], "up", "said during the drag: {log:?}");
    let sentence = log[0][2].as_str().unwrap();
    let state: Value = serde_json::from_str(s["state"].as_str().unwrap()).unwrap();
    let int = |v: &Value| format!("{}", f(v)).replace('-', "\u{2212}");
    // IN snapped to whole numbers (the step is 1): printed as typed.
    let want = format!(
        "IN ({}, {}) gives FIN (",
        int(&state["in"][0]),
        int(&state["in"][1])
    );
    assert!(sentence.starts_with(&want), "{sentence} ({want})");
    assert!(sentence.contains("kinetic energy"), "{sentence}");
    assert!(sentence.chars().count() <= 120, "{sentence}");
    for live in s["live"].as_array().unwrap() {
        if live[0] != "stack-numbers" {
            assert_eq!(live[1], 0, "{live}");
        }
    }
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_drag_latency_of_a_car_and_of_in() {
    // 80 moves each, 25 ms apart: every move reaches a drawn frame. The figures are reported
    // with the load average (docs/benchmarks.md), not asserted: they depend on the machine.
    let l = &run()["latency"];
    for (what, load) in [("car", "car_load"), ("in", "in_load")] {
        let mut ms: Vec<f64> = l[what].as_array().unwrap().iter().map(f).collect();
        assert!(ms.len() >= 80, "{what}: {} of 80 moves drawn", ms.len());
        assert!(ms.iter().all(|t| t.is_finite() && *t > 0.0), "{ms:?}");
        ms.sort_by(f64::total_cmp);
        eprintln!(
            "{what} drag, event to the end of its frame: median {:.1} ms, p95 {:.1} ms \
             (load average {})",
            ms[ms.len() / 2],
            ms[ms.len() * 95 / 100],
            l[load]
        );
    }
}
