//! A body hanging on a string of length `L` (the ballistic pendulum, issue 27 §1): leaving the
//! bottom at speed `f` it rises `h = f^2 / 2g` (energy), and the string then makes the angle
//! `theta = acos(1 - h / L)` with the vertical, the bob `x = L sin(theta) = sqrt(h (2L - h))`
//! to the side. `1 - cos(theta) = 2 sin^2(theta / 2)`, so the angle is computed as
//! `2 asin(sqrt(h / 2L))`, which loses nothing for small swings (where `1 - h / L` rounds to 1).
//! Above `h = L` a string goes slack before the bob gets there (only a rigid rod swings past the
//! horizontal), and the bob flies free to its real highest point (`peak`). Above `2L` a rod
//! would go over the top, but a string still goes slack: it stays taut over the top only when
//! the speed left there holds the bob on its circle, `u^2 = 2 g (h - 2L) >= g L`, so from
//! `h = 5L/2` on the bob loops (`OverTheTop`). Everything is exact rational arithmetic, with
//! the roots and the angle taken to `DIGITS` digits.

use num_traits::Signed;

use crate::line::spring::{PI, root};
use crate::values::rational::{Q, int};

/// How a swing ends.
#[derive(Clone, Debug, PartialEq)]
pub enum Swing {
    /// Up to the horizontal: the angle in degrees and the horizontal displacement, exact
    /// (`Ok`) or to `DIGITS` digits (`Err`).
    Angle {
        degrees: Result<Q, Q>,
        horizontal: Result<Q, Q>,
        /// `h > L`: a string goes slack before this angle (a rod would reach it).
        slack: bool,
        /// With `slack`, the height the bob really reaches on a string (`peak`), exact.
        peak: Option<Q>,
    },
    /// `2L < h < 5L/2`: a rod would go over the top (no rod's angle), a string goes slack
    /// and the bob flies free to `peak`, exact.
    Slack { peak: Q },
    /// `h >= 5L/2`: the string stays taut over the top and the bob loops.
    OverTheTop,
}

/// The swing of a bob rising `h` on a string of length `l` (both in metres, `l > 0`, `h >= 0`).
pub fn swing(h: &Q, l: &Q) -> Swing {
    let two_l = int(2) * l;
    if h * int(2) >= int(5) * l {
        return Swing::OverTheTop;
    }
    if h > &two_l {
        return Swing::Slack { peak: peak(h, l) };
    }
    let horizontal = root(&(h * (&two_l - h)));
    // cos(theta) = 1 - h / L: the angles whose cosine is rational and whose degrees are too.
    let cos = Q::ONE - h / l;
    let exact = [
        ("1", "0"),
        ("1/2", "60"),
        ("0", "90"),
        ("-1/2", "120"),
        ("-1", "180"),
    ]
    .into_iter()
    .find(|(c, _)| q(c) == cos)
    .map(|(_, d)| q(d));
    let degrees = match exact {
        Some(d) => Ok(d),
        None => Err(int(2) * asin(&root(&(h / &two_l)).unwrap_or_else(|r| r)) * int(180) / q(PI)),
    };
    Swing::Angle {
        degrees,
        horizontal,
        slack: h > l,
        peak: (h > l).then(|| peak(h, l)),
    }
}

/// The highest point of a bob whose string goes slack (`L < h < 5L/2`): the string's tension
/// vanishes where `u^2 = -g L cos(theta)` with `u^2 = 2 g h - 2 g L (1 - cos(theta))` (energy),
/// at `c = cos(theta) = 2 (L - h) / 3L`, the height `L (1 - c)`; the bob then flies free with
/// the vertical speed `u sin(theta)` and rises `u^2 sin^2(theta) / 2g = -(L c / 2)(1 - c^2)`
/// more. Exact (no root: only squares appear). Ballistic pendulum with L = 0.5 m, h = 0.8 m:
/// `c = -2/5`, slack at 0.7 m, peak 0.7 + 0.1 (21/25) = 0.784 m.
pub fn peak(h: &Q, l: &Q) -> Q {
    let c = int(2) * (l - h) / (int(3) * l);
    let one_less = Q::ONE - &c * &c;
    l * (Q::ONE - &c) - l * &c / int(2) * one_less
}

fn q(s: &str) -> Q {
    s.parse::<crate::values::number::Number>()
        .map(|n| n.exact())
        .unwrap_or_default()
}

/// `x` rounded to `TRIM_BITS` significant bits (about `DIGITS + 10` digits), so the series
/// below keep short numbers. Relative, not to a fixed number of decimals: an angle of 1e-30 rad
/// (a proton against a tonne) or 1e-51 (a 1e100 m string) keeps all its digits (it was
/// rounded to a multiple of 1e-40 and printed as 6.07633050891e-29 or 0 degrees).
fn trim(x: &Q) -> Q {
    let Some(bits) = crate::values::rational::log2(x) else {
        return Q::ZERO;
    };
    let shift = TRIM_BITS - bits;
    let n = (x * crate::values::rational::pow2(shift)).round();
    Q::from(n) * crate::values::rational::pow2(-shift)
}

/// Significant bits `trim` keeps: 136, above `(DIGITS + 10) log2(10)`.
const TRIM_BITS: isize = 136;

