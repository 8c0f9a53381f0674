//! The plane at its edges, from a hostile review (issue 25): vectors too small or too large for
//! their products in binary64, disks of any size, masses 1e400 apart, impulses that cancel,
//! tangencies, values beyond binary64, negative restitutions and typed forms that were
//! refused. Each expected value is derived in its comment, independently of the program.

use crate::common::{assert_ulps, run, stdout};
use crate::plane::{f, json, vecs};

/// `collide sweep` or `batch` CSV output as rows of cells.
fn csv_rows(out: &str) -> Vec<Vec<String>> {
    out.lines()
        .skip(1)
        .map(|l| l.split(',').map(String::from).collect())
        .collect()
}

#[test]
fn angles_of_tiny_and_huge_vectors_are_their_directions() {
    // Equal masses, elastic, n = (1, -1): v1 = (s, 0) and v2 = (0, s) swap their normal parts,
    // v1' = (0, s), v2' = (s, 0), for any size s: each body turns 90 degrees and the finals are
    // perpendicular. Their dot and cross products underflow (1e-170) or overflow (1e155) in
    // binary64; the angles must not.
    for s in ["1e-170", "1e-300", "1e155", "1e300"] {
        let v = format!("({s},0),(0,{s})");
        // (Their energies are beyond binary64: the angles alone.)
        let j = json(&[
            "-m", "1,1", "-v", &v, "--normal", "(1,-1)", "--show", "angles",
        ]);
        assert_eq!(j["angle_between_deg"], 90.0, "{s}");
        assert_eq!(j["turned_deg"], serde_json::json!([90.0, 90.0]), "{s}");
        let text = stdout(&[
            "solve", "-m", "1,1", "-v", &v, "--normal", "(1,-1)", "--show", "angles",
        ]);
        assert!(text.contains("between v1' and v2'  90°"), "{s}\n{text}");
    }
    // A sweep's row: m = (1, 2), v1 = (1e-300, 0), n = (1, 1), e = 1/2: the impulse on body 2
    // is (1 + e) mu (n.d)/(n.n) n = 1.5 (2/3) (1e-300 / 2) (1, 1) = (0.5e-300)(1, 1), so
    // v1' = (0.5, -0.5) 1e-300 (at -45 degrees: turned 45) and v2' = (0.25, 0.25) 1e-300 (at
    // 45): 90 degrees apart.
    let out = stdout(&[
        "sweep",
        "-m",
        "1,2",
        "-v",
        "(1e-300,0),0",
        "--normal",
        "(1,1)",
        "--vary",
        "e=0.5",
        "--columns",
        "angle1_deg,angle2_deg,turned1_deg,between_deg,jx",
    ]);
    assert_eq!(
        csv_rows(&out),
        [["-45.0", "45.0", "45.0", "90.0", "5e-301"]],
        "{out}"
    );
    // At 1e200 the row is a row, not "a result became NaN".
    let out = stdout(&[
        "sweep",
        "-m",
        "1,1",
        "-v",
        "(1,0),0",
        "--normal",
        "(1,1)",
        "--vary",
        "v1x=1e200",
        "--columns",
        "fin1x,between_deg,error",
    ]);
    assert_eq!(csv_rows(&out), [["5e199", "90.0", ""]], "{out}");
}

