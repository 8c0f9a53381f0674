//! Property tests over wide ranges (proptest), and a no-panic harness: no input to the number,
//! mass, velocity, restitution or tensor parsers, nor any scene text, can panic.

use crate::common;

use std::path::Path;

use collide::accuracy::{Method, Reference, case, errors, solve, ulps};
use collide::line::case::{parse_inertia, parse_masses, parse_velocities};
use collide::line::collision::Collision;
use collide::line::restitution::Restitution;
use collide::scene::Scene;
use collide::solver::Solver;
use collide::solver::binary64::Binary64;
use collide::values::number::Number;
use collide::values::quantity::{from_f64, to_f64};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// A mass `m * 10^k` with `k` in [-290, 290].
fn mass() -> impl Strategy<Value = f64> {
    (1.0f64..10.0, -290i32..=290).prop_map(|(m, k)| m * 10f64.powi(k))
}

/// A velocity of either sign with magnitude 10^[-100, 100] (or 0).
fn velocity() -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => Just(0.0),
        9 => (-10.0f64..10.0, -100i32..=100).prop_map(|(v, k)| v * 10f64.powi(k)),
    ]
}

fn restitution() -> impl Strategy<Value = f64> {
    prop_oneof![Just(0.0), Just(1.0), 0.0f64..=1.0]
}

/// A diagonal case whose results are all representable: masses and velocities are kept so
/// that `m v^2` stays within binary64.
fn diagonal_case() -> impl Strategy<Value = Collision> {
    (mass(), mass(), velocity(), velocity(), restitution()).prop_filter_map(
        "representable",
        |(m1, m2, v1, v2, e)| {
            let ke = (m1.max(m2)).log10() + 2.0 * v1.abs().max(v2.abs()).max(1e-300).log10();
            let small = (m1.min(m2)).log10() + 2.0 * v1.abs().max(v2.abs()).max(1e-300).log10();
            (ke < 300.0 && small > -300.0)
                .then(|| case([[m1, 0.0], [0.0, m2]], [v1, v2], e))
                .flatten()
        },
    )
}

/// A general symmetric tensor `[[a, c], [c, b]]`, `c = rho sqrt(ab)`, moderate velocities.
fn general_case() -> impl Strategy<Value = Collision> {
    (
        -6i32..=6,
        -6i32..=6,
        1.0f64..10.0,
        1.0f64..10.0,
        -0.999f64..0.999,
        -1e3f64..1e3,
        -1e3f64..1e3,
        restitution(),
    )
        .prop_filter_map("positive definite", |(ka, kb, ma, mb, rho, v1, v2, e)| {
            let (a, b) = (ma * 10f64.powi(ka), mb * 10f64.powi(kb));
            case(
                [[a, rho * (a * b).sqrt()], [rho * (a * b).sqrt(), b]],
                [v1, v2],
                e,
            )
        })
}

fn any_case() -> impl Strategy<Value = Collision> {
    prop_oneof![3 => diagonal_case(), 1 => general_case()]
}

/// `|x - y| <= n` ulps of `scale`.
fn within(x: f64, y: f64, scale: f64, n: f64) -> bool {
    ulps(x, &from_f64(y), scale) <= n
}

fn velocity_scale(c: &Collision) -> f64 {
    let f = c.v_fin();
    [c.v_in.x, c.v_in.y, f.x, f.y, c.v_com()]
        .iter()
        .fold(0.0, |m, v| m.max(v.abs()))
}

/// Axiom 1: u.M.V_FIN = u.M.V_IN, to the rounding of FIN (1 ulp of each term's scale).
fn momentum(c: &Collision) -> Result<(), TestCaseError> {
    let m = c.inertia.matrix();
    let (k1, k2) = (m[(0, 0)] + m[(0, 1)], m[(0, 1)] + m[(1, 1)]);
    let fin = c.v_fin();
    let scale = (k1.abs() + k2.abs()) * velocity_scale(c);
    let p_fin = c.inertia.total_momentum(&fin);
    prop_assert!(
        within(p_fin, c.total_momentum(), scale, 2.0),
        "{p_fin} vs {}",
        c.total_momentum()
    );
    Ok(())
}

