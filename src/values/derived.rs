//! Values typed with a derived unit (issue 27 §1): an impulse (`12 N s`, `2.4 kg m/s`,
//! `3 ton mph`), an energy (`48 J`, `7.11e8 J`, `2 kJ`) and a spring constant (`200 N/m`,
//! `5 lbf/in`). Each is a number and, when a unit was typed, the unit's exact size in SI; a plain
//! number is in the case's own units (an impulse in mass unit x velocity unit, an energy in mass
//! unit x velocity unit^2), and a spring constant in N/m.

use crate::values::number::{Number, printable};
use crate::values::rational::{Q, int};
use crate::values::units::{Dimension, QuantityError, energy_unit, lookup, split_number};

/// What a derived value measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Momentum transferred, `N s = kg m/s` (`--impulse`).
    Impulse,
    /// Energy, `J` (`--released`).
    Energy,
    /// A spring constant, `N/m` (`--spring`).
    Stiffness,
}

impl Kind {
    /// The flag that takes it.
    pub fn flag(self) -> &'static str {
        match self {
            Kind::Impulse => "--impulse",
            Kind::Energy => "--released",
            Kind::Stiffness => "--spring",
        }
    }
    fn expected(self) -> &'static str {
        match self {
            Kind::Impulse => "N s, or a mass unit and a velocity unit ('kg m/s', 'g cm/s')",
            Kind::Energy => "J, kJ, eV, MeV, ft*lbf or cal",
            Kind::Stiffness => "N/m, kN/m, N/cm, N/mm, lbf/in or lbf/ft",
        }
    }
}

/// The pound-force in newtons, exact (0.45359237 kg x 9.80665 m/s^2).
const LBF: &str = "4.4482216152605";

/// Spring constants: names and size in N/m, exact.
const STIFFNESS: &[(&[&str], &str, &str)] = &[
    (&["N/m", "kg/s^2"], "1", "1"),
    (&["kN/m"], "1000", "1"),
    (&["N/cm"], "100", "1"),
    (&["N/mm"], "1000", "1"),
    (&["lbf/in"], LBF, "0.0254"),
    (&["lbf/ft"], LBF, "0.3048"),
];

/// A value as typed: its number, and the size of its unit in SI when one was typed.
#[derive(Clone, Debug, PartialEq)]
pub struct Derived {
    pub kind: Kind,
    pub number: Number,
    /// The unit's size in SI (N s, J, N/m); `None` for a plain number.
    pub unit_si: Option<Q>,
    /// As typed, for messages.
    pub text: String,
}

/// Why a text is not the derived value asked for, or cannot be used in the case.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DerivedError {
    #[error("{flag} '{}': {error}", printable(.text))]
    Number {
        flag: &'static str,
        text: String,
        error: QuantityError,
    },
    #[error("{flag} '{}': unknown unit '{}': expected {expected}", printable(.text), printable(.unit))]
    Unit {
        flag: &'static str,
        text: String,
        unit: String,
        expected: &'static str,
    },
    #[error(
        "{flag} '{}' has a unit, but {missing} do not: give them units too, or type {flag} as \
         a plain number in the case's units",
        printable(.text)
    )]
    NoCaseUnits {
        flag: &'static str,
        text: String,
        /// Which of the case's values have no unit ("the masses and velocities").
        missing: &'static str,
    },
    #[error("{flag} '{}' must be above 0", printable(.text))]
    NotPositive { flag: &'static str, text: String },
}

