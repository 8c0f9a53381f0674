//! `collide solve` for several contacts at once (`--positions` and `--radii`, or
//! `--contacts`): pose the touching balls, solve Newton's law at every contact at once (and
//! the sequential answer when asked), render.

use anyhow::Result;
use collide::report::json;
use collide::report::simultaneous;
use collide::space::balls::BallsInput;

use super::Outcome;
use crate::cli::{Format, SolveArgs};

pub fn run(args: &SolveArgs) -> Result<Outcome> {
    let refused = [
        (args.fin.is_some(), "--fin"),
        (args.plot.is_some(), "--plot"),
        (args.contact_time.is_some(), "--contact-time"),
        (args.case.gravity.is_some(), "--gravity"),
        (args.case.inertia.is_some(), "--inertia"),
        (args.reverse, "--reverse"),
        (!args.show.is_empty(), "--show"),
        (args.rigid.active(), "a rigid-body flag"),
        (args.velocity_unit.is_some(), "--velocity-unit"),
        (args.frame != collide::line::frame::Frame::Lab, "--frame"),
    ];
    if let Some((_, flag)) = refused.iter().find(|(on, _)| *on) {
        anyhow::bail!(
            "{flag} is not available with several contacts at once (--positions, --contacts)"
        );
    }
    if let Some(flag) = args
        .knowns
        .knowns()
        .first_flag()
        .or(args.knowns.first_asked(false))
    {
        anyhow::bail!("{flag} is for two bodies on a rail, not several contacts at once");
    }
    if args.balls.sequential && args.balls.positions.is_none() && args.balls.contacts.is_none() {
        anyhow::bail!("--sequential needs the contacts: --positions with --radii, or --contacts");
    }
    // The radii are the balls' here, not two disks' with an impact parameter.
    let mut case = args.case.clone();
    case.radii = None;
    let input = case.space_input(None, args.exact)?;
    let balls = BallsInput {
        input,
        positions: args.balls.positions.clone(),
        radii: args.case.radii.clone(),
        contacts: args.balls.contacts.clone(),
    };
    let rendered = simultaneous::run(&balls, args.balls.sequential, args.case.energy_unit)?;
    Ok(Outcome::print(match args.format {
        Format::Text => rendered.text,
        Format::Json => json::render(&rendered.json),
    }))
}
