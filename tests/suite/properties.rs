//! Property tests over wide ranges (proptest), and a no-panic harness: no input to the number,
//! mass, velocity, restitution or tensor parsers, nor any scene text, can panic.

use crate::common;

use std::path::Path;

use collide::accuracy::{Method, Reference, case, errors, solve, ulps};
use collide::case::{parse_inertia, parse_masses, parse_velocities};
use collide::collision::Collision;
use collide::number::Number;
use collide::quantity::from_f64;
use collide::restitution::Restitution;
use collide::scene::Scene;
use collide::solver::Solver;
use collide::solver::binary64::Binary64;
use proptest::prelude::*;

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

proptest! {
    #![proptest_config(common::proptest_config(512))]

    /// Axiom 1: u.M.V_FIN = u.M.V_IN, to the rounding of FIN (1 ulp of each term's scale).
    #[test]
    fn momentum_is_conserved(c in any_case()) {
        let m = c.inertia.matrix();
        let (k1, k2) = (m[(0, 0)] + m[(0, 1)], m[(0, 1)] + m[(1, 1)]);
        let fin = c.v_fin();
        let scale = (k1.abs() + k2.abs()) * velocity_scale(&c);
        let p_fin = c.inertia.total_momentum(&fin);
        prop_assert!(within(p_fin, c.total_momentum(), scale, 2.0), "{p_fin} vs {}", c.total_momentum());
    }

    /// Sec. 2: 1/2 V_FIN.M.V_FIN = KE_COM + e^2 crunch (the form from the rounded FIN: 2 ulps of
    /// sqrt(KE_IN KE_FIN), as for the forms).
    #[test]
    fn final_energy_is_com_energy_plus_e_squared_crunch(c in any_case()) {
        let s = Binary64::lab(&c);
        let fin = c.v_fin();
        let direct = 0.5 * c.inertia.form(&fin, &fin);
        let scale = s.ke_in().sqrt() * s.ke_fin().sqrt();
        prop_assert!(within(direct, s.ke_fin(), scale, 3.0), "{direct} vs {}", s.ke_fin());
        // And KE_IN = KE_COM + crunch (Koenig) is the quadratic form 1/2 V_IN.M.V_IN computed
        // directly.
        let ke_in = 0.5 * c.inertia.form(&c.v_in, &c.v_in);
        prop_assert!(within(s.ke_in(), ke_in, ke_in, 2.0), "{} vs {ke_in}", s.ke_in());
    }

    /// Swapping the bodies swaps the answer.
    #[test]
    fn swapping_the_bodies_swaps_the_answer(c in any_case()) {
        let m = c.inertia.matrix();
        let s = case([[m[(1, 1)], m[(0, 1)]], [m[(0, 1)], m[(0, 0)]]], [c.v_in.y, c.v_in.x], c.restitution.value()).unwrap();
        let (f, g) = (c.v_fin(), s.v_fin());
        let scale = velocity_scale(&c);
        prop_assert!(within(g.x, f.y, scale, 1.0) && within(g.y, f.x, scale, 1.0), "{f:?} vs {g:?}");
        let (s, c) = (Binary64::lab(&s), Binary64::lab(&c));
        prop_assert_eq!(s.crunch(), c.crunch());
        // Either both are a real result, or both are refused (NaN: below binary64's normal
        // range, as KE_COM = 1/2 (m1 v1)^2 / (m1 + m2) is for m1 = 1e-137, m2 = 1e8, v1 = 1e-13).
        let both_refused = s.ke_fin().is_nan() && c.ke_fin().is_nan();
        prop_assert!(both_refused || within(s.ke_fin(), c.ke_fin(), c.ke_fin(), 1.0),
                     "{} vs {}", s.ke_fin(), c.ke_fin());
    }

    /// Sec. 4: a Galilean boost changes no crunch energy. Velocities on a 2^-20 grid and boosts
    /// up to 2^50 keep the boosted inputs exact, so the crunch must be identical to the bit.
    #[test]
    fn crunch_is_the_same_in_every_frame(c in any_case(), v1 in -(1i64 << 30)..(1i64 << 30),
                                         v2 in -(1i64 << 30)..(1i64 << 30), w in -(1i64 << 50)..(1i64 << 50)) {
        let g = 2f64.powi(-20);
        let m = c.inertia.matrix();
        let mm = [[m[(0, 0)], m[(0, 1)]], [m[(1, 0)], m[(1, 1)]]];
        let e = c.restitution.value();
        let lab = case(mm, [v1 as f64 * g, v2 as f64 * g], e).unwrap();
        let moving = case(mm, [(v1 + w) as f64 * g, (v2 + w) as f64 * g], e).unwrap();
        let (lab, moving) = (Binary64::lab(&lab), Binary64::lab(&moving));
        prop_assert_eq!(lab.crunch(), moving.crunch());
        prop_assert_eq!(lab.lost(), moving.lost());
    }

    /// Time-reversal symmetry: the elastic FIN of FIN is IN, to the rounding of the first FIN
    /// (half an ulp) amplified by the second collision, whose map `V -> 2 V_COM u - V` has gain
    /// at most `1 + 2 (|w1| + |w2|)` (1 for a diagonal tensor, large for an ill-conditioned one),
    /// plus its own rounding.
    #[test]
    fn elastic_fin_of_fin_is_in(c in any_case()) {
        let m = c.inertia.matrix();
        let mm = [[m[(0, 0)], m[(0, 1)]], [m[(1, 0)], m[(1, 1)]]];
        let fin = case(mm, [c.v_in.x, c.v_in.y], 1.0).unwrap().v_fin();
        let back = case(mm, [fin.x, fin.y], 1.0).unwrap().v_fin();
        let scale = velocity_scale(&c).max(fin.x.abs()).max(fin.y.abs());
        let (w1, w2) = c.inertia.weights();
        let bound = 1.0 + 0.5 * (1.0 + 2.0 * (w1.abs() + w2.abs()));
        prop_assert!(within(back.x, c.v_in.x, scale, bound) && within(back.y, c.v_in.y, scale, bound),
                     "IN {:?} -> FIN {fin:?} -> {back:?}", c.v_in);
    }

    /// The default solver agrees with exact arithmetic within the stated bound.
    #[test]
    fn impulse_agrees_with_exact(c in any_case()) {
        let e = errors(&solve(Method::Impulse, &c), &Reference::of(&c));
        prop_assert!(e.fin <= 1.0 && e.crunch <= 1.0 && e.lost <= 1.0, "{e:?}");
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
            for d in [collide::units::Dimension::Mass, collide::units::Dimension::Velocity] {
                let _ = collide::units::parse(text, d);
                let _ = collide::units::parse_pair(text, d, "values");
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
        if let Ok(scene) = Scene::parse(Path::new("fuzz.toml"), &text) {
            let _ = collide::report::Report::build(
                &Binary64::new(&scene.case.collision, &scene.frame),
                &scene.sections_needed(),
            );
        }
    }
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
        use collide::units::{Dimension, parse, parse_pair, seconds, energy_unit};
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
        // As a scene field, quoted (units, words) and bare.
        let quoted = text.replace('\\', "\\\\").replace('"', "\\\"").replace('\n', "\\n");
        for field in [format!("\"{quoted}\""), text.clone()] {
            for key in ["masses = [{}, 1]", "velocities = [{}, 1]", "restitution = {}", "gravity = {}"] {
                let line = key.replace("{}", &field);
                let scene = format!("{line}\nmasses = [4, 1]\nvelocities = [60, 10]\n");
                let _ = Scene::parse(Path::new("fuzz.toml"), &scene);
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
            for (_, case) in batch.flatten() {
                prop_assert!(case.v.iter().all(|v| v.is_finite()));
            }
        }
        prop_assert!(start.elapsed().as_secs_f64() < 2.0, "{:?} took {:?}", &text[..text.len().min(40)], start.elapsed());
    }
}
