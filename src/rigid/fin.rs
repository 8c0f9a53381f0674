//! A body's final velocity given in a rigid problem (`--fin 'F1,F2'`, in the plane's grammar,
//! `?` where not given): the whole vector (`'(-0.5,0) m/s'`; a plain number is along x, as `-v`
//! reads it: `'-0.5 m/s'` is `(-0.5, 0)`, `'2 m/s @ 30deg'`), some components (`'(?,0.5) m/s'`),
//! a direction with the speed not given (`'? @ 60deg'`), or a speed with the direction not given
//! (`'2 m/s @ ?'`). Each is a known that fixes one unknown of the impact (`unknowns`), the first
//! of its parts that depends on the unknown; the other parts are checked.
//!
//! Each part is a row `a . v' = c` (a component along an axis; a direction `d` is `d_perp . v'
//! = 0` with `d . v' >= 0`), or the speed `|v'|^2 = s^2`: all rational in the body's final
//! velocity, so the residual is a rational function of the unknown where the impact is
//! (`interpolate`). The impulse moves body i's centre only along the impulse `P` (`v_i' = v_i
//! -+ P / m_i`): without friction `P` is along the contact normal, so a final velocity off the
//! line `v_i + t n` is refused by name, with the impulse's direction.

use num_traits::Signed;

use crate::values::quantity::{significant, sqrt};
use crate::values::rational::{Q, int};

use super::algebra::dot;
use super::outcome::Outcome;
use super::pose::{Either, Resolver};
use super::units::{Measure, Typed};
use super::unsolvable::UnknownError;

/// What one body's typed final velocity gives.
#[derive(Clone, Debug, PartialEq)]
pub enum FinPart {
    /// The components marked `true` of the vector (`?` typed as 0 where not given).
    Parts(Either, [bool; 2]),
    /// `? @ angle`: the direction (the angle as typed), laid out as the unit vector `1 @ angle`.
    Direction(String),
    /// `S @ ?`: the speed.
    Speed(Typed),
}

/// A body's final velocity as typed (`--fin`).
#[derive(Clone, Debug, PartialEq)]
pub struct FinTyped {
    /// The body, from 0.
    pub body: usize,
    pub text: String,
    pub part: FinPart,
}

/// Why a `--fin` text is not a final velocity of a rigid problem.
fn bad(text: &str, why: &str) -> UnknownError {
    UnknownError::Pose(format!("--fin '{text}': {why}"))
}

impl FinTyped {
    /// Body `body`'s final velocity as typed (`None` for `?`: not given).
    pub fn parse(body: usize, text: &str) -> Result<Option<FinTyped>, UnknownError> {
        let t = text.trim();
        if t.is_empty() || t == "?" {
            return Ok(None);
        }
        let lower = t.to_ascii_lowercase();
        if lower.contains("height") || lower.contains("slide") {
            return Err(bad(
                t,
                "a height or a slide is the rail's (a body on a line); a rigid body's final \
                 velocity is a vector '(vx,vy) m/s', a number along x, 'S @ ANGLE', or '? @ ANGLE'",
            ));
        }
        let parse = |s: &str| {
            Either::parse(s, Measure::Velocity, "--fin").map_err(|e| bad(t, &e.to_string()))
        };
        let part = if let Some(rest) = t.strip_prefix('(') {
            let Some((inside, after)) = rest.split_once(')') else {
                return Err(bad(t, "a '(' without its ')'"));
            };
            let parts: Vec<&str> = inside.split(',').map(str::trim).collect();
            if parts.len() != 2 {
                return Err(bad(
                    t,
                    "the homework shapes are in the plane: give '(vx,vy)'",
                ));
            }
            let given = [parts[0] != "?", parts[1] != "?"];
            if given == [false, false] {
                return Ok(None);
            }
            let zeroed: Vec<&str> = parts
                .iter()
                .map(|p| if *p == "?" { "0" } else { p })
                .collect();
            FinPart::Parts(parse(&format!("({}){after}", zeroed.join(",")))?, given)
        } else if let Some((speed, angle)) = t.split_once('@') {
            match (speed.trim().starts_with('?'), angle.trim() == "?") {
                (true, true) => return Ok(None),
                (true, false) => {
                    // Checked here, laid out in the case's units (`resolve`).
                    parse(&format!("1 @ {}", angle.trim()))?;
                    FinPart::Direction(angle.trim().to_string())
                }
                (false, true) => FinPart::Speed(
                    Typed::parse(speed, Measure::Velocity, "--fin")
                        .map_err(|e| bad(t, &e.to_string()))?,
                ),
                (false, false) => FinPart::Parts(parse(t)?, [true, true]),
            }
        } else if t.contains('?') {
            return Err(bad(
                t,
                "'?' stands for a whole velocity, a component '(?,0.5)', the speed '? @ 60deg' \
                 or the direction '2 m/s @ ?'",
            ));
        } else {
            FinPart::Parts(parse(t)?, [true, true])
        };
        Ok(Some(FinTyped {
            body,
            text: t.to_string(),
            part,
        }))
    }

    /// `v1'`.
    pub fn name(&self) -> String {
        format!("v{}'", self.body + 1)
    }

    /// Whether a value carries a unit.
    pub fn has_unit(&self) -> bool {
        match &self.part {
            FinPart::Parts(Either::One(t), _) | FinPart::Speed(t) => t.unit.is_some(),
            FinPart::Parts(Either::Vector(v), _) => v.has_unit(),
            FinPart::Direction(_) => false,
        }
    }

