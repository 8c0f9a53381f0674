//! Speeds from heights and slides (`height 2 m` is the speed `sqrt(2 g h)` of a fall from rest
//! through it, `slide 5 cm mu 0.62` the speed `sqrt(2 mu g d)` friction stops in that distance),
//! and heights from speeds (`--show heights`, `h = v^2 / 2g`), exact.

use super::case_units::Units;
use super::measure::{Quantity, QuantityError, parse_plain};
use super::number::{Number, NumberError};
use super::rational::Q;
use super::unit_table::{Dimension, Unit, lookup};

/// The standard acceleration of gravity, 9.80665 m/s^2 (CGPM 1901), exact by definition.
pub const STANDARD_GRAVITY: &str = "9.80665";

impl Quantity {
    /// A height as the speed of a fall from rest through it (or needed to rise it),
    /// `sqrt(2 g h)` in m/s with the height's sign, and whether that speed is exact: when `2 g h`
    /// is the square of a rational (g = 10, h = 0.2 m: 2 m/s) the speed is that rational;
    /// otherwise it is irrational, and `2 g h` is computed exactly and given a binary64 root
    /// scaled by an even power of two (`rational::sqrt_binary64`: within an ulp of the exact
    /// speed, whatever the size of `2 g h`). Other quantities are
    /// returned as they are (exact).
    pub fn with_gravity(&self, g: &Q) -> Result<(Quantity, bool), NumberError> {
        if !self.height {
            return Ok((self.clone(), true));
        }
        let h = self.number.exact();
        let two_gh = crate::values::rational::int(2) * g * num_traits::Signed::abs(&h);
        let negative = h < Q::ZERO;
        let speed_unit = lookup("m/s", Dimension::Velocity).ok();
        if let Some(root) = crate::values::rational::sqrt_exact(&two_gh) {
            let speed = if negative { -root } else { root };
            let quantity = Quantity {
                number: crate::values::quantity::number_of(&speed)?,
                unit: speed_unit,
                height: false,
            };
            return Ok((quantity, true));
        }
        let what = || {
            format!(
                "sqrt(2 g h) for h = {} m, g = {} m/s^2",
                crate::values::quantity::significant(&num_traits::Signed::abs(&h), 15),
                crate::values::quantity::significant(g, 15)
            )
        };
        let speed =
            crate::values::quantity::to_f64(&crate::values::rational::sqrt_binary64(&two_gh))
                .ok_or_else(|| NumberError::Overflow(what()))?;
        if speed == 0.0 {
            return Err(NumberError::Underflow(what()));
        }
        let speed = if negative { -speed } else { speed };
        let quantity = Quantity {
            number: Number::from_f64(speed)?,
            unit: speed_unit,
            height: false,
        };
        Ok((quantity, false))
    }
}

/// How speeds become heights, `h = v^2 / 2g` (`--show heights`): `g` in m/s^2 and the size of
/// the case's velocity unit in m/s (1 when velocities have no unit: they are taken as m/s).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HeightScale {
    pub g: Q,
    pub velocity_si: Q,
    /// Whether the velocities had no unit (so were taken as m/s).
    pub assumed: bool,
}

impl HeightScale {
    /// For a case in `units`, with `g` (default: standard gravity).
    pub fn new(g: Option<&Number>, units: &Units) -> HeightScale {
        let g = g.map_or_else(
            || {
                STANDARD_GRAVITY
                    .parse::<Number>()
                    .map(|n| n.exact())
                    .unwrap_or_default()
            },
            Number::exact,
        );
        let unit = units
            .velocity
            .and_then(|n| lookup(n, Dimension::Velocity).ok());
        HeightScale {
            g,
            velocity_si: unit.map_or_else(|| crate::values::rational::int(1), Unit::si),
            assumed: unit.is_none(),
        }
    }
    /// `v^2 / 2g` in metres, exact.
    pub fn height(&self, v: &Q) -> Q {
        let v = v * &self.velocity_si;
        &v * &v / (crate::values::rational::int(2) * &self.g)
    }
    /// `g` as a decimal.
    pub fn g_text(&self) -> String {
        crate::values::quantity::terminating_decimal(&self.g, usize::MAX)
            .unwrap_or_else(|| crate::values::quantity::fraction(&self.g))
    }
}

