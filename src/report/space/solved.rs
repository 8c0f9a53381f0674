//! What a problem in the plane or in space was solved for, and its solutions: which are
//! physical collisions, the laws checked rather than used, rendered as text and JSON.

use std::fmt::Write;

use num_traits::Signed;
use serde_json::{Map, Value, json};

use crate::line::frame::Frame;
use crate::space::outcome::{FrameVelocityError, Outcome, dot, sub};
use crate::space::pose::{Posed, outcomes};
use crate::space::solve::{Check, Solved, Statement, Unknown, Velocity};
use crate::values::rational::Q;
use crate::values::units::{EnergyUnit, EnergyUnitError, Units};

use super::super::text::{header_units, wrap};
use super::{
    Overflow, Show, Style, header, json_each, name, reverse_json, reverse_text, speed_angle,
    vector_each,
};

/// Whether component `k` of body `i`'s velocity (after when `fin`) is approximate.
fn mark(o: &Outcome, i: usize, fin: bool, k: usize) -> bool {
    if fin {
        o.approx.fin(i, k)
    } else {
        o.approx.v_in(i, k)
    }
}

/// The `Solved:` lines for the unknowns of one solution.
pub fn solved_text(o: &Outcome, unknowns: &[Unknown], style: &Style) -> String {
    if unknowns.is_empty() {
        return String::new();
    }
    let mut parts: Vec<String> = Vec::new();
    let mut seen: Vec<(usize, bool)> = Vec::new();
    for u in unknowns {
        match *u {
            Unknown::Mass(i) => parts.push(format!(
                "m{} = {}",
                i + 1,
                style.show(&o.masses[i], o.approx.mass(i))
            )),
            Unknown::Restitution => {
                if let Some(e) = &o.e {
                    parts.push(format!("e = {}", style.show(e, o.approx.e())));
                }
            }
            Unknown::Component(i, fin, _)
            | Unknown::Speed(i, fin)
            | Unknown::Direction(i, fin, _) => {
                if seen.contains(&(i, fin)) {
                    continue;
                }
                seen.push((i, fin));
                let v = if fin { &o.fin[i] } else { &o.v_in[i] };
                let polar = speed_angle(style, v);
                let polar = if polar.is_empty() {
                    String::new()
                } else {
                    format!(" = {polar}")
                };
                parts.push(format!(
                    "{} = {}{polar}",
                    name(i, fin),
                    vector_each(style, v, |k| mark(o, i, fin, k))
                ));
            }
        }
    }
    let mut out = String::from("Solved:\n");
    for p in parts {
        out.push_str(&wrap(
            &format!("  {p}"),
            crate::values::terminal::width(),
            "      ",
        ));
    }
    out
}

/// The laws checked rather than used, when any fails or the problem gave more than it needed.
pub fn checks_text(checks: &[Check], used: usize) -> String {
    let mut out = String::new();
    for c in checks.iter().skip(used).filter(|c| !c.ok) {
        let line = format!(
            "Check: {} does NOT hold: it misses by {} (of terms of size {})",
            c.law.name(),
            crate::values::quantity::significant(&c.residual, 3),
            crate::values::quantity::significant(&c.scale, 3)
        );
        out.push_str(&wrap(&line, crate::values::terminal::width(), "  "));
    }
    out
}

/// How a problem's solutions are printed.
pub struct Options<'a> {
    /// The frame to see each solution from.
    pub frame: &'a Frame,
    pub show: Show,
    pub exact: bool,
    pub reverse: bool,
    /// The problem gave final velocities (its FIN unknowns are asked for, not computed).
    pub fin_given: bool,
    pub energy_unit: Option<&'static EnergyUnit>,
}

/// A problem's solutions, as text and as JSON.
pub struct Rendered {
    pub text: String,
    pub json: Value,
    /// Given values contradict a law checked rather than used (exit 1; no event printed).
    pub inconsistent: bool,
}

