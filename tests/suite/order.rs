//! Bodies in the order the problem names them (issue 27 §2). On a rail with no positions two
//! bodies meet iff their velocities differ, and the one faster in `+x` is behind (on the left),
//! whichever was typed first: momentum and `f2 - f1 = e (v1 - v2)` are the same equations with
//! the labels swapped. So a case typed in the other order is the same collision with every pair
//! swapped, bit for bit; a separation may leave either piece on the right. Only data that truly
//! never meet (equal velocities, a ball moving away from a wall) get a note instead.

use crate::common;

use common::{collide, solve_json, stdout};
use serde_json::{Value, json};

/// `v` with every pair `[body 1, body 2]` swapped (and a diagonal tensor's entries, an
/// ellipse's radii), keys that are not pairs unchanged: what the report of the case typed in the other order must be.
fn swapped(v: &Value) -> Value {
    match v {
        Value::Array(a) if a.len() == 2 && a.iter().all(|x| !x.is_array()) => {
            Value::Array(vec![a[1].clone(), a[0].clone()])
        }
        Value::Array(a) if a.len() == 2 => {
            // [[M11, M12], [M21, M22]] -> [[M22, M21], [M12, M11]].
            let row = |r: &Value| swapped(r);
            Value::Array(vec![row(&a[1]), row(&a[0])])
        }
        // An ellipse's radius a lies along V1, b along V2.
        Value::Object(o) if o.contains_key("a") && o.contains_key("b") => {
            let mut o = o.clone();
            let (a, b) = (o["a"].clone(), o["b"].clone());
            o.insert("a".into(), b);
            o.insert("b".into(), a);
            Value::Object(o)
        }
        Value::Object(o) => Value::Object(o.iter().map(|(k, x)| (k.clone(), swapped(x))).collect()),
        other => other.clone(),
    }
}

#[test]
fn case_a_typed_vw_first_is_case_a_with_the_bodies_swapped() {
    // Fig. 1.3: M = diag(4, 1), V_IN = (60, 10), elastic FIN (40, 90), KE 7250, crunch 1000.
    // Typed VW first, (1, 4) at (10, 60): the VW is ahead, the SUV behind on the left catches it;
    // every pair swapped, every scalar (V_COM 50, crunch 1000, P_total 250) the same, bit for
    // bit. Only the products (X.Y scalar, the outer product transposed as well) are left out.
    for exact in [false, true] {
        let flags = |m: &'static str, v: &'static str| {
            let mut a = vec!["-m", m, "-v", v, "--show"];
            a.push("vectors,momentum,forms,energy,ellipses,changes");
            if exact {
                a.push("--exact");
            }
            a
        };
        let (code, a) = solve_json(&flags("4,1", "60,10"));
        let (code_b, mut b) = solve_json(&flags("1,4", "10,60"));
        assert_eq!((code, code_b), (0, 0));
        assert!(a.get("left").is_none(), "typed left to right: no key {a}");
        assert_eq!(b["left"], 2, "{b}");
        assert_eq!(b["approaching"], true);
        b.as_object_mut().unwrap().remove("left");
        assert_eq!(swapped(&a), b, "exact: {exact}");
        let fin = if exact {
            json!(["90", "40"])
        } else {
            json!([90.0, 40.0])
        };
        assert_eq!(b["fin"], fin);
    }
    // Text: the whole default report, with a note on who is behind, not "move apart".
    let text = stdout(&["solve", "-m", "1,4", "-v", "10,60"]);
    for needle in [
        "FIN  V_FIN    (90, 40)",
        "Quadratic forms",
        "crunch = KE_IN - KE_COM = 1/2 mu (V1 - V2)^2  1000",
        "V1 < V2: body 2 is behind (on the left) and catches body 1",
    ] {
        assert!(text.contains(needle), "{needle}:\n{text}");
    }
    assert!(!text.contains("move apart"), "{text}");
}

