//! The subcommands, one file each, each reading top to bottom as "parse, solve, render": it turns
//! validated arguments into the text to print and an exit status. Output is built whole before
//! anything is written, so an error never leaves half a report on stdout (tables stream, and
//! write files atomically).

mod accuracy;
mod balls;
mod contact;
mod frames;
mod pi;
mod plot;
mod rigid_solve;
mod scene;
mod shell;
mod solve;
mod space_solve;
pub mod table;
mod track;
mod view;

use anyhow::Result;
use collide::line::case::Case;
use collide::line::problem::Problem;
use collide::space;
use collide::space::typed::Listed;

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
    /// Whether the case is one for the plane-and-space solver: not two bodies, vectors, or a
    /// line of impact.
    pub fn spatial(&self) -> bool {
        self.masses.as_ref().is_some_and(|m| m.pair.is_none())
            || self.velocities.pair.is_none()
            || self.normal.is_some()
            || self.radii.is_some()
    }

    /// Whether the case is a body against a wall, floor or ceiling in the plane (`-m '1
    /// kg,wall' -v '(17.32,10) m/s,0'`): a smooth rigid contact, solved by the rigid mode as
    /// with `--friction 0` (a wall to the ball's right, a floor below it, a ceiling above).
    pub fn wall_in_plane(&self) -> bool {
        let immovable = |t: &&str| {
            matches!(
                collide::rigid::pose::MassTyped::parse(t, "mass"),
                Ok(collide::rigid::pose::MassTyped::Immovable(_))
            )
        };
        self.spatial()
            && self.normal.is_none()
            && self.radii.is_none()
            && self.masses.as_ref().is_some_and(|m| {
                collide::space::typed::split_bodies(&m.text)
                    .is_ok_and(|b| b.len() == 2 && b.iter().any(immovable))
            })
    }

    /// The typed problem (masses or tensor, velocities, restitution, units), for exact
    /// arithmetic or not: two bodies on a line (the plane and N bodies are `space_input`).
    pub fn problem(&self, fin: Option<&Listed>, exact: bool) -> Result<Problem> {
        let pair = |l: &Listed| {
            l.pair.clone().ok_or_else(|| {
                anyhow::anyhow!(
                    "'{}': N bodies, vectors and lines of impact are for `collide solve` (and \
                     scenes); this takes two bodies on a line",
                    l.text
                )
            })
        };
        if self.normal.is_some() || self.radii.is_some() {
            anyhow::bail!(
                "--normal and --radii describe a collision in the plane or in space: for \
                 `collide solve` (and scenes)"
            );
        }
        Ok(Problem {
            masses: self.masses.as_ref().map(pair).transpose()?,
            velocities: pair(&self.velocities)?,
            fin: fin.map(pair).transpose()?,
            restitution: self.restitution.clone(),
            si: self.si,
            gravity: self.gravity.clone(),
            energy_unit: self.energy_unit,
            exact,
            knowns: Default::default(),
            velocity_unit: None,
        })
    }

    /// `--radii` and `--impact-parameter` as numbers (lengths with units in metres).
    pub fn geometry(
        &self,
    ) -> Result<
        Option<(
            [collide::values::number::Number; 2],
            collide::values::number::Number,
        )>,
    > {
        match (&self.radii, &self.impact_parameter) {
            (Some(r), Some(b)) => match r.0.as_slice() {
                [r1, r2] => space::pose::geometry([r1, r2], b)
                    .map(Some)
                    .map_err(|e| anyhow::anyhow!("--radii, --impact-parameter: {e}")),
                _ => anyhow::bail!(
                    "--radii with --impact-parameter takes two radii R1,R2 (got {}); one per \
                     ball is for touching balls, with --positions",
                    r.0.len()
                ),
            },
            (Some(_), None) => anyhow::bail!(
                "--radii needs --impact-parameter (two disks) or --positions (touching balls, \
                 one radius each)"
            ),
            _ => Ok(None),
        }
    }

    /// The typed problem in the plane or in space (or N bodies on a line).
    pub fn space_input(&self, fin: Option<&Listed>, exact: bool) -> Result<space::pose::Input> {
        use collide::space::typed::{parse_list, parse_masses};
        if self.inertia.is_some() {
            anyhow::bail!(
                "--inertia is a two-body tensor on a line: give --masses for N bodies or vectors"
            );
        }
        let masses = match &self.masses {
            Some(m) => parse_masses(&m.text)?,
            None => anyhow::bail!("give --masses M1,M2,..."),
        };
        let normal = match (&self.normal, self.geometry()?) {
            (Some(n), _) => Some(n.clone()),
            (None, Some((radii, b))) => Some(space::pose::NormalGiven::Geometry { radii, b }),
            _ => None,
        };
        Ok(space::pose::Input {
            masses,
            v_in: parse_list(&self.velocities.text)?,
            fin: fin.map(|f| parse_list(&f.text)).transpose()?,
            normal,
            e: self
                .restitution
                .clone()
                .map(|g| g.map(|r| r.number().clone())),
            si: self.si,
            exact,
        })
    }

    /// The case, with units resolved, for exact arithmetic or not; `?` (an unknown) is for
    /// `collide solve`.
    pub fn into_case(self, exact: bool) -> Result<Case> {
        Ok(self.problem(None, exact)?.into_case(self.inertia)?)
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