/// Parses `text` as a value of `kind`.
pub fn parse(text: &str, kind: Kind) -> Result<Derived, DerivedError> {
    let flag = kind.flag();
    let (number, unit) = split_number(text).map_err(|error| DerivedError::Number {
        flag,
        text: text.trim().to_string(),
        error,
    })?;
    let unit_si = if unit.is_empty() {
        None
    } else {
        Some(unit_size(unit, kind).ok_or_else(|| DerivedError::Unit {
            flag,
            text: text.trim().to_string(),
            unit: unit.to_string(),
            expected: kind.expected(),
        })?)
    };
    let derived = Derived {
        kind,
        number,
        unit_si,
        text: text.trim().to_string(),
    };
    if kind != Kind::Impulse && derived.number.exact() <= Q::ZERO {
        return Err(DerivedError::NotPositive {
            flag,
            text: derived.text,
        });
    }
    Ok(derived)
}

/// The size in SI of the unit named `unit` for `kind`.
fn unit_size(unit: &str, kind: Kind) -> Option<Q> {
    let exact = |s: &str| s.parse::<Number>().ok().map(|n| n.exact());
    match kind {
        Kind::Impulse => {
            let n = unit.replace(['*', '·', '.'], " ");
            let words: Vec<&str> = n.split_whitespace().collect();
            if matches!(words[..], ["N", "s"] | ["Ns"]) {
                return Some(int(1));
            }
            // A mass unit and a velocity unit: 'kg m/s', 'long ton mph'.
            (1..words.len()).find_map(|i| {
                let m = lookup(&words[..i].join(" "), Dimension::Mass).ok()?;
                let v = lookup(&words[i..].join(" "), Dimension::Velocity).ok()?;
                Some(m.si() * v.si())
            })
        }
        Kind::Energy => exact(energy_unit(unit).ok()?.joules),
        Kind::Stiffness => STIFFNESS
            .iter()
            .find(|(names, _, _)| names.contains(&unit))
            .and_then(|(_, n, d)| Some(exact(n)? / exact(d)?)),
    }
}

/// A length (`--length`): `5 m`, `80 cm`, `3 ft` (a plain number is metres), above 0, in
/// metres with the text as typed.
pub fn length(text: &str, flag: &'static str) -> Result<(Q, String), DerivedError> {
    let typed = text.trim().to_string();
    let q = crate::values::units::parse(text, Dimension::Length).map_err(|error| {
        DerivedError::Number {
            flag,
            text: typed.clone(),
            error,
        }
    })?;
    let metres = q.number.exact() * q.unit.map_or_else(|| int(1), |u| u.si());
    if metres <= Q::ZERO {
        return Err(DerivedError::NotPositive { flag, text: typed });
    }
    let shown = if q.unit.is_none() {
        format!("{typed} m")
    } else {
        typed
    };
    Ok((metres, shown))
}

impl Derived {
    /// The value in SI, taking a plain number as SI already.
    pub fn si(&self) -> Q {
        self.number.exact() * self.unit_si.clone().unwrap_or_else(|| int(1))
    }

    /// The value in the case's units, whose unit is `case_si` in SI (`None`: the case has no
    /// units, so a value typed with one cannot be placed in it).
    pub fn in_case(&self, case_si: Option<&Q>) -> Result<Q, DerivedError> {
        match (&self.unit_si, case_si) {
            (None, _) => Ok(self.number.exact()),
            (Some(u), Some(c)) => Ok(self.number.exact() * u / c),
            (Some(_), None) => Err(DerivedError::NoCaseUnits {
                flag: self.kind.flag(),
                text: self.text.clone(),
                missing: "the masses and velocities",
            }),
        }
    }

