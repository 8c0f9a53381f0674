//! Error-free transformations and compensated sums (Ogita, Rump & Oishi, "Accurate sum and dot
//! product", SIAM J. Sci. Comput. 26, 2005). They let a quadratic form such as `V.M.V` be evaluated
//! as if in twice the working precision and then rounded once, so cancellation between its terms
//! (a general tensor with negative `M12`, or a form of two nearly M-orthogonal vectors) costs nothing.

/// `a + b = s + err` exactly (Knuth's TwoSum).
#[inline(always)]
pub fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a * b = p + err` exactly (with a fused multiply-add), barring underflow.
#[inline(always)]
pub fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// `sum(terms)` with one final rounding in the common case (Ogita-Rump-Oishi Sum2).
#[inline]
pub fn sum2(terms: &[f64]) -> f64 {
    let mut s = 0.0;
    let mut c = 0.0;
    for &t in terms {
        let (ns, e) = two_sum(s, t);
        s = ns;
        c += e;
    }
    s + c
}

/// `sum(x[i] * y[i])` as if computed in twice the precision (Ogita-Rump-Oishi Dot2).
#[inline]
pub fn dot2(x: &[f64], y: &[f64]) -> f64 {
    debug_assert_eq!(x.len(), y.len());
    let mut s = 0.0;
    let mut c = 0.0;
    for (&a, &b) in x.iter().zip(y) {
        let (p, ep) = two_prod(a, b);
        let (ns, es) = two_sum(s, p);
        s = ns;
        c += ep + es;
    }
    s + c
}

/// `a*b - c*d` to within 1.5 ulp (Kahan's algorithm with a fused multiply-add).
#[inline]
pub fn diff_of_products(a: f64, b: f64, c: f64, d: f64) -> f64 {
    let w = c * d;
    let err = (-c).mul_add(d, w);
    a.mul_add(b, -w) + err
}

/// `2^k` for `k` in the normal exponent range [-1022, 1023]: scaling by it is exact.
#[inline]
pub fn pow2(k: i32) -> f64 {
    debug_assert!((-1022..=1023).contains(&k));
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// The binary exponent of a finite non-zero `x`: `2^e <= |x| < 2^(e+1)` (subnormals clamp to -1022).
#[inline]
pub fn exponent(x: f64) -> i32 {
    let biased = ((x.to_bits() >> 52) & 0x7ff) as i32;
    biased.max(1) - 1023
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_sum_and_two_prod_are_error_free() {
        let (s, e) = two_sum(1.0, 1e-20);
        assert_eq!((s, e), (1.0, 1e-20));
        let x = 1.0 + f64::EPSILON;
        let (p, e) = two_prod(x, x);
        // (1 + u)^2 = 1 + 2u + u^2: the u^2 = 2^-104 part is the error term.
        assert_eq!(p, 1.0 + 2.0 * f64::EPSILON);
        assert_eq!(e, f64::EPSILON * f64::EPSILON);
    }

    #[test]
    fn dot2_survives_total_cancellation() {
        // 1e16 + 1 - 1e16 = 1, which plain summation gets as 0.
        assert_eq!(dot2(&[1e16, 1.0, -1e16], &[1.0, 1.0, 1.0]), 1.0);
        assert_eq!(sum2(&[1e16, 1.0, -1e16]), 1.0);
    }

    #[test]
    fn kahan_determinant_of_a_nearly_singular_matrix() {
        // det [[1+u, 1], [1, 1-u]] = 1 - u^2 - 1 = -u^2 exactly, with u = 2^-30.
        let u = 2f64.powi(-30);
        assert_eq!(diff_of_products(1.0 + u, 1.0 - u, 1.0, 1.0), -u * u);
    }

    #[test]
    fn powers_of_two() {
        assert_eq!(pow2(0), 1.0);
        assert_eq!(pow2(-3), 0.125);
        assert_eq!(pow2(1000), 2f64.powi(1000));
        assert_eq!(exponent(1.0), 0);
        assert_eq!(exponent(0.75), -1);
        assert_eq!(exponent(-6.0), 2);
    }
}

/// A double-double `hi + lo` (|lo| <= ulp(hi)/2): about 106 significant bits, enough that a short
/// formula evaluated in it and rounded once is correctly rounded but for near-ties.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Dd {
    pub hi: f64,
    pub lo: f64,
}

#[inline]
fn fast_two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    Dd {
        hi: s,
        lo: b - (s - a),
    }
}

impl Dd {
    #[inline]
    pub fn new(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }
    /// `a + b` exactly.
    #[inline]
    pub fn sum(a: f64, b: f64) -> Dd {
        let (hi, lo) = two_sum(a, b);
        Dd { hi, lo }
    }
    /// `a * b` exactly (barring underflow).
    #[inline]
    pub fn prod(a: f64, b: f64) -> Dd {
        let (hi, lo) = two_prod(a, b);
        Dd { hi, lo }
    }
    /// Rounded to the nearest binary64 (but for near-ties).
    #[inline]
    pub fn value(self) -> f64 {
        self.hi + self.lo
    }
}

impl std::ops::Add for Dd {
    type Output = Dd;
    #[inline]
    fn add(self, o: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, o.hi);
        fast_two_sum(s, e + self.lo + o.lo)
    }
}

impl std::ops::Neg for Dd {
    type Output = Dd;
    #[inline]
    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl std::ops::Sub for Dd {
    type Output = Dd;
    #[inline]
    fn sub(self, o: Dd) -> Dd {
        self + -o
    }
}

impl std::ops::Mul for Dd {
    type Output = Dd;
    #[inline]
    fn mul(self, o: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, o.hi);
        fast_two_sum(p, e + (self.hi * o.lo + self.lo * o.hi))
    }
}

impl std::ops::Div for Dd {
    type Output = Dd;
    /// Long division with three quotient digits.
    #[inline]
    fn div(self, o: Dd) -> Dd {
        let q1 = self.hi / o.hi;
        let r = self - o * Dd::new(q1);
        let q2 = r.hi / o.hi;
        let r = r - o * Dd::new(q2);
        let q3 = r.hi / o.hi;
        fast_two_sum(q1, q2) + Dd::new(q3)
    }
}

#[cfg(test)]
mod dd_tests {
    use super::Dd;
    use crate::values::rational::{Q, from_f64, to_f64};

    /// The exact value `hi + lo` of a double-double.
    fn exact(d: Dd) -> Q {
        from_f64(d.hi) + from_f64(d.lo)
    }

    /// `|d - x| / |x|` as a binary64 (exact difference, rounded once).
    fn rel(d: Dd, x: &Q) -> f64 {
        use num_traits::Signed;
        to_f64(&((exact(d) - x) / x).abs()).unwrap()
    }

    /// SplitMix64 (fixed seed): binary64 values `m * 2^k` with 53-bit `m`, both signs, `k` in
    /// [-60, 60].
    fn values(n: usize) -> Vec<f64> {
        let mut s = 0x5EED_u64;
        let mut next = || {
            s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = s;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^ (z >> 31)
        };
        (0..n)
            .map(|_| {
                let m = (next() >> 11) as f64 * super::pow2(-53);
                let k = (next() % 121) as i32 - 60;
                let sign = if next() & 1 == 0 { 1.0 } else { -1.0 };
                sign * (1.0 + m) * super::pow2(k)
            })
            .collect()
    }

    #[test]
    fn sum_and_prod_are_exact_and_their_head_is_the_rounded_value() {
        // Against exact rationals: hi + lo is the exact sum (product), hi is that value rounded
        // to nearest, and |lo| is at most half an ulp of hi. 0.1 + 0.2: the exact sum of the two
        // binary64 values is 0.3000000000000000166533453693773481063544750213623046875, hi is
        // its rounding 0.30000000000000004 and lo the rest, -2.7755575615628914e-17.
        let d = Dd::sum(0.1, 0.2);
        let x = from_f64(0.1) + from_f64(0.2);
        assert_eq!(exact(d), x);
        assert_eq!(d.hi, to_f64(&x).unwrap());
        assert_eq!(d.lo, to_f64(&(x - from_f64(d.hi))).unwrap());
        assert_eq!(d.lo, -2.7755575615628914e-17);
        let v = values(400);
        for w in v.windows(2) {
            let (a, b) = (w[0], w[1]);
            for (d, x) in [
                (Dd::sum(a, b), from_f64(a) + from_f64(b)),
                (Dd::prod(a, b), from_f64(a) * from_f64(b)),
            ] {
                assert_eq!(exact(d), x, "{a} {b}");
                assert_eq!(d.hi, to_f64(&x).unwrap(), "{a} {b}");
                assert!(d.lo.abs() <= 0.5 * super::pow2(super::exponent(d.hi) - 52));
            }
        }
    }

    #[test]
    fn arithmetic_keeps_about_106_bits() {
        // Double-double operations on double-double operands, against the exact rational
        // result: relative error below 2^-100 (Joldes, Muller & Popescu 2017 bound add at 3u^2,
        // mul at 4u^2 and this three-digit division at a few u^2, u = 2^-53; 2^-100 leaves room).
        let bound = super::pow2(-100);
        let v = values(200);
        for w in v.windows(4) {
            let a = Dd::sum(w[0], w[1] * super::pow2(-60));
            let b = Dd::sum(w[2], w[3] * super::pow2(-60));
            let (xa, xb) = (exact(a), exact(b));
            // Sums of like signs: no cancellation, so the relative bound applies.
            let (a, xa) = if (w[0] > 0.0) == (w[2] > 0.0) {
                (a, xa)
            } else {
                (-a, -xa)
            };
            assert!(rel(a + b, &(&xa + &xb)) <= bound, "{a:?} + {b:?}");
            assert!(rel(a * b, &(&xa * &xb)) <= bound, "{a:?} * {b:?}");
            assert!(rel(a / b, &(&xa / &xb)) <= bound, "{a:?} / {b:?}");
            assert_eq!(exact(a - a), Q::default());
        }
    }

    #[test]
    fn double_double_rounds_once() {
        // (1/10 + 2/10) evaluated in double-double from the binary64 0.1 and 0.2 is
        // 0.3000000000000000166..., which rounds to 0.30000000000000004, like exact arithmetic.
        assert_eq!(Dd::sum(0.1, 0.2).value(), 0.1 + 0.2);
        // 7/5 * 2 - 3 = -0.2 exactly from exact inputs; plain binary64 gets -0.19999999999999973.
        let q = Dd::new(7.0) / Dd::new(5.0) * Dd::new(2.0) - Dd::new(3.0);
        assert_eq!(q.value(), -0.2);
        let third = Dd::new(1.0) / Dd::new(3.0);
        assert_eq!((third * Dd::new(3.0)).value(), 1.0);
        assert!(third.lo != 0.0);
    }
}
