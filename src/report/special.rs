//! The reports of the two-body events that are not collisions of two movable bodies: a
//! separation (`separation`) and a ball against a wall (`wall`). Each is exact and rounded once
//! in binary64; text shows the sections in `show`, JSON carries every section computed.

use super::separation::SeparationReport;
use super::wall::WallReport;
use super::{Sections, Unrepresentable, first_unrepresentable};
use crate::line::separation::Separation;
use crate::line::wall::WallCase;
use crate::values::quantity::{Exact, Scalar};

/// An event other than a two-body collision.
#[derive(Clone, Copy, Debug)]
pub enum Special<'a> {
    Separation(&'a Separation),
    Wall(&'a WallCase),
}

/// Text and JSON of a special event.
pub struct Rendered {
    pub text: String,
    pub json: serde_json::Value,
}

impl Special<'_> {
    /// The report: sections in `compute` (JSON), text of those in `show`.
    pub fn render(
        self,
        compute: &Sections,
        show: &Sections,
        exact: bool,
    ) -> Result<Rendered, super::ReportError> {
        if exact {
            let typed: Vec<&crate::values::number::Number> = match self {
                Special::Separation(s) => s.masses.iter().chain(&s.velocities).collect(),
                Special::Wall(w) => w
                    .mass
                    .iter()
                    .chain([w.restitution.number()])
                    .chain(&w.velocities)
                    .collect(),
            };
            crate::values::number::check_exact_length(typed)?;
            Ok(self.in_arithmetic::<Exact>(compute, show)?)
        } else {
            Ok(self.in_arithmetic::<f64>(compute, show)?)
        }
    }

    fn in_arithmetic<N: Scalar>(
        self,
        compute: &Sections,
        show: &Sections,
    ) -> Result<Rendered, super::ReportError> {
        let (text, json) = match self {
            Special::Separation(s) => {
                let r = SeparationReport::<N>::new(s, compute)?;
                (r.text(s, show), serde_json::to_value(&r))
            }
            Special::Wall(w) => {
                let r = WallReport::<N>::new(w, compute);
                (r.text(w, show), serde_json::to_value(&r))
            }
        };
        let json = json.expect("reports serialize");
        if let Some(quantity) = first_unrepresentable(&json) {
            return Err(Unrepresentable::new(quantity).into());
        }
        Ok(Rendered { text, json })
    }

    /// The units of the event's numbers.
    pub fn units(self) -> crate::values::units::Units {
        match self {
            Special::Separation(s) => s.units.clone(),
            Special::Wall(w) => w.units.clone(),
        }
    }
}
