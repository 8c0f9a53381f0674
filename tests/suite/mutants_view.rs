//! The page's Rust (`src/view/`) under mutation (issue 46, the sample of `benches/mutants.sh
//! view`): a test for each mutant the sample missed, in process (the library's answers, what
//! the WebAssembly module answers in the page), against values derived by hand.

use serde_json::{Value, json};

use super::view::ask;

/// A pair of the picture's JSON.
fn pair(v: &Value) -> [f64; 2] {
    [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
}

#[test]
fn the_rigid_picture_is_the_hand_derived_rod() {
    // view_rigid.rs's rod, now the panel's picture rather than its tables (which only the
    // browser reads): a point mass m = 1 at v = 3 hits a free uniform rod (M = 2, L = 2, I = M
    // L^2/12 = 2/3) perpendicularly at its end, r = 1 from its centre, e = 1. Effective mass
    // 1/(1/M + r^2/I) = 1/2; along n = (1, 0) the rail's elastic collision of 1 and 1/2: COM =
    // 3/(3/2) = 2, FIN = 2 COM - IN = (1, 4), impulse P = 1 (3 - 1) = 2 on the rod. The rod's
    // centre leaves at P/M = 1, turning at omega = -P r/I = -3 (its top end hit from the
    // left). The rod stands along y about the origin, hit at its top end (0, 1), where the
    // point is. Every value a small integer or a half: exact in binary64, compared exactly.
    let a = ask(
        json!({"op": "rigid", "m1": "1", "m2": "2", "v1": "3", "target": "rod 2",
                       "hit_at": "end", "e": "1"}),
    );
    assert_eq!(a["ok"], true, "{a}");
    let p = &a["picture"];
    let (ball, rod) = (&p["bodies"][0], &p["bodies"][1]);
    assert_eq!(ball["kind"], "point");
    assert_eq!(rod["kind"], "rod");
    assert_eq!(rod["sizes"], json!([2.0]));
    assert_eq!(
        (ball["mass"].as_f64(), rod["mass"].as_f64()),
        (Some(1.0), Some(2.0))
    );
    assert_eq!(pair(&ball["position"]), [0.0, 1.0]);
    assert_eq!(pair(&rod["position"]), [0.0, 0.0]);
    assert_eq!(pair(&p["point"]), [0.0, 1.0]);
    assert_eq!(pair(&ball["v_in"]), [3.0, 0.0]);
    assert_eq!(pair(&ball["v_fin"]), [1.0, 0.0]);
    assert_eq!(pair(&rod["v_in"]), [0.0, 0.0]);
    assert_eq!(pair(&rod["v_fin"]), [1.0, 0.0]);
    assert_eq!(
        (rod["omega_in"].as_f64(), rod["omega_fin"].as_f64()),
        (Some(0.0), Some(-3.0))
    );
    assert_eq!(rod["pivot"], Value::Null);
    assert_eq!(pair(&p["normal"]), [1.0, 0.0]);
    assert_eq!(pair(&p["tangent"]), [0.0, 1.0]);
    assert_eq!(pair(&p["impulse"]), [2.0, 0.0]);
    assert_eq!(
        (p["impulse_n"].as_f64(), p["impulse_t"].as_f64()),
        (Some(2.0), Some(0.0))
    );
    assert_eq!(p["contact"], "smooth");
    assert_eq!(p["masses"], json!([1.0, 0.5]));
    assert_eq!(pair(&p["in"]), [3.0, 0.0]);
    assert_eq!(p["com"], 2.0);
    assert_eq!(pair(&p["fin"]), [1.0, 4.0]);
    assert_eq!(p["e_along"], 1.0);
}

#[test]
fn a_control_character_in_a_scene_string_is_escaped() {
    // TOML's basic strings take no control character but the tab: each is written \uXXXX.
    let toml = collide::view::shell::toml_value;
    assert_eq!(toml("a\u{1}b"), "\"a\\u0001b\"");
    assert_eq!(toml("6 m/s\u{7f}"), "\"6 m/s\\u007F\"");
    assert_eq!(toml("x\ny"), "\"x\\u000Ay\"");
}
