//! Galilean frames and time reversal (lecture Sec. 4, Figs. 2.5 and 3.4), as a user runs them.

use crate::common;

use collide::accuracy::case;
use collide::line::frame::Frame;
use collide::solver::Solver;
use collide::solver::binary64::Binary64;
use collide::values::quantity::from_f64;
use common::{REL, assert_close, assert_exact, assert_pair, collide, stdout};
use proptest::prelude::*;
use serde::Deserialize;
use serde_json::Value;

#[derive(Deserialize)]
struct Table {
    frames: Vec<Row>,
    invariants: Invariants,
}

#[derive(Deserialize)]
struct Row {
    name: String,
    w: f64,
    #[serde(rename = "in")]
    v_in: [f64; 2],
    com: [f64; 2],
    fin: [f64; 2],
    energy: collide::report::Energy,
}

#[derive(Deserialize)]
struct Invariants {
    crunch: f64,
    lost: f64,
    relative_velocity: f64,
    restitution: f64,
}

#[test]
fn fig_3_4_table_from_collide_frames() {
    let t: Table = serde_json::from_str(&stdout(&[
        "frames", "-m", "6,1", "-v", "3,-4", "--format", "json",
    ]))
    .unwrap();
    let names: Vec<&str> = t.frames.iter().map(|r| r.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "lab",
            "rest-in:1",
            "rest-in:2",
            "com",
            "rest-fin:1",
            "rest-fin:2"
        ]
    );
    let row = |n: &str| t.frames.iter().find(|r| r.name == n).unwrap();
    // Lecture Fig. 3.4: (frame, w, IN, FIN): Earth, VW initially at rest, COM, VW finally at rest.
    // Every value is an integer, exact in binary64: compared exactly.
    for (name, w, v_in, fin) in [
        ("lab", 0.0, [3.0, -4.0], [1.0, 8.0]),
        ("rest-in:2", -4.0, [7.0, 0.0], [5.0, 12.0]),
        ("com", 2.0, [1.0, -6.0], [-1.0, 6.0]),
        ("rest-fin:2", 8.0, [-5.0, -12.0], [-7.0, 0.0]),
    ] {
        let r = row(name);
        assert_exact(r.w, w, name);
        assert_pair(r.v_in, v_in, &format!("{name} IN"));
        assert_pair(r.fin, fin, &format!("{name} FIN"));
        assert_exact(r.energy.crunch, 21.0, &format!("{name} crunch"));
        assert_eq!(r.energy.lost, Some(0.0));
    }
    assert_pair(
        row("com").com,
        [0.0, 0.0],
        "COM at the origin of the COM frame",
    );
    assert_exact(
        row("com").energy.ke_in,
        21.0,
        "KE in the COM frame is all crunch",
    );
    assert_exact(
        row("rest-in:2").energy.ke_in,
        147.0,
        "KE with the VW initially at rest",
    );
    assert_eq!(t.invariants.crunch, 21.0);
    assert_eq!(t.invariants.lost, 0.0);
    assert_eq!(t.invariants.relative_velocity, 7.0);
    assert_eq!(t.invariants.restitution, 1.0);
}

#[test]
fn frames_text_and_extra_rows() {
    let text = stdout(&[
        "frames",
        "-m",
        "6,1",
        "-v",
        "3,-4",
        "--frame",
        "-10",
        "--reverse",
    ]);
    assert!(text.contains("observer at -10"), "{text}");
    assert!(text.contains("crunch = 1/2 mu (V1 - V2)^2 = 21"), "{text}");
    // The time reverse equals the original in the COM row only.
    let verdicts: Vec<&str> = text
        .lines()
        .filter(|l| l.trim_end().ends_with(" yes") || l.trim_end().ends_with(" no"))
        .map(|l| {
            if l.trim_end().ends_with("yes") {
                l.split_whitespace().next().unwrap()
            } else {
                "-"
            }
        })
        .collect();
    assert_eq!(
        verdicts.iter().filter(|v| **v != "-").collect::<Vec<_>>(),
        [&"COM"],
        "{text}"
    );
    assert_eq!(verdicts.len(), 7, "{text}");
}

