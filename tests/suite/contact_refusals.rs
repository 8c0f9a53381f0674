//! `collide contact` refuses what it cannot do, exit 2 with the value named, or handles it: bad
//! input, odd layouts, overlaps at the start, bodies that pass through each other or a wall,
//! damping too heavy to integrate, every run-time failure input can cause, and extremes (tiny or
//! huge masses, a large common velocity, positions far from the origin).

use crate::common::collide;
use crate::contact::{
    args, f, floats, library_settings, library_setup, linear_closed, outcome, refused, rel, run,
};

use std::f64::consts::PI;

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
