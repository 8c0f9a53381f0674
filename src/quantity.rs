//! The scalars a report can hold: binary64 (`f64`) or exact (`Exact`: a rational, or an
//! irrational shown to 20 significant digits and marked approximate). Text and JSON render both
//! through this trait, so one report layout serves `solve` and `solve --exact`.

use std::fmt::Debug;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use serde::Serialize;

use crate::number::{Number, NumberError, num};

/// Digits shown for an approximate (irrational) exact-mode value.
pub const APPROX_DIGITS: usize = 20;

/// A scalar in a report.
pub trait Scalar: Clone + Debug + PartialEq + Serialize + Default {
    /// For people: shortest round-trip decimal (`f64`), or a fraction / exact decimal / `≈`
    /// digits (`Exact`).
    fn show(&self) -> String;
    /// Whether the value is a real result (finite, for binary64).
    fn is_representable(&self) -> bool;
    fn quarter(&self) -> Self;
    fn neg(&self) -> Self;
    /// `1/x`, `None` for 0.
    fn recip(&self) -> Option<Self>;
    /// An exact rational in this arithmetic: rounded once to binary64 (not representable: NaN,
    /// reported by name), or kept exact.
    fn of_rational(q: &BigRational) -> Self;
    /// `|x|`, as a binary64 (for choosing a scale).
    fn magnitude(&self) -> f64;
    /// `x q`: for a binary64, the exact product rounded once (a change of unit).
    fn scale(&self, q: &BigRational) -> Self;
    /// In text, a binary64 below the error bound of its scale (`SNAP_ULPS` ulps of `scale`, the
    /// largest velocity of its vector) is rounding noise of an exact 0 (a car that stops prints
    /// `0`, not `-4.4e-16`); exact values are never changed.
    fn snap(&self, scale: f64) -> Self;
}

/// The stated error bound of a binary64 velocity, in ulps of the largest velocity of its case.
pub const SNAP_ULPS: f64 = 8.0;

impl Scalar for f64 {
    fn show(&self) -> String {
        num(*self)
    }
    fn is_representable(&self) -> bool {
        self.is_finite()
    }
    fn quarter(&self) -> f64 {
        self / 4.0
    }
    fn neg(&self) -> f64 {
        -self
    }
    fn recip(&self) -> Option<f64> {
        (*self != 0.0).then(|| 1.0 / self)
    }
    fn of_rational(q: &BigRational) -> f64 {
        to_f64(q).unwrap_or(f64::NAN)
    }
    fn magnitude(&self) -> f64 {
        self.abs()
    }
    fn scale(&self, q: &BigRational) -> f64 {
        if !self.is_finite() {
            return *self;
        }
        to_f64(&(from_f64(*self) * q)).unwrap_or(f64::NAN)
    }
    fn snap(&self, scale: f64) -> f64 {
        if self.abs() <= SNAP_ULPS * f64::EPSILON * scale.abs() {
            0.0
        } else {
            *self
        }
    }
}

/// An exact-mode value.
#[derive(Clone, Debug, PartialEq)]
pub enum Exact {
    /// Exactly this rational.
    Rational(BigRational),
    /// An irrational value, truncated to the digits kept (shown to `APPROX_DIGITS`).
    Approx(BigRational),
}

impl Default for Exact {
    fn default() -> Exact {
        Exact::Rational(BigRational::zero())
    }
}

impl Exact {
    pub fn rational(&self) -> &BigRational {
        match self {
            Exact::Rational(q) | Exact::Approx(q) => q,
        }
    }
}

impl Serialize for Exact {
    /// Exact values as strings `"p/q"` (or `"p"`); approximate ones as decimal strings of
    /// `APPROX_DIGITS` significant digits (their object carries `"approx": true`).
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Exact::Rational(q) => s.serialize_str(&fraction(q)),
            Exact::Approx(q) => s.serialize_str(&significant(q, APPROX_DIGITS)),
        }
    }
}

