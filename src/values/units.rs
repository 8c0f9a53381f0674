//! Units (issue 8): a mass or velocity may be typed with a unit (`4 t`, `60mph`, `72 km/h`).
//! Numbers keep their units when all masses share one and all velocities share one; otherwise
//! (or with `--si`) everything is converted exactly to kg and m/s. The table of units is
//! `unit_table`, a typed quantity `measure`, a case's units `case_units`, heights `heights`;
//! this file reads a case's values with them (and re-exports them: one path for callers).

use crate::values::number::{FieldsError, Given, Number, NumberError, split_fields};
use crate::values::rational::{Q, int};

pub use super::case_units::{ENERGY_UNITS, EnergyUnit, EnergyUnitError, Units, energy_unit};
use super::heights::parse_height;
pub use super::heights::{HeightScale, STANDARD_GRAVITY};
use super::measure::BadTerm;
pub use super::measure::{Quantity, QuantityError, parse_plain, seconds, split_number};
pub use super::unit_table::{Dimension, UNITS, Unit, UnitError, lookup};

/// Splits `4 t`, `60mph`, `2/3 m/s` or `1e3` into a number and a unit name; a velocity may be
/// a height or a slide (`height 2 m`); any may be a sum of like quantities (`60 kg + 10 kg`).
pub fn parse(text: &str, dimension: Dimension) -> Result<Quantity, QuantityError> {
    let t = text.trim();
    if dimension == Dimension::Velocity
        && let Some(height) = parse_height(t)
    {
        return height;
    }
    match terms(t).as_slice() {
        [_] => parse_plain(t, dimension),
        terms => sum(t, terms, dimension),
    }
}

/// `text` cut at each `+` that adds: not a leading sign (`+4`), not an exponent's (`1e+3`).
fn terms(text: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut start = 0;
    for (i, _) in text.match_indices('+') {
        let before = &text[start..i];
        let b = before.as_bytes();
        // `1e+3`, `2.E+3`: a digit or point, an `e`, then the `+` with no space between.
        let exponent = b.len() >= 2
            && matches!(b[b.len() - 1], b'e' | b'E')
            && (b[b.len() - 2].is_ascii_digit() || b[b.len() - 2] == b'.');
        if before.trim().is_empty() || exponent {
            continue;
        }
        out.push(before);
        start = i + 1;
    }
    out.push(&text[start..]);
    out
}

/// A sum of like quantities, exactly, in the first part's unit (issue 45 §5: a rider and a
/// bike as one body, `60 kg + 10 kg`; `1 kg + 500 g` is 1.5 kg): every part with a unit or
/// none, each read as a value alone, a bad one named.
fn sum(text: &str, terms: &[&str], dimension: Dimension) -> Result<Quantity, QuantityError> {
    let parts = terms
        .iter()
        .map(|term| {
            parse_plain(term, dimension).map_err(|e| {
                QuantityError::Term(Box::new(BadTerm {
                    typed: text.to_string(),
                    part: term.trim().to_string(),
                    error: e.to_string(),
                }))
            })
        })
        .collect::<Result<Vec<Quantity>, _>>()?;
    let unit = parts[0].unit;
    if parts.iter().any(|q| q.unit.is_some() != unit.is_some()) {
        return Err(QuantityError::SumUnits(text.to_string()));
    }
    let si = |q: &Quantity| q.number.exact() * q.unit.map_or_else(|| int(1), Unit::si);
    let total = parts.iter().fold(Q::ZERO, |s, q| s + si(q));
    let total = match unit {
        Some(u) => total / u.si(),
        None => total,
    };
    // The sum of typed values is as typed (`70`, the same case as `70 kg` bit for bit); a
    // text too long to type stays a solved value.
    let solved = crate::values::quantity::number_of(&total)?;
    Ok(Quantity {
        number: solved.text().parse().unwrap_or(solved),
        unit,
        height: false,
    })
}

/// Why a case's units cannot be resolved.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ResolveError {
    #[error("give a unit for every {} or for none (some have one, some not)", .0.name())]
    Mixed(Dimension),
    #[error("--si needs a unit on every mass and velocity")]
    SiNeedsUnits,
    #[error("mixed units need a unit on every mass and velocity")]
    MixedNeedsUnits,
    #[error(transparent)]
    Number(#[from] NumberError),
}

/// Resolved masses and velocities, with their units.
pub type Resolved = (Vec<Given<Number>>, Vec<Given<Number>>, Units);

