//! `collide view`'s page on a desktop's and a phone's screen (issue 43, sections 1 and 4): the
//! velocity plane beside Newton's or Minkowski's diagram at 1280x800 and 1600x1000, stacked at
//! 390x844 with no sideways overflow and 11 px chart text; a finger's swipe scrolls and only a
//! handle drags; Tab never leaves a control under the sticky bar; every text at 4.5:1 contrast;
//! the valid extreme case drawn finite; a drag keeps the velocities' unit; the stack's words when
//! the heavy ball is on top; the drag latency. One run of `view_layout.py` in headless Chromium
//! reports what the page did; each test checks a part against values derived in its comments.

use std::path::Path;
use std::process::Command as StdCommand;
use std::sync::OnceLock;

use serde_json::{Value, json};

use super::view::{cli_json, run_shown, scratch, solve_args};
use crate::common::collide;

/// What the browser did, once for all these tests.
fn layout() -> &'static Value {
    static RUN: OnceLock<Value> = OnceLock::new();
    RUN.get_or_init(|| drive("layout", "view_layout.py"))
}

/// `collide view`'s first page written to `target/tmp/view/<name>/view.html` and driven in the
/// browser by `tests/suite/<driver> PAGE OUT_DIR` (its screenshots left beside the page): the
/// JSON it printed.
pub(crate) fn drive(name: &str, driver: &str) -> Value {
    drive_with(name, driver, &[])
}

