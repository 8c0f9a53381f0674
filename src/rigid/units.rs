//! Quantities of a rigid body as typed: masses, lengths and velocities with the units of the rest
//! of collide (`0.05 kg`, `1.2 m`, `(3,-4) m/s`), angular velocities (`20 rad/s`, `300 rpm`,
//! `5 rev/s`, `90 deg/s`) and moments of inertia (`0.12 kg m^2`, `50 g cm^2`). Numbers and
//! units are split by the values layer's one parser (`values::units::split_number`: `1e-3 m` is
//! a millimetre), and a velocity or a length in the plane may be typed as `size @ angle` with
//! the plane's angles and compass bearings (`20 m/s @ 30deg`, `5 m/s @ N30E`; `Angle::along`),
//! so a string means the same here as on a line and in the plane.
//!
//! A rigid case mixes lengths with velocities and spins (`v + omega x r`), so its units are
//! resolved together: a case without any unit is computed in the numbers as typed (consistent
//! units, spins in radians per time unit); a case with a unit anywhere is converted exactly to SI
//! (kg, m, m/s, rad/s, kg m^2), and every other non-zero value must carry a unit too. Turns
//! (`rpm`, `rev/s`) and degrees are irrational in radians: their values are the binary64 of
//! `pi` times the exact rest, marked approximate.

use crate::space::angle::{Angle, AngleError};
use crate::values::number::{Number, NumberError};
use crate::values::rational::{Q, from_f64, int, ratio, to_f64};
use crate::values::units::{Dimension, QuantityError, lookup, split_number};

/// What a typed value measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Measure {
    Mass,
    Length,
    Velocity,
    /// Angular velocity.
    Spin,
    /// Moment of inertia.
    Inertia,
}

impl Measure {
    pub fn name(self) -> &'static str {
        match self {
            Measure::Mass => "mass",
            Measure::Length => "length",
            Measure::Velocity => "velocity",
            Measure::Spin => "angular velocity",
            Measure::Inertia => "moment of inertia",
        }
    }

    /// The SI unit printed for it.
    pub fn si_name(self) -> &'static str {
        match self {
            Measure::Mass => "kg",
            Measure::Length => "m",
            Measure::Velocity => "m/s",
            Measure::Spin => "rad/s",
            Measure::Inertia => "kg m^2",
        }
    }
}

/// A unit: its name and size in SI, `pi^k` times an exact rational.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidUnit {
    pub name: &'static str,
    /// The size in SI without its factor of pi, as `n/d`.
    num: i64,
    den: i64,
    /// Whether the size has a factor of pi (turns and degrees in radians).
    pi: bool,
    /// Set for units from the common table, whose exact size it holds.
    common: Option<&'static crate::values::units::Unit>,
}

impl RigidUnit {
    /// The size in SI, and whether it is rounded (a factor of pi).
    pub fn si(&self) -> (Q, bool) {
        if let Some(u) = self.common {
            return (u.si(), false);
        }
        let base = ratio(self.num, self.den);
        if self.pi {
            (base * pi(), true)
        } else {
            (base, false)
        }
    }
}

/// The binary64 of pi, exactly, as the one factor turns and degrees carry (so a value typed in
/// rpm comes back in rpm as typed).
pub fn pi() -> Q {
    from_f64(std::f64::consts::PI)
}

/// Angular velocities (`rad/s` first: the SI unit).
const SPIN_UNITS: &[(&[&str], i64, i64, bool)] = &[
    (&["rad/s"], 1, 1, false),
    (&["rpm", "rev/min"], 1, 30, true),
    (&["rev/s", "rps", "Hz"], 2, 1, true),
    (&["deg/s", "°/s"], 1, 180, true),
];

/// Moments of inertia (`kg m^2` first), spellings with a space, `*`, `.` or `·` and `^2` or `²`.
const INERTIA_UNITS: &[(&str, i64, i64)] = &[
    ("kg m^2", 1, 1),
    ("g cm^2", 1, 10_000_000),
    ("kg cm^2", 1, 10_000),
    ("g m^2", 1, 1_000),
    ("lb ft^2", 421_401_100_938_048, 10_000_000_000_000_000),
];

