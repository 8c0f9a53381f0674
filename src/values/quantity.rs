//! The scalars a report can hold: binary64 (`f64`) or exact (`Exact`: a rational, or an
//! irrational shown to 20 significant digits and marked approximate). Text and JSON render both
//! through this trait, so one report layout serves `solve` and `solve --exact`.

use std::fmt::Debug;

use dashu_int::ops::{BitTest, SquareRoot, UnsignedAbs};
use num_traits::{Signed, Zero};

use crate::values::rational::{IBig, Q, UBig, pow10};
use serde::Serialize;

use crate::values::number::{Number, NumberError, num};

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
    fn of_rational(q: &Q) -> Self;
    /// An irrational value known to many more digits than binary64 holds (`q` within
    /// `10^-(APPROX_DIGITS + 2)` of it, relative): rounded once to binary64, or kept as an
    /// approximation marked as such.
    fn of_approx(q: &Q) -> Self {
        Self::of_rational(q)
    }
    /// `self`, the value of the exact `q`; for a binary64, NaN (reported by name) when `q` is not
    /// 0 but `self` came out below the normal range: it underflowed, and printing 0 or a
    /// subnormal for a height, a distance or an angle would be wrong (energies are refused the
    /// same way).
    fn unless_underflow(self, _q: &Q) -> Self {
        self
    }
    /// `|x|`, as a binary64 (for choosing a scale).
    fn magnitude(&self) -> f64;
    /// `x q`: for a binary64, the exact product rounded once (a change of unit).
    fn scale(&self, q: &Q) -> Self;
    /// In text, a binary64 below the error bound of its scale (`SNAP_ULPS` ulps of `scale`, the
    /// largest velocity of its vector) is rounding noise of an exact 0 (a car that stops prints
    /// `0`, not `-4.4e-16`); exact values are never changed.
    fn snap(&self, scale: f64) -> Self;
    /// Exact arithmetic (`--exact`): values are printed as the fractions they are.
    const EXACT: bool;
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
    /// `-x`, with `-0 = 0`: a negated zero (FIN' = -IN with IN = (2, 0)) prints as 0, not -0.
    fn neg(&self) -> f64 {
        if *self == 0.0 { 0.0 } else { -self }
    }
    fn recip(&self) -> Option<f64> {
        (*self != 0.0).then(|| 1.0 / self)
    }
    fn of_rational(q: &Q) -> f64 {
        to_f64(q).unwrap_or(f64::NAN)
    }
    fn unless_underflow(self, q: &Q) -> f64 {
        if !q.is_zero() && self.abs() < f64::MIN_POSITIVE {
            f64::NAN
        } else {
            self
        }
    }
    fn magnitude(&self) -> f64 {
        self.abs()
    }
    fn scale(&self, q: &Q) -> f64 {
        if !self.is_finite() {
            return *self;
        }
        to_f64(&(from_f64(*self) * q)).unwrap_or(f64::NAN)
    }
    const EXACT: bool = false;

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
    Rational(Q),
    /// An irrational value, truncated to the digits kept (shown to `APPROX_DIGITS`).
    Approx(Q),
}

impl Default for Exact {
    fn default() -> Exact {
        Exact::Rational(Q::zero())
    }
}

impl Exact {
    pub fn rational(&self) -> &Q {
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
            Exact::Approx(q) => s.serialize_str(&nearest(q, APPROX_DIGITS)),
        }
    }
}

