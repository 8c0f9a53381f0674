//! `collide view`'s plane panel (issue 29, the plane of issue 25): two pucks with a line of
//! impact. The page's answers against `collide solve --format json` in the plane, the command
//! line and scene it gives back, FIN against the impulse formula computed here, the refusals, and
//! the panel in a real browser (driven once with the rest of the page by `view.rs`).

use serde_json::{Value, json};

use super::view::{
    ask, assert_seen_is_solve, browser, cli_json, drag_timings, run_scene, run_shown, scratch,
};
use crate::common::{REL, assert_close, run, stdout};

/// The plane's cases of the brief: equal masses, elastic, target at rest (the 90-degree rule);
/// the car and the van that lock together (e = 0, no line of impact); a 30-degree normal with a
/// heavier projectile (the largest deflection); a huge mass ratio; e = 2/3 (lecture Fig. 2.3's
/// normal parts); disks with an impact parameter; a frame, the time reverse and exact fractions;
/// units; angles of no special value.
pub fn plane_cases() -> Vec<Value> {
    vec![
        json!({"m1": "1", "m2": "1", "v1": "(4,0)", "v2": "(0,0)", "normal": "30deg"}),
        json!({"m1": "1500 kg", "m2": "2500 kg", "v1": "25 m/s @ E", "v2": "20 m/s @ N", "e": "0"}),
        json!({"m1": "2", "m2": "1", "v1": "(1,0)", "v2": "(0,0)", "normal": "30deg"}),
        json!({"m1": "1e12", "m2": "1", "v1": "(1,0)", "v2": "(0,-1)", "normal": "(1,1)", "e": "0.9"}),
        json!({"m1": "6", "m2": "1", "v1": "(3,2)", "v2": "(-4,-1)", "normal": "0deg", "e": "2/3"}),
        json!({"m1": "1", "m2": "1", "v1": "(1,0)", "v2": "(0,0)", "r1": "1", "r2": "1", "b": "1"}),
        json!({"m1": "1", "m2": "2", "v1": "(4,1)", "v2": "(-1,2)", "normal": "(1,1)", "e": "1/2",
               "frame": "com", "reverse": true, "exact": true}),
        json!({"m1": "0.5 kg", "m2": "0.5 kg", "v1": "2 m/s @ 0deg", "v2": "0", "normal": "N60E"}),
        // Angles whose cosines, sines and atan2 come from the libm (not 0, 30, 45 degrees...),
        // where the platforms' own libms differ in the last bit.
        json!({"m1": "5.5", "m2": "3", "v1": "6 @ 37deg", "v2": "(2.34,3.98)", "normal": "34deg", "e": "0.9"}),
    ]
}

/// `collide solve` flags of a plane case as the page holds it.
fn solve_args(case: &Value) -> Vec<String> {
    let s = |k: &str| case[k].as_str().unwrap_or_default().to_string();
    let mut args = vec![
        "solve".to_string(),
        "-m".into(),
        format!("{},{}", s("m1"), s("m2")),
        "-v".into(),
        format!("{},{}", s("v1"), s("v2")),
    ];
    if !s("normal").is_empty() {
        args.extend(["--normal".into(), s("normal")]);
    }
    if !s("r1").is_empty() {
        args.extend([
            "--radii".into(),
            format!("{},{}", s("r1"), s("r2")),
            "--impact-parameter".into(),
            s("b"),
        ]);
    }
    if !s("e").is_empty() {
        args.extend(["-e".into(), s("e")]);
    }
    if !s("frame").is_empty() {
        args.extend(["--frame".into(), s("frame")]);
    }
    if case["reverse"] == true {
        args.push("--reverse".into());
    }
    if case["exact"] == true {
        args.push("--exact".into());
    }
    args.extend(["--format".into(), "json".into()]);
    args
}

fn plane_request(case: &Value) -> Value {
    let mut r = case.clone();
    r["op"] = "plane".into();
    r
}

