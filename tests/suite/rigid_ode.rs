//! The ODE of friction in space against Routh's exact solution in the plane (issue 46 item 5):
//! random planar impacts of free bodies posed in space with every z zero (the slip keeps its
//! direction, so Routh's piecewise-linear path in exact rationals is the reference). The
//! reported estimate (the difference of the runs at rtol and rtol/100) is not a bound: measured
//! here, the error exceeded it in 193 of 300 cases, all but two below 3.3e-14 (the rounding
//! floor, which the difference does not see), the two others by 1.004x and 1.002x (2.6e-12 and
//! 4.5e-13). The bound docs/rigid.md states, and this test checks in every case, is
//! `2 estimate + 1e-13`.

use collide::rigid::algebra::Mat;
use collide::rigid::body::{Body, Mobility, Motion};
use collide::rigid::impact::Problem;
use collide::rigid::jacobian::{Contact, Pair};
use collide::rigid::laws::{Law, Tangential};
use collide::values::rational::{Q, from_f64, to_f64};

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
    let mut beyond = Vec::new();
    let laws = [Law::Poisson, Law::Newton, Law::Stronge];
    while cases < 300 {
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
        "{cases} planar cases: the error exceeded the estimate in {over} (at most {worst:.2}x); \
         largest error {largest:.2e}"
    );
    assert!(beyond.is_empty(), "{beyond:#?}");
    // The measurement above, as it stands: most cases are at the rounding floor.
    assert!(over > 0 && largest < 1e-11, "{over} {largest}");
}
