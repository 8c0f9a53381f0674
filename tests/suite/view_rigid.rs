//! `collide view`'s rigid panel (issue 43, section 3): a ball hits a rod or a door (free or on a
//! pivot), or a spinning ball meets a rough floor. The library's answers (what the WebAssembly
//! core answers in the page) hold `collide solve --format json` byte for byte; in headless
//! Chromium (`view_rigid.py`, one run at 1280x800 and 390x844) the page's `#rigid-state` does
//! too for 20 random cases, a drag of the hit point moves the state as the command line says, the
//! panel's numbers are those of a case derived by hand, an extreme case draws finite and a bad
//! input greys the panel with the module's message.

use std::sync::OnceLock;

use serde_json::{Value, json};

use super::view::{ask, run_shown, scratch};
use super::view_layout::drive_with;

/// `n` hundredths as a decimal (`-150` is `-1.50`).
pub(crate) fn dec(n: i64) -> String {
    let sign = if n < 0 { "-" } else { "" };
    format!("{sign}{}.{:02}", n.abs() / 100, n.abs() % 100)
}

/// Numbers from `0` to `n - 1` drawn from `seed` (xorshift): the random cases' generator.
pub(crate) fn seeded(mut seed: u64) -> impl FnMut(u64) -> i64 {
    move |n: u64| -> i64 {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % n) as i64
    }
}

/// 20 rigid cases from a fixed seed (xorshift): a ball (a point, or a sphere on a floor) at a rod
/// of random mass and length, free or on a pivot at its end or centre, hit at a random point
/// (never at a centre pivot, where nothing turns it), with e, friction, spin and Garwin's beta
/// drawn among typical values; every fourth a sphere sliding onto a floor.
fn cases() -> Vec<Value> {
    let mut next = seeded(0x9e37_79b9_7f4a_7c15);
    let es = ["elastic", "1", "0", "1/2", "2/3", "0.9"];
    (0..20)
        .map(|k| {
            let m1 = dec(10 + 10 * next(50));
            let e = es[next(es.len() as u64) as usize];
            if k % 4 == 3 {
                let rough = next(3);
                json!({
                    "m1": m1, "m2": "floor",
                    "v1": format!("({},{})", dec(100 * next(11) - 500), dec(-50 - 10 * next(45))),
                    "ball": format!("sphere {}", dec(10 + 10 * next(20))),
                    "spin": if next(2) == 0 { String::new() } else { dec(100 * next(41) - 2000) },
                    "e": e,
                    "friction": match rough { 0 => "0.1", 1 => "1", _ => "" },
                    "beta": if rough == 2 { "1" } else { "" },
                })
            } else {
                let length = 20 + 10 * next(29);
                let pivot = ["", "end", "centre"][next(3) as usize];
                let hit = match pivot {
                    "end" => 1 + next(length as u64),
                    _ => {
                        let h = 1 + next((length / 2) as u64);
                        if next(2) == 0 { h } else { -h }
                    }
                };
                json!({
                    "m1": m1, "m2": dec(10 + 10 * next(80)),
                    "v1": if next(2) == 0 { dec(100 + 10 * next(90)) }
                          else { format!("({},{})", dec(100 + 10 * next(40)), dec(10 * next(41) - 200)) },
                    "target": format!("rod {}", dec(length)),
                    "pivot": pivot,
                    "hit_at": dec(hit),
                    "e": e,
                    "friction": if next(3) == 0 { "0.3" } else { "" },
                })
            }
        })
        .collect()
}

/// The page's request of a case (every field, empty when not given).
fn request(case: &Value) -> Value {
    let mut r = json!({"op": "rigid"});
    for f in [
        "m1", "m2", "v1", "target", "pivot", "hit_at", "ball", "spin", "e", "friction", "beta",
    ] {
        r[f] = case[f].as_str().unwrap_or_default().into();
    }
    r
}

