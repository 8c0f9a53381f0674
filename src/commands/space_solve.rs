//! `collide solve` in the plane, in space, or for N bodies on a line: pose the typed problem,
//! solve its unknowns, keep the physical solutions, render them.

use anyhow::Result;
use collide::frame::Frame;
use collide::report::space::{self as report, Show, Style};
use collide::report::{Section, json};
use collide::space::outcome::{Outcome as Event, dot};
use collide::space::pose::outcomes;
use collide::space::solve::{self, Check, Unknown, Velocity};

use super::Outcome;
use crate::cli::{Format, SolveArgs};

/// Why a solution is left out when another one is physical.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Verdict {
    Physical,
    /// FIN = IN: the bodies pass without an impulse.
    NoImpulse,
    /// They would approach after or separate before, along the impulse.
    Unphysical,
    /// A speed along a given direction came out negative (the opposite direction).
    NegativeSpeed,
}

pub fn run(args: &SolveArgs) -> Result<Outcome> {
    let refused = [
        (args.plot.is_some(), "--plot"),
        (args.contact_time.is_some(), "--contact-time"),
        (args.case.gravity.is_some(), "--gravity"),
    ];
    if let Some((_, flag)) = refused.iter().find(|(on, _)| *on) {
        anyhow::bail!(
            "{flag} is not available in the plane, in space or for N bodies yet (it describes \
             two bodies on a line)"
        );
    }
    let show = show(&args.show)?;
    let input = args.case.space_input(args.fin.as_ref(), args.exact)?;
    let posed = input.pose()?;
    let solved = solve::solve(&posed.statement)?;
    // The final velocities are unknowns of the laws, but only what the problem marked '?' (or
    // gave as final velocities) is "solved" for the reader.
    let asked: Vec<Unknown> = solved
        .unknowns
        .iter()
        .filter(|u| args.fin.is_some() || !matches!(u, Unknown::Component(_, true, _)))
        .copied()
        .collect();
    let mut units = posed.units.clone();
    if let Some(u) = args.case.energy_unit {
        units = units.with_energy_unit(u)?;
    }
    let style = Style::new(args.exact, units.energy_scale());
    let all = outcomes(&posed, &solved);
    if all.is_empty() {
        anyhow::bail!(
            "no real solution: the given values cannot satisfy the laws together (the energy \
             equation has no real root); check them"
        );
    }
    // Judged in the lab; printed as the frame asked sees it.
    let seen_from = |o: Event| -> Result<Event> {
        let w = o.observer(&args.frame, posed.typed_values)?;
        Ok(o.boost(&w))
    };
    let judged: Vec<(Event, Vec<Check>, Verdict)> = all
        .into_iter()
        .map(|(o, c)| {
            let v = verdict(&o, &posed.statement);
            Ok((seen_from(o)?, c, v))
        })
        .collect::<Result<_>>()?;
    let frame_line = (args.frame != Frame::Lab).then(|| {
        format!(
            "Seen from: {} (every velocity less the observer's)\n",
            args.frame.describe()
        )
    });
    let keep: Vec<&(Event, Vec<Check>, Verdict)> =
        if judged.iter().any(|(_, _, v)| *v == Verdict::Physical) {
            judged
                .iter()
                .filter(|(_, _, v)| *v == Verdict::Physical)
                .collect()
        } else {
            judged.iter().collect()
        };
    let inconsistent = keep.iter().all(|(_, c, _)| c.iter().any(|c| !c.ok));
    let many = keep.len() > 1;
    // A collision asked outright whose bodies do not approach along the line of impact: they
    // never meet, and no FIN is printed.
    if let [(o, _, Verdict::Unphysical)] = keep.as_slice()
        && asked.is_empty()
        && let Some(n) = &o.normal
    {
        let along = dot(n, &collide::space::outcome::sub(&o.v_in[0], &o.v_in[1]));
        return receding(o, &along, &style, &units, args.format);
    }
    match args.format {
        Format::Text => {
            let mut out = String::new();
            for (k, (o, checks, v)) in keep.iter().enumerate() {
                if many {
                    out.push_str(&format!(
                        "{}Solution {} of {} ({})\n",
                        if k > 0 { "\n" } else { "" },
                        k + 1,
                        keep.len(),
                        describe(*v)
                    ));
                } else if *v != Verdict::Physical {
                    out.push_str(&collide::report::text::wrap(
                        &format!("Note: {}", describe(*v)),
                        80,
                        "  ",
                    ));
                }
                out.push_str(&report::header(o, &style, &units));
                out.push_str(frame_line.as_deref().unwrap_or_default());
                out.push_str(&collide::report::text::header_units(&units));
                out.push_str(&report::solved_text(o, &asked, &style));
                out.push_str(&report::checks_text(checks, 0));
                if inconsistent {
                    out.push_str(
                        "The given values contradict each other, so no collision is printed: \
                         check them, or mark one '?' to solve for it.\n",
                    );
                    continue;
                }
                out.push_str(&report::text(o, show, &style, &units)?);
                if args.reverse {
                    out.push_str(&report::reverse_text(o, &style)?);
                }
            }
            Ok(Outcome {
                stdout: out,
                status: u8::from(inconsistent),
            })
        }
        Format::Json => {
            let render = |o: &Event, checks: &[Check], v: Verdict| -> Result<serde_json::Value> {
                let mut j = if inconsistent {
                    serde_json::json!({ "consistent": false })
                } else {
                    report::json(o, show, &style)?
                };
                let m = j.as_object_mut().expect("an object");
                if args.reverse && !inconsistent {
                    m.insert("reverse".into(), report::reverse_json(o, &style)?);
                }
                if !asked.is_empty() {
                    m.insert("solved".into(), solved_json(o, &asked, &style));
                }
                let failed: Vec<serde_json::Value> = checks
                    .iter()
                    .filter(|c| !c.ok)
                    .map(|c| serde_json::json!({"law": c.law.name(), "residual": c.residual}))
                    .collect();
                if !failed.is_empty() {
                    m.insert("failed_checks".into(), failed.into());
                }
                if v != Verdict::Physical {
                    m.insert("note".into(), describe(v).into());
                }
                Ok(j)
            };
            let mut j = if many {
                let list = keep
                    .iter()
                    .map(|(o, c, v)| render(o, c, *v))
                    .collect::<Result<Vec<_>>>()?;
                serde_json::json!({ "solutions": list })
            } else {
                let (o, c, v) = keep[0];
                render(o, c, *v)?
            };
            if !units_empty(&units) {
                let m = j.as_object_mut().expect("an object");
                let mut u = serde_json::Map::new();
                if let Some(x) = units.mass {
                    u.insert("mass".into(), x.into());
                }
                if let Some(x) = units.velocity {
                    u.insert("velocity".into(), x.into());
                }
                u.insert("energy".into(), units.energy().into());
                m.insert("units".into(), u.into());
            }
            Ok(Outcome {
                stdout: json::render(&j),
                status: u8::from(inconsistent),
            })
        }
    }
}