/// `kg*m^2`, `kg·m²`, `kg.m^2` all as `kg m^2`.
fn canonical_inertia(name: &str) -> String {
    name.replace(['*', '·', '.'], " ")
        .replace('²', "^2")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// Why a typed rigid-body value is not one.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RigidUnitError {
    #[error("{what} '{text}': {error}")]
    Number {
        what: String,
        text: String,
        error: NumberError,
    },
    #[error("{what} '{text}': {error}")]
    Quantity {
        what: String,
        text: String,
        error: QuantityError,
    },
    #[error("{what} '{text}': unknown {} unit '{unit}' (known: {known})", .measure.name())]
    Unit {
        what: String,
        text: String,
        measure: Measure,
        unit: String,
        known: String,
    },
    #[error(
        "{what} '{text}': expected a vector of {expected} components '(a,b{})' with an optional \
         unit after the ')'", if *.expected == 3 { ",c" } else { "" }
    )]
    Vector {
        what: String,
        text: String,
        expected: usize,
    },
    #[error("{what} '{text}': {error}")]
    Angle {
        what: String,
        text: String,
        error: AngleError,
    },
    #[error(
        "{what} '{text}': a size along a direction must be >= 0 (a negative size is the \
         opposite direction)"
    )]
    NegativeSize { what: String, text: String },
    #[error(
        "--exact: {what} '{text}': cos and sin of {angle} are irrational, and exact arithmetic \
         holds rationals only: give it as components, e.g. '(4,3) m/s', or drop --exact"
    )]
    Irrational {
        what: String,
        text: String,
        angle: String,
    },
    #[error(
        "{what} '{text}' has no unit while other values have one: a rigid case with units is \
         computed in SI, so give every value its unit (e.g. '{example}'), or none"
    )]
    Bare {
        what: String,
        text: String,
        example: &'static str,
    },
}

/// A typed scalar: a number and its unit.
#[derive(Clone, Debug, PartialEq)]
pub struct Typed {
    pub number: Number,
    pub unit: Option<RigidUnit>,
    pub measure: Measure,
    /// The text, for messages.
    pub text: String,
}

/// A typed vector: its components and one unit, or a size and an angle in the plane
/// (`5 m/s @ 30deg`: `parts` is the one size, `angle` its direction).
#[derive(Clone, Debug, PartialEq)]
pub struct TypedVec {
    pub parts: Vec<Number>,
    pub unit: Option<RigidUnit>,
    pub measure: Measure,
    pub text: String,
    pub angle: Option<Angle>,
}

fn common_unit(name: &str, measure: Measure) -> Option<RigidUnit> {
    let dimension = match measure {
        Measure::Mass => Dimension::Mass,
        Measure::Length => Dimension::Length,
        Measure::Velocity => Dimension::Velocity,
        Measure::Spin | Measure::Inertia => return None,
    };
    lookup(name, dimension).ok().map(|u| RigidUnit {
        name: u.name(),
        num: 1,
        den: 1,
        pi: false,
        common: Some(u),
    })
}

/// The unit called `name` for `measure`.
fn unit(name: &str, measure: Measure) -> Option<RigidUnit> {
    match measure {
        Measure::Spin => SPIN_UNITS
            .iter()
            .find(|(names, ..)| names.contains(&name))
            .map(|(names, num, den, pi)| RigidUnit {
                name: names[0],
                num: *num,
                den: *den,
                pi: *pi,
                common: None,
            }),
        Measure::Inertia => {
            let c = canonical_inertia(name);
            INERTIA_UNITS
                .iter()
                .find(|(n, ..)| *n == c)
                .map(|(n, num, den)| RigidUnit {
                    name: n,
                    num: *num,
                    den: *den,
                    pi: false,
                    common: None,
                })
        }
        _ => common_unit(name, measure),
    }
}

fn known(measure: Measure) -> String {
    match measure {
        Measure::Spin => SPIN_UNITS
            .iter()
            .map(|(n, ..)| n[0])
            .collect::<Vec<_>>()
            .join(", "),
        Measure::Inertia => INERTIA_UNITS
            .iter()
            .map(|(n, ..)| *n)
            .collect::<Vec<_>>()
            .join(", "),
        Measure::Mass => "kg, g, t, lb, ...".into(),
        Measure::Length => "m, cm, mm, km, ft, in".into(),
        Measure::Velocity => "m/s, km/h, mph, ft/s, ...".into(),
    }
}

impl Typed {
    /// Parses `<number> [<unit>]` measuring `measure`; `what` names it in messages. The
    /// number and the unit are split as everywhere else (`split_number`).
    pub fn parse(text: &str, measure: Measure, what: &str) -> Result<Typed, RigidUnitError> {
        let t = text.trim();
        let (number, name) = split_number(t).map_err(|error| match error {
            QuantityError::Number(error) => RigidUnitError::Number {
                what: what.into(),
                text: t.into(),
                error,
            },
            error => RigidUnitError::Quantity {
                what: what.into(),
                text: t.into(),
                error,
            },
        })?;
        let unit = if name.is_empty() {
            None
        } else {
            Some(unit_named(name, measure, what, t)?)
        };
        Ok(Typed {
            number,
            unit,
            measure,
            text: t.into(),
        })
    }

