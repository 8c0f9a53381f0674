//! Metamorphic tests (issue 24): the same case told another way must give the same answer told
//! that way, in every subcommand that prints energies or velocities (solve, frames, scene,
//! sweep, batch, track, contact). None of these trusts an output: each compares two outputs by
//! a relation that holds exactly in the physics.
//!
//! - Units: energies in J and in kJ, eV, MeV, cal or ft*lbf differ by exactly the unit's factor;
//!   velocities in m/s and km/h by 3.6, energies by 3.6^2. Each output is rounded once from
//!   an exact value (an energy converted from its binary64 or its exact value, a velocity
//!   computed from exactly scaled inputs), and the factor is applied here, exactly, to the other
//!   output's rounded value: they differ by at most `1 + F ulp(y) / (2 ulp(F y))` ulps
//!   (`round(F y)` against `round(F round(y))`), below 2 for every factor here. Masses scaled
//!   by a power of 4 (with the stiffness, in contact) give bit-identical velocities and
//!   energies scaled exactly.
//! - Mirror: swapping the bodies' order and the direction of the track (`x -> -x`) mirrors the
//!   answer: FIN' = (-FIN2, -FIN1), energies equal (to 1 ulp: the impulse form is symmetric).
//! - Galilean boost: adding `w` to every velocity changes no relative quantity (crunch, loss,
//!   changes of velocity, the COM frame's whole report), and shifts the rest by `w`.
//! - Time reversal: `--reverse` of `--reverse` is the original (exactly in `--exact`).
//!
//! The factors are written here from the units' definitions (1 cal = 4.184 J, 1 ft lbf =
//! 0.3048 m x 4.4482216152605 N, the eV of the 2019 SI, 1 mph = 0.44704 m/s, 1 short ton =
//! 907.18474 kg), not read from the program's table.

use std::collections::BTreeMap;

use crate::common;
use crate::invariants::{num, nums};

use collide::values::rational::Q;
use common::{collide, stdout};
use serde_json::Value;

/// A decimal or fraction, exactly.
pub(crate) fn q(s: &str) -> Q {
    s.parse::<collide::values::number::Number>()
        .unwrap()
        .exact()
}

/// `x f`, exact, rounded once.
pub(crate) fn times(x: f64, f: &Q) -> f64 {
    collide::values::quantity::to_f64(&(collide::values::quantity::from_f64(x) * f)).unwrap()
}

/// Distance in ulps between two binary64 of the same sign (0 for equal values, -0 = 0).
pub(crate) fn ulps(a: f64, b: f64) -> u64 {
    if a == b {
        return 0;
    }
    if a.signum() != b.signum() {
        return u64::MAX;
    }
    (a.abs().to_bits() as i64 - b.abs().to_bits() as i64).unsigned_abs()
}

