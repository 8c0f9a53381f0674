//! The plane and space code (`src/space/`) under mutation (issue 46, the samples of
//! `benches/mutants.sh space`): a test for each mutant a sample missed, against values derived
//! by hand or from tables, each with its tolerance.

use collide::space::angle::Angle;

/// An ulp of `x`: the spacing of binary64 at its exponent.
fn ulp(x: f64) -> f64 {
    collide::accuracy::ulp(x)
}

#[test]
fn sines_of_degrees_near_30_keep_the_radian_s_rounding_error() {
    // `sin_cos_degrees` takes sin(t pi/180) as sin(hi + lo) = sin hi + lo cos hi, hi + lo the
    // double-double radian; the mutant `sin hi - lo cos hi` is off by 2 lo cos hi, up to an ulp
    // and more where the radian's rounding lo is largest. At 29.4 to 29.9 degrees (sin about
    // 1/2, an ulp 5.55e-17) lo is near half an ulp of hi, and the mutant lands 1.75 to 2.27
    // ulps from the true sine; the code is within 0.3 ulp. The sines of the typed decimals
    // (29.9 is 299/10 exactly, rounded to binary64 only after the reduction), to 25 digits
    // (any table; mpmath at 40 digits):
    for (deg, sin) in [
        ("29.9deg", "0.4984877397538303320134237"),
        ("29.4deg", "0.4909037536151408316986544"),
        ("29.7deg", "0.4954586684324075380504821"),
        ("29.5deg", "0.4924235601034671197987344"),
    ] {
        let a: Angle = deg.parse().unwrap();
        let (_, s, _) = a.unit();
        let sin: f64 = sin.parse().unwrap();
        // Within an ulp, as the function's comment claims: here it is the nearest binary64
        // (0 ulps from the rounded literal), the mutant 2 ulps from it.
        assert!(
            (s - sin).abs() <= ulp(sin),
            "{deg}: {s} against {sin}: {:.2} ulps",
            (s - sin).abs() / ulp(sin)
        );
    }
}

#[test]
fn three_unequal_balls_in_a_row_stick_together_at_once() {
    // Balls of radius 1 at x = 0, 2, 4 (touching), masses 1, 2, 1, the first at 1 onto the
    // others at rest, e = 0 at both contacts at once. All three leave together at the centre of
    // momentum's velocity 1/(1 + 2 + 1) = 1/4: body 1 loses 3/4 of momentum (the impulse at
    // 1-2), body 3 gains 1/4 (at 2-3), body 2 gains 3/4 - 1/4 = 1/2 = 2 (1/4). Both impulses are
    // positive and both gaps close at rate 0: Newton's law at each contact holds, so this is
    // the LCP's answer, exactly. The solver's own check (momentum kept, energy never created)
    // must accept it: the mutant `m + v` for `m v` in that check keeps sum(m + v) only where
    // the masses are equal, and refuses this.
    use collide::space::contacts::{simultaneous, touching};
    use collide::values::rational::{Q, int, ratio};
    let pos: Vec<Vec<Q>> = (0..3).map(|i| vec![int(2 * i), int(0)]).collect();
    let c = touching(&pos, &vec![int(1); 3]).unwrap();
    assert_eq!(c.len(), 2);
    let masses = vec![int(1), int(2), int(1)];
    let v = vec![vec![int(1), int(0)], vec![int(0); 2], vec![int(0); 2]];
    let s = simultaneous(&masses, &v, &c, &int(0)).unwrap();
    for f in &s.fin {
        assert_eq!(*f, vec![ratio(1, 4), int(0)]);
    }
    assert!(s.w_fin.iter().all(|w| w.is_zero()), "{:?}", s.w_fin);
}

#[test]
fn the_double_double_bound_decides_ordinary_impacts_itself() {
    // `impact::general` takes the double-double value when its error bound cannot change the
    // rounding (`bounded`) and the exact rational form otherwise, so a bound too loose costs
    // speed, not digits (the mutant `4 + U` for `4 U` in `Bounded::round`'s margin, 2^-51
    // relative, two ulps: every inexact value goes to the exact form). By hand: masses 1, 2,
    // v1 = (3, 1), v2 = 0, n = (1, 1), e = 1/2: s = n.(v1 - v2)/n.n = 2, j1 = (1 + e) s m2/M
    // = 2, j2 = (1 + e) s m1/M = 1, so v1' = (3, 1) - 2 (1, 1) = (1, -1), v2' = (1, 1).
    use collide::space::impact::{bounded, exact};
    let got = bounded([1.0, 2.0], [[3.0, 1.0], [0.0, 0.0]], [1.0, 1.0], 0.5);
    assert_eq!(got, Some([[1.0, -1.0], [1.0, 1.0]]));
    // With e = 0.7 and n = (1, 3) the answer is rounded (s = 6/10 = 3/5, j1 = 1.7 (3/5)(2/3)
    // = 0.68, whose binary64 multiples of n are inexact): the bound decides it, and as the
    // exact form rounds it.
    let (m, v, n) = ([1.0, 2.0], [[3.0, 1.0], [0.0, 0.0]], [1.0, 3.0]);
    assert_eq!(bounded(m, v, n, 0.7), Some(exact(m, v, n, 0.7)));
}
