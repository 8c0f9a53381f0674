//! `collide solve` for rigid bodies at impact: the homework shapes typed on the command line
//! (`--target`, `--pivot`, `--hit-at`, `--ball`, `--spin`, `--friction`), laid out, solved and
//! rendered; also the picture (`collide plot`) and a scene's `[[body]]` report.

use anyhow::Result;
use collide::report::rigid::{self as report, RigidUnits};
use collide::report::space::Style;
use collide::report::{Section, Sections, json};
use collide::rigid::fin::FinTyped;
use collide::rigid::homework::{HitTyped, Homework};
use collide::rigid::impact::{ImpactError, Problem};
use collide::rigid::pose::{Either, LawsTyped, MassTyped};
use collide::rigid::units::{Measure, Typed};
use collide::rigid::unknowns::{self, Asked, Known, Unknown};
use collide::space::typed::{Listed, split_bodies};
use collide::values::number::{Given, Number};
use collide::values::units::EnergyUnit;

use super::Outcome;
use crate::cli::{CaseArgs, Format, RigidArgs, SolveArgs};

pub fn run(args: &SolveArgs) -> Result<Outcome> {
    let after = args.show.contains(&Section::Swing) || args.show.contains(&Section::Rolling);
    let refused = [
        (args.frame != collide::line::frame::Frame::Lab, "--frame"),
        (args.plot.is_some(), "--plot (use collide plot)"),
        (args.contact_time.is_some(), "--contact-time"),
        (args.reverse, "--reverse"),
        (
            args.case.gravity.is_some() && !after,
            "--gravity (but with --show swing or rolling)",
        ),
        (
            args.case.inertia.is_some(),
            "--inertia (give --target or --ball)",
        ),
        (
            args.case.normal.is_some(),
            "--normal (the homework shapes set it)",
        ),
        (args.case.radii.is_some(), "--radii"),
    ];
    if let Some((_, flag)) = refused.iter().find(|(on, _)| *on) {
        anyhow::bail!(
            "{flag} is not available for rigid bodies (--target, --ball, --spin, --friction...); \
             a general contact is a scene with [[body]] tables"
        );
    }
    let mut show = show(&args.show)?;
    after_impact(&mut show, args)?;
    let (homework, asked) = typed(&args.case, &args.rigid, args.fin.as_ref(), args.exact)?;
    if !asked.is_empty() {
        return solved(&homework, &asked, &show, args);
    }
    let (stdout, status) = report_of(
        homework.pose()?,
        &show,
        args.exact,
        args.case.energy_unit,
        args.format,
    )?;
    Ok(Outcome { stdout, status })
}

/// What the swing and the slide to rolling need: `g` (`--gravity`) and the floor's friction
/// (`--floor-friction`, only with `--show rolling`), each above 0.
fn after_impact(show: &mut Sections, args: &SolveArgs) -> Result<()> {
    let positive = |n: &Number, flag: &str, what: &str| -> Result<collide::values::rational::Q> {
        let q = n.exact();
        if q <= collide::values::rational::Q::ZERO {
            anyhow::bail!("{flag} {n}: {what} must be above 0");
        }
        Ok(q)
    };
    if let Some(g) = &args.case.gravity {
        show.gravity = Some(positive(g, "--gravity", "g")?);
    }
    if let Some(mu) = &args.rigid.floor_friction {
        if !show.contains(Section::Rolling) {
            anyhow::bail!(
                "--floor-friction {mu} is the floor's friction under a ball sliding to rolling: \
                 ask for it with --show rolling"
            );
        }
        show.floor_friction = Some(positive(
            mu,
            "--floor-friction",
            "the floor's coefficient of kinetic friction (a frictionless floor never stops a slip)",
        )?);
    }
    Ok(())
}

/// A problem with a `?` (or a given final value to check): solved, then reported with its
/// `Solved:` and `Check:` lines (JSON `solved`, `check`).
fn solved(hw: &Homework, asked: &Asked, show: &Sections, args: &SolveArgs) -> Result<Outcome> {
    let solution = unknowns::solve(hw, asked)?;
    if let Some(c) = solution
        .checks
        .iter()
        .find(|c| !c.approx && !c.residual.is_zero())
    {
        anyhow::bail!(
            "the given {} contradicts the impact: it misses by {} (mark a value '?' to solve \
             for it)",
            c.name,
            collide::values::quantity::significant(&c.residual, 15)
        );
    }
    let problem = solution.problem.clone();
    let u = units(problem.si, args.case.energy_unit)?;
    let style = Style::new(args.exact, u.units.energy_scale());
    let lines = report::solved::text(&solution, &style, problem.si);
    let (out, status) = report_of(
        problem,
        show,
        args.exact,
        args.case.energy_unit,
        args.format,
    )?;
    let stdout = match args.format {
        Format::Text => lines + &out,
        Format::Json => {
            let mut j: serde_json::Value = serde_json::from_str(&out)?;
            report::solved::annotate(&mut j, &solution, &style);
            json::render(&j)
        }
    };
    Ok(Outcome { stdout, status })
}