#[test]
fn case_a_in_the_com_frame() {
    let j: Value = serde_json::from_str(&stdout(&[
        "solve",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--frame",
        "com",
        "--show",
        "vectors,energy",
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(j["frame"], serde_json::json!({"name": "com", "w": 50.0}));
    assert_eq!(j["in"], serde_json::json!([10.0, -40.0]));
    assert_eq!(j["fin"], serde_json::json!([-10.0, 40.0]));
    assert_eq!(j["com"], serde_json::json!([0.0, 0.0]));
    assert_eq!(j["energy"]["crunch"], 1000.0);
    assert_eq!(
        j["energy"]["in"], 1000.0,
        "in the COM frame all KE is crunch"
    );
}

#[test]
fn reversal_of_case_a() {
    let lab: Value = serde_json::from_str(&stdout(&[
        "solve",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--reverse",
        "--show",
        "vectors",
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(lab["reverse"]["in"], serde_json::json!([-40.0, -90.0]));
    assert_eq!(lab["reverse"]["fin"], serde_json::json!([-60.0, -10.0]));
    assert_eq!(lab["reverse"]["equals_original"], false);
    let com: Value = serde_json::from_str(&stdout(&[
        "solve",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--frame",
        "com",
        "--reverse",
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(com["reverse"]["equals_original"], true);
    assert_eq!(com["reverse"]["in"], com["in"]);
}

#[test]
fn reversal_of_ka_whump_is_an_explosion() {
    let j: Value = serde_json::from_str(&stdout(&[
        "solve",
        "-m",
        "6,1",
        "-v",
        "3,-4",
        "-e",
        "2/3",
        "--reverse",
        "--exact",
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(j["reverse"]["restitution"], "3/2");
    assert_eq!(j["reverse"]["energy"]["gained"], "35/3");
    assert_eq!(j["reverse"]["energy"]["in"], "70/3");
    let text = stdout(&["solve", "-m", "6,1", "-v", "3,-4", "-e", "2/3", "--reverse"]);
    assert!(text.contains("an explosion"), "{text}");
}

#[test]
fn reversal_of_ka_runch_is_refused() {
    for cmd in [
        ["solve", "-m", "4,1", "-v", "60,10", "-e", "0", "--reverse"],
        ["frames", "-m", "4,1", "-v", "60,10", "-e", "0", "--reverse"],
    ] {
        let out = collide().args(cmd).output().unwrap();
        assert_eq!(out.status.code(), Some(2));
        assert!(out.stdout.is_empty());
        assert!(String::from_utf8_lossy(&out.stderr).contains("not determined"));
    }
}

#[test]
fn bad_frames_are_refused() {
    let out = collide()
        .args(["solve", "-m", "4,1", "-v", "60,10", "--frame", "rest-in:3"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    // Two bodies on a line have no third body to be at rest with.
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("frame 'rest-in:3': two bodies on a line"),
        "{err}"
    );
    let out = collide()
        .args(["solve", "-m", "4,1", "-v", "60,10", "--frame", "rest-in:x"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("'rest-in:x' is not a frame"));
}

#[test]
fn fig_3_4_scenes_pass() {
    let out = stdout(&[
        "scene",
        "scenarios/fig-2-3-elastic.toml",
        "scenarios/fig-3-4-vw-initially-at-rest.toml",
        "scenarios/fig-3-4-com.toml",
        "scenarios/fig-3-4-vw-finally-at-rest.toml",
    ]);
    assert!(out.contains("4 scenes: 4 pass, 0 fail"), "{out}");
}

proptest! {
    #![proptest_config(common::proptest_config(400))]

    /// Crunch, energy lost and the relative velocity are the same in every frame, even under
    /// boosts of 1e15 with relative velocities of order 1; FIN shifts by exactly -w (1 ulp).
    #[test]
    fn invariance_under_random_boosts(
        m1 in 1e-3f64..1e3, m2 in 1e-3f64..1e3, v1 in -10.0f64..10.0, v2 in -10.0f64..10.0,
        e in prop_oneof![Just(0.0), Just(1.0), 0.0f64..1.0], k in 0i32..=15, s in -1.0f64..1.0,
    ) {
        let c = case([[m1, 0.0], [0.0, m2]], [v1, v2], e).unwrap();
        let w = s * 10f64.powi(k);
        let lab = Binary64::lab(&c);
        let moving = Binary64::new(&c, &Frame::Velocity(collide::values::number::Number::from_f64(w).unwrap()));
        prop_assert_eq!(moving.crunch(), lab.crunch());
        prop_assert_eq!(moving.lost(), lab.lost());
        prop_assert_eq!(moving.relative_velocity(), lab.relative_velocity());
        // Against the exact FIN of the binary64 inputs, shifted by the exact w.
        let exact_fin = collide::solver::exact::ExactCollision::from_binary64(&c).v_fin_q();
        let fin_w = moving.v_fin();
        for i in 0..2 {
            let expected = &exact_fin[i] - from_f64(w);
            let scale = fin_w[i].abs().max(w.abs()).max(lab.v_fin()[i].abs()).max(1e-300);
            prop_assert!(collide::accuracy::ulps(fin_w[i], &expected, scale) <= 1.0);
        }
    }
}

// Issue 24: small restitutions and energy units in the frames table.

/// `collide frames ARGS`: (exit code, stdout, stderr).
fn outcome(args: &[&str]) -> (i32, String, String) {
    common::run(&[&["frames"], args].concat())
}

#[test]
fn a_tiny_restitution_agrees_in_every_frame_relative_to_its_own_size() {
    // -e 1e-17 exited 2: "restitution e is not the same in every frame: -3.08e-33 in the lab".
    // e seen in a frame, -(FIN1 - FIN2)/(IN1 - IN2), cancels FIN's digits: it is checked
    // against e beyond that rounding, and the invariant printed is e itself.
    for e in ["1e-17", "1e-100", "1e-150"] {
        let (code, out, err) = outcome(&["-m", "1,2", "-v", "1,0", "-e", e, "--format", "json"]);
        assert_eq!(code, 0, "-e {e}: {err}");
        let t: Table = serde_json::from_str(&out).unwrap();
        assert_eq!(
            t.invariants.restitution,
            e.parse::<f64>().unwrap(),
            "-e {e}"
        );
        // crunch = 1/2 mu u^2 = 1/2 (2/3) 1 = 1/3 in every frame.
        assert_close(t.invariants.crunch, 1.0 / 3.0, REL, "crunch");
        let (_, text, _) = outcome(&["-m", "1,2", "-v", "1,0", "-e", e]);
        assert!(
            text.contains(&format!("e = -(FIN1 - FIN2)/(IN1 - IN2) = {e}")),
            "{text}"
        );
    }
    // At 1e-300 the COM frame's KE_FIN = e^2 crunch = 1e-600/3 is below binary64: refused by
    // name, with the way out frames has (no --show), and --exact prints it.
    for e in ["1e-300", "5e-324"] {
        let (code, out, err) = outcome(&["-m", "1,2", "-v", "1,0", "-e", e]);
        assert_eq!(code, 2, "{out}");
        assert!(
            err.contains("energy.fin in frame com") && err.contains("--exact"),
            "{err}"
        );
        assert!(
            !err.contains("--show") && !err.contains("not the same"),
            "{err}"
        );
        let (code, out, err) = outcome(&["-m", "1,2", "-v", "1,0", "-e", e, "--exact"]);
        assert_eq!(code, 0, "{err}");
        assert!(out.contains(&format!("(IN1 - IN2) = {e}")), "{out}");
    }
}

#[test]
fn frames_energies_are_in_the_unit_the_label_names() {
    // They were joules under an eV label, in text and JSON. KE_IN = 1/2 1 kg (2 m/s)^2 = 2 J
    // = 2 / 1.602176634e-19 eV (exact), rounded once.
    let ev = |j: &str| {
        let q = |s: &str| {
            s.parse::<collide::values::number::Number>()
                .unwrap()
                .exact()
        };
        collide::values::quantity::to_f64(&(q(j) / q("1.602176634e-19"))).unwrap()
    };
    let args = ["-m", "1 kg,12 kg", "-v", "2 m/s,0", "--energy-unit", "eV"];
    let (code, out, err) = outcome(&[&args[..], &["--format", "json"]].concat());
    assert_eq!(code, 0, "{err}");
    let t: Table = serde_json::from_str(&out).unwrap();
    let lab = &t.frames[0];
    assert_eq!(lab.energy.ke_in, ev("2"));
    // crunch = 1/2 mu u^2 with mu = 12/13: 24/13 J, in every frame.
    assert_close(t.invariants.crunch, ev("24") / 13.0, REL, "crunch in eV");
    for row in &t.frames {
        assert_close(row.energy.crunch, ev("24") / 13.0, REL, &row.name);
    }
    let (_, text, _) = outcome(&args);
    assert!(text.contains("energies in eV"), "{text}");
    assert!(
        text.contains(&collide::values::number::num(ev("2"))),
        "{text}"
    );
}

#[test]
fn frames_moving_with_com_or_fin_keep_every_digit_of_a_small_restitution() {
    // m = (1, 2), V = (1, 0): V_COM = 1/3, IN_COM = (2/3, -1/3), FIN_COM = -e IN_COM; finally
    // at rest FIN2 - FIN1 = e (V1 - V2) = e. FIN was the difference of lab velocities, which
    // kept only their rounding: (3.08e-33, 0) in the COM frame for e = 1e-150.
    for e in [1e-150, 1e-17, 0.5] {
        let t: Table = serde_json::from_str(&stdout(&[
            "frames",
            "-m",
            "1,2",
            "-v",
            "1,0",
            "-e",
            &format!("{e:e}"),
            "--format",
            "json",
        ]))
        .unwrap();
        let row = |n: &str| t.frames.iter().find(|r| r.name == n).unwrap();
        let rel = 4.0 * f64::EPSILON;
        let com = row("com");
        assert_close(com.fin[0], -e * 2.0 / 3.0, rel, "COM FIN1");
        assert_close(com.fin[1], e / 3.0, rel, "COM FIN2");
        assert_eq!(row("rest-fin:1").fin[0], 0.0);
        assert_close(row("rest-fin:1").fin[1], e, rel, "rest-fin:1 FIN2");
        assert_close(row("rest-fin:2").fin[0], -e, rel, "rest-fin:2 FIN1");
        assert_eq!(row("rest-fin:2").fin[1], 0.0);
        // COM in the finally-at-rest frames: V_COM - FIN1 = -e w2 d = 2e/3 (d = V2 - V1 = -1,
        // w2 = m2 / M = 2/3).
        assert_close(
            row("rest-fin:1").com[0],
            2.0 * e / 3.0,
            rel,
            "rest-fin:1 COM",
        );
    }
}