/// Resolves a case's quantities: keeps the numbers when all masses share a unit (or none has one)
/// and all velocities share one, unless `si`; otherwise converts everything exactly to kg and m/s.
/// `?` placeholders stay unknown.
pub fn resolve(
    masses: &[Given<Quantity>],
    velocities: &[Given<Quantity>],
    si: bool,
) -> Result<Resolved, ResolveError> {
    fn common(
        qs: &[Given<Quantity>],
        dimension: Dimension,
    ) -> Result<(bool, Option<&'static Unit>), ResolveError> {
        // A bare 0 is 0 in any unit (`72 km/h,0`).
        let given: Vec<&Quantity> = qs
            .iter()
            .filter_map(Given::known)
            .filter(|q| !(q.unit.is_none() && q.number.value() == 0.0))
            .collect();
        let with = given.iter().filter(|q| q.unit.is_some()).count();
        if with != 0 && with != given.len() {
            return Err(ResolveError::Mixed(dimension));
        }
        let first = given.iter().find_map(|q| q.unit);
        let shared = given
            .iter()
            .all(|q| q.unit.map(Unit::name) == first.map(Unit::name));
        Ok((shared, first))
    }
    let (mass_shared, mass_unit) = common(masses, Dimension::Mass)?;
    let (vel_shared, vel_unit) = common(velocities, Dimension::Velocity)?;
    let any_unit = mass_unit.is_some() || vel_unit.is_some();
    let convert = si || !mass_shared || !vel_shared;
    if convert && (mass_unit.is_none() || vel_unit.is_none()) {
        return Err(if si {
            ResolveError::SiNeedsUnits
        } else {
            ResolveError::MixedNeedsUnits
        });
    }
    let to = |qs: &[Given<Quantity>]| -> Result<Vec<Given<Number>>, ResolveError> {
        qs.iter()
            .map(|q| match q {
                Given::Unknown => Ok(Given::Unknown),
                Given::Wall => Ok(Given::Wall),
                Given::Known(q) if convert => {
                    let si = q.number.exact()
                        * q.unit
                            .map(Unit::si)
                            .unwrap_or_else(|| crate::values::rational::int(1));
                    // A decimal when the converted value has one (10 g is 0.01 kg, not 1/100).
                    Ok(Given::Known(crate::values::quantity::number_of(&si)?))
                }
                Given::Known(q) => Ok(Given::Known(q.number.clone())),
            })
            .collect()
    };
    let units = if convert {
        Units {
            mass: Some("kg"),
            velocity: Some("m/s"),
            energy_as: None,
        }
    } else if any_unit {
        Units {
            mass: mass_unit.map(Unit::name),
            velocity: vel_unit.map(Unit::name),
            energy_as: None,
        }
    } else {
        Units::default()
    };
    Ok((to(masses)?, to(velocities)?, units))
}

/// Two values as typed (`M1,M2`, `V1,V2`, `F1,F2`): numbers with optional units, or `?`.
#[derive(Clone, Debug, PartialEq)]
pub struct Pair(pub [Given<Quantity>; 2]);

/// Why a text is not a pair of quantities.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PairError {
    #[error(transparent)]
    Fields(#[from] FieldsError),
    /// A bad value, named by its dimension when the message starts with it (`mass 'abc' ...`).
    #[error("{}", value_message(*.dimension, .error))]
    Value {
        dimension: Dimension,
        error: QuantityError,
    },
}

fn value_message(dimension: Dimension, e: &QuantityError) -> String {
    let e = e.to_string();
    if e.starts_with('\'') {
        format!("{} {e}", dimension.name())
    } else {
        e
    }
}

