//! The flags of runs in time: `track` (bodies on a rail with walls and gravity) and `contact`
//! (contact forces integrated through each impact), and their tables of runs (`--vary`).

use std::path::PathBuf;

use clap::{Args, ValueEnum};

use super::Format;
use collide::line::restitution::Restitution;
use collide::table::batch::InputFormat;
use collide::table::sweep::{DEFAULT_MAX_ROWS, Shard};
use collide::table::writer::Header;
use collide::values::number::{Number, NumberList};

/// Bodies on a track: masses, positions, velocities, sizes, walls (`track` and `contact`).
#[derive(Args, Debug)]
pub struct LayoutArgs {
    /// Masses, left to right, e.g. 1,100
    #[arg(short, long, value_name = "M1,M2,...", allow_hyphen_values = true)]
    pub masses: NumberList,

    /// Positions of the bodies' centres, increasing left to right, e.g. 1,2
    #[arg(
        short = 'x',
        long,
        value_name = "X1,X2,...",
        allow_hyphen_values = true
    )]
    pub positions: NumberList,

    /// Velocities, e.g. 0,-1
    #[arg(short, long, value_name = "V1,V2,...", allow_hyphen_values = true)]
    pub velocities: NumberList,

    /// Sizes (lengths along the track) [default: 0, points]
    #[arg(long, value_name = "S1,S2,...", allow_hyphen_values = true)]
    pub sizes: Option<NumberList>,

    /// A wall (an immovable body) at this position, left of every body; the floor under gravity
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub left_wall: Option<Number>,

    /// A wall at this position, right of every body
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub right_wall: Option<Number>,
}

/// What happens on a track besides its bodies: restitutions and gravity (`track`, `view track`).
#[derive(Args, Debug)]
pub struct TrackRules {
    /// Restitution between bodies: a number in [0, 1], 'elastic' or 'inelastic'
    #[arg(short = 'e', long, value_name = "E", default_value = "elastic",
          value_parser = Restitution::parse_dissipative, allow_hyphen_values = true)]
    pub restitution: Restitution,

    /// Restitution at the walls [default: the same as between bodies]
    #[arg(long, value_name = "E", value_parser = Restitution::parse_dissipative,
          allow_hyphen_values = true)]
    pub wall_restitution: Option<Restitution>,

    /// Uniform acceleration toward the left (the left wall is a floor, positions are heights)
    #[arg(
        long,
        value_name = "G",
        default_value = "0",
        allow_hyphen_values = true
    )]
    pub gravity: Number,
}

#[derive(Args, Debug)]
pub struct TrackArgs {
    #[command(flatten)]
    pub layout: LayoutArgs,

    #[command(flatten)]
    pub rules: TrackRules,

    /// Give the state at this time (>= 0): collisions up to it, free flight after the last one
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub until: Option<Number>,

    /// Stop after this many collisions (not given: 1e6 for a motion that never ends, elastic
    /// and held by gravity or two walls)
    #[arg(long, value_name = "N", default_value_t = collide::track::DEFAULT_MAX_COLLISIONS)]
    pub max_collisions: u64,

    /// Write every collision (time, who, velocities before and after) to FILE ('-': stderr)
    #[arg(long, value_name = "FILE", conflicts_with = "vary")]
    pub log: Option<PathBuf>,

    /// Format of the log [default: jsonl for a .jsonl file, else csv]
    #[arg(long, value_enum)]
    pub log_format: Option<InputFormat>,

    /// Output format [default: text; with --vary, from -o's extension, else csv]
    #[arg(long, value_enum)]
    pub format: Option<RunFormat>,

    #[command(flatten)]
    pub table: RunTableArgs,
}

/// The output of `track` and `contact`: a report of one run, or with --vary a table of runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum RunFormat {
    /// Aligned text for people (a report; with --vary, aligned columns)
    Text,
    /// One JSON object (stable schema: docs/json.md); not with --vary (use jsonl)
    Json,
    /// With --vary: comma-separated values with a header line
    Csv,
    /// With --vary: one JSON object a line
    Jsonl,
    /// With --vary: Apache Parquet, zstd, float64 columns (needs -o FILE)
    Parquet,
}

/// A table of runs (`--vary`): one row per run over a grid of parameters, as `collide sweep`.
#[derive(Args, Debug, Clone)]
pub struct RunTableArgs {
    /// A parameter to vary, one row per run: NAME=FROM:TO:COUNT, NAME=FROM:TO:COUNT:log or
    /// NAME=a,b,c, with NAME any number of the run: m1, x1, v1, s1 (mass, position, velocity,
    /// size of body 1), ... and the flags (stiffness, zeta, e, gravity, until, ...; '_' or '-');
    /// repeat for a cartesian product (the last varies fastest)
    #[arg(long, value_name = "NAME=RANGE", allow_hyphen_values = true)]
    pub vary: Vec<String>,

    /// Only the K-th of N contiguous slices of the runs (K from 1), as for collide sweep
    #[arg(long, value_name = "K/N", requires = "vary")]
    pub shard: Option<Shard>,

    /// Refuse sweeps of more runs than this
    #[arg(long, value_name = "N", default_value_t = DEFAULT_MAX_ROWS)]
    pub max_rows: u64,

    /// Columns of a table of runs, comma-separated [default: the varied parameters, the run's
    /// summary, error]
    #[arg(long, value_delimiter = ',', value_name = "COLUMNS", requires = "vary")]
    pub columns: Vec<String>,

    /// Write the table of runs to FILE atomically
    #[arg(short, long, value_name = "FILE", requires = "vary")]
    pub output: Option<PathBuf>,