#[test]
fn frames_see_the_swapped_case_from_the_swapped_body() {
    // Case A from the SUV initially at rest (w = 60): IN (0, -50), FIN (-20, 30). Typed VW
    // first, the SUV is body 2: rest-in:2 sees IN (-50, 0), FIN (30, -20); e = 1 and the crunch
    // 1000 in every frame.
    let (_, a) = solve_json(&["-m", "4,1", "-v", "60,10", "--frame", "rest-in:1"]);
    let (_, b) = solve_json(&["-m", "1,4", "-v", "10,60", "--frame", "rest-in:2"]);
    assert_eq!(a["in"], json!([0.0, -50.0]));
    assert_eq!(b["in"], json!([-50.0, 0.0]));
    assert_eq!(b["fin"], json!([30.0, -20.0]));
    assert_eq!(b["energy"]["crunch"], 1000.0);
    assert_eq!(b["left"], 2);
    let frames = stdout(&["frames", "-m", "1,4", "-v", "10,60"]);
    assert!(
        frames.contains("crunch = 1/2 mu (V1 - V2)^2 = 1000"),
        "{frames}"
    );
    assert!(
        frames.contains("e = -(FIN1 - FIN2)/(IN1 - IN2) = 1"),
        "{frames}"
    );
}

#[test]
fn a_catch_up_typed_in_reading_order_is_answered() {
    // A 1200 kg car at 10 m/s is rear-ended by an 1800 kg truck at 20 m/s and they lock bumpers:
    // V_COM = (1200 10 + 1800 20) / 3000 = 48000 / 3000 = 16 m/s. Elastic instead:
    // FIN = 2 V_COM - V_IN = (22, 12) m/s (the car pushed ahead, the truck slowed).
    let args = ["-m", "1200 kg,1800 kg", "-v", "10 m/s,20 m/s"];
    let text = stdout(&[&["solve"], &args[..], &["-e", "0"]].concat());
    assert!(
        text.starts_with("FIN: v1' = v2' = 16 m/s (the bodies stick)\n"),
        "{text}"
    );
    let (code, j) = solve_json(&args);
    assert_eq!(code, 0);
    assert_eq!(j["fin"], json!([22.0, 12.0]));
    let text = stdout(&[&["solve"], &args[..]].concat());
    assert!(
        text.starts_with("FIN: v1' = 22 m/s, v2' = 12 m/s\n"),
        "{text}"
    );
}

