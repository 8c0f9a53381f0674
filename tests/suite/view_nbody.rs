//! `collide view`'s panel of up to five pucks (issue 43, section 2): N bodies that stick or
//! explode, and touching balls under Newton's law at every contact at once. The library's
//! answers (what the WebAssembly core answers in the page) hold `collide solve --format json`
//! byte for byte for 10 seeded random cases; in headless Chromium (`view_nbody.py`, one page
//! load) the page's `#nball-state` does too, the cue ball onto two touching balls reads the
//! published -0.76 and 2.63 from the panel, the pucks move along v' after the impact, a bad
//! input greys the panel, and five balls fit a phone (their inputs and values whole); a slow
//! puck's arrow starts at its disk's edge; P's name clears the axes'.

use std::sync::OnceLock;

use serde_json::{Value, json};

use super::view::{ask, run_shown, scratch};
use super::view_layout::drive_with;
use super::view_rigid::{dec, f, read, seeded};

/// 10 cases from a fixed seed (xorshift), N = 3, 4, 5 in turn, a stick, an explosion and
/// touching balls in turn. Touching balls are a chain: each ball touches the one before it
/// along (1,0), (0.8,0.6) or (0.8,-0.6), its centre `R_a + R_b` from it in exact hundredths
/// (radii 0.5, 1 or 1.5), so every step turns at most 74 degrees and no two balls overlap
/// (two steps of lengths a, b at most 74 degrees apart span more than the radii they join);
/// the cue ball moves into the chain, the others are at rest or drift.
fn cases() -> Vec<Value> {
    let mut next = seeded(0x2545_f491_4f6c_dd1d);
    let vector = |x: i64, y: i64| format!("({},{})", dec(x), dec(y));
    (0..10)
        .map(|k| {
            let n = 3 + k % 3;
            let masses: Vec<String> = (0..n).map(|_| dec(10 + 10 * next(50))).collect();
            match k % 3 {
                0 => json!({
                    "mode": "stick", "masses": masses,
                    "velocities": (0..n).map(|_| vector(10 * next(81) - 400, 10 * next(81) - 400))
                        .collect::<Vec<_>>(),
                }),
                1 => {
                    // From one common velocity, all but the last given after.
                    let v = vector(10 * next(41) - 200, 10 * next(41) - 200);
                    let mut fin: Vec<String> = (1..n)
                        .map(|_| vector(10 * next(81) - 400, 10 * next(81) - 400))
                        .collect();
                    fin.push("?".into());
                    json!({"mode": "explode", "masses": masses, "velocities": vec![v; n as usize],
                           "fin": fin})
                }
                _ => {
                    let radii: Vec<i64> = (0..n).map(|_| 50 * (1 + next(3))).collect();
                    let (mut x, mut y) = (0i64, 0i64);
                    let mut positions = vec![vector(0, 0)];
                    for i in 1..n as usize {
                        let d = radii[i - 1] + radii[i];
                        let (dx, dy) = [(10, 0), (8, 6), (8, -6)][next(3) as usize];
                        x += d * dx / 10;
                        y += d * dy / 10;
                        positions.push(vector(x, y));
                    }
                    let mut velocities = vec![vector(100 + 10 * next(30), 10 * next(11) - 50)];
                    velocities.extend((1..n).map(|_| {
                        if next(2) == 0 {
                            "0".to_string()
                        } else {
                            vector(10 * next(11) - 50, 10 * next(11) - 50)
                        }
                    }));
                    let e = ["elastic", "0", "1/2", "0.9"][next(4) as usize];
                    json!({
                        "mode": "contacts", "masses": masses, "velocities": velocities,
                        "positions": positions,
                        "radii": radii.iter().map(|r| dec(*r)).collect::<Vec<_>>(),
                        "e": e,
                    })
                }
            }
        })
        .collect()
}

fn request(case: &Value) -> Value {
    let mut r = case.clone();
    r["op"] = "nbody".into();
    r
}

#[test]
fn nbody_answers_are_solve_json_byte_for_byte() {
    let cases = cases();
    for mode in ["stick", "explode", "contacts"] {
        assert!(cases.iter().any(|c| c["mode"] == mode), "no {mode} case");
    }
    for case in cases {
        let a = ask(request(&case));
        assert_eq!(a["ok"], true, "{case}: {a}");
        let command = a["command"].as_str().unwrap();
        assert_eq!(
            a["state"].as_str().unwrap(),
            run_shown(command),
            "{command}"
        );
    }
}

