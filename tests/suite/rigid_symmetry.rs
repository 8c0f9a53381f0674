//! Rigid bodies at impact under symmetries and on random data: the bodies swapped, a Galilean
//! boost, the scene turned (in the plane and in space), momentum and energy kept to 4 ulps on
//! random frictionless impacts, Stronge's law never gaining energy and Newton's flagged exactly
//! when it does, and the ODE of friction in space against Routh's closed form in the plane.

use crate::common;
use crate::rigid::{f, q, scene};

use collide::rigid::algebra::{self, Mat};
use collide::rigid::body::{Body, Mobility, Motion};
use collide::rigid::impact::Problem;
use collide::rigid::jacobian::{Contact, Pair};
use collide::rigid::laws::{Law, Tangential};
use collide::rigid::outcome::{Energy, Outcome};
use collide::values::rational::{Q, from_f64, int, ratio, to_f64};
use proptest::prelude::*;

/// The planar scene of a spinning disk against a spinning box, exact: bodies in the order
/// asked (the normal turned around when swapped), every velocity boosted by `w`, or the whole
/// scene turned a quarter, `(x, y) -> (-y, x)`.
fn two_bodies(swap: bool, w: [i64; 2], turn: bool, mu: &str) -> String {
    let t = |x: i64, y: i64| if turn { [-y, x] } else { [x, y] };
    let body = |m: i64, p: [i64; 2], v: [i64; 2], omega: i64, shape: &str| {
        format!(
            "[[body]]\nmass = {m}\nposition = [{}, {}]\nvelocity = [{}, {}]\nomega = {omega}\nshape = \"{shape}\"\n",
            p[0],
            p[1],
            v[0] + w[0],
            v[1] + w[1]
        )
    };
    let ball = body(2, t(-1, 2), t(4, -1), 3, "disk 1");
    let target = body(5, t(1, 0), t(0, 0), -1, "box (2,6)");
    let (first, second, sign) = if swap {
        (target, ball, -1)
    } else {
        (ball, target, 1)
    };
    let (c, n) = (t(0, 2), t(1, 0));
    format!(
        "exact = true\n{first}{second}[contact]\npoint = [{}, {}]\nnormal = [{}, {}]\n\
         restitution = \"1/2\"\nfriction = \"{mu}\"\n",
        c[0],
        c[1],
        sign * n[0],
        sign * n[1]
    )
}

#[test]
fn metamorphic_swap_boost_turn() {
    // Swapping the bodies (and turning the normal around) swaps the answer; a Galilean boost w
    // adds w to every final velocity (spins and energy lost unchanged); a quarter turn of the
    // scene turns every vector and keeps every spin (about z, a turn in the plane).
    for mu in ["0", "1/10", "2"] {
        let (_, base) = scene("base", &two_bodies(false, [0, 0], false, mu));
        let (_, swapped) = scene("swapped", &two_bodies(true, [0, 0], false, mu));
        assert_eq!(base["fin"][0], swapped["fin"][1], "mu {mu}");
        assert_eq!(base["fin"][1], swapped["fin"][0], "mu {mu}");
        assert_eq!(base["energy"]["lost"], swapped["energy"]["lost"]);
        assert_eq!(base["contact"], swapped["contact"]);
        let (_, boosted) = scene("boosted", &two_bodies(false, [7, -3], false, mu));
        for b in 0..2 {
            assert_eq!(
                q(&boosted["fin"][b]["v"][0]),
                q(&base["fin"][b]["v"][0]) + int(7)
            );
            assert_eq!(
                q(&boosted["fin"][b]["v"][1]),
                q(&base["fin"][b]["v"][1]) - int(3)
            );
            assert_eq!(boosted["fin"][b]["omega"], base["fin"][b]["omega"]);
        }
        assert_eq!(boosted["energy"]["lost"], base["energy"]["lost"]);
        let (_, turned) = scene("turned", &two_bodies(false, [0, 0], true, mu));
        for b in 0..2 {
            assert_eq!(q(&turned["fin"][b]["v"][0]), -q(&base["fin"][b]["v"][1]));
            assert_eq!(q(&turned["fin"][b]["v"][1]), q(&base["fin"][b]["v"][0]));
            assert_eq!(turned["fin"][b]["omega"], base["fin"][b]["omega"]);
        }
    }
}

/// A free body in the plane or in space: mass, centre, inertia (`None`: a particle).
fn free(i: usize, m: Q, x: Vec<Q>, inertia: Option<Mat>) -> Body {
    Body::new(i, Some(m), x, Mobility::Free { inertia }, None).unwrap()
}

/// A random symmetric positive definite 3x3 tensor `A^T A + 1/10`.
fn spd(a: &[f64]) -> Mat {
    let m: Mat = (0..3)
        .map(|i| (0..3).map(|j| from_f64(a[3 * i + j])).collect())
        .collect();
    let mut t = algebra::mul(&algebra::transpose(&m), &m);
    for (k, row) in t.iter_mut().enumerate() {
        row[k] += ratio(1, 10);
    }
    t
}

