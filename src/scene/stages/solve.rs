//! Solving a chain of stages: each stage posed with the velocities it takes, in exact
//! arithmetic (every decision) and, unless the scene is exact, again in binary64 (what is
//! printed).

use std::collections::BTreeMap;

use super::super::SceneError;
use super::system::{Carried, velocities_in};
use super::{SolvedStages, Stage, StageRun, StagesScene};
use crate::line::chain::{Line, Meeting, Object, OrderError, Side};
use crate::line::problem::Posed;
use crate::report::stages::object_name;
use crate::values::quantity::fraction;
use crate::values::rational::Q;
use crate::values::units::{Dimension, lookup};

impl StagesScene {
    pub(super) fn at(&self, stage: &Stage, message: String) -> SceneError {
        SceneError {
            path: self.about.path.clone(),
            at: Some((stage.line, 1)),
            message: format!("[[stage]] {}: {message}", stage.name),
        }
    }

    /// Solves the chain: each stage with the velocities its references take, in the scene's
    /// arithmetic, with every decision (the stage happens, the order holds, what comes next)
    /// made on the exact chain.
    pub fn solve(&self) -> Result<SolvedStages, SceneError> {
        let Carried { runs: exact, fixed } = self.carry(true)?;
        let mut line = Line::default();
        let mut walls: BTreeMap<Side, (Q, usize)> = BTreeMap::new();
        for (i, (stage, run)) in self.stages.iter().zip(&exact).enumerate() {
            self.decide(i, stage, run, (&exact, &mut line, &mut walls))?;
        }
        // Every stage in one velocity unit (decided above): the values compare.
        self.check(&exact)?;
        let runs = if self.exact {
            exact.clone()
        } else {
            self.carry(false)?.runs
        };
        let latest = |runs: &[StageRun], b: usize| {
            let (i, slot) = self.latest(b);
            (runs[i].fin[slot].clone(), i)
        };
        let velocity = |o: Object| match o {
            Object::Body(b) => latest(&exact, b).0,
            Object::Wall(side) => walls[&side].0.clone(),
        };
        let meetings = line.meetings(velocity);
        let pairs = (line.neighbours().into_iter())
            .map(|(left, right, _)| Meeting {
                left,
                right,
                closing: velocity(left) - velocity(right),
            })
            .collect();
        Ok(SolvedStages {
            after: (0..self.bodies.len()).map(|b| latest(&runs, b)).collect(),
            meetings,
            pairs,
            velocity_unit: exact.first().and_then(|r| r.posed.units().velocity),
            runs,
            fixed,
        })
    }

    /// Body `b`'s last stage and its place in it.
    pub(super) fn latest(&self, b: usize) -> (usize, usize) {
        self.stages
            .iter()
            .enumerate()
            .rev()
            .find_map(|(i, s)| {
                s.objects
                    .iter()
                    .position(|o| *o == Object::Body(b))
                    .map(|slot| (i, slot))
            })
            .expect("every body is in a stage")
    }

