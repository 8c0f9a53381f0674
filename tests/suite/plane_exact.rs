//! The plane's and space's report against exact rational arithmetic on random cases (issue 46
//! item 6): two bodies in the plane and in space, masses from 1e-20 to 5e21, approaching by
//! construction; every velocity, the impulse, V_COM and each energy is the exact value rounded
//! once (0 ulps), the normal parts are correctly rounded (checked by squaring, exactly), the
//! speeds and angles (binary64 `hypot` and `atan2` of the exact values) within 2 ulps; and 3 or
//! 4 bodies that stick (`-e 0`) or explode (`--fin` with one unknown) likewise.

use crate::common;
use crate::plane::{f, impact, json, vecs};

use collide::values::rational::{Q, from_f64, half, int, ratio, to_f64};
use proptest::prelude::*;
use serde_json::Value;
use std::cmp::Ordering;

/// A mass `k 10^a` as typed, its binary64 value exactly, and the typed decimal exactly.
fn mass() -> impl Strategy<Value = (String, Q, Q)> {
    (1i64..50, -20i32..=20).prop_map(|(k, a)| {
        let t = format!("{k}e{a}");
        let q = from_f64(t.parse::<f64>().unwrap());
        let typed = t
            .parse::<collide::values::number::Number>()
            .unwrap()
            .exact();
        (t, q, typed)
    })
}

/// A vector of `dim` dyadic components `n / 2^k` (binary64 holds them exactly).
fn vector(dim: usize) -> impl Strategy<Value = Vec<Q>> {
    proptest::collection::vec((-2000i64..2000, 0u32..6), dim)
        .prop_map(|v| v.into_iter().map(|(n, k)| ratio(n, 1 << k)).collect())
}

fn text(v: &[Q]) -> String {
    let c: Vec<String> = v.iter().map(|x| to_f64(x).unwrap().to_string()).collect();
    format!("({})", c.join(","))
}

fn dot(a: &[Q], b: &[Q]) -> Q {
    a.iter().zip(b).fold(Q::ZERO, |s, (x, y)| s + x * y)
}

fn sub(a: &[Q], b: &[Q]) -> Vec<Q> {
    a.iter().zip(b).map(|(x, y)| x - y).collect()
}

/// `1/2 sum m_i |v_i|^2`.
fn kinetic(m: &[Q], v: &[Vec<Q>]) -> Q {
    m.iter()
        .zip(v)
        .fold(Q::ZERO, |s, (mi, vi)| s + half() * mi * dot(vi, vi))
}

/// `sum m_i v_i` and `sum m_i`.
fn momentum(m: &[Q], v: &[Vec<Q>]) -> (Vec<Q>, Q) {
    let dim = v[0].len();
    let p = (0..dim)
        .map(|k| m.iter().zip(v).fold(Q::ZERO, |s, (mi, vi)| s + mi * &vi[k]))
        .collect();
    (p, m.iter().fold(Q::ZERO, |s, x| s + x))
}

/// `x sqrt(b)` against `a` (`b > 0`), exactly.
fn cmp_root(x: &Q, a: &Q, b: &Q) -> Ordering {
    match (x >= &Q::ZERO, a >= &Q::ZERO) {
        (true, false) => Ordering::Greater,
        (false, true) => Ordering::Less,
        (true, true) => (x * x * b).cmp(&(a * a)),
        (false, false) => (a * a).cmp(&(x * x * b)),
    }
}

/// Whether `r` is `a / sqrt(b)` correctly rounded: the exact value lies between the midpoints
/// of `r` and its binary64 neighbours.
fn rounds_root(r: f64, a: &Q, b: &Q) -> bool {
    let lo = (from_f64(r) + from_f64(r.next_down())) * half();
    let hi = (from_f64(r) + from_f64(r.next_up())) * half();
    cmp_root(&lo, a, b) != Ordering::Greater && cmp_root(&hi, a, b) != Ordering::Less
}

/// Whether `r` is within `k` ulps of `sqrt(s)` (`s >= 0`): `(r -/+ k ulp)^2` brackets `s`.
fn near_root(r: f64, s: &Q, k: i32) -> bool {
    let ulp = from_f64(r.next_up() - r);
    let (lo, hi) = (
        from_f64(r) - &ulp * int(k.into()),
        from_f64(r) + ulp * int(k.into()),
    );
    (lo <= Q::ZERO || &lo * &lo <= *s) && &hi * &hi >= *s
}