/// Sec. 2: 1/2 V_FIN.M.V_FIN = KE_COM + e^2 crunch (the form from the rounded FIN: 2 ulps of
/// sqrt(KE_IN KE_FIN), as for the forms).
fn final_energy(c: &Collision) -> Result<(), TestCaseError> {
    let s = Binary64::lab(c);
    let fin = c.v_fin();
    let direct = 0.5 * c.inertia.form(&fin, &fin);
    let scale = s.ke_in().sqrt() * s.ke_fin().sqrt();
    prop_assert!(
        within(direct, s.ke_fin(), scale, 3.0),
        "{direct} vs {}",
        s.ke_fin()
    );
    // And KE_IN = KE_COM + crunch (Koenig) is the quadratic form 1/2 V_IN.M.V_IN computed
    // directly.
    let ke_in = 0.5 * c.inertia.form(&c.v_in, &c.v_in);
    prop_assert!(
        within(s.ke_in(), ke_in, ke_in, 2.0),
        "{} vs {ke_in}",
        s.ke_in()
    );
    Ok(())
}

/// Swapping the bodies swaps the answer.
fn swap(c: &Collision) -> Result<(), TestCaseError> {
    let m = c.inertia.matrix();
    let s = case(
        [[m[(1, 1)], m[(0, 1)]], [m[(0, 1)], m[(0, 0)]]],
        [c.v_in.y, c.v_in.x],
        c.restitution.value(),
    )
    .unwrap();
    let (f, g) = (c.v_fin(), s.v_fin());
    let scale = velocity_scale(c);
    prop_assert!(
        within(g.x, f.y, scale, 1.0) && within(g.y, f.x, scale, 1.0),
        "{f:?} vs {g:?}"
    );
    let (s, c) = (Binary64::lab(&s), Binary64::lab(c));
    prop_assert_eq!(s.crunch(), c.crunch());
    // Either both are a real result, or both are refused (NaN: below binary64's normal
    // range, as KE_COM = 1/2 (m1 v1)^2 / (m1 + m2) is for m1 = 1e-137, m2 = 1e8, v1 = 1e-13).
    let both_refused = s.ke_fin().is_nan() && c.ke_fin().is_nan();
    prop_assert!(
        both_refused || within(s.ke_fin(), c.ke_fin(), c.ke_fin(), 1.0),
        "{} vs {}",
        s.ke_fin(),
        c.ke_fin()
    );
    Ok(())
}

/// Sec. 4: a Galilean boost changes no crunch energy. Velocities on a 2^-20 grid and boosts
/// up to 2^50 keep the boosted inputs exact, so the crunch must be identical to the bit.
fn boost(c: &Collision, (v1, v2, w): (i64, i64, i64)) -> Result<(), TestCaseError> {
    let g = 2f64.powi(-20);
    let m = c.inertia.matrix();
    let mm = [[m[(0, 0)], m[(0, 1)]], [m[(1, 0)], m[(1, 1)]]];
    let e = c.restitution.value();
    let lab = case(mm, [v1 as f64 * g, v2 as f64 * g], e).unwrap();
    let moving = case(mm, [(v1 + w) as f64 * g, (v2 + w) as f64 * g], e).unwrap();
    let (lab, moving) = (Binary64::lab(&lab), Binary64::lab(&moving));
    prop_assert_eq!(lab.crunch(), moving.crunch());
    prop_assert_eq!(lab.lost(), moving.lost());
    Ok(())
}

/// Time-reversal symmetry: the elastic FIN of FIN is IN, to the rounding of the first FIN
/// (half an ulp) amplified by the second collision, whose map `V -> 2 V_COM u - V` has gain
/// at most `1 + 2 (|w1| + |w2|)` (1 for a diagonal tensor, large for an ill-conditioned one),
/// plus its own rounding.
fn time_reversal(c: &Collision) -> Result<(), TestCaseError> {
    let m = c.inertia.matrix();
    let mm = [[m[(0, 0)], m[(0, 1)]], [m[(1, 0)], m[(1, 1)]]];
    let fin = case(mm, [c.v_in.x, c.v_in.y], 1.0).unwrap().v_fin();
    let back = case(mm, [fin.x, fin.y], 1.0).unwrap().v_fin();
    let scale = velocity_scale(c).max(fin.x.abs()).max(fin.y.abs());
    let (w1, w2) = c.inertia.weights();
    let bound = 1.0 + 0.5 * (1.0 + 2.0 * (w1.abs() + w2.abs()));
    prop_assert!(
        within(back.x, c.v_in.x, scale, bound) && within(back.y, c.v_in.y, scale, bound),
        "IN {:?} -> FIN {fin:?} -> {back:?}",
        c.v_in
    );
    Ok(())
}

