//! Units (issue 31 §5, mutants of `src/values/units.rs` that no test caught): the nearest-name
//! suggestion for a mistyped unit, and speeds as heights in another velocity unit and gravity.

use crate::common;

use collide::values::units::{Dimension, UnitError, lookup};

/// The suggestion for a mistyped unit: `Some(name)` or `None` (no known name within 2 edits).
fn suggestion(typed: &str, d: Dimension) -> Option<&'static str> {
    match lookup(typed, d) {
        Err(UnitError::DidYouMean { near, .. }) => Some(near),
        Err(UnitError::Unknown { .. }) => None,
        other => panic!("{typed}: {other:?}"),
    }
}

#[test]
fn a_mistyped_unit_gets_the_nearest_name() {
    // Edit distance (an insertion, deletion, substitution or swap of neighbours counts 1),
    // at most 2, ties to the first name in byte order; the nearest three, by hand:
    //   mhp: mph 1 (a swap), kph 2, m/s 2     kks: kts 1, km/s 2, kn 2
    //   h: kn 2, kph 2, mph 2                 kk: kn 1, kph 2, km/h 3
    //   mk/: km/h 2 (a swap, an insertion), km/s 2, kn 2
    //   mk: kn 2, m/s 2, mph 2                knott: knot 1, knots 1
    //   xyzzy: nothing within 5               kgxyz: kg 3 (too far)
    //   kgx: kg 1                             slgu: slug 1 (a swap)
    for (typed, near) in [
        ("mhp", Some("mph")),
        ("kks", Some("kts")),
        ("h", Some("kn")),
        ("kk", Some("kn")),
        ("mk/", Some("km/h")),
        ("mk", Some("kn")),
        ("knott", Some("knot")),
        ("xyzzy", None),
    ] {
        assert_eq!(suggestion(typed, Dimension::Velocity), near, "{typed}");
    }
    // Three deletions away is too far: no suggestion.
    assert_eq!(suggestion("kgxyz", Dimension::Mass), None);
    assert_eq!(suggestion("kgx", Dimension::Mass), Some("kg"));
    assert_eq!(suggestion("slgu", Dimension::Mass), Some("slug"));
}

#[test]
fn the_spellings_sources_use_are_units_with_their_exact_factors() {
    // Issue 45 §5: each spelling against its exact size in m/s, by the definitions
    // (1 ft = 0.3048 m, 1 mi = 1609.344 m, 1 nautical mile = 1852 m, 1 h = 3600 s):
    //   fps = ft/sec = 0.3048 = 381/1250; m/sec = 1; km/hr = kph = 1000/3600 = 5/18;
    //   km/sec = 1000; mi/h = mi/hr = 1609.344/3600 = 0.44704 = 1397/3125;
    //   kts = 1852/3600 = 463/900; cm/sec = 1/100.
    use collide::values::rational::{int, ratio};
    for (name, si, printed) in [
        ("fps", ratio(381, 1250), "ft/s"),
        ("ft/sec", ratio(381, 1250), "ft/s"),
        ("m/sec", int(1), "m/s"),
        ("kph", ratio(5, 18), "km/h"),
        ("km/hr", ratio(5, 18), "km/h"),
        ("km/sec", int(1000), "km/s"),
        ("mi/h", ratio(1397, 3125), "mph"),
        ("mi/hr", ratio(1397, 3125), "mph"),
        ("kts", ratio(463, 900), "knot"),
        ("cm/sec", ratio(1, 100), "cm/s"),
    ] {
        let unit = lookup(name, Dimension::Velocity).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(unit.si(), si, "{name}");
        assert_eq!(unit.name(), printed, "{name}");
    }
    // Typed on the command line: a 2 kg ball at 15 fps (= 15 ft/s) stopping a 1 kg one at rest,
    // elastic: v1' = (2 - 1)/3 * 15 = 5 ft/s, v2' = 2*2/3 * 15 = 20 ft/s, printed in ft/s.
    let out = common::stdout(&["solve", "-m", "2 kg,1 kg", "-v", "15 fps,0", "--exact"]);
    assert!(
        out.starts_with("FIN: v1' = 5 ft/s, v2' = 20 ft/s\n"),
        "{out}"
    );
}

