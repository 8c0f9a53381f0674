//! Homework from the shell (issue 8): units, and solving for whatever is unknown. Expected values
//! are the lecture's (cases A and B) or derived by hand in the comments.

use crate::common;

use common::{collide, stdout};
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let mut a = vec!["solve"];
    a.extend_from_slice(args);
    a.extend(["--format", "json"]);
    serde_json::from_str(&stdout(&a)).unwrap()
}

#[track_caller]
fn refused(args: &[&str], needles: &[&str]) {
    let out = collide().arg("solve").args(args).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: stderr lacks {n:?}:\n{err}");
    }
}

#[test]
fn the_issues_examples() {
    // Fig. 1.3 read backwards: f2 from momentum, e from restitution.
    let j = json(&["-m", "4,1", "-v", "60,10", "--fin", "40,?"]);
    assert_eq!(j["solved"], serde_json::json!({"f2": 90.0, "e": 1.0}));
    assert_eq!(
        j["fin"],
        serde_json::json!([40.0, 90.0]),
        "the solved problem is printed in full"
    );
    let j = json(&["-m", "4,?", "-v", "60,10", "--fin", "40,90"]);
    assert_eq!(j["solved"], serde_json::json!({"m2": 1.0, "e": 1.0}));
    let text = stdout(&["solve", "-m", "4,?", "-v", "60,10", "--fin", "40,90"]);
    assert!(text.starts_with("Solved: m2 = 1, e = 1\n"), "{text}");
    assert!(
        text.contains("Quadratic forms"),
        "the whole report follows:\n{text}"
    );
}

#[test]
fn every_pair_of_unknowns_in_case_b_exactly() {
    // Fig. 2.3 ka-whump: m = (6, 1), V = (3, -4), FIN = (4/3, 6), e = 2/3.
    let full = ["6", "1", "3", "-4", "4/3", "6", "2/3"];
    let names = ["m1", "m2", "v1", "v2", "f1", "f2", "e"];
    for i in 0..7 {
        for j in (i + 1)..7 {
            let mut v = full.map(String::from);
            v[i] = "?".into();
            v[j] = "?".into();
            let (m, vel, fin) = (
                format!("{},{}", v[0], v[1]),
                format!("{},{}", v[2], v[3]),
                format!("{},{}", v[4], v[5]),
            );
            let args = ["-m", &m, "-v", &vel, "--fin", &fin, "-e", &v[6], "--exact"];
            if i < 2 && j < 2 {
                // Two masses: momentum fixes only their ratio, 6.
                refused(&args, &["infinitely many", "m1/m2 = 6"]);
                continue;
            }
            let out = json(&args);
            assert_eq!(
                out["solved"][names[i]], full[i],
                "{} of {}, {}",
                names[i], names[i], names[j]
            );
            assert_eq!(
                out["solved"][names[j]], full[j],
                "{} of {}, {}",
                names[j], names[i], names[j]
            );
        }
    }
}