/// The default solver is what the README claims, "correctly rounded (worst 0.5 ulp)" against
/// exact rational arithmetic on the same binary64 inputs: FIN within half an ulp of the velocity
/// scale, and the crunch and the energy lost (natural scale: themselves) equal to the exact
/// value rounded to nearest wherever that is a normal number (below, half an ulp of 2^-1022).
fn impulse_exact(c: &Collision) -> Result<(), TestCaseError> {
    let o = solve(Method::Impulse, c);
    let r = Reference::of(c);
    let e = errors(&o, &r);
    prop_assert!(e.fin <= 0.5 && e.crunch <= 0.5 && e.lost <= 0.5, "{e:?}");
    for (got, exact) in [(o.crunch, &r.crunch), (o.lost, &r.lost)] {
        let rounded = to_f64(exact).unwrap();
        if rounded.abs() >= f64::MIN_POSITIVE {
            prop_assert_eq!(got, rounded, "exact {}", exact);
        }
    }
    Ok(())
}

/// Every property of this file on one case.
fn every_property(c: &Collision, grid: (i64, i64, i64)) -> Result<(), TestCaseError> {
    momentum(c)?;
    final_energy(c)?;
    swap(c)?;
    boost(c, grid)?;
    time_reversal(c)?;
    impulse_exact(c)
}

/// The boost test's velocities and boost, on its grid.
fn grid() -> impl Strategy<Value = (i64, i64, i64)> {
    (
        -(1i64 << 30)..(1i64 << 30),
        -(1i64 << 30)..(1i64 << 30),
        -(1i64 << 50)..(1i64 << 50),
    )
}

proptest! {
    #![proptest_config(common::proptest_config(512))]

    #[test]
    fn momentum_is_conserved(c in any_case()) {
        momentum(&c)?;
    }

    #[test]
    fn final_energy_is_com_energy_plus_e_squared_crunch(c in any_case()) {
        final_energy(&c)?;
    }

    #[test]
    fn swapping_the_bodies_swaps_the_answer(c in any_case()) {
        swap(&c)?;
    }

    #[test]
    fn crunch_is_the_same_in_every_frame(c in any_case(), g in grid()) {
        boost(&c, g)?;
    }

    #[test]
    fn elastic_fin_of_fin_is_in(c in any_case()) {
        time_reversal(&c)?;
    }

    #[test]
    fn impulse_agrees_with_exact(c in any_case()) {
        impulse_exact(&c)?;
    }
}

proptest! {
    // The runs above replay the same cases on every run (seed 2026), so a failure is
    // reproducible; this one draws new cases each run (its seed, printed with the failure,
    // replays them through COLLIDE_PROPTEST_SEED), so that CI explores over time.
    #![proptest_config(common::proptest_config_fresh(128))]

    #[test]
    fn every_property_on_cases_no_run_has_seen(c in any_case(), g in grid()) {
        every_property(&c, g)?;
    }
}

proptest! {
    #![proptest_config(common::proptest_config(2000))]

    /// No string makes a parser panic; whatever parses is finite.
    #[test]
    fn parsers_never_panic(s in any::<String>(), t in "[-+0-9eE./, ;a-z?]{0,24}") {
        for text in [&s, &t] {
            if let Ok(n) = text.parse::<Number>() {
                prop_assert!(n.value().is_finite());
                let _ = n.exact();
            }
            let _ = parse_masses(text);
            let _ = parse_velocities(text);
            let _ = parse_inertia(text);
            for d in [collide::values::units::Dimension::Mass, collide::values::units::Dimension::Velocity] {
                let _ = collide::values::units::parse(text, d);
                let _ = collide::values::units::parse_pair(text, d, "values");
            }
            if let Ok(e) = text.parse::<Restitution>() {
                prop_assert!(e.value() >= 0.0 && e.value().is_finite());
            }
        }
    }

    /// No scene text makes the loader panic: random lines from the scene grammar, and noise.
    #[test]
    fn scene_loader_never_panics(
        lines in prop::collection::vec(
            prop_oneof![
                "(masses|velocities|inertia|restitution|show|title|exact|expect|foo) = ",
                "\\[expect\\]",
                "\"?(fin|energy\\.crunch|ellipses\\.in\\.a|in\\.0|x)\"? = ",
            ].prop_flat_map(|key| (Just(key), prop_oneof![
                "\\[[-0-9e./\" ,]{0,16}\\]",
                "\\[\\[[-0-9., ]{0,10}\\], ?\\[[-0-9., ]{0,10}\\]\\]",
                "\"[a-z0-9/.\\-]{0,8}\"",
                "[-0-9.e]{1,8}",
                "\\{ ?value ?= ?[0-9.]{1,4},? ?(abs|rel|tol)? ?=? ?[0-9.e-]{0,5} ?\\}",
                "(true|false|inf|nan)",
            ])).prop_map(|(k, v)| format!("{k}{v}")),
            0..8),
        noise in any::<String>(),
    ) {
        let text = lines.join("\n");
        let _ = Scene::parse(Path::new("fuzz.toml"), &text);
        let _ = Scene::parse(Path::new("fuzz.toml"), &noise);
    }
}

