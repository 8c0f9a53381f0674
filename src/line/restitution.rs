//! The coefficient of restitution `e >= 0` (lecture Sec. 1): `e = 1` elastic ("ka-bong"),
//! `0 < e < 1` ("ka-whump"), `e = 0` totally inelastic ("ka-runch"), and `e > 1` superelastic:
//! the bodies separate faster than they met, so energy stored in them (a spring, an explosive)
//! is released. The lecture's time-reversed ka-whump is one, with `e' = 1/e` (Sec. 4).

use std::fmt;
use std::str::FromStr;

use crate::values::number::{Number, NumberError};

/// A coefficient of restitution, validated to be finite and `>= 0` as typed.
#[derive(Clone, Debug, PartialEq)]
pub struct Restitution(Number);

/// Why a value is not a restitution.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RestitutionError {
    #[error(
        "restitution '{0}' is negative: expected a number >= 0 (0 totally inelastic, 1 elastic, \
         above 1 superelastic)"
    )]
    Negative(String),
    #[error(
        "restitution '{0}' is above 1 (superelastic): here it must be in [0, 1], from 0 (totally \
         inelastic) to 1 (elastic)"
    )]
    Superelastic(String),
    #[error(
        "restitution {0}: expected a number >= 0 such as 2/3, or the words 'elastic' (1) or \
         'inelastic' (0)"
    )]
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

    /// Checked on the value as typed: `-1e-400` is refused although its nearest binary64 is
    /// -0, so binary64 and exact modes accept the same inputs. Values above 1 are superelastic
    /// (energy released); `dissipative` refuses them where a model cannot have them.
    pub fn new(n: Number) -> Result<Restitution, RestitutionError> {
        let v = n.value();
        // A typed -0 or -1e-400 rounds to 0: its exact value decides.
        if v.is_finite() && v >= 0.0 && (v != 0.0 || n.exact() >= crate::values::rational::Q::ZERO)
        {
            Ok(Restitution(n))
        } else {
            Err(RestitutionError::Negative(n.to_string()))
        }
    }

    /// A restitution in [0, 1] as typed (`1.0000000000000001` is refused though it rounds to 1):
    /// for models whose invariants say energy is never gained (`collide track`).
    pub fn dissipative(n: Number) -> Result<Restitution, RestitutionError> {
        let e = Restitution::new(n)?;
        if e.is_superelastic() {
            return Err(RestitutionError::Superelastic(e.to_string()));
        }
        Ok(e)
    }

    pub fn value(&self) -> f64 {
        self.0.value()
    }

    pub fn number(&self) -> &Number {
        &self.0
    }

    /// Exactly 1 as typed (`0.99999999999999999999999` is not, though it rounds to 1).
    pub fn is_elastic(&self) -> bool {
        self.value() == 1.0 && self.0.exact() == crate::values::rational::int(1)
    }

    /// `FromStr`, then `dissipative`'s check (a command-line parser for `collide track`).
    pub fn parse_dissipative(s: &str) -> Result<Restitution, RestitutionError> {
        let e: Restitution = s.parse()?;
        Restitution::dissipative(e.0)
    }

    /// Above 1 as typed (`1.0000000000000001` is, though it rounds to 1): energy is released.
    pub fn is_superelastic(&self) -> bool {
        self.value() > 1.0
            || (self.value() == 1.0 && self.0.exact() > crate::values::rational::int(1))
    }

    /// Exactly 0 as typed.
    pub fn is_totally_inelastic(&self) -> bool {
        self.value() == 0.0 && self.0.exact() == crate::values::rational::Q::ZERO
    }

    /// The lecture's name for the collision.
    pub fn kind(&self) -> &'static str {
        if self.is_elastic() {
            "elastic: ka-bong"
        } else if self.is_totally_inelastic() {
            "totally inelastic: ka-runch"
        } else if self.is_superelastic() {
            "superelastic: energy released"
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
        crate::values::number::deserialize_parsed(d, "a number >= 0 or \"elastic\" / \"inelastic\"")
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
    fn negative_is_refused_and_above_one_is_superelastic() {
        for bad in ["-0.1", "-4/3", "-1e-300"] {
            let e = bad.parse::<Restitution>().unwrap_err().to_string();
            assert!(e.contains(bad) && e.contains("negative"), "{e}");
        }
        for sup in ["1.5", "4/3", "1.0000000000000001"] {
            let e = sup.parse::<Restitution>().unwrap();
            assert!(e.is_superelastic() && !e.is_elastic(), "{sup}");
            let n: Number = sup.parse().unwrap();
            let refused = Restitution::dissipative(n).unwrap_err().to_string();
            assert!(refused.contains("[0, 1]"), "{refused}");
        }
        assert!(!"1".parse::<Restitution>().unwrap().is_superelastic());
        assert!(
            !"0.99999999999999999999999"
                .parse::<Restitution>()
                .unwrap()
                .is_superelastic()
        );
        let e = "bouncy".parse::<Restitution>().unwrap_err().to_string();
        assert!(e.contains("'bouncy'") && e.contains("elastic"), "{e}");
    }
}
