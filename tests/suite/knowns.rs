//! Knowns homework problems give beyond masses, velocities and restitution (issue 27 §1): a
//! bullet passing through a block, an impulse, the energy released, a spring, a pendulum,
//! sliding with friction. Every expected value is exact, derived by hand in the comments from
//! the published problem's numbers; binary64 results are held to `REL` (4 ulps) of them or to
//! the exact value itself when it is a binary64, `--exact` results to the fraction.

use crate::common;

use common::{REL, assert_close, collide};
use serde_json::{Value, json};

/// `collide solve ARGS --format json` (any exit code), with the code.
fn solve_json(args: &[&str]) -> (i32, Value) {
    let out = collide()
        .args([&["solve"], args, &["--format", "json"]].concat())
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    (
        out.status.code().unwrap_or(-1),
        serde_json::from_str(&text).unwrap_or(Value::Null),
    )
}

/// `collide solve ARGS`: code, stdout, stderr.
fn run(args: &[&str]) -> (i32, String, String) {
    common::run(&[&["solve"], args].concat())
}

/// Exit 2, nothing on stdout, and stderr naming each of `needles`.
#[track_caller]
fn refused(args: &[&str], needles: &[&str]) {
    let (code, out, err) = run(args);
    assert_eq!(code, 2, "{args:?}: {err}");
    assert!(out.is_empty(), "{args:?}: {out}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: stderr lacks {n:?}:\n{err}");
    }
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

mod pass_through {
    use super::*;

    #[test]
    fn a_bullet_emerges_at_220_m_s() {
        // H. C. Verma, Concepts of Physics 1, ch. 9: a 0.01 kg bullet at 500 m/s passes through
        // a 2 kg block hung on a 5 m string, which rises 0.1 m (g = 9.8): the block leaves at
        // sqrt(2 9.8 0.1) = sqrt(1.96) = 1.4 m/s, and 0.01 500 = 0.01 f1 + 2 1.4 gives
        // f1 = (5 - 2.8) / 0.01 = 220 m/s (the book's answer). Energy lost in the two:
        // KE_IN = 1/2 0.01 500^2 = 1250; KE_FIN = 1/2 0.01 220^2 + 1/2 2 1.4^2 = 242 + 1.96;
        // lost = 1006.04 = 25151/25 J (by the product: mu = 2/201, (500 - 218.6)(500 + 218.6)
        // = 202214.04, 1/2 (2/201) 202214.04 = 1006.04).
        let args = [
            "-m",
            "0.01 kg,2 kg",
            "-v",
            "500 m/s,0",
            "--fin",
            "?,height 0.1 m",
            "--gravity",
            "9.8",
            "--pass-through",
            "--show",
            "vectors,energy,changes",
        ];
        let (code, j) = solve_json(&[&args[..], &["--exact"]].concat());
        assert_eq!(code, 0, "{j}");
        assert_eq!(j["event"], "pass-through");
        assert_eq!(j["solved"], json!({"f1": "220"}));
        assert_eq!(j["fin"], json!(["220", "7/5"]));
        assert_eq!(j["energy"]["lost"], "25151/25");
        assert_eq!(j["energy"]["in"], "1250");
        assert!(j.get("restitution").is_none(), "never a restitution: {j}");
        assert!(j["energy"].get("released").is_none(), "{j}");
        // The lost energy by the product is KE_IN - KE_FIN, and the bodies' own changes sum
        // to minus it: dKE = (-1008, 1.96).
        assert_eq!(j["changes"]["dke"], json!(["-1008", "49/25"]));
        let (code, j) = solve_json(&args);
        assert_eq!(code, 0);
        assert_close(f(&j["energy"]["lost"]), 1006.04, REL, "lost");
        assert_eq!(f(&j["fin"][0]), 220.0);
        let (_, text, _) = run(&args);
        for needle in [
            "Solved: f1 = 220 m/s",
            "no e (pass-through",
            "body 1 has passed through body 2",
            "lost = 1/2 mu ((V1 - V2)^2 - (f1 - f2)^2)  1006.04",
        ] {
            assert!(text.contains(needle), "{needle}:\n{text}");
        }
        assert!(!text.contains("e = "), "no restitution printed:\n{text}");
    }

