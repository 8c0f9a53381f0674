//! Unknowns in rigid problems (issue 42 section 2, and section 5's mu): one value typed `?` (a
//! speed, a mass, `--hit-at ?`, `-e ?`, `--friction ?`) fixed by a given final spin
//! (`--fin-spin`) or `--pivot-impulse 0`. Each answer is derived by hand in the test's comments
//! and compared exactly under `--exact`, or relatively in binary64; refusals exit 2 naming why.

use crate::common::{assert_close, run_solve, solve_refused};
use crate::rigid::{f, json, q};

use collide::values::rational::{Q, int, ratio};

/// The bullet: 3.00 g, its path at 60 deg to a 0.500 m, 4.00 kg rod pivoted at its
/// centre, lodging in its top end; the rod's final spin is the last argument.
fn bullet(spin: &str) -> Vec<String> {
    [
        "-m",
        "3.00 g,4.00 kg",
        "-v",
        "? @ -30deg,0",
        "--target",
        "rod 0.500 m",
        "--pivot",
        "centre",
        "--hit-at",
        "end",
        "--join",
        "--fin-spin",
        spin,
    ]
    .map(String::from)
    .to_vec()
}

#[test]
fn a_bullets_speed_from_the_spin_of_the_rod_it_lodges_in() {
    // About the pivot: the bullet's path at 60 deg to the rod passes at r sin 60 from it, r =
    // L/2 = 1/4 m, so L = m v r sin 60 (clockwise: the rod turns at -10 rad/s, spins being
    // counterclockwise positive), and after I = I_p + m r^2 = 4 (1/4)/12 + 3/1000 (1/16) =
    // 4009/48000 kg m^2. v = I |omega| / (m r sin 60) = (4009/48000) 10 / ((3/4000) sqrt(3)/2)
    // = 20045 / (9 sqrt 3) = 1285.887 m/s.
    let args = bullet(",-10 rad/s");
    let a: Vec<&str> = args.iter().map(String::as_str).collect();
    let j = json(&a);
    let v = 20045.0 / (9.0 * 3f64.sqrt());
    // cos and sin of -30 deg are binary64 and the speed is rounded once: 1e-13 relative.
    assert_close(f(&j["solved"]["v1"]), v, 1e-13, "v1");
    assert_close(f(&j["fin"][1]["omega"]), -10.0, 1e-13, "omega2'");
    assert!(f(&j["check"]["omega2'"]).abs() < 1e-12, "{}", j["check"]);
    assert_eq!(j["law"], "join");
    // The text's first line is the answer.
    let (code, out, _) = run_solve(&a);
    assert_eq!(code, 0);
    assert!(out.starts_with("Solved: v1 = 1285.88"), "{out}");
    // +10 rad/s (counterclockwise) needs the bullet to come from the other side: the speed
    // along -30deg would be -1285.9 m/s, and a size along a direction is >= 0.
    let args = bullet(",10 rad/s");
    let a: Vec<&str> = args.iter().map(String::as_str).collect();
    solve_refused(&a, &["v1 = -1285.88", "out of its range", "other sign"]);
}

#[test]
fn the_centre_of_percussion_is_two_thirds_down_the_rod() {
    // A rod of length L on its end pivot hit at d: v_cm' = (d - L/2)... the pivot's impulse is
    // M v_cm' - P = P (M (L/2) d / I_p - 1) = P (3d/(2L) - 1), zero at d = 2L/3: 2 for L = 3,
    // whatever the masses and e.
    let j = json(&[
        "-m",
        "1,2",
        "-v",
        "3,0",
        "--target",
        "rod 3",
        "--pivot",
        "end",
        "--hit-at",
        "?",
        "--pivot-impulse",
        "0",
        "--exact",
    ]);
    assert_eq!(q(&j["solved"]["hit_at"]), int(2));
    assert_eq!(q(&j["pivot_impulse"][1][0]), Q::ZERO);
    assert_eq!(q(&j["pivot_impulse"][1][1]), Q::ZERO);
    assert_eq!(q(&j["check"]["the pivot's impulse"]), Q::ZERO);
    // The door of docs/rigid.md, 0.9 m: 0.6 m, exactly, in SI.
    let j = json(&[
        "-m",
        "50 g,2 kg",
        "-v",
        "10 m/s,0",
        "--target",
        "door 0.9 m",
        "--pivot",
        "end",
        "--hit-at",
        "?",
        "--pivot-impulse",
        "0",
        "--exact",
    ]);
    assert_eq!(q(&j["solved"]["hit_at"]), ratio(3, 5));
}

