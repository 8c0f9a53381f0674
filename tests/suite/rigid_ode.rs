//! The ODE of friction in space against Routh's exact solution in the plane (issue 46 item 5):
//! random planar impacts of free bodies posed in space with every z zero (the slip keeps its
//! direction, so Routh's piecewise-linear path in exact rationals is the reference). The
//! reported estimate (the difference of the runs at rtol and rtol/100) is not a bound: measured
//! here, the error exceeded it in 193 of 300 cases, all but two below 3.3e-14 (the rounding
//! floor, which the difference does not see), the two others by 1.004x and 1.002x (2.6e-12 and
//! 4.5e-13). The bound docs/rigid.md states, and this test checks in every case, is
//! `2 estimate + 1e-13`.

use collide::rigid::algebra::{Mat, apply, mul, transpose};
use collide::rigid::body::{Body, Mobility, Motion};
use collide::rigid::impact::Problem;
use collide::rigid::jacobian::{Contact, Pair};
use collide::rigid::laws::{Law, Mode, Tangential};
use collide::rigid::slip::Slip;
use collide::values::rational::{Q, from_f64, int, ratio, to_f64};

/// A small deterministic generator (xorshift64*): a number in `(-3, 3)`.
struct Draw(u64);

impl Draw {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let u = (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64;
        6.0 * u - 3.0
    }
}

/// The same impact in the plane (`dim = 2`) and in space (every z zero, the inertia tensor
/// `diag(I, I, I_zz)` with the plane's `I_zz`): the numbers `d` are masses, inertias, centres,
/// velocities, spins, the contact point and normal; the normal is turned around when the
/// contact points separate along it.
fn problem(d: &[f64], dim: usize, mu: f64, e: f64, law: Law) -> Problem {
    let q = from_f64;
    let at = |k: usize| -> Vec<Q> {
        let mut v = vec![q(d[k]), q(d[k + 1])];
        if dim == 3 {
            v.push(Q::ZERO);
        }
        v
    };
    let spin = |k: usize| -> Vec<Q> {
        if dim == 2 {
            vec![q(d[k])]
        } else {
            vec![Q::ZERO, Q::ZERO, q(d[k])]
        }
    };
    let body = |i: usize| -> Body {
        let m = q(d[i].abs() + 0.1);
        let izz = q(d[2 + i].abs() + 0.1);
        let inertia: Mat = if dim == 2 {
            vec![vec![izz]]
        } else {
            let ixx = q(d[4 + i].abs() + 0.1);
            vec![
                vec![ixx.clone(), Q::ZERO, Q::ZERO],
                vec![Q::ZERO, ixx, Q::ZERO],
                vec![Q::ZERO, Q::ZERO, izz],
            ]
        };
        Body::new(
            i + 1,
            Some(m),
            at(6 + 2 * i),
            Mobility::Free {
                inertia: Some(inertia),
            },
            None,
        )
        .unwrap()
    };
    let motions = [
        Motion {
            v: at(10),
            omega: spin(12),
        },
        Motion {
            v: at(13),
            omega: spin(15),
        },
    ];
    let mut pair = Pair {
        bodies: [body(0), body(1)],
        contact: Contact {
            point: at(16),
            normal: at(18),
        },
    };
    let w = pair.relative_velocity(&motions);
    let along = collide::rigid::algebra::dot(&pair.contact.normal, &w);
    if along < Q::ZERO {
        pair.contact.normal = collide::rigid::algebra::neg(&pair.contact.normal);
    }
    Problem {
        pair,
        motions,
        e: q(e),
        law,
        tangential: Tangential::Coulomb(q(mu)),
        approx: false,
        rtol: 1e-10,
        si: false,
    }
}