#[test]
fn unknowns_are_solved_whichever_body_is_typed_first() {
    // Fig. 2.3 ka-whump typed VW first: m = (1, 6), V = (-4, 3), FIN = (6, 4/3), e = 2/3
    // (f2 - f1 = 4/3 - 6 = -14/3 = e (v1 - v2) = 2/3 (-7)). Every pair of unknowns comes back
    // as these fractions; two masses give only their ratio m1/m2 = 1/6.
    let full = ["1", "6", "-4", "3", "6", "4/3", "2/3"];
    let names = ["m1", "m2", "v1", "v2", "f1", "f2", "e"];
    for i in 0..7 {
        for k in (i + 1)..7 {
            let mut v = full.map(String::from);
            v[i] = "?".into();
            v[k] = "?".into();
            let (m, vel, fin) = (
                format!("{},{}", v[0], v[1]),
                format!("{},{}", v[2], v[3]),
                format!("{},{}", v[4], v[5]),
            );
            let mut args = vec!["-m", &m, "-v", &vel, "--fin", &fin, "--exact"];
            args.extend(["-e", &v[6]]);
            let (code, j) = solve_json(&args);
            if i < 2 && k < 2 {
                assert_eq!(code, 2, "two masses: only their ratio");
                continue;
            }
            assert_eq!(code, 0, "{} and {}", names[i], names[k]);
            assert_eq!(
                (&j["solved"][names[i]], &j["solved"][names[k]]),
                (&json!(full[i]), &json!(full[k])),
                "{} and {}",
                names[i],
                names[k]
            );
            assert_eq!(j["left"], 2);
        }
    }
    // Fig. 1.3 read backwards, VW first: the SUV's speed 60 mph and e = 1.
    let (code, j) = solve_json(&[
        "-m",
        "1 ton,4 ton",
        "-v",
        "10 mph,?",
        "--fin",
        "90 mph,40 mph",
    ]);
    assert_eq!(code, 0);
    assert_eq!(j["solved"], json!({"v2": 60.0, "e": 1.0}));
    // Passing through is still refused, in either order: V = (10, 60), FIN (30, 55) gives
    // e = (55 - 30) / (10 - 60) = -1/2.
    let out = collide()
        .args(["solve", "-m", "1,4", "-v", "10,60", "--fin", "30,55"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("e = -1/2 < 0"), "{err}");
}

#[test]
fn a_rifle_fired_bullet_first() {
    // A 4.0 kg rifle fires a 10 g bullet at 550 m/s, typed bullet first: 0 = 0.01 550 + 4 f2,
    // f2 = -5.5/4 = -11/8 m/s. Released: 1/2 0.01 550^2 + 1/2 4 (11/8)^2 = 1512.5 + 3.78125 =
    // 48521/32 J. The bullet ends up on the right: `left` is 2. Typed rifle first, the same
    // numbers swapped and no `left`.
    let args = ["-m", "10 g,4.0 kg", "-v", "0,0", "--fin", "550 m/s,?"];
    let (code, j) = solve_json(&[&args[..], &["--show", "energy", "--exact"]].concat());
    assert_eq!(code, 0);
    assert_eq!(j["event"], "separation");
    assert_eq!(j["solved"], json!({"f2": "-11/8"}));
    assert_eq!(j["energy"]["released"], "48521/32");
    assert_eq!(j["left"], 2);
    let (_, j) = solve_json(&[&args[..], &["--show", "energy"]].concat());
    assert_eq!(j["energy"]["released"], 1516.28125);
    let (code, j) = solve_json(&["-m", "4.0 kg,10 g", "-v", "0,0", "--fin", "?,550 m/s"]);
    assert_eq!(code, 0);
    assert_eq!(j["solved"], json!({"f1": -1.375}));
    assert!(j.get("left").is_none(), "{j}");
    let text = stdout(&[&["solve"], &args[..]].concat());
    assert!(
        text.contains("f1 > f2: body 1 moves off to the right of body 2"),
        "{text}"
    );
    // Equal masses from rest: 2 and -2, either way round.
    let (code, j) = solve_json(&["-m", "1,1", "-v", "0,0", "--fin", "2,?"]);
    assert_eq!((code, &j["fin"]), (0, &json!([2.0, -2.0])));
}

#[test]
fn only_bodies_that_never_meet_get_the_note() {
    // Equal velocities: no collision, FIN = IN, `approaching` false.
    let (code, j) = solve_json(&["-m", "4,1", "-v", "5,5", "--show", "vectors"]);
    assert_eq!((code, &j["approaching"]), (0, &Value::Bool(false)));
    assert_eq!(j["fin"], json!([5.0, 5.0]));
    assert!(j.get("left").is_none(), "{j}");
    let text = stdout(&["solve", "-m", "4,1", "-v", "5,5"]);
    assert!(text.contains("V1 = V2: the bodies never meet"), "{text}");
    // A ball moving away from a wall (the wall's side is typed): still a note.
    let text = stdout(&["solve", "-m", "wall,1", "-v", "0,5"]);
    assert!(text.contains("so they do not meet"), "{text}");
    // A scene checks `left` like any key.
    let scene = "masses = [1, 4]\nvelocities = [10, 60]\n[expect]\nleft = 2\nfin = [90, 40]\n";
    let out = collide()
        .args(["scene", "-"])
        .write_stdin(scene)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
}
