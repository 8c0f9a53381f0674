//! Numbers as a homework writes them: integers, decimals, scientific notation (`1e-3`) and simple
//! fractions (`2/3`). Each keeps the text it was typed as, so exact arithmetic can start from what
//! the user wrote rather than from its rounded binary64 value.

use std::fmt;
use std::str::FromStr;

use crate::values::rational::{IBig, Q, from_f64, pow10, to_f64};

/// Decimal exponents beyond this are refused outright: they are far outside binary64 and would
/// only cost memory in exact arithmetic.
const MAX_EXPONENT: i64 = 9999;

/// The parts of a fraction may be larger (`1e9999/1e10000` is 0.1; a value solved in exact
/// arithmetic from long decimals has long parts): the fraction's value must be in range.
const MAX_PART_EXPONENT: i64 = 100_000;

/// The longest number read, in characters: longer ones are refused at once (README "Limits").
pub const MAX_CHARS: usize = 10_000;

/// The longest typed number `--exact` computes with, in characters: exact arithmetic grows
/// faster than the length (1,000 digits: about 7 ms for the default report, 15 ms for every
/// section as text and JSON; `cargo bench --bench exact`).
pub const EXACT_MAX_CHARS: usize = 1_000;

/// A typed number too long for exact arithmetic.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "--exact: '{start}...' has {chars} characters; exact arithmetic reads at most \
     {EXACT_MAX_CHARS} per typed number (its cost grows faster than the length): shorten it, or \
     drop --exact (binary64 reads up to {MAX_CHARS})"
)]
pub struct ExactTooLong {
    pub start: String,
    pub chars: usize,
}

/// Refuses a typed number longer than `EXACT_MAX_CHARS` for exact arithmetic.
pub fn check_exact_length<'a>(
    numbers: impl IntoIterator<Item = &'a Number>,
) -> Result<(), ExactTooLong> {
    for n in numbers {
        if let Some(t) = &n.text
            && t.len() > EXACT_MAX_CHARS
        {
            return Err(ExactTooLong {
                start: t.chars().take(20).collect(),
                chars: t.chars().count(),
            });
        }
    }
    Ok(())
}

/// A finite number with the text it came from (none for a number made from a binary64, whose
/// text is its shortest round-trip decimal, derived when asked for).
#[derive(Clone, Debug)]
pub struct Number {
    value: f64,
    text: Option<Box<str>>,
    /// Solved rather than typed (`Number::solved`): headers show its decimal, not its fraction.
    derived: bool,
    /// A problem's unknown, solved (`Number::answer`), not a unit conversion: `--exact`
    /// headers show its fraction, as `Solved:` does.
    answer: bool,
}

/// Equal value and text (whether typed or solved does not matter).
impl PartialEq for Number {
    fn eq(&self, other: &Number) -> bool {
        self.value == other.value && self.text == other.text
    }
}

/// Text as it may be quoted in a message: control characters escaped (`'5\u{7}'` for a BEL),
/// so none is lost (a terminal, or clap's rendering, drops them) or sent to the terminal.
pub fn printable(text: &str) -> String {
    text.chars()
        .map(|c| {
            if c.is_control() {
                c.escape_default().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
}

/// Why a text is not a number. Quoted values are shown with [`printable`].
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum NumberError {
    #[error("an empty value is not a number: expected {EXPECTED}")]
    Empty,
    #[error("'{}' is not a number: expected {EXPECTED}", printable(.0))]
    Syntax(String),
    #[error("'{}' divides by zero", printable(.0))]
    ZeroDenominator(String),
    #[error("'{}' is too large for binary64 (|x| must be below 1.8e308)", printable(.0))]
    Overflow(String),
    #[error(
        "'{}' is too small for binary64 (it rounds to 0; |x| must be above 4.9e-324)",
        printable(.0)
    )]
    Underflow(String),
    /// A fraction whose numerator or denominator has a decimal exponent beyond
    /// [`MAX_PART_EXPONENT`] (whatever the fraction's value).
    #[error(
        "'{}': the numerator and denominator of a fraction are read up to decimal exponents of \
         +-{MAX_PART_EXPONENT} (each of about that many digits at most); write it with smaller \
         exponents (1e100000/1e99999 as 10/1)",
        printable(.0)
    )]
    PartExponent(String),
    #[error(
        "'{}...' is a number of {chars} characters: at most {MAX_CHARS} are read (see the \
         README's limits)",
        printable(.start)
    )]
    TooLong { start: String, chars: usize },
}