/// Parses `a,b` where each is `?` or a number with an optional unit; `what` names them.
pub fn parse_pair(text: &str, dimension: Dimension, what: &str) -> Result<Pair, PairError> {
    let [a, b] = split_fields::<2>(text, what)?;
    let one = |t: &str| {
        let parsed = if dimension == Dimension::Mass {
            Given::parse_mass(t, |t| parse(t, dimension))
        } else {
            Given::parse(t, |t| parse(t, dimension))
        };
        parsed.map_err(|error| PairError::Value { dimension, error })
    };
    Ok(Pair([one(a)?, one(b)?]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parsing_quantities() {
        let q = parse("4 t", Dimension::Mass).unwrap();
        assert_eq!((q.number.value(), q.unit.map(Unit::name)), (4.0, Some("t")));
        let q = parse("60mph", Dimension::Velocity).unwrap();
        assert_eq!(
            (q.number.value(), q.unit.map(Unit::name)),
            (60.0, Some("mph"))
        );
        let q = parse("72 km/h", Dimension::Velocity).unwrap();
        assert_eq!(q.unit.map(Unit::name), Some("km/h"));
        let q = parse("2/3 m/s", Dimension::Velocity).unwrap();
        assert_eq!(q.number.value(), 2.0 / 3.0);
        let q = parse("1e3kg", Dimension::Mass).unwrap();
        assert_eq!(q.number.value(), 1000.0);
        assert_eq!(parse("4", Dimension::Mass).unwrap().unit, None);
        assert_eq!(
            parse("1 long ton", Dimension::Mass)
                .unwrap()
                .unit
                .map(Unit::name),
            Some("long ton")
        );
    }

    #[test]
    fn slides_are_heights_of_mu_d() {
        // 'slide 5 cm mu 0.62': v^2 = 2 mu g d = 2 g (0.62 0.05), the height 0.031 m, signed.
        let h = |t: &str| parse(t, Dimension::Velocity).map(|q| (q.number.exact(), q.height));
        let q = |s: &str| s.parse::<Number>().unwrap().exact();
        assert_eq!(h("slide 5 cm mu 0.62"), Ok((q("0.031"), true)));
        assert_eq!(h("-slide 2 ft mu 1/2"), Ok((q("-0.3048"), true)));
        for bad in [
            "slide 5 cm",
            "slide 5 cm mu 0",
            "slide -5 cm mu 1",
            "slide 5 kg mu 1",
        ] {
            assert!(h(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn unknown_and_ambiguous_units_say_what_to_write() {
        let e = parse("60 mhp", Dimension::Velocity)
            .unwrap_err()
            .to_string();
        assert!(e.contains("did you mean 'mph'"), "{e}");
        let e = parse("4 T", Dimension::Mass).unwrap_err().to_string();
        assert!(
            e.contains("ambiguous") && e.contains("'t'") && e.contains("'ton'"),
            "{e}"
        );
        let e = parse("4 mph", Dimension::Mass).unwrap_err().to_string();
        assert!(e.contains("unit of velocity, not of mass"), "{e}");
        let e = parse("abc", Dimension::Mass).unwrap_err().to_string();
        assert!(e.contains("'abc' is not a number"), "{e}");
    }

    #[test]
    fn resolution_keeps_shared_units_and_converts_mixed_ones() {
        let q = |s: &str, d| Given::Known(parse(s, d).unwrap());
        use Dimension::*;
        let (m, v, u) = resolve(
            &[q("4 ton", Mass), q("1 ton", Mass)],
            &[q("60 mph", Velocity), q("10 mph", Velocity)],
            false,
        )
        .unwrap();
        assert_eq!(m[0].known().unwrap().value(), 4.0);
        assert_eq!(v[1].known().unwrap().value(), 10.0);
        assert_eq!(u.energy(), "ton mph^2");
        // Mixed: 1500 kg and 1 t -> 1500 and 1000 kg; 72 km/h -> 20 m/s exactly.
        let (m, v, u) = resolve(
            &[q("1500 kg", Mass), q("1 t", Mass)],
            &[q("72 km/h", Velocity), q("0 km/h", Velocity)],
            false,
        )
        .unwrap();
        assert_eq!(
            (m[0].known().unwrap().value(), m[1].known().unwrap().value()),
            (1500.0, 1000.0)
        );
        assert_eq!(v[0].known().unwrap().value(), 20.0);
        assert_eq!(u.energy(), "J");
        // --si: 60 mph = 26.8224 m/s exactly.
        let (_, v, _) = resolve(
            &[q("4 t", Mass), q("1 t", Mass)],
            &[q("60 mph", Velocity), q("10 mph", Velocity)],
            true,
        )
        .unwrap();
        assert_eq!(
            v[0].known().unwrap().exact(),
            "26.8224".parse::<Number>().unwrap().exact()
        );
        let e = resolve(
            &[q("4 t", Mass), q("1", Mass)],
            &[q("1", Velocity), q("2", Velocity)],
            false,
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("every mass or for none"), "{e}");
        // A bare 0 takes any unit.
        let (_, v, u) = resolve(
            &[q("1500 kg", Mass), q("900 kg", Mass)],
            &[q("72 km/h", Velocity), q("0", Velocity)],
            false,
        )
        .unwrap();
        assert_eq!(
            (v[1].known().unwrap().value(), u.energy()),
            (0.0, "kg (km/h)^2".to_string())
        );
        let (_, _, u) = resolve(
            &[q("4", Mass), q("1", Mass)],
            &[q("1", Velocity), q("2", Velocity)],
            false,
        )
        .unwrap();
        assert_eq!(u.energy(), "mass unit x velocity unit^2");
    }
}