#[test]
fn the_ode_error_is_within_twice_its_estimate_plus_1e_13_of_routh() {
    let mut draw = Draw(0x0DE5_0046_2026_1126);
    let (mut cases, mut over, mut worst, mut largest) = (0, 0, 0.0f64, 0.0f64);
    let mut compression = 0.0f64;
    let mut beyond = Vec::new();
    let laws = [Law::Poisson, Law::Newton, Law::Stronge];
    let mut drawn = 0;
    while cases < 300 {
        // A draw the plane refuses is drawn again, but at least 90% must solve: a solver that
        // refused everything looped here until the mutation run's time limit (mutants
        // `impact.rs:98`, `:109`). Measured: all 300 of the first 300 draws solve.
        drawn += 1;
        assert!(drawn <= 333, "only {cases} of {drawn} drawn impacts solved");
        let d: Vec<f64> = (0..20).map(|_| draw.next()).collect();
        let (mu, e) = (0.05 + (draw.next() + 3.0) / 3.0, (draw.next() + 3.0) / 6.0);
        let law = laws[cases % 3];
        let Ok(plane) = collide::rigid::solve(problem(&d, 2, mu, e, law)) else {
            continue;
        };
        let space = collide::rigid::solve(problem(&d, 3, mu, e, law)).unwrap();
        let exact = &plane.impact.impulse;
        let got = &space.impact.impulse;
        let size = exact
            .iter()
            .fold(0.0f64, |s, x| s.hypot(to_f64(x).unwrap()));
        let err = (0..2).fold(0.0f64, |s, k| {
            s.hypot(to_f64(&(&got[k] - &exact[k])).unwrap())
        }) / size;
        assert_eq!(to_f64(&got[2]).unwrap(), 0.0);
        let estimate = space.impact.ode.as_ref().unwrap().error;
        // The compression impulse (item 5c) against Routh's exact one.
        let lc = to_f64(&plane.impact.compression).unwrap();
        let c = (to_f64(&space.impact.compression).unwrap() - lc).abs() / lc;
        // Measured: at most 4.4e-12 (relative); allowed 1e-11, as the impulse.
        assert!(c <= 1e-11, "{law:?} mu {mu} e {e}: compression {c:e}");
        compression = compression.max(c);
        if err > 2.0 * estimate + 1e-13 {
            beyond.push(format!(
                "{law:?} mu {mu} e {e}: error {err:e}, estimate {estimate:e}"
            ));
        }
        if err > estimate {
            over += 1;
            worst = worst.max(err / estimate);
        }
        largest = largest.max(err);
        cases += 1;
    }
    eprintln!(
        "{cases} planar cases of {drawn} drawn: the error exceeded the estimate in {over} \
         (at most {worst:.2}x); \
         largest error {largest:.2e}; compression {compression:.2e}"
    );
    assert!(beyond.is_empty(), "{beyond:#?}");
    // The measurement above, as it stands: most cases are at the rounding floor.
    assert!(over > 0 && largest < 1e-11, "{over} {largest}");
}

/// The rotation of the quaternion `(1, 2, 2, 4) / 5`, exact in rationals:
/// `R = [[-15, 0, 20], [16, -15, 12], [12, 20, 9]] / 25` (each row of length 25, `R R^T = 1`).
fn turned() -> Mat {
    let rows = [[-15, 0, 20], [16, -15, 12], [12, 20, 9]];
    rows.iter()
        .map(|r| r.iter().map(|&x| ratio(x, 25)).collect())
        .collect()
}

/// The rotation of the quaternion `(1, 2, 3, 4) / sqrt 30`, exact in rationals:
/// `R = [[-20, 4, 22], [20, -10, 20], [10, 28, 4]] / 30` (each row of length 30). It takes the
/// floor's normal `(0, -1, 0)` to `(-4, 10, -28) / 30`, which has no zero component: the standing
/// contact's first tangent is then the x axis made perpendicular to `n` (`e - (e.n) n`, with
/// `e.n = -2/15`), where the turn above (`n = (0, 3/5, -4/5)`) gives `e.n = 0` and any sign of
/// that product the same answer (mutant `impact.rs:324`, `v - d n` to `v + d n`).
pub(crate) fn turned_oblique() -> Mat {
    let rows = [[-20, 4, 22], [20, -10, 20], [10, 28, 4]];
    rows.iter()
        .map(|r| r.iter().map(|&x| ratio(x, 30)).collect())
        .collect()
}