/// The outcome's final values as binary64 (the report rounds once), back in exact arithmetic.
fn rounded(o: &Outcome) -> [Motion; 2] {
    let r = |v: &[Q]| -> Vec<Q> { v.iter().map(|x| from_f64(to_f64(x).unwrap())).collect() };
    [0, 1].map(|i| Motion {
        v: r(&o.fin[i].v),
        omega: r(&o.fin[i].omega),
    })
}

/// `|a - b| / scale` in units of binary64's epsilon.
fn ulps(a: &Q, b: &Q, scale: &Q) -> f64 {
    let d = to_f64(&(a - b)).unwrap().abs();
    d / (f64::EPSILON * to_f64(scale).unwrap().abs().max(f64::MIN_POSITIVE))
}

fn random_problem(dim: usize, data: &[f64], e: Q, tangential: Tangential, law: Law) -> Problem {
    let v = |k: usize, n: usize| -> Vec<Q> { (0..n).map(|i| from_f64(data[k + i])).collect() };
    let rot = algebra::rot_dim(dim);
    let inertia = |k: usize| -> Mat {
        if dim == 2 {
            vec![vec![from_f64(data[k].abs() + 0.1)]]
        } else {
            spd(&data[k..k + 9])
        }
    };
    let bodies = [
        free(
            1,
            from_f64(data[0].abs() + 0.1),
            v(2, dim),
            Some(inertia(20)),
        ),
        free(
            2,
            from_f64(data[1].abs() + 0.1),
            v(5, dim),
            Some(inertia(30)),
        ),
    ];
    let motions = [
        Motion {
            v: v(8, dim),
            omega: v(11, rot),
        },
        Motion {
            v: v(14, dim),
            omega: v(17, rot),
        },
    ];
    let pair = Pair {
        bodies,
        contact: Contact {
            point: v(40, dim),
            normal: v(44, dim),
        },
    };
    Problem {
        pair,
        motions,
        e,
        law,
        tangential,
        approx: false,
        rtol: 1e-10,
        si: false,
    }
}

fn data() -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec(-3.0f64..3.0, 48)
}

proptest! {
    #![proptest_config(common::proptest_config(200))]

    /// Frictionless impacts in the plane and in space: linear momentum and angular momentum
    /// (about the contact point; no external impulse) of the rounded FIN agree with IN to 4 ulps
    /// of the momenta's scale, and for e = 1 the energy to 4 ulps: the only error is FIN's
    /// one rounding.
    #[test]
    fn frictionless_impacts_keep_momentum_and_elastic_energy(d in data(), dim in 2usize..4) {
        let p = random_problem(dim, &d, Q::ONE, Tangential::Smooth, Law::Poisson);
        let Ok(o) = collide::rigid::solve(p) else { return Ok(()) };
        let fin = rounded(&o);
        let scale_p = o.bodies().iter().zip(o.v_in()).chain(o.bodies().iter().zip(&fin))
            .map(|(b, m)| b.momentum(m).iter().fold(Q::ZERO, |s, x| s + x.clone() * x))
            .fold(Q::ZERO, |s, x| if x > s { x } else { s });
        let scale_p = from_f64(to_f64(&scale_p).unwrap().sqrt());
        let (pi, pf) = (o.momentum(o.v_in()), o.momentum(&fin));
        for k in 0..dim {
            prop_assert!(ulps(&pi[k], &pf[k], &scale_p) <= 4.0, "P[{}]", k);
        }
        let c = o.problem.pair.contact.point.clone();
        let (li, lf) = (o.angular(o.v_in(), &c), o.angular(&fin, &c));
        // Angular momentum's scale: |r| |p| + |I omega| with |r| up to a few units.
        let lscale = li.iter().chain(&lf).fold(Q::ZERO, |s, x| s + x.clone() * x);
        let lscale = from_f64(to_f64(&lscale).unwrap().sqrt() + 10.0 * to_f64(&scale_p).unwrap());
        for k in 0..li.len() {
            prop_assert!(ulps(&li[k], &lf[k], &lscale) <= 4.0, "L[{}]", k);
        }
        let (ki, kf) = (o.ke_in(), o.kinetic(&fin));
        prop_assert!(ulps(&ki, &kf, &ki) <= 4.0, "KE {} {}", to_f64(&ki).unwrap(), to_f64(&kf).unwrap());
    }

    /// Stronge's energetic law never creates energy on random frictional impacts in the plane
    /// (exact, Routh) and in space (the ODE, within its error estimate); Newton's law is
    /// flagged exactly when its FIN has more energy than IN.
    #[test]
    fn stronge_never_gains_and_newton_is_flagged(d in data(), mu in 0.05f64..2.0, e in 0.0f64..1.0, dim in 2usize..4) {
        let mu = from_f64(mu);
        let e = from_f64(e);
        let p = random_problem(dim, &d, e.clone(), Tangential::Coulomb(mu.clone()), Law::Stronge);
        if let Ok(o) = collide::rigid::solve(p) {
            prop_assert!(!matches!(o.energy(), Energy::Gained(_)), "{:?}", o.energy());
            prop_assert!(o.paradox().is_none());
        }
        if dim == 2 {
            let p = random_problem(dim, &d, e, Tangential::Coulomb(mu), Law::Newton);
            if let Ok(o) = collide::rigid::solve(p) {
                let gained = o.ke_fin() > o.ke_in();
                prop_assert_eq!(gained, o.paradox().is_some());
                prop_assert_eq!(gained, matches!(o.energy(), Energy::Gained(_)));
            }
        }
    }
}

