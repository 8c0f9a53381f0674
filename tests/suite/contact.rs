//! `collide contact` as a user runs it: the closed forms of a single contact (linear and Hertz)
//! for stiffness 1 to 1e12, the calibrated restitution, convergence to the impulse model as the
//! stiffness grows, the stiff backstop's limit (which the impulse model misses), energy
//! bookkeeping, unstable steps refused, the Hertz cradle, bad input, JSON, the pictures and the
//! work-precision report.
//!
//! Expected values are computed here from the closed forms (Schwager & Poeschel 2007 for the
//! linear law; Hertz's d_max and the contact-time integral as a Beta function), not taken from
//! the program.

use crate::common;

use std::f64::consts::PI;

use common::collide;
use serde_json::Value;

fn run(args: &[&str]) -> Value {
    let out = collide()
        .arg("contact")
        .args(args)
        .args(["--format", "json"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// Runs and expects exit 2 with `needle` in the message and nothing on stdout.
#[track_caller]
fn refused(args: &[&str], needle: &str) {
    let out = collide().arg("contact").args(args).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(err.contains(needle), "{args:?}: {err} lacks {needle:?}");
    assert!(out.stdout.is_empty(), "{args:?} wrote to stdout");
    assert!(!err.contains("panicked"), "{err}");
}

/// A command line's words.
fn args(line: &str) -> Vec<&str> {
    line.split_whitespace().collect()
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("{v} is not a number"))
}

fn floats(v: &Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(f).collect()
}

#[track_caller]
fn rel(actual: f64, expected: f64, tol: f64, what: &str) {
    let r = (actual - expected).abs() / expected.abs();
    assert!(
        r <= tol,
        "{what}: {actual} against {expected} (rel {r:.2e} > {tol:e})"
    );
}

/// The linear law's closed forms for reduced mass `mu`, impact speed `v`, ratio `zeta < 1`:
/// `(t_c, e, d_max)` with t_c = (pi - 2 atan(beta/omega)) / omega, e = exp(-beta t_c), and
/// d_max at the zero of d' (tan(omega t) = omega / beta): d = (v/omega) e^(-beta t) sin(omega t).
fn linear_closed(k: f64, mu: f64, zeta: f64, v: f64) -> (f64, f64, f64) {
    let w0 = (k / mu).sqrt();
    let w = w0 * (1.0 - zeta * zeta).sqrt();
    let beta = zeta * w0;
    let tc = (PI - 2.0 * (beta / w).atan()) / w;
    let tm = (w / beta).atan() / w;
    (
        tc,
        (-beta * tc).exp(),
        v / w * (-beta * tm).exp() * (w * tm).sin(),
    )
}

#[test]
fn a_single_linear_contact_gives_its_closed_forms_for_k_from_1_to_1e12() {
    // Two equal bodies touching, body 1 moving at 1: mu = 1/2.
    for k in ["1", "1e3", "1e6", "1e9", "1e12"] {
        let kk: f64 = k.parse().unwrap();
        let (tc, e, dmax) = linear_closed(kk, 0.5, 0.2, 1.0);
        let j = run(&args(&format!(
            "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --stiffness {k} --zeta 0.2 --tol 1e-12"
        )));
        let c = &j["contacts"][0];
        rel(f(&c["duration"]), tc, 1e-10, &format!("k = {k}: t_c"));
        rel(f(&c["restitution"]), e, 1e-10, &format!("k = {k}: e"));
        rel(
            f(&c["max_overlap"]),
            dmax,
            1e-10,
            &format!("k = {k}: d_max"),
        );
        // Impulse form: J = (1 + e) mu u.
        let v = floats(&j["v"]);
        rel(v[0], 1.0 - (1.0 + e) * 0.5, 1e-10, "v1");
        rel(v[1], (1.0 + e) * 0.5, 1e-10, "v2");
        assert_eq!(j["contacts"].as_array().unwrap().len(), 1);
    }
    // The lecture-style numbers quoted in the issue, from the same formulas.
    let (tc, e, _) = linear_closed(2.0, 1.0, 0.2, 1.0);
    rel(e, 0.5717400276, 1e-10, "e(zeta = 0.2)");
    rel(tc * 2f64.sqrt(), 2.7953544, 1e-7, "omega0 t_c(zeta = 0.2)");
}

#[test]
fn the_default_accuracy_is_1e_8_of_the_relative_speed() {
    // auto (no --tol): final velocities within 1e-8 of the initial relative speed (here 3).
    let (_, e, _) = linear_closed(1e4, 2.0 / 3.0, 0.5, 3.0);
    let j = run(&args(
        "-m 1,2 -x 0,1 --sizes 1,1 -v 2,-1 --stiffness 1e4 --zeta 0.5",
    ));
    let u = 3.0;
    let jimp = (1.0 + e) * (2.0 / 3.0) * u;
    let v = floats(&j["v"]);
    assert!((v[0] - (2.0 - jimp)).abs() <= 1e-8 * u, "{v:?}");
    assert!((v[1] - (-1.0 + jimp / 2.0)).abs() <= 1e-8 * u, "{v:?}");
}

#[test]
fn asking_for_e_gives_that_e() {
    for (args, e) in [
        (
            args("-m 1,3 -x 0,1 --sizes 1,1 -v 1,0 --stiffness 1e6 -e 0.5 --tol 1e-12"),
            0.5,
        ),
        (
            args(
                "-m 1 -x 0 --sizes 1 -v 1 --right-wall 0.5 --wall-stiffness 1e6 --wall-restitution 0.5 --tol 1e-12",
            ),
            0.5,
        ),
        (
            args("-m 2,1 -x 0,1 --sizes 1,1 -v 1,-1 --stiffness 10 -e 0.05 --tol 1e-12"),
            0.05,
        ),
    ] {
        let j = run(&args);
        rel(
            f(&j["contacts"][0]["restitution"]),
            e,
            1e-10,
            &format!("{args:?}"),
        );
    }
    // The wall case: the body leaves at -e v.
    let j = run(&args(
        "-m 1 -x 0 --sizes 1 -v 1 --right-wall 0.5 --wall-stiffness 1e6 --wall-restitution 0.5 --tol 1e-12",
    ));
    rel(floats(&j["v"])[0], -0.5, 1e-10, "v after the wall");
    rel(
        floats(&j["impulse_model"]["v"])[0],
        -0.5,
        0.0,
        "impulse model",
    );
}

#[test]
fn an_elastic_hertz_contact_gives_its_closed_forms() {
    // d_max = (5 mu v^2 / (4 k))^(2/5); t_c = 2 B d_max / v with B = int_0^1 dx / sqrt(1 -
    // x^(5/2)) = (2/5) Gamma(2/5) Gamma(1/2) / Gamma(9/10) (tabulated Gamma values).
    let b = 0.4 * 2.218_159_543_757_688 * PI.sqrt() / 1.068_628_702_119_319_4;
    rel(2.0 * b, 2.94328, 2e-6, "the issue's Hertz constant");
    for (k, m2, v) in [("1", "3", 1.0), ("1e6", "1", 2.0), ("1e12", "0.5", 1.0)] {
        let (kk, m2f): (f64, f64) = (k.parse().unwrap(), m2.parse().unwrap());
        let mu = m2f / (1.0 + m2f);
        let dmax = (5.0 * mu * v * v / (4.0 * kk)).powf(0.4);
        let masses = format!("1,{m2}");
        let speeds = format!("{v},0");
        let j = run(&args(&format!(
            "-m {masses} -x 0,1 --sizes 1,1 -v {speeds} --law hertz --stiffness {k} --tol 1e-12"
        )));
        let c = &j["contacts"][0];
        rel(
            f(&c["max_overlap"]),
            dmax,
            1e-10,
            &format!("k = {k}: d_max"),
        );
        rel(
            f(&c["duration"]),
            2.0 * b * dmax / v,
            1e-10,
            &format!("k = {k}: t_c"),
        );
        rel(f(&c["restitution"]), 1.0, 1e-10, "elastic");
        let e = &j["energy"];
        rel(f(&e["end"]), f(&e["start"]), 1e-10, "energy");
    }
}

#[test]
fn separate_contacts_converge_to_the_impulse_model_as_k_grows() {
    // Body 1 hits body 2, which then bounces off a wall: contacts apart in time. Velocities
    // match the impulse model (linear law: e exact at any k); positions at a later time differ
    // by O(t_c) = O(1/sqrt k): 100 times the stiffness, 10 times closer.
    let e = linear_closed(1.0, 1.0, 0.2, 1.0).1;
    let track = {
        let out = collide()
            .args(args(
                "track -m 1,2 -x 0,2 --sizes 1,1 -v 1,0 --right-wall 4 -e",
            ))
            .arg(e.to_string())
            .args(["--until", "8", "--format", "json"])
            .output()
            .unwrap();
        serde_json::from_slice::<Value>(&out.stdout).unwrap()
    };
    let tx = floats(&track["x"]);
    let mut gaps = Vec::new();
    for k in ["1e2", "1e4", "1e6", "1e8"] {
        let j = run(&args(&format!(
            "-m 1,2 -x 0,2 --sizes 1,1 -v 1,0 --right-wall 4 --stiffness {k} --zeta 0.2 --until 8"
        )));
        let (v, vi) = (floats(&j["v"]), floats(&j["impulse_model"]["v"]));
        for i in 0..2 {
            assert!(
                (v[i] - vi[i]).abs() <= 1e-8,
                "k = {k}: {v:?} against {vi:?}"
            );
        }
        let x = floats(&j["x"]);
        gaps.push((x[0] - tx[0]).abs().max((x[1] - tx[1]).abs()));
    }
    for w in gaps.windows(2) {
        let ratio = w[0] / w[1];
        assert!((9.0..11.0).contains(&ratio), "{gaps:?}");
    }
}

#[test]
fn the_stiff_backstop_reaches_its_own_limit_not_the_impulse_model() {
    // Body 2 rests against a wall of stiffness K (critically damped); body 1 hits it through a
    // soft contact (k = 1, c = 0.4). As K grows body 2 becomes a fixed backstop: body 1 bounces
    // off a fixed spring-dashpot with mu = m1 = 1, zeta = 0.4 / 2 = 0.2, so v1 -> -e(0.2) and
    // v2 -> 0. Sequential impulses (collide track) give something else entirely.
    let e = linear_closed(1.0, 1.0, 0.2, 1.0).1;
    let mut misses = Vec::new();
    for k in ["1e4", "1e6", "1e8"] {
        let j = run(&args(&format!(
            "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --right-wall 1.5 --stiffness 1 --damping 0.4 --wall-stiffness {k} --wall-zeta 1"
        )));
        assert_eq!(j["method"], "bdf", "auto picks a stiff method");
        let v = floats(&j["v"]);
        misses.push((v[0] + e).abs());
        let vi = floats(&j["impulse_model"]["v"]);
        assert!(
            (vi[0] - v[0]).abs() > 0.5,
            "impulse model {vi:?} against {v:?}"
        );
    }
    assert!(
        misses[0] < 1e-4 && misses[1] < 1e-6 && misses[2] < 1e-8,
        "{misses:?}"
    );
    assert!(misses[0] > 10.0 * misses[1], "{misses:?}");
}

#[test]
fn energy_is_kept_without_damping_and_never_created() {
    // 16 to 18 contacts, with symmetric impacts that begin and end together.
    for law in ["linear", "hertz"] {
        let j = run(&args(&format!(
            "-m 1,2,1 -x 0,1.5,3 --sizes 1,1,1 -v 1,0,-1 --law {law} --left-wall -2 --right-wall 5 --stiffness 100 --until 20"
        )));
        let e = &j["energy"];
        rel(f(&e["end"]), f(&e["start"]), 1e-8, law);
        assert!(f(&e["dissipated"]) >= 0.0);
    }
    for (law, d) in [("linear", "0.3"), ("hunt-crossley", "0.5")] {
        let j = run(&args(&format!(
            "-m 1,2,1 -x 0,1.5,3 --sizes 1,1,1 -v 1,0,-1 --law {law} --damping {d} --left-wall -2 --right-wall 5 --stiffness 100 --until 20"
        )));
        let e = &j["energy"];
        assert!(f(&e["dissipated"]) > 0.0, "{law}: {e}");
        assert!(f(&e["end"]) < f(&e["start"]), "{law}: {e}");
        rel(
            f(&e["start"]) - f(&e["dissipated"]),
            f(&e["end"]),
            1e-12,
            "bookkeeping",
        );
    }
}

#[test]
fn a_hertz_cradle_does_not_give_0_0_1() {
    // Three touching equal balls, elastic Hertz contacts: the time-domain answer (tsit45, bdf
    // and sdirk at tolerance 1e-13 agree to 1e-10), while the sequential impulses give
    // (0, 0, 1). Momentum is exact by construction, so it is checked tightly.
    let j = run(&args(
        "-m 1,1,1 -x 0,1,2 --sizes 1,1,1 -v 1,0,0 --law hertz --tol 1e-12",
    ));
    let v = floats(&j["v"]);
    let reference = [-0.070_952_353_66, 0.076_403_039_07, 0.994_549_314_6];
    for i in 0..3 {
        assert!((v[i] - reference[i]).abs() < 1e-9, "{v:?}");
    }
    assert_eq!(floats(&j["impulse_model"]["v"]), vec![0.0, 0.0, 1.0]);
    rel(v.iter().sum(), 1.0, 1e-12, "momentum");
}

#[test]
fn explicit_steps_past_the_stability_limit_are_refused() {
    let stiff = args(
        "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --right-wall 1.5 --stiffness 1 --damping 0.4 --wall-stiffness 1e10 --wall-zeta 1",
    );
    for method in ["verlet", "symplectic-euler", "rk4"] {
        let mut args = stiff.to_vec();
        args.extend(["--method", method, "--dt", "1e-3"]);
        refused(&args, "is unstable on the stiffest contact");
    }
    // Undamped, Verlet's limit is omega h = 2: k = 1e6 against a wall, mu = 1: h < 2e-3.
    let wall = args("-m 1 -x 0 --sizes 1 -v 1 --right-wall 0.5");
    let mut args = wall.to_vec();
    args.extend([
        "--wall-stiffness",
        "1e6",
        "--method",
        "verlet",
        "--dt",
        "2.1e-3",
    ]);
    refused(&args, "omega dt = 2.100 > 2.000");
    let mut args = wall.to_vec();
    args.extend([
        "--wall-stiffness",
        "1e6",
        "--method",
        "verlet",
        "--dt",
        "1e-5",
    ]);
    let j = run(&args);
    rel(floats(&j["v"])[0], -1.0, 1e-6, "verlet below its limit");
}

#[test]
fn bad_input_is_refused_with_exit_2() {
    let two = args("-m 1,1 -x 0,1 --sizes 1,1 -v 1,0");
    let with = |extra: &[&'static str]| {
        let mut a = two.to_vec();
        a.extend(extra);
        a
    };
    refused(
        &with(&["--stiffness", "0"]),
        "stiffness 0 must be a finite number > 0",
    );
    refused(&with(&["--stiffness", "-1"]), "stiffness -1");
    refused(&with(&["--stiffness", "inf"]), "stiffness inf");
    refused(&with(&["-e", "0"]), "restitution 0 cannot be reached");
    refused(&with(&["-e", "1.5"]), "restitution 1.5");
    refused(&with(&["--damping", "-1"]), "damping -1");
    refused(
        &with(&["--law", "hertz", "--zeta", "0.2"]),
        "hertz contacts take no --zeta",
    );
    refused(
        &with(&["--law", "hunt-crossley", "-e", "0.5"]),
        "hunt-crossley",
    );
    refused(
        &with(&["--method", "bdf", "--dt", "0.1"]),
        "--dt is for the fixed-step",
    );
    refused(
        &with(&["--method", "rk4", "--tol", "1e-6"]),
        "--dt is for the fixed-step",
    );
    refused(&with(&["--method", "rk4", "--dt", "-1"]), "--dt -1");
    refused(&with(&["--tol", "0"]), "--tol 0");
    refused(&with(&["--until", "-1"]), "-1");
    refused(
        &with(&["--zeta", "0.2", "-e", "0.5"]),
        "cannot be used with",
    );
    refused(&with(&["--methods", "rk4"]), "--work-precision");
    refused(&args("-m 1,1 -x 0,0.5 --sizes 1,1 -v 1,0"), "overlap");
    refused(
        &with(&args("--method rk4 --dt 1e-9 --max-steps 1000")),
        "more than 1000 steps",
    );
}

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
fn work_precision_measures_every_method_against_the_exact_answer() {
    let svg = scratch("wpd.svg");
    let mut line = args(
        "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --stiffness 1 --zeta 0.2 --work-precision \
         --methods verlet,implicit-euler,bdf --plot",
    );
    line.push(svg.to_str().unwrap());
    let j = run(&line);
    assert_eq!(j["reference"]["kind"], "exact");
    let e = linear_closed(1.0, 0.5, 0.2, 1.0).1;
    let v = floats(&j["reference"]["v"]);
    rel(v[0], 1.0 - (1.0 + e) * 0.5, 1e-15, "exact reference");
    let rows = j["rows"].as_array().unwrap();
    for method in ["verlet", "implicit-euler", "bdf"] {
        let mine: Vec<&Value> = rows.iter().filter(|r| r["method"] == method).collect();
        assert!(mine.len() >= 3, "{method}: {} rows", mine.len());
        let errors: Vec<f64> = mine.iter().filter_map(|r| r["error"].as_f64()).collect();
        // Smaller steps or tolerances: the error falls by orders of magnitude.
        let (first, best) = (
            errors[0],
            errors.iter().cloned().fold(f64::INFINITY, f64::min),
        );
        assert!(best < first * 1e-3, "{method}: {errors:?}");
        for r in &mine {
            assert!(r["ns"].as_f64().is_some_and(|ns| ns > 0.0) || r["unstable"] == true);
            assert!(r["kind"] == "explicit" || r["kind"] == "implicit");
        }
    }
    let text = std::fs::read_to_string(&svg).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let labels: Vec<&str> = doc.descendants().filter_map(|n| n.text()).collect();
    for m in ["verlet", "implicit-euler", "bdf"] {
        assert!(labels.contains(&m), "{m} not in {labels:?}");
    }
    std::fs::remove_file(&svg).unwrap();
}

#[test]
fn work_precision_marks_unstable_rows() {
    let j = run(&args(
        "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --right-wall 1.5 --stiffness 1 --damping 0.4 --wall-stiffness 1e6 --wall-zeta 1 --work-precision --methods verlet,bdf",
    ));
    assert_eq!(j["reference"]["kind"], "run");
    assert!(f(&j["reference"]["uncertainty"]) < 1e-9);
    let rows = j["rows"].as_array().unwrap();
    let verlet: Vec<&Value> = rows.iter().filter(|r| r["method"] == "verlet").collect();
    assert!(verlet[0]["unstable"] == true && verlet[0].get("error").is_none());
    assert!(verlet.iter().any(|r| r["unstable"] == false));
    // bdf reaches 1e-6 error for far less work than Verlet.
    let cheapest = |m: &str| {
        rows.iter()
            .filter(|r| r["method"] == m && r["error"].as_f64().is_some_and(|e| e <= 1e-6))
            .map(|r| r["rhs_evals"].as_u64().unwrap())
            .min()
            .unwrap()
    };
    assert!(cheapest("bdf") * 10 < cheapest("verlet"), "{rows:?}");
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

/// A file name in the temporary folder, unique to this process.
fn scratch(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("collide-contact-{}-{name}", std::process::id()))
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

#[test]
fn odd_layouts_are_refused_or_handled() {
    // Points cannot overlap without passing through each other.
    refused(&args("-m 1,1 -x 0,1 -v 1,0"), "body 1 has size 0");
    // Contacts far too short for binary64 stepping are refused at once, not run to the cap.
    refused(
        &args("-m 1e300,1e-300 -x 0,1 --sizes 1,1 -v 1,0"),
        "too short to integrate",
    );
    // A light body (contact time 3e-12, under diffsol's default 1e-13 floor on steps):
    // elastic, so v2 = 2 m1 / (m1 + m2) = 2 to 1e-8.
    let j = run(&args("-m 1,1e-24 -x 0,1 --sizes 1,1 -v 1,0"));
    assert!((floats(&j["v"])[1] - 2.0).abs() < 1e-8, "{}", j["v"]);
    // --until 0 with a contact under way at the start: the state at 0.
    let j = run(&args("-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --until 0"));
    assert_eq!(floats(&j["v"]), vec![1.0, 0.0]);
    assert_eq!(j["stop"], "until");
    // Huge values in messages are short.
    refused(
        &args("-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --method rk4 --dt 1e300"),
        "--dt 1e300 is unstable",
    );
}

#[test]
fn a_large_common_velocity_does_not_swamp_the_contact() {
    // Case: zeta = 0.2 between equal bodies, relative speed 1, both moving at about 1e8. The
    // loss is mu u^2 (1 - e^2) / 2 = (1 - e^2) / 4 whatever the common velocity (it was printed
    // as 0 when the lab energies, 1e16, were subtracted).
    let e = linear_closed(1.0, 0.5, 0.2, 1.0).1;
    let j = run(&args(
        "-m 1,1 -x 0,1 --sizes 1,1 -v 100000001,100000000 --zeta 0.2 --tol 1e-12",
    ));
    rel(
        f(&j["energy"]["dissipated"]),
        (1.0 - e * e) / 4.0,
        1e-9,
        "dissipated",
    );
    rel(f(&j["contacts"][0]["restitution"]), e, 1e-9, "e");
    let v = floats(&j["v"]);
    // Each velocity to the binary64 resolution of 1e8 (1.5e-8) and the 1e-9 contact accuracy.
    assert!((v[0] - (1e8 + 1.0 - (1.0 + e) / 2.0)).abs() < 3e-8, "{v:?}");
    assert!((v[1] - (1e8 + (1.0 + e) / 2.0)).abs() < 3e-8, "{v:?}");
}

// Issue 24: false physics or numbers from `collide contact`, each refused or corrected.

/// Runs `collide contact args`: (exit code, stdout, stderr).
fn outcome(args: &[&str]) -> (i32, String, String) {
    let out = collide().arg("contact").args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn bodies_that_pass_through_each_other_or_a_wall_are_refused_at_the_step_it_happens() {
    // A soft contact (k = 0.1, mu = 1/2, v = 1: d_max = v / sqrt(k / mu) = 2.236 > (s1 + s2)/2
    // = 1) lets the centres cross and come back within one stretch; it was printed with exit 0
    // and max_overlap 2.236 (refused only with --until 5, where the crossing was at the end).
    for line in [
        "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --stiffness 0.1",
        "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --stiffness 0.1 --format json",
        "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --stiffness 0.1 --method rk4",
        "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --stiffness 0.1 --method bdf",
        // Sizes 1e-300: any overlap at all crosses the centres (both ended at 2.1107).
        "-m 1,1 -x 0,1 --sizes 1e-300,1e-300 -v 1,0",
        // k = 5e-324 printed "impulse model: e = NaN" and d_max 3e161.
        "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --stiffness 5e-324",
        "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --stiffness 5e-324 --work-precision",
    ] {
        let (code, out, err) = outcome(&args(line));
        assert_eq!(code, 2, "{line}: {out}{err}");
        assert!(out.is_empty(), "{line}: {out}");
        for needle in [
            "bodies 1 and 2 passed through each other at t = ",
            "x1 = ",
            "x2 = ",
            "--stiffness",
            "smaller speed",
        ] {
            assert!(err.contains(needle), "{line}: {err} lacks {needle:?}");
        }
        assert!(!err.contains("NaN") && !err.contains("inf"), "{err}");
    }
    // Through a wall: k = 0.01 against m = 1 at v = 1 needs d_max = 10, past the centre at 0.5.
    let (code, _, err) = outcome(&args(
        "-m 1 -x 0 --sizes 1 -v 1 --right-wall 0.5 --wall-stiffness 0.01",
    ));
    assert_eq!(code, 2, "{err}");
    for needle in [
        "body 1 passed through the right wall at t = ",
        "with the wall at 0.5",
        "--wall-stiffness, now 0.01",
    ] {
        assert!(err.contains(needle), "{err} lacks {needle:?}");
    }
    // Just stiff enough (d_max = sqrt(mu / k) = 0.707 < 1 at k = 1): runs, and the deepest
    // overlap is the closed form's, below the sum of the half sizes.
    let j = run(&args("-m 1,1 -x 0,1 --sizes 1,1 -v 1,0"));
    let d = f(&j["contacts"][0]["max_overlap"]);
    rel(d, 0.5f64.sqrt(), 1e-9, "d_max = v / omega0");
}

#[test]
fn heavy_damping_is_stiff_and_auto_integrates_it_with_bdf() {
    // A heavily damped contact's decay rate c/mu = 2 zeta omega0 outruns its own time scale:
    // tsit45 (which auto picked) ran 10-14 s to the 2e7-step cap. Expected: the closed forms of
    // an overdamped linear contact (Schwager & Poeschel; zeta > 1):
    // omega0 t_c = 2 ln(zeta + s) / s with s = sqrt(zeta^2 - 1), e = exp(-zeta omega0 t_c).
    let e_of = |zeta: f64| {
        let s = ((zeta - 1.0) * (zeta + 1.0)).sqrt();
        (-zeta * 2.0 * (zeta - 1.0 + s).ln_1p() / s).exp()
    };
    // mu = 1/2, k = 1: c = 1e10 is zeta = 1e10 / (2 sqrt(1/2)).
    for (flag, value, zeta) in [
        ("--zeta", "1e6", 1e6),
        ("--damping", "1e10", 1e10 / 2f64.sqrt()),
    ] {
        let j = run(&[
            "-m", "1,1", "-x", "0,1", "--sizes", "1,1", "-v", "1,0", flag, value,
        ]);
        assert_eq!(j["method"], "bdf", "{flag} {value}");
        let e = e_of(zeta);
        let v = floats(&j["v"]);
        // Impulse form J = (1 + e) mu u, to the default accuracy (1e-8 of the speed, 1).
        assert!(
            (v[0] - (1.0 - e) / 2.0).abs() < 1e-8,
            "{flag} {value}: {v:?}"
        );
        assert!(
            (v[1] - (1.0 + e) / 2.0).abs() < 1e-8,
            "{flag} {value}: {v:?}"
        );
    }
    let j = run(&args("-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 -e 1e-10"));
    assert_eq!(j["method"], "bdf");
    let v = floats(&j["v"]);
    assert!((v[1] - (1.0 + 1e-10) / 2.0).abs() < 1e-8, "{v:?}");
    // Light damping stays with tsit45.
    let j = run(&args("-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --zeta 0.2"));
    assert_eq!(j["method"], "tsit45");
}

#[test]
fn a_body_between_two_walls_asks_for_until_not_a_tolerance() {
    // It bounces for ever; the run failed after 15 s suggesting --tol.
    let (code, out, err) = outcome(&args(
        "-m 1 -x 0 --sizes 1 -v 1 --left-wall -0.5 --right-wall 0.5",
    ));
    assert_eq!(code, 2, "{out}{err}");
    assert!(err.contains("--until") && !err.contains("--tol"), "{err}");
    // With --until it runs (stiff enough walls: d_max = 1e-2): elastic, so the energy (kinetic
    // and elastic) stays 1/2 m v^2 = 1/2, to the default accuracy.
    let j = run(&args(
        "-m 1 -x 0 --sizes 0.5 -v 1 --left-wall -0.5 --right-wall 0.5 --stiffness 1e4 --until 10",
    ));
    rel(f(&j["energy"]["end"]), 0.5, 1e-8, "energy at t = 10");
    assert!(
        j["contacts"].as_array().unwrap().len() > 10,
        "{}",
        j["contacts"]
    );
    // At rest between the walls: nothing happens, and that is the answer.
    let j = run(&args(
        "-m 1 -x 0 --sizes 1 -v 0 --left-wall -0.5 --right-wall 0.5",
    ));
    assert_eq!(floats(&j["v"]), vec![0.0]);
}

#[test]
fn a_horizon_below_the_solvers_resolution_returns_the_initial_state() {
    // "ODE solver error: Stop time is at the current state time", exit 2.
    for method in ["auto", "bdf", "sdirk", "rk4"] {
        let j = run(&args(&format!(
            "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --until 1e-300 --method {method}"
        )));
        assert_eq!(floats(&j["v"]), vec![1.0, 0.0], "{method}");
        // x1 = 0 + 1 x 1e-300, exactly.
        assert_eq!(floats(&j["x"]), vec![1e-300, 1.0], "{method}");
        assert_eq!(j["stop"], "until");
    }
}

#[test]
fn damping_too_heavy_to_integrate_says_so_and_not_rescale_the_masses() {
    // -e 1e-300 needs zeta ~ 5e149: the contact lasts 2e-150. The message said "rescale the
    // units (masses, stiffness)", which changes nothing about a restitution.
    let (code, _, err) = outcome(&args("-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 -e 1e-300"));
    assert_eq!(code, 2, "{err}");
    for needle in ["damping", "larger restitution", "collide track -e 0"] {
        assert!(err.contains(needle), "{err} lacks {needle:?}");
    }
    assert!(!err.contains("rescale"), "{err}");
    // The bound it names works: e just above it runs.
    let bound: f64 = err
        .split("e >= ")
        .nth(1)
        .and_then(|t| t.split(' ').next())
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("no bound in {err}"));
    let e = format!("{:e}", bound * 1.01);
    let (code, _, err) = outcome(&[
        "-m", "1,1", "-x", "0,1", "--sizes", "1,1", "-v", "1,0", "-e", &e,
    ]);
    assert!(!err.contains("too short"), "-e {e}: {code} {err}");
    // Masses that make the contact short still say rescale.
    refused(
        &args("-m 1e300,1e-300 -x 0,1 --sizes 1,1 -v 1,0"),
        "rescale the units",
    );
}

#[test]
fn work_precision_refuses_the_flags_of_a_single_run() {
    // --method, --dt and --tol were silently ignored by the ladder.
    let base = "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --work-precision --methods rk4";
    for extra in ["--method bdf", "--dt 1e-3", "--tol 1e-6", "--max-steps 10"] {
        let line = format!("{base} {extra}");
        let flag = extra.split(' ').next().unwrap();
        refused(&args(&line), &format!("{flag} is for one run"));
    }
}

#[test]
fn the_reduced_mass_of_tiny_or_huge_masses_does_not_underflow() {
    // mu = m1 m2 / (m1 + m2) underflowed to 0 for masses 1e-200 (the contact "lasted 0e0" and
    // was refused); 1e200 overflowed. Elastic, equal masses: the bodies swap velocities.
    for (m, k) in [("1e-200,1e-200", "1"), ("1e200,1e200", "1e200")] {
        let j = run(&args(&format!(
            "-m {m} -x 0,1 --sizes 1,1 -v 1,0 --stiffness {k}"
        )));
        let v = floats(&j["v"]);
        assert!(v[0].abs() < 1e-8 && (v[1] - 1.0).abs() < 1e-8, "{m}: {v:?}");
    }
}
