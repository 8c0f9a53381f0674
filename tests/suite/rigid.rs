//! Rigid bodies at impact (physics.md section 7, issue 26), against closed forms derived in each
//! test's comments, exact arithmetic done here, and metamorphic relations (bodies swapped, a
//! Galilean boost, the scene turned, other units). Every JSON report read here passes
//! `invariants`: no null (NaN or infinity would be null), and energy gained only where the
//! report says the FIN is not physical.

use crate::common;

use collide::rational::{Q, from_f64, int, ratio, to_f64};
use collide::rigid::algebra::{self, Mat};
use collide::rigid::body::{Body, Mobility, Motion};
use collide::rigid::impact::Problem;
use collide::rigid::jacobian::{Contact, Pair};
use collide::rigid::laws::{Law, Mode, Tangential};
use collide::rigid::outcome::{Energy, Outcome};
use common::run;
use proptest::prelude::*;
use serde_json::Value;

/// Checks the invariants of every rigid JSON report: no null anywhere (a NaN or an infinity
/// would be written as null), and energy gained only with `"physical": false` and a reason.
fn invariants(j: &Value) {
    fn walk(v: &Value, path: &str) {
        match v {
            Value::Null => panic!("null at {path}"),
            Value::Array(a) => a
                .iter()
                .enumerate()
                .for_each(|(i, x)| walk(x, &format!("{path}.{i}"))),
            Value::Object(m) => m.iter().for_each(|(k, x)| walk(x, &format!("{path}.{k}"))),
            Value::Number(n) => assert!(n.as_f64().unwrap().is_finite(), "{path}"),
            _ => {}
        }
    }
    walk(j, "");
    if let Some(e) = j.get("energy") {
        let gained = e.get("gained").is_some();
        assert_eq!(gained, j["physical"] == false, "{j}");
        assert_eq!(gained, j.get("paradox").is_some(), "{j}");
        assert!(gained || e.get("lost").is_some(), "{j}");
    }
}

/// `collide solve ARGS --format json`, its exit status, the invariants checked.
fn solve(args: &[&str]) -> (i32, Value) {
    let mut a = vec!["solve"];
    a.extend_from_slice(args);
    a.extend(["--format", "json"]);
    let (code, out, err) = run(&a);
    assert!(code == 0 || code == 1, "{args:?}: exit {code}: {err}");
    let j: Value = serde_json::from_str(&out).unwrap();
    invariants(&j);
    (code, j)
}

fn json(args: &[&str]) -> Value {
    let (code, j) = solve(args);
    assert_eq!(code, 0, "{args:?}");
    j
}

/// A rigid scene from text, run: exit status and report.
fn scene(name: &str, text: &str) -> (i32, Value) {
    let dir = common_dir();
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).unwrap();
    let (code, out, err) = run(&["scene", path.to_str().unwrap(), "--format", "json"]);
    assert!(code == 0 || code == 1, "{name}: exit {code}: {err}");
    let j: Value = serde_json::from_str(&out).unwrap();
    invariants(&j["report"]);
    (code, j["report"].clone())
}