    #[test]
    fn published_problems_by_hand() {
        // H. C. Verma ch. 9: 20 g at 300 m/s through a 500 g block that rises 20 cm (g = 10):
        // the block leaves at sqrt(2 10 0.2) = 2 m/s, f1 = (6 - 1) / 0.02 = 250 m/s.
        let (code, j) = solve_json(&[
            "-m",
            "20 g,500 g",
            "-v",
            "300 m/s,0",
            "--fin",
            "?,height 20 cm",
            "--gravity",
            "10",
            "--pass-through",
            "--exact",
        ]);
        assert_eq!((code, &j["solved"]), (0, &json!({"f1": "250"})));
        // Serway & Jewett: a 6.00 g bullet at 896 m/s through a 1.25 kg block, out at 435 m/s:
        // the block leaves at 0.006 (896 - 435) / 1.25 = 2.766 / 1.25 = 1383/625 = 2.2128 m/s.
        let (code, j) = solve_json(&[
            "-m",
            "6.00 g,1.25 kg",
            "-v",
            "896 m/s,0",
            "--fin",
            "435 m/s,?",
            "--pass-through",
            "--exact",
        ]);
        assert_eq!((code, &j["solved"]), (0, &json!({"f2": "1383/625"})));
        // Serway & Jewett: 5.00 g at 400 m/s through a 1.00 kg block that leaves at 1.50 m/s
        // (it then compresses a 900 N/m spring by 5.00 cm): f1 = (2 - 1.5) / 0.005 = 100 m/s;
        // lost 1/2 0.005 (400^2 - 100^2) - 1/2 1.5^2 = 375 - 1.125 = 373.875 = 2991/8 J
        // (published: 374 J). In grams and cm/s the same energy is 2991/8 1e7 g cm^2/s^2.
        let (code, j) = solve_json(&[
            "-m",
            "0.005,1",
            "-v",
            "400,0",
            "--fin",
            "?,1.5",
            "--pass-through",
            "--show",
            "energy",
        ]);
        assert_eq!(code, 0);
        assert_eq!(
            (f(&j["solved"]["f1"]), f(&j["energy"]["lost"])),
            (100.0, 373.875)
        );
        let (_, j) = solve_json(&[
            "-m",
            "5 g,1000 g",
            "-v",
            "40000 cm/s,0",
            "--fin",
            "?,150 cm/s",
            "--pass-through",
            "--show",
            "energy",
        ]);
        assert_eq!(f(&j["energy"]["lost"]), 373.875e7);
        assert_eq!(f(&j["solved"]["f1"]), 10000.0);
    }

    #[test]
    fn typed_block_first_the_bullet_is_body_2() {
        // The Serway problem with the block typed first: the same numbers swapped, and body 2
        // has passed through body 1 (which is now on the left: no `left` key).
        let (code, j) = solve_json(&[
            "-m",
            "1,0.005",
            "-v",
            "0,400",
            "--fin",
            "1.5,?",
            "--pass-through",
            "--show",
            "vectors,energy",
        ]);
        assert_eq!(code, 0);
        assert_eq!(j["fin"], json!([1.5, 100.0]));
        assert_eq!(f(&j["energy"]["lost"]), 373.875);
        assert!(j.get("left").is_none(), "{j}");
        let (_, text, _) = run(&[
            "-m",
            "1,0.005",
            "-v",
            "0,400",
            "--fin",
            "1.5,?",
            "--pass-through",
        ]);
        assert!(text.contains("body 2 has passed through body 1"), "{text}");
        // Everything given: momentum is checked (0.005 400 = 0.005 100 + 1.5).
        let (code, j) = solve_json(&[
            "-m",
            "0.005,1",
            "-v",
            "400,0",
            "--fin",
            "100,1.5",
            "--pass-through",
        ]);
        assert_eq!((code, &j["check"]), (0, &json!({"momentum": 0.0})));
    }

    #[test]
    fn what_is_not_a_pass_through_is_refused() {
        let base = ["-m", "1,1", "-v", "4,0", "--pass-through"];
        let with = |fin: &'static str| [&base[..], &["--fin", fin]].concat();
        // Bounced back (f1 = 1, f2 = 3: e = 1/2): not through.
        refused(
            &with("1,?"),
            &["does not come out ahead", "e = 1/2", "--pass-through"],
        );
        // Out faster relative to the block than it went in: energy from nowhere.
        refused(
            &with("5,?"),
            &["|f1 - f2| = 6 > |v1 - v2| = 4", "create kinetic energy"],
        );
        // Momentum alone fixes one unknown.
        refused(&with("?,?"), &["2 unknowns (f1, f2)", "momentum"]);
        // e is no law of a perforation; walls and rigid bodies have no pass-through.
        refused(
            &[&with("3,?")[..], &["-e", "0.5"]].concat(),
            &["--pass-through"],
        );
        refused(
            &[
                "-m",
                "wall,1",
                "-v",
                "0,-4",
                "--fin",
                "0,?",
                "--pass-through",
            ],
            &["--pass-through", "wall"],
        );
        refused(
            &[
                "-m",
                "1,1",
                "-v",
                "4,0",
                "--fin",
                "3,?",
                "--pass-through",
                "--friction",
                "0.2",
            ],
            &["--pass-through", "rail"],
        );
        refused(
            &[
                "-m",
                "1,1",
                "-v",
                "4,0",
                "--fin",
                "3,?",
                "--pass-through",
                "--frame",
                "com",
            ],
            &["--frame", "passes through"],
        );
        refused(
            &["-m", "1,1", "-v", "4,4", "--fin", "3,?", "--pass-through"],
            &["never meet"],
        );
    }
}

mod impulse {
    use super::*;

