//! `collide solve`: one collision (or separation) from the command line.

use anyhow::Result;
use collide::line::problem::Posed;
use collide::line::slide;
use collide::plot::Kind;
use collide::report::not_shown::{self, Event};
use collide::report::special::Special;
use collide::report::{AnyReport, Sections, json, solved};
use collide::values::number::Given;

use super::{Outcome, plot};
use crate::cli::{Format, SolveArgs};

pub fn run(args: SolveArgs) -> Result<Outcome> {
    if args.format == Format::Json && args.plot.as_deref() == Some(std::path::Path::new("term")) {
        anyhow::bail!(
            "--plot term draws text, which would break the JSON on stdout: with --format json \
             use --plot FILE.svg"
        );
    }
    if args.balls.active() {
        return super::balls::run(&args);
    }
    // With --show slides, --friction is the floor's (two bodies on a rail), not a contact's.
    let slides = args.show.contains(&collide::report::Section::Slides);
    let floor = slides.then_some(args.rigid.friction.as_ref()).flatten();
    let slides_given = match args.fin.as_ref().filter(|f| f.pair.is_some()) {
        Some(fin) => slide::slides(&fin.text)?,
        None => Vec::new(),
    };
    let floor_unknown = matches!(floor, Some(Given::Unknown));
    if let Some(bare) = slides_given.iter().find(|s| s.bare && !floor_unknown) {
        anyhow::bail!(
            "'{}': a slide with no mu is on the floor whose mu is solved for (--friction ? \
             --show slides); give its mu ('slide D mu 0.62'), or 'slide D mu ?' to solve it",
            bare.typed
        );
    }
    if slides {
        match floor {
            _ if args.rigid.active_beyond_friction() || args.case.spatial() => anyhow::bail!(
                "--show slides is for two bodies on a rail (with --friction MU, the floor's), not \
                 rigid bodies, the plane, space or more than two bodies"
            ),
            Some(Given::Known(mu)) if mu.exact() > collide::values::rational::Q::ZERO => {}
            Some(Given::Known(mu)) => anyhow::bail!(
                "--friction {mu}: the floor's coefficient of kinetic friction must be above 0 \
                 (a frictionless floor never stops a slide)"
            ),
            Some(Given::Unknown) if !slides_given.is_empty() => {}
            Some(_) => anyhow::bail!(
                "--friction ? with --show slides: nothing fixes the floor's mu; give a slide \
                 after the collision in --fin ('?,slide 20 cm': mu = f^2 / (2 g d)), or give \
                 mu (--friction MU)"
            ),
            None => anyhow::bail!(
                "--show slides needs --friction MU, the floor's coefficient of kinetic friction"
            ),
        }
    }
    let rigid = (args.rigid.active() || (args.case.wall_in_plane() && args.fin.is_none()))
        && floor.is_none();
    if let Some(flag) = (args.knowns.knowns().first_flag()).or(args.knowns.first_asked(false))
        && (rigid || args.case.spatial())
    {
        anyhow::bail!(
            "{flag} is for two bodies on a rail (not rigid bodies, the plane, space or more than \
             two bodies)"
        );
    }
    let plane = args.case.spatial() || args.fin.as_ref().is_some_and(|f| f.pair.is_none());
    if args.velocity_unit.is_some() && (rigid || plane) {
        anyhow::bail!(
            "--velocity-unit is for two bodies on a rail (not rigid bodies, the plane, space or \
             more than two bodies)"
        );
    }
    if rigid {
        return super::rigid_solve::run(&args);
    }
    // Final velocities given as vectors make the case one in the plane too (`-v 0,0 --fin
    // '(2,0),(-1,0)'`: a bare 0 is the zero vector of any dimension).
    if args.case.spatial() || args.fin.as_ref().is_some_and(|f| f.pair.is_none()) {
        return super::space_solve::run(&args);
    }
    args.frame.on_line()?;
    let mut problem = args.case.problem(args.fin.as_ref(), args.exact)?;
    problem.knowns = args.knowns.knowns();
    problem.velocity_unit = args.velocity_unit;
    let posed = problem.solve(args.case.inertia.clone())?;
    let mut sections = Sections::new(if args.show.is_empty() {
        collide::report::Section::DEFAULT.to_vec()
    } else {
        args.show.clone()
    });
    sections.contact_time = args.contact_time.clone();
    let units = posed.units().clone();
    sections.heights = Some(collide::values::units::HeightScale::new(
        args.case.gravity.as_ref(),
        &units,
    ));
    sections.energy_scale = units.energy_scale();
    sections.force_scale = units.force_scale();
    let g = sections
        .heights
        .as_ref()
        .map(|h| h.g.clone())
        .unwrap_or_default();
    sections.asked = args.knowns.asked(&units, &g);
    sections.asked.friction = floor
        .and_then(Given::known)
        .map(|mu| (mu.exact(), mu.to_string()));
    let (case, unknowns) = match &posed {
        // Bodies that start together are pushed apart: e = (v2' - v1') / (v1 - v2) has no
        // denominator, and a typed -e would print FIN = IN as if it were an answer.
        Posed::Collision(case, _)
            if args.fin.is_some()
                && args.case.restitution.is_some()
                && case.collision.v_in.x == case.collision.v_in.y =>
        {
            anyhow::bail!(
                "-e {}: e is undefined for a separation (the bodies start together, V1 = V2 = \
                 {}, so e = (v2' - v1') / (v1 - v2) divides by zero); drop -e and give what \
                 the problem gives: a final velocity, or the energy released",
                case.restitution(),
                collide::values::number::num(case.collision.v_in.x)
            );
        }
        Posed::Collision(case, unknowns) => (case, unknowns),
        _ if !slides_given.is_empty() => anyhow::bail!(
            "'{}': mu ? in a slide is solved from a collision of two movable bodies (not a \
             wall, a separation or a pass-through)",
            slides_given[0].typed
        ),
        Posed::Separation(s, solved) => {
            return special(Special::Separation(s), Some(solved), &sections, &args);
        }
        Posed::Wall(w, solved) => {
            return special(Special::Wall(w), solved.as_ref(), &sections, &args);
        }
        Posed::Separations(pair) => return two_ways(pair, &sections, &args),
    };
    // Given data that contradict a checked law fail like a failed [expect] (exit 1), and no
    // collision is printed: one recomputed from e would differ from the given FIN.
    if let Some(s) = unknowns.as_ref().filter(|s| s.inconsistent()) {
        return Ok(Outcome {
            stdout: inconsistent_report(s, &case.units, &args),
            status: 1,
        });
    }
    let mu = match &sections.heights {
        Some(h) => collide::report::floor::floor_friction(case, &slides_given, h, args.exact)?,
        None => None,
    };
    if let (Some(mu), true) = (&mu, floor_unknown) {
        sections.asked.friction = Some((mu.value.clone(), mu.shown.clone()));
    }
    let report = AnyReport::of(case, &args.frame, args.exact, &sections, args.reverse)?;
    let mut stdout = match args.format {
        Format::Text => {
            mu.as_ref().map(|m| m.line.clone()).unwrap_or_default()
                + &report.text(case, &sections, unknowns.as_ref())
                + &not_shown::text(Event::Collision, &args.show)
        }
        Format::Json => {
            let mut json = report.json();
            solved::annotate(&mut json, &case.units, unknowns.as_ref(), args.exact);
            if let (Some(mu), Some(map)) = (&mu, json.as_object_mut()) {
                let solved = map.entry("solved").or_insert_with(|| serde_json::json!({}));
                solved["mu"] = mu.json.clone();
            }
            with_notes(&mut json, Event::Collision, &args.show);
            json::render(&json)
        }
    };
    if let Some(target) = &args.plot {
        stdout.push_str(&plot::draw(
            case,
            &args.frame,
            Kind::Velocity,
            false,
            target,
        )?);
    }
    Ok(Outcome { stdout, status: 0 })
}

