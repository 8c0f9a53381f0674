//! Several contacts at once (issue 42 section 4; physics.md section 8): touching balls by
//! positions and radii or by named contacts, Newton's law at every contact as an LCP, against
//! answers derived here by hand; the sequential answer; one contact as the two-body solver bit
//! for bit; relabelled, rotated and mirrored cases; the rack's invariants; bad input refused.

use serde_json::Value;

use crate::common::{assert_close, number, solve_json, solve_refused, stdout};
use collide::values::rational::Q;

/// The published case: a cue ball at 3.8 onto two touching equal balls, contacts at +-30 deg.
const CUE: [&str; 4] = ["-m", "1,1,1", "-v", "(3.8,0),0,0"];

fn vec2(v: &Value) -> [f64; 2] {
    [number(&v[0]), number(&v[1])]
}

fn fin(j: &Value) -> Vec<[f64; 2]> {
    j["fin"].as_array().unwrap().iter().map(vec2).collect()
}

/// An exact JSON value (`"-1/3"`) as a rational.
fn q(v: &Value) -> Q {
    let s = v.as_str().unwrap_or_else(|| panic!("not exact: {v}"));
    s.parse::<Q>()
        .unwrap_or_else(|_| panic!("not a fraction: {s}"))
}

#[test]
fn the_published_cue_ball_onto_two_touching_balls_by_hand() {
    // n2 = (c, s), n3 = (c, -s), c = cos 30, s = 1/2; w_k = n_k.(v_k - v_1) = -3.8 c.
    // A = J M^-1 J^T: A_kk = 1/m1 + 1/mk = 2, A_23 = n2.n3 / m1 = c^2 - s^2 = 1/2. Both push
    // (w' = -w): 2 w + A P = 0, by symmetry (2 + 1/2) P = 7.6 c, P = 7.6 c / (2 c^2 + 1) =
    // 3.04 c. Cue ball: 3.8 - 2 P c = 3.8 - 6.08 (3/4) = -0.76; ball 2: P n2 = (3.04 c^2,
    // 3.04 c s) = (2.28, 1.52 c), speed 3.04 c = 2.6327 at 30 deg. The normals enter as the
    // binary64 cosine and sine of 30 deg: within 1e-14 of the exact answer.
    let (code, j) = solve_json(&[&CUE[..], &["--contacts", "1-2 @ 30deg,1-3 @ -30deg"]].concat());
    assert_eq!(code, 0);
    let c = 3f64.sqrt() / 2.0;
    let f = fin(&j);
    assert_close(f[0][0], -0.76, 1e-14, "cue ball");
    assert!(f[0][1].abs() < 1e-15, "{:?}", f[0]);
    for (k, sign) in [(1, 1.0), (2, -1.0)] {
        assert_close(f[k][0], 2.28, 1e-14, "x");
        assert_close(f[k][1], sign * 1.52 * c, 1e-14, "y");
        assert_close(
            number(&j["contacts"][k - 1]["impulse"]),
            7.6 * c / (2.0 * c * c + 1.0),
            1e-14,
            "P",
        );
        assert_close(number(&j["fin_angle_deg"][k]), sign * 30.0, 1e-13, "angle");
    }
    assert_eq!(j["law"], "newton-simultaneous");
    // The same with centres typed to four digits, (1.732, 1) for (sqrt 3, 1): within the
    // 0.1% touching tolerance, and within 1e-4 of the published numbers (1.732 is 2.5e-5 off).
    let (code, p) = solve_json(
        &[
            &CUE[..],
            &[
                "--positions",
                "(0,0),(1.732,1),(1.732,-1)",
                "--radii",
                "1,1,1",
            ],
        ]
        .concat(),
    );
    assert_eq!(code, 0);
    assert!((fin(&p)[0][0] + 0.76).abs() < 1e-4);
    assert!((number(&p["fin_speed"][1]) - 3.04 * c).abs() < 1e-4);
    // Balls 2 and 3 touch too (2 apart): that pair parts, with no impulse.
    assert_eq!(p["contacts"][2]["pair"], serde_json::json!([2, 3]));
    assert_eq!(number(&p["contacts"][2]["impulse"]), 0.0);
    assert_eq!(number(&p["energy"]["lost"]), 0.0);
    let text = stdout(
        &[
            &["solve"],
            &CUE[..],
            &["--contacts", "1-2 @ 30deg,1-3 @ -30deg"],
        ]
        .concat(),
    );
    assert!(text.contains("(-0.76, 0)"), "{text}");
    assert!(
        text.contains("Newton's restitution at every contact at once"),
        "{text}"
    );
}