    #[test]
    fn the_impulse_on_a_has_magnitude_12_m_u() {
        // A-level style (units m = 1, u = 1): A (3m) at 6u hits B (2m) at rest, and the impulse
        // on A has magnitude 12mu, so on B it is +12: f2 = 0 + 12/2 = 6, f1 = 6 - 12/3 = 2,
        // e = (6 - 2)/(6 - 0) = 2/3. KE 54 -> 1/2 3 4 + 1/2 2 36 = 42: 12 lost
        // (= (1 - 4/9) 21.6, the crunch 1/2 (6/5) 36).
        let (code, j) = solve_json(&["-m", "3,2", "-v", "6,0", "--impulse", "12", "--exact"]);
        assert_eq!(code, 0, "{j}");
        assert_eq!(j["solved"], json!({"f1": "2", "f2": "6", "e": "2/3"}));
        assert_eq!(j["energy"]["lost"], "12");
        let (code, j) = solve_json(&["-m", "3,2", "-v", "6,0", "--impulse", "12"]);
        assert_eq!((code, &j["fin"]), (0, &json!([2.0, 6.0])));
        assert_close(f(&j["restitution"]), 2.0 / 3.0, REL, "e");
        // B typed first: the impulse on body 2 (now A) is -12; the same collision swapped.
        let (code, j) = solve_json(&["-m", "2,3", "-v", "0,6", "--impulse", "-12", "--exact"]);
        assert_eq!(code, 0);
        assert_eq!(j["solved"], json!({"f1": "6", "f2": "2", "e": "2/3"}));
        // In grams and cm/s, 12 N s is 1.2e6 g cm/s (1 g cm/s = 1e-5 N s): f = (200, 600) cm/s.
        for j_typed in ["12 N s", "1.2e6 g cm/s", "12 kg*m/s"] {
            let (code, j) = solve_json(&[
                "-m",
                "3000 g,2000 g",
                "-v",
                "600 cm/s,0",
                "--impulse",
                j_typed,
                "--exact",
            ]);
            assert_eq!(code, 0, "{j_typed}");
            assert_eq!(j["solved"], json!({"f1": "200", "f2": "600", "e": "2/3"}));
        }
    }

    #[test]
    fn an_impulse_with_other_knowns() {
        // e given as well: restitution is checked and holds (f2 - f1 = 4 = 2/3 6).
        let (code, j) = solve_json(&["-m", "3,2", "-v", "6,0", "--impulse", "12", "-e", "2/3"]);
        assert_eq!((code, &j["check"]), (0, &json!({"restitution": 0.0})));
        // e = 1/2 contradicts it: f2 - f1 - e (v1 - v2) = 4 - 3 = 1, exit 1.
        let (code, j) = solve_json(&["-m", "3,2", "-v", "6,0", "--impulse", "12", "-e", "0.5"]);
        assert_eq!((code, &j["check"]["restitution"]), (1, &json!(1.0)));
        // A mass unknown, B's final speed given: 12 = m2 (6 - 0), m2 = 2; f1 = 2, e = 2/3.
        let (code, j) = solve_json(&[
            "-m",
            "3,?",
            "-v",
            "6,0",
            "--fin",
            "?,6",
            "--impulse",
            "12",
            "--exact",
        ]);
        assert_eq!(code, 0);
        assert_eq!(j["solved"], json!({"m2": "2", "f1": "2", "e": "2/3"}));
        // From rest (an explosion giving B 12 N s): f2 = 6, f1 = -12/3 = -4; released
        // 1/2 3 16 + 1/2 2 36 = 60 (= 1/2 (6/5) 10^2).
        let (code, j) = solve_json(&[
            "-m",
            "3,2",
            "-v",
            "0,0",
            "--impulse",
            "12",
            "--show",
            "energy",
        ]);
        assert_eq!(code, 0);
        assert_eq!(
            (&j["event"], &j["fin"]),
            (&json!("separation"), &json!([-4.0, 6.0]))
        );
        assert_eq!(f(&j["energy"]["released"]), 60.0);
        // A bullet through a block, the block's impulse given: 1.5 = 1 f2, f1 = 400 - 1.5/0.005.
        let (code, j) = solve_json(&[
            "-m",
            "0.005,1",
            "-v",
            "400,0",
            "--pass-through",
            "--impulse",
            "1.5",
        ]);
        assert_eq!((code, &j["fin"]), (0, &json!([100.0, 1.5])));
        assert_eq!(j["event"], "pass-through");
    }

    #[test]
    fn bad_impulses_are_refused() {
        refused(
            &["-m", "3,2", "-v", "6,0", "--impulse", "12 N"],
            &["--impulse", "unknown unit 'N'"],
        );
        refused(
            &["-m", "3,2", "-v", "6,0", "--impulse", "12 N s"],
            &["--impulse '12 N s' has a unit"],
        );
        refused(
            &["-m", "3,2", "-v", "6,0", "--impulse", "twelve"],
            &["--impulse"],
        );
        // The wrong sign sends the bodies through each other: f2 = -6, f1 = 10, e = -16/6.
        refused(
            &["-m", "3,2", "-v", "6,0", "--impulse", "-12"],
            &["e = -8/3 < 0", "--pass-through"],
        );
        refused(
            &["-m", "wall,2", "-v", "0,-6", "--impulse", "12"],
            &["--impulse", "wall"],
        );
        refused(
            &["-m", "?,?", "-v", "6,0", "--fin", "?,6", "--impulse", "12"],
            &["4 unknowns", "impulse1, impulse2 and restitution"],
        );
    }
}

