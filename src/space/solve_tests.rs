//! Unit tests of `space::solve` (a file of their own: the solver is long enough).

use super::*;
use crate::values::rational::{int, ratio, to_f64};

fn k(n: i64) -> Given<Q> {
    Given::Known(int(n))
}

fn vk(v: &[i64]) -> Velocity {
    Velocity::known(v.iter().map(|x| int(*x)).collect())
}

fn as_q(e: &Exact) -> Q {
    e.rational().clone()
}

/// Bodies that stick: the closed form (`stuck_together`) gives what the elimination gives,
/// solution for solution and check for check, on 3 to 6 bodies in 1 to 3 dimensions with
/// fractional masses and velocities (a fixed pseudo-random sequence); and by hand: masses 1,
/// 2, 3 at (3, 1), (0, 2), (-1, -1/2): P = (3 - 3, 1 + 4 - 3/2) = (0, 7/2), so every body
/// ends at P / 6 = (0, 7/12).
#[test]
fn bodies_that_stick_take_the_closed_form_of_the_elimination() {
    let mut seed = 7u64;
    let mut next = |lo: i64, span: u64| {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        lo + ((seed >> 33) % span) as i64
    };
    for case in 0..40 {
        let (n, dim) = (3 + case % 4, 1 + case % 3);
        let masses = (0..n)
            .map(|_| Given::Known(ratio(next(1, 9), next(1, 4))))
            .collect();
        let v_in = (0..n)
            .map(|_| Velocity::known((0..dim).map(|_| ratio(next(-9, 19), next(1, 5))).collect()))
            .collect();
        let g = Statement {
            dim,
            masses,
            v_in,
            fin: vec![Velocity::unknown(dim); n],
            normal: None,
            e: Some(k(0)),
            inexact: false,
        };
        assert_eq!(solve(&g), solve_with(&g, false), "case {case}");
    }
    let g = Statement {
        dim: 2,
        masses: vec![k(1), k(2), k(3)],
        v_in: vec![
            vk(&[3, 1]),
            vk(&[0, 2]),
            Velocity::known(vec![int(-1), ratio(-1, 2)]),
        ],
        fin: vec![Velocity::unknown(2); 3],
        normal: None,
        e: Some(k(0)),
        inexact: false,
    };
    let s = solve(&g).unwrap();
    for fin in &s.solutions[0].fin {
        assert_eq!(
            fin.iter().map(as_q).collect::<Vec<_>>(),
            [int(0), ratio(7, 12)]
        );
    }
    assert!(
        s.solutions[0]
            .checks
            .iter()
            .all(|c| c.ok && c.residual.is_zero())
    );
}

#[test]
fn smooth_disks_at_45_degrees() {
    // m = 1, 1; v1 = (4, 0), v2 = 0; n = (1, 1): the normal part of v1 is (2, 2), passed
    // to body 2 (equal masses, elastic); the tangential part (2, -2) stays.
    let g = Statement {
        dim: 2,
        masses: vec![k(1), k(1)],
        v_in: vec![vk(&[4, 0]), vk(&[0, 0])],
        fin: vec![Velocity::unknown(2), Velocity::unknown(2)],
        normal: Some(vec![int(1), int(1)]),
        e: None,
        inexact: false,
    };
    let s = solve(&g).unwrap();
    assert_eq!(s.solutions.len(), 1);
    let f = &s.solutions[0].fin;
    assert_eq!(f[0].iter().map(as_q).collect::<Vec<_>>(), [int(2), int(-2)]);
    assert_eq!(f[1].iter().map(as_q).collect::<Vec<_>>(), [int(2), int(2)]);
    assert!(s.solutions[0].checks.iter().all(|c| c.ok));
}