impl Scalar for Exact {
    fn show(&self) -> String {
        match self {
            // Fractions throughout (`-1/4` beside `-1/3`, never `-0.25` beside `-1/3`); a long
            // fraction with a short decimal (`21/5000000000000000`) as that decimal.
            // Long values are never written out in full only to be dropped.
            // A long terminating value in exact scientific notation (1/5e-324 = 2e323), before
            // giving up to digits marked approximate.
            Exact::Rational(q) => match fraction_within(q, 40) {
                Some(f) if f.len() <= 24 => f,
                f => terminating_decimal(q, 40)
                    .or(f)
                    .or_else(|| short_scientific(q))
                    .unwrap_or_else(|| format!("≈{}", significant(q, APPROX_DIGITS))),
            },
            Exact::Approx(q) => format!("≈{}", nearest(q, APPROX_DIGITS)),
        }
    }
    fn is_representable(&self) -> bool {
        true
    }
    fn quarter(&self) -> Exact {
        let q = self.rational() / crate::values::rational::int(4);
        self.with(q)
    }
    fn neg(&self) -> Exact {
        self.with(-self.rational())
    }
    fn recip(&self) -> Option<Exact> {
        (!self.rational().is_zero()).then(|| self.with(Q::ONE / self.rational()))
    }
    fn of_rational(q: &Q) -> Exact {
        Exact::Rational(q.clone())
    }
    fn of_approx(q: &Q) -> Exact {
        Exact::Approx(q.clone())
    }
    fn magnitude(&self) -> f64 {
        to_f64(self.rational()).map_or(f64::INFINITY, f64::abs)
    }
    fn scale(&self, q: &Q) -> Exact {
        self.with(self.rational() * q)
    }
    const EXACT: bool = true;

    fn snap(&self, _scale: f64) -> Exact {
        self.clone()
    }
}

impl Exact {
    /// `q`, as exact or approximate as `self`.
    fn with(&self, q: Q) -> Exact {
        match self {
            Exact::Rational(_) => Exact::Rational(q),
            Exact::Approx(_) => Exact::Approx(q),
        }
    }
}

/// The exact value in scientific notation when it has at most `APPROX_DIGITS` significant
/// digits (`2e323`): as short as the approximation, and exact.
fn short_scientific(q: &Q) -> Option<String> {
    scientific(q, 40).filter(|t| {
        let mantissa = t.split('e').next().unwrap_or_default();
        mantissa.chars().filter(char::is_ascii_digit).count() <= APPROX_DIGITS
    })
}

/// `"p/q"`, or `"p"` for an integer.
pub fn fraction(q: &Q) -> String {
    if q.is_int() {
        q.numerator().to_string()
    } else {
        format!("{}/{}", q.numerator(), q.denominator())
    }
}

/// A value computed exactly (solved, converted) as a `Number`: its text a decimal when it has a
/// short one (`1.16`, `0.01`), else its fraction (`5/3`); exact either way.
pub fn number_of(q: &Q) -> Result<Number, NumberError> {
    let text = terminating_decimal(q, 40)
        .or_else(|| scientific(q, 40))
        .unwrap_or_else(|| fraction(q));
    Number::solved(&text)
}

/// The exact value in scientific notation (`2e154`, `-1.25e-303`), when it is a terminating
/// decimal whose notation has at most `max_chars` characters.
pub fn scientific(q: &Q, max_chars: usize) -> Option<String> {
    if q.is_zero() {
        return Some("0".into());
    }
    let plain = terminating_decimal(q, usize::MAX)?;
    let (sign, plain) = match plain.strip_prefix('-') {
        Some(p) => ("-", p),
        None => ("", plain.as_str()),
    };
    let (int, frac) = plain.split_once('.').unwrap_or((plain, ""));
    let all = format!("{int}{frac}");
    let first = all.find(|c| c != '0')?;
    let digits = all[first..].trim_end_matches('0');
    let exponent = int.len() as i64 - 1 - first as i64;
    let (lead, rest) = digits.split_at(1);
    let dot = if rest.is_empty() { "" } else { "." };
    Some(format!("{sign}{lead}{dot}{rest}e{exponent}")).filter(|t| t.len() <= max_chars)
}