mod released {
    use super::*;

    /// The `solutions` of a two-way separation's JSON.
    fn solutions(args: &[&str]) -> Vec<Value> {
        let (code, j) = solve_json(args);
        assert_eq!(code, 0, "{args:?}: {j}");
        j["solutions"].as_array().expect("two solutions").clone()
    }

    #[test]
    fn rocket_stages_both_ways() {
        // Cutnell & Johnson 7.51 read backwards: stages of 1200 kg (upper) and 2400 kg at
        // 4900 m/s part with 5.76e8 J (the released energy of the book's answer, 1/2 800 1200^2).
        // mu = 800, |f1 - f2| = sqrt(2 5.76e8 / 800) = 1200; the centre of mass keeps 4900, so
        // f1 = 4900 -+ (2/3) 1200 and f2 = 4900 +- (1/3) 1200: (4100, 5300) with the upper stage
        // behind, (5700, 4500) with it ahead (the book's 5700 and 4500 m/s).
        let args = [
            "-m",
            "1200 kg,2400 kg",
            "-v",
            "4900 m/s,4900 m/s",
            "--fin",
            "?,?",
            "--released",
            "5.76e8 J",
            "--show",
            "energy",
        ];
        let s = solutions(&[&args[..], &["--exact"]].concat());
        assert_eq!(s.len(), 2);
        assert_eq!(s[0]["solved"], json!({"f1": "4100", "f2": "5300"}));
        assert_eq!(s[1]["solved"], json!({"f1": "5700", "f2": "4500"}));
        assert!(s[0].get("left").is_none() && s[1]["left"] == 2, "{s:?}");
        for one in &s {
            assert_eq!(one["energy"]["released"], "576000000");
            assert_eq!(one["event"], "separation");
        }
        let (_, text, _) = run(&args);
        for needle in [
            "Two solutions: the energy released fixes the relative speed",
            "Solution 1: body 1 on the left, body 2 on the right (f1 < f2):",
            "Solution 2: body 1 on the right, body 2 on the left (f1 > f2):",
            "Solved: f1 = 5700 m/s, f2 = 4500 m/s",
        ] {
            assert!(text.contains(needle), "{needle}:\n{text}");
        }
        // 7.11e8 J: |f1 - f2| = sqrt(1777500), irrational. In binary64 the energy comes back
        // within a few ulps (710999999.9999999 here), momentum 3600 4900 is kept, and --sig 3
        // prints 711000000.
        let mut other = args;
        other[7] = "7.11e8 J";
        for one in solutions(&other) {
            assert_close(f(&one["energy"]["released"]), 7.11e8, REL, "released");
            let p = 1200.0 * f(&one["fin"][0]) + 2400.0 * f(&one["fin"][1]);
            assert_close(p, 3600.0 * 4900.0, REL, "momentum");
            let d = f(&one["fin"][0]) - f(&one["fin"][1]);
            assert_close(d.abs(), 1777500f64.sqrt(), 2.0 * REL, "|f1 - f2|");
        }
        let text = common::stdout(&[&["--sig", "3", "solve"], &other[..]].concat());
        assert!(
            text.contains("released = 1/2 mu (f1 - f2)^2  711000000"),
            "{text}"
        );
        refused(
            &[&other[..], &["--exact"]].concat(),
            &["--released 7.11e8 J", "sqrt(1777500)", "irrational"],
        );
    }

    #[test]
    fn the_pieces_are_given_48_j() {
        // A 3 kg body at rest splits into 1 kg and 2 kg pieces given 48 J: mu = 2/3,
        // |f1 - f2| = sqrt(96 / (2/3)) = 12, so (-8, 4) or (8, -4) m/s; KE 32 + 16 = 48.
        // The same in kJ and in ft*lbf (48 J = 48 / 1.3558179483314004 ft*lbf).
        for energy in ["48 J", "0.048 kJ"] {
            let s = solutions(&[
                "-m",
                "1 kg,2 kg",
                "-v",
                "0,0 m/s",
                "--fin",
                "?,?",
                "--released",
                energy,
                "--show",
                "changes",
                "--exact",
            ]);
            assert_eq!(s[0]["fin"], json!(["-8", "4"]), "{energy}");
            assert_eq!(s[1]["fin"], json!(["8", "-4"]));
            assert_eq!(s[1]["changes"]["ke_fin"], json!(["32", "16"]));
        }
        // Giancoli 7-?: one piece 1.5 times the other (2 and 3 kg), 7500 J released: the KE
        // splits inversely to the masses, 4500 J and 3000 J, whichever piece goes right.
        for one in solutions(&[
            "-m",
            "2,3",
            "-v",
            "0,0",
            "--fin",
            "?,?",
            "--released",
            "7500",
            "--show",
            "changes",
        ]) {
            let ke = &one["changes"]["ke_fin"];
            assert_close(f(&ke[0]), 4500.0, REL, "KE of the 2 kg piece");
            assert_close(f(&ke[1]), 3000.0, REL, "KE of the 3 kg piece");
        }
    }

