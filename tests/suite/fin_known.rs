//! Final values as knowns (issue 42 sections 2 and 5): a rigid body's final velocity given with
//! `--fin` (a vector, components with `?`, a direction, a speed) fixes e, a mass or mu, and one
//! off the line the impulse allows is refused by name; a scene's `fin` with `slide D mu ?`
//! solves the floor's mu. Each value is derived by hand in the comments and compared exactly
//! under `--exact`, or relatively in binary64.

use crate::common::{assert_close, collide, run, run_solve, solve_refused};
use crate::rigid::{f, json, q};

use collide::values::rational::{Q, int, ratio};

/// A 0.1 kg ball at 3 m/s onto the top end of a free 1 kg, 1.2 m rod standing along y, then
/// `rest`.
fn rod<'a>(rest: &[&'a str]) -> Vec<&'a str> {
    let mut a = vec![
        "-m",
        "0.1 kg,1 kg",
        "-v",
        "3 m/s,0",
        "--target",
        "rod 1.2 m",
        "--hit-at",
        "end",
    ];
    a.extend(rest);
    a
}

#[test]
fn e_and_the_rods_mass_from_the_balls_final_velocity() {
    // The rod's end, d = L/2 from its centre, has the effective mass 1/(1/M + d^2/I) with I =
    // M L^2/12: d^2/I = 3/M, so M/4. The contact's 1D collision: P = (1 + e) m_r v, m_r = m
    // (M/4)/(m + M/4), and the ball's v1' = v - P/m = v - (1 + e) v M/(4m + M).
    // m = 1/10, M = 1: M/(4m + M) = 5/7; v1' = -1/2 gives 1 + e = (7/2)(7/5)/3 = 49/30, e =
    // 19/30. The rod: v2' = P/M = (49/30)(3)(1/14) = 7/20, and omega2' = -P d/I = -(7/20)(3/5)
    // /(3/25) = -7/4 (clockwise: struck above its centre from the left).
    let j = json(&rod(&["-e", "?", "--fin", "-0.5 m/s,?", "--exact"]));
    assert_eq!(q(&j["solved"]["e"]), ratio(19, 30));
    assert_eq!(q(&j["check"]["v1'"]), Q::ZERO);
    assert_eq!(q(&j["fin"][0]["v"][0]), ratio(-1, 2));
    assert_eq!(q(&j["fin"][0]["v"][1]), Q::ZERO);
    assert_eq!(q(&j["fin"][1]["v"][0]), ratio(7, 20));
    assert_eq!(q(&j["fin"][1]["omega"]), ratio(-7, 4));
    // The text says it first, and the check against the FIN as typed.
    let (code, out, _) = run_solve(&rod(&["-e", "?", "--fin", "-0.5 m/s,?", "--exact"]));
    assert_eq!(code, 0);
    assert!(
        out.starts_with("Solved: e = 19/30\nCheck: v1' = '-0.5 m/s' holds exactly\n"),
        "{out}"
    );
    // In binary64: e = 19/30 to 1e-15 relative (the samples are exact rationals of the binary64
    // input; the root is rounded once).
    let j = json(&rod(&["-e", "?", "--fin", "-0.5 m/s,?"]));
    assert_close(f(&j["solved"]["e"]), 19.0 / 30.0, 1e-15, "e");
    // The rod's mass with e = 1/2 and the ball left at rest: v = (1 + e) v M/(4m + M), so 4m +
    // M = (3/2) M, M = 8m = 4/5 kg.
    let mut a = rod(&["-e", "0.5", "--fin", "0,?", "--exact"]);
    a[1] = "0.1 kg,?";
    let j = json(&a);
    assert_eq!(q(&j["solved"]["m2"]), ratio(4, 5));
    // The rod's velocity given as a vector instead: (7/20, 0) is e = 19/30 again.
    let j = json(&rod(&["-e", "?", "--fin", "?,(0.35,0) m/s", "--exact"]));
    assert_eq!(q(&j["solved"]["e"]), ratio(19, 30));
}

#[test]
fn a_pivoted_rods_centre_and_mu_on_a_rough_floor() {
    // The same rod on a pivot at its bottom end, struck at its top (d = L = 6/5): I_p = M L^2/3
    // = 12/25, the tip's effective mass I_p/L^2 = 1/3, m_r = (1/10)(1/3)/(1/10 + 1/3) = 1/13,
    // P = 3 (1 + e)/13, omega' = P L/I_p = 5P/2, and the centre's speed (L/2) omega' = 3P/2 =
    // 9 (1 + e)/26. Given 7/20: 1 + e = (7/20)(26/9) = 91/90, e = 1/90.
    let j = json(&rod(&[
        "--pivot",
        "end",
        "-e",
        "?",
        "--fin",
        "?,(0.35,0) m/s",
        "--exact",
    ]));
    assert_eq!(q(&j["solved"]["e"]), ratio(1, 90));
    // A solid sphere (m = 1) at (3, -4) onto a rough floor, e = 1/2: P_n = (1 + e) 4 = 6. While
    // it slides, P_t = mu P_n against the slip, so vx' = 3 - 6 mu; the slip changes by P_t (1/m
    // + R^2/I) = (7/2) P_t, so it stops at mu = 3/(7/2 . 6) = 1/7. vx' = 5/2 is mu = 1/12 <
    // 1/7: it slides throughout. vy' = e 4 = 2 whatever mu is ('?').
    let ball = |fin: &'static str, exact: bool| {
        let mut a = vec![
            "-m",
            "1 kg,floor",
            "-v",
            "(3,-4) m/s,0",
            "--ball",
            "sphere 0.1 m",
            "--friction",
            "?",
            "-e",
            "0.5",
            "--fin",
        ];
        a.push(fin);
        if exact {
            a.push("--exact");
        }
        a
    };
    let j = json(&ball("(2.5,?) m/s,?", true));
    assert_eq!(q(&j["solved"]["mu"]), ratio(1, 12));
    assert_eq!(q(&j["fin"][0]["v"][1]), int(2));
    // The direction instead: (5/2, 2) is at atan(4/5) = 38.6598... deg; in binary64 the
    // direction's cos and sin are rounded: mu = 1/12 to 1e-14 relative.
    let j = json(&ball("? @ 38.659808254090095deg,?", false));
    assert_close(f(&j["solved"]["mu"]), 1.0 / 12.0, 1e-14, "mu");
    // vx' = 2 would need the slip to reverse: sticking (every mu >= 1/7) gives 3 - 6/7 = 15/7
    // (printed to 15 digits).
    solve_refused(
        &ball("(2,?) m/s,?", true),
        &[
            "no mu gives v1' = '(2,?) m/s'",
            "sticking gives v1' = (2.14285714285714, 2)",
        ],
    );
}