/// Why solutions cannot be printed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RenderError {
    #[error(transparent)]
    Overflow(#[from] Overflow),
    #[error(transparent)]
    Frame(#[from] FrameVelocityError),
    #[error(transparent)]
    EnergyUnit(#[from] EnergyUnitError),
    #[error(
        "no real solution: the given values cannot satisfy the laws together (the energy \
         equation has no real root); check them"
    )]
    NoSolution,
    #[error(
        "e = {0} < 0: along the line of impact the bodies would pass through each other (the \
         final velocities given approach, or stay, where a collision separates them); check them"
    )]
    NegativeRestitution(String),
    #[error(
        "{0}: its speed along the direction given for it comes out negative (the body would \
         leave the opposite way), so no collision has these directions; check them (or give \
         the direction as '?')"
    )]
    NegativeSpeed(String),
}

/// Why a solution is left out when another one is physical.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    Physical,
    /// FIN = IN: the bodies pass without an impulse.
    NoImpulse,
    /// They would approach after or separate before, along the impulse.
    Unphysical,
    /// A speed along a given direction came out negative (the opposite direction).
    NegativeSpeed,
}

impl Verdict {
    pub fn describe(self) -> &'static str {
        match self {
            Verdict::Physical => "physical",
            Verdict::NoImpulse => "no impulse: the bodies pass each other unchanged",
            Verdict::Unphysical => {
                "unphysical: along the impulse the bodies would separate before or approach after"
            }
            Verdict::NegativeSpeed => "a speed along a given direction is negative",
        }
    }

    /// Whether a solution is a physical collision.
    pub fn of(o: &Outcome, st: &Statement) -> Verdict {
        for (i, v) in st.fin.iter().chain(&st.v_in).enumerate() {
            if let Velocity::Speed { unit } = v {
                let body = i % o.bodies();
                let vel = if i < o.bodies() {
                    &o.fin[body]
                } else {
                    &o.v_in[body]
                };
                if dot(vel, unit) < Q::ZERO {
                    return Verdict::NegativeSpeed;
                }
            }
        }
        if o.bodies() != 2 {
            return Verdict::Physical;
        }
        if o.impulse_line().is_none() {
            return if o.v_in == o.fin {
                Verdict::NoImpulse
            } else {
                Verdict::Physical
            };
        }
        match o.physical() {
            Some(false) => Verdict::Unphysical,
            _ => Verdict::Physical,
        }
    }
}

/// A problem's solutions judged in the lab: the one answer `solve`, `frames` and `plot` all take.
pub enum Judged {
    /// A collision asked outright whose bodies do not approach along the line of impact: they do
    /// not collide (no FIN). `along` is `n.(v1 - v2) <= 0`.
    Receding { o: Box<Outcome>, along: Q },
    /// The solutions kept (the physical ones, or all, when none is), with their checks and
    /// verdicts; `inconsistent` when given values contradict a law checked (exit 1).
    Solutions {
        kept: Vec<(Outcome, Vec<Check>, Verdict)>,
        inconsistent: bool,
    },
}

/// The unknowns the reader asked for: the final velocities are unknowns of the laws, but only
/// what the problem marked '?' (or gave as final velocities) is "solved" for the reader.
pub fn asked(solved: &Solved, fin_given: bool) -> Vec<Unknown> {
    solved
        .unknowns
        .iter()
        .filter(|u| fin_given || !matches!(u, Unknown::Component(_, true, _)))
        .copied()
        .collect()
}

