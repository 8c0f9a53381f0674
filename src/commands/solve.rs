//! `collide solve`: one collision (or separation) from the command line.

use anyhow::Result;
use collide::plot::Kind;
use collide::problem::Posed;
use collide::report::separation::AnySeparation;
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
    let posed = args
        .case
        .problem(args.fin.as_ref())
        .solve(args.case.inertia.clone())?;
    let mut sections = Sections::new(args.show.clone());
    sections.contact_time = args.contact_time.clone();
    let (case, unknowns) = match posed {
        Posed::Collision(case, unknowns) => (case, unknowns),
        Posed::Separation(separation, solved) => {
            let extra = [
                (args.frame != collide::frame::Frame::Lab).then_some("--frame"),
                args.reverse.then_some("--reverse"),
                args.plot.as_ref().map(|_| "--plot"),
            ];
            if let Some(flag) = extra.into_iter().flatten().next() {
                anyhow::bail!(
                    "{flag}: the bodies start together (V1 = V2) and are pushed apart, a \
                     separation with e undefined; {flag} describes a collision"
                );
            }
            let report = AnySeparation::new(&separation, &sections, args.exact)?;
            let stdout = match args.format {
                Format::Text => {
                    solved::text(&solved, args.exact) + &report.text(&separation, &sections)
                }
                Format::Json => {
                    let mut json = report.json();
                    solved::annotate(&mut json, &separation.units, Some(&solved), args.exact);
                    json::render(&json)
                }
            };
            let status = u8::from(solved.inconsistent());
            return Ok(Outcome { stdout, status });
        }
    };
    // Given data that contradict a checked law fail like a failed [expect] (exit 1), and no
    // collision is printed: one recomputed from e would differ from the given FIN.
    if let Some(s) = unknowns.as_ref().filter(|s| s.inconsistent()) {
        let stdout = match args.format {
            Format::Text => {
                solved::text(s, args.exact)
                    + "The given values contradict each other, so no collision is printed: \
                       check them, or mark one '?' to solve for it.\n"
            }
            Format::Json => {
                let mut json = serde_json::json!({ "consistent": false });
                solved::annotate(&mut json, &case.units, Some(s), args.exact);
                json::render(&json)
            }
        };
        return Ok(Outcome { stdout, status: 1 });
    }
    let report = AnyReport::of(&case, &args.frame, args.exact, &sections, args.reverse)?;
    let mut stdout = match args.format {
        Format::Text => {
            let head = unknowns.as_ref().map(|s| solved::text(s, args.exact));
            head.unwrap_or_default() + &report.text(&case, &sections)
        }
        Format::Json => {
            let mut json = report.json();
            solved::annotate(&mut json, &case.units, unknowns.as_ref(), args.exact);
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
    Ok(Outcome { stdout, status: 0 })
}
