//! `collide view` against a hostile review of its page (the plane panel and the velocity plane):
//! stale numbers after an input error, 'undefined' printed, units, sliders, tiny velocities,
//! keys past a refused value, drags in frames that move with the dragged velocity. The steps
//! (view_hostile.json) run in the one browser session of `view.rs`; each test reads what its
//! steps saw and compares with values derived by hand in its comments.

use serde_json::Value;

use super::view::browser;

/// The scripted steps (see run_steps in view_browser.py).
pub fn steps() -> Value {
    serde_json::from_str(include_str!("view_hostile.json")).expect("view_hostile.json parses")
}

/// What the step named `name` read, after checking that no page error happened up to it.
fn read<'a>(b: &'a Value, name: &str) -> &'a Value {
    let r = &b["steps"][name];
    assert!(!r.is_null(), "no step read {name}: {}", b["steps"]);
    assert_eq!(r["errors"], Value::Array(vec![]), "page errors by {name}");
    &r["value"]
}

/// Two numbers of a JSON array.
fn pair(v: &Value) -> [f64; 2] {
    [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
}

/// A velocity as the page types it, `(x,y)` with an optional unit, as numbers.
fn typed_pair(text: &str) -> [f64; 2] {
    let inner = text.trim().trim_start_matches('(');
    let inner = &inner[..inner.find(')').expect("(x,y)")];
    let mut it = inner.split(',').map(|x| x.trim().parse::<f64>().unwrap());
    [it.next().unwrap(), it.next().unwrap()]
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_an_input_error_greys_out_and_labels_the_last_valid_case() {
    let Some(b) = browser() else { return };
    // m1 = -1 in the plane panel: the pucks, the numbers, the momentum triangle, the energy
    // bars and the normal parts are the previous case's, so each is marked and labelled (five
    // notes); a valid m1 takes it away.
    let bad = read(b, "p1_bad");
    assert_eq!(
        bad["stale"],
        serde_json::json!([true, true, true, true]),
        "{bad}"
    );
    let notes = bad["notes"].as_array().unwrap();
    assert_eq!(notes.len(), 5, "{bad}");
    assert!(
        notes
            .iter()
            .all(|n| n.as_str().unwrap().contains("Last valid case"))
    );
    assert!(bad["error"].as_str().unwrap().contains("mass -1"), "{bad}");
    assert_eq!(
        read(b, "p1_good"),
        &serde_json::json!({"stale": 0, "notes": 0})
    );
    // The two-body panel the same: its velocity plane, numbers, rail and diagrams.
    let bad = read(b, "c1_bad");
    assert_eq!(
        bad["stale"],
        serde_json::json!([true, true, true, true]),
        "{bad}"
    );
    assert_eq!(bad["notes"], 1, "{bad}");
    assert_eq!(read(b, "c1_good"), 0);
    assert_eq!(read(b, "end"), 0);
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_the_reverse_of_a_sticking_collision_says_why_e_is_undefined() {
    let Some(b) = browser() else { return };
    // m = 1, 1, v1 = (4,0), n at 30 degrees, e = 0, time reverse: 1/e has no value; the page
    // says what `collide solve --reverse` says, never JavaScript's "undefined" alone.
    let text = read(b, "p9").as_str().unwrap().to_string();
    assert!(
        text.contains("e\u{2032} = undefined: 1/e with e = 0, the stuck bodies fly apart"),
        "{text}"
    );
    assert!(!text.contains("1/e = undefined"), "{text}");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_the_impulse_is_listed_under_a_momentum_unit() {
    let Some(b) = browser() else { return };
    // The car and the van (kg, m/s): J = m2 (v2' - v2) = 2500 ((9.375, 12.5) - (0, 20)) =
    // (23437.5, -18750) kg m/s, a momentum; the velocities' table (m/s) must not hold it.
    let tables = read(b, "p10").as_array().unwrap();
    let velocities = tables
        .iter()
        .find(|t| t["caption"] == "Velocities (m/s)")
        .expect("a velocities table");
    assert!(
        !velocities["rows"].to_string().contains('J'),
        "{velocities}"
    );
    let impulse = tables
        .iter()
        .find(|t| t["rows"].to_string().contains("J on body 2"))
        .expect("an impulse table");
    assert_eq!(impulse["caption"], "Impulse (kg m/s)", "{impulse}");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_mass_sliders_hold_masses_with_units() {
    let Some(b) = browser() else { return };
    // The car and the van: m1 = 1500 kg, m2 = 2500 kg; the sliders are log10 of the mass, step
    // 0.01: log10 1500 = 3.1761, log10 2500 = 3.3979.
    let s = read(b, "p7_slider");
    for (i, m) in [1500f64, 2500.0].iter().enumerate() {
        let v: f64 = s[i].as_str().unwrap().parse().unwrap();
        assert!((v - m.log10()).abs() <= 0.005 + 1e-12, "{s}");
    }
    // ArrowLeft on m1's slider: 10^3.17 = 1479.1, to 3 digits 1480, in the unit typed.
    let left = read(b, "p7_left");
    assert_eq!(left["m1"], "1480 kg", "{left}");
    assert_eq!(left["error"], "", "{left}");
    assert_eq!(pair(&left["state"]["masses"]), [1480.0, 2500.0], "{left}");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_tiny_velocities_move_by_keys_and_drags_without_errors() {
    let Some(b) = browser() else { return };
    // v1 = (1e-99, 0), v2 = 0: the pucks' scale is 180 / 1e-99 units per velocity unit, so the
    // step is 10^ceil(log10(1e-99 / 180)) = 1e-101 (toFixed cannot print its 101 decimals):
    // two ArrowUps put v1 at (1e-99, 2e-101).
    assert_eq!(read(b, "p2_keys"), "(1e-99,2e-101)");
    let drag = read(b, "p2_drag");
    assert_eq!(drag["dragging"], false, "{drag}");
    let v = typed_pair(drag["v1"].as_str().unwrap());
    assert!(v[0] > 1e-99 && v[0] < 1e-98 && v[1] < 0.0, "{drag}");
    // The velocity plane of two bodies the same: V1 = 1e-99, V2 = 0, ArrowUp twice moves V2.
    let keys = read(b, "c2_keys");
    assert_eq!(keys[0], "1e-99", "{keys}");
    let v2: f64 = keys[1].as_str().unwrap().parse().unwrap();
    assert!(v2 > 0.0 && v2 < 1e-99, "{keys}");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_arrow_keys_go_past_a_refused_value() {
    let Some(b) = browser() else { return };
    // Disks, v1 = (1, 0), v2 = (0.98, 0), step 0.01: ArrowRight on v2 four times gives 0.99,
    // 1.00 (v2 = v1, refused: the disks never meet), 1.01, 1.02 (was: stuck at 1.00).
    let r = read(b, "p5");
    assert_eq!(r["map"]["step"].as_f64(), Some(0.01), "{r}");
    assert_eq!(r["v2"], "(1.02,0.00)", "{r}");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_drags_in_a_moving_frame_put_the_arrow_under_the_mouse() {
    let Some(b) = browser() else { return };
    // m = 1, 1, v1 = (4, 0), v2 = 0, COM frame: w = (2, 0), v1 drawn as u1 = (2, 0). Dragged
    // 40 picture units right (10 moves) at s units per velocity unit, u1 = (2 + 40/s, 0) is
    // under the mouse, and u1 = (m2 / M) (v1 - v2) gives the lab v1 = (4 + 80/s, 0), to the
    // step (was: the frame's velocity added again at every move, v1 running away).
    let map = read(b, "p3_map");
    let (s, step) = (map["s"].as_f64().unwrap(), map["step"].as_f64().unwrap());
    assert_eq!(pair(&map["w"]), [2.0, 0.0], "{map}");
    let r = read(b, "p3_com");
    let v1 = typed_pair(r["v1"].as_str().unwrap());
    assert!(
        (v1[0] - (4.0 + 80.0 / s)).abs() <= step / 2.0 + 1.0 / s,
        "{r} with s = {s}"
    );
    assert_eq!(v1[1], 0.0, "{r}");
    // On screen, in the COM frame: u1 = v1 / 2, u2 = -u1 (exactly: halves of a short decimal).
    assert_eq!(r["state"]["in"][0][0], v1[0] / 2.0, "{r}");
    assert_eq!(r["state"]["in"][1][0], -v1[0] / 2.0, "{r}");
    // Body 1 initially at rest: v1 is 0 on screen whatever it is, so only v2 has a handle;
    // finally at rest, FIN depends on both: neither, and the picture says why.
    let rest_in = read(b, "p3_rest_in");
    assert_eq!(rest_in["tips"], serde_json::json!(["tip-2"]), "{rest_in}");
    assert!(
        rest_in["note"]
            .as_str()
            .unwrap()
            .starts_with("v\u{2081} moves with this frame")
    );
    let rest_fin = read(b, "p3_rest_fin");
    assert_eq!(rest_fin["tips"], serde_json::json!([]), "{rest_fin}");
    assert!(
        rest_fin["note"]
            .as_str()
            .unwrap()
            .starts_with("v\u{2081} and v\u{2082} move with this frame")
    );
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_disk_fields_take_lengths_with_units() {
    let Some(b) = browser() else { return };
    // Disks, v1 = (1, 0), v2 = 0, R1 = R2 = 2.5 cm, b = 1 in: sin phi = 2.54 / 5 = 0.508, phi
    // the angle between v1 - v2 (along x) and the line of impact (the state is `collide
    // solve`'s, checked natively in view_plane.rs); no error, and the b slider at 1 (inches).
    let r = read(b, "p6");
    assert_eq!(r["error"], "", "{r}");
    assert!(r["state"]["fin"].is_array(), "{r}");
    assert_eq!(r["slider"], "1", "{r}");
    // n = (cos phi, -sin phi) from body 1 to body 2 for b > 0 (body 2 below the path), or
    // mirrored: either way |n_y| = 0.508.
    let ny = r["state"]["normal"][1].as_f64().unwrap().abs();
    assert!((ny - 0.508).abs() <= 1e-15, "{r}");
}

/// Boxes `[name, x, y, width, height]` (picture units) that overlap, as pairs of names.
fn overlaps(boxes: &Value) -> Vec<(String, String)> {
    let b: Vec<(String, [f64; 4])> = boxes
        .as_array()
        .unwrap()
        .iter()
        .map(|x| {
            let n = |k: usize| x[k].as_f64().unwrap();
            (x[0].as_str().unwrap().to_string(), [n(1), n(2), n(3), n(4)])
        })
        .collect();
    let mut out = Vec::new();
    for (i, (na, a)) in b.iter().enumerate() {
        for (nb, c) in &b[i + 1..] {
            // Inside each other's extent on both axes by more than half a unit (not touching).
            let x = a[0] < c[0] + c[2] - 0.5 && c[0] < a[0] + a[2] - 0.5;
            let y = a[1] < c[1] + c[3] - 0.5 && c[1] < a[1] + a[3] - 0.5;
            if x && y && a[2] > 0.0 && c[2] > 0.0 {
                out.push((na.clone(), nb.clone()));
            }
        }
    }
    out
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_a_body_at_rest_before_is_not_said_to_turn() {
    let Some(b) = browser() else { return };
    // Disks: v1 = (1, 0), v2 = 0, b = 1 = (R1 + R2) / 2: phi = 30 degrees, v1' = v1 - (v1.n) n
    // turns v1 by 90 - 30 = 60 degrees; body 2 was at rest, so it did not "turn" (collide
    // solve's text leaves the line out; its JSON's turned_deg says 0).
    let text = read(b, "p11").as_str().unwrap();
    assert!(text.contains("body 1 turned 60\u{b0}"), "{text}");
    assert!(!text.contains("body 2 turned"), "{text}");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_momentum_labels_do_not_cover_each_other() {
    let Some(b) = browser() else { return };
    // v1 = (4, 0), v2 = 0 (m = 1, 1, n at 30 degrees): p2 = 0 ends on P; its label would
    // cover P's. No label overlaps another or an axis name, P is labelled, p2 (zero) is not.
    let boxes = read(b, "p13");
    assert_eq!(overlaps(boxes), vec![], "{boxes}");
    let names: Vec<&str> = boxes
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x[0].as_str().unwrap())
        .collect();
    assert!(
        names.contains(&"P") && !names.contains(&"p\u{2082}"),
        "{names:?}"
    );
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_the_time_reverse_is_drawn_in_the_plane_pictures() {
    let Some(b) = browser() else { return };
    // m = 1, 1, v1 = (4, 0), v2 = 0, n at 30 degrees, elastic: the normal parts (v1.n, v2.n)
    // go from IN = (4 cos 30, 0) = (3.464, 0) to FIN = (0, 3.464) (equal masses swap them), so
    // the reverse starts at IN' = -FIN = (0, -3.464) and ends at FIN' = -IN = (-3.464, 0).
    let r = read(b, "p15");
    assert_eq!(r["arrows"], serde_json::json!(["rev-1", "rev-2"]), "{r}");
    assert_eq!(
        r["points"],
        serde_json::json!(["n-point-rev-in", "n-point-rev-fin"]),
        "{r}"
    );
    let labels = r["labels"].to_string();
    assert!(labels.contains("IN\u{2032} (0, \u{2212}3.464)"), "{labels}");
    assert!(
        labels.contains("FIN\u{2032} (\u{2212}3.464, 0)"),
        "{labels}"
    );
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_arrows_moved_by_keys_stay_in_the_picture() {
    let Some(b) = browser() else { return };
    // e = 3 (superelastic), v1 pushed up by Shift+ArrowUp six times: FIN grows past the scale
    // the picture had; every arrow and label must stay inside the 560 x 460 picture.
    let boxes = read(b, "p12");
    for x in boxes.as_array().unwrap() {
        let n = |k: usize| x[k].as_f64().unwrap();
        assert!(
            n(1) >= 0.0 && n(2) >= 0.0 && n(1) + n(3) <= 560.0 && n(2) + n(4) <= 460.0,
            "{x} outside the picture"
        );
    }
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_the_normal_parts_zoom_in_and_keep_their_axis_names() {
    let Some(b) = browser() else { return };
    // m = 1e6, 1, n at 30 degrees, elastic, v2 = 0: along n, IN = (a, 0), COM = 1e6 a / (1e6 +
    // 1) ~ a on both axes, FIN = 2 COM - IN ~ (a, 2a), with a = v1.n: zoomed in, the three
    // points are apart (each pair > 20 units; unzoomed they sat in one dot), and no label
    // covers another or an axis name.
    let r = read(b, "p14");
    let p: Vec<[f64; 2]> = r["points"].as_array().unwrap().iter().map(pair).collect();
    for i in 0..3 {
        for j in i + 1..3 {
            let d = (p[i][0] - p[j][0]).hypot(p[i][1] - p[j][1]);
            assert!(d > 20.0, "{r}");
        }
    }
    assert_eq!(overlaps(&r["labels"]), vec![], "{r}");
}

#[test]
fn without_javascript_the_page_says_where_its_numbers_are() {
    // The page as written (no script run): the status names what is shown without JavaScript
    // (was: "loading its WebAssembly core..." for ever), each panel has a note, and the plane's
    // JSON is in the page, byte for byte `collide solve`'s.
    let page = crate::common::stdout(&[
        "view",
        "-m",
        "1,1",
        "-v",
        "(4,0),(0,0)",
        "--normal",
        "30deg",
    ]);
    let status = &page[page.find("<p id=\"status\"").unwrap()..];
    let status = &status[..status.find("</p>").unwrap()];
    assert!(
        status.contains("Without JavaScript this page shows only the numbers"),
        "{status}"
    );
    assert!(!status.contains("loading"), "{status}");
    // The velocity plane, the stack, the plane, the five pucks and the rigid bodies.
    assert_eq!(page.matches("<noscript>").count(), 5);
    let solve = crate::common::stdout(&[
        "solve",
        "-m",
        "1,1",
        "-v",
        "(4,0),(0,0)",
        "--normal",
        "30deg",
        "--format",
        "json",
    ]);
    assert!(page.contains(&format!(
        "<pre id=\"plane-state\" class=\"json\">{solve}</pre>"
    )));
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_with_javascript_the_status_says_ready() {
    let Some(b) = browser() else { return };
    let status = read(b, "status").as_str().unwrap();
    assert!(status.starts_with("Ready:"), "{status}");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_the_pucks_title_keeps_the_mass_unit_and_edits_leave_the_preset() {
    let Some(b) = browser() else { return };
    // The car and the van: m1 = 1500 kg, m2 = 2500 kg, e = 0, as typed (units included).
    let title = read(b, "p17_title").as_str().unwrap();
    assert!(
        title.starts_with("m\u{2081} = 1500 kg, m\u{2082} = 2500 kg, e = 0"),
        "{title}"
    );
    // e typed: no longer the preset; the menu says "(as given or typed)".
    assert_eq!(read(b, "p17_preset"), "");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_an_input_during_a_frame_shift_is_what_the_page_shows() {
    let Some(b) = browser() else { return };
    // Case A (M = diag(4, 1), V_IN = (60, 10)): "COM" is clicked, and e = 0.5 typed while the
    // 0.7 s shift runs. In the COM frame (w = V_COM = 50) IN is (10, -40) and FIN = -e IN =
    // (-5, 20); the shift used to end on the case it began with (e = 1: FIN (-10, 40)).
    let r = read(b, "c_frame_then_e");
    assert_eq!(r["e"], "0.5", "{r}");
    assert_eq!(r["state"]["restitution"], 0.5, "{r}");
    assert_eq!(r["state"]["frame"]["name"], "com", "{r}");
    assert_eq!(pair(&r["state"]["in"]), [10.0, -40.0], "{r}");
    assert_eq!(pair(&r["state"]["fin"]), [-5.0, 20.0], "{r}");
    // lost = (1 - e^2) crunch = 3/4 (1/2 (4/5) 50^2) = 750.
    assert_eq!(r["state"]["energy"]["lost"], 750.0, "{r}");
    assert_eq!(r["stale"], 0, "{r}");
    // Back in the lab with e = 1: elastic FIN (40, 90), Fig. 1.3.
    let r = read(b, "c_frame_back");
    assert_eq!(pair(&r["state"]["fin"]), [40.0, 90.0], "{r}");
    assert!(r["state"]["frame"].is_null(), "{r}");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_a_refused_stack_greys_the_last_run_and_stops_play() {
    let Some(b) = browser() else { return };
    // Masses "1,-1": the tower, the world lines and the numbers are the last valid run's, so
    // each is greyed and labelled, and Play is disabled; a valid input (the two-ball preset)
    // takes it all back.
    let bad = read(b, "s_bad");
    assert_eq!(bad["stale"], serde_json::json!([true, true, true]), "{bad}");
    assert_eq!(bad["play"], true, "{bad}");
    let good = read(b, "s_good");
    assert_eq!(
        good["stale"],
        serde_json::json!([false, false, false]),
        "{good}"
    );
    assert_eq!(good["play"], false, "{good}");
}

/// The velocity plane's map as the drag steps read it: origin, scale, step, the frame's w; the
/// typed velocities; the case's JSON.
fn plane_read(r: &Value) -> (f64, f64, f64, [f64; 2], Value) {
    let m = &r["map"];
    let (s, step, w) = (
        m[2].as_f64().unwrap(),
        m[3].as_f64().unwrap(),
        m[4].as_f64().unwrap(),
    );
    let v = [
        r["v"][0].as_str().unwrap().parse::<f64>().unwrap(),
        r["v"][1].as_str().unwrap().parse::<f64>().unwrap(),
    ];
    (s, step, w, v, r["state"].clone())
}

#[test]
fn browser_dragging_in_puts_it_under_the_pointer_in_the_lab_and_com_frames() {
    let Some(b) = browser() else { return };
    // Case A, M = diag(4, 1), V = (60, 10), lab: IN dragged 30 picture units right and 20 down
    // at s units per velocity unit goes to the pointer, (60 + 30/s, 10 - 20/s), to the step
    // (half a step, and a picture unit for the mouse's whole pixels).
    let (s, step, w, _, _) = plane_read(read(b, "c_drag_lab_map"));
    assert_eq!(w, 0.0);
    let (_, _, _, v, state) = plane_read(read(b, "c_drag_lab"));
    let tol = step / 2.0 + 1.0 / s;
    assert!((v[0] - (60.0 + 30.0 / s)).abs() <= tol, "{v:?} s = {s}");
    assert!((v[1] - (10.0 - 20.0 / s)).abs() <= tol, "{v:?} s = {s}");
    assert_eq!(pair(&state["in"]), v);
    // COM (w = V_COM = (4 60 + 10) / 5 = 50): IN = (10, -40), on the zero-momentum line
    // 4 u1 + u2 = 0. Dragged along that line, 10 right and 40 down (picture units), the pointer
    // is over (10 + 10/s, -40 - 40/s); the case keeps w = 50 and the relative velocity
    // d = u1 - u2 = 50 + 50/s, so V = (50 + d/5, 50 - 4d/5) = (60 + 10/s, 10 - 40/s) (was: w
    // added again at every move, IN running off: a 50 px drag gave V = (184, 107)).
    let (s, step, w, _, state) = plane_read(read(b, "c_drag_com_map"));
    assert_eq!(w, 50.0);
    assert_eq!(pair(&state["in"]), [10.0, -40.0]);
    let (_, _, w2, v, state) = plane_read(read(b, "c_drag_com"));
    let tol = step / 2.0 + 1.0 / s;
    assert_eq!(state["frame"]["name"], "com", "{state}");
    assert!((v[0] - (60.0 + 10.0 / s)).abs() <= tol, "{v:?} s = {s}");
    assert!((v[1] - (10.0 - 40.0 / s)).abs() <= tol, "{v:?} s = {s}");
    // The frame's velocity stays where it was, to the step: (4 V1 + V2) / 5.
    assert!((w2 - 50.0).abs() <= tol, "w = {w2}");
    // IN on screen, from the typed values: (d/5, -4d/5) with d = V1 - V2 (exact: short
    // decimals times 1/5 and 4/5 round once each, as the core's does; 2 ulps allowed).
    let d = v[0] - v[1];
    let u = pair(&state["in"]);
    for (got, want) in u.iter().zip([d / 5.0, -4.0 * d / 5.0]) {
        assert!(
            (got - want).abs() <= 2.0 * f64::EPSILON * want.abs(),
            "{u:?} d = {d}"
        );
    }
    // Under the pointer: (10 + 10/s, -40 - 40/s), within the step's reach on screen.
    assert!((u[0] - (10.0 + 10.0 / s)).abs() <= tol, "{u:?}");
    assert!((u[1] - (-40.0 - 40.0 / s)).abs() <= 4.0 * tol, "{u:?}");
    // A drag off the line (50 right) moves d by 50/s, along the 45-degree line to the line:
    // IN moves (10/s, -40/s), not away from the pointer.
    let (_, _, w3, v3, state3) = plane_read(read(b, "c_drag_com_off"));
    let d3 = v3[0] - v3[1];
    assert!(
        (d3 - (d + 50.0 / s)).abs() <= 2.0 * tol,
        "d = {d} -> {d3}, s = {s}"
    );
    assert!((w3 - 50.0).abs() <= 2.0 * tol, "w = {w3}");
    let u3 = pair(&state3["in"]);
    assert!(
        (u3[0] - (u[0] + 10.0 / s)).abs() <= 2.0 * tol,
        "{u:?} -> {u3:?}"
    );
}
