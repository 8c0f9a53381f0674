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
    refused(&args, "omega dt = 2.100, not below 2.000");
    // The step it suggests is the limit over omega: 2 / 1000 s.
    refused(&args, "use --dt below 2.000e-3 or an implicit method");
    // At the limit itself (omega h = 1000 x 0.002 = 2 exactly in binary64): symplectic Euler
    // and Verlet have a double eigenvalue -1 there, and the run blew up at its first step
    // ("the energy grew to 5.000e0 times its start"): refused up front instead.
    for method in ["symplectic-euler", "verlet"] {
        let mut args = wall.to_vec();
        args.extend([
            "--wall-stiffness",
            "1e6",
            "--method",
            method,
            "--dt",
            "2e-3",
        ]);
        refused(&args, "omega dt = 2.000, not below 2.000");
    }
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
    // RK4's limit on the imaginary axis is omega h = 2 sqrt 2 = 2.828: refused at h = 2.9e-3,
    // run at 2.7e-3.
    for (dt, refused_here) in [("2.9e-3", true), ("2.7e-3", false)] {
        let mut args = wall.to_vec();
        args.extend(["--wall-stiffness", "1e6", "--method", "rk4", "--dt", dt]);
        if refused_here {
            refused(&args, "omega dt = 2.900, not below 2.828");
        } else {
            assert_eq!(run(&args)["method"], "rk4");
        }
    }
}

