//! Published homework problems, the rest (issue 24 and after): no false number from --reverse,
//! --energy-unit, a wall or a typed -0; textbook rounding, significant figures, forces in newtons.

use crate::common;

use common::{REL, assert_close};
use serde_json::Value;

use super::problems::{f, json, run};

// Issue 24: no false number from --reverse, --energy-unit, a wall or a typed -0.

#[test]
fn the_reversed_restitution_is_refused_by_name_or_printed_exactly_never_inf() {
    // e' = 1/e overflowed: "e' inf" in text, "restitution": null in JSON, exit 0.
    for e in ["5e-324", "1e-309"] {
        for format in ["text", "json"] {
            let (code, out, err) = run(&[
                "-m",
                "1,2",
                "-v",
                "1,0",
                "-e",
                e,
                "--reverse",
                "--format",
                format,
            ]);
            assert_eq!(code, 2, "-e {e}: {out}");
            assert!(out.is_empty(), "{out}");
            assert!(
                err.contains(&format!("1/e = 1/{e}")) && err.contains("--exact"),
                "{err}"
            );
        }
    }
    // Exactly: 1/(5e-324) = 2e323, a terminating decimal, printed in exact notation.
    let (code, out, _) = run(&[
        "-m",
        "1,2",
        "-v",
        "1,0",
        "-e",
        "5e-324",
        "--reverse",
        "--exact",
    ]);
    assert_eq!(code, 0);
    let line = out.lines().find(|l| l.contains("e'")).unwrap();
    assert!(line.contains(" 2e323 "), "{line}");
    let (_, j) = json("-m 1,2 -v 1,0 -e 5e-324 --reverse --exact");
    assert_eq!(j["reverse"]["restitution"], format!("2{}", "0".repeat(323)));
}

#[test]
fn reversed_energies_are_in_the_energy_unit_and_never_negative() {
    // -m '1 kg,12 kg' -v '2 m/s,0' -e 1/2: KE_IN = 2 J, V_COM = 2/13, FIN = (-10/13, 3/13):
    // KE_FIN = 1/2 (100/169) + 6 (9/169) = 104/169 = 8/13 J; lost = 2 - 8/13 = 18/13 J. In kJ
    // each is 1/1000 of that; they were printed in J under the kJ label.
    let (code, j) = json("-m 1kg,12kg -v 2m/s,0 -e 1/2 --reverse --energy-unit kJ");
    assert_eq!(code, 0);
    let r = &j["reverse"]["energy"];
    assert_close(f(&r["in"]), 8.0 / 13.0 / 1000.0, REL, "KE_IN' = KE_FIN");
    assert_close(f(&r["fin"]), 0.002, REL, "KE_FIN' = KE_IN");
    assert_close(f(&r["gained"]), 18.0 / 13.0 / 1000.0, REL, "gained");
    assert!(r.get("lost").is_none(), "{r}");
    // e = 2 (superelastic: the original releases (e^2 - 1) crunch = 3 (1/3) = 1): its reverse
    // loses 1, said as "lost", not as "gained": -1.
    let (code, j) = json("-m 1,2 -v 1,0 -e 2 --reverse");
    assert_eq!(code, 0);
    let r = &j["reverse"]["energy"];
    assert_close(f(&r["lost"]), 1.0, REL, "lost");
    assert!(r.get("gained").is_none(), "{r}");
    // No -0 in the reversed vectors (FIN' = -IN with IN2 = 0).
    assert_eq!(j["reverse"]["fin"], serde_json::json!([-1.0, 0.0]));
    assert!(!serde_json::to_string(&j).unwrap().contains("-0.0"), "{j}");
}

#[test]
fn the_forms_line_is_in_one_unit() {
    // "1 - -0.846 = crunch = 1.15e19" mixed the forms' J with eV: the forms and their crunch
    // stay in the case's unit (J), the energy section is in eV. crunch = 1/2 (12/13) 4 = 24/13.
    let (code, out, _) = run(&["-m", "1 kg,12 kg", "-v", "2 m/s,0", "--energy-unit", "eV"]);
    assert_eq!(code, 0);
    let line = out.lines().find(|l| l.contains("V_IN.M.V_IN/4")).unwrap();
    assert!(
        line.contains(&format!(
            "= crunch = {}",
            collide::values::number::num(24.0 / 13.0)
        )),
        "{line}"
    );
}

