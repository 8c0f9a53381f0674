//! The range of an unknown restitution for which a chain of stages meets a condition (issue 42
//! §2: "for what e' does a second collision happen?"). Every velocity after the stage whose `e'`
//! is unknown is affine in `e'` (each later stage is linear in its velocities, with known masses
//! and `e`), so each neighbour pair's closing speed after the last stage is affine in `e'`, and
//! the condition holds on a union of intervals of the physical range `0 <= e' <= 1`. At an
//! endpoint where a closing speed is 0 the two move together: no collision, an open end.
//!
//! JSON: `"range": {"unknown": "wall.e", "symbol": "e'", "condition", "intervals": [{"lo",
//! "lo_open", "hi", "hi_open"}], "text", "after": {BODY: {"constant", "slope"}}}`, with
//! `"closest"` when no `e'` meets the condition and `"excluded": {"intervals", "why"}` when for
//! some `e'` the chain is not the one given (a later stage would not happen).

use serde_json::{Map, Value, json};

use super::block::{Block, paragraph};
use crate::values::number::num;
use crate::values::quantity::{Exact, Scalar, fraction, to_f64};
use crate::values::rational::Q;

/// How the unknown is written in the text.
pub const SYMBOL: &str = "e'";

/// A value affine in the unknown: `constant + slope e'`.
#[derive(Clone, Debug, PartialEq)]
pub struct Affine {
    pub constant: Q,
    pub slope: Q,
}

impl Affine {
    /// The value that is `at0` at `e' = 0` and `at1` at `e' = 1`.
    pub fn through(at0: &Q, at1: &Q) -> Affine {
        Affine {
            constant: at0.clone(),
            slope: at1 - at0,
        }
    }

    /// The value at `e`.
    pub fn at(&self, e: &Q) -> Q {
        &self.constant + &self.slope * e
    }

    /// `self - other`.
    pub fn minus(&self, other: &Affine) -> Affine {
        Affine {
            constant: &self.constant - &other.constant,
            slope: &self.slope - &other.slope,
        }
    }

    /// Where it is 0, when it changes with `e'`.
    pub fn root(&self) -> Option<Q> {
        (!self.slope.is_zero()).then(|| -(&self.constant / &self.slope))
    }
}

/// An interval of `e'`: `lo < e'` or `lo <= e'`, and `e' < hi` or `e' <= hi`.
#[derive(Clone, Debug, PartialEq)]
pub struct Interval {
    pub lo: Q,
    pub lo_open: bool,
    pub hi: Q,
    pub hi_open: bool,
}

/// What is asked of the chain after its last stage.
#[derive(Clone, Debug, PartialEq)]
pub enum Condition {
    /// Some neighbours approach (`None`), or these two (by name).
    Again(Option<[String; 2]>),
    /// No neighbours approach.
    NoFurther,
}

impl Condition {
    /// As a scene writes it: `collide again`, `A and B collide again`, `no further collision`.
    pub fn text(&self) -> String {
        match self {
            Condition::Again(None) => "collide again".into(),
            Condition::Again(Some([a, b])) => format!("{a} and {b} collide again"),
            Condition::NoFurther => "no further collision".into(),
        }
    }

    /// The sentence's subject: `A and B collide again`, `Another collision`, `No further
    /// collision`.
    fn sentence(&self) -> String {
        match self {
            Condition::Again(None) => "Another collision".into(),
            Condition::Again(Some(_)) => self.text(),
            Condition::NoFurther => "No further collision".into(),
        }
    }
}

/// The answer: where the condition holds, and each body's velocity after the last stage.
#[derive(Clone, Debug)]
pub struct Range {
    /// The unknown, as a reference names it (`wall.e`).
    pub unknown: String,
    pub condition: Condition,
    /// Where it holds, in order, within `[0, 1]` and where the chain is as given.
    pub intervals: Vec<Interval>,
    /// When it holds nowhere: how close it comes (a sentence).
    pub closest: Option<String>,
    /// Where the chain is not the one given, and why (the first reason met).
    pub excluded: Option<(Vec<Interval>, String)>,
    /// Each body's velocity after the last stage and the stage it comes from.
    pub after: Vec<(String, Affine, String)>,
    /// Values as fractions, or binary64 (each rounded once from the exact value).
    pub exact: bool,
    pub velocity_unit: Option<&'static str>,
}

