//! `--fin` in rigid problems (`src/rigid/fin.rs`, issue 42 sections 2 and 5) under metamorphic
//! relations, each base case first checked against its hand value (derived in `fin_known.rs`
//! and restated here):
//! - other units: masses in g, lengths in cm, speeds in cm/s or km/h. The typed values differ by
//!   the exact factors 1000, 100, 100 and 3.6, so their SI values are the same rationals, and the
//!   report (in SI: the solved e, mass, mu or speed, every velocity, spin, impulse and energy)
//!   must be the same bit for bit, in binary64 and under `--exact`;
//! - the geometry reflected (a rod across the x axis: the hit point, the pivot and the
//!   velocities' y negated; a ball on a floor across the y axis: the velocities' x negated):
//!   e, the mass, mu and speeds unchanged bit for bit, the reflected component of every position
//!   and velocity, every spin and the tangential impulse negated, the check's residual the same
//!   size (binary64 arithmetic is symmetric in sign, so no ulp is allowed either way);
//! - the known given on the other body: the same e exactly, within 1 ulp in binary64.

use serde_json::Value;

use crate::common::assert_ulps;
use crate::rigid::{f, json, q};

use collide::values::rational::{Q, int, ratio};

/// The report of `collide solve ARGS` in JSON (exit 0, the invariants checked), `--exact` too
/// when asked.
fn report(args: &[&str], exact: bool) -> Value {
    let mut a = args.to_vec();
    if exact {
        a.push("--exact");
    }
    json(&a)
}

/// Keys whose value is a vector (or, `pivot_impulse`, a list of vectors) in the plane.
const VECTORS: [&str; 8] = [
    "position",
    "point",
    "normal",
    "v",
    "vector",
    "pivot",
    "centre",
    "pivot_impulse",
];

/// Keys whose value changes sign under a reflection: spins (about z) and the impulse along the
/// tangent `t = (-n_y, n_x)`, which a reflection turns around.
const PSEUDO: [&str; 2] = ["omega", "tangential"];

/// `b == -a` for a JSON number (binary64: `==`, so only the sign of a zero may differ) or an
/// exact fraction string.
fn negated(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Number(_), Value::Number(_)) => f(b) == -f(a),
        (Value::String(_), Value::String(_)) => q(b) == -q(a),
        _ => false,
    }
}

/// `|a| == |b|`, for a check's residual (a reflected component's residual changes sign).
fn same_size(a: &Value, b: &Value) -> bool {
    a == b || negated(a, b)
}

/// Asserts that report `b` is report `a` reflected across the axis whose normal is coordinate
/// `axis` (1: across the x axis, y negated; 0: across the y axis, x negated), at `path`.
fn assert_reflected(a: &Value, b: &Value, axis: usize, path: &str) {
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            let keys = |o: &serde_json::Map<String, Value>| o.keys().cloned().collect::<Vec<_>>();
            assert_eq!(keys(x), keys(y), "{path}: the keys");
            for (k, va) in x {
                let vb = &y[k];
                let at = format!("{path}.{k}");
                if k == "units" {
                    // Names of units ("omega": "rad/s"), not values.
                    assert_eq!(va, vb, "{at}");
                } else if VECTORS.contains(&k.as_str()) && va.is_array() {
                    assert_vector(va, vb, axis, &at);
                } else if PSEUDO.contains(&k.as_str()) && !va.is_object() {
                    assert!(negated(va, vb), "{at}: {vb} is not -{va}");
                } else if k == "check" {
                    for (name, r) in va.as_object().unwrap() {
                        assert!(same_size(r, &vb[name]), "{at}.{name}: {r} against {vb}");
                    }
                } else {
                    assert_reflected(va, vb, axis, &at);
                }
            }
        }
        (Value::Array(x), Value::Array(y)) => {
            assert_eq!(x.len(), y.len(), "{path}: the lengths");
            for (i, (va, vb)) in x.iter().zip(y).enumerate() {
                assert_reflected(va, vb, axis, &format!("{path}[{i}]"));
            }
        }
        _ => assert_eq!(a, b, "{path}: not the same bit for bit"),
    }
}