/// `|x - y|` in ulps of `y`.
fn ulps(x: f64, y: f64) -> f64 {
    if x == y {
        return 0.0;
    }
    (x - y).abs() / (y.abs().next_up() - y.abs())
}

/// The angle of `atan2(|a x b|, a.b)` from the exact products rounded once (the velocities
/// here are dyadic and at most 1e44: no product leaves binary64).
fn angle(a: &[Q], b: &[Q]) -> f64 {
    let c2 = if a.len() == 2 {
        let c = &a[0] * &b[1] - &a[1] * &b[0];
        &c * &c
    } else {
        let c = [
            &a[1] * &b[2] - &a[2] * &b[1],
            &a[2] * &b[0] - &a[0] * &b[2],
            &a[0] * &b[1] - &a[1] * &b[0],
        ];
        dot(&c, &c)
    };
    to_f64(&c2)
        .unwrap()
        .sqrt()
        .atan2(to_f64(&dot(a, b)).unwrap())
        .to_degrees()
}

/// Every exact value of the report rounded once: FIN, V_COM and the energies; the crunch is
/// `KE_IN - KE_COM`, or with a line of impact the normal part's, `crunch`.
fn check_common(
    j: &Value,
    m: &[Q],
    vi: &[Vec<Q>],
    vf: &[Vec<Q>],
    crunch: Option<Q>,
) -> Result<(), TestCaseError> {
    let got = vecs(&j["fin"]);
    for (b, v) in vf.iter().enumerate() {
        for (k, x) in v.iter().enumerate() {
            prop_assert_eq!(got[b][k], to_f64(x).unwrap(), "fin {} {}", b, k);
        }
        // The speed: binary64 hypot of the rounded components, within 2 ulps of |v'|.
        let speed = f(&j["fin_speed"][b]);
        prop_assert!(near_root(speed, &dot(v, v), 2), "speed {}: {}", b, speed);
    }
    let (p, total) = momentum(m, vi);
    let com: Vec<Q> = p.iter().map(|x| x / &total).collect();
    for (k, x) in com.iter().enumerate() {
        prop_assert_eq!(f(&j["v_com"][k]), to_f64(x).unwrap(), "v_com {}", k);
    }
    let (ki, kf) = (kinetic(m, vi), kinetic(m, vf));
    let kc = half() * dot(&p, &p) / &total;
    let lost = &ki - &kf;
    let energies = [
        ("in", ki.clone()),
        ("fin", kf),
        ("com", kc.clone()),
        ("crunch", crunch.unwrap_or(&ki - &kc)),
        if lost < Q::ZERO {
            ("released", -lost)
        } else {
            ("lost", lost)
        },
    ];
    for (key, x) in energies {
        prop_assert_eq!(f(&j["energy"][key]), to_f64(&x).unwrap(), "energy {}", key);
    }
    Ok(())
}

/// Two bodies of masses 1e-20 to 5e21 (ratios to 5e41), dyadic velocities, an integer normal
/// turned around when the bodies separate along it (the relative velocity itself when they
/// slide across it), e = k/4, in the plane or in space.
/// (mass, velocity, normal, 4 e).
type TwoBodies = (Vec<(String, Q, Q)>, Vec<Vec<Q>>, Vec<i64>, i64);

fn two_bodies() -> impl Strategy<Value = TwoBodies> {
    (2usize..4).prop_flat_map(|dim| {
        (
            proptest::collection::vec(mass(), 2),
            proptest::collection::vec(vector(dim), 2),
            proptest::collection::vec(-9i64..10, dim),
            0i64..=4,
        )
    })
}