#[test]
fn a_final_velocity_off_the_impulses_line_or_not_fixing_it_is_refused() {
    // The impulse on a smooth contact is along n = (1, 0): the ball's v1' - v1 is along x, so a
    // y component of 0.2 contradicts the impact, whatever e is; said with the line.
    solve_refused(
        &rod(&["-e", "?", "--fin", "(-0.5,0.2) m/s,?", "--exact"]),
        &[
            "e = 0.633333333333333 gives v1' = (-0.5, 0)",
            "only along (1, 0)",
            "off that line",
        ],
    );
    // vy' = 0 holds for every e: nothing fixes it.
    solve_refused(
        &rod(&["-e", "?", "--fin", "(?,0) m/s,?"]),
        &["every e gives the same value"],
    );
    // v1' = 3 - (15/7)(1 + e) is along x for every e: '? @ 180deg' (leftward) holds for every e
    // in (2/5, 1], '? @ 0deg' for every e in [0, 2/5): the side alone does not fix e.
    for d in ["? @ 180deg,?", "? @ 0deg,?"] {
        solve_refused(
            &rod(&["-e", "?", "--fin", d, "--exact"]),
            &["every e gives a final velocity on the given line; the side alone"],
        );
    }
    // '? @ 90deg' needs vx' = 0: only e = 2/5, where the ball stops; a body at rest has no
    // direction, so nothing fits (it was solved as e = 2/5 with "holds exactly").
    solve_refused(
        &rod(&["-e", "?", "--fin", "? @ 90deg,?", "--exact"]),
        &[
            "e = 0.4 gives v1' = (0, 0) (a body at rest has no direction)",
            "only along (1, 0)",
        ],
    );
    // A speed of 1/2 is v1' = +-1/2: e = 1/6 (v1' = 3 - (7/6)(15/7) = 1/2) and e = 19/30.
    solve_refused(
        &rod(&["-e", "?", "--fin", "0.5 m/s @ ?,?", "--exact"]),
        &[
            "more than one value fits",
            "e = 0.166666666666666 and e = 0.633333333333333",
        ],
    );
    // With e given and nothing unknown, the FIN is checked: e = 1/2 gives v1' = 3 - (3/2)(3)(5/7)
    // = -3/14, which misses -1/2 by 2/7 (printed to 15 digits).
    solve_refused(
        &rod(&["-e", "0.5", "--fin", "-0.5 m/s,?", "--exact"]),
        &[
            "the given v1' contradicts the impact",
            "misses by 0.285714285714285",
        ],
    );
    let (code, out, _) = run_solve(&rod(&["-e", "0.5", "--fin", "-3/14 m/s,?", "--exact"]));
    assert_eq!(code, 0);
    assert!(
        out.starts_with("Check: v1' = '-3/14 m/s' holds exactly\n"),
        "{out}"
    );
    // The rail's heights and slides, and a floor's velocity, are refused by name.
    solve_refused(
        &rod(&["-e", "?", "--fin", "?,height 1 m"]),
        &["--fin 'height 1 m'", "the rail's"],
    );
    solve_refused(
        &[
            "-m",
            "1 kg,floor",
            "-v",
            "(3,-4) m/s,0",
            "--ball",
            "sphere 0.1 m",
            "-e",
            "?",
            "--fin",
            "?,(0,0) m/s",
        ],
        &["body 2 is a floor"],
    );
}

#[test]
fn a_scenes_slide_with_mu_unknown_solves_the_floors_mu() {
    // scenarios/homework-slide-mu.toml: 0.1 kg at 400 m/s lodges in 3.9 kg (f = 40/4 = 10
    // m/s), which slides 20 m with g = 10: mu = f^2/(2 g d) = 100/400 = 1/4.
    let (code, out, err) = run(&[
        "scene",
        "scenarios/homework-slide-mu.toml",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["report"]["solved"]["mu"], "1/4", "{j}");
    assert_eq!(j["checks"], 3, "{j}");
    // A bare slide (no mu) in a scene has no floor's mu to take: refused at its line.
    let text =
        "masses = [1, 3]\nvelocities = [4, 0]\nrestitution = 0\nfin = [\"?\", \"slide 1 m\"]\n";
    let out = collide()
        .args(["scene", "-"])
        .write_stdin(text)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("'slide 1 m'") && err.contains("<stdin>:4:"),
        "{err}"
    );
    // With a wall there is no collision of two movable bodies to solve it from.
    let text = "masses = [1, \"wall\"]\nvelocities = [4, 0]\nrestitution = 0.5\nfin = [\"slide 1 m mu ?\", 0]\n";
    let out = collide()
        .args(["scene", "-"])
        .write_stdin(text)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("two movable bodies"), "{err}");
}
