//! Unknowns in rigid problems (issue 42 section 2): one value typed `?` (a speed, `-v '? @
//! -30deg,0'`; a mass; the hit point, `--hit-at ?`; `e`; mu, `--friction ?`), fixed by one
//! given final value: a body's final spin (`--fin-spin`) or a pivot that feels no impulse
//! (`--pivot-impulse 0`, the centre of percussion).
//!
//! The impact is solved exactly at sample values of the unknown, and the given quantity is a
//! rational function of it (`interpolate`): without friction `P = (1 + e) (n.w)/(n.K.n) n`, and
//! for bodies that join `P = K^-1 w`, so a final spin is affine in a speed or in `e`, and
//! rational in a mass or in the hit point (`omega' = m v d / (I_p + m d^2)` for a bullet that
//! lodges; the pivot's impulse `P (3d/(2L) - 1)` of a rod on its end). The unknown is a root
//! of that function's numerator in the unknown's range; each root is checked by solving the
//! impact again with it (the residual), and there must be exactly one. With Coulomb friction
//! the impact is piecewise (Routh's phases): mu is found where the contact slides throughout
//! (`P_t = mu P_n`, rational in mu); a given state the contact reaches only by sticking is
//! reached by every mu from the one at which the slip just stops, and that range is the
//! answer (`mu >= X`).

use num_traits::{Signed, Zero};

use crate::values::number::Number;
use crate::values::quantity::fraction;
use crate::values::rational::{Q, from_f64, int, pow2, to_f64};

use super::fin::{FinTyped, Resolved};
use super::homework::{HitTyped, Homework};
use super::impact::{ImpactError, Problem};
use super::interpolate::{self, Poly, Root, Roots};
use super::outcome::Outcome;
use super::pose::{Either, MassTyped, Resolver};
use super::units::{Measure, Typed};

mod friction;
pub use super::unsolvable::UnknownError;

/// What a rigid problem may leave unknown (`?`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unknown {
    /// Body `i`'s speed: `?` along x (signed), or the size of `? @ angle` (>= 0).
    Speed(usize),
    Mass(usize),
    /// `--hit-at ?`: the distance from the pivot (from the centre when free).
    HitAt,
    Restitution,
    Friction,
}

impl Unknown {
    /// The name printed: `v1`, `m2`, `hit_at`, `e`, `mu`.
    pub fn name(self) -> String {
        match self {
            Unknown::Speed(i) => format!("v{}", i + 1),
            Unknown::Mass(i) => format!("m{}", i + 1),
            Unknown::HitAt => "hit_at".into(),
            Unknown::Restitution => "e".into(),
            Unknown::Friction => "mu".into(),
        }
    }

    /// What it measures (`None`: a pure number).
    pub fn measure(self) -> Option<Measure> {
        match self {
            Unknown::Speed(_) => Some(Measure::Velocity),
            Unknown::Mass(_) => Some(Measure::Mass),
            Unknown::HitAt => Some(Measure::Length),
            Unknown::Restitution | Unknown::Friction => None,
        }
    }
}

/// A final value the problem gives.
#[derive(Clone, Debug, PartialEq)]
pub enum Known {
    /// Body `i`'s final spin (`--fin-spin`), counterclockwise positive.
    Spin(usize, Typed),
    /// The pivot gives its body no impulse (`--pivot-impulse 0`).
    PivotImpulseZero,
    /// A body's final velocity, or parts of it (`--fin`, `fin`).
    Fin(FinTyped),
}

impl Known {
    /// The name printed: `omega2'`, `pivot impulse`.
    pub fn name(&self) -> String {
        match self {
            Known::Spin(i, _) => format!("omega{}'", i + 1),
            Known::PivotImpulseZero => "the pivot's impulse".into(),
            Known::Fin(f) => f.name(),
        }
    }
}

/// The unknowns and the final values of a problem.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Asked {
    pub unknowns: Vec<Unknown>,
    pub knowns: Vec<Known>,
}

impl Asked {
    pub fn is_empty(&self) -> bool {
        self.unknowns.is_empty() && self.knowns.is_empty()
    }
}