/// A standing contact pushed sideways (issue 46 item 5d): a body of mass 1 with `I_zz = 1/3`
/// centred at (0, 1) touches the floor at (1/2, 0) moving at `v = (-1, -1)`, `omega = 1`: the
/// contact point moves at `v + omega (-r_y, r_x) = (-1, -1) + (1, 1/2) = (0, -1/2)`, so it does
/// not slip, but `K = 1 + 3 (1, 1/2)(1, 1/2)^T` has `K_tn / K_tt = (3/2) / 4 = 3/8`: the normal
/// impulse pushes the contact sideways, and it sticks for `mu >= 3/8` and slips (one way)
/// below. In the plane (`dim = 2`) Routh's answer is exact; in space (`dim = 3`, `I = diag(1,
/// 1, 1/3)`, every z zero) the ODE starts from a stopped slip; `turn` rotates every vector and
/// the inertia tensor (`R I R^T`) of the space scene.
fn standing(dim: usize, turn: Option<&Mat>, mu: Q, law: Law) -> Problem {
    on_floor(dim, turn, Tangential::Coulomb(mu), law, int(-1))
}

/// The body of [`standing`] on its floor with `tangential` and `v = (vx, -1)`: the contact
/// point moves at `(vx + 1, -1/2)` (sliding at `vx + 1` along x), `K = [[4, 3/2], [3/2, 7/4]]`
/// in (x, y), `K_tn != 0`.
pub(crate) fn on_floor(
    dim: usize,
    turn: Option<&Mat>,
    tangential: Tangential,
    law: Law,
    vx: Q,
) -> Problem {
    let vec3 = |x: Vec<Q>| -> Vec<Q> {
        let mut x = x;
        if dim == 3 {
            x.push(Q::ZERO);
        }
        turn.map_or(x.clone(), |r| apply(r, &x))
    };
    let third = ratio(1, 3);
    let (omega, inertia) = if dim == 2 {
        (vec![int(1)], vec![vec![third]])
    } else {
        let i = vec![
            vec![int(1), Q::ZERO, Q::ZERO],
            vec![Q::ZERO, int(1), Q::ZERO],
            vec![Q::ZERO, Q::ZERO, third],
        ];
        let i = turn.map_or(i.clone(), |r| mul(&mul(r, &i), &transpose(r)));
        let w = vec![Q::ZERO, Q::ZERO, int(1)];
        (turn.map_or(w.clone(), |r| apply(r, &w)), i)
    };
    let rod = Body::new(
        1,
        Some(int(1)),
        vec3(vec![Q::ZERO, int(1)]),
        Mobility::Free {
            inertia: Some(inertia),
        },
        None,
    )
    .unwrap();
    let floor = Body::new(
        2,
        None,
        vec3(vec![Q::ZERO, Q::ZERO]),
        Mobility::Immovable { word: "floor" },
        None,
    )
    .unwrap();
    let rest = Motion {
        v: vec3(vec![Q::ZERO, Q::ZERO]),
        omega: vec![Q::ZERO; if dim == 2 { 1 } else { 3 }],
    };
    Problem {
        pair: Pair {
            bodies: [rod, floor],
            contact: Contact {
                point: vec3(vec![ratio(1, 2), Q::ZERO]),
                normal: vec3(vec![Q::ZERO, int(-1)]),
            },
        },
        motions: [
            Motion {
                v: vec3(vec![vx, int(-1)]),
                omega,
            },
            rest,
        ],
        e: ratio(1, 2),
        law,
        tangential,
        approx: false,
        rtol: 1e-10,
        si: false,
    }
}

/// `|a - b| / |b|` of two impulses.
fn relative(a: &[f64], b: &[f64]) -> f64 {
    let size = b.iter().fold(0.0f64, |s, x| s.hypot(*x));
    a.iter().zip(b).fold(0.0f64, |s, (x, y)| s.hypot(x - y)) / size
}