    /// The checks of stage `i` on the exact chain: it happens (body 1 catches body 2), its
    /// bodies keep their masses, velocity unit and order, and its wall stays where it was.
    fn decide(
        &self,
        i: usize,
        stage: &Stage,
        run: &StageRun,
        (runs, line, walls): (&[StageRun], &mut Line, &mut BTreeMap<Side, (Q, usize)>),
    ) -> Result<(), SceneError> {
        let name = |o: Object| object_name(&self.bodies, o);
        let v = velocities_in(&run.posed);
        // Who is on the left: known for bodies that met before (they stay neighbours), else
        // the one faster in +x, whichever is typed first, as for any collision on a line (issue
        // 27 §2); a wall is on the side it is typed on. The collision happens when the left
        // one is the faster.
        let wall = stage.objects.iter().any(|o| matches!(o, Object::Wall(_)));
        let [o0, o1] = stage.objects;
        let typed_order = wall || line.left_of(o0, o1) || (v[0] > v[1] && !line.left_of(o1, o0));
        let (left, right, v_left, v_right) = if typed_order {
            (o0, o1, &v[0], &v[1])
        } else {
            (o1, o0, &v[1], &v[0])
        };
        if v_left <= v_right {
            let shown = |q: &Q| crate::values::quantity::Exact::Rational(q.clone());
            use crate::values::quantity::Scalar;
            let why = if wall {
                "the ball moves away from the wall".to_string()
            } else if v[0] == v[1] {
                "they move together and never meet".to_string()
            } else {
                format!(
                    "{} is on the left of {} since they met, and not faster",
                    name(left),
                    name(right)
                )
            };
            return Err(self.at(
                stage,
                format!(
                    "{} (v = {}) and {} (v = {}) do not approach, so this collision does not \
                     happen: {why}",
                    name(o0),
                    shown(&v[0]).show(),
                    name(o1),
                    shown(&v[1]).show()
                ),
            ));
        }
        let unit = run.posed.units().velocity;
        if let Some(first) = runs.first().filter(|_| i > 0)
            && first.posed.units().velocity != unit
        {
            let say =
                |u: Option<&str>| u.map_or("without a unit".to_string(), |u| format!("in {u}"));
            return Err(self.at(
                stage,
                format!(
                    "its velocities are {}, those of {} {}: a chain keeps one velocity unit, to \
                     compare the bodies after it",
                    say(unit),
                    self.stages[0].name,
                    say(first.posed.units().velocity)
                ),
            ));
        }
        for (slot, taken) in stage.takes.iter().enumerate() {
            let Some(t) = taken else { continue };
            let (before, now) = (
                mass_of(&runs[t.stage].posed, t.body),
                mass_of(&run.posed, slot),
            );
            if before != now {
                return Err(self.at(
                    stage,
                    format!(
                        "body {} is {} (taken from {}), of mass {} in {} but {} here: a body \
                         keeps its mass",
                        slot + 1,
                        name(stage.objects[slot]),
                        t.text,
                        mass_text(&runs[t.stage].posed, t.body),
                        self.stages[t.stage].name,
                        mass_text(&run.posed, slot),
                    ),
                ));
            }
        }
        for (slot, o) in stage.objects.iter().enumerate() {
            let Object::Wall(side) = *o else { continue };
            let w = v[slot].clone();
            match walls.get(&side) {
                Some((before, k)) if *before != w => {
                    return Err(self.at(
                        stage,
                        format!(
                            "the wall on the {side} moves at {} here but at {} in {}: a chain \
                             has one wall on each side",
                            fraction(&w),
                            fraction(before),
                            self.stages[*k].name
                        ),
                    ));
                }
                Some(_) => {}
                None => {
                    walls.insert(side, (w, i));
                }
            }
        }
        let through = matches!(&run.posed, Posed::Separation(_, s) if s.pass_through);
        let met = match through {
            true => line.pass(left, right, i),
            false => line.collide(left, right, i),
        };
        met.map_err(|e| {
            let m = match e {
                OrderError::Reversed { left, right } => format!(
                    "{} is on the right of {} since earlier stages, but here {} catches {} \
                         from the left: they would pass through each other",
                    name(left),
                    name(right),
                    name(left),
                    name(right)
                ),
                OrderError::Taken {
                    object,
                    side,
                    neighbour,
                    since,
                } => format!(
                    "{}'s neighbour on the {side} is {} (they met in {}), and nothing passes \
                         between bodies on a line: {} cannot meet {}",
                    name(object),
                    name(neighbour),
                    self.stages[since].name,
                    name(object),
                    name(if side == Side::Right { right } else { left })
                ),
            };
            self.at(stage, m)
        })
    }
}

/// The mass of body `slot` of a posed stage as typed, with its unit.
fn mass_text(posed: &Posed, slot: usize) -> String {
    let (m, unit) = match posed {
        Posed::Collision(case, _) => (
            case.inertia().entries()[slot][slot].clone(),
            case.units.mass,
        ),
        // A ball whose mass is not given: `?` as typed.
        Posed::Wall(w, _) => match &w.mass {
            Some(m) => (m.clone(), w.units.mass),
            None => return "?".into(),
        },
        Posed::Separation(s, _) => (s.masses[slot].clone(), s.units.mass),
        Posed::Separations(pair) => (pair[0].0.masses[slot].clone(), pair[0].0.units.mass),
    };
    match unit {
        Some(u) => format!("{} {u}", m.brief()),
        None => m.brief(),
    }
}

/// The mass of body `slot` of a posed stage, in kg when it has a unit (`None` for a wall).
fn mass_of(posed: &Posed, slot: usize) -> Option<(bool, Q)> {
    let (m, unit) = match posed {
        Posed::Collision(case, _) => (
            case.inertia().entries()[slot][slot].exact(),
            case.units.mass,
        ),
        Posed::Wall(w, _) if w.ball() == slot => (w.m()?, w.units.mass),
        Posed::Wall(..) => return None,
        Posed::Separation(s, _) => (s.masses[slot].exact(), s.units.mass),
        Posed::Separations(pair) => (pair[0].0.masses[slot].exact(), pair[0].0.units.mass),
    };
    Some(match unit.and_then(|u| lookup(u, Dimension::Mass).ok()) {
        Some(u) => (true, m * u.si()),
        None => (false, m),
    })
}