proptest! {
    #![proptest_config(common::proptest_config(128))]

    /// Two bodies, every value of the report against the impulse form in exact arithmetic.
    #[test]
    fn two_bodies_are_the_exact_form_rounded((ms, mut v, n, e) in two_bodies()) {
        let dim = v[0].len();
        if v[0] == v[1] {
            v[0][0] += int(1);
        }
        let rel = sub(&v[0], &v[1]);
        let mut n: Vec<Q> = n.into_iter().map(int).collect();
        match dot(&n, &rel).cmp(&Q::ZERO) {
            Ordering::Less => n = n.iter().map(|x| -x).collect(),
            Ordering::Equal => n = rel.clone(),
            Ordering::Greater => {}
        }
        prop_assert!(dot(&n, &rel) > Q::ZERO);
        let m: Vec<Q> = ms.iter().map(|x| x.1.clone()).collect();
        let masses: Vec<&str> = ms.iter().map(|x| x.0.as_str()).collect();
        let vel = format!("{},{}", text(&v[0]), text(&v[1]));
        let et = format!("{e}/4");
        let j = json(&["-m", &masses.join(","), "-v", &vel, "--normal", &text(&n), "-e", &et]);
        let fin = impact([m[0].clone(), m[1].clone()], [v[0].clone(), v[1].clone()], &n, &ratio(e, 4));
        let nn = dot(&n, &n);
        let along = dot(&n, &rel);
        let crunch = half() * &m[0] * &m[1] / (&m[0] + &m[1]) * &along * &along / &nn;
        check_common(&j, &m, &v, &fin, Some(crunch))?;
        // The impulse on body 2, m2 (v2' - v2).
        for k in 0..dim {
            let x = &m[1] * (&fin[1][k] - &v[1][k]);
            prop_assert_eq!(f(&j["impulse"][k]), to_f64(&x).unwrap(), "impulse {}", k);
        }
        // The normal parts v.n / |n|, correctly rounded.
        for (key, vs) in [("in", &v), ("fin", &fin.to_vec())] {
            for b in 0..2 {
                let r = f(&j["normal_parts"][key][b]);
                prop_assert!(rounds_root(r, &dot(&vs[b], &n), &nn), "normal part {} {}: {}", key, b, r);
            }
        }
        // Angles: atan2 of the exact dot and cross products, within 2 ulps.
        let between = f(&j["angle_between_deg"]);
        prop_assert!(ulps(between, angle(&fin[0], &fin[1])) <= 2.0, "between {}", between);
        for b in 0..2 {
            let t = f(&j["turned_deg"][b]);
            prop_assert!(ulps(t, angle(&v[b], &fin[b])) <= 2.0, "turned {}: {}", b, t);
            if dim == 2 {
                let a = f(&j["fin_angle_deg"][b]);
                let x = to_f64(&fin[b][0]).unwrap();
                let y = to_f64(&fin[b][1]).unwrap();
                prop_assert!(ulps(a, y.atan2(x).to_degrees()) <= 2.0, "angle {}: {}", b, a);
            }
        }
    }

    /// 3 or 4 bodies that stick (`-e 0`): every FIN is V_COM = P / M rounded once, the energy
    /// lost is the crunch (the masses' binary64 values); and that explode from rest (`--fin` known for all but one body, `?`):
    /// the unknown is `-sum m_i v_i' / m_k`, the energy released `KE_FIN`.
    #[test]
    fn three_or_four_bodies_stick_and_explode(
        (ms, v, unknown) in (2usize..4, 3usize..5).prop_flat_map(|(dim, count)| (
            proptest::collection::vec(mass(), count),
            proptest::collection::vec(vector(dim), count),
            0..count,
        ))
    ) {
        let m: Vec<Q> = ms.iter().map(|x| x.1.clone()).collect();
        let masses: Vec<&str> = ms.iter().map(|x| x.0.as_str()).collect();
        let masses = masses.join(",");
        let vel: Vec<String> = v.iter().map(|x| text(x)).collect();
        let j = json(&["-m", &masses, "-v", &vel.join(","), "-e", "0"]);
        let (p, total) = momentum(&m, &v);
        let com: Vec<Q> = p.iter().map(|x| x / &total).collect();
        check_common(&j, &m, &v, &vec![com; v.len()], None)?;
        prop_assert_eq!(&j["energy"]["lost"], &j["energy"]["crunch"]);
        // The explosion: v_k' = -(sum of the others' m_i v_i') / m_k, a problem with an
        // unknown, so solved from the masses as typed (decimal), not their binary64 values.
        let m: Vec<Q> = ms.iter().map(|x| x.2.clone()).collect();
        let rest: Vec<String> = v.iter().map(|x| text(&vec![Q::ZERO; x.len()])).collect();
        let mut fin_typed = vel.clone();
        fin_typed[unknown] = "?".into();
        let j = json(&["-m", &masses, "-v", &rest.join(","), "--fin", &fin_typed.join(",")]);
        let mut fin = v.clone();
        let others: Vec<Q> = (0..v[0].len())
            .map(|k| (0..v.len()).filter(|i| *i != unknown).fold(Q::ZERO, |s, i| s + &m[i] * &v[i][k]))
            .collect();
        fin[unknown] = others.iter().map(|x| -x / &m[unknown]).collect();
        let zero = vec![vec![Q::ZERO; v[0].len()]; v.len()];
        check_common(&j, &m, &zero, &fin, None)?;
    }
}