/// A vector (or a list of them) with component `axis` negated and the other the same.
fn assert_vector(a: &Value, b: &Value, axis: usize, path: &str) {
    let (x, y) = (a.as_array().unwrap(), b.as_array().unwrap());
    assert_eq!(x.len(), y.len(), "{path}");
    if x.iter().all(Value::is_array) {
        for (i, (va, vb)) in x.iter().zip(y).enumerate() {
            assert_vector(va, vb, axis, &format!("{path}[{i}]"));
        }
        return;
    }
    assert_eq!(x.len(), 2, "{path}: a vector in the plane");
    for i in 0..2 {
        if i == axis {
            assert!(
                negated(&x[i], &y[i]),
                "{path}[{i}]: {} is not -{}",
                y[i],
                x[i]
            );
        } else {
            assert_eq!(x[i], y[i], "{path}[{i}]: not the same bit for bit");
        }
    }
}

/// One case: its arguments in SI, the same typed in other units, and reflected.
struct Case {
    name: &'static str,
    si: &'static [&'static str],
    units: &'static [&'static [&'static str]],
    reflected: &'static [&'static str],
    /// 1: across the x axis (y negated), 0: across the y axis (x negated).
    axis: usize,
}

/// A 0.1 kg ball at (3, 1) m/s onto the top end of a free 1 kg, 1.2 m rod standing along y,
/// which it leaves at (-0.5, 1) m/s: e = 19/30 (`fin_known.rs`: v1' = 3 - (1 + e) 15/7 along
/// the normal x; the smooth impulse leaves the y component alone).
const ROD_E: Case = Case {
    name: "e from the ball's final velocity",
    si: &[
        "-m",
        "0.1 kg,1 kg",
        "-v",
        "(3,1) m/s,0",
        "--target",
        "rod 1.2 m",
        "--hit-at",
        "end",
        "-e",
        "?",
        "--fin",
        "(-0.5,1) m/s,?",
    ],
    units: &[
        &[
            "-m",
            "100 g,1000 g",
            "-v",
            "(300,100) cm/s,0",
            "--target",
            "rod 120 cm",
            "--hit-at",
            "end",
            "-e",
            "?",
            "--fin",
            "(-50,100) cm/s,?",
        ],
        &[
            "-m",
            "100 g,1 kg",
            "-v",
            "(10.8,3.6) km/h,0",
            "--target",
            "rod 1.2 m",
            "--hit-at",
            "end",
            "-e",
            "?",
            "--fin",
            "(-1.8,3.6) km/h,?",
        ],
    ],
    reflected: &[
        "-m",
        "0.1 kg,1 kg",
        "-v",
        "(3,-1) m/s,0",
        "--target",
        "rod 1.2 m",
        "--hit-at",
        "-0.6 m",
        "-e",
        "?",
        "--fin",
        "(-0.5,-1) m/s,?",
    ],
    axis: 1,
};

/// The same rod with e = 1/2 and the ball left with no x velocity: its mass M = 8m = 4/5 kg
/// (`fin_known.rs`: 0 = 3 - (3/2) 3 M/(4m + M) gives 4m + M = 3M/2).
const ROD_MASS: Case = Case {
    name: "the rod's mass from the ball's final velocity",
    si: &[
        "-m",
        "0.1 kg,?",
        "-v",
        "(3,1) m/s,0",
        "--target",
        "rod 1.2 m",
        "--hit-at",
        "end",
        "-e",
        "0.5",
        "--fin",
        "(0,1) m/s,?",
    ],
    units: &[
        &[
            "-m",
            "100 g,?",
            "-v",
            "(300,100) cm/s,0",
            "--target",
            "rod 120 cm",
            "--hit-at",
            "end",
            "-e",
            "0.5",
            "--fin",
            "(0,100) cm/s,?",
        ],
        &[
            "-m",
            "0.1 kg,?",
            "-v",
            "(10.8,3.6) km/h,0",
            "--target",
            "rod 1.2 m",
            "--hit-at",
            "end",
            "-e",
            "0.5",
            "--fin",
            "(0,3.6) km/h,?",
        ],
    ],
    reflected: &[
        "-m",
        "0.1 kg,?",
        "-v",
        "(3,-1) m/s,0",
        "--target",
        "rod 1.2 m",
        "--hit-at",
        "-0.6 m",
        "-e",
        "0.5",
        "--fin",
        "(0,-1) m/s,?",
    ],
    axis: 1,
};