#[test]
fn heights_use_the_velocity_unit_and_the_given_gravity() {
    // 36 km/h = 10 m/s exactly; with g = 10: v^2 / 2g = 5 m, and after e = 1/2, 5/4 m.
    let out = common::stdout(&[
        "solve",
        "-m",
        "1,wall",
        "-v",
        "36 km/h,0",
        "-e",
        "0.5",
        "--show",
        "heights",
        "--gravity",
        "10",
        "--exact",
        "--format",
        "json",
    ]);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["heights"], serde_json::json!({"in": "5", "fin": "5/4"}));
    let text = common::stdout(&[
        "solve",
        "-m",
        "1,wall",
        "-v",
        "36 km/h,0",
        "-e",
        "0.5",
        "--show",
        "heights",
        "--gravity",
        "10",
    ]);
    assert!(text.contains("v^2 / 2g, g = 10 m/s^2, in m"), "{text}");
    // Standard gravity, named as typed in the heading: 9.80665.
    let text = common::stdout(&[
        "solve",
        "-m",
        "1,wall",
        "-v",
        "height 2 m,0",
        "-e",
        "0.5",
        "--show",
        "heights",
    ]);
    assert!(text.contains("g = 9.80665 m/s^2"), "{text}");
    assert!(
        text.contains("  IN   2 ") && text.contains("  FIN  0.5 "),
        "{text}"
    );
}

#[test]
fn a_height_of_zero_is_a_speed_of_zero_and_energy_units_need_both_units() {
    use collide::values::units::{EnergyUnitError, Units, energy_unit, parse};
    // 0 m is a height (a speed of 0), not a negative one; -1 m is refused.
    let q = parse("height 0 m", Dimension::Velocity).unwrap();
    assert!(q.height && q.number.exact() == collide::values::rational::int(0));
    assert!(parse("height -1 m", Dimension::Velocity).is_err());
    // --energy-unit converts from the case's energy unit, so it needs units on the masses
    // and on the velocities: either missing is refused.
    let j = energy_unit("J").unwrap();
    for (mass, velocity) in [(Some("kg"), None), (None, Some("m/s")), (None, None)] {
        let units = Units {
            mass,
            velocity,
            energy_as: None,
        };
        assert_eq!(
            units.with_energy_unit(j),
            Err(EnergyUnitError::NoUnits("J"))
        );
    }
    let units = Units {
        mass: Some("kg"),
        velocity: Some("km/h"),
        energy_as: None,
    };
    // 1 kg (km/h)^2 = (1/3.6)^2 J = 25/324 J.
    let scale = units.with_energy_unit(j).unwrap().energy_scale().unwrap();
    assert_eq!(scale, collide::values::rational::ratio(25, 324));
}

/// An energy released typed with a unit (`--released '48 J'`) is converted into the case's
/// energy unit (mass unit x velocity unit^2): 1 kg and 2 kg pushed apart from rest by 48 J move
/// at -8 and 4 m/s (momentum 0, 1/2 (1) 64 + 1/2 (2) 16 = 48), printed in the velocities'
/// unit: -800 and 400 cm/s with masses in grams, -28.8 and 14.4 km/h; 0.048 kJ is the same.
#[test]
fn an_energy_released_with_a_unit_is_converted_to_the_case_units() {
    for (m, v, released, want) in [
        (
            "1000 g,2000 g",
            "0 cm/s,0 cm/s",
            "48 J",
            "f1 = -800 cm/s, f2 = 400 cm/s",
        ),
        (
            "1 kg,2 kg",
            "0 km/h,0 km/h",
            "48 J",
            "f1 = -28.8 km/h, f2 = 14.4 km/h",
        ),
        (
            "1 kg,2 kg",
            "0 km/h,0 km/h",
            "0.048 kJ",
            "f1 = -28.8 km/h, f2 = 14.4 km/h",
        ),
    ] {
        let out = common::collide()
            .args(["solve", "-m", m, "-v", v, "--released", released])
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success(),
            "{m} {v} {released}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(
            text.contains(&format!("Solved: {want}")),
            "{m} {v} {released}: {text}"
        );
    }
}

