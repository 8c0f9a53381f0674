//! `collide contact` against the closed forms (issue 46: contact.rs split by job; the methods,
//! the refusals and the outputs are in contact_methods.rs, contact_refusals.rs and
//! contact_outputs.rs, which share the helpers here): a single contact (linear and Hertz) for
//! stiffness 1 to 1e12, the calibrated restitution, convergence to the impulse model as the
//! stiffness grows, the stiff backstop's limit (which the impulse model misses), energy
//! bookkeeping, the Hertz cradle, chains of contacts and the impulse models by hand.
//!
//! Expected values are computed here from the closed forms (Schwager & Poeschel 2007 for the
//! linear law; Hertz's d_max and the contact-time integral as a Beta function), not taken from
//! the program.

use crate::common::collide;

use std::f64::consts::PI;

use serde_json::Value;

pub(crate) fn run(args: &[&str]) -> Value {
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
pub(crate) fn refused(args: &[&str], needle: &str) {
    let out = collide().arg("contact").args(args).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(err.contains(needle), "{args:?}: {err} lacks {needle:?}");
    assert!(out.stdout.is_empty(), "{args:?} wrote to stdout");
    assert!(!err.contains("panicked"), "{err}");
}

/// A command line's words.
pub(crate) fn args(line: &str) -> Vec<&str> {
    line.split_whitespace().collect()
}

pub(crate) fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("{v} is not a number"))
}

pub(crate) fn floats(v: &Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(f).collect()
}

#[track_caller]
pub(crate) fn rel(actual: f64, expected: f64, tol: f64, what: &str) {
    let r = (actual - expected).abs() / expected.abs();
    assert!(
        r <= tol,
        "{what}: {actual} against {expected} (rel {r:.2e} > {tol:e})"
    );
}

/// The linear law's closed forms for reduced mass `mu`, impact speed `v`, ratio `zeta < 1`:
/// `(t_c, e, d_max)` with t_c = (pi - 2 atan(beta/omega)) / omega, e = exp(-beta t_c), and
/// d_max at the zero of d' (tan(omega t) = omega / beta): d = (v/omega) e^(-beta t) sin(omega t).
pub(crate) fn linear_closed(k: f64, mu: f64, zeta: f64, v: f64) -> (f64, f64, f64) {
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

/// A file name in the temporary folder, unique to this process.
pub(crate) fn scratch(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("collide-contact-{}-{name}", std::process::id()))
}

/// A setup through the library: bodies `(mass, x, v, size)` under one undamped law of
/// stiffness `k` between them (and default walls' law).
pub(crate) fn library_setup(
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

/// The linear law of stiffness 1, undamped, for pairs and walls.
pub(crate) fn linear_laws() -> collide::contact::Laws {
    collide::contact::Laws {
        kind: collide::contact::LawKind::Linear,
        k: 1.0,
        damping: None,
        wall_k: None,
        wall_damping: None,
    }
}

/// Settings for a library run: `method` (`None`: auto) with step `dt`, a trace if asked.
pub(crate) fn library_settings(
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

// Issue 24: false physics or numbers from `collide contact`, each refused or corrected.

/// Runs `collide contact args`: (exit code, stdout, stderr).
pub(crate) fn outcome(args: &[&str]) -> (i32, String, String) {
    let out = collide().arg("contact").args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
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