fn floats(v: &[Q]) -> Vec<f64> {
    v.iter().map(|x| to_f64(x).unwrap()).collect()
}

#[test]
fn a_standing_contact_pushed_sideways_is_routh_in_space_and_turned() {
    // Worst relative error measured over the eighteen cases below: 5.8e-15 (space), 6.1e-15
    // (turned) and 6.1e-15 (turned obliquely); the issue asks for 1e-12, a margin of over 150.
    let (r, r2) = (turned(), turned_oblique());
    let mut worst = [0.0f64; 3];
    for (mu, mode) in [(ratio(1, 2), Mode::Stick), (ratio(1, 5), Mode::Slip)] {
        for law in [Law::Poisson, Law::Newton, Law::Stronge] {
            let plane = collide::rigid::solve(standing(2, None, mu.clone(), law)).unwrap();
            assert_eq!(plane.impact.mode, mode, "{law:?}");
            if law == Law::Poisson {
                // By hand, with w_n = 1/2, K_nn = 7/4, K_tn = 3/2 (sign aside), K_tt = 4.
                // Stick: K_nn - K_tn^2 / K_tt = 19/16, l_c = (1/2) / (19/16) = 8/19, P_n =
                // (3/2) l_c = 12/19, |P_t| = (3/8) P_n = 9/38. Slip (mu = 1/5, the way that
                // K_tn pushes): K_nn - mu K_tn = 29/20, l_c = 10/29, P_n = 15/29, |P_t| = 3/29.
                let (lc, pn, pt) = if mode == Mode::Stick {
                    (ratio(8, 19), ratio(12, 19), ratio(9, 38))
                } else {
                    (ratio(10, 29), ratio(15, 29), ratio(3, 29))
                };
                let p = &plane.impact.impulse;
                let abs = |x: &Q| if *x < Q::ZERO { -x.clone() } else { x.clone() };
                assert_eq!((abs(&p[0]), abs(&p[1])), (pt, pn));
                assert_eq!(plane.impact.compression, lc);
            }
            let mut exact = floats(&plane.impact.impulse);
            exact.push(0.0);
            let lc = to_f64(&plane.impact.compression).unwrap();
            let space = collide::rigid::solve(standing(3, None, mu.clone(), law)).unwrap();
            let rotated = collide::rigid::solve(standing(3, Some(&r), mu.clone(), law)).unwrap();
            let oblique = collide::rigid::solve(standing(3, Some(&r2), mu.clone(), law)).unwrap();
            // The turned scenes' impulses turned back: R^T P.
            let back = apply(&transpose(&r), &rotated.impact.impulse);
            let back2 = apply(&transpose(&r2), &oblique.impact.impulse);
            for (k, (got, o)) in [
                (&space.impact.impulse, &space),
                (&back, &rotated),
                (&back2, &oblique),
            ]
            .into_iter()
            .enumerate()
            {
                assert_eq!(o.impact.mode, mode, "{law:?} {k}");
                let err = relative(&floats(got), &exact);
                assert!(err <= 1e-12, "{law:?} mu {mu}: {k}: {err:e}");
                worst[k] = worst[k].max(err);
                // The compression impulse (item 5c): l_c with |n| = 1.
                let c = to_f64(&o.impact.compression).unwrap();
                assert!((c - lc).abs() <= 1e-12 * lc, "{law:?} {k}: {c} {lc}");
            }
        }
    }
    eprintln!(
        "standing contact: worst relative error {:.2e} (space), {:.2e} (turned), {:.2e} \
         (turned obliquely)",
        worst[0], worst[1], worst[2]
    );
}

