//! The report of a chain of stages (`[[stage]]` scenes, issue 27 §4): each stage's own report
//! under a line naming it, then each body's velocity after the last stage and the answer to
//! "do they collide again?" ([`crate::line::chain`]).
//!
//! JSON: `{"event": "stages", "stages": [{"name", "event": "collision" | "wall", "bodies",
//! "takes": {"v1" | "v2": "stage1.fin2"}, "report"}], "after": {BODY: v}, "next": [{"bodies":
//! [LEFT, RIGHT], "closing_speed"}], "collide_again", "units": {"velocity"}}`; a wall is named
//! `left wall` or `right wall`. A chain solved as one system adds `"system": {"fixed":
//! [{"velocity": "stage1.fin1", "by": "stage2", "value"}], "check": true}`; a stage's `event`
//! may be `pass-through`. A chain asked for a range of one stage's `e'` (a `condition`) has
//! `"range"` ([`super::range`]) in place of `after`, `next` and `collide_again`; the stages from
//! the unknown one on have `"affine": {"in", "fin"}` in place of `"report"`.

use serde_json::{Map, Value, json};

use super::block::{Block, paragraph};
use super::range::Range;
use crate::line::chain::{Meeting, Object};
use crate::values::number::num;
use crate::values::quantity::{Exact, Scalar, fraction, to_f64};
use crate::values::rational::Q;

/// A stage as the chain's report shows it: its own report, rendered, and what names it.
pub struct StagePart {
    pub name: String,
    /// The name is the default `stageN`.
    pub numbered: bool,
    /// `collision`, `pass-through` or `wall`.
    pub event: &'static str,
    pub objects: [Object; 2],
    /// The velocities taken from earlier stages: `(body, "stage1.fin2")`.
    pub takes: Vec<(usize, String)>,
    pub text: String,
    pub json: Value,
    /// A stage whose velocities depend on an unknown `e'`: them, affine in it (in place of
    /// `report`; `json` is then unused).
    pub affine: Option<Value>,
}

/// A velocity an earlier stage leaves with that a later stage fixed (the chain solved as one
/// system, issue 42 §5): `stage1.fin1` fixed by `stage2`.
#[derive(Clone, Debug, PartialEq)]
pub struct Fixed {
    /// The reference, as written (`stage1.fin1`).
    pub text: String,
    /// The later stage that fixed it.
    pub by: String,
    /// Its value, exactly.
    pub value: Q,
}

/// A chain solved, for the report.
pub struct Chain<'a> {
    pub stages: Vec<StagePart>,
    /// Each body's name, by number.
    pub bodies: &'a [String],
    /// Each body's velocity after the last stage, and the stage it comes from.
    pub after: Vec<(Q, String)>,
    pub meetings: &'a [Meeting],
    pub velocity_unit: Option<&'a str>,
    /// Values as fractions (`exact = true`), or binary64.
    pub exact: bool,
    /// The taken velocities later stages fixed (none: solved in stage order).
    pub fixed: &'a [Fixed],
    /// The range of `e'` asked, in place of `after` and the answer.
    pub range: Option<&'a Range>,
}

/// A body's name, or `the wall on the right`.
pub fn object_name(bodies: &[String], o: Object) -> String {
    match o {
        Object::Body(b) => bodies[b].clone(),
        Object::Wall(side) => format!("the wall on the {side}"),
    }
}

/// A body's name, or `right wall` (as JSON names it).
pub fn object_key(bodies: &[String], o: Object) -> String {
    match o {
        Object::Body(b) => bodies[b].clone(),
        Object::Wall(side) => format!("{side} wall"),
    }
}