const EXPECTED: &str = "an integer, a decimal, scientific notation (1e-3) or a fraction (2/3)";

/// A parsed decimal `(-1)^negative * digits * 10^exp10`.
struct Decimal {
    negative: bool,
    digits: IBig,
    exp10: i64,
}

impl Decimal {
    fn parse(s: &str) -> Option<Decimal> {
        let (negative, rest) = match s.as_bytes().first()? {
            b'-' => (true, &s[1..]),
            b'+' => (false, &s[1..]),
            _ => (false, s),
        };
        let (mantissa, exponent) = match rest.find(['e', 'E']) {
            Some(i) => (&rest[..i], Some(&rest[i + 1..])),
            None => (rest, None),
        };
        let (int, frac) = match mantissa.find('.') {
            Some(i) => (&mantissa[..i], &mantissa[i + 1..]),
            None => (mantissa, ""),
        };
        let all_digits = |t: &str| t.bytes().all(|b| b.is_ascii_digit());
        if int.len() + frac.len() == 0 || !all_digits(int) || !all_digits(frac) {
            return None;
        }
        let mut exp10: i64 = match exponent {
            None => 0,
            Some(e) => {
                let digits = e.strip_prefix(['+', '-']).unwrap_or(e);
                if digits.is_empty() || !all_digits(digits) {
                    return None;
                }
                // Saturate: anything past MAX_EXPONENT is refused below anyway.
                let magnitude = digits.trim_start_matches('0').parse::<i64>().unwrap_or(
                    if digits.trim_start_matches('0').is_empty() {
                        0
                    } else {
                        i64::MAX / 4
                    },
                );
                if e.starts_with('-') {
                    -magnitude
                } else {
                    magnitude
                }
            }
        };
        exp10 -= frac.len() as i64;
        let digits: IBig = format!("{int}{frac}").parse().unwrap_or_default();
        Some(Decimal {
            negative,
            digits,
            exp10,
        })
    }

    fn is_zero(&self) -> bool {
        self.digits.is_zero()
    }

    /// Order of magnitude of the value, roughly: number of digits plus the exponent.
    fn magnitude(&self) -> i64 {
        self.digits.to_string().len() as i64 + self.exp10
    }

    fn to_rational(&self) -> Q {
        let scale = pow10(self.exp10.unsigned_abs() as usize);
        let mut r = if self.exp10 >= 0 {
            Q::from(&self.digits * scale)
        } else {
            Q::from_parts(self.digits.clone(), scale)
        };
        if self.negative {
            r = -r;
        }
        r
    }
}

fn check_range(d: &Decimal, text: &str, limit: i64) -> Result<(), NumberError> {
    if !d.is_zero() && d.magnitude() > limit {
        return Err(NumberError::Overflow(text.to_string()));
    }
    if !d.is_zero() && d.magnitude() < -limit {
        return Err(NumberError::Underflow(text.to_string()));
    }
    Ok(())
}

/// A fraction's part within the exponents read (the limit is on the part, not on a value).
fn check_part(d: &Decimal, text: &str) -> Result<(), NumberError> {
    if !d.is_zero() && d.magnitude().abs() > MAX_PART_EXPONENT {
        return Err(NumberError::PartExponent(text.to_string()));
    }
    Ok(())
}

impl Number {
    /// The nearest binary64 to the typed value.
    pub fn value(&self) -> f64 {
        self.value
    }

