//! Bodies that join (`--join`, issue 42 section 1; physics.md section 8): the striking particle
//! stays at the contact point and the pair moves on as one rigid body. Each answer is derived by
//! hand in the test's comments (angular momentum about the pivot, or linear and angular momentum
//! about the combined centre when free) and compared exactly under `--exact`, and to a few ulps
//! in binary64; the rail's `-e 0` gives the same omega where both apply; bad combinations exit 2.

use crate::common::{assert_ulps, rounded, run_solve, solve_refused};
use crate::rigid::{f, json, q};

use collide::values::rational::{Q, int, ratio};

/// The disk of the issue: 2.0 g at 500 m/s along the tangent at the top of a 3.2 kg, 0.5 m
/// disk on an axle through its centre.
const DISK: [&str; 12] = [
    "-m",
    "2.0 g,3.2 kg",
    "-v",
    "500 m/s,0",
    "--target",
    "disk 0.5 m",
    "--pivot",
    "centre",
    "--hit-at",
    "0.5 m",
    "--join",
    "--format",
];

fn disk(exact: bool) -> serde_json::Value {
    let mut a: Vec<&str> = DISK[..11].to_vec();
    if exact {
        a.push("--exact");
    }
    json(&a)
}

#[test]
fn a_bullet_along_a_tangent_joins_a_disk_on_its_axle() {
    // m = 1/500 kg at v = 500 m/s along y = R = 1/2 m, tangent to the disk's rim at its top (the
    // normal through the centre is across the path: a grazing contact, which joins). About the
    // axle: L = -R m v = -1/2 (clockwise), I_p = M R^2/2 = 16/5 * 1/4 / 2 = 2/5, and with the
    // bullet in the rim I = 2/5 + m R^2 = 2/5 + 1/2000 = 801/2000, so
    // omega' = -m v R / (I_p + m R^2) = -(1/2) / (801/2000) = -1000/801 = -1.2484 rad/s.
    let j = disk(true);
    assert_eq!(j["contact"], "joined");
    // No restitution law is used: the JSON names the join (issue 42: it said "poisson").
    assert_eq!(j["law"], "join");
    let joined = &j["joined"];
    assert_eq!(q(&joined["omega"]), ratio(-1000, 801));
    assert_eq!(q(&j["fin"][1]["omega"]), ratio(-1000, 801));
    // M = 1/500 + 16/5 = 1601/500 kg; centre (0, (1/500 * 1/2)/M) = (0, 1/3202); I about the
    // axle 801/2000; v_cm = omega x X = (-omega * 1/3202, 0) = (1000/(801 * 3202), 0).
    assert_eq!(q(&joined["mass"]), ratio(1601, 500));
    assert_eq!(q(&joined["centre"][1]), ratio(1, 3202));
    assert_eq!(q(&joined["inertia"]), ratio(801, 2000));
    assert_eq!(q(&joined["pivot"][0]), Q::ZERO);
    assert_eq!(q(&joined["v"][0]), ratio(1000, 801 * 3202));
    assert_eq!(q(&joined["v"][1]), Q::ZERO);
    // The bullet moves with the rim: omega x (0, 1/2) = (500/801, 0) m/s.
    assert_eq!(q(&j["fin"][0]["v"][0]), ratio(500, 801));
    // Energy: KE_IN = 1/2 m v^2 = 250 J, KE_FIN = 1/2 I omega^2 = 801/4000 * 10^6/801^2 =
    // 250/801, lost 250 * 800/801 = 200000/801 J.
    assert_eq!(q(&j["energy"]["lost"]), ratio(200_000, 801));
    // binary64: the same omega to a few ulps (2.0 g is 0.002 rounded to binary64 once).
    let b = disk(false);
    assert_ulps(
        f(&b["joined"]["omega"]),
        rounded(&ratio(-1000, 801)),
        4.0,
        "omega'",
    );
    assert_ulps(
        f(&b["joined"]["inertia"]),
        rounded(&ratio(801, 2000)),
        4.0,
        "I",
    );
}

#[test]
fn the_text_shows_the_joined_body_and_the_energy_lost() {
    // The same disk in text: the combined body's mass, centre, inertia about the axle, omega
    // (-1000/801 = -1.24843945068664 rad/s) and the energy lost (200000/801 = 249.687890137328 J).
    let (code, out, err) = run_solve(&DISK[..11]);
    assert_eq!(code, 0, "{err}");
    for line in [
        "The joined body (one rigid body after the impact)",
        "  M       3.202 kg",
        "  I_p     0.4005 kg m^2",
        "about the pivot (0, 0)",
        "  omega   -1.24843945068664 rad/s",
        "  lost    249.687890137328 J",
        "The bodies join: the ball stays at the contact point (e = 0, no slip: w' = 0)",
        "contact         joined",
        // v_cm is the momentum after over M, (1601/500) v = 1/801 kg m/s (the pivot's impulse
        // takes the rest): not the contact's impulse P = 0.9988 N s over M (it said "P / M").
        "  v_cm    (0.000389893644811568, 0) m/s  P_FIN / M",
    ] {
        assert!(out.contains(line), "missing {line:?}:\n{out}");
    }
    // The grazing contact has no normal approach: no restitution is printed along n.
    assert!(!out.contains("e along n"), "{out}");
}