/// A separation or a wall: its own report, and the flags that describe only a collision of two
/// movable bodies refused.
fn special(
    event: Special,
    solved: Option<&collide::line::unknowns::Solved>,
    sections: &Sections,
    args: &SolveArgs,
) -> Result<Outcome> {
    let extra = [
        (args.frame != collide::line::frame::Frame::Lab).then_some("--frame"),
        args.reverse.then_some("--reverse"),
        args.plot.as_ref().map(|_| "--plot"),
        args.knowns
            .first_asked(matches!(event, Special::Separation(_))),
        (matches!(event, Special::Wall(_))
            && args.show.contains(&collide::report::Section::Slides))
        .then_some("--show slides"),
    ];
    if let Some(flag) = extra.into_iter().flatten().next() {
        let what = match event {
            Special::Separation(s) if s.kind == collide::line::separation::Kind::PassThrough => {
                "one body passes through the other, and only momentum holds"
            }
            Special::Separation(_) => {
                "the bodies start together (V1 = V2) and are pushed apart, a separation with e \
                 undefined"
            }
            Special::Wall(_) => "one body is a wall (immovable)",
        };
        anyhow::bail!("{flag}: {what}; {flag} describes a collision of two movable bodies");
    }
    let units = event.units();
    if let Some(s) = solved.filter(|s| s.inconsistent()) {
        return Ok(Outcome {
            stdout: inconsistent_report(s, &units, args),
            status: 1,
        });
    }
    let head = solved
        .map(|s| solved::text(s, args.exact, &units))
        .unwrap_or_default();
    let report = event.render(sections, sections, args.exact)?;
    let kind = match event {
        Special::Separation(s) if s.kind == collide::line::separation::Kind::PassThrough => {
            Event::PassThrough
        }
        Special::Separation(_) => Event::Separation,
        Special::Wall(_) => Event::Wall,
    };
    let stdout = match args.format {
        Format::Text => head + &report.text + &not_shown::text(kind, &args.show),
        Format::Json => {
            let mut json = report.json;
            solved::annotate(&mut json, &units, solved, args.exact);
            with_notes(&mut json, kind, &args.show);
            json::render(&json)
        }
    };
    Ok(Outcome { stdout, status: 0 })
}