/// The impulse's unit is named from the units typed: mass unit x velocity unit, each as typed
/// or described when missing (`--show changes`' header, wrapped for the terminal).
#[test]
fn the_impulse_unit_is_named_from_the_units_typed() {
    for (m, v, want) in [
        ("1 kg,2 kg", "3 m/s,0 m/s", "impulse in kg m/s,"),
        ("1 g,2 g", "3 cm/s,0 cm/s", "impulse in g cm/s,"),
        ("1 kg,2 kg", "3,0", "impulse in kg x velocity unit,"),
        ("1,2", "3 m/s,0 m/s", "impulse in mass unit x m/s,"),
        ("1,2", "3,0", "impulse in mass unit x velocity unit,"),
    ] {
        let out = common::collide()
            .args(["solve", "-m", m, "-v", v, "-e", "1", "--show", "changes"])
            .output()
            .unwrap();
        assert!(out.status.success(), "{m} {v}");
        let text = String::from_utf8_lossy(&out.stdout)
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        assert!(text.contains(want), "{m} {v}: {text}");
    }
}

/// Converting (`--si`, or mixed units such as kg beside g) needs a unit on the masses AND on
/// the velocities: units on one side only are refused by name, exit 2, nothing on stdout.
#[test]
fn converting_needs_units_on_both_sides() {
    for (args, want) in [
        (
            &["-m", "1 kg,2 kg", "-v", "3,0", "--si"][..],
            "--si needs a unit on every mass and velocity",
        ),
        (
            &["-m", "1,2", "-v", "3 m/s,0 m/s", "--si"][..],
            "--si needs a unit on every mass and velocity",
        ),
        (
            &["-m", "1 kg,500 g", "-v", "3,0"][..],
            "mixed units need a unit on every mass and velocity",
        ),
        (
            &["-m", "1,2", "-v", "3 m/s,0 km/h"][..],
            "mixed units need a unit on every mass and velocity",
        ),
    ] {
        let out = common::collide().arg("solve").args(args).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert!(err.contains(want), "{args:?}: {err}");
    }
}

/// Issue 45 §5: a value may be a sum of like quantities (a rider and a bike as one body),
/// with or without spaces, in mixed units, exactly; `1e+3` keeps its meaning; a bad part is
/// named.
#[test]
fn sums_of_like_quantities_are_one_value() {
    use collide::values::rational::{int, ratio};
    use collide::values::units::parse;
    // A 60 kg rider on a 10 kg bike at 5 m/s sticks to a 5 kg cart at rest: the same case as
    // 70 kg, bit for bit, however the sum is written.
    let json = |m: &str, v: &str| {
        common::stdout(&["solve", "-m", m, "-v", v, "-e", "0", "--format", "json"])
    };
    let want = json("70 kg,5 kg", "5 m/s,0");
    for m in [
        "60 kg+10 kg,5 kg",
        "60 kg + 10 kg,5 kg",
        "60kg+10kg,5kg",
        "50 kg + 10 kg + 10 kg,5 kg",
    ] {
        assert_eq!(json(m, "5 m/s,0"), want, "{m}");
    }
    // Velocities too: 3 m/s + 2 m/s is 5 m/s.
    assert_eq!(json("70 kg,5 kg", "3 m/s + 2 m/s,0"), want);
    // Exact: 0.1 + 0.2 is 3/10 (binary64 would give 0.30000000000000004), and mixed units are
    // converted exactly to the first part's: 1 kg + 500 g = 3/2 kg; 1 m + 50 cm = 3/2 m.
    let exact = |text: &str, d: Dimension| {
        let q = parse(text, d).unwrap_or_else(|e| panic!("{text}: {e}"));
        (q.number.exact(), q.unit.map(|u| u.name()))
    };
    assert_eq!(
        exact("0.1 kg + 0.2 kg", Dimension::Mass),
        (ratio(3, 10), Some("kg"))
    );
    assert_eq!(exact("0.1+0.2", Dimension::Mass), (ratio(3, 10), None));
    assert_eq!(
        exact("1 kg + 500 g", Dimension::Mass),
        (ratio(3, 2), Some("kg"))
    );
    assert_eq!(
        exact("1 m + 50 cm", Dimension::Length),
        (ratio(3, 2), Some("m"))
    );
    // An exponent's + is an exponent: 1e+3 g + 1 kg = 1000 g + 1000 g = 2000 g; +4 is 4.
    assert_eq!(
        exact("1e+3 g + 1 kg", Dimension::Mass),
        (int(2000), Some("g"))
    );
    assert_eq!(exact("1e+3", Dimension::Mass), (int(1000), None));
    assert_eq!(exact("+4", Dimension::Mass), (int(4), None));
    // A bad part is named; units on every part or none; a sum has no heights.
    for (text, needles) in [
        ("60 kg + 10 kgg", &["'10 kgg'", "did you mean 'kg'"][..]),
        ("60 kg + abc", &["'abc'"][..]),
        ("60 kg + 10", &["every part of a sum or to none"][..]),
        ("60 kg +", &["its part ''"][..]),
        ("60 kg + 2 m/s", &["'2 m/s'", "velocity"][..]),
    ] {
        let e = parse(text, Dimension::Mass).unwrap_err().to_string();
        for n in needles {
            assert!(e.contains(n), "{text}: {n} in {e}");
        }
    }
    let (code, _, err) = common::run(&["solve", "-m", "60 kg+abc,5 kg", "-v", "5 m/s,0"]);
    assert_eq!(code, 2);
    assert!(err.contains("'abc'"), "{err}");
}

