//! The stages no stage-by-stage order solves, as one linear system (issue 42 §5). When every
//! unsolved stage's masses and `e` are known, its laws are linear in its four velocities
//! `(v1, v2, f1, f2)` (in the stage's units):
//!
//! - momentum: `m1 v1 + m2 v2 - m1 f1 - m2 f2 = 0` (Axiom 1, docs/physics.md §1);
//! - restitution: `-e v1 + e v2 - f1 + f2 = 0`, i.e. `f2 - f1 = -e (v2 - v1)` (§1, "ka-whump");
//!   none for a pass-through (momentum alone);
//! - a ball against a wall moving at `W`: `e v + f = (1 + e) W` (`f - W = -e (v - W)`).
//!
//! A velocity one stage takes from another is one unknown shared by both. The system is solved
//! exactly ([`linear::solve`], rationals; a binary64 chain rounds the exact solution once, when
//! it is carried). Each stage is then solved again by `Problem::solve` with the system's values
//! for all but as many of its unknowns as it has laws (its own `?` first), so its report says
//! what it solved; `check` then checks every stage with the chain's values.

use super::super::SceneError;
use super::linear::{self, Unsolvable};
use super::{StageRun, StagesScene};
use crate::line::chain::Object;
use crate::line::problem::Problem;
use crate::line::restitution::Restitution;
use crate::report::stages::Fixed;
use crate::values::number::Given;
use crate::values::quantity::fraction;
use crate::values::rational::{Q, int};
use crate::values::units::{Dimension, Pair, Quantity, lookup, resolve};

/// What the fixed velocities are fixed by, in the chain's report.
const BY: &str = "the system";

/// An unsolved stage's values in its units: masses (`None`: a wall), the four velocities
/// (`None`: unknown), `e` (`None`: a pass-through) and the velocity unit.
struct Linear {
    masses: [Option<Q>; 2],
    velocities: [Option<Q>; 4],
    e: Option<Q>,
    unit: Option<&'static str>,
}