impl Chain<'_> {
    fn show(&self, q: &Q) -> String {
        if self.exact {
            Exact::Rational(q.clone()).show()
        } else {
            num(to_f64(q).unwrap_or(f64::NAN))
        }
    }

    fn value(&self, q: &Q) -> Value {
        if self.exact {
            Value::String(fraction(q))
        } else {
            json!(to_f64(q))
        }
    }

    fn name(&self, o: Object) -> String {
        object_name(self.bodies, o)
    }

    /// Text for people.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let n = self.stages.len();
        for (i, s) in self.stages.iter().enumerate() {
            if i > 0 {
                out.push('\n');
            }
            let named = if s.numbered {
                String::new()
            } else {
                format!(" ({})", s.name)
            };
            let takes: Vec<String> = s
                .takes
                .iter()
                .map(|(body, from)| format!("V{} = {from}", body + 1))
                .collect();
            let takes = if takes.is_empty() {
                String::new()
            } else {
                format!("; {}", takes.join(", "))
            };
            out.push_str(&paragraph(&format!(
                "Stage {} of {n}{named}: {} and {}{takes}",
                i + 1,
                self.name(s.objects[0]),
                self.name(s.objects[1]),
            )));
            out.push_str(&s.text);
        }
        if let Some(r) = self.range {
            r.text(&mut out);
            return out;
        }
        let unit = self
            .velocity_unit
            .map(|u| format!(" in {u}"))
            .unwrap_or_default();
        let mut b = Block::new(format!("After the last stage (velocities{unit})"));
        for (body, (v, stage)) in self.after.iter().enumerate() {
            b.row(&self.bodies[body], self.show(v), format!("from {stage}"));
        }
        b.render(&mut out);
        out.push_str(&paragraph(&self.answer()));
        if !self.fixed.is_empty() {
            out.push('\n');
            out.push_str(&paragraph(&self.system()));
        }
        out
    }

    /// `Solved as one system: stage2 fixes stage1.fin1 = 720, and ... Check: ...`, for a chain
    /// whose later stages fixed an earlier one's unknowns.
    fn system(&self) -> String {
        // One clause per stage that fixes, its values in order.
        let mut each: Vec<String> = Vec::new();
        for (k, f) in self.fixed.iter().enumerate() {
            let value = format!("{} = {}", f.text, self.show(&f.value));
            match k.checked_sub(1).map(|p| &self.fixed[p].by) {
                Some(by) if *by == f.by => {
                    if let Some(last) = each.last_mut() {
                        last.push_str(&format!(", {value}"));
                    }
                }
                _ => each.push(format!("{} fixes {value}", f.by)),
            }
        }
        format!(
            "Solved as one system: {}, and the stage that leaves it is solved with it as a \
             given FIN. Check: every stage again with these values: each FIN worked out forward \
             is what the next stage takes, and momentum holds, exactly.",
            each.join("; ")
        )
    }

    /// `Another collision: yes; A catches B, closing at 5/2`, or `no; ...`.
    fn answer(&self) -> String {
        let one = |m: &Meeting| {
            let closing = self.show(&m.closing);
            match (m.left, m.right) {
                (Object::Body(_), Object::Body(_)) => format!(
                    "{} catches {}, closing at {closing}",
                    self.name(m.left),
                    self.name(m.right)
                ),
                (Object::Body(_), wall) | (wall, _) => {
                    let body = if wall == m.right { m.left } else { m.right };
                    format!(
                        "{} moves toward {}, closing at {closing}",
                        self.name(body),
                        self.name(wall)
                    )
                }
            }
        };
        match self.meetings {
            [] => "Another collision: no; no two neighbours approach".into(),
            [m] => format!("Another collision: yes; {}", one(m)),
            all => format!(
                "Another collision: yes; {}; which comes first depends on where they are",
                all.iter().map(one).collect::<Vec<_>>().join("; ")
            ),
        }
    }

    /// The report as JSON (see the module docs).
    pub fn json(&self) -> Value {
        let key = |o: Object| Value::String(object_key(self.bodies, o));
        let stages: Vec<Value> = self
            .stages
            .iter()
            .map(|s| {
                let takes: Map<String, Value> = s
                    .takes
                    .iter()
                    .map(|(body, from)| (format!("v{}", body + 1), Value::String(from.clone())))
                    .collect();
                let mut stage = json!({
                    "name": s.name,
                    "event": s.event,
                    "bodies": [key(s.objects[0]), key(s.objects[1])],
                    "takes": takes,
                });
                match &s.affine {
                    Some(a) => stage["affine"] = a.clone(),
                    None => stage["report"] = s.json.clone(),
                }
                stage
            })
            .collect();
        if let Some(r) = self.range {
            let mut out = json!({"event": "stages", "stages": stages, "range": r.json()});
            if let Some(u) = self.velocity_unit {
                out["units"] = json!({ "velocity": u });
            }
            return out;
        }
        let after: Map<String, Value> = self
            .after
            .iter()
            .enumerate()
            .map(|(b, (v, _))| (self.bodies[b].clone(), self.value(v)))
            .collect();
        let next: Vec<Value> = self
            .meetings
            .iter()
            .map(|m| {
                json!({
                    "bodies": [key(m.left), key(m.right)],
                    "closing_speed": self.value(&m.closing),
                })
            })
            .collect();
        let mut out = json!({
            "event": "stages",
            "stages": stages,
            "after": after,
            "next": next,
            "collide_again": !self.meetings.is_empty(),
        });
        if let Some(u) = self.velocity_unit {
            out["units"] = json!({ "velocity": u });
        }
        if !self.fixed.is_empty() {
            let fixed: Vec<Value> = self
                .fixed
                .iter()
                .map(|f| json!({"velocity": f.text, "by": f.by, "value": self.value(&f.value)}))
                .collect();
            out["system"] = json!({ "fixed": fixed, "check": true });
        }
        out
    }
}
