//! The coefficient of restitution `e` in [0, 1] (lecture Sec. 1): `e = 1` elastic ("ka-bong"),
//! `0 < e < 1` ("ka-whump"), `e = 0` totally inelastic ("ka-runch").

use std::fmt;
use std::str::FromStr;

use crate::number::{Number, NumberError};

/// A coefficient of restitution, validated to lie in [0, 1].
#[derive(Clone, Debug, PartialEq)]
pub struct Restitution(Number);

/// Why a value is not a restitution.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RestitutionError {
    #[error(
        "restitution '{0}' is outside [0, 1]: expected a number from 0 (totally inelastic) to 1 (elastic)"
    )]
    OutOfRange(String),
    #[error("restitution {0}, or the words 'elastic' (1) or 'inelastic' (0)")]
    Number(NumberError),
}

// Not `#[from]`: the chain would print the number error twice.
impl From<NumberError> for RestitutionError {
    fn from(e: NumberError) -> RestitutionError {
        RestitutionError::Number(e)
    }
}

impl Restitution {
    pub fn elastic() -> Restitution {
        Restitution(Number::from_f64(1.0).expect("1 is a number"))
    }

    /// Checked on the value as typed: `1.0000000000000001` is refused although its nearest
    /// binary64 is 1, so binary64 and exact modes accept the same inputs.
    pub fn new(n: Number) -> Result<Restitution, RestitutionError> {
        let v = n.value();
        let inside = (0.0..=1.0).contains(&v)
            && (v != 1.0 || n.exact() <= num_rational::BigRational::from_integer(1.into()))
            && (v != 0.0 || n.exact() >= num_rational::BigRational::from_integer(0.into()));
        if inside {
            Ok(Restitution(n))
        } else {
            Err(RestitutionError::OutOfRange(n.to_string()))
        }
    }

    pub fn value(&self) -> f64 {
        self.0.value()
    }

    pub fn number(&self) -> &Number {
        &self.0
    }

    /// Exactly 1 as typed (`0.99999999999999999999999` is not, though it rounds to 1).
    pub fn is_elastic(&self) -> bool {
        self.value() == 1.0 && self.0.exact() == num_rational::BigRational::from_integer(1.into())
    }

    /// Exactly 0 as typed.
    pub fn is_totally_inelastic(&self) -> bool {
        self.value() == 0.0 && self.0.exact() == num_rational::BigRational::from_integer(0.into())
    }

    /// The lecture's name for the collision.
    pub fn kind(&self) -> &'static str {
        if self.is_elastic() {
            "elastic: ka-bong"
        } else if self.is_totally_inelastic() {
            "totally inelastic: ka-runch"
        } else {
            "ka-whump"
        }
    }
}

impl FromStr for Restitution {
    type Err = RestitutionError;
    fn from_str(s: &str) -> Result<Restitution, RestitutionError> {
        let t = match s.trim() {
            "elastic" => "1",
            "inelastic" => "0",
            t => t,
        };
        Restitution::new(t.parse()?)
    }
}

impl fmt::Display for Restitution {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.0)
    }
}

impl<'de> serde::Deserialize<'de> for Restitution {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Restitution, D::Error> {
        crate::number::deserialize_parsed(d, "a number in [0, 1] or \"elastic\" / \"inelastic\"")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_and_numbers() {
        assert_eq!("elastic".parse::<Restitution>().unwrap().value(), 1.0);
        assert_eq!("inelastic".parse::<Restitution>().unwrap().value(), 0.0);
        assert_eq!("2/3".parse::<Restitution>().unwrap().value(), 2.0 / 3.0);
        assert_eq!("2/3".parse::<Restitution>().unwrap().to_string(), "2/3");
    }

    #[test]
    fn outside_zero_one_is_refused() {
        for bad in ["1.5", "-0.1", "4/3"] {
            let e = bad.parse::<Restitution>().unwrap_err().to_string();
            assert!(e.contains(bad) && e.contains("[0, 1]"), "{e}");
        }
        let e = "bouncy".parse::<Restitution>().unwrap_err().to_string();
        assert!(e.contains("'bouncy'") && e.contains("elastic"), "{e}");
    }
}