/// The solutions of a posed problem judged in the lab, once, for every output: the physical
/// ones (or all, when none is); a collision asked outright whose bodies do not approach is
/// [`Judged::Receding`]; a restitution solved below zero, or a speed solved negative along the
/// direction the problem gave it, is no collision and an error (the rail refuses the same way).
pub fn judge(
    posed: &Posed,
    solved: &Solved,
    fin_given: bool,
    exact: bool,
) -> Result<Judged, RenderError> {
    let style = Style::new(exact, None).with_bearings(posed.bearings);
    let asked = asked(solved, fin_given);
    let all = outcomes(posed, solved);
    if all.is_empty() {
        return Err(RenderError::NoSolution);
    }
    let judged: Vec<(Outcome, Vec<Check>, Verdict)> = all
        .into_iter()
        .map(|(o, c)| {
            let v = Verdict::of(&o, &posed.statement);
            (o, c, v)
        })
        .collect();
    let inconsistent_all = judged.iter().all(|(_, c, _)| c.iter().any(|c| !c.ok));
    // A speed solved negative along a given direction contradicts the data as typed: the body
    // leaves the other way. Such a solution is never printed as a collision.
    let (negative, rest): (Vec<_>, Vec<_>) = judged
        .into_iter()
        .partition(|(_, _, v)| *v == Verdict::NegativeSpeed);
    if rest.is_empty()
        && !inconsistent_all
        && let Some((o, _, _)) = negative.first()
    {
        return Err(RenderError::NegativeSpeed(negative_speed(
            o,
            &posed.statement,
            &style,
        )));
    }
    let judged = if rest.is_empty() { negative } else { rest };
    let kept: Vec<(Outcome, Vec<Check>, Verdict)> =
        if judged.iter().any(|(_, _, v)| *v == Verdict::Physical) {
            judged
                .into_iter()
                .filter(|(_, _, v)| *v == Verdict::Physical)
                .collect()
        } else {
            judged
        };
    let inconsistent = kept.iter().all(|(_, c, _)| c.iter().any(|c| !c.ok));
    // A restitution solved below zero is no collision (the rail refuses it the same way): the
    // bodies would pass through each other.
    if !inconsistent
        && let [(o, _, Verdict::Unphysical)] = kept.as_slice()
        && let Some(e) = o.e.as_ref().filter(|e| e.is_negative())
    {
        return Err(RenderError::NegativeRestitution(
            style.show(e, o.approx.e()),
        ));
    }
    if let [(o, _, Verdict::Unphysical)] = kept.as_slice()
        && asked.is_empty()
        && let Some(n) = &o.normal
    {
        let along = dot(n, &sub(&o.v_in[0], &o.v_in[1]));
        return Ok(Judged::Receding {
            o: Box::new(o.clone()),
            along,
        });
    }
    Ok(Judged::Solutions { kept, inconsistent })
}

/// Which final or initial velocity came out against the direction it was given in, as the
/// error says it: `v1' = ... @ 102.098°, against its given direction`.
fn negative_speed(o: &Outcome, st: &Statement, style: &Style) -> String {
    for (i, v) in st.fin.iter().chain(&st.v_in).enumerate() {
        if let Velocity::Speed { unit } = v {
            let body = i % o.bodies();
            let fin = i < o.bodies();
            let vel = if fin { &o.fin[body] } else { &o.v_in[body] };
            if dot(vel, unit) < Q::ZERO {
                let polar = speed_angle(style, vel);
                let at = if polar.is_empty() {
                    vector_each(style, vel, |k| mark(o, body, fin, k))
                } else {
                    polar
                };
                return format!("{} solves to {at}", name(body, fin));
            }
        }
    }
    String::new()
}

/// A solution as an observer sees it: the event boosted, its checks, its verdict, and the
/// observer's velocity with whether it is approximate.
type Seen = (Outcome, Vec<Check>, Verdict, Vec<Q>, bool);