/// The typed homework problem of the command line, without unknowns (`collide plot`).
pub fn homework(case: &CaseArgs, rigid: &RigidArgs, exact: bool) -> Result<Homework> {
    let (hw, asked) = typed(case, rigid, None, exact)?;
    if let Some(u) = asked.unknowns.first() {
        anyhow::bail!(
            "{} = ?: solve it first (collide solve), then give its value",
            u.name()
        );
    }
    Ok(hw)
}

/// The typed homework problem of the command line, a `?` holding `1` in its place, and what
/// it asks: its unknowns and the final values given (`--fin-spin`, `--pivot-impulse`).
pub fn typed(
    case: &CaseArgs,
    rigid: &RigidArgs,
    fin: Option<&Listed>,
    exact: bool,
) -> Result<(Homework, Asked)> {
    let mut asked = Asked::default();
    let Some(masses) = &case.masses else {
        anyhow::bail!("give --masses M1,M2 (the ball, then the target, a wall or a floor)");
    };
    let two = |text: &str, what: &str| -> Result<Vec<String>> {
        let parts = split_bodies(text)?;
        if parts.is_empty() || parts.len() > 2 {
            anyhow::bail!(
                "{what} '{text}': give one or two values (the ball's, then the target's)"
            );
        }
        Ok(parts.into_iter().map(String::from).collect())
    };
    let m = two(&masses.text, "--masses")?;
    let [m1, m2] = m.as_slice() else {
        anyhow::bail!(
            "--masses '{}': give two (the ball's, then the target's, or wall, floor, ceiling)",
            masses.text
        );
    };
    let mut mass = |i: usize, text: &str| -> Result<MassTyped> {
        let text = match unknowns::placeholder(text, "--masses")? {
            Some(t) => {
                asked.unknowns.push(Unknown::Mass(i));
                t
            }
            None => text.to_string(),
        };
        Ok(MassTyped::parse(&text, "mass")?)
    };
    let masses = [mass(0, m1)?, mass(1, m2)?];
    let mut v = two(&case.velocities.text, "--velocities")?;
    for (i, t) in v.iter_mut().enumerate() {
        if let Some(p) = unknowns::placeholder(t, "--velocities")? {
            asked.unknowns.push(Unknown::Speed(i));
            *t = p;
        }
    }
    let velocity = |i: usize| -> Result<Option<Either>> {
        v.get(i)
            .map(|t| Either::parse(t, Measure::Velocity, "velocity"))
            .transpose()
            .map_err(Into::into)
    };
    let spins: Vec<String> = match &rigid.spin {
        Some(s) => two(s, "--spin")?,
        None => Vec::new(),
    };
    let spin = |i: usize| -> Result<Option<Typed>> {
        spins
            .get(i)
            .map(|t| Typed::parse(t, Measure::Spin, "--spin"))
            .transpose()
            .map_err(Into::into)
    };
    if rigid.join && case.restitution.is_some() {
        anyhow::bail!(
            "--join makes the bodies one rigid body, which is e = 0 with no slip: leave out -e"
        );
    }
    let restitution = match &case.restitution {
        None => Number::from_f64(1.0)?,
        Some(Given::Known(r)) => r.number().clone(),
        Some(_) => {
            asked.unknowns.push(Unknown::Restitution);
            Number::from_f64(0.5)?
        }
    };
    let friction = match &rigid.friction {
        None => None,
        Some(Given::Known(mu)) => Some(mu.clone()),
        Some(_) => {
            asked.unknowns.push(Unknown::Friction);
            Some(Number::from_f64(0.5)?)
        }
    };
    if matches!(rigid.hit_at, Some(HitTyped::Unknown)) {
        asked.unknowns.push(Unknown::HitAt);
    }
    asked.knowns = knowns(rigid)?;
    if let Some(fin) = fin {
        asked.knowns.extend(fins(&fin.text)?);
    }
    let homework = Homework {
        masses,
        velocities: [velocity(0)?, velocity(1)?],
        spins: [spin(0)?, spin(1)?],
        ball: rigid.ball.clone(),
        target: rigid.target.clone(),
        pivot: rigid.pivot.clone(),
        hit_at: rigid.hit_at.clone(),
        laws: LawsTyped {
            restitution,
            friction,
            law: rigid.law,
            tangential_restitution: rigid.tangential_restitution.clone(),
            join: rigid.join,
        },
        exact,
        // The homework shapes are in the plane: no ODE (a scene's `tol` sets it in space).
        rtol: None,
    };
    Ok((homework, asked))
}