#[test]
fn the_published_cue_ball_one_contact_at_a_time_by_hand() {
    // --sequential on the published case, c = cos 30, s = 1/2. 1-2 first: equal elastic balls
    // swap the normal part, 3.8 c along n2 = (c, s): ball 2 (2.85, 1.9 c), the cue ball (3.8 -
    // 2.85, -1.9 c) = (0.95, -1.9 c). Then 1-3, n3 = (c, -s): the cue ball's part along n3 is
    // 0.95 c + 0.95 c = 1.9 c, so ball 3 (1.425, -0.95 c) and the cue ball (-0.475, -0.95 c),
    // 0.95 at -120 deg. Nothing approaches after (n2.(v2 - v1) = 4.75 c, n3.(v3 - v1) = 1.9 c):
    // 2 impacts, and KE 1/2 (0.9025 + 10.83 + 2.7075) = 7.22 kept. The simultaneous answer was
    // (-0.76, 0): the law matters.
    let (code, j) = solve_json(
        &[
            &CUE[..],
            &["--contacts", "1-2 @ 30deg,1-3 @ -30deg", "--sequential"],
        ]
        .concat(),
    );
    assert_eq!(code, 0);
    let c = 3f64.sqrt() / 2.0;
    let s = &j["sequential"];
    assert_eq!(s["impacts"], 2);
    let f = fin(s);
    for (k, want) in [
        (0, [-0.475, -0.95 * c]),
        (1, [2.85, 1.9 * c]),
        (2, [1.425, -0.95 * c]),
    ] {
        assert_close(f[k][0], want[0], 1e-14, "x");
        assert_close(f[k][1], want[1], 1e-14, "y");
    }
    assert_close(number(&s["energy"]["fin"]), 7.22, 1e-14, "KE");
    // The simultaneous answer is printed beside it, unchanged.
    assert_close(fin(&j)[0][0], -0.76, 1e-14, "cue ball");
}

#[test]
fn newtons_cradle_of_three_simultaneous_and_sequential_by_hand() {
    // Three unit balls in a row, the first at 1, e = 1: w = (-1, 0), A = [[2, -1], [-1, 2]].
    // Both push: 2 w + A P = 0, so 2 P1 - P2 = 2, -P1 + 2 P2 = 0: P = (4/3, 2/3);
    // v1' = 1 - 4/3 = -1/3, v2' = 4/3 - 2/3 = 2/3, v3' = 2/3 (energy 1/9 + 4/9 + 4/9 = 1).
    // Sequential, 1-2 then 2-3: equal elastic pairs swap, (0, 1, 0) then (0, 0, 1).
    let (code, j) = solve_json(&[
        "-m",
        "1,1,1",
        "-v",
        "(1,0),0,0",
        "--positions",
        "(0,0),(2,0),(4,0)",
        "--radii",
        "1,1,1",
        "--sequential",
        "--exact",
    ]);
    assert_eq!(code, 0);
    let f = |v: &Value| -> Vec<Q> { v.as_array().unwrap().iter().map(q).collect() };
    let r = |n: i64, d: i64| collide::values::rational::ratio(n, d);
    assert_eq!(f(&j["fin"][0]), vec![r(-1, 3), r(0, 1)]);
    assert_eq!(f(&j["fin"][1]), vec![r(2, 3), r(0, 1)]);
    assert_eq!(f(&j["fin"][2]), vec![r(2, 3), r(0, 1)]);
    assert_eq!(q(&j["contacts"][0]["impulse"]), r(4, 3));
    assert_eq!(q(&j["contacts"][1]["impulse"]), r(2, 3));
    assert_eq!(q(&j["energy"]["lost"]), r(0, 1));
    let s = &j["sequential"];
    assert_eq!(f(&s["fin"][0]), vec![r(0, 1), r(0, 1)]);
    assert_eq!(f(&s["fin"][1]), vec![r(0, 1), r(0, 1)]);
    assert_eq!(f(&s["fin"][2]), vec![r(1, 1), r(0, 1)]);
    assert_eq!(s["impacts"], 2);
    // Inelastic, e = 0: the three move on together at 1/3 (every contact closes).
    let (_, j) = solve_json(&[
        "-m",
        "1,1,1",
        "-v",
        "(1,0),0,0",
        "--contacts",
        "1-2 @ (1,0),2-3 @ (1,0)",
        "-e",
        "0",
        "--exact",
    ]);
    for i in 0..3 {
        assert_eq!(q(&j["fin"][i][0]), r(1, 3));
    }
}

