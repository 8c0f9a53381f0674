//! `collide contact`'s integrators: unstable steps refused, the default steps, the work counters
//! of fixed-step and adaptive methods, Newton's iteration in implicit steps, the history kept
//! for `--plot`, stiff damping and BDF, and the work-precision report against exact answers.

use crate::contact::{
    args, f, floats, library_settings, library_setup, linear_closed, linear_laws, outcome, refused,
    rel, run, scratch,
};

use serde_json::Value;

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
fn work_precision_refuses_the_flags_of_a_single_run() {
    // --method, --dt and --tol were silently ignored by the ladder.
    let base = "-m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --work-precision --methods rk4";
    for extra in ["--method bdf", "--dt 1e-3", "--tol 1e-6", "--max-steps 10"] {
        let line = format!("{base} {extra}");
        let flag = extra.split(' ').next().unwrap();
        refused(&args(&line), &format!("{flag} is for one run"));
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