    #[test]
    fn one_final_velocity_given_the_energy_is_checked() {
        // f1 = -6 from rest with 2 and 3 kg: f2 = 4; released 1/2 2 36 + 1/2 3 16 = 60.
        let (code, j) = solve_json(&[
            "-m",
            "2,3",
            "-v",
            "0,0",
            "--fin",
            "-6,?",
            "--released",
            "60",
        ]);
        assert_eq!((code, &j["check"]), (0, &json!({"energy": 0.0})));
        assert_eq!(j["solved"]["f2"], 4.0);
        // 50 contradicts it by 10: exit 1, no event printed.
        let (code, j) = solve_json(&[
            "-m",
            "2,3",
            "-v",
            "0,0",
            "--fin",
            "-6,?",
            "--released",
            "50",
        ]);
        assert_eq!(
            (code, &j["check"]["energy"], &j["consistent"]),
            (1, &json!(10.0), &json!(false))
        );
    }

    #[test]
    fn bad_energies_are_refused() {
        let base = ["-m", "2,3", "-v", "0,0", "--fin", "?,?"];
        let with = |e: &'static str| [&base[..], &["--released", e]].concat();
        refused(&with("0"), &["--released '0' must be above 0"]);
        refused(&with("-5 J"), &["--released", "above 0"]);
        refused(&with("48 W"), &["--released '48 W'", "unknown unit 'W'"]);
        refused(&with("48 J"), &["--released '48 J' has a unit"]);
        refused(
            &["-m", "2,3", "-v", "1,0", "--fin", "?,?", "--released", "60"],
            &["--released 60", "start together", "V1 != V2"],
        );
        refused(&[&with("60")[..], &["-e", "0.5"]].concat(), &["--released"]);
        refused(
            &[&with("60")[..], &["--pass-through"]].concat(),
            &["--released"],
        );
    }
}

mod spring {
    use super::*;

    /// `collide solve ARGS --spring K --format json`'s `spring` object.
    fn spring(args: &[&str]) -> Value {
        let (code, j) = solve_json(args);
        assert_eq!(code, 0, "{args:?}: {j}");
        j["spring"].clone()
    }

    #[test]
    fn halliday_blocks_compress_the_spring_a_quarter_metre() {
        // Halliday, Resnick & Walker, ch. 9: block 1 (2.0 kg) at 10 m/s catches block 2
        // (5.0 kg) at 3.0 m/s, which carries a spring of k = 1120 N/m. At closest approach both
        // move at V_COM = 5 m/s and the spring holds the crunch 1/2 (10/7) 7^2 = 35 J:
        // x = sqrt(2 35 / 1120) = sqrt(1/16) = 0.25 m (the book's answer), exactly. The
        // reduced-mass oscillator omega = sqrt(1120 / (10/7)) = 28 rad/s is in contact half a
        // period: t = pi / 28 s.
        let args = [
            "-m",
            "2.0 kg,5.0 kg",
            "-v",
            "10 m/s,3.0 m/s",
            "--spring",
            "1120 N/m",
        ];
        let s = spring(&[&args[..], &["--exact"]].concat());
        assert_eq!(
            (&s["k"], &s["compression"]),
            (&json!("1120"), &json!("1/4"))
        );
        assert!(
            s["contact_time"]
                .as_str()
                .unwrap()
                .starts_with("0.1121997376282069013"),
            "{s}"
        );
        let s = spring(&args);
        assert_eq!(f(&s["compression"]), 0.25);
        assert_close(
            f(&s["contact_time"]),
            std::f64::consts::PI / 28.0,
            REL,
            "pi/28",
        );
        let (_, text, _) = run(&args);
        assert!(
            text.contains("x_max = sqrt(2 crunch / k)  0.25 m"),
            "{text}"
        );
        // The same spring every way the case can be told: block 2 typed first, seen from the
        // COM frame, in grams and cm/s with k in N/cm (11.2 N/cm = 1120 N/m), and plain.
        for other in [
            vec![
                "-m",
                "5.0 kg,2.0 kg",
                "-v",
                "3.0 m/s,10 m/s",
                "--spring",
                "1120 N/m",
            ],
            vec![
                "-m",
                "2.0 kg,5.0 kg",
                "-v",
                "10 m/s,3.0 m/s",
                "--spring",
                "1120 N/m",
                "--frame",
                "com",
            ],
            vec![
                "-m",
                "2000 g,5000 g",
                "-v",
                "1000 cm/s,300 cm/s",
                "--spring",
                "11.2 N/cm",
            ],
            vec!["-m", "2,5", "-v", "10,3", "--spring", "1120"],
        ] {
            let s = spring(&other);
            assert_eq!(f(&s["compression"]), 0.25, "{other:?}");
            assert_close(f(&s["contact_time"]), std::f64::consts::PI / 28.0, REL, "t");
        }
        // 1 lbf/in = 4.4482216152605 / 0.0254 N/m: x = sqrt(70 / k), t = pi sqrt((10/7) / k).
        let k: f64 = 4.4482216152605 / 0.0254;
        let s = spring(&[
            "-m",
            "2 kg,5 kg",
            "-v",
            "10 m/s,3 m/s",
            "--spring",
            "1 lbf/in",
        ]);
        assert_close(
            f(&s["compression"]),
            (70.0 / k).sqrt(),
            2.0 * REL,
            "x in lbf/in",
        );
        assert_close(
            f(&s["contact_time"]),
            std::f64::consts::PI * (10.0 / 7.0 / k).sqrt(),
            2.0 * REL,
            "t in lbf/in",
        );
    }