/// The fields of a valid scene (case A), in order, with their values.
const VALID: [(&str, &str); 7] = [
    ("title", "\"Case A\""),
    ("masses", "[4, 1]"),
    ("velocities", "[60, 10]"),
    ("restitution", "1"),
    ("show", "[\"vectors\", \"energy\"]"),
    ("frame", "\"lab\""),
    ("exact", "false"),
];

/// A value for a mass, velocity or restitution: mostly numbers a user types (integers,
/// decimals, fractions, units), some out of range, some not numbers.
fn number_token() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => "[1-9][0-9]{0,2}",
        3 => "[0-9]\\.[0-9]{1,3}",
        2 => "\"[1-9]/[1-9]\"",
        2 => "\"[1-9]{1,2} ?(kg|g|t|lb|m/s|km/h|mph|furlong)\"",
        1 => "-[1-9]",
        1 => Just("0".to_string()),
        1 => "[1-9]e-?[0-9]{1,3}",
        1 => "\"[a-z?]{1,5}\"",
    ]
}

/// A replacement value for field `i` of [`VALID`].
fn field_value(i: usize) -> BoxedStrategy<String> {
    let pair = prop_oneof![
        8 => (number_token(), number_token()).prop_map(|(a, b)| format!("[{a}, {b}]")),
        1 => number_token().prop_map(|a| format!("[{a}]")),
        1 => (number_token(), number_token(), number_token())
            .prop_map(|(a, b, c)| format!("[{a}, {b}, {c}]")),
    ];
    let section = prop::sample::select(vec![
        "vectors",
        "momentum",
        "forms",
        "energy",
        "ellipses",
        "products",
        "changes",
        "heights",
        "diagnostics",
        "all",
        "nothing",
    ]);
    match VALID[i].0 {
        "title" => "\"[ -~&&[^\"\\\\]]{0,30}\"".boxed(),
        "masses" | "velocities" => pair.boxed(),
        "restitution" => prop_oneof![
            4 => number_token(),
            1 => prop::sample::select(vec!["\"elastic\"", "\"inelastic\"", "\"2/3\"", "0.5"])
                .prop_map(String::from),
        ]
        .boxed(),
        "show" => prop::collection::vec(section, 0..4)
            .prop_map(|v| {
                format!(
                    "[{}]",
                    v.iter()
                        .map(|s| format!("\"{s}\""))
                        .collect::<Vec<_>>()
                        .join(", ")
                )
            })
            .boxed(),
        "frame" => prop::sample::select(vec![
            "\"lab\"",
            "\"com\"",
            "\"rest-in:1\"",
            "\"rest-in:2\"",
            "\"rest-fin:1\"",
            "\"rest-fin:2\"",
            "\"25\"",
            "\"-7/2\"",
            "\"rest-in:3\"",
            "\"moon\"",
            "3",
        ])
        .prop_map(String::from)
        .boxed(),
        _ => prop::sample::select(vec!["true", "false", "\"yes\"", "1"])
            .prop_map(String::from)
            .boxed(),
    }
}

/// Case A's scene with field `i` given `value`.
fn scene_with(i: usize, value: &str) -> String {
    VALID
        .iter()
        .enumerate()
        .map(|(j, (key, v))| format!("{key} = {}\n", if j == i { value } else { v }))
        .collect()
}