#[test]
fn rigid_answers_are_solve_json_byte_for_byte() {
    for case in cases() {
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
fn a_bad_rigid_input_names_its_field() {
    // The rod reaches 1 from its centre: a hit at 5 is off it (the command line's message).
    let a = ask(
        json!({"op": "rigid", "m1": "1", "m2": "4", "v1": "3", "target": "rod 2",
                      "hit_at": "5"}),
    );
    assert_eq!(a["ok"], false, "{a}");
    assert_eq!(a["field"], "hit_at", "{a}");
    assert!(
        a["error"].as_str().unwrap().contains("off the target"),
        "{a}"
    );
    let a = ask(json!({"op": "rigid", "m1": "-1", "m2": "4", "v1": "3", "target": "rod 2"}));
    assert_eq!(
        (a["ok"].clone(), a["field"].clone()),
        (json!(false), json!("m1")),
        "{a}"
    );
}

/// What the browser did, once for all the browser tests.
fn run() -> &'static Value {
    static RUN: OnceLock<Value> = OnceLock::new();
    RUN.get_or_init(|| {
        let file = scratch("rigid").join("cases.json");
        std::fs::write(&file, serde_json::to_string(&cases()).unwrap()).unwrap();
        drive_with("rigid", "view_rigid.py", &[file.to_str().unwrap()])
    })
}

pub(crate) fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// A number as the panel prints it (a minus sign for `-`).
pub(crate) fn read(text: &str) -> f64 {
    text.replace('\u{2212}', "-")
        .parse()
        .unwrap_or_else(|_| panic!("not a number: {text:?}"))
}

/// A pair `(x, y)` as the panel prints it.
fn read_pair(text: &str) -> [f64; 2] {
    let inner = text.trim_start_matches('(').trim_end_matches(')');
    let (a, b) = inner.split_once(", ").unwrap_or_else(|| panic!("{text:?}"));
    [read(a), read(b)]
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_rigid_state_is_the_cli_json_for_20_random_cases() {
    let got = run()["cases"].as_array().unwrap();
    let cases = cases();
    assert_eq!(got.len(), cases.len());
    for (case, page) in cases.iter().zip(got) {
        assert_eq!(page["error"], Value::Null, "{case}: {page}");
        let command = page["command"].as_str().unwrap();
        assert_eq!(
            page["state"].as_str().unwrap(),
            run_shown(command),
            "{command}"
        );
        // The command shown is the one of the case typed.
        assert_eq!(command, ask(request(case))["command"], "{case}");
    }
    assert_eq!(run()["console"], json!([]), "console: {}", run()["console"]);
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_rigid_hit_point_drag_moves_the_state_as_the_cli_says() {
    let hit = &run()["hit"];
    assert_eq!(hit["before"]["hit_at"], "end");
    // Dragged 60 CSS pixels down from the top end (at 1 from the centre of the rod of length
    // 2): the hit point goes to 1 - 60 (viewBox units per pixel) / (screen units per unit of
    // length), snapped to the step, a power of 10 at or above one screen unit.
    let s = f(&hit["scale_before"]);
    let down = f(&hit["dy_screen"]) * f(&hit["drop"]["units"]) / s;
    let step = 10f64.powf((1.0 / s).log10().ceil());
    let at = read(hit["after"]["hit_at"].as_str().unwrap());
    assert!(
        (at - (1.0 - down)).abs() <= step,
        "hit at {at}, expected {} within {step}",
        1.0 - down
    );
    assert!(at < 1.0 && at > -1.0, "{at}");
    let command = hit["after"]["command"].as_str().unwrap();
    assert!(
        command.contains(&format!(
            "--hit-at {}",
            hit["after"]["hit_at"].as_str().unwrap()
        )),
        "{command}"
    );
    assert_ne!(hit["after"]["state"], hit["before"]["state"]);
    assert_eq!(hit["after"]["state"].as_str().unwrap(), run_shown(command));
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_rigid_panel_shows_the_hand_derived_rod() {
    // A point mass m = 1 at v = 3 hits a free uniform rod (M = 2, L = 2, I = M L^2/12 = 2/3)
    // perpendicularly at its end, r = L/2 = 1 from its centre, e = 1. The rod's effective mass
    // there is 1/(1/M + r^2/I) = 1/(1/2 + 3/2) = 1/2 (M/4), so along the normal it is the rail's
    // elastic collision of 1 and 1/2: COM = (1 * 3)/(3/2) = 2, FIN = 2 COM - IN = (1, 4), and
    // the impulse P = m (3 - 1) = 2. The rod's centre leaves at P/M = 1 and it turns at
    // omega = -P r / I = -3 (clockwise: hit on its top end from the left); its end moves at
    // 1 + 3 * 1 = 4, as FIN says. Energy: 1/2 * 9 = 1/2 * 1 + 1/2 * 2 * 1 + 1/2 * 2/3 * 9.
    let hand = &run()["hand"];
    let t = &hand["tables"];
    let row = |table: &str, name: &str| -> Vec<String> {
        let (_, rows) = t
            .as_object()
            .unwrap()
            .iter()
            .find(|(k, _)| k.starts_with(table))
            .unwrap_or_else(|| panic!("no table {table} in {t}"));
        rows.as_array()
            .unwrap()
            .iter()
            .find(|r| r[0] == name)
            .unwrap_or_else(|| panic!("no row {name} in {rows}"))
            .as_array()
            .unwrap()
            .iter()
            .skip(1)
            .map(|c| c.as_str().unwrap().to_string())
            .collect()
    };
    // Exact small integers, printed to 7 digits: read back exactly.
    assert_eq!(read_pair(&row("Impulse", "P")[0]), [2.0, 0.0]);
    assert_eq!(read(&row("Impulse", "Pn")[0]), 2.0);
    let v1 = row("Velocities", "v1");
    assert_eq!(
        (read_pair(&v1[0]), read_pair(&v1[1])),
        ([3.0, 0.0], [1.0, 0.0])
    );
    let v2 = row("Velocities", "v2");
    assert_eq!(
        (read_pair(&v2[0]), read_pair(&v2[1])),
        ([0.0, 0.0], [1.0, 0.0])
    );
    let w2 = row("Velocities", "ω2");
    assert_eq!((read(&w2[0]), read(&w2[1])), (0.0, -3.0));
    let along = |name: &str| -> Vec<f64> { row("Along", name).iter().map(|c| read(c)).collect() };
    assert_eq!(along("meff"), [1.0, 0.5]);
    assert_eq!(along("IN"), [3.0, 0.0]);
    assert_eq!(along("COM"), [2.0, 2.0]);
    assert_eq!(along("FIN"), [1.0, 4.0]);
    assert_eq!(along("e along n"), [1.0]);
    assert!(
        hand["contact"]
            .as_str()
            .unwrap()
            .starts_with("contact smooth")
    );
    // And the state the panel holds says so too, as the command line prints it.
    let state: Value = serde_json::from_str(hand["read"]["state"].as_str().unwrap()).unwrap();
    assert_eq!(state["fin"][1]["omega"], -3.0);
    assert_eq!(
        hand["read"]["state"].as_str().unwrap(),
        run_shown(hand["read"]["command"].as_str().unwrap())
    );
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_rigid_floor_names_the_contact() {
    // docs/rigid.md's sphere (m = 1, R = 1, I = 2/5) falling at 1 onto a floor with mu = 1 and
    // sliding at 7, here spinning at 2 counterclockwise: its contact point slips at
    // 7 + R omega = 9, and a tangential impulse P_t changes that slip by 7/2 P_t / m, so it
    // would stop only at P_t = 18/7, above mu P_n = 2 (P_n = (1 + e) m v_n = 2): it slips
    // throughout, v' = 7 - 2 = 5 and omega' = 2 - R P_t / I = -3.
    let floor = &run()["floor"];
    let t = &floor["tables"]["Velocities and spins"];
    assert_eq!(t[0][2], "(5, 1)", "{t}");
    assert_eq!(t[1][2], "\u{2212}3", "{t}");
    assert!(
        floor["contact"]
            .as_str()
            .unwrap()
            .starts_with("contact slip"),
        "{floor}"
    );
    assert_eq!(
        floor["read"]["state"].as_str().unwrap(),
        run_shown(floor["read"]["command"].as_str().unwrap())
    );
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_rigid_arrows_start_at_the_disks_edge() {
    // The sphere on the floor above: v1 = (7, -1) before and (5, 1) after (derived there). The
    // arrows share one scale, k = 120 / max |v| = 120 / sqrt(50) viewBox units per velocity
    // unit, and start at the disk's edge along their velocity (screen y down: the direction
    // (vx, -vy) / |v|): from = centre + r u, tip = from + k v. Coordinates are drawn to 0.01.
    let a = &run()["floor"]["arrows"];
    let at = |v: &Value| [f(&v[0]), f(&v[1])];
    let (c, r) = (at(&a["centre"]), f(&a["r"]));
    assert!(r > 10.0, "the ball is drawn as a disk: {a}");
    let k = 120.0 / 50f64.sqrt();
    for (name, v) in [("v1", [7.0, -1.0]), ("v1_fin", [5.0, 1.0])] {
        let speed = f64::hypot(v[0], v[1]);
        let u = [v[0] / speed, -v[1] / speed];
        let (from, tip) = (at(&a[name]["from"]), at(&a[name]["tip"]));
        for j in 0..2 {
            let edge = c[j] + r * u[j];
            assert!(
                (from[j] - edge).abs() <= 0.02,
                "{name} starts at {from:?}, not at the edge {edge}: {a}"
            );
            let end = from[j] + k * speed * u[j];
            assert!(
                (tip[j] - end).abs() <= 0.03,
                "{name} ends at {tip:?}, not {end}: {a}"
            );
        }
    }
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_rigid_extreme_case_draws_finite_and_bad_input_greys() {
    let r = run();
    let x = &r["extreme"];
    assert_eq!(x["read"]["error"], Value::Null, "{x}");
    assert_eq!(
        x["bad"], false,
        "NaN or Infinity in the rigid pictures: {x}"
    );
    assert_eq!(
        x["read"]["state"].as_str().unwrap(),
        run_shown(x["read"]["command"].as_str().unwrap())
    );
    let bad = &r["bad"];
    assert!(
        bad["read"]["error"]
            .as_str()
            .unwrap()
            .contains("off the target"),
        "{bad}"
    );
    assert_eq!(bad["stale"], true, "{bad}");
    assert_eq!(bad["invalid"], "true", "{bad}");
    assert_eq!(bad["read"]["state"], "", "{bad}");
    // On a phone the panel fits: no sideways scrolling.
    let phone = &r["phone"];
    assert!(f(&phone["page"]) <= f(&phone["window"]), "{phone}");
    assert_eq!(r["console"], json!([]), "console: {}", r["console"]);
}