#[test]
fn disks_of_any_size_give_the_same_line_of_impact() {
    // Only b / (R1 + R2) = 1/2 counts: phi = 30 degrees, and with equal masses at rest the
    // finals are (1/4, -sqrt(3)/4) and (3/4, sqrt(3)/4) for v1 = (1, 0), whatever the size of
    // the disks (1e154 squared overflows, 1e-160 squared underflows).
    let base = json(&[
        "-m",
        "1,1",
        "-v",
        "(1,0),0",
        "--radii",
        "1,1",
        "--impact-parameter",
        "1",
    ]);
    let fin = vecs(&base["fin"]);
    assert_ulps(fin[1][1], 3f64.sqrt() / 4.0, 2.0, "v2'y");
    for r in ["1e154", "1e200", "1e308", "1e-160", "1e-200", "1e-320"] {
        let radii = format!("{r},{r}");
        let j = json(&[
            "-m",
            "1,1",
            "-v",
            "(1,0),0",
            "--radii",
            &radii,
            "--impact-parameter",
            r,
        ]);
        assert_eq!(j["fin"], base["fin"], "radii {r}");
        let out = stdout(&[
            "sweep",
            "-m",
            "1,1",
            "-v",
            "(1,0),0",
            "--radii",
            &radii,
            "--impact-parameter",
            r,
            "--vary",
            "e=1",
            "--columns",
            "fin2x,fin2y,between_deg",
        ]);
        let row = &csv_rows(&out)[0];
        let got: Vec<f64> = row.iter().map(|x| x.parse().unwrap()).collect();
        assert_ulps(got[0], 0.75, 2.0, &format!("{r}: fin2x"));
        assert_ulps(got[1], fin[1][1], 2.0, &format!("{r}: fin2y"));
    }
    // A disk of 1e300 beside one of 1: b = 1e299 is sin(phi) = 1/10 (5.7392 degrees).
    let j = json(&[
        "-m",
        "1,1",
        "-v",
        "(1,0),0",
        "--radii",
        "1e300,1",
        "--impact-parameter",
        "1e299",
    ]);
    let n = vecs(&serde_json::json!([j["normal"]]))[0].clone();
    let phi = n[1].atan2(n[0]).to_degrees();
    assert!((phi - 0.1f64.asin().to_degrees()).abs() < 1e-12, "{phi}");
    // At the edge: |b| = R1 + R2 in binary64 values is a grazing contact both ways (no
    // collision), and a miss names both sides (they print alike to 15 digits, so it says by
    // how much).
    for b in ["1.1", "-1.1"] {
        let (code, out, err) = run(&[
            "solve",
            "-m",
            "1,1",
            "-v",
            "(1.5,0.3),(-0.2,0.1)",
            "--radii",
            "0.7,0.4",
            "--impact-parameter",
            b,
        ]);
        assert_eq!((code, out.as_str()), (2, ""), "{b}");
        assert!(
            err.contains(
                "|b| = 1.1 is larger than R1 + R2 = 1.1 (by 1.11022302462516e-16 in binary64"
            ),
            "{err}"
        );
        let out = stdout(&[
            "sweep",
            "-m",
            "1,1",
            "-v",
            "(1.5,0.3),(-0.2,0.1)",
            "--radii",
            "0.7,0.4",
            "--impact-parameter",
            "0",
            "--vary",
            &format!("b={b}"),
            "--columns",
            "b,fin1x,error",
        ]);
        assert!(csv_rows(&out)[0][1].is_empty(), "b = {b}: {out}");
    }
}

#[test]
fn sweep_energies_and_impulses_keep_their_digits() {
    // m = (1e200, 1e-200), v1 = (1, 0), n = (1, 0), e = 1/2: mu = 1e-200 (1 + 1e-400)^-1, so
    // crunch = mu/2 = 5e-201 and lost = (1 - 1/4) crunch = 3.75e-201 (m2 / (m1 + m2)
    // underflows to 0 in binary64: they printed 0).
    let cols = ["--columns", "crunch,lost,jx"];
    for (m, crunch, lost) in [
        ("1e200,1e-200", 5e-201, 3.75e-201),
        ("1e160,1e-160", 5e-161, 3.75e-161),
    ] {
        let mut a = vec![
            "sweep", "-m", m, "-v", "(1,0),0", "--normal", "(1,0)", "--vary", "e=0.5",
        ];
        a.extend(cols);
        let row = &csv_rows(&stdout(&a))[0];
        let got: Vec<f64> = row.iter().map(|x| x.parse().unwrap()).collect();
        assert_ulps(got[0], crunch, 2.0, &format!("{m}: crunch"));
        assert_ulps(got[1], lost, 4.0, &format!("{m}: lost"));
        // The impulse on body 2: (1 + e) mu (n.d) = 1.5 mu.
        assert_ulps(got[2], 1.5 * 2.0 * crunch, 4.0, &format!("{m}: impulse"));
        // As collide solve prints them (correctly rounded), to a few ulps.
        let j = json(&["-m", m, "-v", "(1,0),0", "--normal", "(1,0)", "-e", "0.5"]);
        assert_ulps(
            got[0],
            f(&j["energy"]["crunch"]),
            2.0,
            &format!("{m}: crunch vs solve"),
        );
    }
    // n = (1e-20, 1), v1 = (0, 1), v2 = (3, 0), equal masses, elastic: n.d = -3e-20 + 1, so the
    // impulse on body 2 is (n.d / n.n) n = (1 - 3e-20)/(1 + 1e-40) (1e-20, 1), whose x part
    // is 1e-20 to binary64 (m2 (v2' - v2) cancels it to 0).
    let out = stdout(&[
        "sweep",
        "-m",
        "1,1",
        "-v",
        "(0,1),(3,0)",
        "--normal",
        "(1e-20,1)",
        "--vary",
        "e=1",
        "--columns",
        "jx,jy",
    ]);
    assert_eq!(csv_rows(&out), [["1e-20", "1.0"]], "{out}");
    let j = json(&["-m", "1,1", "-v", "(0,1),(3,0)", "--normal", "(1e-20,1)"]);
    assert_eq!(
        vecs(&serde_json::json!([j["impulse"]]))[0],
        vec![1e-20, 1.0]
    );
}