/// Bodies that do not approach along the line of impact: the note alone.
fn receding(
    o: &Event,
    along: &collide::rational::Q,
    style: &Style,
    units: &collide::units::Units,
    format: Format,
) -> Result<Outcome> {
    let stdout = match format {
        Format::Text => {
            let mut out = report::header(o, style, units);
            out.push_str(&collide::report::text::wrap(
                &format!(
                    "Note: the bodies do not approach along the line of impact: n.(v1 - v2) = \
                     {} <= 0, so they do not collide (no FIN).",
                    style.show(along, o.approx)
                ),
                80,
                "  ",
            ));
            out
        }
        Format::Json => {
            let a = o.approx;
            let vecs: Vec<serde_json::Value> = o
                .v_in
                .iter()
                .map(|v| v.iter().map(|x| style.json(x, a)).collect())
                .collect();
            json::render(&serde_json::json!({
                "dim": o.dim,
                "masses": o.masses.iter().map(|m| style.json(m, a)).collect::<Vec<_>>(),
                "normal": o.normal.as_ref().map(|n| n.iter().map(|x| style.json(x, a)).collect::<Vec<_>>()),
                "in": vecs,
                "approaching": false,
            }))
        }
    };
    Ok(Outcome { stdout, status: 0 })
}

fn units_empty(u: &collide::units::Units) -> bool {
    u.mass.is_none() && u.velocity.is_none()
}

/// The sections asked for, among those that mean something here.
fn show(list: &[Section]) -> Result<Show> {
    if list.is_empty() {
        return Ok(Show::default());
    }
    let mut s = Show {
        vectors: false,
        momentum: false,
        forms: false,
        energy: false,
        angles: false,
    };
    for section in list {
        match section {
            Section::Vectors => s.vectors = true,
            Section::Momentum => s.momentum = true,
            Section::Forms => s.forms = true,
            Section::Energy => s.energy = true,
            Section::Angles => s.angles = true,
            Section::All => {
                s = Show {
                    vectors: true,
                    momentum: true,
                    forms: true,
                    energy: true,
                    angles: true,
                }
            }
            other => anyhow::bail!(
                "--show {}: in the plane, in space and for N bodies the sections are vectors, \
                 momentum, forms, energy, angles and all",
                clap::ValueEnum::to_possible_value(other)
                    .map(|v| v.get_name().to_string())
                    .unwrap_or_default()
            ),
        }
    }
    Ok(s)
}

fn describe(v: Verdict) -> &'static str {
    match v {
        Verdict::Physical => "physical",
        Verdict::NoImpulse => "no impulse: the bodies pass each other unchanged",
        Verdict::Unphysical => {
            "unphysical: along the impulse the bodies would separate before or approach after"
        }
        Verdict::NegativeSpeed => "a speed along a given direction is negative",
    }
}