#[test]
fn a_sliding_contact_turned_obliquely_is_routh_turned() {
    // The floor case of `standing` with v = (vx, -1): the contact slides at w = (vx + 1, -1/2),
    // so the ODE's first tangent is that slip made perpendicular to n (`unit_perpendicular`'s
    // `across`, d = v.n). Turned by `turned_oblique`, n = (-4, 10, -28)/30 and the slip have no
    // zero component, so every product of d counts (mutant `impact.rs:323`, the second `+` of
    // d to `-`, missed by the standing contact, whose world axis has a single 1).
    // By hand, in (t, n) = ((1, 0), (0, -1)): K_tt = 4, K_nn = 7/4, K_tn = -3/2, w_n = 1/2, and
    // while it slides (s = sign w_t) dw_t/dP_n = -(K_tn + mu K_tt s), dw_n/dP_n = -(K_nn + mu
    // K_tn s). Forward (vx = 0, w_t = 1): mu = 1/5 speeds the slip up (+7/10); mu = 1/2 slows it
    // by 1/2 a unit while compression ends at 1/2 and Poisson's end at 3/4 (slip 5/8 left);
    // mu = 2 stops it at 2/13, and mu >= |K_tn / K_tt| = 3/8 holds it. Back (vx = -2, w_t =
    // -1): mu = 1/5 stops it at 10/23, after Poisson's end at 15/41; mu = 1/2 at 2/7, after
    // compression (1/5), before the end (3/10): it sticks; mu = 2 stops it at 2/19, where w_n =
    // 1/2 - (19/4)(2/19) = 0: the slip stops exactly at compression. (There the ODE's phase
    // after the stop began past w_n = 0 and ran until its state was infinite, before compression
    // was taken within the slip's closing and at a phase's start: `slip/ode.rs`.) Routh's
    // answer in the plane is exact. Worst relative error measured over the 36 runs (flat and
    // turned, 6 cases, 3 laws): 2.1e-14 (the coincident case 1.0e-15); the bound is the
    // standing contact's 1e-12.
    let r = turned_oblique();
    let mut worst = 0.0f64;
    for (vx, mu, mode) in [
        (0, ratio(1, 5), Mode::Slip),
        (0, ratio(1, 2), Mode::Slip),
        (0, int(2), Mode::Stick),
        (-2, ratio(1, 5), Mode::Slip),
        (-2, ratio(1, 2), Mode::Stick),
        (-2, int(2), Mode::Stick),
    ] {
        for law in [Law::Poisson, Law::Newton, Law::Stronge] {
            let case =
                |dim, turn| on_floor(dim, turn, Tangential::Coulomb(mu.clone()), law, int(vx));
            let plane = collide::rigid::solve(case(2, None)).unwrap();
            assert_eq!(plane.impact.mode, mode, "{law:?} vx {vx} mu {mu}");
            let mut exact = floats(&plane.impact.impulse);
            exact.push(0.0);
            for turn in [None, Some(&r)] {
                let o = collide::rigid::solve(case(3, turn))
                    .unwrap_or_else(|e| panic!("{law:?} vx {vx} mu {mu}: {e}"));
                assert_eq!(o.impact.mode, mode, "{law:?} vx {vx} mu {mu}");
                let back = turn.map_or(o.impact.impulse.clone(), |r| {
                    apply(&transpose(r), &o.impact.impulse)
                });
                let err = relative(&floats(&back), &exact);
                assert!(err <= 1e-12, "{law:?} vx {vx} mu {mu}: {err:e}");
                worst = worst.max(err);
            }
        }
    }
    eprintln!("sliding contact: worst relative error {worst:.2e}");
}

/// The slip ODE `dw/dP_n = -K (1, mu s)`, `s = w_t / |w_t|`, `dP_t/dP_n = mu s`, in the contact
/// frame, written again here: the state `(w_n, w_t1, w_t2, P_t1, P_t2)`.
fn slip_rate(k: &[[f64; 3]; 3], mu: f64, y: [f64; 5]) -> [f64; 5] {
    let s = y[1].hypot(y[2]);
    let f = [1.0, mu * y[1] / s, mu * y[2] / s];
    let dw = |r: usize| -(k[r][0] * f[0] + k[r][1] * f[1] + k[r][2] * f[2]);
    [dw(0), dw(1), dw(2), f[1], f[2]]
}