#[test]
fn a_single_contact_is_the_two_body_solver_bit_for_bit() {
    // One contact is the two-body smooth impact: the same exact rational FIN, rounded once.
    let cases: [(&[&str], &[&str], &[&str]); 4] = [
        (
            &["-m", "1,2", "-v", "(3,1),(-1,0.5)", "-e", "0.7"],
            &["--normal", "(1.732,1)"],
            &["--positions", "(0,0),(1.732,1)", "--radii", "1,1"],
        ),
        (
            &["-m", "0.3,5", "-v", "(2.5,-1.25),(0.1,0.2)"],
            &["--normal", "30deg"],
            &["--contacts", "1-2 @ 30deg"],
        ),
        (
            &["-m", "4,1", "-v", "(60,0),(10,0)", "-e", "2/3"],
            &["--normal", "(1,0)"],
            &["--contacts", "1-2 @ (1,0)"],
        ),
        (
            &["-m", "1,3", "-v", "(1,2),(0,0)", "-e", "1/2", "--exact"],
            &["--normal", "(3,4)"],
            &["--positions", "(0,0),(3,4)", "--radii", "2,3"],
        ),
    ];
    for (case, two, many) in cases {
        let (c1, a) = solve_json(&[case, two].concat());
        let (c2, b) = solve_json(&[case, many].concat());
        assert_eq!((c1, c2), (0, 0), "{case:?}");
        for key in ["in", "fin", "v_com", "impulse"] {
            assert_eq!(a[key], b[key], "{case:?} {key}");
        }
        for key in ["in", "fin", "lost"] {
            assert_eq!(a["energy"][key], b["energy"][key], "{case:?} energy.{key}");
        }
    }
}

#[test]
fn relabelled_bodies_give_the_answer_permuted() {
    // Unequal masses so that the labels matter; the cue ball last, then in the middle.
    let base = solve_json(&[
        "-m",
        "1,2,3",
        "-v",
        "(3.8,0.5),0,(0,-0.25)",
        "--positions",
        "(0,0),(1.732,1),(1.732,-1)",
        "--radii",
        "1,1,1",
    ])
    .1;
    for (order, masses, v, pos) in [
        (
            [2, 0, 1],
            "3,1,2",
            "(0,-0.25),(3.8,0.5),0",
            "(1.732,-1),(0,0),(1.732,1)",
        ),
        (
            [1, 2, 0],
            "2,3,1",
            "0,(0,-0.25),(3.8,0.5)",
            "(1.732,1),(1.732,-1),(0,0)",
        ),
    ] {
        let (code, j) = solve_json(&[
            "-m",
            masses,
            "-v",
            v,
            "--positions",
            pos,
            "--radii",
            "1,1,1",
        ]);
        assert_eq!(code, 0);
        for (new, old) in order.iter().enumerate() {
            assert_eq!(j["fin"][new], base["fin"][*old], "{order:?}");
        }
        assert_eq!(j["energy"]["fin"], base["energy"]["fin"]);
    }
}

