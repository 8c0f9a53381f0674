//! After a rigid impact (issue 42 section 3; physics.md section 8): the swing of a body on a
//! pivot under gravity (`--show swing`) and a round body sliding to rolling on the floor
//! (`--show rolling`, `--floor-friction`). Each answer is derived by hand in the test's comments
//! and compared exactly under `--exact` (rises, rolling speeds, times and distances are
//! rational) and to a stated tolerance in binary64 (angles through `acos`); a section that does
//! not apply says why.

use crate::common::{assert_close, assert_ulps, rounded, run_solve, solve_refused};
use crate::rigid::{f, json, q};

use collide::values::rational::{Q, int, ratio};

/// The case: 10 g of clay at 2.5 m/s sticks to the lower tip of a 75 g, 30 cm rod on
/// an axle through its centre.
const CLAY: [&str; 13] = [
    "-m",
    "10 g,75 g",
    "-v",
    "2.5 m/s,0",
    "--target",
    "rod 30 cm",
    "--pivot",
    "centre",
    "--hit-at",
    "-15 cm",
    "--join",
    "--show",
    "swing",
];

fn with(base: &[&str], more: &[&str]) -> Vec<String> {
    base.iter().chain(more).map(|s| s.to_string()).collect()
}

fn js(args: &[String]) -> serde_json::Value {
    let a: Vec<&str> = args.iter().map(String::as_str).collect();
    json(&a)
}

#[test]
fn clay_on_a_rod_on_its_axle_swings_67_degrees() {
    // About the axle: L = m v d = 0.01 * 2.5 * 0.15 = 3/800 (the clay passes below the axle
    // moving +x: counterclockwise). I = M L^2/12 + m d^2 = 0.075 * 0.09/12 + 0.01 * 0.0225 =
    // 9/16000 + 9/40000 = 63/80000, so omega = (3/800)/(63/80000) = 100/21 rad/s and
    // KE = 1/2 I omega^2 = 1/2 * 63/80000 * 10000/441 = 1/112 J. The joined body, M = 17/200 kg,
    // has its centre at l = 0.01 * 0.15 / 0.085 = 3/170 m straight below the axle (only the
    // clay's mass is off it), so with g = 9.8 = 49/5 the centre rises
    // dh = KE / (M g) = (1/112) / (17/200 * 49/5) = 125/11662 m, and
    // cos(theta) = 1 - dh / l = 1 - (125/11662)(170/3) = 6868/17493: theta = 66.88 degrees.
    let exact = js(&with(&CLAY, &["--gravity", "9.8", "--exact"]));
    let s = &exact["swing"];
    assert_eq!(s["body"], "joined");
    assert_eq!(q(&s["omega"]), ratio(100, 21));
    assert_eq!(q(&s["energy"]), ratio(1, 112));
    assert_eq!(q(&s["mass"]), ratio(17, 200));
    assert_eq!(q(&s["inertia"]), ratio(63, 80000));
    assert_eq!(q(&s["length"]), ratio(3, 170));
    assert_eq!(q(&s["arm"][1]), ratio(-3, 170));
    assert_eq!(q(&s["rise"]), ratio(125, 11662));
    assert_eq!(s["end"], "stops");
    assert_eq!(s["over_the_top"], false);
    let b = js(&with(&CLAY, &["--gravity", "9.8"]));
    let theta = (6868.0f64 / 17493.0).acos().to_degrees();
    // acos and the degrees each round once: 1e-14 relative covers them and the cast.
    assert_close(f(&b["swing"]["angle_deg"]), theta, 1e-14, "theta");
    assert!((f(&b["swing"]["angle_deg"]) - 66.88).abs() < 0.005);
    // In binary64 the typed decimals are binary64 numbers (0.01 is not 1/100): a few ulps.
    assert_ulps(
        f(&b["swing"]["rise"]),
        rounded(&ratio(125, 11662)),
        8.0,
        "dh",
    );
    // The text says it in words.
    let a: Vec<String> = with(&CLAY, &["--gravity", "9.8"]);
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    let (code, text, _) = run_solve(&a);
    assert_eq!(code, 0);
    assert!(
        text.contains("The swing (gravity g = 9.8 m/s^2 along -y)"),
        "{text}"
    );
    assert!(text.contains("theta  66.8827400507539 deg"), "{text}");
}