#[test]
fn an_unknown_against_a_wall_is_never_a_receding_ball() {
    // FIN -0.5 with e = 1/2 "solved" v2 = 1: the ball moving away from the wall on its left.
    for line in [
        "-m wall,1 -v 0,? --fin 0,-0.5 -e 0.5",
        "-m wall,1 -v 0,1 --fin 0,-0.5",
        "-m 1,wall -v ?,0 --fin 0.5,0 -e 0.5",
    ] {
        let args: Vec<&str> = line.split(' ').collect();
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{line}: {out}");
        assert!(
            err.contains("moves away from the wall") && err.contains("unphysical"),
            "{line}: {err}"
        );
    }
    // The bounce it describes: v2 = -1 toward the wall, f2 = -e v2 = 1/2.
    let (code, j) = json("-m wall,1 -v 0,? --fin 0,0.5 -e 0.5 --exact");
    assert_eq!(code, 0);
    assert_eq!(j["solved"]["v2"], "-1");
}

#[test]
fn typed_negative_zeros_print_as_zero_in_headers() {
    let (code, out, _) = run(&["-m", "1,2", "-v", "-0.0,1", "-e", "-0"]);
    assert_eq!(code, 0);
    let header = out.lines().next().unwrap();
    assert_eq!(
        header,
        "M = diag(1, 2)   V_IN = (0, 1)   e = 0 (totally inelastic: ka-runch)"
    );
}

/// Issue 27 §3: rounding and display as a textbook reader expects.
#[test]
fn textbook_rounding_and_display() {
    // --sig rounds half away from zero: V_COM = (1 x 0.25) / 2 = 0.125 exactly, to 2 digits
    // 0.13 (it printed 0.12, ties to even); 7.105e8 to 3 digits: 7.11e8 (masses 1420999999
    // and 1 both at 1: KE_IN = 1/2 x 1.421e9 = 710500000 exactly; it printed 710000000).
    let (_, out, _) = run(&["-m", "1,1", "-v", "0.25,0", "-e", "0", "--sig", "2"]);
    assert!(out.contains("V_COM = P_total / M_total = 0.13"), "{out}");
    let (_, out, _) = run(&[
        "-m",
        "1420999999,1",
        "-v",
        "1,1",
        "--show",
        "energy",
        "--sig",
        "3",
    ]);
    assert!(
        out.contains(" 711000000 ") && !out.contains("710000000"),
        "{out}"
    );
    // The Moon's recoil: 1000 kg at 5 m/s sticks to 7.35e22 kg at rest: V_COM = 5000 /
    // (7.35e22 + 1000) = 6.80272108843537e-20 m/s to 15 digits (a quotient, accurate to its
    // own ulps), not 0; elastic, the Moon leaves at twice that.
    let (_, out, _) = run(&["-m", "1000 kg,7.35e22 kg", "-v", "5 m/s,0", "-e", "0"]);
    assert!(
        out.contains("V_COM = P_total / M_total = 6.80272108843537e-20"),
        "{out}"
    );
    assert!(
        out.contains("v1' = v2' = 6.80272108843537e-20 m/s"),
        "{out}"
    );
    let (_, out, _) = run(&["-m", "1000 kg,7.35e22 kg", "-v", "5 m/s,0", "-e", "1"]);
    assert!(out.contains("v2' = 1.36054421768707e-19 m/s"), "{out}");
    // Noise is still noise: equal masses, elastic, v = (0.1, 0.2): FIN = (0.2, 0.1) exactly
    // in the impulse form, and a frame's rounding prints no -1e-17.
    let (_, out, _) = run(&["-m", "1,1", "-v", "0.3,0.1", "--frame", "com"]);
    assert!(!out.contains("e-17") && !out.contains("e-18"), "{out}");
    // A separation with a typed e: refused, e is undefined there.
    let (code, out, err) = run(&["-m", "1,1", "-v", "0,0", "--fin", "?,?", "-e", "2.80e3"]);
    assert_eq!(code, 2);
    assert!(
        out.is_empty() && err.contains("e is undefined for a separation"),
        "{err}"
    );
    // --exact prints exact values everywhere: FIN1 = 11/7 gives e = 3/7 (f2 = 32/7:
    // 6 x 3 - 4 = 6 x 11/7 + f2, e = (32/7 - 11/7) / 7 = 3/7), in the header too.
    let (_, out, _) = run(&["-m", "6,1", "-v", "3,-4", "--fin", "11/7,?", "--exact"]);
    assert!(out.contains("Solved: f2 = 32/7, e = 3/7"), "{out}");
    assert!(
        out.contains("e = 3/7 (ka-whump)") && !out.contains('≈'),
        "{out}"
    );
    // A wall: the share kept beside the share lost, e^2 = 1/4 and 1 - e^2 = 3/4.
    let (_, j) = json("-m 1,wall -v 4,0 -e 0.5 --show changes");
    assert_eq!(f(&j["changes"]["lost_fraction"]), 0.75);
    assert_eq!(f(&j["changes"]["kept_fraction"]), 0.25);
}