/// `--velocity-unit` (issue 42 section 5): the case is converted exactly to the asked unit
/// before it is solved, so every speed of the report (text, JSON, solved values) is the one
/// solution in that unit.
mod velocity_unit {
    use crate::common::{assert_ulps, run_solve, solve_json, solve_refused};
    use serde_json::json;

    #[test]
    fn a_car_crash_read_in_mi_per_h() {
        // 1500 kg at 72 km/h = 20 m/s onto 900 kg at rest, they stick: 20 1500/2400 = 12.5 m/s.
        // 1 mph = 0.44704 m/s exactly, so 12.5 m/s = 12.5/0.44704 = 78125/2794 mph (=
        // 27.9617036506800...) and 20 m/s = 62500/1397 mph. Energies stay in J: 1/2 1500 20^2
        // = 300000 J before, 1/2 2400 12.5^2 = 187500 J after.
        let args = [
            "-m",
            "1500 kg,900 kg",
            "-v",
            "72 km/h,0",
            "-e",
            "0",
            "--velocity-unit",
            "mi/h",
        ];
        let (code, j) = solve_json(&[&args[..], &["--exact"]].concat());
        assert_eq!(code, 0, "{j}");
        assert_eq!(j["fin"], json!(["78125/2794", "78125/2794"]));
        assert_eq!(j["in"], json!(["62500/1397", "0"]));
        assert_eq!(j["energy"]["in"], "300000");
        assert_eq!(j["energy"]["fin"], "187500");
        assert_eq!(j["units"]["velocity"], "mph");
        let (_, j) = solve_json(&args);
        assert_ulps(
            j["fin"][0].as_f64().unwrap(),
            78125.0 / 2794.0,
            1.0,
            "v' in mph",
        );
        let (_, text, _) = run_solve(&args);
        assert!(
            text.contains("FIN: v1' = v2' = 27.96170365068 mph (the bodies stick)"),
            "{text}"
        );
        assert!(text.contains("velocities in mph, energies in J"), "{text}");
    }

    #[test]
    fn a_solved_speed_is_in_the_asked_unit() {
        // They stick at 20 mph = 32.18688 km/h: v1 = 32.18688 2400/1500 = 51.499008 km/h.
        let (code, j) = solve_json(&[
            "-m",
            "1500 kg,900 kg",
            "-v",
            "?,0",
            "--fin",
            "20 mph,20 mph",
            "--velocity-unit",
            "km/h",
            "--exact",
        ]);
        assert_eq!(code, 0, "{j}");
        // As fractions: 32.18688 = 100584/3125, 51.499008 = 804672/15625.
        assert_eq!(j["solved"]["v1"], "804672/15625");
        assert_eq!(j["fin"], json!(["100584/3125", "100584/3125"]));
    }

    #[test]
    fn speeds_without_units_or_beyond_the_rail_are_refused() {
        solve_refused(
            &["-m", "1500,900", "-v", "72,0", "--velocity-unit", "mph"],
            &["--velocity-unit mph", "72", "no unit"],
        );
        solve_refused(
            &[
                "-m",
                "1 kg,wall",
                "-v",
                "(3,1) m/s,0",
                "--velocity-unit",
                "mph",
            ],
            &["--velocity-unit", "rail"],
        );
        solve_refused(
            &[
                "-m",
                "1 kg,1 kg",
                "-v",
                "3 m/s,0",
                "--velocity-unit",
                "furlong",
            ],
            &["furlong"],
        );
    }
}