    /// The text as typed (trimmed), or the shortest decimal of a binary64-born number.
    pub fn text(&self) -> std::borrow::Cow<'_, str> {
        match &self.text {
            Some(t) => std::borrow::Cow::Borrowed(t),
            None => std::borrow::Cow::Owned(format!("{:?}", self.value)),
        }
    }

    /// The typed value as an exact rational (a binary64-born number: its exact binary value).
    pub fn exact(&self) -> Q {
        let Some(text) = &self.text else {
            return from_f64(self.value);
        };
        // The text was validated when this Number was made, so both parses succeed.
        match text.split_once('/') {
            Some((n, d)) => match (Decimal::parse(n), Decimal::parse(d)) {
                (Some(n), Some(d)) => n.to_rational() / d.to_rational(),
                _ => Q::ZERO,
            },
            None => Decimal::parse(text)
                .map(|d| d.to_rational())
                .unwrap_or_default(),
        }
    }

    /// Exactly the given binary64 value, which must be finite; no allocation.
    pub fn from_f64(value: f64) -> Result<Number, NumberError> {
        if value.is_finite() {
            Ok(Number {
                value,
                text: None,
                derived: false,
                answer: false,
            })
        } else {
            Err(NumberError::Syntax(format!("{value}")))
        }
    }

    /// For a header: the text as typed, or (a solved value that is a fraction, such as `e = 1/3`
    /// from final velocities, a unit conversion, a long typed value) its nearest binary64 in
    /// text digits, marked `≈`: exact fractions are for `--exact`'s own lines.
    pub fn brief(&self) -> String {
        // A typed -0 (or -0.0, 0/-5) is 0: a header shows no sign on it.
        if self.value == 0.0 && self.exact().is_zero() {
            return "0".into();
        }
        let text = self.to_string();
        let fraction = text.contains('/') && (self.derived || text.len() > 24);
        if fraction || text.len() > 40 {
            format!("≈{}", num(self.value))
        } else {
            text
        }
    }

    /// Whether this value was solved rather than typed (`Number::solved`).
    pub fn is_derived(&self) -> bool {
        self.derived
    }

    /// The same value marked as the answer to a problem's unknown.
    pub fn answer(self) -> Number {
        Number {
            answer: true,
            ..self
        }
    }

    /// Whether this value answers a problem's unknown (`Number::answer`).
    pub fn is_answer(&self) -> bool {
        self.answer
    }

    /// The same binary64 value without its typed text (so a clone allocates nothing).
    pub fn untyped(&self) -> Number {
        Number {
            value: self.value,
            text: None,
            derived: false,
            answer: false,
        }
    }

    /// Whether two numbers have the same exact value.
    pub fn same_value(&self, other: &Number) -> bool {
        // Different nearest binary64 values mean different exact values; equal ones need the
        // exact comparison only when a typed text is involved and the texts differ.
        self.value == other.value
            && match (&self.text, &other.text) {
                (None, None) => true,
                (Some(a), Some(b)) if a == b => true,
                _ => self.exact() == other.exact(),
            }
    }
}

impl FromStr for Number {
    type Err = NumberError;

    fn from_str(s: &str) -> Result<Number, NumberError> {
        Number::parse_text(s, true)
    }
}

impl Number {
    /// A value solved in exact arithmetic, from its decimal or fraction text: no length limit
    /// (that is for typed text), but it must be a binary64 number.
    pub fn solved(text: &str) -> Result<Number, NumberError> {
        Number::parse_text(text, false)
    }

    fn parse_text(s: &str, typed: bool) -> Result<Number, NumberError> {
        let text = s.trim();
        if text.is_empty() {
            return Err(NumberError::Empty);
        }
        if typed && text.len() > MAX_CHARS {
            return Err(NumberError::TooLong {
                start: text.chars().take(20).collect(),
                chars: text.chars().count(),
            });
        }
        let syntax = || NumberError::Syntax(text.to_string());
        let value = match text.split_once('/') {
            None => {
                let d = Decimal::parse(text).ok_or_else(syntax)?;
                check_range(&d, text, MAX_EXPONENT)?;
                let v: f64 = text.parse().map_err(|_| syntax())?;
                if v.is_infinite() {
                    return Err(NumberError::Overflow(text.to_string()));
                }
                if v == 0.0 && !d.is_zero() {
                    return Err(NumberError::Underflow(text.to_string()));
                }
                v
            }
            Some((n, d)) => {
                let (n, d) = (n.trim(), d.trim());
                let n = Decimal::parse(n).ok_or_else(syntax)?;
                let d = Decimal::parse(d).ok_or_else(syntax)?;
                check_part(&n, text)?;
                check_part(&d, text)?;
                if d.is_zero() {
                    return Err(NumberError::ZeroDenominator(text.to_string()));
                }
                // The nearest binary64 to the exact ratio (ties to even).
                let v = to_f64(&(n.to_rational() / d.to_rational())).unwrap_or(f64::INFINITY);
                if v.is_infinite() {
                    return Err(NumberError::Overflow(text.to_string()));
                }
                if v == 0.0 && !n.is_zero() {
                    return Err(NumberError::Underflow(text.to_string()));
                }
                v
            }
        };
        Ok(Number {
            value,
            text: Some(text.into()),
            derived: !typed,
            answer: false,
        })
    }
}