    #[test]
    fn the_spring_agrees_with_the_contact_model_in_time() {
        // `collide contact` integrates the linear law F = k d through the impact (zeta = 0):
        // its contact lasts pi sqrt(mu / k) and its overlap peaks at sqrt(2 crunch / k), to the
        // integrator's tolerance (1e-10 per step: agreement to 1e-8 here).
        let s = spring(&["-m", "2,5", "-v", "10,3", "--spring", "1120"]);
        let out = common::stdout(&[
            "contact",
            "-m",
            "2,5",
            "-x",
            "0,1",
            "--sizes",
            "1,1",
            "-v",
            "10,3",
            "--stiffness",
            "1120",
            "--zeta",
            "0",
            "--format",
            "json",
        ]);
        let c: Value = serde_json::from_str(&out).unwrap();
        let contact = &c["contacts"][0];
        assert_close(
            f(&contact["duration"]),
            f(&s["contact_time"]),
            1e-8,
            "duration",
        );
        assert_close(
            f(&contact["max_overlap"]),
            f(&s["compression"]),
            1e-8,
            "overlap",
        );
    }

    #[test]
    fn bad_springs_are_refused() {
        let base = ["-m", "2,5", "-v", "10,3"];
        let with = |k: &'static str| [&base[..], &["--spring", k]].concat();
        refused(&with("0"), &["--spring '0' must be above 0"]);
        refused(&with("-3 N/m"), &["--spring '-3 N/m' must be above 0"]);
        refused(&with("3 N"), &["--spring '3 N'", "N/m, kN/m"]);
        refused(
            &["-m", "2,5", "-v", "0,0", "--fin", "1,?", "--spring", "10"],
            &["--spring", "separation"],
        );
        refused(
            &["-m", "wall,5", "-v", "0,-3", "--spring", "10"],
            &["--spring", "wall"],
        );
    }
}

mod pendulum {
    use super::*;

    /// The `pendulum` object of `collide solve ARGS --format json`.
    fn pendulum(args: &[&str]) -> Value {
        let (code, j) = solve_json(args);
        assert_eq!(code, 0, "{args:?}: {j}");
        j["pendulum"].clone()
    }

    #[test]
    fn verma_block_on_a_5_m_string() {
        // H. C. Verma ch. 9 (the bullet that emerges at 220 m/s): the 2 kg block hangs on a
        // 5 m string and rises 0.1 m, so cos(theta) = 1 - 0.1/5 = 0.98: theta =
        // acos(0.98) = 11.4783409545336 degrees, and it moves x = sqrt(h (2L - h)) =
        // sqrt(0.99) = 0.994987437106620 m sideways. Only the block was at rest: it alone swings.
        let args = [
            "-m",
            "0.01 kg,2 kg",
            "-v",
            "500 m/s,0",
            "--fin",
            "?,height 0.1 m",
            "--gravity",
            "9.8",
            "--pass-through",
            "--length",
            "5 m",
        ];
        let p = pendulum(&args);
        let swings = p["swings"].as_array().unwrap();
        assert_eq!((swings.len(), &swings[0]["body"]), (1, &json!(2)));
        assert_close(
            f(&swings[0]["angle_deg"]),
            0.98f64.acos().to_degrees(),
            REL,
            "theta",
        );
        assert_close(f(&swings[0]["horizontal"]), 0.99f64.sqrt(), REL, "x");
        assert!(swings[0].get("slack").is_none());
        let p = pendulum(&[&args[..], &["--exact"]].concat());
        assert_eq!(p["swings"][0]["height"], "1/10");
        assert_eq!((&p["length"], &p["g"]), (&json!("5"), &json!("49/5")));
        // The same swing in centimetres.
        let mut cm = args;
        cm[10] = "500 cm";
        let p = pendulum(&cm);
        assert_close(
            f(&p["swings"][0]["angle_deg"]),
            0.98f64.acos().to_degrees(),
            REL,
            "cm",
        );
    }