#[test]
fn the_ode_in_space_agrees_with_routh_in_the_plane() {
    // The same impact as a planar scene (Routh, exact) and as a scene in space with every z
    // zero (the ODE): the slip stays in the plane, so the answers agree to the ODE's accuracy,
    // and the reported error estimate bounds the actual error of the impulse.
    for (mu, law) in [("0.2", "poisson"), ("0.6", "stronge"), ("1.5", "newton")] {
        let plane = format!(
            "[[body]]\nmass = 2\nposition = [-1, 1]\nvelocity = [3, 1]\nomega = 2\ninertia = 1\n\
             [[body]]\nmass = 3\nposition = [1, -1]\nvelocity = [-1, 0]\nomega = -1\ninertia = 2\n\
             [contact]\npoint = [0, 0]\nnormal = [2, 1]\nrestitution = 0.6\nfriction = {mu}\nlaw = \"{law}\"\n"
        );
        let space = format!(
            "[[body]]\nmass = 2\nposition = [-1, 1, 0]\nvelocity = [3, 1, 0]\nomega = [0, 0, 2]\ninertia = [1, 1, 1]\n\
             [[body]]\nmass = 3\nposition = [1, -1, 0]\nvelocity = [-1, 0, 0]\nomega = [0, 0, -1]\ninertia = [2, 2, 2]\n\
             [contact]\npoint = [0, 0, 0]\nnormal = [2, 1, 0]\nrestitution = 0.6\nfriction = {mu}\nlaw = \"{law}\"\n"
        );
        let (_, a) = scene("plane-ode", &plane);
        let (_, b) = scene("space-ode", &space);
        assert_eq!(a["contact"], b["contact"], "mu {mu}");
        let size = f(&a["impulse"]["normal"]).hypot(f(&a["impulse"]["tangential"]));
        let err = (f(&a["impulse"]["vector"][0]) - f(&b["impulse"]["vector"][0]))
            .hypot(f(&a["impulse"]["vector"][1]) - f(&b["impulse"]["vector"][1]))
            / size;
        let estimate = f(&b["ode"]["error_estimate"]);
        assert!(
            err <= estimate.max(1e-13) * 10.0,
            "mu {mu} {law}: error {err}, estimate {estimate}"
        );
        assert!(err < 1e-9, "mu {mu}: {err}");
        assert!(f(&b["ode"]["seconds"]) > 0.0);
        assert_eq!(f(&b["impulse"]["vector"][2]), 0.0);
    }
}

#[test]
fn a_scene_in_space_turns_with_its_axes() {
    // Cycling the axes (x, y, z) -> (y, z, x) of every vector and tensor is a rotation: every
    // final velocity and spin cycles the same way, exactly without friction and to the ODE's
    // accuracy with it (the slip turns: the contact frame is built from other axes).
    let scene_of = |cycle: bool, mu: &str| {
        let c = |v: [&str; 3]| -> String {
            let v = if cycle { [v[2], v[0], v[1]] } else { v };
            format!("[{}, {}, {}]", v[0], v[1], v[2])
        };
        let inertia = if cycle {
            "[[1.5, 0, 0.1], [0, 1, 0.2], [0.1, 0.2, 2]]"
        } else {
            "[[1, 0.2, 0], [0.2, 2, 0.1], [0, 0.1, 1.5]]"
        };
        format!(
            "[[body]]\nmass = 1\nposition = {}\nvelocity = {}\nomega = {}\nshape = \"sphere 1\"\n\
             [[body]]\nmass = 2\nposition = {}\nvelocity = {}\ninertia = {inertia}\n\
             [contact]\npoint = {}\nnormal = {}\nrestitution = 0.7\nfriction = {mu}\nlaw = \"stronge\"\n",
            c(["0", "0", "1"]),
            c(["1", "0.5", "-2"]),
            c(["3", "-1", "2"]),
            c(["0.3", "0.2", "-1"]),
            c(["0", "0", "0"]),
            c(["0", "0", "0"]),
            c(["0", "0", "-1"]),
        )
    };
    for mu in ["0", "0.4"] {
        let (_, a) = scene("axes", &scene_of(false, mu));
        let (_, b) = scene("axes-cycled", &scene_of(true, mu));
        let tol = if mu == "0" { 0.0 } else { 1e-9 };
        for body in 0..2 {
            for key in ["v", "omega"] {
                let x = &a["fin"][body][key];
                let y = &b["fin"][body][key];
                for k in 0..3 {
                    let (p, q) = (f(&x[k]), f(&y[(k + 1) % 3]));
                    assert!(
                        (p - q).abs() <= tol,
                        "mu {mu} body {body} {key}[{k}]: {p} {q}"
                    );
                }
            }
        }
    }
}
