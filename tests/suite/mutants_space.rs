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