/// FIN by the impulse formula (physics.md section 7), here in binary64:
/// `v1' = v1 - (1 + e) mu (n.(v1 - v2)) / (n.n) / m1 n`, `v2' = v2 + ... / m2 n`.
fn impulse_fin(m: [f64; 2], v: [[f64; 2]; 2], n: [f64; 2], e: f64) -> [[f64; 2]; 2] {
    let mu = m[0] * m[1] / (m[0] + m[1]);
    let along = n[0] * (v[0][0] - v[1][0]) + n[1] * (v[0][1] - v[1][1]);
    let j = (1.0 + e) * mu * along / (n[0] * n[0] + n[1] * n[1]);
    [
        [v[0][0] - j / m[0] * n[0], v[0][1] - j / m[0] * n[1]],
        [v[1][0] + j / m[1] * n[0], v[1][1] + j / m[1] * n[1]],
    ]
}

fn vector(v: &Value) -> [f64; 2] {
    [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
}

fn vectors(v: &Value) -> [[f64; 2]; 2] {
    [vector(&v[0]), vector(&v[1])]
}

/// `|a - b|` within `tol` times the largest velocity of the case, component by component.
#[track_caller]
fn assert_near(a: [[f64; 2]; 2], b: [[f64; 2]; 2], scale: f64, tol: f64, what: &str) {
    for i in 0..2 {
        for k in 0..2 {
            assert!(
                (a[i][k] - b[i][k]).abs() <= tol * scale,
                "{what}: {a:?} against {b:?}"
            );
        }
    }
}

#[test]
fn plane_answers_equal_solve_json_byte_for_byte() {
    for case in plane_cases() {
        let a = ask(plane_request(&case));
        assert_eq!(a["ok"], true, "{case}: {a}");
        assert_eq!(
            a["state"].as_str().unwrap(),
            cli_json(&solve_args(&case)),
            "{case}"
        );
    }
}

#[test]
fn plane_command_and_scene_shown_reproduce_the_state() {
    for case in plane_cases() {
        let a = ask(plane_request(&case));
        let state = a["state"].as_str().unwrap();
        let command = a["command"].as_str().unwrap();
        assert_eq!(run_shown(command), state, "{command}");
        let report = run_scene(a["scene"].as_str().unwrap(), "plane");
        let expected: Value = serde_json::from_str(state).unwrap();
        assert_eq!(report, expected, "{}", a["scene"]);
    }
}

#[test]
fn plane_fin_follows_the_impulse_formula_and_the_closed_forms() {
    let fin = |case: Value| {
        let a = ask(plane_request(&case));
        let s: Value = serde_json::from_str(a["state"].as_str().unwrap()).unwrap();
        (s, a["picture"].clone())
    };
    // Equal masses, elastic, target at rest, n at 30 degrees: body 2 leaves along n with
    // v cos 30 = 2 sqrt(3), body 1 across it with v sin 30 = 2, at right angles.
    let (s, _) = fin(plane_cases()[0].clone());
    let r3 = 3f64.sqrt();
    assert_near(
        vectors(&s["fin"]),
        [[1.0, -r3], [3.0, r3]],
        4.0,
        4.0 * f64::EPSILON,
        "90-degree rule",
    );
    assert_close(s["fin_speed"][0].as_f64().unwrap(), 2.0, REL, "v sin 30");
    assert_close(
        s["fin_speed"][1].as_f64().unwrap(),
        2.0 * r3,
        REL,
        "v cos 30",
    );
    assert_close(s["angle_between_deg"].as_f64().unwrap(), 90.0, REL, "90");
    // Car and van stick: V = P / M_total = (37500, 50000) / 4000 = (9.375, 12.5), exactly.
    let (s, _) = fin(plane_cases()[1].clone());
    assert_eq!(vectors(&s["fin"]), [[9.375, 12.5], [9.375, 12.5]]);
    // Heavier projectile (m1/m2 = 2), n at 30 degrees: deflected by asin(1/2) = 30 degrees,
    // the most it can be.
    let (s, _) = fin(plane_cases()[2].clone());
    assert_close(s["turned_deg"][0].as_f64().unwrap(), 30.0, 1e-14, "asin");
    // Lecture Fig. 2.3 along n = +x: the normal parts (3, -4) go to (4/3, 6) with e = 2/3; the
    // tangential parts 2 and -1 pass unchanged.
    let (s, _) = fin(plane_cases()[4].clone());
    assert_near(
        vectors(&s["fin"]),
        [[4.0 / 3.0, 2.0], [6.0, -1.0]],
        6.0,
        f64::EPSILON,
        "ka-whump",
    );
    // Every case with a line of impact: FIN as the impulse formula gives it here, with the
    // unit normal the page drew (the disks' from sin(phi) = b / (R1 + R2) checked first).
    for (k, case) in plane_cases().into_iter().enumerate() {
        let (s, p) = fin(case.clone());
        let Some(n) = p["normal"].as_array().map(|_| vector(&p["normal"])) else {
            continue;
        };
        if case["r1"].is_string() {
            // b = 1, R1 + R2 = 2, v1 - v2 along +x: n at asin(1/2) = 30 degrees.
            let (c, sn) = (3f64.sqrt() / 2.0, 0.5);
            assert!(
                (n[0] - c).abs() <= 2e-16 && (n[1] - sn).abs() <= 2e-16,
                "{n:?}"
            );
        }
        if case["exact"] == true {
            continue;
        }
        let m = [
            p["masses"][0].as_f64().unwrap(),
            p["masses"][1].as_f64().unwrap(),
        ];
        let v = vectors(&p["in"]);
        let e = p["e"].as_f64().unwrap();
        let scale = v.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs()));
        assert_near(
            vectors(&s["fin"]),
            impulse_fin(m, v, n, e),
            scale,
            1e-14,
            &format!("case {k}: {case}"),
        );
    }
}