#[test]
fn car_and_van_stick() {
    // physics.md section 7: (9.375, 12.5) m/s.
    let g = Statement {
        dim: 2,
        masses: vec![k(1500), k(2500)],
        v_in: vec![vk(&[25, 0]), vk(&[0, 20])],
        fin: vec![Velocity::unknown(2), Velocity::unknown(2)],
        normal: None,
        e: Some(k(0)),
        inexact: false,
    };
    let s = solve(&g).unwrap();
    let f = &s.solutions[0].fin;
    assert_eq!(as_q(&f[0][0]), ratio(75, 8));
    assert_eq!(as_q(&f[1][1]), ratio(25, 2));
}

#[test]
fn equal_masses_elastic_deflection_has_the_trivial_and_the_90_degree_solution() {
    // v1 = (4, 0) on a body at rest; body 1 leaves along the unit (3/5, 4/5) at an unknown
    // speed s. Energy: 16 = s^2 + |(4,0) - s u|^2 = 16 - 8 s (3/5) + 2 s^2, so s = 0 (no
    // collision: body 1 keeps... nothing, body 2 takes all) or s = 12/5 = 4 cos(53.13 deg);
    // body 2 gets (4, 0) - 12/5 (3/5, 4/5) = (64/25, -48/25), perpendicular to u.
    let g = Statement {
        dim: 2,
        masses: vec![k(1), k(1)],
        v_in: vec![vk(&[4, 0]), vk(&[0, 0])],
        fin: vec![
            Velocity::Speed {
                unit: vec![ratio(3, 5), ratio(4, 5)],
            },
            Velocity::unknown(2),
        ],
        normal: None,
        e: Some(k(1)),
        inexact: false,
    };
    let s = solve(&g).unwrap();
    assert_eq!(s.solutions.len(), 2);
    let mut speeds: Vec<Q> = s
        .solutions
        .iter()
        .map(|x| as_q(&x.fin[0][0]) / ratio(3, 5))
        .collect();
    speeds.sort();
    assert_eq!(speeds, vec![int(0), ratio(12, 5)]);
    let moving = s
        .solutions
        .iter()
        .find(|x| !x.fin[0][0].rational().is_zero())
        .unwrap();
    let f2 = &moving.fin[1];
    assert_eq!(as_q(&f2[0]), int(4) - ratio(36, 25));
    assert_eq!(as_q(&f2[1]), -ratio(48, 25));
}

#[test]
fn too_few_laws_say_how_many_values_are_missing() {
    let g = Statement {
        dim: 2,
        masses: vec![k(1), k(1)],
        v_in: vec![Velocity::unknown(2), vk(&[0, 0])],
        fin: vec![Velocity::unknown(2), Velocity::unknown(2)],
        normal: None,
        e: Some(k(1)),
        inexact: false,
    };
    let e = solve(&g).unwrap_err().to_string();
    assert!(e.contains("6 unknowns"), "{e}");
}

#[test]
fn an_unknown_direction_is_found_on_its_circle() {
    // Equal masses, elastic, body 2 at rest, v1 = (5, 0); body 1 leaves at speed 3 in an
    // unknown direction: body 2's velocity is perpendicular with speed 4, so body 1 leaves
    // at +-acos(3/5) = +-53.13 degrees: (9/5, +-12/5).
    let g = Statement {
        dim: 2,
        masses: vec![k(1), k(1)],
        v_in: vec![vk(&[5, 0]), vk(&[0, 0])],
        fin: vec![Velocity::Direction { speed: int(3) }, Velocity::unknown(2)],
        normal: None,
        e: Some(k(1)),
        inexact: false,
    };
    let s = solve(&g).unwrap();
    assert_eq!(s.solutions.len(), 2);
    for sol in &s.solutions {
        let x = to_f64(sol.fin[0][0].rational()).unwrap();
        let y = to_f64(sol.fin[0][1].rational()).unwrap();
        assert!((x - 1.8).abs() < 1e-12, "{x}");
        assert!((y.abs() - 2.4).abs() < 1e-12, "{y}");
        assert!(sol.checks.iter().all(|c| c.ok), "{:?}", sol.checks);
    }
}