impl fmt::Display for Number {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.text {
            Some(t) => f.write_str(t),
            None => f.write_str(&num(self.value)),
        }
    }
}

/// A binary64 as people read it: rounded to the text digits (`--sig`, 15 by default), then its
/// shortest round-trip digits, plain for `1e-5 <= |x| < 1e16` and in scientific notation outside.
/// With `--sig N` typed, exactly N digits, trailing zeros kept (`padded`).
pub fn num(x: f64) -> String {
    let digits = TEXT_DIGITS.load(std::sync::atomic::Ordering::Relaxed);
    let rounded = round_significant(x, digits);
    if TEXT_PADDED.load(std::sync::atomic::Ordering::Relaxed) {
        padded(rounded, digits)
    } else {
        num_full(rounded)
    }
}

/// `x` to exactly `digits` significant digits, trailing zeros kept as a book prints them
/// (issue 45 §5: 0.15 to 3 digits is `0.150`, 0.087 is `0.0870`, 6 is `6.00`; 7250 to 3 is
/// `7250`), plain for `1e-5 <= |x| < 1e16` and `d.dde±x` outside, as `num_full`. The digits are
/// Rust's correctly rounded ones of the binary64 `x`, which for `x` rounded by
/// `round_significant` to at most 15 digits are that decimal's. 0 and `digits` 0 (`--sig full`)
/// are `num_full`'s.
pub fn padded(x: f64, digits: u8) -> String {
    if digits == 0 || x == 0.0 || !x.is_finite() {
        return num_full(x);
    }
    let sci = format!("{:.*e}", usize::from(digits) - 1, x);
    let Some((mantissa, exponent)) = sci.split_once('e') else {
        return num_full(x);
    };
    let Ok(exponent) = exponent.parse::<i32>() else {
        return num_full(x);
    };
    if !(1e-5..1e16).contains(&x.abs()) {
        return sci;
    }
    let sign = if x < 0.0 { "-" } else { "" };
    let all: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    match usize::try_from(exponent) {
        // 1 <= |x|: the first exponent + 1 digits before the point, zeros if they run out.
        Ok(e) if all.len() <= e + 1 => format!("{sign}{all}{}", "0".repeat(e + 1 - all.len())),
        Ok(e) => format!("{sign}{}.{}", &all[..=e], &all[e + 1..]),
        // |x| < 1: zeros after the point up to the first digit.
        Err(_) => format!(
            "{sign}0.{}{all}",
            "0".repeat(exponent.unsigned_abs() as usize - 1)
        ),
    }
}