#[test]
fn clay_sticks_to_the_end_of_a_free_rod() {
    // Clay m = 1 at v = 5 onto the top end (0, 1) of a free rod M = 4, L = 2 (I_cm = M L^2/12 =
    // 4/3). Combined: mass 5, centre X = (0, 1 * 1/5) = (0, 1/5), v_cm = m v / 5 = 1. Inertia
    // about X: rod 4/3 + 4 (1/5)^2 = 4/3 + 4/25, clay 1 * (4/5)^2 = 16/25: 4/3 + 4/5 = 32/15.
    // Angular momentum about X: the clay's (x - X) x m v = (0, 4/5) x (5, 0) = -4, so
    // omega = -4 / (32/15) = -15/8. Energy: 25/2 before, 1/2 5 1^2 + 1/2 32/15 225/64 = 5/2 +
    // 15/4 = 25/4 after: lost 25/4, the crunch of the rail with the rod end's effective mass
    // M/4 = 1 (1/2 (1 * 1/2) 5^2).
    let j = json(&[
        "-m", "1,4", "-v", "5,0", "--target", "rod 2", "--hit-at", "end", "--join", "--exact",
        "--show", "all",
    ]);
    let joined = &j["joined"];
    assert_eq!(q(&joined["mass"]), int(5));
    assert_eq!(q(&joined["centre"][1]), ratio(1, 5));
    assert_eq!(q(&joined["inertia"]), ratio(32, 15));
    assert!(joined.get("pivot").is_none(), "{joined}");
    assert_eq!(q(&joined["v"][0]), int(1));
    assert_eq!(q(&joined["omega"]), ratio(-15, 8));
    assert_eq!(q(&j["energy"]["lost"]), ratio(25, 4));
    assert_eq!(q(&j["along_normal"]["crunch"]), ratio(25, 4));
    // The clay leaves with the rod's end: v_cm + omega x (0, 4/5) = (1 + 15/8 4/5, 0) = (5/2,
    // 0), so its impulse is 1 (5 - 5/2) = 5/2 along the normal, all of it compression (bodies
    // that join never separate: mutant `impact.rs:218`, `/` to `%` in `P.n / n.n`, gave 1/2).
    assert_eq!(q(&j["fin"][0]["v"][0]), ratio(5, 2));
    assert_eq!(q(&j["impulse"]["normal"]), ratio(5, 2));
    assert_eq!(q(&j["impulse"]["compression"]), ratio(5, 2));
    // Free: momentum (5, 0) and angular momentum about the contact point are kept.
    assert_eq!(j["momentum"]["kept"], true);
    assert_eq!(j["momentum"]["in"], j["momentum"]["fin"]);
    assert_eq!(
        j["momentum"]["angular"]["in"],
        j["momentum"]["angular"]["fin"]
    );
}

#[test]
fn clay_from_any_direction_joins() {
    // The same rod and clay, the clay at v = (3, -4) (not along the normal): v_cm = (3, -4)/5,
    // L about X = (0, 4/5) x (3, -4) = 0 * (-4) - 4/5 * 3 = -12/5, omega = -12/5 * 15/32 =
    // -9/8. The clay moves with the rod's end after: v_cm + omega x (0, 4/5) =
    // (3/5 + 9/8 * 4/5, -4/5) = (3/5 + 9/10, -4/5) = (3/2, -4/5).
    let j = json(&[
        "-m", "1,4", "-v", "(3,-4),0", "--target", "rod 2", "--hit-at", "end", "--join", "--exact",
    ]);
    assert_eq!(q(&j["joined"]["v"][0]), ratio(3, 5));
    assert_eq!(q(&j["joined"]["v"][1]), ratio(-4, 5));
    assert_eq!(q(&j["joined"]["omega"]), ratio(-9, 8));
    assert_eq!(q(&j["fin"][0]["v"][0]), ratio(3, 2));
    assert_eq!(q(&j["fin"][0]["v"][1]), ratio(-4, 5));
}

#[test]
fn a_ballistic_pendulum_with_a_rod() {
    // A 10 g bullet at 400 m/s into the top end of a 2 kg, 1 m rod hinged at its bottom end:
    // I_p = M L^2/3 = 2/3, with the bullet at L from the hinge I = 2/3 + 1/100 = 203/300, and
    // about the hinge L = -m v L = -4, so omega' = -4 * 300/203 = -1200/203 = -5.911 rad/s.
    // The centre: (1/100 * 1/2 + 2 * 0)/(201/100) = 1/402 above the rod's centre, 101/201
    // above the hinge; v_cm = -omega * 101/201 = 1200 * 101/(203 * 201). Energy: 800 J before,
    // 1/2 (203/300) (1200/203)^2 = 2400/203 after: lost 160000/203 J.
    let j = json(&[
        "-m",
        "10 g,2 kg",
        "-v",
        "400 m/s,0",
        "--target",
        "rod 1 m",
        "--pivot",
        "end",
        "--hit-at",
        "end",
        "--join",
        "--exact",
    ]);
    let joined = &j["joined"];
    assert_eq!(q(&joined["omega"]), ratio(-1200, 203));
    assert_eq!(q(&joined["inertia"]), ratio(203, 300));
    assert_eq!(q(&joined["pivot"][1]), ratio(-1, 2));
    assert_eq!(q(&joined["centre"][1]), ratio(1, 402));
    assert_eq!(q(&joined["v"][0]), ratio(1200 * 101, 203 * 201));
    assert_eq!(q(&j["energy"]["lost"]), ratio(160_000, 203));
}