/// A value typed with `?`: the same text with `1` in its place (`? @ -30deg` is `1 @ -30deg`,
/// `? kg` is `1 kg`); `None` when it has no `?`.
pub fn placeholder(text: &str, what: &'static str) -> Result<Option<String>, UnknownError> {
    let t = text.trim();
    if !t.contains('?') {
        return Ok(None);
    }
    match t.strip_prefix('?') {
        Some(rest) if !rest.contains('?') => Ok(Some(format!("1{rest}"))),
        _ => Err(UnknownError::Where(what, t.to_string())),
    }
}

/// What was solved: the unknown's value (in the case's units), or for mu where the contact
/// sticks the least value (`at_least`).
#[derive(Clone, Debug, PartialEq)]
pub struct Value {
    pub unknown: Unknown,
    pub value: Q,
    /// Not rational, or from binary64 input: held to 40 digits, or binary64.
    pub approx: bool,
    /// `mu >= value`: every friction from it on gives this FIN (the contact sticks).
    pub at_least: bool,
}

/// A given final value against the impact solved with the unknown in place.
#[derive(Clone, Debug, PartialEq)]
pub struct Check {
    pub name: String,
    pub given: Q,
    /// The impact's value less the given one (a vector's size for the pivot's impulse).
    pub residual: Q,
    /// The residual is a rounding, not exactly 0.
    pub approx: bool,
    /// The given value as typed, where it is not one number (a final velocity).
    pub typed: Option<String>,
}

/// A problem with its unknown solved.
#[derive(Clone, Debug, PartialEq)]
pub struct Solution {
    /// The problem with the value in place, to report.
    pub problem: Problem,
    pub value: Option<Value>,
    pub checks: Vec<Check>,
}

/// The unknown's value as a typed number in the case's units (SI when it has any).
fn number(x: &Q) -> Option<Number> {
    Number::solved(&fraction(x)).ok()
}

/// The homework with `x` for the unknown (`None` when `x` is not a binary64 number).
pub fn with(hw: &Homework, u: Unknown, x: &Q, si: bool) -> Option<Homework> {
    let n = number(x)?;
    let unit = match (u.measure(), si) {
        (Some(m), true) => {
            Typed::parse(&format!("1 {}", m.si_name()), m, "")
                .ok()?
                .unit
        }
        _ => None,
    };
    let set = |t: &mut Typed| {
        t.number = n.clone();
        t.unit = unit;
    };
    let mut h = hw.clone();
    match u {
        Unknown::Speed(i) => match h.velocities[i].as_mut()? {
            Either::One(t) => set(t),
            Either::Vector(v) => {
                v.parts = vec![n.clone()];
                v.unit = unit;
            }
        },
        Unknown::Mass(i) => match &mut h.masses[i] {
            MassTyped::Mass(t) => set(t),
            MassTyped::Immovable(_) => return None,
        },
        Unknown::HitAt => {
            let mut t = Typed::parse("0", Measure::Length, "--hit-at").ok()?;
            set(&mut t);
            h.hit_at = Some(HitTyped::At(t));
        }
        Unknown::Restitution => h.laws.restitution = n,
        Unknown::Friction => h.laws.friction = Some(n),
    }
    Some(h)
}

/// The problem with `x` in place. A speed scales the velocity of size 1 laid out (`1 @
/// -30deg`), exactly: laid out again, the components of `x @ -30deg` would be rounded to
/// binary64, and the impact would not be rational in `x`.
pub fn problem_at(hw: &Homework, u: Unknown, x: &Q, si: bool) -> Result<Problem, String> {
    let at = match u {
        Unknown::Speed(_) => Q::ONE,
        _ => x.clone(),
    };
    let h = with(hw, u, &at, si).ok_or_else(|| "not a binary64 number".to_string())?;
    let mut problem = h.pose().map_err(|e| e.to_string())?;
    if let Unknown::Speed(i) = u {
        let v = &mut problem.motions[i].v;
        *v = super::algebra::scale(v, x);
    }
    Ok(problem)
}

/// The impact with `x` in place.
fn outcome(hw: &Homework, u: Unknown, x: &Q, si: bool) -> Result<Outcome, String> {
    let problem = problem_at(hw, u, x, si)?;
    super::solve(problem).map_err(|e| match e {
        ImpactError::NotApproaching(_) => "the bodies do not approach at the contact".into(),
        e => e.to_string(),
    })
}

/// A given value, resolved in the case's units.
struct Given {
    known: Known,
    value: Q,
    approx: bool,
    /// A final velocity's parts, resolved.
    fin: Option<Resolved>,
}