    #[test]
    fn ballistic_pendulum_angles_exactly_where_they_are_rational() {
        // A 10 g bullet lodges in a 2 kg block on a 1 m string that rises 20 cm (g = 10): the
        // pair leaves at sqrt(2 10 0.2) = 2 m/s, so v1 = 201 2 / 0.01 = 40200 cm/s = 402 m/s;
        // cos(theta) = 0.8: x = sqrt(0.2 1.8) = 0.6 m exactly, theta = acos(0.8) =
        // 36.869897645844021296855612559093... degrees (the 3-4-5 triangle).
        let args = [
            "-m",
            "10 g,2 kg",
            "-v",
            "?,0",
            "-e",
            "0",
            "--fin",
            "height 20 cm,height 20 cm",
            "--gravity",
            "10",
            "--length",
            "1 m",
            "--exact",
        ];
        let (code, j) = solve_json(&args);
        assert_eq!(code, 0, "{j}");
        assert_eq!(j["solved"]["v1"], "402");
        let s = &j["pendulum"]["swings"][0];
        assert_eq!(s["horizontal"], "3/5");
        assert!(
            s["angle_deg"]
                .as_str()
                .unwrap()
                .starts_with("36.86989764584402129"),
            "{s}"
        );
        // Rising half the string: 60 degrees exactly (cos = 1/2), x = L sqrt(3)/2; to the
        // horizontal (h = L): 90, x = L.
        let p = pendulum(&[
            "-m",
            "1,1",
            "-v",
            "2,0",
            "-e",
            "0",
            "--gravity",
            "10",
            "--length",
            "0.1",
            "--exact",
        ]);
        // V_COM = 1: h = 1/20 = L/2.
        assert_eq!(p["swings"][0]["angle_deg"], "60");
        assert!(
            p["swings"][0]["horizontal"]
                .as_str()
                .unwrap()
                .starts_with("0.0866025403784438646")
        );
        let p = pendulum(&[
            "-m",
            "1,1",
            "-v",
            "2,0",
            "-e",
            "0",
            "--gravity",
            "10",
            "--length",
            "0.05",
            "--exact",
        ]);
        assert_eq!(
            (&p["swings"][0]["angle_deg"], &p["swings"][0]["horizontal"]),
            (&json!("90"), &json!("1/20"))
        );
    }

    #[test]
    fn two_bobs_both_swing_and_the_frame_does_not_matter() {
        // Two bobs on 1 m strings meet at the bottom at 2 and -1 m/s, elastic and equal:
        // they swap, FIN (-1, 2). With g = 10 they rise 0.05 and 0.2 m: cos = 0.95 and 0.8.
        let args = [
            "-m",
            "1,1",
            "-v",
            "2,-1",
            "--gravity",
            "10",
            "--length",
            "1",
        ];
        for frame in ["lab", "com", "rest-in:2"] {
            let p = pendulum(&[&args[..], &["--frame", frame]].concat());
            let s = p["swings"].as_array().unwrap();
            assert_eq!(s.len(), 2, "{frame}");
            assert_close(
                f(&s[0]["angle_deg"]),
                0.95f64.acos().to_degrees(),
                REL,
                "body 1",
            );
            assert_close(
                f(&s[1]["angle_deg"]),
                0.8f64.acos().to_degrees(),
                REL,
                "body 2",
            );
            assert_eq!(f(&s[1]["horizontal"]), 0.6, "{frame}");
        }
        // Higher than the string (g = 10, 5 m/s: h = 1.25 > L = 1): a string goes slack.
        let p = pendulum(&["-m", "1,1", "-v", "5,0", "--gravity", "10", "--length", "1"]);
        assert_eq!(p["swings"][0]["slack"], true);
        let (_, text, _) = run(&["-m", "1,1", "-v", "5,0", "--gravity", "10", "--length", "1"]);
        assert!(text.contains("h > L: a string goes slack"), "{text}");
    }

    #[test]
    fn swings_that_cannot_be_are_refused() {
        // 10 m/s with g = 10: h = 5 m > 2 L = 2 m: over the top.
        refused(
            &[
                "-m",
                "1,1",
                "-v",
                "10,0",
                "--gravity",
                "10",
                "--length",
                "1",
            ],
            &["--length 1 m", "body 2 would rise 5 m", "over the top"],
        );
        refused(
            &["-m", "1,1", "-v", "1,0", "--length", "0"],
            &["--length '0' must be above 0"],
        );
        refused(
            &["-m", "1,1", "-v", "1,0", "--length", "1 kg"],
            &["--length '1 kg'"],
        );
        refused(
            &["-m", "wall,1", "-v", "0,-1", "--length", "1"],
            &["--length", "wall"],
        );
    }
}

mod slides {
    use super::*;