    /// The value in the case's units: as typed (no units anywhere) or in SI; whether it is
    /// rounded (a factor of pi). `exact`: the typed value, else its binary64.
    pub fn value(&self, si: bool, exact: bool) -> Result<(Q, bool), RigidUnitError> {
        resolve(
            &self.number,
            self.unit.as_ref(),
            si,
            exact,
            (&self.text, self.measure),
        )
    }
}

/// The unit called `name` for `measure`, or an error naming the nearest ones (the common
/// table's suggestions for masses, lengths and velocities).
fn unit_named(
    name: &str,
    measure: Measure,
    what: &str,
    text: &str,
) -> Result<RigidUnit, RigidUnitError> {
    if let Some(u) = unit(name, measure) {
        return Ok(u);
    }
    let dimension = match measure {
        Measure::Mass => Some(Dimension::Mass),
        Measure::Length => Some(Dimension::Length),
        Measure::Velocity => Some(Dimension::Velocity),
        Measure::Spin | Measure::Inertia => None,
    };
    if let Some(Err(error)) = dimension.map(|d| lookup(name, d)) {
        return Err(RigidUnitError::Quantity {
            what: what.into(),
            text: text.into(),
            error: error.into(),
        });
    }
    Err(RigidUnitError::Unit {
        what: what.into(),
        text: text.into(),
        measure,
        unit: name.into(),
        known: known(measure),
    })
}

/// A typed number's value: `n` times its unit's size in SI when `si`, exact, or (`exact` false)
/// the binary64 nearest that product, as the plane converts (`values::units::resolve`: `10.8
/// km/h` is 3 m/s exactly, as typed, not the binary64 of 10.8 times 5/18). A unit with a factor
/// of pi (turns, degrees) multiplies the binary64 of `n` by the one pi, so `300 rpm` reads back
/// as 300.
fn resolve(
    n: &Number,
    unit: Option<&RigidUnit>,
    si: bool,
    exact: bool,
    (text, measure): (&str, Measure),
) -> Result<(Q, bool), RigidUnitError> {
    let binary64 = |q: Q| {
        if exact {
            q
        } else {
            to_f64(&q).map_or(q, from_f64)
        }
    };
    match (unit, si) {
        (Some(u), _) => match u.si() {
            (size, true) => Ok((binary64(n.exact()) * size, true)),
            (size, false) => Ok((binary64(n.exact() * size), false)),
        },
        (None, true) if n.value() != 0.0 => Err(RigidUnitError::Bare {
            what: measure.name().into(),
            text: text.into(),
            example: match measure {
                Measure::Mass => "0.05 kg",
                Measure::Length => "1.2 m",
                Measure::Velocity => "(3,-4) m/s",
                Measure::Spin => "20 rad/s",
                Measure::Inertia => "0.1 kg m^2",
            },
        }),
        _ => Ok((binary64(n.exact()), false)),
    }
}

impl TypedVec {
    /// Parses `(a,b[,c]) [unit]`, with `dims` the sizes allowed; a velocity or a length in the
    /// plane also as `size [unit] @ angle` (`20 m/s @ 30deg`, `5 m/s @ N30E`).
    pub fn parse(
        text: &str,
        measure: Measure,
        what: &str,
        dims: &[usize],
    ) -> Result<TypedVec, RigidUnitError> {
        let t = text.trim();
        let bad = || RigidUnitError::Vector {
            what: what.into(),
            text: t.into(),
            expected: *dims.last().unwrap_or(&2),
        };
        if let Some((size, angle)) = t.split_once('@')
            && matches!(measure, Measure::Velocity | Measure::Length)
            && dims.contains(&2)
        {
            let size = Typed::parse(size, measure, what)?;
            let angle = angle
                .parse::<Angle>()
                .map_err(|error| RigidUnitError::Angle {
                    what: what.into(),
                    text: t.into(),
                    error,
                })?;
            if size.number.value() < 0.0 {
                return Err(RigidUnitError::NegativeSize {
                    what: what.into(),
                    text: t.into(),
                });
            }
            return Ok(TypedVec {
                parts: vec![size.number],
                unit: size.unit,
                measure,
                text: t.into(),
                angle: Some(angle),
            });
        }
        let inner = t.strip_prefix('(').ok_or_else(bad)?;
        let (inside, after) = inner.split_once(')').ok_or_else(bad)?;
        let parts = inside
            .split(',')
            .map(|p| {
                p.trim()
                    .parse::<Number>()
                    .map_err(|error| RigidUnitError::Number {
                        what: what.into(),
                        text: t.into(),
                        error,
                    })
            })
            .collect::<Result<Vec<_>, _>>()?;
        if !dims.contains(&parts.len()) {
            return Err(bad());
        }
        let after = after.trim();
        let unit = if after.is_empty() {
            None
        } else {
            Some(unit_named(after, measure, what, t)?)
        };
        Ok(TypedVec {
            parts,
            unit,
            measure,
            text: t.into(),
            angle: None,
        })
    }

