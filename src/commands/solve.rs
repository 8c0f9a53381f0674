//! `collide solve`: one collision from the command line.

use anyhow::Result;
use collide::plot::Kind;
use collide::report::{AnyReport, Sections, json, solved};

use super::{Outcome, plot};
use crate::cli::{Format, SolveArgs};

pub fn run(args: SolveArgs) -> Result<Outcome> {
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
    Ok(Outcome::print(stdout))
}