#[test]
fn the_page_sees_pucks_that_do_not_collide_from_their_initial_velocities() {
    // v1 = (-4, 0), v2 = 0, n at 30 degrees: n.(v1 - v2) < 0, no collision, FIN = IN, so body 1
    // "finally at rest" moves at w = v1 = (-4, 0), and the page draws v1 = (0, 0), v2 = (4, 0)
    // (the state byte for byte as `collide solve`, which checks the same hand values).
    let case = json!({"m1": "1", "m2": "1", "v1": "(-4,0)", "v2": "(0,0)", "normal": "30deg",
                      "frame": "rest-fin:1"});
    let a = ask(plane_request(&case));
    assert_eq!(a["ok"], true, "{a}");
    assert_eq!(a["picture"]["w"], json!([-4.0, 0.0]), "{a}");
    assert_eq!(a["picture"]["in"], json!([[0.0, 0.0], [4.0, 0.0]]), "{a}");
    assert_eq!(a["picture"]["fin"], Value::Null, "{a}");
    assert_eq!(a["state"].as_str().unwrap(), cli_json(&solve_args(&case)));
}

#[test]
fn the_plane_refuses_what_it_cannot_draw_by_name() {
    let base = json!({"m1": "1", "m2": "1", "v1": "(1,0)", "v2": "(0,0)", "normal": "30deg"});
    let with = |k: &str, v: &str| {
        let mut c = base.clone();
        c[k] = v.into();
        c
    };
    let mut disks = base.clone();
    disks.as_object_mut().unwrap().remove("normal");
    disks["r1"] = "1".into();
    disks["r2"] = "1".into();
    disks["b"] = "3".into();
    // Both velocities numbers is a collision on a line, which the plane does not draw.
    for (case, field, words) in [
        (with("m2", "-1"), "m2", "mass -1 "),
        (with("v1", "?"), "v1", "'?'"),
        (with("v1", "1,0"), "v1", "2 values"),
        (
            json!({"m1": "1", "m2": "1", "v1": "0", "v2": "0", "normal": "30deg"}),
            "v1",
            "vectors",
        ),
        (with("e", "-2"), "e", "'-2'"),
        (with("normal", "sideways"), "normal", "sideways"),
        (with("frame", "(1,2,3)"), "frame", "(1,2,3)"),
        (disks, "b", "miss each other"),
    ] {
        let a = ask(plane_request(&case));
        assert_eq!(a["ok"], false, "{case}");
        assert_eq!(a["field"], field, "{case}: {a}");
        assert!(
            a["error"].as_str().unwrap().contains(words),
            "{case}: {}",
            a["error"]
        );
    }
    // Scenes the panel cannot draw are refused by name, with where to run them.
    for (scene, words) in [
        ("scenarios/plane-explosion.toml", "it has 3 bodies"),
        ("scenarios/plane-pucks-scatter.toml", "final velocities"),
    ] {
        let (code, out, err) = run(&["view", scene]);
        assert_eq!((code, out.as_str()), (2, ""), "{scene}");
        assert!(
            err.contains(words) && err.contains("collide scene"),
            "{err}"
        );
    }
    let (code, out, err) = run(&["view", "-m", "1,1,1", "-v", "(1,0),0,0"]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(err.contains("'1,1,1'") || err.contains("3"), "{err}");
}

/// The plane's JSON as the page holds it before any script runs (`<pre id="plane-state">`).
fn written_state(page: &str) -> String {
    let open = "<pre id=\"plane-state\" class=\"json\">";
    let from = page.find(open).unwrap() + open.len();
    let to = from + page[from..].find("</pre>").unwrap();
    page[from..to]
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&")
}

#[test]
fn view_takes_disk_radii_with_units_as_solve_does() {
    // R1 = R2 = 2.5 cm, b = 1 in = 2.54 cm: sin phi = b / (R1 + R2) = 2.54 / 5 = 0.508, only the
    // ratio enters; the page's JSON is `collide solve`'s for the same flags (was: exit 2,
    // "radius R1 '2.5 cm': not a number"). The picture's lengths are in metres.
    let flags = [
        "-m",
        "1,1",
        "-v",
        "(4,0),0",
        "--radii",
        "2.5 cm,2.5 cm",
        "--impact-parameter",
        "1 in",
    ];
    let page = stdout(&[&["view"][..], &flags].concat());
    let solve = stdout(&[&["solve"][..], &flags, &["--format", "json"]].concat());
    assert_eq!(written_state(&page), solve);
    let a = ask(
        json!({"op": "plane", "m1": "1", "m2": "1", "v1": "(4,0)", "v2": "0",
                       "r1": "2.5 cm", "r2": "2.5 cm", "b": "1 in"}),
    );
    assert_eq!(a["ok"], true, "{a}");
    assert_eq!(a["picture"]["radii"], json!([0.025, 0.025]), "{a}");
    assert_eq!(a["picture"]["b"], json!(0.0254), "{a}");
    let sin_phi = a["picture"]["b"].as_f64().unwrap() / 0.05;
    assert_close(sin_phi, 0.508, 4.0 * f64::EPSILON, "sin phi");
    // A scene with lengths: the same state.
    let dir = scratch("radii-units");
    let scene = dir.join("disks.toml");
    std::fs::write(
        &scene,
        "masses = [1, 1]\nvelocities = [\"(4,0)\", \"0\"]\nradii = [\"2.5 cm\", \"2.5 cm\"]\n\
         impact_parameter = \"1 in\"\n",
    )
    .unwrap();
    let page = stdout(&["view", scene.to_str().unwrap()]);
    let report: Value = serde_json::from_str(&stdout(&[
        "scene",
        scene.to_str().unwrap(),
        "--format",
        "json",
    ]))
    .map(|v: Value| v["report"].clone())
    .unwrap();
    assert_eq!(
        serde_json::from_str::<Value>(&written_state(&page)).unwrap(),
        report
    );
    // Some with a unit, some without: refused, at the field that differs.
    let a = ask(
        json!({"op": "plane", "m1": "1", "m2": "1", "v1": "(4,0)", "v2": "0",
                       "r1": "2.5 cm", "r2": "2.5 cm", "b": "1"}),
    );
    assert_eq!(
        (a["ok"].clone(), a["field"].clone()),
        (json!(false), json!("b")),
        "{a}"
    );
    assert!(
        a["error"]
            .as_str()
            .unwrap()
            .contains("all with a length unit"),
        "{a}"
    );
}

#[test]
fn the_page_names_the_field_at_fault_in_its_own_words() {
    let base = json!({"op": "plane", "m1": "1", "m2": "1", "v1": "(4,0)", "v2": "(0,0)",
                      "normal": "30deg", "line": "normal"});
    let with = |pairs: &[(&str, &str)]| {
        let mut c = base.clone();
        for (k, v) in pairs {
            c[*k] = (*v).into();
        }
        c
    };
    let none = |e: &str| with(&[("normal", ""), ("line", "none"), ("e", e)]);
    for (case, field, words) in [
        // A result beyond binary64 from the largest value typed, not from m1.
        (with(&[("v1", "(1e300,0)")]), "v1", "beyond binary64"),
        (with(&[("e", "1e300")]), "e", "beyond binary64"),
        // The line of impact chosen but left empty is missing, not "1 more known value".
        (
            with(&[("normal", "")]),
            "normal",
            "the line of impact n is missing",
        ),
        (none("1"), "e", "only e = 0 (the pucks stick)"),
        (none("0.5"), "e", "only e = 0 (the pucks stick)"),
        // Disks with v1 = v2: the page's words for b, no command-line flag.
        (
            json!({"op": "plane", "m1": "1", "m2": "1", "v1": "(1,0)", "v2": "(1,0)", "r1": "1",
                   "r2": "1", "b": "1", "line": "disks"}),
            "v2",
            "the impact parameter b needs both initial velocities",
        ),
        (with(&[("m1", "")]), "m1", "m1 is empty: give a mass"),
        (with(&[("v1", "")]), "v1", "v1 is empty: give a velocity"),
        (with(&[("v2", " ")]), "v2", "v2 is empty: give a velocity"),
        (
            with(&[("e", "1e309")]),
            "e",
            "too large for binary64 (|x| must be below 1.8e308): expected a number >= 0",
        ),
        (
            with(&[("e", "0/0")]),
            "e",
            "'0/0' divides by zero: expected a number >= 0",
        ),
    ] {
        let a = ask(case.clone());
        assert_eq!(a["ok"], false, "{case}");
        let error = a["error"].as_str().unwrap();
        assert_eq!(a["field"], field, "{case}: {error}");
        assert!(error.contains(words), "{case}: {error}");
        assert!(
            !error.contains("--"),
            "a flag in the page's message: {error}"
        );
    }
    // The two-body panel: V1 = 1e300 overflows the quadratic forms, at v1.
    let a = ask(json!({"op": "solve", "m1": "4", "m2": "1", "v1": "1e300", "v2": "10"}));
    assert_eq!(
        (a["ok"].clone(), a["field"].clone()),
        (json!(false), json!("v1")),
        "{a}"
    );
    assert!(!a["error"].as_str().unwrap().contains("--show"), "{a}");
    // The command line: three masses for the page's two bodies, and where to run them.
    let (code, out, err) = run(&["view", "-m", "1,2,3", "-v", "1,2,3"]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(
        err.contains("collide view draws two bodies") && err.contains("collide solve"),
        "{err}"
    );
}

#[test]
fn view_opens_the_plane_from_flags_and_scenes() {
    // Flags: the page opens on the plane with the case, whose JSON is `collide solve`'s.
    for flags in [
        &["-m", "2,1", "-v", "(1,0),(0,0)", "--normal", "30deg"][..],
        &[
            "-m",
            "1,1",
            "-v",
            "(1,0),(0,0)",
            "--radii",
            "1,1",
            "--impact-parameter",
            "0.5",
            "-e",
            "2/3",
        ],
    ] {
        let page = stdout(&[&["view"][..], flags].concat());
        assert!(page.contains("\"focus\":\"plane\""));
        let solve = stdout(&[&["solve"][..], flags, &["--format", "json"]].concat());
        assert_eq!(written_state(&page), solve, "{flags:?}");
    }
    // Scenes in the plane: the page's JSON is the scene's report.
    for scene in [
        "scenarios/plane-car-and-van.toml",
        "scenarios/plane-max-deflection.toml",
        "scenarios/plane-pucks-45.toml",
    ] {
        let page = stdout(&["view", scene]);
        assert!(page.contains("\"focus\":\"plane\""), "{scene}");
        let report: Value = serde_json::from_str(&stdout(&["scene", scene, "--format", "json"]))
            .map(|v: Value| v["report"].clone())
            .unwrap();
        let state: Value = serde_json::from_str(&written_state(&page)).unwrap();
        assert_eq!(state, report, "{scene}");
    }
    // A line of impact without vectors is refused as the command line refuses it.
    let (code, out, err) = run(&["view", "-m", "1,1", "-v", "1,0", "--normal", "30deg"]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(err.contains("components"), "{err}");
    // The same input gives the same bytes.
    let file = scratch("page").join("plane.html");
    let (code, _, err) = run(&[
        "view",
        "scenarios/plane-car-and-van.toml",
        "-o",
        file.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        std::fs::read_to_string(&file).unwrap(),
        stdout(&["view", "scenarios/plane-car-and-van.toml"])
    );
}

// ------------------------------------------------------------------ in a real browser

/// The drag of the brief: body 1's arrow dragged from (1, 0) to (0.6, 0.5), m = (1, 2), n at 30
/// degrees, e = 2/3.
pub const DRAG_TO: [f64; 2] = [0.6, 0.5];

/// What the browser does with the plane panel (part of `view.rs`'s plan).
pub fn browser_plan(dir: &std::path::Path) -> Value {
    let disks =
        json!({"m1": "1", "m2": "1", "v1": "(1,0)", "v2": "(0,0)", "r1": "1", "r2": "1", "b": "1"});
    json!({
        "cases": plane_cases().into_iter().filter(|c| c["exact"] != true && c["reverse"] != true).collect::<Vec<_>>(),
        "drag": {"case": {"m1": "1", "m2": "2", "v1": "(1,0)", "v2": "(0,0)", "normal": "30deg", "e": "2/3"},
                 "body": 0, "to": DRAG_TO},
        "keys": ["2", "ArrowUp", "ArrowUp", "ArrowRight"],
        "screenshot": {
            "case": disks,
            "path": dir.join("pucks.png"),
            "colours": {"body1": [37, 99, 235], "body2": [220, 38, 38]},
            // The tips of the arrows where the physics puts them, computed here: v1 = (1, 0);
            // n at 30 degrees (sin phi = 1/2), equal masses, elastic: v1' = v1 - (v1.n) n =
            // (1/4, -sqrt(3)/4), v2' = (v1.n) n = (3/4, sqrt(3)/4). And the disks' rims.
            "probes": [
                {"body": 0, "colour": "body1", "velocity": [1.0, 0.0]},
                {"body": 0, "colour": "body1", "velocity": [0.25, -0.4330127018922193]},
                {"body": 1, "colour": "body2", "velocity": [0.75, 0.4330127018922193]},
                {"body": 0, "colour": "body1", "rim_deg": 90.0},
                {"body": 0, "colour": "body1", "rim_deg": 180.0},
                {"body": 0, "colour": "body1", "rim_deg": 270.0},
                {"body": 1, "colour": "body2", "rim_deg": 90.0},
                {"body": 1, "colour": "body2", "rim_deg": 0.0}
            ]
        }
    })
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_plane_state_equals_solve_json() {
    let Some(b) = browser() else { return };
    let cases: Vec<Value> = plane_cases()
        .into_iter()
        .filter(|c| c["exact"] != true && c["reverse"] != true)
        .collect();
    let seen = b["plane"]["cases"].as_array().unwrap();
    assert_eq!(seen.len(), cases.len());
    for (case, seen) in cases.iter().zip(seen) {
        assert_seen_is_solve(seen, &solve_args(case), case);
    }
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_plane_drag_moves_the_arrow_and_fin_follows_the_impulse() {
    let Some(b) = browser() else { return };
    let d = &b["plane"]["drag"];
    let before: Value = serde_json::from_str(d["before"].as_str().unwrap()).unwrap();
    let after: Value = serde_json::from_str(d["after"].as_str().unwrap()).unwrap();
    assert_eq!(vectors(&before["in"]), [[1.0, 0.0], [0.0, 0.0]]);
    // IN: body 1's velocity is where the mouse let go, to the step the drag snaps to; body 2's
    // did not move.
    let step = d["map"]["step"].as_f64().unwrap();
    let v = vectors(&after["in"]);
    for k in 0..2 {
        assert!(
            (v[0][k] - DRAG_TO[k]).abs() <= step,
            "v1 {:?}, dragged to {DRAG_TO:?} (step {step})",
            v[0]
        );
    }
    assert_eq!(v[1], [0.0, 0.0]);
    // FIN by the impulse formula, computed here with n = (cos 30, sin 30).
    let n = [3f64.sqrt() / 2.0, 0.5];
    let expected = impulse_fin([1.0, 2.0], v, n, 2.0 / 3.0);
    assert_near(
        vectors(&after["fin"]),
        expected,
        1.0,
        1e-15,
        "FIN after the drag",
    );
    // Momentum is kept: m1 v1' + m2 v2' = m1 v1.
    let f = vectors(&after["fin"]);
    for k in 0..2 {
        assert_close(f[0][k] + 2.0 * f[1][k], v[0][k], 8.0 * REL, "momentum");
    }
    // The command shown reproduces the state, which is `collide solve`'s for the new IN.
    let command = d["command"].as_str().unwrap();
    assert_eq!(
        run_shown(command),
        d["after"].as_str().unwrap(),
        "{command}"
    );
    // Measured and printed, not asserted: the guide keeps wall-clock limits out of tests (a
    // loaded machine is slower, not wrong); docs/benchmarks.md reports the figures.
    drag_timings(&d["timings"], "plane drag");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_plane_keys_move_the_chosen_arrow_by_the_step() {
    let Some(b) = browser() else { return };
    // After the drag: '2' chooses body 2's arrow, then two steps up and one right.
    let drag: Value = serde_json::from_str(b["plane"]["drag"]["after"].as_str().unwrap()).unwrap();
    let keys: Value = serde_json::from_str(b["plane"]["keys"]["state"].as_str().unwrap()).unwrap();
    let step = b["plane"]["keys"]["map"]["step"].as_f64().unwrap();
    let (v0, v) = (vectors(&drag["in"]), vectors(&keys["in"]));
    assert_eq!(v[0], v0[0], "body 1 stays");
    assert_close(v[1][0], v0[1][0] + step, REL, "v2 x after Right");
    assert_close(v[1][1], v0[1][1] + 2.0 * step, REL, "v2 y after Up x2");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_plane_screenshot_shows_the_pucks_and_arrows() {
    let Some(b) = browser() else { return };
    let s = &b["plane"]["screenshot"];
    assert_eq!(s["error"], "", "{s}");
    let (w, h) = (s["width"].as_u64().unwrap(), s["height"].as_u64().unwrap());
    assert!(w >= 400, "{s}");
    assert!(
        s["white"].as_f64().unwrap() < 0.97 * (w * h) as f64,
        "blank: {s}"
    );
    for name in ["body1", "body2"] {
        assert!(
            s["counts"][name].as_u64().unwrap() > 400,
            "too few {name} pixels: {s}"
        );
    }
    // The disks touch along the line of impact at 30 degrees (sin phi = b / (R1 + R2) = 1/2),
    // drawn to scale (R1 = R2).
    let m = &s["map"];
    let c = [vector(&m["c"][0]), vector(&m["c"][1])];
    let r = vector(&m["radii"]);
    assert_close(r[0], r[1], REL, "equal radii");
    let (dx, dy) = (c[1][0] - c[0][0], c[0][1] - c[1][1]);
    assert_close(dx.hypot(dy), r[0] + r[1], 1e-9, "touching");
    assert!(
        (dy.atan2(dx).to_degrees() - 30.0).abs() < 1e-6,
        "{dx}, {dy}"
    );
    // Each arrow's tip and each rim probed finds its colour within 3 pixels of where the
    // physics computed above puts it.
    for (k, d) in s["probes"].as_array().unwrap().iter().enumerate() {
        let d = d.as_f64().unwrap_or(f64::INFINITY);
        assert!(
            d <= 3.0,
            "probe {k}: nearest pixel of its colour {d} px away: {s}"
        );
    }
}