#[test]
fn nbody_momentum_arrows_add_up_to_p() {
    // The three-piece explosion of docs/plane.md: 1, 2, 3 kg from rest, v1' = (2,0), v2' =
    // (0,1), so v3' = -(2, 2)/3 and the momenta (2,0) + (0,2) + (-2,-2) = 0 = P.
    let a = ask(
        json!({"op": "nbody", "mode": "explode", "masses": ["1 kg", "2 kg", "3 kg"],
                       "velocities": ["0", "0", "0"], "fin": ["(2,0) m/s", "(0,1) m/s", "?"]}),
    );
    assert_eq!(a["ok"], true, "{a}");
    let p = &a["picture"];
    assert_eq!(
        p["momenta"]["p_fin"],
        json!([[2.0, 0.0], [0.0, 2.0], [-2.0, -2.0]])
    );
    assert_eq!(p["momenta"]["p_total"], json!([0.0, 0.0]));
    // A puck of 1.5e308 at 1.5 has a momentum of 2.25e308, beyond binary64, while its energy,
    // 1.6875e308, is not (collide solve prints the case): no momentum is drawn (no infinity).
    let huge = ask(
        json!({"op": "nbody", "mode": "stick", "masses": ["1.5e308", "1"],
                          "velocities": ["(1.5,0)", "0"]}),
    );
    assert_eq!(huge["ok"], true, "{huge}");
    assert_eq!(huge["picture"]["momenta"], Value::Null, "{huge}");
    assert_eq!(p["velocity_unit"], "m/s");
    assert_eq!(
        a["command"],
        "collide solve -m '1 kg,2 kg,3 kg' -v 0,0,0 --fin '(2,0) m/s,(0,1) m/s,?'"
    );
    // Six pucks are more than the panel takes; a velocity that is two names its field.
    let six = ask(
        json!({"op": "nbody", "mode": "stick", "masses": vec!["1"; 6],
                         "velocities": vec!["(1,0)"; 6]}),
    );
    assert_eq!(
        (six["ok"].clone(), six["field"].clone()),
        (json!(false), json!("count"))
    );
    let two = ask(
        json!({"op": "nbody", "mode": "stick", "masses": ["1", "1", "1"],
                         "velocities": ["(1,0)", "(1,0),(2,0)", "0"]}),
    );
    assert_eq!(two["field"], "v2", "{two}");
}