/// `num` without rounding: the shortest round-trip digits whatever `--sig` says (a scene check's
/// actual value, where a near miss must not print as the expected value).
pub fn num_full(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 {
        "0".to_string()
    } else if (1e-5..1e16).contains(&a) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Significant digits of numbers in text for people (`--sig`): 15 by default, what spreadsheets
/// show, so `0.6320687500000001` reads `0.63206875`; 0 means the shortest round-trip form
/// (`--sig full`). JSON and tables always carry the full binary64 value.
static TEXT_DIGITS: std::sync::atomic::AtomicU8 = std::sync::atomic::AtomicU8::new(15);

/// Whether `--sig N` was typed: then text prints exactly N digits, trailing zeros kept
/// (`padded`); the default 15 digits print the shortest form, `0.15`.
static TEXT_PADDED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Sets the significant digits of text output, as `--sig` asks (1..=17, printed with trailing
/// zeros; 0 for the shortest round-trip form).
pub fn set_text_digits(digits: u8) {
    TEXT_DIGITS.store(digits.min(17), std::sync::atomic::Ordering::Relaxed);
    TEXT_PADDED.store(digits != 0, std::sync::atomic::Ordering::Relaxed);
}

/// `x` rounded to `digits` significant decimal digits (0: unchanged), as the nearest binary64
/// of that decimal, so its shortest form has at most `digits` digits. The rounding is the
/// textbook's: half away from zero, on the decimal people read (the shortest round-trip digits
/// of `x`, when they end one digit past the cut), so 0.125 to 2 digits is 0.13, 0.145 is 0.15
/// and 7.105e8 to 3 is 7.11e8 (issue 27; Rust's own formatting rounds exact ties to even and
/// 0.145 by its binary value: 0.12, 0.14, 7.10e8); otherwise by the exact binary value.
pub fn round_significant(x: f64, digits: u8) -> f64 {
    if digits == 0 || digits >= 17 || x == 0.0 || !x.is_finite() {
        return x;
    }
    let shortest = format!("{:e}", x.abs());
    let Some((mantissa, exponent)) = shortest.split_once('e') else {
        return x;
    };
    let Ok(mut exponent) = exponent.parse::<i32>() else {
        return x;
    };
    let all: Vec<u8> = mantissa.bytes().filter(u8::is_ascii_digit).collect();
    let n = usize::from(digits);
    if all.len() <= n {
        return x;
    }
    if all.len() > n + 1 || all.len() > 15 {
        // More digits than one past the cut: the binary64 is no tie there, and its exact
        // value decides. So do 16 or 17 shortest digits, a computed value's rather than a
        // decimal anyone typed or reads as one (3.4641016151377548 is shortest
        // 3.464101615137755, yet to 15 digits it is ...775): the default 15 digits are
        // unchanged.
        return finite_or(format!("{:.*e}", n - 1, x).parse().unwrap_or(x), x);
    }
    let mut kept = all[..n].to_vec();
    if all[n] >= b'5' {
        // Carry from the last kept digit; 9.99 -> 10.0 moves the exponent.
        let mut i = n;
        loop {
            if i == 0 {
                kept.insert(0, b'1');
                kept.pop();
                exponent += 1;
                break;
            }
            i -= 1;
            if kept[i] == b'9' {
                kept[i] = b'0';
            } else {
                kept[i] += 1;
                break;
            }
        }
    }
    let sign = if x < 0.0 { "-" } else { "" };
    let rest = std::str::from_utf8(&kept[1..]).unwrap_or("0");
    finite_or(
        format!("{sign}{}.{rest}0e{exponent}", char::from(kept[0]))
            .parse()
            .unwrap_or(x),
        x,
    )
}

/// `rounded`, unless rounding carried it past binary64's largest value (1.7976931348623157e308
/// to 15 digits is 1.79769313486232e308, which reads as infinity): then `x` as it is.
fn finite_or(rounded: f64, x: f64) -> f64 {
    if rounded.is_finite() { rounded } else { x }
}

/// A value a problem gives, or `?` for one it asks for, or (for a mass) a wall.
#[derive(Clone, Debug, PartialEq)]
pub enum Given<T> {
    Known(T),
    Unknown,
    /// An immovable body (`wall`, `inf`): a mass too large to be moved by anything.
    Wall,
}

impl<T> Given<T> {
    /// Parses `?` as unknown, anything else with `parse`.
    pub fn parse<E>(text: &str, parse: impl FnOnce(&str) -> Result<T, E>) -> Result<Given<T>, E> {
        if text.trim() == "?" {
            Ok(Given::Unknown)
        } else {
            parse(text).map(Given::Known)
        }
    }

    /// Parses `wall`, `floor`, `ceiling`, `inf`, `infinity` or `∞` as an immovable body, else
    /// as `parse`.
    pub fn parse_mass<E>(
        text: &str,
        parse: impl FnOnce(&str) -> Result<T, E>,
    ) -> Result<Given<T>, E> {
        let t = text.trim().to_ascii_lowercase();
        if ["wall", "inf", "infinity", "∞", "floor", "ceiling"].contains(&t.as_str()) {
            Ok(Given::Wall)
        } else {
            Given::parse(text, parse)
        }
    }

    pub fn known(&self) -> Option<&T> {
        match self {
            Given::Known(t) => Some(t),
            Given::Unknown | Given::Wall => None,
        }
    }

    pub fn is_wall(&self) -> bool {
        matches!(self, Given::Wall)
    }

    pub fn is_unknown(&self) -> bool {
        matches!(self, Given::Unknown)
    }

    pub fn map<U>(self, f: impl FnOnce(T) -> U) -> Given<U> {
        match self {
            Given::Known(t) => Given::Known(f(t)),
            Given::Unknown => Given::Unknown,
            Given::Wall => Given::Wall,
        }
    }
}

/// A list with the wrong number of comma-separated fields.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("expected {expected} comma-separated {what}, got {got} in '{text}'")]
pub struct FieldsError {
    pub expected: usize,
    pub got: usize,
    pub what: String,
    pub text: String,
}

/// Splits `a,b,...` into exactly `N` trimmed fields; `what` names them in the error.
pub fn split_fields<'a, const N: usize>(
    text: &'a str,
    what: &str,
) -> Result<[&'a str; N], FieldsError> {
    let fields: Vec<&str> = text.split(',').map(str::trim).collect();
    let got = fields.len();
    fields.try_into().map_err(|_| FieldsError {
        expected: N,
        got,
        what: what.to_string(),
        text: text.trim().to_string(),
    })
}

/// A comma-separated list of numbers (`-x 1,2.5,4` for a track), as typed.
#[derive(Clone, Debug, PartialEq)]
pub struct NumberList(pub Vec<Number>);

impl FromStr for NumberList {
    type Err = NumberError;
    fn from_str(s: &str) -> Result<NumberList, NumberError> {
        s.split(',')
            .map(str::parse)
            .collect::<Result<_, _>>()
            .map(NumberList)
    }
}

/// Deserializes a value written as a TOML/JSON number or string through its `FromStr`: an
/// integer as its digits, a float as the shortest decimal that rounds to it (which is what was
/// typed), a string as it is. One rule for every typed value of a scene (numbers, restitutions,
/// frames); `expecting` says what the value should be.
pub fn deserialize_parsed<'de, T, D>(d: D, expecting: &'static str) -> Result<T, D::Error>
where
    T: FromStr,
    T::Err: fmt::Display,
    D: serde::Deserializer<'de>,
{
    struct V<T>(&'static str, std::marker::PhantomData<T>);
    impl<T: FromStr> serde::de::Visitor<'_> for V<T>
    where
        T::Err: fmt::Display,
    {
        type Value = T;
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            f.write_str(self.0)
        }
        fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<T, E> {
            v.to_string().parse().map_err(E::custom)
        }
        fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<T, E> {
            v.to_string().parse().map_err(E::custom)
        }
        fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<T, E> {
            format!("{v:?}").parse().map_err(E::custom)
        }
        fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<T, E> {
            v.parse().map_err(E::custom)
        }
    }
    d.deserialize_any(V(expecting, std::marker::PhantomData))
}

