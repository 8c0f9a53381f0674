//! `collide solve`: one collision from the command line.

use anyhow::Result;
use collide::plot::Kind;
use collide::report::{AnyReport, Sections, json, solved};

use super::{Outcome, plot};
use crate::cli::{Format, SolveArgs};

pub fn run(args: SolveArgs) -> Result<Outcome> {
    if args.format == Format::Json && args.plot.as_deref() == Some(std::path::Path::new("term")) {
        anyhow::bail!(
            "--plot term draws text, which would break the JSON on stdout: with --format json \
             use --plot FILE.svg"
        );
    }
    let (case, unknowns) = args
        .case
        .problem(args.fin.as_ref())
        .solve(args.case.inertia.clone())?;
    let sections = Sections::new(args.show);
    let report = AnyReport::of(&case, &args.frame, args.exact, &sections, args.reverse)?;
    let mut stdout = match args.format {
        Format::Text => {
            let head = unknowns.as_ref().map(|s| solved::text(s, args.exact));
            head.unwrap_or_default() + &report.text(&case, &sections)
        }
        Format::Json => {
            let mut json = report.json();
            solved::annotate(&mut json, &case, unknowns.as_ref(), args.exact);
            json::render(&json)
        }
    };
    if let Some(target) = &args.plot {
        stdout.push_str(&plot::draw(
            &case,
            &args.frame,
            Kind::Velocity,
            false,
            target,
        )?);
    }
    // Given data that contradict a checked law fail like a failed [expect] (exit 1).
    let status = u8::from(unknowns.as_ref().is_some_and(|s| s.inconsistent()));
    Ok(Outcome { stdout, status })
}
