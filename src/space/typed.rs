//! Velocities as homework types them in the plane or in space: components `(4,1)`,
//! `(4,1,0) m/s`, polar `6 m/s @ 30deg`, compass bearings `15 m/s @ N30E`, and unknowns: `?` (the
//! whole vector), `? @ 30deg` (the speed), `5.2 m/s @ ?` (the direction), `(?,3)` (a component).
//! Bodies are separated by commas at the top level; commas inside parentheses belong to the
//! vector: `-v '(4,1),(-1,0.5)'`. A plain number is a velocity on a line (one dimension).

use crate::values::number::{Given, Number, NumberError};
use crate::values::units::{
    Dimension, Pair, PairError, Quantity, QuantityError, Unit, lookup, parse as parse_quantity,
    parse_pair,
};

use super::angle::{Angle, AngleError};

/// A velocity as typed.
#[derive(Clone, Debug, PartialEq)]
pub enum Typed {
    /// A number (with a unit, or a height), or `?`: on a line, or a whole unknown vector; a
    /// bare `0` is also the zero vector of any dimension.
    Scalar(Given<Quantity>),
    /// `(a,b[,c]) [unit]`.
    Components {
        parts: Vec<Given<Number>>,
        unit: Option<&'static Unit>,
    },
    /// `speed [unit] @ angle`, in the plane.
    Polar {
        speed: Given<Quantity>,
        angle: Given<Angle>,
    },
}

/// Why a text is not a velocity or a list of them.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TypedError {
    #[error("'{0}': a '(' without its ')'")]
    Unbalanced(String),
    #[error("'{text}': a vector has 2 or 3 components, got {got}")]
    Size { text: String, got: usize },
    #[error("'{text}': component {error}")]
    Component { text: String, error: NumberError },
    #[error("'{text}': {error}")]
    Quantity { text: String, error: QuantityError },
    #[error(transparent)]
    Angle(#[from] AngleError),
    #[error("'{0}': after the ')' only a unit may follow (e.g. '(4,1) m/s')")]
    AfterParen(String),
    #[error(
        "velocities mix dimensions ({0}): give every body's velocity as a vector of the same \
         size, or every one as a number (a bare 0 is the zero vector)"
    )]
    Mixed(String),
    #[error("an empty value in '{0}': separate the bodies with one comma")]
    Empty(String),
}

/// Splits a list of bodies at the commas outside parentheses.
pub fn split_bodies(text: &str) -> Result<Vec<&str>, TypedError> {
    let mut out = Vec::new();
    let mut depth = 0i32;
    let mut start = 0;
    for (i, c) in text.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' if depth == 0 => {
                out.push(text[start..i].trim());
                start = i + 1;
            }
            _ => {}
        }
        if depth < 0 {
            return Err(TypedError::Unbalanced(text.trim().to_string()));
        }
    }
    if depth != 0 {
        return Err(TypedError::Unbalanced(text.trim().to_string()));
    }
    out.push(text[start..].trim());
    if out.iter().any(|s| s.is_empty()) {
        return Err(TypedError::Empty(text.trim().to_string()));
    }
    Ok(out)
}

/// Whether a list of bodies is more than the two numbers of a 1D two-body case: a vector, a
/// polar velocity, or a count other than two.
pub fn is_spatial(text: &str) -> bool {
    split_bodies(text).is_ok_and(|b| b.len() > 2 || b.iter().any(|s| s.contains(['(', '@'])))
}

impl Typed {
    /// Parses one body's velocity.
    pub fn parse(text: &str) -> Result<Typed, TypedError> {
        let t = text.trim();
        if let Some(rest) = t.strip_prefix('(') {
            let close = rest
                .find(')')
                .ok_or_else(|| TypedError::Unbalanced(t.to_string()))?;
            let inside = &rest[..close];
            let after = rest[close + 1..].trim();
            let parts: Vec<&str> = inside.split(',').map(str::trim).collect();
            if !(2..=3).contains(&parts.len()) {
                return Err(TypedError::Size {
                    text: t.to_string(),
                    got: parts.len(),
                });
            }
            let parts = parts
                .iter()
                .map(|p| {
                    Given::parse(p, str::parse::<Number>).map_err(|error| TypedError::Component {
                        text: t.to_string(),
                        error,
                    })
                })
                .collect::<Result<Vec<_>, _>>()?;
            let unit = if after.is_empty() {
                None
            } else if after.starts_with(|c: char| c.is_alphabetic() || c == 'µ') {
                Some(
                    lookup(after, Dimension::Velocity).map_err(|e| TypedError::Quantity {
                        text: t.to_string(),
                        error: e.into(),
                    })?,
                )
            } else {
                return Err(TypedError::AfterParen(t.to_string()));
            };
            return Ok(Typed::Components { parts, unit });
        }
        let quantity = |s: &str| {
            Given::parse(s, |s| parse_quantity(s, Dimension::Velocity)).map_err(|error| {
                TypedError::Quantity {
                    text: t.to_string(),
                    error,
                }
            })
        };
        if let Some((speed, angle)) = t.split_once('@') {
            let angle = Given::parse(angle, str::parse::<Angle>)?;
            return Ok(Typed::Polar {
                speed: quantity(speed)?,
                angle,
            });
        }
        Ok(Typed::Scalar(quantity(t)?))
    }

    /// The dimension this velocity fixes: 1 for a number, the component count, 2 for polar;
    /// `None` for `?` and a bare 0 (any dimension).
    pub fn dimension(&self) -> Option<usize> {
        match self {
            Typed::Scalar(Given::Known(q)) if q.number.value() == 0.0 && q.unit.is_none() => None,
            Typed::Scalar(Given::Known(_)) => Some(1),
            Typed::Scalar(_) => None,
            Typed::Components { parts, .. } => Some(parts.len()),
            Typed::Polar { .. } => Some(2),
        }
    }
}