/// A ball of mass 1 at 3 onto the top end of a free rod (4, length 2): `ARGS` then the rest.
fn rod(rest: &[&str]) -> Vec<String> {
    let mut a: Vec<String> = ["-v", "3,0", "--target", "rod 2", "--hit-at", "end"]
        .map(String::from)
        .to_vec();
    a.extend(rest.iter().map(|s| s.to_string()));
    a
}

fn run_rod(rest: &[&str]) -> serde_json::Value {
    let a = rod(rest);
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    json(&a)
}

#[test]
fn e_and_a_mass_from_the_final_spin() {
    // The rod's effective mass at its end: 1/(1/m1 + 1/4 + (1)^2/(4/3)) = m1/(1 + m1); the
    // impulse P = (1 + e) m_eff 3 and omega2' = -(r x P)/I = -P (1)/(4/3) = -3P/4.
    // m1 = 1: omega2' = -(9/8)(1 + e); given -27/16, e = 1/2.
    let j = run_rod(&["-m", "1,4", "-e", "?", "--fin-spin", ",-27/16", "--exact"]);
    assert_eq!(q(&j["solved"]["e"]), ratio(1, 2));
    assert_eq!(q(&j["fin"][1]["omega"]), ratio(-27, 16));
    // e = 1: omega2' = -(9/2) m1/(1 + m1); given -2, 9 m1 = 4 + 4 m1, m1 = 4/5.
    let j = run_rod(&["-m", "?,4", "--fin-spin", ",-2", "--exact"]);
    assert_eq!(q(&j["solved"]["m1"]), ratio(4, 5));
    assert_eq!(q(&j["check"]["omega2'"]), Q::ZERO);
    // The same in binary64: 0.8 to an ulp or two.
    let j = run_rod(&["-m", "?,4", "--fin-spin", ",-2"]);
    assert_close(f(&j["solved"]["m1"]), 0.8, 1e-15, "m1");
}

#[test]
fn a_final_spin_in_rev_s_rpm_or_deg_s() {
    // Issue 42 section 2: --fin-spin takes rad/s, rpm, rev/s and deg/s. Half a turn a second
    // is -0.5 rev/s = -30 rpm = -180 deg/s = -pi rad/s, with pi binary64's (the one factor turns
    // and degrees carry, rigid/units.rs): the same rational in each spelling. As above, omega2'
    // = -(9/2) m1/(1 + m1), so 9 m1 = 2 pi (1 + m1): m1 = 2 pi/(9 - 2 pi) = 2.3127 kg, bit for
    // bit the same whichever unit is typed, within 2 ulps of that value (the root rounded
    // once). --exact refuses a turn or a degree by name: pi is irrational.
    let pi = collide::values::rational::from_f64(std::f64::consts::PI);
    let two_pi = &pi + &pi;
    let m1 = &two_pi / &(int(9) - &two_pi);
    let mut binary64 = Vec::new();
    for spin in [",-0.5 rev/s", ",-30 rpm", ",-180 deg/s", ",-0.5 Hz"] {
        let j = run_rod(&["-m", "?,4", "--fin-spin", spin]);
        binary64.push(f(&j["solved"]["m1"]));
        assert_eq!(f(&j["fin"][1]["omega"]), -std::f64::consts::PI, "{spin}");
    }
    assert!(binary64.iter().all(|&x| x == binary64[0]), "{binary64:?}");
    crate::common::assert_ulps(
        binary64[0],
        crate::common::rounded(&m1),
        2.0,
        "m1 from -pi rad/s",
    );
    let a = rod(&["-m", "?,4", "--fin-spin", ",-30 rpm", "--exact"]);
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    solve_refused(&a, &["--exact", "-30 rpm", "irrational"]);
}