#[test]
fn a_ballistic_pendulum_with_a_rod_swings_past_the_horizontal() {
    // 10 g at 400 m/s lodges in the lower end of a 2 kg, 1 m rod hanging from its top end
    // (pivot (0, 1/2), hit 1 m below it). About the pivot L = m v L = 4, I = M L^2/3 + m L^2
    // = 2/3 + 1/100 = 203/300, omega = 1200/203, KE = 1/2 I omega^2 = 2400/203 J. M = 201/100
    // kg, centre 1.01/2.01 = 101/201 m below the pivot; with g = 49/5,
    // dh = (2400/203) / (201/100 * 49/5) = 1200000/1999347 m, and
    // dh / l = 1200000/1004647 (> 1, < 2: past the horizontal, not over the top; a rod holds
    // there where a string would go slack): cos(theta) = -195353/1004647.
    let args = [
        "-m",
        "10 g,2 kg",
        "-v",
        "400 m/s,0",
        "--target",
        "rod 1 m",
        "--pivot",
        "(0,0.5) m",
        "--hit-at",
        "-1 m",
        "--join",
        "--show",
        "swing",
        "--gravity",
        "9.8",
    ];
    let exact = js(&with(&args, &["--exact"]));
    assert_eq!(q(&exact["swing"]["energy"]), ratio(2400, 203));
    assert_eq!(q(&exact["swing"]["rise"]), ratio(1200000, 1999347));
    assert_eq!(q(&exact["swing"]["length"]), ratio(101, 201));
    let b = js(&with(&args, &[]));
    let theta = (-195353.0f64 / 1004647.0).acos().to_degrees();
    assert_close(f(&b["swing"]["angle_deg"]), theta, 1e-14, "theta");
}

#[test]
fn the_rails_pendulum_is_the_same_computation_for_a_point_bob() {
    // A point bob: 1 kg of clay at 5 m/s joins the lower end of a 1 m rod of 1e-12 kg hanging
    // from its top end; on the rail, 1 kg at 5 m/s joins a 1e-12 kg bob (-e 0) on a 1 m string.
    // Rigid: omega = m v L / (mu L^2/3 + m L^2) = 5/(1 + mu/3), KE = 1/2 (1 + mu/3) omega^2 =
    // 25/(2 (1 + mu/3)), dh = KE / ((1 + mu) g). Rail: f = 5/(1 + mu), h = f^2 / 2g. Both are
    // 25/(2g) = 125/98 m to 1e-12 relative (mu = 1e-12): the same energy balance.
    let mu = 1e-12;
    let g = 9.8;
    let rigid = json(&[
        "-m",
        "1 kg,1e-12 kg",
        "-v",
        "5 m/s,0",
        "--target",
        "rod 1 m",
        "--pivot",
        "(0,0.5) m",
        "--hit-at",
        "-1 m",
        "--join",
        "--show",
        "swing",
        "--gravity",
        "9.8",
    ]);
    let rise = f(&rigid["swing"]["rise"]);
    assert_close(
        rise,
        12.5 / ((1.0 + mu / 3.0) * (1.0 + mu) * g),
        1e-15,
        "rigid dh",
    );
    let (code, rail) = crate::common::solve_json(&[
        "-m",
        "1 kg,1e-12 kg",
        "-v",
        "5 m/s,0",
        "-e",
        "0",
        "--length",
        "1 m",
        "--gravity",
        "9.8",
    ]);
    assert_eq!(code, 0);
    let h = f(&rail["pendulum"]["swings"][0]["height"]);
    assert_close(
        h,
        25.0 / (1.0 + mu) / (1.0 + mu) / (2.0 * g),
        1e-15,
        "rail h",
    );
    assert_close(rise, h, 1e-11, "the same swing");
    let (a_rigid, a_rail) = (
        f(&rigid["swing"]["angle_deg"]),
        f(&rail["pendulum"]["swings"][0]["angle_deg"]),
    );
    // 125/98 is past the horizontal: cos(theta) = 1 - 125/98 = -27/98.
    assert_close(
        a_rail,
        (-27.0f64 / 98.0).acos().to_degrees(),
        1e-11,
        "rail theta",
    );
    assert_close(a_rigid, a_rail, 1e-11, "the same angle");
}

/// A 1 kg ball at `v` sticks to the lower end of a 1 kg, 2 m rod on an axle through its
/// centre (no units: g as given).
fn rod(v: &str, g: &str) -> Vec<String> {
    let v = format!("{v},0");
    let a = [
        "-m",
        "1,1",
        "-v",
        &v,
        "--target",
        "rod 2",
        "--pivot",
        "centre",
        "--hit-at",
        "-1",
        "--join",
        "--show",
        "swing",
        "--gravity",
        g,
    ];
    a.iter().map(|s| s.to_string()).collect()
}

