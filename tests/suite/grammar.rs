//! One grammar for every value in every mode (issue 41): a rigid case typed in components, as
//! `speed @ angle`, as a compass bearing, with exponents in every field and in other units is
//! one case, and its JSON is the same bit for bit (units converted by exact factors: 10.8 km/h
//! is 3 m/s, 25 cm is 0.25 m); a scene's vectors are strings or arrays, its normal too.

use crate::common;
use crate::rigid::{json, scene};

use common::{number, solve_refused};
use serde_json::Value;

/// A 0.5 kg ball at 3 m/s along +x hits a free 2 kg, 1 m rod 0.25 m above its centre (e = 1).
/// By hand: I = M L^2 / 12 = 1/6, m_eff = (1/m + 1/M + b^2 / I)^-1 = (2 + 1/2 + 3/8)^-1 = 8/23,
/// P = (1 + e) m_eff v = 48/23 N s; v1' = 3 - P/m = -27/23, v2' = P/M = 24/23, the rod's spin
/// -b P / I = -72/23 rad/s (clockwise: hit above its centre from the left).
const ROD: [&str; 8] = [
    "-m",
    "0.5 kg,2 kg",
    "-v",
    "(3,0) m/s,0",
    "--target",
    "rod 1 m",
    "--hit-at",
    "0.25 m",
];

/// The rod case with `field` (a flag) replaced by `value`, or several.
fn rod_with(changes: &[(&str, &str)]) -> Vec<String> {
    let mut args: Vec<String> = ROD.iter().map(|s| s.to_string()).collect();
    for (flag, value) in changes {
        let i = args.iter().position(|a| a == flag).unwrap();
        args[i + 1] = value.to_string();
    }
    args
}

fn solve(args: &[String]) -> Value {
    json(&args.iter().map(String::as_str).collect::<Vec<_>>())
}

#[test]
fn a_rigid_case_typed_every_way_is_one_case() {
    let base = solve(&rod_with(&[]));
    let fin = &base["fin"];
    assert_eq!(number(&fin[0]["v"][0]), -27.0 / 23.0);
    assert_eq!(number(&fin[1]["v"][0]), 24.0 / 23.0);
    assert_eq!(number(&fin[1]["omega"]), -72.0 / 23.0);
    // Each of these failed before: the rigid mode's own splitter read '2.5e-1 m' as 2 with the
    // unit 'e-1 m', and knew no '@'.
    let ways: &[&[(&str, &str)]] = &[
        &[("-v", "3 m/s,0")],
        &[("-v", "3 m/s @ 0deg,0")],
        &[("-v", "3 m/s @ 0°,0")],
        &[("-v", "3 m/s @ E,0")],
        &[("-v", "3 m/s @ 360deg,0 m/s @ N")],
        &[("-v", "3 m/s @ N90E,0")],
        &[
            ("-m", "5e-1 kg,2e3 g"),
            ("-v", "3e0 m/s @ 0e0deg,0e0 m/s"),
            ("--target", "rod 1e2 cm"),
            ("--hit-at", "2.5e-1 m"),
        ],
        // Other units by exact factors: 10.8 km/h = 10.8 x 1000/3600 = 3 m/s exactly.
        &[
            ("-m", "500 g,2000 g"),
            ("-v", "10.8 km/h @ E,0"),
            ("--target", "rod 100 cm"),
            ("--hit-at", "25 cm"),
        ],
        &[("-v", "300 cm/s @ 0deg,0"), ("--hit-at", "250 mm")],
    ];
    for changes in ways {
        let j = solve(&rod_with(changes));
        assert_eq!(j, base, "{changes:?}");
    }
}

#[test]
fn thirty_degrees_is_the_binary64_of_the_product() {
    // 20 m/s @ 30deg: (20 cos 30, 20 sin 30) with sin 30 = 1/2 exactly and cos 30 the binary64
    // nearest sqrt(3)/2 (sqrt is correctly rounded, /2 exact), the product rounded once: the
    // components the plane reads for the same text. N60E is the same direction as a bearing.
    let x = 20.0 * (3f64.sqrt() / 2.0);
    let components = format!("({x:?},10) m/s,0");
    let base = solve(&rod_with(&[("-v", &components)]));
    assert_eq!(number(&base["in"][0]["v"][0]), x);
    assert_eq!(number(&base["in"][0]["v"][1]), 10.0);
    for v in ["20 m/s @ 30deg,0", "20 m/s @ N60E,0", "72 km/h @ 30°,0"] {
        assert_eq!(solve(&rod_with(&[("-v", v)])), base, "{v}");
    }
    // The plane reads the same text as the same vector.
    let (_, plane) = common::solve_json(&["-m", "1,1", "-v", "20 m/s @ 30deg,0", "--normal", "E"]);
    assert_eq!(number(&plane["in"][0][0]), x, "{plane}");
}