#[test]
fn a_tangency_is_one_solution_exactly() {
    // v1' + v2' = (0, 4) with |v1'| = |v2'| = 2: the only way is v1' = v2' = (0, 2), the
    // bodies leave together (e = 0); the energy equation's double root, no sign change.
    let j = json(&[
        "-m",
        "1,1",
        "-v",
        "(0,4),0",
        "--fin",
        "2 @ ?,2 @ ?",
        "--exact",
    ]);
    assert_eq!(j["fin"], serde_json::json!([["0", "2"], ["0", "2"]]));
    assert_eq!(j["restitution"], "0");
    // 2.1 instead of 2: two mirror solutions, as before.
    let j = json(&["-m", "1,1", "-v", "(0,4),0", "--fin", "2.1 @ ?,2.1 @ ?"]);
    assert_eq!(j["solutions"].as_array().map(Vec::len), Some(2));
}

#[test]
fn values_beyond_binary64_are_never_printed_as_zero_nan_or_inf() {
    // e = 3.4e308: the final velocities given are a contradiction (exit 1), but the solved e
    // is printed as itself, not as 0 beside "superelastic".
    let (code, out, _) = run(&[
        "solve",
        "-m",
        "1,1",
        "-v",
        "(1,0),(0,0)",
        "--fin",
        "(-1.7e308,0),(1.7e308,0)",
        "--normal",
        "(1,0)",
    ]);
    assert_eq!(code, 1);
    assert!(out.contains("e = ≈3.4e308 (superelastic"), "{out}");
    assert!(!out.contains("e = 0"), "{out}");
    // On the rail: a residual of 2e308 and one of -1.7976931348623157e308 (which rounds to 15
    // digits past binary64's largest).
    for (args, misses) in [
        (
            ["-m", "1,1", "-v", "1,0", "--fin", "1e308,?"],
            // -2e308 + 1, to 20 digits (rounded).
            "≈-2e308",
        ),
        (
            [
                "-m",
                "5e-324,2/3",
                "-v",
                "2/3,5e-324",
                "--fin",
                "1.7976931348623157e308,?",
            ],
            "-1.7976931348623157e308",
        ),
    ] {
        let mut a = vec!["solve"];
        a.extend(args);
        a.extend(["-e", "0"]);
        let (code, out, _) = run(&a);
        assert_eq!(code, 1);
        assert!(out.contains(&format!("misses by {misses}")), "{out}");
        assert!(!out.contains("inf") && !out.contains("NaN"), "{out}");
    }
    // The line of impact of disks of 1e308 in exact arithmetic: its angle, not NaN.
    let out = stdout(&[
        "solve",
        "-m",
        "1,1",
        "-v",
        "(1,2),0",
        "--radii",
        "1e308,1e308",
        "--impact-parameter",
        "0",
        "--exact",
    ]);
    assert!(out.contains("at 63.434948822922°"), "{out}");
}

