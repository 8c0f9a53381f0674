//! A typed quantity: a number with an optional unit (`4 t`, `60mph`, `1e-3 m`), split by the one
//! parser every mode uses (`split_number`), and why a text is not one. Heights and slides
//! (`height 2 m`) are read on top of it (`heights`), a case's pair of them in `units`.

use crate::values::number::{Number, NumberError, printable};
use crate::values::rational::Q;
use crate::values::unit_table::{Dimension, Unit, UnitError, lookup};

/// A typed value: a number with an optional unit.
#[derive(Clone, Debug, PartialEq)]
pub struct Quantity {
    pub number: Number,
    pub unit: Option<&'static Unit>,
    /// A velocity typed as a height (`height 2 m`): `number` is the signed height in metres,
    /// to become the speed `sqrt(2 g h)` once `g` is known (`with_gravity`).
    pub height: bool,
}

/// Why a text is not a quantity.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum QuantityError {
    #[error(transparent)]
    Number(#[from] NumberError),
    #[error(transparent)]
    Unit(#[from] UnitError),
    #[error(
        "contact time '{}' must be above 0 (a duration such as '2 ms' or '0.01 s')",
        printable(.0)
    )]
    NotPositive(String),
    #[error(
        "'{}': a height must be >= 0; give the direction as a sign: '-height 2 m' (down)",
        printable(.0)
    )]
    NegativeHeight(String),
    #[error(
        "'{}': a speed from a slide is 'slide D mu MU' (the distance friction MU > 0 stops it \
         in, e.g. 'slide 5 cm mu 0.62': sqrt(2 mu g d)); a sign gives the direction",
        printable(.0)
    )]
    Slide(String),
    #[error(
        "'{}': the height is {metres} m (mu d for a slide), beyond binary64 (it must be below \
         1.8e308 m and above 4.9e-324 m)",
        printable(.typed)
    )]
    HeightRange { typed: String, metres: String },
    #[error("{0}")]
    Term(Box<BadTerm>),
    #[error(
        "'{}': give a unit to every part of a sum or to none ('60 kg + 10 kg', '1 kg + 500 g')",
        printable(.0)
    )]
    SumUnits(String),
}

/// A bad part of a sum (`'60 kg + 10 kgg': its part '10 kgg': ...`), boxed in
/// [`QuantityError::Term`] so that the error stays small.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("'{}': its part '{}': {error}", printable(.typed), printable(.part))]
pub struct BadTerm {
    pub typed: String,
    pub part: String,
    pub error: String,
}

/// Splits `4 t`, `60mph`, `12 N s` or `1e3` into its number and the rest (a unit name, trimmed;
/// empty for a plain number).
pub fn split_number(t: &str) -> Result<(Number, &str), QuantityError> {
    let t = t.trim();
    // A whole number (or one that is out of range, or divides by zero) has no unit: its own
    // error is the one to report.
    match t.parse::<Number>() {
        Ok(number) => {
            return Ok((number, ""));
        }
        Err(e) if !matches!(e, NumberError::Syntax(_)) => return Err(e.into()),
        Err(_) => {}
    }
    // The longest prefix that is a number, followed by a unit name. Only the places where a
    // unit could start are tried (before a space, a letter or `°`: `90°/s`), so a long text
    // costs one parse per such place, not one per character. The longest prefix that reads as
    // a number out of range is that number's error ('1e9999 m': too large, not the unit
    // 'e9999 m').
    let cut = (1..=t.len())
        .rev()
        .filter(|&i| {
            t.is_char_boundary(i)
                && t[i..]
                    .chars()
                    .next()
                    .is_none_or(|c| c.is_whitespace() || c.is_alphabetic() || c == '°')
        })
        .find_map(|i| match t[..i].parse::<Number>() {
            Ok(_) => Some(Ok(i)),
            Err(NumberError::Syntax(_) | NumberError::Empty) => None,
            Err(e) => Some(Err(e)),
        })
        .transpose()?;
    let Some(i) = cut else {
        // No number at all: the number parser says why.
        return Err(t
            .parse::<Number>()
            .err()
            .unwrap_or(NumberError::Empty)
            .into());
    };
    let number: Number = t[..i].parse()?;
    Ok((number, t[i..].trim()))
}

/// A number with an optional unit of `dimension` (no heights: `units::parse` reads those).
pub fn parse_plain(text: &str, dimension: Dimension) -> Result<Quantity, QuantityError> {
    let (number, rest) = split_number(text.trim())?;
    let unit = if rest.is_empty() {
        None
    } else {
        Some(lookup(rest, dimension)?)
    };
    Ok(Quantity {
        number,
        unit,
        height: false,
    })
}

/// A duration in seconds, exactly: `2 ms`, `0.5 s`, or a bare number of seconds; it must be
/// above 0 (`--contact-time`).
pub fn seconds(text: &str) -> Result<Q, QuantityError> {
    let q = parse_plain(text, Dimension::Time)?;
    let s = q.number.exact()
        * q.unit
            .map_or_else(|| crate::values::rational::int(1), Unit::si);
    if s <= Q::ZERO {
        return Err(QuantityError::NotPositive(text.trim().to_string()));
    }
    Ok(s)
}