#[test]
fn forces_print_in_newtons_whatever_the_units() {
    // A 145 g ball at 40 m/s hits a wall, e = 1/2, in 2 ms: dv = -60 m/s, dp = -8.7 N s,
    // F = dp / T = -4350 N (it printed -4350000 "in g m/s per second"); the same ball typed
    // in kg and km/h gives the same newtons (40 m/s = 144 km/h).
    for (m, v) in [("145 g", "40 m/s"), ("0.145 kg", "144 km/h")] {
        let (_, out, _) = run(&[
            "-m",
            &format!("{m},wall"),
            "-v",
            &format!("{v},0"),
            "-e",
            "1/2",
            "--contact-time",
            "2ms",
            "--show",
            "changes",
            "--format",
            "json",
        ]);
        let j: Value = serde_json::from_str(&out).unwrap();
        let force = f(&j["changes"]["average_force"]);
        assert!(
            (force + 4350.0).abs() <= 4350.0 * 4.0 * f64::EPSILON,
            "{m}, {v}: {force}"
        );
    }
    let (_, out, _) = run(&[
        "-m",
        "145 g,wall",
        "-v",
        "40 m/s,0",
        "-e",
        "1/2",
        "--contact-time",
        "2ms",
        "--show",
        "changes",
    ]);
    assert!(out.contains("-4350") && out.contains("in N"), "{out}");
}

/// Issue 45 §5: `--sig N` prints N significant figures, trailing zeros kept as a book prints
/// them; JSON keeps the numbers.
#[test]
fn sig_keeps_trailing_zeros() {
    // Equal masses that stick, body 2 at rest: V_COM = v1 / 2, and KE_IN = 1/2 v1^2.
    //   v1 = 0.3:   V_COM = 0.15 -> 0.150,   KE_IN = 0.045 -> 0.0450
    //   v1 = 0.174: V_COM = 0.087 -> 0.0870, KE_IN = 0.015138 -> 0.0151
    //   v1 = 12:    V_COM = 6 -> 6.00,       KE_IN = 72 -> 72.0
    for (v1, v_com, ke_in) in [
        ("0.3", "0.150", "0.0450"),
        ("0.174", "0.0870", "0.0151"),
        ("12", "6.00", "72.0"),
    ] {
        let v = format!("{v1},0");
        let args = ["-m", "1,1", "-v", &v, "-e", "0", "--show", "vectors,energy"];
        let (_, out, _) = run(&[&args[..], &["--sig", "3"]].concat());
        assert!(
            out.contains(&format!("V_COM = P_total / M_total = {v_com}\n")),
            "{v1}: {out}"
        );
        assert!(
            out.contains(&format!("  KE_IN  {ke_in}")) || out.contains(&format!(" {ke_in}\n")),
            "{v1}: {out}"
        );
        // The typed values print as typed.
        assert!(out.contains(&format!("V_IN = ({v1}, 0)")), "{v1}: {out}");
    }
    // Without --sig, the shortest form: 0.15.
    let (_, out, _) = run(&["-m", "1,1", "-v", "0.3,0", "-e", "0"]);
    assert!(out.contains("= 0.15\n"), "{out}");
    // JSON carries numbers whatever --sig says.
    let (_, j) = json("-m 1,1 -v 0.3,0 -e 0 --sig 3");
    assert_eq!(j["v_com"], serde_json::json!(0.15));
}