    /// As [`Derived::in_case`], for a case in `units`: an error names which of the masses and
    /// velocities have no unit (a `?` has none).
    pub fn in_units(
        &self,
        case_si: Option<&Q>,
        units: &crate::values::units::Units,
    ) -> Result<Q, DerivedError> {
        self.in_case(case_si).map_err(|e| match e {
            DerivedError::NoCaseUnits { flag, text, .. } => DerivedError::NoCaseUnits {
                flag,
                text,
                missing: match (units.mass, units.velocity) {
                    (Some(_), None) => "the velocities",
                    (None, Some(_)) => "the masses (a '?' has none)",
                    _ => "the masses and velocities",
                },
            },
            e => e,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(s: &str) -> Q {
        s.parse::<Number>().unwrap().exact()
    }

    #[test]
    fn units_by_hand() {
        // 12 N s is 12 kg m/s; 3 g cm/s is 3e-3 kg 1e-2 m/s = 3e-5 N s.
        assert_eq!(parse("12 N s", Kind::Impulse).unwrap().si(), q("12"));
        assert_eq!(parse("12 N*s", Kind::Impulse).unwrap().si(), q("12"));
        assert_eq!(parse("2.4 kg m/s", Kind::Impulse).unwrap().si(), q("2.4"));
        assert_eq!(parse("3 g cm/s", Kind::Impulse).unwrap().si(), q("3e-5"));
        assert_eq!(parse("-12 Ns", Kind::Impulse).unwrap().si(), q("-12"));
        // 48 J; 2 kJ = 2000 J; 1 cal = 4.184 J (thermochemical).
        assert_eq!(parse("48 J", Kind::Energy).unwrap().si(), q("48"));
        assert_eq!(parse("2 kJ", Kind::Energy).unwrap().si(), q("2000"));
        assert_eq!(
            parse("7.11e8 J", Kind::Energy).unwrap().si(),
            q("711000000")
        );
        // 200 N/m; 1 lbf/in = 4.4482216152605 / 0.0254 N/m = 175.126835246476... N/m.
        assert_eq!(parse("200 N/m", Kind::Stiffness).unwrap().si(), q("200"));
        assert_eq!(
            parse("1 lbf/in", Kind::Stiffness).unwrap().si(),
            q("4.4482216152605") / q("0.0254")
        );
        // Plain numbers: no unit; in the case's units as typed.
        let j = parse("12/5", Kind::Impulse).unwrap();
        assert_eq!((j.unit_si.clone(), j.in_case(None)), (None, Ok(q("12/5"))));
        // 12 N s in a case in g and cm/s (1e-5 N s each): 1.2e6.
        let j = parse("12 N s", Kind::Impulse).unwrap();
        assert_eq!(j.in_case(Some(&q("1e-5"))), Ok(q("1.2e6")));
    }

    #[test]
    fn bad_values_name_the_flag() {
        let e = parse("12 N", Kind::Impulse).unwrap_err().to_string();
        assert!(
            e.contains("--impulse '12 N'") && e.contains("unknown unit 'N'"),
            "{e}"
        );
        let e = parse("48 W", Kind::Energy).unwrap_err().to_string();
        assert!(e.contains("--released") && e.contains("J, kJ"), "{e}");
        let e = parse("-200 N/m", Kind::Stiffness).unwrap_err().to_string();
        assert!(e.contains("--spring '-200 N/m' must be above 0"), "{e}");
        let e = parse("0 J", Kind::Energy).unwrap_err().to_string();
        assert!(e.contains("above 0"), "{e}");
        let e = parse("lots", Kind::Energy).unwrap_err().to_string();
        assert!(e.contains("--released 'lots'"), "{e}");
        let e = parse("12 N s", Kind::Impulse)
            .unwrap()
            .in_case(None)
            .unwrap_err()
            .to_string();
        assert!(e.contains("has a unit, but the masses"), "{e}");
        // 80 cm = 0.8 m; 3 ft = 0.9144 m; a plain number is metres.
        assert_eq!(length("80 cm", "--length"), Ok((q("0.8"), "80 cm".into())));
        assert_eq!(length("3 ft", "--length").unwrap().0, q("0.9144"));
        assert_eq!(length("5", "--length"), Ok((q("5"), "5 m".into())));
        let e = length("0 m", "--length").unwrap_err().to_string();
        assert!(e.contains("--length '0 m' must be above 0"), "{e}");
        let e = length("5 kg", "--length").unwrap_err().to_string();
        assert!(e.contains("--length '5 kg'"), "{e}");
    }
}