    /// Report each failed run on stderr and leave it out (default: a row with its error, or,
    /// without an error column, stop at the first)
    #[arg(long, requires = "vary")]
    pub skip_bad: bool,

    /// Which shards carry the header line (CSV, text), as for collide sweep
    #[arg(long, value_enum, requires = "vary")]
    pub header: Option<Header>,
}

/// An integration method for `collide contact`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MethodArg {
    /// Picks bdf when contact time scales differ by more than 100x (stiff), else tsit45
    Auto,
    /// Fixed step: v += h a, then x += h v (Euler-Cromer)
    SymplecticEuler,
    /// Fixed step: velocity Verlet
    Verlet,
    /// Fixed step: classical Runge-Kutta 4
    Rk4,
    /// Fixed step: implicit Euler (Newton)
    ImplicitEuler,
    /// Fixed step: implicit midpoint (Newton)
    ImplicitMidpoint,
    /// Adaptive: Tsitouras 5(4), explicit (diffsol)
    Tsit45,
    /// Adaptive: variable-order BDF (diffsol)
    Bdf,
    /// Adaptive: ESDIRK3(4), L-stable (diffsol)
    Sdirk,
}

impl MethodArg {
    pub fn method(self) -> Option<collide::contact::Method> {
        match self {
            MethodArg::Auto => None,
            m => collide::contact::Method::parse(
                m.to_possible_value().expect("no skipped values").get_name(),
            ),
        }
    }
}

#[derive(Args, Debug)]
pub struct ContactArgs {
    #[command(flatten)]
    pub layout: LayoutArgs,

    /// Contact law
    #[arg(long, value_enum, default_value_t = collide::contact::LawKind::Linear)]
    pub law: collide::contact::LawKind,

    /// Stiffness k of the contacts between bodies (force per overlap, or per overlap^(3/2))
    #[arg(
        long,
        value_name = "K",
        default_value_t = 1.0,
        allow_hyphen_values = true
    )]
    pub stiffness: f64,

    /// Damping between bodies: c of the linear law (force per speed), chi of Hunt-Crossley
    /// (per speed)
    #[arg(
        long,
        value_name = "C",
        group = "body_damping",
        allow_hyphen_values = true
    )]
    pub damping: Option<f64>,

    /// Damping ratio zeta = c / (2 sqrt(k mu)) between bodies (linear law)
    #[arg(
        long,
        value_name = "Z",
        group = "body_damping",
        allow_hyphen_values = true
    )]
    pub zeta: Option<f64>,

    /// Restitution between bodies (linear law): zeta is found from it exactly
    #[arg(
        short = 'e',
        long,
        value_name = "E",
        group = "body_damping",
        allow_hyphen_values = true
    )]
    pub restitution: Option<f64>,

    /// Stiffness at the walls [default: --stiffness]
    #[arg(long, value_name = "K", allow_hyphen_values = true)]
    pub wall_stiffness: Option<f64>,

    /// Damping coefficient at the walls [default: the bodies' damping]
    #[arg(
        long,
        value_name = "C",
        group = "wall_damping_group",
        allow_hyphen_values = true
    )]
    pub wall_damping: Option<f64>,

    /// Damping ratio at the walls
    #[arg(
        long,
        value_name = "Z",
        group = "wall_damping_group",
        allow_hyphen_values = true
    )]
    pub wall_zeta: Option<f64>,

    /// Restitution at the walls (linear law)
    #[arg(
        long,
        value_name = "E",
        group = "wall_damping_group",
        allow_hyphen_values = true
    )]
    pub wall_restitution: Option<f64>,

    /// Integration method
    #[arg(long, value_enum, default_value_t = MethodArg::Auto)]
    pub method: MethodArg,

    /// Step of the fixed-step methods [default: 1/64 of the shortest contact time]
    #[arg(long, value_name = "H", allow_hyphen_values = true)]
    pub dt: Option<f64>,

    /// Tolerance (relative; absolute in units of the overlap and speed scales) of the adaptive
    /// methods [default: 1e-10; 1e-12 for the Hertzian laws]
    #[arg(long, value_name = "TOL", allow_hyphen_values = true)]
    pub tol: Option<f64>,

    /// Give the state at this time (>= 0)
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub until: Option<Number>,

    /// Stop with an error after this many steps
    #[arg(long, value_name = "N", default_value_t = collide::contact::DEFAULT_MAX_STEPS)]
    pub max_steps: u64,

    /// Error against run time for each method on a ladder of tolerances or steps
    #[arg(long, conflicts_with = "vary")]
    pub work_precision: bool,

    /// Methods for --work-precision [default: all]
    #[arg(
        long,
        value_enum,
        value_delimiter = ',',
        value_name = "LIST",
        requires = "work_precision"
    )]
    pub methods: Option<Vec<MethodArg>>,

    /// Write a picture to FILE.svg: the work-precision diagram with --work-precision, else the
    /// force and overlap of each contact against time
    #[arg(long, value_name = "FILE.svg", conflicts_with = "vary")]
    pub plot: Option<PathBuf>,

    /// Output format [default: text; with --vary, from -o's extension, else csv]
    #[arg(long, value_enum)]
    pub format: Option<RunFormat>,

    #[command(flatten)]
    pub table: RunTableArgs,
}

impl RunFormat {
    /// The format of one run's report.
    pub fn report(format: Option<RunFormat>) -> anyhow::Result<Format> {
        match format {
            None | Some(RunFormat::Text) => Ok(Format::Text),
            Some(RunFormat::Json) => Ok(Format::Json),
            Some(f) => anyhow::bail!(
                "--format {} is for a table of runs: add --vary NAME=RANGE, or use text or json",
                f.to_possible_value()
                    .map_or("?".into(), |v| v.get_name().to_string())
            ),
        }
    }
}
