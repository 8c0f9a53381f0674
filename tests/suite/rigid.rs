//! Rigid bodies at impact (physics.md section 7, issue 26), against closed forms derived in each
//! test's comments and exact arithmetic done here; units; bad input; the picture. Symmetries,
//! random impacts and the ODE are in `rigid_symmetry`. Every JSON report read here passes
//! `invariants`: no null (NaN or infinity would be null), and energy gained only where the
//! report says the FIN is not physical.

use crate::common;

use collide::rigid::laws::Mode;
use collide::values::rational::{Q, from_f64, int, ratio};
use common::run;
use serde_json::Value;

/// Checks the invariants of every rigid JSON report: nothing null, NaN or infinite (the net's
/// `all_real`), and energy gained only with `"physical": false` and a reason.
pub(crate) fn invariants(j: &Value) {
    crate::invariants::all_real(j).unwrap();
    if let Some(e) = j.get("energy") {
        let gained = e.get("gained").is_some();
        assert_eq!(gained, j["physical"] == false, "{j}");
        assert_eq!(gained, j.get("paradox").is_some(), "{j}");
        assert!(gained || e.get("lost").is_some(), "{j}");
    }
}

/// `collide solve ARGS --format json`, its exit status, the invariants checked.
pub(crate) fn solve(args: &[&str]) -> (i32, Value) {
    let mut a = vec!["solve"];
    a.extend_from_slice(args);
    a.extend(["--format", "json"]);
    let (code, out, err) = run(&a);
    assert!(code == 0 || code == 1, "{args:?}: exit {code}: {err}");
    let j: Value = serde_json::from_str(&out).unwrap();
    invariants(&j);
    (code, j)
}

pub(crate) fn json(args: &[&str]) -> Value {
    let (code, j) = solve(args);
    assert_eq!(code, 0, "{args:?}");
    j
}

/// A rigid scene from text, run: exit status and report.
pub(crate) fn scene(name: &str, text: &str) -> (i32, Value) {
    let dir = common_dir();
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).unwrap();
    let (code, out, err) = run(&["scene", path.to_str().unwrap(), "--format", "json"]);
    assert!(code == 0 || code == 1, "{name}: exit {code}: {err}");
    let j: Value = serde_json::from_str(&out).unwrap();
    invariants(&j["report"]);
    (code, j["report"].clone())
}