/// Issue 45 §5: a ball against a wall asked only in speeds and e needs no mass, and nothing
/// that needs one is printed.
#[test]
fn a_wall_rebound_in_speeds_needs_no_mass() {
    // The ball (body 2) comes at -3 toward the wall on the left, at rest, and leaves at 2:
    // f - w = -e (v - w) gives 2 = 3 e, e = 2/3, whatever the mass. The wall on the right and
    // the ball at 3 leaving at -2: the same. The changes that need no mass: dv = f - v = 5
    // (or -5), lost / crunch = 1 - e^2 = 5/9 and kept / crunch = e^2 = 4/9.
    for (m, v, fin, dv) in [
        ("wall,?", "0,-3", "0,2", "5"),
        ("?,wall", "3,0", "-2,0", "-5"),
    ] {
        let (code, j) = json(&format!(
            "-m {m} -v {v} --fin {fin} --exact --show vectors,momentum,energy,changes"
        ));
        assert_eq!(code, 0, "{m}: {j}");
        assert_eq!(j["solved"], serde_json::json!({"e": "2/3"}), "{m}");
        assert_eq!(j["restitution"], "2/3", "{m}");
        for key in ["mass", "momentum", "energy"] {
            assert!(j.get(key).is_none(), "{m}: {key} in {j}");
        }
        let changes = &j["changes"];
        assert!(changes.get("impulse").is_none(), "{m}: {j}");
        assert_eq!(
            (
                &changes["dv"],
                &changes["lost_fraction"],
                &changes["kept_fraction"]
            ),
            (&Value::from(dv), &Value::from("5/9"), &Value::from("4/9")),
            "{m}"
        );
    }
    let (code, out, _) = run(&["-m", "wall,?", "-v", "0,-3", "--fin", "0,2", "--exact"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("Solved: e = 2/3"), "{out}");
    assert!(out.contains("M = (wall, ?)"), "{out}");
    assert!(out.contains("The ball's mass is not given"), "{out}");
    assert!(!out.contains("KE_IN"), "{out}");
}

#[test]
fn significant_figures_keep_their_trailing_zeros() {
    // Issue 45 §5, by hand: each value to `d` digits as a book prints it (`--sig d`).
    for (x, d, want) in [
        (0.15, 3, "0.150"),
        (0.087, 3, "0.0870"),
        (-0.087, 3, "-0.0870"),
        (6.0, 3, "6.00"),
        (60.0, 3, "60.0"),
        (7250.0, 3, "7250"),
        (711000000.0, 3, "711000000"),
        (1.33, 3, "1.33"),
        (10.0, 3, "10.0"),
        (2.0, 1, "2"),
        (0.1, 16, "0.1000000000000000"),
        // 0.1 is 0.1000000000000000055511151231257827 in binary64: 17 digits say so.
        (0.1, 17, "0.10000000000000001"),
        (6.8e-20, 3, "6.80e-20"),
        (1.5e16, 3, "1.50e16"),
        (1.2e-5, 3, "0.0000120"),
        (0.0, 3, "0"),
        (0.25, 0, "0.25"),
    ] {
        assert_eq!(collide::values::number::padded(x, d), want, "{x} to {d}");
    }
}