/// The final values given: `--fin-spin 'W1,W2'` (`?` or empty for a spin not given; a plain
/// number is in rad/s) and `--pivot-impulse 0`.
fn knowns(rigid: &RigidArgs) -> Result<Vec<Known>> {
    let mut out = Vec::new();
    if let Some(text) = &rigid.fin_spin {
        let parts: Vec<&str> = text.split(',').map(str::trim).collect();
        if parts.len() > 2 {
            anyhow::bail!("--fin-spin '{text}': give one or two spins 'W1,W2' (empty for none)");
        }
        for (i, t) in parts.into_iter().enumerate() {
            if t.is_empty() || t == "?" {
                continue;
            }
            let mut spin = Typed::parse(t, Measure::Spin, "--fin-spin")?;
            if spin.unit.is_none() {
                spin = Typed::parse(&format!("{t} rad/s"), Measure::Spin, "--fin-spin")?;
            }
            out.push(Known::Spin(i, spin));
        }
        if out.is_empty() {
            anyhow::bail!("--fin-spin '{text}': no spin given (empty or '?' for both bodies)");
        }
    }
    if let Some(p) = &rigid.pivot_impulse {
        if p.value() != 0.0 {
            anyhow::bail!(
                "--pivot-impulse {p}: only 0 is solved for (the pivot feels nothing: the centre \
                 of percussion)"
            );
        }
        out.push(Known::PivotImpulseZero);
    }
    Ok(out)
}

/// The final velocities given, `--fin 'F1,F2'` (`?` for one not given): a known each.
fn fins(text: &str) -> Result<Vec<Known>> {
    let parts = split_bodies(text)?;
    if parts.len() > 2 {
        anyhow::bail!("--fin '{text}': give one or two final velocities 'F1,F2' ('?' for none)");
    }
    let mut out = Vec::new();
    for (i, t) in parts.into_iter().enumerate() {
        if let Some(f) = FinTyped::parse(i, t)? {
            out.push(Known::Fin(f));
        }
    }
    if out.is_empty() {
        anyhow::bail!("--fin '{text}': no final velocity given ('?' for both bodies)");
    }
    Ok(out)
}

/// The units of a posed problem: SI when it had any unit.
fn units(si: bool, energy: Option<&'static EnergyUnit>) -> Result<RigidUnits> {
    let mut u = RigidUnits::new(si);
    if let Some(e) = energy {
        u.units = u.units.with_energy_unit(e)?;
    }
    Ok(u)
}

/// The report of a rigid problem in `format`, and its exit status (1: energy created).
pub fn report_of(
    problem: Problem,
    show: &Sections,
    exact: bool,
    energy: Option<&'static EnergyUnit>,
    format: Format,
) -> Result<(String, u8)> {
    let u = units(problem.si, energy)?;
    let style = Style::new(exact, u.units.energy_scale());
    let outcome = match collide::rigid::solve(problem) {
        Ok(o) => o,
        Err(ImpactError::NotApproaching(along)) => {
            let note = report::not_approaching(&along);
            return Ok(match format {
                Format::Text => (
                    collide::report::text::wrap(&note, collide::values::terminal::width(), "  "),
                    0,
                ),
                Format::Json => (
                    json::render(&serde_json::json!({ "approaching": false, "note": note })),
                    0,
                ),
            });
        }
        Err(e) => return Err(e.into()),
    };
    let status = u8::from(outcome.paradox().is_some());
    let out = match format {
        Format::Text => {
            let text = collide::report::space::named(
                || report::json(&outcome, show, &style, &u),
                || report::text(&outcome, show, &style, &u),
            )?;
            report::header(&outcome, &style, &u) + &text
        }
        Format::Json => json::render(&report::json(&outcome, show, &style, &u)?),
    };
    Ok((out, status))
}

/// The sections asked for, among those that mean something for rigid bodies.
pub fn show(list: &[Section]) -> Result<Sections> {
    if let Some(other) = list.iter().find(|s| !report::SECTIONS.contains(s)) {
        anyhow::bail!(
            "--show {}: for rigid bodies the sections are vectors, momentum, forms (the inertia \
             tensor, the Jacobian rows, K), energy, swing, rolling and all",
            clap::ValueEnum::to_possible_value(other)
                .map(|v| v.get_name().to_string())
                .unwrap_or_default()
        );
    }
    Ok(Sections::new(if list.is_empty() {
        report::DEFAULT.to_vec()
    } else {
        list.to_vec()
    }))
}

/// The picture of a rigid impact typed on the command line.
pub fn svg(case: &CaseArgs, rigid: &RigidArgs) -> Result<String> {
    let problem = homework(case, rigid, false)?.pose()?;
    let outcome = collide::rigid::solve(problem)?;
    Ok(collide::plot::rigid::svg(&outcome))
}
