//! A case as the user gave it (numbers with their typed text), validated once, with its
//! binary64 collision.

use nalgebra::Vector2;

use crate::line::collision::Collision;
use crate::line::inertia::{InertiaError, InertiaTensor, Mass, MassError};
use crate::line::restitution::Restitution;
use crate::values::number::{FieldsError, Number, NumberError, split_fields};

/// A validated two-body case.
#[derive(Clone, Debug)]
pub struct Case {
    pub velocities: [Number; 2],
    pub collision: Collision,
    /// The units the numbers are in (none: as given).
    pub units: crate::values::units::Units,
}

impl Case {
    pub fn new(inertia: InertiaTensor, velocities: [Number; 2], restitution: Restitution) -> Case {
        let v = Vector2::new(velocities[0].value(), velocities[1].value());
        Case {
            velocities,
            collision: Collision::new(inertia, v, restitution),
            units: Default::default(),
        }
    }

    pub fn inertia(&self) -> &InertiaTensor {
        &self.collision.inertia
    }

    pub fn restitution(&self) -> &Restitution {
        &self.collision.restitution
    }

    /// Whether a value of the case was solved rather than typed (a homework problem's).
    pub fn solved(&self) -> bool {
        self.inertia()
            .entries()
            .iter()
            .flatten()
            .chain(&self.velocities)
            .chain([self.restitution().number()])
            .any(|n| n.is_derived())
    }

    /// Refuses typed numbers too long for exact arithmetic (`--exact`).
    pub fn check_exact(&self) -> Result<(), crate::values::number::ExactTooLong> {
        let m = self.inertia().entries();
        crate::values::number::check_exact_length(
            m.iter()
                .flatten()
                .chain(&self.velocities)
                .chain([self.restitution().number()]),
        )
    }
}

/// Why a text is not a case's masses, velocities or tensor.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CaseError {
    #[error(transparent)]
    Fields(#[from] FieldsError),
    #[error(transparent)]
    Mass(#[from] MassError),
    #[error("velocity {0}")]
    Velocity(NumberError),
    #[error("expected 2 rows separated by ';' (M11,M12;M21,M22), got {rows} in '{text}'")]
    Rows { rows: usize, text: String },
    #[error("inertia entry {0}")]
    Entry(NumberError),
    #[error(transparent)]
    Inertia(#[from] InertiaError),
}

/// `M1,M2` (as typed on the command line).
pub fn parse_masses(text: &str) -> Result<[Mass; 2], CaseError> {
    let [a, b] = split_fields::<2>(text, "masses M1,M2")?;
    Ok([a.parse()?, b.parse()?])
}

/// `V1,V2`.
pub fn parse_velocities(text: &str) -> Result<[Number; 2], CaseError> {
    let [a, b] = split_fields::<2>(text, "velocities V1,V2")?;
    let v = |s: &str| s.parse::<Number>().map_err(CaseError::Velocity);
    Ok([v(a)?, v(b)?])
}

/// `M11,M12;M21,M22`: a symmetric positive definite tensor.
pub fn parse_inertia(text: &str) -> Result<InertiaTensor, CaseError> {
    let rows: Vec<&str> = text.split(';').collect();
    let [r1, r2]: [&str; 2] = rows.try_into().map_err(|rows: Vec<&str>| CaseError::Rows {
        rows: rows.len(),
        text: text.trim().to_string(),
    })?;
    let row = |r: &str| -> Result<[Number; 2], CaseError> {
        let [a, b] = split_fields::<2>(r, "entries in each row of M11,M12;M21,M22")?;
        let n = |s: &str| s.parse::<Number>().map_err(CaseError::Entry);
        Ok([n(a)?, n(b)?])
    };
    Ok(InertiaTensor::general([row(r1)?, row(r2)?])?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_what_the_issue_shows() {
        let m = parse_masses("4,1").unwrap();
        assert_eq!((m[0].value(), m[1].value()), (4.0, 1.0));
        let v = parse_velocities("3,-4").unwrap();
        assert_eq!((v[0].value(), v[1].value()), (3.0, -4.0));
        let t = parse_inertia("4,0.5;0.5,1").unwrap();
        assert_eq!(t.matrix()[(0, 1)], 0.5);
    }

    #[test]
    fn names_the_bad_value() {
        let e = parse_masses("4,abc").unwrap_err().to_string();
        assert!(e.contains("'abc'"), "{e}");
        let e = parse_masses("4").unwrap_err().to_string();
        assert!(e.contains("expected 2") && e.contains("got 1"), "{e}");
        let e = parse_velocities("1,2,3").unwrap_err().to_string();
        assert!(e.contains("got 3"), "{e}");
        let e = parse_inertia("4,0.5;0.4,1").unwrap_err().to_string();
        assert!(e.contains("not symmetric"), "{e}");
        let e = parse_inertia("1,2;2,1").unwrap_err().to_string();
        assert!(e.contains("not positive definite"), "{e}");
        let e = parse_inertia("1,0").unwrap_err().to_string();
        assert!(e.contains("2 rows"), "{e}");
    }
}