/// What the browser did, once for all the browser tests.
fn run() -> &'static Value {
    static RUN: OnceLock<Value> = OnceLock::new();
    RUN.get_or_init(|| {
        let file = scratch("nbody").join("cases.json");
        std::fs::write(&file, serde_json::to_string(&cases()).unwrap()).unwrap();
        drive_with("nbody", "view_nbody.py", &[file.to_str().unwrap()])
    })
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_nbody_state_is_the_cli_json_for_10_random_cases() {
    let got = run()["cases"].as_array().unwrap();
    let cases = cases();
    assert_eq!(got.len(), cases.len());
    for (case, page) in cases.iter().zip(got) {
        assert_eq!(page["error"], Value::Null, "{case}: {page}");
        assert_eq!(page["bad"], false, "NaN or Infinity drawn: {case}");
        let command = page["command"].as_str().unwrap();
        assert_eq!(command, ask(request(case))["command"], "{case}");
        assert_eq!(
            page["state"].as_str().unwrap(),
            run_shown(command),
            "{command}"
        );
    }
    assert_eq!(run()["console"], json!([]), "console: {}", run()["console"]);
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_nbody_cue_ball_reads_the_published_answer() {
    // Three equal balls, radius 1, the cue ball at 3.8 onto two touching it at +-30 degrees
    // (centres (sqrt 3, +-1)), elastic. Contact normals n2 = (c, s), n3 = (c, -s), c = cos 30 =
    // sqrt(3)/2, s = 1/2; both push: Newton's law w' = -w at each with A = J M^-1 J^T, A_kk = 2,
    // A_23 = n2.n3 = c^2 - s^2 = 1/2, so 2.5 P = 2 * 3.8 c and P = 3.04 c = 1.52 sqrt 3 =
    // 2.63271723; the cue ball keeps 3.8 - 2 P c = 3.8 - 6.08 * 3/4 = -0.76, the others leave at
    // P = 2.633 at +-30 degrees (the published -0.76 and 2.6 m/s). The panel types sqrt 3 as
    // 1.732 (3e-5 short), which moves the answer by less than 1e-4: the tolerance.
    let cue = &run()["cue"];
    let rows = cue["tables"]["Velocities"].as_array().unwrap();
    let pair = |text: &str| -> [f64; 2] {
        let inner = text.trim_start_matches('(').trim_end_matches(')');
        let (a, b) = inner.split_once(", ").unwrap();
        [read(a), read(b)]
    };
    let fin1 = pair(rows[0][2].as_str().unwrap());
    assert!((fin1[0] + 0.76).abs() < 1e-4 && fin1[1] == 0.0, "{fin1:?}");
    let p = 1.52 * 3f64.sqrt();
    for (row, angle) in [(1, 30.0), (2, -30.0)] {
        let polar = rows[row][3].as_str().unwrap();
        let (speed, at) = polar.split_once(" @ ").unwrap();
        assert!((read(speed) - p).abs() < 1e-4, "{polar}");
        assert!(
            (read(at.trim_end_matches('°')) - angle).abs() < 1e-2,
            "{polar}"
        );
    }
    let read_back = &cue["read"];
    assert_eq!(
        read_back["state"].as_str().unwrap(),
        run_shown(read_back["command"].as_str().unwrap())
    );
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_nbody_pucks_move_along_their_paths_and_bad_input_greys() {
    let r = run();
    // One step (a twentieth of the run, 0.1 in t) after the impact, the cue ball has moved by
    // tau * 0.1 * v1' in the world, s times that on screen (y up in the world, down on screen).
    let m = &r["motion"];
    let (map, fin) = (&m["map"], &m["fin"]);
    let step = f(&m["after"]["t"]) - f(&m["impact"]["t"]);
    assert!((step - 0.1).abs() < 1e-12, "{m}");
    let k = f(&map["s"]) * f(&map["tau"]) * step;
    let dx = f(&m["after"]["x"]) - f(&m["impact"]["x"]);
    let dy = f(&m["after"]["y"]) - f(&m["impact"]["y"]);
    // Drawn to 0.01 of a unit (the SVG's rounding).
    assert!((dx - k * f(&fin[0])).abs() <= 0.011, "{m}");
    assert!((dy + k * f(&fin[1])).abs() <= 0.011, "{m}");
    assert!(dx < 0.0, "the cue ball bounces back: {m}");
    // Play ran the time on.
    assert!(
        f(&r["played"]["t"]) != f(&m["after"]["t"]),
        "{}",
        r["played"]
    );
    let bad = &r["bad"];
    assert!(
        bad["read"]["error"].as_str().unwrap().contains("mass"),
        "{bad}"
    );
    assert_eq!(bad["stale"], true, "{bad}");
    assert_eq!(bad["invalid"], "true", "{bad}");
    assert_eq!(bad["read"]["state"], "", "{bad}");
    let phone = &r["phone"];
    assert!(f(&phone["page"]) <= f(&phone["window"]), "{phone}");
    assert_eq!(phone["bad"], false, "{phone}");
    assert_eq!(r["console"], json!([]), "console: {}", r["console"]);
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_nbody_slow_arrow_from_the_edge_p_clear_of_px_and_a_phone_shows_whole_values() {
    let r = run();
    // The cue ball after the impact: v1' = (-0.76, 0) against the fastest speed 3.8, so its
    // arrow is 90 * 0.76 / 3.8 = 18 units long (the one scale k = 90 / 3.8), shorter than the
    // puck's radius (s units for radius 1, about 47): it starts at the disk's edge, r from the
    // centre along v1', and keeps its length k |v1'| (to the SVG's 0.01 rounding).
    let a = &r["arrow"];
    let (k, radius) = (f(&a["map"]["k"]), f(&a["r"]));
    let v = [f(&a["fin"][0]), f(&a["fin"][1])];
    assert!((v[0] + 0.76).abs() < 1e-4 && v[1] == 0.0, "{a}");
    assert!(
        k * v[0].hypot(v[1]) < radius,
        "the arrow would be inside the disk: {a}"
    );
    let (c, from, tip) = (&a["centre"], &a["from"], &a["tip"]);
    let unit = [v[0] / v[0].hypot(v[1]), -v[1] / v[0].hypot(v[1])]; // y down on screen
    for i in 0..2 {
        let want_from = f(&c[i]) + radius * unit[i];
        assert!((f(&from[i]) - want_from).abs() <= 0.011, "{a}");
        let sign = if i == 0 { 1.0 } else { -1.0 };
        let want_tip = want_from + sign * k * v[i];
        assert!((f(&tip[i]) - want_tip).abs() <= 0.011, "{a}");
    }
    // The momenta chart's names (P at the tip of P = (3.8, 0), the axes' px and py): no two
    // boxes overlap.
    let labels = r["labels"].as_array().unwrap();
    assert!(labels.iter().any(|l| l[0] == "P"), "{labels:?}");
    for (i, p) in labels.iter().enumerate() {
        for q in &labels[i + 1..] {
            let apart = f(&p[1]) + f(&p[3]) <= f(&q[1])
                || f(&q[1]) + f(&q[3]) <= f(&p[1])
                || f(&p[2]) + f(&p[4]) <= f(&q[2])
                || f(&q[2]) + f(&q[4]) <= f(&p[2]);
            assert!(apart, "{p} covers {q}");
        }
    }
    // On a 390 px phone (five balls, then the cue ball's preset): every input shows its value
    // whole, and the table of values fits its box (no sideways scroll inside it).
    for fit in r["phone"]["fit"].as_array().unwrap() {
        for input in fit["inputs"].as_array().unwrap() {
            assert!(f(&input[2]) <= f(&input[3]), "cut: {input}");
        }
        let n = &fit["numbers"];
        assert!(f(&n[0]) <= f(&n[1]), "the values scroll sideways: {n}");
    }
}