fn over(v: &str, g: &str) -> serde_json::Value {
    js(&with(
        &rod(v, g).iter().map(String::as_str).collect::<Vec<_>>(),
        &["--exact"],
    ))
}

#[test]
fn over_the_top_and_just_to_the_top() {
    // I = 1 * 4/12 + 1 * 1 = 4/3, omega = m v d / I = 3v/4; M = 2, centre l = 1/2 below the
    // axle (y0 = -1/2); KE = 1/2 (4/3)(9 v^2/16) = 3 v^2/8 and dh = KE/(M g) = 3 v^2/(16 g).
    // The top is l - y0 = 1 above: v = 8, g = 10 gives dh = 6/5 > 1, over the top with
    // omega_top^2 = omega^2 - 2 M g (l - y0)/I = 36 - 30 = 6; g = 12 gives dh = 1 exactly: it
    // just reaches the top.
    let s = over("8", "10");
    assert_eq!(s["swing"]["end"], "over the top");
    assert_eq!(s["swing"]["over_the_top"], true);
    assert_eq!(q(&s["swing"]["rise"]), int(1));
    let b = js(&rod("8", "10"));
    assert_ulps(f(&b["swing"]["omega_top"]), 6f64.sqrt(), 2.0, "omega_top");
    let t = over("8", "12");
    assert_eq!(t["swing"]["end"], "reaches the top");
    assert_eq!(q(&t["swing"]["rise"]), int(1));
}

#[test]
fn a_struck_rod_swings_alone_and_free_bodies_say_why_not() {
    // 1 kg at 2 hits the lower end of a 3 kg, 2-long rod hanging from its top end, e = 1. The
    // rod's effective mass there is I_p/d^2 = (3 * 4/3)/4 = 1: equal masses, the ball stops and
    // the rod's end leaves at 2, omega = 1, KE = 1/2 * 4 * 1 = 2; its centre is l = 1 below the
    // pivot, M = 3: dh = 2/(3 g) = 1/15 with g = 10, cos(theta) = 14/15.
    let args = [
        "-m",
        "1,3",
        "-v",
        "2,0",
        "--target",
        "rod 2",
        "--pivot",
        "(0,1)",
        "--hit-at",
        "-2",
        "--show",
        "swing",
        "--gravity",
        "10",
    ];
    let e = js(&with(&args, &["--exact"]));
    assert_eq!(e["swing"]["body"], 2);
    assert_eq!(q(&e["swing"]["rise"]), ratio(1, 15));
    let b = js(&with(&args, &[]));
    assert_close(
        f(&b["swing"]["angle_deg"]),
        (14.0f64 / 15.0).acos().to_degrees(),
        1e-14,
        "theta",
    );
    // A free rod does not swing: the section says why.
    let free = json(&[
        "-m", "1,3", "-v", "2,0", "--target", "rod 2", "--show", "swing",
    ]);
    let note = free["swing"]["note"].as_str().unwrap();
    assert!(note.contains("no body is on a pivot"), "{note}");
    let (code, text, _) = run_solve(&[
        "-m", "1,3", "-v", "2,0", "--target", "rod 2", "--show", "swing",
    ]);
    assert_eq!(code, 0);
    assert!(
        text.contains("The swing (gravity g = 9.80665 along -y)"),
        "{text}"
    );
    assert!(text.contains("no swing: no body is on a pivot"), "{text}");
}

/// The wall: a solid sphere (1 kg, R = 1 m) rolling at 1 m/s into a smooth wall, e = 1.
const WALL: [&str; 14] = [
    "-m",
    "1 kg,wall",
    "-v",
    "(1,0) m/s,0",
    "--ball",
    "sphere 1 m",
    "--spin",
    "-1 rad/s",
    "-e",
    "1",
    "--show",
    "rolling",
    "--exact",
    "--format",
];