/// Renders values in the scene's arithmetic.
#[derive(Clone, Copy, Debug)]
pub struct Values {
    pub exact: bool,
}

impl Values {
    pub fn show(self, q: &Q) -> String {
        if self.exact {
            Exact::Rational(q.clone()).show()
        } else {
            num(to_f64(q).unwrap_or(f64::NAN))
        }
    }

    pub fn json(self, q: &Q) -> Value {
        if self.exact {
            Value::String(fraction(q))
        } else {
            json!(to_f64(q))
        }
    }

    /// `c + s e'`, `-2/3 e'`, `-1/3`.
    pub fn affine(self, a: &Affine) -> String {
        let term = |s: &Q| match s {
            s if *s == Q::ONE => SYMBOL.to_string(),
            s if *s == -Q::ONE => format!("-{SYMBOL}"),
            s => format!("{} {SYMBOL}", self.show(s)),
        };
        match (a.constant.is_zero(), a.slope.is_zero()) {
            (_, true) => self.show(&a.constant),
            (true, false) => term(&a.slope),
            (false, false) => {
                let sign = if a.slope < Q::ZERO { "-" } else { "+" };
                let abs = if a.slope < Q::ZERO {
                    -a.slope.clone()
                } else {
                    a.slope.clone()
                };
                format!("{} {sign} {}", self.show(&a.constant), term(&abs))
            }
        }
    }

    pub fn affine_json(self, a: &Affine) -> Value {
        json!({"constant": self.json(&a.constant), "slope": self.json(&a.slope)})
    }

    /// `1/2 < e' <= 1`, `e' = 1/2`, or `0 <= e' < 1/3 or 1/2 < e' <= 1`.
    pub fn intervals(self, all: &[Interval]) -> String {
        let one = |i: &Interval| {
            if i.lo == i.hi {
                return format!("{SYMBOL} = {}", self.show(&i.lo));
            }
            let op = |open: bool| if open { "<" } else { "<=" };
            format!(
                "{} {} {SYMBOL} {} {}",
                self.show(&i.lo),
                op(i.lo_open),
                op(i.hi_open),
                self.show(&i.hi)
            )
        };
        all.iter().map(one).collect::<Vec<_>>().join(" or ")
    }

    fn intervals_json(self, all: &[Interval]) -> Value {
        all.iter()
            .map(|i| {
                json!({"lo": self.json(&i.lo), "lo_open": i.lo_open, "hi": self.json(&i.hi),
                       "hi_open": i.hi_open})
            })
            .collect()
    }
}

/// The stage whose `e'` is unknown, or one after it: its velocities affine in `e'`.
#[derive(Clone, Debug)]
pub struct AffineStage {
    /// The stage whose restitution is asked.
    pub asked: bool,
    /// `collision`, `pass-through` or `wall`.
    pub event: &'static str,
    pub v_in: [Affine; 2],
    pub fin: [Affine; 2],
}

impl AffineStage {
    /// `e' = ?, the restitution asked` and the velocities, as text.
    pub fn text(&self, v: Values) -> String {
        let pair = |p: &[Affine; 2]| format!("({}, {})", v.affine(&p[0]), v.affine(&p[1]));
        let head = if self.asked {
            format!("{SYMBOL} = ?: this stage's restitution, asked (the range below)")
        } else {
            format!("Its velocities depend on {SYMBOL}")
        };
        paragraph(&format!(
            "{head}; V_IN = {}, V_FIN = {}",
            pair(&self.v_in),
            pair(&self.fin)
        ))
    }

    /// `{"in": [A, A], "fin": [A, A]}`, each `{"constant", "slope"}`.
    pub fn json(&self, v: Values) -> Value {
        let pair = |p: &[Affine; 2]| json!([v.affine_json(&p[0]), v.affine_json(&p[1])]);
        json!({"in": pair(&self.v_in), "fin": pair(&self.fin)})
    }
}