/// `asin(s)` for `0 <= s <= 1`, as `atan(s / sqrt(1 - s^2))` with the argument halved
/// (`atan t = 2 atan(t / (1 + sqrt(1 + t^2)))`) until it is below 1/8, then Taylor's series, to
/// about `DIGITS` digits.
pub fn asin(s: &Q) -> Q {
    if s >= &Q::ONE {
        return q(PI) / int(2);
    }
    let sq = |x: &Q| root(x).unwrap_or_else(|r| r);
    let mut t = trim(&(s / sq(&(Q::ONE - s * s))));
    let mut doublings = 0;
    while t.abs() > q("0.125") {
        t = trim(&(&t / (Q::ONE + sq(&(Q::ONE + &t * &t)))));
        doublings += 1;
    }
    // atan t = t - t^3/3 + t^5/5 - ...: |t| <= 1/8, so 40 terms give 70 digits.
    let t2 = trim(&(&t * &t));
    let (mut sum, mut power) = (Q::ZERO, t.clone());
    for k in 0..40 {
        let term = &power / int(2 * k + 1);
        sum = if k % 2 == 0 { sum + term } else { sum - term };
        power = trim(&(&power * &t2));
    }
    sum * int(1 << doublings)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(x: &Q, expected: f64, what: &str) {
        let got = crate::values::rational::to_f64(x).unwrap();
        assert!(
            (got - expected).abs() <= 4.0 * f64::EPSILON * expected.abs(),
            "{what}: {got} against {expected}"
        );
    }

    #[test]
    fn swings_by_hand() {
        // H. C. Verma ch. 9: a block on a 5 m string rises 0.1 m: cos(theta) = 0.98,
        // theta = 11.4783409545...; x = sqrt(0.1 9.9) = sqrt(0.99) = 0.994987437106620 m.
        let Swing::Angle {
            degrees,
            horizontal,
            slack,
            ..
        } = swing(&q("0.1"), &q("5"))
        else {
            panic!("swings")
        };
        close(
            degrees.as_ref().unwrap_err(),
            0.98f64.acos().to_degrees(),
            "theta",
        );
        close(horizontal.as_ref().unwrap_err(), 0.99f64.sqrt(), "x");
        assert!(!slack);
        // h = 0.2 m on 1 m: cos = 0.8, x = sqrt(0.2 1.8) = sqrt(0.36) = 0.6 exactly;
        // theta = acos(0.8) = 36.8698976458440 degrees (the 3-4-5 triangle).
        let Swing::Angle {
            degrees,
            horizontal,
            ..
        } = swing(&q("0.2"), &q("1"))
        else {
            panic!("swings")
        };
        assert_eq!(horizontal, Ok(q("0.6")));
        let d = degrees.unwrap_err();
        let want = q("36.86989764584402129685561255909341");
        assert!(
            ((&d - &want) / &want).abs() < q("1e-28"),
            "{}",
            crate::values::quantity::significant(&d, 30)
        );
        // h = L/2: 60 degrees exactly; h = L: 90 (x = L); h = 3L/2: 120, slack; 2L: 180.
        for (h, deg, slack_expected) in [
            ("0.5", "60", false),
            ("1", "90", false),
            ("1.5", "120", true),
            ("2", "180", true),
        ] {
            let Swing::Angle { degrees, slack, .. } = swing(&q(h), &q("1")) else {
                panic!("{h}")
            };
            assert_eq!((degrees, slack), (Ok(q(deg)), slack_expected), "h = {h}");
        }
        // 2L < h < 5L/2: slack, no rod's angle. h = 2.2 on L = 1: c = 2 (1 - 2.2) / 3 = -0.8,
        // slack at 1.8 m, then up (0.8 / 2)(1 - 0.64) = 0.144: 1.944 m. From 5L/2 it loops:
        // at the top u^2 = 2 g (2.5 - 2) = g L, just enough to keep the string taut.
        assert_eq!(swing(&q("2.2"), &q("1")), Swing::Slack { peak: q("1.944") });
        assert_eq!(
            swing(&q("2.4999"), &q("1")),
            Swing::Slack {
                peak: peak(&q("2.4999"), &q("1"))
            }
        );
        assert_eq!(swing(&q("2.5"), &q("1")), Swing::OverTheTop);
        assert_eq!(peak(&q("2.5"), &q("1")), q("2"));
        // Slack: L = 0.5, h = 0.8 (g = 10, f = 4): c = 2 (0.5 - 0.8) / 1.5 = -2/5, slack at
        // 0.5 (7/5) = 0.7 m with u^2 = 10 0.5 2/5 = 2, then up 2 (21/25) / 20 = 0.084: 0.784 m.
        assert_eq!(peak(&q("0.8"), &q("0.5")), q("0.784"));
        // h = 2L on L = 1: c = -2/3, slack at 5/3 with u^2 = 2g/3, up (1/3)(5/9) = 5/27: 50/27.
        assert_eq!(peak(&q("2"), &q("1")), q("50/27"));
        // A tiny swing, where 1 - h/L rounds to 1 in binary64: 1e-20 m on 1 m,
        // theta = 2 asin(sqrt(5e-21)) = 2 sqrt(5e-21) rad to 1e-40 relative.
        let Swing::Angle { degrees, .. } = swing(&q("1e-20"), &q("1")) else {
            panic!("tiny")
        };
        close(
            &degrees.unwrap_err(),
            (2.0 * 5e-21f64.sqrt()).to_degrees(),
            "tiny theta",
        );
    }
}
