//! A range asked of a chain (issue 42 §2): one stage's restitution unknown (`restitution =
//! "?"`) and a top-level `condition` on what follows the last stage (`"collide again"`, `"A and
//! B collide again"`, `"no further collision"`). "For what e' does a second collision happen?"
//!
//! Every other value is given, so every velocity from the unknown stage on is affine in `e'`
//! (each stage's FIN is linear in its IN with known masses and `e`, and the unknown stage's IN
//! does not depend on `e'`): the chain is carried exactly at `e' = 0` and `e' = 1`, each velocity
//! taken as the line through the two, and that line is checked at `e' = 1/2`. Every decision
//! (each stage happens, the order of the bodies, which neighbours approach after the last stage)
//! is a sign of a difference of two such velocities, so it is constant between their roots in
//! `(0, 1)`. The chain is then solved as a plain chain ([`StagesScene::solve`], exactly) at each
//! root, at 0 and 1 and once inside each gap between them: where the condition holds is a union
//! of intervals with exact rational ends ([`crate::report::range`]).

use std::ops::Range as Span;
use std::path::Path;

use toml::Spanned;

use super::super::{SceneError, located};
use super::system::velocities_in;
use super::{SolvedStages, Stage, StageRun, StagesScene};
use crate::line::chain::{Meeting, Object, Side};
use crate::line::problem::Posed;
use crate::line::restitution::Restitution;
use crate::report::range::{Affine, AffineStage, Condition, Interval, Range, SYMBOL, Values};
use crate::report::stages::object_name;
use crate::values::number::Given;
use crate::values::quantity::fraction;
use crate::values::rational::{Q, half};

/// What a scene asks: the stage whose `e'` is unknown and the condition.
#[derive(Clone, Debug)]
pub struct Asked {
    pub condition: Condition,
    /// The two objects `"A and B collide again"` names.
    pub pair: Option<[Object; 2]>,
    /// The stage (0-based) whose restitution is unknown.
    pub stage: usize,
}

/// A chain whose condition is answered as a range.
#[derive(Clone, Debug)]
pub struct SolvedRange {
    /// The stages before the unknown one (they do not depend on it), in the scene's arithmetic.
    pub runs: Vec<StageRun>,
    /// The unknown stage and those after it, their velocities affine in `e'`.
    pub affine: Vec<AffineStage>,
    pub range: Range,
}

/// `A and B collide again` with its two names, `collide again`, `no further collision`.
fn condition(text: &str) -> Option<Condition> {
    let words = text.split_whitespace().collect::<Vec<_>>().join(" ");
    match words.as_str() {
        "collide again" => return Some(Condition::Again(None)),
        "no further collision" | "no further collisions" => return Some(Condition::NoFurther),
        _ => {}
    }
    let (a, b) = words.strip_suffix(" collide again")?.split_once(" and ")?;
    Some(Condition::Again(Some([a.to_string(), b.to_string()])))
}

/// The object a condition names: a body by name, or `wall` (`left wall`, `right wall`).
fn object(name: &str, stages: &[Stage], bodies: &[String]) -> Result<Object, String> {
    if let Some(b) = bodies.iter().position(|b| b == name) {
        return Ok(Object::Body(b));
    }
    let mut walls: Vec<Side> = stages
        .iter()
        .flat_map(|s| s.objects)
        .filter_map(|o| match o {
            Object::Wall(side) => Some(side),
            Object::Body(_) => None,
        })
        .collect();
    walls.sort();
    walls.dedup();
    let side = match name {
        "left wall" => Some(Side::Left),
        "right wall" => Some(Side::Right),
        "wall" if walls.len() == 1 => Some(walls[0]),
        "wall" if walls.len() == 2 => {
            return Err(
                "'wall': the chain has a wall on each side: name \"left wall\" or \
                        \"right wall\""
                    .into(),
            );
        }
        _ => None,
    };
    match side {
        Some(s) if walls.contains(&s) => Ok(Object::Wall(s)),
        _ => Err(format!(
            "'{name}' names no body of the chain: expected {}{}",
            bodies.join(", "),
            if walls.is_empty() { "" } else { " or \"wall\"" }
        )),
    }
}

