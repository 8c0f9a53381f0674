//! `collide solve` in the plane, in space, or for N bodies on a line: pose the typed problem,
//! solve its unknowns, keep the physical solutions, render them.

use anyhow::Result;
use collide::line::frame::Frame;
use collide::report::json;
use collide::report::space::solved::{Judged, Options, Verdict, judge, receding, render};
use collide::report::space::{self as report, Style};
use collide::space::outcome::Outcome as Event;
use collide::space::solve;

use super::Outcome;
use crate::cli::{Format, SolveArgs};

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
    let input = args.case.space_input(args.fin.as_ref(), args.exact)?;
    let posed = input.pose()?;
    let solved = solve::solve(&posed.statement)?;
    let rendered = render(
        &posed,
        &solved,
        &Options {
            frame: &args.frame,
            show: collide::scene::show_of(&args.show).map_err(|m| anyhow::anyhow!("--show {m}"))?,
            exact: args.exact,
            reverse: args.reverse,
            fin_given: args.fin.is_some(),
            energy_unit: args.case.energy_unit,
        },
    )?;
    Ok(Outcome {
        stdout: match args.format {
            Format::Text => rendered.text,
            Format::Json => json::render(&rendered.json),
        },
        status: u8::from(rendered.inconsistent),
    })
}

/// `collide frames` in the plane, in space or for N bodies: the event seen from the standard
/// frames (lab, each body initially at rest, COM, each body finally at rest) and any asked for,
/// with the invariants checked equal in every frame before anything is printed.
pub fn frames(args: &crate::cli::FramesArgs) -> Result<Outcome> {
    let input = args.case.space_input(None, args.exact)?;
    let posed = input.pose()?;
    let solved = solve::solve(&posed.statement)?;
    let mut units = posed.units.clone();
    if let Some(u) = args.case.energy_unit {
        units = units.with_energy_unit(u)?;
    }
    let style = Style::new(args.exact, units.energy_scale()).with_bearings(posed.bearings);
    // The outcome `solve` takes (judged once): bodies that do not approach do not collide.
    let lab = match judge(&posed, &solved, false, args.exact)? {
        Judged::Receding { o, along } => {
            let note = receding(&o, &along, &style, &units, &Frame::Lab, &[])?;
            return Ok(Outcome::print(match args.format {
                Format::Text => note.text,
                Format::Json => json::render(&note.json),
            }));
        }
        Judged::Solutions { kept, inconsistent } => match kept.as_slice() {
            [(o, _, v)] if !inconsistent && matches!(v, Verdict::Physical | Verdict::NoImpulse) => {
                o.clone()
            }
            [(_, _, v)] if !inconsistent => {
                anyhow::bail!(
                    "frames needs a collision; this case has none ({})",
                    v.describe()
                )
            }
            [_] => anyhow::bail!(
                "the given values contradict each other (see `collide solve`), so there is no \
                 collision to show in frames"
            ),
            all => anyhow::bail!("frames needs one collision; this case has {}", all.len()),
        },
    };
    let lab = &lab;
    let stuck = lab.e.as_ref().is_some_and(|e| e.is_zero());
    let n = lab.bodies();
    let mut list: Vec<Frame> = vec![Frame::Lab];
    list.extend((1..=n).map(Frame::RestIn));
    list.push(Frame::Com);
    if !stuck {
        list.extend((1..=n).map(Frame::RestFin));
    }
    list.extend(args.frame.iter().cloned());
    let seen: Vec<(String, Vec<collide::values::rational::Q>, bool, Event)> = list
        .iter()
        .map(|f| {
            let w = lab.observer(f, posed.typed_values)?;
            let approx = lab.observer_approx(f);
            Ok((f.describe(), w.clone(), approx, lab.boost(&w, approx)))
        })
        .collect::<Result<_>>()?;
    // The invariants hold exactly in every frame (exact arithmetic): check, never assume.
    for (name, _, _, o) in &seen {
        if o.crunch() != lab.crunch() || o.lost() != lab.lost() {
            anyhow::bail!(
                "internal check failed: the crunch or lost energy differs in the {name} frame; \
                 nothing is printed"
            );
        }
    }
    let views: Vec<report::frames::FrameView> = seen
        .iter()
        .map(|(name, w, approx, o)| report::frames::FrameView {
            name: name.clone(),
            w: w.clone(),
            w_approx: *approx,
            seen: o,
        })
        .collect();
    let stdout = match args.format {
        Format::Text => {
            let text = report::named(
                || report::frames::json(&views, args.reverse, &style),
                || report::frames::text(&views, args.reverse, &style, &units),
            )?;
            report::header(lab, &style, &units)
                + &collide::report::text::header_units(&units)
                + &text
        }
        Format::Json => json::render(&report::frames::json(&views, args.reverse, &style)?),
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
    // The outcome `solve` takes (judged once): bodies that do not approach pass unchanged.
    let (o, note) = match judge(&posed, &solved, false, false)? {
        Judged::Receding { o, .. } => (
            o.as_happens(),
            "   no collision: they do not approach along n",
        ),
        Judged::Solutions { kept, inconsistent } => match kept.as_slice() {
            [(o, _, v)] if !inconsistent && matches!(v, Verdict::Physical | Verdict::NoImpulse) => {
                (o.clone(), "")
            }
            [(_, _, v)] if !inconsistent => {
                anyhow::bail!("no collision to draw: {}", v.describe())
            }
            [_] => anyhow::bail!(
                "the given values contradict each other (see `collide solve`): no collision \
                 to draw"
            ),
            all => anyhow::bail!(
                "the picture needs one solution; this case has {}",
                all.len()
            ),
        },
    };
    let o = &o;
    let title = format!(
        "masses {}{note}",
        o.masses
            .iter()
            .map(|m| collide::values::number::num(
                collide::values::rational::to_f64(m).unwrap_or(f64::NAN)
            ))
            .collect::<Vec<_>>()
            .join(", ")
    );
    Ok(collide::plot::plane::svg(o, &title))
}
