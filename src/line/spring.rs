//! A spring between two colliding bodies (issue 27 §1: "the block compresses a spring of
//! k = 200 N/m; find the maximum compression"). At closest approach both bodies move at V_COM,
//! and the spring holds exactly the crunch energy `1/2 mu (v1 - v2)^2` (lecture Sec. 2), so
//! `1/2 k x^2 = crunch` gives `x_max = sqrt(2 crunch / k)`. An ideal (linear, massless) spring
//! makes the pair a harmonic oscillator of the reduced mass, `omega = sqrt(k / mu)`, in contact
//! for half a period: `t = pi sqrt(mu / k)`, whatever the speeds. Both are in SI (J, kg, N/m:
//! metres and seconds), from exact values; the roots are taken to `DIGITS` digits.

use crate::values::rational::Q;

/// Digits the roots are taken to: beyond binary64 and the 20 digits exact mode shows.
pub const DIGITS: usize = 30;

/// pi to 36 significant digits.
pub const PI: &str = "3.14159265358979323846264338327950288";

/// A root: exact when `q` is a rational square (`Ok`), else to `DIGITS` digits (`Err`).
pub fn root(q: &Q) -> Result<Q, Q> {
    crate::values::rational::sqrt_exact(q).ok_or_else(|| crate::values::quantity::sqrt(q, DIGITS))
}

/// `x_max = sqrt(2 crunch / k)`, exact or to `DIGITS` digits (`root`).
pub fn compression(crunch: &Q, k: &Q) -> Result<Q, Q> {
    root(&(Q::from(2) * crunch / k))
}

/// `t = pi sqrt(mu / k)`, to `DIGITS` digits (pi is irrational).
pub fn contact_time(mu: &Q, k: &Q) -> Q {
    let pi: Q = PI
        .parse::<crate::values::number::Number>()
        .map(|n| n.exact())
        .unwrap_or_default();
    let r = root(&(mu / k)).unwrap_or_else(|r| r);
    pi * r
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::Signed;

    fn q(s: &str) -> Q {
        s.parse::<crate::values::number::Number>().unwrap().exact()
    }

    #[test]
    fn halliday_blocks_and_spring() {
        // Halliday, Resnick & Walker, ch. 9: block 1 (2.0 kg) at 10 m/s catches block 2 (5.0 kg)
        // at 3.0 m/s, which carries a spring of k = 1120 N/m: mu = 10/7, crunch =
        // 1/2 (10/7) 7^2 = 35 J, x = sqrt(70 / 1120) = sqrt(1/16) = 0.25 m exactly (the book's
        // answer); t = pi sqrt((10/7) / 1120) = pi sqrt(1/784) = pi/28 s.
        assert_eq!(compression(&q("35"), &q("1120")), Ok(q("0.25")));
        let t = contact_time(&q("10/7"), &q("1120"));
        let pi_over_28 = q(PI) / q("28");
        assert_eq!(t, pi_over_28);
        // 1 J into 3 N/m: x = sqrt(2/3), irrational: 0.816496580927726032732428024901...
        let x = compression(&q("1"), &q("3")).unwrap_err();
        let err = (&x * &x - q("2/3")) / q("2/3");
        assert!(
            err.abs() < q("1e-29"),
            "{}",
            crate::values::quantity::fraction(&err)
        );
    }
}