/// Each `?` of the chain, as `stage1's velocity 1`, with its stage and whether it is an `e`.
fn unknowns(stages: &[Stage]) -> Vec<(usize, bool, String)> {
    let mut out = Vec::new();
    for (i, s) in stages.iter().enumerate() {
        let p = &s.problem;
        if let Some(m) = &p.masses {
            for (slot, g) in m.0.iter().enumerate() {
                if g.is_unknown() {
                    out.push((i, false, format!("{}'s mass {}", s.name, slot + 1)));
                }
            }
        }
        for (slot, g) in p.velocities.0.iter().enumerate() {
            if g.is_unknown() && s.takes[slot].is_none() {
                out.push((i, false, format!("{}'s velocity {}", s.name, slot + 1)));
            }
        }
        if matches!(p.restitution, Some(Given::Unknown)) {
            out.push((i, true, format!("{}'s e", s.name)));
        }
    }
    out
}

/// Reads a scene's `condition`: the one unknown `e`, the condition, the objects it names.
pub(super) fn asked(
    (path, text): (&Path, &str),
    given: &Spanned<String>,
    stages: &[Stage],
    bodies: &[String],
) -> Result<Asked, SceneError> {
    let span: Span<usize> = given.span();
    let err = |m: String| located(path, text, Some(span.clone()), format!("condition: {m}"));
    let typed = given.get_ref().trim();
    let condition = condition(typed).ok_or_else(|| {
        err(format!(
            "'{typed}': expected \"collide again\", \"A and B collide again\" (two bodies, or a \
             body and \"wall\") or \"no further collision\""
        ))
    })?;
    let all = unknowns(stages);
    let stage = match all.as_slice() {
        [] => {
            return Err(err(format!(
                "no unknown: a condition asks for the range of one stage's restitution {SYMBOL} \
                 over [0, 1]; write restitution = \"?\" in that stage"
            )));
        }
        [(i, true, _)] => *i,
        [(_, false, what)] => {
            return Err(err(format!(
                "the unknown is {what}, not a restitution: a condition asks for the range of \
                 one stage's e (restitution = \"?\"); without a condition the scene solves for \
                 {what}"
            )));
        }
        many => {
            let list: Vec<&str> = many.iter().map(|u| u.2.as_str()).collect();
            return Err(err(format!(
                "{} unknowns ({}): a condition asks for the range of one stage's e, every other \
                 value given",
                many.len(),
                list.join(", ")
            )));
        }
    };
    if stages[stage].problem.knowns.pass_through {
        return Err(err(format!(
            "{} is a pass-through, which has no restitution: ask the range of a collision's or \
             a wall's e",
            stages[stage].name
        )));
    }
    for s in stages {
        let fin = s.problem.fin.as_ref();
        if !s.problem.knowns.pass_through
            && fin.is_some_and(|f| f.0.iter().any(|g| !g.is_unknown()))
        {
            return Err(err(format!(
                "{} gives fin: a final velocity would fix {SYMBOL} (without the condition the \
                 scene solves for it); with a condition only a pass-through gives fin",
                s.name
            )));
        }
    }
    if let Some((s, e)) = stages[stage..]
        .iter()
        .find_map(|s| s.expect.first().map(|e| (s, e)))
    {
        return Err(SceneError {
            path: path.to_path_buf(),
            at: Some((e.line, 1)),
            message: format!(
                "[stage.expect] of {}: its values depend on {SYMBOL} ({}'s restitution, \
                 unknown); check the range in the top-level [expect] (\"range.text\")",
                s.name, stages[stage].name
            ),
        });
    }
    let pair = match &condition {
        Condition::Again(Some([a, b])) => {
            let (x, y) = (
                object(a, stages, bodies).map_err(&err)?,
                object(b, stages, bodies).map_err(&err)?,
            );
            if x == y {
                return Err(err(format!("'{a}' and '{b}' are one object: name two")));
            }
            Some([x, y])
        }
        _ => None,
    };
    Ok(Asked {
        condition,
        pair,
        stage,
    })
}