/// One classical fourth-order Runge-Kutta step of length `h`.
fn rk4(k: &[[f64; 3]; 3], mu: f64, y: [f64; 5], h: f64) -> [f64; 5] {
    let at = |y: [f64; 5], d: [f64; 5], c: f64| std::array::from_fn(|i| y[i] + c * d[i]);
    let k1 = slip_rate(k, mu, y);
    let k2 = slip_rate(k, mu, at(y, k1, h / 2.0));
    let k3 = slip_rate(k, mu, at(y, k2, h / 2.0));
    let k4 = slip_rate(k, mu, at(y, k3, h));
    std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
}

/// The reference of the turning slip: RK4 with `n` steps of `1/n` while `w_n > 0`, the last
/// step's length bisected until `w_n` changes sign at adjacent binary64 lengths (the
/// compression `P_c`), then `n` equal steps to Poisson's end `(1 + e) P_c`. Returns `P_c` and
/// the state there.
fn reference(k: &[[f64; 3]; 3], mu: f64, e: f64, w0: [f64; 3], n: usize) -> (f64, [f64; 5]) {
    let mut y = [w0[0], w0[1], w0[2], 0.0, 0.0];
    let mut x = 0.0;
    let h = 1.0 / n as f64;
    while rk4(k, mu, y, h)[0] > 0.0 {
        y = rk4(k, mu, y, h);
        x += h;
    }
    let (mut lo, mut hi) = (0.0, h);
    while lo + (hi - lo) / 2.0 > lo && lo + (hi - lo) / 2.0 < hi {
        let mid = lo + (hi - lo) / 2.0;
        if rk4(k, mu, y, mid)[0] > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    y = rk4(k, mu, y, hi);
    let pc = x + hi;
    let h = e * pc / n as f64;
    for _ in 0..n {
        y = rk4(k, mu, y, h);
    }
    (pc, y)
}

#[test]
fn a_turning_slip_follows_a_fixed_step_rk4_of_the_slip_ode() {
    // K couples the normal to t1 and t1 to t2, and the slip starts along t2 + a bit of t1: the
    // push K_tn (along t1) and the friction (against the slip) turn the slip during the impact (by
    // 23.2 degrees), which slips throughout (mu = 0.3 is too little to stop it), Poisson e
    // = 1/2. The reference: compression where w_n = 0 (a last RK4 step whose length is bisected
    // until w_n changes sign at adjacent binary64 lengths), then RK4 to P_n = 3/2 P_c, 20,000
    // steps each: good to about 1e-13 (the one at 2,000 steps is 8.9e-14 from it).
    // Measured at the default rtol 1e-10: the impulse 4.1e-12 (relative) from the reference,
    // the compression 1.35e-12, the error estimate 1.8e-10 (here the truncation, which the
    // estimate sees, dominates the rounding); the checks allow 1e-11 (a margin of 2.4) and the
    // bound docs/rigid.md states, 2 estimate + 1e-13, at rtol 1e-10 and 1e-12 (there: 8.9e-14,
    // the reference's own level, estimate 4.1e-12).
    let k = [[2.0, 0.8, 0.0], [0.8, 3.0, 0.5], [0.0, 0.5, 2.5]];
    let (mu, e) = (0.3, 0.5);
    let w0 = [1.0, 0.3, 2.0];
    let slip = Slip {
        k,
        w0,
        mu,
        e,
        law: Law::Poisson,
    };
    let (pc, y) = reference(&k, mu, e, w0, 20_000);
    let (pc_coarse, y_coarse) = reference(&k, mu, e, w0, 2_000);
    let reference = [(1.0 + e) * pc, y[3], y[4]];
    // The reference's own error: RK4's falls 10^4-fold from 2,000 to 20,000 steps a phase, so
    // the coarser run's distance is about its error.
    let own = relative(
        &[(1.0 + e) * pc_coarse, y_coarse[3], y_coarse[4]],
        &reference,
    );
    // It truly turns: the angle between the slip before and after.
    let turn = (w0[1] * y[2] - w0[2] * y[1]).atan2(w0[1] * y[1] + w0[2] * y[2]);
    assert!(turn.abs().to_degrees() > 20.0, "{}", turn.to_degrees());

    let got = slip.estimated(1e-10).unwrap();
    assert_eq!((got.run.mode, got.run.stick), (Mode::Slip, None));
    let err = relative(&got.run.impulse, &reference);
    let compression = (got.run.compression - pc).abs() / pc;
    let fine = slip.estimated(1e-12).unwrap();
    let fine_err = relative(&fine.run.impulse, &reference);
    eprintln!(
        "turning slip: turned {:.1} degrees; impulse error {err:.2e}, compression \
         {compression:.2e}, estimate {:.2e}; at rtol 1e-12 {fine_err:.2e}, estimate {:.2e}; \
         the reference's own error {own:.2e}",
        turn.to_degrees(),
        got.error,
        fine.error
    );
    assert!(own <= 1e-13, "{own:e}");
    assert!(err <= 1e-11 && err <= 2.0 * got.error + 1e-13, "{err:e}");
    assert!(compression <= 1e-11, "{compression:e}");
    assert!(fine_err <= 2.0 * fine.error + 1e-13, "{fine_err:e}");
}

/// Small rational cases, where a random float never lands: events that coincide. The floor
/// case of [`on_floor`] sliding at `vx + 1` for vx = -4 to 3 by halves, 13 values of mu from
/// 1/8 to 5, e = 0, 1/4, 1/2, 1, the three laws: 2,340 impacts in space (the ODE) against Routh
/// in the plane (exact), each with its mode and within the bound docs/rigid.md states, `2
/// estimate + 1e-13`. Before the fix in `slip/ode.rs` the 12 at vx = -2, mu = 2 (the slip stops
/// exactly at compression, whatever e) failed ("the state became infinite"). Measured: the
/// largest error 7.3e-12 (a reversing slip at mu = 1/8, within its bound), 0.5 s.
#[test]
fn a_grid_of_small_rational_cases_in_space_is_routh_within_the_bound() {
    let mu_of = [
        (1, 8),
        (1, 5),
        (1, 4),
        (1, 3),
        (3, 8),
        (1, 2),
        (2, 3),
        (3, 4),
        (1, 1),
        (3, 2),
        (2, 1),
        (3, 1),
        (5, 1),
    ];
    let mut cases = 0;
    for vx2 in -8..=6 {
        for &(a, b) in &mu_of {
            for e in [Q::ZERO, ratio(1, 4), ratio(1, 2), int(1)] {
                for law in [Law::Poisson, Law::Newton, Law::Stronge] {
                    let mu = ratio(a, b);
                    let case = |dim| {
                        let tangential = Tangential::Coulomb(mu.clone());
                        let mut p = on_floor(dim, None, tangential, law, ratio(vx2, 2));
                        p.e = e.clone();
                        p
                    };
                    let what = format!("vx {vx2}/2 mu {mu} e {e} {law:?}");
                    let plane = collide::rigid::solve(case(2))
                        .unwrap_or_else(|err| panic!("{what}: plane: {err}"));
                    let space = collide::rigid::solve(case(3))
                        .unwrap_or_else(|err| panic!("{what}: space: {err}"));
                    assert_eq!(space.impact.mode, plane.impact.mode, "{what}");
                    let mut exact = floats(&plane.impact.impulse);
                    exact.push(0.0);
                    let err = relative(&floats(&space.impact.impulse), &exact);
                    let estimate = space.impact.ode.as_ref().map_or(0.0, |o| o.error);
                    assert!(
                        err <= 2.0 * estimate + 1e-13,
                        "{what}: {err:e}, estimate {estimate:e}"
                    );
                    cases += 1;
                }
            }
        }
    }
    assert_eq!(cases, 2340);
}