impl StagesScene {
    /// The unsolved stages solved as one system and put in `runs`, with the taken velocities
    /// the system fixed; `None` when a stage is not linear in its velocities (a mass or `e`
    /// unknown, a known beyond the pass-through, a speed unit asked), so the chain keeps the
    /// stage-by-stage refusal.
    pub(super) fn joint(
        &self,
        runs: &mut [Option<StageRun>],
        exact: bool,
    ) -> Result<Option<Vec<Fixed>>, SceneError> {
        let open: Vec<usize> = (0..runs.len()).filter(|&i| runs[i].is_none()).collect();
        let mut stages = Vec::new();
        for &i in &open {
            let Some(l) = self.linear(i, runs, exact)? else {
                return Ok(None);
            };
            stages.push(l);
        }
        // A stage with no velocity unit has bare numbers (or 0), which any unit takes.
        let unit = stages.iter().find_map(|l| l.unit);
        if stages
            .iter()
            .any(|l| l.unit.is_some_and(|u| Some(u) != unit))
        {
            return Ok(None);
        }
        for l in &mut stages {
            l.unit = unit;
        }
        // Each unknown slot (stage, 0..4) gets a variable; a taken IN is its source's FIN.
        let mut var: Vec<[Option<usize>; 4]> = vec![[None; 4]; open.len()];
        let mut names: Vec<String> = Vec::new();
        for (k, &i) in open.iter().enumerate() {
            for (slot, v) in var[k].iter_mut().enumerate() {
                if stages[k].velocities[slot].is_none() && self.source(i, slot, &open).is_none() {
                    *v = Some(names.len());
                    names.push(self.slot_name(i, slot));
                }
            }
        }
        for (k, &i) in open.iter().enumerate() {
            for slot in 0..2 {
                if let Some((j, s)) = self.source(i, slot, &open) {
                    let kj = open.iter().position(|&o| o == j).unwrap_or(k);
                    var[k][slot] = var[kj][s];
                    stages[k].velocities[slot] = stages[kj].velocities[s].clone();
                }
            }
        }
        let n = names.len();
        let mut rows: Vec<Vec<Q>> = Vec::new();
        let mut laws: Vec<String> = Vec::new();
        for (k, &i) in open.iter().enumerate() {
            let l = &stages[k];
            let name = &self.stages[i].name;
            let mut law = |terms: Vec<(usize, Q)>, rhs: Q, what: &str| {
                let mut row = vec![Q::ZERO; n + 1];
                row[n] = rhs;
                for (slot, c) in terms {
                    match (&l.velocities[slot], var[k][slot]) {
                        (Some(v), _) => row[n] = &row[n] - &c * v,
                        (None, Some(x)) => row[x] = &row[x] + &c,
                        (None, None) => {}
                    }
                }
                rows.push(row);
                laws.push(format!("{what} in {name}"));
            };
            match (&l.masses, &l.e) {
                ([Some(m1), Some(m2)], e) => {
                    let (m1, m2) = (m1.clone(), m2.clone());
                    let momentum = vec![(0, m1.clone()), (1, m2.clone()), (2, -m1), (3, -m2)];
                    law(momentum, Q::ZERO, "momentum");
                    if let Some(e) = e {
                        let r = vec![(0, -e.clone()), (1, e.clone()), (2, -int(1)), (3, int(1))];
                        law(r, Q::ZERO, "restitution");
                    }
                }
                ([None, Some(_)], Some(e)) | ([Some(_), None], Some(e)) => {
                    let (ball, wall) = if l.masses[0].is_none() {
                        (1, 0)
                    } else {
                        (0, 1)
                    };
                    let w = l.velocities[wall].clone().unwrap_or_default();
                    let rhs = (int(1) + e) * w;
                    law(
                        vec![(ball, e.clone()), (2 + ball, int(1))],
                        rhs,
                        "restitution",
                    );
                }
                _ => return Ok(None),
            }
        }
        let first = &self.stages[open[0]];
        let x = linear::solve(&rows, n).map_err(|why| match why {
            Unsolvable::Underdetermined { rank, open } => {
                let list =
                    |v: Vec<&String>| v.iter().map(|s| s.as_str()).collect::<Vec<_>>().join(", ");
                self.at(
                    first,
                    format!(
                        "no stage is determined alone, and together the unsolved stages' laws \
                         give {rank} independent equations for {n} unknowns ({}): {} stay \
                         unknown; give one more known",
                        list(names.iter().collect()),
                        list(open.iter().map(|&o| &names[o]).collect())
                    ),
                )
            }
            Unsolvable::Contradiction { row, residual } => self.at(
                first,
                format!(
                    "the given values contradict each other: solved as one system, {} misses \
                     by {}",
                    laws[row],
                    fraction(&residual)
                ),
            ),
        })?;
        for (k, l) in stages.iter_mut().enumerate() {
            for (slot, v) in var[k].iter().enumerate() {
                if let Some(v) = v {
                    l.velocities[slot] = Some(x[*v].clone());
                }
            }
        }
        let mut fixed = Vec::new();
        for (k, &i) in open.iter().enumerate() {
            let problem = self.with_values(i, &stages[k], exact)?;
            runs[i] = Some(self.run(i, &problem, exact)?);
            for (slot, v) in var[k].iter().enumerate().take(2) {
                if let (Some(t), Some(_)) = (&self.stages[i].takes[slot], v)
                    && open.contains(&t.stage)
                {
                    fixed.push(Fixed {
                        text: t.text.clone(),
                        by: BY.into(),
                        value: stages[k].velocities[slot].clone().unwrap_or_default(),
                    });
                }
            }
        }
        Ok(Some(fixed))
    }

    /// The stage and slot (2 or 3: a FIN) an IN slot of stage `i` takes, when that stage is
    /// unsolved.
    fn source(&self, i: usize, slot: usize, open: &[usize]) -> Option<(usize, usize)> {
        let t = self.stages[i].takes.get(slot)?.as_ref()?;
        open.contains(&t.stage).then_some((t.stage, 2 + t.body))
    }

    /// `stage1.fin2 (B)`: a velocity of a stage, named as a reference is.
    fn slot_name(&self, i: usize, slot: usize) -> String {
        let stage = &self.stages[i];
        let which = if slot < 2 { "in" } else { "fin" };
        let body = match stage.objects[slot % 2] {
            Object::Body(b) => format!(" ({})", self.bodies[b]),
            Object::Wall(_) => String::new(),
        };
        format!("{}.{which}{}{body}", stage.name, slot % 2 + 1)
    }