/// One exact solve of the chain at a value of `e'`: the condition, or why the chain is not as
/// given there.
struct Sample {
    e: Q,
    outcome: Result<SolvedStages, String>,
}

impl StagesScene {
    /// The scene with `e'` given, as a plain chain (`exact`: in fractions).
    fn with_e(&self, asked: &Asked, e: &Q, exact: bool) -> Result<StagesScene, SceneError> {
        let mut s = self.clone();
        s.range = None;
        s.exact = exact;
        let stage = &mut s.stages[asked.stage];
        let r = fraction(e)
            .parse::<Restitution>()
            .map_err(|why| self.at(&self.stages[asked.stage], format!("e' = {e}: {why}")))?;
        stage.problem.restitution = Some(Given::Known(r));
        Ok(s)
    }

    /// Answers the scene's condition as a range of `e'` (see the module docs).
    pub fn solve_range(&self) -> Result<SolvedRange, SceneError> {
        let Some(asked) = &self.range else {
            return Err(SceneError {
                path: self.about.path.clone(),
                at: None,
                message: "no condition: this chain is solved for its values".into(),
            });
        };
        let k = asked.stage;
        let raw = |e: &Q| -> Result<Vec<StageRun>, SceneError> {
            Ok(self.with_e(asked, e, true)?.carry(true)?.runs)
        };
        let (at0, at1, mid) = (raw(&Q::ZERO)?, raw(&Q::ONE)?, raw(&half())?);
        // Each stage's IN and FIN, affine in e'; checked at 1/2.
        let lines: Vec<[[Affine; 2]; 2]> = (0..self.stages.len())
            .map(|i| {
                let pairs = |r: &[StageRun]| [velocities_in(&r[i].posed), r[i].fin.clone()];
                let (a, b) = (pairs(&at0), pairs(&at1));
                [0, 1].map(|w| [0, 1].map(|s| Affine::through(&a[w][s], &b[w][s])))
            })
            .collect();
        for (i, line) in lines.iter().enumerate() {
            let m = [velocities_in(&mid[i].posed), mid[i].fin.clone()];
            if (0..4).any(|x| line[x / 2][x % 2].at(&half()) != m[x / 2][x % 2]) {
                return Err(self.at(
                    &self.stages[i],
                    format!("its velocities are not affine in {SYMBOL}: no range is computed"),
                ));
            }
        }
        // The objects after the last stage: each body's latest FIN, each wall's velocity.
        let mut objects: Vec<(Object, Affine)> = Vec::new();
        for (i, s) in self.stages.iter().enumerate() {
            for (slot, o) in s.objects.iter().enumerate() {
                objects.retain(|(x, _)| x != o);
                let v = match o {
                    Object::Body(_) => &lines[i][1][slot],
                    Object::Wall(_) => &lines[i][0][slot],
                };
                objects.push((*o, v.clone()));
            }
        }
        // Where a decision can change: a stage's two IN, or two objects that can be neighbours
        // after it, equal: two that met in a stage (any two once a pass-through swapped some).
        let through = at0.iter().any(|r| matches!(r.posed, Posed::Separation(..)));
        let met = |a: Object, b: Object| {
            through
                || self
                    .stages
                    .iter()
                    .any(|s| s.objects == [a, b] || s.objects == [b, a])
        };
        let mut differences: Vec<Affine> =
            lines[k..].iter().map(|l| l[0][0].minus(&l[0][1])).collect();
        for (x, (o, a)) in objects.iter().enumerate() {
            let others = objects[x + 1..].iter().filter(|(p, _)| met(*o, *p));
            differences.extend(others.map(|(_, b)| a.minus(b)));
        }
        let mut points: Vec<Q> = differences
            .iter()
            .filter_map(Affine::root)
            .filter(|r| *r > Q::ZERO && *r < Q::ONE)
            .chain([Q::ZERO, Q::ONE])
            .collect();
        points.sort();
        points.dedup();
        // At each point, and inside each gap.
        let mut samples: Vec<Sample> = Vec::new();
        for (x, p) in points.iter().enumerate() {
            let mut es = vec![p.clone()];
            if let Some(next) = points.get(x + 1) {
                es.push((p + next) * half());
            }
            for e in es {
                let outcome = self
                    .with_e(asked, &e, true)?
                    .solve()
                    .map_err(|why| why.message);
                samples.push(Sample { e, outcome });
            }
        }
        if samples.iter().all(|s| s.outcome.is_err()) {
            let why = samples[0]
                .outcome
                .as_ref()
                .err()
                .cloned()
                .unwrap_or_default();
            return Err(self.at(
                &self.stages[k],
                format!("for no {SYMBOL} in [0, 1] is the chain the one given: {why}"),
            ));
        }
        let holds: Vec<Option<bool>> = samples
            .iter()
            .map(|s| s.outcome.as_ref().ok().map(|o| self.holds(asked, o)))
            .collect();
        let intervals = runs(&points, &holds, |h| h == Some(true));
        let excluded = runs(&points, &holds, |h| h.is_none());
        let excluded = (!excluded.is_empty()).then(|| {
            let why = samples.iter().find_map(|s| s.outcome.as_ref().err());
            (excluded, why.cloned().unwrap_or_default())
        });
        let values = Values { exact: self.exact };
        let closest = intervals
            .is_empty()
            .then(|| self.closest(asked, &samples, values));
        let exact_runs = self.with_e(asked, &Q::ZERO, self.exact)?;
        let runs = match self.exact {
            true => at0[..k].to_vec(),
            false => exact_runs.carry(false)?.runs[..k].to_vec(),
        };
        let affine = lines[k..]
            .iter()
            .zip(&at0[k..])
            .enumerate()
            .map(|(j, (l, run))| AffineStage {
                asked: j == 0,
                event: match &run.posed {
                    Posed::Wall(..) => "wall",
                    Posed::Separation(..) => "pass-through",
                    _ => "collision",
                },
                v_in: l[0].clone(),
                fin: l[1].clone(),
            })
            .collect();
        let after = (0..self.bodies.len())
            .map(|b| {
                let (i, slot) = self.latest(b);
                (
                    self.bodies[b].clone(),
                    lines[i][1][slot].clone(),
                    self.stages[i].name.clone(),
                )
            })
            .collect();
        Ok(SolvedRange {
            runs,
            affine,
            range: Range {
                unknown: format!("{}.e", self.stages[k].name),
                condition: asked.condition.clone(),
                intervals,
                closest,
                excluded,
                after,
                exact: self.exact,
                velocity_unit: at0.first().and_then(|r| r.posed.units().velocity),
            },
        })
    }