/// `fraction(q)` when it has at most `max_chars` characters; decided from the bit lengths first
/// (`p` has at least `floor((bits - 1) log10 2) + 1` digits), so a long one is never written out.
pub fn fraction_within(q: &Q, max_chars: usize) -> Option<String> {
    let digits = |bits: usize| (bits.max(1) - 1) * 30103 / 100000 + 1;
    let fewest = digits(q.numerator().unsigned_abs().bit_len())
        + if q.is_int() {
            0
        } else {
            1 + digits(q.denominator().bit_len())
        };
    if fewest > max_chars {
        return None;
    }
    Some(fraction(q)).filter(|f| f.len() <= max_chars)
}

/// The exact decimal expansion, when the denominator has no prime factors but 2 and 5 and it has
/// at most `max_chars` characters. Integer arithmetic only (a rational product would cost a gcd
/// of long numbers).
pub fn terminating_decimal(q: &Q, max_chars: usize) -> Option<String> {
    let mut d = q.denominator().clone();
    let twos = d.trailing_zeros().unwrap_or(0);
    d >>= twos;
    let fives = power_of_five(&d)?;
    let places = twos.max(fives);
    if places > 0 && places + 2 > max_chars {
        return None;
    }
    // numer * 10^places / denom is exact.
    let n = q.numerator() * IBig::from(pow10(places)) / IBig::from(q.denominator().clone());
    let digits = n.abs().to_string();
    let sign = if n.is_negative() { "-" } else { "" };
    if places == 0 {
        return Some(format!("{sign}{digits}")).filter(|t| t.len() <= max_chars);
    }
    let padded = format!("{digits:0>width$}", width = places + 1);
    let (int, frac) = padded.split_at(padded.len() - places);
    Some(format!("{sign}{int}.{frac}")).filter(|t| t.len() <= max_chars)
}

/// `k` when `d = 5^k`. From the bit length, `k` is within one of `(bits - 1) / log2 5`: a power
/// and a comparison or three, where dividing by 5 a digit at a time is quadratic in the length.
fn power_of_five(d: &UBig) -> Option<usize> {
    let guess = ((d.bit_len().max(1) - 1) as f64 / 5f64.log2()).round() as usize;
    (guess.saturating_sub(1)..=guess + 1).find(|&k| UBig::from(5u8).pow(k) == *d)
}

/// `q` to `n` significant digits (truncated), plain for moderate exponents, else `d.ddde±x`.
/// Truncation keeps the side: an exact energy just below 35 prints `34.999...`, never `35`
/// beside a loss of `4.2e-22`.
pub fn significant(q: &Q, n: usize) -> String {
    digits(q, n, false)
}

/// `q` to `n` significant digits, rounded half away from zero: for an irrational value held to
/// more digits than shown, whose side the digits held do not know (an approximation of 8 from
/// below prints `8`, never `7.9999999999999999999` beside an elastic label).
pub fn nearest(q: &Q, n: usize) -> String {
    digits(q, n, true)
}