/// Work counters of the adaptive methods: Tsitouras 5(4) has 7 stages, the first the last
/// one of the step before (FSAL): 6 evaluations a step taken or rejected, and a few to
/// start; BDF and SDIRK evaluate at least once a step.
#[test]
fn adaptive_methods_count_their_evaluations() {
    for method in ["tsit45", "bdf", "sdirk"] {
        let j = run(&args(&format!(
            "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --method {method}"
        )));
        let n = |k: &str| j["stats"][k].as_u64().unwrap();
        let (steps, evals) = (n("steps") + n("rejected"), n("rhs_evals"));
        assert!(steps > 10, "{method}: {steps} steps");
        if method == "tsit45" {
            assert!(
                (6 * steps..=6 * steps + 10).contains(&evals),
                "{method}: {evals} evaluations for {steps} steps"
            );
        } else {
            assert!(
                evals >= steps,
                "{method}: {evals} evaluations for {steps} steps"
            );
        }
    }
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
    // A step too small for the budget is refused before the run: the contact lasts pi/sqrt(2)
    // = 2.2214 (k = 1, reduced mass 1/2), so --dt 1e-9 needs 2.2e9 steps; the least step within
    // 1000 steps is 2.2214e-3. At 5e-324 the count is past binary64's range (the run used to
    // repeat steps lost in the time's rounding and grew to gigabytes).
    for needle in [
        "--dt 1e-9 is too small",
        "2.22144146907918)",
        "2.221e9 steps",
        "--max-steps 1000;",
        "0.00222144146907918 or more",
    ] {
        refused(
            &with(&args("--method rk4 --dt 1e-9 --max-steps 1000")),
            needle,
        );
    }
    refused(
        &with(&args("--method rk4 --dt 5e-324")),
        "would take more than 1.798e308 steps",
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

/// A method's ladder stops at the first rung whose error is below 1e-11 (`work::ENOUGH`):
/// RK4, fourth order, divides its error by about 16 a halving of the step, from 8e-5 at the
/// first rung: below 1e-11 after 6 halvings, the 7th and last row.
#[test]
fn work_precision_stops_a_ladder_once_it_is_accurate_enough() {
    let j = run(&args(
        "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --stiffness 1 --zeta 0.2 --work-precision \
         --methods rk4",
    ));
    let errors: Vec<f64> = j["rows"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["error"].as_f64().unwrap())
        .collect();
    let enough = collide::contact::work::ENOUGH;
    assert_eq!(enough, 1e-11);
    assert_eq!(errors.len(), 7, "{errors:?}");
    assert!(errors[6] < enough, "{errors:?}");
    assert!(errors[..6].iter().all(|e| *e >= enough), "{errors:?}");
    for w in errors.windows(2) {
        let ratio = w[0] / w[1];
        assert!((10.0..25.0).contains(&ratio), "{errors:?}");
    }
}

/// Newton's iteration in an implicit step stops when a correction is at rounding level: at
/// least two iterations a step (the first corrects the predictor by about the step times a
/// rate, far above rounding), and about two in all (it converges quadratically: on the linear
/// law the first lands exactly, a linear system). So 2 to 3 Jacobians a step, on both laws
/// and both implicit one-step methods, and one evaluation more than Jacobians a solve.
#[test]
fn implicit_steps_iterate_newton_to_rounding() {
    for law in ["linear", "hertz"] {
        for method in ["implicit-euler", "implicit-midpoint"] {
            let j = run(&args(&format!(
                "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --stiffness 1 --law {law} \
                 --method {method} --dt 1e-3"
            )));
            let steps = j["stats"]["steps"].as_f64().unwrap();
            let jacobians = j["stats"]["jacobians"].as_f64().unwrap();
            assert!(steps > 2000.0, "{law} {method}: {steps} steps");
            // One evaluation for the predictor of each solve (a step, or a partial step of the
            // event search: a few), then one a Newton iteration (each with its Jacobian).
            let evals = j["stats"]["rhs_evals"].as_f64().unwrap();
            let solves = evals - jacobians;
            assert!(
                solves >= steps && solves <= steps + 50.0,
                "{law} {method}: {evals} evaluations, {jacobians} Jacobians, {steps} steps"
            );
            assert!(
                (2.0 * steps..=3.0 * steps).contains(&jacobians),
                "{law} {method}: {jacobians} Jacobians for {steps} steps"
            );
        }
    }
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

/// A setup through the library: bodies `(mass, x, v, size)` under one undamped law of
/// stiffness `k` between them (and default walls' law).
fn library_setup(
    bodies: &[(f64, f64, f64, f64)],
    kind: collide::contact::LawKind,
    k: f64,
) -> collide::contact::Setup {
    use collide::line::inertia::Mass;
    let bodies = bodies
        .iter()
        .map(|&(m, x, v, size)| collide::track::Body {
            m: Mass::from_f64(m).unwrap(),
            x,
            v,
            size,
        })
        .collect();
    let laws = collide::contact::Laws {
        kind,
        k,
        damping: None,
        wall_k: None,
        wall_damping: None,
    };
    collide::contact::Setup::new(bodies, (None, None), laws)
}

/// Work-precision's exact reference (one contact, in closed form): an undamped linear wall
/// has e = 1, so a body moving towards it leaves with -v; one moving away never touches it
/// and keeps v. On either wall (the guards on the direction, each way). A pair (masses 1 and 3,
/// speeds 3 and 1, mu = 3/4) closes at u = 2 (a sum of the speeds would be 4) and takes J = (1
/// + e) mu u = 2 x 3/4 x 2 = 3: 0 and 2.
#[test]
fn the_exact_reference_bounces_only_towards_a_wall() {
    use collide::contact::{LawKind, work};
    for (walls, v, want) in [
        ((None, Some(2.0)), 1.0, -1.0),
        ((None, Some(2.0)), -1.0, -1.0),
        ((Some(-2.0), None), -1.0, 1.0),
        ((Some(-2.0), None), 1.0, 1.0),
    ] {
        let bodies = library_setup(&[(1.0, 0.0, v, 1.0)], LawKind::Linear, 1.0).bodies;
        let setup = collide::contact::Setup::new(bodies, walls, linear_laws());
        let exact = work::exact(&setup).unwrap().expect("one contact");
        assert_eq!(exact, vec![want], "walls {walls:?}, v = {v}");
    }
    let bodies = library_setup(
        &[(1.0, 0.0, 3.0, 1.0), (3.0, 2.0, 1.0, 1.0)],
        LawKind::Linear,
        1.0,
    )
    .bodies;
    let setup = collide::contact::Setup::new(bodies, (None, None), linear_laws());
    assert_eq!(work::exact(&setup).unwrap(), Some(vec![0.0, 2.0]));
}

/// Work-precision's errors are relative to the speed scale: a linear contact at twice the
/// speed is the same motion scaled by 2 (its frequencies do not depend on speed), so every
/// rung's error is the same number at -v 1,0 and -v 2,0 (to the rounding of the event
/// search), and its steps the same. (Every other ladder tested closes at 1, where dividing by
/// the speed or not agree.)
#[test]
fn work_precision_errors_are_relative_to_the_speed() {
    let ladder = |v: &str| {
        let j = run(&args(&format!(
            "-m 1,1 -x 0,1 --sizes 1,1 -v {v} --stiffness 4 --zeta 0.2 --work-precision --methods rk4"
        )));
        j["rows"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| (f(&r["error"]), f(&r["steps"])))
            .collect::<Vec<_>>()
    };
    let (one, two) = (ladder("1,0"), ladder("2,0"));
    assert!(one.len() >= 4, "{one:?}");
    for ((e1, s1), (e2, s2)) in one.iter().zip(&two) {
        assert_eq!(s1, s2, "steps");
        rel(*e2, *e1, 1e-6, &format!("error at {s1} steps"));
    }
}

/// With no relative speed at all (two bodies moving together, no wall: a speed scale of 0)
/// nothing touches, so every rung is exact: errors of 0, and a run reference's uncertainty 0
/// (not 0 / 0: errors are relative to the speed scale, or to 1 m/s where it is 0).
#[test]
fn work_precision_with_no_relative_speed_is_exact() {
    for until in ["", " --until 1"] {
        let j = run(&args(&format!(
            "-m 1,1 -x 0,1 --sizes 1,1 -v 1,1 --work-precision --methods rk4,bdf{until}"
        )));
        assert_eq!(floats(&j["reference"]["v"]), [1.0, 1.0], "{until}");
        if !until.is_empty() {
            assert_eq!(f(&j["reference"]["uncertainty"]), 0.0);
        }
        let rows = j["rows"].as_array().unwrap();
        assert!(rows.len() >= 2, "{j}");
        for r in rows {
            assert_eq!(f(&r["error"]), 0.0, "{until}: {r}");
        }
    }
}

/// The speed scale is the largest relative speed at the start: between the bodies (two at 3
/// and 3: none), and against a wall when there is one, either one (a body's own speed: 3).
#[test]
fn the_speed_scale_counts_a_wall_on_either_side() {
    use collide::contact::{LawKind, Setup};
    let bodies = library_setup(
        &[(1.0, 0.0, 3.0, 1.0), (1.0, 2.0, 3.0, 1.0)],
        LawKind::Linear,
        1.0,
    )
    .bodies;
    for (walls, want) in [
        ((None, None), 0.0),
        ((Some(-5.0), None), 3.0),
        ((None, Some(5.0)), 3.0),
        ((Some(-5.0), Some(5.0)), 3.0),
    ] {
        let setup = Setup::new(bodies.clone(), walls, linear_laws());
        assert_eq!(setup.speed_scale(), want, "walls {walls:?}");
    }
}

/// The linear law of stiffness 1, undamped, for pairs and walls.
fn linear_laws() -> collide::contact::Laws {
    collide::contact::Laws {
        kind: collide::contact::LawKind::Linear,
        k: 1.0,
        damping: None,
        wall_k: None,
        wall_damping: None,
    }
}

/// Settings for a library run: `method` (`None`: auto) with step `dt`, a trace if asked.
fn library_settings(
    method: Option<collide::contact::Method>,
    dt: Option<f64>,
    trace: bool,
) -> collide::contact::Settings {
    collide::contact::Settings {
        method,
        dt,
        tol: None,
        until: None,
        max_steps: 1_000_000,
        trace,
    }
}

/// The library refuses bodies that overlap at the start, by number, as the command line does
/// (sizes 1 and 3 with centres 1.9 apart, under half their sum, 2; sizes 1, 1, 1 with the second
/// pair 0.9 apart, under 1); touching is allowed, and the contact then starts at once. Apart,
/// it starts when the gap closes: centres 5 apart, reach 2, closing at 1 m/s: at t = 3 s.
#[test]
fn the_library_refuses_overlaps_and_contacts_start_when_the_gap_closes() {
    use collide::contact::{ContactError, LawKind, simulate};
    let settings = library_settings(None, None, false);
    let simulated = |bodies: &[(f64, f64, f64, f64)]| {
        simulate(&library_setup(bodies, LawKind::Linear, 100.0), &settings)
    };
    let refused = |bodies: &[(f64, f64, f64, f64)]| match simulated(bodies) {
        Err(e @ ContactError::Track(_)) => e.to_string(),
        other => panic!("expected an overlap, got {:?}", other.map(|_| "a run")),
    };
    let m = refused(&[(1.0, 0.0, 1.0, 1.0), (1.0, 1.9, 0.0, 3.0)]);
    assert!(m.starts_with("bodies 1 and 2 overlap"), "{m}");
    let m = refused(&[
        (1.0, 0.0, 0.0, 1.0),
        (1.0, 1.0, 0.0, 1.0),
        (1.0, 1.9, 0.0, 1.0),
    ]);
    assert!(m.starts_with("bodies 2 and 3 overlap"), "{m}");
    let touching = simulated(&[(1.0, 0.0, 1.0, 1.0), (1.0, 2.0, 0.0, 3.0)]).unwrap();
    assert_eq!(touching.contacts[0].start, 0.0);
    let apart = simulated(&[(1.0, 0.0, 1.0, 1.0), (1.0, 5.0, 0.0, 3.0)]).unwrap();
    let start = apart.contacts[0].start;
    assert!((start - 3.0).abs() <= 4.0 * f64::EPSILON * 3.0, "{start}");
}

/// The default step of a fixed-step method, from the contacts' durations pi / omega0: the
/// pair (k = 1, mu = 1/2) lasts pi / sqrt 2 = 2.221 s, the wall (k = 16, m = 1) pi / 4 =
/// 0.785 s. An explicit method takes 64 steps of the shortest (pi / 256: stability), an
/// implicit one 1000 of the longest (pi / (1000 sqrt 2): accuracy on the slowest).
#[test]
fn fixed_steps_default_to_the_contacts_durations() {
    let line = "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --right-wall 5 --wall-stiffness 16 --method";
    let pi = std::f64::consts::PI;
    for (method, dt) in [
        ("rk4", pi / 256.0),
        ("verlet", pi / 256.0),
        ("implicit-euler", pi / 2f64.sqrt() / 1000.0),
        ("implicit-midpoint", pi / 2f64.sqrt() / 1000.0),
    ] {
        let j = run(&args(&format!("{line} {method}")));
        rel(j["dt"].as_f64().unwrap(), dt, 4.0 * f64::EPSILON, method);
    }
}

/// A contact that begins at an approach below 1e-8 of the run's speed scale (its largest
/// relative speed) counts as pressed, not as an impact, and has no restitution. Bodies 1 and 2
/// touch and close at 1e-5 while body 3 leaves: at 1e4 (scale 1e4, threshold 1e-4: pressed)
/// or at 1e-3 (threshold 1e-11: an impact, undamped, e = 1).
#[test]
fn a_contact_closing_far_slower_than_the_run_is_pressed() {
    for (v3, impact) in [("1e4", false), ("1e-3", true)] {
        let j = run(&args(&format!(
            "-m 1,1,1 -x 0,1,10 -v 1e-5,0,{v3} --sizes 1,1,1 --stiffness 1"
        )));
        let c = &j["contacts"][0];
        assert_eq!(c["between"], serde_json::json!([1, 2]), "{v3}");
        rel(c["speed"].as_f64().unwrap(), 1e-5, 1e-7, "closing speed");
        if impact {
            rel(c["restitution"].as_f64().unwrap(), 1.0, 1e-8, "e");
        } else {
            assert!(c.get("restitution").is_none_or(|e| e.is_null()), "{c}");
        }
    }
}

/// Work counters: a fixed-step method costs its stages per step (RK4 4, Verlet 2, symplectic
/// Euler 1), on every step taken and on each step the event search retries (a few per
/// contact): so a multiple of the stages, at least stages x steps, and not 10% more.
#[test]
fn fixed_steps_count_their_stages() {
    for (method, stages) in [("rk4", 4), ("verlet", 2), ("symplectic-euler", 1)] {
        let j = run(&args(&format!(
            "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --method {method} --dt 1e-3"
        )));
        let n = |k: &str| j["stats"][k].as_u64().unwrap();
        let (steps, evals) = (n("steps"), n("rhs_evals"));
        // The contact lasts pi / sqrt 2 = 2.22 s: 2,222 steps of 1e-3.
        assert_eq!(steps, 2222, "{method}");
        assert_eq!(evals % stages, 0, "{method}: {evals}");
        assert!(
            evals >= stages * steps && evals <= stages * steps * 11 / 10,
            "{method}: {evals} evaluations for {steps} steps"
        );
    }
}

/// The history kept for `--plot` is thinned to every other sample whenever it reaches its cap
/// (100,000): a contact of pi / sqrt 2 = 2.22 s stepped at 1e-5 (222,000 samples) keeps at most
/// the cap, spread over the whole contact (no gap of more than 16 steps, as after four
/// thinnings), in time order.
#[test]
fn a_long_history_is_thinned_evenly() {
    use collide::contact::{Fixed, LawKind, Method, simulate};
    let setup = library_setup(
        &[(1.0, 0.0, 1.0, 1.0), (1.0, 1.0, 0.0, 1.0)],
        LawKind::Linear,
        1.0,
    );
    let settings = library_settings(Some(Method::Fixed(Fixed::Verlet)), Some(1e-5), true);
    let run = simulate(&setup, &settings).unwrap();
    let h = &run.history;
    assert!(
        h.len() > 50_000 && h.len() <= 100_001,
        "{} samples",
        h.len()
    );
    let c = &run.contacts[0];
    let duration = std::f64::consts::PI / 2f64.sqrt();
    // Each thinning drops the oldest sample too: the first left is a few steps in.
    assert!(
        h[0].t - c.start <= 16.0 * 1e-5,
        "first sample at {}",
        h[0].t
    );
    assert!(
        (h[h.len() - 1].t - (c.start + duration)).abs() <= 1e-3,
        "last sample at {}",
        h[h.len() - 1].t
    );
    let widest = h.windows(2).map(|w| w[1].t - w[0].t).fold(0.0, f64::max);
    assert!(h.windows(2).all(|w| w[1].t > w[0].t), "out of order");
    assert!(widest <= 16.0 * 1e-5 * (1.0 + 1e-9), "a gap of {widest}");
}

/// The scales that pick a method and a default step come from the impact speed: two 2 kg
/// bodies (mu = 1) meeting at 4 m/s with Hertz k = 0.625 reach d = (5/4 mu v^2 / k)^(2/5) = 4
/// and have the natural frequency sqrt(3/2 k d^(1/2) / mu) = sqrt(1.875) there.
#[test]
fn scales_come_from_the_impact_speed() {
    use collide::contact::{LawKind, Scales};
    let setup = library_setup(
        &[(2.0, 0.0, 4.0, 1.0), (2.0, 5.0, 0.0, 1.0)],
        LawKind::Hertz,
        0.625,
    );
    let scales = Scales::of(&setup, &setup.slots().unwrap());
    assert_eq!(scales.speed, 4.0);
    assert!(
        (scales.overlap - 4.0).abs() <= 8.0 * f64::EPSILON,
        "{}",
        scales.overlap
    );
    let natural = scales.natural[0];
    assert!(
        (natural - 1.875f64.sqrt()).abs() <= 4.0 * f64::EPSILON,
        "{natural}"
    );
}

/// Damping so heavy that the contact ends within 1e-100 s is refused with its numbers, each by
/// hand: k = 1, mu = 1/2, omega0 = sqrt 2; the fastest rate c/mu = 2 zeta omega0, so the
/// contact lasts pi / (2 sqrt 2 zeta) = 1.111e-101 at zeta = 1e101; e = 1 / (4 zeta^2) =
/// 2.500e-203 (overdamped: e = exp(-2 ln(2 zeta)) to first order); the most damping allowed,
/// zeta = pi / (2 sqrt 2 1e-100) = 1.111e100, and its e = 1 / (4 zeta^2) = 2.026e-201. At zeta
/// = 1e200 the restitution underflows and is left out of the message.
#[test]
fn a_contact_too_damped_to_integrate_is_refused_with_its_numbers() {
    let message = |zeta: &str| {
        let line = format!("-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --zeta {zeta}");
        let out = collide().arg("contact").args(args(&line)).output().unwrap();
        assert_eq!(out.status.code(), Some(2));
        assert!(out.stdout.is_empty());
        // The message is wrapped for the terminal: one line of single spaces.
        String::from_utf8_lossy(&out.stderr)
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ")
    };
    let m = message("1e101");
    for part in [
        "the shortest contact lasts 1.111e-101",
        "(zeta = 1.000e101, restitution e = 2.500e-203)",
        "(e >= 2.026e-201 here, zeta <= 1.111e100)",
    ] {
        assert!(m.contains(part), "{m} lacks {part}");
    }
    let m = message("1e200");
    assert!(m.contains("(zeta = 1.000e200) ends it that fast"), "{m}");
    // Where the bound's restitution underflows too it is left out: k = 1e-130, omega0 =
    // sqrt(2e-130) = 1.414e-65, zeta <= pi / (2e-100 omega0) = 1.111e165, whose e = 1 / (4
    // zeta^2) is below the smallest subnormal.
    let line = "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --stiffness 1e-130 --zeta 1e200";
    let out = collide().arg("contact").args(args(line)).output().unwrap();
    let m = String::from_utf8_lossy(&out.stderr)
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    assert!(
        m.contains("a larger restitution (zeta <= 1.111e165 here);"),
        "{m}"
    );
}

/// The impulse model needs one restitution for all the pairs: a damping coefficient c = 0.4
/// gives each pair its own (zeta = c / (2 sqrt(k mu)), mu = 2/3 and 6/5), so there is none;
/// a damping ratio zeta = 0.2 gives every pair the same, e = exp(-2 zeta acos(zeta) /
/// sqrt(1 - zeta^2)) = 0.57174 (the linear law's contact ends where its force does).
#[test]
fn the_impulse_model_needs_one_restitution_for_the_pairs() {
    let base = "-m 1,2,3 -x 0,2,4 --sizes 1,1,1 -v 1,0,-1 --stiffness 100";
    let j = run(&args(&format!("{base} --damping 0.4")));
    assert!(j["impulse_model"].is_null(), "{}", j["impulse_model"]);
    let j = run(&args(&format!("{base} --zeta 0.2")));
    let zeta: f64 = 0.2;
    let e = (-2.0 * zeta * zeta.acos() / (1.0 - zeta * zeta).sqrt()).exp();
    rel(
        j["impulse_model"]["e"].as_f64().unwrap(),
        e,
        1e-14,
        "the pairs' e",
    );
    // "One" is to 1e-12 relative. Overdamped (c = 70.7, k = 100, zeta = c / (2 sqrt(k mu)) =
    // 5.0): equal masses share e = exp(-2 zeta ln(zeta + s) / s), s = sqrt(zeta^2 - 1), =
    // 0.0092872; a third mass of 1 + 2e-11 moves its pair's mu by 5e-12 and its e by 9.4e-12
    // relative: two restitutions, no model.
    let base = "-x 0,2,4 --sizes 1,1,1 -v 1,0,0 --stiffness 100 --damping 70.7";
    let j = run(&args(&format!("-m 1,1,1 {base}")));
    let zeta: f64 = 70.7 / (2.0 * 50f64.sqrt());
    let s = ((zeta - 1.0) * (zeta + 1.0)).sqrt();
    let e = (-2.0 * zeta * (zeta + s).ln() / s).exp();
    rel(
        j["impulse_model"]["e"].as_f64().unwrap(),
        e,
        1e-13,
        "overdamped e",
    );
    let j = run(&args(&format!("-m 1,1,1.00000000002 {base}")));
    assert!(j["impulse_model"].is_null(), "{}", j["impulse_model"]);
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
    // The positions reported are the lab's at the reported time: the centre of mass moves
    // uniformly (m = 1, 3 at v = 2, 0: from 3/4 at w = 1/2), whatever the integration did, and
    // the overlap is (s1 + s2)/2 - (x2 - x1). Both to the 15 digits printed.
    let (code, _, err) = outcome(&args(
        "-m 1,3 -x 0,1 --sizes 1,1 -v 2,0 --stiffness 0.1 --method rk4",
    ));
    assert_eq!(code, 2, "{err}");
    let err = err.split_whitespace().collect::<Vec<_>>().join(" ");
    let after = |key: &str| -> f64 {
        let rest = &err[err.find(key).unwrap_or_else(|| panic!("{err} lacks {key}")) + key.len()..];
        let end = rest.find([',', ':', ' ']).unwrap_or(rest.len());
        rest[..end]
            .parse()
            .unwrap_or_else(|_| panic!("{key} in {err}"))
    };
    let (t, x1, x2) = (after("at t = "), after("x1 = "), after("x2 = "));
    let overlap = after("an overlap of ");
    let com = (x1 + 3.0 * x2) / 4.0;
    assert!(
        (com - (0.75 + 0.5 * t)).abs() <= 1e-13,
        "{err}: centre of mass at {com}"
    );
    assert!((overlap - (1.0 - (x2 - x1))).abs() <= 1e-13, "{err}");
    assert!(x1 > x2, "{err}: not through each other");
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
    // Either wall meets the centre at half the body's size (0.5 for size 1, not the size): k =
    // 1.5625 against m = 1 at 1 m/s needs d_max = v sqrt(m / k) = 0.8 (refused where the
    // overlap passes 0.5); k = 6.25 needs 0.4 (runs, that deep).
    for (side, v) in [("left", -1.0), ("right", 1.0)] {
        let line = format!("-m 1 -x 0 --sizes 1 -v {v} --{side}-wall {}", v / 2.0);
        let (code, _, err) = outcome(&args(&format!("{line} --wall-stiffness 1.5625")));
        assert_eq!(code, 2, "{err}");
        assert!(
            err.contains(&format!("body 1 passed through the {side} wall"))
                && err.contains("where 0.5 means the centres met"),
            "{err}"
        );
        let j = run(&args(&format!("{line} --wall-stiffness 6.25")));
        rel(f(&j["contacts"][0]["max_overlap"]), 0.4, 1e-9, side);
    }
    // Unequal sizes, in either order (1 and 3: the centres meet at an overlap of 2, the sum of
    // the half sizes; a mean taken of one size twice would put it at 1 or 3): an overlap of
    // 3/2 (k = 2/9, mu = 1/2: d_max = sqrt(mu / k) = 3/2) runs; 5/2 (k = 2/25) is refused.
    for sizes in ["1,3", "3,1"] {
        let line = format!("-m 1,1 -x 0,3 --sizes {sizes} -v 1,0 --stiffness");
        let j = run(&args(&format!("{line} {}", 2.0 / 9.0)));
        let d = f(&j["contacts"][0]["max_overlap"]);
        rel(
            d,
            1.5,
            1e-9,
            &format!("sizes {sizes}: d_max = sqrt(mu / k)"),
        );
        let (code, _, err) = outcome(&args(&format!("{line} 0.08")));
        assert_eq!(code, 2, "sizes {sizes}: {err}");
        assert!(err.contains("passed through each other"), "{err}");
    }
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

// Issue 31 §2, §4: contacts against closed forms chained by hand, every runtime failure forced.

/// `(t_c, e, d_max, d_end)` of a linear contact with ratio `zeta < 1` for stiffness `k`,
/// reduced mass `mu`, impact speed `u`: as `linear_closed`, and the overlap left when the force
/// reaches zero, `d_end = -(c/k) d'_end = (c/k) e u` with `c = 2 zeta sqrt(k mu)`.
fn linear_contact(k: f64, mu: f64, zeta: f64, u: f64) -> (f64, f64, f64, f64) {
    let (tc, e, dmax) = linear_closed(k, mu, zeta, u);
    let c = 2.0 * zeta * (k * mu).sqrt();
    (tc, e, dmax, c / k * e * u)
}

/// Contacts of a run as `(between, start, duration, max_overlap, speed, restitution)`.
fn records(j: &Value) -> Vec<(String, f64, f64, f64, f64, f64)> {
    j["contacts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            (
                c["between"].to_string(),
                f(&c["start"]),
                f(&c["duration"]),
                f(&c["max_overlap"]),
                f(&c["speed"]),
                f(&c["restitution"]),
            )
        })
        .collect()
}

/// Two equal bodies (sizes 1, at 0 and 2, body 1 at speed 1) and a right wall at 5, linear
/// contacts with zeta = 0.2: body 1 hits body 2 at t = 1 (gap 1 / closing speed 1), body 2
/// leaves at (1 + e)/2 and hits the wall, comes back at -e (1 + e)/2 and meets body 1 again.
/// Every start, duration, deepest overlap, impact speed and restitution from the closed forms
/// of the linear law, chained by hand through the free flights between contacts:
/// - pair (mu = 1/2): starts at 1; ends at 1 + t_c with overlap d_end left (force zero), the
///   centre of mass at 1 + t/2, so x2 = 1 + t/2 + (1 - d_end)/2;
/// - wall (mu = 1): body 2's right edge reaches 5 after (4.5 - x2) / v2; it ends with body 2 at
///   4.5 + d_end(wall) moving at -e v2;
/// - pair again: the gap x2 - x1 - 1 closes at v1 - v2'.
fn chained_contacts(k: f64) -> [(f64, f64, f64, f64, f64); 3] {
    let zeta = 0.2;
    let (tc, e, dmax, dend) = linear_contact(k, 0.5, zeta, 1.0);
    let (t1, t1_end) = (1.0, 1.0 + tc);
    let (v1, v2) = ((1.0 - e) / 2.0, (1.0 + e) / 2.0);
    let com = 1.0 + t1_end / 2.0;
    let (x1, x2) = (com - (1.0 - dend) / 2.0, com + (1.0 - dend) / 2.0);
    let t2 = t1_end + (4.5 - x2) / v2;
    let (tcw, ew, dmaxw, dendw) = linear_contact(k, 1.0, zeta, v2);
    let t2_end = t2 + tcw;
    let x1_at = x1 + v1 * (t2_end - t1_end);
    let (x2_at, v2_back) = (4.5 + dendw, -ew * v2);
    let u3 = v1 - v2_back;
    let t3 = t2_end + (x2_at - x1_at - 1.0) / u3;
    let (tc3, e3, dmax3, _) = linear_contact(k, 0.5, zeta, u3);
    [
        (t1, tc, dmax, 1.0, e),
        (t2, tcw, dmaxw, v2, ew),
        (t3, tc3, dmax3, u3, e3),
    ]
}

#[test]
fn contact_starts_order_and_values_follow_the_closed_forms() {
    let expected = chained_contacts(1e4);
    let j = run(&args(
        "-m 1,1 -x 0,2 --sizes 1,1 -v 1,0 --right-wall 5 --stiffness 1e4 --zeta 0.2 --tol 1e-12",
    ));
    let got = records(&j);
    assert!(got.len() >= 3, "{got:?}");
    let who = ["[1,2]", "[2,\"right\"]", "[1,2]"];
    for (i, ((between, start, duration, dmax, speed, e), (t, tc, d, u, ee))) in
        got.iter().zip(expected).enumerate()
    {
        assert_eq!(between, who[i], "contact {i}: order");
        let what = |q: &str| format!("contact {i} ({between}): {q}");
        rel(*start, t, 1e-10, &what("start"));
        rel(*duration, tc, 1e-9, &what("duration"));
        rel(*dmax, d, 1e-9, &what("max_overlap"));
        rel(*speed, u, 1e-9, &what("speed"));
        rel(*e, ee, 1e-9, &what("restitution"));
    }
    // The first contact begins after an exact free flight: gap 1 at closing speed 1.
    assert_eq!(got[0].1, 1.0);
    // Listed in order of their start.
    assert!(got.windows(2).all(|w| w[0].1 <= w[1].1), "{got:?}");
}

#[test]
fn fixed_step_event_times_match_the_closed_forms() {
    // The same chain with the fixed-step methods. The first contact starts after an exact free
    // flight (gap / closing speed = 1, to the bit); later starts carry each method's error in
    // the contact before them: O((omega h)^2) for Verlet and implicit midpoint, O((omega h)^4)
    // for RK4, here omega h = sqrt(2e4) 1e-4 = 0.014.
    let expected = chained_contacts(1e4);
    for (method, tol) in [("verlet", 1e-4), ("implicit-midpoint", 1e-4), ("rk4", 1e-8)] {
        let j = run(&args(&format!(
            "-m 1,1 -x 0,2 --sizes 1,1 -v 1,0 --right-wall 5 --stiffness 1e4 --zeta 0.2 --method {method} --dt 1e-4"
        )));
        let got = records(&j);
        assert_eq!(got[0].1, 1.0, "{method}: first start");
        for (i, (g, x)) in got.iter().zip(expected).enumerate() {
            rel(g.1, x.0, tol, &format!("{method}: start of contact {i}"));
            rel(
                g.2,
                x.1,
                100.0 * tol,
                &format!("{method}: duration of contact {i}"),
            );
        }
    }
}

#[test]
fn dissipated_energy_is_the_sum_of_each_contacts_loss() {
    // Contacts apart in time (checked below), each between two bodies or a body and a wall,
    // lose (1 - e_i^2) 1/2 mu_i u_i^2 (the crunch of the pair, lecture Sec. 2), with u_i the
    // recorded impact speed and e_i the recorded restitution: the sum must be the run's
    // `dissipated`, which the program computes from energies instead. For the linear law each
    // e_i is also the closed form of its zeta_i = c / (2 sqrt(k mu_i)).
    for (law, damping) in [("linear", "0.3"), ("hunt-crossley", "0.5")] {
        let j = run(&args(&format!(
            "-m 1,2,1 -x 0,2,4.5 --sizes 1,1,1 -v 1,0,-0.5 --law {law} --damping {damping} --left-wall -3 --right-wall 7 --stiffness 100 --until 20 --tol 1e-12"
        )));
        let m: [f64; 3] = [1.0, 2.0, 1.0];
        let contacts = j["contacts"].as_array().unwrap();
        assert!(contacts.len() >= 4, "{law}: {} contacts", contacts.len());
        let mut spans: Vec<(f64, f64)> = Vec::new();
        let mut loss = 0.0;
        for c in contacts {
            let (start, u) = (f(&c["start"]), f(&c["speed"]));
            let Some(d) = c["duration"].as_f64() else {
                panic!("{law}: a contact still open at --until: {c}")
            };
            spans.push((start, start + d));
            let b = &c["between"];
            let mu = match (b[0].as_u64(), b[1].as_u64()) {
                (Some(i), Some(k)) => {
                    m[i as usize - 1] * m[k as usize - 1] / (m[i as usize - 1] + m[k as usize - 1])
                }
                (None, Some(k)) => m[k as usize - 1],
                (Some(i), None) => m[i as usize - 1],
                _ => unreachable!(),
            };
            let e = f(&c["restitution"]);
            if law == "linear" {
                let zeta = 0.3 / (2.0 * (100.0 * mu).sqrt());
                rel(
                    e,
                    linear_closed(100.0, mu, zeta, u).1,
                    1e-9,
                    &format!("{b}: e(zeta)"),
                );
            }
            loss += (1.0 - e * e) * 0.5 * mu * u * u;
        }
        spans.sort_by(|a, b| a.0.total_cmp(&b.0));
        assert!(
            spans.windows(2).all(|w| w[0].1 < w[1].0),
            "{law}: contacts overlap in time {spans:?}"
        );
        let e = &j["energy"];
        rel(
            f(&e["dissipated"]),
            loss,
            1e-8,
            &format!("{law}: dissipated"),
        );
        rel(
            f(&e["start"]) - loss,
            f(&e["end"]),
            1e-8,
            &format!("{law}: end"),
        );
    }
    // Undamped: the loss is zero to the integration's accuracy, not merely not negative.
    let j = run(&args(
        "-m 1,2,1 -x 0,2,4.5 --sizes 1,1,1 -v 1,0,-0.5 --left-wall -3 --right-wall 7 --stiffness 100 --until 20 --tol 1e-12",
    ));
    assert!(
        f(&j["energy"]["dissipated"]) <= 1e-9 * f(&j["energy"]["start"]),
        "{}",
        j["energy"]
    );
}

/// The Hertz cradle's final velocities, and the time its last contact ends, from an
/// integration that shares nothing with collide: `scenarios/reference/contact.py` with SciPy
/// 1.17.1, run by hand and recorded here so that CI needs no Python. Radau IIA (implicit,
/// order 5) gave (-0.07095235365143369, 0.07640303907120215, 0.9945493145802339) and DOP853
/// (explicit, order 8) (-0.07095235365144358, 0.07640303907116691, 0.9945493145802766), each at
/// rtol 1e-13 and restarted at every contact opening and closing that SciPy's own event search
/// located; they agree to 4e-14, and the last contact ends at t = 3.73145597138 (both).
const HERTZ_CRADLE_SCIPY: [f64; 3] = [
    -0.070_952_353_651_4,
    0.076_403_039_071_2,
    0.994_549_314_580_3,
];
const HERTZ_CRADLE_SCIPY_END: f64 = 3.731_455_971_38;

#[test]
fn the_hertz_cradle_matches_the_scipy_reference() {
    let j = run(&args(
        "-m 1,1,1 -x 0,1,2 --sizes 1,1,1 -v 1,0,0 --law hertz --tol 1e-12",
    ));
    // collide at --tol 1e-12 agrees to 5e-11 (measured).
    let v = floats(&j["v"]);
    for i in 0..3 {
        assert!((v[i] - HERTZ_CRADLE_SCIPY[i]).abs() < 1e-10, "{v:?}");
    }
    rel(
        f(&j["time"]),
        HERTZ_CRADLE_SCIPY_END,
        1e-10,
        "end of the last contact",
    );
    // Energy is kept (elastic contacts): 1/2 sum v^2 = 1/2.
    let ke: f64 = v.iter().map(|v| 0.5 * v * v).sum();
    rel(ke, 0.5, 1e-9, "kinetic energy");
    // The same script's other elastic scenes, recorded the same way: the linear cradle (Radau
    // and DOP853 agree to 1.4e-14; collide to 3e-13) and the two-ball superball on a stiff
    // floor (k = 1e6: Radau only; collide to 4e-10).
    for (line, reference, end, tol) in [
        (
            "-m 1,1,1 -x 0,1,2 --sizes 1,1,1 -v 1,0,0 --stiffness 1 --tol 1e-12",
            &[
                -0.130_261_695_064_525,
                0.150_229_569_434_778,
                0.980_032_125_629_743,
            ][..],
            3.426_976_250_45,
            1e-11,
        ),
        (
            "-m 1,0.1 -x 0.5,1.5 --sizes 1,1 -v -1,-1 --left-wall 0 --stiffness 1 --wall-stiffness 1e6 --tol 1e-12",
            &[0.636_364_868_602_432, 2.636_360_661_989_65][..],
            0.948_796_621_933,
            1e-9,
        ),
    ] {
        let j = run(&args(line));
        let v = floats(&j["v"]);
        for (got, want) in v.iter().zip(reference) {
            assert!(
                (got - want).abs() < tol,
                "{line}: {v:?} against {reference:?}"
            );
        }
        rel(f(&j["time"]), end, 1e-10, &format!("{line}: end"));
    }
}

/// The sequential-impulse model of a layout in which every body touches its neighbours and
/// the walls at t = 0, derived by hand: pairs and walls are resolved left to right, each with
/// the velocities the previous one left (the documented rule for simultaneous events), until
/// no pair approaches and no body moves into a wall. Pair rule (lecture, impulse form):
/// v1' = v1 + (1 + e) m2/(m1 + m2) (v2 - v1), v2' = v2 - (1 + e) m1/(m1 + m2) (v2 - v1); wall:
/// v' = -e_w v.
fn touching_impulses(m: &[f64], v: &mut [f64], e: f64, e_wall: f64, right_wall: bool) {
    for _ in 0..10_000 {
        let mut changed = false;
        for i in 0..m.len() - 1 {
            if v[i] > v[i + 1] {
                let (d, total) = (v[i + 1] - v[i], m[i] + m[i + 1]);
                let (a, b) = (v[i], v[i + 1]);
                v[i] = a + (1.0 + e) * m[i + 1] / total * d;
                v[i + 1] = b - (1.0 + e) * m[i] / total * d;
                changed = true;
            }
        }
        let last = m.len() - 1;
        if right_wall && v[last] > 0.0 {
            v[last] *= -e_wall;
            changed = true;
        }
        if !changed {
            return;
        }
    }
    panic!("no end to the impulses");
}

#[test]
fn impulse_models_are_derived_by_hand() {
    // The stiff backstop (scenarios/contact-backstop-*.toml): body 1 at speed 1 hits body 2,
    // which touches a critically damped wall. Calibrated restitutions from the closed forms:
    // pair c = 0.4, mu = 1/2, zeta = 0.4 / (2 sqrt(1/2)); wall zeta = 1 gives e_w = exp(-2)
    // (t_c = 2 / omega0). The impulses iterate to about (-0.0174, -0.0080).
    let e = linear_closed(1.0, 0.5, 0.4 / (2.0 * 0.5f64.sqrt()), 1.0).1;
    let e_wall = (-2.0f64).exp();
    let mut v = [1.0, 0.0];
    touching_impulses(&[1.0, 1.0], &mut v, e, e_wall, true);
    assert!(
        (v[0] + 0.0174).abs() < 1e-4 && (v[1] + 0.008).abs() < 1e-3,
        "{v:?}"
    );
    for k in ["1e4", "1e10"] {
        let j = run(&args(&format!(
            "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --right-wall 1.5 --stiffness 1 --damping 0.4 --wall-stiffness {k} --wall-zeta 1"
        )));
        let im = &j["impulse_model"];
        rel(f(&im["e"]), e, 1e-12, "pair restitution");
        rel(f(&im["e_wall"]), e_wall, 1e-12, "wall restitution");
        let got = floats(&im["v"]);
        for i in 0..2 {
            assert!((got[i] - v[i]).abs() <= 1e-14, "{got:?} against {v:?}");
        }
    }
    // The cradle: equal elastic balls exchange velocities, (1, 0, 0) -> (0, 0, 1), exactly.
    let mut v = [1.0, 0.0, 0.0];
    touching_impulses(&[1.0, 1.0, 1.0], &mut v, 1.0, 1.0, false);
    assert_eq!(v, [0.0, 0.0, 1.0]);
}

/// Runs and expects exit 2 with a runtime failure: `needle` in the message, nothing on stdout.
#[track_caller]
fn fails_at_run_time(line: &str, needle: &str) {
    refused(&args(line), needle);
}

#[test]
fn every_runtime_failure_that_input_can_cause_is_refused() {
    // Bodies through each other: a contact so soft (k = 1e-6, mu = 1/2: deepest overlap
    // 1 / omega0 = 707) that the centres cross and cross back during one contact; the state at
    // the end is in order again, so only the deepest overlap (> 1, the sum of the half-sizes)
    // shows it.
    fails_at_run_time(
        "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --stiffness 1e-6",
        "bodies 1 and 2 passed through each other",
    );
    // Through a wall likewise (mu = 1, overlap 1000 > the half-size 0.5).
    fails_at_run_time(
        "-m 1 -x 0 --sizes 1 -v 1 --right-wall 0.5 --wall-stiffness 1e-6",
        "body 1 passed through the right wall",
    );
    // Blow-up: symplectic Euler at omega h = 1.2, inside its stability limit 2 (so not refused
    // up front), puts 1/2 k (h v)^2 = 0.72 of elastic energy into the first step: 2.44 times
    // the start.
    fails_at_run_time(
        "-m 1 -x 0 --sizes 1 -v 1 --right-wall 0.5 --wall-stiffness 1e6 --method symplectic-euler --dt 1.2e-3",
        "symplectic-euler failed: the energy grew to 2.440e0 times its start at t = 0.0012",
    );
    // Energy gain: Verlet at omega h = 0.1 on an undamped wall contact ends 3.4e-6 above the
    // start (its modified energy, cut at the event), above the 1e-6 allowed.
    fails_at_run_time(
        "-m 1 -x 0 --sizes 1 -v 1 --right-wall 0.5 --wall-stiffness 1e6 --method verlet --dt 1e-4",
        "verlet gained energy: 0.50000170",
    );
    // The step budget: within it for one contact (64 steps of the default rk4 step), over it
    // for the two of three bodies in a row (100 steps). (A step too small for one contact
    // within the budget is refused before the run: bad_input_is_refused_with_exit_2.)
    fails_at_run_time(
        "-m 1,1,1 -x 0,1,2 --sizes 1,1,1 -v 1,0,0 --method rk4 --max-steps 80",
        "rk4 failed: more than 80 steps",
    );
}

#[test]
fn the_energy_gate_is_relative_to_the_start() {
    // The Verlet run above, with the mass and the wall's stiffness both scaled by s: omega and
    // every step are the same, each energy is s times as large, and so the relative gain is
    // the same 3.4e-6 (above the 1e-6 allowed) at s = 1e-6, where the gain itself is only
    // 1.7e-12 J, as at s = 1e6. The printed gain is checked against the printed energies.
    let mut ratios = Vec::new();
    for (m, k) in [("1e-6", "1"), ("1", "1e6"), ("1e6", "1e12")] {
        let line = format!(
            "-m {m} -x 0 --sizes 1 -v 1 --right-wall 0.5 --wall-stiffness {k} --method verlet \
             --dt 1e-4"
        );
        let out = collide().arg("contact").args(args(&line)).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr).replace("\n  ", " ");
        assert_eq!(out.status.code(), Some(2), "{line}: {err}");
        assert!(out.stdout.is_empty(), "{line} wrote to stdout");
        let words: Vec<&str> = err.split_whitespace().collect();
        let after = |w: &str| -> f64 {
            let i = words
                .iter()
                .position(|x| *x == w)
                .unwrap_or_else(|| panic!("{err}"));
            words[i + 1].trim_start_matches('(').parse().unwrap()
        };
        let (end, start) = (after("energy:"), after("against"));
        let i = words.iter().position(|x| *x == "relative)").unwrap();
        let printed: f64 = words[i - 1].trim_start_matches('(').parse().unwrap();
        let s: f64 = m.parse().unwrap();
        rel(start, 0.5 * s, 1e-15, "start energy");
        rel(
            printed,
            (end - start) / start,
            1e-3,
            "printed relative gain",
        );
        ratios.push(end / start);
    }
    // Above the gate, and the same at every scale but for the rounding of the energies.
    assert!(ratios[1] - 1.0 > 1e-6, "{ratios:?}");
    for r in &ratios {
        rel(
            *r - 1.0,
            ratios[1] - 1.0,
            1e-6,
            "relative gain at each scale",
        );
    }
}

/// Bodies that touch but move apart never begin a contact: a pair touching (centres 1 apart,
/// sizes 1) with body 2 leaving at 1, and a body touching the right wall while leaving it. An
/// undamped law's gate (its force, k d + c d') is exactly 0 there; the contact would begin only
/// on approach. Every method, both laws: no contact, and the bodies carried on exactly.
#[test]
fn touching_bodies_that_move_apart_never_begin_a_contact() {
    for law in ["linear", "hertz"] {
        for method in ["tsit45", "verlet", "implicit-euler"] {
            for (line, x, v) in [
                (
                    "-m 1,1 -x 0,1 --sizes 1,1 -v 0,1 --until 2",
                    [0.0, 3.0],
                    [0.0, 1.0],
                ),
                (
                    "-m 1,1 -x 0,2 --sizes 1,1 -v -1,-1 --right-wall 2.5 --until 2",
                    [-2.0, 0.0],
                    [-1.0, -1.0],
                ),
            ] {
                let mut a = args(line);
                a.extend(["--law", law, "--method", method]);
                let out = run(&a);
                assert_eq!(out["contacts"].as_array().unwrap().len(), 0, "{a:?}: {out}");
                assert_eq!(floats(&out["x"]), x, "{a:?}");
                assert_eq!(floats(&out["v"]), v, "{a:?}");
            }
        }
    }
}

/// With no relative speed (both bodies at 1) a Hertz contact's time scale, which depends on
/// the speed, is taken at unit speed: d_max = (5 mu / (4 k))^(2/5) with mu = 1/2 and k = 1,
/// omega = sqrt(3/2 k d_max^(1/2) / mu), and Verlet's default step is (pi / omega) / 64. (At
/// speed 0 itself the scale would be infinite and no step could be chosen.)
#[test]
fn with_no_relative_speed_the_default_step_is_taken_at_unit_speed() {
    let (k, mu) = (1.0f64, 0.5f64);
    let d = (5.0 * mu / (4.0 * k)).powf(0.4);
    let omega = (1.5 * k * d.sqrt() / mu).sqrt();
    let out = run(&args(
        "-m 1,1 -x 0,2 --sizes 1,1 -v 1,1 --law hertz --method verlet",
    ));
    rel(
        f(&out["dt"]),
        std::f64::consts::PI / omega / 64.0,
        1e-14,
        "dt",
    );
    assert_eq!(out["contacts"].as_array().unwrap().len(), 0);
    assert_eq!(floats(&out["v"]), [1.0, 1.0]);
}

/// A fixed-step run stopped by `--until` inside a contact cuts its last step to land on it:
/// two touching bodies (k = 1, mu = 1/2, omega = sqrt 2, v = 1) have overlap d = sin(phase) /
/// omega and closing speed cos(phase). At --until 1.0001 with steps of 0.003 (not a multiple:
/// 333 steps and one of 0.0011), the end time is 1.0001 exactly. rk4 follows the exact phase
/// omega t to about (omega h)^4 / 120 per radian (1e-11); implicit midpoint, on a linear
/// oscillator, turns the state by exactly 2 atan(omega h / 2) a step with no change of amplitude
/// (its Cayley transform), so its phase is 333 such turns and one of the cut step.
#[test]
fn a_fixed_step_run_stops_on_until_inside_a_contact() {
    let (w, t) = (2f64.sqrt(), 1.0001);
    let turn = |h: f64| 2.0 * (w * h / 2.0).atan();
    for (method, phase, tol) in [
        ("rk4", w * t, 1e-9),
        (
            "implicit-midpoint",
            333.0 * turn(0.003) + turn(0.0011),
            1e-12,
        ),
    ] {
        let line = format!(
            "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --stiffness 1 --method {method} --dt 0.003 \
             --until 1.0001"
        );
        let out = run(&args(&line));
        assert_eq!(f(&out["time"]), t, "{method}");
        assert_eq!(out["stop"], "until", "{method}");
        let (x, v) = (floats(&out["x"]), floats(&out["v"]));
        rel(1.0 - (x[1] - x[0]), phase.sin() / w, tol, method);
        rel(v[0] - v[1], phase.cos(), tol, method);
        // The centre of mass moves on at 1/2.
        rel(x[0] + x[1], 1.0 + t, 1e-15, method);
    }
}

/// A contact that starts late steps in its own time: after the exchanges, a residue of the
/// arithmetic's (1e-16) brings body 2 back to the wall at t = 6.1e15, where ulp(t) = 1 and a
/// step of 0.0123 would be lost in the time's rounding (the run stalled, or printed a duration
/// of 1). The wall contact of k = 16 on a unit mass lasts half a period, pi / 4, as the
/// first one did (Verlet at omega h = 0.049: within 1e-3 of it).
#[test]
fn a_contact_that_starts_late_is_stepped_in_its_own_time() {
    let j = run(&args(
        "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --right-wall 5 --wall-stiffness 16 --method verlet",
    ));
    let late: Vec<&Value> = j["contacts"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| f(&c["start"]) > 1e15)
        .collect();
    assert_eq!(late.len(), 1, "{j}");
    let quarter = std::f64::consts::FRAC_PI_4;
    assert!((f(&late[0]["duration"]) - quarter).abs() < 1e-3, "{j}");
}

/// Only differences of positions matter: a pair 5e19 from the origin (where binary64 spaces
/// positions 8192 apart) collides as a pair near 0 does, to the closed forms of an undamped
/// linear contact (k = 1, mu = 1/2, v = 1: t_c = pi / sqrt(2), d_max = 1 / sqrt(2), e = 1),
/// within the default accuracy (1e-8 of the relative speed; 1e-7 here). Before the run moved
/// its origin to the centre of mass, the overlap there was rounding and the run stopped as
/// "unstable". Where the positions cannot be known well enough (a free flight of 1e20 at 1e10
/// before a contact of 7e-6: the flight's time rounds by 1e-10 s of 1e10), the run is refused
/// by name, never integrated.
#[test]
fn positions_far_from_the_origin_collide_as_near_ones_or_are_refused() {
    let (t_c, d_max) = (PI / 2f64.sqrt(), 1.0 / 2f64.sqrt());
    for x in [
        "-1e5,1e5",
        "5e19,5.00000000000002e19",
        "-7e22,-6.99999999999999e22",
    ] {
        let out = run(&args(&format!("-m 1,1 -x {x} --sizes 1e5,1e5 -v 1,0")));
        let c = &out["contacts"][0];
        rel(f(&c["duration"]), t_c, 1e-7, &format!("{x}: duration"));
        rel(
            f(&c["max_overlap"]),
            d_max,
            1e-7,
            &format!("{x}: max overlap"),
        );
        rel(f(&c["restitution"]), 1.0, 1e-7, &format!("{x}: e"));
        let v = floats(&out["v"]);
        assert!(v[0].abs() < 1e-7 && (v[1] - 1.0).abs() < 1e-7, "{x}: {v:?}");
    }
    refused(
        &args("-m 1,1 -x 0,1e20 -v 1e10,0 --sizes 1,1 --stiffness 1e30"),
        // The flight of 1e10 s lands the centres on each other: the whole size, 1, is rounding.
        "positions known only to +-1.000e0",
    );
}
