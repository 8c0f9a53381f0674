//! A chain solved as one system (issue 42 §5): a velocity a stage takes from an earlier one may
//! be unknown there and fixed by the later stage. A bullet passes through block 1 (`pass_through
//! = true`: momentum alone) and lodges in block 2; the blocks' final speeds are given. Block 1's
//! stage alone has two unknowns (the bullet's entering and leaving speeds) for one law; block
//! 2's stage takes the leaving speed as its `?` and fixes it (`m u = (m + M2) V2`), and block 1's
//! stage is then solved with it as a given FIN (`m v = m u + M1 V1`).
//!
//! The chain's unknowns are the stages' own `?` and every taken velocity (one value, shared by
//! the stage that produces it, as its FIN, and the one that takes it, as its IN). Each stage's
//! laws (momentum, and restitution or the pass-through) involve its own values only, so the
//! system is solved stage by stage in whatever order makes each one determined: a stage whose
//! source is not solved yet is posed with that velocity `?`, and once solved its IN is the
//! source's given FIN. Every value is exact (rationals) in an exact scene. Then each stage is
//! checked again with the solved values ([`check`]): its FIN worked out forward from its
//! masses, IN and solved `e` must be what the next stage takes, and momentum must hold.

use super::super::SceneError;
use super::{StageRun, StagesScene};
use crate::line::problem::{Posed, Problem};
use crate::line::restitution::Restitution;
use crate::report::Sections;
use crate::report::stages::Fixed;
use crate::solver::exact::ExactCollision;
use crate::values::number::{EXACT_MAX_CHARS, Given, Number};
use crate::values::quantity::{fraction, from_f64, to_f64};
use crate::values::rational::Q;
use crate::values::units::{Dimension, Pair, Quantity, lookup};

/// The stages solved, in stage order, with the velocities later stages fixed.
pub(super) struct Carried {
    pub runs: Vec<StageRun>,
    pub fixed: Vec<Fixed>,
}

impl StagesScene {
    /// Each stage posed and solved, its taken velocities the FIN of the stages they name and
    /// its FIN the IN of the later stages that take it, whichever is solved first: exactly
    /// (`exact`), or as the binary64 values printed. A chain that takes known values only is
    /// solved in stage order, in one pass.
    pub(super) fn carry(&self, exact: bool) -> Result<Carried, SceneError> {
        let n = self.stages.len();
        let mut runs: Vec<Option<StageRun>> = vec![None; n];
        let mut errors: Vec<Option<SceneError>> = vec![None; n];
        let mut fixed = Vec::new();
        loop {
            let mut progress = false;
            for i in 0..n {
                if runs[i].is_some() {
                    continue;
                }
                match self.pose(i, &runs, exact) {
                    Ok((run, by_later)) => {
                        fixed.extend(by_later);
                        runs[i] = Some(run);
                        progress = true;
                    }
                    Err(e) => errors[i] = Some(e),
                }
            }
            if !progress {
                break;
            }
        }
        if runs.iter().any(Option::is_none) {
            // No stage is determined alone: the rest as one linear system, when it is one.
            fixed.extend(self.joint(&mut runs, exact)?.unwrap_or_default());
        }
        if let Some(i) = runs.iter().position(Option::is_none) {
            return Err(self.unsolved(i, &runs, errors[i].take()));
        }
        Ok(Carried {
            runs: runs.into_iter().flatten().collect(),
            fixed,
        })
    }

    /// Why stage `i` stays unsolved: its own error, and which of its taken velocities no stage
    /// fixed.
    fn unsolved(
        &self,
        i: usize,
        runs: &[Option<StageRun>],
        error: Option<SceneError>,
    ) -> SceneError {
        let stage = &self.stages[i];
        let mut e = error.unwrap_or_else(|| self.at(stage, "not solved".into()));
        let open: Vec<&str> = stage
            .takes
            .iter()
            .flatten()
            .filter(|t| runs[t.stage].is_none())
            .map(|t| t.text.as_str())
            .collect();
        let takers: Vec<String> = self
            .stages
            .iter()
            .enumerate()
            .filter(|(k, _)| runs[*k].is_none())
            .flat_map(|(_, later)| later.takes.iter().flatten())
            .filter(|t| t.stage == i)
            .map(|t| t.text.clone())
            .collect();
        if !open.is_empty() {
            e.message.push_str(&format!(
                " ({} unknown here: no stage before or after fixes it)",
                open.join(", ")
            ));
        } else if !takers.is_empty() {
            e.message.push_str(&format!(
                " (the later stage that takes {} cannot fix it either: give one more known in \
                 one of them)",
                takers.join(", ")
            ));
        }
        e
    }