#[test]
fn a_sphere_rolling_into_a_smooth_wall_comes_back_rolling_at_three_sevenths() {
    // The smooth wall reverses v (-1 m/s) and keeps the spin (-1 rad/s: the rolling spin of
    // +1 m/s). Angular momentum about the contact point: m v - (I/R) omega = -1 + 2/5 = -3/5
    // over m + I/R^2 = 7/5: v_roll = -3/7 m/s = 3v/7 back. The slip is v + omega R = -2 m/s;
    // with mu = 1/5, g = 10: t = |slip| I / (mu g (I + m R^2)) = 2 (2/5) / (2 * 7/5) = 2/7 s,
    // and the centre moves v t + 1/2 mu g t^2 (friction pushes +x against the slip) =
    // -2/7 + 1/2 * 2 * 4/49 = -10/49 m.
    let j = json(&WALL[..13]);
    let r = &j["rolling"][0];
    assert_eq!(r["body"], 1);
    assert_eq!(q(&r["v_roll"]), ratio(-3, 7));
    assert_eq!(q(&r["omega_roll"]), ratio(3, 7));
    assert_eq!(q(&r["slip"]), int(-2));
    assert!(r.get("time").is_none());
    let mut a = WALL[..13].to_vec();
    a.extend(["--floor-friction", "0.2", "--gravity", "10"]);
    let j = json(&a);
    let r = &j["rolling"][0];
    assert_eq!(q(&r["time"]), ratio(2, 7));
    assert_eq!(q(&r["distance"]), ratio(-10, 49));
    // The wall is not a body that rolls: only body 1 is listed.
    assert_eq!(j["rolling"].as_array().unwrap().len(), 1);
}

#[test]
fn a_cue_ball_hit_at_its_centre_rolls_at_five_sevenths() {
    // A point striker (1) at 7 hits a solid sphere (1, R = 1) at rest through its centre,
    // e = 1: equal masses, the sphere leaves at v = 7 with no spin. v_roll = m v / (m + 2/5 m)
    // = 5/7 v = 5. Slip 7; mu = 1/2, g = 10: t = 7 (2/5) / (5 * 7/5) = 2/5, distance
    // 7 (2/5) - 1/2 * 5 * (2/5)^2 = 14/5 - 2/5 = 12/5.
    let args = [
        "-m",
        "1,1",
        "-v",
        "7,0",
        "--target",
        "sphere 1",
        "-e",
        "1",
        "--show",
        "rolling",
        "--floor-friction",
        "1/2",
        "--gravity",
        "10",
        "--exact",
    ];
    let j = json(&args);
    let rolls = j["rolling"].as_array().unwrap();
    assert!(
        rolls[0]["note"]
            .as_str()
            .unwrap()
            .contains("point particle"),
        "{j}"
    );
    let r = &rolls[1];
    assert_eq!(r["body"], 2);
    assert_eq!(q(&r["v"]), int(7));
    assert_eq!(q(&r["v_roll"]), int(5));
    assert_eq!(q(&r["time"]), ratio(2, 5));
    assert_eq!(q(&r["distance"]), ratio(12, 5));
}

#[test]
fn backspin_against_a_wall_in_binary64() {
    // A solid sphere, m = 1, R = 1/2, at 3 with spin +2 (backspin) into a smooth wall, e = 1:
    // it leaves at -3 with spin 2. With omega_s = -omega the rolling sense, the closed form
    // (5 v + 2 R omega_s)/7 = (-15 - 2)/7 = -17/7, rounded once.
    let j = json(&[
        "-m",
        "1,wall",
        "-v",
        "(3,0),0",
        "--ball",
        "sphere 0.5",
        "--spin",
        "2",
        "-e",
        "1",
        "--show",
        "rolling",
    ]);
    assert_eq!(f(&j["rolling"][0]["v_roll"]), rounded(&ratio(-17, 7)));
    assert_eq!(f(&j["rolling"][0]["omega_roll"]), rounded(&ratio(34, 7)));
}

#[test]
fn the_new_flags_refuse_what_they_cannot_mean() {
    solve_refused(
        &[
            "-m",
            "1,wall",
            "-v",
            "(1,0),0",
            "--ball",
            "sphere 1",
            "--floor-friction",
            "0.2",
        ],
        &["--floor-friction 0.2", "--show rolling"],
    );
    solve_refused(
        &[
            "-m",
            "1,wall",
            "-v",
            "(1,0),0",
            "--ball",
            "sphere 1",
            "--show",
            "rolling",
            "--floor-friction",
            "0",
        ],
        &["--floor-friction 0", "above 0"],
    );
    let negative = rod("8", "-9.8");
    solve_refused(
        &negative.iter().map(String::as_str).collect::<Vec<_>>(),
        &["--gravity -9.8", "above 0"],
    );
    // Without the sections, --gravity still means nothing to a rigid impact.
    solve_refused(
        &[
            "-m",
            "1,1",
            "-v",
            "8,0",
            "--target",
            "rod 2",
            "--gravity",
            "9.8",
        ],
        &["--gravity"],
    );
}