fn common_dir() -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("collide-rigid-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// An exact value of the JSON (`--exact`: a fraction string).
fn q(v: &Value) -> Q {
    match v {
        Value::String(s) => s.parse::<collide::number::Number>().unwrap().exact(),
        Value::Number(n) => from_f64(n.as_f64().unwrap()),
        other => panic!("not a number: {other}"),
    }
}

fn f(v: &Value) -> f64 {
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
        let bq: Q = b.parse::<collide::number::Number>().unwrap().exact();
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

/// The planar scene of a spinning disk against a spinning box, exact: bodies in the order
/// asked (the normal turned around when swapped), every velocity boosted by `w`, or the whole
/// scene turned a quarter, `(x, y) -> (-y, x)`.
fn two_bodies(swap: bool, w: [i64; 2], turn: bool, mu: &str) -> String {
    let t = |x: i64, y: i64| if turn { [-y, x] } else { [x, y] };
    let body = |m: i64, p: [i64; 2], v: [i64; 2], omega: i64, shape: &str| {
        format!(
            "[[body]]\nmass = {m}\nposition = [{}, {}]\nvelocity = [{}, {}]\nomega = {omega}\nshape = \"{shape}\"\n",
            p[0],
            p[1],
            v[0] + w[0],
            v[1] + w[1]
        )
    };
    let ball = body(2, t(-1, 2), t(4, -1), 3, "disk 1");
    let target = body(5, t(1, 0), t(0, 0), -1, "box (2,6)");
    let (first, second, sign) = if swap {
        (target, ball, -1)
    } else {
        (ball, target, 1)
    };
    let (c, n) = (t(0, 2), t(1, 0));
    format!(
        "exact = true\n{first}{second}[contact]\npoint = [{}, {}]\nnormal = [{}, {}]\n\
         restitution = \"1/2\"\nfriction = \"{mu}\"\n",
        c[0],
        c[1],
        sign * n[0],
        sign * n[1]
    )
}

#[test]
fn metamorphic_swap_boost_turn() {
    // Swapping the bodies (and turning the normal around) swaps the answer; a Galilean boost w
    // adds w to every final velocity (spins and energy lost unchanged); a quarter turn of the
    // scene turns every vector and keeps every spin (about z, a turn in the plane).
    for mu in ["0", "1/10", "2"] {
        let (_, base) = scene("base", &two_bodies(false, [0, 0], false, mu));
        let (_, swapped) = scene("swapped", &two_bodies(true, [0, 0], false, mu));
        assert_eq!(base["fin"][0], swapped["fin"][1], "mu {mu}");
        assert_eq!(base["fin"][1], swapped["fin"][0], "mu {mu}");
        assert_eq!(base["energy"]["lost"], swapped["energy"]["lost"]);
        assert_eq!(base["contact"], swapped["contact"]);
        let (_, boosted) = scene("boosted", &two_bodies(false, [7, -3], false, mu));
        for b in 0..2 {
            assert_eq!(
                q(&boosted["fin"][b]["v"][0]),
                q(&base["fin"][b]["v"][0]) + int(7)
            );
            assert_eq!(
                q(&boosted["fin"][b]["v"][1]),
                q(&base["fin"][b]["v"][1]) - int(3)
            );
            assert_eq!(boosted["fin"][b]["omega"], base["fin"][b]["omega"]);
        }
        assert_eq!(boosted["energy"]["lost"], base["energy"]["lost"]);
        let (_, turned) = scene("turned", &two_bodies(false, [0, 0], true, mu));
        for b in 0..2 {
            assert_eq!(q(&turned["fin"][b]["v"][0]), -q(&base["fin"][b]["v"][1]));
            assert_eq!(q(&turned["fin"][b]["v"][1]), q(&base["fin"][b]["v"][0]));
            assert_eq!(turned["fin"][b]["omega"], base["fin"][b]["omega"]);
        }
    }
}

/// A free body in the plane or in space: mass, centre, inertia (`None`: a particle).
fn free(i: usize, m: Q, x: Vec<Q>, inertia: Option<Mat>) -> Body {
    Body::new(i, Some(m), x, Mobility::Free { inertia }, None).unwrap()
}

/// A random symmetric positive definite 3x3 tensor `A^T A + 1/10`.
fn spd(a: &[f64]) -> Mat {
    let m: Mat = (0..3)
        .map(|i| (0..3).map(|j| from_f64(a[3 * i + j])).collect())
        .collect();
    let mut t = algebra::mul(&algebra::transpose(&m), &m);
    for (k, row) in t.iter_mut().enumerate() {
        row[k] += ratio(1, 10);
    }
    t
}

/// The outcome's final values as binary64 (the report rounds once), back in exact arithmetic.
fn rounded(o: &Outcome) -> [Motion; 2] {
    let r = |v: &[Q]| -> Vec<Q> { v.iter().map(|x| from_f64(to_f64(x).unwrap())).collect() };
    [0, 1].map(|i| Motion {
        v: r(&o.fin[i].v),
        omega: r(&o.fin[i].omega),
    })
}

/// `|a - b| / scale` in units of binary64's epsilon.
fn ulps(a: &Q, b: &Q, scale: &Q) -> f64 {
    let d = to_f64(&(a - b)).unwrap().abs();
    d / (f64::EPSILON * to_f64(scale).unwrap().abs().max(f64::MIN_POSITIVE))
}

fn random_problem(dim: usize, data: &[f64], e: Q, tangential: Tangential, law: Law) -> Problem {
    let v = |k: usize, n: usize| -> Vec<Q> { (0..n).map(|i| from_f64(data[k + i])).collect() };
    let rot = algebra::rot_dim(dim);
    let inertia = |k: usize| -> Mat {
        if dim == 2 {
            vec![vec![from_f64(data[k].abs() + 0.1)]]
        } else {
            spd(&data[k..k + 9])
        }
    };
    let bodies = [
        free(
            1,
            from_f64(data[0].abs() + 0.1),
            v(2, dim),
            Some(inertia(20)),
        ),
        free(
            2,
            from_f64(data[1].abs() + 0.1),
            v(5, dim),
            Some(inertia(30)),
        ),
    ];
    let motions = [
        Motion {
            v: v(8, dim),
            omega: v(11, rot),
        },
        Motion {
            v: v(14, dim),
            omega: v(17, rot),
        },
    ];
    let pair = Pair {
        bodies,
        contact: Contact {
            point: v(40, dim),
            normal: v(44, dim),
        },
    };
    Problem {
        pair,
        motions,
        e,
        law,
        tangential,
        approx: false,
        rtol: 1e-10,
        si: false,
    }
}

fn data() -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec(-3.0f64..3.0, 48)
}

proptest! {
    #![proptest_config(common::proptest_config(200))]

    /// Frictionless impacts in the plane and in space: linear momentum and angular momentum
    /// (about the contact point; no external impulse) of the rounded FIN agree with IN to 4 ulps
    /// of the momenta's scale, and for e = 1 the energy to 4 ulps: the only error is FIN's
    /// one rounding.
    #[test]
    fn frictionless_impacts_keep_momentum_and_elastic_energy(d in data(), dim in 2usize..4) {
        let p = random_problem(dim, &d, Q::ONE, Tangential::Smooth, Law::Poisson);
        let Ok(o) = collide::rigid::solve(p) else { return Ok(()) };
        let fin = rounded(&o);
        let scale_p = o.bodies().iter().zip(o.v_in()).chain(o.bodies().iter().zip(&fin))
            .map(|(b, m)| b.momentum(m).iter().fold(Q::ZERO, |s, x| s + x.clone() * x))
            .fold(Q::ZERO, |s, x| if x > s { x } else { s });
        let scale_p = from_f64(to_f64(&scale_p).unwrap().sqrt());
        let (pi, pf) = (o.momentum(o.v_in()), o.momentum(&fin));
        for k in 0..dim {
            prop_assert!(ulps(&pi[k], &pf[k], &scale_p) <= 4.0, "P[{}]", k);
        }
        let c = o.problem.pair.contact.point.clone();
        let (li, lf) = (o.angular(o.v_in(), &c), o.angular(&fin, &c));
        // Angular momentum's scale: |r| |p| + |I omega| with |r| up to a few units.
        let lscale = li.iter().chain(&lf).fold(Q::ZERO, |s, x| s + x.clone() * x);
        let lscale = from_f64(to_f64(&lscale).unwrap().sqrt() + 10.0 * to_f64(&scale_p).unwrap());
        for k in 0..li.len() {
            prop_assert!(ulps(&li[k], &lf[k], &lscale) <= 4.0, "L[{}]", k);
        }
        let (ki, kf) = (o.ke_in(), o.kinetic(&fin));
        prop_assert!(ulps(&ki, &kf, &ki) <= 4.0, "KE {} {}", to_f64(&ki).unwrap(), to_f64(&kf).unwrap());
    }

    /// Stronge's energetic law never creates energy on random frictional impacts in the plane
    /// (exact, Routh) and in space (the ODE, within its error estimate); Newton's law is
    /// flagged exactly when its FIN has more energy than IN.
    #[test]
    fn stronge_never_gains_and_newton_is_flagged(d in data(), mu in 0.05f64..2.0, e in 0.0f64..1.0, dim in 2usize..4) {
        let mu = from_f64(mu);
        let e = from_f64(e);
        let p = random_problem(dim, &d, e.clone(), Tangential::Coulomb(mu.clone()), Law::Stronge);
        if let Ok(o) = collide::rigid::solve(p) {
            prop_assert!(!matches!(o.energy(), Energy::Gained(_)), "{:?}", o.energy());
            prop_assert!(o.paradox().is_none());
        }
        if dim == 2 {
            let p = random_problem(dim, &d, e, Tangential::Coulomb(mu), Law::Newton);
            if let Ok(o) = collide::rigid::solve(p) {
                let gained = o.ke_fin() > o.ke_in();
                prop_assert_eq!(gained, o.paradox().is_some());
                prop_assert_eq!(gained, matches!(o.energy(), Energy::Gained(_)));
            }
        }
    }
}

#[test]
fn the_ode_in_space_agrees_with_routh_in_the_plane() {
    // The same impact as a planar scene (Routh, exact) and as a scene in space with every z
    // zero (the ODE): the slip stays in the plane, so the answers agree to the ODE's accuracy,
    // and the reported error estimate bounds the actual error of the impulse.
    for (mu, law) in [("0.2", "poisson"), ("0.6", "stronge"), ("1.5", "newton")] {
        let plane = format!(
            "[[body]]\nmass = 2\nposition = [-1, 1]\nvelocity = [3, 1]\nomega = 2\ninertia = 1\n\
             [[body]]\nmass = 3\nposition = [1, -1]\nvelocity = [-1, 0]\nomega = -1\ninertia = 2\n\
             [contact]\npoint = [0, 0]\nnormal = [2, 1]\nrestitution = 0.6\nfriction = {mu}\nlaw = \"{law}\"\n"
        );
        let space = format!(
            "[[body]]\nmass = 2\nposition = [-1, 1, 0]\nvelocity = [3, 1, 0]\nomega = [0, 0, 2]\ninertia = [1, 1, 1]\n\
             [[body]]\nmass = 3\nposition = [1, -1, 0]\nvelocity = [-1, 0, 0]\nomega = [0, 0, -1]\ninertia = [2, 2, 2]\n\
             [contact]\npoint = [0, 0, 0]\nnormal = [2, 1, 0]\nrestitution = 0.6\nfriction = {mu}\nlaw = \"{law}\"\n"
        );
        let (_, a) = scene("plane-ode", &plane);
        let (_, b) = scene("space-ode", &space);
        assert_eq!(a["contact"], b["contact"], "mu {mu}");
        let size = f(&a["impulse"]["normal"]).hypot(f(&a["impulse"]["tangential"]));
        let err = (f(&a["impulse"]["vector"][0]) - f(&b["impulse"]["vector"][0]))
            .hypot(f(&a["impulse"]["vector"][1]) - f(&b["impulse"]["vector"][1]))
            / size;
        let estimate = f(&b["ode"]["error_estimate"]);
        assert!(
            err <= estimate.max(1e-13) * 10.0,
            "mu {mu} {law}: error {err}, estimate {estimate}"
        );
        assert!(err < 1e-9, "mu {mu}: {err}");
        assert!(f(&b["ode"]["seconds"]) > 0.0);
        assert_eq!(f(&b["impulse"]["vector"][2]), 0.0);
    }
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
        let mut a = vec!["solve"];
        a.extend(args.iter());
        let out = common::stdout(&a);
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
fn a_scene_in_space_turns_with_its_axes() {
    // Cycling the axes (x, y, z) -> (y, z, x) of every vector and tensor is a rotation: every
    // final velocity and spin cycles the same way, exactly without friction and to the ODE's
    // accuracy with it (the slip turns: the contact frame is built from other axes).
    let scene_of = |cycle: bool, mu: &str| {
        let c = |v: [&str; 3]| -> String {
            let v = if cycle { [v[2], v[0], v[1]] } else { v };
            format!("[{}, {}, {}]", v[0], v[1], v[2])
        };
        let inertia = if cycle {
            "[[1.5, 0, 0.1], [0, 1, 0.2], [0.1, 0.2, 2]]"
        } else {
            "[[1, 0.2, 0], [0.2, 2, 0.1], [0, 0.1, 1.5]]"
        };
        format!(
            "[[body]]\nmass = 1\nposition = {}\nvelocity = {}\nomega = {}\nshape = \"sphere 1\"\n\
             [[body]]\nmass = 2\nposition = {}\nvelocity = {}\ninertia = {inertia}\n\
             [contact]\npoint = {}\nnormal = {}\nrestitution = 0.7\nfriction = {mu}\nlaw = \"stronge\"\n",
            c(["0", "0", "1"]),
            c(["1", "0.5", "-2"]),
            c(["3", "-1", "2"]),
            c(["0.3", "0.2", "-1"]),
            c(["0", "0", "0"]),
            c(["0", "0", "0"]),
            c(["0", "0", "-1"]),
        )
    };
    for mu in ["0", "0.4"] {
        let (_, a) = scene("axes", &scene_of(false, mu));
        let (_, b) = scene("axes-cycled", &scene_of(true, mu));
        let tol = if mu == "0" { 0.0 } else { 1e-9 };
        for body in 0..2 {
            for key in ["v", "omega"] {
                let x = &a["fin"][body][key];
                let y = &b["fin"][body][key];
                for k in 0..3 {
                    let (p, q) = (f(&x[k]), f(&y[(k + 1) % 3]));
                    assert!(
                        (p - q).abs() <= tol,
                        "mu {mu} body {body} {key}[{k}]: {p} {q}"
                    );
                }
            }
        }
    }
}