/// Issue 31: one field of a valid scene changed to a value from its grammar. Every such scene
/// either renders (`collide scene` exits 0 and prints a report) or is refused with exit 2, a
/// message naming the file and located at the field's line (or naming the field), and nothing
/// on stdout; the library decides
/// the same (`Scene::load_any` and the report). At least 40% of the cases render (measured:
/// 63%, 126 of 200), so the branch that renders a changed scene is reached, not dead.
#[test]
fn one_field_changed_in_a_valid_scene_renders_or_is_refused_at_its_line() {
    let dir = std::env::temp_dir().join(format!("collide-mutated-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("scene.toml");
    let (cases, rendered) = (std::cell::Cell::new(0u32), std::cell::Cell::new(0u32));
    let strategy = (0..VALID.len()).prop_flat_map(|i| (Just(i), field_value(i)));
    let mut runner = proptest::test_runner::TestRunner::new(common::proptest_config(200));
    runner
        .run(&strategy, |(i, value)| {
            let text = scene_with(i, &value);
            std::fs::write(&path, &text).unwrap();
            let library = match Scene::load_any(&path) {
                Ok(collide::scene::AnyScene::Case(s)) if !s.exact => {
                    collide::report::Report::build(
                        &Binary64::new(&s.case.collision, &s.frame),
                        &s.sections_needed(),
                    )
                    .map(|_| ())
                    .map_err(|e| e.to_string())
                }
                // A scene the plane reads (three masses, a vector): posed and solved by the
                // library as `collide scene` does.
                Ok(collide::scene::AnyScene::Space(s)) => {
                    s.input.pose().map_err(|e| e.to_string()).and_then(|p| {
                        collide::space::solve::solve(&p.statement)
                            .map(|_| ())
                            .map_err(|e| e.to_string())
                    })
                }
                Ok(_) => Ok(()),
                Err(e) => {
                    // Located on the changed line (line i + 1), or naming the field.
                    let on_line = e.at.is_some_and(|(line, _)| line == i + 1);
                    let stem = &VALID[i].0[..4];
                    let result = e.at.is_none() && e.message.contains("not representable");
                    prop_assert!(on_line || e.message.contains(stem) || result, "{text}: {e}");
                    Err(e.to_string())
                }
            };
            let (code, out, err) = common::run(&["scene", path.to_str().unwrap()]);
            prop_assert!(!err.contains("panicked"), "{text}: {err}");
            prop_assert_eq!(
                code == 0,
                library.is_ok(),
                "{}: {} / {:?}",
                text,
                err,
                library
            );
            if code == 0 {
                prop_assert!(
                    out.contains("V_IN = (") || out.contains("V_IN =") || out.contains("bodies "),
                    "{text}: {out}"
                );
                rendered.set(rendered.get() + 1);
            } else {
                prop_assert_eq!(code, 2, "{}: {}", text, err);
                prop_assert!(
                    out.is_empty() && err.starts_with("error: ") && err.contains("scene.toml"),
                    "{text}: {err}"
                );
            }
            cases.set(cases.get() + 1);
            Ok(())
        })
        .unwrap();
    std::fs::remove_dir_all(&dir).ok();
    let share = f64::from(rendered.get()) / f64::from(cases.get());
    eprintln!(
        "{} of {} changed scenes render ({:.0}%)",
        rendered.get(),
        cases.get(),
        100.0 * share
    );
    assert!(share >= 0.4, "only {share:.2} of the changed scenes render");
}

/// A hostile value: long digit strings, subnormals, huge exponents, fractions with huge parts,
/// control characters, units, words and heights, in bytes that may not be UTF-8.
fn hostile() -> impl Strategy<Value = Vec<u8>> {
    let text = prop_oneof![
        (1usize..12_000, any::<bool>()).prop_map(|(n, dot)| {
            let d = "7".repeat(n);
            if dot { format!("0.{d}") } else { d }
        }),
        prop_oneof![
            Just("4.9e-324"),
            Just("2.4e-324"),
            Just("2.2250738585072011e-308"),
            Just("1e-400"),
            Just("1e400"),
            Just("1e9999/1e10000"),
            Just("1e99999/1e99998"),
            Just("1/0"),
            Just("-0"),
            Just("1e-99999999999999999999"),
            Just("1e+99999999999999999999"),
            Just("wall"),
            Just("inf"),
            Just("NaN"),
            Just("?"),
            Just("height 1e300 km"),
            Just("-height 2 m"),
            Just("height -2 m"),
            Just("∞"),
            Just("2 µs"),
            Just("1e308 km/s"),
        ]
        .prop_map(String::from),
        "[-+0-9eE./ ,;a-z?\u{1b}\u{0}\r\n\t\"'#\\[\\]]{0,40}",
        (1u32..400, 1u32..400).prop_map(|(a, b)| format!("1e{a}/1e-{b}")),
    ];
    (text, any::<Option<u8>>()).prop_map(|(t, byte)| {
        let mut b = t.into_bytes();
        if let Some(x) = byte.filter(|x| *x >= 0x80) {
            // A stray byte that is not UTF-8.
            b.insert(b.len() / 2, x);
        }
        b
    })
}

proptest! {
    #![proptest_config(common::proptest_config(256))]

    /// Issue 13: every parser, scene field and batch column takes a hostile value without a
    /// panic, gives a finite value or an error, and answers within a budget (2 s a value, a hang
    /// guard far above the milliseconds these take, not a speed test).
    #[test]
    fn hostile_values_everywhere(value in hostile()) {
        use collide::values::units::{Dimension, parse, parse_pair, seconds, energy_unit};
        let start = std::time::Instant::now();
        let text = String::from_utf8_lossy(&value).into_owned();
        if let Ok(n) = text.parse::<Number>() {
            prop_assert!(n.value().is_finite());
        }
        for d in [Dimension::Mass, Dimension::Velocity, Dimension::Time, Dimension::Length] {
            if let Ok(q) = parse(&text, d) {
                prop_assert!(q.number.value().is_finite());
            }
            let _ = parse_pair(&format!("{text},1"), d, "values");
        }
        let _ = text.parse::<Restitution>();
        let _ = seconds(&text);
        let _ = energy_unit(&text);
        // As a scene field, quoted (units, words) and bare, in place of the valid value (a second
        // `masses` line would be a duplicate key, refused before the value is read). An error
        // names the field: it is located at the field, or its message says which.
        let quoted = text.replace('\\', "\\\\").replace('"', "\\\"").replace('\n', "\\n");
        for field in [format!("\"{quoted}\""), text.clone()] {
            for (key, line) in [
                ("mass", "masses = [{}, 1]"),
                ("velocit", "velocities = [{}, 1]"),
                ("restitution", "restitution = {}"),
                ("gravity", "gravity = {}"),
            ] {
                let line = line.replace("{}", &field);
                let rest = ["masses = [4, 1]", "velocities = [60, 10]"]
                    .into_iter()
                    .filter(|l| !l.starts_with(&key[..4]))
                    .collect::<Vec<_>>()
                    .join("\n");
                let scene = format!("{line}\n{rest}\n");
                let last_line = 1 + line.matches('\n').count();
                let dir = std::env::temp_dir().join(format!("collide-fuzz-{}", std::process::id()));
                std::fs::create_dir_all(&dir).unwrap();
                let path = dir.join("field.toml");
                std::fs::write(&path, &scene).unwrap();
                if let Err(e) = Scene::load_any(&path) {
                    prop_assert!(!e.message.contains("duplicate key"), "{scene}: {e}");
                    // A value that breaks the TOML syntax (an unclosed quote) is found where
                    // the reader stops: at most the line after the field's.
                    let located = e.at.is_some_and(|(l, _)| l <= last_line + 1);
                    let named = e.message.contains(key)
                        || e.message.contains("not representable");
                    prop_assert!(located || named, "{scene}: {e}");
                }
            }
        }
        // As a batch column, in raw bytes (perhaps not UTF-8).
        let dir = std::env::temp_dir().join(format!("collide-fuzz-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let csv = dir.join("rows.csv");
        let mut bytes = b"m1,m2,v1,v2,e\n".to_vec();
        for col in 0..5 {
            let mut row: Vec<Vec<u8>> = vec![b"4".to_vec(), b"1".to_vec(), b"60".to_vec(), b"10".to_vec(), b"0.5".to_vec()];
            row[col] = value.iter().copied().filter(|b| !matches!(b, b',' | b'\n' | b'\r' | b'"')).collect();
            bytes.extend(row.join(&b','));
            bytes.push(b'\n');
        }
        std::fs::write(&csv, &bytes).unwrap();
        if let Ok(batch) = collide::table::batch::open(Some(&csv), None, 1.0) {
            for (_, case) in batch.on_a_line().flatten() {
                prop_assert!(case.v.iter().all(|v| v.is_finite()));
            }
        }
        prop_assert!(start.elapsed().as_secs_f64() < 2.0, "{:?} took {:?}", &text[..text.len().min(40)], start.elapsed());
    }
}