/// Serde support: a number may be written as a TOML/JSON integer, float or string ("2/3").
impl<'de> serde::Deserialize<'de> for Number {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Number, D::Error> {
        deserialize_parsed(d, "a number, or a string holding one such as \"2/3\"")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn significant_digits_round_half_away_from_zero() {
        // Ties in the decimal people read go away from zero (the textbook's rule), others to
        // the nearest; carries move the exponent.
        for (x, d, want) in [
            (0.125, 2, 0.13),
            (-0.125, 2, -0.13),
            (7.105e8, 3, 7.11e8),
            (0.145, 2, 0.15),
            (2.5, 1, 3.0),
            (0.124, 2, 0.12),
            (9.995, 3, 10.0),
            (-9.96e-300, 2, -1.0e-299),
            (6.79e-17, 3, 6.79e-17),
            (1.0 / 3.0, 15, 0.333333333333333),
            (0.6320687500000001, 15, 0.63206875),
            (12f64.sqrt().hypot(0.0), 15, 3.46410161513775),
            (3.464_101_615_137_755, 15, 3.46410161513775),
        ] {
            assert_eq!(round_significant(x, d), want, "{x} to {d}");
        }
        assert_eq!(round_significant(0.1 + 0.2, 0), 0.1 + 0.2);
        // Rounding up past the largest binary64 would read as infinity: the value stays.
        assert_eq!(round_significant(f64::MAX, 15), f64::MAX);
        assert_eq!(super::num(-f64::MAX), "-1.7976931348623157e308");
        assert_eq!(round_significant(1.7e308, 15), 1.7e308);
    }