/// A slide whose friction is the unknown (issue 42 section 5): `slide 20 cm mu ?`, or a bare
/// `slide 20 cm` whose mu is the floor's (`--friction`). The distance in metres, signed as the
/// motion is (`-slide 2 ft mu ?` slides towards -x), and whether it was bare; `None` when `t` is
/// no such slide (a known `slide D mu MU` is a speed, `parse_height`).
pub fn unknown_slide(t: &str) -> Option<Result<(Q, bool), QuantityError>> {
    let t = t.trim();
    let (negative, rest) = match t.strip_prefix('-') {
        Some(r) => (true, r.trim_start()),
        None => (false, t.strip_prefix('+').unwrap_or(t).trim_start()),
    };
    let slide = rest.strip_prefix("slide")?;
    let (d, bare) = match slide.split_once(" mu ").or_else(|| slide.split_once(" μ ")) {
        Some((d, mu)) if mu.trim() == "?" => (d, false),
        Some(_) => return None,
        None => (slide, true),
    };
    Some((|| {
        let q = parse_plain(d, Dimension::Length)?;
        let unit = q
            .unit
            .map_or_else(|| crate::values::rational::int(1), Unit::si);
        let metres = q.number.exact() * unit;
        if metres <= Q::ZERO {
            return Err(QuantityError::Slide(t.to_string()));
        }
        Ok((if negative { -metres } else { metres }, bare))
    })())
}

/// `height 2 m`, `-height 6 ft` (a speed from a height, signed): the height in metres, exact.
/// `slide 5 cm mu 0.62` (a speed that friction `mu` stops within a distance `d`: `sqrt(2 mu g d)`,
/// issue 27 §1) is the height `mu d`, since `v^2 = 2 g (mu d)`.
pub(crate) fn parse_height(t: &str) -> Option<Result<Quantity, QuantityError>> {
    let (sign, rest) = match t.strip_prefix('-') {
        Some(r) => ("-", r.trim_start()),
        None => ("", t.strip_prefix('+').unwrap_or(t).trim_start()),
    };
    let is_slide = rest.starts_with("slide");
    let (rest, mu) = match rest.strip_prefix("slide") {
        Some(slide) => {
            let Some((d, mu)) = slide.split_once(" mu ").or_else(|| slide.split_once(" μ "))
            else {
                return Some(Err(QuantityError::Slide(t.to_string())));
            };
            match mu.trim().parse::<Number>() {
                Ok(mu) if mu.exact() > Q::ZERO => (d, mu.exact()),
                _ => return Some(Err(QuantityError::Slide(t.to_string()))),
            }
        }
        None => (
            rest.strip_prefix("height")?,
            crate::values::rational::int(1),
        ),
    };
    Some((|| {
        let q = parse_plain(rest, Dimension::Length)?;
        let unit = q
            .unit
            .map_or_else(|| crate::values::rational::int(1), Unit::si);
        let metres = q.number.exact() * unit * mu;
        if metres < Q::ZERO && is_slide {
            return Err(QuantityError::Slide(t.to_string()));
        }
        if metres < Q::ZERO {
            return Err(QuantityError::NegativeHeight(t.to_string()));
        }
        let text = format!("{sign}{}", crate::values::quantity::fraction(&metres));
        // A height out of range is named as typed and in metres, not by its hundreds of digits.
        let number = text.parse().map_err(|e| match e {
            NumberError::Overflow(_) | NumberError::Underflow(_) => QuantityError::HeightRange {
                typed: t.to_string(),
                metres: crate::values::quantity::significant(&metres, 6),
            },
            other => other.into(),
        })?;
        Ok(Quantity {
            number,
            unit: None,
            height: true,
        })
    })())
}