#[test]
fn a_rotated_frame_gives_the_answer_rotated() {
    // The turn by (cos, sin) = (4/5, 3/5) maps the typed decimals to decimals: (1.732, 1) to
    // (1.732 (4/5) - 3/5, 1.732 (3/5) + 4/5) = (0.7856, 1.8392), (1.732, -1) to (1.9856,
    // 0.2392), (3.8, 0) to (3.04, 2.28). Exact arithmetic: FIN turned exactly. Binary64 (the
    // typed decimals rounded once): each component within 4 ulps of the largest speed, 3.8.
    let plain = ["(0,0),(1.732,1),(1.732,-1)", "(3.8,0),0,0"];
    let turned = ["(0,0),(0.7856,1.8392),(1.9856,0.2392)", "(3.04,2.28),0,0"];
    let run = |[pos, v]: [&str; 2], exact: bool| {
        let mut args = vec![
            "-m",
            "1,2,2",
            "-v",
            v,
            "--positions",
            pos,
            "--radii",
            "1,1,1",
        ];
        if exact {
            args.push("--exact");
        }
        solve_json(&args).1
    };
    let (a, b) = (run(plain, true), run(turned, true));
    let (c, s) = (
        collide::values::rational::ratio(4, 5),
        collide::values::rational::ratio(3, 5),
    );
    for i in 0..3 {
        let (x, y) = (q(&a["fin"][i][0]), q(&a["fin"][i][1]));
        assert_eq!(q(&b["fin"][i][0]), &c * &x - &s * &y, "body {i}");
        assert_eq!(q(&b["fin"][i][1]), &s * &x + &c * &y, "body {i}");
    }
    let (a, b) = (run(plain, false), run(turned, false));
    let tol = 4.0 * f64::EPSILON * 3.8;
    for i in 0..3 {
        let [x, y] = vec2(&a["fin"][i]);
        let [u, v] = vec2(&b["fin"][i]);
        assert!((u - (0.8 * x - 0.6 * y)).abs() <= tol, "body {i}: {u}");
        assert!((v - (0.6 * x + 0.8 * y)).abs() <= tol, "body {i}: {v}");
    }
}

/// The scene's rack (`scenarios/contacts-rack.toml`) as `collide solve` arguments, with
/// `--sequential`. A cue ball at (0, 0) moving at 2 touches the apex at (2, 0);
/// row k of the triangle is at x = 2 + 1.7320508 k (2 sqrt(3) within the touching tolerance),
/// its balls at y = -k, -k + 2, ..., k.
fn rack() -> Vec<String> {
    let xs = ["2", "3.7320508", "5.4641016", "7.1961524", "8.9282032"];
    let mut pos = vec!["(0,0)".to_string()];
    for (k, x) in xs.iter().enumerate() {
        for j in 0..=k {
            pos.push(format!("({x},{})", 2 * j as i64 - k as i64));
        }
    }
    let ones = vec!["1"; 16].join(",");
    let v = format!("(2,0){}", ",0".repeat(15));
    let p = pos.join(",");
    [
        "-m",
        &ones,
        "-v",
        &v,
        "--positions",
        &p,
        "--radii",
        &ones,
        "--sequential",
    ]
    .map(String::from)
    .to_vec()
}

#[test]
fn the_rack_keeps_momentum_and_energy_and_its_mirror() {
    let owned = rack();
    let args: Vec<&str> = owned.iter().map(String::as_str).collect();
    // Exact: momentum 16 V_COM = (2, 0) and KE = 2 exactly (e = 1: sum P_k (w_k + w'_k)/2 = 0),
    // in both answers.
    let (code, j) = solve_json(&[&args[..], &["--exact"]].concat());
    assert_eq!(code, 0);
    let r = |n: i64, d: i64| collide::values::rational::ratio(n, d);
    let mut momentum = [Q::ZERO, Q::ZERO];
    for f in j["fin"].as_array().unwrap() {
        momentum[0] += q(&f[0]);
        momentum[1] += q(&f[1]);
    }
    assert_eq!(momentum, [r(2, 1), r(0, 1)]);
    assert_eq!(q(&j["energy"]["fin"]), r(2, 1));
    assert_eq!(q(&j["sequential"]["energy"]["fin"]), r(2, 1));
    assert_eq!(j["contacts"].as_array().unwrap().len(), 31);
    assert_eq!(j["impulses_unique"], false);
    // Binary64: no pair approaches afterwards, in either answer.
    let (_, j) = solve_json(&args);
    for answer in [&j, &j["sequential"]] {
        for c in answer["contacts"].as_array().unwrap() {
            assert!(number(&c["normal_velocity"]["fin"]) >= 0.0, "{c}");
            assert!(number(&c["impulse"]) >= 0.0, "{c}");
        }
    }
    // Mirror (y -> -y maps the rack onto itself): the simultaneous answer is its own mirror
    // image bit for bit (its final velocities are unique and exact before rounding).
    let pos: Vec<[f64; 2]> = j["positions"]
        .as_array()
        .unwrap()
        .iter()
        .map(vec2)
        .collect();
    let f = fin(&j);
    for (i, [x, y]) in pos.iter().enumerate() {
        let k = pos.iter().position(|[a, b]| a == x && *b == -y).unwrap();
        assert_eq!(f[k][0], f[i][0], "ball {}", i + 1);
        assert_eq!(f[k][1], -f[i][1] + 0.0, "ball {}", i + 1);
    }
}

