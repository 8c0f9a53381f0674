//! `collide frames`: one collision seen from the standard Galilean frames (lecture Figs. 2.5 and
//! 3.4), with the invariants checked in every frame.

use anyhow::Result;
use collide::line::case::Case;
use collide::line::frame::Frame;
use collide::report::frames::{self, Agree, FramesTable};
use collide::report::{Irreversible, json};
use collide::solver::Lab;
use collide::solver::exact::ExactCollision;

use super::Outcome;
use crate::cli::{Format, FramesArgs};

pub fn run(args: FramesArgs) -> Result<Outcome> {
    if args.case.spatial() {
        return super::space_solve::frames(&args);
    }
    for f in &args.frame {
        f.on_line()?;
    }
    let case = args.case.into_case(args.exact)?;
    let stuck = case.restitution().is_totally_inelastic();
    if args.reverse && stuck {
        return Err(Irreversible.into());
    }
    let list: Vec<Frame> = Frame::standard()
        .into_iter()
        // e = 0: FIN = COM, so "finally at rest" is the COM frame again.
        .filter(|f| !(stuck && matches!(f, Frame::RestFin(_))))
        .chain(args.frame)
        .collect();
    let stdout = if args.exact {
        case.check_exact()?;
        let lab = ExactCollision::from_case(&case);
        render(&case, &lab, list, args.reverse, args.format)?
    } else {
        render(&case, &case.collision, list, args.reverse, args.format)?
    };
    Ok(Outcome::print(stdout))
}

/// The frames table of `lab` in the arithmetic it holds, rendered.
fn render<L: Lab>(
    case: &Case,
    lab: &L,
    list: Vec<Frame>,
    reverse: bool,
    format: Format,
) -> Result<String>
where
    L::N: Agree,
{
    let t: FramesTable<L::N> =
        frames::table(lab, list, reverse, case.units.energy_scale().as_ref()).map_err(
            |e| match e {
                // frames has --exact but no --show.
                frames::FramesError::Unrepresentable(u) => frames::FramesError::Unrepresentable(
                    u.with_way_out("use --exact or rescale the units"),
                ),
                e => e,
            },
        )?;
    Ok(match format {
        Format::Json => json::render(&t),
        Format::Text => frames::text(case, &t),
    })
}