impl Scalar for Exact {
    fn show(&self) -> String {
        match self {
            // Fractions throughout (`-1/4` beside `-1/3`, never `-0.25` beside `-1/3`); a long
            // fraction with a short decimal (`21/5000000000000000`) as that decimal.
            Exact::Rational(q) => {
                let f = fraction(q);
                let text = if f.len() <= 24 {
                    f
                } else {
                    terminating_decimal(q).unwrap_or(f)
                };
                if text.len() <= 40 {
                    text
                } else {
                    format!("≈{}", significant(q, APPROX_DIGITS))
                }
            }
            Exact::Approx(q) => format!("≈{}", significant(q, APPROX_DIGITS)),
        }
    }
    fn is_representable(&self) -> bool {
        true
    }
    fn quarter(&self) -> Exact {
        let q = self.rational() / BigRational::from_integer(4.into());
        self.with(q)
    }
    fn neg(&self) -> Exact {
        self.with(-self.rational())
    }
    fn recip(&self) -> Option<Exact> {
        (!self.rational().is_zero()).then(|| self.with(self.rational().recip()))
    }
    fn of_rational(q: &BigRational) -> Exact {
        Exact::Rational(q.clone())
    }
    fn magnitude(&self) -> f64 {
        self.rational().abs().to_f64().unwrap_or(f64::INFINITY)
    }
    fn scale(&self, q: &BigRational) -> Exact {
        self.with(self.rational() * q)
    }
    fn snap(&self, _scale: f64) -> Exact {
        self.clone()
    }
}

impl Exact {
    /// `q`, as exact or approximate as `self`.
    fn with(&self, q: BigRational) -> Exact {
        match self {
            Exact::Rational(_) => Exact::Rational(q),
            Exact::Approx(_) => Exact::Approx(q),
        }
    }
}

/// `"p/q"`, or `"p"` for an integer.
pub fn fraction(q: &BigRational) -> String {
    if q.is_integer() {
        q.numer().to_string()
    } else {
        format!("{}/{}", q.numer(), q.denom())
    }
}

/// A value computed exactly (solved, converted) as a `Number`: its text a decimal when it has a
/// short one (`1.16`, `0.01`), else its fraction (`5/3`); exact either way.
pub fn number_of(q: &BigRational) -> Result<Number, NumberError> {
    let text = terminating_decimal(q)
        .filter(|t| t.len() <= 40)
        .unwrap_or_else(|| fraction(q));
    Number::solved(&text)
}

/// The exact decimal expansion when the denominator has no prime factors but 2 and 5. Integer
/// arithmetic only (a rational product would cost a gcd of long numbers).
pub fn terminating_decimal(q: &BigRational) -> Option<String> {
    let mut d = q.denom().clone();
    let twos = d.trailing_zeros().unwrap_or(0) as usize;
    d >>= twos;
    let five = BigInt::from(5);
    let mut fives = 0usize;
    loop {
        let (quotient, rest) = d.div_rem(&five);
        if !rest.is_zero() {
            break;
        }
        d = quotient;
        fives += 1;
    }
    if !d.is_one() {
        return None;
    }
    let places = twos.max(fives);
    // numer * 10^places / denom is exact.
    let n = q.numer() * num_traits::pow(BigInt::from(10), places) / q.denom();
    let digits = n.abs().to_string();
    let sign = if n.is_negative() { "-" } else { "" };
    if places == 0 {
        return Some(format!("{sign}{digits}"));
    }
    let padded = format!("{digits:0>width$}", width = places + 1);
    let (int, frac) = padded.split_at(padded.len() - places);
    Some(format!("{sign}{int}.{frac}"))
}