/// Parses a list of bodies' velocities.
pub fn parse_list(text: &str) -> Result<Vec<Typed>, TypedError> {
    split_bodies(text)?.into_iter().map(Typed::parse).collect()
}

/// The one dimension every velocity of the lists agrees on (1 when none fixes it).
pub fn dimension<'a>(lists: impl IntoIterator<Item = &'a Typed>) -> Result<usize, TypedError> {
    let mut seen: Vec<usize> = lists.into_iter().filter_map(Typed::dimension).collect();
    seen.sort_unstable();
    seen.dedup();
    match seen.as_slice() {
        [] => Ok(1),
        [d] => Ok(*d),
        many => Err(TypedError::Mixed(
            many.iter()
                .map(|d| match d {
                    1 => "numbers".to_string(),
                    d => format!("{d}-vectors"),
                })
                .collect::<Vec<_>>()
                .join(" and "),
        )),
    }
}

/// A list of bodies' masses or velocities as typed on the command line: two numbers of a
/// collision on a line (`pair`), or any other list (N bodies, vectors), kept as text and read by
/// the plane-and-space solver.
#[derive(Clone, Debug, PartialEq)]
pub struct Listed {
    pub text: String,
    pub pair: Option<Pair>,
}

/// Why a list of masses or velocities is not one.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ListedError {
    #[error(transparent)]
    Pair(#[from] PairError),
    #[error(transparent)]
    Typed(#[from] TypedError),
    #[error("{0}")]
    Mass(String),
}

impl Listed {
    /// Two plain values (`4,1`, `?,10 mph`) as a pair, as always; anything else checked as a
    /// list of bodies.
    pub fn parse(text: &str, dimension: Dimension, what: &str) -> Result<Listed, ListedError> {
        let t = text.trim().to_string();
        if !is_spatial(text) {
            return Ok(Listed {
                pair: Some(parse_pair(text, dimension, what)?),
                text: t,
            });
        }
        match dimension {
            Dimension::Mass => {
                parse_masses(text)?;
            }
            _ => {
                parse_list(text)?;
            }
        }
        Ok(Listed {
            text: t,
            pair: None,
        })
    }
}

/// `M1,M2,...`: masses with optional units, `?` for unknown ones, `wall` for an immovable body.
pub fn parse_masses(text: &str) -> Result<Vec<Given<Quantity>>, ListedError> {
    split_bodies(text)?
        .into_iter()
        .map(|s| {
            Given::parse_mass(s, |s| parse_quantity(s, Dimension::Mass)).map_err(|e| {
                let e = e.to_string();
                ListedError::Mass(if e.starts_with('\'') {
                    format!("mass {e}")
                } else {
                    e
                })
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bodies_split_outside_parentheses() {
        assert_eq!(
            split_bodies("(4,1),(-1,0.5)").unwrap(),
            vec!["(4,1)", "(-1,0.5)"]
        );
        assert_eq!(split_bodies("1,2,3").unwrap(), vec!["1", "2", "3"]);
        assert!(split_bodies("(4,1").is_err());
        assert!(split_bodies("4,,1").is_err());
        assert!(is_spatial("(4,1),0"));
        assert!(is_spatial("1,2,3"));
        assert!(!is_spatial("1"));
        assert!(is_spatial("6 m/s @ 30deg,0"));
        assert!(!is_spatial("60 mph,10 mph"));
    }

    #[test]
    fn vectors_polar_bearings_and_unknowns() {
        let Typed::Components { parts, unit } = Typed::parse("(4,1,0) m/s").unwrap() else {
            panic!()
        };
        assert_eq!(parts.len(), 3);
        assert_eq!(unit.map(Unit::name), Some("m/s"));
        let Typed::Components { parts, .. } = Typed::parse("(?,3)").unwrap() else {
            panic!()
        };
        assert!(parts[0].is_unknown());
        let Typed::Polar { speed, angle } = Typed::parse("15 m/s @ N30E").unwrap() else {
            panic!()
        };
        assert_eq!(speed.known().unwrap().number.value(), 15.0);
        assert_eq!(angle.known().unwrap().typed, "N30E");
        let Typed::Polar { speed, angle } = Typed::parse("? @ 30deg").unwrap() else {
            panic!()
        };
        assert!(speed.is_unknown() && angle.known().is_some());
        let Typed::Polar { angle, .. } = Typed::parse("5.2 m/s @ ?").unwrap() else {
            panic!()
        };
        assert!(angle.is_unknown());
        assert_eq!(Typed::parse("?").unwrap(), Typed::Scalar(Given::Unknown));
    }

    #[test]
    fn bad_vectors_are_named() {
        let e = Typed::parse("(1,2,3,4)").unwrap_err().to_string();
        assert!(e.contains("2 or 3 components, got 4"), "{e}");
        let e = Typed::parse("(1,x)").unwrap_err().to_string();
        assert!(e.contains("'x' is not a number"), "{e}");
        let e = Typed::parse("(1,2) mhp").unwrap_err().to_string();
        assert!(e.contains("did you mean 'mph'"), "{e}");
        let e = Typed::parse("3 @ 30").unwrap_err().to_string();
        assert!(e.contains("give its unit"), "{e}");
        let list = parse_list("(1,2),(1,2,3)").unwrap();
        let e = dimension(&list).unwrap_err().to_string();
        assert!(e.contains("2-vectors and 3-vectors"), "{e}");
        assert_eq!(dimension(&parse_list("(1,2),0").unwrap()).unwrap(), 2);
        assert_eq!(dimension(&parse_list("1,2,3").unwrap()).unwrap(), 1);
    }
}
