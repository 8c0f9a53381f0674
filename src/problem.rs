//! A problem as typed, on the command line or in a scene: masses (or a tensor), velocities,
//! perhaps final velocities, a restitution; numbers with units or `?` for unknowns (issue 8).
//! Units are resolved first; the unknowns are then solved exactly (`unknowns`), and the result
//! is an ordinary `Case`.

use anyhow::Result;
use num_rational::BigRational;

use crate::case::Case;
use crate::inertia::{InertiaTensor, Mass};
use crate::number::Number;
use crate::restitution::Restitution;
use crate::units::{Pair, Units, resolve};
use crate::unknowns::{Solved, Var, solve as solve_unknowns};

/// The typed values of a problem.
#[derive(Clone, Debug, Default)]
pub struct Problem {
    /// `None` with a general tensor instead.
    pub masses: Option<Pair>,
    pub velocities: Pair,
    /// Final velocities, when the problem gives them.
    pub fin: Option<Pair>,
    /// `Some(None)` for `?`; not given: elastic, or unknown when FIN is given.
    pub restitution: Option<Option<Restitution>>,
    /// Convert to kg and m/s.
    pub si: bool,
}

impl Problem {
    /// Whether a typed value is `?`.
    pub fn has_unknowns(&self) -> bool {
        let pair = |p: &Option<Pair>| p.as_ref().is_some_and(|p| p.0.iter().any(Option::is_none));
        pair(&self.masses)
            || self.velocities.0.iter().any(Option::is_none)
            || pair(&self.fin)
            || matches!(self.restitution, Some(None))
    }

    /// Resolves units and solves any unknowns; returns the case, and what was solved when the
    /// problem had unknowns or gave FIN.
    pub fn solve(&self, inertia: Option<InertiaTensor>) -> Result<(Case, Option<Solved>)> {
        let masses: Vec<_> = self.masses.as_ref().map_or(Vec::new(), |p| p.0.to_vec());
        if masses.is_empty() && inertia.is_none() {
            anyhow::bail!("give --masses M1,M2 or --inertia 'M11,M12;M21,M22'");
        }
        let mut velocities = self.velocities.0.to_vec();
        if let Some(f) = &self.fin {
            velocities.extend(f.0.iter().cloned());
        }
        let (m, v, units) = resolve(&masses, &velocities, self.si).map_err(anyhow::Error::msg)?;
        let e = match &self.restitution {
            Some(Some(r)) => Some(r.number().clone()),
            Some(None) => None,
            None if self.fin.is_some() => None,
            None => Some(Restitution::elastic().number().clone()),
        };
        if !(self.fin.is_some() || self.has_unknowns()) {
            let case = build(&m, &v, e, inertia, units)?;
            return Ok((case, None));
        }
        if inertia.is_some() || m.is_empty() {
            anyhow::bail!("unknowns and --fin need --masses M1,M2 (not --inertia)");
        }
        let fin = if self.fin.is_some() {
            v[2..4].to_vec()
        } else {
            vec![None, None]
        };
        let known: Vec<Option<Number>> = m
            .iter()
            .chain(&v[..2])
            .chain(&fin)
            .cloned()
            .chain([e])
            .collect();
        let exact: [Option<BigRational>; 7] =
            std::array::from_fn(|i| known[i].as_ref().map(Number::exact));
        let solved = solve_unknowns(exact)?;
        let number = |var: Var| -> Result<Option<Number>> {
            let text = crate::quantity::fraction(solved.get(var));
            text.parse::<Number>()
                .map(Some)
                .map_err(|e| anyhow::anyhow!("{var} = {text}: {e}"))
        };
        let m = vec![number(Var::M1)?, number(Var::M2)?];
        let v = vec![number(Var::V1)?, number(Var::V2)?];
        let case = build(&m, &v, number(Var::E)?, None, units)?;
        Ok((case, Some(solved)))
    }
}

fn build(
    m: &[Option<Number>],
    v: &[Option<Number>],
    e: Option<Number>,
    inertia: Option<InertiaTensor>,
    units: Units,
) -> Result<Case> {
    let need = |x: &Option<Number>| {
        x.clone()
            .ok_or_else(|| anyhow::anyhow!("'?' is only for collide solve"))
    };
    let inertia = match inertia {
        Some(t) if m.is_empty() => t,
        _ => {
            let mass =
                |x: &Option<Number>| need(x).and_then(|n| Mass::new(n).map_err(anyhow::Error::msg));
            InertiaTensor::diagonal(&mass(&m[0])?, &mass(&m[1])?)?
        }
    };
    let e = Restitution::new(need(&e)?).map_err(anyhow::Error::msg)?;
    let mut case = Case::new(inertia, [need(&v[0])?, need(&v[1])?], e);
    case.units = units;
    Ok(case)
}