#[test]
fn a_negative_restitution_is_no_collision() {
    // f = (0.8, 0), (0.2, 0) from (1, 0), (0, 0): e = -(0.8 - 0.2)/(1 - 0) = -0.6 < 0, the
    // bodies would pass through each other: refused as on the rail (exit 2), with or without
    // a line of impact.
    for extra in [&["--normal", "(1,0)"][..], &[]] {
        let mut a = vec![
            "solve",
            "-m",
            "1,1",
            "-v",
            "(1,0),0",
            "--fin",
            "(0.8,0),(0.2,0)",
        ];
        a.extend(extra);
        let (code, out, err) = run(&a);
        assert_eq!((code, out.as_str()), (2, ""), "{err}");
        assert!(
            err.contains(
                "e = -0.6 < 0: along the line of impact the bodies would pass through each other"
            ),
            "{err}"
        );
    }
}

#[test]
fn bearings_near_north_and_south_keep_their_digits() {
    // (1e-15, 1) is atan(1e-15) = 5.72957795130823e-14 degrees east of north (90 minus the
    // angle from +x cancels to 5.68e-14).
    let out = stdout(&[
        "solve",
        "-m",
        "1,1",
        "-v",
        "1 @ N,(1e-15,1)",
        "-e",
        "0",
        "--show",
        "vectors",
    ]);
    assert!(out.contains("(N5.72957795130823e-14E)"), "{out}");
    let out = stdout(&[
        "solve",
        "-m",
        "1,1",
        "-v",
        "1 @ S,(-1e-10,-1)",
        "-e",
        "0",
        "--show",
        "vectors",
    ]);
    assert!(out.contains("(S5.72957795130823e-9W)"), "{out}");
}

#[test]
fn the_frame_is_in_the_json_of_the_plane() {
    // Seen from w = (2, 1), every velocity less w, and the JSON says so.
    let j = json(&[
        "-m",
        "1,2",
        "-v",
        "(4,1),(-1,2)",
        "--normal",
        "(1,1)",
        "--frame",
        "(2,1)",
    ]);
    assert_eq!(j["frame"]["w"], serde_json::json!([2.0, 1.0]));
    assert_eq!(vecs(&j["in"]), vec![vec![2.0, 0.0], vec![-3.0, 1.0]]);
    let j = json(&[
        "-m",
        "1,2",
        "-v",
        "(4,1),(-1,2)",
        "--normal",
        "(1,1)",
        "--frame",
        "com",
    ]);
    // V_COM = ((4, 1) + 2 (-1, 2)) / 3 = (2/3, 5/3).
    let w = vecs(&serde_json::json!([j["frame"]["w"]]))[0].clone();
    assert_eq!(w, vec![2.0 / 3.0, 5.0 / 3.0]);
    assert_eq!(j["frame"]["name"], "com");
    let lab = json(&["-m", "1,2", "-v", "(4,1),(-1,2)", "--normal", "(1,1)"]);
    assert!(lab.get("frame").is_none());
}