impl Given {
    /// The impact's value less the given one, per component.
    fn residual(&self, o: &Outcome) -> Result<Vec<Q>, UnknownError> {
        match &self.known {
            Known::Spin(i, _) => {
                let body = &o.bodies()[*i];
                if let Some(word) = body.immovable() {
                    return Err(UnknownError::NoSpin(i + 1, word));
                }
                if body.inertia().is_none() && body.pivot().is_none() {
                    return Err(UnknownError::NoSpin(i + 1, "point particle"));
                }
                Ok(vec![&o.fin[*i].omega[0] - &self.value])
            }
            Known::PivotImpulseZero => o
                .pivot_impulses()
                .into_iter()
                .flatten()
                .next()
                .ok_or(UnknownError::NoPivot),
            Known::Fin(f) => self
                .fin
                .as_ref()
                .map_or(Ok(Vec::new()), |r| r.residual(f, o)),
        }
    }

    /// `omega2' = -10` (in the case's units).
    fn text(&self) -> String {
        if let Known::Fin(f) = &self.known {
            return format!("{} = '{}'", f.name(), f.text);
        }
        format!(
            "{} = {}",
            self.known.name(),
            crate::values::quantity::significant(&self.value, 15)
        )
    }

    /// The size residuals are measured against: the given value, the spins, or the impulse.
    fn scale(&self, o: &Outcome) -> Q {
        let big = |a: Q, b: Q| if b.clone().abs() > a { b.abs() } else { a };
        match &self.known {
            Known::Spin(i, _) => big(
                big(self.value.clone().abs(), o.fin[*i].omega[0].clone()),
                o.v_in()[*i].omega[0].clone(),
            ),
            Known::PivotImpulseZero => o.impact.impulse.iter().cloned().fold(Q::ZERO, big),
            Known::Fin(f) => self.fin.as_ref().map_or(Q::ONE, |r| r.scale(f, o)),
        }
    }
}

/// The range of the unknown: `(lo, hi)`, `None` for no bound.
type Range = (Option<Q>, Option<Q>);

/// Solves for the one unknown of `hw` from the given final values (the first fixes it, the
/// others are checked); with no unknown, the given values are checked.
pub fn solve(hw: &Homework, asked: &Asked) -> Result<Solution, UnknownError> {
    let si = hw.has_unit();
    let r = Resolver::new(si, hw.exact);
    let mut given = Vec::new();
    for k in &asked.knowns {
        let (value, approx, fin) = match k {
            Known::Spin(_, t) => {
                let v = r.one(t).map_err(|e| UnknownError::Pose(e.to_string()))?;
                (v, r.rounded(), None)
            }
            Known::PivotImpulseZero => (Q::ZERO, false, None),
            Known::Fin(f) => (Q::ZERO, r.rounded(), Some(f.resolve(&r)?)),
        };
        given.push(Given {
            known: k.clone(),
            value,
            approx: approx || r.rounded(),
            fin,
        });
    }
    let unknown = match (asked.unknowns.as_slice(), given.len()) {
        ([], _) => None,
        ([u], 0) => return Err(UnknownError::NoKnown(u.name())),
        ([u], _) => Some(*u),
        (many, k) => {
            return Err(UnknownError::TooMany {
                count: many.len(),
                names: many.iter().map(|u| u.name()).collect::<Vec<_>>().join(", "),
                knowns: k,
                more: many.len().saturating_sub(k).max(1),
            });
        }
    };
    let Some(u) = unknown else {
        let problem = hw.pose().map_err(|e| UnknownError::Pose(e.to_string()))?;
        let o = super::solve(problem).map_err(|e| UnknownError::Pose(e.to_string()))?;
        return Ok(Solution {
            problem: o.problem.clone(),
            value: None,
            checks: checks(&o, &given, false)?,
        });
    };
    let friction = matches!(&hw.laws.friction, Some(m) if m.value() != 0.0);
    if friction && u != Unknown::Friction {
        return Err(UnknownError::WithFriction(u.name()));
    }
    let (value, o) = if u == Unknown::Friction {
        friction::friction_of(hw, &given[0], si)?
    } else {
        rational(hw, u, &given[0], si)?
    };
    let approx = value.approx || !hw.exact;
    Ok(Solution {
        problem: o.problem.clone(),
        checks: checks(&o, &given, approx)?,
        value: Some(value),
    })
}