/// `q` to `n` significant digits (truncated), plain for moderate exponents, else `d.ddde±x`.
pub fn significant(q: &BigRational, n: usize) -> String {
    if q.is_zero() {
        return "0".to_string();
    }
    let sign = if q.is_negative() { "-" } else { "" };
    // Integers only: a = num / den, and floor(a 10^k) = floor(num 10^k / den) (for k < 0,
    // num / (den 10^-k)); rational products would cost gcds of long numbers.
    let (num, den) = (q.numer().abs(), q.denom().clone());
    let ten_to = |k: i64| num_traits::pow(BigInt::from(10), k.unsigned_abs() as usize);
    let scaled = |k: i64| {
        if k >= 0 {
            &num * ten_to(k) / &den
        } else {
            &num / (&den * ten_to(k))
        }
    };
    // Decimal exponent: 10^e <= a < 10^(e+1), first from the bit lengths.
    let bits = num.bits() as i64 - den.bits() as i64;
    let mut e = (bits as f64 * std::f64::consts::LOG10_2).floor() as i64;
    while scaled(-e).is_zero() {
        e -= 1;
    }
    while !scaled(-e - 1).is_zero() {
        e += 1;
    }
    let digits = scaled(n as i64 - 1 - e).to_string();
    if (-5..21).contains(&e) {
        if e >= 0 {
            let e = e as usize;
            let (int, frac) = if e + 1 >= digits.len() {
                (format!("{digits:0<width$}", width = e + 1), String::new())
            } else {
                (digits[..=e].to_string(), digits[e + 1..].to_string())
            };
            let frac = frac.trim_end_matches('0');
            if frac.is_empty() {
                format!("{sign}{int}")
            } else {
                format!("{sign}{int}.{frac}")
            }
        } else {
            let zeros = "0".repeat((-e - 1) as usize);
            format!("{sign}0.{zeros}{}", digits.trim_end_matches('0'))
        }
    } else {
        let frac = digits[1..].trim_end_matches('0');
        let dot = if frac.is_empty() { "" } else { "." };
        format!("{sign}{}{dot}{frac}e{e}", &digits[..1])
    }
}

/// `sqrt(q)` for `q >= 0`, truncated to at least `digits` significant decimal digits.
pub fn sqrt(q: &BigRational, digits: usize) -> BigRational {
    if q.is_zero() || q.is_negative() {
        return BigRational::zero();
    }
    // sqrt(n/d) = sqrt(n d) / d; scale n d by 10^(2k) so the integer root has enough digits.
    let nd = q.numer() * q.denom();
    let have = nd.to_string().len() / 2;
    let k = (digits + 2).saturating_sub(have);
    let scale = num_traits::pow(BigInt::from(10), k);
    let root = (nd * &scale * &scale).sqrt();
    BigRational::new(root, q.denom() * scale)
}

/// The nearest binary64 to an exact value (`None` outside the binary64 range).
pub fn to_f64(q: &BigRational) -> Option<f64> {
    q.to_f64().filter(|x| x.is_finite())
}

/// The exact value of a binary64.
pub fn from_f64(x: f64) -> BigRational {
    BigRational::from_float(x).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn exact_values_print_as_fractions_or_exact_decimals() {
        // Fractions throughout (issue 15: no -0.25 beside -1/3), a long one with a short
        // decimal as the decimal.
        assert_eq!(Exact::Rational(q(4, 3)).show(), "4/3");
        assert_eq!(Exact::Rational(q(70, 3)).show(), "70/3");
        assert_eq!(Exact::Rational(q(-1, 5)).show(), "-1/5");
        assert_eq!(Exact::Rational(q(27075, 4)).show(), "27075/4");
        let tiny = BigRational::new(21.into(), num_traits::pow(BigInt::from(10), 32));
        assert_eq!(
            Exact::Rational(tiny).show(),
            "0.00000000000000000000000000000021"
        );
        assert_eq!(Exact::Rational(q(250, 1)).show(), "250");
        assert_eq!(
            serde_json::to_string(&Exact::Rational(q(4, 3))).unwrap(),
            "\"4/3\""
        );
        assert_eq!(
            serde_json::to_string(&Exact::Rational(q(6, 1))).unwrap(),
            "\"6\""
        );
    }

    #[test]
    fn significant_digits() {
        assert_eq!(significant(&q(1, 3), 5), "0.33333");
        assert_eq!(significant(&q(200, 3), 5), "66.666");
        assert_eq!(significant(&q(7, 1), 20), "7");
        assert_eq!(significant(&q(-1, 1000000), 3), "-1e-6");
        let big = BigRational::from_integer(num_traits::pow(BigInt::from(10), 400) * 3);
        assert_eq!(significant(&big, 4), "3e400");
    }

    #[test]
    fn square_roots_to_twenty_digits() {
        // sqrt(14500/4) = 60.20797289396147740064... (Python's decimal module, 40 digits):
        // lecture Fig. 1.3's IN ellipse radius a. Trailing zeros are not printed.
        let r = sqrt(&q(14500, 4), 30);
        assert_eq!(significant(&r, 20), "60.2079728939614774");
        assert_eq!(
            significant(&sqrt(&q(2, 1), 25), 20),
            "1.4142135623730950488"
        );
        assert_eq!(sqrt(&q(9, 4), 10), q(3, 2));
    }
}