/// The solutions of a posed problem, judged in the lab ([`judge`]) and printed as `opts.frame`
/// sees them: the physical ones (or all, when none is), what was solved, the checks; a
/// collision asked outright whose bodies do not approach along the line of impact gets the
/// note alone.
pub fn render(posed: &Posed, solved: &Solved, opts: &Options) -> Result<Rendered, RenderError> {
    let asked = asked(solved, opts.fin_given);
    let mut units = posed.units.clone();
    if let Some(u) = opts.energy_unit {
        units = units.with_energy_unit(u)?;
    }
    let style = Style::new(opts.exact, units.energy_scale()).with_bearings(posed.bearings);
    let (kept, inconsistent) = match judge(posed, solved, opts.fin_given, opts.exact)? {
        Judged::Receding { o, along } => {
            // No collision: the observer of a "finally at rest" frame moves with FIN = IN.
            let happens = o.as_happens();
            let w = happens.observer(opts.frame, posed.typed_values)?;
            let approx = happens.observer_approx(opts.frame);
            return receding(&o.boost(&w, approx), &along, &style, &units, opts.frame, &w);
        }
        Judged::Solutions { kept, inconsistent } => (kept, inconsistent),
    };
    // Each solution as the observer sees it, with the observer's velocity.
    let mut keep: Vec<Seen> = Vec::new();
    for (o, c, v) in kept {
        let w = o.observer(opts.frame, posed.typed_values)?;
        let approx = o.observer_approx(opts.frame);
        keep.push((o.boost(&w, approx), c, v, w, approx));
    }
    let frame_line = (*opts.frame != Frame::Lab).then(|| {
        format!(
            "Seen from: {} (every velocity less the observer's)\n",
            opts.frame.describe()
        )
    });
    let many = keep.len() > 1;
    let mut text = String::new();
    let mut list = Vec::new();
    for (k, (o, checks, v, w, w_approx)) in keep.iter().enumerate() {
        if many {
            let _ = writeln!(
                text,
                "{}Solution {} of {} ({})",
                if k > 0 { "\n" } else { "" },
                k + 1,
                keep.len(),
                v.describe()
            );
        } else if *v != Verdict::Physical {
            text.push_str(&wrap(
                &format!("Note: {}", v.describe()),
                crate::values::terminal::width(),
                "  ",
            ));
        }
        text.push_str(&header(o, &style, &units));
        text.push_str(frame_line.as_deref().unwrap_or_default());
        text.push_str(&header_units(&units));
        text.push_str(&solved_text(o, &asked, &style));
        text.push_str(&checks_text(checks, 0));
        let mut j = if inconsistent {
            text.push_str(&wrap(
                "The given values contradict each other, so no collision is printed: check them, \
                 or mark one '?' to solve for it.",
                crate::values::terminal::width(),
                "",
            ));
            json!({ "consistent": false })
        } else {
            // The JSON first: an overflow names the quantity (`Style::checked_json`).
            let j = super::json(o, opts.show, &style)?;
            text.push_str(&super::text(o, opts.show, &style, &units)?);
            if opts.reverse {
                text.push_str(&reverse_text(o, &style)?);
            }
            j
        };
        let m = j.as_object_mut().expect("a report is an object");
        if *opts.frame != Frame::Lab {
            let w: Vec<Value> = w.iter().map(|x| style.json(x, *w_approx)).collect();
            m.insert(
                "frame".into(),
                json!({ "name": opts.frame.to_string(), "w": w }),
            );
        }
        if opts.reverse && !inconsistent {
            m.insert("reverse".into(), reverse_json(o, &style)?);
        }
        if !asked.is_empty() {
            m.insert("solved".into(), solved_json(o, &asked, &style));
        }
        let failed: Vec<Value> = checks
            .iter()
            .filter(|c| !c.ok)
            .map(|c| {
                // A number where binary64 holds it, else its decimal text (never inf).
                let residual = crate::values::rational::to_f64(&c.residual)
                    .filter(|x| x.is_finite())
                    .map(Value::from)
                    .unwrap_or_else(|| {
                        crate::values::quantity::significant(&c.residual, 17).into()
                    });
                json!({"law": c.law.name(), "residual": residual})
            })
            .collect();
        if !failed.is_empty() {
            m.insert("failed_checks".into(), failed.into());
        }
        if *v != Verdict::Physical {
            m.insert("note".into(), v.describe().into());
        }
        list.push(j);
    }
    let mut json = if many {
        json!({ "solutions": list })
    } else {
        list.pop().unwrap_or_default()
    };
    annotate_units(&mut json, &units);
    // Every value of the JSON within binary64 (the solved values and the frame's too), or the
    // quantity named; given values that contradict each other print as they are (exit 1), a
    // value beyond binary64 as its decimal text, never 0 (text: `Style::show`).
    let json = if inconsistent {
        super::unmarked(json)
    } else {
        style.checked_json(json)?
    };
    Ok(Rendered {
        text,
        json,
        inconsistent,
    })
}