    /// Whether the condition holds for a chain solved at one `e'`.
    fn holds(&self, asked: &Asked, solved: &SolvedStages) -> bool {
        let again = |m: &Meeting| match asked.pair {
            None => true,
            Some([a, b]) => [m.left, m.right] == [a, b] || [m.left, m.right] == [b, a],
        };
        let any = solved.meetings.iter().any(again);
        match asked.condition {
            Condition::NoFurther => !any,
            Condition::Again(_) => any,
        }
    }

    /// How close the condition comes when it holds for no `e'`: the largest closing speed of
    /// the pair asked (or of any neighbours), or, for `no further collision`, the smallest of
    /// the fastest approach, among the values of `e'` solved.
    fn closest(&self, asked: &Asked, samples: &[Sample], values: Values) -> String {
        let name = |o: Object| object_name(&self.bodies, o);
        let relevant = |m: &&Meeting| match asked.pair {
            None => true,
            Some([a, b]) => [m.left, m.right] == [a, b] || [m.left, m.right] == [b, a],
        };
        let mut best: Option<(&Q, &Meeting)> = None;
        for s in samples {
            let Ok(solved) = &s.outcome else { continue };
            let pick = match asked.condition {
                Condition::Again(_) => solved
                    .pairs
                    .iter()
                    .filter(relevant)
                    .max_by(|x, y| x.closing.cmp(&y.closing)),
                Condition::NoFurther => solved
                    .meetings
                    .iter()
                    .max_by(|x, y| x.closing.cmp(&y.closing)),
            };
            let Some(m) = pick else { continue };
            let better = match (&best, &asked.condition) {
                (None, _) => true,
                (Some((_, b)), Condition::Again(_)) => m.closing > b.closing,
                (Some((_, b)), Condition::NoFurther) => m.closing < b.closing,
            };
            if better {
                best = Some((&s.e, m));
            }
        }
        match best {
            Some((e, m)) => format!(
                "closest at {SYMBOL} = {}, where the closing speed of {} on {} is {}",
                values.show(e),
                name(m.left),
                name(m.right),
                values.show(&m.closing)
            ),
            None => match asked.pair {
                Some([a, b]) => format!(
                    "{} and {} are never neighbours after the last stage",
                    name(a),
                    name(b)
                ),
                None => "no two objects are neighbours after the last stage".into(),
            },
        }
    }
}