    /// Stage `i`'s values resolved in its units, with what solved stages give it; `None` when
    /// its laws are not linear in its velocities with known coefficients.
    fn linear(
        &self,
        i: usize,
        runs: &[Option<StageRun>],
        exact: bool,
    ) -> Result<Option<Linear>, SceneError> {
        let (problem, _) = self.fill(i, runs, exact)?;
        let stage = &self.stages[i];
        let k = &problem.knowns;
        let beyond = k.impulse.is_some()
            || k.released.is_some()
            || k.total_mass.is_some()
            || k.separation_speed.is_some();
        let Some(masses) = &problem.masses else {
            return Ok(None);
        };
        if beyond || problem.velocity_unit.is_some() || masses.0.iter().any(Given::is_unknown) {
            return Ok(None);
        }
        let e = match (&problem.restitution, &problem.fin) {
            _ if k.pass_through => None,
            (Some(Given::Known(r)), _) => Some(r.number().exact()),
            (None, None) => Some(int(1)),
            _ => return Ok(None),
        };
        let g = problem.g().map_err(|e| self.at(stage, format!("{e:#}")))?;
        let fin = problem
            .fin
            .clone()
            .unwrap_or(Pair([Given::Unknown, Given::Unknown]));
        let mut speeds = Vec::new();
        for v in problem.velocities.0.iter().chain(&fin.0) {
            speeds.push(match v {
                Given::Known(q) => match q.with_gravity(&g) {
                    Ok((s, _)) => Given::Known(s),
                    Err(e) => return Err(self.at(stage, format!("{e:#}"))),
                },
                other => other.clone(),
            });
        }
        // Units that resolve only with the unknowns given (mixed units, a `?` without one):
        // the stage-by-stage refusal stands.
        let Ok((m, v, units)) = resolve(&masses.0, &speeds, problem.si) else {
            return Ok(None);
        };
        let q = |g: &Given<crate::values::number::Number>| g.known().map(|n| n.exact());
        let mut velocities = [q(&v[0]), q(&v[1]), q(&v[2]), q(&v[3])];
        for b in 0..2 {
            // A wall keeps its velocity: its FIN is no unknown.
            if m[b].is_wall() {
                velocities[2 + b] = velocities[b].clone();
            }
        }
        Ok(Some(Linear {
            masses: [q(&m[0]), q(&m[1])],
            velocities,
            e,
            unit: units.velocity,
        }))
    }

    /// Stage `i`'s problem with the system's values `l`: all but as many unknowns as the stage
    /// has laws are given (its own `?` stay unknown first, then its FIN, then the IN it takes
    /// from another stage), so `Problem::solve` solves and reports them.
    fn with_values(&self, i: usize, l: &Linear, exact: bool) -> Result<Problem, SceneError> {
        let stage = &self.stages[i];
        let mut problem = stage.problem.clone();
        let walls: Vec<usize> = (0..2).filter(|&b| l.masses[b].is_none()).collect();
        let laws = if l.e.is_none() || !walls.is_empty() {
            1
        } else {
            2
        };
        let typed = |slot: usize| -> Option<&Given<Quantity>> {
            match slot {
                0 | 1 => Some(&problem.velocities.0[slot]),
                _ => problem.fin.as_ref().map(|f| &f.0[slot - 2]),
            }
        };
        let taken_later = |slot: usize| {
            slot >= 2
                && self.stages[i + 1..]
                    .iter()
                    .flat_map(|s| s.takes.iter().flatten())
                    .any(|t| t.stage == i && t.body == slot - 2)
        };
        let own = |slot: usize| {
            typed(slot).is_some_and(Given::is_unknown)
                && !(slot < 2 && stage.takes[slot].is_some())
                && !taken_later(slot)
        };
        let unknown = |slot: usize| typed(slot).is_none_or(Given::is_unknown);
        let mut keep: Vec<usize> = Vec::new();
        let order = (0..4)
            .filter(|&s| own(s))
            .chain([2, 3])
            .chain(0..2)
            .filter(|&s| unknown(s));
        for s in order {
            if keep.len() < laws && !walls.contains(&(s % 2)) && !keep.contains(&s) {
                keep.push(s);
            }
        }
        let unit = l.unit.and_then(|u| lookup(u, Dimension::Velocity).ok());
        let mut values: [Given<Quantity>; 4] = std::array::from_fn(|s| match typed(s) {
            Some(g) => g.clone(),
            None => Given::Unknown,
        });
        for (s, value) in values.iter_mut().enumerate() {
            if keep.contains(&s) || !unknown(s) {
                continue;
            }
            let q = l.velocities[s].clone().unwrap_or_default();
            let number = self.carried(i, &self.slot_name(i, s), &q, exact)?;
            *value = Given::Known(Quantity {
                number,
                unit,
                height: false,
            });
        }
        let [v1, v2, f1, f2] = values;
        problem.velocities = Pair([v1, v2]);
        let forward = (2..4).all(|s| keep.contains(&s) || walls.contains(&(s % 2)));
        if problem.fin.is_some() || !forward {
            problem.fin = Some(Pair([f1, f2]));
            if problem.restitution.is_none() && !problem.knowns.pass_through {
                problem.restitution = Some(Given::Known(Restitution::elastic()));
            }
        }
        Ok(problem)
    }
}