#[test]
fn two_hit_points_give_the_same_spin_and_are_refused_by_name() {
    // Masses 1 and 1, a rod of 6 (I = 3): omega2' = -6 y/(6 + y^2), which is -6/5 at y = 2
    // and at y = 3 (the end): both on the rod, so the hit point is not determined.
    solve_refused(
        &[
            "-m",
            "1,1",
            "-v",
            "3,0",
            "--target",
            "rod 6",
            "--hit-at",
            "?",
            "--fin-spin",
            ",-6/5",
            "--exact",
        ],
        &["more than one value fits", "hit_at = 2 and hit_at = 3"],
    );
}

/// A solid sphere of radius 1, mass 1, at (7, -1) onto a floor, e = 1, with `--friction ?`.
fn ball(spin: &str, exact: bool) -> Vec<String> {
    let mut a: Vec<String> = [
        "-m",
        "1,floor",
        "-v",
        "(7,-1),0",
        "--ball",
        "sphere 1",
        "--friction",
        "?",
        "--fin-spin",
        spin,
    ]
    .map(String::from)
    .to_vec();
    if exact {
        a.push("--exact".into());
    }
    a
}

#[test]
fn mu_where_the_ball_slides_and_a_range_where_it_sticks() {
    // P_n = (1 + e) m v_n = 2. Sliding throughout, P_t = 2 mu and omega' = -R P_t / I =
    // -2 mu/(2/5) = -5 mu: a spin of -5/2 gives mu = 1/2. The slip v + R omega = 7 stops when
    // P_t (1/m + R^2/I) = 7/2 P_t = 7, P_t = 2: from mu = P_t/P_n = 1 on the ball leaves
    // rolling at omega' = -5, so a given -5 is every mu >= 1.
    let a = ball("-5/2", true);
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    let j = json(&a);
    assert_eq!(q(&j["solved"]["mu"]), ratio(1, 2));
    assert_eq!(j["contact"], "slip");
    let a = ball("-5", true);
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    let j = json(&a);
    assert_eq!(q(&j["solved"]["mu_at_least"]), Q::ONE);
    let (_, out, _) = run_solve(&a);
    assert!(
        out.starts_with("Solved: mu >= 1 (the contact sticks"),
        "{out}"
    );
    // -6 is beyond what friction gives: refused, naming the sticking value.
    let a = ball("-6", false);
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    solve_refused(&a, &["no mu gives omega1' = -6", "sticking gives -5"]);
}

#[test]
fn unknowns_without_a_known_or_too_many_are_refused_by_name() {
    let refuse = |rest: &[&str], needles: &[&str]| {
        let a = rod(rest);
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        solve_refused(&a, needles);
    };
    refuse(&["-m", "?,4"], &["m1 = ?", "give 1 more known value"]);
    refuse(
        &["-m", "?,4", "-e", "?", "--fin-spin", ",-2"],
        &["2 unknowns (m1, e)", "give 1 more known value"],
    );
    refuse(
        &["-m", "1,4", "--pivot-impulse", "0", "-e", "?"],
        &["--pivot-impulse 0 needs a pivoted target"],
    );
    refuse(
        &["-m", "?,4", "--fin-spin", ",-2", "--friction", "0.3"],
        &["only mu can be the unknown"],
    );
    refuse(
        &["-m", "1,4", "--fin-spin", "-2,", "-e", "?"],
        &["body 1 is a point particle"],
    );
    refuse(
        &["-m", "1,4", "--fin-spin", ",-2"],
        &["the given omega2' contradicts the impact"],
    );
    // The speed along x may be signed; -3 would make the bodies part, not collide.
    solve_refused(
        &[
            "-m",
            "1,4",
            "-v",
            "?,0",
            "--target",
            "rod 2",
            "--hit-at",
            "end",
            "--fin-spin",
            ",9/4",
            "--exact",
        ],
        &["v1 = -3", "do not approach"],
    );
    solve_refused(
        &[
            "-m",
            "1,4",
            "-v",
            "(?,0),0",
            "--target",
            "rod 2",
            "--fin-spin",
            ",-2",
        ],
        &["not for a component"],
    );
}