#[test]
fn a_point_mass_on_a_rod_joins_as_the_rail_sticks() {
    // Perpendicular onto a free rod the collision matrix is diagonal in (n, t) (the rod's spin
    // moves the contact along n only), so joining is e = 0 along the normal with no slip to
    // stop: --join and -e 0 give the same FIN, and the rail with the rod end's effective mass
    // (M/4 = 1 at the end of M = 4, L = 2) sticks at V_COM = 5/2, the speed of the rod's end
    // after: v2' + (-omega2' * 1) = 5/8 + 15/8 = 5/2.
    for hit in ["end", "1/2", "-1/3"] {
        let base = [
            "-m", "1,4", "-v", "5,0", "--target", "rod 2", "--hit-at", hit, "--exact",
        ];
        let join = json(&[&base[..], &["--join"]].concat());
        let zero = json(&[&base[..], &["-e", "0"]].concat());
        assert_eq!(join["fin"], zero["fin"], "--hit-at {hit}");
    }
    let join = json(&[
        "-m", "1,4", "-v", "5,0", "--target", "rod 2", "--hit-at", "end", "--join", "--exact",
    ]);
    let rail = json(&["-m", "1,1", "-v", "5,0", "-e", "0", "--exact"]);
    assert_eq!(q(&rail["fin"][0]), ratio(5, 2));
    let end = q(&join["fin"][1]["v"][0]) - q(&join["fin"][1]["omega"]);
    assert_eq!(end, q(&rail["fin"][0]));
    assert_eq!(q(&join["fin"][0]["v"][0]), q(&rail["fin"][0]));
}

#[test]
fn a_child_runs_onto_a_turning_merry_go_round() {
    // A platform (disk 2 m, 200 kg: I = 1/2 200 2^2 = 400 kg m^2) turns clockwise at 0.5 rad/s
    // on its axle; a 40 kg child runs at 4 m/s along the tangent at its top (y = R) and jumps
    // on. About the axle: L = 400 (-1/2) - R m v = -200 - 320 = -520, I = 400 + 40 * 4 = 560,
    // omega' = -520/560 = -13/14 rad/s. Energy: 1/2 400 1/4 + 1/2 40 16 = 50 + 320 = 370 J
    // before, 1/2 560 (13/14)^2 = 1690/7 after: lost 900/7 J.
    let j = json(&[
        "-m",
        "40 kg,200 kg",
        "-v",
        "4 m/s,0",
        "--target",
        "disk 2 m",
        "--pivot",
        "centre",
        "--hit-at",
        "2 m",
        "--spin",
        "0,-0.5 rad/s",
        "--join",
        "--exact",
    ]);
    assert_eq!(q(&j["joined"]["omega"]), ratio(-13, 14));
    assert_eq!(q(&j["joined"]["inertia"]), int(560));
    assert_eq!(q(&j["energy"]["lost"]), ratio(900, 7));
}

#[test]
fn bad_combinations_are_refused_by_name() {
    let rod = ["-m", "1,4", "-v", "3,0", "--target", "rod 2", "--join"];
    fn with<'a>(rod: &[&'a str], extra: &[&'a str]) -> Vec<&'a str> {
        [rod, extra].concat()
    }
    solve_refused(&with(&rod, &["-e", "0"]), &["--join", "leave out -e"]);
    solve_refused(&with(&rod, &["--friction", "1"]), &["--join", "--friction"]);
    solve_refused(&with(&rod, &["--law", "newton"]), &["--join", "--law"]);
    solve_refused(
        &with(&rod, &["--tangential-restitution", "1"]),
        &["--join", "--tangential-restitution"],
    );
    solve_refused(&with(&rod, &["--ball", "sphere 1"]), &["--join", "--ball"]);
    solve_refused(
        &["-m", "1,wall", "-v", "3,0", "--join"],
        &["--join", "wall"],
    );
    solve_refused(
        &["-m", "1,floor", "-v", "(3,-1),0", "--join"],
        &["--join", "floor"],
    );
}

#[test]
fn bodies_that_separate_do_not_join() {
    // Moving away from the rod (n.w = -3 < 0): no collision, the note as without --join.
    let (code, out, err) = run_solve(&["-m", "1,4", "-v", "-3,0", "--target", "rod 2", "--join"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("do not approach"), "{out}");
    assert!(!out.contains("joined"), "{out}");
}
