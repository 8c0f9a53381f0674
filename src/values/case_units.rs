//! How values are measured in a case: the mass and velocity units kept (when shared) or SI, the
//! unit energies are printed in (`--energy-unit`), and the units of energy, impulse and force
//! they make.

use crate::values::number::{Number, printable};
use crate::values::rational::Q;
use crate::values::unit_table::{Dimension, Unit, lookup};

/// How values are measured in a case: the units kept (when shared), or SI.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Units {
    pub mass: Option<&'static str>,
    pub velocity: Option<&'static str>,
    /// The unit energies are printed in (`--energy-unit`), when not the case's own.
    pub energy_as: Option<&'static EnergyUnit>,
}

/// A unit energies may be printed in: its name and size in joules, exact.
#[derive(Debug, PartialEq)]
pub struct EnergyUnit {
    pub name: &'static str,
    pub joules: &'static str,
}

/// `--energy-unit` choices.
pub const ENERGY_UNITS: &[EnergyUnit] = &[
    EnergyUnit {
        name: "J",
        joules: "1",
    },
    EnergyUnit {
        name: "kJ",
        joules: "1000",
    },
    // The electronvolt, exact since the 2019 SI (e = 1.602176634e-19 C).
    EnergyUnit {
        name: "eV",
        joules: "1.602176634e-19",
    },
    EnergyUnit {
        name: "MeV",
        joules: "1.602176634e-13",
    },
    // The foot-pound force: 0.3048 m x 4.4482216152605 N, exact.
    EnergyUnit {
        name: "ft*lbf",
        joules: "1.35581794833140040",
    },
    // The thermochemical calorie.
    EnergyUnit {
        name: "cal",
        joules: "4.184",
    },
];

/// Why energies cannot be given in the unit asked for.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum EnergyUnitError {
    #[error(
        "unknown energy unit '{}': expected one of J, kJ, eV, MeV, ft*lbf, cal",
        printable(.0)
    )]
    Unknown(String),
    #[error(
        "--energy-unit {0} needs units on the masses and velocities (e.g. '2 kg', '3 m/s'), \
         to know what the case's energies are in"
    )]
    NoUnits(&'static str),
}

/// The energy unit named `name` (`ft*lbf` also as `ft lbf`, `ft.lbf`).
pub fn energy_unit(name: &str) -> Result<&'static EnergyUnit, EnergyUnitError> {
    let n = name.trim().replace([' ', '.', '·'], "*");
    ENERGY_UNITS
        .iter()
        .find(|u| u.name == n)
        .ok_or_else(|| EnergyUnitError::Unknown(name.trim().to_string()))
}

impl Units {
    /// Energies to be printed in `unit`: refused unless the case has mass and velocity units.
    pub fn with_energy_unit(mut self, unit: &'static EnergyUnit) -> Result<Units, EnergyUnitError> {
        if self.mass.is_none() || self.velocity.is_none() {
            return Err(EnergyUnitError::NoUnits(unit.name));
        }
        self.energy_as = Some(unit);
        Ok(self)
    }

    /// The factor from the case's energy unit (mass unit x velocity unit^2) to the printed one,
    /// exact: `None` when energies are printed in the case's own unit.
    pub fn energy_scale(&self) -> Option<Q> {
        let unit = self.energy_as?;
        let si = |name: Option<&str>, d: Dimension| {
            name.and_then(|n| lookup(n, d).ok())
                .map_or_else(|| crate::values::rational::int(1), Unit::si)
        };
        let m = si(self.mass, Dimension::Mass);
        let v = si(self.velocity, Dimension::Velocity);
        let joules = unit.joules.parse::<Number>().ok()?.exact();
        Some(m * &v * &v / joules)
    }

    /// "ton mph^2", or the generic description when no units were given.
    pub fn energy(&self) -> String {
        if let Some(u) = self.energy_as {
            return u.name.to_string();
        }
        match (self.mass, self.velocity) {
            (Some(m), Some(v)) => {
                if m == "kg" && v == "m/s" {
                    "J".into()
                } else {
                    format!("{m} {}", squared(v))
                }
            }
            (Some(m), None) => format!("{m} x (velocity unit)^2"),
            (None, Some(v)) => format!("(mass unit) {}", squared(v)),
            (None, None) => "mass unit x velocity unit^2".into(),
        }
    }
}

/// `(m/s)^2` (an energy's velocity part; `m/s^2` would be an acceleration), `mph^2`.
fn squared(v: &str) -> String {
    if v.contains('/') {
        format!("({v})^2")
    } else {
        format!("{v}^2")
    }
}

impl Units {
    /// "N" for kg and m/s, else the impulse unit per second.
    pub fn force(&self) -> String {
        if self.force_scale().is_some() {
            "N".into()
        } else {
            format!("{} per second", self.impulse())
        }
    }

    /// The factor from the case's force unit (mass unit x velocity unit per second) to newtons,
    /// when both units are given: forces print in N whatever the units typed (issue 27: "1423000
    /// in g m/s per second" was 1.423 kN).
    pub fn force_scale(&self) -> Option<Q> {
        let m = lookup(self.mass?, Dimension::Mass).ok()?;
        let v = lookup(self.velocity?, Dimension::Velocity).ok()?;
        Some(m.si() * v.si())
    }

    /// The size of the case's energy unit (mass unit x velocity unit^2) in joules, when both
    /// units are given.
    pub fn energy_si(&self) -> Option<Q> {
        let v = lookup(self.velocity?, Dimension::Velocity).ok()?.si();
        Some(self.force_scale()? * v)
    }

    /// "kg m/s" (momentum, impulse), or the generic description.
    pub fn impulse(&self) -> String {
        match (self.mass, self.velocity) {
            (Some(m), Some(v)) => format!("{m} {v}"),
            (Some(m), None) => format!("{m} x velocity unit"),
            (None, Some(v)) => format!("mass unit x {v}"),
            (None, None) => "mass unit x velocity unit".into(),
        }
    }
}