/// A solid 1 kg sphere (R = 0.1 m) at (3, -4) m/s onto a rough floor, e = 1/2, leaving with
/// vx' = 2.5 m/s: mu = 1/12 (`fin_known.rs`: P_n = (1 + e) 4 = 6, vx' = 3 - 6 mu while it
/// slides, which it does up to mu = 1/7). The floor stays below: reflected across the y axis.
const FLOOR_MU: Case = Case {
    name: "mu from a ball's final velocity on a floor",
    si: &[
        "-m",
        "1 kg,floor",
        "-v",
        "(3,-4) m/s,0",
        "--ball",
        "sphere 0.1 m",
        "--friction",
        "?",
        "-e",
        "0.5",
        "--fin",
        "(2.5,?) m/s,?",
    ],
    units: &[
        &[
            "-m",
            "1000 g,floor",
            "-v",
            "(300,-400) cm/s,0",
            "--ball",
            "sphere 10 cm",
            "--friction",
            "?",
            "-e",
            "0.5",
            "--fin",
            "(250,?) cm/s,?",
        ],
        &[
            "-m",
            "1 kg,floor",
            "-v",
            "(10.8,-14.4) km/h,0",
            "--ball",
            "sphere 0.1 m",
            "--friction",
            "?",
            "-e",
            "0.5",
            "--fin",
            "(9,?) km/h,?",
        ],
    ],
    reflected: &[
        "-m",
        "1 kg,floor",
        "-v",
        "(-3,-4) m/s,0",
        "--ball",
        "sphere 0.1 m",
        "--friction",
        "?",
        "-e",
        "0.5",
        "--fin",
        "(-2.5,?) m/s,?",
    ],
    axis: 0,
};

/// A 10 g bullet along x lodges in the top end of a 2 kg, 1 m rod on a pivot at its bottom end,
/// whose centre then moves at 3 m/s: about the pivot I = M L^2/3 + m L^2 = 203/300, omega' =
/// m v L / I = 3v/203, and the centre, L/2 above the pivot, moves at omega' L/2 = 3v/406: v =
/// 406 m/s. Reflected: the pivot above, the bullet in the lower end.
const JOINED_SPEED: Case = Case {
    name: "a bullet's speed from the joined rod's final velocity",
    si: &[
        "-m",
        "10 g,2 kg",
        "-v",
        "?,0",
        "--target",
        "rod 1 m",
        "--pivot",
        "end",
        "--hit-at",
        "end",
        "--join",
        "--fin",
        "?,(3,0) m/s",
    ],
    units: &[
        &[
            "-m",
            "10 g,2000 g",
            "-v",
            "?,0",
            "--target",
            "rod 100 cm",
            "--pivot",
            "end",
            "--hit-at",
            "end",
            "--join",
            "--fin",
            "?,(300,0) cm/s",
        ],
        &[
            "-m",
            "0.01 kg,2 kg",
            "-v",
            "?,0",
            "--target",
            "rod 1 m",
            "--pivot",
            "end",
            "--hit-at",
            "end",
            "--join",
            "--fin",
            "?,(10.8,0) km/h",
        ],
    ],
    reflected: &[
        "-m",
        "10 g,2 kg",
        "-v",
        "?,0",
        "--target",
        "rod 1 m",
        "--pivot",
        "(0,0.5) m",
        "--hit-at",
        "-1 m",
        "--join",
        "--fin",
        "?,(3,0) m/s",
    ],
    axis: 1,
};