#[test]
fn polar_values_refused_where_they_mean_nothing() {
    solve_refused(
        &rod_with(&[("-v", "20 m/s @ 30deg,0")])
            .iter()
            .map(String::as_str)
            .chain(["--exact"])
            .collect::<Vec<_>>(),
        &["velocity '20 m/s @ 30deg'", "irrational", "--exact"],
    );
    solve_refused(
        &rod_with(&[("-v", "-3 m/s @ 0deg,0")])
            .iter()
            .map(String::as_str)
            .collect::<Vec<_>>(),
        &["'-3 m/s @ 0deg'", ">= 0"],
    );
    solve_refused(
        &rod_with(&[("-v", "3 m/s @ 30,0")])
            .iter()
            .map(String::as_str)
            .collect::<Vec<_>>(),
        &["angle '30'", "give its unit"],
    );
}

/// A rigid scene: ball 0.5 kg at 3 m/s along +x, at (-0.1, 0.25) m, onto a free 2 kg body of
/// inertia 1/8 kg m^2 at the origin, contact at (0, 0.25) m with normal +x. By hand:
/// m_eff = (1/0.5 + 1/2 + 0.25^2 / (1/8))^-1 = (2 + 1/2 + 1/2)^-1 = 1/3, P = 2 (1/3) 3 = 2 N s,
/// v1' = 3 - P/0.5 = -1, v2' = P/2 = 1, omega2' = -0.25 P / (1/8) = -4 rad/s.
fn rigid_scene(velocity: &str, inertia: &str, point: &str, normal: &str) -> String {
    format!(
        "[[body]]\nmass = \"0.5 kg\"\nposition = \"(-0.1, 0.25) m\"\nvelocity = {velocity}\n\
         [[body]]\nmass = \"2e3 g\"\ninertia = {inertia}\n\
         [contact]\npoint = {point}\nnormal = {normal}\nrestitution = 1\n"
    )
}

#[test]
fn a_rigid_scene_reads_vectors_as_strings_or_arrays_and_normals_as_the_plane_does() {
    let (code, base) = scene(
        "grammar-base",
        &rigid_scene(
            "\"(3, 0) m/s\"",
            "\"0.125 kg m^2\"",
            "\"(0, 0.25) m\"",
            "[1, 0]",
        ),
    );
    assert_eq!(code, 0);
    assert_eq!(number(&base["fin"][0]["v"][0]), -1.0);
    assert_eq!(number(&base["fin"][1]["v"][0]), 1.0);
    assert_eq!(number(&base["fin"][1]["omega"]), -4.0);
    // Before: `normal = "(1, 0)"` was refused ("invalid type: string"), '1.25e-1 kg m^2' read
    // as 1.25 with the unit 'e-1 kg m^2', and '@' unknown.
    for (i, (v, inertia, point, normal)) in [
        (
            "\"3 m/s @ E\"",
            "\"1.25e-1 kg m^2\"",
            "\"0.25 m @ N\"",
            "\"(1, 0)\"",
        ),
        (
            "\"3e0 m/s @ 0deg\"",
            "\"1250 kg cm^2\"",
            "\"25 cm @ 90deg\"",
            "\"0deg\"",
        ),
        (
            "\"10.8 km/h\"",
            "\"125e-3 kg m^2\"",
            "\"(0, 2.5e-1) m\"",
            "\"E\"",
        ),
    ]
    .into_iter()
    .enumerate()
    {
        let (code, j) = scene(
            &format!("grammar-{i}"),
            &rigid_scene(v, inertia, point, normal),
        );
        assert_eq!((code, &j), (0, &base), "{v} {inertia} {point} {normal}");
    }
}

/// The hostile tokens: not numbers, beyond binary64, other notations, and nothing.
const HOSTILE: [&str; 9] = [
    "NaN", "inf", "-inf", "1e309", "1e-400", "0x10", "３", "1_000", "",
];