/// Each given value against the impact.
fn checks(o: &Outcome, given: &[Given], approx: bool) -> Result<Vec<Check>, UnknownError> {
    given
        .iter()
        .map(|g| {
            let res = g.residual(o)?;
            Ok(Check {
                name: g.known.name(),
                given: g.value.clone(),
                residual: Resolved::miss(&res),
                approx: approx || g.approx || o.approx(),
                typed: match &g.known {
                    Known::Fin(f) => Some(f.text.clone()),
                    _ => None,
                },
            })
        })
        .collect()
}

/// Whether a residual is zero: exactly, or within 1e-9 of the scale when any value is rounded.
fn holds(res: &[Q], scale: &Q, approx: bool) -> bool {
    if !approx {
        return res.iter().all(Zero::is_zero);
    }
    let tol = scale * from_f64(1e-9);
    res.iter().all(|r| r.clone().abs() <= tol)
}

/// Samples of the unknown in its range, binary64 numbers (so each is used as it is).
fn candidates(u: Unknown, range: &Range) -> Vec<Q> {
    let b64 = |q: Q| to_f64(&q).map_or(q, from_f64);
    match range {
        (Some(lo), Some(hi)) => (0..=16)
            .map(|k| b64(lo + (hi - lo) * int(k) / int(16)))
            .filter(|x| u == Unknown::Restitution || (x > lo && x < hi))
            .collect(),
        (lo, _) => {
            let mut out = Vec::new();
            for scale in [0isize, 10, -10, 20, -20] {
                for k in 1..=16 {
                    out.push(pow2(scale) * int(k));
                    if lo.is_none() {
                        out.push(-(pow2(scale) * int(k)));
                    }
                }
            }
            out
        }
    }
}

/// The unknown's range: a size along a direction, a mass, mu >= 0; e in [0, 1]; the hit point
/// on the target.
fn range(hw: &Homework, u: Unknown, si: bool) -> Result<Range, UnknownError> {
    Ok(match u {
        Unknown::Speed(i) => match &hw.velocities[i] {
            Some(Either::Vector(v)) if v.angle.is_some() => (Some(Q::ZERO), None),
            _ => (None, None),
        },
        Unknown::Mass(_) | Unknown::Friction => (Some(Q::ZERO), None),
        Unknown::Restitution => (Some(Q::ZERO), Some(Q::ONE)),
        Unknown::HitAt => {
            let pose = |h: Option<HitTyped>| {
                let mut t = hw.clone();
                t.hit_at = h;
                t.pose().map_err(|e| UnknownError::Pose(e.to_string()))
            };
            let top = pose(Some(HitTyped::End))?;
            let zero = Typed::parse(if si { "0 m" } else { "0" }, Measure::Length, "--hit-at")
                .map_err(|e| UnknownError::Pose(e.to_string()))?;
            let base = pose(Some(HitTyped::At(zero)))?;
            let half = top.pair.contact.point[1].clone();
            let y0 = base.pair.contact.point[1].clone();
            (Some(-&half - &y0), Some(half - y0))
        }
    })
}

/// The unknown where the given value is a rational function of it (no friction).
fn rational(
    hw: &Homework,
    u: Unknown,
    given: &Given,
    si: bool,
) -> Result<(Value, Outcome), UnknownError> {
    if u == Unknown::HitAt
        && let Some(round) = round_target(hw, si)?
    {
        return round_hit(hw, given, si, &round);
    }
    let range = range(hw, u, si)?;
    let samples = sampled(hw, u, given, si, candidates(u, &range), Q::clone)?;
    let found = roots_of(&samples, u, &range)?;
    pick(hw, u, given, si, &range, found, |_| true)
}

/// The residual at samples `s` of a parameter (the unknown at `x_of(s)`), up to
/// `interpolate::SAMPLES` of them where the impact is solved.
fn sampled(
    hw: &Homework,
    u: Unknown,
    given: &Given,
    si: bool,
    at: impl IntoIterator<Item = Q>,
    x_of: impl Fn(&Q) -> Q,
) -> Result<Vec<(Q, Vec<Q>)>, UnknownError> {
    let mut samples = Vec::new();
    for s in at {
        if let Ok(o) = outcome(hw, u, &x_of(&s), si) {
            samples.push((s, given.residual(&o)?));
        }
        if samples.len() == interpolate::SAMPLES {
            break;
        }
    }
    Ok(samples)
}