/// Whether a solution is a physical collision.
fn verdict(o: &Event, st: &solve::Statement) -> Verdict {
    for (i, v) in st.fin.iter().chain(&st.v_in).enumerate() {
        if let Velocity::Speed { unit } = v {
            let body = i % o.bodies();
            let vel = if i < o.bodies() {
                &o.fin[body]
            } else {
                &o.v_in[body]
            };
            if dot(vel, unit) < collide::rational::Q::ZERO {
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

/// `"solved": {"v2'": [..], "m1": ..}`.
fn solved_json(o: &Event, unknowns: &[Unknown], style: &Style) -> serde_json::Value {
    let mut m = serde_json::Map::new();
    for u in unknowns {
        let (key, value) = match *u {
            Unknown::Mass(i) => (format!("m{}", i + 1), style.json(&o.masses[i], o.approx)),
            Unknown::Restitution => match &o.e {
                Some(e) => ("e".to_string(), style.json(e, o.approx)),
                None => continue,
            },
            Unknown::Component(i, fin, _)
            | Unknown::Speed(i, fin)
            | Unknown::Direction(i, fin, _) => {
                let v = if fin { &o.fin[i] } else { &o.v_in[i] };
                (
                    format!("v{}{}", i + 1, if fin { "'" } else { "" }),
                    serde_json::Value::Array(v.iter().map(|x| style.json(x, o.approx)).collect()),
                )
            }
        };
        m.insert(key, value);
    }
    m.into()
}

/// `collide frames` in the plane, in space or for N bodies: the event seen from the standard
/// frames (lab, each body initially at rest, COM, each body finally at rest) and any asked for,
/// with the invariants checked equal in every frame before anything is printed.
pub fn frames(args: &crate::cli::FramesArgs) -> Result<Outcome> {
    let input = args.case.space_input(None, args.exact)?;
    let posed = input.pose()?;
    let solved = solve::solve(&posed.statement)?;
    let all = outcomes(&posed, &solved);
    let [(lab, _)] = all.as_slice() else {
        anyhow::bail!("frames needs one collision; this case has {}", all.len());
    };
    let stuck = lab.e.as_ref().is_some_and(|e| e.is_zero());
    let n = lab.bodies();
    let mut list: Vec<Frame> = vec![Frame::Lab];
    list.extend((1..=n).map(Frame::RestIn));
    list.push(Frame::Com);
    if !stuck {
        list.extend((1..=n).map(Frame::RestFin));
    }
    list.extend(args.frame.iter().cloned());
    let seen: Vec<(String, Vec<collide::rational::Q>, Event)> = list
        .iter()
        .map(|f| {
            let w = lab.observer(f, posed.typed_values)?;
            Ok((f.describe(), w.clone(), lab.boost(&w)))
        })
        .collect::<Result<_>>()?;
    // The invariants hold exactly in every frame (exact arithmetic): check, never assume.
    for (name, _, o) in &seen {
        if o.crunch() != lab.crunch() || o.lost() != lab.lost() {
            anyhow::bail!(
                "internal check failed: the crunch or lost energy differs in the {name} frame; \
                 nothing is printed"
            );
        }
    }
    let mut units = posed.units.clone();
    if let Some(u) = args.case.energy_unit {
        units = units.with_energy_unit(u)?;
    }
    let style = Style::new(args.exact, units.energy_scale());
    let views: Vec<report::FrameView> = seen
        .iter()
        .map(|(name, w, o)| report::FrameView {
            name: name.clone(),
            w: w.clone(),
            seen: o,
        })
        .collect();
    let stdout = match args.format {
        Format::Text => {
            report::header(lab, &style, &units)
                + &collide::report::text::header_units(&units)
                + &report::frames_text(&views, args.reverse, &style, &units)?
        }
        Format::Json => json::render(&report::frames_json(&views, args.reverse, &style)?),
    };
    Ok(Outcome::print(stdout))
}

/// The plane picture of a case given on the command line (one solution, in the plane).
pub fn plane_svg(case: &crate::cli::CaseArgs) -> Result<String> {
    let posed = case.space_input(None, false)?.pose()?;
    if posed.statement.dim != 2 {
        anyhow::bail!(
            "the picture of a collision is drawn in the plane: give 2-vectors (this case has {} \
             dimension{})",
            posed.statement.dim,
            if posed.statement.dim == 1 { "" } else { "s" }
        );
    }
    let solved = solve::solve(&posed.statement)?;
    let all = outcomes(&posed, &solved);
    let [(o, _)] = all.as_slice() else {
        anyhow::bail!(
            "the picture needs one solution; this case has {}",
            all.len()
        );
    };
    let title = format!(
        "masses {}",
        o.masses
            .iter()
            .map(|m| collide::number::num(collide::rational::to_f64(m).unwrap_or(f64::NAN)))
            .collect::<Vec<_>>()
            .join(", ")
    );
    Ok(collide::plot::plane::svg(o, &title))
}