/// Every leaf of a JSON document by path (`energy.in`, `changes.dv[1]`, `frames[3].w`).
pub(crate) fn leaves(v: &Value) -> BTreeMap<String, Value> {
    fn walk(v: &Value, path: String, out: &mut BTreeMap<String, Value>) {
        match v {
            Value::Object(o) => {
                for (k, x) in o {
                    let p = if path.is_empty() {
                        k.clone()
                    } else {
                        format!("{path}.{k}")
                    };
                    walk(x, p, out);
                }
            }
            Value::Array(a) => {
                for (i, x) in a.iter().enumerate() {
                    walk(x, format!("{path}[{i}]"), out);
                }
            }
            leaf => {
                out.insert(path, leaf.clone());
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(v, String::new(), &mut out);
    out
}

/// `b` is `a` told another way: the same paths (but those `skip` names), each number of `b`
/// within `tol` ulps of `rule(path)` applied to `a`'s (a factor, exactly), each other leaf
/// equal.
#[track_caller]
pub(crate) fn alike(
    a: &Value,
    b: &Value,
    rule: &dyn Fn(&str) -> Q,
    tol: u64,
    skip: &[&str],
    what: &str,
) {
    let (la, lb) = (leaves(a), leaves(b));
    let keys = |l: &BTreeMap<String, Value>| -> Vec<String> {
        l.keys()
            .filter(|k| !skip.iter().any(|s| k.starts_with(s)))
            .cloned()
            .collect()
    };
    assert_eq!(keys(&la), keys(&lb), "{what}: different keys");
    for k in keys(&la) {
        let (x, y) = (&la[&k], &lb[&k]);
        match (x.as_f64(), y.as_f64()) {
            (Some(x), Some(y)) => {
                let expected = times(x, &rule(&k));
                assert!(
                    ulps(expected, y) <= tol,
                    "{what}: {k} = {y}, expected {expected} ({x} x {})",
                    rule(&k)
                );
            }
            _ => assert_eq!(x, y, "{what}: {k}"),
        }
    }
}

pub(crate) fn json(args: &[&str]) -> Value {
    serde_json::from_str(&stdout(args)).unwrap_or_else(|e| panic!("{args:?}: {e}"))
}

/// Whether a report path holds an energy (or a quadratic form, which is twice one).
pub(crate) fn is_energy(path: &str) -> bool {
    let p = path.rsplit_once("].").map_or(path, |(_, p)| p);
    p.starts_with("energy.")
        || path.contains(".energy.")
        || [
            "changes.ke_in",
            "changes.ke_fin",
            "changes.dke",
            "invariants.crunch",
            "invariants.lost",
        ]
        .iter()
        .any(|k| path.contains(k))
}

/// Energy units and their size in joules, from their definitions.
fn joules(unit: &str) -> Q {
    match unit {
        "J" => q("1"),
        "kJ" => q("1000"),
        "eV" => q("1.602176634e-19"),
        "MeV" => q("1.602176634e-13"),
        "cal" => q("4.184"),
        "ft*lbf" => q("0.3048") * q("4.4482216152605"),
        _ => unreachable!(),
    }
}

const UNITS: [&str; 6] = ["J", "kJ", "eV", "MeV", "cal", "ft*lbf"];

/// Cases with units: the case's own energy unit in joules, and the flags.
fn unit_cases() -> Vec<(Q, Vec<&'static str>)> {
    let mph = q("0.44704");
    vec![
        (
            q("1"),
            vec!["-m", "4 kg,1 kg", "-v", "60 m/s,10 m/s", "-e", "2/3"],
        ),
        // Mixed: converted to kg and m/s, energies in J.
        (
            q("1"),
            vec!["-m", "1500 kg,1 t", "-v", "72 km/h,0", "-e", "0.2"],
        ),
        (
            q("907.18474") * &mph * &mph,
            vec!["-m", "4 ton,1 ton", "-v", "60 mph,10 mph", "-e", "0.7"],
        ),
        // Daltons and km/s: energies in u (km/s)^2.
        (
            q("1.66053906892e-27") * q("1000000"),
            vec!["-m", "1 u,12 u", "-v", "2 km/s,0"],
        ),
    ]
}

/// `collide CMD CASE FLAGS --format json` in the case's own energy unit and in each of `units`:
/// every energy by the unit's factor, everything else the same.
fn energies_follow_the_unit(cmd: &str, flags: &[&str], units: &[&str], skip: &[&str]) {
    for (own, case) in unit_cases() {
        let base = [&[cmd][..], &case, flags, &["--format", "json"]].concat();
        let reference = json(&base);
        for unit in units {
            let args = [&base[..], &["--energy-unit", unit]].concat();
            let factor = &own / joules(unit);
            let rule = |p: &str| if is_energy(p) { factor.clone() } else { q("1") };
            alike(
                &reference,
                &json(&args),
                &rule,
                2,
                skip,
                &format!("{args:?}"),
            );
        }
    }
}

#[test]
fn solve_energies_in_another_unit_differ_by_exactly_its_factor() {
    let flags = ["--show", "all", "--contact-time", "10ms", "--reverse"];
    energies_follow_the_unit("solve", &flags, &UNITS, &["units.energy"]);
    // The text's energies carry the unit's label.
    for (_, case) in unit_cases() {
        for unit in UNITS {
            let text = stdout(&[&["solve"][..], &case, &["--energy-unit", unit]].concat());
            assert!(text.contains(&format!("in {unit})")), "{text}");
        }
    }
}

#[test]
fn frames_and_scene_energies_in_another_unit_differ_by_exactly_its_factor() {
    energies_follow_the_unit("frames", &["--reverse"], &["kJ", "eV", "ft*lbf"], &[]);
    // A scene with energy_unit, against the same scene without.
    let dir = std::env::temp_dir().join(format!("collide-metamorphic-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = |unit: Option<&str>| {
        let path = dir.join(format!("{}.toml", unit.unwrap_or("own").replace('*', "x")));
        let mut text = "masses = [\"1 kg\", \"12 kg\"]\nvelocities = [\"2 m/s\", \"0\"]\nrestitution = \"1/3\"\nshow = [\"all\"]\n".to_string();
        if let Some(u) = unit {
            text.push_str(&format!("energy_unit = \"{u}\"\n"));
        }
        std::fs::write(&path, text).unwrap();
        json(&["scene", path.to_str().unwrap(), "--format", "json"])["report"].clone()
    };
    let reference = scene(None);
    for unit in ["kJ", "eV", "cal"] {
        let factor = q("1") / joules(unit);
        let rule = |p: &str| if is_energy(p) { factor.clone() } else { q("1") };
        alike(
            &reference,
            &scene(Some(unit)),
            &rule,
            2,
            &["units.energy"],
            unit,
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// The dimension of a two-body report's path, as a power of velocity: 2 for energies, forms,
/// products; 1 for velocities, momenta, impulses, forces, ellipse radii; 0 for the rest
/// (masses, e, fractions, heights in metres, the principal axes, which body is on the left).
fn velocity_power(path: &str) -> i32 {
    let leaf = path.rsplit('.').next().unwrap_or(path);
    if is_energy(path) || path.starts_with("forms.") || path.starts_with("products.") {
        2
    } else if path.contains("axes")
        || path.starts_with("heights.")
        || path.starts_with("inertia")
        || path == "left"
        || path.contains("restitution")
        || path.contains("fraction")
        // Forces print in newtons whatever the typed units: the same force in both.
        || path.contains("average_force")
        || leaf.starts_with('m') && leaf.len() <= 3
        || leaf == "e"
    {
        0
    } else {
        1
    }
}

#[test]
fn velocities_in_km_h_are_3_6_times_those_in_m_s_everywhere() {
    let v36 = q("3.6");
    let rule = |p: &str| {
        let mut f = q("1");
        for _ in 0..velocity_power(p) {
            f *= &v36;
        }
        f
    };
    for (ms, kmh) in [
        (["10 m/s", "5 m/s"], ["36 km/h", "18 km/h"]),
        (["-2.5 m/s", "7.5 m/s"], ["-9 km/h", "27 km/h"]),
    ] {
        for e in ["1", "2/3", "0", "3/2"] {
            let run = |v: [&str; 2], head: &[&str], tail: &[&str]| {
                let v = format!("{},{}", v[0], v[1]);
                json(
                    &[
                        head,
                        &["-m", "4 kg,1 kg", "-v", &v, "-e", e],
                        tail,
                        &["--format", "json"],
                    ]
                    .concat(),
                )
            };
            let solve = ["--show", "all", "--contact-time", "10ms"];
            let what = format!("solve {ms:?} e = {e}");
            alike(
                &run(ms, &["solve"], &solve),
                &run(kmh, &["solve"], &solve),
                &rule,
                2,
                &["units"],
                &what,
            );
            alike(
                &run(ms, &["frames"], &[]),
                &run(kmh, &["frames"], &[]),
                &rule,
                2,
                &[],
                &what,
            );
        }
    }
    // A sweep's rows.
    let sweep = |v: &str| {
        let text = stdout(&[
            "sweep",
            "-m",
            "4 kg,1 kg",
            "-v",
            v,
            "--vary",
            "e=0:1:5",
            "--vary",
            "m2=0.5,2,8",
            "--format",
            "jsonl",
        ]);
        Value::Array(
            text.lines()
                .map(|l| serde_json::from_str(l).unwrap())
                .collect(),
        )
    };
    alike(
        &sweep("10 m/s,-5 m/s"),
        &sweep("36 km/h,-18 km/h"),
        &|p| {
            let leaf = p.rsplit('.').next().unwrap();
            match leaf {
                "m1" | "m2" | "e" => q("1"),
                "ke_in" | "ke_fin" | "crunch" | "lost" => &v36 * &v36,
                _ => v36.clone(),
            }
        },
        2,
        &[],
        "sweep",
    );
}

/// `collide batch` of CSV rows (as JSON Lines rows).
fn batch(rows: &str) -> Value {
    let done = collide()
        .args(["batch", "--input-format", "csv", "--format", "jsonl"])
        .write_stdin(format!("m1,m2,v1,v2,e\n{rows}"))
        .assert()
        .success();
    let text = String::from_utf8(done.get_output().stdout.clone()).unwrap();
    Value::Array(
        text.lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect(),
    )
}

#[test]
fn masses_in_grams_scale_every_energy_by_1000_and_no_velocity() {
    let rows = |scale: &str| {
        [
            ("4", "1", "60", "10", "1"),
            ("6", "1", "3", "-4", "2/3"),
            ("1e-3", "7", "0.25", "-3", "0.1"),
            ("3", "5", "-1", "-8", "0"),
        ]
        .iter()
        .map(|(m1, m2, v1, v2, e)| {
            let m = |m: &str| {
                collide::values::number::num(
                    num(&Value::String(m.to_string())) * scale.parse::<f64>().unwrap(),
                )
            };
            format!("{},{},{v1},{v2},{e}\n", m(m1), m(m2))
        })
        .collect::<String>()
    };
    // kg -> g: 1000, within 2 ulps; kg -> 1/1024 kg: 1024, bit for bit.
    for (scale, tol) in [("1000", 2), ("1024", 0)] {
        let f = q(scale);
        alike(
            &batch(&rows("1")),
            &batch(&rows(scale)),
            &|p| {
                let leaf = p.rsplit('.').next().unwrap();
                match leaf {
                    "m1" | "m2" | "ke_in" | "ke_fin" | "crunch" | "lost" => f.clone(),
                    _ => q("1"),
                }
            },
            tol,
            &[],
            &format!("batch, masses x {scale}"),
        );
    }
}

/// `path` of the mirrored case's report (bodies swapped, track reversed: `x -> -x`), from the
/// original's leaves `doc`: pairs of velocities, momenta, impulses and forces become `(-b, -a)`,
/// per-body energies and heights `(b, a)`, the tensor and the outer product reverse their
/// indices, the ellipses' radii swap (a lies along V1); velocity scalars change sign; energies,
/// forms, e and fractions stay.
pub(crate) fn mirror(path: &str, doc: &BTreeMap<String, Value>) -> Value {
    // The other body's index: every [0] <-> [1] in the path.
    let other = path
        .replace("[0]", "\u{0}")
        .replace("[1]", "[0]")
        .replace('\u{0}', "[1]");
    let at = |p: &str| doc.get(p).cloned().unwrap_or_else(|| panic!("no {p}"));
    let neg = |v: Value| Value::from(-v.as_f64().unwrap());
    let leaf = path.rsplit('.').next().unwrap_or(path);
    let swapped_only = [
        "inertia",
        "products.outer",
        "changes.ke",
        "changes.dke",
        "heights.",
    ];
    match path {
        p if p.starts_with("ellipses.") && (leaf == "a" || leaf == "b") => {
            let (head, _) = p.rsplit_once('.').unwrap();
            at(&format!("{head}.{}", if leaf == "a" { "b" } else { "a" }))
        }
        p if swapped_only.iter().any(|s| p.starts_with(s)) => at(&other),
        p if p.ends_with(']') => neg(at(&other)),
        "v_com" | "momentum.total" | "w" => neg(at(path)),
        _ => at(path),
    }
}

#[test]
fn swapping_the_bodies_mirrors_the_answer() {
    for (m, v, e) in [
        ("4,1", ["60", "10"], "1"),
        ("6,1", ["3", "-4"], "2/3"),
        ("1e-3,7", ["0.25", "-3"], "0.1"),
        ("3,5", ["-1", "-8"], "0"),
        ("2,9", ["5", "1"], "3/2"),
    ] {
        let (m1, m2) = m.split_once(',').unwrap();
        let neg = |s: &str| s.strip_prefix('-').map_or(format!("-{s}"), String::from);
        let here = ["-m", m, "-v", &format!("{},{}", v[0], v[1]), "-e", e].map(String::from);
        let there = [
            "-m",
            &format!("{m2},{m1}"),
            "-v",
            &format!("{},{}", neg(v[1]), neg(v[0])),
            "-e",
            e,
        ]
        .map(String::from);
        let run = |cmd: &[&str], case: &[String]| {
            let case: Vec<&str> = case.iter().map(String::as_str).collect();
            json(&[cmd, &case, &["--format", "json"]].concat())
        };
        // e = 0 has no time reverse.
        let solve: &[&str] = if e == "0" {
            &["solve", "--show", "all"]
        } else {
            &["solve", "--show", "all", "--reverse"]
        };
        let (a, b) = (run(solve, &here), run(solve, &there));
        let la = leaves(&a);
        let expected = la.keys().map(|p| (p.clone(), mirror(p, &la))).collect();
        same(&expected, &leaves(&b), &format!("mirror of {here:?}"));
        // frames: rows rest-in:1 <-> rest-in:2, rest-fin:1 <-> rest-fin:2, w -> -w.
        let (fa, fb) = (run(&["frames"], &here), run(&["frames"], &there));
        let name = |r: &Value| r["name"].as_str().unwrap().to_string();
        for ra in fa["frames"].as_array().unwrap() {
            let other = match name(ra).as_str() {
                "rest-in:1" => "rest-in:2".into(),
                "rest-in:2" => "rest-in:1".into(),
                "rest-fin:1" => "rest-fin:2".into(),
                "rest-fin:2" => "rest-fin:1".into(),
                n => n.to_string(),
            };
            let rb = fb["frames"]
                .as_array()
                .unwrap()
                .iter()
                .find(|r| name(r) == other)
                .unwrap();
            let la = leaves(ra);
            let expected = la
                .keys()
                .filter(|p| *p != "name")
                .map(|p| (p.clone(), mirror(p, &la)))
                .collect();
            let mut lb = leaves(rb);
            lb.remove("name");
            same(&expected, &lb, &format!("frames {} of {here:?}", name(ra)));
        }
    }
}

/// `actual` has the paths of `expected`, each number within 1 ulp, each other leaf equal.
#[track_caller]
pub(crate) fn same(
    expected: &BTreeMap<String, Value>,
    actual: &BTreeMap<String, Value>,
    what: &str,
) {
    assert_eq!(
        expected.keys().collect::<Vec<_>>(),
        actual.keys().collect::<Vec<_>>(),
        "{what}"
    );
    for (k, x) in expected {
        let y = &actual[k];
        match (x.as_f64(), y.as_f64()) {
            (Some(x), Some(y)) => assert!(ulps(x, y) <= 1, "{what}: {k} = {y}, expected {x}"),
            _ => assert_eq!(x, y, "{what}: {k}"),
        }
    }
}

#[test]
fn a_galilean_boost_changes_no_relative_quantity() {
    // w = 16: every boosted input is exact, so the relative velocity is the same number.
    for (m, v, e) in [
        ("4,1", [60.0, 10.0], "1"),
        ("6,1", [3.0, -4.0], "2/3"),
        ("1e-3,7", [0.25, -3.0], "0.1"),
        ("3,5", [-1.0, -8.0], "0"),
    ] {
        for w in [16.0, -1024.0] {
            let run = |shift: f64, extra: &[&str]| {
                let vs = format!("{},{}", v[0] + shift, v[1] + shift);
                json(
                    &[
                        &["solve", "-m", m, "-v", &vs, "-e", e],
                        extra,
                        &["--format", "json"],
                    ]
                    .concat(),
                )
            };
            let (a, b) = (run(0.0, &["--show", "all"]), run(w, &["--show", "all"]));
            let what = format!("{m} {v:?} e = {e}, boost {w}");
            for k in ["crunch", "lost"] {
                assert!(
                    ulps(num(&a["energy"][k]), num(&b["energy"][k])) <= 1,
                    "{what}: {k}"
                );
            }
            for k in ["dv", "impulse"] {
                let (x, y) = (nums(&a["changes"][k]), nums(&b["changes"][k]));
                for i in 0..2 {
                    let scale = x[0].abs().max(x[1].abs());
                    assert!(
                        (x[i] - y[i]).abs() <= 2.0 * f64::EPSILON * scale,
                        "{what}: {k}"
                    );
                }
            }
            // FIN and V_COM shift by w (to the rounding of the larger).
            let (fa, fb) = (nums(&a["fin"]), nums(&b["fin"]));
            for i in 0..2 {
                let scale = fa[i].abs().max(fb[i].abs());
                assert!(
                    (fb[i] - fa[i] - w).abs() <= 2.0 * f64::EPSILON * scale,
                    "{what}: fin"
                );
            }
            // The COM frame's whole report is the same, but the observer's velocity.
            let com: &[&str] = if e == "0" {
                &["--show", "all", "--frame", "com"]
            } else {
                &["--show", "all", "--frame", "com", "--reverse"]
            };
            let (ca, cb) = (run(0.0, com), run(w, com));
            let shifted = |p: &str| if p == "frame.w" { None } else { Some(q("1")) };
            alike(
                &ca,
                &cb,
                &|p| shifted(p).unwrap(),
                2,
                &[
                    "frame.w",
                    "momentum",
                    "forms",
                    "products",
                    "changes.ke",
                    "changes.dke",
                    "changes.transferred",
                ],
                &format!("COM frame: {what}"),
            );
        }
    }
}

/// `collide solve -m M -v V -e E --reverse [--exact] --format json`.
fn reversed(m: &str, v: &str, e: &str, exact: bool) -> Value {
    let mut args = vec![
        "solve",
        "-m",
        m,
        "-v",
        v,
        "-e",
        e,
        "--reverse",
        "--format",
        "json",
    ];
    if exact {
        args.push("--exact");
    }
    json(&args)
}

#[test]
fn reverse_of_reverse_is_the_original() {
    for (m, v, e) in [
        ("6,1", "3,-4", "2/3"),
        ("4,1", "60,10", "1"),
        ("1,3", "2,-1", "1/7"),
        ("2,5", "1,0", "3/2"),
    ] {
        let what = format!("{m} {v} {e}");
        // Exactly: fractions in, fractions out.
        let one = reversed(m, v, e, true);
        let r = &one["reverse"];
        let text = |x: &Value| x.as_str().unwrap().to_string();
        let v2 = format!("{},{}", text(&r["in"][0]), text(&r["in"][1]));
        let two = reversed(m, &v2, &text(&r["restitution"]), true);
        assert_eq!(two["reverse"]["in"], one["in"], "{what}");
        assert_eq!(two["reverse"]["fin"], one["fin"], "{what}");
        assert_eq!(two["reverse"]["restitution"], one["restitution"], "{what}");
        assert_eq!(two["fin"], r["fin"], "{what}: FIN'' = -IN");
        // In binary64: to the rounding of the velocities (IN'' is -FIN', recomputed).
        let one = reversed(m, v, e, false);
        let r = &one["reverse"];
        let v2 = format!("{:e},{:e}", num(&r["in"][0]), num(&r["in"][1]));
        let two = reversed(m, &v2, &format!("{:e}", num(&r["restitution"])), false);
        let (x, y) = (nums(&one["in"]), nums(&two["reverse"]["in"]));
        let scale = x
            .iter()
            .chain(&nums(&one["fin"]))
            .fold(0.0f64, |a, b| a.max(b.abs()));
        for i in 0..2 {
            assert!(
                (x[i] - y[i]).abs() <= 8.0 * f64::EPSILON * scale,
                "{what}: {x:?} {y:?}"
            );
        }
    }
}
