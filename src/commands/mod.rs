//! The subcommands, one file each, each reading top to bottom as "parse, solve, render": it turns
//! validated arguments into the text to print and an exit status. Output is built whole before
//! anything is written, so an error never leaves half a report on stdout (tables stream, and
//! write files atomically).

mod accuracy;
mod contact;
mod frames;
mod pi;
mod plot;
mod scene;
mod shell;
mod solve;
mod table;
mod track;
mod view;

use anyhow::Result;
use collide::case::Case;
use collide::problem::Problem;

use crate::cli::{CaseArgs, Command, LayoutArgs};

/// What a command prints and how it exits.
#[derive(Debug, PartialEq)]
pub struct Outcome {
    pub stdout: String,
    pub status: u8,
}

impl Outcome {
    /// Success, printing `stdout`.
    pub fn print(stdout: String) -> Outcome {
        Outcome { stdout, status: 0 }
    }
}

/// Runs a parsed command. `Err` is bad input: the caller prints it and exits 2.
pub fn run(command: Command) -> Result<Outcome> {
    match command {
        Command::Solve(args) => solve::run(args),
        Command::Scene(args) => scene::run(args),
        Command::Accuracy(args) => accuracy::run(args),
        Command::Frames(args) => frames::run(args),
        Command::Sweep(args) => table::sweep(args),
        Command::Batch(args) => table::batch(args),
        Command::Track(args) => track::run(args),
        Command::Pi(args) => pi::run(args),
        Command::Contact(args) => contact::run(args),
        Command::Plot(args) => plot::run(args),
        Command::View(args) => view::run(args),
        Command::Completions { shell } => shell::completions(shell),
        Command::Man => shell::man(),
    }
}

impl CaseArgs {
    /// The typed problem (masses or tensor, velocities, restitution, units), for exact
    /// arithmetic or not.
    pub fn problem(&self, fin: Option<&collide::units::Pair>, exact: bool) -> Problem {
        Problem {
            masses: self.masses.clone(),
            velocities: self.velocities.clone(),
            fin: fin.cloned(),
            restitution: self.restitution.clone(),
            si: self.si,
            gravity: self.gravity.clone(),
            energy_unit: self.energy_unit,
            exact,
        }
    }

    /// The case, with units resolved, for exact arithmetic or not; `?` (an unknown) is for
    /// `collide solve`.
    pub fn into_case(self, exact: bool) -> Result<Case> {
        Ok(self.problem(None, exact).into_case(self.inertia)?)
    }
}

impl LayoutArgs {
    /// The bodies, one per mass, with a message naming the list that has the wrong count.
    pub fn bodies(&self) -> Result<Vec<collide::track::Body>> {
        use collide::track::BodiesError;
        collide::track::bodies(
            &self.masses.0,
            &self.positions.0,
            &self.velocities.0,
            self.sizes.as_ref().map(|s| s.0.as_slice()),
        )
        .map_err(|e| match e {
            BodiesError::Miscount(m) => anyhow::anyhow!(
                "--{} has {} values for {} masses: give one per body",
                m.list,
                m.got,
                m.bodies
            ),
            BodiesError::Track(e) => e.into(),
        })
    }
}