fn digits(q: &Q, n: usize, round: bool) -> String {
    if q.is_zero() {
        return "0".to_string();
    }
    let sign = if q.is_negative() { "-" } else { "" };
    // Integers only: a = num / den, and floor(a 10^k) = floor(num 10^k / den) (for k < 0,
    // num / (den 10^-k)); rational products would cost gcds of long numbers.
    let (num, den) = (q.numerator().unsigned_abs(), q.denominator().clone());
    let ten_to = |k: i64| pow10(k.unsigned_abs() as usize);
    let scaled = |k: i64| {
        if k >= 0 {
            &num * ten_to(k) / &den
        } else {
            &num / (&den * ten_to(k))
        }
    };
    // Decimal exponent: 10^e <= a < 10^(e+1), first from the bit lengths.
    let bits = num.bit_len() as i64 - den.bit_len() as i64;
    let mut e = (bits as f64 * std::f64::consts::LOG10_2).floor() as i64;
    while scaled(-e).is_zero() {
        e -= 1;
    }
    while !scaled(-e - 1).is_zero() {
        e += 1;
    }
    // Rounded: one digit more, then half away from zero.
    let mut rounded = if round {
        (scaled(n as i64 - e) + UBig::from(5u8)) / UBig::from(10u8)
    } else {
        scaled(n as i64 - 1 - e)
    };
    if rounded >= pow10(n) {
        // 9.99... carried to 10.0...: one more integer digit, one fewer after the point.
        rounded /= UBig::from(10u8);
        e += 1;
    }
    let digits = rounded.to_string();
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
pub fn sqrt(q: &Q, digits: usize) -> Q {
    if q.is_zero() || q.is_negative() {
        return Q::ZERO;
    }
    // sqrt(q) = sqrt(floor(q 10^2k)) / 10^k, truncated. From the bit lengths, log10 q is within
    // 0.31 of e, so q 10^2k >= 10^(2 digits + 5) and its integer root has digits + 2 digits or
    // more: only those are computed, however long q's numerator and denominator are.
    let (n, d) = (q.numerator().unsigned_abs(), q.denominator());
    let e = ((n.bit_len() as f64 - d.bit_len() as f64) * std::f64::consts::LOG10_2).floor() as i64;
    let k = digits as i64 + 3 - e.div_euclid(2);
    let scale = pow10(2 * k.unsigned_abs() as usize);
    if k >= 0 {
        let root = (n * scale / d).sqrt();
        Q::from_parts(root.into(), pow10(k as usize))
    } else {
        let root = (n / (d * scale)).sqrt();
        Q::from(root * pow10(k.unsigned_abs() as usize))
    }
}

pub use crate::values::rational::{from_f64, to_f64};

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Q {
        crate::values::rational::ratio(n, d)
    }

    #[test]
    fn exact_values_print_as_fractions_or_exact_decimals() {
        // Fractions throughout (issue 15: no -0.25 beside -1/3), a long one with a short
        // decimal as the decimal.
        assert_eq!(Exact::Rational(q(4, 3)).show(), "4/3");
        assert_eq!(Exact::Rational(q(70, 3)).show(), "70/3");
        assert_eq!(Exact::Rational(q(-1, 5)).show(), "-1/5");
        assert_eq!(Exact::Rational(q(27075, 4)).show(), "27075/4");
        let tiny = Q::from_parts(IBig::from(21), pow10(32));
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
    fn powers_of_five_are_recognised_at_any_length() {
        for k in [0usize, 1, 2, 3, 26, 27, 28, 100, 1000, 4321] {
            let p = UBig::from(5u8).pow(k);
            assert_eq!(power_of_five(&p), Some(k), "5^{k}");
            assert_eq!(power_of_five(&(&p * UBig::from(3u8))), None, "3 5^{k}");
            assert_eq!(power_of_five(&(&p + UBig::ONE)), None, "5^{k} + 1");
        }
        // 1/(2^3 5^1000) = 2^997 / 10^1000: 1000 places; 1/(3 5^1000) has none.
        let d = UBig::from(8u8) * UBig::from(5u8).pow(1000);
        let t = terminating_decimal(&Q::from_parts(IBig::ONE, d), usize::MAX).unwrap();
        let digits = UBig::from(2u8).pow(997).to_string();
        assert_eq!(t, format!("0.{digits:0>1000}"));
        let d = UBig::from(3u8) * UBig::from(5u8).pow(1000);
        assert_eq!(
            terminating_decimal(&Q::from_parts(IBig::ONE, d), usize::MAX),
            None
        );
        assert_eq!(terminating_decimal(&q(1, 8), 5), Some("0.125".into()));
        assert_eq!(terminating_decimal(&q(1, 8), 4), None);
        assert_eq!(terminating_decimal(&q(-12345, 1), 5), None);
        assert_eq!(fraction_within(&q(-12345, 7), 8), Some("-12345/7".into()));
        assert_eq!(fraction_within(&q(-12345, 7), 7), None);
        assert_eq!(fraction_within(&Q::from(pow10(50)), 50), None);
        assert_eq!(
            fraction_within(&Q::from(pow10(50)), 51).map(|f| f.len()),
            Some(51)
        );
    }

    #[test]
    fn long_terminating_values_in_exact_scientific_notation() {
        assert_eq!(
            scientific(&Q::from(pow10(154) * UBig::from(2u8)), 40).as_deref(),
            Some("2e154")
        );
        let tiny = -Q::from_parts(IBig::from(125), pow10(305));
        assert_eq!(scientific(&tiny, 40).as_deref(), Some("-1.25e-303"));
        assert_eq!(scientific(&q(1234, 10), 40).as_deref(), Some("1.234e2"));
        assert_eq!(scientific(&q(1, 3), 40), None);
        assert_eq!(scientific(&q(1, 1024), 5), None);
        // A solved or converted value: a short decimal, else exact scientific, else a fraction.
        assert_eq!(number_of(&q(1, 100)).unwrap().to_string(), "0.01");
        assert_eq!(number_of(&tiny).unwrap().to_string(), "-1.25e-303");
        assert_eq!(number_of(&q(5, 3)).unwrap().to_string(), "5/3");
    }

    #[test]
    fn significant_digits() {
        assert_eq!(significant(&q(1, 3), 5), "0.33333");
        assert_eq!(significant(&q(200, 3), 5), "66.666");
        assert_eq!(nearest(&q(200, 3), 5), "66.667");
        // An approximation of 8 from below prints 8; the exact value truncated keeps its side.
        let below = q(8, 1) - Q::from_parts(IBig::ONE, pow10(38));
        assert_eq!(nearest(&below, 20), "8");
        assert_eq!(significant(&below, 20), "7.9999999999999999999");
        assert_eq!(nearest(&q(-99999, 10000), 3), "-10");
        assert_eq!(nearest(&q(99999, 1), 3), "100000");
        assert_eq!(nearest(&q(-12345, 10000), 3), "-1.23");
        assert_eq!(nearest(&q(-1235, 1000), 3), "-1.24");
        assert_eq!(significant(&q(7, 1), 20), "7");
        assert_eq!(significant(&q(-1, 1000000), 3), "-1e-6");
        let big = Q::from(pow10(400) * UBig::from(3u8));
        assert_eq!(significant(&big, 4), "3e400");
    }

    #[test]
    fn square_roots_to_twenty_digits() {
        // sqrt(14500/4) = 60.20797289396147740064... (Python's decimal module, 40 digits):
        // lecture Fig. 1.3's IN ellipse radius a. Trailing zeros are not printed.
        let r = sqrt(&q(14500, 4), 30);
        assert_eq!(significant(&r, 20), "60.2079728939614774");
        assert_eq!(nearest(&r, 20), "60.207972893961477401");
        assert_eq!(
            significant(&sqrt(&q(2, 1), 25), 20),
            "1.4142135623730950488"
        );
        assert_eq!(sqrt(&q(9, 4), 10), q(3, 2));
        // Long and huge operands: only the digits asked for are computed, truncated (sqrt(10) =
        // 3.16227766016837933199889...; rounded, the twentieth digit goes up).
        let big = Q::from(pow10(4000) * UBig::from(2u8));
        assert_eq!(
            significant(&sqrt(&big, 25), 20),
            "1.4142135623730950488e2000"
        );
        let small = Q::from_parts(IBig::from(2), pow10(4000));
        assert_eq!(
            significant(&sqrt(&small, 25), 20),
            "1.4142135623730950488e-2000"
        );
        let long = Q::from_parts(IBig::from(pow10(3001)) + IBig::ONE, pow10(3000));
        assert_eq!(significant(&sqrt(&long, 25), 20), "3.1622776601683793319");
        assert_eq!(nearest(&sqrt(&long, 25), 20), "3.162277660168379332");
    }
}