#[test]
fn every_section_asked_of_every_kind_of_case_is_shown_or_says_why() {
    // Issue 42 section 3: a section asked for by name is never silently dropped. For each kind
    // of case, asking for a section beside a base one either changes the text (a heading or a
    // note was added) or exits 2 naming the section; the rail's notes name it in a "Not shown"
    // block.
    let cases: [&[&str]; 8] = [
        &["-m", "1,2", "-v", "3,0"],
        &["-m", "1,wall", "-v", "3,0"],
        &["-m", "1,2", "-v", "0,0", "--fin", "2,?"],
        &["-m", "1,2", "-v", "3,0", "--pass-through", "--fin", "2,?"],
        &["-m", "1,1", "-v", "(1,0),0", "--normal", "(1,1)"],
        &["-m", "1,1,1", "-v", "2,0,0", "-e", "0"],
        &["-m", "1,3", "-v", "2,0", "--target", "rod 2"],
        &CLAY[..11],
    ];
    let sections = [
        "vectors",
        "momentum",
        "forms",
        "energy",
        "ellipses",
        "products",
        "changes",
        "heights",
        "slides",
        "diagnostics",
        "angles",
        "swing",
        "rolling",
    ];
    for case in cases {
        for s in sections {
            let base = if s == "energy" { "vectors" } else { "energy" };
            let run = |show: &str| {
                let mut a: Vec<&str> = case.to_vec();
                a.extend(["--show", show]);
                run_solve(&a)
            };
            let (code0, before, _) = run(base);
            assert_eq!(code0, 0, "{case:?} --show {base}");
            let (code, after, err) = run(&format!("{base},{s}"));
            if code == 2 {
                assert!(err.contains(s), "{case:?} --show {s}: {err}");
                continue;
            }
            assert_eq!(code, 0, "{case:?} --show {s}: {err}");
            assert_ne!(before, after, "{case:?}: --show {s} printed nothing");
            if after.contains("Not shown (asked for, but not for this case)") {
                assert!(
                    after.contains(&format!("\n  {s}")),
                    "{case:?} {s}:\n{after}"
                );
            }
        }
    }
}

#[test]
fn a_pass_through_prints_its_heights() {
    // 5 g at 400 m/s leaves a 1 kg block at 100 m/s: the block takes 0.005 * 300 = 1.5 m/s.
    // Heights v^2 / 2g with g = 10: the bullet's 160000/20 = 8000 m and 10000/20 = 500 m, the
    // block's 2.25/20 = 9/80 m (how high a block on a string would swing).
    let (code, j) = crate::common::solve_json(&[
        "-m",
        "5 g,1 kg",
        "-v",
        "400 m/s,0",
        "--pass-through",
        "--fin",
        "100 m/s,?",
        "--show",
        "heights,forms",
        "--gravity",
        "10",
        "--exact",
    ]);
    assert_eq!(code, 0);
    assert_eq!(q(&j["heights"]["in"][0]), int(8000));
    assert_eq!(q(&j["heights"]["fin"][0]), int(500));
    assert_eq!(q(&j["heights"]["fin"][1]), ratio(9, 80));
    assert!(
        j["not_shown"]["forms"]
            .as_str()
            .unwrap()
            .contains("only momentum")
    );
}

#[test]
fn a_separation_prints_its_heights() {
    // Issue 42 section 3 names pass-through and separation cases. 2 kg and 3 kg start together
    // at rest and 3 kg leaves at 4 m/s: momentum 2 f1 + 3 4 = 0, f1 = -6. Heights v^2 / 2g with
    // g = 10: 36/20 = 9/5 m and 16/20 = 4/5 m after, 0 before; the forms (an energy ellipse and
    // restitution) do not apply, and say so.
    let (code, j) = crate::common::solve_json(&[
        "-m",
        "2,3",
        "-v",
        "0,0",
        "--fin",
        "?,4",
        "--show",
        "heights,forms",
        "--gravity",
        "10",
        "--exact",
    ]);
    assert_eq!(code, 0);
    assert_eq!(j["event"], "separation");
    assert_eq!(q(&j["solved"]["f1"]), int(-6));
    assert_eq!(q(&j["heights"]["in"][0]), Q::ZERO);
    assert_eq!(q(&j["heights"]["in"][1]), Q::ZERO);
    assert_eq!(q(&j["heights"]["fin"][0]), ratio(9, 5));
    assert_eq!(q(&j["heights"]["fin"][1]), ratio(4, 5));
    assert!(
        j["not_shown"]["forms"]
            .as_str()
            .unwrap()
            .contains("only momentum")
    );
}