/// `"units": {"mass", "velocity", "energy"}` when the case has units.
fn annotate_units(json: &mut Value, units: &Units) {
    if units.mass.is_none() && units.velocity.is_none() {
        return;
    }
    let Some(m) = json.as_object_mut() else {
        return;
    };
    let mut u = Map::new();
    if let Some(x) = units.mass {
        u.insert("mass".into(), x.into());
    }
    if let Some(x) = units.velocity {
        u.insert("velocity".into(), x.into());
    }
    u.insert("energy".into(), units.energy().into());
    m.insert("units".into(), u.into());
}

/// Bodies that do not approach along the line of impact: the note alone (seen from `frame`,
/// whose observer moves at `w`).
pub fn receding(
    o: &Outcome,
    along: &Q,
    style: &Style,
    units: &Units,
    frame: &Frame,
    w: &[Q],
) -> Result<Rendered, RenderError> {
    let mut text = header(o, style, units);
    if *frame != Frame::Lab {
        // No collision: FIN = IN, so "finally at rest" is "initially at rest".
        let _ = writeln!(
            text,
            "Seen from: {} (every velocity less the observer's)",
            frame.describe()
        );
        if let Frame::RestFin(i) = frame {
            let _ = writeln!(
                text,
                "  (no collision: FIN = IN, so body {i} initially at rest)"
            );
        }
    }
    text.push_str(&wrap(
        &format!(
            "Note: the bodies do not approach along the line of impact: n.(v1 - v2) = {} <= 0, \
             so they do not collide (no FIN).",
            style.show(along, o.approx.body_in(0) || o.approx.body_in(1))
        ),
        crate::values::terminal::width(),
        "  ",
    ));
    let a = o.approx.all;
    let mut json = json!({
        "dim": o.dim,
        "masses": json_each(style, &o.masses, |i| o.approx.mass(i)),
        "normal": o.normal.as_ref().map(|n| n.iter().map(|x| style.json(x, a)).collect::<Vec<_>>()),
        "in": super::velocities(style, o, false),
        "approaching": false,
    });
    if *frame != Frame::Lab
        && let Some(m) = json.as_object_mut()
    {
        // The observer of a receding pair moves with a typed or a body's typed velocity.
        let a = o.approx.any();
        let w: Vec<Value> = w.iter().map(|x| style.json(x, a)).collect();
        m.insert("frame".into(), json!({ "name": frame.to_string(), "w": w }));
    }
    annotate_units(&mut json, units);
    Ok(Rendered {
        text,
        json,
        inconsistent: false,
    })
}

/// `"solved": {"v2'": [..], "m1": ..}`.
pub fn solved_json(o: &Outcome, unknowns: &[Unknown], style: &Style) -> Value {
    let mut m = Map::new();
    for u in unknowns {
        let (key, value) = match *u {
            Unknown::Mass(i) => (
                format!("m{}", i + 1),
                style.json(&o.masses[i], o.approx.mass(i)),
            ),
            Unknown::Restitution => match &o.e {
                Some(e) => ("e".to_string(), style.json(e, o.approx.e())),
                None => continue,
            },
            Unknown::Component(i, fin, _)
            | Unknown::Speed(i, fin)
            | Unknown::Direction(i, fin, _) => {
                let v = if fin { &o.fin[i] } else { &o.v_in[i] };
                (name(i, fin), json_each(style, v, |k| mark(o, i, fin, k)))
            }
        };
        m.insert(key, value);
    }
    m.into()
}
