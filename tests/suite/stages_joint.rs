//! A chain no stage-by-stage order solves, solved as one linear system (issue 42 §5): every
//! stage alone has more unknowns than laws, the stages together as many laws as unknowns.
//! The shipped scene against the fractions derived by hand below; the same chain in binary64;
//! a chain one known short refused naming its unknowns and its count of independent equations.

use crate::common::collide;
use crate::stages::{file, q, report, report_of};
use serde_json::{Value, json};

const JOINT: &str = "scenarios/stages-joint-wall.toml";

/// The exact value of a report's number or fraction.
fn exact(v: &Value) -> collide::values::rational::Q {
    match v.as_str() {
        Some(s) => q(s),
        None => q(&v.to_string()),
    }
}

/// Each stage's IN and FIN, exactly.
fn velocities(r: &Value) -> Vec<[collide::values::rational::Q; 4]> {
    (0..3)
        .map(|k| {
            let s = &r["stages"][k]["report"];
            [
                exact(&s["in"][0]),
                exact(&s["in"][1]),
                exact(&s["fin"][0]),
                exact(&s["fin"][1]),
            ]
        })
        .collect()
}

#[test]
fn a_chain_no_stage_solves_alone_is_solved_as_one_system() {
    // A (1 kg) at a hits B (2 kg) at rest, e = 1/2: V_COM = a/3, FIN = (1 + e) V_COM - e V_IN
    //   = (a/2 - a/2, a/2) = (0, a/2). B hits the wall, e = 1/2: b'' = -(1/2)(a/2) = -a/4.
    // A (0) and B (-a/4) meet, e = 1: V_COM = -a/6, A's FIN = 2 V_COM - 0 = -a/3 = -2 (given),
    //   so a = 6; B's FIN = 2 V_COM + a/4 = -2 + 3/2 = -1/2.
    // Alone: stage 1 has a, a', b' for 2 laws; the wall b', b'' for 1; the meeting a', b'', fB
    //   for 2: 5 unknowns, 5 laws, only together.
    let r = report(JOINT);
    let want = [
        ["6", "0", "0", "3"],
        ["3", "0", "-3/2", "0"],
        ["0", "-3/2", "-2", "-1/2"],
    ];
    let want: Vec<_> = want.iter().map(|row| row.map(q)).collect();
    assert_eq!(velocities(&r), want);
    let fixed: Vec<(&str, &str)> = r["system"]["fixed"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| (f["velocity"].as_str().unwrap(), f["by"].as_str().unwrap()))
        .collect();
    let by = "the system";
    assert_eq!(
        fixed,
        [("first.fin2", by), ("first.fin1", by), ("wall.fin1", by)]
    );
    assert_eq!(r["collide_again"], json!(false));
    // The same chain in binary64: every value here is a binary64, so each is exact (0 ulps).
    let text = std::fs::read_to_string(JOINT)
        .unwrap()
        .replace("exact = true", "exact = false");
    let b = report_of("joint-binary64.toml", &text);
    assert_eq!(velocities(&b), want);
}

#[test]
fn a_chain_one_known_short_is_refused_naming_its_unknowns() {
    // Without A's final speed the meeting has 4 unknowns: 6 unknowns for 5 laws, every one
    // proportional to a (a' = 0 stays 0 for every a, so it alone is fixed).
    let text: String = std::fs::read_to_string(JOINT)
        .unwrap()
        .replace("fin = [\"-2 m/s\", \"?\"]", "fin = [\"?\", \"?\"]")
        .lines()
        .filter(|l| !l.starts_with('"') && !l.starts_with("fin = [") && !l.starts_with("coll"))
        .map(|l| format!("{l}\n"))
        .collect();
    let text = text.replace(
        "restitution = 1\n",
        "restitution = 1\nfin = [\"?\", \"?\"]\n",
    );
    let path = file("joint-short.toml", &text);
    let out = collide().args(["scene"]).arg(&path).output().unwrap();
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    let flat = stderr.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        flat.contains(
            "[[stage]] first: no stage is determined alone, and together the unsolved stages' \
             laws give 5 independent equations for 6 unknowns (first.in1 (A), first.fin1 (A), \
             first.fin2 (B), wall.fin1 (B), again.fin1 (A), again.fin2 (B))"
        ),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
}