impl Range {
    fn values(&self) -> Values {
        Values { exact: self.exact }
    }

    /// Whether the condition holds for every `e'` in `[0, 1]`.
    fn whole(&self) -> bool {
        matches!(self.intervals.as_slice(), [i] if i.lo.is_zero() && !i.lo_open
            && i.hi == Q::ONE && !i.hi_open)
    }

    /// `1/2 < e' <= 1`, `every e' in [0, 1]` or `no e' in [0, 1]`.
    pub fn answer(&self) -> String {
        if self.intervals.is_empty() {
            format!("no {SYMBOL} in [0, 1]")
        } else if self.whole() {
            format!("every {SYMBOL} in [0, 1]")
        } else {
            self.values().intervals(&self.intervals)
        }
    }

    /// The velocities after the last stage and the answer, as text.
    pub fn text(&self, out: &mut String) {
        let v = self.values();
        let unit = self
            .velocity_unit
            .map(|u| format!(" in {u}"))
            .unwrap_or_default();
        let mut b = Block::new(format!(
            "After the last stage (velocities{unit}, {SYMBOL} the restitution of {})",
            self.unknown.trim_end_matches(".e")
        ));
        for (body, a, stage) in &self.after {
            b.row(body, v.affine(a), format!("from {stage}"));
        }
        b.render(out);
        let mut answer = format!("{} for {}", self.condition.sentence(), self.answer());
        if let Some(c) = &self.closest {
            answer.push_str(&format!(" ({c})"));
        }
        out.push_str(&paragraph(&answer));
        if let Some((where_, why)) = &self.excluded {
            out.push_str(&paragraph(&format!(
                "For {} the chain is not the one given: {why}",
                v.intervals(where_)
            )));
        }
    }

    /// The `range` object of the chain's JSON (see the module docs).
    pub fn json(&self) -> Value {
        let v = self.values();
        let after: Map<String, Value> = self
            .after
            .iter()
            .map(|(body, a, _)| (body.clone(), v.affine_json(a)))
            .collect();
        let mut out = json!({
            "unknown": self.unknown,
            "symbol": SYMBOL,
            "condition": self.condition.text(),
            "intervals": v.intervals_json(&self.intervals),
            "text": self.answer(),
            "after": after,
        });
        if let Some(c) = &self.closest {
            out["closest"] = json!(c);
        }
        if let Some((where_, why)) = &self.excluded {
            out["excluded"] = json!({"intervals": v.intervals_json(where_), "why": why});
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::values::rational::{int, ratio};

    #[test]
    fn affine_values_and_intervals_read_as_a_student_writes_them() {
        let v = Values { exact: true };
        let a = |c: Q, s: Q| Affine {
            constant: c,
            slope: s,
        };
        assert_eq!(v.affine(&a(ratio(-1, 3), Q::ZERO)), "-1/3");
        assert_eq!(v.affine(&a(Q::ZERO, ratio(-2, 3))), "-2/3 e'");
        assert_eq!(v.affine(&a(int(1), int(-1))), "1 - e'");
        assert_eq!(v.affine(&a(ratio(1, 2), int(2))), "1/2 + 2 e'");
        // 2/3 e' - 1/3 is 0 at e' = 1/2.
        assert_eq!(a(ratio(-1, 3), ratio(2, 3)).root(), Some(ratio(1, 2)));
        assert_eq!(a(int(1), Q::ZERO).root(), None);
        let i = |lo: Q, lo_open, hi: Q, hi_open| Interval {
            lo,
            lo_open,
            hi,
            hi_open,
        };
        assert_eq!(
            v.intervals(&[
                i(Q::ZERO, false, ratio(1, 3), true),
                i(ratio(1, 2), true, int(1), false),
                i(int(1), false, int(1), false)
            ]),
            "0 <= e' < 1/3 or 1/2 < e' <= 1 or e' = 1"
        );
    }
}