/// The maximal runs of samples (each point, then the gap after it) for which `keep` holds, as
/// intervals: a run that starts or ends inside a gap is open at that end.
fn runs(
    points: &[Q],
    holds: &[Option<bool>],
    keep: impl Fn(Option<bool>) -> bool,
) -> Vec<Interval> {
    // Sample 2x is points[x]; sample 2x + 1 the gap (points[x], points[x + 1]).
    let end = |s: usize, low: bool| {
        let x = s / 2;
        match (s % 2, low) {
            (0, _) => (points[x].clone(), false),
            (_, true) => (points[x].clone(), true),
            (_, false) => (points[x + 1].clone(), true),
        }
    };
    let mut out = Vec::new();
    let mut start: Option<usize> = None;
    for s in 0..=holds.len() {
        let on = s < holds.len() && keep(holds[s]);
        match (on, start) {
            (true, None) => start = Some(s),
            (false, Some(first)) => {
                let ((lo, lo_open), (hi, hi_open)) = (end(first, true), end(s - 1, false));
                out.push(Interval {
                    lo,
                    lo_open,
                    hi,
                    hi_open,
                });
                start = None;
            }
            _ => {}
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::values::rational::{int, ratio};

    #[test]
    fn conditions_read_in_three_forms() {
        assert_eq!(condition(" collide  again"), Some(Condition::Again(None)));
        assert_eq!(
            condition("no further collision"),
            Some(Condition::NoFurther)
        );
        assert_eq!(
            condition("A and the wall collide again"),
            Some(Condition::Again(Some(["A".into(), "the wall".into()])))
        );
        assert_eq!(condition("A collides again"), None);
    }

    #[test]
    fn runs_of_samples_are_intervals_open_where_they_end_inside_a_gap() {
        // Points 0, 1/2, 1: samples 0, (0, 1/2), 1/2, (1/2, 1), 1.
        let p = [Q::ZERO, ratio(1, 2), int(1)];
        let h = [
            Some(false),
            Some(false),
            Some(false),
            Some(true),
            Some(true),
        ];
        let i = runs(&p, &h, |x| x == Some(true));
        assert_eq!(
            i,
            [Interval {
                lo: ratio(1, 2),
                lo_open: true,
                hi: int(1),
                hi_open: false
            }]
        );
        // True at the point 1/2 alone, and on [0, 1/2).
        let h = [Some(true), Some(true), None, Some(false), Some(true)];
        let i = runs(&p, &h, |x| x == Some(true));
        assert_eq!(i.len(), 2);
        assert_eq!((i[0].hi.clone(), i[0].hi_open), (ratio(1, 2), true));
        assert_eq!((i[1].lo.clone(), i[1].hi.clone()), (int(1), int(1)));
    }
}