/// `drive`, with more arguments after `PAGE OUT_DIR`.
pub(crate) fn drive_with(name: &str, driver: &str, more: &[&str]) -> Value {
    let dir = scratch(name);
    let page = dir.join("view.html");
    collide()
        .args(["view", "-o", page.to_str().unwrap()])
        .assert()
        .success();
    let script = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/suite")
        .join(driver);
    let out = StdCommand::new("python3")
        .arg(script)
        .arg(&page)
        .arg(&dir)
        .args(more)
        .output()
        .expect("python3 runs");
    assert!(
        out.status.success(),
        "{driver} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    eprintln!(
        "{name}: {:.1} s in the browser; screenshots in {}",
        v["seconds"].as_f64().unwrap_or(0.0),
        dir.display()
    );
    v
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_wide_screens_show_the_plane_beside_newton_or_minkowski() {
    for w in layout()["wide"].as_array().unwrap() {
        let (width, height) = (f(&w["window"][0]), f(&w["window"][1]));
        let bar = f(&w["bar"]);
        let plane = &w["plane"];
        for name in ["newton", "minkowski"] {
            let other = &w[name];
            // Both boxes whole in the window below the sticky bar, at once.
            for b in [plane, other] {
                assert!(
                    f(&b["top"]) >= bar - 0.5
                        && f(&b["bottom"]) <= height + 0.5
                        && f(&b["left"]) >= 0.0
                        && f(&b["right"]) <= width + 0.5,
                    "{width}x{height}: {name} {b} (bar {bar})"
                );
            }
            // Side by side: the diagram right of the plane, their heights overlapping mostly.
            assert!(f(&plane["right"]) <= f(&other["left"]), "{w}");
            let overlap = f(&plane["bottom"]).min(f(&other["bottom"]))
                - f(&plane["top"]).max(f(&other["top"]));
            assert!(
                overlap > 0.8 * (f(&other["bottom"]) - f(&other["top"])),
                "{w}"
            );
            // And not tiny: each at least 450 px across.
            assert!(f(&other["right"]) - f(&other["left"]) >= 450.0, "{w}");
        }
        assert!(f(&plane["right"]) - f(&plane["left"]) >= 450.0, "{w}");
        assert_eq!(w["newton_hidden"], true, "the choice shows one diagram");
    }
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_dragging_in_moves_newton_with_it_at_every_step() {
    // Newton's world line of body i runs through (t, x) = (-1, -V_i^IN), (0, 0), (1, V_i^FIN):
    // on the screen its rise over each unit of time is proportional to the velocity, so the
    // two bodies' rises before the collision stand as V1^IN : V2^IN, and after it as FIN's. At
    // every step of the drag both must be the IN and FIN of the case on screen then.
    for w in layout()["wide"].as_array().unwrap() {
        let drag = w["drag"].as_array().unwrap();
        let mut ins = Vec::new();
        for step in drag {
            let lines = &step["newton"];
            let rise = |i: usize, a: usize, b: usize| {
                f(&lines[i][a][1]) - f(&lines[i][b][1]) // screen y grows downward
            };
            for (part, v, (a, b)) in [("in", &step["in"], (0, 1)), ("fin", &step["fin"], (1, 2))] {
                let r = [rise(0, a, b), rise(1, a, b)];
                let v = [f(&v[0]), f(&v[1])];
                let norm = v[0].hypot(v[1]);
                assert!(norm > 0.0, "{step}");
                // The rises along the velocity, off it by no more than the points' rounding
                // (0.005 px at each end of each rise): |r x v| / |v| <= 0.02 px.
                let off = (r[0] * v[1] - r[1] * v[0]).abs() / norm;
                let along = (r[0] * v[0] + r[1] * v[1]) / norm;
                assert!(
                    off <= 0.02 && along > 0.0,
                    "{part} {v:?}, rises {r:?}: {step}"
                );
            }
            ins.push(step["in"].to_string());
        }
        ins.dedup();
        assert!(ins.len() >= 6, "IN moved at {} of 8 steps", ins.len());
    }
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_phone_has_no_sideways_overflow_and_11_px_chart_text() {
    let p = &layout()["phone"];
    for key in ["width", "width_after"] {
        assert!(f(&p[key][0]) <= 390.0, "{key}: {}", p[key]);
        assert_eq!(f(&p[key][1]), 390.0, "{key}: the window is the phone's");
    }
    for (which, t) in p["text"].as_object().unwrap() {
        assert!(f(&t["px"]) >= 10.99, "{which}: {t}");
    }
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_phone_swipe_scrolls_and_only_ins_handle_drags() {
    let p = &layout()["phone"];
    // A vertical swipe of 60% of the picture's height, away from IN: the page scrolls, IN stays.
    let s = &p["swipe"];
    assert!(
        f(&s["after"]["scroll"]) - f(&s["before"]["scroll"]) >= 100.0,
        "{s}"
    );
    assert_eq!(s["after"]["typed"], s["before"]["typed"], "{s}");
    // A finger from IN's handle, 40 px left and 60 px up: the page stays, and IN moves by
    // (-40, +60) px over (scale x screen px per unit) = data units, to the step it snaps to.
    let h = &p["handle"];
    assert_eq!(h["after"]["scroll"], h["before"]["scroll"], "{h}");
    let per_unit = f(&h["map"]["s"]) * f(&h["k"]);
    let step = f(&h["map"]["step"]);
    let expected = [
        f(&h["before"]["state"][0]) - 40.0 / per_unit,
        f(&h["before"]["state"][1]) + 60.0 / per_unit,
    ];
    for k in 0..2 {
        let got = f(&h["after"]["state"][k]);
        assert!(
            (got - expected[k]).abs() <= step * 0.5 + 0.01 / per_unit,
            "V{}: {got}, expected {} (step {step}): {h}",
            k + 1,
            expected[k]
        );
    }
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_tab_never_leaves_the_focused_control_under_the_sticky_bar() {
    for (size, seen) in layout()["focus"].as_object().unwrap() {
        let seen = seen.as_array().unwrap();
        // The page's controls: the links, the two cases' fields, sliders, frames, players...
        assert!(seen.len() >= 60, "{size}: only {} stops", seen.len());
        for c in seen {
            if c["in_bar"] == true {
                continue;
            }
            let room = f(&c["height"]) - f(&c["bar"]);
            let tall = f(&c["bottom"]) - f(&c["top"]) > room;
            assert!(
                f(&c["top"]) >= f(&c["bar"]) - 0.5
                    && (tall || f(&c["bottom"]) <= f(&c["height"]) + 0.5),
                "{size}: {c}"
            );
        }
    }
}

/// WCAG 2 relative luminance of an sRGB colour.
fn luminance(c: [f64; 3]) -> f64 {
    let lin = |u: f64| {
        let u = u / 255.0;
        if u <= 0.04045 {
            u / 12.92
        } else {
            ((u + 0.055) / 1.055).powf(2.4)
        }
    };
    0.2126 * lin(c[0]) + 0.7152 * lin(c[1]) + 0.0722 * lin(c[2])
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_every_text_has_4_5_to_1_contrast() {
    // WCAG 1.4.3: (L1 + 0.05) / (L2 + 0.05) >= 4.5, or 3 for large text (24 px, or 18.66 px
    // bold); a colour with alpha is blended over its background first.
    let texts = layout()["contrast"].as_array().unwrap();
    assert!(texts.len() > 150, "{} texts", texts.len());
    let mut low = Vec::new();
    for t in texts {
        let rgba = |v: &Value| [f(&v[0]), f(&v[1]), f(&v[2]), f(&v[3])];
        let (fg, bg) = (rgba(&t["fg"]), rgba(&t["bg"]));
        let over = |a: f64, b: f64| fg[3] * a + (1.0 - fg[3]) * b;
        let fg = [over(fg[0], bg[0]), over(fg[1], bg[1]), over(fg[2], bg[2])];
        let (l1, l2) = (luminance(fg), luminance([bg[0], bg[1], bg[2]]));
        let ratio = (l1.max(l2) + 0.05) / (l1.min(l2) + 0.05);
        let px = f(&t["px"]);
        let large = px >= 24.0 || (t["bold"] == true && px >= 18.66);
        if ratio < if large { 3.0 } else { 4.5 } {
            low.push(format!("{:.2}:1 {}", ratio, t["what"]));
        }
    }
    assert!(low.is_empty(), "{low:#?}");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_the_valid_extreme_case_draws_finite_with_no_console_error() {
    let b = layout();
    let x = &b["extreme"];
    assert_eq!(x["error"], "", "{x}");
    assert_eq!(x["bad"], json!([]), "NaN or Infinity drawn");
    let case = json!({"m1": "1", "m2": "1e-308", "v1": "0", "v2": "1e308", "e": "0"});
    assert_eq!(x["state"].as_str().unwrap(), cli_json(&solve_args(&case)));
    // No console error or warning, and no page error, in any window of the run.
    let bad: Vec<&Value> = b["console"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|m| m[1] != "log" && m[1] != "info" && m[1] != "debug")
        .collect();
    assert!(bad.is_empty(), "{bad:?}");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_dragging_in_keeps_the_velocities_unit() {
    let u = &layout()["units"];
    assert_eq!(u["error"], "", "{u}");
    let typed: Vec<&str> = u["typed"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| t.as_str().unwrap())
        .collect();
    assert!(typed.iter().all(|t| t.ends_with(" km/h")), "{typed:?}");
    assert_ne!(typed, ["72 km/h", "10 km/h"], "the drag moved IN");
    let case = json!({"m1": "4", "m2": "1", "v1": typed[0], "v2": typed[1], "e": "elastic"});
    assert_eq!(u["state"].as_str().unwrap(), cli_json(&solve_args(&case)));
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_a_heavy_ball_on_top_leaves_downward_and_is_not_said_to_rise() {
    // A ball of mass 1 resting on one of 0.01, dropped: the light ball rebounds from the floor at
    // +u and meets the heavy one at -u; elastically the top ball leaves at
    // ((m2 - m1)(-u) + 2 m1 u) / (m1 + m2) = (-0.99 + 0.02) u / 1.01 = -97/101 u = -0.960396 u.
    let s = &layout()["stack"];
    assert_eq!(s["error"], "", "{s}");
    let numbers = s["numbers"].as_str().unwrap();
    assert!(
        numbers.contains("leaves the collision downward, at \u{2212}0.960396 \u{d7}"),
        "{numbers}"
    );
    assert!(!numbers.contains("rises"), "{numbers}");
    assert!(
        numbers.contains("A heavier ball is above a lighter one"),
        "{numbers}"
    );
    assert_eq!(
        run_shown(s["command"].as_str().unwrap()),
        s["state"].as_str().unwrap()
    );
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_drag_latency_event_to_frame() {
    // 120 mouse moves 25 ms apart: each must reach a drawn frame. The figures are reported
    // (docs/benchmarks.md), not asserted: they depend on the machine's load.
    let mut ms: Vec<f64> = layout()["latency"]
        .as_array()
        .unwrap()
        .iter()
        .map(f)
        .collect();
    assert!(ms.len() >= 120, "{} of 120 moves reached a frame", ms.len());
    ms.sort_by(f64::total_cmp);
    let median = ms[ms.len() / 2];
    let p95 = ms[(ms.len() * 95) / 100];
    eprintln!(
        "drag latency, event to the end of its frame: median {median:.1} ms, p95 {p95:.1} ms, \
         max {:.1} ms ({} moves)",
        ms[ms.len() - 1],
        ms.len()
    );
    assert!(ms.iter().all(|t| t.is_finite() && *t > 0.0), "{ms:?}");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_phet_controls_step_play_at_a_speed_and_reset() {
    let c = &layout()["controls"];
    // The lecture's 2-ball stack runs until 3.6 (8 times the first bounce's time, view.rs).
    let until = f(&c["until"]);
    assert_eq!(until, 3.6);
    // (start, one step, speed at 1x in time units a second): the dual panel's t from -1 to 1 in
    // 40 steps, 2 units in 4 s; the stack's from 0 to `until` in 100 steps, in real time.
    for (prefix, start, step, rate) in [
        ("dual", -1.0, 0.05, 0.5),
        ("stack", 0.0, until / 100.0, 1.0),
    ] {
        let s = &c[prefix];
        assert_eq!(f(&s["start"]), start, "{prefix}: {s}");
        let near = |got: f64, want: f64, what: &str| {
            assert!(
                (got - want).abs() <= 1e-12,
                "{prefix} {what}: {got}, not {want}"
            )
        };
        near(f(&s["three_steps"]), start + 3.0 * step, "after 3 steps");
        near(
            f(&s["one_back"]),
            start + 2.0 * step,
            "after 3 steps and 1 back",
        );
        // Played 0.6 s at 2x and at 1/4x: the time advances at the speed times the rate, within the
        // frames the page's clock shows between the clicks (at least half, on a loaded machine).
        for (speed, x) in [("2", 2.0), ("0.25", 0.25)] {
            let (dt, secs) = (f(&s["rates"][speed][0]), f(&s["rates"][speed][1]));
            let want = x * rate * secs;
            assert!(
                dt > 0.5 * want && dt <= want * 1.01,
                "{prefix} at {speed}x: {dt} in {secs} s, expected about {want}"
            );
        }
        // Reset: paused, at the start, at 1x.
        assert_eq!(f(&s["reset"]["time"]), start, "{prefix}: {s}");
        assert_eq!(s["reset"]["speed"], "1");
        assert_eq!(s["reset"]["pressed"], "false");
    }
    // After Reset the rail shows the case as typed, before the collision: lecture A's IN.
    let rail: Vec<&str> = c["rail"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| t.as_str().unwrap())
        .collect();
    assert!(
        rail.contains(&"before: IN") && rail.contains(&"V = 60") && rail.contains(&"V = 10"),
        "{rail:?}"
    );
}
