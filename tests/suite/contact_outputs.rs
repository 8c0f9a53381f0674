//! `collide contact`'s outputs: the JSON's shape and the law it names, the pictures (`--plot`)
//! and contact scenes (passing, and bad ones located by file and line).

use crate::common::collide;
use crate::contact::{args, run, scratch};

#[test]
fn json_has_the_documented_shape() {
    let j = run(&args(
        "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --right-wall 1.5 --stiffness 1 --damping 0.4 --wall-stiffness 1e10 --wall-zeta 1",
    ));
    let keys: Vec<&str> = j.as_object().unwrap().keys().map(|k| k.as_str()).collect();
    for key in [
        "law",
        "method",
        "time",
        "x",
        "v",
        "contacts",
        "energy",
        "stats",
        "impulse_model",
        "stop",
    ] {
        assert!(keys.contains(&key), "{key} missing from {keys:?}");
    }
    let c = &j["contacts"][1];
    assert_eq!(c["between"], serde_json::json!([2, "right"]));
    for key in ["start", "duration", "max_overlap"] {
        assert!(c[key].is_f64(), "{key}: {c}");
    }
    for key in ["start", "end", "dissipated"] {
        assert!(j["energy"][key].is_f64(), "{key}");
    }
    for key in ["steps", "rejected", "rhs_evals", "jacobians"] {
        assert!(j["stats"][key].is_u64(), "{key}");
    }
    assert!(
        j["stats"]["jacobians"].as_u64().unwrap() > 0,
        "bdf factors Jacobians"
    );
    assert_eq!(j["stop"], "done");
}

#[test]
fn plot_draws_the_history_of_each_contact() {
    let svg = scratch("history.svg");
    let out = collide()
        .args([
            "contact", "-m", "1,1,1", "-x", "0,1,2", "--sizes", "1,1,1", "-v", "1,0,0", "--law",
            "hertz", "--plot",
        ])
        .arg(&svg)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&svg).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let labels: Vec<&str> = doc.descendants().filter_map(|n| n.text()).collect();
    for label in ["1 & 2", "2 & 3", "force", "overlap", "time"] {
        assert!(labels.contains(&label), "{label} not in {labels:?}");
    }
    std::fs::remove_file(&svg).unwrap();
}

#[test]
fn contact_scenes_pass_and_bad_ones_are_located() {
    let names = args(
        "contact-single-zeta-0.2 contact-backstop-1e2 contact-backstop-1e4 contact-backstop-1e8 contact-backstop-1e10 contact-cradle-linear contact-cradle-hertz contact-superball",
    );
    let paths: Vec<String> = names
        .iter()
        .map(|n| format!("scenarios/{n}.toml"))
        .collect();
    let out = collide().arg("scene").args(&paths).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(text.contains("8 scenes: 8 pass, 0 fail"), "{text}");
    let good = std::fs::read_to_string("scenarios/contact-single-zeta-0.2.toml").unwrap();
    let line = good.lines().position(|l| l == "zeta = 0.2").unwrap() + 2;
    let friction = format!(":{line}:1: unknown field `friction`");
    let swap =
        |from: &str, to: &str| good.replacen(&format!("\n{from}\n"), &format!("\n{to}\n"), 1);
    for (edit, needle) in [
        (
            swap("zeta = 0.2", "zeta = 0.2\nfriction = 1"),
            friction.as_str(),
        ),
        (
            swap("zeta = 0.2", "zeta = 0.2\nrestitution = 0.5"),
            "at most one of damping, zeta, restitution",
        ),
        (
            swap("tol = 1e-12", "method = \"euler\""),
            "method 'euler': expected auto, symplectic-euler",
        ),
        (
            swap("stiffness = 1", "stiffness = -1"),
            "stiffness -1 must be",
        ),
        (
            swap("velocities = [1, 0]", "velocities = [1, 0, 2]"),
            "velocities: 3 values for 2 bodies",
        ),
        (
            good.replacen("\"contacts.0.duration\"", "\"contact.duration\"", 1),
            "contact",
        ),
    ] {
        let path = scratch("bad.toml");
        std::fs::write(&path, edit).unwrap();
        let out = collide().arg("scene").arg(&path).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{needle}: {err}");
        assert!(err.contains(needle), "{err} lacks {needle:?}");
        std::fs::remove_file(&path).unwrap();
    }
}

/// The JSON names the law the run used, as `--law` spells it.
#[test]
fn the_json_names_the_law() {
    for law in ["linear", "hertz", "hunt-crossley"] {
        let j = run(&args(&format!(
            "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --law {law}"
        )));
        assert_eq!(j["law"], law);
    }
}