#[test]
fn the_height_a_round_target_is_struck_at() {
    // Issue 42 section 2, on a disk: a ball (1) at 3 lodges (--join) in a free disk (2, R =
    // 1/2, I_cm = m R^2 / 2 = 1/4) at height b = 3/10, the contact at (-2/5, 3/10). The joined
    // body's centre: (1 (-2/5, 3/10) + 2 (0, 0)) / 3 = (-2/15, 1/10). Its angular momentum
    // about it is the ball's, r x p = (-4/15, 1/5) x (3, 0) = -3/5; its inertia there is the
    // disk's 1/4 + 2 |(2/15, -1/10)|^2 = 1/4 + 1/18 = 11/36 plus the ball's 1 |(-4/15, 1/5)|^2
    // = 1/9: 5/12. omega' = (-3/5) / (5/12) = -36/25. Given that spin, b = 3/10 comes back,
    // exactly: the contact (-sqrt(R^2 - b^2), b) is rational in t = tan(phi/2), and t = 1/3.
    let disk = |rest: &[&str]| -> Vec<String> {
        let mut a: Vec<String> = ["-m", "1,2", "-v", "3,0", "--target", "disk 0.5"]
            .map(String::from)
            .to_vec();
        a.extend(rest.iter().map(|s| s.to_string()));
        a
    };
    let args = disk(&[
        "--join",
        "--hit-at",
        "?",
        "--fin-spin",
        ",-36/25",
        "--exact",
    ]);
    let j = json(&args.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(q(&j["solved"]["hit_at"]), ratio(3, 10));
    assert_eq!(q(&j["check"]["omega2'"]), Q::ZERO);
    // In binary64 the same, to rounding.
    let args = disk(&["--join", "--hit-at", "?", "--fin-spin", ",-1.44"]);
    let j = json(&args.iter().map(String::as_str).collect::<Vec<_>>());
    assert_close(f(&j["solved"]["hit_at"]), 0.3, 1e-12, "b");
    // Smooth, on a pivot a quarter to the right of its centre (I_p = 1/4 + 2/16 = 3/8): with
    // s = sin(phi) = b/R, c = cos(phi), the normal (c, -s) has the arm r x n = s/4 about the
    // pivot, K_nn = 1 + (s/4)^2 / (3/8) = 1 + s^2/6, P = 2 (3c) / K_nn, and omega' = P (s/4) /
    // (3/8) = 24 s c / (6 + s^2): 96/53 at b = 3/10 (s = 3/5, c = 4/5). That spin is reached
    // at a second height too (24 s c / (6 + s^2) rises and falls on (0, 1)): both are named.
    let args = disk(&[
        "--pivot",
        "(0.25,0)",
        "--hit-at",
        "?",
        "--fin-spin",
        ",96/53",
    ]);
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    solve_refused(&args, &["more than one value fits", "hit_at = 0.3 and"]);
    // Free or pivoted at its centre, a smooth round target is not turned at all: the normal
    // passes through its centre. b is not determined, and that is said.
    for (pivot, how) in [
        (&[][..], "free"),
        (&["--pivot", "centre"][..], "on a pivot at its centre"),
    ] {
        let mut rest = pivot.to_vec();
        rest.extend(["--hit-at", "?", "--fin-spin", ",0"]);
        let args = disk(&rest);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        solve_refused(&args, &["smooth disk", how, "b is not determined"]);
    }
    // A rod's own error (a value with no unit) is named, not a round target's.
    let rod = "-m|1 kg,2 kg|-v|3,0|--target|rod 1 m|--pivot|end|--hit-at|?|--pivot-impulse|0";
    solve_refused(
        &rod.split('|').collect::<Vec<_>>(),
        &["velocity '3' has no unit"],
    );
}