    #[test]
    fn clay_and_bullets_that_slide_to_a_stop() {
        // Serway & Jewett 9.?: a 12.0 g wad of clay sticks to a 100 g block, which slides 7.50 m
        // on a floor with mu = 0.650 (g = 9.8): the pair left at sqrt(2 0.65 9.8 7.5) =
        // sqrt(95.55) m/s, so the clay came at (112/12) sqrt(95.55) = 91.2330349526238 m/s
        // (the book: 91.2 m/s).
        let slide = "slide 7.50 m mu 0.650";
        let fin = format!("{slide},{slide}");
        let (code, j) = solve_json(&[
            "-m",
            "12.0 g,100 g",
            "-v",
            "?,0",
            "-e",
            "0",
            "--fin",
            &fin,
            "--gravity",
            "9.8",
        ]);
        assert_eq!(code, 0, "{j}");
        assert_close(
            f(&j["solved"]["v1"]),
            112.0 / 12.0 * 95.55f64.sqrt(),
            REL,
            "clay",
        );
        // Halliday, Resnick & Walker 9.?: a 4.5 g bullet stops in a 2.4 kg block that slides
        // 1.8 m with mu = 0.20: the block left at sqrt(2 0.2 9.8 1.8) = sqrt(7.056) = 2.656 m/s
        // (the book: 2.7) and the bullet came at (2.4045/0.0045) sqrt(7.056) (the book:
        // 1.4e3 m/s). --show slides gives the 1.8 m back, for both (they move together).
        let slide = "slide 1.8 m mu 0.20";
        let fin = format!("{slide},{slide}");
        let args = [
            "-m",
            "4.5 g,2.4 kg",
            "-v",
            "?,0",
            "-e",
            "0",
            "--fin",
            &fin,
            "--gravity",
            "9.8",
            "--show",
            "vectors,slides",
            "--friction",
            "0.20",
        ];
        let (code, j) = solve_json(&args);
        assert_eq!(code, 0, "{j}");
        assert_close(
            f(&j["solved"]["v1"]),
            2.4045 / 0.0045 * 7.056f64.sqrt(),
            REL,
            "bullet",
        );
        assert_close(f(&j["fin"][0]), 7.056f64.sqrt(), REL, "block");
        for d in j["slides"]["fin"].as_array().unwrap() {
            assert_close(f(d), 1.8, REL, "slide back");
        }
        let (_, text, _) = run(&args);
        assert!(
            text.contains("FIN  d = f^2 / (2 mu g)  (1.8, 1.8) m"),
            "{text}"
        );
    }

    #[test]
    fn slides_exactly_where_they_are_rational() {
        // g = 10, mu = 0.5, 40 cm: sqrt(2 0.5 10 0.4) = 2 m/s exactly; signed '-slide' is -2.
        let (code, j) = solve_json(&[
            "-m",
            "1,1",
            "-v",
            "slide 40 cm mu 0.5,-slide 0.4 m mu 0.5",
            "--gravity",
            "10",
            "--exact",
        ]);
        assert_eq!((code, &j["in"]), (0, &json!(["2", "-2"])));
        // Pieces from rest, 1 and 2 kg, f1 = -2: f2 = 1; they slide 4/(2 0.5 10) = 2/5 and
        // 1/10 m. In km/h: 36 km/h = 10 m/s slides 100/10 = 10 m.
        let (code, j) = solve_json(&[
            "-m",
            "1,2",
            "-v",
            "0,0",
            "--fin",
            "-2,?",
            "--show",
            "slides",
            "--friction",
            "0.5",
            "--gravity",
            "10",
            "--exact",
        ]);
        assert_eq!(code, 0);
        assert_eq!(
            j["slides"],
            json!({"mu": "1/2", "g": "10", "fin": ["2/5", "1/10"]})
        );
        let (_, j) = solve_json(&[
            "-m",
            "1 kg,1 kg",
            "-v",
            "36 km/h,0",
            "--show",
            "slides",
            "--friction",
            "0.5",
            "--gravity",
            "10",
            "--exact",
        ]);
        // Elastic, equal masses: FIN (0, 36 km/h): body 2 slides 10 m, body 1 stays.
        assert_eq!(j["slides"]["fin"], json!(["0", "10"]));
        // Typed the other way round, the same slides swapped.
        let (_, j) = solve_json(&[
            "-m",
            "1 kg,1 kg",
            "-v",
            "0,36 km/h",
            "--show",
            "slides",
            "--friction",
            "0.5",
            "--gravity",
            "10",
            "--exact",
        ]);
        assert_eq!(j["slides"]["fin"], json!(["10", "0"]));
    }

    #[test]
    fn bad_slides_are_refused() {
        for bad in [
            "slide 5 cm",
            "slide 5 cm mu 0",
            "slide 5 cm mu x",
            "slide -5 cm mu 0.5",
        ] {
            refused(
                &["-m", "1,1", "-v", &format!("{bad},0")],
                &[bad, "slide D mu MU"],
            );
        }
        refused(
            &["-m", "1,1", "-v", "4,0", "--show", "slides"],
            &["--show slides needs --friction"],
        );
        refused(
            &[
                "-m",
                "1,1",
                "-v",
                "4,0",
                "--show",
                "slides",
                "--friction",
                "0",
            ],
            &["--friction 0", "above 0"],
        );
        refused(
            &[
                "-m",
                "1,1",
                "-v",
                "4,0",
                "--show",
                "slides",
                "--friction",
                "0.5",
                "--target",
                "rod 1 m",
            ],
            &["--show slides", "rail"],
        );
        refused(
            &[
                "-m",
                "wall,1",
                "-v",
                "0,-4",
                "--show",
                "slides",
                "--friction",
                "0.5",
            ],
            &["--show slides", "wall"],
        );
        // Without --show slides, --friction is a rigid contact's, as before: it wants a target.
        refused(
            &["-m", "1,1", "-v", "4,0", "--friction", "0.5"],
            &["--target SHAPE"],
        );
    }
}