/// A round target's radius and name (`None`: the target is not round).
fn round_target(hw: &Homework, si: bool) -> Result<Option<(Q, &'static str)>, UnknownError> {
    let Some(target) = &hw.target else {
        return Ok(None);
    };
    let (shape, _) = target
        .resolve(si, hw.exact)
        .map_err(|e| UnknownError::Pose(e.to_string()))?;
    Ok(shape
        .kind
        .round()
        .then(|| (shape.radius(), shape.kind.name())))
}

/// `--hit-at ?` on a round target (a disk, ring, sphere or shell). The contact `(-sqrt(R^2 -
/// b^2), b)` is not rational in the height b, but it is in `t = tan(phi / 2)`, phi the contact's
/// angle from the -x axis: `b = 2 R t / (1 + t^2)` and `sqrt(R^2 - b^2) = R (1 - t^2) / (1 +
/// t^2)` (the rational parametrisation of the circle), so the given value is a rational function
/// of t on (-1, 1), one-to-one with b on (-R, R). A smooth contact on a target free or pivoted at
/// its centre leaves b undetermined: the normal passes through the centre, and the impulse has
/// no moment about it.
fn round_hit(
    hw: &Homework,
    given: &Given,
    si: bool,
    (rad, name): &(Q, &'static str),
) -> Result<(Value, Outcome), UnknownError> {
    let smooth = hw.laws.tangential_restitution.is_none() && !hw.laws.join;
    match &hw.pivot {
        None if smooth => return Err(UnknownError::Round(name, "that is free")),
        Some(super::homework::PivotTyped::Centre) if smooth => {
            return Err(UnknownError::Round(name, "on a pivot at its centre"));
        }
        _ => {}
    }
    let b_of = |t: &Q| int(2) * rad * t / (Q::ONE + t * t);
    // The samples in exact arithmetic, the typed values as the rationals they spell: b rounded
    // to binary64 would make sqrt(R^2 - b^2) irrational, and the samples not a rational
    // function of t. The root is then checked on the problem as typed (`pick`).
    let mut exact = hw.clone();
    exact.exact = true;
    // t = 0, 1/16, -1/16, 2/16, ...: inside (-1, 1), where the ball meets the target.
    let ts = (0..16).flat_map(|k| [k, -k]).skip(1);
    let ts = ts.map(|k| crate::values::rational::ratio(k, 16));
    let samples = sampled(&exact, Unknown::HitAt, given, si, ts, b_of)?;
    let found = roots_of(&samples, Unknown::HitAt, &(Some(-Q::ONE), Some(Q::ONE)))?;
    // A root of degree 3 or more is bisected: where a small rational near it gives the given
    // value exactly (t = 1/3, b = 3R/5), that is the root.
    let exactly = |t: &Q| {
        outcome(&exact, Unknown::HitAt, &b_of(t), si)
            .ok()
            .and_then(|o| given.residual(&o).ok())
            .is_some_and(|r| r.iter().all(Zero::is_zero))
    };
    let found = found
        .into_iter()
        .map(|r| {
            match interpolate::convergents(&r.x)
                .into_iter()
                .find(|t| !r.exact && exactly(t))
            {
                Some(t) => Root {
                    x: b_of(&t),
                    exact: true,
                },
                None => Root {
                    x: b_of(&r.x),
                    exact: r.exact,
                },
            }
        })
        .collect();
    let range = (Some(-rad.clone()), Some(rad.clone()));
    pick(hw, Unknown::HitAt, given, si, &range, found, |_| true)
}

/// The roots of the residual's first component that is not zero for every value, over the
/// whole line (the range is checked after).
fn roots_of(samples: &[(Q, Vec<Q>)], u: Unknown, range: &Range) -> Result<Vec<Root>, UnknownError> {
    let parts = samples.first().map_or(0, |(_, r)| r.len());
    let mut side_only = false;
    for c in 0..parts {
        let points: Vec<(Q, Q)> = samples
            .iter()
            .map(|(x, r)| (x.clone(), r[c].clone()))
            .collect();
        let Some((n, _)) = interpolate::fit(&points) else {
            if c > 0 {
                // The first part is the same for every value; a later one is not rational
                // (a final velocity's side of its direction): nothing fixes the unknown.
                side_only = true;
                break;
            }
            return Err(UnknownError::Pose(format!(
                "{} ?: the impact could not be solved at enough values of it to find it",
                u.name()
            )));
        };
        if let Some(found) = line_roots(&n, range) {
            return Ok(found);
        }
    }
    let why = match side_only {
        true => "a final velocity on the given line; the side alone does not fix it ('S @ A')",
        false => "the same value (the given one)",
    };
    Err(UnknownError::Many(format!(
        "every {} gives {why}",
        u.name()
    )))
}

/// The real roots of `n` over the whole line, or within a bounded range (`None`: `n` is 0).
fn line_roots(n: &Poly, range: &Range) -> Option<Vec<Root>> {
    let b = interpolate::root_bound(n);
    let lo = match &range.0 {
        Some(lo) if range.1.is_some() => lo.clone(),
        _ => -b.clone(),
    };
    let hi = range.1.clone().unwrap_or(b);
    match interpolate::roots(n, &lo, &hi) {
        Roots::All => None,
        Roots::Some(r) => Some(r),
    }
}

/// The one root in the range whose impact gives the given value (`accept` filters the
/// impacts, e.g. a contact that slides throughout).
fn pick(
    hw: &Homework,
    u: Unknown,
    given: &Given,
    si: bool,
    range: &Range,
    found: Vec<Root>,
    accept: impl Fn(&Outcome) -> bool,
) -> Result<(Value, Outcome), UnknownError> {
    let unit = unit_of(u, si);
    let show = |x: &Q| {
        format!(
            "{} = {}{unit}",
            u.name(),
            crate::values::quantity::significant(x, 15)
        )
    };
    let inside = |x: &Q| {
        range.0.as_ref().is_none_or(|lo| x >= lo) && range.1.as_ref().is_none_or(|hi| x <= hi)
    };
    let mut fits = Vec::new();
    let mut why = Vec::new();
    for root in found {
        if !inside(&root.x) {
            why.push(format!(
                "{} is out of its range ({})",
                show(&root.x),
                range_text(u, range)
            ));
            continue;
        }
        if hw.exact && !root.exact {
            return Err(UnknownError::Irrational(
                u.name(),
                crate::values::quantity::significant(&root.x, 15),
            ));
        }
        // As the impact uses it: binary64 input is rounded to binary64.
        let x = if hw.exact {
            root.x.clone()
        } else {
            to_f64(&root.x).map_or(root.x.clone(), from_f64)
        };
        match outcome(hw, u, &x, si) {
            Ok(o) => {
                let res = given.residual(&o)?;
                let approx = !root.exact || !hw.exact || given.approx || o.approx();
                if accept(&o) && holds(&res, &given.scale(&o), approx) {
                    fits.push((
                        Value {
                            unknown: u,
                            value: x,
                            approx: !root.exact || o.approx(),
                            at_least: false,
                        },
                        o,
                    ));
                } else if let Known::Fin(f) = &given.known {
                    why.push(super::fin::off_line(f, &o, &show(&x)));
                } else {
                    why.push(format!("{} does not give it", show(&x)));
                }
            }
            Err(e) => why.push(format!("{} makes no impact: {e}", show(&x))),
        }
    }
    match fits.len() {
        1 => Ok(fits.remove(0)),
        0 if why.is_empty() => Err(UnknownError::None(format!(
            "no {} gives {}",
            u.name(),
            given.text()
        ))),
        0 => Err(UnknownError::Impossible(u.name(), why.join("; "))),
        _ => Err(UnknownError::Many(
            fits.iter()
                .map(|(v, _)| show(&v.value))
                .collect::<Vec<_>>()
                .join(" and "),
        )),
    }
}

/// ` m/s` after a value in SI, or nothing.
fn unit_of(u: Unknown, si: bool) -> String {
    match (u.measure(), si) {
        (Some(m), true) => format!(" {}", m.si_name()),
        _ => String::new(),
    }
}

fn range_text(u: Unknown, range: &Range) -> String {
    match (u, range) {
        (Unknown::Speed(_), (Some(_), None)) => {
            "a size along a direction is >= 0; spins are counterclockwise positive: a spin of \
             the other sign?"
                .into()
        }
        (_, (Some(lo), Some(hi))) => format!(
            "{} to {}",
            crate::values::quantity::significant(lo, 15),
            crate::values::quantity::significant(hi, 15)
        ),
        (_, (Some(_), None)) => "it is > 0".into(),
        _ => "any".into(),
    }
}