const CASES: [&Case; 4] = [&ROD_E, &ROD_MASS, &FLOOR_MU, &JOINED_SPEED];

#[test]
fn the_base_cases_give_their_hand_values() {
    let solved = |c: &Case, exact: bool, name: &str| report(c.si, exact)["solved"][name].clone();
    for (c, name, value) in [
        (&ROD_E, "e", ratio(19, 30)),
        (&ROD_MASS, "m2", ratio(4, 5)),
        (&FLOOR_MU, "mu", ratio(1, 12)),
        (&JOINED_SPEED, "v1", int(406)),
    ] {
        assert_eq!(q(&solved(c, true, name)), value, "{}: exact", c.name);
        // The samples are exact rationals of the binary64 input, the root rounded once: within
        // 2 ulps of the exact value.
        let b = f(&solved(c, false, name));
        assert_ulps(b, crate::common::rounded(&value), 2.0, c.name);
    }
}

#[test]
fn other_units_give_the_same_report_bit_for_bit() {
    for c in CASES {
        for exact in [false, true] {
            let si = report(c.si, exact);
            for typed in c.units {
                assert_eq!(
                    report(typed, exact),
                    si,
                    "{} typed as {typed:?} (exact: {exact})",
                    c.name
                );
            }
        }
    }
}

#[test]
fn the_reflected_case_gives_the_reflected_report_bit_for_bit() {
    for c in CASES {
        for exact in [false, true] {
            let a = report(c.si, exact);
            let b = report(c.reflected, exact);
            // The reflection is a real one: some body leaves spinning.
            let spins = a["fin"].as_array().unwrap().iter().map(|b| q(&b["omega"]));
            assert!(spins.into_iter().any(|w| w != Q::ZERO), "{}", c.name);
            assert_reflected(&a, &b, c.axis, c.name);
            // And the comparison can fail: a report is not its own reflection.
            let own = std::panic::catch_unwind(|| assert_reflected(&a, &a, c.axis, "itself"));
            assert!(own.is_err(), "{}: its own reflection", c.name);
        }
    }
    // The bullet at 10 deg above x and its reflection at -10 deg: v = 406 / cos(10 deg) (the
    // centre's speed takes only the x component, as the case above derives), to 1e-14 relative
    // (cos 10 deg is binary64's), and the reflected report bit for bit.
    let mut up = JOINED_SPEED.si.to_vec();
    up[3] = "? @ 10deg,0";
    up[12] = "?,(3,?) m/s";
    let mut down = JOINED_SPEED.reflected.to_vec();
    down[3] = "? @ -10deg,0";
    down[12] = "?,(3,?) m/s";
    let a = report(&up, false);
    let v = 406.0 / 10f64.to_radians().cos();
    crate::common::assert_close(f(&a["solved"]["v1"]), v, 1e-14, "v1 at 10 deg");
    assert_reflected(&a, &report(&down, false), 1, "the bullet at 10 deg");
}

#[test]
fn the_known_on_either_body_gives_the_same_e() {
    // The rod's final velocity instead of the ball's: v2' = P/M = (1 + e) 3 (1/14) = 7/20 at e =
    // 19/30 (fin_known.rs). The same e exactly; in binary64 within 1 ulp (the two residuals are
    // different rational functions of e, each rounded once).
    let mut rod = ROD_E.si.to_vec();
    rod[3] = "(3,0) m/s,0";
    rod[11] = "?,(0.35,0) m/s";
    let mut ball = ROD_E.si.to_vec();
    ball[3] = "(3,0) m/s,0";
    ball[11] = "(-0.5,?) m/s,?";
    let e = |a: &[&str], exact: bool| report(a, exact)["solved"]["e"].clone();
    assert_eq!(q(&e(&rod, true)), q(&e(&ball, true)));
    assert_eq!(q(&e(&rod, true)), ratio(19, 30));
    assert_ulps(f(&e(&rod, false)), f(&e(&ball, false)), 1.0, "e");
}