/// Every field of the plane and of rigid bodies on the command line, `T` where the token goes,
/// with the words the message must name the field by.
const FIELDS: [(&str, &str); 24] = [
    ("-m|T kg,2 kg|-v|(3,0) m/s,0|--target|rod 1 m", "mass"),
    (
        "-m|1 kg,2 kg|-v|(T,0) m/s,0|--target|rod 1 m",
        "--velocities",
    ),
    (
        "-m|1 kg,2 kg|-v|T m/s @ 30deg,0|--target|rod 1 m",
        "--velocities",
    ),
    (
        "-m|1 kg,2 kg|-v|3 m/s @ Tdeg,0|--target|rod 1 m",
        "--velocities",
    ),
    ("-m|1 kg,2 kg|-v|(3,0) m/s,0|--target|rod T m", "--target"),
    (
        "-m|1 kg,2 kg|-v|(3,0) m/s,0|--target|rod 1 m|--hit-at|T m",
        "--hit-at",
    ),
    (
        "-m|1 kg,2 kg|-v|(3,0) m/s,0|--target|rod 1 m|--pivot|(0,T) m|--hit-at|0.1 m",
        "--pivot",
    ),
    (
        "-m|1 kg,2 kg|-v|(3,0) m/s,0|--target|rod 1 m|--spin|0,T rad/s",
        "--spin",
    ),
    (
        "-m|1 kg,2 kg|-v|(3,0) m/s,0|--ball|sphere T m|--target|rod 1 m",
        "--ball",
    ),
    (
        "-m|1 kg,2 kg|-v|(3,0) m/s,0|--target|rod 1 m|--friction|T",
        "--friction",
    ),
    (
        "-m|1 kg,2 kg|-v|(3,0) m/s,0|--target|rod 1 m|-e|T",
        "--restitution",
    ),
    (
        "-m|1 kg,floor|-v|(3,-4) m/s,0|--tangential-restitution|T",
        "--tangential-restitution",
    ),
    ("-m|1 kg,wall|-v|(T,1) m/s,0|-e|0.5", "--velocities"),
    ("-m|T,2|-v|(3,0),0|--normal|(1,1)", "mass"),
    ("-m|1,2|-v|(T,0),0|--normal|(1,1)", "--velocities"),
    ("-m|1,2|-v|T @ 30deg,0|--normal|(1,1)", "--velocities"),
    ("-m|1,2|-v|3 @ Tdeg,0|--normal|(1,1)", "--velocities"),
    ("-m|1,2|-v|(3,0),0|--normal|(T,1)", "--normal"),
    ("-m|1,2|-v|(3,0),0|--normal|Tdeg", "--normal"),
    (
        "-m|1,2|-v|(3,0),0|--radii|T,1|--impact-parameter|0.5",
        "--radii",
    ),
    (
        "-m|1,2|-v|(3,0),0|--radii|1,1|--impact-parameter|T",
        "--impact-parameter",
    ),
    ("-m|1,2|-v|(3,0),0|--normal|(1,1)|-e|T", "--restitution"),
    ("-m|1,2|-v|(3,0),0|--normal|(1,1)|--fin|(T,0),?", "--fin"),
    ("-m|1,2|-v|(3,0,0),(0,0,T)|--normal|(1,0,0)", "--velocities"),
];

#[test]
fn hostile_tokens_in_every_field_of_the_plane_and_rigid_bodies_are_refused_by_name() {
    for token in HOSTILE {
        for (template, field) in FIELDS {
            let text = template.replace('T', token);
            let args: Vec<&str> = ["solve"].into_iter().chain(text.split('|')).collect();
            let (code, out, err) = common::run(&args);
            assert_eq!(code, 2, "{args:?}: {out}{err}");
            assert!(out.is_empty(), "{args:?}: {out}");
            assert!(!err.contains("panicked"), "{args:?}: {err}");
            assert!(
                err.contains(field),
                "{args:?}: stderr does not name {field}: {err}"
            );
        }
    }
    // -0 is the number 0: refused where 0 is (a mass, a size, a radius), named; elsewhere read
    // as 0, and no output prints "-0".
    for (template, field) in FIELDS {
        let text = template.replace('T', "-0");
        let args: Vec<&str> = ["solve"].into_iter().chain(text.split('|')).collect();
        let (code, out, err) = common::run(&args);
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        match code {
            0 | 1 => assert!(
                !out.contains("-0 ") && !out.contains("-0,"),
                "{args:?}: {out}"
            ),
            2 => assert!(
                err.contains(field) || err.contains("mass") || err.contains("radius"),
                "{args:?}: {err}"
            ),
            _ => panic!("{args:?}: exit {code}: {err}"),
        }
    }
}