    /// A value carried from one stage to another, as a number: exact, or the binary64 value.
    pub(super) fn carried(
        &self,
        i: usize,
        text: &str,
        q: &Q,
        exact: bool,
    ) -> Result<Number, SceneError> {
        let stage = &self.stages[i];
        if exact {
            let f = fraction(q);
            let chars = f.chars().count();
            if self.exact && chars > EXACT_MAX_CHARS {
                return Err(self.at(
                    stage,
                    format!(
                        "{text} is a fraction of {chars} characters: exact arithmetic carries at \
                         most {EXACT_MAX_CHARS} (its cost grows faster than the length); set \
                         exact = false to carry the binary64 value printed"
                    ),
                ));
            }
            f.parse::<Number>().or_else(|_| Number::solved(&f))
        } else {
            Number::from_f64(to_f64(q).unwrap_or(f64::NAN))
        }
        .map_err(|e| self.at(stage, format!("{text} = {}: {e}", fraction(q))))
    }

    /// Stage `i` posed with what the solved stages give it (the IN it takes, the FIN later
    /// stages took) and solved; with the velocities of its FIN that later stages fixed.
    fn pose(
        &self,
        i: usize,
        runs: &[Option<StageRun>],
        exact: bool,
    ) -> Result<(StageRun, Vec<Fixed>), SceneError> {
        let (problem, fixed) = self.fill(i, runs, exact)?;
        Ok((self.run(i, &problem, exact)?, fixed))
    }

    /// Stage `i`'s problem with what the solved stages give it: the IN it takes, the FIN later
    /// stages took (with those fixed values).
    pub(super) fn fill(
        &self,
        i: usize,
        runs: &[Option<StageRun>],
        exact: bool,
    ) -> Result<(Problem, Vec<Fixed>), SceneError> {
        let stage = &self.stages[i];
        let mut problem = stage.problem.clone();
        let velocity = |run: &StageRun, number: Number| {
            let unit = run
                .posed
                .units()
                .velocity
                .and_then(|u| lookup(u, Dimension::Velocity).ok());
            Given::Known(Quantity {
                number,
                unit,
                height: false,
            })
        };
        for (slot, taken) in stage.takes.iter().enumerate() {
            let Some(t) = taken else { continue };
            // Not solved yet: the value is `?` here (as read), to be fixed by this stage.
            let Some(from) = &runs[t.stage] else { continue };
            let number = self.carried(i, &t.text, &from.fin[t.body], exact)?;
            problem.velocities.0[slot] = velocity(from, number);
        }
        let mut fixed = Vec::new();
        for (k, later) in self.stages.iter().enumerate().skip(i + 1) {
            let Some(run) = &runs[k] else { continue };
            for (slot, t) in later.takes.iter().enumerate() {
                let Some(t) = t.as_ref().filter(|t| t.stage == i) else {
                    continue;
                };
                let typed = problem.fin.as_ref().map(|f| &f.0[t.body]);
                if typed.is_some_and(|g| !g.is_unknown()) {
                    // Given here too: the check compares the two.
                    continue;
                }
                let value = velocities_in(&run.posed)[slot].clone();
                let number = self.carried(i, &t.text, &value, exact)?;
                if problem.fin.is_none() {
                    problem.fin = Some(Pair([Given::Unknown, Given::Unknown]));
                    // A FIN given leaves e unknown; this stage said nothing of e: elastic.
                    if problem.restitution.is_none() && !problem.knowns.pass_through {
                        problem.restitution = Some(Given::Known(Restitution::elastic()));
                    }
                }
                if let Some(f) = problem.fin.as_mut() {
                    f.0[t.body] = velocity(run, number);
                }
                fixed.push(Fixed {
                    text: t.text.clone(),
                    by: later.name.clone(),
                    value,
                });
            }
        }
        Ok((problem, fixed))
    }