    /// How many components: 2 for `size @ angle`.
    pub fn dim(&self) -> usize {
        if self.angle.is_some() {
            2
        } else {
            self.parts.len()
        }
    }

    /// A vector of numbers (a TOML array) with no unit.
    pub fn plain(parts: Vec<Number>, measure: Measure) -> TypedVec {
        let text = format!(
            "({})",
            parts
                .iter()
                .map(Number::to_string)
                .collect::<Vec<_>>()
                .join(",")
        );
        TypedVec {
            parts,
            unit: None,
            measure,
            text,
            angle: None,
        }
    }

    /// The components in the case's units, and whether they are rounded (a factor of pi, or
    /// the cosine and sine of an angle that is not a multiple of 90 degrees: refused when
    /// `exact`).
    pub fn value(&self, si: bool, exact: bool) -> Result<(Vec<Q>, bool), RigidUnitError> {
        let mut rounded = false;
        let mut out = Vec::new();
        for p in &self.parts {
            let (q, r) = resolve(p, self.unit.as_ref(), si, exact, (&self.text, self.measure))?;
            rounded |= r;
            out.push(q);
        }
        if let (Some(angle), [size]) = (&self.angle, out.as_slice()) {
            let (parts, r) = angle.along(size);
            if r && exact {
                return Err(RigidUnitError::Irrational {
                    what: self.measure.name().into(),
                    text: self.text.clone(),
                    angle: angle.typed.clone(),
                });
            }
            return Ok((parts, rounded || r));
        }
        Ok((out, rounded))
    }

    pub fn has_unit(&self) -> bool {
        self.unit.is_some()
    }
}

/// Revolutions per minute of an angular velocity in rad/s (binary64, for text): `30 omega / pi`
/// with the same pi as the input, so `300 rpm` reads back as 300.
pub fn rpm(omega: &Q) -> Q {
    omega * int(30) / pi()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spins_and_inertias_in_si() {
        let t = Typed::parse("300 rpm", Measure::Spin, "spin").unwrap();
        let (q, rounded) = t.value(true, false).unwrap();
        assert!(rounded);
        assert_eq!(rpm(&q), int(300));
        let t = Typed::parse("50 g cm^2", Measure::Inertia, "inertia").unwrap();
        assert_eq!(t.value(true, true).unwrap(), (ratio(5, 1_000_000), false));
        let t = Typed::parse("2 kg·m²", Measure::Inertia, "inertia").unwrap();
        assert_eq!(t.value(true, true).unwrap().0, int(2));
        let t = Typed::parse("1.2 m", Measure::Length, "length").unwrap();
        assert_eq!(t.value(true, true).unwrap().0, ratio(6, 5));
        let t = Typed::parse("30 cm", Measure::Length, "length").unwrap();
        assert_eq!(t.value(true, true).unwrap().0, ratio(3, 10));
    }

    #[test]
    fn bare_values_beside_units_are_refused() {
        let t = Typed::parse("0.8", Measure::Length, "--hit-at").unwrap();
        let e = t.value(true, false).unwrap_err().to_string();
        assert!(e.contains("no unit while other values have one"), "{e}");
        assert!(t.value(false, false).is_ok());
        let zero = Typed::parse("0", Measure::Velocity, "v").unwrap();
        assert!(zero.value(true, false).is_ok());
    }

    #[test]
    fn vectors_and_bad_units() {
        let v = TypedVec::parse("(3,-4) m/s", Measure::Velocity, "v", &[2, 3]).unwrap();
        assert_eq!(v.value(true, true).unwrap().0, vec![int(3), int(-4)]);
        let e = TypedVec::parse("(1,2,3,4)", Measure::Length, "x", &[2, 3])
            .unwrap_err()
            .to_string();
        assert!(e.contains("expected a vector"), "{e}");
        let e = Typed::parse("3 rpn", Measure::Spin, "--spin")
            .unwrap_err()
            .to_string();
        assert!(e.contains("unknown angular velocity unit 'rpn'"), "{e}");
        let e = Typed::parse("3 mhp", Measure::Velocity, "-v")
            .unwrap_err()
            .to_string();
        assert!(e.contains("did you mean 'mph'"), "{e}");
    }
}