    /// The rows in the case's units.
    pub fn resolve(&self, r: &Resolver) -> Result<Resolved, UnknownError> {
        let pose = |e: super::pose::PoseError| bad(&self.text, &e.to_string());
        Ok(match &self.part {
            FinPart::Parts(e, given) => {
                let v = r.along_x(e, 2).map_err(pose)?;
                let axis = |k: usize| {
                    let mut a = vec![Q::ZERO; 2];
                    a[k] = Q::ONE;
                    a
                };
                let rows = (0..2)
                    .filter(|k| given[*k])
                    .map(|k| (axis(k), v[k].clone()))
                    .collect();
                Resolved {
                    rows,
                    along: None,
                    speed: None,
                }
            }
            FinPart::Direction(angle) => {
                let unit = if r.si { " m/s" } else { "" };
                let e = Either::parse(&format!("1{unit} @ {angle}"), Measure::Velocity, "--fin")
                    .map_err(|e| bad(&self.text, &e.to_string()))?;
                let d = r.along_x(&e, 2).map_err(pose)?;
                Resolved {
                    rows: vec![(vec![-d[1].clone(), d[0].clone()], Q::ZERO)],
                    along: Some(d),
                    speed: None,
                }
            }
            FinPart::Speed(t) => {
                let s = r.one(t).map_err(pose)?;
                if s.is_negative() {
                    return Err(bad(&self.text, "a speed is >= 0"));
                }
                Resolved {
                    rows: Vec::new(),
                    along: None,
                    speed: Some(s),
                }
            }
        })
    }
}

/// A final velocity given, in the case's units: rows `a . v' = c`, a direction `v'` must point
/// along (not against), a speed.
#[derive(Clone, Debug, PartialEq)]
pub struct Resolved {
    pub rows: Vec<(Vec<Q>, Q)>,
    pub along: Option<Vec<Q>>,
    pub speed: Option<Q>,
}

impl Resolved {
    /// The impact's final velocity against the given one, one value per part (0 where it
    /// holds): each row's `a . v' - c`; against the direction, `d . v'` where it is negative;
    /// the speed's `(|v'|^2 - s^2) / 2s` (about `|v'| - s`).
    pub fn residual(&self, fin: &FinTyped, o: &Outcome) -> Result<Vec<Q>, UnknownError> {
        let i = fin.body;
        if let Some(word) = o.bodies()[i].immovable() {
            return Err(bad(
                &fin.text,
                &format!("body {} is a {word}, which does not move", i + 1),
            ));
        }
        let v = &o.fin[i].v;
        let mut out: Vec<Q> = self.rows.iter().map(|(a, c)| dot(a, v) - c).collect();
        if let Some(d) = &self.along {
            let along = dot(d, v);
            out.push(if v.iter().all(Q::is_zero) {
                // A body at rest points nowhere: the whole size of its velocity before is off.
                let before = &o.v_in()[i].v;
                -before.iter().map(|x| x.clone().abs()).fold(Q::ONE, Q::max)
            } else if along.is_negative() {
                along
            } else {
                Q::ZERO
            });
        }
        if let Some(s) = &self.speed {
            let r = dot(v, v) - s * s;
            out.push(if s.is_zero() { r } else { r / (int(2) * s) });
        }
        Ok(out)
    }

    /// The size of the miss: the residual's length.
    pub fn miss(res: &[Q]) -> Q {
        match res {
            [one] => one.clone(),
            many => sqrt(&dot(many, many), 40),
        }
    }

    /// The size values are measured against: the body's speeds and the values given.
    pub fn scale(&self, fin: &FinTyped, o: &Outcome) -> Q {
        let i = fin.body;
        let size = |v: &[Q]| v.iter().map(|x| x.clone().abs()).fold(Q::ZERO, Q::max);
        let given = self.rows.iter().map(|(_, c)| c.clone().abs());
        [size(&o.fin[i].v), size(&o.v_in()[i].v)]
            .into_iter()
            .chain(given)
            .chain(self.speed.clone())
            .fold(Q::ZERO, Q::max)
    }
}

/// `v1' = (15/7, 2)`: what the impact gives.
pub fn gives(fin: &FinTyped, o: &Outcome) -> String {
    let v = &o.fin[fin.body].v;
    format!(
        "{} = ({}, {})",
        fin.name(),
        significant(&v[0], 15),
        significant(&v[1], 15)
    )
}

/// Why an impact with the unknown at `x` (`shown`) does not give body i's typed final velocity:
/// the velocity it gives, and the line the impulse allows.
pub fn off_line(fin: &FinTyped, o: &Outcome, shown: &str) -> String {
    let i = fin.body;
    let v = &o.fin[i].v;
    let p = &o.impact.impulse;
    let f = |q: &Q| significant(q, 6);
    let pair = |v: &[Q]| format!("({}, {})", f(&v[0]), f(&v[1]));
    let len = sqrt(&dot(p, p), 40);
    let line = if len.is_zero() {
        "there is no impulse".to_string()
    } else {
        let d: Vec<Q> = p.iter().map(|x| x / &len).collect();
        format!(
            "the impulse changes body {}'s velocity only along {} (from {})",
            i + 1,
            pair(&d),
            pair(&o.v_in()[i].v)
        )
    };
    let rest = if matches!(fin.part, FinPart::Direction(_)) && v.iter().all(Q::is_zero) {
        " (a body at rest has no direction)"
    } else {
        ""
    };
    format!(
        "{shown} gives {} = {}{rest}, not the given '{}': {line}; a final velocity off that \
         line contradicts the impact (mark '?' a component not known)",
        fin.name(),
        pair(v),
        fin.text
    )
}