/// The sections asked for by name that `event` does not show, as JSON `not_shown: {section:
/// why}` (issue 42 section 3: never nothing).
fn with_notes(json: &mut serde_json::Value, event: Event, asked: &[collide::report::Section]) {
    if let (Some(notes), Some(map)) = (not_shown::json(event, asked), json.as_object_mut()) {
        map.insert("not_shown".into(), notes);
    }
}

/// A separation with the energy released given and both final velocities unknown: both ways
/// the pieces can part, labelled by which is on the left (JSON `{"solutions": [...]}`).
fn two_ways(
    pair: &[(
        collide::line::separation::Separation,
        collide::line::unknowns::Solved,
    ); 2],
    sections: &Sections,
    args: &SolveArgs,
) -> Result<Outcome> {
    let labels = [
        "Solution 1: body 1 on the left, body 2 on the right (f1 < f2)",
        "Solution 2: body 1 on the right, body 2 on the left (f1 > f2)",
    ];
    let mut text = collide::report::text::paragraph(
        "Two solutions: the energy released fixes the relative speed |f1 - f2|, not which \
         piece ends up on the right",
    );
    let mut solutions = Vec::new();
    for ((s, solved), label) in pair.iter().zip(labels) {
        let Outcome { stdout, status } =
            special(Special::Separation(s), Some(solved), sections, args)?;
        if status != 0 {
            return Ok(Outcome { stdout, status });
        }
        match args.format {
            Format::Text => {
                text.push('\n');
                text.push_str(&collide::report::text::paragraph(&format!("{label}:")));
                text.push_str(&stdout);
            }
            Format::Json => solutions.push(serde_json::from_str::<serde_json::Value>(&stdout)?),
        }
    }
    let stdout = match args.format {
        Format::Text => text,
        Format::Json => json::render(&serde_json::json!({ "solutions": solutions })),
    };
    Ok(Outcome { stdout, status: 0 })
}

/// Given values that contradict a checked law: what was checked, and no event (one recomputed
/// from some of the values would differ from the others).
fn inconsistent_report(
    s: &collide::line::unknowns::Solved,
    units: &collide::values::units::Units,
    args: &SolveArgs,
) -> String {
    match args.format {
        Format::Text => solved::text(s, args.exact, units) + &solved::contradiction(),
        Format::Json => {
            let mut json = serde_json::json!({ "consistent": false });
            solved::annotate(&mut json, units, Some(s), args.exact);
            json::render(&json)
        }
    }
}