    /// Stage `i` solved, with `problem` as its values (`exact`: FIN exactly, else binary64).
    pub(super) fn run(
        &self,
        i: usize,
        problem: &Problem,
        exact: bool,
    ) -> Result<StageRun, SceneError> {
        let stage = &self.stages[i];
        let posed = problem
            .solve(None)
            .map_err(|e| self.at(stage, format!("{e:#}")))?;
        let fin = match &posed {
            Posed::Collision(case, _) if exact => ExactCollision::from_case(case).v_fin_q(),
            Posed::Collision(case, _) => {
                let f = case.collision.v_fin();
                [from_f64(f.x), from_f64(f.y)]
            }
            Posed::Wall(w, _) if exact => w.fin(),
            Posed::Wall(w, _) => w.fin().map(|q| from_f64(to_f64(&q).unwrap_or(f64::NAN))),
            Posed::Separation(s, solved) if solved.pass_through => match exact {
                true => s.fin.clone(),
                false => s
                    .fin
                    .clone()
                    .map(|q| from_f64(to_f64(&q).unwrap_or(f64::NAN))),
            },
            Posed::Separation(..) | Posed::Separations(..) => {
                return Err(self.at(
                    stage,
                    "the bodies start together and are pushed apart (a separation): a stage \
                     is a collision, a pass-through or a bounce off a wall"
                        .into(),
                ));
            }
        };
        let units = posed.units().clone();
        let mut show = Sections::new(stage.show.iter().copied());
        show.contact_time = stage.contact_time.clone();
        show.heights = Some(crate::values::units::HeightScale::new(
            stage.problem.gravity.as_ref(),
            &units,
        ));
        Ok(StageRun { posed, fin, show })
    }

    /// Each stage checked again with the chain's values, exactly: the FIN a stage takes is the
    /// FIN its source stage leaves (a collision's worked out forward from its masses, IN and
    /// solved `e`, a wall's from its `e`), and momentum holds in every stage between two
    /// bodies. Returns the first stage that fails, and why.
    pub(super) fn check(&self, runs: &[StageRun]) -> Result<(), SceneError> {
        for (k, stage) in self.stages.iter().enumerate() {
            let run = &runs[k];
            let v_in = velocities_in(&run.posed);
            for (slot, t) in stage.takes.iter().enumerate() {
                let Some(t) = t else { continue };
                let left = &runs[t.stage].fin[t.body];
                if *left != v_in[slot] {
                    return Err(self.at(
                        stage,
                        format!(
                            "the given values contradict each other: {} leaves {} at {}, but \
                             this stage needs it at {}",
                            self.stages[t.stage].name,
                            t.text,
                            fraction(left),
                            fraction(&v_in[slot])
                        ),
                    ));
                }
            }
            let residual = match &run.posed {
                Posed::Collision(case, _) => {
                    let m = case.inertia().entries();
                    let (m1, m2) = (m[0][0].exact(), m[1][1].exact());
                    &m1 * (&run.fin[0] - &v_in[0]) + &m2 * (&run.fin[1] - &v_in[1])
                }
                Posed::Separation(s, _) => s.momentum_residual(),
                Posed::Wall(..) | Posed::Separations(..) => Q::ZERO,
            };
            if !residual.is_zero() {
                return Err(self.at(
                    stage,
                    format!(
                        "momentum misses by {} with the chain's values",
                        fraction(&residual)
                    ),
                ));
            }
        }
        Ok(())
    }
}

/// IN of a posed stage, exactly (a wall's entry is its velocity).
pub(super) fn velocities_in(posed: &Posed) -> [Q; 2] {
    match posed {
        Posed::Collision(case, _) => case.velocities.each_ref().map(Number::exact),
        Posed::Wall(w, _) => w.v(),
        Posed::Separation(s, _) => s.velocities.each_ref().map(Number::exact),
        Posed::Separations(pair) => pair[0].0.velocities.each_ref().map(Number::exact),
    }
}