#[test]
fn the_contact_scenes_pass() {
    let out = stdout(&[
        "scene",
        "scenarios/contacts-cradle.toml",
        "scenarios/contacts-cue-two-balls.toml",
        "scenarios/contacts-rack.toml",
    ]);
    assert!(out.contains("3 scenes: 3 pass, 0 fail"), "{out}");
}

#[test]
fn the_text_fits_80_columns() {
    let out = crate::common::collide_at_default_width()
        .arg("solve")
        .args(rack())
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("Sequential answer"), "{text}");
    for line in text.lines() {
        assert!(line.chars().count() <= 80, "{line}");
    }
}

#[test]
fn bad_input_exits_2_naming_it() {
    let m3 = ["-m", "1,1,1", "-v", "(1,0),0,0"];
    let refused =
        |extra: &[&str], needles: &[&str]| solve_refused(&[&m3[..], extra].concat(), needles);
    refused(
        &["--positions", "(0,0),(2,0),(3,0)", "--radii", "1,1,1"],
        &["balls 2 and 3 overlap", "0.001"],
    );
    refused(
        &["--positions", "(0,0),(2,0)", "--radii", "1,1,1"],
        &["--positions has 2 values for 3 masses"],
    );
    refused(
        &["--positions", "(0,0),(2,0),(4,0)", "--radii", "1,1"],
        &["--radii has 2 values for 3 masses"],
    );
    refused(
        &["--positions", "(0,0),(2,0),(4,0)", "--radii", "1,0,1"],
        &["radius 0 of body 2"],
    );
    refused(
        &["--positions", "(0,0),(3,0),(6,0)", "--radii", "1,1,1"],
        &["no two balls touch"],
    );
    refused(
        &["--contacts", "1-4 @ 0deg"],
        &["'1-4 @ 0deg'", "body 4 does not exist"],
    );
    refused(
        &["--contacts", "1-1 @ 0deg"],
        &["'1-1 @ 0deg'", "two different bodies"],
    );
    refused(&["--contacts", "1-2"], &["'1-2'", "A-B @ N"]);
    refused(
        &["--contacts", "1-2 @ (1,0,0)"],
        &["3 components", "the velocities 2"],
    );
    refused(
        &["--contacts", "1-2 @ 0deg", "-e", "1.5"],
        &["e = 3/2", "[0, 1]"],
    );
    refused(
        &["--contacts", "1-2 @ 30deg", "--exact"],
        &["--exact", "irrational", "1-2"],
    );
    refused(&["--sequential"], &["--sequential needs the contacts"]);
    let many = 102;
    let chain: Vec<String> = (0..many).map(|i| format!("({},0)", 2 * i)).collect();
    let ones = vec!["1"; many].join(",");
    let v = format!("(1,0){}", ",0".repeat(many - 1));
    solve_refused(
        &[
            "-m",
            &ones,
            "-v",
            &v,
            "--positions",
            &chain.join(","),
            "--radii",
            &ones,
        ],
        &["101 contacts", "at most 100"],
    );
    refused(
        &["--radii", "1,1,1"],
        &["--radii needs --impact-parameter", "--positions"],
    );
    refused(&["--contacts", "1-2 @ 0deg", "--fin", "?,?,?"], &["--fin"]);
    solve_refused(
        &["-m", "1,?,1", "-v", "(1,0),0,0", "--contacts", "1-2 @ 0deg"],
        &["known masses, velocities and e"],
    );
}