pub(crate) fn common_dir() -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("collide-rigid-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// An exact value of the JSON (`--exact`: a fraction string).
pub(crate) fn q(v: &Value) -> Q {
    match v {
        Value::String(s) => s
            .parse::<collide::values::number::Number>()
            .unwrap()
            .exact(),
        Value::Number(n) => from_f64(n.as_f64().unwrap()),
        other => panic!("not a number: {other}"),
    }
}

pub(crate) fn f(v: &Value) -> f64 {
    v.as_f64().unwrap()
}

#[test]
fn a_free_rod_has_the_effective_mass_of_the_closed_form() {
    // A ball (m) hits a free uniform rod (M, L) at b from its centre, perpendicular: the contact
    // point of the rod moves at v + omega b per unit impulse P: 1/M + b^2/I = 1/M + 12 b^2/(M L^2),
    // so with the ball's 1/m the effective mass is (1/m + 1/M + 12 b^2/(M L^2))^-1.
    for (m, big, l, b) in [
        (1, 4, 2, "1"),
        (3, 5, 6, "-2"),
        (2, 7, 3, "1/3"),
        (1, 1, 1, "0"),
    ] {
        let j = json(&[
            "-m",
            &format!("{m},{big}"),
            "-v",
            "2,0",
            "--target",
            &format!("rod {l}"),
            "--hit-at",
            b,
            "--exact",
        ]);
        let bq: Q = b
            .parse::<collide::values::number::Number>()
            .unwrap()
            .exact();
        let expect =
            Q::ONE / (ratio(1, m) + ratio(1, big) + int(12) * &bq * &bq / (int(big) * int(l * l)));
        assert_eq!(q(&j["m_eff"]), expect, "m {m} M {big} L {l} b {b}");
    }
}

#[test]
fn an_elastic_ball_of_a_quarter_of_the_rods_mass_stops_dead() {
    // Hit at the end (b = L/2) the rod alone has 1/(1/M + 12 (L/2)^2/(M L^2)) = M/4: the 1D
    // collision of the ball (M/4) with an equal effective mass, elastic, swaps the normal
    // velocities: the ball stops, exactly (and in binary64: 0, not 1e-17).
    for (ball, rod, l) in [
        ("1", "4", "2"),
        ("0.25 kg", "1 kg", "1.2 m"),
        ("3", "12", "7"),
    ] {
        for exact in [true, false] {
            let masses = format!("{ball},{rod}");
            let target = format!("rod {l}");
            let v = if ball.contains("kg") {
                "3 m/s,0"
            } else {
                "3,0"
            };
            let mut a = vec![
                "-m", &masses, "-v", v, "--target", &target, "--hit-at", "end",
            ];
            if exact {
                a.push("--exact");
            }
            let j = json(&a);
            assert_eq!(q(&j["fin"][0]["v"][0]), Q::ZERO, "{a:?}");
            assert_eq!(
                q(&j["along_normal"]["masses"][0]),
                q(&j["along_normal"]["masses"][1])
            );
        }
    }
}

#[test]
fn the_centre_of_percussion_feels_no_pivot_impulse() {
    // A rod (M, L) pivoted at its end, hit at d from the pivot by an impulse P: I_p = M L^2/3,
    // omega' = P d / I_p, v_cm' = omega' L/2 = 3 P d/(2 M L), so the pivot gives
    // M v_cm' - P = P (3d/(2L) - 1): zero at d = 2L/3, P/2 at the far end d = L.
    for (l, d, factor) in [
        ("3", "2", ratio(0, 1)),
        ("3", "3", ratio(1, 2)),
        ("6", "1", ratio(-3, 4)),
    ] {
        let j = json(&[
            "-m",
            "1,2",
            "-v",
            "5,0",
            "--target",
            &format!("rod {l}"),
            "--pivot",
            "end",
            "--hit-at",
            d,
            "--exact",
            "-e",
            "1/2",
        ]);
        let p = q(&j["impulse"]["normal"]);
        // The pivot impulse is along x (the impulse's line), per body: [ball, rod].
        assert_eq!(q(&j["pivot_impulse"][1][0]), &p * &factor, "L {l} d {d}");
        assert_eq!(q(&j["pivot_impulse"][1][1]), Q::ZERO);
        assert_eq!(
            q(&j["pivot_impulse"][0][0]),
            Q::ZERO,
            "the ball has no pivot"
        );
    }
    // Text says so.
    let (_, out, _) = run(&[
        "solve", "-m", "1,2", "-v", "5,0", "--target", "rod 3", "--pivot", "end", "--hit-at", "2",
    ]);
    assert!(out.contains("none: the centre of percussion"), "{out}");
}

/// `-m 1,floor`, a sphere of radius R sliding at v (falling at 1) with spin w, friction `mu`.
fn floor(v: &str, w: &str, r: &str, mu: &str, e: &str) -> Value {
    json(&[
        "-m",
        "1,floor",
        "-v",
        &format!("({v},-1),0"),
        "--ball",
        &format!("sphere {r}"),
        "--spin",
        w,
        "--friction",
        mu,
        "-e",
        e,
        "--exact",
    ])
}

#[test]
fn a_sliding_ball_leaves_a_rough_floor_rolling() {
    // Sphere I = 2/5 m R^2 on a floor, contact below: the slip u = v + R omega (omega
    // counterclockwise). A tangential impulse F on the ball changes v by F/m and R omega by
    // R^2 F / I = 5/2 F/m, so u by 7/2 F/m. Enough friction stops the slip: F = -2/7 m u, and
    // v' = v - 2/7 (v + R omega) = (v - 2/5 R omega)/(1 + 2/5): 5v/7 without spin, rolling
    // (v' + R omega' = 0). The normal impulse (Poisson, e) is (1 + e) m, friction used is
    // 2/7 |u| <= mu (1 + e).
    for (v, w, r) in [
        ("1", "0", "1"),
        ("7", "0", "1/2"),
        ("2", "3", "1"),
        ("2", "-10", "1/5"),
    ] {
        let j = floor(v, w, r, "10", "1/2");
        let (vq, wq, rq) = (
            q(&Value::String(v.into())),
            q(&Value::String(w.into())),
            q(&Value::String(r.into())),
        );
        let expect = (&vq - ratio(2, 5) * &rq * &wq) / ratio(7, 5);
        assert_eq!(q(&j["fin"][0]["v"][0]), expect, "v {v} w {w} R {r}");
        let omega = q(&j["fin"][0]["omega"]);
        assert_eq!(q(&j["fin"][0]["v"][0]) + &rq * omega, Q::ZERO, "rolling");
        assert_eq!(j["contact"], "stick");
        assert_eq!(q(&j["fin"][0]["v"][1]), ratio(1, 2), "v_y' = e");
    }
    // 5v/7 without spin, binary64.
    let j = json(&[
        "-m",
        "1,floor",
        "-v",
        "(7,-1),0",
        "--ball",
        "sphere 1",
        "--friction",
        "1",
    ]);
    assert_eq!(f(&j["fin"][0]["v"][0]), 5.0);
}

#[test]
fn too_little_friction_slips_throughout_at_mu_times_the_normal_impulse() {
    // mu (1 + e) m < 2/7 m |u|: the slip never stops; the tangential impulse is mu times the
    // normal one, opposing the slip: P_n = (1 + e) = 3/2, |P_t| = 3/20 with mu = 1/10, and
    // v' = v - 3/20, R omega' = R omega - 5/2 (3/20).
    let j = floor("1", "0", "1", "1/10", "1/2");
    assert_eq!(j["contact"], "slip");
    let (pn, pt) = (q(&j["impulse"]["normal"]), q(&j["impulse"]["tangential"]));
    assert_eq!(pn, ratio(3, 2));
    assert_eq!(pt.clone() * pt, ratio(1, 100) * &pn * &pn);
    assert_eq!(q(&j["fin"][0]["v"][0]), ratio(17, 20));
    assert_eq!(q(&j["fin"][0]["omega"]), -ratio(3, 8));
}

#[test]
fn garwins_superball() {
    // e = 1, beta = 1: the contact's normal and slip velocities reverse. With u = v + R omega and
    // a tangential impulse changing u by 7/2 F/m: u' = -u, F = -4/7 m u, so
    // v' = (3v - 4 R omega)/7 and R omega' = R omega + 5/2 F/m = -(10 v + 3 R omega)/7; energy
    // kept: m v'^2/2 + (2/5) m (R omega')^2/2 = m v^2/2 + (1/5) m (R omega)^2 exactly.
    for (v, w) in [(7, 0), (3, 5), (-2, 1), (1, -4)] {
        let j = json(&[
            "-m",
            "2,floor",
            "-v",
            &format!("({v},-3),0"),
            "--ball",
            "sphere 1",
            "--spin",
            &w.to_string(),
            "--tangential-restitution",
            "1",
            "--exact",
        ]);
        assert_eq!(q(&j["fin"][0]["v"][0]), ratio(3 * v - 4 * w, 7));
        assert_eq!(q(&j["fin"][0]["omega"]), -ratio(10 * v + 3 * w, 7));
        assert_eq!(q(&j["fin"][0]["v"][1]), int(3));
        assert_eq!(q(&j["energy"]["lost"]), Q::ZERO);
    }
}

#[test]
fn garwins_ball_returns_toward_the_hand_from_under_a_table() {
    // Thrown at v (no spin) under a table: floor, table underside, floor. Floor: v1 = 3v/7,
    // R w1 = -10v/7. Underside (contact above, u = v - R w, same 7/2): v2 = (3 v1 + 4 R w1)/7 =
    // -31v/49, R w2 = (10 v1 - 3 R w1)/7 = 60v/49. Floor: v3 = (3 v2 - 4 R w2)/7 = -333v/343:
    // it comes back toward the hand.
    let mut vx = "343".to_string();
    let mut vy = -1i64;
    let mut w = "0".to_string();
    for surface in ["floor", "ceiling", "floor"] {
        let j = json(&[
            "-m",
            &format!("1,{surface}"),
            "-v",
            &format!("({vx},{vy}),0"),
            "--ball",
            "sphere 1",
            "--spin",
            &w,
            "--tangential-restitution",
            "1",
            "--exact",
        ]);
        vx = j["fin"][0]["v"][0].as_str().unwrap().to_string();
        w = j["fin"][0]["omega"].as_str().unwrap().to_string();
        vy = -vy;
    }
    assert_eq!(vx, "-333");
    assert_eq!(w, "130");
}

#[test]
fn through_both_centres_it_is_the_rail_bit_for_bit() {
    // Two spinning disks whose line of centres is the normal: the contact points' normal
    // velocities are the centres' (omega x r is across n), the effective masses are the
    // masses, so FIN is the 1D collision; the spins are untouched.
    for (m, v, e) in [
        ("4,1", "60,10", "1"),
        ("6,1", "3,-4", "2/3"),
        ("0.3,1.7", "0.1,-0.7", "0.9"),
    ] {
        let one: Value = serde_json::from_str(&common::stdout(&[
            "solve", "-m", m, "-v", v, "-e", e, "--format", "json",
        ]))
        .unwrap();
        let vs: Vec<&str> = v.split(',').collect();
        let dir = common_dir();
        let path = dir.join("rail.toml");
        let ms: Vec<&str> = m.split(',').collect();
        std::fs::write(
            &path,
            format!(
                "[[body]]\nmass = {}\nposition = [-1, 0]\nvelocity = [{}, 0]\nomega = 3\nshape = \"disk 1\"\n\
                 [[body]]\nmass = {}\nposition = [2, 0]\nvelocity = [{}, 0]\nomega = -2\nshape = \"disk 2\"\n\
                 [contact]\npoint = [0, 0]\nnormal = [1, 0]\nrestitution = \"{e}\"\n",
                ms[0], vs[0], ms[1], vs[1]
            ),
        )
        .unwrap();
        let (_, two) = {
            let (c, out, err) = run(&["scene", path.to_str().unwrap(), "--format", "json"]);
            assert_eq!(c, 0, "{err}");
            let j: Value = serde_json::from_str(&out).unwrap();
            (c, j["report"].clone())
        };
        invariants(&two);
        for b in 0..2 {
            assert_eq!(
                f(&two["fin"][b]["v"][0]).to_bits(),
                f(&one["fin"][b]).to_bits()
            );
            assert_eq!(f(&two["fin"][b]["v"][1]), 0.0);
        }
        assert_eq!(f(&two["fin"][0]["omega"]), 3.0);
        assert_eq!(f(&two["fin"][1]["omega"]), -2.0);
        assert_eq!(
            f(&two["along_normal"]["crunch"]).to_bits(),
            f(&one["energy"]["crunch"]).to_bits()
        );
    }
}

#[test]
fn newtons_law_creating_energy_is_called_kanes_paradox() {
    // A rod (m = 1, L = 2, I = 1/3) falls at (0, -1) spinning at 1 onto a rough floor (mu = 1),
    // its lower end at the origin, its centre at (3/5, 4/5). In (n, t) = ((0, -1), (1, 0)):
    // K~ = [[52/25, 36/25], [36/25, 73/25]], w0 = (8/5, 4/5). Slip: dw/dl = -K~ (1, 1) =
    // (-88/25, -109/25): it sticks at l = 20/109 (w_n = 104/109), before compression; sticking
    // holds (mu K_tt >= |K_tn|) with l_t' = -36/73 and dw_n/dl = -100/73. Newton ends at
    // w_n = -8/5: l_n = 20/109 + (8/5 + 104/109) 73/100 = 256/125, l_t = -92/125. The rod leaves
    // at (92/125, 131/125) with omega = -23/25: KE 0.9610... > 2/3: 184/625 gained.
    let body = "[[body]]\nmass = 1\nposition = [\"3/5\", \"4/5\"]\nvelocity = [0, -1]\nomega = 1\nshape = \"rod 2\"\n\
                [[body]]\nmass = \"floor\"\n[contact]\npoint = [0, 0]\nnormal = [0, -1]\nrestitution = 1\nfriction = 1\n";
    let (code, j) = scene("kane", &format!("exact = true\n{body}law = \"newton\"\n"));
    assert_eq!(code, 1, "energy created is a failed check");
    assert_eq!(j["physical"], false);
    assert!(j["paradox"].as_str().unwrap().contains("Kane"), "{j}");
    assert_eq!(j["fin"][0]["v"], serde_json::json!(["92/125", "131/125"]));
    assert_eq!(j["fin"][0]["omega"], "-23/25");
    assert_eq!(j["energy"]["gained"], "184/625");
    // Poisson (here) and Stronge (always) lose energy instead.
    for law in ["poisson", "stronge"] {
        let (code, j) = scene(law, &format!("{body}law = \"{law}\"\n"));
        assert_eq!(code, 0);
        assert!(f(&j["energy"]["lost"]) > 0.0, "{law}: {j}");
    }
    let path = common_dir().join("kane-text.toml");
    std::fs::write(&path, format!("{body}law = \"newton\"\n")).unwrap();
    let (code, out, _) = run(&["scene", path.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(out.contains("NOT PHYSICAL: energy gained"), "{out}");
    assert!(out.contains("GAINED"), "{out}");
    assert!(!out.contains("\n  lost "), "{out}");
}

#[test]
fn exact_answers_for_rational_data() {
    // A ball (m = 1, v = 5) hits a free box (M = 3, sides 2 x 4) at height 1 on its left face
    // (x = -1), e = 1/3, frictionless: I = 3 (4 + 16)/12 = 5, lever across n is 1:
    // K_nn = 1 + 1/3 + 1/5 = 23/15, P = (1 + e) 5 / K_nn = (4/3)(5)(15/23) = 100/23;
    // v1' = 5 - 100/23 = 15/23, v2' = (100/23)/3 = 100/69, omega2' = -1 P/I = -20/23.
    let j = json(&[
        "-m",
        "1,3",
        "-v",
        "5,0",
        "--target",
        "box (2,4)",
        "--hit-at",
        "1",
        "-e",
        "1/3",
        "--exact",
    ]);
    assert_eq!(j["fin"][0]["v"], serde_json::json!(["15/23", "0"]));
    assert_eq!(j["fin"][1]["v"], serde_json::json!(["100/69", "0"]));
    assert_eq!(j["fin"][1]["omega"], "-20/23");
    assert_eq!(j["impulse"]["normal"], "100/23");
    // Lost = (1 - e^2) crunch = (8/9) (1/2) (15/23) 25 = 500/69 (frictionless: exactly).
    assert_eq!(q(&j["energy"]["lost"]), ratio(500, 69));
    assert_eq!(q(&j["along_normal"]["crunch"]), ratio(375, 46));
    // rpm is irrational in rad/s: refused with --exact, named.
    let (code, out, err) = run(&[
        "solve",
        "-m",
        "1 kg,floor",
        "-v",
        "(1,-1) m/s,0",
        "--ball",
        "sphere 1 m",
        "--spin",
        "30 rpm",
        "--friction",
        "1",
        "--exact",
    ]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(
        err.contains("30 rpm") && err.contains("irrational"),
        "{err}"
    );
}

#[test]
fn units_convert_exactly() {
    // The same impact in kg, m, rad/s and in g, cm, rpm gives the same SI answer (rpm in rad/s
    // carries the binary64 of pi both ways).
    // Values binary64 holds exactly in both (0.0625 kg = 62.5 g, 0.25 m = 25 cm).
    let a = json(&[
        "-m",
        "0.0625 kg,floor",
        "-v",
        "(3,-4) m/s,0",
        "--ball",
        "sphere 0.25 m",
        "--spin",
        "20 rad/s",
        "--friction",
        "0.3",
    ]);
    let b = json(&[
        "-m",
        "62.5 g,floor",
        "-v",
        "(300,-400) cm/s,0",
        "--ball",
        "sphere 25 cm",
        "--spin",
        "20 rad/s",
        "--friction",
        "0.3",
    ]);
    assert_eq!(a["fin"], b["fin"]);
    assert_eq!(a["units"]["energy"], "J");
    let c = json(&[
        "-m",
        "0.06 kg,floor",
        "-v",
        "(3,-4) m/s,0",
        "--ball",
        "sphere 0.03 m",
        "--spin",
        "300 rpm",
        "--friction",
        "0.3",
    ]);
    assert_eq!(f(&c["in"][0]["omega"]), 10.0 * std::f64::consts::PI);
    let (code, out, err) = run(&[
        "solve",
        "-m",
        "0.06 kg,floor",
        "-v",
        "(3,-4),0",
        "--ball",
        "sphere 3 cm",
    ]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(err.contains("'(3,-4)' has no unit"), "{err}");
}

#[test]
fn bad_input_is_named() {
    for (args, says) in [
        (
            vec!["-m", "1,2", "-v", "1,0", "--target", "cone 1"],
            "expected 'rod L'",
        ),
        (
            vec![
                "-m", "1,2", "-v", "1,0", "--target", "rod 1", "--hit-at", "2",
            ],
            "off the target",
        ),
        (
            vec!["-m", "1,2", "-v", "1,0", "--target", "rod 1", "-e", "3/2"],
            "must be in [0, 1]",
        ),
        (
            vec![
                "-m", "1,2", "-v", "1,0", "--target", "rod 1", "--pivot", "end",
            ],
            "give --hit-at",
        ),
        (
            vec!["-m", "1,floor", "-v", "1,0", "--friction", "1"],
            "as a vector",
        ),
        (
            vec!["-m", "1,floor", "-v", "(1,-1),0", "--spin", "2"],
            "a point particle has no spin",
        ),
        (
            vec![
                "-m",
                "1,2",
                "-v",
                "1,0",
                "--target",
                "rod 1",
                "--friction",
                "-1",
            ],
            "friction -1",
        ),
        (
            vec![
                "-m", "1,2", "-v", "1,0", "--target", "rod 1", "--show", "ellipses",
            ],
            "--show ellipses",
        ),
        (
            vec![
                "-m", "1,2", "-v", "1,0", "--target", "rod 1", "--spin", "3 rpn",
            ],
            "rpn",
        ),
    ] {
        let mut a = vec!["solve"];
        a.extend(args.iter());
        let (code, out, err) = run(&a);
        assert_eq!((code, out.as_str()), (2, ""), "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    // collide plot's line pictures are refused for a rigid impact, in one sentence.
    let (code, out, err) = run(&[
        "plot", "-m", "1,4", "-v", "3,0", "--target", "rod 2", "--hit-at", "end", "--term",
    ]);
    assert_eq!((code, out.as_str()), (2, ""), "{err}");
    assert!(
        err.contains("a rigid impact is drawn as its bodies and its impulse plane"),
        "{err}"
    );
    // A scene: unknown keys with file and line.
    let path = common_dir().join("bad.toml");
    std::fs::write(&path, "[[body]]\nmass = 1\nspeed = 3\n[[body]]\nmass = \"wall\"\n[contact]\npoint = [0, 0]\nnormal = [1, 0]\n").unwrap();
    let (code, out, err) = run(&["scene", path.to_str().unwrap()]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(err.contains("bad.toml:3") && err.contains("speed"), "{err}");
    // A body's problem at its table.
    std::fs::write(&path, "[[body]]\nmass = 1\n[[body]]\nmass = 2\nshape = \"disk 1\"\ninertia = 3\n[contact]\npoint = [0, 0]\nnormal = [1, 0]\n").unwrap();
    let (code, _, err) = run(&["scene", path.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        err.contains("bad.toml:3:1: body 2: give its inertia or its shape"),
        "{err}"
    );
    // Bodies that do not approach: a note, no FIN.
    let (code, j) = solve(&["-m", "1,2", "-v", "-1,0", "--target", "rod 1"]);
    assert_eq!(code, 0);
    assert_eq!(j["approaching"], false);
}

#[test]
fn text_fits_80_columns_and_has_every_section() {
    for args in [
        vec![
            "-m",
            "0.05 kg,2 kg",
            "-v",
            "10 m/s,0",
            "--target",
            "door 0.9 m",
            "--pivot",
            "end",
            "--hit-at",
            "0.8 m",
            "--show",
            "all",
        ],
        vec![
            "-m",
            "0.06 kg,floor",
            "-v",
            "(3,-4) m/s,0",
            "--ball",
            "sphere 3 cm",
            "--spin",
            "300 rpm",
            "--friction",
            "0.3",
            "--show",
            "all",
        ],
        vec![
            "-m",
            "1,2",
            "-v",
            "1,0",
            "--target",
            "disk 1",
            "--hit-at",
            "0.6",
            "--friction",
            "0.5",
            "--law",
            "stronge",
            "--show",
            "all",
        ],
    ] {
        // As a user runs it: COLUMNS unset (the other tests' text is as wide as it comes).
        let run = common::collide_at_default_width()
            .arg("solve")
            .args(&args)
            .output()
            .unwrap();
        assert!(run.status.success(), "{args:?}");
        let out = String::from_utf8(run.stdout).unwrap();
        for line in out.lines() {
            assert!(line.chars().count() <= 80, "{args:?}: {line}");
        }
        for heading in [
            "Impulse at the contact",
            "Along the normal",
            "Velocities and spins",
            "Momentum",
            "inertia tensor",
            "Energy",
        ] {
            assert!(out.contains(heading), "{args:?}: {heading}");
        }
    }
}

#[test]
fn the_picture_draws_bodies_contact_and_the_impulse_plane() {
    let out = common::stdout(&[
        "plot",
        "-m",
        "1,floor",
        "-v",
        "(1,-1),0",
        "--ball",
        "sphere 0.3",
        "--friction",
        "0.3",
        "--spin",
        "2",
    ]);
    let doc = roxmltree::Document::parse(&out).expect("well-formed SVG");
    let ids: Vec<&str> = doc
        .descendants()
        .filter_map(|n| n.attribute("id"))
        .collect();
    for id in [
        "body-1",
        "body-2",
        "contact",
        "normal",
        "v1",
        "v1-fin",
        "impulse-path",
        "compression-line",
        "sticking-line",
        "cone-up",
    ] {
        assert!(ids.contains(&id), "{id} missing: {ids:?}");
    }
    // The slip 1 + 0.3 * 2 = 1.6 stops after a tangential impulse of 1.6 / (7/2) = 0.457, within
    // mu P_n = 0.6: the subtitle names the contact as the text report does.
    let texts: String = doc.descendants().filter_map(|n| n.text()).collect();
    assert!(texts.contains("law poisson; contact: stick"), "{texts}");
    // The impulse path ends at the reported impulse: (P_n, P_t) = (2, 2/7 (1.6)...) read from
    // JSON, drawn inside the panel.
    let path = doc
        .descendants()
        .find(|n| n.attribute("id") == Some("impulse-path"))
        .unwrap();
    for p in path.attribute("points").unwrap().split(' ') {
        let (x, y) = p.split_once(',').unwrap();
        let (x, y): (f64, f64) = (x.parse().unwrap(), y.parse().unwrap());
        assert!(
            (470.0..=850.0).contains(&x) && (80.0..=460.0).contains(&y),
            "{p}"
        );
    }
    let j = json(&[
        "-m",
        "1,floor",
        "-v",
        "(1,-1),0",
        "--ball",
        "sphere 0.3",
        "--friction",
        "0.3",
        "--spin",
        "2",
    ]);
    assert_eq!(j["contact"], "stick");
    let _ = Mode::Stick;
}

#[test]
fn a_tiny_inertia_is_refused_not_printed_as_zero() {
    // Issue 41: a 4 kg rod of 1e-308 has I = 4 (1e-308)^2 / 12 = 3.3e-617, below binary64: it
    // printed `I_cm = 0` while the spin came from the true value. Refused in binary64 output,
    // named; --exact prints it (1/3 of 1e-616).
    let args = [
        "-m",
        "1,4",
        "-v",
        "3,0",
        "--target",
        "rod 1e-308",
        "--hit-at",
        "1e-309",
    ];
    common::solve_refused(&args, &["body 2", "I_cm = 3.33333e-617", "--exact"]);
    let (code, j) = solve(&[&args[..], &["--exact"]].concat());
    assert_eq!(code, 0);
    let third = format!("1/3{}", "0".repeat(616));
    assert_eq!(j["bodies"][1]["inertia"], serde_json::json!(third), "{j}");
}