#[test]
fn forms_that_were_refused_are_solved() {
    // Two pieces from rest: -v 0,0 (a bare 0 is the zero vector of any dimension) with final
    // velocities in the plane: momentum gives 1 (2, 0) + 2 v2' = 0, v2' = (-1, 0).
    let j = json(&["-m", "1,2", "-v", "0,0", "--fin", "(2,0),?"]);
    assert_eq!(vecs(&j["fin"]), vec![vec![2.0, 0.0], vec![-1.0, 0.0]]);
    assert!(
        j.get("note").is_none(),
        "pushed apart from rest is physical: {j}"
    );
    // `-e ?` asks what leaving e out asks: e from the finals along the impulse, here
    // -(0.5 - 0.5, ...) . J / ... : equal masses, (1, 0) -> (1/2, -1/2), (1/2, 1/2): J = (1/2,
    // 1/2) on body 2, relative velocity along it before 1/2, after 0 - 1/2... e = 1.
    let asked = json(&[
        "-m",
        "1,1",
        "-v",
        "(1,0),0",
        "--fin",
        "(0.5,-0.5),(0.5,0.5)",
        "-e",
        "?",
    ]);
    let left = json(&[
        "-m",
        "1,1",
        "-v",
        "(1,0),0",
        "--fin",
        "(0.5,-0.5),(0.5,0.5)",
    ]);
    assert_eq!(asked["restitution"], 1.0);
    assert_eq!(asked["fin"], left["fin"]);
    // Three bodies with a line of impact: the message says what a line of impact is.
    let (code, _, err) = run(&[
        "solve",
        "-m",
        "1,2,3",
        "-v",
        "(4,1),(-1,2),(7,7)",
        "--normal",
        "(1,1)",
        "-e",
        "1/2",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("a line of impact (--normal, --radii) is a contact between two bodies, and this case has 3"), "{err}");
}

#[test]
fn a_sweep_row_beyond_binary64_says_so() {
    // KE_IN = 1/2 (1e200)^2 = 5e399: beyond binary64, named as such in the error column.
    let out = stdout(&[
        "sweep",
        "-m",
        "1,1",
        "-v",
        "(1,0),0",
        "--normal",
        "(1,1)",
        "--vary",
        "v1x=1e200",
        "--columns",
        "ke_in,error",
    ]);
    assert!(out.contains("a result is beyond binary64"), "{out}");
}

/// Plane review #30: with `--exact` and an irrational unit normal, the parts along n are
/// approximations, but a body at rest has the part 0 exactly (0 . n = 0): printed `0`, not
/// `≈0`. Hand values: n = (1, 2)/sqrt 5, v1 = (4, 0): v1.n = 4/sqrt 5 = 1.78885438199983...
#[test]
fn an_exact_zero_among_approximations_is_printed_as_zero() {
    let out = stdout(&[
        "solve", "-m", "1,3", "-v", "(4,0),0", "--normal", "(1,2)", "--exact",
    ]);
    let line = out
        .lines()
        .find(|l| l.trim_start().starts_with("IN   ("))
        .unwrap_or_else(|| panic!("no IN line along n:\n{out}"));
    assert!(line.contains("(≈1.78885438199983"), "{line}");
    assert!(line.contains(", 0)"), "{line}");
    assert!(!line.contains("≈0)"), "{line}");
}

#[test]
fn a_finally_at_rest_frame_without_a_collision_is_initially_at_rest() {
    // v1 = (-4, 0), v2 = (0, 0), n at 30 degrees: n.(v1 - v2) = -4 cos 30 < 0, no collision, so
    // FIN = IN and "body 1 finally at rest" moves with v1 = (-4, 0): seen from it v1 = (0, 0),
    // v2 = (0, 0) - (-4, 0) = (4, 0), exactly (was: shifted by the FIN of the collision that
    // does not happen, v1 = (-3, -1.732)). The same as rest-in:1; rest-fin:2 is rest-in:2,
    // which moves with v2 = (0, 0): the lab's velocities.
    let case = ["-m", "1,1", "-v", "(-4,0),(0,0)", "--normal", "30deg"];
    let with = |frame: &str| {
        let mut a = case.to_vec();
        a.extend(["--frame", frame]);
        json(&a)
    };
    for (frame, same, w, seen) in [
        (
            "rest-fin:1",
            "rest-in:1",
            [-4.0, 0.0],
            [[0.0, 0.0], [4.0, 0.0]],
        ),
        (
            "rest-fin:2",
            "rest-in:2",
            [0.0, 0.0],
            [[-4.0, 0.0], [0.0, 0.0]],
        ),
    ] {
        let j = with(frame);
        assert_eq!(j["approaching"], false, "{frame}: {j}");
        assert_eq!(vecs(&j["in"]), seen.map(Vec::from).to_vec(), "{frame}: {j}");
        assert_eq!(j["frame"]["name"], frame, "{j}");
        assert_eq!(
            j["frame"]["w"]
                .as_array()
                .unwrap()
                .iter()
                .map(f)
                .collect::<Vec<_>>(),
            w.to_vec(),
            "{frame}: {j}"
        );
        let k = with(same);
        assert_eq!(j["in"], k["in"], "{frame} against {same}");
        let mut a = vec!["solve"];
        a.extend_from_slice(&case);
        a.extend(["--frame", frame]);
        let text = stdout(&a);
        assert!(text.contains("no collision: FIN = IN"), "{text}");
    }
}

#[test]
fn a_vector_that_prints_as_zero_has_no_angle() {
    // docs/plane.md: a component below binary64's smallest subnormal prints as 0. Equal masses,
    // elastic, body 2 at rest, n = (1e300, 1e-68): body 1 keeps its tangential part,
    // v1' = v1 - (v1.n) n / n.n = 1e35 (r^2, -r) / (1 + r^2) with r = 1e-368: about
    // (1e-701, -1e-333), both below 4.9e-324. It prints (0, 0) and its speed 0, with no angle
    // (it was `0 @ -90°`), and JSON gives it a zero vector's angle, 0.
    let args = [
        "solve",
        "-m",
        "1,1",
        "-v",
        "(1e35,0),(0,0)",
        "--normal",
        "(1e300,1e-68)",
    ];
    let out = stdout(&args);
    let line = out
        .lines()
        .find(|l| l.trim_start().starts_with("v1'"))
        .unwrap();
    assert_eq!(
        line.split_whitespace().collect::<Vec<_>>(),
        ["v1'", "(0,", "0)", "0"],
        "{out}"
    );
    let j = json(&args[1..]);
    assert_eq!(j["fin"][0], serde_json::json!([0.0, 0.0]));
    assert_eq!(f(&j["fin_angle_deg"][0]), 0.0);
    assert_eq!(f(&j["fin_angle_deg"][1]), 0.0);
    // A vector that prints as non-zero keeps its direction: 1e-300 is within binary64.
    let out = stdout(&[
        "solve",
        "-m",
        "1,1",
        "-v",
        "(1e35,0),(0,0)",
        "--normal",
        "(1e300,1e-35)",
    ]);
    let line = out
        .lines()
        .find(|l| l.trim_start().starts_with("v1'"))
        .unwrap();
    assert!(line.ends_with("@ -90°"), "{line}");
}

#[test]
fn a_smooth_wall_in_the_plane_reflects_the_normal_part_times_e() {
    // Issue 41: "a wall in the plane is not supported yet", though solved with --friction 0.
    // A 1 kg puck at (17.32, 10) m/s onto a smooth wall to its right (normal +x), e = 0.8:
    // the normal part reverses times e, the tangent part is kept: v' = (-0.8 x 17.32, 10) =
    // (-13.856, 10), the binary64 product of the typed binary64 values rounded once; lost
    // 1/2 m (1 - e^2) v_n^2 = 0.18 x 17.32^2 = 53.996832 J.
    let args = ["-m", "1 kg,wall", "-v", "(17.32,10) m/s,0", "-e", "0.8"];
    let (code, j) = crate::common::solve_json(&args);
    assert_eq!(code, 0, "{j}");
    let v = &j["fin"][0]["v"];
    assert_eq!(f(&v[0]), -(0.8 * 17.32));
    assert_eq!(f(&v[1]), 10.0);
    assert_ulps(f(&j["energy"]["lost"]), 53.996832, 4.0, "lost");
    // The same answer as --friction 0 (one computation), apart from the friction it names.
    let (_, mut rough) = crate::common::solve_json(&[&args[..], &["--friction", "0"]].concat());
    rough.as_object_mut().unwrap().remove("friction");
    assert_eq!(rough, j);
    let text = stdout(&[&["solve"], &args[..]].concat());
    assert!(text.contains("v1'  (-13.856, 10) m/s"), "{text}");
    // A floor below the ball: (3, -4) m/s with e = 1/2 leaves at (3, 2).
    let (_, j) =
        crate::common::solve_json(&["-m", "0.06 kg,floor", "-v", "(3,-4) m/s,0", "-e", "0.5"]);
    assert_eq!(j["fin"][0]["v"], serde_json::json!([3.0, 2.0]));
    // Where it cannot be laid out, refused by name.
    let (code, _, err) = run(&["solve", "-m", "1,wall,1", "-v", "(1,0),0,0"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("a wall, floor or ceiling in the plane"),
        "{err}"
    );
}