    fn num(s: &str) -> f64 {
        s.parse::<Number>().unwrap().value()
    }

    #[test]
    fn homework_forms() {
        assert_eq!(num("60"), 60.0);
        assert_eq!(num("-4"), -4.0);
        assert_eq!(num("+4"), 4.0);
        assert_eq!(num("0.5"), 0.5);
        assert_eq!(num(".5"), 0.5);
        assert_eq!(num("1e-3"), 1e-3);
        assert_eq!(num("2.5E+2"), 250.0);
        assert_eq!(num("2/3"), 2.0 / 3.0);
        assert_eq!(num(" -1/4 "), -0.25);
        assert_eq!(num("1e300"), 1e300);
    }

    #[test]
    fn a_fraction_is_the_nearest_binary64_to_the_exact_quotient() {
        // 0.1/0.3 is exactly 1/3; dividing the rounded 0.1 by the rounded 0.3 gives 0.33333333333333337.
        assert_eq!(num("0.1/0.3"), 1.0 / 3.0);
        assert_ne!(0.1 / 0.3, 1.0 / 3.0);
    }

    #[test]
    fn exact_values_come_from_the_text() {
        let r = "0.1".parse::<Number>().unwrap().exact();
        assert_eq!(r, crate::values::rational::ratio(1, 10));
        let r = "-2/3".parse::<Number>().unwrap().exact();
        assert_eq!(r, crate::values::rational::ratio(-2, 3));
        let r = "1.5e2".parse::<Number>().unwrap().exact();
        assert_eq!(r, crate::values::rational::int(150));
    }

    #[test]
    fn refusals_say_why() {
        for bad in [
            "abc", "", "1,2", "inf", "NaN", "1e", "--1", "1..2", "0x10", "1/", "e5", ".",
        ] {
            assert!(bad.parse::<Number>().is_err(), "{bad} should be refused");
        }
        assert!(matches!(
            "1/0".parse::<Number>(),
            Err(NumberError::ZeroDenominator(_))
        ));
        assert!(matches!(
            "1e400".parse::<Number>(),
            Err(NumberError::Overflow(_))
        ));
        assert!(matches!(
            "1e-400".parse::<Number>(),
            Err(NumberError::Underflow(_))
        ));
        assert!(matches!(
            "1e999999999999999999999".parse::<Number>(),
            Err(NumberError::Overflow(_))
        ));
        let msg = "abc".parse::<Number>().unwrap_err().to_string();
        assert!(msg.contains("'abc'") && msg.contains("fraction"), "{msg}");
    }

    #[test]
    fn zero_is_fine() {
        assert_eq!(num("0"), 0.0);
        assert_eq!(num("0e-99999999"), 0.0);
        assert_eq!(num("0/5"), 0.0);
    }

    #[test]
    fn fields() {
        assert_eq!(split_fields::<2>(" 4 , 1", "masses").unwrap(), ["4", "1"]);
        let err = split_fields::<2>("4,1,2", "masses").unwrap_err();
        assert_eq!(
            err.to_string(),
            "expected 2 comma-separated masses, got 3 in '4,1,2'"
        );
    }
}