#[test]
fn one_unknown_is_a_consistency_check() {
    let text = stdout(&[
        "solve", "-m", "4,1", "-v", "60,10", "--fin", "40,?", "-e", "1",
    ]);
    assert!(
        text.contains("Solved: f2 = 90\nCheck: restitution holds exactly"),
        "{text}"
    );
    // With e = 1/2 momentum still gives f2 = 90, but restitution misses: 90 - 40 - 25 = 25,
    // and the run fails like a failed [expect] (exit 1), still printing its JSON.
    let out = collide()
        .args([
            "solve", "-m", "4,1", "-v", "60,10", "--fin", "40,?", "-e", "1/2",
        ])
        .args(["--format", "json"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let j: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(j["check"]["restitution"], 25.0);
    // Nothing unknown: both laws checked.
    let j = json(&["-m", "4,1", "-v", "60,10", "--fin", "40,90", "-e", "1"]);
    assert_eq!(
        j["check"],
        serde_json::json!({"momentum": 0.0, "restitution": 0.0})
    );
}

#[test]
fn no_many_and_unphysical_answers_say_which_and_why() {
    refused(
        &["-m", "?,?", "-v", "?,10", "--fin", "40,90"],
        &["4 unknowns", "at most two"],
    );
    refused(&["-m", "?,1", "-v", "60,10"], &["3 unknowns (m1, f1, f2)"]);
    // FIN (70, 90) from m1 = 4, V = (60, 10): 240 + 10 m2 = 280 + 90 m2 needs m2 = -1/2.
    refused(
        &["-m", "4,?", "-v", "60,10", "--fin", "70,90"],
        &["unphysical", "m2 = -1/2"],
    );
    // FIN (55, 30): f2 - f1 = -25 < 0 after an approach of 50: e = -1/2, passing through.
    refused(
        &["-m", "4,1", "-v", "60,10", "--fin", "55,?"],
        &["unphysical", "pass through each other"],
    );
    refused(
        &["-m", "4,1", "-v", "60,10", "--fin", "?,?", "-e", "-3/2"],
        &["negative"],
    );
    // Equal IN velocities: they never meet, e is not determined.
    refused(
        &["-m", "1,1", "-v", "5,5", "--fin", "5,5"],
        &["infinitely many", "never meet"],
    );
    // '?' is for solve.
    let out = collide()
        .args(["frames", "-m", "4,?", "-v", "1,2"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("`collide solve` solves for unknowns"));
}

#[test]
fn units_are_kept_converted_or_refused() {
    // Shared units are kept: the lecture's 7,250 is ton mph^2.
    let j = json(&["-m", "4ton,1ton", "-v", "60mph,10mph", "--show", "energy"]);
    assert_eq!(j["energy"]["in"], 7250.0);
    assert_eq!(
        j["units"],
        serde_json::json!({"mass": "ton", "velocity": "mph", "energy": "ton mph^2"})
    );
    // Mixed units are converted exactly to SI: 1 t = 1000 kg, 72 km/h = 20 m/s.
    let j = json(&[
        "-m",
        "1500 kg,1 t",
        "-v",
        "72 km/h,0",
        "-e",
        "0",
        "--show",
        "vectors",
    ]);
    assert_eq!(j["in"], serde_json::json!([20.0, 0.0]));
    assert_eq!(j["v_com"], 12.0, "1500 x 20 / 2500");
    assert_eq!(j["units"]["energy"], "J");
    // --si: 60 mph = 26.8224 m/s = 16764/625 exactly, 4 ton = 4 x 907.18474 = 3628.73896 kg.
    let j = json(&[
        "-m",
        "4 ton,1 ton",
        "-v",
        "60 mph,10 mph",
        "--si",
        "--exact",
        "--show",
        "vectors",
    ]);
    assert_eq!(j["in"][0], "16764/625");
    assert_eq!(j["inertia"][0][0], "45359237/12500");
    // The homework example: 1500 kg at 72 km/h hits a parked 900 kg car and they stick: 45 km/h.
    let j = json(&[
        "-m",
        "1500 kg,900 kg",
        "-v",
        "72 km/h,0",
        "-e",
        "inelastic",
        "--show",
        "vectors",
    ]);
    assert_eq!(j["fin"], serde_json::json!([45.0, 45.0]));
    refused(
        &["-m", "4,1", "-v", "60 mhp,10"],
        &["'mhp'", "did you mean 'mph'"],
    );
    refused(
        &["-m", "4 T,1 T", "-v", "1,2"],
        &["ambiguous", "'t'", "'ton'"],
    );
    refused(&["-m", "4 kg,1", "-v", "1,2"], &["every mass or for none"]);
    // Units on the masses only: no null in JSON, and the text says the velocities are as given.
    let j = json(&["-m", "7 ton,6 ton", "-v", "90,10", "--show", "vectors"]);
    assert_eq!(
        j["units"],
        serde_json::json!({"mass": "ton", "energy": "ton x (velocity unit)^2"})
    );
    let text = stdout(&[
        "solve",
        "-m",
        "7 ton,6 ton",
        "-v",
        "90,10",
        "--show",
        "vectors",
    ]);
    assert!(
        text.contains("Units: masses in ton, velocities as given"),
        "{text}"
    );
    refused(&["-m", "4,1", "-v", "1,2", "--si"], &["--si needs a unit"]);
    refused(&["-m", "1e999,1", "-v", "1,2"], &["'1e999'", "too large"]);
}

#[test]
fn a_scenes_energy_unit_converts_every_energy_it_labels() {
    // energy_unit = "kJ" printed "energies in kJ" over joules: KE_IN = 1/2 1 kg (2 m/s)^2 = 2 J
    // = 0.002 kJ; per body (changes) 2 J and 0; crunch 1/2 (12/13) 4 = 24/13 J.
    let path = std::env::temp_dir().join(format!("collide-kj-{}.toml", std::process::id()));
    std::fs::write(
        &path,
        "masses = [\"1 kg\", \"12 kg\"]\nvelocities = [\"2 m/s\", \"0\"]\nenergy_unit = \"kJ\"\n\
         show = [\"energy\", \"changes\"]\n",
    )
    .unwrap();
    let p = path.to_str().unwrap();
    let j: Value = serde_json::from_str(&stdout(&["scene", p, "--format", "json"])).unwrap();
    let r = &j["report"];
    let close = |v: &Value, x: f64| (v.as_f64().unwrap() - x).abs() <= 4.0 * f64::EPSILON * x;
    assert!(close(&r["energy"]["in"], 0.002), "{}", r["energy"]);
    assert!(
        close(&r["energy"]["crunch"], 24.0 / 13.0 / 1000.0),
        "{}",
        r["energy"]
    );
    assert!(close(&r["changes"]["ke_in"][0], 0.002), "{}", r["changes"]);
    assert_eq!(r["units"]["energy"], "kJ");
    let text = stdout(&["scene", p]);
    assert!(
        text.contains("energies in kJ") && text.contains(" 0.002 "),
        "{text}"
    );
    // A [sweep] scene has no unit labels: energy_unit is refused, not ignored.
    std::fs::write(
        &path,
        "masses = [\"1 kg\", \"12 kg\"]\nvelocities = [\"2 m/s\", \"0\"]\nenergy_unit = \"kJ\"\n\
         [sweep]\nvary = [\"e=0,1\"]\n",
    )
    .unwrap();
    let out = collide().args(["scene", p]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--energy-unit kJ"));
    std::fs::remove_file(&path).unwrap();
}
